//! Subdivision with creases, corners and carried data: every level's new
//! points as explicit weighted sums of the previous level's (stencils),
//! from OpenSubdiv's masks (`Sdc::Scheme::ComputeEdgeVertexMask` and
//! `ComputeVertexVertexMask`, with the crease/smooth blending of fractional
//! sharpness), so that any per-vertex data — positions, colours, weights of
//! any width — is refined with the same weights.
//!
//! The plain schemes without creases keep their faster passes
//! (`catmull_clark.rs`, `loop_subdivision.rs`); this path serves
//! [`Subdivider`](super::Subdivider), which takes [`SubdivisionOptions`].

use rayon::prelude::*;

use super::creases::{
    child_sharpness_around, fractional_weight, is_sharp, Rule, Sharpness, SubdivisionOptions,
    TriangleRule,
};
use super::level::{Connectivity, Faces};
use super::scheme::{loop_smooth_weights, Scheme};
use crate::buffers::try_vec;
use crate::error::Result;

/// Rows per rayon task.
const CHUNK: usize = 1024;

/// One level's stencils: row r (a point of the next level) is
/// `Σ weights[k] · source(sources[k])` over `offsets[r]..offsets[r + 1]`, where
/// a source below `parent_count` is a point of this level and any other is
/// point `source - parent_count` of the next level (a Catmull-Clark face
/// point, computed first).
#[derive(Debug, Clone)]
pub(crate) struct LevelStencils {
    pub(crate) parent_count: usize,
    pub(crate) offsets: Vec<u32>,
    pub(crate) sources: Vec<u32>,
    pub(crate) weights: Vec<f64>,
    /// Rows from here to the end read only this level: evaluate them first.
    pub(crate) first_independent: usize,
}

impl LevelStencils {
    pub(crate) fn child_count(&self) -> usize {
        self.offsets.len() - 1
    }

    /// Applies the stencils to `parent` (`width` numbers per point) into
    /// `child` (`width` numbers per point of the next level): the rows that
    /// read only the parent first, then the others, each pass in parallel.
    pub(crate) fn apply(&self, parent: &[f64], width: usize, child: &mut [f64]) {
        let (dependent, independent) = child.split_at_mut(self.first_independent * width);
        independent
            .par_chunks_mut(width)
            .with_min_len(CHUNK)
            .enumerate()
            .for_each(|(i, out)| self.row(self.first_independent + i, parent, &[], out));
        let independent = &*independent;
        dependent
            .par_chunks_mut(width)
            .with_min_len(CHUNK)
            .enumerate()
            .for_each(|(r, out)| self.row(r, parent, independent, out));
    }

    /// Row `r` into `out`; `next` holds the next level's points from
    /// `first_independent` on.
    #[inline]
    fn row(&self, r: usize, parent: &[f64], next: &[f64], out: &mut [f64]) {
        let width = out.len();
        out.fill(0.0);
        for k in self.offsets[r] as usize..self.offsets[r + 1] as usize {
            let s = self.sources[k] as usize;
            let w = self.weights[k];
            let source = if s < self.parent_count {
                &parent[s * width..(s + 1) * width]
            } else {
                let s = s - self.parent_count - self.first_independent;
                &next[s * width..(s + 1) * width]
            };
            for (o, &x) in out.iter_mut().zip(source) {
                *o += w * x;
            }
        }
    }
}

/// A small vertex mask: the vertex's own weight, one weight per incident
/// edge (applied to its far end) and one per incident face.
#[derive(Debug, Clone, Default)]
pub(crate) struct Mask {
    pub(crate) vertex: f64,
    pub(crate) edges: Vec<f64>,
    pub(crate) faces: Vec<f64>,
}

impl Mask {
    /// All weights 0, for `edges` edges and `faces` faces.
    pub(crate) fn zero(edges: usize, faces: usize) -> Mask {
        Mask {
            vertex: 0.0,
            edges: vec![0.0; edges],
            faces: vec![0.0; faces],
        }
    }

    fn corner(edges: usize, faces: usize) -> Mask {
        Mask {
            vertex: 1.0,
            ..Mask::zero(edges, faces)
        }
    }

    /// 3/4 the vertex and 1/8 each end of its first and last sharp edges.
    fn crease(sharpness: &[f32], faces: usize) -> Mask {
        let mut mask = Mask {
            vertex: 0.75,
            edges: vec![0.0; sharpness.len()],
            faces: vec![0.0; faces],
        };
        if let (Some(first), Some(last)) = (
            sharpness.iter().position(|&s| is_sharp(s)),
            sharpness.iter().rposition(|&s| is_sharp(s)),
        ) {
            mask.edges[first] = 0.125;
            mask.edges[last] = 0.125;
        }
        mask
    }

    fn smooth(scheme: Scheme, edges: usize, faces: usize) -> Mask {
        match scheme {
            Scheme::CatmullClark => {
                let n = faces as f64;
                let each = 1.0 / (n * n);
                Mask {
                    vertex: (n - 2.0) / n,
                    edges: vec![each; edges],
                    faces: vec![each; faces],
                }
            }
            Scheme::Loop => {
                let (own, each) = loop_smooth_weights(faces);
                Mask {
                    vertex: own,
                    edges: vec![each; edges],
                    faces: vec![0.0; faces],
                }
            }
        }
    }

    fn of(rule: Rule, scheme: Scheme, sharpness: &[f32], faces: usize) -> Mask {
        match rule {
            Rule::Smooth | Rule::Dart => Mask::smooth(scheme, sharpness.len(), faces),
            Rule::Crease => Mask::crease(sharpness, faces),
            Rule::Corner => Mask::corner(sharpness.len(), faces),
        }
    }

    /// `parent_weight · self + (1 - parent_weight) · child`.
    fn blend(&mut self, parent_weight: f64, child: &Mask) {
        let child_weight = 1.0 - parent_weight;
        self.vertex = parent_weight * self.vertex + child_weight * child.vertex;
        for (p, c) in self.edges.iter_mut().zip(&child.edges) {
            *p = parent_weight * *p + child_weight * c;
        }
        for (p, c) in self.faces.iter_mut().zip(&child.faces) {
            *p = parent_weight * *p + child_weight * c;
        }
    }
}

/// The mask of vertex `v`'s child: its own weight, one per edge in the
/// order of [`Sharpness::edges_at`], one per face in the order of
/// `vertex_corners` (face points; zero for Loop). The parent's rule's mask,
/// blended with the child's by the fractional weight when the rule changes
/// (`Sdc::Scheme::ComputeVertexVertexMask`).
pub(crate) fn vertex_mask(
    scheme: Scheme,
    options: &SubdivisionOptions,
    connectivity: &Connectivity,
    sharpness: &Sharpness,
    child: &Sharpness,
    v: usize,
    scratch: &mut Vec<f32>,
) -> Mask {
    let around: Vec<f32> = sharpness
        .edges_at(v)
        .iter()
        .map(|&e| sharpness.edges[e as usize])
        .collect();
    let faces = connectivity.vertex_corners(v).len();
    let parent_rule = sharpness.rules[v];
    let child_rule = child.rules[v];
    let mut mask = Mask::of(parent_rule, scheme, &around, faces);
    if !parent_rule.is_smooth() && child_rule != parent_rule {
        child_sharpness_around(sharpness, options.creasing, connectivity, v, scratch);
        let child_mask = Mask::of(child_rule, scheme, scratch, faces);
        let weight = fractional_weight(
            sharpness.vertices[v],
            child.vertices[v],
            around.iter().copied(),
            scratch,
        );
        mask.blend(f64::from(weight), &child_mask);
    }
    mask
}

/// The weights of edge `e`'s point on each end and each wing (face point or
/// opposite vertex), or `None` for the crease's midpoint
/// (`Sdc::Scheme::ComputeEdgeVertexMask`: smooth, crease, or blended by the
/// sharpness of a crease whose point turns smooth). With
/// [`TriangleRule::Smooth`], Catmull-Clark's smooth weights beside a
/// triangle are OpenSubdiv's `TRI_SUB_SMOOTH` ones.
pub(crate) fn edge_weights(
    scheme: Scheme,
    triangles: TriangleRule,
    faces: &Faces,
    connectivity: &Connectivity,
    sharpness: &Sharpness,
    child: &Sharpness,
    e: usize,
) -> Option<(f64, f64)> {
    let corners = connectivity.edge_corners(e);
    let s = sharpness.edges[e];
    if is_sharp(s) && child.rules[faces.vertex_count + e] == Rule::Crease || corners.len() != 2 {
        return None;
    }
    let (parent_weight, child_weight) = if is_sharp(s) {
        let p = f64::from(s);
        (p, 1.0 - p)
    } else {
        (0.0, 1.0)
    };
    let (smooth_end, smooth_wing) = match scheme {
        Scheme::CatmullClark if triangles == TriangleRule::Smooth => {
            smooth_triangle_weights(faces, connectivity, corners)
        }
        Scheme::CatmullClark => (0.25, 0.25),
        Scheme::Loop => (0.375, 0.125),
    };
    Some((
        parent_weight * 0.5 + child_weight * smooth_end,
        smooth_wing * child_weight,
    ))
}

/// `Sdc::Scheme<SCHEME_CATMARK>::assignSmoothMaskForEdge` with
/// `TRI_SUB_SMOOTH`: a triangle wing weighs 0.470 instead of 1/4, both
/// wings take the mean, and the ends share what is left.
fn smooth_triangle_weights(
    faces: &Faces,
    connectivity: &Connectivity,
    corners: &[u32],
) -> (f64, f64) {
    const TRIANGLE_WING: f64 = 0.470;
    let wing = |c: u32| match faces.corners(connectivity.face_of(c as usize)).len() {
        3 => TRIANGLE_WING,
        _ => 0.25,
    };
    let (first, second) = (wing(corners[0]), wing(corners[1]));
    if first == 0.25 && second == 0.25 {
        return (0.25, 0.25);
    }
    let wing = 0.5 * (first + second);
    (0.5 * (1.0 - 2.0 * wing), wing)
}

/// The stencils taking one level (`faces`, `connectivity`, `sharpness`) to
/// the next (whose sharpness is `child`).
pub(crate) fn level_stencils(
    scheme: Scheme,
    options: &SubdivisionOptions,
    faces: &Faces,
    connectivity: &Connectivity,
    sharpness: &Sharpness,
    child: &Sharpness,
) -> Result<LevelStencils> {
    let vertex_count = faces.vertex_count;
    let edge_count = connectivity.edge_count();
    let face_points = scheme.face_point_count(faces.face_count());
    let rows = vertex_count + edge_count + face_points;
    let face_point = |f: usize| (vertex_count + vertex_count + edge_count + f) as u32;
    let face_of = |c: usize| connectivity.face_of(c);
    let mut offsets = try_vec(rows + 1, "stencils")?;
    offsets.push(0u32);
    let mut sources = Vec::new();
    let mut weights = Vec::new();
    let mut push = |sources_weights: &mut dyn Iterator<Item = (u32, f64)>| {
        for (s, w) in sources_weights {
            sources.push(s);
            weights.push(w);
        }
        offsets.push(sources.len() as u32);
    };

    // Vertex points.
    let mut scratch = Vec::new();
    for v in 0..vertex_count {
        let edges = sharpness.edges_at(v);
        let corners = connectivity.vertex_corners(v);
        let mask = vertex_mask(
            scheme,
            options,
            connectivity,
            sharpness,
            child,
            v,
            &mut scratch,
        );
        let far_end = |e: u32| {
            let [a, b] = connectivity.edges[e as usize];
            if a as usize == v {
                b
            } else {
                a
            }
        };
        push(
            &mut std::iter::once((v as u32, mask.vertex))
                .chain(
                    edges
                        .iter()
                        .zip(&mask.edges)
                        .filter(|(_, &w)| w != 0.0)
                        .map(|(&e, &w)| (far_end(e), w)),
                )
                .chain(
                    corners
                        .iter()
                        .zip(&mask.faces)
                        .filter(|(_, &w)| w != 0.0 && scheme == Scheme::CatmullClark)
                        .map(|(&c, &w)| (face_point(face_of(c as usize)), w)),
                ),
        );
    }

    // Edge points.
    for (e, &[a, b]) in connectivity.edges.iter().enumerate() {
        let corners = connectivity.edge_corners(e);
        let Some((end, wing)) = edge_weights(
            scheme,
            options.triangles,
            faces,
            connectivity,
            sharpness,
            child,
            e,
        ) else {
            push(&mut [(a, 0.5), (b, 0.5)].into_iter());
            continue;
        };
        match scheme {
            Scheme::CatmullClark => {
                push(
                    &mut [
                        (a, end),
                        (b, end),
                        (face_point(face_of(corners[0] as usize)), wing),
                        (face_point(face_of(corners[1] as usize)), wing),
                    ]
                    .into_iter(),
                );
            }
            Scheme::Loop => {
                let opposite = |c: u32| {
                    let f = face_of(c as usize);
                    faces.indices[faces.next(faces.next(c as usize, f), f)]
                };
                push(
                    &mut [
                        (a, end),
                        (b, end),
                        (opposite(corners[0]), wing),
                        (opposite(corners[1]), wing),
                    ]
                    .into_iter(),
                );
            }
        }
    }

    // Face points: centroids.
    for f in 0..face_points {
        let corners = &faces.indices[faces.offsets[f] as usize..faces.offsets[f + 1] as usize];
        let w = 1.0 / corners.len() as f64;
        push(&mut corners.iter().map(|&v| (v, w)));
    }
    Ok(LevelStencils {
        parent_count: vertex_count,
        offsets,
        sources,
        weights,
        first_independent: vertex_count + edge_count,
    })
}

/// Walks counter-clockwise around vertex `v` as OpenSubdiv orders its
/// neighbourhood (`Vtr::Level::orderVertexFacesAndEdges`): from the corner
/// whose outgoing edge is naked on a boundary, else from `first_corner`;
/// edge i leaves v in face i, and edge i + 1 arrives at v in face i. Fills
/// `edges` and `corners` (the corner at v of each face) and returns whether
/// the walk met every edge and face of v (false for non-manifold vertices).
pub(crate) fn walk_around(
    faces: &Faces,
    connectivity: &Connectivity,
    v: usize,
    first_corner: u32,
    edge_count: usize,
    edges: &mut Vec<u32>,
    corners: &mut Vec<u32>,
) -> bool {
    let around = connectivity.vertex_corners(v);
    let met_all = |edges: &Vec<u32>, corners: &Vec<u32>| {
        edges.len() == edge_count && corners.len() == around.len()
    };
    // Most vertices lie inside the surface. A walk from `first_corner` that
    // closes on itself through every corner of v has met no naked edge
    // leaving v, so it is the walk from where a search for one would start.
    if faces.indices.get(first_corner as usize) == Some(&(v as u32))
        && walk_from(
            faces,
            connectivity,
            v,
            first_corner as usize,
            around.len(),
            edges,
            corners,
        ) == Some(true)
        && corners.len() == around.len()
        && connectivity.edge_corners(edges[0] as usize).len() != 1
    {
        return edges.len() == edge_count;
    }
    if around.is_empty() {
        edges.clear();
        corners.clear();
        return false;
    }
    let start = around
        .iter()
        .copied()
        .find(|&c| {
            connectivity
                .edge_corners(connectivity.corner_edges[c as usize] as usize)
                .len()
                == 1
        })
        .unwrap_or(first_corner) as usize;
    walk_from(faces, connectivity, v, start, around.len(), edges, corners).is_some()
        && met_all(edges, corners)
}

/// The walk of [`walk_around`] from corner `start`, taking at most `most`
/// corners: `None` where it fails (too many corners, or an edge leading to
/// another vertex), else whether it closed on its first edge (rather than
/// ending at an edge without exactly two corners).
fn walk_from(
    faces: &Faces,
    connectivity: &Connectivity,
    v: usize,
    start: usize,
    most: usize,
    edges: &mut Vec<u32>,
    corners: &mut Vec<u32>,
) -> Option<bool> {
    edges.clear();
    corners.clear();
    let face_of = |c: usize| connectivity.face_of(c);
    let mut c = start;
    edges.push(connectivity.corner_edges[c]);
    loop {
        corners.push(c as u32);
        if corners.len() > most {
            return None;
        }
        let previous = faces.prev(c, face_of(c));
        let arriving = connectivity.corner_edges[previous];
        if arriving == edges[0] {
            return Some(true);
        }
        edges.push(arriving);
        match *connectivity.edge_corners(arriving as usize) {
            [a, b] => {
                c = if a as usize == previous { b } else { a } as usize;
                if faces.indices[c] as usize != v {
                    return None;
                }
            }
            _ => return Some(false),
        }
    }
}

/// Puts the edges around every vertex in OpenSubdiv's order where the
/// vertex is manifold, so that sums of sharpness add in the same order.
pub(crate) fn order_vertex_edges(
    sharpness: &mut Sharpness,
    faces: &Faces,
    connectivity: &Connectivity,
    first_corners: &[u32],
) {
    let count = first_corners.len().min(faces.vertex_count);
    let offsets = &sharpness.vertex_edge_offsets;
    // Each task orders its own run of vertices, within its own run of edges.
    let mut runs = Vec::with_capacity(count.div_ceil(CHUNK));
    let mut rest = &mut sharpness.vertex_edges[offsets[0] as usize..];
    for first in (0..count).step_by(CHUNK) {
        let end = (first + CHUNK).min(count);
        let (from, to) = (offsets[first] as usize, offsets[end] as usize);
        let (run, tail) = std::mem::take(&mut rest).split_at_mut(to - from);
        runs.push((first..end, from, run));
        rest = tail;
    }
    runs.into_par_iter().for_each_init(
        || (Vec::new(), Vec::new()),
        |(edges, corners), (vertices, from, run)| {
            for v in vertices {
                let range = offsets[v] as usize - from..offsets[v + 1] as usize - from;
                if walk_around(
                    faces,
                    connectivity,
                    v,
                    first_corners[v],
                    range.len(),
                    edges,
                    corners,
                ) {
                    run[range].copy_from_slice(edges);
                }
            }
        },
    );
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::{shapes, Mesh};
    use crate::subdivide::scheme::Scheme;
    use crate::subdivide::subdivider::Subdivider;

    /// Every vertex's walk as OpenSubdiv starts it, from a search for a
    /// naked edge first, against [`walk_around`]: the same answer, and the
    /// same edges and corners where the walk met them all.
    fn assert_walks_as_searched(
        faces: &Faces,
        connectivity: &Connectivity,
        sharpness: &Sharpness,
        first: &[u32],
    ) {
        let (mut edges, mut corners) = (Vec::new(), Vec::new());
        let (mut searched_edges, mut searched_corners) = (Vec::new(), Vec::new());
        for (v, &first_corner) in first.iter().enumerate().take(faces.vertex_count) {
            let around = connectivity.vertex_corners(v);
            let edge_count = sharpness.edges_at(v).len();
            let met = walk_around(
                faces,
                connectivity,
                v,
                first_corner,
                edge_count,
                &mut edges,
                &mut corners,
            );
            let start = around
                .iter()
                .copied()
                .find(|&c| {
                    let e = connectivity.corner_edges[c as usize] as usize;
                    connectivity.edge_corners(e).len() == 1
                })
                .unwrap_or(first_corner) as usize;
            let searched = !around.is_empty()
                && walk_from(
                    faces,
                    connectivity,
                    v,
                    start,
                    around.len(),
                    &mut searched_edges,
                    &mut searched_corners,
                )
                .is_some()
                && searched_edges.len() == edge_count
                && searched_corners.len() == around.len();
            assert_eq!(met, searched, "vertex {v}");
            if met {
                assert_eq!(edges, searched_edges, "vertex {v}");
                assert_eq!(corners, searched_corners, "vertex {v}");
            }
        }
    }

    fn assert_levels_walk_as_searched(mesh: &Mesh) {
        let Ok(refined) = Subdivider::new(mesh, Scheme::CatmullClark, 2, &Default::default())
        else {
            return;
        };
        let cage = &refined.levels[0];
        let lowest: Vec<u32> = (0..cage.faces.vertex_count)
            .map(|v| {
                let around = cage.connectivity.vertex_corners(v);
                around.first().copied().unwrap_or(0)
            })
            .collect();
        assert_walks_as_searched(&cage.faces, &cage.connectivity, &cage.sharpness, &lowest);
        let last = refined.last();
        assert_walks_as_searched(
            &last.faces,
            &last.connectivity,
            &last.sharpness,
            &refined.first_corners,
        );
    }

    #[test]
    fn walks_around_boundaries_fans_and_fins_start_where_a_search_would() {
        for mesh in [
            shapes::quad_grid_with_hole(),
            shapes::triangle_grid_with_hole(),
            shapes::fin(),
            shapes::bow_tie(),
            shapes::mobius_strip(7),
            shapes::fan(12),
            shapes::book(5),
            shapes::mixed_polygons(),
            shapes::cube(),
        ] {
            assert_levels_walk_as_searched(&mesh);
        }
    }

    proptest::proptest! {
        #[test]
        fn walks_around_tangles_start_where_a_search_would(mesh in shapes::tangles()) {
            assert_levels_walk_as_searched(&mesh);
        }
    }
}
