//! Each corner's face and next corner, as a [`Topology`] reads them: when
//! every face has one size (most scanned and every subdivided mesh) they
//! are arithmetic, and the arrays are written only if asked for; a mesh of
//! mixed faces has them written once.
//!
//! [`Topology`]: crate::mesh::topology::Topology

use std::sync::OnceLock;

use rayon::prelude::*;

use crate::buffers::{fill_by_offsets, try_copy, CHUNK};
use crate::error::Result;
use crate::mesh::Mesh;

#[derive(Debug, Clone, Default)]
pub(crate) struct CornerFaces {
    face_count: usize,
    /// The size of every face, or 0 when they differ.
    size: usize,
    /// Where each face's corners start, plus the total; empty when `size` is not 0.
    offsets: Vec<u32>,
    faces: OnceLock<Vec<u32>>,
    next: OnceLock<Vec<u32>>,
}

impl CornerFaces {
    /// The corners of `mesh`'s faces.
    ///
    /// # Errors
    /// [`crate::Error::OutOfMemory`] when the arrays of mixed faces cannot be reserved.
    pub(crate) fn of_mesh(mesh: &Mesh) -> Result<CornerFaces> {
        let face_count = mesh.face_count();
        if let Some(size) = mesh.uniform_face_size() {
            return Ok(CornerFaces {
                face_count,
                size,
                ..CornerFaces::default()
            });
        }
        let offsets = try_copy(mesh.face_offsets(), "face offsets")?;
        let (faces, next) = rayon::join(
            || fill_by_offsets(&offsets, "corner faces", |f, faces| faces.fill(f as u32)),
            || corner_next(&offsets),
        );
        Ok(CornerFaces {
            face_count,
            size: 0,
            faces: OnceLock::from(faces?),
            next: OnceLock::from(next?),
            offsets,
        })
    }

    pub(crate) fn face_count(&self) -> usize {
        self.face_count
    }

    /// The face of corner `c`.
    #[inline]
    pub(crate) fn face(&self, c: usize) -> usize {
        match self.size {
            0 => self.faces()[c] as usize,
            4 => c / 4,
            size => c / size,
        }
    }

    /// The corner after `c` in its face.
    #[inline]
    pub(crate) fn next(&self, c: usize) -> usize {
        match self.size {
            0 => self.next_corners()[c] as usize,
            size if c % size == size - 1 => c + 1 - size,
            _ => c + 1,
        }
    }

    /// The corner before `c` in its face.
    #[inline]
    pub(crate) fn previous(&self, c: usize) -> usize {
        let f = self.face(c);
        if c == self.first_corner(f) {
            self.first_corner(f + 1) - 1
        } else {
            c - 1
        }
    }

    /// Face `f`'s first corner (and for `f` = the face count, the corner count).
    #[inline]
    pub(crate) fn first_corner(&self, f: usize) -> usize {
        match self.size {
            0 => self.offsets[f] as usize,
            size => f * size,
        }
    }

    /// Each corner's face, written on first use when the faces have one size.
    pub(crate) fn faces(&self) -> &[u32] {
        self.faces.get_or_init(|| {
            let corners = self.face_count * self.size;
            let size = self.size.max(1);
            let mut faces = Vec::with_capacity(corners);
            faces.par_extend(
                (0..corners)
                    .into_par_iter()
                    .with_min_len(CHUNK)
                    .map(|c| (c / size) as u32),
            );
            faces
        })
    }

    /// Each corner's next corner, written on first use when the faces have one size.
    pub(crate) fn next_corners(&self) -> &[u32] {
        self.next.get_or_init(|| {
            let corners = self.face_count * self.size;
            let mut next = Vec::with_capacity(corners);
            next.par_extend(
                (0..corners)
                    .into_par_iter()
                    .with_min_len(CHUNK)
                    .map(|c| self.next(c) as u32),
            );
            next
        })
    }
}

/// For each corner, the next corner of its face, written in parallel.
fn corner_next(offsets: &[u32]) -> Result<Vec<u32>> {
    fill_by_offsets(offsets, "next corners", |f, next: &mut [u32]| {
        let start = offsets[f];
        for (k, slot) in next.iter_mut().enumerate() {
            *slot = start + k as u32 + 1;
        }
        if let Some(last) = next.last_mut() {
            *last = start;
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::shapes;

    #[test]
    fn arithmetic_corners_equal_written_ones() {
        for mesh in [
            shapes::torus(40, 30),
            shapes::triangle_torus(20, 10),
            shapes::mixed_polygons(),
        ] {
            let corners = CornerFaces::of_mesh(&mesh).unwrap();
            let offsets = mesh.face_offsets();
            let next = corner_next(offsets).unwrap();
            let faces: Vec<u32> = (0..mesh.face_count())
                .flat_map(|f| std::iter::repeat_n(f as u32, mesh.face(f).len()))
                .collect();
            assert_eq!(corners.faces(), faces);
            assert_eq!(corners.next_corners(), next);
            assert_eq!(corners.face_count(), mesh.face_count());
            for c in 0..mesh.index_count() {
                assert_eq!(corners.face(c), faces[c] as usize);
                assert_eq!(corners.next(c), next[c] as usize);
                assert_eq!(corners.next(corners.previous(c)), c);
            }
            for (f, &offset) in offsets.iter().enumerate() {
                assert_eq!(corners.first_corner(f), offset as usize);
            }
        }
    }
}
