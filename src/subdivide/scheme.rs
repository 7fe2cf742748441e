//! The vocabulary of subdivision, at the bottom of the module: the schemes,
//! the naked-edge modes, the vertex rules, and what one level makes of a
//! level's counts. Everything above (connectivity, rules, gathers, the
//! schemes' point rules, the refiner and the drivers) reads it; it reads
//! nothing of theirs.

use crate::error::{Error, Result, MAX_ELEMENTS};
use crate::mesh::Mesh;

/// What happens along naked edges (edges with one face), the `S` input of
/// Weaverbird's components. The values are stable (the C ABI uses them).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[repr(u32)]
pub enum NakedEdges {
    /// The boundary polyline stays: boundary vertices keep their place, new boundary vertices are edge midpoints.
    #[default]
    Fixed = 0,
    /// The boundary tends to a cubic B-spline and every boundary vertex moves (OpenSubdiv `VTX_BOUNDARY_EDGE_ONLY`).
    Smooth = 1,
    /// As Smooth, but a boundary vertex with one face stays (OpenSubdiv `VTX_BOUNDARY_EDGE_AND_CORNER`).
    CornerFixed = 2,
    /// No boundary surface: every face at a vertex on a naked edge is left
    /// out of the result as a hole, the rest refined as Smooth refines it
    /// (OpenSubdiv `VTX_BOUNDARY_NONE`). A naked edge creased infinitely
    /// sharp keeps its faces. Beyond Weaverbird's three modes.
    None = 3,
}

/// A subdivision scheme. The values are stable (the C ABI uses them).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[repr(u32)]
pub enum Scheme {
    /// Catmull-Clark: any polygons in, quads out.
    CatmullClark = 0,
    /// Loop: triangles in, triangles out.
    Loop = 1,
}

impl Scheme {
    /// The size of every refined face: quads or triangles.
    #[inline]
    pub(crate) fn refined_face_size(self) -> u32 {
        match self {
            Scheme::CatmullClark => 4,
            Scheme::Loop => 3,
        }
    }

    /// How many faces one level makes of a face of `size` corners.
    #[inline]
    pub(crate) fn children_of_face(self, size: u32) -> usize {
        match self {
            Scheme::CatmullClark => size as usize,
            Scheme::Loop => 4,
        }
    }

    /// How many faces `levels` levels make of a face of `size` corners
    /// (the face itself at level 0; every level after the first splits
    /// each face into 4).
    #[inline]
    pub(crate) fn descendants_of_face(self, size: u32, levels: usize) -> usize {
        match levels {
            0 => 1,
            _ => self.children_of_face(size) << (2 * (levels - 1)),
        }
    }

    /// The cage face of every face `levels` levels make of faces of
    /// `sizes`, in order: the children of a face are contiguous.
    pub(crate) fn parents_of(
        self,
        sizes: impl IntoIterator<Item = u32>,
        levels: usize,
    ) -> impl Iterator<Item = u32> {
        sizes.into_iter().enumerate().flat_map(move |(f, size)| {
            std::iter::repeat_n(f as u32, self.descendants_of_face(size, levels))
        })
    }

    /// How many face points a level of `face_count` faces makes: one per
    /// face for Catmull-Clark, none for Loop. The new vertices of a level
    /// are its vertex points, edge points, then these.
    #[inline]
    pub(crate) fn face_point_count(self, face_count: usize) -> usize {
        match self {
            Scheme::CatmullClark => face_count,
            Scheme::Loop => 0,
        }
    }

    /// Ring entries per neighbour of a smooth vertex in a plan:
    /// Catmull-Clark's rings hold the faces between the neighbours too.
    #[inline]
    pub(crate) fn ring_stride(self) -> usize {
        match self {
            Scheme::CatmullClark => 2,
            Scheme::Loop => 1,
        }
    }

    /// The counts of vertices, edges, faces and corners one level makes of
    /// `[v, e, f, c]`. Catmull-Clark: V' = V + E + F, E' = 2E + C, F' = C,
    /// C' = 4C. Loop: V' = V + E, E' = 2E + 3F, F' = 4F, C' = 12F.
    #[inline]
    pub(crate) fn next_counts(self, [v, e, f, c]: [u64; 4]) -> [u64; 4] {
        match self {
            Scheme::CatmullClark => [v + e + f, 2 * e + c, c, 4 * c],
            Scheme::Loop => [v + e, 2 * e + 3 * f, 4 * f, 12 * f],
        }
    }

    /// Refuses a cage this scheme cannot subdivide: Loop needs triangles.
    ///
    /// # Errors
    /// [`Error::NotTriangles`] naming the first face that is not a triangle.
    pub(crate) fn check_cage(self, cage: &Mesh) -> Result<()> {
        match (self, cage.first_non_triangle()) {
            (Scheme::Loop, Some((face, size))) => Err(Error::NotTriangles { face, size }),
            _ => Ok(()),
        }
    }
}

/// Sizes of a refined mesh.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct RefinedCounts {
    pub vertex_count: usize,
    pub face_count: usize,
    /// Sum of the face sizes.
    pub index_count: usize,
}

/// How a vertex point is made from its neighbourhood (OpenSubdiv's
/// `Sdc::Crease::Rule`, with the dart folded into smooth, which shares its mask).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[repr(u8)]
pub(crate) enum VertexRule {
    /// Interior manifold vertex: the scheme's smooth mask.
    Smooth = 0,
    /// On exactly two sharp edges: 3/4 the vertex, 1/8 each sharp neighbour.
    Crease = 1,
    /// Infinitely sharp: the vertex stays where it is.
    Corner = 2,
}

/// Loop's smooth vertex weights `(vertex, each neighbour)` for `valence`
/// neighbours (Loop 1987, as OpenSubdiv's `Scheme<SCHEME_LOOP>` computes them).
#[inline]
pub(crate) fn loop_smooth_weights(valence: usize) -> (f64, f64) {
    if valence == 6 {
        return (0.625, 0.0625);
    }
    let n = valence as f64;
    let beta = 0.25 * (std::f64::consts::TAU / n).cos() + 0.375;
    let neighbour = (0.625 - beta * beta) / n;
    (1.0 - neighbour * n, neighbour)
}

/// Checks every level's size against [`MAX_ELEMENTS`] and returns the last
/// level's vertex, face and index counts, all exact: every face has its own
/// inside edges. See [`Scheme::next_counts`].
pub(crate) fn check_counts(
    scheme: Scheme,
    vertices: u64,
    edges: u64,
    faces: u64,
    corners: u64,
    levels: u32,
) -> Result<(u64, u64, u64)> {
    let mut counts = [vertices, edges, faces, corners];
    for level in 1..=levels {
        counts = scheme.next_counts(counts);
        let [_, _, f, c] = counts;
        if counts.iter().any(|&n| n > MAX_ELEMENTS) {
            return Err(too_large(levels, level, f, c));
        }
    }
    let [v, _, f, c] = counts;
    Ok((v, f, c))
}

/// The refusal of `requested` levels whose `level` is the first past the cap.
pub(crate) fn too_large(requested: u32, level: u32, faces: u64, indices: u64) -> Error {
    let plural = if requested == 1 { "" } else { "s" };
    Error::ResultTooLarge(format!(
        "{requested} level{plural} of subdivision: level {level} would make {faces} faces \
         ({indices} face indices), past the limit of {MAX_ELEMENTS} vertices, faces or indices; \
         use at most {} levels",
        level - 1
    ))
}
