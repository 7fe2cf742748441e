//! The one builder of edges and adjacency, shared by [`Topology`] and the
//! subdivision's levels: every face corner's edge is bucketed under its
//! lower vertex and each small bucket sorted by the higher vertex, so the
//! edges come out sorted without hashing pairs or comparing faces. Every
//! array is reserved fallibly: a mesh too large for memory is an error.
//!
//! The build makes four passes, each on rayon's threads: blocks of corners
//! count their edges' buckets and their vertices, then (each block's
//! entries placed after the earlier blocks', so the order stays ascending)
//! drop their corners into the buckets and into the vertices' lists; ranges
//! of vertices sort their buckets and count their edges, then, knowing
//! where their first edge goes, write their edges. A bucket holds corners
//! only, and becomes the edges' corner list: each corner's higher vertex is
//! read again from the face indices rather than kept beside it, which
//! halves the bucket's memory.
//!
//! Names used throughout: a *corner* is a position in the face indices; the
//! *edge of a corner* runs from that corner's vertex to the next corner's
//! vertex in the same face.
//!
//! [`Topology`]: crate::mesh::topology::Topology

use std::ops::Range;
use std::sync::atomic::{AtomicBool, AtomicU32, Ordering::Relaxed};

use rayon::prelude::*;

use crate::buffers::{split_by_offsets, try_vec, zeroed, CHUNK};
use crate::error::Result;

/// Corners from which the build splits its work across rayon's threads; a
/// smaller mesh is built in one block and one range of vertices, which
/// rayon runs on the calling thread.
const PARALLEL_CORNERS: usize = 16 * CHUNK;

/// How the build splits its work.
#[derive(Debug, Clone, Copy)]
struct Split {
    /// Ranges of corners, each counted and bucketed by one task with its own
    /// count per vertex (so few: one per thread).
    blocks: usize,
    /// Ranges of `1 << shift` vertices, whose counts one task turns into
    /// slots, or whose buckets it sorts and turns into edges.
    shift: u32,
}

impl Split {
    fn of(corner_count: usize, vertex_count: usize) -> Split {
        if corner_count < PARALLEL_CORNERS {
            return Split {
                blocks: 1,
                shift: usize::BITS - vertex_count.leading_zeros(),
            };
        }
        Split {
            blocks: rayon::current_num_threads().clamp(1, corner_count / PARALLEL_CORNERS),
            shift: CHUNK.trailing_zeros(),
        }
    }
}

/// Edges, and the corners on each edge and at each vertex.
#[derive(Debug, Clone, Default)]
pub(crate) struct Adjacency {
    /// Edges as `[low, high]` vertex pairs, sorted. A pair is unique except
    /// where a face repeats a vertex: a degenerate edge `[v, v]`, and a pair
    /// a face meets twice, get one edge per such corner (after the shared
    /// first), as OpenSubdiv gives them.
    pub(crate) edges: Vec<[u32; 2]>,
    /// For each corner, the edge from it to the next corner of its face.
    pub(crate) corner_edges: Vec<u32>,
    /// `edge_corners[edge_offsets[e]..edge_offsets[e + 1]]` are the corners whose edge is e, ascending.
    pub(crate) edge_offsets: Vec<u32>,
    pub(crate) edge_corners: Vec<u32>,
    /// `vertex_corners[vertex_offsets[v]..vertex_offsets[v + 1]]` are the corners at vertex v, ascending.
    pub(crate) vertex_offsets: Vec<u32>,
    pub(crate) vertex_corners: Vec<u32>,
}

impl Adjacency {
    /// The edges and adjacency of faces over `vertex_count` vertices whose
    /// corners hold the vertices `indices`; `next(c)` is the corner after
    /// `c` in its face, `face_of(c)` its face.
    ///
    /// # Errors
    /// [`crate::Error::OutOfMemory`] when the arrays cannot be reserved.
    pub(crate) fn build(
        vertex_count: usize,
        indices: &[u32],
        next: impl Fn(usize) -> usize + Sync,
        face_of: impl Fn(usize) -> usize + Sync,
    ) -> Result<Adjacency> {
        let split = Split::of(indices.len(), vertex_count);
        Adjacency::build_split(vertex_count, indices, next, face_of, split, true)
    }

    /// As [`Adjacency::build`] without the vertices' corners (their lists
    /// are left empty): for a pass that asks only about edges.
    ///
    /// # Errors
    /// As [`Adjacency::build`].
    pub(crate) fn build_edges(
        vertex_count: usize,
        indices: &[u32],
        next: impl Fn(usize) -> usize + Sync,
        face_of: impl Fn(usize) -> usize + Sync,
    ) -> Result<Adjacency> {
        let split = Split::of(indices.len(), vertex_count);
        Adjacency::build_split(vertex_count, indices, next, face_of, split, false)
    }

    /// For each corner, whether it is its edge's only corner (a naked
    /// edge, as [`Adjacency::build`] counts corners, faces naming a vertex
    /// twice included), without the edges themselves: the buckets are
    /// sorted as for the edges, and nothing else is written.
    ///
    /// # Errors
    /// As [`Adjacency::build`].
    pub(crate) fn naked_corners(
        vertex_count: usize,
        indices: &[u32],
        next: impl Fn(usize) -> usize + Sync,
        face_of: impl Fn(usize) -> usize + Sync,
    ) -> Result<Vec<bool>> {
        let split = Split::of(indices.len(), vertex_count);
        let entry = |c: u32| bucket_entry(indices, &next, c);
        let vertices = 1usize << split.shift;
        let Buckets {
            mut edge_corners,
            bucket_offsets,
            ..
        } = buckets(vertex_count, indices, &next, split, false)?;
        let naked: Vec<AtomicBool> = zeroed::<bool>(indices.len(), "naked corners")?
            .into_iter()
            .map(AtomicBool::new)
            .collect();
        split_by_offsets(&mut edge_corners, &bucket_offsets, vertices)
            .into_par_iter()
            .try_for_each(|(lows, corners)| {
                let sink = &mut MarkNaked(&naked);
                sort_buckets(lows, corners, &bucket_offsets, entry, &face_of, sink)
            })?;
        Ok(naked.into_iter().map(AtomicBool::into_inner).collect())
    }

    fn build_split(
        vertex_count: usize,
        indices: &[u32],
        next: impl Fn(usize) -> usize + Sync,
        face_of: impl Fn(usize) -> usize + Sync,
        split: Split,
        with_vertices: bool,
    ) -> Result<Adjacency> {
        let corner_count = indices.len();
        let entry = |c: u32| bucket_entry(indices, &next, c);
        let vertices = 1usize << split.shift;
        let Buckets {
            mut edge_corners,
            bucket_offsets,
            vertex_offsets,
            vertex_corners,
        } = buckets(vertex_count, indices, &next, split, with_vertices)?;

        // Each range of vertices sorts its buckets by (higher vertex, corner),
        // keeping them so, and counts its edges.
        let part_edges = split_by_offsets(&mut edge_corners, &bucket_offsets, vertices)
            .into_par_iter()
            .map(|(lows, corners)| -> Result<u32> {
                let mut count = Count(0);
                sort_buckets(lows, corners, &bucket_offsets, entry, &face_of, &mut count)?;
                Ok(count.0)
            })
            .collect::<Result<Vec<u32>>>()?;
        let mut part_offsets = Vec::with_capacity(part_edges.len() + 1);
        part_offsets.push(0u32);
        for count in part_edges {
            part_offsets.push(part_offsets[part_offsets.len() - 1] + count);
        }
        let edge_count = part_offsets[part_offsets.len() - 1] as usize;

        // Each range writes its edges from its first, and each edge's corners
        // in the order the edges take them.
        let mut edges: Vec<[u32; 2]> = zeroed(edge_count, "edges")?;
        let mut edge_offsets: Vec<u32> = zeroed(edge_count + 1, "edge offsets")?;
        let corner_edges = atomic(zeroed(corner_count, "corner edges")?);
        let edge_parts = split_by_offsets(&mut edges, &part_offsets, 1);
        let end_parts = split_by_offsets(&mut edge_offsets[1..], &part_offsets, 1);
        split_by_offsets(&mut edge_corners, &bucket_offsets, vertices)
            .into_par_iter()
            .zip(edge_parts)
            .zip(end_parts)
            .try_for_each(
                |(((lows, corners), (part, edges)), (_, ends))| -> Result<()> {
                    let base = bucket_offsets[lows.start];
                    let mut entries = Vec::new();
                    let mut write = Write {
                        edges,
                        ends,
                        corners,
                        corner_edges: &corner_edges,
                        first_edge: part_offsets[part.start],
                        first_slot: base,
                        edge: 0,
                        slot: 0,
                    };
                    for low in lows {
                        let bucket = &write.corners[(bucket_offsets[low] - base) as usize
                            ..(bucket_offsets[low + 1] - base) as usize];
                        read_entries(&mut entries, bucket, entry)?;
                        bucket_edges(low as u32, &entries, &face_of, &mut write);
                    }
                    Ok(())
                },
            )?;
        drop(bucket_offsets);

        Ok(Adjacency::from_parts(
            (edges, plain(corner_edges)),
            (edge_offsets, edge_corners),
            (vertex_offsets, vertex_corners),
        ))
    }

    /// The adjacency of its three parts as the builders make them: the
    /// edges and each corner's edge, each edge's corners (offsets and
    /// list), each vertex's corners (offsets and list).
    pub(crate) fn from_parts(
        (edges, corner_edges): (Vec<[u32; 2]>, Vec<u32>),
        (edge_offsets, edge_corners): (Vec<u32>, Vec<u32>),
        (vertex_offsets, vertex_corners): (Vec<u32>, Vec<u32>),
    ) -> Adjacency {
        Adjacency {
            edges,
            corner_edges,
            edge_offsets,
            edge_corners,
            vertex_offsets,
            vertex_corners,
        }
    }

    /// Number of edges.
    #[inline]
    pub(crate) fn edge_count(&self) -> usize {
        self.edges.len()
    }

    /// The corners whose edge is `e`, ascending (so their faces ascend too).
    #[inline]
    pub(crate) fn edge_corners(&self, e: usize) -> &[u32] {
        &self.edge_corners[self.edge_offsets[e] as usize..self.edge_offsets[e + 1] as usize]
    }

    /// The corners at vertex `v`, ascending.
    #[inline]
    pub(crate) fn vertex_corners(&self, v: usize) -> &[u32] {
        &self.vertex_corners[self.vertex_offsets[v] as usize..self.vertex_offsets[v + 1] as usize]
    }
}

/// Each corner under its edge's lower vertex (the edge buckets, each
/// ascending) and, `with_vertices`, under its vertex.
struct Buckets {
    edge_corners: Vec<u32>,
    bucket_offsets: Vec<u32>,
    vertex_offsets: Vec<u32>,
    vertex_corners: Vec<u32>,
}

/// The first passes of the edge builder: [`Buckets`] on all threads.
fn buckets(
    vertex_count: usize,
    indices: &[u32],
    next: impl Fn(usize) -> usize + Sync,
    split: Split,
    with_vertices: bool,
) -> Result<Buckets> {
    let corner_count = indices.len();
    // A corner's vertex and its edge's lower vertex.
    let vertex_and_low = |c: usize| {
        let (a, b) = (indices[c], indices[next(c)]);
        (a, a.min(b))
    };
    let blocks: Vec<Range<usize>> = (0..split.blocks)
        .map(|b| corner_count * b / split.blocks..corner_count * (b + 1) / split.blocks)
        .collect();
    let vertices = 1usize << split.shift;

    // Each block counts its corners under their edge's lower vertex (the
    // edge buckets) and under their vertex, vertex v's count at v + 1.
    let mut edge_slots = per_block_counts(split.blocks, vertex_count, "edge buckets")?;
    let vertex_slots_count = if with_vertices { vertex_count } else { 0 };
    let mut vertex_slots = per_block_counts(split.blocks, vertex_slots_count, "vertex corners")?;
    blocks
        .par_iter()
        .zip(&mut edge_slots[..])
        .zip(&mut vertex_slots[..])
        .for_each(|((corners, edge_counts), vertex_counts)| {
            for c in corners.clone() {
                let (v, low) = vertex_and_low(c);
                edge_counts[low as usize + 1] += 1;
                if with_vertices {
                    vertex_counts[v as usize + 1] += 1;
                }
            }
        });
    rayon::join(
        || first_slots(&mut edge_slots, vertices),
        || first_slots(&mut vertex_slots, vertices),
    );

    // Each block drops its corners, ascending, into the slots after the
    // earlier blocks': every vertex's corners ascend, and the last
    // block's slots end up at the offsets.
    let bucket = atomic(zeroed(corner_count, "edge corners")?);
    let at_vertex = atomic(zeroed(
        if with_vertices { corner_count } else { 0 },
        "vertex corners",
    )?);
    blocks
        .par_iter()
        .zip(&mut edge_slots[..])
        .zip(&mut vertex_slots[..])
        .for_each(|((corners, edge_slots), vertex_slots)| {
            for c in corners.clone() {
                let (v, low) = vertex_and_low(c);
                let slot = &mut edge_slots[low as usize + 1];
                bucket[*slot as usize].store(c as u32, Relaxed);
                *slot += 1;
                if with_vertices {
                    let slot = &mut vertex_slots[v as usize + 1];
                    at_vertex[*slot as usize].store(c as u32, Relaxed);
                    *slot += 1;
                }
            }
        });
    let bucket_offsets = last(edge_slots);
    let vertex_offsets = if with_vertices {
        last(vertex_slots)
    } else {
        Vec::new()
    };
    Ok(Buckets {
        edge_corners: plain(bucket),
        bucket_offsets,
        vertex_offsets,
        vertex_corners: plain(at_vertex),
    })
}

/// Sorts the buckets of the lower vertices `lows`, whose corners are
/// `corners` (from `bucket_offsets[lows.start]` on), by (higher vertex,
/// corner), keeping them so, and hands their edges to `sink` in order.
fn sort_buckets(
    lows: Range<usize>,
    corners: &mut [u32],
    bucket_offsets: &[u32],
    entry: impl Fn(u32) -> u64,
    face_of: impl Fn(usize) -> usize,
    sink: &mut impl Sink,
) -> Result<()> {
    let base = bucket_offsets[lows.start];
    let mut entries = Vec::new();
    for low in lows {
        let bucket = &mut corners
            [(bucket_offsets[low] - base) as usize..(bucket_offsets[low + 1] - base) as usize];
        read_entries(&mut entries, bucket, &entry)?;
        entries.sort_unstable();
        for (corner, &e) in bucket.iter_mut().zip(&entries) {
            *corner = e as u32;
        }
        bucket_edges(low as u32, &entries, &face_of, sink);
    }
    Ok(())
}

/// A bucket's entry for corner `c`: its edge's higher vertex, then the corner.
#[inline]
fn bucket_entry(indices: &[u32], next: impl Fn(usize) -> usize, c: u32) -> u64 {
    let c = c as usize;
    (u64::from(indices[c].max(indices[next(c)])) << 32) | c as u64
}

/// `blocks` zeroed counts of `vertex_count + 1` slots each.
fn per_block_counts(blocks: usize, vertex_count: usize, what: &str) -> Result<Vec<Vec<u32>>> {
    (0..blocks)
        .map(|_| zeroed(vertex_count + 1, what))
        .collect()
}

/// Turns each block's counts (vertex v's at v + 1) into the slot of the
/// block's first entry at v: after every entry at a lower vertex and every
/// earlier block's at v. Ranges of `vertices` are summed, then given their
/// slots, on rayon's threads.
fn first_slots(slots: &mut [Vec<u32>], vertices: usize) {
    let vertex_count = slots.first().map_or(0, |s| s.len() - 1);
    let ranges = vertex_count.div_ceil(vertices);
    let totals: Vec<u32> = (0..ranges)
        .into_par_iter()
        .map(|r| {
            let counts = 1 + r * vertices..1 + ((r + 1) * vertices).min(vertex_count);
            slots
                .iter()
                .map(|s| s[counts.clone()].iter().sum::<u32>())
                .sum()
        })
        .collect();
    let mut per_range: Vec<(u32, Vec<&mut [u32]>)> = Vec::with_capacity(ranges);
    let mut base = 0u32;
    for total in totals {
        per_range.push((base, Vec::with_capacity(slots.len())));
        base += total;
    }
    for block in slots.iter_mut() {
        for (r, part) in block[1..].chunks_mut(vertices).enumerate() {
            per_range[r].1.push(part);
        }
    }
    per_range
        .into_par_iter()
        .for_each(|(mut slot, mut blocks)| match &mut blocks[..] {
            [one] => {
                for count in one.iter_mut() {
                    (*count, slot) = (slot, slot + *count);
                }
            }
            [first, second] => {
                for (a, b) in first.iter_mut().zip(second.iter_mut()) {
                    (*a, *b, slot) = (slot, slot + *a, slot + *a + *b);
                }
            }
            _ => {
                for v in 0..blocks[0].len() {
                    for block in &mut blocks {
                        (block[v], slot) = (slot, slot + block[v]);
                    }
                }
            }
        });
}

/// The last block's slots, which its entries have moved to the offsets.
fn last(mut slots: Vec<Vec<u32>>) -> Vec<u32> {
    slots.pop().unwrap_or_default()
}

/// The same values as atomics, in place (the same layout: no copy).
fn atomic(values: Vec<u32>) -> Vec<AtomicU32> {
    values.into_iter().map(AtomicU32::new).collect()
}

/// The same values as plain integers, in place.
fn plain(values: Vec<AtomicU32>) -> Vec<u32> {
    values.into_iter().map(AtomicU32::into_inner).collect()
}

/// Replaces `entries` with the entries of the corners `bucket`, reserving
/// fallibly (a vertex of a large fan has a large bucket).
fn read_entries(entries: &mut Vec<u64>, bucket: &[u32], entry: impl Fn(u32) -> u64) -> Result<()> {
    if entries.capacity() < bucket.len() {
        *entries = try_vec(bucket.len().max(64), "edge buckets")?;
    }
    entries.clear();
    entries.extend(bucket.iter().map(|&c| entry(c)));
    Ok(())
}

/// Where a bucket's edges go, in order: counted, or written.
trait Sink {
    /// Takes the edge `pair` of the corners `corners`, ascending.
    fn edge(&mut self, pair: [u32; 2], corners: impl Iterator<Item = u32>);
}

/// Counts the edges.
struct Count(u32);

impl Sink for Count {
    #[inline]
    fn edge(&mut self, _: [u32; 2], _: impl Iterator<Item = u32>) {
        self.0 += 1;
    }
}

/// Marks the corners of the edges that have one corner.
struct MarkNaked<'a>(&'a [AtomicBool]);

impl Sink for MarkNaked<'_> {
    #[inline]
    fn edge(&mut self, _: [u32; 2], mut corners: impl Iterator<Item = u32>) {
        if let (Some(c), None) = (corners.next(), corners.next()) {
            self.0[c as usize].store(true, Relaxed);
        }
    }
}

/// Writes the edges of a range of vertices: its edges from its first edge
/// and their ends, its corners over its buckets, each corner's edge.
struct Write<'a> {
    edges: &'a mut [[u32; 2]],
    ends: &'a mut [u32],
    corners: &'a mut [u32],
    corner_edges: &'a [AtomicU32],
    first_edge: u32,
    first_slot: u32,
    /// The edge and the slot of the range written next.
    edge: usize,
    slot: usize,
}

impl Sink for Write<'_> {
    #[inline]
    fn edge(&mut self, pair: [u32; 2], corners: impl Iterator<Item = u32>) {
        let e = self.edge;
        self.edges[e] = pair;
        for corner in corners {
            self.corner_edges[corner as usize].store(self.first_edge + e as u32, Relaxed);
            self.corners[self.slot] = corner;
            self.slot += 1;
        }
        self.ends[e] = self.first_slot + self.slot as u32;
        self.edge += 1;
    }
}

/// The edges of the bucket of `low`, whose `entries` are ascending
/// (higher vertex << 32 | corner), into `sink` in order.
fn bucket_edges(low: u32, entries: &[u64], face_of: impl Fn(usize) -> usize, sink: &mut impl Sink) {
    let corner_of = |entry: u64| entry as u32;
    let high_of = |entry: u64| (entry >> 32) as u32;
    for run in entries.chunk_by(|x, y| high_of(*x) == high_of(*y)) {
        let pair = [low, high_of(run[0])];
        // Corners of one face are contiguous, so a face meeting the
        // pair again follows its earlier corner in the run.
        let again = |k: usize| {
            k > 0 && face_of(corner_of(run[k - 1]) as usize) == face_of(corner_of(run[k]) as usize)
        };
        let degenerate = pair[0] == pair[1];
        if !degenerate && (1..run.len()).all(|k| !again(k)) {
            sink.edge(pair, run.iter().map(|&x| corner_of(x)));
            continue;
        }
        // As OpenSubdiv builds edges from faces: every corner of a
        // degenerate edge, and every corner meeting the pair again in
        // its face, has an edge of its own; the other corners share
        // the first.
        if !degenerate {
            sink.edge(
                pair,
                (0..run.len())
                    .filter(|&k| !again(k))
                    .map(|k| corner_of(run[k])),
            );
        }
        for k in (0..run.len()).filter(|&k| degenerate || again(k)) {
            sink.edge(pair, std::iter::once(corner_of(run[k])));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::{Adjacency, Split};
    use crate::buffers::{prefix_sum, try_copy, try_vec, zeroed};
    use crate::error::Result;

    /// Builds the adjacency of polygons given as vertex lists.
    fn adjacency(vertex_count: usize, faces: &[&[u32]]) -> Adjacency {
        let indices: Vec<u32> = faces.iter().flat_map(|f| f.iter().copied()).collect();
        let mut face_of = Vec::new();
        let mut next = Vec::new();
        for (f, face) in faces.iter().enumerate() {
            let start = face_of.len();
            face_of.extend(std::iter::repeat_n(f, face.len()));
            next.extend((1..face.len()).map(|k| start + k));
            next.push(start);
        }
        Adjacency::build(vertex_count, &indices, |c| next[c], |c| face_of[c]).unwrap()
    }

    #[test]
    fn a_face_repeating_a_vertex_gets_edges_as_opensubdiv_gives_them() {
        // Face 0 meets {1, 4} three times and has a degenerate edge [2, 2];
        // face 1 runs 4 -> 1 again: it shares the pair's first edge.
        let a = adjacency(6, &[&[1, 2, 2, 5, 4, 1, 4], &[4, 1, 0]]);
        let edges_of = |pair: [u32; 2]| -> Vec<usize> {
            (0..a.edge_count())
                .filter(|&e| a.edges[e] == pair)
                .collect()
        };
        let pair = edges_of([1, 4]);
        assert_eq!(pair.len(), 3);
        // Face 0's corners 4 (4 -> 1), 5 (1 -> 4), 6 (4 -> 1), face 1's corner 7 (4 -> 1).
        assert_eq!(a.edge_corners(pair[0]), &[4, 7]);
        assert_eq!(a.edge_corners(pair[1]), &[5]);
        assert_eq!(a.edge_corners(pair[2]), &[6]);
        assert_eq!(edges_of([2, 2]).len(), 1);
        assert!(a.edges.windows(2).all(|w| w[0] <= w[1]));
        for c in 0..9 {
            assert!(a
                .edge_corners(a.corner_edges[c] as usize)
                .contains(&(c as u32)));
        }
        // Without repeats every pair has one edge.
        let plain = adjacency(4, &[&[0, 1, 2], &[2, 1, 3]]);
        assert_eq!(plain.edge_count(), 5);
    }
    /// The builder as it was written first, on one thread corner by corner:
    /// the expectation the parallel builder must meet bit for bit.
    fn serial_reference(
        vertex_count: usize,
        indices: &[u32],
        next: impl Fn(usize) -> usize,
        face_of: impl Fn(usize) -> usize,
    ) -> Result<Adjacency> {
        let corner_count = indices.len();
        let edge_ends = |c: usize| {
            let (a, b) = (indices[c], indices[next(c)]);
            (a.min(b), a.max(b))
        };
        let mut bucket_offsets = zeroed(vertex_count + 1, "edge buckets")?;
        for c in 0..corner_count {
            bucket_offsets[edge_ends(c).0 as usize + 1] += 1;
        }
        prefix_sum(&mut bucket_offsets);
        let mut fill = try_copy(&bucket_offsets, "edge buckets")?;
        let mut bucket: Vec<u64> = zeroed(corner_count, "edge buckets")?;
        for c in 0..corner_count {
            let (low, high) = edge_ends(c);
            let slot = &mut fill[low as usize];
            bucket[*slot as usize] = (u64::from(high) << 32) | c as u64;
            *slot += 1;
        }
        drop(fill);

        let mut edges = try_vec(corner_count, "edges")?;
        let mut edge_offsets = try_vec(corner_count + 1, "edge offsets")?;
        let mut edge_corners = try_vec(corner_count, "edge corners")?;
        let mut corner_edges = zeroed(corner_count, "corner edges")?;
        edge_offsets.push(0u32);
        let mut add_edge = |pair: [u32; 2], corners: &mut dyn Iterator<Item = u32>| {
            let e = edges.len() as u32;
            edges.push(pair);
            for corner in corners {
                corner_edges[corner as usize] = e;
                edge_corners.push(corner);
            }
            edge_offsets.push(edge_corners.len() as u32);
        };
        let corner_of = |entry: u64| entry as u32;
        let high_of = |entry: u64| (entry >> 32) as u32;
        for low in 0..vertex_count {
            let entries =
                &mut bucket[bucket_offsets[low] as usize..bucket_offsets[low + 1] as usize];
            entries.sort_unstable();
            for run in entries.chunk_by(|x, y| high_of(*x) == high_of(*y)) {
                let pair = [low as u32, high_of(run[0])];
                let again = |k: usize| {
                    k > 0
                        && face_of(corner_of(run[k - 1]) as usize)
                            == face_of(corner_of(run[k]) as usize)
                };
                let degenerate = pair[0] == pair[1];
                if !degenerate && (1..run.len()).all(|k| !again(k)) {
                    add_edge(pair, &mut run.iter().map(|&x| corner_of(x)));
                    continue;
                }
                if !degenerate {
                    add_edge(
                        pair,
                        &mut (0..run.len())
                            .filter(|&k| !again(k))
                            .map(|k| corner_of(run[k])),
                    );
                }
                for k in (0..run.len()).filter(|&k| degenerate || again(k)) {
                    add_edge(pair, &mut std::iter::once(corner_of(run[k])));
                }
            }
        }
        drop(bucket);
        edges.shrink_to_fit();
        edge_offsets.shrink_to_fit();

        let mut vertex_offsets = zeroed(vertex_count + 1, "vertex corners")?;
        for &v in indices {
            vertex_offsets[v as usize + 1] += 1;
        }
        prefix_sum(&mut vertex_offsets);
        let mut fill = try_copy(&vertex_offsets, "vertex corners")?;
        let mut vertex_corners = zeroed(corner_count, "vertex corners")?;
        for (c, &v) in indices.iter().enumerate() {
            vertex_corners[fill[v as usize] as usize] = c as u32;
            fill[v as usize] += 1;
        }
        Ok(Adjacency::from_parts(
            (edges, corner_edges),
            (edge_offsets, edge_corners),
            (vertex_offsets, vertex_corners),
        ))
    }

    /// A deterministic stream of pseudo-random numbers (xorshift).
    struct Rng(u64);

    impl Rng {
        fn below(&mut self, n: usize) -> usize {
            self.0 ^= self.0 << 13;
            self.0 ^= self.0 >> 7;
            self.0 ^= self.0 << 17;
            (self.0 % n as u64) as usize
        }
    }

    /// Polygons as one index list with each corner's next corner and face.
    struct Soup {
        vertex_count: usize,
        indices: Vec<u32>,
        next: Vec<usize>,
        face_of: Vec<usize>,
    }

    impl Soup {
        fn new(vertex_count: usize, faces: &[Vec<u32>]) -> Soup {
            let mut soup = Soup {
                vertex_count,
                indices: Vec::new(),
                next: Vec::new(),
                face_of: Vec::new(),
            };
            for (f, face) in faces.iter().enumerate() {
                let start = soup.indices.len();
                soup.indices.extend_from_slice(face);
                soup.face_of.extend(std::iter::repeat_n(f, face.len()));
                soup.next.extend((1..face.len()).map(|k| start + k));
                soup.next.push(start);
            }
            soup
        }

        fn parts(
            &self,
        ) -> (
            impl Fn(usize) -> usize + Sync + '_,
            impl Fn(usize) -> usize + Sync + '_,
        ) {
            (|c| self.next[c], |c| self.face_of[c])
        }

        /// Builds with the split chosen for the mesh, on pools of several
        /// sizes, and with splits much finer than any mesh gets, and checks
        /// every array against the serial reference.
        fn check(&self) {
            let (next, face_of) = self.parts();
            let expected =
                serial_reference(self.vertex_count, &self.indices, &next, &face_of).unwrap();
            let same = |a: &Adjacency, how: &str| {
                assert_eq!(a.edges, expected.edges, "edges, {how}");
                assert_eq!(a.corner_edges, expected.corner_edges, "corner edges, {how}");
                assert_eq!(a.edge_offsets, expected.edge_offsets, "edge offsets, {how}");
                assert_eq!(a.edge_corners, expected.edge_corners, "edge corners, {how}");
                assert_eq!(
                    a.vertex_offsets, expected.vertex_offsets,
                    "vertex offsets, {how}"
                );
                assert_eq!(
                    a.vertex_corners, expected.vertex_corners,
                    "vertex corners, {how}"
                );
            };
            for threads in [1, 2, 3, 8] {
                let pool = rayon::ThreadPoolBuilder::new()
                    .num_threads(threads)
                    .build()
                    .unwrap();
                let a = pool
                    .install(|| Adjacency::build(self.vertex_count, &self.indices, &next, &face_of))
                    .unwrap();
                same(&a, &format!("{threads} threads"));
                // The naked corners alone: those whose edge has one corner.
                let naked = pool
                    .install(|| {
                        Adjacency::naked_corners(self.vertex_count, &self.indices, &next, &face_of)
                    })
                    .unwrap();
                let expected_naked: Vec<bool> = (expected.corner_edges.iter())
                    .map(|&e| expected.edge_corners(e as usize).len() == 1)
                    .collect();
                assert_eq!(naked, expected_naked, "naked corners, {threads} threads");
            }
            for (blocks, shift) in [(1, 0), (2, 3), (5, 6), (13, 10), (64, 2)] {
                let split = Split { blocks, shift };
                let a = Adjacency::build_split(
                    self.vertex_count,
                    &self.indices,
                    &next,
                    &face_of,
                    split,
                    true,
                )
                .unwrap();
                same(&a, &format!("{split:?}"));
                // Edges only: the same edges, no vertex lists.
                let edges = Adjacency::build_split(
                    self.vertex_count,
                    &self.indices,
                    &next,
                    &face_of,
                    split,
                    false,
                )
                .unwrap();
                assert_eq!(edges.edges, expected.edges, "edges only, {split:?}");
                assert_eq!(edges.corner_edges, expected.corner_edges);
                assert_eq!(edges.edge_offsets, expected.edge_offsets);
                assert_eq!(edges.edge_corners, expected.edge_corners);
                assert!(edges.vertex_offsets.is_empty() && edges.vertex_corners.is_empty());
            }
        }
    }

    /// The quads of an `nx` by `ny` grid of vertices `id(i, j)`.
    fn grid(nx: u32, ny: u32, id: impl Fn(u32, u32) -> u32) -> Vec<Vec<u32>> {
        (0..ny)
            .flat_map(|j| (0..nx).map(move |i| (i, j)))
            .map(|(i, j)| vec![id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)])
            .collect()
    }

    #[test]
    fn a_large_quad_grid_matches_the_serial_builder() {
        let (nx, ny) = (420, 310);
        let faces = grid(nx, ny, |i, j| j * (nx + 1) + i);
        assert!(faces.len() * 4 > 6 * super::PARALLEL_CORNERS);
        Soup::new(((nx + 1) * (ny + 1)) as usize, &faces).check();
        // Too small to split: one block on the calling thread.
        Soup::new(11 * 11, &grid(10, 10, |i, j| j * 11 + i)).check();
        Soup::new(0, &[]).check();
    }

    #[test]
    fn shuffled_vertex_numbers_and_isolated_vertices_match_the_serial_builder() {
        let (nx, ny) = (300, 280);
        let count = ((nx + 1) * (ny + 1)) as usize;
        // Spread over three times as many vertices, two of every three unused.
        let mut numbers: Vec<u32> = (0..3 * count as u32).collect();
        let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
        for k in (1..numbers.len()).rev() {
            numbers.swap(k, rng.below(k + 1));
        }
        let faces = grid(nx, ny, |i, j| numbers[(j * (nx + 1) + i) as usize]);
        Soup::new(3 * count, &faces).check();
        // Isolated vertices at both ends and between, numbering in order.
        let faces = grid(nx, ny, |i, j| 1000 + 3 * (j * (nx + 1) + i));
        Soup::new(1000 + 3 * count + 5000, &faces).check();
    }

    #[test]
    fn mixed_face_sizes_and_non_manifold_edges_match_the_serial_builder() {
        let mut rng = Rng(0x2545_f491_4f6c_dd1d);
        // A strip of polygons of 3 to 8 corners over a ring of vertices, each
        // sharing its first edge with the one before: most edges have two
        // faces, some three or more where polygons overlap.
        let vertex_count = 60_000;
        let mut faces = Vec::new();
        let mut at = 0usize;
        while faces.len() < 90_000 {
            let size = 3 + rng.below(6);
            let face: Vec<u32> = (0..size)
                .map(|k| ((at + k) % vertex_count) as u32)
                .collect();
            faces.push(face);
            at += 1 + rng.below(size - 1);
        }
        // Books of pages on one edge, fans round one vertex, both larger
        // than the first scratch of a bucket, and fins on many edges.
        for page in 0..200 {
            faces.push(vec![7, 8, 20_000 + page]);
        }
        for k in 0..500 {
            faces.push(vec![30_000, 40_000 + k, 40_001 + k]);
        }
        for k in 0..5000u32 {
            let v = rng.below(vertex_count - 1) as u32;
            faces.push(vec![v, v + 1, (v + 2 + k) % vertex_count as u32]);
        }
        Soup::new(vertex_count, &faces).check();
    }

    #[test]
    fn faces_repeating_vertices_match_the_serial_builder() {
        let mut rng = Rng(0xd1b5_4a32_d192_ed03);
        let vertex_count = 20_000;
        let mut faces = Vec::new();
        // The pattern of the test above, tiled over the vertices.
        for base in (0..vertex_count as u32 - 6).step_by(5) {
            faces.push([1, 2, 2, 5, 4, 1, 4].map(|v| base + v).to_vec());
            faces.push([4, 1, 0].map(|v| base + v).to_vec());
        }
        // Polygons drawn from a few nearby vertices, so that they repeat
        // vertices, in a row and apart, and meet pairs several times.
        for _ in 0..60_000 {
            let base = rng.below(vertex_count - 8) as u32;
            let size = 3 + rng.below(7);
            faces.push((0..size).map(|_| base + rng.below(5) as u32).collect());
        }
        // A face of one vertex repeated, and pairs met many times in one face.
        faces.push(vec![77; 9]);
        faces.push([5, 6].repeat(40));
        Soup::new(vertex_count, &faces).check();
    }
}
