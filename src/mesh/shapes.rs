//! Named shapes built in code, for tests, benchmarks and examples: each is
//! small, exact and outward-facing where it is closed.

use std::f64::consts::TAU;

use glam::DVec3;

use crate::mesh::Mesh;

fn mesh(positions: Vec<DVec3>, polygons: &[&[u32]]) -> Mesh {
    Mesh::from_polygons(positions, polygons.iter().copied()).expect("named shapes are valid")
}

/// The unit cube `[0,1]^3`: 8 vertices, 6 outward quads.
pub fn cube() -> Mesh {
    let p = (0..8)
        .map(|i| DVec3::new((i & 1) as f64, ((i >> 1) & 1) as f64, ((i >> 2) & 1) as f64))
        .collect();
    mesh(
        p,
        &[
            &[0, 2, 3, 1], // z = 0, facing -z
            &[4, 5, 7, 6], // z = 1
            &[0, 1, 5, 4], // y = 0
            &[2, 6, 7, 3], // y = 1
            &[0, 4, 6, 2], // x = 0
            &[1, 3, 7, 5], // x = 1
        ],
    )
}

/// A regular tetrahedron: 4 outward triangles.
pub fn tetrahedron() -> Mesh {
    let p = vec![
        DVec3::new(1.0, 1.0, 1.0),
        DVec3::new(1.0, -1.0, -1.0),
        DVec3::new(-1.0, 1.0, -1.0),
        DVec3::new(-1.0, -1.0, 1.0),
    ];
    mesh(p, &[&[0, 1, 2], &[0, 3, 1], &[0, 2, 3], &[1, 3, 2]])
}

/// A regular icosahedron: 12 vertices, 20 outward triangles.
pub fn icosahedron() -> Mesh {
    let t = (1.0 + 5f64.sqrt()) / 2.0;
    let p = vec![
        DVec3::new(-1.0, t, 0.0),
        DVec3::new(1.0, t, 0.0),
        DVec3::new(-1.0, -t, 0.0),
        DVec3::new(1.0, -t, 0.0),
        DVec3::new(0.0, -1.0, t),
        DVec3::new(0.0, 1.0, t),
        DVec3::new(0.0, -1.0, -t),
        DVec3::new(0.0, 1.0, -t),
        DVec3::new(t, 0.0, -1.0),
        DVec3::new(t, 0.0, 1.0),
        DVec3::new(-t, 0.0, -1.0),
        DVec3::new(-t, 0.0, 1.0),
    ];
    mesh(
        p,
        &[
            &[0, 11, 5],
            &[0, 5, 1],
            &[0, 1, 7],
            &[0, 7, 10],
            &[0, 10, 11],
            &[1, 5, 9],
            &[5, 11, 4],
            &[11, 10, 2],
            &[10, 7, 6],
            &[7, 1, 8],
            &[3, 9, 4],
            &[3, 4, 2],
            &[3, 2, 6],
            &[3, 6, 8],
            &[3, 8, 9],
            &[4, 9, 5],
            &[2, 4, 11],
            &[6, 2, 10],
            &[8, 6, 7],
            &[9, 8, 1],
        ],
    )
}

/// A torus of `u` × `v` outward quads around the z axis (radii 1 and 0.35).
pub fn torus(u: usize, v: usize) -> Mesh {
    let (major, minor) = (1.0, 0.35);
    let mut p = Vec::with_capacity(u * v);
    for i in 0..u {
        let a = TAU * i as f64 / u as f64;
        for j in 0..v {
            let b = TAU * j as f64 / v as f64;
            let r = major + minor * b.cos();
            p.push(DVec3::new(r * a.cos(), r * a.sin(), minor * b.sin()));
        }
    }
    let id = |i: usize, j: usize| ((i % u) * v + j % v) as u32;
    let faces: Vec<[u32; 4]> = (0..u)
        .flat_map(|i| (0..v).map(move |j| [id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)]))
        .collect();
    Mesh::from_polygons(p, faces).expect("torus is valid")
}

/// The torus of [`torus`] with each quad split into two triangles.
pub fn triangle_torus(u: usize, v: usize) -> Mesh {
    split_quads(&torus(u, v))
}

/// A disc of `n` triangles around one vertex (vertex 0, at the origin),
/// its rim the unit circle in the z = 0 plane: a vertex of valence `n`.
pub fn fan(n: u32) -> Mesh {
    let mut p = vec![DVec3::ZERO];
    p.extend((0..n).map(|k| {
        let a = std::f64::consts::TAU * f64::from(k) / f64::from(n);
        DVec3::new(a.cos(), a.sin(), 0.0)
    }));
    let faces: Vec<[u32; 3]> = (0..n).map(|k| [0, 1 + k, 1 + (k + 1) % n]).collect();
    Mesh::from_polygons(p, faces).expect("fan is valid")
}

/// `n` triangles on one edge (vertices 0 and 1), like the pages of a book:
/// an edge of `n` faces.
pub fn book(n: u32) -> Mesh {
    let mut p = vec![DVec3::ZERO, DVec3::Z];
    p.extend((0..n).map(|k| {
        let a = std::f64::consts::TAU * f64::from(k) / f64::from(n);
        DVec3::new(a.cos(), a.sin(), 0.5)
    }));
    let faces: Vec<[u32; 3]> = (0..n).map(|k| [0, 1, 2 + k]).collect();
    Mesh::from_polygons(p, faces).expect("book is valid")
}

/// A flat grid of `nx` × `ny` unit quads in the z = 0 plane, facing +z.
pub fn quad_grid(nx: usize, ny: usize) -> Mesh {
    let p = (0..=ny)
        .flat_map(|j| (0..=nx).map(move |i| DVec3::new(i as f64, j as f64, 0.0)))
        .collect();
    let id = |i: usize, j: usize| (j * (nx + 1) + i) as u32;
    let faces: Vec<[u32; 4]> = (0..ny)
        .flat_map(|j| {
            (0..nx).map(move |i| [id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)])
        })
        .collect();
    Mesh::from_polygons(p, faces).expect("grid is valid")
}

/// The grid of [`quad_grid`] with each quad split into two triangles.
pub fn triangle_grid(nx: usize, ny: usize) -> Mesh {
    split_quads(&quad_grid(nx, ny))
}

/// A 4 × 4 quad grid with its middle 2 × 2 quads removed: a square hole.
pub fn quad_grid_with_hole() -> Mesh {
    let grid = quad_grid(4, 4);
    let faces: Vec<&[u32]> = grid
        .faces()
        .enumerate()
        .filter(|&(f, _)| ![5, 6, 9, 10].contains(&f))
        .map(|(_, face)| face)
        .collect();
    Mesh::from_polygons(grid.positions().to_vec(), faces).expect("holed grid is valid")
}

/// [`quad_grid_with_hole`] with each quad split into two triangles.
pub fn triangle_grid_with_hole() -> Mesh {
    split_quads(&quad_grid_with_hole())
}

/// A closed solid of mixed polygons: a hexagonal prism whose top and bottom
/// are hexagons, with a vertex added on one vertical edge (its two side faces
/// become pentagons) and one side quad split into two triangles.
pub fn mixed_polygons() -> Mesh {
    let mut p: Vec<DVec3> = (0..12)
        .map(|i| {
            let a = TAU * (i % 6) as f64 / 6.0;
            DVec3::new(a.cos(), a.sin(), if i < 6 { 0.0 } else { 1.0 })
        })
        .collect();
    p.push(DVec3::new(1.0, 0.0, 0.5)); // 12, on the edge 0-6
    mesh(
        p,
        &[
            &[5, 4, 3, 2, 1, 0],
            &[6, 7, 8, 9, 10, 11],
            &[0, 1, 7, 6, 12],
            &[5, 0, 12, 6, 11],
            &[1, 2, 8, 7],
            &[2, 3, 9],
            &[2, 9, 8],
            &[3, 4, 10, 9],
            &[4, 5, 11, 10],
        ],
    )
}

/// A concave L-shaped hexagon in the plane z = `z`, facing +z: area 3,
/// the shape an ear clipper must not cut across.
pub fn l_shaped_hexagon(z: f64) -> Mesh {
    let corners = [
        (0.0, 0.0),
        (2.0, 0.0),
        (2.0, 1.0),
        (1.0, 1.0),
        (1.0, 2.0),
        (0.0, 2.0),
    ]
    .map(|(x, y)| DVec3::new(x, y, z));
    Mesh::from_polygons(corners.to_vec(), [[0u32, 1, 2, 3, 4, 5]]).unwrap()
}

/// Three triangles sharing the edge 0-1: a non-manifold fin.
pub fn fin() -> Mesh {
    let p = vec![
        DVec3::new(0.0, 0.0, 0.0),
        DVec3::new(1.0, 0.0, 0.0),
        DVec3::new(0.5, 1.0, 0.0),
        DVec3::new(0.5, -1.0, 0.0),
        DVec3::new(0.5, 0.0, 1.0),
    ];
    mesh(p, &[&[0, 1, 2], &[1, 0, 3], &[0, 1, 4]])
}

/// Two fans of two triangles each that meet only at vertex 0: a bow-tie.
pub fn bow_tie() -> Mesh {
    let p = vec![
        DVec3::new(0.0, 0.0, 0.0),
        DVec3::new(1.0, -0.5, 0.0),
        DVec3::new(1.2, 0.0, 0.0),
        DVec3::new(1.0, 0.5, 0.0),
        DVec3::new(-1.0, 0.5, 0.0),
        DVec3::new(-1.2, 0.0, 0.0),
        DVec3::new(-1.0, -0.5, 0.0),
    ];
    mesh(p, &[&[0, 1, 2], &[0, 2, 3], &[0, 4, 5], &[0, 5, 6]])
}

/// A Möbius strip of `n` quads (n ≥ 3): not orientable, one boundary loop.
pub fn mobius_strip(n: usize) -> Mesh {
    let mut p = Vec::with_capacity(2 * n);
    for i in 0..n {
        let a = TAU * i as f64 / n as f64;
        let twist = a / 2.0;
        let centre = DVec3::new(a.cos(), a.sin(), 0.0);
        let across = DVec3::new(twist.cos() * a.cos(), twist.cos() * a.sin(), twist.sin()) * 0.3;
        p.push(centre - across);
        p.push(centre + across);
    }
    let faces: Vec<[u32; 4]> = (0..n)
        .map(|i| {
            let (a, b) = (2 * i as u32, 2 * i as u32 + 1);
            let (c, d) = if i + 1 < n {
                (2 * (i as u32 + 1), 2 * (i as u32 + 1) + 1)
            } else {
                (1, 0) // the half twist: the strip closes on itself flipped
            };
            [a, c, d, b]
        })
        .collect();
    Mesh::from_polygons(p, faces).expect("strip is valid")
}

/// Splits every quad along its 0-2 diagonal; other faces are kept.
fn split_quads(mesh: &Mesh) -> Mesh {
    let mut faces: Vec<Vec<u32>> = Vec::with_capacity(mesh.face_count() * 2);
    for f in mesh.faces() {
        if let &[a, b, c, d] = f {
            faces.push(vec![a, b, c]);
            faces.push(vec![a, c, d]);
        } else {
            faces.push(f.to_vec());
        }
    }
    Mesh::from_polygons(mesh.positions().to_vec(), faces).expect("split keeps validity")
}

/// A soup of `sizes.len()` faces whose corners name the vertices of a
/// shuffle of `0..vertices` one after another, `extra` vertices named by
/// none; with `shared`, corner 0 of the last face names the first corner's
/// vertex.
#[cfg(test)]
pub(crate) fn soup(sizes: &[u32], extra: usize, seed: u64, shared: bool) -> Mesh {
    let corners: usize = sizes.iter().map(|&s| s as usize).sum();
    let vertices = corners + extra;
    let mut order: Vec<u32> = (0..vertices as u32).collect();
    // A fixed shuffle (xorshift) so the vertices are named out of order.
    let mut state = seed | 1;
    for i in (1..order.len()).rev() {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        order.swap(i, (state % (i as u64 + 1)) as usize);
    }
    let mut indices = order[..corners].to_vec();
    if shared && sizes.len() > 1 {
        let last = corners - *sizes.last().unwrap() as usize;
        indices[last] = indices[0];
    }
    let positions = (0..vertices)
        .map(|v| DVec3::new(v as f64, (v * v % 7) as f64, (v % 3) as f64))
        .collect();
    Mesh::new(positions, sizes.to_vec(), indices).unwrap()
}

/// Faces over a handful of vertices, so edges carry one, two or more
/// faces either way round and vertices hold several fans; with
/// `repeats`, faces may name a vertex more than once.
#[cfg(test)]
pub(crate) fn tangles() -> impl proptest::strategy::Strategy<Value = Mesh> {
    use proptest::prelude::*;
    let distinct =
        proptest::sample::subsequence((0u32..8).collect::<Vec<_>>(), 3..6).prop_shuffle();
    let repeating = proptest::collection::vec(0u32..8, 3..6);
    prop_oneof![
        proptest::collection::vec(distinct, 1..14).prop_map(|faces| (faces, false)),
        proptest::collection::vec(repeating, 1..14).prop_map(|faces| (faces, true)),
    ]
    .prop_map(|(faces, repeats)| {
        Mesh::new_with(
            (0..8)
                .map(|i| glam::DVec3::new(i as f64, (i * i % 5) as f64, (i % 3) as f64))
                .collect(),
            faces.iter().map(|f| f.len() as u32).collect(),
            faces.concat(),
            crate::mesh::MeshOptions {
                allow_repeated_vertices: repeats,
            },
        )
        .unwrap()
    })
}

/// Random [`soup`]s: up to 40 faces of 3 to 6 corners, some with a vertex
/// shared.
#[cfg(test)]
pub(crate) fn soups() -> impl proptest::strategy::Strategy<Value = Mesh> {
    use proptest::prelude::*;
    (
        proptest::collection::vec(3u32..7, 0..40),
        0usize..5,
        any::<u64>(),
        any::<bool>(),
    )
        .prop_map(|(sizes, extra, seed, shared)| soup(&sizes, extra, seed, shared))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::topology::Topology;

    #[test]
    fn closed_shapes_have_euler_characteristic_of_their_genus() {
        for (mesh, chi) in [
            (cube(), 2),
            (tetrahedron(), 2),
            (icosahedron(), 2),
            (mixed_polygons(), 2),
            (torus(6, 4), 0),
            (triangle_torus(6, 4), 0),
        ] {
            let info = Topology::new(&mesh).info(&mesh);
            let euler = info.vertex_count as i64 - info.edge_count as i64 + info.face_count as i64;
            assert_eq!(euler, chi);
            assert!(info.is_closed && info.is_oriented, "{info:?}");
        }
    }

    #[test]
    fn closed_shapes_face_outward() {
        // Signed volume by the divergence theorem is positive when faces point out.
        for mesh in [
            cube(),
            tetrahedron(),
            icosahedron(),
            mixed_polygons(),
            torus(8, 6),
        ] {
            let volume: f64 = mesh
                .faces()
                .map(|f| {
                    let p: Vec<DVec3> = f.iter().map(|&v| mesh.positions()[v as usize]).collect();
                    (1..p.len() - 1)
                        .map(|i| p[0].dot(p[i].cross(p[i + 1])))
                        .sum::<f64>()
                })
                .sum::<f64>()
                / 6.0;
            assert!(volume > 0.0);
        }
    }
}
