//! Laplacian smoothing with a blend factor.

use glam::DVec3;

use crate::error::Result;
use crate::mesh::Mesh;

use crate::toolbar::split::moved;

use super::{check_iterations, check_unit, NakedEdges, Neighbours};

/// Moves every vertex `blend` of the way towards the average of its
/// neighbours, `iterations` times (Weaverbird's Laplacian Smoothing; `blend`
/// is its Thin factor: 1 jumps to the average, 0 does nothing). All
/// vertices move at once from the previous iteration's positions. The
/// surface shrinks as it smooths; [`super::laplacian_hc`] does not.
///
/// # Errors
/// [`crate::Error::InvalidArgument`] when `blend` is outside [0, 1] or
/// `iterations` passes [`super::MAX_ITERATIONS`];
/// [`crate::Error::DegenerateInput`] naming a vertex whose average overflows
/// `f64` (coordinates near `f64::MAX`).
pub fn laplacian(mesh: &Mesh, iterations: u32, blend: f64, naked: NakedEdges) -> Result<Mesh> {
    check_iterations(iterations)?;
    check_unit("blend", blend)?;
    let neighbours = Neighbours::new(mesh, naked)?;
    let mut current = mesh.positions().to_vec();
    let mut next = current.clone();
    for _ in 0..iterations {
        for (v, p) in next.iter_mut().enumerate() {
            let around = neighbours.of(v);
            if around.is_empty() {
                continue;
            }
            let average =
                around.iter().map(|&j| current[j as usize]).sum::<DVec3>() / around.len() as f64;
            *p = current[v] + (average - current[v]) * blend;
        }
        std::mem::swap(&mut current, &mut next);
    }
    moved(mesh, current, "Laplacian smoothing")
}
