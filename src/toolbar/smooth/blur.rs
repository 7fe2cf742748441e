//! Blur: smoothing of per-vertex values (colours, weights) over the mesh.

use crate::buffers::try_vec;
use crate::error::{Error, Result};
use crate::mesh::Mesh;

use super::{check_iterations, check_unit, NakedEdges, Neighbours};

/// The checks of [`blur`] that need no value, with the values' count alone
/// (the C ABI makes them before it views the caller's buffer).
pub(crate) fn check_blur_arguments(
    mesh: &Mesh,
    value_count: usize,
    components: usize,
    iterations: u32,
    blend: f64,
) -> Result<()> {
    check_iterations(iterations)?;
    check_unit("blend", blend)?;
    if components == 0 {
        return Err(Error::InvalidArgument(
            "components is 0; each vertex needs at least one value".into(),
        ));
    }
    let expected = mesh.vertex_count().checked_mul(components);
    if expected != Some(value_count) {
        return Err(Error::InvalidArgument(format!(
            "{value_count} values were given but the mesh's {} vertices with {components} components need {}",
            mesh.vertex_count(),
            mesh.vertex_count() as u128 * components as u128
        )));
    }
    Ok(())
}

/// Blurs a per-vertex value over the mesh, as Weaverbird's Blur does with
/// vertex colours: each iteration moves every vertex's value `blend` of the
/// way towards the average of its neighbours' values. The positions do not
/// change. `values` holds `components` numbers per vertex, vertex after
/// vertex (3 or 4 for a colour, 1 for a scalar field); `naked` decides, as
/// for positions, which neighbours a boundary vertex listens to (with
/// `Fixed`, boundary values stay).
///
/// Returns the blurred values in the same layout.
///
/// # Errors
/// [`Error::InvalidArgument`] when `components` is 0, when `values` does
/// not hold `components` numbers per vertex (naming both counts), when a
/// value is not finite, when `blend` is outside [0, 1] or `iterations`
/// passes [`super::MAX_ITERATIONS`]; [`Error::OutOfMemory`].
pub fn blur(
    mesh: &Mesh,
    values: &[f64],
    components: usize,
    iterations: u32,
    blend: f64,
    naked: NakedEdges,
) -> Result<Vec<f64>> {
    check_blur_arguments(mesh, values.len(), components, iterations, blend)?;
    if let Some(i) = values.iter().position(|x| !x.is_finite()) {
        return Err(Error::InvalidArgument(format!(
            "value {i} (vertex {}) is not finite",
            i / components
        )));
    }
    let neighbours = Neighbours::new(mesh, naked)?;
    let mut current = try_vec::<f64>(values.len(), "blurred values")?;
    current.extend_from_slice(values);
    let mut next = try_vec::<f64>(values.len(), "blurred values")?;
    next.extend_from_slice(values);
    for _ in 0..iterations {
        for v in 0..mesh.vertex_count() {
            let around = neighbours.of(v);
            if around.is_empty() {
                continue;
            }
            for k in 0..components {
                let sum: f64 = around
                    .iter()
                    .map(|&j| current[j as usize * components + k])
                    .sum();
                let own = current[v * components + k];
                next[v * components + k] = own + (sum / around.len() as f64 - own) * blend;
            }
        }
        std::mem::swap(&mut current, &mut next);
    }
    Ok(current)
}
