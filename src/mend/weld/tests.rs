use super::*;
use crate::mesh::shapes;
use crate::mesh::MeshOptions;
use crate::test_random::{units, words};

fn mesh(positions: &[[f64; 3]], faces: &[&[u32]]) -> Mesh {
    Mesh::from_polygons(
        positions.iter().map(|&p| DVec3::from_array(p)).collect(),
        faces.iter().copied(),
    )
    .unwrap()
}

#[test]
fn join_offsets_indices() {
    let a = shapes::cube();
    let b = shapes::tetrahedron();
    let joined = join(&[&a, &b, &Mesh::empty()]).unwrap();
    assert_eq!(joined.vertex_count(), 12);
    assert_eq!(joined.face_count(), 10);
    assert_eq!(joined.face(6), &[8, 9, 10]);
    assert_eq!(joined.positions()[8], b.positions()[0]);
    assert_eq!(join(&[]).unwrap(), Mesh::empty());
}

#[test]
fn transitive_chain_merges_into_its_first_vertex() {
    // 0.0, 0.6, 1.2, 1.8 apart by 0.6 with tolerance 0.7: one cluster of
    // four though its ends are 1.8 apart.
    let m = mesh(
        &[
            [0.0, 0.0, 0.0],
            [0.6, 0.0, 0.0],
            [1.2, 0.0, 0.0],
            [1.8, 0.0, 0.0],
            [0.0, 5.0, 0.0],
            [5.0, 5.0, 0.0],
        ],
        &[&[0, 5, 4], &[1, 5, 4], &[2, 5, 4], &[3, 5, 4]],
    );
    let (welded, report) = weld(&m, 0.7).unwrap();
    assert_eq!(welded.vertex_count(), 3);
    assert_eq!(welded.positions()[0], DVec3::ZERO);
    assert_eq!(report.merged_vertex_count, 3);
    assert_eq!(report.removed_face_count, 0);
    assert_eq!(welded.face_count(), 4);
    assert!(welded.faces().all(|f| f == [0, 2, 1]));
}

#[test]
fn quad_with_two_merged_corners_becomes_a_triangle() {
    let m = mesh(
        &[
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [1.0, 1e-4, 0.0],
            [0.0, 1.0, 0.0],
        ],
        &[&[0, 1, 2, 3]],
    );
    let (welded, report) = weld(&m, DEFAULT_WELD_TOLERANCE).unwrap();
    assert_eq!(welded.face(0), &[0, 1, 2]);
    assert_eq!(welded.positions()[1], DVec3::X);
    assert_eq!(welded.positions()[2], DVec3::Y);
    assert_eq!(report.merged_vertex_count, 1);
}

#[test]
fn face_collapsing_to_two_vertices_is_removed_and_counted() {
    let m = mesh(
        &[
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [1.0, 0.0, 0.0005],
            [9.0, 9.0, 9.0],
        ],
        // The second face keeps only 0 and 1 after welding 3 into 1.
        &[&[0, 1, 2], &[0, 1, 3], &[4, 0, 2]],
    );
    let (welded, report) = weld(&m, DEFAULT_WELD_TOLERANCE).unwrap();
    assert_eq!(report.removed_face_count, 1);
    assert_eq!(report.merged_vertex_count, 1);
    assert_eq!(report.unused_vertex_count, 0);
    assert_eq!(welded.face_count(), 2);
    assert_eq!(welded.vertex_count(), 4);
}

#[test]
fn unused_vertices_are_left_out_and_counted() {
    let m = mesh(
        &[
            [7.0, 7.0, 7.0],
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
        ],
        &[&[1, 2, 3]],
    );
    let (welded, report) = weld(&m, 0.0).unwrap();
    assert_eq!(report.unused_vertex_count, 1);
    assert_eq!(welded.positions()[0], DVec3::ZERO);
    assert_eq!(welded.face(0), &[0, 1, 2]);
    let (compact, removed) = remove_unused_vertices(&m);
    assert_eq!((&compact, removed), (&welded, 1));
    assert_eq!(remove_unused_vertices_owned(m.clone()), (welded, 1));
    // Every vertex used: the mesh comes back as it was.
    assert_eq!(remove_unused_vertices(&compact), (compact.clone(), 0));
    assert_eq!(
        remove_unused_vertices_owned(compact.clone()),
        (compact.clone(), 0)
    );
    assert_eq!(unused_vertex_count(&m), 1);
    assert_eq!(unused_vertex_count(&compact), 0);
}

#[test]
fn faces_naming_a_vertex_twice_lose_the_repeat_though_nothing_merges() {
    // Four distinct positions, every one in a face: only the repeats change.
    let positions: Vec<DVec3> = [
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [1.0, 1.0, 0.0],
        [0.0, 1.0, 0.0],
    ]
    .into_iter()
    .map(DVec3::from_array)
    .collect();
    let allow = MeshOptions {
        allow_repeated_vertices: true,
    };
    let m = Mesh::new_with(
        positions,
        vec![4, 3, 3],
        vec![0, 1, 1, 2, 2, 3, 0, 3, 3, 0],
        allow,
    )
    .unwrap();
    for (welded, report) in [
        weld(&m, 0.01).unwrap(),
        weld_owned(m.clone(), 0.01).unwrap(),
    ] {
        assert_eq!(report.merged_vertex_count, 0);
        assert_eq!(report.removed_face_count, 1);
        assert_eq!(welded.face_count(), 2);
        assert_eq!(welded.face(0), &[0, 1, 2]);
        assert_eq!(welded.face(1), &[2, 3, 0]);
    }
    // Without the repeats the same mesh comes back as it was, both ways.
    let clean = Mesh::new(m.positions().to_vec(), vec![3, 3], vec![0, 1, 2, 2, 3, 0]).unwrap();
    assert_eq!(
        weld(&clean, 0.01).unwrap(),
        (clean.clone(), WeldReport::default())
    );
    assert_eq!(
        weld_owned(clean.clone(), 0.01).unwrap(),
        (clean, WeldReport::default())
    );
}

#[test]
fn an_unused_last_vertex_is_found_whatever_the_vertex_count() {
    // 64 vertices, the corner only the last face uses left out; then a
    // 65th vertex no face uses: the last vertex ends a word of marks or not.
    let grid = shapes::quad_grid(7, 7);
    assert_eq!(grid.vertex_count(), 64);
    let kept = grid.face_count() - 1;
    let sizes = grid.face_sizes()[..kept].to_vec();
    let corners = grid.face_indices()[..4 * kept].to_vec();
    assert!(!corners.contains(&63));
    let without_corner = Mesh::new(grid.positions().to_vec(), sizes, corners).unwrap();
    let mut positions = grid.positions().to_vec();
    positions.push(DVec3::splat(9.0));
    let with_extra = Mesh::new(
        positions,
        grid.face_sizes().to_vec(),
        grid.face_indices().to_vec(),
    )
    .unwrap();
    for m in [without_corner, with_extra] {
        for (welded, report) in [
            weld(&m, 1e-6).unwrap(),
            weld_owned(m.clone(), 1e-6).unwrap(),
        ] {
            assert_eq!(report.unused_vertex_count, 1);
            assert_eq!(welded.vertex_count(), m.vertex_count() - 1);
        }
    }
}

#[test]
fn zero_tolerance_merges_exact_duplicates_only() {
    let m = mesh(
        &[
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [1.0, 0.0, 0.0],
            [1.0, 1.0, 1e-12],
        ],
        &[&[0, 1, 2], &[3, 4, 2]],
    );
    let (welded, report) = weld(&m, 0.0).unwrap();
    assert_eq!(report.merged_vertex_count, 1);
    assert_eq!(welded.face(1), &[1, 3, 2]);
}

#[test]
fn weld_is_idempotent() {
    let grid = shapes::quad_grid(6, 5);
    // Every face its own vertices, each jittered a little.
    let mut positions = Vec::new();
    let mut faces = Vec::new();
    for (f, face) in grid.faces().enumerate() {
        let mut out = Vec::new();
        for (k, &v) in face.iter().enumerate() {
            let jitter = ((f * 7 + k * 3) % 5) as f64 * 1e-4;
            positions.push(grid.positions()[v as usize] + DVec3::splat(jitter));
            out.push(positions.len() as u32 - 1);
        }
        faces.push(out);
    }
    let loose = Mesh::from_polygons(positions, faces).unwrap();
    let (once, report) = weld(&loose, DEFAULT_WELD_TOLERANCE).unwrap();
    assert_eq!(once.vertex_count(), grid.vertex_count());
    assert_eq!(report.merged_vertex_count, 4 * 30 - 42);
    let (twice, again) = weld(&once, DEFAULT_WELD_TOLERANCE).unwrap();
    assert_eq!(twice, once);
    assert_eq!(again, WeldReport::default());
}

#[test]
fn bad_tolerance_is_named() {
    let cube = shapes::cube();
    for t in [-1.0, f64::NAN, f64::INFINITY] {
        let err = weld(&cube, t).unwrap_err();
        assert!(matches!(&err, Error::InvalidArgument(m) if m.contains("tolerance")));
    }
}

#[test]
fn tolerance_larger_than_the_mesh_merges_everything_quickly() {
    // 40 000 distinct points in one cell: linear, not 800 million pairs.
    let grid = shapes::triangle_grid(199, 99);
    let (welded, report) = weld(&grid, 1e6).unwrap();
    assert_eq!(report.merged_vertex_count, grid.vertex_count() - 1);
    assert_eq!(report.removed_face_count, grid.face_count());
    assert_eq!(welded, Mesh::empty());
}

#[test]
fn far_from_origin_tiny_tolerance_still_works() {
    let m = mesh(
        &[[1e12, 0.0, 0.0], [1e12, 1.0, 0.0], [1e12, 0.0, 1.0]],
        &[&[0, 1, 2]],
    );
    let (welded, report) = weld(&m, 1e-12).unwrap();
    assert_eq!(welded, m);
    assert_eq!(report.merged_vertex_count, 0);
}

#[test]
fn a_face_soup_welds_back_to_its_mesh_in_order_of_first_use() {
    // Every quad of a torus with corners of its own, and after every fifth
    // quad a vertex no face uses: many blocks of vertices on every thread.
    let torus = shapes::torus(100, 60);
    let mut positions = Vec::new();
    let mut faces = Vec::new();
    let mut unused = 0;
    for f in 0..torus.face_count() {
        let start = positions.len() as u32;
        positions.extend(torus.face(f).iter().map(|&v| torus.positions()[v as usize]));
        faces.push((start..start + 4).collect::<Vec<u32>>());
        if f % 5 == 4 {
            positions.push(DVec3::new(1e3 + f as f64, 0.0, 0.0));
            unused += 1;
        }
    }
    let soup = Mesh::from_polygons(positions.clone(), &faces).unwrap();
    let (welded, report) = weld(&soup, 0.0).unwrap();

    // The torus's vertices numbered as its faces first name them.
    let mut number = vec![u32::MAX; torus.vertex_count()];
    let mut order = Vec::new();
    for &v in torus.face_indices() {
        if number[v as usize] == u32::MAX {
            number[v as usize] = order.len() as u32;
            order.push(torus.positions()[v as usize]);
        }
    }
    let renumbered: Vec<u32> = torus
        .face_indices()
        .iter()
        .map(|&v| number[v as usize])
        .collect();
    assert_eq!(welded.positions(), order.as_slice());
    assert_eq!(welded.face_indices(), renumbered.as_slice());
    assert_eq!(report.unused_vertex_count, unused);
    assert_eq!(
        report.merged_vertex_count,
        positions.len() - torus.vertex_count() - unused
    );
    assert_eq!(report.removed_face_count, 0);
}

/// The clusters of `positions` as labels, found with the cells of `grid`
/// packed into one word, then as they are.
fn packed_and_plain_labels(
    positions: &[DVec3],
    tolerance: f64,
    grid: CellGrid,
) -> [(Vec<u32>, usize); 2] {
    let (lo, hi) = bounding_box_of(positions).unwrap();
    let origin = PackedCell::origin(grid.cell(lo), grid.cell(hi)).unwrap();
    let packed = clusters_by(positions, tolerance, |p| {
        PackedCell::of(grid.cell(p), origin)
    })
    .unwrap();
    let plain = clusters_by(positions, tolerance, |p| grid.cell(p)).unwrap();
    [packed.into_labels(), plain.into_labels()]
}

#[test]
fn packed_cells_cluster_as_the_cells_themselves() {
    // Near and exact duplicates on a jittered grid, many per cell and across
    // cell borders, on both sides of the origin.
    let mut unit = units(0x2545_f491_4f6c_dd1d);
    let mut positions = Vec::new();
    for i in 0..20_000 {
        let p = DVec3::new(unit() * 40.0 - 20.0, unit() * 8.0 - 4.0, unit() * 2.0);
        positions.push(p);
        if i % 3 == 0 {
            positions.push(p);
        }
        if i % 5 == 0 {
            positions.push(p + DVec3::splat(0.03 * unit()));
        }
    }
    let tolerance = 0.05;
    let grid = CellGrid::new(positions.iter().copied(), tolerance);
    // The same partition: the clusters numbered in order of their first vertex.
    let [(a, count), (b, _)] = packed_and_plain_labels(&positions, tolerance, grid);
    assert_eq!(a, b);
    // Some vertices merged and most did not, so the comparison could fail.
    let merged = positions.len() - count;
    assert!(merged > 5_000 && merged < positions.len() / 2, "{merged}");
}

#[test]
fn clusters_are_those_of_every_pair_compared() {
    // Points in a box a few cells wide, plus pairs planted across a cell's
    // border in each of the 26 directions: every pair of cells that can
    // hold a close pair is walked, whichever row or order it comes in.
    let tolerance = 0.03;
    let grid = CellGrid::new([DVec3::ZERO, DVec3::ONE].into_iter(), tolerance);
    let mut unit = units(0x9e37_79b9_7f4a_7c15);
    let mut positions: Vec<DVec3> = (0..3_000)
        .map(|_| DVec3::new(unit(), unit(), unit()))
        .collect();
    for dx in -1..=1 {
        for dy in -1..=1 {
            for dz in -1..=1 {
                if (dx, dy, dz) == (0, 0, 0) {
                    continue;
                }
                // Just inside a cell, its partner just across the border.
                let corner = DVec3::splat(1.2 + 0.3 * unit());
                let cell = grid.cell(corner);
                let inner = DVec3::new(cell.0[0] as f64, cell.0[1] as f64, cell.0[2] as f64)
                    * grid.size
                    + DVec3::splat(grid.size * 0.5);
                let d = DVec3::new(dx as f64, dy as f64, dz as f64);
                let a = inner + d * (grid.size * 0.5 - tolerance * 0.1);
                let b = a + d.normalize() * (tolerance * 0.9);
                assert_ne!(grid.cell(a), grid.cell(b));
                positions.extend([a, b]);
            }
        }
    }
    let (expected, count) = every_pair_labels(&positions, tolerance);
    let [(packed, _), (plain, _)] = packed_and_plain_labels(&positions, tolerance, grid);
    assert_eq!(packed, expected);
    assert_eq!(plain, expected);
    // The planted pairs merged, and far from everything did.
    let merged = positions.len() - count;
    assert!(merged >= 26 && merged < positions.len() / 2, "{merged}");
}

/// The clusters of `positions` found by comparing every pair.
fn every_pair_labels(positions: &[DVec3], tolerance: f64) -> (Vec<u32>, usize) {
    let mut every_pair = UnionFind::new(positions.len());
    for i in 0..positions.len() {
        for j in i + 1..positions.len() {
            if within(positions[i], positions[j], tolerance) {
                every_pair.union(i as u32, j as u32);
            }
        }
    }
    every_pair.into_labels()
}

#[test]
fn crowded_cells_cluster_as_every_pair_compared() {
    // Tolerances many times the spacing: blobs of hundreds of points,
    // the nearest points of neighbouring blobs just within or just beyond
    // the tolerance; and two dense sheets a little more, and a little less,
    // than the tolerance apart.
    let mut unit = units(0x6a09_e667_f3bc_c908);
    let tolerance = 0.05;
    let mut cases: Vec<Vec<DVec3>> = Vec::new();
    for spread in [0.02, 0.08, 0.3] {
        let mut positions = Vec::new();
        for blob in 0..12 {
            let centre = DVec3::new((blob % 4) as f64 * 0.11, (blob / 4) as f64 * 0.13, 0.0);
            for _ in 0..150 {
                let d = DVec3::new(unit() - 0.5, unit() - 0.5, unit() - 0.5);
                positions.push(centre + d * spread);
            }
        }
        cases.push(positions);
    }
    for gap in [tolerance * 0.98, tolerance * 1.02] {
        let sheet = |z: f64, unit: &mut dyn FnMut() -> f64| -> Vec<DVec3> {
            (0..900)
                .map(|_| DVec3::new(unit() * 0.4, unit() * 0.4, z))
                .collect()
        };
        cases.push([sheet(0.0, &mut unit), sheet(gap, &mut unit)].concat());
    }
    let mut counts = Vec::new();
    for (case, positions) in cases.iter().enumerate() {
        let grid = CellGrid::new(positions.iter().copied(), tolerance);
        let (expected, count) = every_pair_labels(positions, tolerance);
        let [(packed, _), (plain, _)] = packed_and_plain_labels(positions, tolerance, grid);
        assert_eq!(packed, expected, "case {case}");
        assert_eq!(plain, expected, "case {case}");
        counts.push(count);
    }
    // Blobs that stay apart and blobs that join; sheets joined and apart.
    assert_eq!([counts[0], counts[3], counts[4]], [12, 1, 2], "{counts:?}");
    assert!(counts[1] < 12, "{counts:?}");
}

#[test]
fn cells_too_many_for_21_bits_are_not_packed() {
    let first = Cell([-5, 0, 0]);
    assert!(PackedCell::origin(first, Cell([(1 << 21) - 8, 3, 3])).is_some());
    assert!(PackedCell::origin(first, Cell([(1 << 21) - 7, 3, 3])).is_none());
    assert!(PackedCell::origin(Cell([i64::MIN, 0, 0]), Cell([i64::MAX, 0, 0])).is_none());
}

#[test]
fn a_large_polygon_with_merged_corners_loses_only_its_repeats() {
    // A 20-gon whose corners come in close pairs: it welds to a 10-gon.
    let positions: Vec<[f64; 3]> = (0..20)
        .map(|i| {
            let angle = (i / 2) as f64 * std::f64::consts::TAU / 10.0;
            let jitter = (i % 2) as f64 * 1e-9;
            [angle.cos() + jitter, angle.sin(), 0.0]
        })
        .collect();
    let face: Vec<u32> = (0..20).collect();
    let (welded, report) = weld(&mesh(&positions, &[&face]), 1e-6).unwrap();
    assert_eq!(welded.face_count(), 1);
    assert_eq!(welded.face(0), (0..10).collect::<Vec<u32>>().as_slice());
    assert_eq!(report.merged_vertex_count, 10);
    assert_eq!(report.removed_face_count, 0);
}

#[test]
fn welding_a_mesh_given_away_matches_welding_a_borrowed_one() {
    // Merged corners, a collapsed face, an unused vertex and mixed sizes:
    // every step of the in-place writing moves something.
    let m = mesh(
        &[
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 0.0, 0.0],
            [1.0, 1.0, 0.0],
            [5.0, 5.0, 5.0],
            [1.0, 0.0, 1e-9],
            [0.0, 1.0, 0.0],
            [2.0, 2.0, 0.0],
        ],
        &[&[0, 1, 3, 6], &[2, 5, 1], &[5, 3, 7], &[2, 3, 6, 7]],
    );
    let (welded, report) = weld(&m, 1e-6).unwrap();
    assert_eq!(report.merged_vertex_count, 2);
    assert_eq!(report.removed_face_count, 1);
    assert_eq!(report.unused_vertex_count, 1);
    assert_eq!(welded.face_sizes(), &[4, 3, 4]);
    assert_eq!(welded.face_indices(), &[0, 1, 2, 3, 1, 2, 4, 0, 2, 3, 4]);
    let kept = [0usize, 1, 3, 6, 7].map(|v| m.positions()[v]);
    assert_eq!(welded.positions(), &kept);
    assert_eq!(
        weld_owned(m.clone(), 1e-6).unwrap(),
        (welded.clone(), report)
    );

    // A host's arrays, lent: the weld writes a copy and leaves them as they were.
    let positions: &'static [DVec3] = Vec::leak(m.positions().to_vec());
    let indices: &'static [u32] = Vec::leak(m.face_indices().to_vec());
    let lent = Mesh::borrowing(positions, m.face_sizes(), indices, MeshOptions::default()).unwrap();
    assert_eq!(weld_owned(lent, 1e-6).unwrap(), (welded, report));
    assert_eq!(positions, m.positions());
    assert_eq!(indices, m.face_indices());
}

/// Faces over clusters as a plain walk: each face's clusters in order,
/// the first of each kept, faces under three corners left out.
fn faces_over_clusters_one_by_one(
    sizes: &[u32],
    indices: &[u32],
    cluster_of: &[u32],
) -> (Vec<u32>, Vec<u32>) {
    let (mut kept_sizes, mut kept_indices, mut read) = (Vec::new(), Vec::new(), 0);
    for &size in sizes {
        let mut face: Vec<u32> = Vec::new();
        for &v in &indices[read..read + size as usize] {
            let c = cluster_of[v as usize];
            if !face.contains(&c) {
                face.push(c);
            }
        }
        read += size as usize;
        if face.len() >= 3 {
            kept_sizes.push(face.len() as u32);
            kept_indices.extend(face);
        }
    }
    (kept_sizes, kept_indices)
}

#[test]
fn faces_over_clusters_in_blocks_match_one_face_after_another() {
    // Several blocks of faces of 3 to 40 corners over few clusters: faces
    // collapse in every block, so each block slides down over the gaps,
    // and the large faces drop their repeats through the set.
    let mut word = words(0x2545_F491_4F6C_DD1Du64);
    let mut next = |n: u64| word() % n;
    let vertex_count = 5000;
    for cluster_count in [3, 40, 5000] {
        let cluster_of: Vec<u32> = (0..vertex_count)
            .map(|_| next(cluster_count) as u32)
            .collect();
        let face_count = 2 * FACE_BLOCK + 777;
        let sizes: Vec<u32> = (0..face_count)
            .map(|f| match f % 97 {
                0 => 3 + next(38) as u32,
                _ => 3 + next(2) as u32,
            })
            .collect();
        let total: u32 = sizes.iter().sum();
        let indices: Vec<u32> = (0..total).map(|_| next(vertex_count) as u32).collect();
        let expected = faces_over_clusters_one_by_one(&sizes, &indices, &cluster_of);
        assert!(expected.0.len() < face_count, "some faces collapse");
        assert!(sizes.iter().any(|&n| n as usize > SCANNED_FACE_SIZE));
        let (mut sizes, mut indices) = (sizes, indices);
        let (corners, faces) = faces_over_clusters(&mut sizes, &mut indices, &cluster_of);
        assert_eq!(
            &sizes[..faces],
            expected.0.as_slice(),
            "{cluster_count} clusters"
        );
        assert_eq!(
            &indices[..corners],
            expected.1.as_slice(),
            "{cluster_count} clusters"
        );
    }
}

#[test]
fn cell_pieces_cut_between_whole_cells_and_cover_every_entry() {
    // Cells of 1 to 40 entries, one of them longer than a piece.
    let mut entries = Vec::new();
    for cell in 0..200u32 {
        let size = if cell == 77 { 400 } else { 1 + cell % 40 };
        let first = entries.len() as u32;
        entries.extend((first..first + size).map(|v| (Cell([cell as i64, 0, 0]), v)));
    }
    for count in [1, 2, 7, 16, 1000, 100_000] {
        let cuts: Vec<usize> = cell_pieces(&entries, count)
            .iter()
            .map(|&c| c as usize)
            .collect();
        assert_eq!((cuts[0], *cuts.last().unwrap()), (0, entries.len()));
        assert!(cuts.windows(2).all(|w| w[0] < w[1]), "{count}: {cuts:?}");
        for &cut in &cuts[1..cuts.len() - 1] {
            assert_ne!(
                entries[cut - 1].0,
                entries[cut].0,
                "{count}: cut inside a cell at {cut}"
            );
        }
        assert!(
            cuts.len() - 1 <= count.max(1),
            "{count}: {} pieces",
            cuts.len() - 1
        );
    }
    assert_eq!(cell_pieces::<Cell>(&[], 4), vec![0, 0]);
}

#[test]
fn copies_merged_in_pieces_give_the_clusters_of_every_vertex() {
    // A soup of a torus's quads (each position four times, its copies near
    // in order), some corners nudged within and some beyond the tolerance,
    // and every seventh quad's corners written again far from their face.
    let torus = shapes::torus(40, 30);
    let mut unit = units(0x9e37_79b9_7f4a_7c15);
    let mut positions = Vec::new();
    for f in 0..torus.face_count() {
        for &v in torus.face(f) {
            let p = torus.positions()[v as usize];
            let roll = unit();
            positions.push(match roll {
                r if r < 0.1 => p + DVec3::X * 0.004 * unit(),
                r if r < 0.15 => p + DVec3::Y * 0.02,
                _ => p,
            });
        }
    }
    let again: Vec<DVec3> = positions.iter().step_by(7).copied().collect();
    positions.extend(again);
    for tolerance in [0.0, 0.005] {
        let plain = {
            let (labels, count) = vertex_clusters(&positions, tolerance)
                .unwrap()
                .into_labels();
            Clusters {
                cluster_of: labels,
                count,
            }
        };
        // Some vertices merged and some did not, so the comparison could fail.
        assert!(plain.count > torus.vertex_count() && plain.count < positions.len() / 2);
        // Pieces of 3 show too few copies to merge first: the plain path.
        for piece in [3, 16, 64, 1000, 4096] {
            let pieces = Clusters::with_pieces(&positions, tolerance, piece).unwrap();
            let merged_first = copies::nearby_copies(&positions, piece).unwrap().is_some();
            assert_eq!(merged_first, piece > 3);
            assert!(
                pieces.count == plain.count && pieces.cluster_of == plain.cluster_of,
                "piece {piece}, tolerance {tolerance}"
            );
        }
    }
}

#[test]
fn cells_floor_as_floor_does_at_the_edges() {
    let tiny = f64::from_bits(1);
    for q in [
        0.0,
        -0.0,
        tiny,
        -tiny,
        0.5,
        -0.5,
        1.0 - f64::EPSILON / 2.0,
        -1.0 + f64::EPSILON / 2.0,
        -1.0,
        -3.0,
        2f64.powi(52) + 1.0,
        -(2f64.powi(52) + 1.0),
        2f64.powi(52) - 0.5,
        -(2f64.powi(52) - 0.5),
        2f64.powi(63),
        -(2f64.powi(63)),
        -(2f64.powi(63)) - 4096.0,
        f64::MAX,
        f64::MIN,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NAN,
    ] {
        assert_eq!(floor_to_i64(q), q.floor() as i64, "{q:e}");
    }
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(256))]

    /// The cell's floor is `floor`'s: for a double of any bit pattern,
    /// and for one in [-0.5, 0.5) scaled by 2^-70 to 2^69, which has a
    /// fraction far more often.
    #[test]
    fn cells_floor_as_floor_does(bits in proptest::num::u64::ANY, scale in -70i32..70) {
        let q = f64::from_bits(bits);
        // The bits' mantissa under the exponent of 1: a double in [1, 2).
        let one_to_two = f64::from_bits((bits & !(0x7ff << 52)) | (1023 << 52));
        let scaled = (one_to_two - 1.5) * 2f64.powi(scale);
        for q in [q, scaled] {
            proptest::prop_assert_eq!(floor_to_i64(q), q.floor() as i64, "{:e}", q);
        }
    }

    /// Any positions, any pieces, any tolerance: merging copies first
    /// changes neither the clusters nor their numbering.
    #[test]
    fn copies_merged_first_never_change_the_clusters(
        palette in proptest::collection::vec((0u8..6, 0u8..6, 0u8..3, 0u8..4), 1..40),
        picks in proptest::collection::vec(0usize..1000, 2..400),
        piece in 1usize..40,
        tolerance in proptest::sample::select(vec![0.0, 0.05, 0.3, 1.0, 10.0]),
    ) {
        // Points of a coarse lattice, some nudged by 0.1 or 0.2 (within
        // some tolerances, beyond others), -0 beside +0; each vertex one of
        // a few of them, so that copies abound.
        let palette: Vec<DVec3> = palette
            .iter()
            .map(|&(x, y, z, nudge)| {
                let x = if x == 0 && nudge == 3 { -0.0 } else { f64::from(x) };
                DVec3::new(x, f64::from(y) + 0.1 * f64::from(nudge % 3), f64::from(z))
            })
            .collect();
        let positions: Vec<DVec3> = picks.iter().map(|&k| palette[k % palette.len()]).collect();
        let (plain, plain_count) = vertex_clusters(&positions, tolerance).unwrap().into_labels();
        let pieces = Clusters::with_pieces(&positions, tolerance, piece).unwrap();
        proptest::prop_assert_eq!(pieces.count, plain_count);
        proptest::prop_assert_eq!(pieces.cluster_of, plain);
    }
}
