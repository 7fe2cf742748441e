//! Mesh files and pictures.
