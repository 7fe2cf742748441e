//! Smoothing on a fixed topology: [`laplacian`], [`laplacian_hc`] (volume
//! preserving) and [`blur`] (per-vertex values rather than positions), all
//! with Weaverbird's naked-edge modes ([`NakedEdges`]).
//!
//! Every vertex moves towards the plain average of its neighbours (the
//! "umbrella" operator); the neighbours come from the mesh edges, except on
//! the boundary, where the naked-edge mode decides. A vertex on an edge of
//! three or more faces, and a vertex no face uses, never moves.

mod blur;
mod hc;
mod laplacian;

pub use blur::blur;
pub(crate) use blur::check_blur_arguments;
pub(crate) use hc::check_hc_arguments;
pub use hc::{laplacian_hc, laplacian_hc_with, HcOptions, SmoothDirection};
pub use laplacian::laplacian;

use crate::error::{Error, Result};
use crate::mesh::topology::Topology;
use crate::mesh::Mesh;

/// How vertices on naked edges behave while smoothing — the same three modes
/// as subdivision: `Fixed` keeps boundary vertices where they are; `Smooth`
/// moves them along the boundary, averaged with their neighbours across naked
/// edges only; `CornerFixed` does the same but keeps a boundary vertex with a
/// single face (a corner of the outline).
pub use crate::subdivide::NakedEdges;

/// Most iterations a smoothing call accepts, so a slip of the slider cannot
/// hang the host.
pub const MAX_ITERATIONS: u32 = 10_000;

/// The neighbours each vertex is averaged with (an empty list: it stays).
pub(crate) struct Neighbours {
    offsets: Vec<u32>,
    list: Vec<u32>,
}

impl Neighbours {
    /// # Errors
    /// [`Error::InvalidArgument`] for [`NakedEdges::None`], a mode of
    /// subdivision only (smoothing leaves no holes).
    pub(crate) fn new(mesh: &Mesh, naked: NakedEdges) -> Result<Neighbours> {
        if naked == NakedEdges::None {
            return Err(Error::InvalidArgument(
                "naked-edge mode none leaves holes, which only subdivision makes; smoothing takes \
                 fixed, smooth or corner-fixed"
                    .to_owned(),
            ));
        }
        let topology = Topology::try_new(mesh)?;
        let n = mesh.vertex_count();
        let mut on_boundary = vec![false; n];
        let mut pinned = vec![false; n];
        for (e, &[a, b]) in topology.edges().iter().enumerate() {
            if topology.is_naked_edge(e) {
                on_boundary[a as usize] = true;
                on_boundary[b as usize] = true;
            } else if topology.is_non_manifold_edge(e) {
                pinned[a as usize] = true;
                pinned[b as usize] = true;
            }
        }
        let face_counts = topology.vertex_face_counts();
        for v in 0..n {
            pinned[v] |= on_boundary[v]
                && match naked {
                    NakedEdges::Fixed => true,
                    NakedEdges::Smooth => false,
                    NakedEdges::CornerFixed => face_counts[v] == 1,
                    NakedEdges::None => false,
                };
        }
        // An edge links two vertices when each end may use it.
        let uses = |v: u32, e: usize| {
            let v = v as usize;
            !pinned[v] && (!on_boundary[v] || topology.is_naked_edge(e))
        };
        let mut offsets = vec![0u32; n + 1];
        for (e, &[a, b]) in topology.edges().iter().enumerate() {
            if uses(a, e) {
                offsets[a as usize + 1] += 1;
            }
            if uses(b, e) {
                offsets[b as usize + 1] += 1;
            }
        }
        for v in 0..n {
            offsets[v + 1] += offsets[v];
        }
        let mut fill = offsets.clone();
        let mut list = vec![0u32; offsets[n] as usize];
        for (e, &[a, b]) in topology.edges().iter().enumerate() {
            for (from, to) in [(a, b), (b, a)] {
                if uses(from, e) {
                    list[fill[from as usize] as usize] = to;
                    fill[from as usize] += 1;
                }
            }
        }
        Ok(Neighbours { offsets, list })
    }

    pub(crate) fn of(&self, v: usize) -> &[u32] {
        &self.list[self.offsets[v] as usize..self.offsets[v + 1] as usize]
    }
}

pub(crate) fn check_iterations(iterations: u32) -> Result<()> {
    if iterations > MAX_ITERATIONS {
        return Err(Error::InvalidArgument(format!(
            "iterations is {iterations}; it must be at most {MAX_ITERATIONS}"
        )));
    }
    Ok(())
}

pub(crate) fn check_unit(name: &str, value: f64) -> Result<()> {
    if !(0.0..=1.0).contains(&value) {
        return Err(Error::InvalidArgument(format!(
            "{name} is {value}; it must be between 0 and 1"
        )));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::shapes;

    #[test]
    fn neighbours_follow_the_naked_edge_mode() {
        // 2 × 2 grid: vertex 4 is inside, 1 on a side, 0 a corner.
        let grid = shapes::quad_grid(2, 2);
        let sorted = |n: &Neighbours, v: usize| {
            let mut list = n.of(v).to_vec();
            list.sort_unstable();
            list
        };
        let fixed = Neighbours::new(&grid, NakedEdges::Fixed).unwrap();
        assert_eq!(sorted(&fixed, 4), [1, 3, 5, 7]);
        assert!(fixed.of(1).is_empty() && fixed.of(0).is_empty());
        let smooth = Neighbours::new(&grid, NakedEdges::Smooth).unwrap();
        assert_eq!(sorted(&smooth, 1), [0, 2]);
        assert_eq!(sorted(&smooth, 0), [1, 3]);
        let corner = Neighbours::new(&grid, NakedEdges::CornerFixed).unwrap();
        assert_eq!(sorted(&corner, 1), [0, 2]);
        assert!(corner.of(0).is_empty());
        // A fin's shared edge pins its two vertices.
        let fin = shapes::fin();
        let n = Neighbours::new(&fin, NakedEdges::Smooth).unwrap();
        let topology = Topology::new(&fin);
        for e in topology.non_manifold_edges() {
            for v in topology.edges()[e as usize] {
                assert!(n.of(v as usize).is_empty());
            }
        }
    }
}
