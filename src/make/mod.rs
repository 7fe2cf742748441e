//! Making meshes from points, planes and grids: [`plane`] (the frame points
//! are projected onto), [`delaunay`], [`voronoi`], [`grid`] (a sampled
//! surface), [`stellate`] (a pyramid on every face) and [`primitives`]
//! (Weaverbird's Define panel).

pub mod delaunay;
pub mod grid;
pub mod plane;
pub mod primitives;
pub mod stellate;
pub mod voronoi;
