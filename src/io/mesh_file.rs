//! A mesh with what a file carries beside it: vertex colours, UVs, vertex
//! normals and creases. [`crate::Mesh`] holds only positions and faces; the
//! readers fill a [`MeshFile`] and [`super::read_mesh`] keeps just its mesh.

use glam::DVec3;

use super::{IoError, Location};
use crate::mesh::topology::Topology;
use crate::mesh::Mesh;
use crate::subdivide::{Crease, SHARPNESS_INFINITE};

/// A mesh and the data a file carries with it. Every part but the mesh is
/// optional; what a format cannot hold is listed by [`MeshFile::dropped_by`].
#[derive(Debug, Clone, PartialEq, Default)]
pub struct MeshFile {
    pub mesh: Mesh,
    /// One colour per vertex.
    pub colours: Option<Colours>,
    /// Texture coordinates per face corner.
    pub uvs: Option<Uvs>,
    /// One unit normal per vertex. Written (OBJ `vn`, PLY `nx ny nz`), never
    /// read: normals of an input would not survive any operation.
    pub normals: Option<Vec<DVec3>>,
    /// Creased edges (OBJ `l` polylines and `t crease` tags, or a side file).
    pub creases: Vec<FileCrease>,
    /// Sharp vertices (OBJ `t corner` tags, or a side file).
    pub corners: Vec<FileCorner>,
    /// OBJ materials: the libraries named and each face's material.
    pub materials: Option<Materials>,
    /// Faces that subdivision leaves out (OBJ `t hole` tags, OpenSubdiv's
    /// hole faces), ascending, each once.
    pub holes: Vec<u32>,
}

/// A face with no material (before the file's first `usemtl`).
pub const NO_MATERIAL: u32 = u32::MAX;

/// OBJ materials: the material libraries a file names (`mtllib`), the
/// materials its faces use (`usemtl`), and the material of every face.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Materials {
    /// The `mtllib` file names, in the order named.
    pub libraries: Vec<String>,
    /// The material names, in the order first used.
    pub names: Vec<String>,
    /// For every face, its index in `names`, or [`NO_MATERIAL`].
    pub face_materials: Vec<u32>,
}

impl Materials {
    /// The materials of faces made from others: face `i` takes the material
    /// of face `parent_faces[i]` (subdivision's children, a triangulation's
    /// triangles).
    pub fn inherited(&self, parent_faces: &[u32]) -> Materials {
        Materials {
            libraries: self.libraries.clone(),
            names: self.names.clone(),
            face_materials: parent_faces
                .iter()
                .map(|&f| self.face_materials[f as usize])
                .collect(),
        }
    }
}

/// Vertex colours, red, green, blue and alpha from 0 to 1 (alpha 1 when the
/// file has none).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Colours {
    pub rgba: Vec<[f64; 4]>,
    /// Whether the file gave an alpha channel (and a writer should keep it).
    pub alpha: bool,
}

/// Face-varying texture coordinates: a list of values and, for every face
/// corner (face after face, as [`Mesh::face_indices`]), the value it uses.
/// Corners of one vertex may use different values (a UV seam).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Uvs {
    pub values: Vec<[f64; 2]>,
    pub indices: Vec<u32>,
}

impl Uvs {
    /// One value per vertex when every corner of each vertex uses the same
    /// value (no seams; what PLY's per-vertex `s t` can hold), else `None`.
    /// A vertex without faces gets (0, 0).
    pub fn per_vertex(&self, mesh: &Mesh) -> Option<Vec<[f64; 2]>> {
        let mut per_vertex: Vec<Option<[f64; 2]>> = vec![None; mesh.vertex_count()];
        for (&v, &i) in mesh.face_indices().iter().zip(&self.indices) {
            let value = *self.values.get(i as usize)?;
            match &mut per_vertex[v as usize] {
                slot @ None => *slot = Some(value),
                Some(seen) if *seen == value => {}
                Some(_) => return None,
            }
        }
        Some(
            per_vertex
                .into_iter()
                .map(|v| v.unwrap_or([0.0; 2]))
                .collect(),
        )
    }

    /// Per-vertex values as face-varying ones: each corner uses its vertex's value.
    pub fn from_per_vertex(mesh: &Mesh, values: Vec<[f64; 2]>) -> Uvs {
        Uvs {
            values,
            indices: mesh.face_indices().to_vec(),
        }
    }
}

/// A creased edge read from a file: its two vertices (0-based), its
/// sharpness (0 smooth, [`SHARPNESS_INFINITE`] or more a hard crease) and the
/// line it was read from (0 when made in code).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FileCrease {
    pub edge: [u32; 2],
    pub sharpness: f64,
    pub line: usize,
}

/// A sharp vertex read from a file: its index (0-based), sharpness and line.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FileCorner {
    pub vertex: u32,
    pub sharpness: f64,
    pub line: usize,
}

impl MeshFile {
    /// A file holding only a mesh.
    pub fn new(mesh: Mesh) -> MeshFile {
        MeshFile {
            mesh,
            ..MeshFile::default()
        }
    }

    /// Whether anything besides the mesh is held.
    pub fn has_attributes(&self) -> bool {
        !self.attribute_names().is_empty()
    }

    /// Names of what is held besides the mesh, for messages.
    pub fn attribute_names(&self) -> Vec<&'static str> {
        let mut names = Vec::new();
        if self.colours.is_some() {
            names.push("vertex colours");
        }
        if self.uvs.is_some() {
            names.push("UVs");
        }
        if self.normals.is_some() {
            names.push("normals");
        }
        if !self.creases.is_empty() {
            names.push("creases");
        }
        if !self.corners.is_empty() {
            names.push("corners");
        }
        if self.materials.is_some() {
            names.push("materials");
        }
        if !self.holes.is_empty() {
            names.push("holes");
        }
        names
    }

    /// What writing this in `format` would lose: OBJ holds everything; PLY
    /// colours, normals and UVs without seams; OFF and STL only the mesh.
    /// (Materials are OBJ's alone.)
    pub fn dropped_by(&self, format: super::Format) -> Vec<&'static str> {
        use super::Format;
        let mut dropped = self.attribute_names();
        match format {
            Format::Obj => dropped.clear(),
            Format::Ply => dropped.retain(|&name| match name {
                "vertex colours" | "normals" => false,
                "UVs" => self
                    .uvs
                    .as_ref()
                    .is_some_and(|uvs| uvs.per_vertex(&self.mesh).is_none()),
                _ => true,
            }),
            Format::Off | Format::Stl => {}
        }
        dropped
    }

    /// The creases as [`crate::subdivide::SubdivisionOptions`] wants them.
    pub fn subdivision_creases(&self) -> Vec<Crease> {
        self.creases.iter().map(|c| (c.edge, c.sharpness)).collect()
    }

    /// The corners as [`crate::subdivide::SubdivisionOptions`] wants them.
    pub fn subdivision_corners(&self) -> Vec<(u32, f64)> {
        self.corners
            .iter()
            .map(|c| (c.vertex, c.sharpness))
            .collect()
    }

    /// Checks that every crease joins two vertices that share an edge of the
    /// mesh and every corner is one of its vertices.
    ///
    /// # Errors
    /// [`IoError::Parse`] at the line of the first crease or corner that is not.
    pub fn check_creases(&self) -> Result<(), IoError> {
        check_creases(&self.mesh, &self.creases, &self.corners)
    }
}

/// Checks creases and corners against `mesh` (see [`MeshFile::check_creases`]).
///
/// # Errors
/// [`IoError::Parse`] at the line of the first crease whose vertices are not
/// an edge, or the first corner past the last vertex.
pub fn check_creases(
    mesh: &Mesh,
    creases: &[FileCrease],
    corners: &[FileCorner],
) -> Result<(), IoError> {
    let n = mesh.vertex_count();
    if !creases.is_empty() {
        let topology = Topology::new(mesh);
        for c in creases {
            let [a, b] = c.edge;
            let problem = if a as usize >= n || b as usize >= n {
                Some(format!("the mesh has {n} vertices (0 to {})", n.max(1) - 1))
            } else if topology.find_edge(a, b).is_none() {
                Some("they are not joined by an edge of the mesh".to_owned())
            } else {
                None
            };
            if let Some(problem) = problem {
                return Err(IoError::parse(
                    Location::Line(c.line),
                    format!("the crease from vertex {a} to vertex {b} cannot be used: {problem}"),
                ));
            }
        }
    }
    if let Some(c) = corners.iter().find(|c| c.vertex as usize >= n) {
        return Err(IoError::parse(
            Location::Line(c.line),
            format!(
                "corner vertex {} is past the last vertex: the mesh has {n} vertices (0 to {})",
                c.vertex,
                n.max(1) - 1
            ),
        ));
    }
    Ok(())
}

/// Reads a sharpness: a number of 0 or more, or `inf`/`infinite`/`infinity`
/// for [`SHARPNESS_INFINITE`].
pub(crate) fn parse_sharpness(word: &[u8], line: usize) -> Result<f64, IoError> {
    let text = std::str::from_utf8(word).unwrap_or("").to_ascii_lowercase();
    if matches!(text.as_str(), "inf" | "infinite" | "infinity") {
        return Ok(SHARPNESS_INFINITE);
    }
    match text.parse::<f64>() {
        Ok(s) if s.is_finite() && s >= 0.0 => Ok(s.min(SHARPNESS_INFINITE)),
        _ => Err(IoError::parse(
            Location::Line(line),
            format!(
                "expected a sharpness (a number of 0 or more, or \"inf\"), found {}",
                super::text::show(word)
            ),
        )),
    }
}
