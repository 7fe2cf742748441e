//! Transforms of Weaverbird's toolbar: [`offset`] and [`thicken`] (three
//! offset types), [`window`] and [`picture_frame`] (face insets),
//! [`sierpinski_carpet`], [`bevel_edges`] and [`bevel_vertices`].

mod bevel;
mod carpet;
mod inset;
mod offset;

pub use bevel::{bevel_edges, bevel_vertices};
pub use carpet::sierpinski_carpet;
pub(crate) use inset::check_distance_count;
pub use inset::{picture_frame, window, InsetMode};
pub use offset::{offset, thicken, OffsetType};
