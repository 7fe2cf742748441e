//! The Catmull-Clark limit surface as bicubic Bézier patches, for NURBS
//! export: one patch per face of the cage refined `isolation` levels.
//!
//! Each patch is fitted to exact limit points (the limit masks of
//! [`super::Limit`] at the vertices of deeper levels, which sit on the
//! surface at the dyadic parameters of the face):
//! - its corners are the limit points of the face's corners;
//! - each edge's two inner control points fit the limit points at ¼, ½, ¾
//!   of the edge (least squares), computed once per edge, so two patches
//!   meeting at an edge share its curve exactly and the patches are
//!   watertight everywhere, across creases and boundaries included;
//! - the four inner control points fit the nine inner limit points of the
//!   face's ¼ grid.
//!
//! Where the limit surface is a bicubic B-spline patch (a face whose
//! neighbourhood is regular: away from extraordinary vertices, crease ends
//! and corners; along smooth boundaries and infinitely sharp creases too)
//! the samples lie on that cubic and the fit reproduces it to rounding:
//! the patch is exact. Faces touching an irregular point are
//! approximations; each patch's error is its largest distance from the
//! limit points of the ⅛ grid (81 points, most not used by the fit), and it
//! falls as `isolation` rises, since those faces shrink.

use glam::DVec3;
use rayon::prelude::*;
use std::collections::HashMap;

use super::creases::SubdivisionOptions;
use super::scheme::Scheme;
use super::subdivider::Subdivider;
use crate::error::{Error, Result};
use crate::mesh::Mesh;

/// The most isolation levels: the fit reads the limit three levels deeper.
pub const MAX_ISOLATION: u32 = 8;

/// A bicubic Bézier patch: `control[i][j]` is the control point i along u
/// and j along v; u runs from the face's first corner towards its second,
/// v towards its last, so `du × dv` points out of a counter-clockwise face.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BezierPatch {
    /// The cage face the patch lies on.
    pub cage_face: u32,
    /// Control points, `[u][v]`.
    pub control: [[DVec3; 4]; 4],
    /// The patch's largest distance from the limit points of its ⅛ grid.
    pub error: f64,
}

impl BezierPatch {
    /// The point at `(u, v)` in `[0, 1]²` (de Casteljau's weights).
    pub fn point(&self, u: f64, v: f64) -> DVec3 {
        let (bu, bv) = (bernstein(u), bernstein(v));
        let mut p = DVec3::ZERO;
        for (row, &wu) in self.control.iter().zip(&bu) {
            for (&c, &wv) in row.iter().zip(&bv) {
                p += wu * wv * c;
            }
        }
        p
    }

    /// The control points along the patch's edge `k` (0: v = 0, 1: u = 1,
    /// 2: v = 1, 3: u = 0), in the direction the face's corners run.
    pub fn edge(&self, k: usize) -> [DVec3; 4] {
        let c = &self.control;
        match k {
            0 => [c[0][0], c[1][0], c[2][0], c[3][0]],
            1 => [c[3][0], c[3][1], c[3][2], c[3][3]],
            2 => [c[3][3], c[2][3], c[1][3], c[0][3]],
            _ => [c[0][3], c[0][2], c[0][1], c[0][0]],
        }
    }
}

/// The patches of a cage's limit surface and what the fit measured.
#[derive(Debug, Clone, PartialEq)]
pub struct LimitPatches {
    /// One patch per face of the refined cage, in the refined faces' order
    /// (the children of each cage face together).
    pub patches: Vec<BezierPatch>,
    /// The isolation levels the cage was refined.
    pub isolation: u32,
    /// The largest error of any patch.
    pub max_error: f64,
    /// How many patches are exact: an error within 1e-12 of the cage's size.
    pub exact_count: usize,
    /// The size the exactness is measured against: the cage's bounding-box
    /// diagonal.
    pub size: f64,
}

/// The limit surface of `cage` (Catmull-Clark, with `options`) as one
/// bicubic Bézier patch per face of the cage refined `isolation` levels.
///
/// # Errors
/// [`Error::InvalidArgument`] for an isolation outside `1..=MAX_ISOLATION`
/// or options naming another scheme's rule; what [`Subdivider::new`]
/// refuses (bad creases, holes, a result past the size cap, which the fit's
/// three deeper levels count towards).
pub fn limit_patches(
    cage: &Mesh,
    options: &SubdivisionOptions,
    isolation: u32,
) -> Result<LimitPatches> {
    if !(1..=MAX_ISOLATION).contains(&isolation) {
        return Err(Error::InvalidArgument(format!(
            "isolation is {isolation}; it must be 1 to {MAX_ISOLATION} (every face becomes a quad after one level)"
        )));
    }
    // Squared distances of coordinates far from 1 over- or underflow: such a
    // cage is fitted at an exact power-of-two scale and the result scaled back.
    let largest = cage
        .positions()
        .iter()
        .map(|p| p.abs().max_element())
        .fold(0.0, f64::max);
    if largest > 0.0 && !(1e-100..=1e100).contains(&largest) {
        let k = largest.log2().round().clamp(-1000.0, 1000.0) as i32;
        let (down, up) = (2f64.powi(-k), 2f64.powi(k));
        let scaled = cage
            .with_positions(cage.positions().iter().map(|&p| p * down).collect())
            .map_err(Error::from)?;
        let mut patches = limit_patches(&scaled, options, isolation)?;
        for patch in &mut patches.patches {
            patch.control = patch.control.map(|row| row.map(|p| p * up));
            patch.error *= up;
        }
        patches.max_error *= up;
        patches.size *= up;
        return Ok(patches);
    }
    let fine = Subdivider::new(cage, Scheme::CatmullClark, isolation + 3, options)?;
    let limit = fine.limit()?.positions;
    let size = cage
        .bounding_box()
        .map_or(0.0, |(low, high)| (high - low).length());

    // Every refined level is quads; the children of face f of level
    // `isolation` are the 64 faces from 64 f three levels down, and share
    // its cage face.
    let fine_faces = fine.face_indices();
    let face_count = fine.face_count() / 64;
    let parents: Vec<u32> = fine.parent_faces().into_iter().step_by(64).collect();
    let grids: Vec<Grid> = (0..face_count)
        .into_par_iter()
        .map(|f| Grid::of(&fine_faces[256 * f..256 * (f + 1)]))
        .collect();

    // Each edge's curve once, in the direction of its lower corner, keyed by
    // its ends and its midpoint (pairs repeat where a face repeats a vertex).
    let mut curves: HashMap<[u32; 3], [DVec3; 4]> = HashMap::new();
    for grid in &grids {
        for k in 0..4 {
            let ids = grid.edge(k);
            let forward = ids[0] < ids[8];
            let key = edge_key(&ids);
            curves.entry(key).or_insert_with(|| {
                let mut along = ids;
                if !forward {
                    along.reverse();
                }
                fit_curve(&along.map(|v| limit[v as usize]))
            });
        }
    }

    let patches: Vec<BezierPatch> = grids
        .par_iter()
        .zip(parents.par_iter())
        .map(|(grid, &cage_face)| {
            let edges: [[DVec3; 4]; 4] = std::array::from_fn(|k| {
                let ids = grid.edge(k);
                let mut curve = curves[&edge_key(&ids)];
                if ids[0] > ids[8] {
                    curve.reverse();
                }
                curve
            });
            let control = fit_patch(&edges, |a, b| limit[grid.at(2 * a, 2 * b) as usize]);
            let mut patch = BezierPatch {
                cage_face,
                control,
                error: 0.0,
            };
            for a in 0..=8 {
                for b in 0..=8 {
                    let exact = limit[grid.at(a, b) as usize];
                    let distance = (patch.point(a as f64 / 8.0, b as f64 / 8.0) - exact).length();
                    patch.error = patch.error.max(distance);
                }
            }
            patch
        })
        .collect();
    let max_error = patches.iter().map(|p| p.error).fold(0.0, f64::max);
    let exact_count = patches.iter().filter(|p| p.error <= 1e-12 * size).count();
    Ok(LimitPatches {
        patches,
        isolation,
        max_error,
        exact_count,
        size,
    })
}

fn edge_key(ids: &[u32; 9]) -> [u32; 3] {
    [ids[0].min(ids[8]), ids[0].max(ids[8]), ids[4]]
}

/// The vertices of a face's ⅛ grid three levels down: `at(a, b)` is the
/// vertex at `(a / 8, b / 8)` of the face's parameters.
struct Grid([u32; 81]);

impl Grid {
    /// From the face's 64 descendants (their 256 corners, in order).
    fn of(corners: &[u32]) -> Grid {
        let mut ids = [u32::MAX; 81];
        for (d, quad) in corners.chunks_exact(4).enumerate() {
            // Child k of a quad sits at its corner k: its corner 0 there,
            // its corner 1 towards corner k + 1, its corner 3 towards k - 1.
            let path = [d / 16, d / 4 % 4, d % 4];
            for (j, &v) in quad.iter().enumerate() {
                let (mut origin, mut axes) = ([0i32, 0], [[8i32, 0], [0, 8]]);
                for &k in &path {
                    let (du, dv) = (axes[0], axes[1]);
                    let corner = |k: usize| match k % 4 {
                        0 => [0, 0],
                        1 => du,
                        2 => [du[0] + dv[0], du[1] + dv[1]],
                        _ => dv,
                    };
                    let (here, next, previous) = (corner(k), corner(k + 1), corner(k + 3));
                    origin = [origin[0] + here[0], origin[1] + here[1]];
                    axes = [
                        [(next[0] - here[0]) / 2, (next[1] - here[1]) / 2],
                        [(previous[0] - here[0]) / 2, (previous[1] - here[1]) / 2],
                    ];
                }
                let corner = match j {
                    0 => [0, 0],
                    1 => axes[0],
                    2 => [axes[0][0] + axes[1][0], axes[0][1] + axes[1][1]],
                    _ => axes[1],
                };
                let (a, b) = (origin[0] + corner[0], origin[1] + corner[1]);
                ids[(9 * a + b) as usize] = v;
            }
        }
        Grid(ids)
    }

    fn at(&self, a: usize, b: usize) -> u32 {
        self.0[9 * a + b]
    }

    /// The nine grid vertices along edge `k` (as [`BezierPatch::edge`]).
    fn edge(&self, k: usize) -> [u32; 9] {
        std::array::from_fn(|t| match k {
            0 => self.at(t, 0),
            1 => self.at(8, t),
            2 => self.at(8 - t, 8),
            _ => self.at(0, 8 - t),
        })
    }
}

/// The cubic Bernstein weights at `t`.
fn bernstein(t: f64) -> [f64; 4] {
    let s = 1.0 - t;
    [s * s * s, 3.0 * t * s * s, 3.0 * t * t * s, t * t * t]
}

/// A cubic Bézier curve through `samples[0]` and `samples[8]` whose inner
/// control points fit the samples at ¼, ½ and ¾ (least squares).
fn fit_curve(samples: &[DVec3; 9]) -> [DVec3; 4] {
    let (p0, p3) = (samples[0], samples[8]);
    // Normal equations of the two inner control points over t = ¼, ½, ¾.
    let (mut m, mut r) = ([[0.0; 2]; 2], [DVec3::ZERO; 2]);
    for k in [2, 4, 6] {
        let b = bernstein(k as f64 / 8.0);
        let rest = samples[k] - b[0] * p0 - b[3] * p3;
        for i in 0..2 {
            for j in 0..2 {
                m[i][j] += b[i + 1] * b[j + 1];
            }
            r[i] += b[i + 1] * rest;
        }
    }
    let det = m[0][0] * m[1][1] - m[0][1] * m[1][0];
    let p1 = (m[1][1] * r[0] - m[0][1] * r[1]) / det;
    let p2 = (m[0][0] * r[1] - m[1][0] * r[0]) / det;
    [p0, p1, p2, p3]
}

/// A bicubic patch with the four boundary curves `edges` (as
/// [`BezierPatch::edge`] lists them) whose four inner control points fit
/// `sample(a, b)`, the limit points at `(a / 4, b / 4)` for a, b in 1..=3.
fn fit_patch(edges: &[[DVec3; 4]; 4], sample: impl Fn(usize, usize) -> DVec3) -> [[DVec3; 4]; 4] {
    let mut c = [[DVec3::ZERO; 4]; 4];
    for t in 0..4 {
        c[t][0] = edges[0][t];
        c[3][t] = edges[1][t];
        c[3 - t][3] = edges[2][t];
        c[0][3 - t] = edges[3][t];
    }
    // Unknowns c[1][1], c[2][1], c[1][2], c[2][2]; normal equations over the
    // nine inner samples.
    const INNER: [(usize, usize); 4] = [(1, 1), (2, 1), (1, 2), (2, 2)];
    let (mut m, mut r) = ([[0.0; 4]; 4], [DVec3::ZERO; 4]);
    for a in 1..=3 {
        for b in 1..=3 {
            let (bu, bv) = (bernstein(a as f64 / 4.0), bernstein(b as f64 / 4.0));
            let mut rest = sample(a, b);
            for i in 0..4 {
                for j in 0..4 {
                    if !INNER.contains(&(i, j)) {
                        rest -= bu[i] * bv[j] * c[i][j];
                    }
                }
            }
            let w = INNER.map(|(i, j)| bu[i] * bv[j]);
            for x in 0..4 {
                for y in 0..4 {
                    m[x][y] += w[x] * w[y];
                }
                r[x] += w[x] * rest;
            }
        }
    }
    let solved = solve4(m, r);
    for (x, &(i, j)) in INNER.iter().enumerate() {
        c[i][j] = solved[x];
    }
    c
}

/// Solves the symmetric positive definite 4 × 4 system `m x = r`
/// (Gaussian elimination; the matrix is the same well-conditioned one for
/// every patch).
fn solve4(mut m: [[f64; 4]; 4], mut r: [DVec3; 4]) -> [DVec3; 4] {
    for k in 0..4 {
        let pivot = m[k];
        for i in k + 1..4 {
            let f = m[i][k] / pivot[k];
            for (x, &p) in m[i][k..].iter_mut().zip(&pivot[k..]) {
                *x -= f * p;
            }
            r[i] -= f * r[k];
        }
    }
    let mut x = [DVec3::ZERO; 4];
    for k in (0..4).rev() {
        let mut sum = r[k];
        for j in k + 1..4 {
            sum -= m[k][j] * x[j];
        }
        x[k] = sum / m[k][k];
    }
    x
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_fits_reproduce_a_cubic_exactly() {
        let cubic = |t: f64| DVec3::new(t, t * t * t - 2.0 * t, 0.5 * t * t);
        let samples: [DVec3; 9] = std::array::from_fn(|k| cubic(k as f64 / 8.0));
        let curve = fit_curve(&samples);
        for k in 0..=8 {
            let t = k as f64 / 8.0;
            let b = bernstein(t);
            let p = b[0] * curve[0] + b[1] * curve[1] + b[2] * curve[2] + b[3] * curve[3];
            assert!((p - cubic(t)).length() < 1e-14, "t = {t}");
        }
    }

    #[test]
    fn the_grid_is_the_faces_descendants_in_place() {
        // On a bumped grid with a pentagon: every grid point is a vertex,
        // neighbours along u and v share an edge, the corners are the face's.
        let cage = crate::mesh::shapes::mixed_polygons();
        let options = SubdivisionOptions::new(super::super::NakedEdges::Smooth);
        let coarse = Subdivider::new(&cage, Scheme::CatmullClark, 1, &options).unwrap();
        let fine = Subdivider::new(&cage, Scheme::CatmullClark, 4, &options).unwrap();
        let fine_mesh = fine.mesh().unwrap();
        let topology = crate::Topology::new(&fine_mesh);
        for f in 0..coarse.face_count() {
            let quad = &coarse.face_indices()[4 * f..4 * f + 4];
            let grid = Grid::of(&fine.face_indices()[256 * f..256 * (f + 1)]);
            assert_eq!(
                [grid.at(0, 0), grid.at(8, 0), grid.at(8, 8), grid.at(0, 8)],
                [quad[0], quad[1], quad[2], quad[3]],
                "face {f}"
            );
            for a in 0..=8 {
                for b in 0..=8 {
                    if a < 8 {
                        assert!(topology
                            .find_edge(grid.at(a, b), grid.at(a + 1, b))
                            .is_some());
                    }
                    if b < 8 {
                        assert!(topology
                            .find_edge(grid.at(a, b), grid.at(a, b + 1))
                            .is_some());
                    }
                }
            }
        }
    }
}
