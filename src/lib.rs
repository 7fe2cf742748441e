//! Weft: subdivision surfaces and mesh tools for computational design.
//!
//! The crate's map, one folder per family, as in `ffi/` and the C# layers:
//! - [`mesh`]: the polygon mesh (`f64` positions, faces as sizes plus flat
//!   indices) and its validation; [`topology`](mesh::topology) (edges,
//!   adjacency, naked and non-manifold parts, components, orientability),
//!   [`analysis`](mesh::analysis) (normals, planarity, boundaries),
//!   [`triangulate`](mesh::triangulate) and named [`shapes`](mesh::shapes).
//! - [`subdivide`]: Catmull-Clark and Loop with the naked-edge modes, and the
//!   refiner that re-evaluates new positions on a fixed topology.
//! - [`mend`]: [`weld`](mend::weld) (join, weld, the relative tolerance,
//!   unused vertices), [`t_nodes`](mend::t_nodes), [`cull`](mend::cull),
//!   [`orient`](mend::orient) (unify, outward), [`matching`](mend::matching)
//!   (picked points and lines to vertices and edges).
//! - [`make`]: [`plane`](make::plane), [`delaunay`](make::delaunay),
//!   [`voronoi`](make::voronoi), [`grid`](make::grid),
//!   [`stellate`](make::stellate), [`primitives`](make::primitives).
//! - [`toolbar`]: the rest of Weaverbird's toolbar: linear
//!   [`split`](toolbar::split)s, [`smooth`](toolbar::smooth),
//!   [`transform`](toolbar::transform) (offset, thicken, window, bevel),
//!   [`extract`](toolbar::extract) (dual, edges, reroute, mesh from lines) and
//!   [`tile`](toolbar::tile).
//! - [`io`]: mesh files (OBJ, PLY, STL, OFF) and pictures, for the `weft` command.
//! - [`error`]: the one error type; `buffers`: memory reserved fallibly
//!   (running out is an error, never an abort) and filled in parallel.
//! - `ffi`: the C ABI declared in `include/weft.h`. It only converts and
//!   checks; the geometry knows nothing of it.
//! - `src/bin/weft/`: the `weft` command, which only parses, calls the
//!   library and prints.
//!
//! Which layer may call which, from the bottom up: `error` and `buffers`
//! call nothing of the crate; [`mesh`] calls only them (its one edge
//! builder, `mesh/adjacency.rs`, serves [`Topology`] and the subdivision's
//! levels alike); [`subdivide`], [`mend`], [`make`] and [`toolbar`] call
//! [`mesh`] and each other's public functions; [`io`] calls the geometry to
//! read and write files; `ffi` converts buffers and statuses and calls the
//! geometry, which never calls `ffi`, [`io`] or the binary.
//!
//! Everything outside `ffi` is safe Rust.
#![deny(unsafe_code)]
#![deny(unsafe_op_in_unsafe_fn)]

mod buffers;
pub mod error;
pub mod io;
pub mod make;
pub mod mend;
pub mod mesh;
pub mod subdivide;
#[cfg(test)]
mod test_random;
pub mod toolbar;

#[allow(unsafe_code)]
pub mod ffi;

pub use error::{Error, MeshError, Result};
pub use glam::DVec3;
pub use mesh::topology::{MeshInfo, Topology};
pub use mesh::{Mesh, MeshOptions};

/// The library's version, as in `Cargo.toml`.
pub const VERSION: &str = env!("CARGO_PKG_VERSION");
