//! Exact copies of a position that lie near each other in the vertex order.
//!
//! A triangle soup (an STL file's, a mesh whose faces each have corners of
//! their own) holds every position about six times, and the copies of a
//! position come from neighbouring faces, so from nearby places in the
//! vertex order. Merging them piece by piece, each piece of the vertices
//! through a hash table in the cache, leaves the weld's sort and cells a
//! sixth of the vertices to handle. Copies in different pieces stay apart
//! here and meet again as exact duplicates in the weld's cells.

use glam::DVec3;
use rayon::prelude::*;

use crate::buffers::{fresh_zeroed, prefix_sum, split_by_offsets};
use crate::error::Result;

use super::mix_words;

/// Vertices in a piece: 6 MB of positions and a 2 MB table, in the cache.
pub(crate) const PIECE: usize = 1 << 18;

/// Vertices of the sample that decides whether to merge copies first: a
/// few rows of a soup's faces, cheap beside a weld that gains nothing.
pub(crate) const SAMPLE: usize = 1 << 14;

/// The vertices' distinct positions, piece by piece.
pub(crate) struct Copies {
    /// Each vertex's site: where the first copy of its position in its
    /// piece is in `sites`.
    pub(crate) site_of: Vec<u32>,
    /// The first copy of each position in each piece, in vertex order.
    pub(crate) sites: Vec<DVec3>,
}

/// The copies in `positions`, pieces of `piece` vertices each, or `None`
/// when there is only one piece or a sample from the front shows the
/// copies not worth merging first (fewer than a quarter of its vertices
/// are copies: an indexed mesh's vertices, or a soup whose faces are in no
/// spatial order).
pub(crate) fn nearby_copies(positions: &[DVec3], piece: usize) -> Result<Option<Copies>> {
    let piece = piece.max(1);
    if positions.len() <= piece || !worth_merging(&positions[..piece.min(SAMPLE)]) {
        return Ok(None);
    }
    // Fresh pages, faulted in where the pieces write them, on all threads.
    let mut site_of = fresh_zeroed::<u32>(positions.len(), "the weld's copies")?;
    let mut counts = vec![0u32];
    counts.par_extend(
        positions
            .par_chunks(piece)
            .zip(site_of.par_chunks_mut(piece))
            .map_init(Vec::new, |table, (positions, site_of)| {
                piece_sites(positions, site_of, table)
            }),
    );
    prefix_sum(&mut counts);
    let site_count = *counts.last().unwrap_or(&0) as usize;
    let mut sites = fresh_zeroed::<DVec3>(site_count, "the weld's sites")?;
    // Each piece's sites into its part of `sites`, and its vertices' sites
    // numbered among all pieces'.
    split_by_offsets(&mut sites, &counts, 1)
        .into_par_iter()
        .zip(positions.par_chunks(piece))
        .zip(site_of.par_chunks_mut(piece))
        .for_each(|(((pieces, sites), positions), site_of)| {
            let offset = counts[pieces.start];
            let mut next = 0;
            for (p, site) in positions.iter().zip(site_of) {
                if *site == next {
                    sites[next as usize] = *p;
                    next += 1;
                }
                *site += offset;
            }
        });
    Ok(Some(Copies { site_of, sites }))
}

/// Whether the copies in `sample`, the first vertices of a mesh, are worth
/// merging before the cells: at least a quarter of them are copies.
pub(crate) fn worth_merging(sample: &[DVec3]) -> bool {
    let sample = &sample[..sample.len().min(SAMPLE)];
    let sample_sites = piece_sites(sample, &mut vec![0; sample.len()], &mut Vec::new());
    sample_sites as usize * 4 <= sample.len() * 3
}

/// Corners a piece of [`append_triangle_sites`] holds: 2^16 whole
/// triangles (three quarters of [`PIECE`] corners), so that a reader's
/// block of 2^18 triangles is four pieces, as many for each of two or
/// four threads.
const TRIANGLE_PIECE: usize = 3 << 16;

/// Appends the sites of `corners` (three a triangle) to `sites`, and each
/// corner's site to `corner_sites`, as [`nearby_copies`] numbers them
/// piece by piece, but for one thing: a triangle never names a site twice.
/// A corner that is a copy of another corner of its own triangle gets a
/// site of its own after its piece's, so the triangle stays a face of
/// three distinct vertices and the weld that follows finds the copy and
/// drops the face, as it would in the soup. Every site is the first copy
/// of its position in its piece or such a corner, so each cluster the weld
/// finds starts at the site of its first corner, and the clusters and
/// their order are those of the soup.
///
/// # Errors
/// [`crate::Error::OutOfMemory`].
pub(crate) fn append_triangle_sites(
    corners: &[DVec3],
    sites: &mut Vec<DVec3>,
    corner_sites: &mut Vec<u32>,
) -> Result<()> {
    let start = corner_sites.len();
    let grow = |what: &str, needed: usize| {
        crate::error::Error::OutOfMemory(format!("could not reserve {needed} more {what}"))
    };
    corner_sites
        .try_reserve(corners.len())
        .map_err(|_| grow("corners for the read's copies", corners.len()))?;
    corner_sites.resize(start + corners.len(), 0);
    let pieces = corner_sites[start..].par_chunks_mut(TRIANGLE_PIECE);
    let mut counts = vec![0u32];
    counts.par_extend(corners.par_chunks(TRIANGLE_PIECE).zip(pieces).map_init(
        Vec::new,
        |table, (corners, site_of)| {
            let count = piece_sites(corners, site_of, table);
            own_sites_for_triangle_copies(site_of, count)
        },
    ));
    prefix_sum(&mut counts);
    let base = sites.len();
    let added = *counts.last().unwrap_or(&0) as usize;
    sites
        .try_reserve(added)
        .map_err(|_| grow("positions for the read's copies", added))?;
    sites.resize(base + added, DVec3::ZERO);
    let base = base as u32;
    split_by_offsets(&mut sites[base as usize..], &counts, 1)
        .into_par_iter()
        .zip(corners.par_chunks(TRIANGLE_PIECE))
        .zip(corner_sites[start..].par_chunks_mut(TRIANGLE_PIECE))
        .for_each(|(((pieces, sites), corners), site_of)| {
            let offset = base + counts[pieces.start];
            let mut next = 0;
            for (p, site) in corners.iter().zip(site_of) {
                // First copies come in order, a later copy below them; a
                // triangle's own copies, numbered after every first copy
                // and in order too, are never below.
                if *site >= next {
                    sites[*site as usize] = *p;
                }
                next += u32::from(*site == next);
                *site += offset;
            }
        });
    Ok(())
}

/// Gives each corner that repeats a site of its own triangle (three
/// corners in a row) a new site after the piece's `count`; returns the
/// piece's count with them.
fn own_sites_for_triangle_copies(site_of: &mut [u32], mut count: u32) -> u32 {
    for triangle in site_of.chunks_exact_mut(3) {
        for k in 1..3 {
            if triangle[..k].contains(&triangle[k]) {
                triangle[k] = count;
                count += 1;
            }
        }
    }
    count
}

/// Numbers the distinct positions of one piece in order of their first
/// copy, writing each vertex's number into `site_of`; returns how many.
/// Positions are one when they compare equal (-0 and +0 are one, a NaN is
/// a position of its own), as in the weld's cells. A position whose probe
/// runs past [`MAX_PROBES`] slots (only positions made to share their hash
/// get there) is a site of its own, and its copies meet it in the cells.
fn piece_sites(positions: &[DVec3], site_of: &mut [u32], table: &mut Vec<u32>) -> u32 {
    const EMPTY: u32 = u32::MAX;
    // At most half full, so a probe ends within a few slots.
    let bits = (2 * positions.len()).next_power_of_two().trailing_zeros();
    table.clear();
    table.resize(1 << bits, EMPTY);
    let mask = (1 << bits) - 1;
    let mut count = 0;
    for (v, &p) in positions.iter().enumerate() {
        let mut slot = slot_of(p, bits);
        let mut copy_of = None;
        for _ in 0..MAX_PROBES {
            let there = table[slot];
            if there == EMPTY {
                table[slot] = v as u32;
                break;
            }
            if positions[there as usize] == p {
                copy_of = Some(there);
                break;
            }
            slot = (slot + 1) & mask;
        }
        site_of[v] = match copy_of {
            Some(there) => site_of[there as usize],
            None => {
                count += 1;
                count - 1
            }
        };
    }
    count
}

/// The longest probe of [`piece_sites`]: it keeps a file crafted so that
/// its positions share one hash from making the weld quadratic.
const MAX_PROBES: usize = 64;

/// Where a position starts its probe in a table of `2^bits` slots.
#[inline]
fn slot_of(p: DVec3, bits: u32) -> usize {
    // Adding 0 makes -0 and +0 one key: they are one position.
    let h = mix_words((p + 0.0).to_array().map(f64::to_bits));
    ((h ^ (h >> 32)).wrapping_mul(0x9E37_79B9_7F4A_7C15) >> (64 - bits)) as usize
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn copies_in_a_piece_share_its_first_copy_and_pieces_keep_their_own() {
        let p = |x: f64| DVec3::new(x, 1.0, 2.0);
        let positions = [
            p(0.0),
            p(1.0),
            p(-0.0),
            p(1.0),
            // Second piece: a copy of the first piece's position, f64::NAN twice.
            p(1.0),
            p(f64::NAN),
            p(f64::NAN),
            p(1.0),
        ];
        let copies = nearby_copies(&positions, 4).unwrap().unwrap();
        assert_eq!(copies.site_of, [0, 1, 0, 1, 2, 3, 4, 2]);
        let sites = copies.sites;
        assert_eq!(sites.len(), 5);
        assert_eq!((sites[0], sites[1], sites[2]), (p(0.0), p(1.0), p(1.0)));
        assert!(sites[3].x.is_nan() && sites[4].x.is_nan());
    }

    #[test]
    fn positions_that_share_one_hash_are_sites_of_their_own_past_the_longest_probe() {
        // Distinct positions whose hashes are all equal, each twice in a
        // row: the first MAX_PROBES fill the probe, and the rest, and
        // their copies, cannot find one another.
        let k1: u64 = 0x9E37_79B9_7F4A_7C15;
        let k2_inverse = (0..6).fold(1u64, |inverse: u64, _| {
            inverse.wrapping_mul(2u64.wrapping_sub(0xC2B2_AE3D_27D4_EB4Fu64.wrapping_mul(inverse)))
        });
        let colliding: Vec<DVec3> = (1..)
            .map(|i| {
                let x = f64::from(i);
                let y = f64::from_bits((x.to_bits().wrapping_mul(k1)).wrapping_mul(k2_inverse));
                DVec3::new(x, y, 0.0)
            })
            .filter(|p| p.y.is_finite() && p.y != 0.0)
            .take(2 * MAX_PROBES)
            .collect();
        let bits = 10;
        assert!(colliding
            .iter()
            .all(|&p| slot_of(p, bits) == slot_of(colliding[0], bits)));
        let positions: Vec<DVec3> = colliding.iter().flat_map(|&p| [p, p]).collect();
        let mut site_of = vec![0; positions.len()];
        let sites = piece_sites(&positions, &mut site_of, &mut Vec::new());
        // The first MAX_PROBES positions are found again by their copies.
        for i in 0..MAX_PROBES {
            assert_eq!(site_of[2 * i], site_of[2 * i + 1]);
        }
        // Past the probe, every vertex is a site.
        assert_eq!(sites as usize, MAX_PROBES + 2 * MAX_PROBES);
        assert!(site_of.windows(2).all(|w| w[1] >= w[0] && w[1] <= w[0] + 1));
        // And the weld's clusters are those of the vertices one by one.
        let (plain, count) = super::super::vertex_clusters(&positions, 0.0)
            .unwrap()
            .into_labels();
        let pieces = super::super::Clusters::with_pieces(&positions, 0.0, 64).unwrap();
        assert_eq!((pieces.cluster_of, pieces.count), (plain, count));
        assert_eq!(count, 2 * MAX_PROBES);
    }

    #[test]
    fn a_first_piece_of_few_copies_or_a_single_piece_leaves_the_vertices_alone() {
        let distinct: Vec<DVec3> = (0..16).map(|i| DVec3::splat(i as f64)).collect();
        assert!(nearby_copies(&distinct, 8).unwrap().is_none());
        let repeated = vec![DVec3::ONE; 8];
        assert!(nearby_copies(&repeated, 8).unwrap().is_none());
        assert!(nearby_copies(&repeated, 4).unwrap().is_some());
    }
}
