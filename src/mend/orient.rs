//! Orientation: whether a mesh can be wound consistently, making it so, and
//! flipping it.
//!
//! Two faces are compatible when the edge they share runs in opposite
//! directions in them. A connected piece is orientable when every face can
//! be given a winding compatible with all its neighbours (a Möbius strip
//! cannot).

use glam::DVec3;

use rayon::prelude::*;

use crate::buffers::{split_by_offsets, CHUNK};
use crate::mesh::topology::Topology;
use crate::mesh::Mesh;

/// Whether every connected piece of the mesh can be given one consistent
/// winding. Edges with three or more faces do not constrain.
pub fn is_orientable(mesh: &Mesh) -> bool {
    Topology::new(mesh)
        .orientation()
        .component_orientable
        .iter()
        .all(|&o| o)
}

/// Gives every connected piece one consistent winding, flipping the fewest
/// faces of the piece; then turns each closed piece (no naked and no
/// non-manifold edge) so that it faces outward, i.e. encloses a positive
/// signed volume. Returns the result and how many faces were reversed.
///
/// A piece that is not orientable is wound as the walk across its edges
/// from its first face found it (as consistent as it can be); it is never
/// turned outward, having no inside. Reversed faces keep their first corner
/// first, as [`flip`] does.
pub fn unify_orientation(mesh: &Mesh) -> (Mesh, usize) {
    let (unified, report) = orient_outward(mesh);
    (unified, report.flipped_faces)
}

/// What [`orient_outward`] found and changed, piece by piece (a piece is a
/// set of faces connected through shared edges).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct OrientReport {
    /// Faces reversed.
    pub flipped_faces: usize,
    /// Connected pieces.
    pub pieces: usize,
    /// Closed pieces that enclosed a negative volume and were turned outward.
    pub turned_outward: usize,
    /// Pieces with a naked or non-manifold edge: unified, but with no inside
    /// to face away from.
    pub open_pieces: usize,
    /// Pieces that no winding makes consistent (a Möbius strip).
    pub non_orientable_pieces: usize,
}

/// As [`unify_orientation`], with a report of the pieces: how many were
/// closed and turned outward, how many open (unified only) and how many
/// cannot be oriented. A mesh read from STL must be welded first, or every
/// triangle is a piece of its own.
pub fn orient_outward(mesh: &Mesh) -> (Mesh, OrientReport) {
    orient_outward_owned(mesh.clone())
}

/// [`orient_outward`] on a mesh the caller gives up: its faces are reversed
/// where they are, so a command that reads a mesh only to orient it needs
/// no second copy of its positions and faces.
pub fn orient_outward_owned(mut mesh: Mesh) -> (Mesh, OrientReport) {
    if mesh.corners_share_no_vertex() {
        // STL as stored: no face has a neighbour, so each is an open piece
        // of its own, wound as it is.
        let faces = mesh.face_count();
        let report = OrientReport {
            pieces: faces,
            open_pieces: faces,
            ..OrientReport::default()
        };
        return (mesh, report);
    }
    let (reversed, report) = faces_to_reverse(&mesh);
    reverse_in_place(&mut mesh, |f| reversed[f]);
    (mesh, report)
}

/// Which faces [`orient_outward`] reverses, and its report.
fn faces_to_reverse(mesh: &Mesh) -> (Vec<bool>, OrientReport) {
    let topology = Topology::new(mesh);
    let orientation = topology.orientation();
    let component_count = orientation.component_orientable.len();

    // Per piece: faces to flip in the walk's assignment, faces in all.
    let mut flips = vec![0usize; component_count];
    let mut sizes = vec![0usize; component_count];
    for (f, &c) in orientation.face_component.iter().enumerate() {
        sizes[c as usize] += 1;
        flips[c as usize] += orientation.face_flip[f] as usize;
    }
    // Inverting the whole assignment is as consistent; take the smaller.
    let mut invert: Vec<bool> = (0..component_count)
        .map(|c| 2 * flips[c] > sizes[c])
        .collect();
    let reversed_face = |f: usize, invert: &[bool]| {
        orientation.face_flip[f] ^ invert[orientation.face_component[f] as usize]
    };

    // Closed, orientable pieces must enclose a positive volume.
    let mut open = vec![false; component_count];
    for e in 0..topology.edge_count() {
        if topology.edge_face_count(e) != 2 {
            let c = topology.corner_faces()[topology.edge_corners(e)[0] as usize];
            open[orientation.face_component[c as usize] as usize] = true;
        }
    }
    // Measured from a point of each piece: far from the origin, volumes
    // measured from the origin would cancel in round-off. Only the closed,
    // orientable pieces' volumes decide anything.
    let measured: Vec<bool> = (0..component_count)
        .map(|c| orientation.component_orientable[c] && !open[c])
        .collect();
    let mut origin = vec![None; component_count];
    let mut volume = vec![0.0f64; component_count];
    for f in 0..mesh.face_count() {
        let c = orientation.face_component[f] as usize;
        if !measured[c] {
            continue;
        }
        let o = *origin[c].get_or_insert(mesh.positions()[mesh.face(f)[0] as usize]);
        let v = signed_volume_of_face(mesh, f, o);
        volume[c] += if reversed_face(f, &invert) { -v } else { v };
    }
    let mut report = OrientReport {
        pieces: component_count,
        ..OrientReport::default()
    };
    for c in 0..component_count {
        if !orientation.component_orientable[c] {
            report.non_orientable_pieces += 1;
        } else if open[c] {
            report.open_pieces += 1;
        } else if volume[c] < 0.0 {
            invert[c] = !invert[c];
            report.turned_outward += 1;
        }
    }

    let reversed: Vec<bool> = (0..mesh.face_count())
        .into_par_iter()
        .with_min_len(CHUNK)
        .map(|f| reversed_face(f, &invert))
        .collect();
    report.flipped_faces = reversed.par_iter().filter(|&&r| r).count();
    (reversed, report)
}

/// Reverses every face. Each face keeps its first corner first and lists
/// the others backwards (`[a, b, c, d]` becomes `[a, d, c, b]`): a face's
/// first corner is where its subdivided children start, so this keeps that
/// anchor where it was and flipping twice gives the input back.
pub fn flip(mesh: &Mesh) -> Mesh {
    flip_owned(mesh.clone())
}

/// [`flip`] on a mesh the caller gives up, its faces reversed where they are.
pub fn flip_owned(mut mesh: Mesh) -> Mesh {
    reverse_in_place(&mut mesh, |_| true);
    mesh
}

/// The signed volume a mesh encloses (positive when closed and facing out;
/// meaningful only for closed, oriented meshes), by the divergence theorem
/// over a fan of each face.
pub fn signed_volume(mesh: &Mesh) -> f64 {
    let Some((lo, hi)) = mesh.bounding_box() else {
        return 0.0;
    };
    let centre = (lo + hi) / 2.0;
    (0..mesh.face_count())
        .map(|f| signed_volume_of_face(mesh, f, centre))
        .sum()
}

/// The signed volume of the cone from `origin` over face `f`, fanned from its first corner.
fn signed_volume_of_face(mesh: &Mesh, f: usize, origin: DVec3) -> f64 {
    let p = mesh.positions();
    let face = mesh.face(f);
    let a = p[face[0] as usize] - origin;
    face[1..]
        .windows(2)
        .map(|w| a.dot((p[w[0] as usize] - origin).cross(p[w[1] as usize] - origin)))
        .sum::<f64>()
        / 6.0
}

/// Reverses the faces `reversed` says, in place: first corner first, the
/// others backwards. Blocks of faces in parallel.
fn reverse_in_place(mesh: &mut Mesh, reversed: impl Fn(usize) -> bool + Sync + Send) {
    let (offsets, indices) = mesh.offsets_and_face_indices_mut();
    split_by_offsets(indices, offsets, CHUNK)
        .into_par_iter()
        .for_each(|(faces, corners)| {
            let base = offsets[faces.start] as usize;
            for f in faces.filter(|&f| reversed(f)) {
                corners[offsets[f] as usize - base + 1..offsets[f + 1] as usize - base].reverse();
            }
        });
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::shapes;

    #[test]
    fn flip_keeps_the_first_corner_and_undoes_itself() {
        let cube = shapes::cube();
        let flipped = flip(&cube);
        assert_eq!(flipped.face(0), &[0, 1, 3, 2]);
        assert!((signed_volume(&flipped) + 1.0).abs() < 1e-12);
        assert_eq!(flip(&flipped), cube);
    }

    #[test]
    fn inside_out_cube_is_turned_outward() {
        let (fixed, flipped) = unify_orientation(&flip(&shapes::cube()));
        assert_eq!(flipped, 6);
        assert_eq!(fixed, shapes::cube());
    }

    #[test]
    fn open_piece_flips_the_minority() {
        let grid = shapes::quad_grid(3, 1);
        let mut faces: Vec<Vec<u32>> = grid.faces().map(|f| f.to_vec()).collect();
        faces[0].reverse();
        let mesh = Mesh::from_polygons(grid.positions().to_vec(), faces).unwrap();
        let (fixed, flipped) = unify_orientation(&mesh);
        assert_eq!(flipped, 1);
        assert!(Topology::new(&fixed).info(&fixed).is_oriented);
        assert_eq!(fixed.face(1), grid.face(1));
    }

    #[test]
    fn owned_flip_is_the_borrowed_flip() {
        let mesh = shapes::mixed_polygons();
        assert_eq!(flip_owned(mesh.clone()), flip(&mesh));
    }

    proptest::proptest! {
        /// A mesh whose corners share no vertex is oriented without its
        /// edges; the edges would say the same.
        #[test]
        fn a_soup_is_oriented_as_its_topology_says(mesh in shapes::soups()) {
            let (oriented, report) = orient_outward(&mesh);
            let (reversed, expected) = faces_to_reverse(&mesh);
            proptest::prop_assert_eq!(report, expected);
            let mut by_topology = mesh.clone();
            reverse_in_place(&mut by_topology, |f| reversed[f]);
            proptest::prop_assert_eq!(oriented, by_topology);
        }
    }
}
