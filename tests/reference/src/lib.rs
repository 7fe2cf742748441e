//! (filled in by the reference bridge)
