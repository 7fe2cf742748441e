//! The nearest point of the limit surface to a query point: candidate faces
//! from a uniform grid of their bounding boxes, visited nearest first, each
//! projected by damped Gauss-Newton from the nearest of a few samples of the
//! surface on it, until no unvisited face can be nearer.
//!
//! A face's limit surface lies in the convex hull of the cage points around
//! it (subdivision weights are not negative, except at Catmull-Clark
//! vertices of two faces, for which the boxes are padded by a quarter).

use glam::DVec3;
use rayon::prelude::*;

use super::{tile_width, LimitSurface, Scratch, CHUNK};
use crate::error::{Error, Result};

/// Samples per side of a face's (or sub-face's) starting grid.
const STARTS: usize = 5;

/// Gauss-Newton iterations at most per start.
const ITERATIONS: usize = 50;

/// A starting sample: its (u, v) and its point.
type Start = ([f64; 2], DVec3);

/// The starting samples and the boxes of every face, and the grid over them.
#[derive(Debug, Clone)]
pub(super) struct Index {
    /// Per face, its samples `starts[offsets[f]..offsets[f + 1]]`: (u, v), point.
    offsets: Vec<u32>,
    starts: Vec<Start>,
    boxes: Vec<[DVec3; 2]>,
    origin: DVec3,
    cell: f64,
    /// A power of two near 1 / the cage's size: distances are squared in
    /// these units, so that they neither overflow for a cage near the top
    /// of the double range nor underflow for a tiny one (exactly: scaling
    /// by a power of two changes no comparison).
    unit: f64,
    dims: [usize; 3],
    cells: Vec<u32>,
    cell_faces: Vec<u32>,
}

impl Index {
    /// `q`, or where it is far beyond the cage (more than 10^100 times the
    /// cage's size from it, where squared distances would overflow), the
    /// point at that distance in its direction: so far away, every point of
    /// the surface is equally near to the precision of a double.
    fn within_reach(&self, q: DVec3) -> DVec3 {
        let extent = DVec3::new(
            self.dims[0] as f64,
            self.dims[1] as f64,
            self.dims[2] as f64,
        ) * self.cell;
        let centre = self.origin + 0.5 * extent;
        let reach = 1e100 * extent.max_element().max(f64::MIN_POSITIVE);
        let offset = q - centre;
        let far = offset.abs().max_element();
        if far > reach && far.is_finite() {
            centre + offset * (reach / far)
        } else {
            q
        }
    }
}

/// The power of two nearest `x` (a positive number), within 2^±1000.
fn power_of_two_near(x: f64) -> f64 {
    let exponent = x.log2().round();
    let exponent = if exponent.is_finite() {
        exponent.clamp(-1000.0, 1000.0)
    } else {
        0.0
    };
    2f64.powi(exponent as i32)
}

/// The (u, v) domain Newton stays in: a whole quad or triangle, or one tile
/// of a face of sub-faces.
#[derive(Clone, Copy)]
enum Domain {
    Quad,
    Triangle,
    Tile(f64, f64),
}

/// How far inside its face's corners Newton stays: exactly at an
/// extraordinary corner the derivatives are the limit tangents, not the
/// parameterisation's, which would mislead the steps.
const CORNER_GAP: f64 = 1e-13;

impl Domain {
    /// [`Domain::clamp_edges`], then off the corners by [`CORNER_GAP`].
    fn clamp(self, uv: [f64; 2]) -> [f64; 2] {
        let [u, v] = self.clamp_edges(uv);
        let (x, y, size) = match self {
            Domain::Quad => (0.0, 0.0, 1.0),
            Domain::Tile(x, y) => (x, y, 0.5),
            Domain::Triangle => {
                return match (u, v) {
                    (0.0, 0.0) => [CORNER_GAP, CORNER_GAP],
                    (1.0, 0.0) => [1.0 - 2.0 * CORNER_GAP, CORNER_GAP],
                    (0.0, 1.0) => [CORNER_GAP, 1.0 - 2.0 * CORNER_GAP],
                    _ => [u, v],
                };
            }
        };
        let (s, t) = ((u - x) / size, (v - y) / size);
        let at_end = |a: f64| a == 0.0 || a == 1.0;
        if at_end(s) && at_end(t) {
            let inward = |a: f64| {
                if a == 0.0 {
                    CORNER_GAP
                } else {
                    1.0 - CORNER_GAP
                }
            };
            return [x + size * inward(s), y + size * inward(t)];
        }
        [u, v]
    }

    /// The direction along the edge `uv` lies on when `step` leads out of
    /// the domain across it, or `None` inside or at a corner.
    fn edge_direction(self, [u, v]: [f64; 2], step: [f64; 2]) -> Option<[f64; 2]> {
        let (lo_u, hi_u, lo_v, hi_v) = match self {
            Domain::Quad => (0.0, 1.0, 0.0, 1.0),
            Domain::Tile(x, y) => (x, x + 0.5, y, y + 0.5),
            Domain::Triangle => (0.0, f64::INFINITY, 0.0, f64::INFINITY),
        };
        let out_u = (u <= lo_u && step[0] < 0.0) || (u >= hi_u && step[0] > 0.0);
        let out_v = (v <= lo_v && step[1] < 0.0) || (v >= hi_v && step[1] > 0.0);
        let out_w = matches!(self, Domain::Triangle) && u + v >= 1.0 && step[0] + step[1] > 0.0;
        match (out_u, out_v, out_w) {
            (true, false, false) => Some([0.0, 1.0]),
            (false, true, false) => Some([1.0, 0.0]),
            (false, false, true) => Some([1.0, -1.0]),
            _ => None,
        }
    }

    fn edge_directions(self) -> Vec<[f64; 2]> {
        match self {
            Domain::Triangle => vec![[1.0, 0.0], [0.0, 1.0], [1.0, -1.0]],
            _ => vec![[1.0, 0.0], [0.0, 1.0]],
        }
    }

    fn corners(self) -> Vec<[f64; 2]> {
        match self {
            Domain::Quad => vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]],
            Domain::Triangle => vec![[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]],
            Domain::Tile(x, y) => vec![[x, y], [x + 0.5, y], [x + 0.5, y + 0.5], [x, y + 0.5]],
        }
    }

    fn clamp_edges(self, [u, v]: [f64; 2]) -> [f64; 2] {
        match self {
            Domain::Quad => [u.clamp(0.0, 1.0), v.clamp(0.0, 1.0)],
            Domain::Tile(x, y) => [u.clamp(x, x + 0.5), v.clamp(y, y + 0.5)],
            Domain::Triangle => {
                let (u, v) = (u.clamp(0.0, 1.0), v.clamp(0.0, 1.0));
                let excess = u + v - 1.0;
                if excess <= 0.0 {
                    return [u, v];
                }
                // The nearest point of the edge u + v = 1, in (u, v).
                let (u, v) = (u - 0.5 * excess, v - 0.5 * excess);
                if u < 0.0 {
                    [0.0, 1.0]
                } else if v < 0.0 {
                    [1.0, 0.0]
                } else {
                    [u, v.min(1.0 - u)]
                }
            }
        }
    }
}

impl LimitSurface {
    fn face_domain(&self, f: usize, [u, v]: [f64; 2]) -> Domain {
        match (self.scheme, self.face_sizes[f]) {
            (super::Scheme::Loop, _) => Domain::Triangle,
            (_, 4) => Domain::Quad,
            (_, n) => {
                let w = tile_width(n as usize) as f64;
                let x = (u + 0.25).floor().clamp(0.0, w - 1.0);
                Domain::Tile(x, (v + 0.25).floor().max(0.0))
            }
        }
    }

    /// The samples Newton starts from, in each face's domain.
    fn face_starts(&self, f: usize) -> Vec<[f64; 2]> {
        let step = |i: usize| i as f64 / (STARTS - 1) as f64;
        let mut out = Vec::new();
        match (self.scheme, self.face_sizes[f] as usize) {
            (super::Scheme::Loop, _) => {
                for i in 0..STARTS {
                    for j in 0..STARTS - i {
                        out.push([step(i), step(j)]);
                    }
                }
            }
            (_, 4) => {
                for i in 0..STARTS {
                    for j in 0..STARTS {
                        out.push([step(i), step(j)]);
                    }
                }
            }
            (_, n) => {
                let w = tile_width(n);
                for tile in 0..n {
                    let (x, y) = ((tile % w) as f64, (tile / w) as f64);
                    for i in 0..STARTS {
                        for j in 0..STARTS {
                            out.push([x + 0.5 * step(i), y + 0.5 * step(j)]);
                        }
                    }
                }
            }
        }
        out
    }

    /// Builds the index (once, on the first projection).
    pub(super) fn build_index(&self) -> Result<Index> {
        let face_count = self.face_count();
        let per_face: Vec<(Vec<Start>, [DVec3; 2])> = (0..face_count)
            .into_par_iter()
            .map(|f| {
                let mut scratch = self.scratch();
                let visible = !self.holes.as_ref().is_some_and(|h| h[f]);
                let starts = match visible {
                    true => self
                        .face_starts(f)
                        .into_iter()
                        .map(|uv| (uv, self.point(f, uv, &mut scratch)[0]))
                        .collect(),
                    false => Vec::new(),
                };
                let graph = &self.faces[f];
                let (mut lo, mut hi) = (DVec3::splat(f64::MAX), DVec3::splat(f64::MIN));
                for &c in &graph.vertices {
                    let p = self.cage_positions[c as usize];
                    (lo, hi) = (lo.min(p), hi.max(p));
                }
                let pad = (hi - lo) * 0.25;
                (starts, [lo - pad, hi + pad])
            })
            .collect();
        let mut offsets = vec![0u32];
        let mut starts = Vec::new();
        let mut boxes = Vec::with_capacity(face_count);
        for (s, b) in per_face {
            starts.extend(s);
            offsets.push(starts.len() as u32);
            boxes.push(b);
        }
        let (mut lo, mut hi) = (DVec3::splat(f64::MAX), DVec3::splat(f64::MIN));
        let mut mean = 0.0;
        for b in &boxes {
            (lo, hi) = (lo.min(b[0]), hi.max(b[1]));
            mean += (b[1] - b[0]).max_element() / face_count.max(1) as f64;
        }
        if boxes.is_empty() {
            (lo, hi) = (DVec3::ZERO, DVec3::ZERO);
        }
        // About one face per cell, at most 2^21 cells.
        let extent = (hi - lo).max(DVec3::splat(f64::MIN_POSITIVE));
        let unit = power_of_two_near(1.0 / extent.max_element());
        let scaled = extent * unit;
        let volume_cell = (scaled.x * scaled.y * scaled.z / (1 << 21) as f64).cbrt() / unit;
        let cell = mean
            .max(volume_cell)
            .max(extent.max_element() / 128.0)
            .max(f64::MIN_POSITIVE);
        let dims = ((extent / cell).floor().as_uvec3() + 1)
            .to_array()
            .map(|d| d as usize);
        let cell_of = |p: DVec3| {
            let c = ((p - lo) / cell).floor();
            [0, 1, 2].map(|k| (c[k].max(0.0) as usize).min(dims[k] - 1))
        };
        let index = |c: [usize; 3]| (c[2] * dims[1] + c[1]) * dims[0] + c[0];
        let mut counts = vec![0u32; dims[0] * dims[1] * dims[2] + 1];
        let each = |f: usize, visit: &mut dyn FnMut(usize)| {
            let (a, b) = (cell_of(boxes[f][0]), cell_of(boxes[f][1]));
            for z in a[2]..=b[2] {
                for y in a[1]..=b[1] {
                    for x in a[0]..=b[0] {
                        visit(index([x, y, z]));
                    }
                }
            }
        };
        for f in 0..face_count {
            each(f, &mut |c| counts[c + 1] += 1);
        }
        for c in 1..counts.len() {
            counts[c] += counts[c - 1];
        }
        let total = *counts.last().unwrap_or(&0) as usize;
        if total as u64 > crate::error::MAX_ELEMENTS {
            return Err(Error::ResultTooLarge(format!(
                "the closest-point grid would hold {total} entries"
            )));
        }
        let mut cell_faces = vec![0u32; total];
        let mut fill = counts.clone();
        for f in 0..face_count {
            each(f, &mut |c| {
                cell_faces[fill[c] as usize] = f as u32;
                fill[c] += 1;
            });
        }
        Ok(Index {
            offsets,
            starts,
            boxes,
            origin: lo,
            cell,
            unit,
            dims,
            cells: counts,
            cell_faces,
        })
    }

    /// The nearest point of the surface to each of `points`: its face, its
    /// (u, v) and its position (the surface evaluated there).
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] for a query that is not finite or buffers
    /// of other lengths (nothing written); [`Error::ResultTooLarge`] for a
    /// cage too large to index.
    pub fn closest_points(
        &self,
        points: &[DVec3],
        faces: &mut [u32],
        uvs: &mut [f64],
        positions: &mut [DVec3],
    ) -> Result<()> {
        let n = points.len();
        if faces.len() != n || uvs.len() != 2 * n || positions.len() != n {
            return Err(Error::InvalidArgument(format!(
                "{n} query points need room for {n} faces, {} parameters and {n} positions",
                2 * n
            )));
        }
        if let Some(i) = points.iter().position(|p| !p.is_finite()) {
            return Err(Error::InvalidArgument(format!(
                "query point {i} has a non-finite coordinate"
            )));
        }
        if self
            .holes
            .as_ref()
            .is_some_and(|h| h.iter().all(|&hole| hole))
        {
            return Err(Error::InvalidArgument(
                "the surface has no face to project onto (every face is a hole)".into(),
            ));
        }
        let index = match self.index.get() {
            Some(index) => index,
            None => {
                let built = self.build_index()?;
                self.index.get_or_init(|| built)
            }
        };
        faces
            .par_chunks_mut(CHUNK)
            .zip(uvs.par_chunks_mut(2 * CHUNK))
            .zip(positions.par_chunks_mut(CHUNK))
            .enumerate()
            .for_each(|(chunk, ((faces, uvs), positions))| {
                let mut scratch = self.scratch();
                let mut seen = vec![u32::MAX; self.face_count()];
                for k in 0..faces.len() {
                    let i = chunk * CHUNK + k;
                    let q = index.within_reach(points[i]);
                    let (f, uv, p) = self.nearest(index, q, i as u32, &mut seen, &mut scratch);
                    faces[k] = f;
                    uvs[2 * k..2 * k + 2].copy_from_slice(&uv);
                    positions[k] = p;
                }
            });
        Ok(())
    }

    /// The nearest point to `q`: faces in grid shells around q, each
    /// projected unless its box is farther than the best so far.
    fn nearest(
        &self,
        index: &Index,
        q: DVec3,
        stamp: u32,
        seen: &mut [u32],
        scratch: &mut Scratch,
    ) -> (u32, [f64; 2], DVec3) {
        let mut best = (f64::INFINITY, 0u32, [0.0; 2], DVec3::NAN);
        let c = ((q - index.origin) / index.cell).floor();
        let centre = [c.x, c.y, c.z].map(|x| x.clamp(-1e9, 1e9) as i64);
        let dims = index.dims.map(|d| d as i64);
        // The farthest shell that still meets the grid.
        let reach = (0..3)
            .map(|k| (centre[k]).abs().max((dims[k] - 1 - centre[k]).abs()))
            .max()
            .unwrap_or(0);
        // The nearest shell that meets the grid (q may lie outside it).
        let start = (0..3)
            .map(|k| (-centre[k]).max(centre[k] - (dims[k] - 1)).max(0))
            .max()
            .unwrap_or(0);
        for r in start..=reach {
            // Every point of shell r is at least (r - 1) cells from q.
            if r >= 1 && ((r - 1) as f64 * index.cell * index.unit).powi(2) > best.0 {
                break;
            }
            let range = |k: usize| (centre[k] - r).max(0)..=(centre[k] + r).min(dims[k] - 1);
            for z in range(2) {
                for y in range(1) {
                    for x in range(0) {
                        let on_shell = (x - centre[0]).abs() == r
                            || (y - centre[1]).abs() == r
                            || (z - centre[2]).abs() == r;
                        if !on_shell {
                            continue;
                        }
                        let cell = ((z * dims[1] + y) * dims[0] + x) as usize;
                        let list = index.cells[cell] as usize..index.cells[cell + 1] as usize;
                        for &f in &index.cell_faces[list] {
                            if seen[f as usize] == stamp {
                                continue;
                            }
                            seen[f as usize] = stamp;
                            let [lo, hi] = index.boxes[f as usize];
                            if ((q.clamp(lo, hi) - q) * index.unit).length_squared() > best.0 {
                                continue;
                            }
                            self.project_on(index, f as usize, q, &mut best, scratch);
                        }
                    }
                }
            }
        }
        (best.1, best.2, best.3)
    }

    /// Projects `q` on face `f` from its nearest samples (one per tile),
    /// keeping the result in `best` when nearer.
    fn project_on(
        &self,
        index: &Index,
        f: usize,
        q: DVec3,
        best: &mut (f64, u32, [f64; 2], DVec3),
        scratch: &mut Scratch,
    ) {
        let starts = &index.starts[index.offsets[f] as usize..index.offsets[f + 1] as usize];
        let per_domain = match (self.scheme, self.face_sizes[f]) {
            (super::Scheme::CatmullClark, n) if n != 4 => STARTS * STARTS,
            _ => starts.len(),
        };
        for domain_starts in starts.chunks(per_domain.max(1)) {
            // The two nearest samples: one alone may sit on a line of
            // symmetry that leads Newton to a saddle of the distance.
            let mut nearest = [(f64::INFINITY, [0.0; 2]); 2];
            let gap = |p: DVec3| ((p - q) * index.unit).length_squared();
            for &(uv, p) in domain_starts {
                let d = gap(p);
                if let Some(k) = nearest.iter().position(|&(e, _)| d < e) {
                    nearest[k..].rotate_right(1);
                    nearest[k] = (d, uv);
                }
            }
            let Some(&(_, first)) = nearest.first().filter(|n| n.0.is_finite()) else {
                continue;
            };
            let domain = self.face_domain(f, first);
            for &(d, uv) in &nearest {
                if !d.is_finite() {
                    continue;
                }
                let (uv, p) = self.newton(f, domain, uv, q, index.unit, scratch);
                let d = gap(p);
                if d < best.0 {
                    *best = (d, f as u32, uv, p);
                }
            }
            // The domain's corners, where Newton converges slowly near an
            // extraordinary vertex (the parameterisation is singular there).
            for corner in domain.corners() {
                let p = self.point(f, corner, scratch)[0];
                let d = gap(p);
                if d < best.0 {
                    *best = (d, f as u32, corner, p);
                }
            }
        }
    }

    /// Damped Gauss-Newton on `|P(u, v) − q|²` within `domain`, lengths
    /// measured in `unit`s (see [`Index::unit`]).
    fn newton(
        &self,
        f: usize,
        domain: Domain,
        start: [f64; 2],
        q: DVec3,
        unit: f64,
        scratch: &mut Scratch,
    ) -> ([f64; 2], DVec3) {
        let scaled = |[p, pu, pv]: [DVec3; 3]| [p, pu * unit, pv * unit];
        let gap = |p: DVec3| ((p - q) * unit).length_squared();
        let mut uv = domain.clamp(start);
        let [mut p, mut pu, mut pv] = scaled(self.point(f, uv, scratch));
        let mut d = gap(p);
        for _ in 0..ITERATIONS {
            let r = (p - q) * unit;
            let (a, b, c) = (pu.dot(pu), pu.dot(pv), pv.dot(pv));
            let (g0, g1) = (pu.dot(r), pv.dot(r));
            let damping = 1e-12 * (a + c);
            let det = (a + damping) * (c + damping) - b * b;
            let step = if det > 0.0 && det.is_finite() {
                [
                    -((c + damping) * g0 - b * g1) / det,
                    -((a + damping) * g1 - b * g0) / det,
                ]
            } else {
                break;
            };
            // On an edge of the domain with the step leading out: a step
            // along the edge instead (projected Newton); at a corner, or
            // when that fails, a step along each edge direction in turn.
            let ahead = [uv[0] + step[0], uv[1] + step[1]];
            let along = |e: [f64; 2]| {
                let pe = pu * e[0] + pv * e[1];
                let t = -pe.dot(r) / pe.length_squared().max(f64::MIN_POSITIVE);
                [t * e[0], t * e[1]]
            };
            if step[0].abs() + step[1].abs() < 1e-15 {
                break;
            }
            let mut steps = vec![step];
            if domain.clamp_edges(ahead) != ahead {
                if let Some(e) = domain.edge_direction(uv, step) {
                    steps[0] = along(e);
                }
                steps.extend(domain.edge_directions().into_iter().map(along));
            }
            let mut moved = false;
            let mut last = 0.0;
            'steps: for step in steps {
                let mut scale = 1.0;
                for _ in 0..30 {
                    let next = domain.clamp([uv[0] + scale * step[0], uv[1] + scale * step[1]]);
                    if next == uv {
                        break;
                    }
                    let [np, npu, npv] = scaled(self.point(f, next, scratch));
                    let nd = gap(np);
                    if nd < d {
                        (uv, p, pu, pv, d, moved) = (next, np, npu, npv, nd, true);
                        last = (step[0].abs() + step[1].abs()) * scale;
                        break 'steps;
                    }
                    scale *= 0.5;
                }
            }
            if !moved || last < 1e-15 {
                break;
            }
        }
        (uv, p)
    }

    /// The surface and its derivatives at `uv` on face `f` (in its domain).
    fn point(&self, f: usize, [u, v]: [f64; 2], scratch: &mut Scratch) -> [DVec3; 3] {
        let sub_face = self.domain(0, f as u32, u, v).ok().flatten();
        self.sample(f, u, v, sub_face, scratch)
    }
}
