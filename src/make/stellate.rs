//! Stellate (Weaverbird's Stellate / Cumulation): a pyramid on every face.

use glam::DVec3;

use crate::mesh::analysis::newell_vector;

use crate::buffers::try_vec;
use crate::error::{Error, Result, MAX_ELEMENTS};
use crate::mesh::Mesh;

/// The height of each face's apex above its centroid, along its normal.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Heights<'a> {
    /// One height for every face.
    One(f64),
    /// One height per face, in face order.
    PerFace(&'a [f64]),
}

/// The unit Newell normal of a polygon (zero when it has no area) and its
/// vertex average.
pub(crate) fn newell_normal_and_centroid(corners: &[DVec3]) -> (DVec3, DVec3) {
    let centroid = corners.iter().sum::<DVec3>() / corners.len() as f64;
    (newell_vector(corners).normalize_or_zero(), centroid)
}

/// Checks that a per-face height list of `count` values suits a mesh of
/// `face_count` faces, from its length alone (the C ABI checks it before it
/// views the caller's buffer).
pub(crate) fn check_height_count(count: usize, face_count: usize) -> Result<()> {
    if count != face_count {
        return Err(Error::InvalidArgument(format!(
            "{count} heights were given for a mesh of {face_count} faces; give one per face"
        )));
    }
    Ok(())
}

/// Raises a pyramid on every face: a new vertex at the face's centroid (the
/// average of its corners) moved along its Newell normal by the face's
/// height (negative heights go behind the face), and a fan of triangles
/// `(a, b, apex)` for each edge `a → b` of the face, so the triangles keep
/// the face's orientation.
///
/// Output order: the input's vertices keep their indices, then one apex per
/// face (face f's apex is vertex `vertex_count + f`); the fan of face f is
/// contiguous and its first triangle stands on f's first edge. A face with
/// no area has no normal: its apex stays at its centroid.
///
/// # Errors
/// - [`Error::InvalidArgument`] when a per-face list's length differs from
///   the face count (naming both), or naming the first face whose height is
///   not finite.
/// - [`Error::ResultTooLarge`] past [`MAX_ELEMENTS`].
pub fn stellate(mesh: &Mesh, heights: Heights) -> Result<Mesh> {
    let face_count = mesh.face_count();
    if let Heights::PerFace(list) = heights {
        check_height_count(list.len(), face_count)?;
    }
    let height = |f: usize| match heights {
        Heights::One(h) => h,
        Heights::PerFace(list) => list[f],
    };
    if let Some(f) = (0..face_count).find(|&f| !height(f).is_finite()) {
        return Err(Error::InvalidArgument(format!(
            "the height of face {f} is {}; heights must be finite",
            height(f)
        )));
    }
    let vertex_count = mesh.vertex_count() as u64 + face_count as u64;
    let triangle_count = mesh.index_count() as u64;
    if vertex_count > MAX_ELEMENTS || triangle_count * 3 > MAX_ELEMENTS {
        return Err(Error::ResultTooLarge(format!(
            "stellating {face_count} faces would make {vertex_count} vertices and {triangle_count} triangles, over the limit of {MAX_ELEMENTS} elements"
        )));
    }
    let mut positions = try_vec(vertex_count as usize, "the stellated vertices")?;
    positions.extend_from_slice(mesh.positions());
    let mut face_sizes = try_vec(triangle_count as usize, "the stellated faces")?;
    face_sizes.resize(triangle_count as usize, 3);
    let mut face_indices = try_vec(triangle_count as usize * 3, "the stellated faces")?;
    let mut corners = Vec::new();
    for (f, face) in mesh.faces().enumerate() {
        corners.clear();
        corners.extend(face.iter().map(|&v| mesh.positions()[v as usize]));
        let (normal, centroid) = newell_normal_and_centroid(&corners);
        let apex = (mesh.vertex_count() + f) as u32;
        positions.push(centroid + normal * height(f));
        for k in 0..face.len() {
            face_indices.extend_from_slice(&[face[k], face[(k + 1) % face.len()], apex]);
        }
    }
    if let Some(p) = positions.iter().position(|p| !p.is_finite()) {
        return Err(Error::InvalidArgument(format!(
            "the apex of face {} lands at a non-finite position; the height is too large",
            p - mesh.vertex_count()
        )));
    }
    Ok(Mesh::from_valid_parts(positions, face_sizes, face_indices))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::shapes;
    use crate::mesh::topology::Topology;

    #[test]
    fn a_cube_gets_a_pyramid_on_every_face() {
        let cube = shapes::cube();
        let out = stellate(&cube, Heights::One(0.5)).unwrap();
        assert_eq!(out.vertex_count(), cube.vertex_count() + 6);
        assert_eq!(out.face_count(), 24);
        assert_eq!(&out.positions()[..8], cube.positions());
        let info = Topology::new(&out).info(&out);
        assert!(info.is_closed && info.is_oriented);
        let (lo, hi) = cube.bounding_box().unwrap();
        let center = (lo + hi) * 0.5;
        let half = (hi - lo).x * 0.5;
        for f in 0..6 {
            let apex = out.positions()[8 + f];
            // Outward along the face normal, half a unit past the face.
            assert!(((apex - center).length() - (half + 0.5)).abs() < 1e-12);
            let fan: Vec<&[u32]> = (0..4).map(|k| out.face(4 * f + k)).collect();
            assert!(fan.iter().all(|t| t[2] == 8 + f as u32));
            assert_eq!(fan[0][..2], cube.face(f)[..2]);
        }
    }

    #[test]
    fn per_face_heights_and_negative_heights() {
        let cube = shapes::cube();
        let heights = [0.0, -0.25, 1.0, 2.0, -1.0, 0.5];
        let out = stellate(&cube, Heights::PerFace(&heights)).unwrap();
        for (f, &h) in heights.iter().enumerate() {
            let corners: Vec<DVec3> = cube.face_positions(f).collect();
            let (normal, centroid) = newell_normal_and_centroid(&corners);
            assert!((out.positions()[8 + f] - (centroid + normal * h)).length() < 1e-12);
        }
    }

    #[test]
    fn bad_heights_are_named() {
        let cube = shapes::cube();
        let e = stellate(&cube, Heights::PerFace(&[1.0; 5])).unwrap_err();
        assert!(
            matches!(&e, Error::InvalidArgument(m) if m.contains("5 heights") && m.contains("6 faces")),
            "{e}"
        );
        let heights = [0.0, 0.0, f64::NAN, 0.0, 0.0, 0.0];
        let e = stellate(&cube, Heights::PerFace(&heights)).unwrap_err();
        assert!(
            matches!(&e, Error::InvalidArgument(m) if m.contains("face 2")),
            "{e}"
        );
        let e = stellate(&cube, Heights::One(f64::INFINITY)).unwrap_err();
        assert!(
            matches!(&e, Error::InvalidArgument(m) if m.contains("face 0")),
            "{e}"
        );
        let far = cube
            .with_positions(cube.positions().iter().map(|p| *p * 1e308).collect())
            .unwrap();
        let e = stellate(&far, Heights::One(f64::MAX)).unwrap_err();
        assert!(
            matches!(&e, Error::InvalidArgument(m) if m.contains("non-finite")),
            "{e}"
        );
    }
}
