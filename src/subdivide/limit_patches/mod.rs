//! The Catmull-Clark limit surface as bicubic Bézier patches, for NURBS
//! export: one patch per face of the cage refined `isolation` levels.
//!
//! Where the limit surface over a face is a bicubic B-spline (its four
//! corners regular: four quads, four smooth edges, no sharpness), the patch
//! is that B-spline's Bézier form, straight from the refined cage
//! (`regular.rs`). Every other patch is fitted to exact limit points (the
//! limit masks of [`super::Limit`] at the vertices of three levels deeper,
//! which sit on the surface at the dyadic parameters of the face):
//! - its corners are the limit points of the face's corners;
//! - each edge's two inner control points fit the limit points at ¼, ½, ¾
//!   of the edge (least squares), by sums symmetric in the edge's direction;
//!   an edge between two regular vertices is their limit curve instead,
//!   the one the regular patch beside it has, so the two patches meeting at
//!   an edge share its curve bit for bit and the patches are watertight
//!   everywhere, across creases and boundaries included;
//! - the four inner control points fit the nine inner limit points of the
//!   face's ¼ grid.
//!
//! Along smooth boundaries and infinitely sharp creases the surface is a
//! B-spline too, and there the fit reproduces it to rounding. Faces touching
//! an irregular point are approximations; each fitted patch's error is its
//! largest distance from the limit points of the ⅛ grid (81 points, most
//! not used by the fit), and it falls as `isolation` rises, since those
//! faces shrink.

use glam::DVec3;
use rayon::prelude::*;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;

use super::creases::SubdivisionOptions;
use super::level::{Connectivity, Faces};
use super::scheme::{check_counts, Scheme};
use super::subdivider::Subdivider;
use crate::buffers::try_vec;
use crate::error::{Error, Result};
use crate::mesh::{Mesh, MeshOptions};
use regular::Isolated;

mod regular;

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
    /// The patch's largest distance from the limit points of its ⅛ grid;
    /// 0 for a patch made as the B-spline the surface is there.
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
/// three deeper levels count towards); [`Error::ResultTooLarge`] when the
/// faces sharing a vertex with one face would make more than 262,144
/// patches (a vertex of very many faces at a high isolation), naming the
/// face and the vertex.
///
/// The cage is fitted piece by piece, each piece with the faces around it,
/// so memory follows a piece of a few thousand patches and the patches
/// themselves, not the whole cage three levels past `isolation`.
pub fn limit_patches(
    cage: &Mesh,
    options: &SubdivisionOptions,
    isolation: u32,
) -> Result<LimitPatches> {
    check_isolation(isolation)?;
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
    patches_in_pieces(cage, options, isolation, PIECE_PATCHES)
}

/// How many patches [`limit_patches`] makes, and whether it accepts the
/// cage, options and isolation, without fitting them: one per face of the
/// cage refined `isolation` levels.
///
/// # Errors
/// As [`limit_patches`], but for the refusal of a vertex of very many faces.
pub fn limit_patch_count(
    cage: &Mesh,
    options: &SubdivisionOptions,
    isolation: u32,
) -> Result<usize> {
    check_isolation(isolation)?;
    Ok(checked_cage(cage, options, isolation)?.2)
}

fn check_isolation(isolation: u32) -> Result<()> {
    if !(1..=MAX_ISOLATION).contains(&isolation) {
        return Err(Error::InvalidArgument(format!(
            "isolation is {isolation}; it must be 1 to {MAX_ISOLATION} (every face becomes a quad after one level)"
        )));
    }
    Ok(())
}

/// About how many patches one piece of the cage and the faces around it
/// make: each is subdivided on its own, three levels past `isolation`, at
/// roughly 30 KB a patch (30 MB a piece), so memory follows the piece and
/// not the cage, and a piece's levels stay near the processor's caches.
const PIECE_PATCHES: usize = 1024;

/// The most patches the faces around one cage face may make (~7 GB of
/// subdivision): more is a vertex of very many faces at a high isolation.
const MAX_PIECE_PATCHES: usize = 1 << 18;

/// The patches, made piece by piece: cage faces with every face sharing a
/// vertex with one of them, since the limit surface over a face
/// depends on those alone. Each piece is refined as a cage of its own whose
/// faces and vertices keep the whole cage's order, so every list walked near
/// the piece's faces runs in the same order and every limit point rounds as
/// it would on the whole cage: the patches are those of one piece, bit for
/// bit, whatever the `budget`.
fn patches_in_pieces(
    cage: &Mesh,
    options: &SubdivisionOptions,
    isolation: u32,
    budget: usize,
) -> Result<LimitPatches> {
    let (whole, starts, total) = checked_cage(cage, options, isolation)?;
    let level = &whole.levels[0];
    let refined = Subdivider::new(cage, Scheme::CatmullClark, isolation, options)?;
    let isolated = Isolated::new(&refined, cage.positions())?;
    let layout = Layout::of(cage, &starts, total, isolation);
    let size = cage
        .bounding_box()
        .map_or(0.0, |(low, high)| (high - low).length());
    let mut patches = try_vec(total, "patches")?;
    patches.resize(
        total,
        BezierPatch {
            cage_face: 0,
            control: [[DVec3::ZERO; 4]; 4],
            error: 0.0,
        },
    );
    // Regular faces first, straight from the refined cage; the others
    // are fitted to the limit three levels further down.
    let mut fitted = try_vec(total, "patches")?;
    fitted.resize(total, false);
    patches
        .par_iter_mut()
        .zip(&mut fitted)
        .enumerate()
        .for_each(|(slot, (patch, fitted))| {
            let (cage_face, face) = layout.face_of(slot);
            match isolated.regular_patch(face) {
                Some(control) => {
                    *patch = BezierPatch {
                        cage_face,
                        control,
                        error: 0.0,
                    }
                }
                None => *fitted = true,
            }
        });
    let mut to_fit = vec![false; cage.face_count()];
    for (slot, _) in fitted.iter().enumerate().filter(|(_, &f)| f) {
        to_fit[layout.face_of(slot).0 as usize] = true;
    }
    let tags = CageTags::of(&level.connectivity, cage, options);
    let pieces = pieces(
        &level.faces,
        &level.connectivity,
        isolation,
        budget,
        &to_fit,
    )?;
    // One piece at a time on each thread: a piece's subdivision gains
    // little from more threads, and fewer pieces at once hold less memory.
    let taken = AtomicUsize::new(0);
    let placed = Mutex::new(&mut patches);
    let workers = rayon::current_num_threads().clamp(1, pieces.len().max(1));
    let fit = Fit {
        cage,
        connectivity: &level.connectivity,
        options,
        tags: &tags,
        isolation,
        isolated: &isolated,
        layout: &layout,
        fitted: &fitted,
    };
    (0..workers)
        .into_par_iter()
        .try_for_each(|_| -> Result<()> {
            while let Some(piece) = pieces.get(taken.fetch_add(1, Ordering::Relaxed)) {
                let made = fit.piece_patches(piece)?;
                let mut patches = placed
                    .lock()
                    .unwrap_or_else(|poisoned| poisoned.into_inner());
                for (slot, patch) in made {
                    patches[slot] = patch;
                }
            }
            Ok(())
        })?;
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

/// The whole cage checked, so that errors name its faces and vertices and
/// the size cap counts the fit's three deeper levels, with where each cage
/// face's patches start and how many there are in all.
fn checked_cage(
    cage: &Mesh,
    options: &SubdivisionOptions,
    isolation: u32,
) -> Result<(Subdivider, Vec<usize>, usize)> {
    let whole = Subdivider::new(cage, Scheme::CatmullClark, 0, options)?;
    check_counts(
        Scheme::CatmullClark,
        cage.vertex_count() as u64,
        whole.levels[0].connectivity.edge_count() as u64,
        cage.face_count() as u64,
        cage.index_count() as u64,
        isolation + 3,
    )?;
    // A face left out (a hole, or beside an open vertex when naked edges
    // are left out) has none; the others their children's children.
    let mut shown = vec![false; cage.face_count()];
    for f in whole.parent_faces() {
        shown[f as usize] = true;
    }
    let per_corner = patches_per_corner(isolation);
    let mut starts = Vec::with_capacity(cage.face_count());
    let mut total = 0;
    for (face, &shown) in cage.faces().zip(&shown) {
        starts.push(total);
        if shown {
            total += face.len() * per_corner;
        }
    }
    Ok((whole, starts, total))
}

/// Patches of each corner of a cage face: the corner's quad of level 1,
/// split `isolation - 1` more times.
fn patches_per_corner(isolation: u32) -> usize {
    1 << (2 * (isolation - 1))
}

/// Cage faces whose patches are made together.
#[derive(Debug)]
struct Piece {
    faces: Vec<u32>,
    /// Those faces and every face sharing a vertex with one, ascending.
    ring: Vec<u32>,
}

/// Cuts the cage's faces `wanted` into pieces, each grown breadth first
/// from the lowest face left (so that pieces are round and their rings
/// thin) until its ring would make more than `budget` patches, or twice its
/// first face's ring where that makes more (up to [`MAX_PIECE_PATCHES`]): faces around a vertex of many
/// faces share most of their rings, and are refined together instead of
/// one at a time. Faces that add nothing to a ring always join it.
///
/// # Errors
/// [`Error::ResultTooLarge`] when one face's ring makes more than
/// [`MAX_PIECE_PATCHES`], naming the face and its vertex of most faces.
fn pieces(
    faces: &Faces,
    connectivity: &Connectivity,
    isolation: u32,
    budget: usize,
    wanted: &[bool],
) -> Result<Vec<Piece>> {
    let per_corner = patches_per_corner(isolation);
    let face_count = faces.face_count();
    let mut taken: Vec<bool> = wanted.iter().map(|&w| !w).collect();
    // The piece whose ring holds each face and vertex so far.
    let mut face_piece = vec![u32::MAX; face_count];
    let mut vertex_piece = vec![u32::MAX; faces.vertex_count];
    let mut pieces = Vec::new();
    let (mut added, mut queue) = (Vec::new(), std::collections::VecDeque::new());
    let mut seed = 0;
    loop {
        while seed < face_count && taken[seed] {
            seed += 1;
        }
        if seed == face_count {
            return Ok(pieces);
        }
        let id = pieces.len() as u32;
        let mut piece = Piece {
            faces: Vec::new(),
            ring: Vec::new(),
        };
        let (mut ring_patches, mut piece_budget) = (0, budget);
        queue.clear();
        queue.push_back(seed as u32);
        while let Some(f) = queue.pop_front() {
            let f = f as usize;
            if taken[f] {
                continue;
            }
            // The faces face f adds to the ring, and their patches.
            added.clear();
            let mut patches = 0;
            for &v in faces.face(f) {
                if std::mem::replace(&mut vertex_piece[v as usize], id) == id {
                    continue;
                }
                for &c in connectivity.vertex_corners(v as usize) {
                    let g = connectivity.face_of(c as usize);
                    if std::mem::replace(&mut face_piece[g], id) != id {
                        added.push(g as u32);
                        patches += faces.corners(g).len() * per_corner;
                    }
                }
            }
            if piece.faces.is_empty() && patches > MAX_PIECE_PATCHES {
                let crowded = faces
                    .face(f)
                    .iter()
                    .copied()
                    .max_by_key(|&v| connectivity.vertex_corners(v as usize).len())
                    .unwrap_or(0);
                return Err(Error::ResultTooLarge(format!(
                    "face {f} and the faces sharing a vertex with it (vertex {crowded} has {} faces) \
                     would make {patches} patches at isolation {isolation}, past the {MAX_PIECE_PATCHES} \
                     that can be fitted together; use a lower isolation",
                    connectivity.vertex_corners(crowded as usize).len()
                )));
            }
            // Past the budget the piece ends here: the marks face f left
            // belong to a ring no longer grown.
            if !piece.faces.is_empty() && patches > 0 && ring_patches + patches > piece_budget {
                break;
            }
            if piece.faces.is_empty() {
                // Within the most one face's ring may make, memory's bound.
                piece_budget = budget.max(2 * patches).min(MAX_PIECE_PATCHES.max(budget));
            }
            taken[f] = true;
            piece.faces.push(f as u32);
            piece.ring.extend_from_slice(&added);
            ring_patches += patches;
            queue.extend(added.iter().filter(|&&g| !taken[g as usize]));
        }
        piece.ring.sort_unstable();
        pieces.push(piece);
    }
}

/// The options' creases, corners and holes by cage edge, vertex and face,
/// as the whole cage reads them (the last given wins).
struct CageTags {
    creases: Vec<Option<f64>>,
    corners: Vec<Option<f64>>,
    holes: Vec<bool>,
}

impl CageTags {
    /// The options are already checked against the cage.
    fn of(connectivity: &Connectivity, cage: &Mesh, options: &SubdivisionOptions) -> CageTags {
        let mut creases = vec![None; connectivity.edge_count()];
        for &([a, b], sharpness) in &options.creases {
            if let Some(e) = connectivity.find_edge(a, b) {
                creases[e as usize] = Some(sharpness);
            }
        }
        let mut corners = vec![None; cage.vertex_count()];
        for &(v, sharpness) in &options.corners {
            corners[v as usize] = Some(sharpness);
        }
        let mut holes = vec![false; cage.face_count()];
        for &f in &options.holes {
            holes[f as usize] = true;
        }
        CageTags {
            creases,
            corners,
            holes,
        }
    }
}

/// What the fit of every piece reads.
struct Fit<'a> {
    cage: &'a Mesh,
    connectivity: &'a Connectivity,
    options: &'a SubdivisionOptions,
    tags: &'a CageTags,
    isolation: u32,
    isolated: &'a Isolated<'a>,
    layout: &'a Layout,
    /// Per slot: whether its patch is fitted.
    fitted: &'a [bool],
}

impl Fit<'_> {
    /// The fitted patches of `piece`'s faces with their slots, from its
    /// ring refined on its own.
    fn piece_patches(&self, piece: &Piece) -> Result<Vec<(usize, BezierPatch)>> {
        let (cage, connectivity, options, tags) =
            (self.cage, self.connectivity, self.options, self.tags);
        let mut vertices: Vec<u32> = piece
            .ring
            .iter()
            .flat_map(|&f| cage.face(f as usize).iter().copied())
            .collect();
        vertices.sort_unstable();
        vertices.dedup();
        let local = |v: u32| vertices.binary_search(&v).unwrap_or(0) as u32;
        let ring_faces = piece.ring.iter().map(|&f| cage.face(f as usize));
        let sizes: Vec<u32> = ring_faces.clone().map(|face| face.len() as u32).collect();
        let indices: Vec<u32> = ring_faces.flatten().map(|&v| local(v)).collect();
        let positions = vertices
            .iter()
            .map(|&v| cage.positions()[v as usize])
            .collect();
        let ring_cage = Mesh::new_with(
            positions,
            sizes,
            indices,
            MeshOptions {
                allow_repeated_vertices: true,
            },
        )
        .map_err(Error::from)?;
        let mut ring_options = SubdivisionOptions {
            creases: Vec::new(),
            corners: Vec::new(),
            holes: Vec::new(),
            ..options.clone()
        };
        for (i, &f) in piece.ring.iter().enumerate() {
            for c in cage.face_start(f as usize)
                ..cage.face_start(f as usize) + cage.face(f as usize).len()
            {
                let e = connectivity.corner_edges[c] as usize;
                if let Some(sharpness) = tags.creases[e] {
                    let [a, b] = connectivity.edges[e];
                    ring_options.creases.push(([local(a), local(b)], sharpness));
                }
            }
            if tags.holes[f as usize] {
                ring_options.holes.push(i as u32);
            }
        }
        for (i, &v) in vertices.iter().enumerate() {
            if let Some(sharpness) = tags.corners[v as usize] {
                ring_options.corners.push((i as u32, sharpness));
            }
        }

        let fine = Subdivider::new(
            &ring_cage,
            Scheme::CatmullClark,
            self.isolation + 3,
            &ring_options,
        )?;
        // Every refined level is quads; the children of face f of level
        // `isolation` are the 64 faces from 64 f three levels down, and
        // the faces of each cage face are in the whole cage's order.
        let fine_faces = fine.face_indices();
        let parents = fine.parent_faces();
        let mut ours = vec![false; piece.ring.len()];
        for &f in &piece.faces {
            ours[piece.ring.binary_search(&f).unwrap_or(0)] = true;
        }
        let mut grids = Vec::new();
        let mut child = 0;
        for g in 0..fine.face_count() / 64 {
            let parent = parents[64 * g] as usize;
            child = if g > 0 && parents[64 * (g - 1)] as usize == parent {
                child + 1
            } else {
                0
            };
            let cage_face = piece.ring[parent];
            let (slot, face) = self.layout.place(cage_face, child);
            if ours[parent] && self.fitted[slot] {
                let grid = Grid::of(&fine_faces[256 * g..256 * (g + 1)]);
                grids.push((grid, cage_face, slot, face));
            }
        }
        // The limit at the grids' points alone, not at the rest of the ring.
        let mut points: Vec<u32> = grids.iter().flat_map(|(grid, ..)| grid.0).collect();
        points.sort_unstable();
        points.dedup();
        let limit = fine
            .limit_at_vertices(
                ring_cage.positions(),
                points.par_iter().map(|&v| v as usize),
            )?
            .positions;
        Ok(grids
            .into_par_iter()
            .map(|(grid, cage_face, slot, face)| {
                let grid = Grid(grid.0.map(|v| points.binary_search(&v).unwrap_or(0) as u32));
                (
                    slot,
                    fitted_patch(&grid, &limit, self.isolated, face, cage_face),
                )
            })
            .collect())
    }
}

/// Where the patches lie: each shown cage face's patches in one run of
/// slots, as its faces of the refined cage are in one run of faces.
struct Layout {
    /// Per cage face, its first slot and its first refined face.
    starts: Vec<usize>,
    first_faces: Vec<usize>,
    /// Per slot, its cage face and its refined face.
    slots: Vec<(u32, u32)>,
}

impl Layout {
    /// `starts` and `total` as [`checked_cage`] gives them.
    fn of(cage: &Mesh, starts: &[usize], total: usize, isolation: u32) -> Layout {
        let per_corner = patches_per_corner(isolation);
        let mut first_faces = Vec::with_capacity(cage.face_count());
        let mut slots = Vec::with_capacity(total);
        let mut next_face = 0;
        for (f, face) in cage.faces().enumerate() {
            first_faces.push(next_face);
            let shown = starts.get(f + 1).copied().unwrap_or(total) - starts[f];
            slots.extend((0..shown).map(|k| (f as u32, (next_face + k) as u32)));
            next_face += face.len() * per_corner;
        }
        Layout {
            starts: starts.to_vec(),
            first_faces,
            slots,
        }
    }

    /// The cage face and refined face of `slot`.
    fn face_of(&self, slot: usize) -> (u32, usize) {
        let (cage_face, face) = self.slots[slot];
        (cage_face, face as usize)
    }

    /// The slot and refined face of child `k` of cage face `cage_face`.
    fn place(&self, cage_face: u32, k: usize) -> (usize, usize) {
        let f = cage_face as usize;
        (self.starts[f] + k, self.first_faces[f] + k)
    }
}

/// The patch of refined face `face` fitted to the limit points of `grid`,
/// with its error. At regular vertices its corners are the refined cage's
/// limit points, and along edges between them its edges are their limit
/// curves, as the patches beside it have them. Elsewhere the limit points
/// three levels down stand: a sharpness that has not yet decayed to zero,
/// or two faces at a vertex, where OpenSubdiv's limit is the point itself,
/// make the refined cage's limit there differ from theirs.
fn fitted_patch(
    grid: &Grid,
    limit: &[DVec3],
    isolated: &Isolated,
    face: usize,
    cage_face: u32,
) -> BezierPatch {
    let corners = isolated.corners_of(face);
    let edges: [[DVec3; 4]; 4] = std::array::from_fn(|k| {
        isolated
            .edge_curve(face, corners.start + k)
            .unwrap_or_else(|| {
                let samples = grid.edge(k).map(|v| limit[v as usize]);
                let corner = |c: usize, sample| {
                    isolated
                        .regular_corner(isolated.vertex_at(corners.start + c % 4))
                        .unwrap_or(sample)
                };
                fit_curve(corner(k, samples[0]), corner(k + 1, samples[8]), &samples)
            })
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

/// A cubic Bézier curve from `p0` to `p3` whose inner control points fit
/// `samples` at ¼, ½ and ¾ (least squares; the samples run from t = 0 to 1
/// in eighths). Every sum pairs a sample with its mirror, so the ends and
/// samples reversed give the curve reversed bit for bit: the two patches at
/// an edge, each fitting it from its own side, share its curve exactly.
fn fit_curve(p0: DVec3, p3: DVec3, samples: &[DVec3; 9]) -> [DVec3; 4] {
    // The weights at ¼ (those at ¾ are the same reversed) and at ½.
    let (q, h) = (bernstein(0.25), bernstein(0.5));
    let near = samples[2] - (q[0] * p0 + q[3] * p3);
    let far = samples[6] - (q[3] * p0 + q[0] * p3);
    let middle = samples[4] - (h[0] * p0 + h[3] * p3);
    // Normal equations of the two inner control points: the matrix is
    // symmetric and persymmetric, [[d, o], [o, d]].
    let d = (q[1] * q[1] + q[2] * q[2]) + h[1] * h[1];
    let o = (q[1] * q[2] + q[2] * q[1]) + h[1] * h[2];
    let r1 = (q[1] * near + q[2] * far) + h[1] * middle;
    let r2 = (q[2] * near + q[1] * far) + h[2] * middle;
    let det = d * d - o * o;
    [p0, (d * r1 - o * r2) / det, (d * r2 - o * r1) / det, p3]
}

/// A bicubic patch with the four boundary curves `edges` (as
/// [`BezierPatch::edge`] lists them) whose four inner control points fit
/// `sample(a, b)`, the limit points at `(a / 4, b / 4)` for a, b in 1..=3.
fn fit_patch(edges: &[[DVec3; 4]; 4], sample: impl Fn(usize, usize) -> DVec3) -> [[DVec3; 4]; 4] {
    let mut c = with_edges(edges);
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

/// Control points with the four boundary curves `edges` (as
/// [`BezierPatch::edge`] lists them) and zeros inside.
fn with_edges(edges: &[[DVec3; 4]; 4]) -> [[DVec3; 4]; 4] {
    let mut c = [[DVec3::ZERO; 4]; 4];
    for t in 0..4 {
        c[t][0] = edges[0][t];
        c[3][t] = edges[1][t];
        c[3 - t][3] = edges[2][t];
        c[0][3 - t] = edges[3][t];
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
        let curve = fit_curve(samples[0], samples[8], &samples);
        for k in 0..=8 {
            let t = k as f64 / 8.0;
            let b = bernstein(t);
            let p = b[0] * curve[0] + b[1] * curve[1] + b[2] * curve[2] + b[3] * curve[3];
            assert!((p - cubic(t)).length() < 1e-14, "t = {t}");
        }
    }

    #[test]
    fn a_curve_fitted_backwards_is_the_curve_reversed_bit_for_bit() {
        let mut unit = crate::test_random::units(11);
        for _ in 0..1000 {
            let samples: [DVec3; 9] =
                std::array::from_fn(|_| DVec3::new(unit(), unit(), unit()) * 1e3 - 500.0);
            let mut backwards = samples;
            backwards.reverse();
            let mut curve = fit_curve(backwards[0], backwards[8], &backwards);
            curve.reverse();
            assert_eq!(curve, fit_curve(samples[0], samples[8], &samples));
        }
    }

    /// `mesh` with every coordinate moved by up to a tenth, so that sums
    /// taken in another order would round differently.
    pub(super) fn jittered(mesh: &Mesh, seed: u64) -> Mesh {
        let mut unit = crate::test_random::units(seed);
        let moved = mesh
            .positions()
            .iter()
            .map(|&p| p + 0.1 * DVec3::new(unit(), unit(), unit()))
            .collect();
        mesh.with_positions(moved).unwrap()
    }

    #[test]
    fn patches_made_in_pieces_are_those_of_the_whole_cage() {
        use super::super::{Creasing, NakedEdges, TriangleRule};
        use crate::mesh::shapes;
        let creased = |naked_edges| SubdivisionOptions {
            creases: vec![([7, 8], f64::INFINITY), ([8, 9], 2.0), ([14, 15], 0.5)],
            corners: vec![(0, f64::INFINITY), (14, 1.5)],
            holes: vec![15],
            creasing: Creasing::Chaikin,
            ..SubdivisionOptions::new(naked_edges)
        };
        let smooth_triangles = SubdivisionOptions {
            triangles: TriangleRule::Smooth,
            ..SubdivisionOptions::new(NakedEdges::Smooth)
        };
        let cases = [
            (
                jittered(&shapes::torus(5, 7), 1),
                SubdivisionOptions::default(),
                1,
            ),
            (
                jittered(&shapes::cube(), 2),
                SubdivisionOptions::default(),
                2,
            ),
            (
                jittered(&shapes::quad_grid(5, 5), 3),
                creased(NakedEdges::Fixed),
                1,
            ),
            (
                jittered(&shapes::quad_grid(5, 5), 4),
                creased(NakedEdges::Smooth),
                2,
            ),
            (
                jittered(&shapes::quad_grid(5, 5), 5),
                creased(NakedEdges::CornerFixed),
                1,
            ),
            (
                jittered(&shapes::quad_grid(5, 5), 6),
                creased(NakedEdges::None),
                1,
            ),
            (jittered(&shapes::mixed_polygons(), 7), smooth_triangles, 1),
            (
                jittered(&shapes::icosahedron(), 8),
                SubdivisionOptions::default(),
                1,
            ),
            (
                jittered(&shapes::fin(), 9),
                SubdivisionOptions::default(),
                1,
            ),
            (
                jittered(&shapes::fan(12), 10),
                SubdivisionOptions::default(),
                1,
            ),
        ];
        for (k, (cage, options, isolation)) in cases.iter().enumerate() {
            let whole = patches_in_pieces(cage, options, *isolation, usize::MAX).unwrap();
            assert!(!whole.patches.is_empty(), "case {k}");
            // One patch per refined face, on its cage face, faces left out
            // by holes and open vertices included.
            let refined = Subdivider::new(cage, Scheme::CatmullClark, *isolation, options).unwrap();
            let on: Vec<u32> = whole.patches.iter().map(|p| p.cage_face).collect();
            assert_eq!(on, refined.parent_faces(), "case {k}");
            let count = limit_patch_count(cage, options, *isolation).unwrap();
            assert_eq!(count, on.len(), "case {k}");
            for budget in [1, 24, 100] {
                let pieces = patches_in_pieces(cage, options, *isolation, budget).unwrap();
                assert_eq!(pieces, whole, "case {k}, pieces of {budget} patches");
            }
        }
    }

    #[test]
    fn pieces_hold_their_rings_within_the_budget() {
        let cage = crate::mesh::shapes::quad_grid(60, 60);
        let mut around = vec![Vec::new(); cage.vertex_count()];
        for (f, face) in cage.faces().enumerate() {
            for &v in face {
                around[v as usize].push(f as u32);
            }
        }
        let whole = Subdivider::new(&cage, Scheme::CatmullClark, 0, &Default::default()).unwrap();
        let level = &whole.levels[0];
        let budget = 16 * 400;
        let all = vec![true; cage.face_count()];
        let cut = pieces(&level.faces, &level.connectivity, 2, budget, &all).unwrap();
        assert!(cut.len() > 4);
        let mut owner = vec![usize::MAX; cage.face_count()];
        for (k, piece) in cut.iter().enumerate() {
            assert!(piece.ring.len() * 16 <= budget);
            assert!(piece.ring.windows(2).all(|w| w[0] < w[1]));
            for &f in &piece.faces {
                assert_eq!(owner[f as usize], usize::MAX, "face {f} twice");
                owner[f as usize] = k;
                for &v in cage.face(f as usize) {
                    for g in &around[v as usize] {
                        assert!(piece.ring.binary_search(g).is_ok());
                    }
                }
            }
        }
        assert!(owner.iter().all(|&k| k != usize::MAX));
        // Grown breadth first, pieces are round: their rings hold well
        // under twice their faces (rows of faces would need three times).
        let faces: usize = cut.iter().map(|p| p.faces.len()).sum();
        let rings: usize = cut.iter().map(|p| p.ring.len()).sum();
        assert!(rings < 2 * faces, "{rings} ring faces for {faces} faces");
        // Around a vertex of many faces, a piece takes every face of its ring.
        let fan = crate::mesh::shapes::fan(300);
        let whole = Subdivider::new(&fan, Scheme::CatmullClark, 0, &Default::default()).unwrap();
        let level = &whole.levels[0];
        let all = vec![true; fan.face_count()];
        let cut = pieces(&level.faces, &level.connectivity, 1, 16, &all).unwrap();
        assert_eq!(cut.len(), 1);
        let error = pieces(&level.faces, &level.connectivity, 8, 16, &all);
        let Err(Error::ResultTooLarge(message)) = error else {
            panic!("{error:?}")
        };
        assert!(message.contains("has 300 faces"), "{message}");
    }

    #[test]
    fn faces_around_a_crowded_vertex_share_pieces() {
        // Each pole triangle's ring alone (the pole's 64 triangles) makes
        // more patches than the budget at isolation 3; refined a face at a
        // time, each pole would be refined 64 times.
        let sphere = crate::make::primitives::uv_sphere(1.0, 64, 32).unwrap();
        let whole = Subdivider::new(&sphere, Scheme::CatmullClark, 0, &Default::default()).unwrap();
        let level = &whole.levels[0];
        let all = vec![true; sphere.face_count()];
        let cut = pieces(&level.faces, &level.connectivity, 3, 1024, &all).unwrap();
        let at_poles = cut
            .iter()
            .filter(|p| p.faces.iter().any(|&f| sphere.face(f as usize).len() == 3))
            .count();
        assert!(at_poles <= 8, "the poles' triangles in {at_poles} pieces");
        let faces: usize = cut.iter().map(|p| p.faces.len()).sum();
        assert_eq!(faces, sphere.face_count());
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
