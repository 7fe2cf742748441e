//! Mesh files and pictures, for the `weft` command and for tests.
//!
//! One file per format: [`obj`] (Wavefront OBJ, polygons kept), [`ply`]
//! (Stanford PLY, ASCII and binary either endian), [`stl`] (ASCII and binary,
//! triangles unwelded), [`off`] (Object File Format). Each has a `parse` on
//! bytes and a `write` to any [`std::io::Write`]; [`read_mesh`] and
//! [`write_mesh`] choose the format by the file's extension.
//!
//! A file may carry more than a mesh: [`read_mesh_file`] and
//! [`write_mesh_file`] keep vertex colours, UVs, normals and creases in a
//! [`MeshFile`] (what each format holds is in its module's doc, and
//! [`MeshFile::dropped_by`] says what a format would lose). [`creases`]
//! reads crease side files.
//!
//! Readers never panic, whatever the bytes: a malformed file is an
//! [`IoError::Parse`] naming the line (text) or byte offset (binary) and what
//! was expected, and every count read from a file is checked against the
//! input that remains before anything is allocated for it. Writers write to a
//! temporary file in the output's folder and rename it into place, so a
//! failure never leaves a half-written file behind.
//!
//! [`render`] draws a mesh into a PNG picture.

use std::fmt;
use std::fs;
use std::io::Write;
use std::path::{Path, PathBuf};

use glam::DVec3;
use thiserror::Error;

use crate::error::MeshError;
use crate::mend::weld::weld_owned;
use crate::mesh::{Mesh, MeshOptions};

pub use mesh_file::{
    check_creases, Colours, FileCorner, FileCrease, Materials, MeshFile, Uvs, NO_MATERIAL,
};

mod blocks;
pub mod creases;
mod decimal;
mod disk_writer;
mod mesh_file;
pub mod obj;
pub mod off;
pub mod ply;
pub mod render;
pub mod step;
pub mod stl;
mod text;

/// Where in a file a problem is: a line of a text file or a byte offset of a binary one.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Location {
    /// A 1-based line number.
    Line(usize),
    /// A 0-based byte offset.
    Byte(usize),
}

impl fmt::Display for Location {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Location::Line(n) => write!(f, "line {n}"),
            Location::Byte(n) => write!(f, "byte {n}"),
        }
    }
}

/// Why a mesh file could not be read or written.
#[derive(Debug, Error)]
pub enum IoError {
    /// The operating system refused: the file is missing, unreadable, or the disk is full.
    #[error("{}: cannot {action}: {source}", .path.display())]
    File {
        path: PathBuf,
        action: &'static str,
        source: std::io::Error,
    },
    /// The folder an output should go to does not exist.
    #[error("{}: the folder {} does not exist", .path.display(), .folder.display())]
    MissingFolder { path: PathBuf, folder: PathBuf },
    /// The extension names no format Weft knows.
    #[error("{}: unknown mesh format (use .obj, .ply, .stl or .off)", .path.display())]
    UnknownFormat { path: PathBuf },
    /// The file's content does not follow its format.
    #[error("{}{location}: {message}", file_prefix(.file))]
    Parse {
        file: Option<PathBuf>,
        location: Location,
        message: String,
    },
    /// Welding the mesh read failed (memory ran out).
    #[error("{}: cannot weld: {source}", .path.display())]
    Weld { path: PathBuf, source: crate::Error },
    /// The file is well formed but its faces do not make a valid mesh.
    #[error("{}{location}: {source}", file_prefix(.file))]
    InvalidMesh {
        file: Option<PathBuf>,
        location: Location,
        source: MeshError,
    },
}

fn file_prefix(file: &Option<PathBuf>) -> String {
    match file {
        Some(path) => format!("{}: ", path.display()),
        None => String::new(),
    }
}

impl IoError {
    /// A parse error at `location`; the message says what was expected.
    pub(crate) fn parse(location: Location, message: impl Into<String>) -> IoError {
        IoError::Parse {
            file: None,
            location,
            message: message.into(),
        }
    }

    /// Names the file a parse error came from.
    pub fn in_file(self, path: &Path) -> IoError {
        match self {
            IoError::Parse {
                location, message, ..
            } => IoError::Parse {
                file: Some(path.to_path_buf()),
                location,
                message,
            },
            IoError::InvalidMesh {
                location, source, ..
            } => IoError::InvalidMesh {
                file: Some(path.to_path_buf()),
                location,
                source,
            },
            other => other,
        }
    }

    /// The line or byte offset of a content error.
    pub fn location(&self) -> Option<Location> {
        match self {
            IoError::Parse { location, .. } | IoError::InvalidMesh { location, .. } => {
                Some(*location)
            }
            _ => None,
        }
    }
}

/// The mesh file formats.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Format {
    Obj,
    Ply,
    Stl,
    Off,
}

impl Format {
    /// The format named by a path's extension, case-insensitive.
    ///
    /// # Errors
    /// [`IoError::UnknownFormat`] for any other extension or none.
    pub fn from_path(path: &Path) -> Result<Format, IoError> {
        let ext = path
            .extension()
            .and_then(|e| e.to_str())
            .map(str::to_ascii_lowercase);
        match ext.as_deref() {
            Some("obj") => Ok(Format::Obj),
            Some("ply") => Ok(Format::Ply),
            Some("stl") => Ok(Format::Stl),
            Some("off") => Ok(Format::Off),
            _ => Err(IoError::UnknownFormat {
                path: path.to_path_buf(),
            }),
        }
    }
}

/// How PLY data is stored.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum PlyEncoding {
    Ascii,
    #[default]
    BinaryLittleEndian,
    BinaryBigEndian,
}

/// Options for reading.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ReadOptions {
    /// Merge vertices at identical positions (STL stores every triangle's
    /// corners separately), as [`weld`](crate::mend::weld::weld) at tolerance 0 does: faces that
    /// collapse are dropped, the vertices no face uses are left out.
    pub weld: bool,
    /// Accept faces that name a vertex more than once, as
    /// [`MeshOptions::allow_repeated_vertices`] (OBJ, PLY and OFF; STL's
    /// corners are always distinct).
    pub allow_repeated_vertices: bool,
}

impl ReadOptions {
    fn mesh_options(&self) -> MeshOptions {
        MeshOptions {
            allow_repeated_vertices: self.allow_repeated_vertices,
        }
    }
}

/// Options for writing.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct WriteOptions {
    /// PLY encoding; binary little endian by default.
    pub ply: PlyEncoding,
    /// Write STL as text instead of binary.
    pub stl_ascii: bool,
}

/// Reads a mesh file, choosing the format by its extension.
///
/// # Errors
/// [`IoError`] naming the file and, for bad content, the line or byte offset.
pub fn read_mesh(path: impl AsRef<Path>) -> Result<Mesh, IoError> {
    read_mesh_with(path, &ReadOptions::default())
}

/// Reads a mesh file with options (see [`ReadOptions`]).
///
/// # Errors
/// As [`read_mesh`].
pub fn read_mesh_with(path: impl AsRef<Path>, options: &ReadOptions) -> Result<Mesh, IoError> {
    let path = path.as_ref();
    let format = Format::from_path(path)?;
    if options.weld {
        // The weld follows: a soup's copies merged while reading.
        return read_mesh_to_weld(path, options).map(|read| read.mesh);
    }
    read_path(format, path, options.mesh_options(), false).map(|file| file.mesh)
}

/// A mesh read for a weld to follow (see [`read_mesh_to_weld`]).
#[derive(Debug, Clone, PartialEq)]
pub struct ReadToWeld {
    /// The mesh, whose weld is the weld of the file's mesh.
    pub mesh: Mesh,
    /// Vertices of the file merged into an exact copy of their position
    /// while reading (with `weld`, by the weld at tolerance 0 too): add them
    /// to the count of merged vertices of the weld that follows.
    pub merged_copies: usize,
}

/// Reads a mesh file that is to be welded next, as [`read_mesh_with`]
/// reads it (`options.weld` set, the weld at tolerance 0 included), but
/// for binary STL: there, the exact copies of a position near each other
/// in the file (each position of a soup, about six times) are merged while
/// reading, a block of triangles at a time, so that a sixth of the corners'
/// positions are held. The mesh's faces are the file's triangles, each
/// with three distinct vertices (a triangle whose corners are copies of
/// one another keeps them apart, for the weld to remove), and
/// [`weld`](crate::mend::weld::weld) of it at any tolerance gives the mesh
/// and the report it gives for the file's own corners, but for the copies
/// merged here, counted in [`ReadToWeld::merged_copies`].
///
/// # Errors
/// As [`read_mesh_with`]; [`IoError::Weld`] when memory runs out merging.
pub fn read_mesh_to_weld(
    path: impl AsRef<Path>,
    options: &ReadOptions,
) -> Result<ReadToWeld, IoError> {
    let path = path.as_ref();
    if Format::from_path(path)? == Format::Stl {
        if let Some((mesh, copies)) = stl::read_path_to_weld(path)? {
            let (mesh, merged) = match options.weld {
                true => weld_identical(path, mesh)?,
                false => (mesh, 0),
            };
            return Ok(ReadToWeld {
                mesh,
                merged_copies: copies + merged,
            });
        }
    }
    let (mesh, merged_copies) = match options.weld {
        true => weld_identical(
            path,
            read_mesh_with(
                path,
                &ReadOptions {
                    weld: false,
                    ..*options
                },
            )?,
        )?,
        false => (read_mesh_with(path, options)?, 0),
    };
    Ok(ReadToWeld {
        mesh,
        merged_copies,
    })
}

/// Reads a mesh file with its colours, UVs and creases (what its format
/// holds), choosing the format by its extension. With `options.weld`, the
/// welded mesh comes without them (STL holds none).
///
/// # Errors
/// As [`read_mesh`], and malformed colours, UVs or creases with their line.
pub fn read_mesh_file(path: impl AsRef<Path>, options: &ReadOptions) -> Result<MeshFile, IoError> {
    let path = path.as_ref();
    let format = Format::from_path(path)?;
    if options.weld && format == Format::Stl {
        // STL holds no attributes: its copies merged while reading.
        return read_mesh_with(path, options).map(MeshFile::new);
    }
    let file = read_path(format, path, options.mesh_options(), true)?;
    if options.weld {
        Ok(MeshFile::new(weld_identical(path, file.mesh)?.0))
    } else {
        Ok(file)
    }
}

/// A mesh file of `format` read from disk by its format's own reader: every
/// one a block at a time but binary PLY, read whole; with its attributes
/// (`attributes`: malformed ones refused) where it has them.
fn read_path(
    format: Format,
    path: &Path,
    options: MeshOptions,
    attributes: bool,
) -> Result<MeshFile, IoError> {
    match format {
        Format::Obj if attributes => obj::read_file_at(path, options),
        Format::Obj => obj::read_mesh_at(path, options).map(MeshFile::new),
        Format::Ply => ply::read_path(path, attributes, options),
        Format::Stl => stl::read_path(path).map(MeshFile::new),
        Format::Off => off::read_path(path, options).map(MeshFile::new),
    }
}

/// What a failure to read `path` becomes.
pub(crate) fn read_failed(path: &Path) -> impl Fn(std::io::Error) -> IoError + Copy + '_ {
    move |source| IoError::File {
        path: path.to_path_buf(),
        action: "read",
        source,
    }
}

/// The whole content of a file, or the error that names it.
pub(crate) fn read_bytes(path: &Path) -> Result<Vec<u8>, IoError> {
    fs::read(path).map_err(read_failed(path))
}

/// The weld of [`ReadOptions::weld`]: the library's [`weld`](crate::mend::weld::weld) at tolerance 0,
/// which merges vertices at identical positions and drops faces that
/// collapse, written over the mesh read; with how many vertices it merged.
fn weld_identical(path: &Path, mesh: Mesh) -> Result<(Mesh, usize), IoError> {
    weld_owned(mesh, 0.0)
        .map(|(welded, report)| (welded, report.merged_vertex_count))
        .map_err(|source| IoError::Weld {
            path: path.to_path_buf(),
            source,
        })
}

/// Parses the bytes of a mesh file of the given format with its colours,
/// UVs and creases.
///
/// # Errors
/// As [`parse_mesh`].
pub fn parse_mesh_file(format: Format, bytes: &[u8]) -> Result<MeshFile, IoError> {
    parse_mesh_file_with(format, bytes, MeshOptions::default(), true)
}

/// As [`parse_mesh_file`], accepting what `options` allows; with
/// `attributes` false, malformed colours or UVs do not matter (the mesh
/// alone is wanted).
fn parse_mesh_file_with(
    format: Format,
    bytes: &[u8],
    options: MeshOptions,
    attributes: bool,
) -> Result<MeshFile, IoError> {
    match format {
        Format::Obj if attributes => obj::parse_file_with(bytes, options),
        Format::Obj => obj::parse_with(bytes, options).map(MeshFile::new),
        Format::Ply => ply::read(bytes, attributes, options),
        Format::Stl => stl::parse(bytes).map(MeshFile::new),
        Format::Off => off::parse_with(bytes, options).map(MeshFile::new),
    }
}

/// Writes a mesh file with what its format can hold of the colours, UVs,
/// normals and creases ([`MeshFile::dropped_by`] lists the rest).
///
/// # Errors
/// As [`write_mesh_with`]; [`IoError::File`] also when an attribute does not
/// have one entry per vertex or corner.
pub fn write_mesh_file(
    path: impl AsRef<Path>,
    file: &MeshFile,
    options: &WriteOptions,
) -> Result<(), IoError> {
    let path = path.as_ref();
    let format = Format::from_path(path)?;
    write_atomically(path, |w| write_file_to(format, w, file, options))
}

/// Writes a mesh file in `format` to any writer (see [`write_mesh_file`]).
///
/// # Errors
/// Whatever the writer returns; [`std::io::ErrorKind::InvalidInput`] when an
/// attribute does not have one entry per vertex or corner.
pub fn write_file_to(
    format: Format,
    w: &mut dyn Write,
    file: &MeshFile,
    options: &WriteOptions,
) -> std::io::Result<()> {
    match format {
        Format::Obj => obj::write_file(w, file),
        Format::Ply => ply::write_file(w, file, options.ply),
        Format::Stl | Format::Off => write_to(format, w, &file.mesh, options),
    }
}

/// Refuses attributes whose sizes do not match the mesh.
pub(crate) fn check_attribute_sizes(file: &MeshFile) -> std::io::Result<()> {
    let mesh = &file.mesh;
    let refuse = |what: String| Err(std::io::Error::new(std::io::ErrorKind::InvalidInput, what));
    if let Some(colours) = &file.colours {
        if colours.rgba.len() != mesh.vertex_count() {
            return refuse(format!(
                "{} colours for {} vertices",
                colours.rgba.len(),
                mesh.vertex_count()
            ));
        }
    }
    if let Some(normals) = &file.normals {
        if normals.len() != mesh.vertex_count() {
            return refuse(format!(
                "{} normals for {} vertices",
                normals.len(),
                mesh.vertex_count()
            ));
        }
    }
    if let Some(uvs) = &file.uvs {
        if uvs.indices.len() != mesh.index_count() {
            return refuse(format!(
                "{} UV indices for {} face corners",
                uvs.indices.len(),
                mesh.index_count()
            ));
        }
        if let Some(&i) = uvs
            .indices
            .iter()
            .find(|&&i| i as usize >= uvs.values.len())
        {
            return refuse(format!("UV index {i} is past the {} UVs", uvs.values.len()));
        }
    }
    if let Some(materials) = &file.materials {
        if materials.face_materials.len() != mesh.face_count() {
            return refuse(format!(
                "{} face materials for {} faces",
                materials.face_materials.len(),
                mesh.face_count()
            ));
        }
        let names = materials.names.len();
        if let Some(&m) = materials
            .face_materials
            .iter()
            .find(|&&m| m != mesh_file::NO_MATERIAL && m as usize >= names)
        {
            return refuse(format!("face material {m} is past the {names} materials"));
        }
    }
    let n = mesh.vertex_count();
    if let Some(c) = file
        .creases
        .iter()
        .find(|c| c.edge.iter().any(|&v| v as usize >= n))
    {
        return refuse(format!("crease {:?} is past the {n} vertices", c.edge));
    }
    if let Some(c) = file.corners.iter().find(|c| c.vertex as usize >= n) {
        return refuse(format!("corner {} is past the {n} vertices", c.vertex));
    }
    Ok(())
}

/// Parses the bytes of a mesh file of the given format.
///
/// # Errors
/// [`IoError::Parse`] or [`IoError::InvalidMesh`] with the line or byte offset.
pub fn parse_mesh(format: Format, bytes: &[u8]) -> Result<Mesh, IoError> {
    match format {
        Format::Obj => obj::parse(bytes),
        Format::Ply => ply::parse(bytes),
        Format::Stl => stl::parse(bytes),
        Format::Off => off::parse(bytes),
    }
}

/// Writes a mesh file in the format its extension names, with default options.
///
/// # Errors
/// As [`write_mesh_with`].
pub fn write_mesh(path: impl AsRef<Path>, mesh: &Mesh) -> Result<(), IoError> {
    write_mesh_with(path, mesh, &WriteOptions::default())
}

/// Writes a mesh file in the format its extension names. STL holds only
/// triangles: polygons are written as fans.
///
/// # Errors
/// [`IoError::UnknownFormat`], [`IoError::MissingFolder`], or
/// [`IoError::File`] when the file cannot be written; the output is then left
/// as it was.
pub fn write_mesh_with(
    path: impl AsRef<Path>,
    mesh: &Mesh,
    options: &WriteOptions,
) -> Result<(), IoError> {
    let path = path.as_ref();
    let format = Format::from_path(path)?;
    write_atomically(path, |w| write_to(format, w, mesh, options))
}

/// Writes a mesh in `format` to any writer.
///
/// # Errors
/// Whatever the writer returns.
pub fn write_to(
    format: Format,
    w: &mut dyn Write,
    mesh: &Mesh,
    options: &WriteOptions,
) -> std::io::Result<()> {
    match format {
        Format::Obj => obj::write(w, mesh),
        Format::Ply => ply::write(w, mesh, options.ply),
        Format::Stl => stl::write(w, mesh, options.stl_ascii),
        Format::Off => off::write(w, mesh),
    }
}

/// Writes through `fill` into a temporary file beside `path`, puts it on
/// disk (block by block while the rest is written, past the page cache
/// where the file system allows), then renames it into
/// place: readers of `path` never see a partial file, even after a crash.
///
/// # Errors
/// [`IoError::MissingFolder`] when the folder does not exist; [`IoError::File`]
/// for anything the operating system refuses.
pub fn write_atomically(
    path: &Path,
    fill: impl FnOnce(&mut dyn Write) -> std::io::Result<()>,
) -> Result<(), IoError> {
    let folder = match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
        _ => PathBuf::from("."),
    };
    if !folder.is_dir() {
        return Err(IoError::MissingFolder {
            path: path.to_path_buf(),
            folder,
        });
    }
    let name = path
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    let temporary = folder.join(format!(".{name}.{}.partial", std::process::id()));
    let file_error = |action, source| IoError::File {
        path: path.to_path_buf(),
        action,
        source,
    };
    let result = (|| {
        let file = fs::File::create(&temporary).map_err(|e| file_error("create", e))?;
        let file = std::thread::scope(|scope| {
            let mut writer = disk_writer::DiskWriter::new(scope, &temporary, file);
            fill(&mut writer).map_err(|e| file_error("write", e))?;
            writer.finish().map_err(|e| file_error("write", e))
        })?;
        file.sync_all().map_err(|e| file_error("write", e))?;
        drop(file);
        fs::rename(&temporary, path).map_err(|e| file_error("replace", e))
    })();
    if result.is_err() {
        let _ = fs::remove_file(&temporary);
    }
    result
}

/// Builds the mesh a reader collected, turning a validation error into one at
/// the line or byte offset where the offending face or vertex was read.
pub(crate) fn build_mesh(
    positions: Vec<DVec3>,
    face_sizes: Vec<u32>,
    face_indices: Vec<u32>,
    vertex_location: impl Fn(usize) -> Location,
    face_location: impl Fn(usize) -> Location,
) -> Result<Mesh, IoError> {
    let parts = (positions, face_sizes, face_indices);
    build_mesh_with(
        parts,
        MeshOptions::default(),
        vertex_location,
        face_location,
    )
}

/// As [`build_mesh`], accepting what `options` allows.
pub(crate) fn build_mesh_with(
    (positions, face_sizes, face_indices): (Vec<DVec3>, Vec<u32>, Vec<u32>),
    options: MeshOptions,
    vertex_location: impl Fn(usize) -> Location,
    face_location: impl Fn(usize) -> Location,
) -> Result<Mesh, IoError> {
    Mesh::new_with(positions, face_sizes, face_indices, options).map_err(|source| {
        let location = match &source {
            MeshError::IndexOutOfRange { face, .. }
            | MeshError::FaceTooSmall { face, .. }
            | MeshError::RepeatedIndex { face, .. } => face_location(*face),
            MeshError::NonFiniteCoordinate { vertex, .. } => vertex_location(*vertex),
            _ => Location::Byte(0),
        };
        IoError::InvalidMesh {
            file: None,
            location,
            source,
        }
    })
}
