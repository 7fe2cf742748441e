//! Subdivision with creases, corners and carried data: every level's new
//! points as explicit weighted sums of the previous level's (stencils),
//! from OpenSubdiv's masks (`Sdc::Scheme::ComputeEdgeVertexMask` and
//! `ComputeVertexVertexMask`, with the crease/smooth blending of fractional
//! sharpness), so that any per-vertex data — positions, colours, weights of
//! any width — is refined with the same weights.
//!
//! The plain schemes without creases keep their faster passes
//! (`catmull_clark.rs`, `loop_subdivision.rs`); this path serves
//! [`Subdivider`], which takes [`SubdivisionOptions`].

use glam::DVec3;
use rayon::prelude::*;

use super::creases::{
    cage_sharpness, child_sharpness, child_sharpness_around, fractional_weight, is_sharp, Rule,
    Sharpness, SubdivisionOptions,
};
use super::level::{Connectivity, Faces};
use super::rules::loop_smooth_weights;
use super::{catmull_clark, check_counts, loop_subdivision, scale, Scheme};
use crate::buffers::try_vec;
use crate::buffers::zeroed;
use crate::error::{Error, Result};
use crate::mesh::Mesh;

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
    fn corner(edges: usize, faces: usize) -> Mask {
        Mask {
            vertex: 1.0,
            edges: vec![0.0; edges],
            faces: vec![0.0; faces],
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
/// sharpness of a crease whose point turns smooth).
pub(crate) fn edge_weights(
    scheme: Scheme,
    sharpness: &Sharpness,
    child: &Sharpness,
    vertex_count: usize,
    e: usize,
    face_count: usize,
) -> Option<(f64, f64)> {
    let s = sharpness.edges[e];
    if is_sharp(s) && child.rules[vertex_count + e] == Rule::Crease || face_count != 2 {
        return None;
    }
    let (parent_weight, child_weight) = if is_sharp(s) {
        let p = f64::from(s);
        (p, 1.0 - p)
    } else {
        (0.0, 1.0)
    };
    Some(match scheme {
        Scheme::CatmullClark => (
            parent_weight * 0.5 + child_weight * 0.25,
            0.25 * child_weight,
        ),
        Scheme::Loop => (
            parent_weight * 0.5 + child_weight * 0.375,
            0.125 * child_weight,
        ),
    })
}

/// The stencils taking one level (`faces`, `connectivity`, `sharpness`) to
/// the next (whose sharpness is `child`).
fn level_stencils(
    scheme: Scheme,
    options: &SubdivisionOptions,
    faces: &Faces,
    connectivity: &Connectivity,
    sharpness: &Sharpness,
    child: &Sharpness,
) -> Result<LevelStencils> {
    let vertex_count = faces.vertex_count;
    let edge_count = connectivity.edge_count();
    let face_points = match scheme {
        Scheme::CatmullClark => faces.face_count(),
        Scheme::Loop => 0,
    };
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
        let Some((end, wing)) =
            edge_weights(scheme, sharpness, child, vertex_count, e, corners.len())
        else {
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

/// One level kept for face-varying data and the limit: its faces and
/// connectivity, and where OpenSubdiv starts walking around each vertex.
#[derive(Debug, Clone)]
pub(crate) struct KeptLevel {
    pub(crate) faces: Faces,
    pub(crate) connectivity: Connectivity,
    pub(crate) sharpness: Sharpness,
}

/// A subdivision with creases, corners and carried data, planned once for a
/// cage's topology and [`SubdivisionOptions`]: OpenSubdiv's
/// `Far::TopologyRefiner` with `PrimvarRefiner`, as stencils.
///
/// Build it with [`Subdivider::new`]; [`Subdivider::mesh`] gives the refined
/// mesh, [`Subdivider::evaluate`] re-evaluates new cage positions,
/// [`Subdivider::vertex_data`] carries per-vertex values of any width,
/// [`Subdivider::face_varying`] per-corner values (UVs), and
/// [`Subdivider::limit`] the limit surface. Output order is the same as
/// [`super::subdivide`]'s.
#[derive(Debug, Clone)]
pub struct Subdivider {
    pub(crate) scheme: Scheme,
    pub(crate) options: SubdivisionOptions,
    pub(crate) cage_vertex_count: usize,
    pub(crate) cage_positions: Vec<DVec3>,
    pub(crate) stencils: Vec<LevelStencils>,
    /// Every level's faces and connectivity, the cage first, the last level last.
    pub(crate) levels: Vec<KeptLevel>,
    /// Per vertex of the last level, the corner OpenSubdiv starts its walk
    /// around the vertex from (its first incident face).
    pub(crate) first_corners: Vec<u32>,
}

impl Subdivider {
    /// Plans `levels` levels of `scheme` on `cage` with `options`.
    ///
    /// # Errors
    /// [`Error::NotTriangles`] for Loop on a face that is not a triangle;
    /// [`Error::InvalidArgument`] for a crease whose vertices are not an edge
    /// of the cage (naming it), a corner past the vertex count, or a negative
    /// or NaN sharpness; [`Error::ResultTooLarge`] when a level would pass
    /// [`crate::error::MAX_ELEMENTS`]; [`Error::OutOfMemory`].
    pub fn new(
        cage: &Mesh,
        scheme: Scheme,
        levels: u32,
        options: &SubdivisionOptions,
    ) -> Result<Subdivider> {
        if scheme == Scheme::Loop {
            if let Some((face, size)) = cage.first_non_triangle() {
                return Err(Error::NotTriangles { face, size });
            }
        }
        let mut faces = Faces::of_mesh(cage);
        let mut connectivity = Connectivity::new(&faces)?;
        check_counts(
            scheme,
            cage.vertex_count() as u64,
            connectivity.edge_count() as u64,
            cage.face_count() as u64,
            cage.index_count() as u64,
            levels,
        )?;
        let mut sharpness = cage_sharpness(&faces, &connectivity, options)?;
        let levels = if cage.face_count() == 0 { 0 } else { levels };
        // OpenSubdiv's walk around a cage vertex starts in its lowest face,
        // around an edge's child in the edge's lowest face.
        let mut vertex_first: Vec<u32> = (0..faces.vertex_count)
            .map(|v| connectivity.vertex_corners(v).first().copied().unwrap_or(0))
            .collect();
        order_vertex_edges(&mut sharpness, &faces, &connectivity, &vertex_first);
        let mut edge_first: Vec<u32> = (0..connectivity.edge_count())
            .map(|e| connectivity.edge_corners(e)[0])
            .collect();
        let mut stencils = Vec::new();
        let mut kept = Vec::new();
        for _ in 0..levels {
            let next_faces = match scheme {
                Scheme::CatmullClark => catmull_clark::child_faces(&faces, &connectivity, true)?,
                Scheme::Loop => loop_subdivision::child_faces(&faces, &connectivity, true)?,
            };
            let next_connectivity = Connectivity::new(&next_faces)?;
            let mut next_sharpness = child_sharpness(
                scheme,
                options.creasing,
                &sharpness,
                &faces,
                &connectivity,
                &next_connectivity,
            )?;
            stencils.push(level_stencils(
                scheme,
                options,
                &faces,
                &connectivity,
                &sharpness,
                &next_sharpness,
            )?);
            (vertex_first, edge_first) = child_first_corners(
                scheme,
                &faces,
                &connectivity,
                &next_connectivity,
                &vertex_first,
                &edge_first,
            )?;
            order_vertex_edges(
                &mut next_sharpness,
                &next_faces,
                &next_connectivity,
                &vertex_first,
            );
            kept.push(KeptLevel {
                faces: std::mem::replace(&mut faces, next_faces),
                connectivity: std::mem::replace(&mut connectivity, next_connectivity),
                sharpness: std::mem::replace(&mut sharpness, next_sharpness),
            });
        }
        kept.push(KeptLevel {
            faces,
            connectivity,
            sharpness,
        });
        Ok(Subdivider {
            scheme,
            options: options.clone(),
            cage_vertex_count: cage.vertex_count(),
            cage_positions: cage.positions().to_vec(),
            stencils,
            levels: kept,
            first_corners: vertex_first,
        })
    }

    /// The scheme.
    pub fn scheme(&self) -> Scheme {
        self.scheme
    }

    /// The options it was built with.
    pub fn options(&self) -> &SubdivisionOptions {
        &self.options
    }

    /// Number of levels.
    pub fn levels(&self) -> usize {
        self.stencils.len()
    }

    /// Number of cage vertices.
    pub fn cage_vertex_count(&self) -> usize {
        self.cage_vertex_count
    }

    /// Number of cage face corners (the length of face-varying indices).
    pub fn cage_corner_count(&self) -> usize {
        self.levels[0].faces.corner_count()
    }

    pub(crate) fn last(&self) -> &KeptLevel {
        self.levels.last().expect("the cage is always kept")
    }

    /// Number of refined vertices.
    pub fn vertex_count(&self) -> usize {
        self.last().faces.vertex_count
    }

    /// Number of refined faces.
    pub fn face_count(&self) -> usize {
        self.last().faces.face_count()
    }

    /// The refined faces' vertex indices, one face after another.
    pub fn face_indices(&self) -> &[u32] {
        &self.last().faces.indices
    }

    /// Where each refined face starts in [`Subdivider::face_indices`], plus the total.
    pub fn face_offsets(&self) -> &[u32] {
        &self.last().faces.offsets
    }

    /// Refines per-vertex data: `data` holds `width` numbers per cage vertex;
    /// the result `width` numbers per refined vertex, interpolated with the
    /// same weights as the positions (OpenSubdiv's `PrimvarRefiner::Interpolate`).
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] when `width` is 0, `data` does not hold
    /// `width` numbers per cage vertex or one of them is NaN or infinite;
    /// [`Error::OutOfMemory`]; [`Error::DegenerateInput`] naming the vertex
    /// when a refined value lies beyond the largest `f64` (values near
    /// `f64::MAX` are refined at an exactly scaled-down size, so the sums
    /// never overflow).
    pub fn vertex_data(&self, data: &[f64], width: usize) -> Result<Vec<f64>> {
        self.refine_values(data, width, "the vertex data")
    }

    fn refine_values(&self, data: &[f64], width: usize, what: &str) -> Result<Vec<f64>> {
        let n = self.vertex_count().checked_mul(width).ok_or_else(|| {
            Error::ResultTooLarge(format!("{width} numbers per vertex are too many"))
        })?;
        let mut out = try_vec(n, "refined vertex data")?;
        out.resize(n, 0.0);
        self.refine_values_into(data, width, &mut out, what)?;
        Ok(out)
    }

    /// As [`Subdivider::vertex_data`], into `out` (`width` numbers per refined vertex).
    ///
    /// # Errors
    /// As [`Subdivider::vertex_data`], and when `out` has another length.
    pub fn vertex_data_into(&self, data: &[f64], width: usize, out: &mut [f64]) -> Result<()> {
        self.refine_values_into(data, width, out, "the vertex data")
    }

    fn refine_values_into(
        &self,
        data: &[f64],
        width: usize,
        out: &mut [f64],
        what: &str,
    ) -> Result<()> {
        if width == 0 {
            return Err(Error::InvalidArgument(
                "the data width must be at least 1".to_owned(),
            ));
        }
        if data.len() != self.cage_vertex_count * width {
            return Err(Error::InvalidArgument(format!(
                "{} numbers given for {} cage vertices of width {width}; expected {}",
                data.len(),
                self.cage_vertex_count,
                self.cage_vertex_count * width
            )));
        }
        if out.len() != self.vertex_count() * width {
            return Err(Error::InvalidArgument(format!(
                "the output holds {} numbers but {} refined vertices of width {width} need {}",
                out.len(),
                self.vertex_count(),
                self.vertex_count() * width
            )));
        }
        if let Some(i) = data.iter().position(|x| !x.is_finite()) {
            return Err(Error::InvalidArgument(format!(
                "{what} of cage vertex {} has a non-finite value {} at component {}",
                i / width,
                data[i],
                i % width
            )));
        }
        let Some((last, intermediate)) = self.stencils.split_last() else {
            out.copy_from_slice(data);
            return Ok(());
        };
        // Values near the top of the f64 range are refined at an exactly
        // scaled-down size (see `scale.rs`); ordinary values as they are.
        let scale = scale::for_values(data);
        let mut current = match scale {
            Some(scale) => data.iter().map(|x| x * scale.down).collect(),
            None => data.to_vec(),
        };
        for level in intermediate {
            let mut next = zeroed(level.child_count() * width, "refined vertex data")?;
            level.apply(&current, width, &mut next);
            current = next;
        }
        last.apply(&current, width, out);
        match scale {
            Some(scale) => scale::restore_values(out, width, scale, what, "refined vertex"),
            None => Ok(()),
        }
    }

    /// Refined positions of new cage positions into `out`.
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] when `cage` does not hold one position per
    /// cage vertex, `out` one per refined vertex, or a coordinate is not finite;
    /// [`Error::DegenerateInput`] as [`Subdivider::vertex_data`].
    pub fn evaluate(&self, cage: &[DVec3], out: &mut [DVec3]) -> Result<()> {
        if let Some(v) = cage.iter().position(|p| !p.is_finite()) {
            return Err(Error::InvalidArgument(format!(
                "cage vertex {v} has a non-finite coordinate"
            )));
        }
        if cage.len() != self.cage_vertex_count || out.len() != self.vertex_count() {
            return Err(Error::InvalidArgument(format!(
                "the subdivision takes {} cage positions and makes {}; {} and {} were given",
                self.cage_vertex_count,
                self.vertex_count(),
                cage.len(),
                out.len()
            )));
        }
        let flat: Vec<f64> = cage.iter().flat_map(|p| p.to_array()).collect();
        let refined = self.refine_values(&flat, 3, "the position")?;
        for (p, xyz) in out.iter_mut().zip(refined.chunks_exact(3)) {
            *p = DVec3::new(xyz[0], xyz[1], xyz[2]);
        }
        Ok(())
    }

    /// The refined mesh at the cage positions it was built from.
    ///
    /// # Errors
    /// [`Error::OutOfMemory`].
    pub fn mesh(&self) -> Result<Mesh> {
        let mut positions = try_vec(self.vertex_count(), "refined positions")?;
        positions.resize(self.vertex_count(), DVec3::ZERO);
        self.evaluate(&self.cage_positions, &mut positions)?;
        let faces = &self.last().faces;
        let sizes = faces.offsets.windows(2).map(|w| w[1] - w[0]).collect();
        Ok(Mesh::from_valid_parts(
            positions,
            sizes,
            faces.indices.clone(),
        ))
    }
}

/// Where OpenSubdiv starts walking around each vertex of the next level and
/// each edge's first face, from this level's (see [`Subdivider::new`]): a
/// vertex's child starts in the child of its first face, an edge point in
/// the child of the edge's first face at the edge's far end, a face point in
/// the face's first child; a half edge's first face is the child of the
/// edge's first face that holds it.
fn child_first_corners(
    scheme: Scheme,
    faces: &Faces,
    connectivity: &Connectivity,
    child: &Connectivity,
    vertex_first: &[u32],
    edge_first: &[u32],
) -> Result<(Vec<u32>, Vec<u32>)> {
    let vertex_count = faces.vertex_count;
    let edge_count = connectivity.edge_count();
    let face_of = |c: usize| connectivity.face_of(c);
    // The first corner of the child face at parent corner c.
    let child_face_corner = |c: usize| -> usize {
        match scheme {
            Scheme::CatmullClark => 4 * c,
            Scheme::Loop => {
                let f = face_of(c);
                let local = c - faces.offsets[f] as usize;
                3 * (4 * f + local)
            }
        }
    };
    // Where the edge point sits in the child face at the edge's far end.
    let edge_point_slot = match scheme {
        Scheme::CatmullClark => 3,
        Scheme::Loop => 2,
    };
    let mut vertices = try_vec(child.vertex_offsets.len() - 1, "vertex order")?;
    vertices.extend(
        vertex_first
            .iter()
            .map(|&c| child_face_corner(c as usize) as u32),
    );
    for &c in edge_first.iter().take(edge_count) {
        let c = c as usize;
        let far = faces.next(c, face_of(c));
        vertices.push((child_face_corner(far) + edge_point_slot) as u32);
    }
    if scheme == Scheme::CatmullClark {
        for f in 0..faces.face_count() {
            vertices.push((child_face_corner(faces.offsets[f] as usize) + 2) as u32);
        }
    }

    let mut edges: Vec<u32> = (0..child.edge_count())
        .map(|e| child.edge_corners(e)[0])
        .collect();
    for (e, &c) in edge_first.iter().enumerate() {
        let c = c as usize;
        let far = faces.next(c, face_of(c));
        for corner in [
            child_face_corner(c),
            child_face_corner(far) + edge_point_slot,
        ] {
            let half = child.corner_edges[corner] as usize;
            // Only the halves of this edge (one end a parent vertex).
            let [low, high] = child.edges[half];
            if (low as usize) < vertex_count && high as usize == vertex_count + e {
                edges[half] = corner as u32;
            }
        }
    }
    Ok((vertices, edges))
}

/// Subdivides `mesh` with `scheme`, `levels` times, with creases, corners
/// and the naked-edge mode of `options` (OpenSubdiv's semi-sharp creasing).
/// With no creases and no corners it equals [`super::subdivide`].
///
/// # Errors
/// As [`Subdivider::new`].
pub fn subdivide_with(
    mesh: &Mesh,
    scheme: Scheme,
    levels: u32,
    options: &SubdivisionOptions,
) -> Result<Mesh> {
    Subdivider::new(mesh, scheme, levels, options)?.mesh()
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
    edges.clear();
    corners.clear();
    let around = connectivity.vertex_corners(v);
    if around.is_empty() {
        return false;
    }
    let face_of = |c: usize| connectivity.face_of(c);
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
    let mut c = start;
    edges.push(connectivity.corner_edges[c]);
    loop {
        corners.push(c as u32);
        if corners.len() > around.len() {
            return false;
        }
        let previous = faces.prev(c, face_of(c));
        let arriving = connectivity.corner_edges[previous];
        if arriving == edges[0] {
            break;
        }
        edges.push(arriving);
        match *connectivity.edge_corners(arriving as usize) {
            [a, b] => {
                c = if a as usize == previous { b } else { a } as usize;
                if faces.indices[c] as usize != v {
                    return false;
                }
            }
            _ => break,
        }
    }
    edges.len() == edge_count && corners.len() == around.len()
}

/// Puts the edges around every vertex in OpenSubdiv's order where the
/// vertex is manifold, so that sums of sharpness add in the same order.
pub(crate) fn order_vertex_edges(
    sharpness: &mut Sharpness,
    faces: &Faces,
    connectivity: &Connectivity,
    first_corners: &[u32],
) {
    let (mut edges, mut corners) = (Vec::new(), Vec::new());
    for (v, &first) in first_corners.iter().enumerate().take(faces.vertex_count) {
        let range = sharpness.vertex_edge_offsets[v] as usize
            ..sharpness.vertex_edge_offsets[v + 1] as usize;
        if walk_around(
            faces,
            connectivity,
            v,
            first,
            range.len(),
            &mut edges,
            &mut corners,
        ) {
            sharpness.vertex_edges[range].copy_from_slice(&edges);
        }
    }
}
