//! Cull adjacent faces: the walls inside an aggregation of joined boxes.
//!
//! When boxes that touch are joined and welded, each shared wall appears
//! twice, once from each box and in opposite windings. Those twins lie inside
//! the aggregate; removing every copy leaves its outer skin, which is what
//! subdivision should see.

use rayon::prelude::*;

use crate::buffers::{split_by_offsets, CHUNK};
use crate::mesh::Mesh;

/// Removes every face that has a twin with the same set of vertices, in
/// either orientation and from any starting corner; all copies go, not all
/// but one. Returns the culled mesh and the number of faces removed.
///
/// Twins are found by sorting the faces by their sorted vertex lists (on
/// all threads), so the cost is O(n log n) comparisons of short lists,
/// never a comparison of all pairs. Faces are compared by vertex index:
/// weld first so that coincident corners share an index.
///
/// The vertices are kept as they are, even those no remaining face uses, so
/// that the indices stay those of the input; [`crate::mend::weld::remove_unused_vertices`]
/// leaves the unused ones out.
pub fn cull_adjacent(mesh: &Mesh) -> (Mesh, usize) {
    match twins_of(mesh) {
        Some((remove, removed)) => (without_faces(mesh, &remove, removed), removed),
        None => (mesh.clone(), 0),
    }
}

/// [`cull_adjacent`] on a mesh the caller gives up: when no face has a twin
/// it comes back as it is, with no copy made.
pub fn cull_adjacent_owned(mesh: Mesh) -> (Mesh, usize) {
    match twins_of(&mesh) {
        Some((remove, removed)) => (without_faces(&mesh, &remove, removed), removed),
        None => (mesh, 0),
    }
}

/// Which faces have a twin, and how many; `None` when none has.
fn twins_of(mesh: &Mesh) -> Option<(Vec<bool>, usize)> {
    // Twins share their vertices; faces whose corners all have vertices of
    // their own (STL as stored) share none, and need no sort to say so.
    if mesh.corners_share_no_vertex() {
        return None;
    }
    faces_with_a_twin(mesh)
}

/// [`twins_of`] by sorting the faces by their sorted corners.
fn faces_with_a_twin(mesh: &Mesh) -> Option<(Vec<bool>, usize)> {
    let face_count = mesh.face_count();
    let offsets = mesh.face_offsets();
    // Each face's corners sorted, and the faces sorted by them, on all
    // threads: only which faces share a key matters, not their order.
    let mut sorted_corners = mesh.face_indices().to_vec();
    split_by_offsets(&mut sorted_corners, offsets, CHUNK)
        .into_par_iter()
        .for_each(|(faces, corners)| {
            let base = offsets[faces.start] as usize;
            for f in faces {
                corners[offsets[f] as usize - base..offsets[f + 1] as usize - base].sort_unstable();
            }
        });
    let key = |f: u32| {
        let f = f as usize;
        &sorted_corners[offsets[f] as usize..offsets[f + 1] as usize]
    };
    let mut order: Vec<u32> = (0..face_count as u32).into_par_iter().collect();
    order.par_sort_unstable_by(|&a, &b| key(a).cmp(key(b)));

    let mut remove = vec![false; face_count];
    let mut start = 0;
    for i in 1..=order.len() {
        if i == order.len() || key(order[i]) != key(order[start]) {
            if i - start > 1 {
                for &f in &order[start..i] {
                    remove[f as usize] = true;
                }
            }
            start = i;
        }
    }
    let removed = remove.iter().filter(|&&r| r).count();
    (removed > 0).then_some((remove, removed))
}

/// The mesh without the `removed` faces `remove` marks; every vertex kept.
fn without_faces(mesh: &Mesh, remove: &[bool], removed: usize) -> Mesh {
    let mut face_sizes = Vec::with_capacity(mesh.face_count() - removed);
    let mut face_indices = Vec::with_capacity(mesh.index_count());
    for (f, face) in mesh.faces().enumerate() {
        if !remove[f] {
            face_sizes.push(face.len() as u32);
            face_indices.extend_from_slice(face);
        }
    }
    Mesh::from_valid_parts(mesh.positions().to_vec(), face_sizes, face_indices)
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;

    #[test]
    fn twins_in_any_orientation_and_start_all_go() {
        let p = (0..6).map(|i| DVec3::new(i as f64, (i * i) as f64, 0.0));
        let mesh = Mesh::from_polygons(
            p.collect(),
            [
                vec![0, 1, 2, 3],
                vec![2, 1, 0, 3], // reversed, other start
                vec![1, 2, 3, 0], // same winding, other start
                vec![0, 1, 2],    // a subset is not a twin
                vec![3, 4, 5],
            ],
        )
        .unwrap();
        let (culled, removed) = cull_adjacent(&mesh);
        assert_eq!(removed, 3);
        assert_eq!(culled.face_count(), 2);
        assert_eq!(culled.face(0), &[0, 1, 2]);
        assert_eq!(culled.face(1), &[3, 4, 5]);
        assert_eq!(culled.vertex_count(), 6);
    }

    #[test]
    fn nothing_to_cull_returns_the_mesh() {
        let cube = crate::mesh::shapes::cube();
        assert_eq!(cull_adjacent(&cube), (cube, 0));
    }

    #[test]
    fn owned_cull_is_the_borrowed_cull() {
        let mesh = crate::mesh::shapes::cube();
        let (welded, _) =
            crate::mend::weld::weld(&crate::mend::weld::join(&[&mesh, &mesh]).unwrap(), 0.0)
                .unwrap();
        assert_eq!(cull_adjacent_owned(welded.clone()), cull_adjacent(&welded));
        assert_eq!(cull_adjacent_owned(welded.clone()).1, 12);
        assert_eq!(cull_adjacent_owned(mesh.clone()), (mesh, 0));
    }

    proptest::proptest! {
        /// Faces whose corners share no vertex have no twin, as the sort
        /// would find.
        #[test]
        fn a_soup_has_twins_only_where_the_sort_finds_them(mesh in crate::mesh::shapes::soups()) {
            proptest::prop_assert_eq!(twins_of(&mesh), faces_with_a_twin(&mesh));
        }
    }
}
