//! Subdivision schemes.
