//! Weft: subdivision surfaces and mesh tools for computational design.
//!
//! The crate's map:
//! - [`mesh`]: the polygon mesh (`f64` positions, faces as sizes plus flat
//!   indices) and its validation; [`error`]: the one error type.
//! - [`topology`]: edges, adjacency, naked and non-manifold parts, components,
//!   orientability. [`shapes`]: named shapes built in code.
//! - [`subdivide`]: Catmull-Clark and Loop with the naked-edge modes, and the
//!   refiner that re-evaluates new positions on a fixed topology.
//! - Mending: [`weld`] (join, weld), [`t_nodes`], [`cull`], [`orient`],
//!   [`analysis`] (normals, planarity, boundaries), [`triangulate`].
//! - Making: [`plane`], [`delaunay`], [`voronoi`], [`grid`], [`stellate`], [`primitives`].
//! - The rest of Weaverbird's toolbar: [`split`] (linear subdivisions),
//!   [`smooth`], [`transform`] (offset, thicken, window, bevel) and
//!   [`extract`] (dual, edges, reroute, mesh from lines), [`tile`] (faces
//!   re-filled by fans, strips and stitches).
//! - [`io`]: mesh files (OBJ, PLY, STL, OFF) and pictures, for the `weft` command.
//! - `ffi`: the C ABI declared in `include/weft.h`. It only converts and
//!   checks; the geometry knows nothing of it.
//!
//! Everything outside `ffi` is safe Rust.
#![deny(unsafe_code)]
#![deny(unsafe_op_in_unsafe_fn)]

/// cbindgen:ignore
pub mod analysis;
/// cbindgen:ignore
pub mod cull;
/// cbindgen:ignore
pub mod delaunay;
/// cbindgen:ignore
pub mod error;
/// cbindgen:ignore
pub mod extract;
/// cbindgen:ignore
pub mod grid;
/// cbindgen:ignore
pub mod io;
mod linalg;
/// cbindgen:ignore
pub mod mesh;
/// cbindgen:ignore
pub mod orient;
/// cbindgen:ignore
pub mod plane;
/// cbindgen:ignore
pub mod primitives;
/// cbindgen:ignore
pub mod shapes;
/// cbindgen:ignore
pub mod smooth;
/// cbindgen:ignore
pub mod split;
/// cbindgen:ignore
pub mod stellate;
/// cbindgen:ignore
pub mod subdivide;
/// cbindgen:ignore
pub mod t_nodes;
/// cbindgen:ignore
pub mod tile;
/// cbindgen:ignore
pub mod topology;
/// cbindgen:ignore
pub mod transform;
/// cbindgen:ignore
pub mod triangulate;
/// cbindgen:ignore
pub mod voronoi;
/// cbindgen:ignore
pub mod weld;

#[allow(unsafe_code)]
pub mod ffi;

pub use error::{Error, MeshError, Result};
pub use glam::DVec3;
pub use mesh::Mesh;
pub use topology::{MeshInfo, Topology};

/// The library's version, as in `Cargo.toml`.
pub const VERSION: &str = env!("CARGO_PKG_VERSION");
