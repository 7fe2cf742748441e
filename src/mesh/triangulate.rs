//! Triangulation of polygon meshes, so that triangle-only operations (Loop
//! subdivision) can follow any mesh: triangles stay as they are, a quad is
//! split along its shorter diagonal, an n-gon is ear-clipped in its best-fit
//! plane (Newell's normal), so concave n-gons come out right.

use glam::{DVec2, DVec3};

use crate::buffers::try_vec;
use crate::error::Result;
use crate::mesh::analysis::newell_vector;
use crate::mesh::Mesh;

mod large_polygons;

/// A triangulated mesh and the input face each triangle comes from.
#[derive(Debug, Clone, PartialEq)]
pub struct Triangulation {
    /// The triangles, over the input's vertices (same indices, same positions).
    pub mesh: Mesh,
    /// For each triangle, the index of the face it was cut from; the
    /// triangles of one face are contiguous and in face order.
    pub parent_faces: Vec<u32>,
}

/// Triangulates every face of `mesh`: a face of n corners makes n − 2
/// triangles with the face's winding; vertices are not changed.
///
/// # Errors
/// [`crate::Error::OutOfMemory`] when the result cannot be reserved.
pub fn triangulate(mesh: &Mesh) -> Result<Triangulation> {
    let triangle_count: usize = mesh.face_sizes().iter().map(|&s| s as usize - 2).sum();
    let mut indices = try_vec(3 * triangle_count, "triangles")?;
    let mut parent_faces = try_vec(triangle_count, "parent faces")?;
    let positions = mesh.positions();
    let mut scratch = EarClipper::default();
    for (f, face) in mesh.faces().enumerate() {
        let before = indices.len();
        match *face {
            [a, b, c] => indices.extend_from_slice(&[a, b, c]),
            [a, b, c, d] => {
                let p = |v: u32| positions[v as usize];
                if p(a).distance_squared(p(c)) <= p(b).distance_squared(p(d)) {
                    indices.extend_from_slice(&[a, b, c, a, c, d]);
                } else {
                    indices.extend_from_slice(&[a, b, d, b, c, d]);
                }
            }
            _ => scratch.clip(face, positions, &mut indices),
        }
        let made = (indices.len() - before) / 3;
        parent_faces.extend(std::iter::repeat_n(f as u32, made));
    }
    let sizes = vec![3u32; triangle_count];
    Ok(Triangulation {
        mesh: Mesh::from_valid_parts(positions.to_vec(), sizes, indices),
        parent_faces,
    })
}

/// `mesh` as triangles, for the operations that need them (Loop, Split
/// Triangles): a copy when every face is a triangle, else [`triangulate`].
/// Returns the triangulation and the number of input faces that were not
/// triangles, so a front-end can say how many it split.
///
/// # Errors
/// [`crate::Error::OutOfMemory`] when the result cannot be reserved.
pub fn as_triangles(mesh: &Mesh) -> Result<(Triangulation, usize)> {
    let split_faces = mesh.face_sizes().iter().filter(|&&s| s != 3).count();
    if split_faces > 0 {
        return Ok((triangulate(mesh)?, split_faces));
    }
    let mut parent_faces = try_vec(mesh.face_count(), "parent faces")?;
    parent_faces.extend(0..mesh.face_count() as u32);
    let copy = Triangulation {
        mesh: mesh.clone(),
        parent_faces,
    };
    Ok((copy, 0))
}

/// Reusable buffers for ear clipping.
#[derive(Default)]
struct EarClipper {
    points: Vec<DVec2>,
    remaining: Vec<usize>,
}

impl EarClipper {
    /// Appends the n − 2 triangles of polygon `face`.
    fn clip(&mut self, face: &[u32], positions: &[DVec3], out: &mut Vec<u32>) {
        let corners: Vec<DVec3> = face.iter().map(|&v| positions[v as usize]).collect();
        // A basis of the best-fit plane oriented so the polygon winds
        // counter-clockwise. Newell's vector is twice the polygon's area
        // long; the basis is orthonormal only when built from a unit normal.
        let normal = newell_vector(&corners).normalize_or_zero();
        let axis_u = normal.any_orthonormal_vector();
        let axis_v = normal.cross(axis_u);
        self.points.clear();
        self.points.extend(
            corners
                .iter()
                .map(|&p| DVec2::new(p.dot(axis_u), p.dot(axis_v))),
        );
        self.remaining.clear();
        self.remaining.extend(0..face.len());
        let scale = self
            .points
            .iter()
            .fold(0.0f64, |m, p| m.max(p.abs().max_element()))
            .max(f64::MIN_POSITIVE);
        let epsilon = 1e-12 * scale * scale;
        if face.len() >= large_polygons::LARGE {
            large_polygons::clip(&self.points, epsilon, |corners| {
                out.extend(corners.map(|k| face[k]));
            });
            return;
        }

        while self.remaining.len() > 3 {
            let n = self.remaining.len();
            let ear = (0..n)
                .find(|&i| self.is_ear(i, epsilon))
                // Degenerate input (collinear or self-overlapping): cut the
                // most convex corner so that the polygon still closes.
                .unwrap_or_else(|| self.most_convex(n));
            let (prev, next) = ((ear + n - 1) % n, (ear + 1) % n);
            out.extend_from_slice(&[
                face[self.remaining[prev]],
                face[self.remaining[ear]],
                face[self.remaining[next]],
            ]);
            self.remaining.remove(ear);
        }
        out.extend(self.remaining.iter().map(|&i| face[i]));
    }

    fn corner(&self, i: usize) -> (DVec2, DVec2, DVec2) {
        let n = self.remaining.len();
        let at = |k: usize| self.points[self.remaining[k % n]];
        (at(i + n - 1), at(i), at(i + 1))
    }

    fn is_ear(&self, i: usize, epsilon: f64) -> bool {
        let (a, b, c) = self.corner(i);
        if (b - a).perp_dot(c - b) <= epsilon {
            return false; // reflex or flat
        }
        let n = self.remaining.len();
        (0..n)
            .filter(|&k| k != i && k != (i + 1) % n && k != (i + n - 1) % n)
            .all(|k| !inside_triangle(self.points[self.remaining[k]], a, b, c))
    }

    fn most_convex(&self, n: usize) -> usize {
        (0..n)
            .max_by(|&i, &j| {
                let turn = |k: usize| {
                    let (a, b, c) = self.corner(k);
                    (b - a).perp_dot(c - b)
                };
                turn(i).total_cmp(&turn(j))
            })
            .unwrap_or(0)
    }
}

/// Whether `p` lies inside or on triangle `abc` (counter-clockwise).
fn inside_triangle(p: DVec2, a: DVec2, b: DVec2, c: DVec2) -> bool {
    (b - a).perp_dot(p - a) >= 0.0
        && (c - b).perp_dot(p - b) >= 0.0
        && (a - c).perp_dot(p - c) >= 0.0
}

#[cfg(test)]
mod tests {
    use super::*;

    fn area(mesh: &Mesh) -> f64 {
        mesh.faces()
            .map(|f| {
                let p: Vec<DVec3> = f.iter().map(|&v| mesh.positions()[v as usize]).collect();
                newell_vector(&p).length() / 2.0
            })
            .sum()
    }

    #[test]
    fn quad_uses_the_shorter_diagonal() {
        let p = vec![
            DVec3::new(0.0, 0.0, 0.0),
            DVec3::new(3.0, 0.0, 0.0),
            DVec3::new(3.5, 1.0, 0.0),
            DVec3::new(0.5, 1.0, 0.0),
        ];
        let mesh = Mesh::from_polygons(p, [[0u32, 1, 2, 3]]).unwrap();
        let t = triangulate(&mesh).unwrap();
        // 1-3 is shorter than 0-2.
        assert_eq!(t.mesh.face_indices(), &[0, 1, 3, 1, 2, 3]);
        assert_eq!(t.parent_faces, vec![0, 0]);
    }

    #[test]
    fn a_folded_hexagon_keeps_its_winding() {
        // Two squares meeting at a right angle along the middle of the
        // hexagon's long sides; those two corners are straight in the
        // best-fit plane, one of them slightly reflex.
        let p = [
            (-1.00156, -0.32860, 1.00466),
            (-0.33696, -0.33077, 1.00034),
            (-0.33034, 0.33112, 1.00370),
            (-0.99774, 0.33576, 0.99899),
            (-0.99599, 0.33404, 0.33505),
            (-0.99929, -0.33210, 0.33576),
        ]
        .map(|(x, y, z)| DVec3::new(x, y, z))
        .to_vec();
        let normal = newell_vector(&p);
        let mesh = Mesh::from_polygons(p, [[0u32, 1, 2, 3, 4, 5]]).unwrap();
        let t = triangulate(&mesh).unwrap();
        assert_eq!(t.mesh.face_count(), 4);
        for f in t.mesh.faces() {
            let q: Vec<DVec3> = f.iter().map(|&v| t.mesh.positions()[v as usize]).collect();
            assert!(newell_vector(&q).dot(normal) > 0.0, "{f:?}");
        }
    }

    #[test]
    fn concave_l_shape_keeps_its_area() {
        let mesh = crate::mesh::shapes::l_shaped_hexagon(0.0);
        let t = triangulate(&mesh).unwrap();
        assert_eq!(t.mesh.face_count(), 4);
        assert!((area(&t.mesh) - 3.0).abs() < 1e-12);
        // Every triangle keeps the polygon's winding (+z).
        for f in t.mesh.faces() {
            let q: Vec<DVec3> = f.iter().map(|&v| t.mesh.positions()[v as usize]).collect();
            assert!(newell_vector(&q).z > 0.0);
        }
    }
}
