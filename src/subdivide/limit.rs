//! The limit surface at the vertices of the last level: where each vertex
//! would end after infinitely many levels, and the surface's tangents and
//! normal there, with OpenSubdiv's limit masks (`Sdc::Scheme::
//! ComputeVertexMask`: `assignSmoothMask`, `assignCreaseMask`,
//! `assignCornerMask` and their tangent masks, applied as
//! `Far::PrimvarRefiner::Limit` applies them).
//!
//! Smooth vertices use the eigen-analysis masks of the scheme (Halstead,
//! Kass and DeRose 1993 for Catmull-Clark; Loop 1987); crease and boundary
//! vertices the cubic B-spline along the crease and Biermann, Levin and
//! Zorin's (2000) cross tangent; corners stay, with their two first edges
//! as tangents.

use std::collections::HashMap;

use glam::DVec3;
use rayon::prelude::*;

use super::creases::{is_sharp, Rule};
use super::scale;
use super::scheme::Scheme;
use super::stencils::{walk_around, Mask};
use super::subdivider::Subdivider;
use crate::error::{Error, Result};

/// Limit positions, tangents and unit normals, one per vertex of the last
/// level, in its vertex order.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Limit {
    /// Limit positions.
    pub positions: Vec<DVec3>,
    /// First tangent (along a crease, in the direction of its first edge).
    pub du: Vec<DVec3>,
    /// Second tangent (across a crease, into the surface).
    pub dv: Vec<DVec3>,
    /// `du × dv` normalised: pointing outward from counter-clockwise faces;
    /// zero where the tangents are parallel.
    pub normals: Vec<DVec3>,
}

// A limit mask weighs the vertex, the far end of each edge around it and,
// where a stencil's mask weighs a face point, the face's corner opposite the
// vertex (Catmull-Clark quads only).

impl Subdivider {
    /// The limit surface at the last level's vertices, for the cage
    /// positions the subdivider was built from.
    ///
    /// # Errors
    /// As [`Subdivider::limit_of`].
    pub fn limit(&self) -> Result<Limit> {
        self.limit_of(&self.cage_positions)
    }

    /// The limit surface at the last level's vertices for new cage
    /// positions. Isolated vertices keep their place with zero tangents;
    /// around a non-manifold vertex the tangents follow the edges' index
    /// order (OpenSubdiv leaves them unordered there too).
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] for Catmull-Clark at level 0 on a cage with
    /// faces that are not quads (refine once first), or positions as
    /// [`Subdivider::evaluate`] refuses them; [`Error::OutOfMemory`];
    /// [`Error::DegenerateInput`] naming the vertex when a limit position or
    /// tangent lies beyond the largest `f64` (positions near `f64::MAX` are
    /// evaluated at an exactly scaled-down size, so the sums never overflow).
    pub fn limit_of(&self, cage: &[DVec3]) -> Result<Limit> {
        let Some(scale) = scale::for_points(cage) else {
            return self.limit_at(cage);
        };
        // Positions and tangents are linear in the cage and the normals
        // unchanged by a uniform scale.
        let mut limit = self.limit_at(&scale::scaled_points(cage, scale))?;
        scale::restore_points(&mut limit.positions, scale, "the limit position")?;
        scale::restore_points(&mut limit.du, scale, "the first limit tangent")?;
        scale::restore_points(&mut limit.dv, scale, "the second limit tangent")?;
        Ok(limit)
    }

    /// Limit positions and unit normals at the cage positions it was built
    /// from, without the tangents: these succeed where only a tangent would
    /// lie beyond the largest `f64`.
    ///
    /// # Errors
    /// As [`Subdivider::limit_of`], for the positions only.
    pub(crate) fn limit_positions_and_normals(&self) -> Result<(Vec<DVec3>, Vec<DVec3>)> {
        let cage = &self.cage_positions;
        let Some(scale) = scale::for_points(cage) else {
            let limit = self.limit_at(cage)?;
            return Ok((limit.positions, limit.normals));
        };
        let mut limit = self.limit_at(&scale::scaled_points(cage, scale))?;
        scale::restore_points(&mut limit.positions, scale, "the limit position")?;
        Ok((limit.positions, limit.normals))
    }

    fn limit_at(&self, cage: &[DVec3]) -> Result<Limit> {
        self.limit_at_vertices(cage, (0..self.vertex_count()).into_par_iter())
    }

    /// [`Subdivider::limit_of`] at the last level's `vertices` alone, in
    /// their order, for positions that need no scaling (see `scale.rs`).
    pub(crate) fn limit_at_vertices(
        &self,
        cage: &[DVec3],
        vertices: impl IndexedParallelIterator<Item = usize>,
    ) -> Result<Limit> {
        self.check_limit_faces()?;
        let mut points = vec![DVec3::ZERO; self.vertex_count()];
        self.evaluate(cage, &mut points)?;
        Ok(self.limit_from_points(&points, vertices))
    }

    /// The limit at the last level's `vertices` from that level's `points`;
    /// Catmull-Clark's faces are quads (see `check_limit_faces`).
    pub(crate) fn limit_from_points(
        &self,
        points: &[DVec3],
        vertices: impl IndexedParallelIterator<Item = usize>,
    ) -> Limit {
        let ((positions, du), (dv, normals)) = vertices
            .with_min_len(VERTICES_PER_TASK)
            .map_init(StencilScratch::default, |scratch, v| {
                let [position, du, dv] = self.limit_sums(v, points, scratch, 3);
                ((position, du), (dv, unit_normal(du, dv)))
            })
            .unzip();
        Limit {
            positions,
            du,
            dv,
            normals,
        }
    }

    /// The limit positions alone at every last-level vertex that is
    /// `wanted`, the bits [`Subdivider::limit_from_points`] gives them;
    /// zero at the others.
    pub(crate) fn limit_positions_where(
        &self,
        points: &[DVec3],
        wanted: impl Fn(usize) -> bool + Sync,
    ) -> Vec<DVec3> {
        (0..self.vertex_count())
            .into_par_iter()
            .with_min_len(VERTICES_PER_TASK)
            .map_init(StencilScratch::default, |scratch, v| {
                if wanted(v) {
                    self.limit_sums(v, points, scratch, 1)[0]
                } else {
                    DVec3::ZERO
                }
            })
            .collect()
    }

    /// The first `wanted` of vertex `v`'s limit position, first and second
    /// tangent from `points` (the rest zero); a vertex without edges stays,
    /// with zero tangents.
    fn limit_sums(
        &self,
        v: usize,
        points: &[DVec3],
        scratch: &mut StencilScratch,
        wanted: usize,
    ) -> [DVec3; 3] {
        let p = points[v];
        let Some(kind) = self.limit_stencil(v, scratch) else {
            return [p, DVec3::ZERO, DVec3::ZERO];
        };
        let StencilScratch {
            far,
            opposite,
            masks,
            ..
        } = scratch;
        let masks = masks.of(self.scheme, kind);
        let apply = |mask: &Mask| {
            let mut sum = p * mask.vertex;
            for (w, &q) in mask.edges.iter().zip(far.iter()) {
                sum += points[q as usize] * *w;
            }
            for (w, &q) in mask.faces.iter().zip(opposite.iter()) {
                sum += points[q as usize] * *w;
            }
            sum
        };
        let mut sums = [DVec3::ZERO; 3];
        for (sum, mask) in sums.iter_mut().zip(masks).take(wanted) {
            *sum = apply(mask);
        }
        sums
    }

    /// The limit masks at the cage `vertices` of a subdivider of no levels,
    /// as weights of the cage's points: for each vertex the weights of its
    /// position, first and second tangent, by point ascending, zeros left
    /// out. Each weight is summed in the order [`Subdivider::limit_of`]
    /// sums its point's terms, so the weights are the bits `limit_of` gives
    /// for unit points.
    ///
    /// # Errors
    /// As [`Subdivider::limit_of`] (Catmull-Clark on faces that are not quads).
    pub(crate) fn cage_limit_weights(
        &self,
        vertices: impl Iterator<Item = usize>,
    ) -> Result<Vec<[Weights; 3]>> {
        debug_assert_eq!(self.levels(), 0, "the weights are of the cage's points");
        self.check_limit_faces()?;
        let mut scratch = StencilScratch::default();
        let mut out = Vec::new();
        for v in vertices {
            let Some(kind) = self.limit_stencil(v, &mut scratch) else {
                out.push([vec![(v as u32, 1.0)], Vec::new(), Vec::new()]);
                continue;
            };
            let StencilScratch {
                far,
                opposite,
                masks,
                ..
            } = &mut scratch;
            let weights = |mask: &Mask| {
                // `limit_of` starts each sum at the vertex's term.
                let far = mask.edges.iter().zip(far.iter());
                let opposite = mask.faces.iter().zip(opposite.iter());
                summed(
                    std::iter::once((v as u32, mask.vertex))
                        .chain(far.chain(opposite).map(|(&w, &q)| (q, w)))
                        .collect(),
                )
            };
            out.push(masks.of(self.scheme, kind).each_ref().map(weights));
        }
        Ok(out)
    }

    /// Refuses Catmull-Clark's limit on faces that are not quads.
    fn check_limit_faces(&self) -> Result<()> {
        let faces = &self.last().faces;
        if self.scheme == Scheme::CatmullClark {
            if let Some(f) =
                (0..faces.face_count()).find(|&f| faces.offsets[f + 1] - faces.offsets[f] != 4)
            {
                return Err(Error::InvalidArgument(format!(
                    "the Catmull-Clark limit needs quads but face {f} is not one; \
                     subdivide at least one level"
                )));
            }
        }
        Ok(())
    }

    /// What the limit at last-level vertex `v` weighs and how: into
    /// `scratch`, the far end of each of its edges in ring order and the
    /// corner opposite `v` in each of its faces (Catmull-Clark); returned,
    /// which masks weigh those and `v`. `None` for a vertex without edges,
    /// which stays.
    fn limit_stencil(&self, v: usize, scratch: &mut StencilScratch) -> Option<MaskKind> {
        let last = self.last();
        let faces = &last.faces;
        let connectivity = &last.connectivity;
        let sharpness = &last.sharpness;
        let edge_count = sharpness.edges_at(v).len();
        if edge_count == 0 {
            return None;
        }
        let StencilScratch {
            edges,
            corners,
            far,
            opposite,
            ..
        } = scratch;
        let ordered = walk_around(
            faces,
            connectivity,
            v,
            self.first_corners[v],
            edge_count,
            edges,
            corners,
        );
        if !ordered {
            edges.clear();
            edges.extend_from_slice(sharpness.edges_at(v));
            corners.clear();
        }
        far.clear();
        far.extend(edges.iter().map(|&e| {
            let [a, b] = connectivity.edges[e as usize];
            if a as usize == v {
                b
            } else {
                a
            }
        }));
        opposite.clear();
        if self.scheme == Scheme::CatmullClark {
            opposite.extend(corners.iter().map(|&c| {
                let f = connectivity.face_of(c as usize);
                let start = faces.offsets[f] as usize;
                let local = (c as usize - start + 2) % 4;
                faces.indices[start + local]
            }));
        }
        let is_sharp_edge = |&e: &u32| is_sharp(sharpness.edges[e as usize]);
        let mut rule = sharpness.rules[v];
        // Catmull-Clark's smooth limit has no mask for two faces
        // (OpenSubdiv takes the corner's); Loop's covers any valence.
        let two_quads = self.scheme == Scheme::CatmullClark && corners.len() == 2;
        if rule.is_smooth() && (two_quads || !ordered) {
            rule = Rule::Corner;
        }
        let (edges_len, faces_len) = (edges.len(), corners.len());
        Some(match rule {
            Rule::Smooth | Rule::Dart => MaskKind::Smooth {
                edges: edges_len,
                faces: faces_len,
            },
            Rule::Crease => MaskKind::Crease {
                edges: edges_len,
                faces: faces_len,
                first: edges.iter().position(is_sharp_edge).unwrap_or(0),
                last: edges.iter().rposition(is_sharp_edge).unwrap_or(0),
            },
            Rule::Corner => MaskKind::Corner { edges: edges_len },
        })
    }
}

/// Vertices of one rayon task: enough that each task's few masks are worked
/// out once for many vertices.
const VERTICES_PER_TASK: usize = 1024;

/// Which limit masks a vertex takes: all they depend on besides the scheme,
/// so that vertices of one kind share them.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
enum MaskKind {
    Smooth {
        edges: usize,
        faces: usize,
    },
    /// Sharp edges `first` and `last` in the counter-clockwise order.
    Crease {
        edges: usize,
        faces: usize,
        first: usize,
        last: usize,
    },
    Corner {
        edges: usize,
    },
}

/// Masks by kind, each worked out once: the vertices of a level take only
/// a handful of kinds.
#[derive(Debug, Default)]
struct MaskCache(HashMap<MaskKind, [Mask; 3]>);

impl MaskCache {
    /// Position, first and second tangent masks of `kind`.
    fn of(&mut self, scheme: Scheme, kind: MaskKind) -> &[Mask; 3] {
        self.0.entry(kind).or_insert_with(|| match kind {
            MaskKind::Smooth { edges, faces } => smooth_masks(scheme, edges, faces),
            MaskKind::Crease {
                edges,
                faces,
                first,
                last,
            } => crease_masks(scheme, edges, faces, first, last),
            MaskKind::Corner { edges } => corner_masks(scheme, edges),
        })
    }
}

/// What one thread reuses from vertex to vertex: the walk around it, the
/// points its limit weighs (see `limit_stencil`) and the masks met so far.
#[derive(Debug, Default)]
struct StencilScratch {
    edges: Vec<u32>,
    corners: Vec<u32>,
    /// The far end of each of its edges, in ring order.
    far: Vec<u32>,
    /// The corner opposite it in each of its quads (Catmull-Clark).
    opposite: Vec<u32>,
    masks: MaskCache,
}

/// Weights of points, `(point, weight)`.
pub(crate) type Weights = Vec<(u32, f64)>;

/// Terms `(point, weight)` summed by point, ascending, each point's terms
/// in their order (as a sum over them from zero adds them); zeros left out.
pub(crate) fn summed(mut terms: Weights) -> Weights {
    // A stable sort keeps each point's terms in their order.
    terms.sort_by_key(|&(point, _)| point);
    let mut sums: Weights = Vec::with_capacity(terms.len());
    for (point, w) in terms {
        match sums.last_mut() {
            Some((last, sum)) if *last == point => *sum += w,
            _ => sums.push((point, w)),
        }
    }
    sums.retain(|&(_, w)| w != 0.0);
    sums
}

/// `du × dv` normalised, or zero where the tangents are parallel. Each
/// tangent is first scaled by a power of two to a magnitude near 1, which
/// changes no bit of the result but keeps the cross product from
/// overflowing (tangents beyond about 1e154) or underflowing (below 1e-154).
fn unit_normal(du: DVec3, dv: DVec3) -> DVec3 {
    fn near_one(t: DVec3) -> DVec3 {
        let largest = t.abs().max_element();
        if largest == 0.0 || !largest.is_finite() {
            return t;
        }
        let exponent = ((largest.to_bits() >> 52) & 0x7ff) as i32 - 1023;
        // Subnormal tangents: two exact steps keep the factor a normal number.
        let k = exponent.max(-1022);
        let t = t * f64::from_bits(((1023 - k / 2) as u64) << 52);
        t * f64::from_bits(((1023 - (k - k / 2)) as u64) << 52)
    }
    near_one(du).cross(near_one(dv)).normalize_or_zero()
}

/// Position, first and second tangent masks of a smooth vertex.
fn smooth_masks(scheme: Scheme, edges: usize, faces: usize) -> [Mask; 3] {
    let n = faces;
    let valence = n as f64;
    let mut position = Mask::zero(edges, faces);
    let mut du = Mask::zero(edges, faces);
    match scheme {
        Scheme::CatmullClark => {
            let (f, e, v) = if n == 4 {
                (1.0 / 36.0, 1.0 / 9.0, 4.0 / 9.0)
            } else {
                let f = 1.0 / (valence * (valence + 5.0));
                let e = 4.0 * f;
                (f, e, 1.0 - valence * (e + f))
            };
            position.vertex = v;
            position.edges.fill(e);
            position.faces.fill(f);
            if n == 4 {
                du.edges.copy_from_slice(&[4.0, 0.0, -4.0, 0.0]);
                du.faces.copy_from_slice(&[1.0, -1.0, -1.0, 1.0]);
            } else {
                let theta = 2.0 * std::f64::consts::PI / valence;
                let cos_theta = theta.cos();
                let cos_half = (theta * 0.5).cos();
                let lambda = 5.0 / 16.0
                    + 1.0 / 16.0 * (cos_theta + cos_half * (2.0 * (9.0 + cos_theta)).sqrt());
                let face_scale = 1.0 / (4.0 * lambda - 1.0);
                for i in 0..n {
                    let c0 = (i as f64 * theta).cos();
                    let c1 = ((i + 1) as f64 * theta).cos();
                    du.edges[i] = 4.0 * c0;
                    du.faces[i] = face_scale * (c0 + c1);
                }
            }
        }
        Scheme::Loop => {
            if n == 6 {
                position.vertex = 0.5;
                position.edges.fill(1.0 / 12.0);
            } else {
                let inverse = 1.0 / valence;
                let cos_theta = (std::f64::consts::PI * 2.0 * inverse).cos();
                let beta = 0.25 * cos_theta + 0.375;
                let gamma = (0.625 - beta * beta) * inverse;
                let e = 1.0 / (valence + 3.0 / (8.0 * gamma));
                position.vertex = 1.0 - e * valence;
                position.edges.fill(e);
            }
            let alpha = 2.0 * std::f64::consts::PI / valence;
            let mut dv = Mask::zero(edges, faces);
            for i in 0..n.min(edges) {
                du.edges[i] = (alpha * i as f64).cos();
                dv.edges[i] = (alpha * i as f64).sin();
            }
            return [position, du, dv];
        }
    }
    // Catmull-Clark's second tangent is the first turned by one edge.
    let mut dv = Mask::zero(edges, faces);
    for i in 0..n {
        dv.edges[(i + 1) % n] = du.edges[i];
        dv.faces[(i + 1) % n] = du.faces[i];
    }
    [position, du, dv]
}

/// Masks of a crease vertex whose sharp edges are `first` and `last` in the
/// counter-clockwise order; the cross tangent spans the faces between them.
fn crease_masks(
    scheme: Scheme,
    edges: usize,
    faces: usize,
    first: usize,
    last: usize,
) -> [Mask; 3] {
    let mut position = Mask::zero(edges, faces);
    position.vertex = 2.0 / 3.0;
    position.edges[first] = 1.0 / 6.0;
    position.edges[last] = 1.0 / 6.0;
    let mut du = Mask::zero(edges, faces);
    let along = match scheme {
        Scheme::CatmullClark => 0.5,
        Scheme::Loop => 1.5,
    };
    du.edges[first] = along;
    du.edges[last] = -along;
    let mut dv = Mask::zero(edges, faces);
    let interior = last.saturating_sub(first + 1);
    let has_faces = faces > 0;
    match scheme {
        Scheme::CatmullClark => match interior {
            0 => {
                dv.vertex = -6.0;
                dv.edges[first] = 3.0;
                dv.edges[last] = 3.0;
            }
            1 => {
                dv.vertex = -4.0 / 6.0;
                dv.edges[first] = -1.0 / 6.0;
                dv.edges[first + 1] = 4.0 / 6.0;
                dv.edges[last] = -1.0 / 6.0;
                if has_faces {
                    dv.faces[first] = 1.0 / 6.0;
                    dv.faces[first + 1] = 1.0 / 6.0;
                }
            }
            _ => {
                // Biermann, Levin and Zorin (2000), as OpenSubdiv weighs it.
                let k = (interior + 1) as f64;
                let theta = std::f64::consts::PI / k;
                let (sin_theta, cos_theta) = theta.sin_cos();
                let denominator = 1.0 / (k * (3.0 + cos_theta));
                let r = (cos_theta + 1.0) / sin_theta;
                dv.vertex = 4.0 * r * (cos_theta - 1.0) * denominator;
                let crease = -r * (1.0 + 2.0 * cos_theta) * denominator;
                dv.edges[first] = crease;
                dv.edges[last] = crease;
                if has_faces {
                    dv.faces[first] = sin_theta * denominator;
                }
                let mut sin_next = sin_theta;
                for i in 1..=interior {
                    let sin_i = sin_next;
                    sin_next = ((i + 1) as f64 * theta).sin();
                    dv.edges[first + i] = 4.0 * sin_i * denominator;
                    if has_faces {
                        dv.faces[first + i] = (sin_i + sin_next) * denominator;
                    }
                }
            }
        },
        Scheme::Loop => match interior {
            0 => {
                dv.vertex = -6.0;
                dv.edges[first] = 3.0;
                dv.edges[last] = 3.0;
            }
            1 => {
                dv.vertex = -3.0;
                dv.edges[first + 1] = 3.0;
            }
            2 => {
                let root3 = f64::from(1.732_050_8_f32);
                let half_root3 = root3 * 0.5;
                dv.vertex = -root3;
                dv.edges[first] = -half_root3;
                dv.edges[last] = -half_root3;
                dv.edges[first + 1] = root3;
                dv.edges[first + 2] = root3;
            }
            _ => {
                let theta = std::f64::consts::PI / (interior + 1) as f64;
                let crease = -3.0 * theta.sin();
                let coefficient = -3.0 * (2.0 * theta.cos() - 2.0);
                dv.edges[first] = crease;
                dv.edges[last] = crease;
                for i in 1..=interior {
                    dv.edges[first + i] = coefficient * (i as f64 * theta).sin();
                }
            }
        },
    }
    [position, du, dv]
}

/// Masks of a corner: it stays; the tangents run along its first two edges.
fn corner_masks(scheme: Scheme, edges: usize) -> [Mask; 3] {
    let scale = match scheme {
        Scheme::CatmullClark => 1.0,
        Scheme::Loop => 3.0,
    };
    let mut position = Mask::zero(edges, 0);
    position.vertex = 1.0;
    let mut du = Mask::zero(edges, 0);
    let mut dv = Mask::zero(edges, 0);
    du.vertex = -scale;
    dv.vertex = -scale;
    if edges >= 2 {
        du.edges[0] = scale;
        dv.edges[1] = scale;
    }
    [position, du, dv]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::shapes;
    use crate::subdivide::creases::SubdivisionOptions;

    #[test]
    fn positions_alone_are_the_limit_s_positions() {
        let grid = shapes::quad_grid_with_hole();
        let creased = SubdivisionOptions {
            creases: vec![([0, 1], 1.5), ([1, 2], f64::INFINITY)],
            corners: vec![(5, 2.0)],
            ..Default::default()
        };
        let mut checked = 0;
        for (mesh, options) in [
            (shapes::mixed_polygons(), SubdivisionOptions::default()),
            (grid, creased),
            (shapes::fin(), SubdivisionOptions::default()),
        ] {
            for scheme in [Scheme::CatmullClark, Scheme::Loop] {
                let Ok(refined) = Subdivider::new(&mesh, scheme, 2, &options) else {
                    continue;
                };
                let mut points = vec![DVec3::ZERO; refined.vertex_count()];
                refined.evaluate(mesh.positions(), &mut points).unwrap();
                let limit = refined.limit().unwrap();
                checked += 1;
                let wanted = |v: usize| v % 3 != 1;
                let alone = refined.limit_positions_where(&points, wanted);
                for (v, (&p, &q)) in alone.iter().zip(&limit.positions).enumerate() {
                    let expected = if wanted(v) { q } else { DVec3::ZERO };
                    assert_eq!(
                        p.to_array().map(f64::to_bits),
                        expected.to_array().map(f64::to_bits)
                    );
                }
            }
        }
        assert!(checked >= 3, "{checked} cages refined");
    }
}
