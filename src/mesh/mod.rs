//! The polygon mesh: `f64` positions and faces as sizes plus flat indices.
//!
//! Triangles, quads and n-gons may be mixed. Counter-clockwise seen from the
//! front is the front face. A `Mesh` is always valid: every constructor checks
//! its input, so operations may rely on in-range indices, faces of at least
//! three corners and finite coordinates. A face names each vertex once,
//! unless the mesh was built with [`MeshOptions::allow_repeated_vertices`]
//! (OpenSubdiv's non-manifold faces, such as `0 1 1 2`).

pub(crate) mod adjacency;
pub mod analysis;
mod buffer;
pub(crate) mod corners;
pub(crate) mod linalg;
pub mod shapes;
pub mod topology;
pub mod triangulate;

use std::sync::OnceLock;

use glam::{DVec2, DVec3};
use rayon::prelude::*;

use self::buffer::Buffer;
use crate::buffers::{advised_copy, try_copy, try_vec};
use crate::error::{Error, MeshError, Result, MAX_ELEMENTS};

/// Inputs from this many items up are copied and checked on all threads
/// (a host's buffers cross at the speed of memory, not of one core).
const PARALLEL_CHECK_ITEMS: usize = 1 << 16;
/// Items per task of those checks.
const CHECK_CHUNK: usize = 16384;

/// What a constructor accepts beyond the faces every mesh may have.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct MeshOptions {
    /// Accept faces that name a vertex more than once (`0 1 1 2`,
    /// `0 1 2 1 3`), which OpenSubdiv subdivides as non-manifold topology.
    /// Off by default, since such a face is most often broken input.
    pub allow_repeated_vertices: bool,
}

/// A validated polygon mesh.
#[derive(Debug, Clone, Default)]
pub struct Mesh {
    positions: Buffer<DVec3>,
    face_indices: Buffer<u32>,
    faces: FaceLayout,
}

/// How the flat indices split into faces. When every face has the same
/// size (every refined level, most scanned meshes), a face's corners are
/// arithmetic, and the sizes and offsets arrays are written only if asked
/// for: a subdivided mesh does not pay for them.
#[derive(Debug, Clone, Default)]
struct FaceLayout {
    count: usize,
    /// `Some(k)` when there are faces and each has k corners.
    uniform: Option<u32>,
    sizes: OnceLock<Vec<u32>>,
    /// `offsets[f]..offsets[f + 1]` are face f's corners; one longer than `sizes`.
    offsets: OnceLock<Vec<u32>>,
}

impl FaceLayout {
    /// The layout of `sizes`: uniform when they are all equal, else with
    /// the offsets written.
    fn of_sizes(sizes: Vec<u32>) -> FaceLayout {
        let count = sizes.len();
        match uniform_size(&sizes) {
            Some(size) => FaceLayout {
                count,
                uniform: Some(size),
                sizes: OnceLock::from(sizes),
                offsets: OnceLock::new(),
            },
            None => FaceLayout {
                count,
                uniform: None,
                offsets: OnceLock::from(offsets(&sizes)),
                sizes: OnceLock::from(sizes),
            },
        }
    }

    /// The layout of sizes a host lends: none kept when uniform, else copied.
    fn of_lent_sizes(sizes: &[u32]) -> FaceLayout {
        match uniform_size(sizes) {
            Some(size) => FaceLayout::uniform(sizes.len(), size),
            None => FaceLayout::of_sizes(advised_copy(sizes)),
        }
    }

    fn uniform(count: usize, size: u32) -> FaceLayout {
        FaceLayout {
            count,
            uniform: (count > 0).then_some(size),
            ..FaceLayout::default()
        }
    }

    fn sizes(&self) -> &[u32] {
        self.sizes.get_or_init(|| match self.uniform {
            Some(size) => {
                let mut sizes = Vec::with_capacity(self.count);
                sizes.par_extend(rayon::iter::repeat_n(size, self.count).with_min_len(CHECK_CHUNK));
                sizes
            }
            None => Vec::new(),
        })
    }

    fn offsets(&self) -> &[u32] {
        self.offsets.get_or_init(|| match self.uniform {
            Some(size) => {
                let mut offsets = Vec::with_capacity(self.count + 1);
                offsets.par_extend(
                    (0..self.count as u32 + 1)
                        .into_par_iter()
                        .with_min_len(CHECK_CHUNK)
                        .map(|f| f * size),
                );
                offsets
            }
            None => offsets(self.sizes()),
        })
    }

    /// Where face `f`'s corners start (for `f` = the count, where they end).
    #[inline]
    fn start(&self, f: usize) -> usize {
        match self.uniform {
            Some(size) => f * size as usize,
            None => self.offsets()[f] as usize,
        }
    }

    #[inline]
    fn range(&self, f: usize) -> std::ops::Range<usize> {
        self.start(f)..self.start(f + 1)
    }

    fn into_sizes(self) -> Vec<u32> {
        self.sizes();
        self.sizes.into_inner().unwrap_or_default()
    }
}

impl PartialEq for FaceLayout {
    fn eq(&self, other: &FaceLayout) -> bool {
        // Equal sizes have the same uniformity: compare arrays only when mixed.
        self.count == other.count
            && self.uniform == other.uniform
            && (self.uniform.is_some() || self.sizes() == other.sizes())
    }
}

impl PartialEq for Mesh {
    fn eq(&self, other: &Mesh) -> bool {
        *self.positions == *other.positions
            && *self.face_indices == *other.face_indices
            && self.faces == other.faces
    }
}

impl Mesh {
    /// The empty mesh: no vertices, no faces.
    pub fn empty() -> Mesh {
        Mesh::default()
    }

    /// Builds a mesh from positions, one size per face and the faces' vertex
    /// indices one after another.
    ///
    /// # Errors
    /// [`MeshError`] naming the first face, corner or vertex that is wrong.
    pub fn new(
        positions: Vec<DVec3>,
        face_sizes: Vec<u32>,
        face_indices: Vec<u32>,
    ) -> Result<Mesh, MeshError> {
        Mesh::new_with(positions, face_sizes, face_indices, MeshOptions::default())
    }

    /// As [`Mesh::new`], accepting what `options` allows.
    ///
    /// # Errors
    /// As [`Mesh::new`].
    pub fn new_with(
        positions: Vec<DVec3>,
        face_sizes: Vec<u32>,
        face_indices: Vec<u32>,
        options: MeshOptions,
    ) -> Result<Mesh, MeshError> {
        check_counts(positions.len(), &face_sizes, face_indices.len())?;
        check_positions(&positions)?;
        let mesh = Mesh::with_offsets(positions, face_sizes, face_indices);
        mesh.check_faces(options.allow_repeated_vertices)?;
        Ok(mesh)
    }

    /// Builds a mesh from flat `x, y, z` coordinates (three per vertex).
    ///
    /// # Errors
    /// As [`Mesh::new`]; a coordinate count that is not a multiple of 3 is a
    /// [`MeshError::CountMismatch`].
    pub fn from_flat(
        coordinates: &[f64],
        face_sizes: &[u32],
        face_indices: &[u32],
    ) -> Result<Mesh, MeshError> {
        Mesh::from_flat_with(
            coordinates,
            face_sizes,
            face_indices,
            MeshOptions::default(),
        )
    }

    /// As [`Mesh::from_flat`], accepting what `options` allows.
    ///
    /// # Errors
    /// As [`Mesh::from_flat`].
    pub fn from_flat_with(
        coordinates: &[f64],
        face_sizes: &[u32],
        face_indices: &[u32],
        options: MeshOptions,
    ) -> Result<Mesh, MeshError> {
        if coordinates.len() % 3 != 0 {
            return Err(MeshError::CountMismatch {
                sum: (coordinates.len() / 3 * 3) as u64,
                index_count: coordinates.len(),
            });
        }
        // Check sizes before copying so a huge count fails without allocating.
        check_counts(coordinates.len() / 3, face_sizes, face_indices.len())?;
        // Three f64 are a DVec3: one block copy.
        let positions = advised_copy(bytemuck::cast_slice::<f64, DVec3>(coordinates));
        Mesh::new_with(
            positions,
            advised_copy(face_sizes),
            advised_copy(face_indices),
            options,
        )
    }

    /// A mesh that reads a host's arrays in place, checked as
    /// [`Mesh::new_with`] checks them; the sizes are copied only when they
    /// differ. Whatever writes to the mesh, or clones it, copies first.
    /// For the C ABI, whose caller promises that the arrays outlive the mesh
    /// unchanged (the `'static`).
    ///
    /// # Errors
    /// As [`Mesh::new`].
    pub(crate) fn borrowing(
        positions: &'static [DVec3],
        face_sizes: &[u32],
        face_indices: &'static [u32],
        options: MeshOptions,
    ) -> Result<Mesh, MeshError> {
        check_counts(positions.len(), face_sizes, face_indices.len())?;
        check_positions(positions)?;
        let mesh = Mesh {
            positions: Buffer::Lent(positions),
            face_indices: Buffer::Lent(face_indices),
            faces: FaceLayout::of_lent_sizes(face_sizes),
        };
        mesh.check_faces(options.allow_repeated_vertices)?;
        Ok(mesh)
    }

    /// Builds a mesh from a list of polygons, each a list of vertex indices.
    ///
    /// # Errors
    /// As [`Mesh::new`].
    pub fn from_polygons<F: AsRef<[u32]>>(
        positions: Vec<DVec3>,
        polygons: impl IntoIterator<Item = F>,
    ) -> Result<Mesh, MeshError> {
        Mesh::from_polygons_with(positions, polygons, MeshOptions::default())
    }

    /// As [`Mesh::from_polygons`], accepting what `options` allows.
    ///
    /// # Errors
    /// As [`Mesh::new`].
    pub fn from_polygons_with<F: AsRef<[u32]>>(
        positions: Vec<DVec3>,
        polygons: impl IntoIterator<Item = F>,
        options: MeshOptions,
    ) -> Result<Mesh, MeshError> {
        let mut face_sizes = Vec::new();
        let mut face_indices = Vec::new();
        for polygon in polygons {
            let polygon = polygon.as_ref();
            face_sizes.push(u32::try_from(polygon.len()).unwrap_or(u32::MAX));
            face_indices.extend_from_slice(polygon);
        }
        Mesh::new_with(positions, face_sizes, face_indices, options)
    }

    /// Builds a mesh from parts an operation has produced itself and knows to
    /// be valid. Checked in debug builds only.
    pub(crate) fn from_valid_parts(
        positions: Vec<DVec3>,
        face_sizes: Vec<u32>,
        face_indices: Vec<u32>,
    ) -> Mesh {
        let mesh = Mesh::with_offsets(positions, face_sizes, face_indices);
        debug_assert!(check_counts(
            mesh.positions.len(),
            mesh.face_sizes(),
            mesh.face_indices.len()
        )
        .is_ok());
        debug_assert_eq!(mesh.check_faces(true), Ok(()));
        mesh
    }

    /// The parts with each face's offset into `face_indices`, unchecked.
    fn with_offsets(positions: Vec<DVec3>, face_sizes: Vec<u32>, face_indices: Vec<u32>) -> Mesh {
        Mesh {
            positions: positions.into(),
            face_indices: face_indices.into(),
            faces: FaceLayout::of_sizes(face_sizes),
        }
    }

    /// As [`Mesh::from_valid_parts`], for faces all of `size` corners (a
    /// refined level): no sizes or offsets are written unless asked for.
    pub(crate) fn from_valid_uniform_parts(
        positions: Vec<DVec3>,
        size: u32,
        face_indices: Vec<u32>,
    ) -> Result<Mesh, crate::Error> {
        let face_count = face_indices.len() / size as usize;
        let mesh = Mesh {
            positions: positions.into(),
            face_indices: face_indices.into(),
            faces: FaceLayout::uniform(face_count, size),
        };
        debug_assert_eq!(mesh.face_offsets(), offsets(mesh.face_sizes()));
        debug_assert_eq!(mesh.check_faces(true), Ok(()));
        Ok(mesh)
    }

    /// Number of vertices.
    #[inline]
    pub fn vertex_count(&self) -> usize {
        self.positions.len()
    }

    /// Number of faces.
    #[inline]
    pub fn face_count(&self) -> usize {
        self.faces.count
    }

    /// Number of face corners (the length of [`Mesh::face_indices`]).
    #[inline]
    pub fn index_count(&self) -> usize {
        self.face_indices.len()
    }

    /// The vertex positions.
    #[inline]
    pub fn positions(&self) -> &[DVec3] {
        &self.positions
    }

    /// Whether the mesh reads a host's arrays in place (`weft_mesh_new_borrowed`).
    pub fn is_borrowed(&self) -> bool {
        self.positions.is_lent() || self.face_indices.is_lent()
    }

    /// The number of corners of each face.
    #[inline]
    pub fn face_sizes(&self) -> &[u32] {
        self.faces.sizes()
    }

    /// Every face's vertex indices, one face after another.
    #[inline]
    pub fn face_indices(&self) -> &[u32] {
        &self.face_indices
    }

    /// Where each face starts in [`Mesh::face_indices`], plus the total at the end.
    #[inline]
    pub fn face_offsets(&self) -> &[u32] {
        self.faces.offsets()
    }

    /// Where face `f`'s corners start in [`Mesh::face_indices`] (arithmetic
    /// when the faces have one size: no offsets are written).
    #[inline]
    pub fn face_start(&self, f: usize) -> usize {
        self.faces.start(f)
    }

    /// The vertex indices of face `f`.
    ///
    /// # Panics
    /// When `f` is not below [`Mesh::face_count`].
    #[inline]
    pub fn face(&self, f: usize) -> &[u32] {
        &self.face_indices[self.faces.range(f)]
    }

    /// The faces in order, each as its vertex indices.
    pub fn faces(&self) -> impl ExactSizeIterator<Item = &[u32]> + '_ {
        (0..self.faces.count).map(move |f| self.face(f))
    }

    /// The positions of face `f`'s corners.
    pub fn face_positions(&self, f: usize) -> impl ExactSizeIterator<Item = DVec3> + '_ {
        self.face(f)
            .iter()
            .map(move |&v| self.positions[v as usize])
    }

    /// The number of corners every face has, when there are faces and they
    /// all have the same number.
    pub fn uniform_face_size(&self) -> Option<usize> {
        self.faces.uniform.map(|size| size as usize)
    }

    /// Whether no vertex is named by two corners, of one face or of two: a
    /// mesh as STL stores it, each triangle with corners of its own, whose
    /// faces share no edge until welded. Stops at the first vertex named
    /// twice, which a mesh with shared vertices meets within its first faces.
    pub fn corners_share_no_vertex(&self) -> bool {
        let indices = self.face_indices();
        if indices.len() > self.vertex_count() {
            return false;
        }
        // As an STL file is read: corner k names vertex k. Checked in
        // blocks, which vectorise, before the general walk.
        let numbered_in_order = indices
            .par_chunks(1 << 16)
            .enumerate()
            .all(|(block, chunk)| {
                let first = (block << 16) as u32;
                chunk
                    .iter()
                    .zip(first..)
                    .fold(true, |all, (&v, k)| all & (v == k))
            });
        if numbered_in_order {
            return true;
        }
        let mut named = vec![0u64; self.vertex_count().div_ceil(64)];
        indices.iter().all(|&v| {
            let (word, bit) = (v as usize / 64, 1u64 << (v % 64));
            let fresh = named[word] & bit == 0;
            named[word] |= bit;
            fresh
        })
    }

    /// Whether every face is a triangle (true for the empty mesh).
    pub fn is_triangle_mesh(&self) -> bool {
        self.face_count() == 0 || self.faces.uniform == Some(3)
    }

    /// Whether every face is a quad (true for the empty mesh).
    pub fn is_quad_mesh(&self) -> bool {
        self.face_count() == 0 || self.faces.uniform == Some(4)
    }

    /// The first face that is not a triangle, with its size.
    pub fn first_non_triangle(&self) -> Option<(usize, usize)> {
        match self.faces.uniform {
            Some(3) => None,
            Some(size) => Some((0, size as usize)),
            None => {
                let sizes = self.face_sizes();
                sizes
                    .iter()
                    .position(|&s| s != 3)
                    .map(|f| (f, sizes[f] as usize))
            }
        }
    }

    /// The first vertex with a NaN or infinite coordinate (only a result
    /// of arithmetic that overflowed can have one), scanned on all threads.
    pub fn first_non_finite_vertex(&self) -> Option<usize> {
        first_non_finite(&self.positions)
    }

    /// Replaces the positions, keeping the faces.
    ///
    /// # Errors
    /// A count that differs from the vertex count, or a non-finite coordinate.
    pub fn with_positions(&self, positions: Vec<DVec3>) -> Result<Mesh, MeshError> {
        if positions.len() != self.positions.len() {
            return Err(MeshError::CountMismatch {
                sum: self.positions.len() as u64,
                index_count: positions.len(),
            });
        }
        check_positions(&positions)?;
        Ok(Mesh {
            positions: positions.into(),
            ..self.clone()
        })
    }

    /// Mutable positions: faces stay as they are. The caller keeps them finite.
    pub fn positions_mut(&mut self) -> &mut [DVec3] {
        self.positions.to_mut()
    }

    /// The face offsets beside mutable face indices. The caller only
    /// reorders corners within a face, so every face keeps its vertices
    /// (what `flip` and `orient_outward` do in place).
    pub(crate) fn offsets_and_face_indices_mut(&mut self) -> (&[u32], &mut [u32]) {
        (self.faces.offsets(), self.face_indices.to_mut())
    }

    /// A copy of the face sizes, reserved fallibly. Sizes the mesh finds by
    /// arithmetic (every face of one size) are written for the copy only,
    /// not kept in the mesh as [`Mesh::face_sizes`] keeps them.
    pub(crate) fn try_copy_face_sizes(&self, what: &str) -> Result<Vec<u32>> {
        match (self.faces.uniform, self.faces.sizes.get()) {
            (Some(size), None) => {
                let mut sizes = try_vec(self.faces.count, what)?;
                sizes.resize(self.faces.count, size);
                Ok(sizes)
            }
            _ => try_copy(self.face_sizes(), what),
        }
    }

    /// Takes the mesh apart into positions, face sizes and face indices.
    pub fn into_parts(self) -> (Vec<DVec3>, Vec<u32>, Vec<u32>) {
        (
            self.positions.into_vec(),
            self.faces.into_sizes(),
            self.face_indices.into_vec(),
        )
    }

    /// The axis-aligned bounding box `(min, max)`, or `None` without vertices.
    pub fn bounding_box(&self) -> Option<(DVec3, DVec3)> {
        bounding_box_of(self.positions())
    }

    /// Checks every face; the error names the first bad one. Blocks of
    /// faces are checked on all threads and the first failing face is the
    /// one reported, as a pass in order would. Repeated vertices are
    /// refused unless `allow_repeats`.
    fn check_faces(&self, allow_repeats: bool) -> Result<(), MeshError> {
        let vertex_count = self.positions.len();
        let face_count = self.face_count();
        // The first face of `faces` that fails, read in order; triangles and
        // quads first in one pass without early exit, which vectorises.
        let first_failing = |faces: std::ops::Range<usize>| {
            let corners = |size: usize| &self.face_indices[faces.start * size..faces.end * size];
            let all_pass = match self.faces.uniform {
                Some(3) => bytemuck::cast_slice::<u32, [u32; 3]>(corners(3))
                    .iter()
                    .fold(true, |all, t| all & quick_face_check(t, vertex_count)),
                Some(4) => bytemuck::cast_slice::<u32, [u32; 4]>(corners(4))
                    .iter()
                    .fold(true, |all, q| all & quick_face_check(q, vertex_count)),
                _ => false,
            };
            if all_pass {
                return None;
            }
            for face in faces {
                let corners = self.face(face);
                if !quick_face_check(corners, vertex_count)
                    && face_error(face, corners, vertex_count, allow_repeats).is_err()
                {
                    return Some(face);
                }
            }
            None
        };
        let first_bad = if face_count < PARALLEL_CHECK_ITEMS {
            first_failing(0..face_count)
        } else {
            (0..face_count.div_ceil(CHECK_CHUNK))
                .into_par_iter()
                .find_map_first(|block| {
                    first_failing(block * CHECK_CHUNK..((block + 1) * CHECK_CHUNK).min(face_count))
                })
        };
        match first_bad {
            Some(face) => face_error(face, self.face(face), vertex_count, allow_repeats),
            None => Ok(()),
        }
    }
}

/// One pass over the common small faces: indices in range and no vertex
/// named twice. False for anything else, which [`face_error`] then reads
/// in detail.
#[inline]
fn quick_face_check(corners: &[u32], vertex_count: usize) -> bool {
    match *corners {
        [a, b, c] => (a.max(b).max(c) as usize) < vertex_count && a != b && b != c && a != c,
        [a, b, c, d] => {
            (a.max(b).max(c).max(d) as usize) < vertex_count
                && a != b
                && a != c
                && a != d
                && b != c
                && b != d
                && c != d
        }
        _ => false,
    }
}

/// The error of a face that failed the quick check (or of any other
/// face), naming the first problem: too few corners, an index out of range,
/// a repeated vertex.
fn face_error(
    face: usize,
    corners: &[u32],
    vertex_count: usize,
    allow_repeats: bool,
) -> Result<(), MeshError> {
    if corners.len() < 3 {
        return Err(MeshError::FaceTooSmall {
            face,
            size: corners.len(),
        });
    }
    if let Some(corner) = corners.iter().position(|&i| i as usize >= vertex_count) {
        return Err(MeshError::IndexOutOfRange {
            face,
            corner,
            index: corners[corner],
            vertex_count,
        });
    }
    match repeated_corner(corners).filter(|_| !allow_repeats) {
        Some((first, second)) => Err(MeshError::RepeatedIndex {
            face,
            index: corners[first],
            first,
            second,
        }),
        None => Ok(()),
    }
}

/// The first two corners of a polygon that name the same vertex.
pub(crate) fn repeated_corner(corners: &[u32]) -> Option<(usize, usize)> {
    if corners.len() <= 16 {
        for i in 0..corners.len() {
            for j in i + 1..corners.len() {
                if corners[i] == corners[j] {
                    return Some((i, j));
                }
            }
        }
        return None;
    }
    // Large n-gons: sort to stay O(n log n).
    let mut sorted: Vec<(u32, usize)> = corners.iter().copied().zip(0..).collect();
    sorted.sort_unstable();
    sorted
        .windows(2)
        .filter(|w| w[0].0 == w[1].0)
        .map(|w| (w[0].1.min(w[1].1), w[0].1.max(w[1].1)))
        .min_by_key(|&(_, second)| second)
}

/// `q.floor() as i64`, without the call to `floor` that the x86-64
/// baseline (no SSE4.1 rounding instruction) makes: the truncation, one
/// less when it rounded up.
#[inline]
pub(crate) fn floor_to_i64(q: f64) -> i64 {
    let truncated = q as i64;
    truncated.saturating_sub(i64::from(truncated as f64 > q))
}

/// The bounding box `(min, max)` of points in a plane; for none, the
/// empty box from +∞ to −∞.
pub(crate) fn bounds_2d(points: &[DVec2]) -> (DVec2, DVec2) {
    points.iter().fold(
        (DVec2::splat(f64::INFINITY), DVec2::splat(f64::NEG_INFINITY)),
        |(low, high), &p| (low.min(p), high.max(p)),
    )
}

/// The axis-aligned bounding box `(min, max)` of `points`, or `None` for
/// none; blocks of points on all threads (minima and maxima do not depend
/// on the order they are taken in).
pub(crate) fn bounding_box_of(points: &[DVec3]) -> Option<(DVec3, DVec3)> {
    let first = *points.first()?;
    let join = |(lo_a, hi_a): (DVec3, DVec3), (lo_b, hi_b): (DVec3, DVec3)| {
        (lo_a.min(lo_b), hi_a.max(hi_b))
    };
    Some(
        points
            .par_iter()
            .with_min_len(CHECK_CHUNK)
            .fold(|| (first, first), |bounds, &p| join(bounds, (p, p)))
            .reduce(|| (first, first), join),
    )
}

/// Checks the vertex, face and index counts of a mesh to be built against
/// [`MAX_ELEMENTS`], from the counts alone: the C ABI calls it before it
/// views a caller's buffers, so a count past the cap never becomes a slice.
pub(crate) fn check_element_counts(
    vertex_count: usize,
    face_count: usize,
    index_count: usize,
) -> Result<(), MeshError> {
    for (what, count) in [
        ("vertex", vertex_count),
        ("index", index_count),
        ("face", face_count),
    ] {
        if count as u64 > MAX_ELEMENTS {
            return Err(MeshError::TooLarge {
                what,
                count: count as u64,
                limit: MAX_ELEMENTS,
            });
        }
    }
    Ok(())
}

fn check_counts(
    vertex_count: usize,
    face_sizes: &[u32],
    index_count: usize,
) -> Result<(), MeshError> {
    check_element_counts(vertex_count, face_sizes.len(), index_count)?;
    let sum: u64 = if face_sizes.len() < PARALLEL_CHECK_ITEMS {
        face_sizes.iter().map(|&s| s as u64).sum()
    } else {
        face_sizes
            .par_chunks(CHECK_CHUNK)
            .map(|block| block.iter().map(|&s| s as u64).sum::<u64>())
            .sum()
    };
    if sum != index_count as u64 {
        return Err(MeshError::CountMismatch { sum, index_count });
    }
    Ok(())
}

/// The first of `positions` with a NaN or infinite coordinate, scanned on
/// all threads.
pub(crate) fn first_non_finite(positions: &[DVec3]) -> Option<usize> {
    match check_positions(positions) {
        Err(MeshError::NonFiniteCoordinate { vertex, .. }) => Some(vertex),
        _ => None,
    }
}

fn check_positions(positions: &[DVec3]) -> Result<(), MeshError> {
    // A flat scan the compiler vectorises; the vertex only on failure.
    let coordinates: &[f64] = bytemuck::cast_slice(positions);
    let finite = if coordinates.len() < PARALLEL_CHECK_ITEMS {
        coordinates.iter().all(|x| x.is_finite())
    } else {
        // A fold without early exit, so that it vectorises.
        coordinates
            .par_chunks(CHECK_CHUNK)
            .all(|block| block.iter().fold(true, |all, x| all & x.is_finite()))
    };
    if finite {
        return Ok(());
    }
    let vertex = positions.iter().position(|p| !p.is_finite()).unwrap_or(0);
    let p = positions[vertex];
    Err(MeshError::NonFiniteCoordinate {
        vertex,
        x: p.x,
        y: p.y,
        z: p.z,
    })
}

/// The size every face has, when there are faces and they all have one.
fn uniform_size(face_sizes: &[u32]) -> Option<u32> {
    let size = *face_sizes.first()?;
    let same = if face_sizes.len() < PARALLEL_CHECK_ITEMS {
        face_sizes.iter().all(|&s| s == size)
    } else {
        // A fold without early exit, so that it vectorises.
        face_sizes
            .par_chunks(CHECK_CHUNK)
            .all(|block| block.iter().fold(true, |all, &s| all & (s == size)))
    };
    same.then_some(size)
}

fn offsets(face_sizes: &[u32]) -> Vec<u32> {
    let mut offsets = Vec::with_capacity(face_sizes.len() + 1);
    let mut total = 0u32;
    offsets.push(0);
    for &s in face_sizes {
        total += s;
        offsets.push(total);
    }
    offsets
}

/// Checks a distance tolerance (weld, T-nodes, planarity): finite and not
/// negative.
pub(crate) fn check_tolerance(tolerance: f64) -> Result<()> {
    if tolerance.is_finite() && tolerance >= 0.0 {
        Ok(())
    } else {
        Err(Error::InvalidArgument(format!(
            "tolerance is {tolerance}; it must be a finite distance of 0 or more"
        )))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::shapes;

    /// A torus large enough for the parallel checks, as flat buffers.
    fn large_torus() -> (Vec<f64>, Vec<u32>, Vec<u32>) {
        let torus = shapes::torus(300, 300);
        assert!(torus.face_count() >= 4 * PARALLEL_CHECK_ITEMS / 3);
        let coordinates = bytemuck::cast_slice(torus.positions()).to_vec();
        let (_, sizes, indices) = torus.into_parts();
        (coordinates, sizes, indices)
    }

    #[test]
    fn corners_share_no_vertex_in_order_out_of_order_or_after_many_blocks() {
        // Triangles over 3n vertices, corner k naming `order(k)`; long
        // enough for several of the in-order check's blocks.
        let soup = |n: usize, order: &dyn Fn(usize) -> u32| {
            let positions = (0..3 * n).map(|k| DVec3::splat(k as f64)).collect();
            let indices = (0..3 * n).map(order).collect();
            Mesh::new(positions, vec![3; n], indices).unwrap()
        };
        let n = 100_000;
        assert!(soup(n, &|k| k as u32).corners_share_no_vertex());
        // Each triangle's corners turned: no vertex named twice, not in order.
        let turned = |k: usize| (k - k % 3 + (k + 1) % 3) as u32;
        assert!(soup(n, &turned).corners_share_no_vertex());
        // In order but for the last triangle, which names the first vertex
        // (its own third vertex is unused).
        let last = 3 * n - 1;
        let repeat_at_end = |k: usize| if k == last { 0 } else { k as u32 };
        assert!(!soup(n, &repeat_at_end).corners_share_no_vertex());
        // A shared vertex in the second block only.
        let shared = |k: usize| if k == 70_000 { 69_998 } else { k as u32 };
        assert!(!soup(n, &shared).corners_share_no_vertex());
        assert!(!shapes::cube().corners_share_no_vertex());
    }

    #[test]
    fn copied_face_sizes_of_uniform_faces_are_not_kept_in_the_mesh() {
        // Built as a refined level is, without the debug build's checks
        // (which read the sizes).
        let cube = shapes::cube();
        let quads = Mesh {
            positions: cube.positions().to_vec().into(),
            face_indices: cube.face_indices().to_vec().into(),
            faces: FaceLayout::uniform(6, 4),
        };
        assert!(quads.faces.sizes.get().is_none());
        assert_eq!(quads.try_copy_face_sizes("sizes").unwrap(), vec![4; 6]);
        assert!(quads.faces.sizes.get().is_none());
        // Mixed sizes, and sizes already written, are copied as they stand.
        let mixed = shapes::mixed_polygons();
        assert_eq!(
            mixed.try_copy_face_sizes("sizes").unwrap(),
            mixed.face_sizes()
        );
        assert_eq!(quads.face_sizes(), &[4; 6]);
        assert_eq!(quads.try_copy_face_sizes("sizes").unwrap(), vec![4; 6]);
        assert_eq!(
            Mesh::empty().try_copy_face_sizes("sizes").unwrap(),
            Vec::<u32>::new()
        );
    }

    #[test]
    fn parallel_checks_report_the_first_bad_face() {
        let (coordinates, sizes, mut indices) = large_torus();
        let vertex_count = coordinates.len() / 3;
        // A late face in another block, then an earlier one: the earlier is named.
        indices[4 * 80_000 + 2] = vertex_count as u32 + 7;
        assert_eq!(
            Mesh::from_flat(&coordinates, &sizes, &indices),
            Err(MeshError::IndexOutOfRange {
                face: 80_000,
                corner: 2,
                index: vertex_count as u32 + 7,
                vertex_count,
            })
        );
        indices[4 * 20_001 + 3] = indices[4 * 20_001];
        assert!(matches!(
            Mesh::from_flat(&coordinates, &sizes, &indices),
            Err(MeshError::RepeatedIndex {
                face: 20_001,
                first: 0,
                second: 3,
                ..
            })
        ));
        // Accepted repeats are passed over, the index past the end is not.
        assert!(matches!(
            Mesh::from_flat_with(
                &coordinates,
                &sizes,
                &indices,
                MeshOptions {
                    allow_repeated_vertices: true
                }
            ),
            Err(MeshError::IndexOutOfRange { face: 80_000, .. })
        ));
    }

    #[test]
    fn parallel_checks_find_non_finite_coordinates_and_count_mismatches() {
        let (mut coordinates, mut sizes, indices) = large_torus();
        coordinates[3 * 70_000 + 1] = f64::NAN;
        assert!(matches!(
            Mesh::from_flat(&coordinates, &sizes, &indices),
            Err(MeshError::NonFiniteCoordinate { vertex: 70_000, .. })
        ));
        coordinates[3 * 70_000 + 1] = 0.0;
        sizes[50_000] = 5;
        assert!(matches!(
            Mesh::from_flat(&coordinates, &sizes, &indices),
            Err(MeshError::CountMismatch { .. })
        ));
    }

    #[test]
    fn large_meshes_keep_their_offsets() {
        let (coordinates, _, indices) = large_torus();
        let uniform = Mesh::from_flat(&coordinates, &vec![4; indices.len() / 4], &indices).unwrap();
        assert_eq!(
            uniform.face_offsets(),
            offsets_in_order(uniform.face_sizes())
        );
        // Mixed sizes: the quads' corners regrouped as triangles and a hexagon.
        let mut sizes = vec![4u32; indices.len() / 4];
        sizes.truncate(sizes.len() - 3);
        sizes.extend([3, 3, 6]);
        let triangles: Vec<u32> = indices[..indices.len() - 12].to_vec();
        let mut mixed = triangles.clone();
        mixed.extend([0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11]);
        let mesh = Mesh::from_flat(&coordinates, &sizes, &mixed).unwrap();
        assert_eq!(mesh.face_offsets(), offsets_in_order(&sizes));
        assert_eq!(mesh.face(mesh.face_count() - 1), &[6, 7, 8, 9, 10, 11]);
    }

    fn offsets_in_order(sizes: &[u32]) -> Vec<u32> {
        std::iter::once(0)
            .chain(sizes.iter().scan(0, |total, &s| {
                *total += s;
                Some(*total)
            }))
            .collect()
    }

    fn square() -> Vec<DVec3> {
        vec![
            DVec3::new(0.0, 0.0, 0.0),
            DVec3::new(1.0, 0.0, 0.0),
            DVec3::new(1.0, 1.0, 0.0),
            DVec3::new(0.0, 1.0, 0.0),
        ]
    }

    #[test]
    fn mixed_faces_are_kept_in_order() {
        let mesh = Mesh::from_polygons(square(), [vec![0, 1, 2], vec![0, 2, 3]]).unwrap();
        assert_eq!(mesh.face_count(), 2);
        assert_eq!(mesh.face(1), &[0, 2, 3]);
        assert_eq!(mesh.face_offsets(), &[0, 3, 6]);
        assert!(mesh.is_triangle_mesh());
    }

    #[test]
    fn each_bad_input_names_its_place() {
        let err = Mesh::from_polygons(square(), [vec![0, 1, 2], vec![0, 2, 9]]).unwrap_err();
        assert_eq!(
            err,
            MeshError::IndexOutOfRange {
                face: 1,
                corner: 2,
                index: 9,
                vertex_count: 4
            }
        );
        let err = Mesh::from_polygons(square(), [vec![0, 1]]).unwrap_err();
        assert_eq!(err, MeshError::FaceTooSmall { face: 0, size: 2 });
        let err = Mesh::from_polygons(square(), [vec![0, 1, 2, 1]]).unwrap_err();
        assert_eq!(
            err,
            MeshError::RepeatedIndex {
                face: 0,
                index: 1,
                first: 1,
                second: 3
            }
        );
        let mut p = square();
        p[2].y = f64::NAN;
        let err = Mesh::from_polygons(p, [vec![0, 1, 2]]).unwrap_err();
        assert!(matches!(
            err,
            MeshError::NonFiniteCoordinate { vertex: 2, .. }
        ));
        assert!(err.to_string().contains("vertex 2"));
        let err = Mesh::new(square(), vec![3, 3], vec![0, 1, 2]).unwrap_err();
        assert_eq!(
            err,
            MeshError::CountMismatch {
                sum: 6,
                index_count: 3
            }
        );
    }

    #[test]
    fn repeated_index_in_a_large_ngon_is_found() {
        let positions: Vec<DVec3> = (0..40).map(|i| DVec3::new(i as f64, 0.0, 0.0)).collect();
        let mut polygon: Vec<u32> = (0..40).collect();
        polygon[30] = 7;
        let err = Mesh::from_polygons(positions, [polygon]).unwrap_err();
        assert_eq!(
            err,
            MeshError::RepeatedIndex {
                face: 0,
                index: 7,
                first: 7,
                second: 30
            }
        );
    }

    #[test]
    fn empty_mesh_is_valid() {
        let mesh = Mesh::new(vec![], vec![], vec![]).unwrap();
        assert_eq!(mesh, Mesh::empty());
        assert_eq!(mesh.faces().count(), 0);
        assert!(mesh.bounding_box().is_none());
    }
}
