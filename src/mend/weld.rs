//! Join meshes and weld their vertices.
//!
//! [`join`] concatenates meshes;
//! [`weld`] merges vertices that lie within a tolerance
//! of each other, in transitive clusters found through a spatial
//! hash (cells as wide as the tolerance, each vertex compared only with the
//! 27 cells around its own), so a million vertices weld in a fraction of a
//! second and no pair of distant vertices is ever compared.
//!
//! T-nodes, the vertices that lie inside another face's edge and so cannot
//! weld, are found and repaired in [`crate::mend::t_nodes`].

use std::collections::HashMap;
use std::hash::{BuildHasherDefault, Hash, Hasher};
use std::sync::atomic::{AtomicBool, Ordering::Relaxed};

use glam::DVec3;
use rayon::prelude::*;

use crate::buffers::{
    fresh_zeroed, par_map, par_offsets, prefix_sum, split_by_offsets, try_copy, try_vec, CHUNK,
};
use crate::error::{Error, Result, MAX_ELEMENTS};
use crate::mesh::topology::UnionFind;
use crate::mesh::{bounding_box_of, check_tolerance, floor_to_i64, repeated_corner, Mesh};
use crowded::{close_pair, first_close_pair, Crowded, Group, COMPARED};

mod copies;
mod crowded;
pub(crate) use copies::{
    append_triangle_sites, nearby_copies, worth_merging, Copies, PIECE as COPIES_PIECE,
    SAMPLE as COPIES_SAMPLE,
};

/// The weld tolerance to use when the host gives none: 0.001 model units.
///
/// It is Rhino's default absolute tolerance, the distance under which Rhino
/// itself treats two points as one: a millimetre in a model drawn in metres,
/// a thousandth of an inch in one drawn in inches. Surface meshes that meet
/// along a seam put their seam vertices far closer than that, while distinct
/// vertices of a design are far further apart.
pub const DEFAULT_WELD_TOLERANCE: f64 = 0.001;

/// The share of a mesh's bounding-box diagonal that [`relative_tolerance`]
/// takes: a millionth, far above the round-off of coordinates written to
/// files (about 1e-15 of the model's size in doubles, 1e-7 in the floats of
/// STL) and far below the spacing of any vertices a model means to keep
/// apart, whatever its units or size.
pub const RELATIVE_TOLERANCE: f64 = 1e-6;

/// The tolerance to weld `mesh` with when none is given: [`RELATIVE_TOLERANCE`]
/// times its bounding-box diagonal (0 for an empty mesh or a single point,
/// which then merges exact duplicates only). A dense scan and a 5 cm part
/// keep every vertex they mean to keep, where an absolute 0.001 would
/// collapse their faces.
pub fn relative_tolerance(mesh: &Mesh) -> f64 {
    mesh.bounding_box()
        .map_or(0.0, |(lo, hi)| (hi - lo).length() * RELATIVE_TOLERANCE)
}

/// What [`weld`] changed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct WeldReport {
    /// Vertices that merged into another vertex: the input's vertex count
    /// minus the number of clusters.
    pub merged_vertex_count: usize,
    /// Faces left with fewer than 3 distinct vertices, and so removed.
    pub removed_face_count: usize,
    /// Clusters that no remaining face uses, and so were left out.
    pub unused_vertex_count: usize,
}

/// Concatenates meshes: the vertices of each follow those of the ones before
/// it, and its face indices are offset to match. Faces keep their order.
///
/// # Errors
/// [`Error::ResultTooLarge`] when the joined vertex or index count passes
/// [`MAX_ELEMENTS`]; [`Error::OutOfMemory`] when the result cannot be allocated.
pub fn join(meshes: &[&Mesh]) -> Result<Mesh> {
    let vertex_total: u64 = meshes.iter().map(|m| m.vertex_count() as u64).sum();
    let index_total: u64 = meshes.iter().map(|m| m.index_count() as u64).sum();
    let face_total: u64 = meshes.iter().map(|m| m.face_count() as u64).sum();
    for (what, total) in [("vertices", vertex_total), ("face corners", index_total)] {
        if total > MAX_ELEMENTS {
            return Err(Error::ResultTooLarge(format!(
                "joining {} meshes gives {total} {what}, more than the limit of {MAX_ELEMENTS}",
                meshes.len()
            )));
        }
    }
    let mut positions = try_vec(vertex_total as usize, "the joined positions")?;
    let mut face_sizes = try_vec(face_total as usize, "the joined face sizes")?;
    let mut face_indices = try_vec(index_total as usize, "the joined face indices")?;
    for mesh in meshes {
        let offset = positions.len() as u32;
        positions.extend_from_slice(mesh.positions());
        face_sizes.extend_from_slice(mesh.face_sizes());
        face_indices.extend(mesh.face_indices().iter().map(|&v| v + offset));
    }
    Ok(Mesh::from_valid_parts(positions, face_sizes, face_indices))
}

/// Merges every two vertices at most `tolerance` apart, transitively: when a
/// is within the tolerance of b and b of c, all three become one vertex even
/// if a and c are further apart. A tolerance of 0 merges exact duplicates.
///
/// The merged vertex keeps the position of the cluster's **first** vertex
/// (the lowest input index), not the average. Seams of surface meshes must
/// stay where the surface put them: an average would pull each seam vertex
/// towards whichever piece happened to contribute more copies, and along a
/// transitive chain it would drift further than the tolerance. The first
/// vertex keeps every output position an input position, and it makes weld
/// idempotent: two clusters are more than the tolerance apart everywhere, so
/// their first vertices are too, and welding again changes nothing.
///
/// Faces keep their order and winding. A face keeps the first occurrence of
/// each vertex and drops repeats (a quad with two merged corners becomes a
/// triangle); a face left with fewer than 3 distinct vertices is removed.
/// Vertices that no remaining face uses are left out, so the result is ready
/// to subdivide; the others keep the order of their first input vertex.
///
/// Clusters are found with a spatial hash of cells as wide as the tolerance:
/// each vertex is compared with the vertices of the 27 cells around it, and
/// exact duplicates are merged by sorting before any distance is measured.
/// In a triangle soup, whose every position has several copies near each
/// other in the vertex order, those copies are merged first, piece by piece
/// through a hash table, and the cells sort only the distinct positions.
/// A cell whose vertices all lie within the tolerance of each other merges
/// without comparing them; a crowded cell that is not so is split into
/// parts that are, and two parts need one close pair to merge, or none when
/// their boxes lie too far apart. So a tolerance many times the vertices'
/// spacing (which collapses faces) costs about as much as a small one,
/// and memory stays linear in the vertex count.
/// Distances are compared without squaring the coordinates' differences, so
/// welding means the same near 1e-300 and near 1e300.
///
/// # Errors
/// [`Error::InvalidArgument`] when `tolerance` is negative, NaN or infinite;
/// [`Error::OutOfMemory`] when the result cannot be allocated.
pub fn weld(mesh: &Mesh, tolerance: f64) -> Result<(Mesh, WeldReport)> {
    let clusters = Clusters::of(mesh.positions(), tolerance)?;
    let unchanged = clusters.leave_unchanged(mesh)?;
    let positions = try_copy(mesh.positions(), "the welded positions")?;
    let face_sizes = mesh.try_copy_face_sizes("the welded face sizes")?;
    let face_indices = try_copy(mesh.face_indices(), "the welded face indices")?;
    if unchanged {
        let copy = Mesh::from_valid_parts(positions, face_sizes, face_indices);
        return Ok((copy, WeldReport::default()));
    }
    clusters.apply(positions, face_sizes, face_indices)
}

/// As [`weld`], the result written over `mesh`'s own arrays: a command that
/// reads a mesh only to weld it needs no second copy of its positions and
/// faces (for 10 M triangles, 280 MB less to allocate and fault in).
///
/// # Errors
/// As [`weld`].
pub fn weld_owned(mesh: Mesh, tolerance: f64) -> Result<(Mesh, WeldReport)> {
    let clusters = Clusters::of(mesh.positions(), tolerance)?;
    if clusters.leave_unchanged(&mesh)? {
        return Ok((mesh, WeldReport::default()));
    }
    let (positions, face_sizes, face_indices) = mesh.into_parts();
    clusters.apply(positions, face_sizes, face_indices)
}

/// Each position's cluster at `tolerance` (what [`weld`] merges), numbered
/// in order of their first position, and how many there are.
///
/// # Errors
/// As [`weld`].
pub(crate) fn position_clusters(positions: &[DVec3], tolerance: f64) -> Result<(Vec<u32>, usize)> {
    let clusters = Clusters::of(positions, tolerance)?;
    Ok((clusters.cluster_of, clusters.count))
}

/// The clusters of a weld: each vertex's, numbered in order of their first
/// vertex, and how many there are.
struct Clusters {
    cluster_of: Vec<u32>,
    count: usize,
}

impl Clusters {
    fn of(positions: &[DVec3], tolerance: f64) -> Result<Clusters> {
        Clusters::with_pieces(positions, tolerance, copies::PIECE)
    }

    /// [`Clusters::of`], the copies merged first in pieces of `piece`
    /// vertices when that pays.
    fn with_pieces(positions: &[DVec3], tolerance: f64, piece: usize) -> Result<Clusters> {
        check_tolerance(tolerance)?;
        let (cluster_of, count) = match copies::nearby_copies(positions, piece)? {
            // The clusters of the distinct positions: each cluster's first
            // vertex is the first copy of its position, so a site, and the
            // sites keep the vertices' order.
            Some(Copies { mut site_of, sites }) => {
                let (site_cluster, count) = vertex_clusters(&sites, tolerance)?.into_labels();
                site_of
                    .par_iter_mut()
                    .with_min_len(CHUNK)
                    .for_each(|s| *s = site_cluster[*s as usize]);
                (site_of, count)
            }
            None => vertex_clusters(positions, tolerance)?.into_labels(),
        };
        Ok(Clusters { cluster_of, count })
    }

    /// Whether welding `mesh` (whose positions the clusters are of) leaves
    /// it as it is: no vertex merged, no face names a vertex twice, and
    /// every vertex is in a face. A mesh welded before is, and so, most
    /// often, is an STL read to be welded (`io::read_mesh_to_weld`), its
    /// copies merged as it was read: checked in one read of the faces,
    /// where [`Clusters::apply`] writes them all.
    ///
    /// # Errors
    /// [`Error::OutOfMemory`].
    fn leave_unchanged(&self, mesh: &Mesh) -> Result<bool> {
        // Numbered in order of their first vertex, clusters of one vertex
        // each are the vertices themselves.
        if self.count != self.cluster_of.len() {
            return Ok(false);
        }
        // Each thread reads a run of faces and marks the vertices they name
        // in a bit set of its own, which stays in its cache.
        let words = mesh.vertex_count().div_ceil(64);
        let faces = mesh.face_count();
        let run = faces.div_ceil(rayon::current_num_threads()).max(1);
        let marks = (0..faces.div_ceil(run))
            .into_par_iter()
            .map(|r| {
                let mut marked = fresh_zeroed::<u64>(words, "the welded vertices")?;
                for f in r * run..((r + 1) * run).min(faces) {
                    let face = mesh.face(f);
                    if repeated_corner(face).is_some() {
                        return Ok(None);
                    }
                    for &v in face {
                        marked[v as usize / 64] |= 1 << (v % 64);
                    }
                }
                Ok(Some(marked))
            })
            .collect::<Result<Option<Vec<Vec<u64>>>>>()?;
        let Some(marks) = marks else {
            return Ok(false);
        };
        let unused_bits = words * 64 - mesh.vertex_count();
        Ok((0..words).all(|w| {
            let every = match w + 1 == words {
                true => u64::MAX >> unused_bits,
                false => u64::MAX,
            };
            marks.iter().fold(0, |all, marked| all | marked[w]) == every
        }))
    }

    /// The welded mesh, written over the arrays of the mesh the clusters
    /// are of: every write lands at or before what is still to be read.
    fn apply(
        self,
        mut positions: Vec<DVec3>,
        mut face_sizes: Vec<u32>,
        mut face_indices: Vec<u32>,
    ) -> Result<(Mesh, WeldReport)> {
        let Clusters {
            cluster_of,
            count: cluster_count,
        } = self;
        let vertex_count = positions.len();

        // Faces over clusters, repeats dropped, collapsed faces removed.
        let (kept_corners, kept_faces) =
            faces_over_clusters(&mut face_sizes, &mut face_indices, &cluster_of);
        let removed_face_count = face_sizes.len() - kept_faces;
        face_indices.truncate(kept_corners);
        face_sizes.truncate(kept_faces);

        // Keep only the clusters some face uses, in order of their first
        // vertex (marked and numbered on all threads).
        let used = par_map(cluster_count, "the welded vertices", |_| {
            AtomicBool::new(false)
        })?;
        face_indices
            .par_iter()
            .with_min_len(CHUNK)
            .for_each(|&c| used[c as usize].store(true, Relaxed));
        // Each kept cluster's new index, and the count after the last.
        let new_index = par_offsets(cluster_count, "the welded vertices", |c| {
            u32::from(used[c].load(Relaxed))
        })?;
        drop(used);
        // Each cluster's first vertex is where its number first appears, and
        // the k-th kept cluster's is at k or after it, past every slot
        // written before it.
        let mut next_cluster = 0;
        for (v, &c) in cluster_of.iter().enumerate() {
            if c == next_cluster {
                let c = c as usize;
                if new_index[c] != new_index[c + 1] {
                    positions[new_index[c] as usize] = positions[v];
                }
                next_cluster += 1;
            }
        }
        drop(cluster_of);
        positions.truncate(new_index[cluster_count] as usize);
        face_indices
            .par_iter_mut()
            .with_min_len(CHUNK)
            .for_each(|c| *c = new_index[*c as usize]);
        let report = WeldReport {
            merged_vertex_count: vertex_count - cluster_count,
            removed_face_count,
            unused_vertex_count: cluster_count - positions.len(),
        };
        Ok((
            Mesh::from_valid_parts(positions, face_sizes, face_indices),
            report,
        ))
    }
}

/// Faces per block of [`faces_over_clusters`].
const FACE_BLOCK: usize = 16 * 1024;

/// Rewrites the faces over `cluster_of`, in place: each face's corners
/// become their clusters, a cluster met again in the same face is dropped,
/// and a face left with fewer than three corners is removed. Returns how
/// many corners and faces are kept, at the front of `indices` and `sizes`.
/// Blocks of faces are rewritten on all threads, each within its own
/// corners, then slid down over what the blocks before them dropped.
fn faces_over_clusters(
    sizes: &mut [u32],
    indices: &mut [u32],
    cluster_of: &[u32],
) -> (usize, usize) {
    let block_corners: Vec<usize> = sizes
        .par_chunks(FACE_BLOCK)
        .map(|block| block.iter().map(|&n| n as usize).sum())
        .collect();
    let mut blocks = Vec::with_capacity(block_corners.len());
    let mut rest = &mut *indices;
    for (face_block, &corners) in sizes.chunks_mut(FACE_BLOCK).zip(&block_corners) {
        let (here, after) = rest.split_at_mut(corners);
        blocks.push((face_block, here));
        rest = after;
    }
    let kept: Vec<(usize, usize)> = blocks
        .into_par_iter()
        .map(|(block_sizes, block_indices)| compact_faces(block_sizes, block_indices, cluster_of))
        .collect();
    let (mut corner_end, mut face_end, mut corner_start) = (0, 0, 0);
    for (b, (&(corners, faces), &block_corners)) in kept.iter().zip(&block_corners).enumerate() {
        let face_start = b * FACE_BLOCK;
        if corner_start != corner_end {
            indices.copy_within(corner_start..corner_start + corners, corner_end);
        }
        if face_start != face_end {
            sizes.copy_within(face_start..face_start + faces, face_end);
        }
        corner_start += block_corners;
        corner_end += corners;
        face_end += faces;
    }
    (corner_end, face_end)
}

/// Faces larger than this drop their repeats through a set rather than by
/// looking back over the corners already kept.
const SCANNED_FACE_SIZE: usize = 32;

/// [`faces_over_clusters`] on one block: the kept faces' sizes and corners
/// written at the front of `sizes` and `indices`; returns how many.
fn compact_faces(sizes: &mut [u32], indices: &mut [u32], cluster_of: &[u32]) -> (usize, usize) {
    let (mut read, mut written, mut kept_faces) = (0, 0, 0);
    let mut seen = std::collections::HashSet::new();
    for f in 0..sizes.len() {
        let start = written;
        let size = sizes[f] as usize;
        // Every corner is read before anything is written over it:
        // `written` never passes `corner`.
        if size <= SCANNED_FACE_SIZE {
            for corner in read..read + size {
                let c = cluster_of[indices[corner] as usize];
                if !indices[start..written].contains(&c) {
                    indices[written] = c;
                    written += 1;
                }
            }
        } else {
            seen.clear();
            for corner in read..read + size {
                let c = cluster_of[indices[corner] as usize];
                if seen.insert(c) {
                    indices[written] = c;
                    written += 1;
                }
            }
        }
        read += size;
        if written - start < 3 {
            written = start;
        } else {
            sizes[kept_faces] = (written - start) as u32;
            kept_faces += 1;
        }
    }
    (written, kept_faces)
}

/// How many vertices no face uses.
pub fn unused_vertex_count(mesh: &Mesh) -> usize {
    used_vertices(mesh).map_or(0, |used| used.iter().filter(|&&u| !u).count())
}

/// Leaves out the vertices no face uses; the others keep their order.
/// Returns the compacted mesh and how many vertices were left out.
pub fn remove_unused_vertices(mesh: &Mesh) -> (Mesh, usize) {
    match used_vertices(mesh) {
        Some(used) => without_unused(mesh, &used),
        None => (mesh.clone(), 0),
    }
}

/// [`remove_unused_vertices`] on a mesh the caller gives up: when every
/// vertex is used it comes back as it is, with no copy made.
pub fn remove_unused_vertices_owned(mesh: Mesh) -> (Mesh, usize) {
    match used_vertices(&mesh) {
        Some(used) => without_unused(&mesh, &used),
        None => (mesh, 0),
    }
}

/// Which vertices a face uses; `None` when every one is.
fn used_vertices(mesh: &Mesh) -> Option<Vec<bool>> {
    let mut used = vec![false; mesh.vertex_count()];
    for &v in mesh.face_indices() {
        used[v as usize] = true;
    }
    used.contains(&false).then_some(used)
}

/// The mesh with only the vertices `used` marks, renumbered in order.
fn without_unused(mesh: &Mesh, used: &[bool]) -> (Mesh, usize) {
    let mut new_index = vec![u32::MAX; mesh.vertex_count()];
    let mut positions = Vec::with_capacity(mesh.vertex_count());
    for (v, slot) in new_index.iter_mut().enumerate() {
        if used[v] {
            *slot = positions.len() as u32;
            positions.push(mesh.positions()[v]);
        }
    }
    let removed = mesh.vertex_count() - positions.len();
    let indices = mesh
        .face_indices()
        .iter()
        .map(|&v| new_index[v as usize])
        .collect();
    (
        Mesh::from_valid_parts(positions, mesh.face_sizes().to_vec(), indices),
        removed,
    )
}

/// Whether `p` and `q` are at most `tolerance` apart. The difference is
/// scaled by its largest coordinate before it is squared, so the test holds
/// for coordinates near 1e-300 (whose squares underflow to 0, which would
/// weld distinct vertices at tolerance 0) and near 1e300 (whose squares
/// overflow).
#[inline]
pub(crate) fn within(p: DVec3, q: DVec3, tolerance: f64) -> bool {
    let d = p - q;
    let unit = d.abs().max_element();
    unit == 0.0 || unit * (d / unit).length() <= tolerance
}

/// Unions every two vertices at most `tolerance` apart.
fn vertex_clusters(positions: &[DVec3], tolerance: f64) -> Result<UnionFind> {
    let Some((lo, hi)) = bounding_box_of(positions) else {
        return Ok(UnionFind::new(0));
    };
    let grid = CellGrid::with_reach(lo.abs().max(hi.abs()).max_element(), tolerance);
    // The cells of the bounding box's corners bound every cell.
    let (first, last) = (grid.cell(lo), grid.cell(hi));
    match PackedCell::origin(first, last) {
        Some(origin) => clusters_by(positions, tolerance, |p| {
            PackedCell::of(grid.cell(p), origin)
        }),
        None => clusters_by(positions, tolerance, |p| grid.cell(p)),
    }
}

/// [`vertex_clusters`] with the cells as `cell_of` numbers them.
fn clusters_by<K: CellKey>(
    positions: &[DVec3],
    tolerance: f64,
    cell_of: impl Fn(DVec3) -> K + Sync,
) -> Result<UnionFind> {
    if positions.is_empty() {
        return Ok(UnionFind::new(0));
    }
    // By cell (one parallel sort, comparing the cells alone); each cell's
    // vertices are then put in order of exact position, then index, so that
    // duplicates become neighbours with their lowest index first.
    let mut entries = try_vec::<(K, u32)>(positions.len(), "the weld cells")?;
    entries.par_extend(
        positions
            .par_iter()
            .enumerate()
            .with_min_len(4096)
            .map(|(v, &p)| (cell_of(p), v as u32)),
    );
    entries.par_sort_unstable_by_key(|entry| entry.0);
    let mut order = try_vec::<u32>(positions.len(), "the weld order")?;
    order.par_extend(entries.par_iter().with_min_len(4096).map(|&(_, v)| v));
    let by_position = |&a: &u32, &b: &u32| {
        let (pa, pb) = (positions[a as usize], positions[b as usize]);
        // Adding 0 makes -0 and +0 one key: they are one position.
        let (pa, pb) = (pa + 0.0, pb + 0.0);
        pa.x.total_cmp(&pb.x)
            .then(pa.y.total_cmp(&pb.y))
            .then(pa.z.total_cmp(&pb.z))
            .then(a.cmp(&b))
    };

    // The cells in pieces of whole cells, on all threads. Each piece finds
    // its cells' distinct positions ("sites", each standing for its exact
    // duplicates), writes each vertex's site over its entry's index, and
    // counts its cells and sites.
    let cuts = cell_pieces(&entries, 8 * rayon::current_num_threads());
    let counts: Vec<(u32, u32)> = split_by_offsets(&mut entries, &cuts, 1)
        .into_par_iter()
        .zip(split_by_offsets(&mut order, &cuts, 1))
        .map(|((_, entries), (_, order))| piece_sites(positions, entries, order, &by_position))
        .collect();

    // Sites of each occupied cell: sites[cell_starts[k]..cell_starts[k + 1]],
    // each piece's written into its own part in one more pass, a stream
    // over its entries (a vertex is a site when its entry names itself).
    let running = |count: fn(&(u32, u32)) -> u32| {
        let mut offsets: Vec<u32> = std::iter::once(0).chain(counts.iter().map(count)).collect();
        prefix_sum(&mut offsets);
        offsets
    };
    let (cell_offsets, site_offsets) = (running(|c| c.0), running(|c| c.1));
    let (cell_count, site_count) = (
        cell_offsets[counts.len()] as usize,
        site_offsets[counts.len()],
    );
    let filler = entries[0].0;
    let mut cell_keys = par_map(cell_count, "the weld cells", |_| filler)?;
    let mut cell_starts = par_map(cell_count + 1, "the weld cells", |_| site_count)?;
    let mut sites = par_map(site_count as usize, "the weld sites", |_| 0u32)?;
    split_by_offsets(&mut cell_keys, &cell_offsets, 1)
        .into_par_iter()
        .zip(split_by_offsets(
            &mut cell_starts[..cell_count],
            &cell_offsets,
            1,
        ))
        .zip(split_by_offsets(&mut sites, &site_offsets, 1))
        .for_each(|(((pieces, keys), (_, starts)), (_, sites))| {
            let piece = pieces.start;
            let range = cuts[piece] as usize..cuts[piece + 1] as usize;
            let (mut cell, mut site) = (0, 0);
            for (&(key, site_of), &v) in entries[range.clone()].iter().zip(&order[range]) {
                if cell == 0 || key != keys[cell - 1] {
                    keys[cell] = key;
                    starts[cell] = site_offsets[piece] + site as u32;
                    cell += 1;
                }
                if site_of == v {
                    sites[site] = v;
                    site += 1;
                }
            }
        });
    // Each duplicate joins its site (every site is the lowest index of its
    // position, so is the root of a new set).
    let mut clusters = UnionFind::new(positions.len());
    // As many sites as vertices: no vertex has a copy.
    if site_count as usize != positions.len() {
        for (&(_, site), &v) in entries.iter().zip(&order) {
            if site != v {
                clusters.union(site, v);
            }
        }
    }
    drop((entries, order));
    if tolerance == 0.0 {
        return Ok(clusters);
    }

    // A cell whose sites all lie within the tolerance of each other (its
    // box's diagonal is short enough) is one cluster without comparing its
    // pairs, and two such cells need only one close pair to become one.
    // The other cells are split into groups that are (`crowded.rs`). This
    // keeps crowded cells, down to a tolerance larger than the whole mesh,
    // near linear in time and linear in memory.
    let crowded = Crowded::split(&mut sites, &cell_starts, positions, tolerance);
    let tight = &crowded.tight;
    let cell_sites = |k: usize| &sites[cell_starts[k] as usize..cell_starts[k + 1] as usize];
    let group_sites = |group: &Group| &sites[group.start as usize..group.end as usize];
    // Two groups: at most one close pair when both are tight, else every
    // one (a group that could not be split: rounding at the ends of the
    // f64 range).
    let join_groups = |a: &Group, b: &Group, pairs: &mut Vec<(u32, u32)>| {
        if a.apart(b, tolerance) {
            return;
        }
        let both_tight = a.tight && b.tight;
        if both_tight && a.all_within(b, tolerance) {
            pairs.push((sites[a.start as usize], sites[b.start as usize]));
            return;
        }
        if both_tight {
            // Large groups are ruled out or in box by box, not pair by pair.
            let (here, there) = (group_sites(a), group_sites(b));
            pairs.extend(match here.len() * there.len() <= COMPARED {
                true => first_close_pair(here, there, positions, tolerance),
                false => {
                    let (mut here, mut there) = (here.to_vec(), there.to_vec());
                    close_pair(&mut here, &mut there, positions, tolerance)
                }
            });
            return;
        }
        for &u in group_sites(a) {
            let pu = positions[u as usize];
            for &v in group_sites(b) {
                if within(pu, positions[v as usize], tolerance) {
                    pairs.push((u, v));
                }
            }
        }
    };
    // The pairs to join, blocks of cells on all threads (the clusters do not
    // depend on the order the pairs are joined in), then joined on one.
    // The cells are sorted, and so are the cells one row away from
    // them: each block finds its neighbours in a row by walking both
    // sorted lists side by side, without hashing.
    const CELLS: usize = 4096;
    let pairs: Vec<Vec<(u32, u32)>> = (0..cell_keys.len().div_ceil(CELLS))
        .into_par_iter()
        .map(|block| {
            let cells = block * CELLS..((block + 1) * CELLS).min(cell_keys.len());
            let mut pairs = Vec::new();
            let chain = |sites: &[u32], pairs: &mut Vec<(u32, u32)>| {
                pairs.extend(sites[1..].iter().map(|&b| (sites[0], b)));
            };
            for k in cells.clone() {
                if tight[k] {
                    chain(cell_sites(k), &mut pairs);
                    continue;
                }
                let groups = crowded.groups(k);
                for (i, group) in groups.iter().enumerate() {
                    match group.tight {
                        true => chain(group_sites(group), &mut pairs),
                        false => {
                            let here = group_sites(group);
                            for (j, &a) in here.iter().enumerate() {
                                let pa = positions[a as usize];
                                for &b in &here[j + 1..] {
                                    if within(pa, positions[b as usize], tolerance) {
                                        pairs.push((a, b));
                                    }
                                }
                            }
                        }
                    }
                    for other in &groups[i + 1..] {
                        join_groups(group, other, &mut pairs);
                    }
                }
            }
            // Each pair of neighbouring cells once: only the 13 "forward"
            // neighbours, the next cell of the row and three cells in each
            // of four rows. A row's three cells are consecutive in the
            // cells' order, so one walk finds all three.
            let mut close = |k: usize, other: usize| {
                let (here, there) = (cell_sites(k), cell_sites(other));
                // Two tight cells are each one cluster: one close pair joins them.
                if tight[k] && tight[other] && here.len() * there.len() <= COMPARED {
                    pairs.extend(first_close_pair(here, there, positions, tolerance));
                    return;
                }
                // A crowded cell, or two tight cells of many sites: by groups,
                // a tight cell's its own (its box left unbounded).
                let whole = |k: usize| Group {
                    start: cell_starts[k],
                    end: cell_starts[k + 1],
                    low: DVec3::NEG_INFINITY,
                    high: DVec3::INFINITY,
                    tight: true,
                };
                let (one, two) = ([whole(k)], [whole(other)]);
                let here = if tight[k] {
                    &one[..]
                } else {
                    crowded.groups(k)
                };
                let there = if tight[other] {
                    &two[..]
                } else {
                    crowded.groups(other)
                };
                for a in here {
                    for b in there {
                        join_groups(a, b, &mut pairs);
                    }
                }
            };
            for k in cells.clone() {
                let next = k + 1;
                if next < cell_keys.len() && cell_keys[next] == cell_keys[k].offset([0, 0, 1]) {
                    close(k, next);
                }
            }
            for [dx, dy] in FORWARD_ROWS {
                let first = cell_keys[cells.start].offset([dx, dy, -1]);
                let mut other = cell_keys.partition_point(|&c| c < first);
                for k in cells.clone() {
                    let (low, high) = (
                        cell_keys[k].offset([dx, dy, -1]),
                        cell_keys[k].offset([dx, dy, 1]),
                    );
                    while other < cell_keys.len() && cell_keys[other] < low {
                        other += 1;
                    }
                    // The cells from `low` to `high` are the row's three.
                    let row = cell_keys[other..].iter().take_while(|&&c| c <= high);
                    for there in other..other + row.count() {
                        close(k, there);
                    }
                }
            }
            pairs
        })
        .collect();
    for (a, b) in pairs.into_iter().flatten() {
        clusters.union(a, b);
    }
    Ok(clusters)
}

/// Where to cut `entries`, sorted by cell, into about `count` pieces of
/// whole cells: the first entry of each piece, then the length.
fn cell_pieces<K: CellKey>(entries: &[(K, u32)], count: usize) -> Vec<u32> {
    let step = entries.len().div_ceil(count.max(1)).max(1);
    let mut cuts = vec![0];
    let mut at = step;
    while at < entries.len() {
        // Forward to the start of the next cell.
        at = cell_end(entries, at - 1);
        if at < entries.len() {
            cuts.push(at as u32);
        }
        at += step;
    }
    cuts.push(entries.len() as u32);
    cuts
}

/// The end of the cell of `entries[at]`, `entries` sorted by cell. Most
/// cells hold a vertex or two: a scan, not a binary search that would miss
/// the cache at every step.
fn cell_end<K: CellKey>(entries: &[(K, u32)], at: usize) -> usize {
    let key = entries[at].0;
    at + entries[at..].iter().take_while(|e| e.0 == key).count()
}

/// The sites of one piece of whole cells: each cell's vertices in `order`
/// are put in order of exact position, so that duplicates become
/// neighbours with their lowest index, the site, first; each entry's index
/// is then overwritten with its vertex's site. Returns how many cells and
/// sites the piece holds.
fn piece_sites<K: CellKey>(
    positions: &[DVec3],
    entries: &mut [(K, u32)],
    order: &mut [u32],
    by_position: &(impl Fn(&u32, &u32) -> std::cmp::Ordering + Sync),
) -> (u32, u32) {
    let (mut cells, mut sites) = (0, 0);
    let mut start = 0;
    while start < entries.len() {
        let end = cell_end(entries, start);
        let group = &mut order[start..end];
        // A cell of copies of one position (an STL's corners) needs only
        // its indices in order.
        let first = positions[group[0] as usize];
        match group.len() {
            1 => {}
            _ if group[1..].iter().all(|&v| positions[v as usize] == first) => {
                group.sort_unstable()
            }
            n if n < 1 << 16 => group.sort_unstable_by(by_position),
            _ => group.par_sort_unstable_by(by_position),
        }
        cells += 1;
        let mut site = group[0];
        sites += 1;
        for (k, &v) in group.iter().enumerate() {
            if positions[v as usize] != positions[site as usize] {
                site = v;
                sites += 1;
            }
            entries[start + k].1 = site;
        }
        start = end;
    }
    (cells, sites)
}

/// The rows of cells (x, y offsets) that hold the 12 of the 26
/// neighbouring cells that come after (0, 0, 0) in lexicographic order
/// outside its own row, three in each (z - 1, z, z + 1); with (0, 0, 1)
/// and their mirror images they make all 26.
const FORWARD_ROWS: [[i64; 2]; 4] = [[0, 1], [1, -1], [1, 0], [1, 1]];

/// A grid cell as the clusters sort and walk them.
trait CellKey: Copy + Ord + Send + Sync {
    /// The cell `d` cells away.
    fn offset(self, d: [i64; 3]) -> Self;
}

impl CellKey for Cell {
    #[inline]
    fn offset(self, d: [i64; 3]) -> Cell {
        Cell::offset(self, d)
    }
}

/// A cell's coordinates in one word, 21 bits each, counted from one cell
/// before the lowest: the numbers of every cell and of its neighbours are
/// in the coordinates' order, so they sort and step alike, and a sort of
/// them moves half the bytes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub(crate) struct PackedCell(u64);

impl PackedCell {
    const BITS: u32 = 21;

    /// Where the numbering starts, when the cells from `first` to `last`
    /// (the lowest and highest in each axis) and their neighbours fit.
    pub(crate) fn origin(first: Cell, last: Cell) -> Option<[i64; 3]> {
        let fits = (0..3).all(|i| {
            last.0[i]
                .checked_sub(first.0[i])
                .is_some_and(|span| span + 2 < 1 << Self::BITS)
        });
        fits.then(|| first.0.map(|c| c - 1))
    }

    #[inline]
    fn of(cell: Cell, origin: [i64; 3]) -> PackedCell {
        let [x, y, z] = [0, 1, 2].map(|i| (cell.0[i] - origin[i]) as u64);
        PackedCell((x << (2 * Self::BITS)) | (y << Self::BITS) | z)
    }
}

impl CellKey for PackedCell {
    #[inline]
    fn offset(self, [dx, dy, dz]: [i64; 3]) -> PackedCell {
        // Every field stays inside its 21 bits, so the sum carries nothing.
        PackedCell(
            self.0
                .wrapping_add_signed((dx << (2 * Self::BITS)) + (dy << Self::BITS) + dz),
        )
    }
}

/// A cell of a uniform grid, by its integer coordinates.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, PartialOrd, Ord)]
pub(crate) struct Cell(pub(crate) [i64; 3]);

impl Cell {
    #[inline]
    pub(crate) fn offset(self, d: [i64; 3]) -> Cell {
        Cell([self.0[0] + d[0], self.0[1] + d[1], self.0[2] + d[2]])
    }

    /// How many face-to-face steps lead from this cell to `other` (the
    /// Manhattan distance, saturating).
    pub(crate) fn steps_to(self, other: Cell) -> u64 {
        (0..3).fold(0u64, |total, i| {
            total.saturating_add(self.0[i].abs_diff(other.0[i]))
        })
    }
}

/// Three words mixed into one by large odd multipliers, which spread
/// neighbouring cells (and positions) over a table.
#[inline]
pub(crate) fn mix_words([x, y, z]: [u64; 3]) -> u64 {
    x.wrapping_mul(0x9E37_79B9_7F4A_7C15)
        ^ y.wrapping_mul(0xC2B2_AE3D_27D4_EB4F)
        ^ z.wrapping_mul(0x1656_67B1_9E37_79F9)
}

impl Hash for Cell {
    #[inline]
    fn hash<H: Hasher>(&self, state: &mut H) {
        let h = mix_words(self.0.map(|c| c as u64));
        state.write_u64(h ^ (h >> 29));
    }
}

/// Passes a [`Cell`]'s own mixed hash through unchanged.
#[derive(Default)]
pub(crate) struct CellHasher(u64);

impl Hasher for CellHasher {
    #[inline]
    fn finish(&self) -> u64 {
        self.0
    }
    #[inline]
    fn write(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.0 = (self.0.rotate_left(8) ^ b as u64).wrapping_mul(0x9E37_79B9_7F4A_7C15);
        }
    }
    #[inline]
    fn write_u64(&mut self, value: u64) {
        self.0 = value;
    }
}

/// A hash map keyed by grid cells.
pub(crate) type CellMap<V> = HashMap<Cell, V, BuildHasherDefault<CellHasher>>;

/// A uniform grid over space: cells of a given size, never smaller than what
/// keeps every cell coordinate well inside `i64` for the points it serves.
#[derive(Debug, Clone, Copy)]
pub(crate) struct CellGrid {
    pub(crate) size: f64,
}

impl CellGrid {
    /// A grid of cells at least `size` wide for points like `points`.
    pub(crate) fn new(points: impl Iterator<Item = DVec3>, size: f64) -> CellGrid {
        CellGrid::with_reach(
            points.fold(0.0f64, |m, p| m.max(p.abs().max_element())),
            size,
        )
    }

    /// As [`CellGrid::new`], for points whose largest coordinate magnitude
    /// is `reach`.
    pub(crate) fn with_reach(reach: f64, size: f64) -> CellGrid {
        // 2^-40 of the coordinates' reach keeps cell numbers below 2^41, and a
        // cell that wide is still below the round-off of the coordinates.
        // Never below the smallest normal number: a cell width of 0 (the
        // floor of subnormal coordinates) would put points in no cell at all.
        let floor = if reach > 0.0 {
            (reach * 2f64.powi(-40)).max(f64::MIN_POSITIVE)
        } else {
            1.0
        };
        CellGrid {
            size: size.max(floor),
        }
    }

    /// Each vertex with its cell, sorted by cell (then vertex): the
    /// vertices of one cell side by side. `what` names the buffer in an
    /// out-of-memory error.
    pub(crate) fn sorted_cells(&self, positions: &[DVec3], what: &str) -> Result<Vec<(Cell, u32)>> {
        let mut entries = try_vec::<(Cell, u32)>(positions.len(), what)?;
        entries.extend(
            positions
                .iter()
                .enumerate()
                .map(|(v, &p)| (self.cell(p), v as u32)),
        );
        entries.par_sort_unstable();
        Ok(entries)
    }

    #[inline]
    pub(crate) fn cell(&self, p: DVec3) -> Cell {
        let c = p / self.size;
        Cell([c.x, c.y, c.z].map(floor_to_i64))
    }
}

#[cfg(test)]
mod tests;
