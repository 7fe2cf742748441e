//! The rest of Weaverbird's toolbar: [`split`] (linear subdivisions),
//! [`smooth`], [`transform`] (offset, thicken, window, bevel), [`extract`]
//! (dual, edges, reroute, mesh from lines) and [`tile`] (faces re-filled by
//! fans, strips and stitches).

pub mod extract;
pub mod smooth;
pub mod split;
pub mod tile;
pub mod transform;
