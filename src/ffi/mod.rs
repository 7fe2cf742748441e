//! The C ABI declared in `include/weft.h`: conversions, checks, statuses and
//! errors only. No geometry lives here; every export forwards to the library.
//!
//! Each file groups one family of exports; `boundary` holds the rules they
//! all follow (see its doc).

#![deny(clippy::undocumented_unsafe_blocks)]

// The modules come in the order of `include/weft.h`, since cbindgen emits
// items in the order it meets them (a comment between two keeps rustfmt
// from sorting them).

// The status, the errors and the rules every export follows.
pub mod boundary;
// The mesh handle: construction, accessors, copies, topology info.
pub mod mesh;
// Mesh files read and written as the command line does.
pub mod files;
// Points and lines matched to vertices and edges.
pub mod matching;
// Catmull-Clark, Loop, parent faces, triangulation.
pub mod subdivide;
// Refine once, evaluate many times.
pub mod refiner;
// Creases, corners and carried data (vertex data, UVs, the limit surface).
pub mod creases;
// The limit surface anywhere: evaluation with derivatives.
pub mod limit_surface;
// Creases found on a mesh: unwelded seams and folds.
pub mod crease_edges;
// The limit surface as bicubic patches, for NURBS export.
pub mod limit_patches;
// Join, weld, T-nodes, cull, normals, planarity.
pub mod mend;
// Unify, turn outward, flip.
pub mod orient;
// Delaunay, Voronoi, grids, stellate, primitives.
pub mod make;
// The rest of Weaverbird's toolbar: splits and smoothing, transforms, extracts.
pub mod toolbar;
// Offsets, thickening, windows, frames, bevels, tiles.
pub mod transform;
// The dual, edges, rerouted faces, a mesh from lines.
pub mod extract;

pub use boundary::WeftStatus;
pub use mesh::{WeftMesh, WeftMeshInfo};
