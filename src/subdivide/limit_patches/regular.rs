//! What the patches take straight from the cage refined `isolation` levels,
//! without refining further: the limit point at every vertex, the patches
//! of regular faces and the limit curves of edges between regular vertices.
//!
//! A vertex is regular when it has four edges, none of them sharp, and four
//! quads around it, manifold and turned one way, with the smooth rule. Over
//! a face whose four corners are regular, the limit surface is the uniform
//! bicubic B-spline of the face and its ring: its Bézier points are the
//! corners' limit points, its edges' curves, and inner points that weigh the
//! face's own four points. Along an edge whose two ends are regular, the
//! limit curve is the uniform cubic B-spline of the points across the edge,
//! whatever lies beyond them: refining leaves the rows beside the edge to
//! the face and edge rules, and the vertex rule only to the edge's own
//! regular vertices. Each of these is worked out from its vertex or edge
//! alone, by sums that give the same bits whichever face asks, so patches
//! made here and patches fitted beside them share their corners and edges
//! bit for bit.

use glam::DVec3;
use rayon::prelude::*;

use crate::error::Result;
use crate::subdivide::creases::Rule;
use crate::subdivide::level::{Connectivity, Faces};
use crate::subdivide::stencils::walk_around;
use crate::subdivide::subdivider::Subdivider;

/// The refined cage the patches are made on.
pub(super) struct Isolated<'a> {
    faces: &'a Faces<'static>,
    connectivity: &'a Connectivity,
    points: Vec<DVec3>,
    limits: Vec<DVec3>,
    /// The edges of each regular vertex in order around it; `None` for the others.
    rings: Vec<Option<[u32; 4]>>,
}

impl<'a> Isolated<'a> {
    /// The last level of `refined` (Catmull-Clark, one level or more) at
    /// `cage`, which needs no scaling (see `scale.rs`).
    ///
    /// # Errors
    /// As [`Subdivider::evaluate`].
    pub(super) fn new(refined: &'a Subdivider, cage: &[DVec3]) -> Result<Isolated<'a>> {
        let last = refined.last();
        let (faces, connectivity, sharpness) = (&last.faces, &last.connectivity, &last.sharpness);
        let mut points = vec![DVec3::ZERO; refined.vertex_count()];
        refined.evaluate(cage, &mut points)?;
        let rings: Vec<Option<[u32; 4]>> = (0..faces.vertex_count)
            .into_par_iter()
            .map_init(
                || (Vec::new(), Vec::new()),
                |(edges, corners), v| {
                    // The smooth rule: no sharpness at the vertex or on its edges.
                    let smooth =
                        sharpness.rules[v] == Rule::Smooth && sharpness.edges_at(v).len() == 4;
                    let ordered = smooth
                        && walk_around(
                            faces,
                            connectivity,
                            v,
                            refined.first_corners[v],
                            4,
                            edges,
                            corners,
                        )
                        && corners.len() == 4
                        && corners
                            .iter()
                            .all(|&c| faces.corners(connectivity.face_of(c as usize)).len() == 4);
                    ordered.then(|| [edges[0], edges[1], edges[2], edges[3]])
                },
            )
            .collect();
        // Only regular vertices' limits are read.
        let limits = refined.limit_positions_where(&points, |v| rings[v].is_some());
        Ok(Isolated {
            faces,
            connectivity,
            points,
            limits,
            rings,
        })
    }

    /// The corners of refined face `face`.
    pub(super) fn corners_of(&self, face: usize) -> std::ops::Range<usize> {
        self.faces.corners(face)
    }

    /// The vertex at `corner`.
    pub(super) fn vertex_at(&self, corner: usize) -> u32 {
        self.faces.indices[corner]
    }

    /// The limit point at `v` when it is regular: the corner of every patch
    /// there.
    pub(super) fn regular_corner(&self, v: u32) -> Option<DVec3> {
        self.rings[v as usize].map(|_| self.limits[v as usize])
    }

    /// The limit curve of the edge leaving `corner` (of face `face`), as
    /// Bézier points in the face's direction, when both its ends are
    /// regular.
    pub(super) fn edge_curve(&self, face: usize, corner: usize) -> Option<[DVec3; 4]> {
        let a = self.faces.indices[corner];
        let b = self.faces.indices[self.faces.next(corner, face)];
        let edge = self.connectivity.corner_edges[corner];
        let (qa, qb) = (self.across(a, edge)?, self.across(b, edge)?);
        // From the other face the edge runs from b: its inner points are
        // these reversed, as `x + y` is `y + x`.
        Some([
            self.limits[a as usize],
            (2.0 * qa + qb) / 3.0,
            (qa + 2.0 * qb) / 3.0,
            self.limits[b as usize],
        ])
    }

    /// At regular vertex `v` of `edge`, the point of the cubic B-spline
    /// along the edge: `v` averaged with its neighbours across the edge
    /// (the far ends of the edges beside it around `v`), 4 : 1 : 1.
    fn across(&self, v: u32, edge: u32) -> Option<DVec3> {
        let ring = self.rings[v as usize]?;
        let i = ring.iter().position(|&e| e == edge)?;
        let far = |e: u32| {
            let [a, b] = self.connectivity.edges[e as usize];
            self.points[if a == v { b } else { a } as usize]
        };
        let (x, y) = (far(ring[(i + 1) % 4]), far(ring[(i + 3) % 4]));
        Some((4.0 * self.points[v as usize] + (x + y)) / 6.0)
    }

    /// The Bézier points of face `face`'s patch when its four corners are
    /// regular: there the limit surface is exactly this bicubic.
    pub(super) fn regular_patch(&self, face: usize) -> Option<[[DVec3; 4]; 4]> {
        let corners = self.faces.corners(face);
        if corners.len() != 4 {
            return None;
        }
        let start = corners.start;
        let edges: [[DVec3; 4]; 4] = [
            self.edge_curve(face, start)?,
            self.edge_curve(face, start + 1)?,
            self.edge_curve(face, start + 2)?,
            self.edge_curve(face, start + 3)?,
        ];
        let mut control = super::with_edges(&edges);
        // The inner points weigh the face's corners by the bilinear
        // weights at ⅓ and ⅔: `p[a][b]` is the corner at u = a, v = b.
        let point = |k: usize| self.points[self.faces.indices[start + k] as usize];
        let p = [[point(0), point(3)], [point(1), point(2)]];
        const THIRDS: [[f64; 2]; 2] = [[2.0 / 3.0, 1.0 / 3.0], [1.0 / 3.0, 2.0 / 3.0]];
        for (i, wu) in THIRDS.iter().enumerate() {
            for (j, wv) in THIRDS.iter().enumerate() {
                control[i + 1][j + 1] = (wu[0] * wv[0]) * p[0][0]
                    + (wu[0] * wv[1]) * p[0][1]
                    + (wu[1] * wv[0]) * p[1][0]
                    + (wu[1] * wv[1]) * p[1][1];
            }
        }
        Some(control)
    }
}

#[cfg(test)]
mod tests {
    use super::super::tests::jittered;
    use super::*;
    use crate::mesh::shapes;
    use crate::subdivide::{Creasing, NakedEdges, Scheme, SubdivisionOptions};

    #[test]
    fn edge_curves_between_regular_vertices_lie_on_the_limit() {
        // A 6 × 6 grid with a hard crease along one row, a semi-sharp one
        // (Chaikin) along a column and a semi-sharp corner: edges beside
        // them, between regular vertices, are curves of the limit too.
        let id = |i: u32, j: u32| j * 7 + i;
        let mut creases: Vec<([u32; 2], f64)> = (1..5)
            .map(|i| ([id(i, 3), id(i + 1, 3)], f64::INFINITY))
            .collect();
        creases.extend((1..5).map(|j| ([id(2, j), id(2, j + 1)], 1.5)));
        let creased = SubdivisionOptions {
            creases,
            corners: vec![(id(4, 4), 2.0)],
            creasing: Creasing::Chaikin,
            ..SubdivisionOptions::new(NakedEdges::Fixed)
        };
        let smooth = SubdivisionOptions::new(NakedEdges::Smooth);
        let cases = [
            (jittered(&shapes::quad_grid(6, 6), 21), creased, 1),
            (jittered(&shapes::cube(), 22), smooth.clone(), 2),
            (shapes::mixed_polygons(), smooth, 2),
        ];
        for (k, (cage, options, isolation)) in cases.iter().enumerate() {
            let refined = Subdivider::new(cage, Scheme::CatmullClark, *isolation, options).unwrap();
            let isolated = Isolated::new(&refined, cage.positions()).unwrap();
            let fine = Subdivider::new(cage, Scheme::CatmullClark, isolation + 3, options).unwrap();
            let limit = fine.limit().unwrap().positions;
            let (low, high) = cage.bounding_box().unwrap();
            let size = (high - low).length();
            let faces = &refined.last().faces;
            let (mut curves, mut regular, mut irregular) = (0, 0, 0);
            for f in 0..faces.face_count() {
                for c in faces.corners(f) {
                    let Some([a, b, c, d]) = isolated.edge_curve(f, c) else {
                        irregular += 1;
                        continue;
                    };
                    for t in 0..=8 {
                        let t = t as f64 / 8.0;
                        let s = 1.0 - t;
                        let p = s * s * s * a
                            + 3.0 * s * s * t * b
                            + 3.0 * s * t * t * c
                            + t * t * t * d;
                        let nearest = limit
                            .iter()
                            .map(|q| (*q - p).length())
                            .fold(f64::INFINITY, f64::min);
                        assert!(nearest < 1e-12 * size, "case {k}, face {f}: {nearest}");
                    }
                    curves += 1;
                }
                regular += usize::from(isolated.regular_patch(f).is_some());
            }
            assert!(curves > 0 && irregular > 0 && regular > 0, "case {k}");
        }
    }
}
