//! Mesh Window and Picture Frame: each face inset, framed by quads.

use glam::DVec3;

use crate::error::{Error, Result};
use crate::mesh::Mesh;
use crate::toolbar::split::{face_normal, Builder};

/// How far a face's inner copy sits from its edges.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum InsetMode {
    /// A share of the edges: corner `v` goes to `v + t·(next − v) + t·(prev − v)`,
    /// `t` in [0, 0.5) (a triangle's inner face shrinks to a point at 1/3).
    #[default]
    EdgeFraction,
    /// The parallelogram rule, a distance in model units: corner `v` goes
    /// to the point at distance `d` from both of its edges, within the face
    /// (`v + d / sin θ · (u_next + u_prev)` with unit edge directions), so a
    /// planar face gets a frame of constant width. At a straight corner it
    /// moves `d` perpendicular to the edge; a reflex corner moves outwards
    /// as the rule says.
    Parallelogram,
}

/// Insets each face by its distance and keeps both the frame of quads and
/// the inner face (Weaverbird's Mesh Window). `distances` holds one value
/// for every face or one per face.
///
/// Output: the input's vertices, then the inner corners face by face; for
/// each face its quads `[corner k, corner k+1, inner k+1, inner k]`, then
/// its inner face.
///
/// # Errors
/// [`Error::InvalidArgument`] when `distances` has neither 1 nor one value
/// per face (naming both numbers), or when a distance is negative, not
/// finite, or (for [`InsetMode::EdgeFraction`]) not below 0.5, or wider
/// than a face allows (its inset would turn over and its frame cross
/// itself; the message names the face and the widest it takes);
/// [`Error::ResultTooLarge`] past the size cap.
pub fn window(mesh: &Mesh, distances: &[f64], mode: InsetMode) -> Result<Mesh> {
    inset(mesh, distances, mode, true)
}

/// As [`window`], but only the frame is kept: each face becomes a ring of
/// quads around a new hole (Weaverbird's Picture Frame).
///
/// # Errors
/// As [`window`].
pub fn picture_frame(mesh: &Mesh, distances: &[f64], mode: InsetMode) -> Result<Mesh> {
    inset(mesh, distances, mode, false)
}

/// Checks that `count` distances suit a mesh of `face_count` faces (one for
/// every face, or one per face), from the count alone (the C ABI checks it
/// before it views the caller's buffer).
pub(crate) fn check_distance_count(count: usize, face_count: usize) -> Result<()> {
    if count != 1 && count != face_count {
        return Err(Error::InvalidArgument(format!(
            "{count} distances were given for a mesh of {face_count} faces; give one distance, or one per face"
        )));
    }
    Ok(())
}

fn inset(mesh: &Mesh, distances: &[f64], mode: InsetMode, keep_inner: bool) -> Result<Mesh> {
    let faces = mesh.face_count();
    check_distance_count(distances.len(), faces)?;
    for (i, &d) in distances.iter().enumerate() {
        let limit = if mode == InsetMode::EdgeFraction {
            0.5
        } else {
            f64::INFINITY
        };
        if !(d >= 0.0 && d < limit) {
            let range = if mode == InsetMode::EdgeFraction {
                "at least 0 and below 0.5"
            } else {
                "finite and at least 0"
            };
            return Err(Error::InvalidArgument(format!(
                "distance {i} is {d}; it must be {range}"
            )));
        }
    }
    let corners = mesh.index_count() as u64;
    let inner_faces = if keep_inner { faces as u64 } else { 0 };
    let inner_indices = if keep_inner { corners } else { 0 };
    let mut out = Builder::new(
        if keep_inner {
            "mesh window"
        } else {
            "picture frame"
        },
        mesh.vertex_count() as u64 + corners,
        corners + inner_faces,
        4 * corners + inner_indices,
    )?;
    out.positions.extend_from_slice(mesh.positions());
    let mut inner = Vec::new();
    let mut corners = Vec::new();
    for f in 0..faces {
        let d = distances[if distances.len() == 1 { 0 } else { f }];
        let outer = mesh.face(f);
        let points: Vec<DVec3> = mesh.face_positions(f).collect();
        let normal = face_normal(mesh, f);
        inset_corners(&points, normal, mode, d, &mut corners);
        if !keeps_its_shape(&points, &corners, normal) {
            return Err(too_wide(f, &points, normal, mode, d));
        }
        let n = points.len();
        inner.clear();
        for &q in &corners {
            inner.push(out.vertex(q));
        }
        for k in 0..n {
            let k1 = (k + 1) % n;
            out.face(&[outer[k], outer[k1], inner[k1], inner[k]]);
        }
        if keep_inner {
            out.face(&inner);
        }
    }
    out.finish()
}

/// The inner corners of a face inset by `d`.
fn inset_corners(points: &[DVec3], normal: DVec3, mode: InsetMode, d: f64, out: &mut Vec<DVec3>) {
    let n = points.len();
    out.clear();
    out.extend((0..n).map(|k| {
        let (p, next, prev) = (points[k], points[(k + 1) % n], points[(k + n - 1) % n]);
        match mode {
            InsetMode::EdgeFraction => p + (next - p) * d + (prev - p) * d,
            InsetMode::Parallelogram => parallelogram(p, next, prev, normal, d),
        }
    }));
}

/// Whether the inset face runs the same way as the face, edge by edge and
/// as a whole: an inset wider than the face turns its inner polygon over
/// (a triangle's past a third of its edges) and its frame crosses itself.
fn keeps_its_shape(points: &[DVec3], inner: &[DVec3], normal: DVec3) -> bool {
    let n = points.len();
    let area: DVec3 = (0..n).map(|k| inner[k].cross(inner[(k + 1) % n])).sum();
    area.dot(normal) > 0.0
        && (0..n).all(|k| {
            let k1 = (k + 1) % n;
            (inner[k1] - inner[k]).dot(points[k1] - points[k]) >= 0.0
        })
}

/// The refusal of an inset wider than face `f`, with the widest the face takes.
fn too_wide(f: usize, points: &[DVec3], normal: DVec3, mode: InsetMode, d: f64) -> Error {
    let (mut fits, mut crosses) = (0.0, d);
    let mut corners = Vec::new();
    for _ in 0..40 {
        let middle = (fits + crosses) / 2.0;
        inset_corners(points, normal, mode, middle, &mut corners);
        if keeps_its_shape(points, &corners, normal) {
            fits = middle;
        } else {
            crosses = middle;
        }
    }
    Error::InvalidArgument(format!(
        "distance {d} is wider than face {f} allows: its inset would cross itself; \
         that face takes at most {fits:.6}"
    ))
}

fn parallelogram(p: DVec3, next: DVec3, prev: DVec3, normal: DVec3, d: f64) -> DVec3 {
    let (u_next, u_prev) = (
        (next - p).normalize_or_zero(),
        (prev - p).normalize_or_zero(),
    );
    let sine = normal.dot(u_next.cross(u_prev));
    if sine.abs() < 1e-6 {
        return p + normal.cross(u_next) * d;
    }
    p + (u_next + u_prev) * (d / sine)
}
