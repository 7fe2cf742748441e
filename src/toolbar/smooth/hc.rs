//! The HC algorithm: Laplacian smoothing that pushes back to keep volume.

use glam::DVec3;

use crate::error::{Error, Result};
use crate::mesh::analysis::vertex_normals;
use crate::mesh::Mesh;

use crate::toolbar::split::moved;

use super::{check_iterations, check_unit, NakedEdges, Neighbours};

/// Which way a vertex may move while smoothing (Weaverbird's orientation
/// input of LaplacianHC, whose meaning it does not document; this is the
/// reading Weft gives it).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum SmoothDirection {
    /// Anywhere: the published algorithm.
    #[default]
    Free,
    /// Only along the line of its original vertex normal: bumps flatten,
    /// but no vertex slides across the surface, so the tessellation (and a
    /// texture or panel layout on it) stays where it was.
    AlongNormal,
    /// Only within the plane through its original position across its
    /// original vertex normal: the vertices even out over the surface
    /// (relaxation) while the shape barely changes.
    Tangential,
}

/// The inputs of [`laplacian_hc_with`] besides the mesh and iterations.
#[derive(Clone, Copy, Debug)]
pub struct HcOptions<'a> {
    /// α, Weaverbird's partial-original input, in [0, 1].
    pub alpha: f64,
    /// β, in [0, 1]; above 0.5 is recommended.
    pub beta: f64,
    /// Which boundary vertices move.
    pub naked: NakedEdges,
    /// Which way vertices may move (Weaverbird's orientation input).
    pub direction: SmoothDirection,
    /// Weaverbird's activation input: one weight per vertex in [0, 1], how
    /// much of each step the vertex takes (0 keeps it where it is, 1 is the
    /// full step; booleans are 0 and 1). `None` activates every vertex.
    pub activation: Option<&'a [f64]>,
}

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
/// volume of a closed mesh is kept much better. Every vertex may move
/// freely; [`laplacian_hc_with`] adds Weaverbird's orientation and
/// activation inputs.
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
    let options = HcOptions {
        alpha,
        beta,
        naked,
        direction: SmoothDirection::Free,
        activation: None,
    };
    laplacian_hc_with(mesh, iterations, &options)
}

/// [`laplacian_hc`] with Weaverbird's remaining LaplacianHC inputs: the
/// activation weights scale both steps of each iteration for each vertex
/// (a vertex of weight 0 stays and anchors its neighbours), and the
/// direction then restricts where each vertex may go relative to its
/// original position and original vertex normal (the angle-weighted
/// normal of [`crate::mesh::analysis::vertex_normals`]).
///
/// # Errors
/// [`Error::InvalidArgument`] as [`laplacian_hc`], and when the activation
/// list's length is not the vertex count (naming both) or a weight is not
/// in [0, 1] (naming the vertex).
pub fn laplacian_hc_with(mesh: &Mesh, iterations: u32, options: &HcOptions) -> Result<Mesh> {
    check_hc_arguments(
        mesh,
        iterations,
        options.alpha,
        options.beta,
        options.activation.map(<[f64]>::len),
    )?;
    let (alpha, beta) = (options.alpha, options.beta);
    let weights = activation_weights(options.activation)?;
    let weight = |v: usize| weights.as_ref().map_or(1.0, |w| w[v]);
    let normals = match options.direction {
        SmoothDirection::Free => Vec::new(),
        _ => vertex_normals(mesh),
    };
    let neighbours = Neighbours::new(mesh, options.naked)?;
    let original = mesh.positions();
    let mut p = original.to_vec();
    let mut q = p.clone();
    let mut b = vec![DVec3::ZERO; p.len()];
    for _ in 0..iterations {
        q.copy_from_slice(&p);
        for v in 0..p.len() {
            let around = neighbours.of(v);
            if !around.is_empty() {
                let average =
                    around.iter().map(|&j| q[j as usize]).sum::<DVec3>() / around.len() as f64;
                // A full weight takes the average itself, as published, with no round-off.
                p[v] = match weight(v) {
                    1.0 => average,
                    w => q[v] + (average - q[v]) * w,
                };
            }
            b[v] = p[v] - (original[v] * alpha + q[v] * (1.0 - alpha));
        }
        for v in 0..p.len() {
            let around = neighbours.of(v);
            if around.is_empty() {
                continue;
            }
            let mean = around.iter().map(|&j| b[j as usize]).sum::<DVec3>() / around.len() as f64;
            p[v] -= (b[v] * beta + mean * (1.0 - beta)) * weight(v);
            let offset = p[v] - original[v];
            p[v] = match options.direction {
                SmoothDirection::Free => p[v],
                SmoothDirection::AlongNormal => original[v] + normals[v] * offset.dot(normals[v]),
                SmoothDirection::Tangential => p[v] - normals[v] * offset.dot(normals[v]),
            };
        }
    }
    moved(mesh, p, "HC smoothing")
}

/// The checks of [`laplacian_hc_with`] that need no weight, with the
/// activation list's length alone (the C ABI makes them before it views the
/// caller's buffer).
pub(crate) fn check_hc_arguments(
    mesh: &Mesh,
    iterations: u32,
    alpha: f64,
    beta: f64,
    activation_count: Option<usize>,
) -> Result<()> {
    check_iterations(iterations)?;
    check_unit("alpha", alpha)?;
    check_unit("beta", beta)?;
    if let Some(count) = activation_count {
        if count != mesh.vertex_count() {
            return Err(Error::InvalidArgument(format!(
                "activation has {count} values but the mesh has {} vertices; give one per vertex",
                mesh.vertex_count()
            )));
        }
    }
    Ok(())
}

/// Checks the activation weights, one per vertex (counted by
/// [`check_hc_arguments`]): each in [0, 1].
fn activation_weights(activation: Option<&[f64]>) -> Result<Option<&[f64]>> {
    let Some(weights) = activation else {
        return Ok(None);
    };
    if let Some(v) = weights.iter().position(|w| !(0.0..=1.0).contains(w)) {
        return Err(Error::InvalidArgument(format!(
            "activation of vertex {v} is {}; it must be between 0 and 1",
            weights[v]
        )));
    }
    Ok(Some(weights))
}
