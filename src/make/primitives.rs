//! Primitive meshes (Weaverbird's Define panel): a plane grid, a subdivided
//! box, a UV sphere, the five platonic solids, and the prism, antiprism,
//! pyramid and dipyramid of n sides.
//!
//! Every solid is centred on the origin, closed, welded (no two vertices at
//! one position), outward-facing (positive signed volume) and of Euler
//! characteristic 2; the n-sided solids stand on the XY plane's directions
//! with their axis along z. Sizes must be positive and finite.

use std::collections::HashMap;
use std::f64::consts::TAU;

use glam::DVec3;

use crate::buffers::try_vec;
use crate::error::{Error, Result, MAX_ELEMENTS};
use crate::make::grid::mesh_from_grid;
use crate::mesh::Mesh;

/// The five platonic solids.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Platonic {
    /// 4 vertices, 4 triangles.
    Tetrahedron,
    /// The cube: 8 vertices, 6 quads.
    Hexahedron,
    /// 6 vertices, 8 triangles.
    Octahedron,
    /// 20 vertices, 12 pentagons.
    Dodecahedron,
    /// 12 vertices, 20 triangles.
    Icosahedron,
}

/// The solids built on a regular n-gon.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Sided {
    /// Two n-gons joined by n quads.
    Prism,
    /// Two n-gons, one turned by half a side, joined by 2n triangles.
    Antiprism,
    /// An n-gon base and n triangles meeting at the apex.
    Pyramid,
    /// Two pyramids base to base: 2n triangles.
    Dipyramid,
}

fn check_size(value: f64, name: &str) -> Result<()> {
    if value.is_finite() && value > 0.0 {
        Ok(())
    } else {
        Err(Error::InvalidArgument(format!(
            "{name} is {value}; it must be a positive finite number"
        )))
    }
}

fn check_count(value: usize, minimum: usize, name: &str) -> Result<()> {
    if value < minimum {
        Err(Error::InvalidArgument(format!(
            "{name} is {value}; it must be at least {minimum}"
        )))
    } else {
        Ok(())
    }
}

/// Refuses a result of `corners` face corners past [`MAX_ELEMENTS`]; `None`
/// is a count that overflowed 64 bits. The corners bound the vertex and
/// face counts of every primitive, so this one check covers all three.
fn check_total(corners: Option<u64>, what: &str) -> Result<()> {
    match corners {
        Some(corners) if corners <= MAX_ELEMENTS => Ok(()),
        Some(corners) => Err(Error::ResultTooLarge(format!(
            "{what} would have {corners} face corners, over the limit of {MAX_ELEMENTS}"
        ))),
        None => Err(Error::ResultTooLarge(format!(
            "{what} would have more than {} face corners, over the limit of {MAX_ELEMENTS}",
            u64::MAX
        ))),
    }
}

/// `a × b × c` in 64 bits, `None` on overflow.
fn product(factors: &[usize]) -> Option<u64> {
    factors
        .iter()
        .try_fold(1u64, |total, &f| total.checked_mul(u64::try_from(f).ok()?))
}

/// A flat rectangle of `size_x × size_y` on the XY plane, centred on the
/// origin and facing +z, divided into `u_count × v_count` quads (x, then y).
/// It is open: Euler characteristic 1.
///
/// # Errors
/// [`Error::InvalidArgument`] for a size that is not positive and finite or
/// a count of 0; [`Error::ResultTooLarge`] past [`MAX_ELEMENTS`].
pub fn plane_grid(size_x: f64, size_y: f64, u_count: usize, v_count: usize) -> Result<Mesh> {
    check_size(size_x, "size_x")?;
    check_size(size_y, "size_y")?;
    check_count(u_count, 1, "u_count")?;
    check_count(v_count, 1, "v_count")?;
    check_total(product(&[u_count, v_count, 4]), "the plane grid")?;
    let mut points = try_vec((u_count + 1) * (v_count + 1), "the plane grid's points")?;
    for j in 0..=v_count {
        for i in 0..=u_count {
            points.push(DVec3::new(
                size_x * (i as f64 / u_count as f64 - 0.5),
                size_y * (j as f64 / v_count as f64 - 0.5),
                0.0,
            ));
        }
    }
    mesh_from_grid(&points, u_count + 1, v_count + 1, false, false, false)
}

/// A box of `size` centred on the origin, each side divided into quads:
/// `u_count` along x, `v_count` along y, `w_count` along z. The sides share
/// their edge vertices (one welded, closed mesh).
///
/// # Errors
/// As [`plane_grid`].
pub fn box_grid(size: DVec3, u_count: usize, v_count: usize, w_count: usize) -> Result<Mesh> {
    check_size(size.x, "size_x")?;
    check_size(size.y, "size_y")?;
    check_size(size.z, "size_z")?;
    let counts = [u_count, v_count, w_count];
    for (count, name) in counts.iter().zip(["u_count", "v_count", "w_count"]) {
        check_count(*count, 1, name)?;
    }
    let sides = [
        product(&[u_count, v_count]),
        product(&[v_count, w_count]),
        product(&[w_count, u_count]),
    ];
    let quads = sides
        .into_iter()
        .try_fold(0u64, |total, side| total.checked_add(side?));
    check_total(quads.and_then(|q| q.checked_mul(8)), "the box")?;
    // Each quad has 4 corners and the sides' corners bound the vertices.
    let quad_count = 2 * quads.unwrap_or(0) as usize;
    let mut positions = try_vec(quad_count + 2, "the box's vertices")?;
    let mut lattice: HashMap<[usize; 3], u32> = HashMap::new();
    lattice.try_reserve(quad_count + 2).map_err(|_| {
        Error::OutOfMemory(format!(
            "could not reserve the box's {quad_count} lattice cells"
        ))
    })?;
    let mut vertex = |cell: [usize; 3], positions: &mut Vec<DVec3>| -> u32 {
        *lattice.entry(cell).or_insert_with(|| {
            positions.push(DVec3::new(
                size.x * (cell[0] as f64 / counts[0] as f64 - 0.5),
                size.y * (cell[1] as f64 / counts[1] as f64 - 0.5),
                size.z * (cell[2] as f64 / counts[2] as f64 - 0.5),
            ));
            (positions.len() - 1) as u32
        })
    };
    let mut polygons: Vec<[u32; 4]> = try_vec(quad_count, "the box's faces")?;
    // For the side across axis a, walk axes b and c with e_b × e_c = e_a.
    for a in 0..3 {
        let (b, c) = ((a + 1) % 3, (a + 2) % 3);
        for high in [false, true] {
            for j in 0..counts[c] {
                for i in 0..counts[b] {
                    let corner = |di: usize, dj: usize| {
                        let mut cell = [0; 3];
                        cell[a] = if high { counts[a] } else { 0 };
                        cell[b] = i + di;
                        cell[c] = j + dj;
                        cell
                    };
                    let mut quad = [corner(0, 0), corner(1, 0), corner(1, 1), corner(0, 1)]
                        .map(|cell| vertex(cell, &mut positions));
                    if !high {
                        quad.reverse();
                    }
                    polygons.push(quad);
                }
            }
        }
    }
    Ok(Mesh::from_polygons(positions, polygons)?)
}

/// A sphere of `radius` centred on the origin: `u_count` segments around
/// the z axis and `v_count` from the south pole to the north pole. Each pole
/// is a single vertex with a fan of triangles; the rest are quads. Vertex
/// order: south pole, the rings from south to north (each starting on +x,
/// counter-clockwise about +z), north pole.
///
/// # Errors
/// [`Error::InvalidArgument`] for a radius that is not positive and finite,
/// `u_count < 3` or `v_count < 2`; [`Error::ResultTooLarge`] past
/// [`MAX_ELEMENTS`].
pub fn uv_sphere(radius: f64, u_count: usize, v_count: usize) -> Result<Mesh> {
    check_size(radius, "radius")?;
    check_count(u_count, 3, "u_count")?;
    check_count(v_count, 2, "v_count")?;
    check_total(product(&[u_count, v_count, 4]), "the sphere")?;
    let rings = v_count - 1;
    let mut positions = try_vec(u_count * rings + 2, "the sphere's vertices")?;
    positions.push(DVec3::new(0.0, 0.0, -radius));
    for j in 1..v_count {
        let polar = std::f64::consts::PI * j as f64 / v_count as f64;
        for i in 0..u_count {
            let around = TAU * i as f64 / u_count as f64;
            positions.push(DVec3::new(
                radius * polar.sin() * around.cos(),
                radius * polar.sin() * around.sin(),
                -radius * polar.cos(),
            ));
        }
    }
    positions.push(DVec3::new(0.0, 0.0, radius));
    let north = (positions.len() - 1) as u32;
    let ring = |j: usize, i: usize| (1 + (j - 1) * u_count + i % u_count) as u32;
    let mut polygons: Vec<Vec<u32>> = try_vec(u_count * v_count, "the sphere's faces")?;
    for i in 0..u_count {
        polygons.push(vec![0, ring(1, i + 1), ring(1, i)]);
    }
    for j in 1..rings {
        for i in 0..u_count {
            polygons.push(vec![
                ring(j, i),
                ring(j, i + 1),
                ring(j + 1, i + 1),
                ring(j + 1, i),
            ]);
        }
    }
    for i in 0..u_count {
        polygons.push(vec![ring(rings, i), ring(rings, i + 1), north]);
    }
    Ok(Mesh::from_polygons(positions, polygons)?)
}

/// A platonic solid whose vertices lie on the sphere of `radius` about the
/// origin (the circumradius).
///
/// Any positive finite radius works, `f64::MAX` included: the faces are
/// found on the solid of radius 1, then scaled.
///
/// # Errors
/// [`Error::InvalidArgument`] for a radius that is not positive and finite.
pub fn platonic(kind: Platonic, radius: f64) -> Result<Mesh> {
    check_size(radius, "radius")?;
    let phi = (1.0 + 5f64.sqrt()) / 2.0;
    let mut points: Vec<DVec3> = Vec::new();
    let signs = [-1.0, 1.0];
    // The classic coordinates; each list is then scaled to the circumradius.
    let cyclic = |a: f64, b: f64, points: &mut Vec<DVec3>| {
        for &s in &signs {
            for &t in &signs {
                points.push(DVec3::new(0.0, s * a, t * b));
                points.push(DVec3::new(s * a, t * b, 0.0));
                points.push(DVec3::new(t * b, 0.0, s * a));
            }
        }
    };
    let cube_corners = |points: &mut Vec<DVec3>| {
        for &x in &signs {
            for &y in &signs {
                for &z in &signs {
                    points.push(DVec3::new(x, y, z));
                }
            }
        }
    };
    match kind {
        Platonic::Tetrahedron => points.extend([
            DVec3::new(1.0, 1.0, 1.0),
            DVec3::new(1.0, -1.0, -1.0),
            DVec3::new(-1.0, 1.0, -1.0),
            DVec3::new(-1.0, -1.0, 1.0),
        ]),
        Platonic::Hexahedron => cube_corners(&mut points),
        Platonic::Octahedron => {
            for axis in [DVec3::X, DVec3::Y, DVec3::Z] {
                points.extend([axis, -axis]);
            }
        }
        Platonic::Dodecahedron => {
            cube_corners(&mut points);
            cyclic(1.0 / phi, phi, &mut points);
        }
        Platonic::Icosahedron => cyclic(1.0, phi, &mut points),
    }
    for p in &mut points {
        *p /= p.length();
    }
    // The faces are found on the unit solid: at the given radius the hull's
    // cross products overflow (radius near f64::MAX) or underflow (near 0).
    let unit = convex_hull_of_few(points)?;
    let scaled = unit.positions().iter().map(|&p| p * radius).collect();
    Ok(unit.with_positions(scaled)?)
}

/// The faces of the convex hull of a few points in convex position (all
/// are corners): every plane through three points with all others behind it
/// is a face, its points sorted counter-clockwise about the outward normal.
/// Cubic in the point count: only for the platonic solids' handful.
fn convex_hull_of_few(points: Vec<DVec3>) -> Result<Mesh> {
    let n = points.len();
    let scale = points.iter().map(|p| p.length()).fold(0.0, f64::max);
    let tolerance = scale * 1e-9;
    let mut faces: Vec<Vec<u32>> = Vec::new();
    let mut seen: Vec<Vec<u32>> = Vec::new();
    for i in 0..n {
        for j in i + 1..n {
            for k in j + 1..n {
                let (a, b, c) = (points[i], points[j], points[k]);
                let mut normal = (b - a).cross(c - a);
                if normal.length() <= tolerance * scale {
                    continue;
                }
                normal = normal.normalize();
                let plane_normal = normal;
                let side = |p: DVec3| plane_normal.dot(p - a);
                let (mut front, mut back) = (false, false);
                for p in &points {
                    front |= side(*p) > tolerance;
                    back |= side(*p) < -tolerance;
                }
                if front && back {
                    continue;
                }
                if front {
                    normal = -normal;
                }
                let mut on: Vec<u32> = (0..n as u32)
                    .filter(|&m| side(points[m as usize]).abs() <= tolerance)
                    .collect();
                if on.len() < 3 || seen.contains(&on) {
                    continue;
                }
                seen.push(on.clone());
                let center =
                    on.iter().map(|&m| points[m as usize]).sum::<DVec3>() / on.len() as f64;
                let x = (points[on[0] as usize] - center).normalize();
                let y = normal.cross(x);
                on.sort_by(|&p, &q| {
                    let angle = |m: u32| {
                        let d = points[m as usize] - center;
                        d.dot(y).atan2(d.dot(x))
                    };
                    angle(p).total_cmp(&angle(q))
                });
                faces.push(on);
            }
        }
    }
    Ok(Mesh::from_polygons(points, faces)?)
}

/// A solid on a regular n-gon of circumradius `radius` about the z axis,
/// `height` tall along z and centred on the origin (the first corner of the
/// lower n-gon lies on +x). The pyramid's base is at `-height / 2` and its
/// apex at `+height / 2`; the dipyramid's apexes are at `±height / 2`.
///
/// # Errors
/// [`Error::InvalidArgument`] for `sides < 3` or a radius or height that is
/// not positive and finite; [`Error::ResultTooLarge`] past [`MAX_ELEMENTS`].
pub fn sided(kind: Sided, sides: usize, radius: f64, height: f64) -> Result<Mesh> {
    check_count(sides, 3, "sides")?;
    check_size(radius, "radius")?;
    check_size(height, "height")?;
    check_total(product(&[sides, 8]), "the solid")?;
    let n = sides;
    let corner = |i: f64, z: f64| {
        let a = TAU * i / n as f64;
        DVec3::new(radius * a.cos(), radius * a.sin(), z)
    };
    let (low, high) = (-height / 2.0, height / 2.0);
    let mut positions: Vec<DVec3> = (0..n).map(|i| corner(i as f64, low)).collect();
    let mut polygons: Vec<Vec<u32>> = Vec::new();
    let base = |i: usize| (i % n) as u32;
    let bottom: Vec<u32> = (0..n as u32).rev().collect();
    match kind {
        Sided::Prism | Sided::Antiprism => {
            let turn = if kind == Sided::Antiprism { 0.5 } else { 0.0 };
            positions.extend((0..n).map(|i| corner(i as f64 + turn, high)));
            let top = |i: usize| (n + i % n) as u32;
            polygons.push(bottom);
            polygons.push((0..n).map(top).collect());
            for i in 0..n {
                if kind == Sided::Prism {
                    polygons.push(vec![base(i), base(i + 1), top(i + 1), top(i)]);
                } else {
                    polygons.push(vec![base(i), base(i + 1), top(i)]);
                    polygons.push(vec![top(i), base(i + 1), top(i + 1)]);
                }
            }
        }
        Sided::Pyramid => {
            positions.push(DVec3::new(0.0, 0.0, high));
            polygons.push(bottom);
            for i in 0..n {
                polygons.push(vec![base(i), base(i + 1), n as u32]);
            }
        }
        Sided::Dipyramid => {
            for p in &mut positions {
                p.z = 0.0;
            }
            positions.push(DVec3::new(0.0, 0.0, high));
            positions.push(DVec3::new(0.0, 0.0, low));
            for i in 0..n {
                polygons.push(vec![base(i), base(i + 1), n as u32]);
                polygons.push(vec![base(i + 1), base(i), n as u32 + 1]);
            }
        }
    }
    Ok(Mesh::from_polygons(positions, polygons)?)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::topology::Topology;

    fn signed_volume(mesh: &Mesh) -> f64 {
        let mut volume = 0.0;
        for f in 0..mesh.face_count() {
            let p: Vec<DVec3> = mesh.face_positions(f).collect();
            for k in 1..p.len() - 1 {
                volume += p[0].dot(p[k].cross(p[k + 1])) / 6.0;
            }
        }
        volume
    }

    /// Closed, oriented outward, welded, Euler characteristic 2; returns the volume.
    fn check_solid(mesh: &Mesh, what: &str) -> f64 {
        let info = Topology::new(mesh).info(mesh);
        assert!(info.is_closed, "{what} is not closed");
        assert!(info.is_oriented, "{what} is not consistently oriented");
        assert_eq!(info.non_manifold_vertex_count, 0, "{what}");
        assert_eq!(info.component_count, 1, "{what}");
        let euler = info.vertex_count as i64 - info.edge_count as i64 + info.face_count as i64;
        assert_eq!(euler, 2, "{what}: Euler characteristic");
        let mut sorted: Vec<[u64; 3]> = mesh
            .positions()
            .iter()
            .map(|p| p.to_array().map(|c| (c + 0.0).to_bits()))
            .collect();
        sorted.sort();
        sorted.dedup();
        assert_eq!(
            sorted.len(),
            mesh.vertex_count(),
            "{what} has duplicate positions"
        );
        let volume = signed_volume(mesh);
        assert!(volume > 0.0, "{what} faces inward");
        // Every face faces away from the centre (all these solids are convex, centred on the origin).
        for f in 0..mesh.face_count() {
            let p: Vec<DVec3> = mesh.face_positions(f).collect();
            let normal: DVec3 = (0..p.len()).map(|k| p[k].cross(p[(k + 1) % p.len()])).sum();
            let center = p.iter().sum::<DVec3>() / p.len() as f64;
            assert!(normal.dot(center) > 0.0, "{what}: face {f} faces inward");
        }
        volume
    }

    #[test]
    fn platonic_solids() {
        let expected = [
            (Platonic::Tetrahedron, 4, 4, 3),
            (Platonic::Hexahedron, 8, 6, 4),
            (Platonic::Octahedron, 6, 8, 3),
            (Platonic::Dodecahedron, 20, 12, 5),
            (Platonic::Icosahedron, 12, 20, 3),
        ];
        for (kind, vertices, faces, size) in expected {
            let mesh = platonic(kind, 2.0).unwrap();
            assert_eq!(mesh.vertex_count(), vertices, "{kind:?}");
            assert_eq!(mesh.face_count(), faces, "{kind:?}");
            assert!(mesh.face_sizes().iter().all(|&s| s == size), "{kind:?}");
            assert!(mesh
                .positions()
                .iter()
                .all(|p| (p.length() - 2.0).abs() < 1e-12));
            check_solid(&mesh, &format!("{kind:?}"));
        }
        // The cube of circumradius √3 is the cube of side 2.
        let cube = platonic(Platonic::Hexahedron, 3f64.sqrt()).unwrap();
        assert!((signed_volume(&cube) - 8.0).abs() < 1e-12);
    }

    #[test]
    fn sided_solids() {
        for n in [3, 4, 5, 12] {
            let prism = sided(Sided::Prism, n, 1.0, 2.0).unwrap();
            assert_eq!((prism.vertex_count(), prism.face_count()), (2 * n, n + 2));
            let area = 0.5 * n as f64 * (TAU / n as f64).sin();
            assert!((check_solid(&prism, "prism") - 2.0 * area).abs() < 1e-12);
            let antiprism = sided(Sided::Antiprism, n, 1.0, 2.0).unwrap();
            assert_eq!(
                (antiprism.vertex_count(), antiprism.face_count()),
                (2 * n, 2 * n + 2)
            );
            check_solid(&antiprism, "antiprism");
            let pyramid = sided(Sided::Pyramid, n, 1.0, 3.0).unwrap();
            assert_eq!(
                (pyramid.vertex_count(), pyramid.face_count()),
                (n + 1, n + 1)
            );
            assert!((check_solid(&pyramid, "pyramid") - area).abs() < 1e-12);
            let dipyramid = sided(Sided::Dipyramid, n, 1.0, 3.0).unwrap();
            assert_eq!(
                (dipyramid.vertex_count(), dipyramid.face_count()),
                (n + 2, 2 * n)
            );
            assert!((check_solid(&dipyramid, "dipyramid") - area).abs() < 1e-12);
        }
    }

    #[test]
    fn box_and_sphere() {
        let b = box_grid(DVec3::new(2.0, 3.0, 4.0), 2, 3, 4).unwrap();
        assert_eq!(b.face_count(), 2 * (2 * 3 + 3 * 4 + 4 * 2));
        // All lattice points but the inner ones.
        assert_eq!(b.vertex_count(), 3 * 4 * 5 - 2 * 3);
        assert!((check_solid(&b, "box") - 24.0).abs() < 1e-12);
        let unit = box_grid(DVec3::ONE, 1, 1, 1).unwrap();
        assert_eq!((unit.vertex_count(), unit.face_count()), (8, 6));
        check_solid(&unit, "unit box");

        let sphere = uv_sphere(2.0, 8, 6).unwrap();
        assert_eq!(sphere.vertex_count(), 2 + 8 * 5);
        assert_eq!(sphere.face_count(), 8 * 6);
        assert_eq!(sphere.face_sizes().iter().filter(|&&s| s == 3).count(), 16);
        assert!(sphere
            .positions()
            .iter()
            .all(|p| (p.length() - 2.0).abs() < 1e-12));
        check_solid(&sphere, "sphere");
        check_solid(&uv_sphere(1.0, 3, 2).unwrap(), "smallest sphere");
    }

    #[test]
    fn plane_grid_is_open_and_faces_up() {
        let mesh = plane_grid(4.0, 2.0, 4, 2).unwrap();
        assert_eq!((mesh.vertex_count(), mesh.face_count()), (15, 8));
        assert_eq!(
            mesh.bounding_box(),
            Some((DVec3::new(-2.0, -1.0, 0.0), DVec3::new(2.0, 1.0, 0.0)))
        );
        let info = Topology::new(&mesh).info(&mesh);
        assert_eq!(info.naked_edge_count, 12);
        assert_eq!(
            info.vertex_count as i64 - info.edge_count as i64 + info.face_count as i64,
            1
        );
        let p: Vec<DVec3> = mesh.face_positions(0).collect();
        assert!((p[1] - p[0]).cross(p[2] - p[0]).z > 0.0);
    }

    #[test]
    fn bad_arguments_are_named() {
        let e = sided(Sided::Prism, 2, 1.0, 1.0).unwrap_err();
        assert!(
            matches!(&e, Error::InvalidArgument(m) if m.contains("sides is 2")),
            "{e}"
        );
        let e = sided(Sided::Pyramid, 5, 1.0, -1.0).unwrap_err();
        assert!(
            matches!(&e, Error::InvalidArgument(m) if m.contains("height is -1")),
            "{e}"
        );
        let e = platonic(Platonic::Icosahedron, f64::NAN).unwrap_err();
        assert!(
            matches!(&e, Error::InvalidArgument(m) if m.contains("radius")),
            "{e}"
        );
        let e = uv_sphere(1.0, 2, 4).unwrap_err();
        assert!(
            matches!(&e, Error::InvalidArgument(m) if m.contains("u_count is 2")),
            "{e}"
        );
        let e = box_grid(DVec3::ONE, 1, 0, 1).unwrap_err();
        assert!(
            matches!(&e, Error::InvalidArgument(m) if m.contains("v_count is 0")),
            "{e}"
        );
        let e = plane_grid(1.0, 1.0, 1 << 20, 1 << 20).unwrap_err();
        assert!(matches!(e, Error::ResultTooLarge(_)), "{e}");
    }
}
