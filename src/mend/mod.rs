//! Mending: the steps that turn meshes which only look connected into one
//! surface subdivision can see. [`weld`] (join, weld), [`t_nodes`] (find and
//! repair), [`cull`] (the walls inside joined boxes) and [`orient`]
//! (orientability, unify, flip), [`matching`] (picked points and lines
//! to vertices and edges).

pub mod cull;
pub mod matching;
pub mod orient;
pub mod t_nodes;
pub mod weld;
