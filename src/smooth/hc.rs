//! The HC algorithm: Laplacian smoothing that pushes back to keep volume.

use glam::DVec3;

use crate::error::Result;
use crate::mesh::Mesh;

use crate::split::moved;

use super::{check_iterations, check_unit, NakedEdges, Neighbours};

/// Smooths with the HC ("Humphrey's Classes") algorithm of J. Vollmer,
/// R. Mann and H. Müller, "Improved Laplacian Smoothing of Noisy Surface
/// Meshes", Computer Graphics Forum 18(3), 1999, as published: each
/// iteration first takes every vertex to the average `p` of its neighbours,
/// records how far it went, `b = p − (α·o + (1 − α)·q)` (`o` the original
/// position, `q` the position before this iteration), then pushes every
/// vertex back by `β·b + (1 − β)·mean(b of its neighbours)`.
///
/// - `alpha` (α, Weaverbird's partial-original input) in [0, 1]: how much
///   the push-back aims at the original points rather than the previous
///   iteration's; 0 is the paper's usual choice.
/// - `beta` (β) in [0, 1]: how much of a vertex's own displacement, rather
///   than its neighbours', is undone; the paper recommends a value above
///   0.5 (0.5–0.6 works well).
///
/// The shrinking of plain Laplacian smoothing is largely cancelled, so the
/// volume of a closed mesh is kept much better. Weaverbird's orientation
/// and per-vertex activation inputs have no counterpart here: pinned
/// vertices come from `naked` only.
///
/// # Errors
/// [`crate::Error::InvalidArgument`] when `alpha` or `beta` is outside
/// [0, 1] or `iterations` passes [`super::MAX_ITERATIONS`];
/// [`crate::Error::DegenerateInput`] naming a vertex whose update overflows
/// `f64` (coordinates near `f64::MAX`).
pub fn laplacian_hc(
    mesh: &Mesh,
    iterations: u32,
    alpha: f64,
    beta: f64,
    naked: NakedEdges,
) -> Result<Mesh> {
    check_iterations(iterations)?;
    check_unit("alpha", alpha)?;
    check_unit("beta", beta)?;
    let neighbours = Neighbours::new(mesh, naked);
    let original = mesh.positions();
    let mut p = original.to_vec();
    let mut q = p.clone();
    let mut b = vec![DVec3::ZERO; p.len()];
    for _ in 0..iterations {
        q.copy_from_slice(&p);
        for v in 0..p.len() {
            let around = neighbours.of(v);
            if !around.is_empty() {
                p[v] = around.iter().map(|&j| q[j as usize]).sum::<DVec3>() / around.len() as f64;
            }
            b[v] = p[v] - (original[v] * alpha + q[v] * (1.0 - alpha));
        }
        for v in 0..p.len() {
            let around = neighbours.of(v);
            if around.is_empty() {
                continue;
            }
            let mean = around.iter().map(|&j| b[j as usize]).sum::<DVec3>() / around.len() as f64;
            p[v] -= b[v] * beta + mean * (1.0 - beta);
        }
    }
    moved(mesh, p, "HC smoothing")
}
