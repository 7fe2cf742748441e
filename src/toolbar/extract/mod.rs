//! Extraction and topology tools of Weaverbird's toolbar: [`dual`],
//! [`vertices`], [`mesh_edges`] and [`edge_segments`], [`reroute_faces`],
//! and [`mesh_from_lines`].

mod dual;
mod edges;
mod lines;
mod reroute;

pub use dual::{dual, DualMode};
pub use edges::{edge_segments, mesh_edges, vertices};
pub use lines::mesh_from_lines;
pub use reroute::reroute_faces;
