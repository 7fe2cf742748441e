//! The C ABI declared in `include/weft.h`: conversions, checks, statuses and
//! errors only. No geometry lives here; every export forwards to the library.
//!
//! Each file groups one family of exports; `boundary` holds the rules they
//! all follow (see its doc).

pub mod boundary;
pub mod creases;
pub mod files;
pub mod make;
pub mod matching;
pub mod mend;
pub mod mesh;
pub mod refiner;
pub mod subdivide;
pub mod toolbar;

pub use boundary::WeftStatus;
pub use mesh::{WeftMesh, WeftMeshInfo};
