//! T-nodes: vertices that lie inside another face's naked edge.
//!
//! Two surface meshes with different U/V counts meet along a seam where the
//! vertices of one fall between the vertices of the other. Welding cannot
//! join them (no two vertices coincide); the seam stays open and subdivision
//! pulls it apart. [`find_t_nodes`](crate::mend::t_nodes::find_t_nodes) reports
//! each such vertex with the edge and the parameter along it;
//! [`repair_t_nodes`](crate::mend::t_nodes::repair_t_nodes) inserts the vertex
//! into that edge, so the face becomes an n-gon and both sides share every
//! seam edge.
//!
//! The naked edges are registered in the cells of a uniform grid that they
//! pass through (a 3-D digital differential analyser, Amanatides & Woo 1987),
//! and each boundary vertex is tested against the edges of the cells within
//! the tolerance of it only (its own, and of its 26 neighbours those whose
//! side is that close), on all threads.

use glam::DVec3;
use rayon::prelude::*;

use crate::buffers::{try_vec, CHUNK};
use crate::error::Result;
use crate::mend::weld::{within, Cell, CellGrid, CellMap};
use crate::mesh::check_tolerance;
use crate::mesh::corners::CornerFaces;
use crate::mesh::topology::Edges;
use crate::mesh::Mesh;

/// Naked edges whose cells one task finds.
const SEGMENTS_A_PART: usize = 1 << 16;

/// A vertex lying inside a naked edge of a face it does not belong to.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TNode {
    /// The vertex that lies on the edge.
    pub vertex: u32,
    /// The edge's vertices in the direction the face runs it.
    pub edge: [u32; 2],
    /// The face whose edge it is.
    pub face: u32,
    /// Where the vertex's closest point on the edge lies, from 0 at
    /// `edge[0]` to 1 at `edge[1]`; always strictly between.
    pub parameter: f64,
}

/// Finds the T-nodes: each vertex on a naked edge of its own faces that lies
/// within `tolerance` of the inside of a naked edge of another face, and
/// further than `tolerance` from both its ends (closer, it is a matter for
/// welding). Sorted by face, then by the edge's place in the face, then by
/// parameter.
///
/// Only boundary vertices are candidates: a vertex inside its own surface
/// that touches another piece's boundary cannot be stitched into it.
///
/// Distances are measured without squaring coordinates, so the search works
/// the same for coordinates near 1e-300 or 1e300, and the grid of cells the
/// edges are filed in coarsens until they cross a number of cells linear in
/// their count: time and memory stay linear whatever the scale.
///
/// # Errors
/// [`Error::InvalidArgument`](crate::Error::InvalidArgument) when `tolerance`
/// is negative, NaN or infinite; [`Error::OutOfMemory`](crate::Error::OutOfMemory).
pub fn find_t_nodes(mesh: &Mesh, tolerance: f64) -> Result<Vec<TNode>> {
    Ok(find_with_corners(mesh, tolerance)?
        .into_iter()
        .map(|(_, node)| node)
        .collect())
}

/// Inserts every T-node's vertex into its edge (several on one edge in order
/// of parameter), turning the face into an n-gon; positions do not change.
/// Returns the repaired mesh and the number of vertices inserted.
///
/// A vertex already in a face is not inserted into it twice.
///
/// # Errors
/// As [`find_t_nodes`].
pub fn repair_t_nodes(mesh: &Mesh, tolerance: f64) -> Result<(Mesh, usize)> {
    let nodes = find_with_corners(mesh, tolerance)?;
    if nodes.is_empty() {
        return Ok((mesh.clone(), 0));
    }
    let corners = mesh.face_indices();
    let mut face_sizes = try_vec::<u32>(mesh.face_count(), "the repaired face sizes")?;
    let mut face_indices =
        try_vec::<u32>(corners.len() + nodes.len(), "the repaired face indices")?;
    let mut inserted = 0;
    let mut next = 0;
    for (f, w) in mesh.face_offsets().windows(2).enumerate() {
        let start = face_indices.len();
        let face = &corners[w[0] as usize..w[1] as usize];
        for c in w[0]..w[1] {
            face_indices.push(corners[c as usize]);
            while next < nodes.len() && nodes[next].0 == c {
                let v = nodes[next].1.vertex;
                debug_assert_eq!(nodes[next].1.face as usize, f);
                if !face.contains(&v) && !face_indices[start..].contains(&v) {
                    face_indices.push(v);
                    inserted += 1;
                }
                next += 1;
            }
        }
        face_sizes.push((face_indices.len() - start) as u32);
    }
    Ok((
        Mesh::from_valid_parts(mesh.positions().to_vec(), face_sizes, face_indices),
        inserted,
    ))
}

/// The T-nodes with the corner whose edge each lies on, sorted by corner and parameter.
fn find_with_corners(mesh: &Mesh, tolerance: f64) -> Result<Vec<(u32, TNode)>> {
    check_tolerance(tolerance)?;
    // A naked edge has one corner: which corners those are is all the
    // search needs of the topology.
    let (corners, naked) =
        rayon::join(|| CornerFaces::of_mesh(mesh), || Edges::naked_corners(mesh));
    let (corners, naked) = (corners?, naked?);
    let naked_corner: Vec<u32> = (0..naked.len() as u32)
        .into_par_iter()
        .with_min_len(CHUNK)
        .filter(|&c| naked[c as usize])
        .collect();
    drop(naked);
    if naked_corner.is_empty() {
        return Ok(Vec::new());
    }
    let positions = mesh.positions();
    let corner_vertices = mesh.face_indices();
    let segment = |k: usize| {
        let c = naked_corner[k] as usize;
        (
            positions[corner_vertices[c] as usize],
            positions[corner_vertices[corners.next(c)] as usize],
        )
    };
    // Cells about as long as the naked edges, so that each edge passes
    // through a few cells and each cell holds a few edges.
    let mean_length = (0..naked_corner.len())
        .map(|k| {
            let (a, b) = segment(k);
            a.distance(b)
        })
        .sum::<f64>()
        / naked_corner.len() as f64;
    // The mean can underflow to 0 (coordinates near 1e-300 square to 0) or
    // come out far too small; coarsen until the edges pass through a number
    // of cells linear in their count, so the cell lists stay small.
    let cell_limit = 8 * naked_corner.len() as u64 + 64;
    let mut size = mean_length.max(tolerance);
    let grid = loop {
        let grid = CellGrid::new(positions.iter().copied(), size);
        let cell_count = (0..naked_corner.len()).fold(0u64, |total, k| {
            let (a, b) = segment(k);
            total.saturating_add(1 + grid.cell(a).steps_to(grid.cell(b)))
        });
        if cell_count <= cell_limit || !grid.size.is_finite() {
            break grid;
        }
        size = grid.size * 2.0;
    };

    // Every naked edge under each cell it passes through, sorted by cell:
    // on all threads, as a mesh read from STL has nothing but naked edges.
    let parts: Vec<Vec<(Cell, u32)>> = (0..naked_corner.len().div_ceil(SEGMENTS_A_PART))
        .into_par_iter()
        .map(|part| {
            let ks = part * SEGMENTS_A_PART..((part + 1) * SEGMENTS_A_PART).min(naked_corner.len());
            let (mut entries, mut cells) = (Vec::with_capacity(3 * ks.len()), Vec::new());
            for k in ks {
                let (a, b) = segment(k);
                cells_on_segment(&grid, a, b, &mut cells);
                entries.extend(cells.iter().map(|&cell| (cell, k as u32)));
            }
            entries
        })
        .collect();
    let mut entries = try_vec(
        parts.iter().map(Vec::len).sum(),
        "the T-node search's cells",
    )?;
    for part in parts {
        entries.extend(part);
    }
    entries.par_sort_unstable();
    entries.dedup();
    let mut cell_ranges: CellMap<(u32, u32)> = CellMap::default();
    let mut start = 0;
    for i in 1..=entries.len() {
        if i == entries.len() || entries[i].0 != entries[start].0 {
            cell_ranges.insert(entries[start].0, (start as u32, i as u32));
            start = i;
        }
    }

    let mut on_boundary = vec![false; mesh.vertex_count()];
    for &c in &naked_corner {
        on_boundary[corner_vertices[c as usize] as usize] = true;
        on_boundary[corner_vertices[corners.next(c as usize)] as usize] = true;
    }
    // The T-nodes at vertex v, among the edges of the cells within
    // `tolerance` of it.
    let nodes_at = |v: usize, candidates: &mut Vec<u32>, found: &mut Vec<(u32, TNode)>| {
        let p = positions[v];
        candidates.clear();
        for cell in cells_near(&grid, p, tolerance) {
            if let Some(&(s, e)) = cell_ranges.get(&cell) {
                candidates.extend(entries[s as usize..e as usize].iter().map(|x| x.1));
            }
        }
        candidates.sort_unstable();
        candidates.dedup();
        for &k in candidates.iter() {
            let c = naked_corner[k as usize] as usize;
            let (va, vb) = (corner_vertices[c], corner_vertices[corners.next(c)]);
            let (a, b) = (positions[va as usize], positions[vb as usize]);
            // At an end (a copy of v, as STL stores every corner): a matter
            // for welding, as `parameter_inside` finds, without arithmetic.
            if p == a || p == b {
                continue;
            }
            let face = corners.face(c) as u32;
            if va as usize == v
                || vb as usize == v
                || mesh.face(face as usize).contains(&(v as u32))
            {
                continue;
            }
            if let Some(t) = parameter_inside(p, a, b, tolerance) {
                found.push((
                    c as u32,
                    TNode {
                        vertex: v as u32,
                        edge: [va, vb],
                        face,
                        parameter: t,
                    },
                ));
            }
        }
    };
    let mut found: Vec<(u32, TNode)> = (0..mesh.vertex_count())
        .into_par_iter()
        .with_min_len(CHUNK)
        .filter(|&v| on_boundary[v])
        .fold(
            || (Vec::new(), Vec::new()),
            |(mut candidates, mut found), v| {
                nodes_at(v, &mut candidates, &mut found);
                (candidates, found)
            },
        )
        .map(|(_, found)| found)
        .reduce(Vec::new, |mut a, mut b| {
            a.append(&mut b);
            a
        });
    found.par_sort_unstable_by(|x, y| {
        x.0.cmp(&y.0)
            .then(x.1.parameter.total_cmp(&y.1.parameter))
            .then(x.1.vertex.cmp(&y.1.vertex))
    });
    Ok(found)
}

/// Where `p` lies along the edge from `a` to `b` (0 at `a`, 1 at `b`) when
/// it is within `tolerance` of the edge's inside and further than that from
/// both ends (closer, it is a matter for welding).
fn parameter_inside(p: DVec3, a: DVec3, b: DVec3, tolerance: f64) -> Option<f64> {
    // Measured in units of the edge's largest coordinate difference, so
    // squares neither underflow (coordinates near 1e-300) nor overflow
    // (near 1e300).
    let unit = (b - a).abs().max_element();
    if unit == 0.0 || !unit.is_finite() {
        return None;
    }
    let d = (b - a) / unit;
    let t = ((p - a) / unit).dot(d) / d.length_squared();
    if !(t > 0.0 && t < 1.0) {
        return None;
    }
    let near_end = within(p, a, tolerance) || within(p, b, tolerance);
    (!near_end && within(p, a.lerp(b, t), tolerance)).then_some(t)
}

/// The cells of `grid` within `tolerance` of `p` (the cell of `p` and
/// those of its 26 neighbours whose side is that close), which hold every
/// edge passing within `tolerance` of `p`: cells are never narrower than
/// `tolerance`. A margin of 2^-10 of a cell covers the round-off of placing
/// `p` and the edges in cells: cell numbers stay below 2^41 (see
/// [`CellGrid::with_reach`]), where a double's step is 2^-12.
fn cells_near(grid: &CellGrid, p: DVec3, tolerance: f64) -> impl Iterator<Item = Cell> {
    let home = grid.cell(p);
    let reach = tolerance / grid.size + 1.0 / 1024.0;
    let steps = |axis: usize| {
        let t = p[axis] / grid.size;
        let inside = t - home.0[axis] as f64;
        let low = (inside <= reach) as i64;
        let high = (1.0 - inside <= reach) as i64;
        -low..=high
    };
    let (xs, ys, zs) = (steps(0), steps(1), steps(2));
    xs.flat_map(move |dx| {
        let zs = zs.clone();
        ys.clone()
            .flat_map(move |dy| zs.clone().map(move |dz| home.offset([dx, dy, dz])))
    })
}

/// The cells the segment from `a` to `b` passes through, in order
/// (Amanatides & Woo's traversal).
fn cells_on_segment(grid: &CellGrid, a: DVec3, b: DVec3, cells: &mut Vec<Cell>) {
    cells.clear();
    let (start, end) = (grid.cell(a), grid.cell(b));
    let mut cell = start;
    cells.push(cell);
    let d = b - a;
    let mut step = [0i64; 3];
    let mut t_max = [f64::INFINITY; 3];
    let mut t_delta = [f64::INFINITY; 3];
    for axis in 0..3 {
        if d[axis] > 0.0 {
            step[axis] = 1;
            let boundary = (cell.0[axis] + 1) as f64 * grid.size;
            t_max[axis] = (boundary - a[axis]) / d[axis];
            t_delta[axis] = grid.size / d[axis];
        } else if d[axis] < 0.0 {
            step[axis] = -1;
            let boundary = cell.0[axis] as f64 * grid.size;
            t_max[axis] = (boundary - a[axis]) / d[axis];
            t_delta[axis] = -grid.size / d[axis];
        }
    }
    // The number of steps is fixed by the end cell, so round-off cannot loop.
    let steps = start.steps_to(end);
    for _ in 0..steps {
        let axis = if t_max[0] <= t_max[1] && t_max[0] <= t_max[2] {
            0
        } else if t_max[1] <= t_max[2] {
            1
        } else {
            2
        };
        cell.0[axis] += step[axis];
        t_max[axis] += t_delta[axis];
        cells.push(cell);
    }
    if cell != end {
        cells.push(end);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::topology::Topology;

    #[test]
    fn segment_cells_are_connected_and_reach_the_end() {
        let grid = CellGrid { size: 1.0 };
        let mut cells = Vec::new();
        let (a, b) = (DVec3::new(0.5, 0.2, 0.1), DVec3::new(3.7, -2.4, 1.9));
        cells_on_segment(&grid, a, b, &mut cells);
        assert_eq!(cells.first(), Some(&grid.cell(a)));
        assert_eq!(cells.last(), Some(&grid.cell(b)));
        assert_eq!(cells.len(), 1 + 3 + 3 + 1);
        for w in cells.windows(2) {
            let moved: i64 = (0..3).map(|i| (w[1].0[i] - w[0].0[i]).abs()).sum();
            assert_eq!(moved, 1);
        }
        // Every cell is touched by the segment: sample it finely.
        for i in 0..=1000 {
            let p = a.lerp(b, i as f64 / 1000.0);
            assert!(cells.contains(&grid.cell(p)), "{p}");
        }
    }

    #[test]
    fn vertex_on_a_neighbours_edge_is_found_and_inserted() {
        // Two triangles; vertex 4 lies in the middle of the first one's edge 1-2.
        let p = vec![
            DVec3::new(0.0, 0.0, 0.0),
            DVec3::new(2.0, 0.0, 0.0),
            DVec3::new(2.0, 2.0, 0.0),
            DVec3::new(4.0, 0.0, 0.0),
            DVec3::new(2.0, 0.5, 0.0),
        ];
        let mesh = Mesh::from_polygons(p, [[0u32, 1, 2], [4, 3, 2]]).unwrap();
        let nodes = find_t_nodes(&mesh, 1e-6).unwrap();
        assert_eq!(nodes.len(), 1);
        assert_eq!(nodes[0].vertex, 4);
        assert_eq!(nodes[0].edge, [1, 2]);
        assert_eq!(nodes[0].face, 0);
        assert!((nodes[0].parameter - 0.25).abs() < 1e-12);
        let (repaired, count) = repair_t_nodes(&mesh, 1e-6).unwrap();
        assert_eq!(count, 1);
        assert_eq!(repaired.face(0), &[0, 1, 4, 2]);
        assert_eq!(repaired.face(1), &[4, 3, 2]);
        let topology = Topology::new(&repaired);
        let shared = topology.find_edge(4, 2).unwrap();
        assert_eq!(topology.edge_face_count(shared), 2);
    }

    /// Every boundary vertex against every naked edge of another face, with
    /// the search's own test of a pair: what the grid may only make faster.
    fn every_pair(mesh: &Mesh, tolerance: f64) -> Vec<(u32, TNode)> {
        let topology = Topology::new(mesh);
        let positions = mesh.positions();
        let naked: Vec<u32> = topology
            .naked_edges()
            .iter()
            .map(|&e| topology.edge_corners(e as usize)[0])
            .collect();
        let mut boundary: Vec<u32> = naked
            .iter()
            .flat_map(|&c| {
                let next = topology.corner_next()[c as usize];
                [
                    topology.corner_vertices()[c as usize],
                    topology.corner_vertices()[next as usize],
                ]
            })
            .collect();
        boundary.sort_unstable();
        boundary.dedup();
        let mut found = Vec::new();
        for &v in &boundary {
            let p = positions[v as usize];
            for &c in &naked {
                let va = topology.corner_vertices()[c as usize];
                let vb = topology.corner_vertices()[topology.corner_next()[c as usize] as usize];
                let face = topology.corner_faces()[c as usize];
                if mesh.face(face as usize).contains(&v) {
                    continue;
                }
                let (a, b) = (positions[va as usize], positions[vb as usize]);
                if let Some(t) = parameter_inside(p, a, b, tolerance) {
                    let node = TNode {
                        vertex: v,
                        edge: [va, vb],
                        face,
                        parameter: t,
                    };
                    found.push((c, node));
                }
            }
        }
        found.sort_by(|x, y| {
            x.0.cmp(&y.0)
                .then(x.1.parameter.total_cmp(&y.1.parameter))
                .then(x.1.vertex.cmp(&y.1.vertex))
        });
        found
    }

    proptest::proptest! {
        /// Strips of quads side by side, each with its own number of
        /// divisions along the shared seams, the strips' vertices apart
        /// (as read from STL) or shared within a strip; points put on the
        /// seams' grid lines and cell sides included, where the cells near
        /// a vertex are chosen.
        #[test]
        fn the_grid_finds_what_every_pair_finds(
            divisions in proptest::collection::vec(1u32..7, 2..5),
            scale in proptest::sample::select(vec![1.0, 0.01, 3.0e4]),
            soup: bool,
            tolerance in proptest::sample::select(vec![1e-9, 1e-3, 0.05]),
        ) {
            let mut positions = Vec::new();
            let mut faces: Vec<Vec<u32>> = Vec::new();
            for (strip, &n) in divisions.iter().enumerate() {
                let x = strip as f64;
                let first = positions.len() as u32;
                for i in 0..=n {
                    let y = i as f64 / n as f64;
                    positions.push(DVec3::new(x, y, 0.0) * scale);
                    positions.push(DVec3::new(x + 1.0, y, 0.0) * scale);
                }
                for i in 0..n {
                    let q = first + 2 * i;
                    faces.push(vec![q, q + 1, q + 3, q + 2]);
                }
            }
            if soup {
                let mut apart = Vec::new();
                for face in &mut faces {
                    for v in face.iter_mut() {
                        apart.push(positions[*v as usize]);
                        *v = apart.len() as u32 - 1;
                    }
                }
                positions = apart;
            }
            let mesh = Mesh::from_polygons(positions, faces).unwrap();
            let tolerance = tolerance * scale;
            proptest::prop_assert_eq!(
                find_with_corners(&mesh, tolerance).unwrap(),
                every_pair(&mesh, tolerance)
            );
        }
    }
}
