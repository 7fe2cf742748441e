//! Shapes built in code (Weft's named shapes among them) and comparison
//! helpers shared by the tests.
#![allow(dead_code)]

use weft_reference::RefMesh;

/// A shape of `weft::mesh::shapes` as the bridge takes it.
fn from_weft(mesh: weft::Mesh) -> RefMesh {
    RefMesh {
        positions: mesh.positions().iter().flat_map(|p| p.to_array()).collect(),
        face_sizes: mesh.face_sizes().to_vec(),
        face_indices: mesh.face_indices().to_vec(),
    }
}

/// The unit cube `[0,1]^3`, 6 outward quads.
pub fn cube() -> RefMesh {
    from_weft(weft::mesh::shapes::cube())
}

/// A regular tetrahedron, 4 outward triangles.
pub fn tetrahedron() -> RefMesh {
    from_weft(weft::mesh::shapes::tetrahedron())
}

/// A regular icosahedron, 20 outward triangles.
pub fn icosahedron() -> RefMesh {
    from_weft(weft::mesh::shapes::icosahedron())
}

/// An `nx` × `ny` quad grid over a curved height field, so that no three
/// boundary vertices are collinear and boundary rules show.
pub fn bumpy_quad_grid(nx: u32, ny: u32) -> RefMesh {
    let mut positions = Vec::new();
    for j in 0..=ny {
        for i in 0..=nx {
            let (x, y) = (i as f64, j as f64);
            positions.extend([x, y, 0.1 * x * y + 0.05 * x * x - 0.03 * y * y]);
        }
    }
    let id = |i: u32, j: u32| j * (nx + 1) + i;
    let mut face_indices = Vec::new();
    for j in 0..ny {
        for i in 0..nx {
            face_indices.extend([id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)]);
        }
    }
    RefMesh {
        positions,
        face_sizes: vec![4; (nx * ny) as usize],
        face_indices,
    }
}

/// Three quads sharing the edge 0-1: a non-manifold fin.
pub fn fin() -> RefMesh {
    RefMesh::from_polygons(
        &[
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [1.0, 1.0, 0.0],
            [0.0, 1.0, 0.0],
            [1.0, -1.0, 0.0],
            [0.0, -1.0, 0.0],
            [1.0, 0.0, 1.0],
            [0.0, 0.0, 1.0],
        ],
        &[&[0, 1, 2, 3], &[1, 0, 5, 4], &[0, 1, 6, 7]],
    )
}

/// Two triangles touching at vertex 0 only: a bow-tie.
pub fn bow_tie() -> RefMesh {
    RefMesh::from_polygons(
        &[
            [0.0, 0.0, 0.0],
            [1.0, 1.0, 0.0],
            [1.0, -1.0, 0.0],
            [-1.0, -1.0, 0.0],
            [-1.0, 1.0, 0.0],
        ],
        &[&[0, 2, 1], &[0, 4, 3]],
    )
}

pub fn distance(a: [f64; 3], b: [f64; 3]) -> f64 {
    ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)).sqrt()
}

/// The vertex of `mesh` nearest to `p` and its distance.
pub fn nearest(mesh: &RefMesh, p: [f64; 3]) -> (usize, f64) {
    (0..mesh.vertex_count())
        .map(|v| (v, distance(mesh.position(v), p)))
        .min_by(|a, b| a.1.total_cmp(&b.1))
        .expect("mesh has vertices")
}

/// Asserts that `a` and `b` are the same mesh up to vertex and face order:
/// every vertex of `a` has a distinct vertex of `b` within `tolerance`, and
/// the faces, mapped through that matching and rotated to start at their
/// smallest index, are the same set (orientation included).
pub fn assert_same_mesh(a: &RefMesh, b: &RefMesh, tolerance: f64) {
    assert_eq!(a.vertex_count(), b.vertex_count(), "vertex counts");
    assert_eq!(a.face_count(), b.face_count(), "face counts");
    let mut map = vec![0u32; a.vertex_count()];
    let mut used = vec![false; b.vertex_count()];
    for (v, slot) in map.iter_mut().enumerate() {
        let (w, d) = nearest(b, a.position(v));
        assert!(
            d <= tolerance,
            "vertex {v} at {:?} is {d} from the nearest vertex of the other mesh",
            a.position(v)
        );
        assert!(!used[w], "two vertices match vertex {w}");
        used[w] = true;
        *slot = w as u32;
    }
    let canonical = |face: Vec<u32>| {
        let start = (0..face.len()).min_by_key(|&i| face[i]).unwrap();
        let mut rotated = face[start..].to_vec();
        rotated.extend_from_slice(&face[..start]);
        rotated
    };
    let mut fa: Vec<Vec<u32>> = a
        .faces()
        .map(|f| canonical(f.iter().map(|&v| map[v as usize]).collect()))
        .collect();
    let mut fb: Vec<Vec<u32>> = b.faces().map(|f| canonical(f.to_vec())).collect();
    fa.sort();
    fb.sort();
    assert_eq!(fa, fb, "faces differ");
}
