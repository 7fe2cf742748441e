//! The one error type of the library. Every variant says what is wrong and
//! where (which face, which corner, which vertex), so a host can show the
//! sentence to a designer as it is.

use thiserror::Error;

/// Why a mesh could not be built from the given buffers.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum MeshError {
    /// A face refers to a vertex that does not exist.
    #[error("face {face}, corner {corner}: vertex index {index} is out of range (the mesh has {vertex_count} vertices)")]
    IndexOutOfRange {
        face: usize,
        corner: usize,
        index: u32,
        vertex_count: usize,
    },
    /// A face with fewer than three corners.
    #[error("face {face} has {size} vertices; a face needs at least 3")]
    FaceTooSmall { face: usize, size: usize },
    /// The same vertex appears twice in one face.
    #[error("face {face} uses vertex {index} twice (corners {first} and {second})")]
    RepeatedIndex {
        face: usize,
        index: u32,
        first: usize,
        second: usize,
    },
    /// A coordinate is NaN or infinite.
    #[error("vertex {vertex} has a non-finite coordinate ({x}, {y}, {z})")]
    NonFiniteCoordinate {
        vertex: usize,
        x: f64,
        y: f64,
        z: f64,
    },
    /// The face sizes do not add up to the number of indices given.
    #[error("the face sizes add up to {sum} indices but {index_count} indices were given")]
    CountMismatch { sum: u64, index_count: usize },
    /// More vertices or indices than 32-bit indices can address.
    #[error("{what} count {count} exceeds the limit of {limit}")]
    TooLarge {
        what: &'static str,
        count: u64,
        limit: u64,
    },
}

/// Every failure of a Weft operation.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum Error {
    /// The input mesh (or the buffers it was to be made from) is invalid.
    #[error("invalid mesh: {0}")]
    InvalidMesh(#[from] MeshError),
    /// An argument other than the mesh is out of its domain; the text names it.
    #[error("invalid argument: {0}")]
    InvalidArgument(String),
    /// An operation that needs triangles met another polygon.
    #[error("face {face} has {size} vertices but this operation needs a triangle mesh; triangulate the mesh first")]
    NotTriangles { face: usize, size: usize },
    /// The result would pass the documented size cap or overflow 32-bit indices.
    #[error("result too large: {0}")]
    ResultTooLarge(String),
    /// Memory for the result could not be reserved.
    #[error("out of memory: {0}")]
    OutOfMemory(String),
    /// A caller's output buffer is shorter than the result; the text names
    /// it, with its length and the length needed.
    #[error("buffer too small: {0}")]
    BufferTooSmall(String),
    /// The input is geometrically degenerate for this operation (collinear points, too few points, a zero-length axis).
    #[error("degenerate input: {0}")]
    DegenerateInput(String),
}

/// The library's result type.
pub type Result<T, E = Error> = std::result::Result<T, E>;

/// Largest number of vertices, faces or indices a result may have: every index
/// must fit a `u32`, and the memory for it must stay within reach of a
/// desktop machine (2^31 indices is 8 GiB of indices alone).
pub const MAX_ELEMENTS: u64 = (1 << 31) - 1;
