//! [`Subdivider`]: subdivision with creases, corners and carried data,
//! planned once for a cage's topology as levels of stencils
//! (`stencils.rs`), then applied to positions, per-vertex data of any width,
//! face-varying values and the limit surface.

use glam::DVec3;

use super::creases::{cage_sharpness, child_sharpness, Sharpness, SubdivisionOptions};
use super::holes::{cage_holes, visible_faces, Visible};
use super::level::{Connectivity, Faces};
use super::point_rules::child_faces;
use super::scale;
use super::scheme::Scheme;
use super::stencils::{level_stencils, order_vertex_edges, LevelStencils};
use crate::buffers::{try_vec, zeroed};
use crate::error::{Error, Result};
use crate::mesh::Mesh;

/// One level kept for face-varying data and the limit: its faces and
/// connectivity, and where OpenSubdiv starts walking around each vertex.
#[derive(Debug, Clone)]
pub(crate) struct KeptLevel {
    pub(crate) faces: Faces<'static>,
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
    /// With holes: the last level's faces without theirs.
    pub(crate) visible: Option<Visible>,
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
        scheme.check_cage(cage)?;
        let (mut faces, mut connectivity) = Connectivity::of_cage(cage, scheme, levels, true)?;
        let mut sharpness = cage_sharpness(&faces, &connectivity, options)?;
        let holes = cage_holes(&faces, &connectivity, options)?;
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
            let next_faces = child_faces(scheme, &faces, &connectivity, true)?;
            // Written from this level's, so the edges inside each face are
            // its own, as OpenSubdiv's are.
            let next_connectivity = connectivity.refine(scheme, &faces, true)?;
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
                faces: std::mem::replace(&mut faces, next_faces).into_owned(),
                connectivity: std::mem::replace(&mut connectivity, next_connectivity),
                sharpness: std::mem::replace(&mut sharpness, next_sharpness),
            });
        }
        let visible = match holes {
            Some(holes) => Some(visible_faces(
                cage.face_sizes(),
                scheme,
                levels as usize,
                &holes,
                &faces,
            )?),
            None => None,
        };
        kept.push(KeptLevel {
            faces: faces.into_owned(),
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
            visible,
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

    /// The refined faces the result shows: the last level's, less the
    /// children of holes.
    pub(crate) fn output_faces(&self) -> &Faces<'static> {
        self.visible
            .as_ref()
            .map_or(&self.last().faces, |visible| &visible.faces)
    }

    /// Number of refined faces (holes leave none).
    pub fn face_count(&self) -> usize {
        self.output_faces().face_count()
    }

    /// The refined faces' vertex indices, one face after another.
    pub fn face_indices(&self) -> &[u32] {
        &self.output_faces().indices
    }

    /// Where each refined face starts in [`Subdivider::face_indices`], plus the total.
    pub fn face_offsets(&self) -> &[u32] {
        &self.output_faces().offsets
    }

    /// The cage face each refined face comes from.
    pub fn parent_faces(&self) -> Vec<u32> {
        match &self.visible {
            Some(visible) => visible.parents.clone(),
            None => {
                let cage = &self.levels[0].faces;
                let sizes = (0..cage.face_count()).map(|f| cage.corners(f).len() as u32);
                self.scheme.parents_of(sizes, self.levels()).collect()
            }
        }
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
        let faces = self.output_faces();
        let sizes = faces.sizes();
        Ok(Mesh::from_valid_parts(
            positions,
            sizes,
            faces.indices.to_vec(),
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
