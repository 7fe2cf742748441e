//! Holes: cage faces left out of the result, as OpenSubdiv's hole tags and
//! its `VTX_BOUNDARY_NONE` make them. A hole changes no point: its vertices
//! and edges shape the neighbours as before, and its children are computed
//! like any others. Only the output drops them, so the filter reads the
//! last level's faces alone: the children of a cage face are contiguous.

use super::creases::{SubdivisionOptions, SHARPNESS_INFINITE};
use super::level::{Connectivity, Faces};
use super::scheme::{NakedEdges, Scheme};
use crate::buffers::{try_vec, zeroed};
use crate::error::{Error, Result};

/// Which cage faces are holes: the options' holes, and with
/// [`NakedEdges::None`] every face at a vertex on a naked edge that the
/// user did not crease infinitely sharp
/// (`Far::TopologyRefinerFactoryBase::prepareComponentTagsAndSharpness`).
/// `None` when there is no hole.
///
/// # Errors
/// [`Error::InvalidArgument`] naming a hole past the face count.
pub(crate) fn cage_holes(
    faces: &Faces,
    connectivity: &Connectivity,
    options: &SubdivisionOptions,
) -> Result<Option<Vec<bool>>> {
    let face_count = faces.face_count();
    if options.holes.is_empty() && options.naked_edges != NakedEdges::None {
        return Ok(None);
    }
    let mut holes: Vec<bool> = zeroed(face_count, "holes")?;
    for (i, &f) in options.holes.iter().enumerate() {
        if f as usize >= face_count {
            return Err(Error::InvalidArgument(format!(
                "hole {i} is face {f}, but the mesh has {face_count} faces"
            )));
        }
        holes[f as usize] = true;
    }
    if options.naked_edges == NakedEdges::None {
        let kept = hard_naked_edges(connectivity, options)?;
        for v in 0..faces.vertex_count {
            let open = connectivity
                .vertex_edges(v)
                .iter()
                .any(|&e| connectivity.edge_corners(e as usize).len() == 1 && !kept[e as usize]);
            if open {
                for &c in connectivity.vertex_corners(v) {
                    holes[connectivity.face_of(c as usize)] = true;
                }
            }
        }
    }
    Ok(holes.contains(&true).then_some(holes))
}

/// [`cage_holes`] of a mesh.
///
/// # Errors
/// As [`cage_holes`]; [`Error::OutOfMemory`].
pub(crate) fn mesh_holes(
    cage: &crate::Mesh,
    options: &SubdivisionOptions,
) -> Result<Option<Vec<bool>>> {
    if options.holes.is_empty() && options.naked_edges != NakedEdges::None {
        return Ok(None);
    }
    let faces = Faces::of_mesh(cage);
    let connectivity = Connectivity::new(&faces)?;
    cage_holes(&faces, &connectivity, options)
}

/// Per edge, whether the user's last crease on it is infinitely sharp.
/// The creases were checked by `cage_sharpness`; one that is not an edge
/// is passed over here.
fn hard_naked_edges(
    connectivity: &Connectivity,
    options: &SubdivisionOptions,
) -> Result<Vec<bool>> {
    let mut hard: Vec<bool> = zeroed(connectivity.edge_count(), "holes")?;
    for &([a, b], sharpness) in &options.creases {
        if let Some(e) = connectivity.find_edge(a, b) {
            hard[e as usize] = sharpness >= SHARPNESS_INFINITE;
        }
    }
    Ok(hard)
}

/// The last level's faces without the children of holes.
#[derive(Debug, Clone)]
pub(crate) struct Visible {
    /// The kept faces, with offsets.
    pub(crate) faces: Faces<'static>,
    /// For each kept face corner, its corner in the last level.
    pub(crate) corners: Vec<u32>,
    /// For each kept face, its cage face.
    pub(crate) parents: Vec<u32>,
}

/// Keeps the faces of `last` (the result of `levels` levels of `scheme` on
/// a cage with faces of `cage_sizes`) whose cage face is not in `holes`.
///
/// # Errors
/// [`Error::OutOfMemory`].
pub(crate) fn visible_faces(
    cage_sizes: &[u32],
    scheme: Scheme,
    levels: usize,
    holes: &[bool],
    last: &Faces,
) -> Result<Visible> {
    let children = |size: u32| scheme.descendants_of_face(size, levels);
    let (mut face_count, mut corner_count) = (0, 0);
    let mut first = 0;
    for (&size, &hole) in cage_sizes.iter().zip(holes) {
        let n = children(size);
        if !hole {
            face_count += n;
            corner_count += (first..first + n)
                .map(|f| last.corners(f).len())
                .sum::<usize>();
        }
        first += n;
    }
    let mut offsets = try_vec(face_count + 1, "visible faces")?;
    let mut indices = try_vec(corner_count, "visible faces")?;
    let mut corners = try_vec(corner_count, "visible faces")?;
    let mut parents = try_vec(face_count, "visible faces")?;
    offsets.push(0);
    let mut first = 0;
    for (parent, (&size, &hole)) in cage_sizes.iter().zip(holes).enumerate() {
        let n = children(size);
        if !hole {
            for f in first..first + n {
                let range = last.corners(f);
                corners.extend(range.start as u32..range.end as u32);
                indices.extend_from_slice(&last.indices[range]);
                offsets.push(indices.len() as u32);
                parents.push(parent as u32);
            }
        }
        first += n;
    }
    Ok(Visible {
        faces: Faces {
            vertex_count: last.vertex_count,
            size: 0,
            offsets: offsets.into(),
            indices: indices.into(),
        },
        corners,
        parents,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::shapes;
    use crate::subdivide::Subdivider;

    fn holes_of(mesh: &crate::Mesh, options: &SubdivisionOptions) -> Option<Vec<bool>> {
        let faces = Faces::of_mesh(mesh);
        let connectivity = Connectivity::new(&faces).unwrap();
        cage_holes(&faces, &connectivity, options).unwrap()
    }

    #[test]
    fn boundary_none_holes_every_face_at_the_boundary() {
        // A 3x3 grid: only the middle face touches no boundary vertex.
        let grid = shapes::quad_grid(3, 3);
        let holes = holes_of(&grid, &SubdivisionOptions::new(NakedEdges::None)).unwrap();
        let kept: Vec<usize> = (0..9).filter(|&f| !holes[f]).collect();
        assert_eq!(kept, vec![4]);
        assert_eq!(
            holes_of(&grid, &SubdivisionOptions::new(NakedEdges::Smooth)),
            None
        );
        // A closed cube has no boundary, so no hole.
        assert_eq!(
            holes_of(&shapes::cube(), &SubdivisionOptions::new(NakedEdges::None)),
            None
        );
    }

    #[test]
    fn hard_creased_boundary_keeps_its_faces() {
        let grid = shapes::quad_grid(1, 1);
        let mut options = SubdivisionOptions::new(NakedEdges::None);
        options.creases = vec![
            ([0, 1], 10.0),
            ([1, 3], 10.0),
            ([3, 2], 10.0),
            ([2, 0], 10.0),
        ];
        assert_eq!(holes_of(&grid, &options), None);
        options.creases[3].1 = 2.0;
        assert_eq!(holes_of(&grid, &options), Some(vec![true]));
    }

    #[test]
    fn a_hole_past_the_faces_is_named() {
        let mut options = SubdivisionOptions::new(NakedEdges::Smooth);
        options.holes = vec![0, 6];
        let err = Subdivider::new(&shapes::cube(), Scheme::CatmullClark, 1, &options).unwrap_err();
        assert_eq!(
            err.to_string(),
            "invalid argument: hole 1 is face 6, but the mesh has 6 faces"
        );
    }

    #[test]
    fn holes_drop_their_children_and_keep_every_point() {
        let cube = shapes::cube();
        let plain = Subdivider::new(
            &cube,
            Scheme::CatmullClark,
            2,
            &SubdivisionOptions::default(),
        )
        .unwrap();
        let options = SubdivisionOptions {
            holes: vec![1, 4],
            ..SubdivisionOptions::default()
        };
        let holed = Subdivider::new(&cube, Scheme::CatmullClark, 2, &options).unwrap();
        assert_eq!(holed.vertex_count(), plain.vertex_count());
        assert_eq!(holed.face_count(), plain.face_count() - 2 * 16);
        assert_eq!(
            holed.mesh().unwrap().positions(),
            plain.mesh().unwrap().positions()
        );
        let parents = holed.parent_faces();
        assert!(parents.iter().all(|&p| p != 1 && p != 4));
        assert_eq!(parents.len(), holed.face_count());
        // The kept faces are the plain ones, in order.
        let kept: Vec<u32> = (0..plain.face_count())
            .filter(|f| ![1, 4].contains(&(f / 16)))
            .flat_map(|f| plain.face_indices()[4 * f..4 * f + 4].to_vec())
            .collect();
        assert_eq!(holed.face_indices(), &kept[..]);
    }
}
