//! A mesh's arrays: its own, or a host's, lent for as long as the mesh lives.
//!
//! A host that hands Weft a million vertices pays for a copy it may not
//! need: `weft_mesh_new_borrowed` lends the host's arrays instead, and the
//! mesh reads them in place. What is lent stays with the mesh it was lent
//! to: a clone, or anything that writes, owns a copy.

use std::ops::Deref;

/// The values of one mesh array.
#[derive(Debug)]
pub(crate) enum Buffer<T: 'static> {
    Own(Vec<T>),
    /// Lent by a host, who keeps it alive and unchanged until the mesh
    /// holding it is dropped (the `'static` is that promise, made at the C ABI).
    Lent(&'static [T]),
}

impl<T> Buffer<T> {
    /// The values as a vector of their own, copied when lent.
    pub(crate) fn into_vec(self) -> Vec<T>
    where
        T: Clone,
    {
        match self {
            Buffer::Own(values) => values,
            Buffer::Lent(values) => values.to_vec(),
        }
    }

    /// The values to write, copied first when lent: a host's array is never written.
    pub(crate) fn to_mut(&mut self) -> &mut Vec<T>
    where
        T: Clone,
    {
        if let Buffer::Lent(values) = *self {
            *self = Buffer::Own(values.to_vec());
        }
        match self {
            Buffer::Own(values) => values,
            Buffer::Lent(_) => unreachable!("a lent buffer was copied just above"),
        }
    }

    /// Whether the values are a host's.
    pub(crate) fn is_lent(&self) -> bool {
        matches!(self, Buffer::Lent(_))
    }
}

impl<T> Default for Buffer<T> {
    fn default() -> Buffer<T> {
        Buffer::Own(Vec::new())
    }
}

impl<T> Deref for Buffer<T> {
    type Target = [T];

    #[inline]
    fn deref(&self) -> &[T] {
        match self {
            Buffer::Own(values) => values,
            Buffer::Lent(values) => values,
        }
    }
}

/// A clone owns its values: the lender promised them to one mesh only.
impl<T: Clone> Clone for Buffer<T> {
    fn clone(&self) -> Buffer<T> {
        Buffer::Own(self.to_vec())
    }
}

impl<T> From<Vec<T>> for Buffer<T> {
    fn from(values: Vec<T>) -> Buffer<T> {
        Buffer::Own(values)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::error::MeshError;
    use crate::mesh::{shapes, Mesh, MeshOptions};
    use glam::DVec3;

    static LENT: [u32; 4] = [1, 2, 3, 4];

    #[test]
    fn a_lent_buffer_is_read_in_place_and_copied_before_it_is_written() {
        let mut buffer = Buffer::Lent(&LENT[..]);
        assert!(std::ptr::eq(buffer.as_ptr(), LENT.as_ptr()));
        let clone = buffer.clone();
        assert!(!clone.is_lent());
        assert!(!std::ptr::eq(clone.as_ptr(), LENT.as_ptr()));
        buffer.to_mut()[0] = 9;
        assert!(!buffer.is_lent());
        assert_eq!(&*buffer, &[9, 2, 3, 4]);
        assert_eq!(LENT, [1, 2, 3, 4]);
        assert_eq!(Buffer::Lent(&LENT[..]).into_vec(), LENT.to_vec());
    }

    /// A mesh's arrays as a host holds them, leaked so that they outlive any mesh.
    fn lent(mesh: &Mesh) -> (&'static [DVec3], Vec<u32>, &'static [u32]) {
        (
            mesh.positions().to_vec().leak(),
            mesh.face_sizes().to_vec(),
            mesh.face_indices().to_vec().leak(),
        )
    }

    fn borrowing(
        (positions, sizes, indices): &(&'static [DVec3], Vec<u32>, &'static [u32]),
    ) -> Result<Mesh, MeshError> {
        Mesh::borrowing(positions, sizes, indices, MeshOptions::default())
    }

    fn copying(
        (positions, sizes, indices): &(&'static [DVec3], Vec<u32>, &'static [u32]),
    ) -> Result<Mesh, MeshError> {
        Mesh::from_flat(bytemuck::cast_slice(positions), sizes, indices)
    }

    #[test]
    fn a_borrowing_mesh_reads_the_host_arrays_and_equals_a_copied_one() {
        for shape in [
            shapes::torus(300, 300),
            shapes::triangle_torus(200, 200),
            shapes::mixed_polygons(),
            Mesh::empty(),
        ] {
            let host = lent(&shape);
            let mesh = borrowing(&host).unwrap();
            assert_eq!(mesh, shape);
            assert_eq!(mesh.face_offsets(), shape.face_offsets());
            for f in 0..=shape.face_count() {
                assert_eq!(mesh.face_start(f), shape.face_offsets()[f] as usize);
            }
            assert_eq!(mesh.face_sizes(), shape.face_sizes());
            assert!(mesh.is_borrowed());
            if shape.vertex_count() > 0 {
                assert!(std::ptr::eq(mesh.positions().as_ptr(), host.0.as_ptr()));
                assert!(std::ptr::eq(mesh.face_indices().as_ptr(), host.2.as_ptr()));
            }
            let clone = mesh.clone();
            assert!(!clone.is_borrowed());
            assert_eq!(clone, mesh);
            let mut written = borrowing(&host).unwrap();
            if let Some(first) = written.positions_mut().first_mut() {
                *first = DVec3::splat(7.0);
            }
            assert_eq!(host.0, shape.positions());
            assert_eq!(mesh.into_parts(), shape.clone().into_parts());
        }
    }

    #[test]
    fn a_borrowing_mesh_refuses_what_a_copied_one_refuses() {
        let quads = lent(&shapes::torus(300, 300));
        let triangles = lent(&shapes::triangle_torus(200, 200));
        let mixed = lent(&shapes::mixed_polygons());
        let vertex_count = |host: &(&[DVec3], Vec<u32>, &[u32])| host.0.len() as u32;
        let mut cases = Vec::new();
        for (host, face_size) in [(&quads, 4), (&triangles, 3), (&mixed, 0)] {
            let n = vertex_count(host);
            let late = if face_size == 0 {
                1
            } else {
                70_000 * face_size
            };
            let early = if face_size == 0 {
                0
            } else {
                20_001 * face_size
            };
            // An index past the end in a late block and a repeat in an
            // earlier one: the earlier face is named, as in order.
            let mut indices = host.2.to_vec();
            indices[late + 1] = n + 3;
            cases.push((host.0, host.1.clone(), indices.clone()));
            indices[early + 2] = indices[early];
            if face_size > 0 {
                let host = (host.0, host.1.clone(), &*indices.clone().leak());
                assert!(matches!(
                    borrowing(&host),
                    Err(MeshError::RepeatedIndex {
                        face: 20_001,
                        first: 0,
                        second: 2,
                        ..
                    })
                ));
            }
            cases.push((host.0, host.1.clone(), indices));
            let mut positions = host.0.to_vec();
            positions[host.0.len() / 2].y = f64::NAN;
            cases.push((positions.leak(), host.1.clone(), host.2.to_vec()));
            let mut sizes = host.1.clone();
            sizes[0] += 1;
            cases.push((host.0, sizes, host.2.to_vec()));
        }
        let mut short = mixed.1.clone();
        let last = short.len() - 1;
        short[last] = 2;
        short[0] += mixed.1[last] - 2;
        cases.push((mixed.0, short, mixed.2.to_vec()));
        for (positions, sizes, indices) in cases {
            let host = (positions, sizes, &*indices.leak());
            // Debug text, since a NaN coordinate in the error is not equal to itself.
            let expected = format!("{:?}", copying(&host).unwrap_err());
            assert_eq!(format!("{:?}", borrowing(&host).unwrap_err()), expected);
        }
    }
}
