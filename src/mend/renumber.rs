//! The renumbering that follows a weld, on all threads, giving the numbers
//! one pass in order gives: clusters numbered in order of their first
//! vertex, faces rewritten over clusters (a cluster a face names twice kept
//! once, faces left with fewer than three corners dropped), and clusters no
//! face uses left out.

use std::sync::atomic::{AtomicBool, AtomicU32, Ordering::Relaxed};

use glam::DVec3;
use rayon::prelude::*;

use crate::buffers::{fill_by_offsets, par_offsets, try_vec, CHUNK};
use crate::error::Result;
use crate::mesh::Mesh;

/// Rewrites each vertex's cluster root into its cluster's number, the
/// clusters numbered in order of their first (lowest) vertex, and returns
/// each cluster's first vertex.
pub(crate) fn number_clusters(cluster_of: &mut [u32]) -> Result<Vec<u32>> {
    let n = cluster_of.len();
    let mut first = try_vec(n, "the weld clusters")?;
    first.par_extend(
        (0..n)
            .into_par_iter()
            .with_min_len(CHUNK)
            .map(|_| AtomicU32::new(u32::MAX)),
    );
    cluster_of
        .par_iter()
        .enumerate()
        .with_min_len(CHUNK)
        .for_each(|(v, &root)| {
            first[root as usize].fetch_min(v as u32, Relaxed);
        });
    // before[v]: how many clusters start before vertex v.
    let before = par_offsets(n, "the weld clusters", |v| {
        u32::from(first[cluster_of[v] as usize].load(Relaxed) == v as u32)
    })?;
    let starts = |v: usize| before[v + 1] > before[v];
    // Each root's number, written once by its cluster's first vertex.
    (0..n)
        .into_par_iter()
        .with_min_len(CHUNK)
        .filter(|&v| starts(v))
        .for_each(|v| first[cluster_of[v] as usize].store(before[v], Relaxed));
    cluster_of
        .par_iter_mut()
        .with_min_len(CHUNK)
        .for_each(|c| *c = first[*c as usize].load(Relaxed));
    let mut first_vertex = try_vec(before[n] as usize, "the weld clusters")?;
    first_vertex.par_extend(
        (0..n as u32)
            .into_par_iter()
            .with_min_len(CHUNK)
            .filter(|&v| starts(v as usize)),
    );
    Ok(first_vertex)
}

/// The faces of `mesh` over clusters: each face's clusters in corner order,
/// each once, and faces of fewer than three dropped. Returns the sizes, the
/// indices and how many faces were dropped.
pub(crate) fn faces_over_clusters(
    mesh: &Mesh,
    cluster_of: &[u32],
) -> Result<(Vec<u32>, Vec<u32>, usize)> {
    let face_count = mesh.face_count();
    let kept = |f: usize| {
        let mut count = 0;
        for_each_kept(mesh.face(f), cluster_of, |_| count += 1);
        if count < 3 {
            0
        } else {
            count
        }
    };
    let offsets = par_offsets(face_count, "the welded face offsets", kept)?;
    let face_indices = fill_by_offsets(&offsets, "the welded face indices", |f, out| {
        if !out.is_empty() {
            let mut slots = out.iter_mut();
            for_each_kept(mesh.face(f), cluster_of, |c| {
                if let Some(slot) = slots.next() {
                    *slot = c;
                }
            });
        }
    })?;
    let mut face_sizes = try_vec(face_count, "the welded face sizes")?;
    face_sizes.par_extend(
        (0..face_count)
            .into_par_iter()
            .with_min_len(CHUNK)
            .filter_map(|f| Some(offsets[f + 1] - offsets[f]).filter(|&size| size > 0)),
    );
    let removed = face_count - face_sizes.len();
    Ok((face_sizes, face_indices, removed))
}

/// Calls `keep` with the cluster of each corner of `face` whose cluster no
/// earlier corner has, in corner order.
fn for_each_kept(face: &[u32], cluster_of: &[u32], mut keep: impl FnMut(u32)) {
    let cluster = |i: usize| cluster_of[face[i] as usize];
    if face.len() <= 16 {
        for i in 0..face.len() {
            let c = cluster(i);
            if (0..i).all(|j| cluster(j) != c) {
                keep(c);
            }
        }
        return;
    }
    // Large n-gons: sorted by cluster, then corner, the first of each run
    // is the corner that keeps it.
    let mut order: Vec<(u32, usize)> = (0..face.len()).map(|i| (cluster(i), i)).collect();
    order.sort_unstable();
    let mut first = vec![false; face.len()];
    for (k, &(c, i)) in order.iter().enumerate() {
        if k == 0 || order[k - 1].0 != c {
            first[i] = true;
        }
    }
    for (i, _) in first.iter().enumerate().filter(|(_, &f)| f) {
        keep(cluster(i));
    }
}

/// The positions of the clusters the faces use (each its first vertex's),
/// in cluster order, with the faces renumbered over them; returns the
/// positions and how many clusters no face uses.
pub(crate) fn used_clusters(
    positions: &[DVec3],
    first_vertex: &[u32],
    face_indices: &mut [u32],
) -> Result<(Vec<DVec3>, usize)> {
    let cluster_count = first_vertex.len();
    let mut used = try_vec(cluster_count, "the welded vertex numbers")?;
    used.par_extend(
        (0..cluster_count)
            .into_par_iter()
            .with_min_len(CHUNK)
            .map(|_| AtomicBool::new(false)),
    );
    face_indices
        .par_iter()
        .with_min_len(CHUNK)
        .for_each(|&c| used[c as usize].store(true, Relaxed));
    let new_index = par_offsets(cluster_count, "the welded vertex numbers", |c| {
        u32::from(used[c].load(Relaxed))
    })?;
    let kept = new_index[cluster_count] as usize;
    let mut out_positions = try_vec(kept, "the welded positions")?;
    out_positions.par_extend(
        (0..cluster_count)
            .into_par_iter()
            .with_min_len(CHUNK)
            .filter(|&c| used[c].load(Relaxed))
            .map(|c| positions[first_vertex[c] as usize]),
    );
    if kept < cluster_count {
        face_indices
            .par_iter_mut()
            .with_min_len(CHUNK)
            .for_each(|c| *c = new_index[*c as usize]);
    }
    Ok((out_positions, cluster_count - kept))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::shapes;

    /// What a renumbering gives: the cluster of each vertex, the first
    /// vertices, the sizes and indices, the faces removed, the positions and
    /// the clusters unused.
    type Renumbered = (
        Vec<u32>,
        Vec<u32>,
        Vec<u32>,
        Vec<u32>,
        usize,
        Vec<DVec3>,
        usize,
    );

    /// The renumbering one pass in order gives.
    fn in_order(mesh: &Mesh, roots: &[u32]) -> Renumbered {
        let mut label = vec![u32::MAX; roots.len()];
        let mut first_vertex = Vec::new();
        let cluster_of: Vec<u32> = (0..roots.len())
            .map(|v| {
                let root = roots[v] as usize;
                if label[root] == u32::MAX {
                    label[root] = first_vertex.len() as u32;
                    first_vertex.push(v as u32);
                }
                label[root]
            })
            .collect();
        let (mut sizes, mut indices, mut removed) = (Vec::new(), Vec::new(), 0);
        for face in mesh.faces() {
            let start = indices.len();
            for &v in face {
                let c = cluster_of[v as usize];
                if !indices[start..].contains(&c) {
                    indices.push(c);
                }
            }
            if indices.len() - start < 3 {
                indices.truncate(start);
                removed += 1;
            } else {
                sizes.push((indices.len() - start) as u32);
            }
        }
        let mut new_index = vec![u32::MAX; first_vertex.len()];
        indices.iter().for_each(|&c| new_index[c as usize] = 0);
        let mut positions = Vec::new();
        for (c, slot) in new_index.iter_mut().enumerate() {
            if *slot == 0 {
                *slot = positions.len() as u32;
                positions.push(mesh.positions()[first_vertex[c] as usize]);
            }
        }
        indices.iter_mut().for_each(|c| *c = new_index[*c as usize]);
        let unused = first_vertex.len() - positions.len();
        (
            cluster_of,
            first_vertex,
            sizes,
            indices,
            removed,
            positions,
            unused,
        )
    }

    fn renumbered(mesh: &Mesh, roots: &[u32]) -> Renumbered {
        let mut cluster_of = roots.to_vec();
        let first_vertex = number_clusters(&mut cluster_of).unwrap();
        let (sizes, mut indices, removed) = faces_over_clusters(mesh, &cluster_of).unwrap();
        let (positions, unused) =
            used_clusters(mesh.positions(), &first_vertex, &mut indices).unwrap();
        (
            cluster_of,
            first_vertex,
            sizes,
            indices,
            removed,
            positions,
            unused,
        )
    }

    /// Roots as a union-find leaves them: any member of the cluster, here
    /// the vertex `step` places on, so that clusters span parallel blocks.
    fn roots(vertex_count: usize, step: usize, joined: impl Fn(usize) -> bool) -> Vec<u32> {
        (0..vertex_count)
            .map(|v| {
                if joined(v) {
                    ((v / step * step + step / 2).min(vertex_count - 1)) as u32
                } else {
                    v as u32
                }
            })
            .collect()
    }

    #[test]
    fn parallel_renumbering_equals_one_pass_in_order() {
        let quads = shapes::torus(300, 300);
        let n = quads.vertex_count();
        let polygons = shapes::mixed_polygons();
        // A large n-gon that names some clusters twice.
        let ring: Vec<DVec3> = (0..40)
            .map(|i| DVec3::new((i as f64).cos(), (i as f64).sin(), 0.0))
            .collect();
        let ngon = Mesh::from_polygons(ring, [(0..40u32).collect::<Vec<_>>()]).unwrap();
        let cases = [
            (&quads, roots(n, 1, |_| false)),
            // Neighbours merge in runs of 3: faces lose corners, some collapse.
            (&quads, roots(n, 3, |v| v % 7 != 0)),
            // Clusters 5000 vertices wide, their roots far from their first vertex.
            (&quads, roots(n, 5000, |v| v % 2 == 0)),
            // Everything one cluster: every face collapses, nothing is used.
            (&quads, vec![(n / 2) as u32; n]),
            (&polygons, roots(polygons.vertex_count(), 2, |v| v > 2)),
            (&ngon, roots(40, 4, |v| v % 3 == 1)),
        ];
        let (mut removed, mut unused, mut shortened) = (0, 0, 0);
        for (mesh, roots) in cases {
            let expected = in_order(mesh, &roots);
            removed += expected.4;
            unused += expected.6;
            shortened += expected.2.iter().filter(|&&size| size == 3).count();
            assert_eq!(renumbered(mesh, &roots), expected);
        }
        // The cases reach every path: dropped faces, unused clusters, faces that lost corners.
        assert!(removed > 0 && unused > 0 && shortened > 0);
    }
}
