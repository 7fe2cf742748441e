//! T-nodes: vertices that lie inside another face's naked edge.
//!
//! Two surface meshes with different U/V counts meet along a seam where the
//! vertices of one fall between the vertices of the other. Welding cannot
//! join them (no two vertices coincide); the seam stays open and subdivision
//! pulls it apart. [`find_t_nodes`] reports
//! each such vertex with the edge and the parameter along it;
//! [`repair_t_nodes`] inserts the vertex
//! into that edge, so the face becomes an n-gon and both sides share every
//! seam edge.
//!
//! The boundary vertices' positions (each once, however many copies an STL
//! file holds of it) are filed in the cells of a uniform grid within the
//! tolerance of them (their own, and of its 26 neighbours those whose side
//! is that close). Each naked edge walks the cells it passes through (a 3-D
//! digital differential analyser, Amanatides & Woo 1987) and is tested
//! against the positions filed there only, on all threads. A cell holding
//! many positions (on long thin triangles the cells fit the long edges,
//! and the short edges' positions crowd them) has them sorted along the
//! axis they spread most: an edge tests only those within its own extent
//! along it. Where the positions crowd cells as long as the edges (many
//! long edges ending close together, as pages on one spine), the cells are
//! halved while the edges still pass through a number linear in their count.

use std::collections::HashMap;
use std::hash::{BuildHasherDefault, Hash, Hasher};
use std::ops::Range;
use std::sync::atomic::{AtomicBool, Ordering::Relaxed};

use glam::DVec3;
use rayon::prelude::*;

use crate::buffers::{fill_by_offsets, fresh_zeroed, prefix_sum, split_by_offsets, try_vec, CHUNK};
use crate::error::{Error, Result};
use crate::mend::weld::{
    mix_words, nearby_copies, within, Cell, CellGrid, CellHasher, Copies, PackedCell, COPIES_PIECE,
};
use crate::mesh::corners::CornerFaces;
use crate::mesh::topology::Edges;
use crate::mesh::Mesh;
use crate::mesh::{bounding_box_of, check_tolerance};

/// Naked edges one task sums the lengths of.
const SEGMENTS_A_PART: usize = 1 << 16;

/// Cells holding more sites than this are sorted along the axis their
/// sites spread most, so that an edge tests only those within its own
/// extent along it: on long thin triangles the cells fit the long edges
/// and hold hundreds of the short edges' positions.
const CROWDED_CELL: usize = 32;

/// How the search divides its work; the tests choose other values so that
/// small meshes take every path.
#[derive(Debug, Clone, Copy)]
struct Tuning {
    /// Vertices among which copies of a position are merged.
    copies_piece: usize,
    /// Sites a cell holds before it is sorted along an axis.
    crowded_cell: usize,
    /// How many of the boundary's vertices one of them may share its cell
    /// with, on average, before the cells are halved.
    crowded_grid: f64,
}

/// The share of a cell that covers the round-off of placing points and
/// edges in cells: cell numbers stay below 2^41 (see
/// [`CellGrid::with_reach`]), where a double's step is 2^-12 of a cell.
const ROUND_OFF: f64 = 1.0 / 1024.0;

const TUNING: Tuning = Tuning {
    copies_piece: COPIES_PIECE,
    crowded_cell: CROWDED_CELL,
    crowded_grid: CROWDED_GRID,
};

/// Cells whose vertices share them with more than this many others, on
/// average, are halved (see [`finer_where_crowded`]).
const CROWDED_GRID: f64 = 64.0;

/// The most boundary vertices the crowding of the cells is measured on.
const CROWDING_SAMPLE: usize = 1 << 16;

/// The narrowest cell, in tolerances. A position is filed under every cell
/// within the tolerance of it: in cells four times the tolerance, 1.5 along
/// each axis on average (3.4 in all), where cells as narrow as the
/// tolerance file every position under 27.
const NARROWEST_CELL: f64 = 4.0;

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
/// edges walk coarsens until they cross a number of cells linear in their
/// count, whatever the scale.
///
/// # Errors
/// [`Error::InvalidArgument`] when `tolerance`
/// is negative, NaN or infinite; [`Error::ResultTooLarge`]
/// when a tolerance as wide as the cells files the positions under more than
/// 2^32 cells; [`Error::OutOfMemory`].
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
    let (face_sizes, face_indices, inserted) = faces_with_nodes_inserted(mesh, &nodes, MANY_NODES)?;
    Ok((
        Mesh::from_valid_parts(mesh.positions().to_vec(), face_sizes, face_indices),
        inserted,
    ))
}

/// A repair and the T-nodes it inserted, as [`repair_t_nodes_owned`] gives them.
#[derive(Debug, Clone)]
pub struct TNodeRepair {
    /// The mesh with every T-node inserted into its edge.
    pub mesh: Mesh,
    /// How many vertices were inserted into faces.
    pub inserted: usize,
    /// The T-nodes as [`find_t_nodes`] lists them.
    pub t_nodes: Vec<TNode>,
}

/// [`repair_t_nodes`] on a mesh the caller gives up, with the list
/// [`find_t_nodes`] gives: one search serves both, and the positions are
/// moved into the repaired mesh, not copied. A mesh without T-nodes comes
/// back as it is.
///
/// # Errors
/// As [`find_t_nodes`].
pub fn repair_t_nodes_owned(mesh: Mesh, tolerance: f64) -> Result<TNodeRepair> {
    let nodes = find_with_corners(&mesh, tolerance)?;
    let (mesh, inserted) = if nodes.is_empty() {
        (mesh, 0)
    } else {
        let (face_sizes, face_indices, inserted) =
            faces_with_nodes_inserted(&mesh, &nodes, MANY_NODES)?;
        let (positions, _, _) = mesh.into_parts();
        (
            Mesh::from_valid_parts(positions, face_sizes, face_indices),
            inserted,
        )
    };
    Ok(TNodeRepair {
        mesh,
        inserted,
        t_nodes: nodes.into_iter().map(|(_, node)| node).collect(),
    })
}

/// Nodes on one face past which its vertices are looked up in a set.
const MANY_NODES: usize = 32;

/// The face sizes and corners of `mesh` with each of `nodes` (sorted by
/// corner and parameter) inserted after its corner, and how many were;
/// faces with more than `many_nodes` look their vertices up in a set.
fn faces_with_nodes_inserted(
    mesh: &Mesh,
    nodes: &[(u32, TNode)],
    many_nodes: usize,
) -> Result<(Vec<u32>, Vec<u32>, usize)> {
    let corners = mesh.face_indices();
    let mut face_sizes = try_vec::<u32>(mesh.face_count(), "the repaired face sizes")?;
    let mut face_indices =
        try_vec::<u32>(corners.len() + nodes.len(), "the repaired face indices")?;
    let mut inserted = 0;
    let mut next = 0;
    // The vertices a face with many nodes holds so far: a long edge can
    // take a million, which searching the face for each would square.
    let mut held = std::collections::HashSet::new();
    for (f, w) in mesh.face_offsets().windows(2).enumerate() {
        let start = face_indices.len();
        let face = &corners[w[0] as usize..w[1] as usize];
        let face_nodes = nodes[next..].partition_point(|node| node.0 < w[1]);
        let many = face_nodes > many_nodes;
        if many {
            held.clear();
            held.extend(face.iter().copied());
        }
        for c in w[0]..w[1] {
            face_indices.push(corners[c as usize]);
            while next < nodes.len() && nodes[next].0 == c {
                let v = nodes[next].1.vertex;
                debug_assert_eq!(nodes[next].1.face as usize, f);
                let new = match many {
                    true => held.insert(v),
                    false => !face.contains(&v) && !face_indices[start..].contains(&v),
                };
                if new {
                    face_indices.push(v);
                    inserted += 1;
                }
                next += 1;
            }
        }
        face_sizes.push((face_indices.len() - start) as u32);
    }
    Ok((face_sizes, face_indices, inserted))
}

/// The T-nodes with the corner whose edge each lies on, sorted by corner and parameter.
fn find_with_corners(mesh: &Mesh, tolerance: f64) -> Result<Vec<(u32, TNode)>> {
    find_tuned(mesh, tolerance, TUNING)
}

/// [`find_with_corners`], its work divided as `tuning` says.
fn find_tuned(mesh: &Mesh, tolerance: f64, tuning: Tuning) -> Result<Vec<(u32, TNode)>> {
    check_tolerance(tolerance)?;
    // A naked edge has one corner: which corners those are is all the
    // search needs of the topology.
    let corners = CornerFaces::of_mesh(mesh)?;
    let naked = Edges::naked_corners_with(mesh, &corners)?;
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
    let segment = |c: u32| {
        let c = c as usize;
        (
            positions[corner_vertices[c] as usize],
            positions[corner_vertices[corners.next(c)] as usize],
        )
    };
    // Sums over fixed blocks of edges, so that they do not depend on how the
    // threads share the work.
    let sum_over_edges = |term: &(dyn Fn(DVec3, DVec3) -> DVec3 + Sync)| -> DVec3 {
        let blocks: Vec<DVec3> = naked_corner
            .par_chunks(SEGMENTS_A_PART)
            .map(|block| {
                block
                    .iter()
                    .map(|&c| {
                        let (a, b) = segment(c);
                        term(a, b)
                    })
                    .sum()
            })
            .collect();
        blocks.iter().sum()
    };
    // The logarithms of the edges' lengths (of those whose length is not
    // 0, as it is where coordinates near 1e-300 square to 0), how many
    // those are, and the sums of the lengths along each axis.
    let sums = sum_over_edges(&|a, b| {
        let length = a.distance(b);
        let measured = length > 0.0 && length.is_finite();
        let log = if measured { length.ln() } else { 0.0 };
        DVec3::new(log, measured as u32 as f64, (b - a).abs().element_sum())
    });
    let edge_count = naked_corner.len() as f64;
    // Cells about as long as the naked edges, so that each edge passes
    // through a few cells and each cell holds a few positions. The
    // geometric mean: on long thin triangles the long edges would make
    // cells that hold hundreds of the short edges' positions.
    let mean_length = if sums.y > 0.0 {
        (sums.x / sums.y).exp()
    } else {
        0.0
    };
    // The mean can underflow to 0 (coordinates near 1e-300 square to 0) or
    // come out far too small; coarsen until the edges pass through a number
    // of cells linear in their count, so the cell lists stay small.
    let cell_limit = 8.0 * edge_count + 64.0;
    let (lo, hi) = bounding_box_of(positions).expect("a mesh with naked edges has vertices");
    let reach = lo.abs().max(hi.abs()).max_element();
    let mut size = mean_length.max(NARROWEST_CELL * tolerance);
    let grid = loop {
        let grid = CellGrid::with_reach(reach, size);
        // An edge passes through at most 1 + (|d| / size + 1) cells along
        // each axis of its difference d: no count is needed when that bound
        // is within the limit (cells as long as the edges, on most meshes).
        let bound = 4.0 * edge_count + sums.z / grid.size;
        let within_limit = bound <= cell_limit || {
            let count = sum_over_edges(&|a, b| {
                DVec3::new(1.0 + grid.cell(a).steps_to(grid.cell(b)) as f64, 0.0, 0.0)
            });
            count.x <= cell_limit
        };
        if within_limit || !grid.size.is_finite() {
            break grid;
        }
        size = grid.size * 2.0;
    };
    // The boundary's vertices from every stride-th naked edge, each once.
    let stride = naked_corner.len().div_ceil(CROWDING_SAMPLE);
    let mut sampled: Vec<u32> = naked_corner
        .iter()
        .step_by(stride)
        .map(|&c| corner_vertices[c as usize])
        .collect();
    sampled.sort_unstable();
    sampled.dedup();
    let sampled: Vec<DVec3> = sampled.iter().map(|&v| positions[v as usize]).collect();
    let grid = finer_where_crowded(
        grid,
        (reach, tolerance),
        (&sampled, stride as f64),
        tuning.crowded_grid,
        |finer| {
            let count = sum_over_edges(&|a, b| {
                DVec3::new(1.0 + finer.cell(a).steps_to(finer.cell(b)) as f64, 0.0, 0.0)
            });
            count.x <= 8.0 * cell_limit
        },
    );
    let search = Search {
        mesh,
        corners: &corners,
        naked_corner: &naked_corner,
        grid,
        tolerance,
        tuning: Tuning {
            copies_piece: tuning.copies_piece.max(1),
            ..tuning
        },
    };
    // Cells numbered in one word when the mesh spans few enough of them:
    // half the bytes to sort and compare.
    match PackedCell::origin(grid.cell(lo), grid.cell(hi)) {
        Some(origin) => search.run(|cell| NarrowKey::of(cell, origin)),
        None => search.run(WideKey::of),
    }
}

/// `grid` with its cells halved while the boundary's vertices crowd them:
/// where many long edges end close together (pages on one edge, spokes to
/// a dense rim), cells as long as the edges hold thousands of vertices, and
/// every edge would test every one. Halved while the vertices `sampled`
/// (one in `stride` of them) share a cell with more than `crowded` others
/// on average, the cells stay no narrower than [`NARROWEST_CELL`]
/// tolerances and within `reach`'s grid, and `edges_fit` says the edges
/// still pass through few enough cells.
fn finer_where_crowded(
    mut grid: CellGrid,
    (reach, tolerance): (f64, f64),
    (sampled, stride): (&[DVec3], f64),
    crowded: f64,
    edges_fit: impl Fn(&CellGrid) -> bool,
) -> CellGrid {
    if sampled.is_empty() {
        return grid;
    }
    // Each sampled pair in a cell stands for stride² pairs of its vertices,
    // each sampled vertex for `stride` vertices.
    let crowding = |grid: &CellGrid| {
        let mut cells: Vec<Cell> = sampled.iter().map(|&p| grid.cell(p)).collect();
        cells.par_sort_unstable();
        let pairs: f64 = cells
            .chunk_by(|a, b| a == b)
            .map(|run| (run.len() * (run.len() - 1)) as f64)
            .sum();
        stride * pairs / sampled.len() as f64
    };
    while grid.size / 2.0 >= NARROWEST_CELL * tolerance && crowding(&grid) > crowded {
        let finer = CellGrid::with_reach(reach, grid.size / 2.0);
        if finer.size >= grid.size || !edges_fit(&finer) {
            break;
        }
        grid = finer;
    }
    grid
}

/// What the search for T-nodes works on: the naked edges (by their corners)
/// and the grid of cells they are filed in.
struct Search<'a> {
    mesh: &'a Mesh,
    corners: &'a CornerFaces,
    naked_corner: &'a [u32],
    grid: CellGrid,
    tolerance: f64,
    tuning: Tuning,
}

impl Search<'_> {
    /// Which vertices are on a naked edge.
    fn boundary_vertices(&self) -> Vec<bool> {
        let on_boundary: Vec<AtomicBool> = (0..self.mesh.vertex_count())
            .into_par_iter()
            .with_min_len(CHUNK)
            .map(|_| AtomicBool::new(false))
            .collect();
        self.naked_corner.par_chunks(CHUNK).for_each(|corners| {
            for &c in corners {
                let (va, vb) = self.ends(c);
                on_boundary[va as usize].store(true, Relaxed);
                on_boundary[vb as usize].store(true, Relaxed);
            }
        });
        on_boundary
            .into_par_iter()
            .with_min_len(CHUNK)
            .map(AtomicBool::into_inner)
            .collect()
    }

    /// Where a site within the tolerance of the segment from `a` to `b`
    /// can lie along `axis`, when the segment meets it in `cell`: the
    /// segment's extent within the cell's, widened by the tolerance and by
    /// the [`ROUND_OFF`] margin the cells near a site are filed with.
    fn extent_in_cell(&self, a: DVec3, b: DVec3, cell: Cell, axis: usize) -> (f64, f64) {
        let size = self.grid.size;
        let cell_start = cell.0[axis] as f64 * size;
        let margin = self.tolerance + size * ROUND_OFF;
        (
            a[axis].min(b[axis]).max(cell_start) - margin,
            a[axis].max(b[axis]).min(cell_start + size) + margin,
        )
    }

    /// The vertices of corner `c`'s edge.
    fn ends(&self, c: u32) -> (u32, u32) {
        let corner_vertices = self.mesh.face_indices();
        let c = c as usize;
        (corner_vertices[c], corner_vertices[self.corners.next(c)])
    }

    /// The T-nodes, with the cells numbered by `key`.
    fn run<K: BlockKey>(&self, key: impl Fn(Cell) -> K + Sync) -> Result<Vec<(u32, TNode)>> {
        let sites = BoundarySites::of(self)?;
        // Each site under every cell within the tolerance of it, sorted by
        // cell: an edge meets the sites near it in the cells it passes
        // through.
        let near = |s: u32| {
            // A position whose copies are all inside the surface is in no cell.
            let filed = !sites.vertices(s).is_empty();
            cells_near(&self.grid, sites.positions[s as usize], self.tolerance)
                .filter(move |_| filed)
        };
        let mut offsets: Vec<u32> = Vec::with_capacity(sites.count() + 1);
        offsets.push(0);
        offsets.par_extend(
            (0..sites.count() as u32)
                .into_par_iter()
                .with_min_len(CHUNK)
                .map(|s| near(s).count() as u32),
        );
        let total: u64 = offsets.par_iter().map(|&n| n as u64).sum();
        if total > u32::MAX as u64 {
            return Err(Error::ResultTooLarge(format!(
                "the T-node search files the boundary's {} positions under {total} cells, \
                 more than 2^32; give a smaller tolerance",
                sites.count()
            )));
        }
        prefix_sum(&mut offsets);
        let mut entries = fill_by_offsets(&offsets, "the T-node search's cells", |s, out| {
            for (slot, cell) in out.iter_mut().zip(near(s as u32)) {
                *slot = (key(cell), s as u32);
            }
        })?;
        entries.par_sort_unstable();
        let index = CellIndex::of(entries, &sites.positions, self.tuning.crowded_cell)?;
        // Edge by edge, in the order of their corners: blocks of edges on
        // all threads, each block's T-nodes in corner order.
        let blocks: Vec<Vec<(u32, TNode)>> = self
            .naked_corner
            .par_chunks(CHUNK)
            .map_init(
                || (Vec::new(), Vec::new(), RecentCells::default()),
                |(cells_on, candidates, recent), block| {
                    let mut found = Vec::new();
                    for &c in block {
                        let ends = self.ends(c);
                        let positions = self.mesh.positions();
                        let (a, b) = (positions[ends.0 as usize], positions[ends.1 as usize]);
                        cells_on_segment(&self.grid, a, b, cells_on);
                        candidates.clear();
                        for &cell in cells_on.iter() {
                            let (start, end, axis) = recent.range(&index, key(cell));
                            let part = start as usize..end as usize;
                            let filed = &index.entries[part.clone()];
                            let near = match axis {
                                Some(axis) => {
                                    let along = self.extent_in_cell(a, b, cell, axis as usize);
                                    within_extent(filed, &index.coordinates[part], along)
                                }
                                None => filed,
                            };
                            candidates.extend(near.iter().map(|&(_, s)| s));
                        }
                        // A site near a cell's side is under both cells.
                        if cells_on.len() > 1 {
                            candidates.sort_unstable();
                            candidates.dedup();
                        }
                        self.nodes_on_edge(c, ends, &sites, candidates, &mut found);
                    }
                    found
                },
            )
            .collect();
        let mut found = try_vec(blocks.iter().map(Vec::len).sum(), "the T-nodes")?;
        for block in blocks {
            found.extend(block);
        }
        Ok(found)
    }

    /// The T-nodes on the naked edge of corner `c`, from vertex `va` to
    /// `vb`, among the `candidates` (sites), sorted by parameter and vertex,
    /// appended to `found`.
    fn nodes_on_edge(
        &self,
        c: u32,
        (va, vb): (u32, u32),
        sites: &BoundarySites,
        candidates: &[u32],
        found: &mut Vec<(u32, TNode)>,
    ) {
        let positions = self.mesh.positions();
        let (a, b) = (positions[va as usize], positions[vb as usize]);
        let first = found.len();
        let face = self.corners.face(c as usize);
        let face_vertices = self.mesh.face(face);
        for &s in candidates.iter() {
            let p = sites.positions[s as usize];
            // At an end (a copy of a or b, as STL stores every corner): a
            // matter for welding, as `parameter_inside` finds, without
            // arithmetic.
            if p == a || p == b {
                continue;
            }
            let Some(t) = parameter_inside(p, a, b, self.tolerance) else {
                continue;
            };
            for &v in sites.vertices(s) {
                // Not on an edge of one of its own faces.
                if face_vertices.contains(&v) {
                    continue;
                }
                found.push((
                    c,
                    TNode {
                        vertex: v,
                        edge: [va, vb],
                        face: face as u32,
                        parameter: t,
                    },
                ));
            }
        }
        found[first..].sort_unstable_by(|x, y| {
            x.1.parameter
                .total_cmp(&y.1.parameter)
                .then(x.1.vertex.cmp(&y.1.vertex))
        });
    }
}

/// The boundary vertices' distinct positions (sites), each with the
/// boundary vertices at it. A mesh as STL stores it has about six copies of
/// each position; each site is tested against an edge once for all of them.
/// Copies are merged among nearby vertices only (see
/// [`crate::mend::weld::nearby_copies`]): copies left apart are sites of
/// their own, found the same way.
struct BoundarySites {
    positions: Vec<DVec3>,
    /// Site s's vertices are `members[offsets[s]..offsets[s + 1]]`, in order.
    offsets: Vec<u32>,
    members: Vec<u32>,
}

impl BoundarySites {
    fn of(search: &Search) -> Result<BoundarySites> {
        let mesh = search.mesh;
        let on_boundary = search.boundary_vertices();
        let piece = search.tuning.copies_piece;
        let Some(Copies { site_of, sites }) = nearby_copies(mesh.positions(), piece)? else {
            // Every boundary vertex a site of its own.
            let members: Vec<u32> = (0..mesh.vertex_count() as u32)
                .into_par_iter()
                .with_min_len(CHUNK)
                .filter(|&v| on_boundary[v as usize])
                .collect();
            return Ok(BoundarySites {
                positions: members
                    .par_iter()
                    .map(|&v| mesh.positions()[v as usize])
                    .collect(),
                offsets: (0..=members.len() as u32).collect(),
                members,
            });
        };
        // A piece's vertices name only its own sites, which follow those of
        // the pieces before (its first vertex is its first site): each
        // piece counts and files its members on its own thread.
        let pieces: Vec<Range<usize>> = (0..site_of.len())
            .step_by(piece)
            .map(|first| first..(first + piece).min(site_of.len()))
            .collect();
        // Where each piece's sites start, and where the last one's end.
        let site_starts: Vec<u32> = pieces
            .iter()
            .map(|vertices| site_of[vertices.start])
            .chain([sites.len() as u32])
            .collect();
        let mut counts = fresh_zeroed::<u32>(sites.len() + 1, "the boundary's sites")?;
        split_by_offsets(&mut counts[1..], &site_starts, 1)
            .into_par_iter()
            .for_each(|(piece, counts)| {
                let first_site = site_starts[piece.start] as usize;
                for v in pieces[piece.start].clone() {
                    counts[site_of[v] as usize - first_site] += on_boundary[v] as u32;
                }
            });
        prefix_sum(&mut counts);
        let offsets = counts;
        let mut members = fresh_zeroed::<u32>(
            *offsets.last().unwrap_or(&0) as usize,
            "the boundary's vertices",
        )?;
        let member_starts: Vec<u32> = site_starts.iter().map(|&s| offsets[s as usize]).collect();
        split_by_offsets(&mut members, &member_starts, 1)
            .into_par_iter()
            .for_each(|(piece, members)| {
                let piece_sites =
                    site_starts[piece.start] as usize..site_starts[piece.end] as usize;
                let base = member_starts[piece.start];
                let mut next: Vec<u32> = offsets[piece_sites.clone()]
                    .iter()
                    .map(|&o| o - base)
                    .collect();
                for v in pieces[piece.start].clone() {
                    if on_boundary[v] {
                        let slot = &mut next[site_of[v] as usize - piece_sites.start];
                        members[*slot as usize] = v as u32;
                        *slot += 1;
                    }
                }
            });
        Ok(BoundarySites {
            positions: sites,
            offsets,
            members,
        })
    }

    fn count(&self) -> usize {
        self.positions.len()
    }

    fn vertices(&self, s: u32) -> &[u32] {
        &self.members[self.offsets[s as usize] as usize..self.offsets[s as usize + 1] as usize]
    }
}

/// A cell's number in the search's sort, which puts the cells of each
/// block of 8 × 8 × 8 together: the cells an edge passes through are then
/// found among the few of its block, which the edges before it have
/// brought into the cache, not across a table of every cell.
trait BlockKey: Copy + Default + Ord + Send + Sync {
    /// The block's own key.
    type Block: Copy + Eq + Hash + Send + Sync;
    fn block(self) -> Self::Block;
}

/// A cell counted from an origin, for a mesh spanning fewer than 2^21 cells
/// in each axis: its block's coordinates (18 bits each), then its own
/// place in the block (3 bits each).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, PartialOrd, Ord)]
struct NarrowKey(u64);

impl NarrowKey {
    fn of(cell: Cell, origin: [i64; 3]) -> NarrowKey {
        let [x, y, z] = [0, 1, 2].map(|i| (cell.0[i] - origin[i]) as u64);
        NarrowKey(
            (x >> 3) << 45 | (y >> 3) << 27 | (z >> 3) << 9 | (x & 7) << 6 | (y & 7) << 3 | (z & 7),
        )
    }
}

/// A [`NarrowKey`]'s block, hashed as a word whose bits are mixed.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
struct NarrowBlock(u64);

impl Hash for NarrowBlock {
    fn hash<H: Hasher>(&self, state: &mut H) {
        let h = mix_words([self.0, 0, 0]);
        state.write_u64(h ^ (h >> 29));
    }
}

impl BlockKey for NarrowKey {
    type Block = NarrowBlock;
    fn block(self) -> NarrowBlock {
        NarrowBlock(self.0 >> 9)
    }
}

/// A cell of a mesh spanning more cells than a [`NarrowKey`] counts: its
/// block, then its place in the block.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, PartialOrd, Ord)]
struct WideKey {
    block: Cell,
    place: u16,
}

impl WideKey {
    fn of(cell: Cell) -> WideKey {
        let [x, y, z] = cell.0;
        WideKey {
            block: Cell(cell.0.map(|c| c >> 3)),
            place: ((x & 7) << 6 | (y & 7) << 3 | (z & 7)) as u16,
        }
    }
}

impl BlockKey for WideKey {
    type Block = Cell;
    fn block(self) -> Cell {
        self.block
    }
}

/// The sites filed under each cell, sorted by cell, with where each cell's
/// and each block's part starts. A crowded cell's sites are sorted along
/// an axis.
struct CellIndex<K: BlockKey> {
    entries: Vec<(K, u32)>,
    /// Each cell in order with where its entries start; one more at the
    /// end, where the last one's end.
    cells: Vec<(K, u32)>,
    /// The axis each cell's sites are sorted along, if they are.
    axes: Vec<Option<u8>>,
    /// Each entry's site's coordinate along its cell's axis, for the cells
    /// sorted along one: searched without a look at the sites.
    coordinates: Vec<f64>,
    /// Where each block's cells are in `cells`.
    blocks: HashMap<K::Block, (u32, u32), BuildHasherDefault<CellHasher>>,
}

impl<K: BlockKey> CellIndex<K> {
    /// The index of `entries` (cell and site), sorted by cell; fewer than
    /// 2^32 of them. The sites of each cell holding more than `crowded`
    /// are sorted along the axis of `positions` they spread most.
    fn of(mut entries: Vec<(K, u32)>, positions: &[DVec3], crowded: usize) -> Result<CellIndex<K>> {
        let mut cells: Vec<(K, u32)> = (0..entries.len())
            .into_par_iter()
            .with_min_len(CHUNK)
            .filter(|&i| i == 0 || entries[i].0 != entries[i - 1].0)
            .map(|i| (entries[i].0, i as u32))
            .collect();
        cells.push((K::default(), entries.len() as u32));
        let mut blocks = HashMap::default();
        let mut start = 0;
        for i in 1..cells.len() {
            if i == cells.len() - 1 || cells[i].0.block() != cells[start].0.block() {
                blocks.insert(cells[start].0.block(), (start as u32, i as u32));
                start = i;
            }
        }
        let starts: Vec<u32> = cells.iter().map(|&(_, start)| start).collect();
        let mut axes = vec![None; cells.len()];
        // Pages of cells not crowded are never touched.
        let mut coordinates = fresh_zeroed::<f64>(entries.len(), "the T-node search's cells")?;
        split_by_offsets(&mut entries, &starts, CHUNK)
            .into_par_iter()
            .zip(split_by_offsets(&mut coordinates, &starts, CHUNK))
            .zip(axes.par_chunks_mut(CHUNK))
            .for_each(|(((cells, entries), (_, coordinates)), axes)| {
                let base = starts[cells.start] as usize;
                for (cell, axis) in cells.zip(axes) {
                    let part = starts[cell] as usize - base..starts[cell + 1] as usize - base;
                    let filed = &mut entries[part.clone()];
                    if filed.len() > crowded {
                        let along = sort_along_widest_axis(filed, positions);
                        for (x, &(_, s)) in coordinates[part].iter_mut().zip(filed.iter()) {
                            *x = positions[s as usize][along as usize];
                        }
                        *axis = Some(along);
                    }
                }
            });
        Ok(CellIndex {
            entries,
            cells,
            axes,
            coordinates,
            blocks,
        })
    }

    /// Where the entries of `cell` are in `entries`, and the axis they are
    /// sorted along if they are.
    fn range(&self, cell: K) -> (u32, u32, Option<u8>) {
        let Some(&(first, end)) = self.blocks.get(&cell.block()) else {
            return (0, 0, None);
        };
        let block = &self.cells[first as usize..end as usize];
        match block.binary_search_by(|&(k, _)| k.cmp(&cell)) {
            Ok(i) => {
                let i = first as usize + i;
                (self.cells[i].1, self.cells[i + 1].1, self.axes[i])
            }
            Err(_) => (0, 0, None),
        }
    }
}

/// Sorts one cell's entries by their sites' coordinate along the axis
/// they spread most, and gives that axis.
fn sort_along_widest_axis<K>(filed: &mut [(K, u32)], positions: &[DVec3]) -> u8 {
    let at = |&(_, s): &(K, u32)| positions[s as usize];
    let (lo, hi) = filed.iter().fold(
        (DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY)),
        |(lo, hi), entry| (lo.min(at(entry)), hi.max(at(entry))),
    );
    let spread = hi - lo;
    let axis = if spread.x >= spread.y && spread.x >= spread.z {
        0
    } else if spread.y >= spread.z {
        1
    } else {
        2
    };
    filed.sort_unstable_by(|x, y| at(x)[axis].total_cmp(&at(y)[axis]).then(x.1.cmp(&y.1)));
    axis as u8
}

/// The entries of a cell, sorted along an axis where they lie at
/// `coordinates`, that lie within `extent` along it.
fn within_extent<'a, K>(
    filed: &'a [(K, u32)],
    coordinates: &[f64],
    (low, high): (f64, f64),
) -> &'a [(K, u32)] {
    let first = coordinates.partition_point(|&x| x < low);
    let count = coordinates[first..].partition_point(|&x| x <= high);
    &filed[first..first + count]
}

/// The cells one thread looked up last, with where their entries are: an
/// edge most often starts in a cell the edges just before it passed
/// through (a triangle's next edge starts where the last one ended).
struct RecentCells<K> {
    cells: [(K, u32, u32, Option<u8>); 8],
    filled: usize,
    next: usize,
}

impl<K: BlockKey> Default for RecentCells<K> {
    fn default() -> RecentCells<K> {
        RecentCells {
            cells: [(K::default(), 0, 0, None); 8],
            filled: 0,
            next: 0,
        }
    }
}

impl<K: BlockKey> RecentCells<K> {
    /// [`CellIndex::range`], remembered.
    fn range(&mut self, index: &CellIndex<K>, cell: K) -> (u32, u32, Option<u8>) {
        if let Some(&(_, start, end, axis)) = self.cells[..self.filled].iter().find(|x| x.0 == cell)
        {
            return (start, end, axis);
        }
        let (start, end, axis) = index.range(cell);
        self.cells[self.next] = (cell, start, end, axis);
        self.next = (self.next + 1) % self.cells.len();
        self.filled = (self.filled + 1).min(self.cells.len());
        (start, end, axis)
    }
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
/// `tolerance`, and a margin of [`ROUND_OFF`] of a cell more.
fn cells_near(grid: &CellGrid, p: DVec3, tolerance: f64) -> impl Iterator<Item = Cell> {
    let home = grid.cell(p);
    let reach = tolerance / grid.size + ROUND_OFF;
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

    /// In the narrowest cells a position is filed under 3.4 cells on
    /// average, which hold every point within the tolerance of it; in cells
    /// as narrow as the tolerance, under 27.
    #[test]
    fn positions_are_filed_under_few_of_the_narrowest_cells() {
        let mut next = crate::test_random::units(0x7e57_ce11_5eed_0042);
        let tolerance = 1e-3;
        let (narrowest, narrow) = (
            CellGrid::with_reach(1.0, NARROWEST_CELL * tolerance),
            CellGrid::with_reach(1.0, tolerance),
        );
        let mut filed = 0;
        for _ in 0..10_000 {
            let p = DVec3::new(next(), next(), next());
            let cells: Vec<Cell> = cells_near(&narrowest, p, tolerance).collect();
            assert!((1..=27).contains(&cells.len()), "{p}: {}", cells.len());
            filed += cells.len();
            // Every point within the tolerance lies in one of them.
            for _ in 0..8 {
                let offset = DVec3::new(next(), next(), next()) * 2.0 - 1.0;
                let q = p + offset.normalize_or_zero() * tolerance * 0.999;
                assert!(cells.contains(&narrowest.cell(q)), "{p} {q}");
            }
            assert_eq!(cells_near(&narrow, p, tolerance).count(), 27);
        }
        // About 1.5 along each axis, 3.4 in all.
        assert!((30_000..40_000).contains(&filed), "{filed}");
    }

    #[test]
    fn crowded_cells_are_halved_and_spread_ones_kept() {
        let fits = |_: &CellGrid| true;
        let grid = CellGrid::with_reach(2.0, 1.0);
        // 10,000 points on a circle of radius 1: thousands to a cell, about
        // 50 in cells of 1/32 (about 100 in cells of 1/16).
        let circle: Vec<DVec3> = (0..10_000)
            .map(|k| {
                let a = std::f64::consts::TAU * k as f64 / 10_000.0;
                DVec3::new(a.cos(), a.sin(), 0.5)
            })
            .collect();
        let finer = finer_where_crowded(grid, (2.0, 1e-6), (&circle, 1.0), CROWDED_GRID, fits);
        assert_eq!(finer.size, 1.0 / 32.0);
        // One in ten of them stands for all: the same cells.
        let tenth: Vec<DVec3> = circle.iter().copied().step_by(10).collect();
        let sampled = finer_where_crowded(grid, (2.0, 1e-6), (&tenth, 10.0), CROWDED_GRID, fits);
        assert!(sampled.size <= 2.0 * finer.size && finer.size <= 2.0 * sampled.size);
        // Never narrower than NARROWEST_CELL tolerances, nor past what the
        // edges allow.
        let wide = finer_where_crowded(grid, (2.0, 0.1), (&circle, 1.0), CROWDED_GRID, fits);
        assert_eq!(wide.size, 0.5);
        let wider = finer_where_crowded(grid, (2.0, 0.15), (&circle, 1.0), CROWDED_GRID, fits);
        assert_eq!(wider.size, 1.0);
        let stopped = finer_where_crowded(grid, (2.0, 1e-6), (&circle, 1.0), CROWDED_GRID, |g| {
            g.size >= 0.25
        });
        assert_eq!(stopped.size, 0.25);
        // A grid of points one cell apart stays as it is.
        let spread: Vec<DVec3> = (0..10_000)
            .map(|k| DVec3::new((k % 100) as f64 + 0.5, (k / 100) as f64 + 0.5, 0.5))
            .collect();
        let kept = finer_where_crowded(grid, (100.0, 1e-6), (&spread, 1.0), CROWDED_GRID, fits);
        assert_eq!(kept.size, grid.size);
    }

    #[test]
    fn pages_on_one_edge_find_the_vertices_on_their_edges() {
        // 3,000 pages whose naked edges run from their tips to the spine's
        // ends, and a small triangle at the middle of every hundredth
        // page's edge from vertex 0: one T-node each.
        let book = crate::mesh::shapes::book(3_000);
        let mut positions = book.positions().to_vec();
        let mut faces: Vec<Vec<u32>> = book.faces().map(<[u32]>::to_vec).collect();
        for page in (0..3_000).step_by(100) {
            let middle = positions[2 + page] * 0.5;
            let first = positions.len() as u32;
            let above = middle + DVec3::new(0.0, 0.0, 0.01);
            let out = DVec3::new(1.02 * middle.x, 1.02 * middle.y, above.z);
            positions.extend([middle, above, out]);
            faces.push(vec![first, first + 1, first + 2]);
        }
        let mesh = Mesh::from_polygons(positions, faces).unwrap();
        let found = find_tuned(&mesh, 1e-6, TUNING).unwrap();
        assert_eq!(found.len(), 30);
        assert_eq!(found, every_pair(&mesh, 1e-6));
    }

    /// Two triangles where vertex 4 lies a quarter along the first one's
    /// edge 1-2 (with `t_node`), or two sharing that edge (without).
    fn two_triangles(t_node: bool) -> Mesh {
        let p = vec![
            DVec3::new(0.0, 0.0, 0.0),
            DVec3::new(2.0, 0.0, 0.0),
            DVec3::new(2.0, 2.0, 0.0),
            DVec3::new(4.0, 0.0, 0.0),
            DVec3::new(2.0, 0.5, 0.0),
        ];
        let second = if t_node { [4u32, 3, 2] } else { [1, 3, 2] };
        Mesh::from_polygons(p, [[0u32, 1, 2], second]).unwrap()
    }

    #[test]
    fn vertex_on_a_neighbours_edge_is_found_and_inserted() {
        let mesh = two_triangles(true);
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

    /// A sliver of a triangle whose two long edges both pass within the
    /// tolerance of the top vertices of a strip of 200 quads: each vertex
    /// is a node of both edges, and is inserted once, wherever the face's
    /// vertices are looked up.
    #[test]
    fn many_nodes_on_one_face_are_inserted_once_each() {
        let n = 200;
        let mut positions: Vec<DVec3> = (0..=n)
            .flat_map(|i| {
                let x = i as f64 / n as f64;
                [DVec3::new(x, 0.0, 0.0), DVec3::new(x, -0.01, 0.0)]
            })
            .collect();
        let mut faces: Vec<Vec<u32>> = (0..n as u32)
            .map(|i| vec![2 * i + 1, 2 * i + 3, 2 * i + 2, 2 * i])
            .collect();
        let base = positions.len() as u32;
        positions.extend([
            DVec3::new(0.0, 0.0, 0.0),
            DVec3::new(1.0, 0.0, 0.0),
            DVec3::new(1.0, 0.0005, 0.0),
        ]);
        faces.push(vec![base, base + 1, base + 2]);
        let mesh = Mesh::from_polygons(positions, faces).unwrap();
        let nodes = find_with_corners(&mesh, 1e-3).unwrap();
        let on_sliver = nodes.iter().filter(|node| node.1.face == n as u32).count();
        assert!(on_sliver > 2 * (n - 10), "{on_sliver} nodes");
        let in_set = faces_with_nodes_inserted(&mesh, &nodes, 0).unwrap();
        let searched = faces_with_nodes_inserted(&mesh, &nodes, usize::MAX).unwrap();
        assert_eq!(in_set, searched);
        let (sizes, indices, inserted) = in_set;
        let sliver = &indices[indices.len() - sizes[n] as usize..];
        let mut distinct = sliver.to_vec();
        distinct.sort_unstable();
        distinct.dedup();
        assert_eq!(distinct.len(), sliver.len(), "a vertex inserted twice");
        assert_eq!(inserted, n - 1 + nodes.len() - on_sliver);
    }

    #[test]
    fn an_owned_repair_moves_the_positions_rather_than_copying_them() {
        for (mesh, expected) in [(two_triangles(true), 1), (two_triangles(false), 0)] {
            let buffer = mesh.positions().as_ptr();
            let repair = repair_t_nodes_owned(mesh, 1e-6).unwrap();
            assert_eq!(
                (repair.inserted, repair.t_nodes.len()),
                (expected, expected)
            );
            assert_eq!(repair.mesh.positions().as_ptr(), buffer);
        }
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
        /// a vertex are chosen. Copies of a position are merged among a
        /// few vertices at a time or among all; cells are sorted along an
        /// axis from 0 or 2 sites on, or as in use; with `far`, the last
        /// strip lies so far away that cells are numbered by wide keys;
        /// with `off_seam`, every other strip is moved off the seams by
        /// two thirds of the tolerance, across the plane and out of it.
        #[test]
        fn the_grid_finds_what_every_pair_finds(
            divisions in proptest::collection::vec(1u32..7, 2..5),
            scale in proptest::sample::select(vec![1.0, 0.01, 3.0e4]),
            soup: bool,
            tolerance in proptest::sample::select(vec![1e-9, 1e-3, 0.05]),
            piece in proptest::sample::select(vec![5usize, 16, 1 << 18]),
            crowded_cell in proptest::sample::select(vec![0usize, 2, CROWDED_CELL]),
            crowded_grid in proptest::sample::select(vec![0.0, 1.0, CROWDED_GRID]),
            far: bool,
            off_seam: bool,
        ) {
            let mut positions = Vec::new();
            let mut faces: Vec<Vec<u32>> = Vec::new();
            for (strip, &n) in divisions.iter().enumerate() {
                let last = strip + 1 == divisions.len();
                let x = strip as f64 + if far && last { 1.0e7 } else { 0.0 };
                let moved = if off_seam && strip % 2 == 1 {
                    DVec3::new(0.6, 0.0, 0.3) * tolerance
                } else {
                    DVec3::ZERO
                };
                let first = positions.len() as u32;
                for i in 0..=n {
                    let y = i as f64 / n as f64;
                    positions.push((DVec3::new(x, y, 0.0) + moved) * scale);
                    positions.push((DVec3::new(x + 1.0, y, 0.0) + moved) * scale);
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
                find_tuned(&mesh, tolerance, Tuning { copies_piece: piece, crowded_cell, crowded_grid }).unwrap(),
                every_pair(&mesh, tolerance)
            );
            // One search for the list and the repair gives what two do.
            let repair = repair_t_nodes_owned(mesh.clone(), tolerance).unwrap();
            let (repaired, inserted) = repair_t_nodes(&mesh, tolerance).unwrap();
            proptest::prop_assert_eq!(repair.t_nodes, find_t_nodes(&mesh, tolerance).unwrap());
            proptest::prop_assert_eq!(repair.inserted, inserted);
            proptest::prop_assert_eq!(repair.mesh, repaired);
        }
    }
}
