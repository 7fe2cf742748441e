//! OpenSubdiv 3.5 and OpenMesh 9 as references for Weft's tests and
//! benchmarks, reached through [`cxx`].
//!
//! Everything takes and returns flat arrays ([`RefMesh`]: xyz positions, face
//! sizes, face vertex indices) in `f64`. Arguments are checked here (lengths,
//! index ranges) so that the C++ libraries never see out-of-range indices;
//! what the libraries themselves refuse comes back as a [`ReferenceError`]
//! carrying their message.
//!
//! - [`opensubdiv_refine`], [`opensubdiv_refine_vertex_data`],
//!   [`opensubdiv_refine_vertex_data`], [`opensubdiv_refine_face_varying`],
//!   [`opensubdiv_limit`]: Far `TopologyDescriptor` → `TopologyRefinerFactory`
//!   → `RefineUniform` → `PrimvarRefinerReal<double>`, level by level.
//! - [`OsdRefiner`]: the same refiner, built once and applied to several
//!   primvars.
//! - [`OsdStencils`]: `Far::StencilTableFactoryReal<double>` for the last level,
//!   to re-evaluate new cage positions (`UpdateValues`), and
//!   [`OsdParallelStencils`], the single-precision table evaluated by
//!   `Osd::OmpEvaluator` on several threads.
//!
//! The C++ side is compiled `-O3 -march=native -DNDEBUG` and refines with
//! OpenSubdiv's default `UniformOptions`, as its users run it.
//! - [`openmesh_catmull_clark`], [`openmesh_loop`]: OpenMesh's uniform
//!   `CatmullClarkT` (on a `PolyMesh`) and `LoopT` (on a `TriMesh`) with
//!   `Vec3d` points.
//!
//! Output order of OpenSubdiv (Vtr's uniform refinement with its default
//! `orderVerticesFromFacesFirst = false`), at each level: first the children
//! of the parent's vertices (so the cage's vertices keep their indices), then
//! one point per parent face in face order, then one per parent edge in Vtr's
//! edge order (edges numbered as first met walking the faces' corners). The
//! children of face f are contiguous and child i starts at corner i of f:
//! cube face `[0, 2, 3, 1]` gives `[v0, e(0,2), f, e(1,0)]` first. Weft's
//! order differs (edge points before face points, edges sorted), so compare
//! by matching positions or through a map built from that rule.

mod bridge;

use bridge::ffi;
use std::fmt;

/// The sharpness OpenSubdiv treats as infinite (`Sdc::Crease::SHARPNESS_INFINITE`).
/// Larger values, `f32::INFINITY` included, are passed on as this value.
pub const SHARPNESS_INFINITE: f32 = 10.0;

/// The most levels OpenSubdiv's uniform refinement takes (a 4-bit field).
pub const MAX_LEVELS: u32 = 15;

/// A polygon mesh as flat arrays.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct RefMesh {
    /// x, y, z of every vertex.
    pub positions: Vec<f64>,
    /// The number of corners of every face.
    pub face_sizes: Vec<u32>,
    /// The vertex of every corner, face after face.
    pub face_indices: Vec<u32>,
}

impl RefMesh {
    /// A mesh from positions and polygons.
    pub fn from_polygons(positions: &[[f64; 3]], faces: &[&[u32]]) -> RefMesh {
        RefMesh {
            positions: positions.iter().flatten().copied().collect(),
            face_sizes: faces.iter().map(|f| f.len() as u32).collect(),
            face_indices: faces.iter().flat_map(|f| f.iter().copied()).collect(),
        }
    }

    /// The number of vertices.
    pub fn vertex_count(&self) -> usize {
        self.positions.len() / 3
    }

    /// The number of faces.
    pub fn face_count(&self) -> usize {
        self.face_sizes.len()
    }

    /// The position of vertex `v`.
    pub fn position(&self, v: usize) -> [f64; 3] {
        [
            self.positions[3 * v],
            self.positions[3 * v + 1],
            self.positions[3 * v + 2],
        ]
    }

    /// The faces as index slices, in order.
    pub fn faces(&self) -> impl Iterator<Item = &[u32]> + '_ {
        let mut start = 0;
        self.face_sizes.iter().map(move |&n| {
            let face = &self.face_indices[start..start + n as usize];
            start += n as usize;
            face
        })
    }
}

/// A failure reported by OpenSubdiv or OpenMesh, or an argument refused
/// before reaching them.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ReferenceError(pub String);

impl fmt::Display for ReferenceError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for ReferenceError {}

impl From<cxx::Exception> for ReferenceError {
    fn from(e: cxx::Exception) -> Self {
        ReferenceError(e.what().to_owned())
    }
}

fn refuse<T>(message: String) -> Result<T, ReferenceError> {
    Err(ReferenceError(message))
}

/// The subdivision scheme (`Sdc::SchemeType`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Scheme {
    /// `SCHEME_CATMARK`: any polygons in, quads out.
    #[default]
    CatmullClark,
    /// `SCHEME_LOOP`: triangles in, triangles out.
    Loop,
    /// `SCHEME_BILINEAR`: any polygons in, quads out, nothing moves.
    Bilinear,
}

/// How boundary vertices are treated (`Sdc::Options::VtxBoundaryInterpolation`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum BoundaryInterpolation {
    /// `VTX_BOUNDARY_NONE`: as `EdgeOnly`, and every face at a vertex on a
    /// boundary edge not creased infinitely sharp is a hole (Weft's `None`).
    None,
    /// `VTX_BOUNDARY_EDGE_ONLY`: boundary edges are infinitely sharp creases;
    /// every boundary vertex follows the B-spline rule (Weft's `Smooth`).
    #[default]
    EdgeOnly,
    /// `VTX_BOUNDARY_EDGE_AND_CORNER`: as `EdgeOnly`, and a boundary vertex
    /// with one incident face is a corner that stays put (Weft's `CornerFixed`).
    EdgeAndCorner,
}

/// How semi-sharp creases soften (`Sdc::Options::CreasingMethod`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum CreasingMethod {
    /// `CREASE_UNIFORM`: sharpness drops by one per level.
    #[default]
    Uniform,
    /// `CREASE_CHAIKIN`: sharpness of child edges averaged with neighbours.
    Chaikin,
}

/// Where face-varying data is interpolated linearly
/// (`Sdc::Options::FVarLinearInterpolation`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum FVarLinear {
    /// `FVAR_LINEAR_NONE`: smooth everywhere ("edge only").
    None,
    /// `FVAR_LINEAR_CORNERS_ONLY`: sharpen corners only.
    CornersOnly,
    /// `FVAR_LINEAR_CORNERS_PLUS1`: "edge corner".
    CornersPlus1,
    /// `FVAR_LINEAR_CORNERS_PLUS2`: "edge and corner + propagate corner".
    CornersPlus2,
    /// `FVAR_LINEAR_BOUNDARIES`: sharpen all boundaries ("always sharp").
    Boundaries,
    /// `FVAR_LINEAR_ALL`: bilinear everywhere (OpenSubdiv's default).
    #[default]
    All,
}

/// The Sdc options, creases and corners handed to OpenSubdiv
/// (`Sdc::Options` and the tag arrays of `Far::TopologyDescriptor`).
///
/// Sharpness values of [`SHARPNESS_INFINITE`] (10) or more are infinite.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct OsdOptions {
    /// The scheme.
    pub scheme: Scheme,
    /// The boundary rule.
    pub boundary: BoundaryInterpolation,
    /// The crease softening rule.
    pub creasing: CreasingMethod,
    /// Creased edges as vertex pairs (`creaseVertexIndexPairs`); each pair
    /// must be an edge of the cage.
    pub crease_edges: Vec<[u32; 2]>,
    /// One sharpness per crease edge (`creaseWeights`).
    pub crease_sharpness: Vec<f32>,
    /// Sharp vertices (`cornerVertexIndices`).
    pub corner_vertices: Vec<u32>,
    /// One sharpness per sharp vertex (`cornerWeights`).
    pub corner_sharpness: Vec<f32>,
    /// The face-varying linear option (used by
    /// [`opensubdiv_refine_face_varying`]).
    pub fvar_linear: FVarLinear,
    /// Hole faces (`holeIndices`): refined but tagged, and left out of
    /// [`OsdRefiner::faces`] and the face-varying indices, as OpenSubdiv's
    /// users skip them.
    pub holes: Vec<u32>,
    /// Catmark's "smooth triangle" weights (`TRI_SUB_SMOOTH`) instead of
    /// `TRI_SUB_CATMARK`.
    pub smooth_triangles: bool,
    /// Build the last level's full topology (`fullTopologyInLastLevel`).
    /// Off by default, as OpenSubdiv's users refine for positions and faces
    /// (it doubles the refinement's time); [`OsdRefiner::limit`] needs it on.
    pub full_topology: bool,
}

impl OsdOptions {
    /// Options for `scheme` with `boundary` and nothing else tagged.
    pub fn new(scheme: Scheme, boundary: BoundaryInterpolation) -> OsdOptions {
        OsdOptions {
            scheme,
            boundary,
            ..OsdOptions::default()
        }
    }

    /// Weft's `Fixed` naked-edge mode in OpenSubdiv's terms: `EdgeOnly` with
    /// every boundary vertex of `cage` (one on an edge with a single face)
    /// tagged with infinite corner sharpness. Creases are left empty.
    pub fn fixed(scheme: Scheme, cage: &RefMesh) -> OsdOptions {
        let corners = boundary_vertices(cage);
        OsdOptions {
            scheme,
            boundary: BoundaryInterpolation::EdgeOnly,
            corner_sharpness: vec![SHARPNESS_INFINITE; corners.len()],
            corner_vertices: corners,
            ..OsdOptions::default()
        }
    }

    fn settings(&self) -> ffi::OsdSettings {
        ffi::OsdSettings {
            scheme: match self.scheme {
                Scheme::CatmullClark => 0,
                Scheme::Loop => 1,
                Scheme::Bilinear => 2,
            },
            boundary: match self.boundary {
                BoundaryInterpolation::None => 0,
                BoundaryInterpolation::EdgeOnly => 1,
                BoundaryInterpolation::EdgeAndCorner => 2,
            },
            creasing: match self.creasing {
                CreasingMethod::Uniform => 0,
                CreasingMethod::Chaikin => 1,
            },
            fvar_linear: self.fvar_linear as u32,
            triangles: self.smooth_triangles as u32,
            full_topology: self.full_topology,
        }
    }
}

/// The vertices of `cage` that lie on an edge used by exactly one face, in
/// increasing order.
pub fn boundary_vertices(cage: &RefMesh) -> Vec<u32> {
    let mut edges: Vec<(u32, u32)> = Vec::with_capacity(cage.face_indices.len());
    for face in cage.faces() {
        for (i, &a) in face.iter().enumerate() {
            let b = face[(i + 1) % face.len()];
            edges.push((a.min(b), a.max(b)));
        }
    }
    edges.sort_unstable();
    let mut boundary = Vec::new();
    let mut i = 0;
    while i < edges.len() {
        let mut j = i + 1;
        while j < edges.len() && edges[j] == edges[i] {
            j += 1;
        }
        if j - i == 1 {
            boundary.extend([edges[i].0, edges[i].1]);
        }
        i = j;
    }
    boundary.sort_unstable();
    boundary.dedup();
    boundary
}

fn check_cage(cage: &RefMesh) -> Result<(), ReferenceError> {
    if !cage.positions.len().is_multiple_of(3) {
        return refuse(format!(
            "positions hold {} numbers, not a multiple of 3",
            cage.positions.len()
        ));
    }
    let vertex_count = cage.vertex_count();
    if vertex_count > i32::MAX as usize {
        return refuse(format!(
            "{vertex_count} vertices are more than OpenSubdiv indexes"
        ));
    }
    let corners: usize = cage.face_sizes.iter().map(|&n| n as usize).sum();
    if corners != cage.face_indices.len() {
        return refuse(format!(
            "face sizes add up to {corners} corners but {} face indices were given",
            cage.face_indices.len()
        ));
    }
    if let Some(f) = cage.face_sizes.iter().position(|&n| n < 3) {
        return refuse(format!(
            "face {f} has {} corners; a face needs 3",
            cage.face_sizes[f]
        ));
    }
    if let Some(c) = cage
        .face_indices
        .iter()
        .position(|&v| v as usize >= vertex_count)
    {
        return refuse(format!(
            "face index {c} is vertex {}, but there are {vertex_count} vertices",
            cage.face_indices[c]
        ));
    }
    Ok(())
}

fn check_levels(levels: u32) -> Result<(), ReferenceError> {
    if levels > MAX_LEVELS {
        return refuse(format!(
            "{levels} levels asked; OpenSubdiv refines at most {MAX_LEVELS}"
        ));
    }
    Ok(())
}

fn clamp_sharpness(values: &[f32], what: &str) -> Result<Vec<f32>, ReferenceError> {
    if let Some(i) = values.iter().position(|s| s.is_nan()) {
        return refuse(format!("{what} sharpness {i} is NaN"));
    }
    Ok(values.iter().map(|&s| s.min(SHARPNESS_INFINITE)).collect())
}

/// A cage refined uniformly by OpenSubdiv (`Far::TopologyRefiner` after
/// `RefineUniform` with `fullTopologyInLastLevel`), ready to interpolate any
/// number of primvars.
pub struct OsdRefiner {
    inner: cxx::UniquePtr<ffi::OsdRefiner>,
    cage_vertex_count: usize,
    cage_corner_count: usize,
    cage_face_count: usize,
    cage_value_count: usize,
}

impl OsdRefiner {
    /// Builds the refiner of `cage`'s topology (its positions are not used)
    /// with `options`, refined `levels` times (0..=[`MAX_LEVELS`]).
    ///
    /// Non-manifold cages (an edge with three faces, a bow-tie vertex) are
    /// accepted, as OpenSubdiv accepts them.
    ///
    /// # Errors
    /// A malformed cage or options (lengths, index ranges, NaN sharpness,
    /// too many levels), or OpenSubdiv's message when it rejects the
    /// topology.
    pub fn new(cage: &RefMesh, options: &OsdOptions, levels: u32) -> Result<Self, ReferenceError> {
        Self::build(cage, options, levels, None)
    }

    /// As [`OsdRefiner::new`], with one face-varying channel: `value_count`
    /// values and the value of every corner of the cage in `value_indices`.
    pub fn with_face_varying(
        cage: &RefMesh,
        options: &OsdOptions,
        levels: u32,
        value_count: usize,
        value_indices: &[u32],
    ) -> Result<Self, ReferenceError> {
        Self::build(cage, options, levels, Some((value_count, value_indices)))
    }

    fn build(
        cage: &RefMesh,
        options: &OsdOptions,
        levels: u32,
        fvar: Option<(usize, &[u32])>,
    ) -> Result<Self, ReferenceError> {
        check_cage(cage)?;
        check_levels(levels)?;
        let vertex_count = cage.vertex_count();
        if options.crease_edges.len() != options.crease_sharpness.len() {
            return refuse(format!(
                "{} crease edges but {} crease sharpness values",
                options.crease_edges.len(),
                options.crease_sharpness.len()
            ));
        }
        if options.corner_vertices.len() != options.corner_sharpness.len() {
            return refuse(format!(
                "{} corner vertices but {} corner sharpness values",
                options.corner_vertices.len(),
                options.corner_sharpness.len()
            ));
        }
        if let Some(i) = options
            .crease_edges
            .iter()
            .position(|e| e.iter().any(|&v| v as usize >= vertex_count))
        {
            return refuse(format!(
                "crease edge {i} {:?} names a vertex past {vertex_count}",
                options.crease_edges[i]
            ));
        }
        if let Some(i) = options
            .corner_vertices
            .iter()
            .position(|&v| v as usize >= vertex_count)
        {
            return refuse(format!(
                "corner {i} is vertex {}, past {vertex_count}",
                options.corner_vertices[i]
            ));
        }
        if let Some(i) = options
            .holes
            .iter()
            .position(|&f| f as usize >= cage.face_count())
        {
            return refuse(format!(
                "hole {i} is face {}, past {}",
                options.holes[i],
                cage.face_count()
            ));
        }
        let (value_count, value_indices) = fvar.unwrap_or((0, &[]));
        if fvar.is_some() {
            if value_indices.len() != cage.face_indices.len() {
                return refuse(format!(
                    "{} face-varying indices for {} corners",
                    value_indices.len(),
                    cage.face_indices.len()
                ));
            }
            if value_count > i32::MAX as usize {
                return refuse(format!("{value_count} face-varying values are too many"));
            }
            if let Some(c) = value_indices
                .iter()
                .position(|&i| i as usize >= value_count)
            {
                return refuse(format!(
                    "corner {c} has face-varying value {}, but there are {value_count}",
                    value_indices[c]
                ));
            }
            if value_indices.is_empty() {
                return refuse("a face-varying channel needs at least one face".to_owned());
            }
        }
        let crease_pairs: Vec<u32> = options.crease_edges.iter().flatten().copied().collect();
        let crease_sharpness = clamp_sharpness(&options.crease_sharpness, "crease")?;
        let corner_sharpness = clamp_sharpness(&options.corner_sharpness, "corner")?;
        let inner = ffi::osd_refiner_new(
            vertex_count as u32,
            &cage.face_sizes,
            &cage.face_indices,
            &crease_pairs,
            &crease_sharpness,
            &options.corner_vertices,
            &corner_sharpness,
            value_count as u32,
            value_indices,
            &options.holes,
            &options.settings(),
            levels,
        )?;
        Ok(OsdRefiner {
            inner,
            cage_vertex_count: vertex_count,
            cage_corner_count: value_indices.len(),
            cage_value_count: value_count,
            cage_face_count: cage.face_count(),
        })
    }

    /// The number of vertices of the last level.
    pub fn vertex_count(&self) -> usize {
        self.inner.vertex_count()
    }

    /// The number of faces of the last level.
    pub fn face_count(&self) -> usize {
        self.inner.face_count()
    }

    /// The last level's faces (`TopologyLevel::GetFaceVertices`, face by
    /// face) with empty positions.
    pub fn faces(&self) -> RefMesh {
        let mut face_sizes = vec![0; self.inner.face_count()];
        let mut face_indices = vec![0; self.inner.corner_count()];
        self.inner.faces(&mut face_sizes, &mut face_indices);
        RefMesh {
            positions: Vec::new(),
            face_sizes,
            face_indices,
        }
    }

    fn check_data(&self, data: &[f64], width: usize) {
        assert!(width > 0, "the data width must be at least 1");
        assert_eq!(
            data.len(),
            self.cage_vertex_count * width,
            "{} vertices of width {width} need {} numbers",
            self.cage_vertex_count,
            self.cage_vertex_count * width
        );
    }

    /// Per-vertex data of `width` numbers per cage vertex, interpolated like
    /// positions (`PrimvarRefiner::Interpolate` level by level); the last
    /// level's values in its vertex order.
    ///
    /// # Panics
    /// When `width` is 0 or `data` does not hold `width` numbers per cage
    /// vertex, or (with the C++ exception's message) when memory runs out.
    pub fn interpolate(&self, data: &[f64], width: usize) -> Vec<f64> {
        self.check_data(data, width);
        let mut out = vec![0.0; self.vertex_count() * width];
        if let Err(e) = self.inner.interpolate(data, width, false, &mut out) {
            panic!("OpenSubdiv's interpolation failed: {}", e.what());
        }
        out
    }

    /// As [`OsdRefiner::interpolate`] with `PrimvarRefiner::InterpolateVarying`
    /// (linear: face and edge points are plain averages, vertices keep their
    /// value).
    ///
    /// # Panics
    /// As [`OsdRefiner::interpolate`].
    pub fn interpolate_varying(&self, data: &[f64], width: usize) -> Vec<f64> {
        self.check_data(data, width);
        let mut out = vec![0.0; self.vertex_count() * width];
        if let Err(e) = self.inner.interpolate(data, width, true, &mut out) {
            panic!("OpenSubdiv's varying interpolation failed: {}", e.what());
        }
        out
    }

    /// Face-varying values (`width` numbers each) of the channel given to
    /// [`OsdRefiner::with_face_varying`], refined with
    /// `PrimvarRefiner::InterpolateFaceVarying`: the last level's values and
    /// the value of every corner of its faces (same face order as
    /// [`OsdRefiner::faces`]).
    ///
    /// # Panics
    /// When the refiner has no face-varying channel, `values` does not hold
    /// `width` numbers per value, or memory runs out.
    pub fn interpolate_face_varying(&self, values: &[f64], width: usize) -> (Vec<f64>, Vec<u32>) {
        assert!(
            self.cage_corner_count > 0,
            "the refiner has no face-varying channel; build it with with_face_varying"
        );
        assert!(width > 0, "the data width must be at least 1");
        assert_eq!(
            values.len(),
            self.cage_value_count * width,
            "{} face-varying values of width {width} need {} numbers",
            self.cage_value_count,
            self.cage_value_count * width
        );
        let mut out = vec![0.0; self.inner.fvar_value_count() * width];
        let mut indices = vec![0; self.inner.corner_count()];
        if let Err(e) = self
            .inner
            .interpolate_face_varying(values, width, &mut out, &mut indices)
        {
            panic!(
                "OpenSubdiv's face-varying interpolation failed: {}",
                e.what()
            );
        }
        (out, indices)
    }

    /// The limit surface at the last level's vertices: positions and the two
    /// tangents `du`, `dv` from `PrimvarRefiner::Limit` applied to the last
    /// level's interpolated `cage_positions`, and unit normals `du × dv`
    /// (zero where the cross product vanishes). The refiner must have been
    /// built with [`OsdOptions::full_topology`].
    ///
    /// # Errors
    /// OpenSubdiv's message if it cannot evaluate the limit (also when the
    /// last level lacks its full topology).
    ///
    /// # Panics
    /// When `cage_positions` does not hold 3 numbers per cage vertex.
    pub fn limit(&self, cage_positions: &[f64]) -> Result<Limit, ReferenceError> {
        self.check_data(cage_positions, 3);
        let n = self.vertex_count() * 3;
        let mut positions = vec![0.0; n];
        let mut du = vec![0.0; n];
        let mut dv = vec![0.0; n];
        self.inner
            .limit(cage_positions, &mut positions, &mut du, &mut dv)?;
        let normals = du
            .chunks_exact(3)
            .zip(dv.chunks_exact(3))
            .flat_map(|(a, b)| {
                let c = [
                    a[1] * b[2] - a[2] * b[1],
                    a[2] * b[0] - a[0] * b[2],
                    a[0] * b[1] - a[1] * b[0],
                ];
                let length = (c[0] * c[0] + c[1] * c[1] + c[2] * c[2]).sqrt();
                let scale = if length > 0.0 { 1.0 / length } else { 0.0 };
                c.map(|x| x * scale)
            })
            .collect();
        Ok(Limit {
            positions,
            du,
            dv,
            normals,
        })
    }
}

impl OsdRefiner {
    /// The limit surface of the cage (the refiner's base level) at
    /// `faces[i]`, `(uvs[2 i], uvs[2 i + 1])`, by OpenSubdiv's Bfr
    /// (`Bfr::RefinerSurfaceFactory`, `Surface<double>::Evaluate`), with
    /// `approx_smooth` and `approx_sharp` levels of its approximation of
    /// irregular faces (`SetApproxLevelSmooth`, `SetApproxLevelSharp`;
    /// regular faces are exact at any level). Parameters as Bfr's
    /// `Parameterization`. Returns positions, du and dv, 3 numbers each.
    ///
    /// # Errors
    /// A face out of range or one Bfr cannot evaluate (a hole).
    ///
    /// # Panics
    /// When `cage_positions` does not hold 3 numbers per cage vertex or
    /// `uvs` not 2 per face.
    pub fn bfr_evaluate(
        &self,
        cage_positions: &[f64],
        approx: (i32, i32),
        faces: &[u32],
        uvs: &[f64],
    ) -> Result<[Vec<f64>; 3], ReferenceError> {
        let n = 3 * faces.len();
        let (mut p, mut du, mut dv) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
        self.bfr_evaluate_into(
            cage_positions,
            approx,
            faces,
            uvs,
            [&mut p, &mut du, &mut dv],
        )?;
        Ok([p, du, dv])
    }

    /// [`OsdRefiner::bfr_evaluate`] into the caller's buffers (positions,
    /// du, dv), as a host that evaluates again and again keeps them.
    ///
    /// # Errors
    /// As [`OsdRefiner::bfr_evaluate`].
    ///
    /// # Panics
    /// As [`OsdRefiner::bfr_evaluate`], and when a buffer does not hold 3
    /// numbers per sample.
    pub fn bfr_evaluate_into(
        &self,
        cage_positions: &[f64],
        approx: (i32, i32),
        faces: &[u32],
        uvs: &[f64],
        [p, du, dv]: [&mut [f64]; 3],
    ) -> Result<(), ReferenceError> {
        assert_eq!(cage_positions.len(), 3 * self.cage_vertex_count);
        assert_eq!(uvs.len(), 2 * faces.len());
        let n = 3 * faces.len();
        assert!(p.len() == n && du.len() == n && dv.len() == n);
        if let Some(&f) = faces.iter().find(|&&f| f as usize >= self.cage_face_count) {
            return Err(ReferenceError(format!("face {f} is out of range")));
        }
        self.inner.bfr_evaluate(
            cage_positions,
            approx.0.clamp(0, 10),
            approx.1.clamp(0, 10),
            faces,
            uvs,
            p,
            du,
            dv,
        )?;
        Ok(())
    }
}

/// Limit positions, tangents and normals, 3 numbers per vertex of the last
/// level, in its vertex order.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Limit {
    /// Limit positions.
    pub positions: Vec<f64>,
    /// First tangent (`dstTan1` of `PrimvarRefiner::Limit`).
    pub du: Vec<f64>,
    /// Second tangent (`dstTan2`).
    pub dv: Vec<f64>,
    /// `du × dv`, normalised; zero where it vanishes. It points outward when
    /// the cage's faces run counter-clockwise seen from outside.
    pub normals: Vec<f64>,
}

/// Refines `cage` `levels` times with OpenSubdiv and interpolates its
/// positions: Far `TopologyDescriptor` → `TopologyRefinerFactory::Create` →
/// `RefineUniform` (default `UniformOptions`) →
/// `PrimvarRefinerReal<double>::Interpolate` level by level.
///
/// Returns the last level: its vertices in OpenSubdiv's order (see the crate
/// docs) and its faces (`GetFaceVertices`, face by face). Level 0 returns the
/// cage as OpenSubdiv sees it.
///
/// # Errors
/// As [`OsdRefiner::new`].
pub fn opensubdiv_refine(
    cage: &RefMesh,
    options: &OsdOptions,
    levels: u32,
) -> Result<RefMesh, ReferenceError> {
    let refiner = OsdRefiner::new(cage, options, levels)?;
    let mut mesh = refiner.faces();
    mesh.positions = refiner.interpolate(&cage.positions, 3);
    Ok(mesh)
}

/// How per-vertex data is refined: OpenSubdiv's vertex primvars (with the
/// positions' weights) or varying ones (linear).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Primvar {
    /// `PrimvarRefiner::Interpolate`.
    Vertex,
    /// `PrimvarRefiner::InterpolateVarying`.
    Varying,
}

/// Per-vertex data of any `width` carried through OpenSubdiv's refinement
/// as `kind` says, in the vertex order of [`opensubdiv_refine`]'s output.
///
/// # Errors
/// As [`OsdRefiner::new`].
///
/// # Panics
/// When `width` is 0 or `vertex_data` does not hold `width` numbers per vertex.
pub fn opensubdiv_refine_vertex_data(
    cage: &RefMesh,
    options: &OsdOptions,
    levels: u32,
    (vertex_data, width): (&[f64], usize),
    kind: Primvar,
) -> Result<Vec<f64>, ReferenceError> {
    let refiner = OsdRefiner::new(cage, options, levels)?;
    Ok(match kind {
        Primvar::Vertex => refiner.interpolate(vertex_data, width),
        Primvar::Varying => refiner.interpolate_varying(vertex_data, width),
    })
}

/// UVs carried face-varying: `uvs` holds 2 numbers per value, `uv_indices`
/// the value of every corner of `cage`. One FVar channel with
/// `options.fvar_linear`, refined with `PrimvarRefiner::InterpolateFaceVarying`.
///
/// Returns the last level's values (2 numbers each) and the value of every
/// corner of its faces, in the face order of [`opensubdiv_refine`]'s output.
///
/// # Errors
/// As [`OsdRefiner::new`], and when `uv_indices` does not give one in-range
/// value per corner.
///
/// # Panics
/// When `uvs` has an odd length.
pub fn opensubdiv_refine_face_varying(
    cage: &RefMesh,
    options: &OsdOptions,
    levels: u32,
    uvs: &[f64],
    uv_indices: &[u32],
) -> Result<(Vec<f64>, Vec<u32>), ReferenceError> {
    assert!(uvs.len().is_multiple_of(2), "uvs hold 2 numbers per value");
    let refiner = OsdRefiner::with_face_varying(cage, options, levels, uvs.len() / 2, uv_indices)?;
    Ok(refiner.interpolate_face_varying(uvs, 2))
}

/// The limit surface at the vertices of [`opensubdiv_refine`]'s output:
/// `PrimvarRefiner::Limit` on the last level (see [`OsdRefiner::limit`]).
///
/// # Errors
/// As [`OsdRefiner::new`] and [`OsdRefiner::limit`].
pub fn opensubdiv_limit(
    cage: &RefMesh,
    options: &OsdOptions,
    levels: u32,
) -> Result<Limit, ReferenceError> {
    let options = OsdOptions {
        full_topology: true,
        ..options.clone()
    };
    OsdRefiner::new(cage, &options, levels)?.limit(&cage.positions)
}

/// OpenSubdiv's stencil table for the last level of a uniform refinement
/// (`Far::StencilTableFactoryReal<double>` with interpolation mode vertex,
/// offsets, no control vertices, last level only, intermediate levels
/// factorized), built once and re-applied to new cage positions with
/// `UpdateValues`.
pub struct OsdStencils {
    table: cxx::UniquePtr<ffi::OsdStencils>,
    cage_vertex_count: usize,
    /// The refined faces (positions empty); vertex order as
    /// [`opensubdiv_refine`].
    pub faces: RefMesh,
}

impl OsdStencils {
    /// Refines `cage`'s topology `levels` times (1..=[`MAX_LEVELS`]) and
    /// builds the stencils of the last level's vertices.
    ///
    /// # Errors
    /// As [`OsdRefiner::new`]; `levels` 0 is refused.
    pub fn new(cage: &RefMesh, options: &OsdOptions, levels: u32) -> Result<Self, ReferenceError> {
        if levels == 0 {
            return refuse("stencils need at least one level".to_owned());
        }
        let refiner = OsdRefiner::new(cage, options, levels)?;
        let table = ffi::osd_stencils_new(&refiner.inner)?;
        Ok(OsdStencils {
            table,
            cage_vertex_count: cage.vertex_count(),
            faces: refiner.faces(),
        })
    }

    /// The number of refined vertices (one stencil each).
    pub fn vertex_count(&self) -> usize {
        self.table.stencil_count()
    }

    /// Evaluates the stencils (`StencilTable::UpdateValues`) on
    /// `cage_positions` (xyz per cage vertex) into `out` (xyz per refined
    /// vertex); allocates nothing.
    ///
    /// # Panics
    /// When a buffer has the wrong length.
    pub fn update(&self, cage_positions: &[f64], out: &mut [f64]) {
        self.check_lengths(cage_positions, out);
        self.table.update(cage_positions, out);
    }

    /// [`OsdStencils::update`] spread over `threads` threads (at least one),
    /// each calling `UpdateValues` on a contiguous range of the stencils:
    /// Far's table on several cores without Osd's evaluators.
    ///
    /// # Panics
    /// When a buffer has the wrong length, or a thread cannot be started.
    pub fn update_on_threads(&self, cage_positions: &[f64], out: &mut [f64], threads: u32) {
        self.check_lengths(cage_positions, out);
        self.table
            .update_on_threads(cage_positions, out, threads)
            .expect("threads start to update the stencils");
    }

    fn check_lengths(&self, cage_positions: &[f64], out: &[f64]) {
        assert_eq!(
            cage_positions.len(),
            self.cage_vertex_count * 3,
            "cage positions must hold xyz for {} vertices",
            self.cage_vertex_count
        );
        assert_eq!(
            out.len(),
            self.vertex_count() * 3,
            "out must hold xyz for {} vertices",
            self.vertex_count()
        );
    }
}

/// OpenSubdiv's own parallel re-evaluation: a single-precision
/// `Far::StencilTable` (what Osd's evaluators take) for the last level,
/// applied by `Osd::OmpEvaluator::EvalStencils` on a chosen number of OpenMP
/// threads. Debian's OpenSubdiv 3.5 has the OpenMP evaluator and no TBB one.
pub struct OsdParallelStencils {
    table: cxx::UniquePtr<ffi::OsdParallelStencils>,
    cage_vertex_count: usize,
}

impl OsdParallelStencils {
    /// Refines `cage`'s topology `levels` times (1..=[`MAX_LEVELS`]) and
    /// builds the stencils.
    ///
    /// # Errors
    /// As [`OsdRefiner::new`]; `levels` 0 is refused.
    pub fn new(cage: &RefMesh, options: &OsdOptions, levels: u32) -> Result<Self, ReferenceError> {
        if levels == 0 {
            return refuse("stencils need at least one level".to_owned());
        }
        let refiner = OsdRefiner::new(cage, options, levels)?;
        let table = ffi::osd_parallel_stencils_new(&refiner.inner)?;
        Ok(OsdParallelStencils {
            table,
            cage_vertex_count: cage.vertex_count(),
        })
    }

    /// The number of refined vertices (one stencil each).
    pub fn vertex_count(&self) -> usize {
        self.table.stencil_count()
    }

    /// Evaluates the stencils on `cage_positions` (xyz per cage vertex) into
    /// `out` (xyz per refined vertex) on `threads` OpenMP threads (at least
    /// one); allocates nothing.
    ///
    /// # Panics
    /// When a buffer has the wrong length, or OpenSubdiv's evaluator fails.
    pub fn update(&self, cage_positions: &[f32], out: &mut [f32], threads: u32) {
        assert_eq!(cage_positions.len(), self.cage_vertex_count * 3);
        assert_eq!(out.len(), self.vertex_count() * 3);
        self.table
            .update(cage_positions, out, threads)
            .expect("OmpEvaluator evaluates the stencils");
    }
}

type OpenMeshRun = fn(&[f64], &[u32], &[u32], u32) -> Result<ffi::OmMesh, cxx::Exception>;

fn openmesh(cage: &RefMesh, levels: u32, run: OpenMeshRun) -> Result<RefMesh, ReferenceError> {
    check_cage(cage)?;
    let mesh = run(
        &cage.positions,
        &cage.face_sizes,
        &cage.face_indices,
        levels,
    )?;
    Ok(RefMesh {
        positions: mesh.positions,
        face_sizes: mesh.face_sizes,
        face_indices: mesh.face_indices,
    })
}

/// OpenMesh's `Subdivider::Uniform::CatmullClarkT` applied `levels` times to
/// `cage` loaded into a `PolyMesh` with `Vec3d` points.
///
/// Returns OpenMesh's vertices in handle order (the cage's first, then what
/// each level adds) and its faces in handle order, each starting at the face's
/// halfedge. On closed meshes it equals OpenSubdiv; on boundaries it uses
/// (1,4,1)/6-like weights rather than the B-spline rule, so it is no
/// reference there.
///
/// # Errors
/// A malformed cage, or a face OpenMesh refuses (non-manifold edge or vertex,
/// a face flipped against its neighbour).
pub fn openmesh_catmull_clark(cage: &RefMesh, levels: u32) -> Result<RefMesh, ReferenceError> {
    openmesh(cage, levels, ffi::om_catmull_clark)
}

/// OpenMesh's `Subdivider::Uniform::LoopT` applied `levels` times to `cage`
/// loaded into a `TriMesh` with `Vec3d` points. Output order as
/// [`openmesh_catmull_clark`].
///
/// # Errors
/// As [`openmesh_catmull_clark`], and when a face is not a triangle.
pub fn openmesh_loop(cage: &RefMesh, levels: u32) -> Result<RefMesh, ReferenceError> {
    if let Some(f) = cage.face_sizes.iter().position(|&n| n != 3) {
        return refuse(format!(
            "face {f} has {} corners; OpenMesh's Loop needs triangles",
            cage.face_sizes[f]
        ));
    }
    openmesh(cage, levels, ffi::om_loop)
}
