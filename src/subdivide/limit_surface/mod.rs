//! The limit surface anywhere: positions and first derivatives at any
//! parameter of any cage face, exact.
//!
//! # Parameterisation
//! - A quad (Catmull-Clark): `(u, v)` in `[0, 1]²` from its first corner, u
//!   towards the second corner and v towards the last.
//! - A triangle (Loop): barycentric `(u, v)`, `u, v ≥ 0`, `u + v ≤ 1`:
//!   corner 0 at (0, 0), corner 1 at (1, 0), corner 2 at (0, 1).
//! - Any other face of n corners (Catmull-Clark triangles and n-gons), as
//!   OpenSubdiv's `Bfr::Parameterization` `QUAD_SUBFACES`: the face is the n
//!   quads of its first subdivision, quad i (at corner i) laid out as the
//!   tile `[x, x + ½] × [y, y + ½]` with `x = i mod w`, `y = ⌊i / w⌋` and
//!   `w = 2` for n < 5, 3 for n < 10, else `1 + ⌊√(n − 1)⌋`; inside the tile,
//!   u runs from corner i towards the midpoint of edge i and v towards the
//!   midpoint of the edge before it.
//!
//! # Method
//! Each cage face has a graph of local refinements (`local.rs`), built once:
//! a regular face is a bicubic B-spline (Catmull-Clark) or quartic box spline
//! (Loop) patch of its 16 or 12 control points (`patches.rs`, `basis.rs`;
//! boundary and infinitely sharp crease patches with phantom points); any
//! other face is refined one level with the subdivider's own rules, and each
//! child is again a patch or refined further (faces with alike
//! neighbourhoods share these refinements). Evaluation walks down to the
//! patch that holds the sample, applying each level's weights to a few dozen
//! points, and evaluates the patch: the result is the limit surface to
//! rounding. Consecutive samples of one face reuse what the walk made at
//! its root. Exactly at an extraordinary vertex or a crease end the limit
//! masks of [`super::Limit`] give the point and its tangents. A sample at a
//! corner, or within 2⁻⁶⁰ of the face size of an irregular point, is
//! followed 60 levels down and takes the limit of the nearest corner there,
//! with that tiny face's edges as derivatives (an error far below rounding
//! in the position, about 2⁻⁶⁰ relative in the derivatives).
//!
//! # Closest points
//! [`LimitSurface::closest_points`] (`closest.rs`) projects points onto the
//! surface: candidate faces from a grid of their bounding boxes, nearest
//! first, each by projected Gauss-Newton from its nearest surface samples.
//!
//! # Derivatives
//! `du` and `dv` are the derivatives of the position by the face's u and v.
//! At an extraordinary vertex or a crease end the parameterisation has no
//! derivative; there `du` and `dv` are the limit tangents that
//! [`super::Limit`] gives (scaled to the refinement level), so that
//! `du × dv` is the limit normal. At a corner (an infinitely sharp vertex,
//! where the surface has a kink) they are the one-sided derivatives of the
//! face evaluated, so each face gives its own normal there.

mod basis;
mod closest;
mod local;
mod patches;

use glam::DVec3;
use rayon::prelude::*;

use super::creases::SubdivisionOptions;
use super::holes::mesh_holes;
use super::scheme::Scheme;
use super::subdivider::Subdivider;
use crate::buffers::try_vec;
use crate::error::{Error, Result};
use crate::mesh::Mesh;
use local::{FaceGraph, Kind};

/// Levels followed at most below a cage face before a sample takes the
/// values of the nearest irregular point.
const MAX_DEPTH: usize = 60;

/// Samples per parallel task.
const CHUNK: usize = 256;

/// The limit surface of a cage, ready to evaluate anywhere: build it once
/// with [`LimitSurface::new`], evaluate with [`LimitSurface::evaluate`].
#[derive(Debug, Clone)]
pub struct LimitSurface {
    scheme: Scheme,
    cage_positions: Vec<DVec3>,
    face_sizes: Vec<u32>,
    holes: Option<Vec<bool>>,
    faces: Vec<FaceGraph>,
    largest: usize,
    /// Built on the first projection.
    index: std::sync::OnceLock<closest::Index>,
}

/// Two buffers of local points for one evaluation at a time.
/// A task's working points: the points of the node a walk is at and of
/// the child it goes to, and what the last sample's face's root gave (the
/// points of its children, or its patch's control points), which the next
/// samples of that face reuse (as samples face by face and the closest
/// points' steps come).
#[derive(Default)]
struct Scratch {
    here: Vec<DVec3>,
    next: Vec<DVec3>,
    face: usize,
    first_children: Vec<FirstChild>,
    /// The control points of the face's root, when it is a patch.
    root_control: Option<Control>,
}

/// A patch's control points, relative to its walk's origin (Loop's first 12).
type Control = [DVec3; 16];

/// The points of a child of the face's root node, relative to `origin`,
/// when made.
#[derive(Default)]
struct FirstChild {
    made: bool,
    origin: DVec3,
    points: Vec<DVec3>,
}

/// One evaluated sample: position, d/du, d/dv.
type Sample = [DVec3; 3];

/// The most faces around one cage vertex. Every face around a vertex
/// keeps the local refinement of the vertex's whole ring: at 1,024 faces
/// about 1.7 GB and 17 s on a two-core AMD EPYC guest.
pub const MAX_LIMIT_VALENCE: usize = 1024;

impl LimitSurface {
    /// Prepares the limit surface of `cage` subdivided with `scheme` and
    /// `options` (naked-edge mode, creases, corners, holes, creasing, the
    /// triangle rule).
    ///
    /// # Errors
    /// As [`Subdivider::new`] (Loop on a face that is not a triangle, a bad
    /// crease, corner or hole); [`Error::InvalidArgument`] for a cage
    /// coordinate that is not finite, or a face whose semi-sharp creases
    /// would need more than 65536 local refinements;
    /// [`Error::ResultTooLarge`] for a vertex with more than [`MAX_LIMIT_VALENCE`]
    /// faces around it.
    pub fn new(cage: &Mesh, scheme: Scheme, options: &SubdivisionOptions) -> Result<LimitSurface> {
        if let Some(v) = cage.positions().iter().position(|p| !p.is_finite()) {
            return Err(Error::InvalidArgument(format!(
                "cage vertex {v} has a non-finite coordinate"
            )));
        }
        let subdivider = Subdivider::new(cage, scheme, 0, options)?;
        let level = &subdivider.levels[0];
        let crowded = (0..level.faces.vertex_count)
            .map(|v| (level.connectivity.vertex_corners(v).len(), v))
            .max();
        if let Some((valence, v)) = crowded.filter(|&(valence, _)| valence > MAX_LIMIT_VALENCE) {
            return Err(Error::ResultTooLarge(format!(
                "cage vertex {v} has {valence} faces around it; the limit surface takes at most \
                 {MAX_LIMIT_VALENCE} around a vertex (each face around one refines the whole ring on \
                 its own, so the memory and time grow as the square of the count)"
            )));
        }
        let holes = mesh_holes(cage, options)?;
        let expansions = local::Expansions::default();
        let faces: Vec<FaceGraph> = (0..cage.face_count())
            .into_par_iter()
            .map(|f| local::face_graph(scheme, level, f, options, &expansions))
            .collect::<Result<_>>()?;
        let largest = faces.iter().map(FaceGraph::largest).max().unwrap_or(0);
        Ok(LimitSurface {
            scheme,
            cage_positions: cage.positions().to_vec(),
            face_sizes: cage.face_sizes().to_vec(),
            holes,
            faces,
            largest,
            index: std::sync::OnceLock::new(),
        })
    }

    /// The scheme.
    pub fn scheme(&self) -> Scheme {
        self.scheme
    }

    /// Number of cage faces.
    pub fn face_count(&self) -> usize {
        self.face_sizes.len()
    }

    /// Checks that `(u, v)` lies in the domain of face `f` (see the module
    /// doc) and returns the sub-face and its local coordinates for
    /// Catmull-Clark faces that are not quads.
    fn domain(&self, sample: usize, f: u32, u: f64, v: f64) -> Result<Option<(usize, f64, f64)>> {
        let face_count = self.face_count();
        if f as usize >= face_count {
            return Err(Error::InvalidArgument(format!(
                "sample {sample}: face {f} is out of range (the cage has {face_count} faces)"
            )));
        }
        if !u.is_finite() || !v.is_finite() {
            return Err(Error::InvalidArgument(format!(
                "sample {sample} on face {f}: (u, v) = ({u}, {v}) is not finite"
            )));
        }
        if self.holes.as_ref().is_some_and(|h| h[f as usize]) {
            return Err(Error::InvalidArgument(format!(
                "sample {sample}: face {f} is a hole, not part of the surface"
            )));
        }
        let n = self.face_sizes[f as usize] as usize;
        let outside = |domain: &str| {
            Err(Error::InvalidArgument(format!(
                "sample {sample}: (u, v) = ({u}, {v}) is outside the domain of face {f} ({domain})"
            )))
        };
        match (self.scheme, n) {
            (Scheme::Loop, _) => {
                // u + v may pass 1 by rounding when v = 1 - u was computed.
                if u < 0.0 || v < 0.0 || u + v > 1.0 + 2.0 * f64::EPSILON {
                    return outside("a triangle: u ≥ 0, v ≥ 0, u + v ≤ 1");
                }
                Ok(None)
            }
            (Scheme::CatmullClark, 4) => {
                if !(0.0..=1.0).contains(&u) || !(0.0..=1.0).contains(&v) {
                    return outside("a quad: 0 ≤ u ≤ 1, 0 ≤ v ≤ 1");
                }
                Ok(None)
            }
            (Scheme::CatmullClark, _) => {
                let width = tile_width(n);
                let tile = |x: f64| (x + 0.25).floor().max(0.0);
                let (x, y) = (tile(u).min(width as f64 - 1.0), tile(v));
                let i = y as usize * width + x as usize;
                let (s, t) = (2.0 * (u - x), 2.0 * (v - y));
                if i >= n || !(0.0..=1.0).contains(&s) || !(0.0..=1.0).contains(&t) {
                    return outside(&format!(
                        "{n} corners: the {n} tiles [x, x + 1/2] × [y, y + 1/2], x = i mod \
                         {width}, y = i div {width}"
                    ));
                }
                Ok(Some((i, s, t)))
            }
        }
    }

    /// Evaluates the limit surface at `faces[i]`, `(uvs[2 i], uvs[2 i + 1])`
    /// into `positions[i]`, and the derivatives by u and v into `du[i]`
    /// and `dv[i]` when given. Parallel; nothing is allocated per sample.
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] naming the first sample whose face is out
    /// of range or a hole, or whose parameter is not finite or outside the
    /// face's domain, or buffers of the wrong length; nothing is written then.
    pub fn evaluate(
        &self,
        faces: &[u32],
        uvs: &[f64],
        positions: &mut [DVec3],
        du: Option<&mut [DVec3]>,
        dv: Option<&mut [DVec3]>,
    ) -> Result<()> {
        let count = faces.len();
        let lengths_fit = uvs.len() == 2 * count
            && positions.len() == count
            && du.as_ref().is_none_or(|d| d.len() == count)
            && dv.as_ref().is_none_or(|d| d.len() == count);
        if !lengths_fit {
            return Err(Error::InvalidArgument(format!(
                "{count} samples need {} parameters and room for {count} results",
                2 * count
            )));
        }
        let mut sub_faces = try_vec(count, "sample domains")?;
        for (i, &f) in faces.iter().enumerate() {
            sub_faces.push(self.domain(i, f, uvs[2 * i], uvs[2 * i + 1])?);
        }
        fn split(out: Option<&mut [DVec3]>, count: usize) -> Vec<Option<&mut [DVec3]>> {
            match out {
                Some(out) => out.chunks_mut(CHUNK).map(Some).collect(),
                None => (0..count.div_ceil(CHUNK)).map(|_| None).collect(),
            }
        }
        let tasks: Vec<_> = positions
            .chunks_mut(CHUNK)
            .zip(split(du, count))
            .zip(split(dv, count))
            .enumerate()
            .collect();
        tasks
            .into_par_iter()
            .for_each(|(chunk, ((p, mut du), mut dv))| {
                let mut scratch = self.scratch();
                for k in 0..p.len() {
                    let i = chunk * CHUNK + k;
                    let (u, v) = (uvs[2 * i], uvs[2 * i + 1]);
                    let [position, d_u, d_v] =
                        self.sample(faces[i] as usize, u, v, sub_faces[i], &mut scratch);
                    p[k] = position;
                    if let Some(du) = du.as_deref_mut() {
                        du[k] = d_u;
                    }
                    if let Some(dv) = dv.as_deref_mut() {
                        dv[k] = d_v;
                    }
                }
            });
        Ok(())
    }

    fn scratch(&self) -> Scratch {
        Scratch {
            here: vec![DVec3::ZERO; self.largest],
            next: vec![DVec3::ZERO; self.largest],
            face: usize::MAX,
            first_children: Vec::new(),
            root_control: None,
        }
    }

    /// One sample, its domain checked.
    fn sample(
        &self,
        f: usize,
        u: f64,
        v: f64,
        sub_face: Option<(usize, f64, f64)>,
        scratch: &mut Scratch,
    ) -> Sample {
        let graph = &self.faces[f];
        if scratch.face != f {
            scratch.face = f;
            scratch.root_control = None;
            for first in &mut scratch.first_children {
                first.made = false;
            }
        }
        let Scratch {
            mut here,
            mut next,
            face,
            mut first_children,
            mut root_control,
        } = std::mem::take(scratch);
        // Points are kept relative to `origin`, moved to the first point at
        // every level: their differences, which shrink by half per level,
        // keep their full precision however deep the walk goes.
        let origin_index = graph.vertices.first().map_or(0, |&c| c as usize);
        let mut origin = self
            .cage_positions
            .get(origin_index)
            .copied()
            .unwrap_or_default();
        if root_control.is_none() {
            for (slot, &c) in here.iter_mut().zip(&graph.vertices) {
                *slot = self.cage_positions[c as usize] - origin;
            }
        }
        // (Pu, Pv) = (a Ps + b Pt, c Ps + d Pt) for the node's own (s, t).
        let mut frame = [1.0, 0.0, 0.0, 1.0];
        let (mut s, mut t) = (u, v);
        let mut node = 0usize;
        let mut result = None;
        for depth in 0..=MAX_DEPTH {
            let current = &graph.nodes[node];
            match &current.kind {
                Kind::Patch(rows) => {
                    let control = match depth {
                        0 => *root_control.get_or_insert_with(|| control_points(rows, &here)),
                        _ => control_points(rows, &here),
                    };
                    result = Some(patch(self.scheme, &control, s, t));
                    break;
                }
                Kind::Refine { children, corners } => {
                    let corner = at_corner(self.scheme, s, t);
                    let limit = |k: usize| corners.get(k).and_then(Option::as_ref);
                    if let Some(k) = corner.filter(|&k| limit(k).is_some_and(|l| l.irregular)) {
                        result = limit(k).map(|l| corner_limit(self.scheme, l, k, &here));
                        break;
                    }
                    if depth == MAX_DEPTH {
                        let k = nearest_corner(self.scheme, s, t);
                        let corner = here[current.corners[k] as usize];
                        let position = limit(k).map_or(corner, |l| l.masks.apply(0, &here));
                        let [ps, pt] = chords(self.scheme, k, &current.corners, &here);
                        result = Some([position, ps, pt]);
                        break;
                    }
                    let (j, s2, t2, step) = match (depth, sub_face) {
                        (0, Some((i, s, t))) => (i, s, t, [2.0, 0.0, 0.0, 2.0]),
                        _ => child_at(self.scheme, s, t),
                    };
                    // Chain rule: the child's (s', t') of the node's (s, t).
                    let [ss, st, ts, tt] = step;
                    let [a, b, c, d] = frame;
                    frame = [
                        a * ss + b * st,
                        a * ts + b * tt,
                        c * ss + d * st,
                        c * ts + d * tt,
                    ];
                    let Some(child) = children.get(j) else {
                        break;
                    };
                    let rows = child.points.rows();
                    if depth == 0 && first_children.len() < children.len() {
                        first_children.resize_with(children.len(), FirstChild::default);
                    }
                    match first_children.get_mut(j).filter(|_| depth == 0) {
                        // The same points, made the same way for a sample before.
                        Some(first) if first.made => {
                            next[..rows].copy_from_slice(&first.points);
                            origin = first.origin;
                        }
                        first => {
                            for (r, slot) in next.iter_mut().enumerate().take(rows) {
                                *slot = child.points.apply(r, &here);
                            }
                            let shift = next[0];
                            origin += shift;
                            for slot in next.iter_mut().take(rows) {
                                *slot -= shift;
                            }
                            if let Some(first) = first {
                                first.points.clear();
                                first.points.extend_from_slice(&next[..rows]);
                                (first.made, first.origin) = (true, origin);
                            }
                        }
                    }
                    std::mem::swap(&mut here, &mut next);
                    (s, t) = (s2, t2);
                    node = child.node as usize;
                }
            }
        }
        *scratch = Scratch {
            here,
            next,
            face,
            first_children,
            root_control,
        };
        let [p, ps, pt] = result.unwrap_or([DVec3::NAN; 3]);
        let [a, b, c, d] = frame;
        [origin + p, ps * a + pt * b, ps * c + pt * d]
    }
}

/// `Bfr::Parameterization`'s tile width for a face of `n` corners.
fn tile_width(n: usize) -> usize {
    if n < 10 {
        2 + usize::from(n > 4)
    } else {
        1 + ((n - 1) as f64).sqrt() as usize
    }
}

/// Position and (s, t) derivatives of a regular patch.
/// The control points of a patch of `rows` on `points`.
fn control_points(rows: &[patches::Row], points: &[DVec3]) -> Control {
    let mut control = [DVec3::ZERO; 16];
    for (p, row) in control.iter_mut().zip(rows) {
        for k in 0..row.len as usize {
            *p += points[row.points[k] as usize] * row.weights[k];
        }
    }
    control
}

/// A patch's position and derivatives at `(s, t)` from its control points.
fn patch(scheme: Scheme, control: &Control, s: f64, t: f64) -> Sample {
    let mut out = [DVec3::ZERO; 3];
    let mut add = |weights: &[[f64; 16]; 3], n: usize| {
        for (i, p) in control.iter().enumerate().take(n) {
            for (o, w) in out.iter_mut().zip(weights) {
                *o += *p * w[i];
            }
        }
    };
    match scheme {
        Scheme::CatmullClark => add(&basis::bicubic(s, t), 16),
        Scheme::Loop => {
            let w = basis::box_spline(s, t);
            let mut wide = [[0.0; 16]; 3];
            for (wide, w) in wide.iter_mut().zip(&w) {
                wide[..12].copy_from_slice(w);
            }
            add(&wide, 12);
        }
    }
    out
}

/// The corner of the node's face that `(s, t)` is exactly at.
fn at_corner(scheme: Scheme, s: f64, t: f64) -> Option<usize> {
    match (scheme, s, t) {
        (_, 0.0, 0.0) => Some(0),
        (_, 1.0, 0.0) => Some(1),
        (Scheme::CatmullClark, 1.0, 1.0) => Some(2),
        (Scheme::CatmullClark, 0.0, 1.0) => Some(3),
        (Scheme::Loop, 0.0, 1.0) => Some(2),
        _ => None,
    }
}

fn nearest_corner(scheme: Scheme, s: f64, t: f64) -> usize {
    match scheme {
        Scheme::CatmullClark => match (s >= 0.5, t >= 0.5) {
            (false, false) => 0,
            (true, false) => 1,
            (true, true) => 2,
            (false, true) => 3,
        },
        Scheme::Loop if s + t <= 0.5 => 0,
        Scheme::Loop if s >= t => 1,
        Scheme::Loop => 2,
    }
}

/// The limit at corner `k` with its tangents turned into the face's (s, t)
/// frame: the masks' first tangent runs along the edge leaving the corner,
/// the second along the edge arriving at it.
fn corner_limit(scheme: Scheme, limit: &local::CornerLimit, k: usize, points: &[DVec3]) -> Sample {
    let p = limit.masks.apply(0, points);
    let du = limit.masks.apply(1, points);
    let dv = limit.masks.apply(2, points);
    let (ps, pt) = match (scheme, k) {
        (Scheme::CatmullClark, 1) => (-dv, du),
        (Scheme::CatmullClark, 2) => (-du, -dv),
        (Scheme::CatmullClark, 3) => (dv, -du),
        _ => (du, dv),
    };
    [p, ps, pt]
}

/// The derivatives at corner `k` of a node's face (`corners` its points
/// among `points`) 2⁻⁶⁰ of the cage face across: its edges there, which at that
/// size lie along the surface's one-sided tangents (at a corner or a crease
/// end, each face has its own).
fn chords(scheme: Scheme, k: usize, corners: &[u32], points: &[DVec3]) -> [DVec3; 2] {
    let p = |i: usize| points[corners[i] as usize];
    match (scheme, k) {
        (Scheme::Loop, _) => [p(1) - p(0), p(2) - p(0)],
        (_, 0) => [p(1) - p(0), p(3) - p(0)],
        (_, 1) => [p(1) - p(0), p(2) - p(1)],
        (_, 2) => [p(2) - p(3), p(2) - p(1)],
        _ => [p(2) - p(3), p(3) - p(0)],
    }
}

/// The child holding `(s, t)`, its coordinates there, and the derivatives
/// `[∂s'/∂s, ∂s'/∂t, ∂t'/∂s, ∂t'/∂t]` (see `subdivide/mod.rs` for the order
/// of children: child i starts at corner i; Loop's fourth is the middle).
fn child_at(scheme: Scheme, s: f64, t: f64) -> (usize, f64, f64, [f64; 4]) {
    let unit = |x: f64| x.clamp(0.0, 1.0);
    match scheme {
        Scheme::CatmullClark => match (s > 0.5, t > 0.5) {
            (false, false) => (0, unit(2.0 * s), unit(2.0 * t), [2.0, 0.0, 0.0, 2.0]),
            (true, false) => (1, unit(2.0 * t), unit(2.0 - 2.0 * s), [0.0, 2.0, -2.0, 0.0]),
            (true, true) => (
                2,
                unit(2.0 - 2.0 * s),
                unit(2.0 - 2.0 * t),
                [-2.0, 0.0, 0.0, -2.0],
            ),
            (false, true) => (3, unit(2.0 - 2.0 * t), unit(2.0 * s), [0.0, -2.0, 2.0, 0.0]),
        },
        Scheme::Loop => {
            let (j, s2, t2, step) = if s + t <= 0.5 {
                (0, 2.0 * s, 2.0 * t, [2.0, 0.0, 0.0, 2.0])
            } else if s >= 0.5 {
                (1, 2.0 * t, 2.0 * (1.0 - s - t), [0.0, 2.0, -2.0, -2.0])
            } else if t >= 0.5 {
                (2, 2.0 * (1.0 - s - t), 2.0 * s, [-2.0, -2.0, 2.0, 0.0])
            } else {
                (3, 2.0 * (s + t) - 1.0, 1.0 - 2.0 * s, [2.0, 2.0, -2.0, 0.0])
            };
            let (s2, t2) = (unit(s2), unit(t2));
            (j, s2, t2.min(1.0 - s2), step)
        }
    }
}

#[cfg(test)]
mod tests;
