//! Mending: the steps that turn meshes which only look connected into one
//! surface subdivision can see. [`weld`] (join, weld), [`t_nodes`] (find and
//! repair), [`cull`] (the walls inside joined boxes) and [`orient`]
//! (orientability, unify, flip).

pub mod cull;
pub mod orient;
pub mod t_nodes;
pub mod weld;
