//! Wavefront OBJ: vertices, faces, vertex colours, UVs, normals and creases;
//! polygons are kept as polygons.
//!
//! Read:
//! - `v x y z`, optionally followed by `w` (ignored) or by a colour `r g b`
//!   or `r g b a` from 0 to 1 (the common extension of MeshLab and others);
//!   when one vertex has a colour, every vertex must.
//! - `vt u v [w]` texture coordinates (w ignored).
//! - `f` corners as `v`, `v/vt`, `v/vt/vn` or `v//vn`, positive (1-based) or
//!   negative (relative to the vertices or UVs read so far) indices; when one
//!   corner names a `vt`, every corner of every face must.
//! - `l` polylines: every segment is an infinitely sharp crease (the
//!   polyline's vertices must be joined by edges of the mesh where the
//!   creases are used).
//! - OpenSubdiv's tags with 0-based indices: `t crease 2/1/0 i j s` (more
//!   indices make a chain; one sharpness for all, or one per segment) and
//!   `t corner 1/1/0 v s` (more vertices, one sharpness or one each), and
//!   `t hole N/0/0 f1 … fN`, faces that subdivision leaves out.
//! - `mtllib` file names and `usemtl` materials: each face keeps the
//!   material in force where it stands.
//!   Other tags, `vn` (normals are recomputed by whatever needs them),
//!   comments, groups and any other statement are ignored.
//!
//! Write: `v x y z [r g b [a]]` with round-trip exact numbers, `vn` and `vt`
//! when present, `f` with 1-based `v`, `v/vt`, `v//vn` or `v/vt/vn`
//! corners, infinitely sharp creases as `l` segments and the others and the
//! corners and holes as `t` tags; `mtllib` and a `usemtl` wherever the material
//! changes.

use std::collections::HashMap;
use std::io::Write;
use std::path::Path;

use glam::DVec3;

use super::blocks::write_in_blocks;
use super::decimal::{push_f64, push_fixed, push_u64, put_f64, put_u64, F64_ROOM};
use super::mesh_file::{Colours, FileCorner, FileCrease, Materials, MeshFile, Uvs, NO_MATERIAL};
use super::text::{lines, parse_f64, parse_i64, show, words};
use super::{build_mesh_with, IoError, Location};
use crate::mesh::{Mesh, MeshOptions};
use crate::subdivide::SHARPNESS_INFINITE;
use tags::tag;

mod fast;
mod tags;

/// Parses an OBJ file into its mesh alone.
///
/// # Errors
/// As [`parse_file`].
pub fn parse(data: &[u8]) -> Result<Mesh, IoError> {
    parse_with(data, MeshOptions::default())
}

/// As [`parse`], accepting what `options` allows.
pub(crate) fn parse_with(data: &[u8], options: MeshOptions) -> Result<Mesh, IoError> {
    // The mesh alone: problems with colours, UVs or creases do not matter.
    read(data, options).map(|(file, _)| file.mesh)
}

/// Parses an OBJ file with its colours, UVs and creases.
///
/// # Errors
/// [`IoError::Parse`] for a line that is not what OBJ expects (a missing or
/// non-numeric coordinate, an index of 0 or one reaching before the first
/// vertex or UV, a vertex without a colour when others have one, a face
/// without UVs when others have them, a malformed `l` or `t`);
/// [`IoError::InvalidMesh`] for a face the mesh rejects (an index past the
/// last vertex, fewer than 3 corners, a repeated vertex), each with its line.
pub fn parse_file(data: &[u8]) -> Result<MeshFile, IoError> {
    parse_file_with(data, MeshOptions::default())
}

/// As [`parse_file`], accepting what `options` allows.
pub(crate) fn parse_file_with(data: &[u8], options: MeshOptions) -> Result<MeshFile, IoError> {
    with_attribute_error(read(data, options))
}

fn with_attribute_error(
    read: Result<(MeshFile, Option<IoError>), IoError>,
) -> Result<MeshFile, IoError> {
    match read? {
        (_, Some(attribute_error)) => Err(attribute_error),
        (file, None) => Ok(file),
    }
}

/// Reads the mesh and its attributes: on all threads when every line is
/// well formed (the common case), else line by line, which finds the first
/// problem and its line. The two give the same result. (The fast reader
/// builds its meshes with the default checks: a face `options` lets
/// through sends the file to the line-by-line reader.)
fn read(data: &[u8], options: MeshOptions) -> Result<(MeshFile, Option<IoError>), IoError> {
    match fast::read_bytes(data, fast::BLOCK, fast::PIECE) {
        Some(file) => Ok((file, None)),
        None => read_sequential(data, options),
    }
}

/// Reads an OBJ file from disk a block at a time, never holding all its
/// bytes (see [`read`]); returns the first problem with an attribute
/// beside the file. Errors name the file.
pub(crate) fn read_path(
    path: &Path,
    options: MeshOptions,
) -> Result<(MeshFile, Option<IoError>), IoError> {
    let failed = super::read_failed(path);
    let file = std::fs::File::open(path).map_err(failed)?;
    match fast::read_source(file, fast::BLOCK, fast::PIECE).map_err(failed)? {
        Some(file) => Ok((file, None)),
        None => {
            let data = super::read_bytes(path)?;
            read_sequential(&data, options)
                .map(|(file, problem)| (file, problem.map(|e| e.in_file(path))))
                .map_err(|e| e.in_file(path))
        }
    }
}

/// As [`parse_file`], for a file on disk.
pub(crate) fn read_file_at(path: &Path, options: MeshOptions) -> Result<MeshFile, IoError> {
    with_attribute_error(read_path(path, options))
}

/// As [`parse`], for a file on disk.
pub(crate) fn read_mesh_at(path: &Path, options: MeshOptions) -> Result<Mesh, IoError> {
    read_path(path, options).map(|(file, _)| file.mesh)
}

/// Reads the mesh and its attributes line by line; returns the first
/// problem with an attribute beside the file instead of failing on it.
fn read_sequential(
    data: &[u8],
    options: MeshOptions,
) -> Result<(MeshFile, Option<IoError>), IoError> {
    let mut attribute_error: Option<IoError> = None;
    let mut note = |e: IoError| {
        if attribute_error.is_none() {
            attribute_error = Some(e);
        }
    };
    let mut positions = Vec::new();
    let mut vertex_lines = Vec::new();
    // The colour of every vertex, and the line of the first vertex read.
    let mut colours: Vec<Option<[f64; 4]>> = Vec::new();
    let mut alpha = false;
    let mut uv_values: Vec<[f64; 2]> = Vec::new();
    let mut uv_indices: Vec<u32> = Vec::new();
    // Whether faces name UVs, and the line of the first face.
    let mut faces_have_uvs: Option<(bool, usize)> = None;
    let mut face_sizes = Vec::new();
    let mut face_indices = Vec::new();
    let mut face_lines = Vec::new();
    let mut statements = Statements::new();
    for (line, text) in lines(data) {
        let mut w = words(text);
        match w.next() {
            Some(b"v") => {
                let numbers: Vec<&[u8]> = w.collect();
                let names = ["x", "y", "z", "w or red", "green", "blue", "alpha"];
                if numbers.len() < 3 {
                    return Err(IoError::parse(
                        Location::Line(line),
                        format!(
                            "expected 3 coordinates after \"v\"; {} is missing",
                            names[numbers.len()]
                        ),
                    ));
                }
                if numbers.len() == 5 || numbers.len() > 7 {
                    note(IoError::parse(
                        Location::Line(line),
                        format!(
                            "expected \"v x y z\", \"v x y z w\", \"v x y z r g b\" or \
                             \"v x y z r g b a\"; found {} numbers",
                            numbers.len()
                        ),
                    ));
                }
                let mut values = [0.0; 7];
                for (k, ((word, value), name)) in
                    numbers.iter().zip(&mut values).zip(names).enumerate()
                {
                    match parse_f64(word, line, name) {
                        Ok(x) => *value = x,
                        Err(e) if k < 3 => return Err(e),
                        Err(e) => note(e),
                    }
                }
                positions.push(DVec3::new(values[0], values[1], values[2]));
                vertex_lines.push(line);
                let colour = match numbers.len() {
                    6 => Some([values[3], values[4], values[5], 1.0]),
                    7 => {
                        alpha = true;
                        Some([values[3], values[4], values[5], values[6]])
                    }
                    _ => None,
                };
                if let Some(c) = colour {
                    if let Some(k) = c.iter().position(|x| !x.is_finite()) {
                        note(IoError::parse(
                            Location::Line(line),
                            format!("colour channel {} is not a finite number", names[3 + k]),
                        ));
                    }
                }
                if let Some(first) = colours.first() {
                    if first.is_some() != colour.is_some() {
                        let (has, lacks) = if colour.is_some() {
                            (line, vertex_lines[0])
                        } else {
                            (vertex_lines[0], line)
                        };
                        note(IoError::parse(
                            Location::Line(line),
                            format!(
                                "vertex {} has {} colour: every vertex must have a colour \
                                 (\"v x y z r g b\") or none (line {has} has one, line {lacks} \
                                 has none)",
                                positions.len(),
                                if colour.is_some() { "a" } else { "no" }
                            ),
                        ));
                    }
                }
                colours.push(colour);
            }
            Some(b"vt") => {
                let mut uv = [0.0; 2];
                match w.next() {
                    None => note(IoError::parse(Location::Line(line), "expected \"vt u v\"")),
                    Some(u) => {
                        let v = w.next();
                        let parsed = parse_f64(u, line, "texture coordinate u").and_then(|u| {
                            let v =
                                v.map_or(Ok(0.0), |v| parse_f64(v, line, "texture coordinate v"))?;
                            Ok([u, v])
                        });
                        match parsed {
                            Ok(value) => uv = value,
                            Err(e) => note(e),
                        }
                    }
                }
                uv_values.push(uv);
            }
            Some(b"f") => {
                let mut size = 0u32;
                for corner in w {
                    let mut parts = corner.split(|&b| b == b'/');
                    let index = parts.next().unwrap_or(corner);
                    let value = parse_i64(index, line, "a vertex index")?;
                    face_indices.push(resolve(value, positions.len(), line, corner, "vertex")?);
                    let uv = parts.next().filter(|t| !t.is_empty());
                    let (has_uvs, first_line) = *faces_have_uvs.get_or_insert((uv.is_some(), line));
                    if has_uvs != uv.is_some() {
                        note(IoError::parse(
                            Location::Line(line),
                            format!(
                                "corner {} {} a texture coordinate but the face on line \
                                 {first_line} {}: every corner must name one (\"v/vt\") or none",
                                show(corner),
                                if uv.is_some() {
                                    "names"
                                } else {
                                    "does not name"
                                },
                                if has_uvs { "does" } else { "does not" }
                            ),
                        ));
                    }
                    if let Some(uv) = uv {
                        let index =
                            parse_i64(uv, line, "a texture coordinate index").and_then(|value| {
                                resolve(value, uv_values.len(), line, corner, "texture coordinate")
                            });
                        match index {
                            Ok(i) => uv_indices.push(i),
                            Err(e) => {
                                note(e);
                                uv_indices.push(0);
                            }
                        }
                    }
                    size = size.saturating_add(1);
                }
                face_sizes.push(size);
                face_lines.push(line);
                statements.face();
            }
            Some(b"mtllib") => statements.mtllib(w),
            Some(b"usemtl") => statements.usemtl(text),
            Some(b"l") => {
                if let Some(e) = statements.polyline(w, line, positions.len()) {
                    note(e);
                }
            }
            Some(b"t") => {
                if let Err(e) = statements.tag(w, line) {
                    note(e);
                }
            }
            _ => {}
        }
    }
    let colours = match colours.first() {
        Some(Some(_)) => Some(colours.into_iter().flatten().collect()),
        _ => None,
    };
    let collected = Collected {
        positions,
        vertex_lines,
        colours,
        alpha,
        uv_values,
        uv_indices,
        has_uvs: faces_have_uvs.is_some_and(|(uvs, _)| uvs),
        face_sizes,
        face_indices,
        face_lines,
        statements,
    };
    collected.finish(attribute_error, options)
}

/// What a pass over the lines gathers, before the checks that need the
/// whole file. The line-by-line reader and the parallel one both make it.
pub(super) struct Collected {
    pub(super) positions: Vec<DVec3>,
    /// The line of each vertex; empty when the reader did not keep them
    /// (a problem is then found again line by line).
    pub(super) vertex_lines: Vec<usize>,
    /// One colour per vertex, when the first vertex has one.
    pub(super) colours: Option<Vec<[f64; 4]>>,
    pub(super) alpha: bool,
    pub(super) uv_values: Vec<[f64; 2]>,
    pub(super) uv_indices: Vec<u32>,
    /// Whether the faces name UVs.
    pub(super) has_uvs: bool,
    pub(super) face_sizes: Vec<u32>,
    pub(super) face_indices: Vec<u32>,
    /// The line of each face; empty as `vertex_lines`.
    pub(super) face_lines: Vec<usize>,
    pub(super) statements: Statements,
}

/// The statements besides vertices and faces: polylines, tags and
/// materials, read in file order by both readers.
#[derive(Default)]
pub(super) struct Statements {
    pub(super) creases: Vec<FileCrease>,
    pub(super) corners: Vec<FileCorner>,
    pub(super) holes: Vec<(u32, usize)>,
    /// Polyline vertices to check against the vertex count at the end.
    pub(super) line_vertices: Vec<(u32, usize)>,
    pub(super) materials: Materials,
    /// The material in force.
    material: u32,
    /// Faces read before any material, not yet in `materials` (most files
    /// have no materials, and then none are stored).
    unwritten: usize,
    material_index: HashMap<Vec<u8>, u32>,
}

impl Statements {
    pub(super) fn new() -> Statements {
        Statements {
            material: NO_MATERIAL,
            ..Statements::default()
        }
    }

    /// A face was read: it takes the material in force.
    pub(super) fn face(&mut self) {
        self.faces(1);
    }

    /// `count` faces were read without a material statement among them.
    pub(super) fn faces(&mut self, count: usize) {
        if self.material == NO_MATERIAL && self.materials.face_materials.is_empty() {
            self.unwritten += count;
        } else {
            self.write_materials();
            let materials = &mut self.materials.face_materials;
            materials.resize(materials.len() + count, self.material);
        }
    }

    /// Stores the materials of the faces read before any.
    fn write_materials(&mut self) {
        if self.unwritten > 0 {
            self.materials
                .face_materials
                .resize(self.unwritten, NO_MATERIAL);
            self.unwritten = 0;
        }
    }

    /// `mtllib` and its file names.
    pub(super) fn mtllib<'a>(&mut self, words: impl Iterator<Item = &'a [u8]>) {
        self.materials
            .libraries
            .extend(words.map(|name| String::from_utf8_lossy(name).into_owned()));
    }

    /// `usemtl` on the line `text`.
    pub(super) fn usemtl(&mut self, text: &[u8]) {
        // The name is the rest of the line: names may hold spaces.
        let name = rest_of_line(text, b"usemtl");
        let next = self.materials.names.len() as u32;
        let names = &mut self.materials.names;
        self.material = *self.material_index.entry(name.to_vec()).or_insert_with(|| {
            names.push(String::from_utf8_lossy(name).into_owned());
            next
        });
    }

    /// `l` and its vertex indices, `vertex_count` vertices having been read:
    /// every segment an infinitely sharp crease. Returns the first problem.
    pub(super) fn polyline<'a>(
        &mut self,
        words: impl Iterator<Item = &'a [u8]>,
        line: usize,
        vertex_count: usize,
    ) -> Option<IoError> {
        let mut previous = None;
        let mut count = 0;
        for corner in words {
            let index = corner.split(|&b| b == b'/').next().unwrap_or(corner);
            let v = match parse_i64(index, line, "a vertex index")
                .and_then(|value| resolve(value, vertex_count, line, corner, "vertex"))
            {
                Ok(v) => v,
                Err(e) => return Some(e),
            };
            self.line_vertices.push((v, line));
            if let Some(p) = previous.filter(|&p| p != v) {
                self.creases.push(FileCrease {
                    edge: [p, v],
                    sharpness: SHARPNESS_INFINITE,
                    line,
                });
            }
            previous = Some(v);
            count += 1;
        }
        (count < 2).then(|| {
            IoError::parse(
                Location::Line(line),
                "expected \"l\" and at least 2 vertex indices",
            )
        })
    }

    /// `t` and its words: an OpenSubdiv tag.
    pub(super) fn tag<'a>(
        &mut self,
        words: impl Iterator<Item = &'a [u8]>,
        line: usize,
    ) -> Result<(), IoError> {
        tag(
            words.collect(),
            line,
            &mut self.creases,
            &mut self.corners,
            &mut self.holes,
        )
    }
}

impl Collected {
    /// The checks that need the whole file, and the mesh; `attribute_error`
    /// is the first problem with an attribute found while reading.
    pub(super) fn finish(
        self,
        attribute_error: Option<IoError>,
        options: MeshOptions,
    ) -> Result<(MeshFile, Option<IoError>), IoError> {
        let mut attribute_error = attribute_error;
        let mut note = |e: IoError| {
            if attribute_error.is_none() {
                attribute_error = Some(e);
            }
        };
        let Collected {
            positions,
            vertex_lines,
            colours,
            alpha,
            uv_values,
            uv_indices,
            has_uvs,
            face_sizes,
            face_indices,
            face_lines,
            statements,
        } = self;
        let mut statements = statements;
        let kept = &statements.materials;
        if !kept.libraries.is_empty() || !kept.names.is_empty() {
            statements.write_materials();
        }
        let Statements {
            creases,
            corners,
            holes,
            line_vertices,
            materials,
            ..
        } = statements;
        let line_of =
            |lines: &[usize], k: usize| Location::Line(lines.get(k).copied().unwrap_or(0));
        let tagged = creases
            .iter()
            .flat_map(|c| c.edge.map(|v| (v, c.line)))
            .chain(corners.iter().map(|c| (c.vertex, c.line)));
        if let Some((v, line)) = tagged
            .filter(|(v, _)| *v as usize >= positions.len())
            .min_by_key(|&(_, line)| line)
        {
            note(IoError::parse(
                Location::Line(line),
                format!(
                    "vertex {v} is past the last vertex: the file has {} (0 to {} in tags)",
                    positions.len(),
                    positions.len().max(1) - 1
                ),
            ));
        }
        if let Some(&(f, line)) = holes
            .iter()
            .filter(|(f, _)| *f as usize >= face_sizes.len())
            .min_by_key(|&&(_, line)| line)
        {
            note(IoError::parse(
                Location::Line(line),
                format!(
                    "hole face {f} is past the last face: the file has {} (0 to {} in tags)",
                    face_sizes.len(),
                    face_sizes.len().max(1) - 1
                ),
            ));
        }
        let mut holes: Vec<u32> = holes
            .into_iter()
            .map(|(f, _)| f)
            .filter(|&f| (f as usize) < face_sizes.len())
            .collect();
        holes.sort_unstable();
        holes.dedup();
        if let Some(&(v, line)) = line_vertices
            .iter()
            .find(|(v, _)| *v as usize >= positions.len())
        {
            note(IoError::parse(
                Location::Line(line),
                format!(
                    "polyline vertex {} is past the last vertex ({})",
                    v as u64 + 1,
                    positions.len()
                ),
            ));
        }
        if let Some(i) = uv_indices
            .iter()
            .position(|&i| i as usize >= uv_values.len())
        {
            // Find the face of corner i for its line.
            let face = face_sizes
                .iter()
                .scan(0usize, |end, &s| {
                    *end += s as usize;
                    Some(*end)
                })
                .position(|end| end > i)
                .unwrap_or(0);
            note(IoError::parse(
                line_of(&face_lines, face),
                format!(
                    "texture coordinate index {} is past the last \"vt\" ({})",
                    uv_indices[i] as u64 + 1,
                    uv_values.len()
                ),
            ));
        }
        let mesh = build_mesh_with(
            (positions, face_sizes, face_indices),
            options,
            |v| line_of(&vertex_lines, v),
            |f| line_of(&face_lines, f),
        )?;
        let colours = colours.map(|rgba| Colours { rgba, alpha });
        let file = MeshFile {
            mesh,
            colours,
            uvs: has_uvs.then_some(Uvs {
                values: uv_values,
                indices: uv_indices,
            }),
            normals: None,
            creases,
            corners,
            materials: (!materials.libraries.is_empty() || !materials.names.is_empty())
                .then_some(materials),
            holes,
        };
        Ok((file, attribute_error))
    }
}

/// The text of a line after its keyword, without surrounding white space.
fn rest_of_line<'a>(text: &'a [u8], keyword: &[u8]) -> &'a [u8] {
    let start = text
        .windows(keyword.len())
        .position(|w| w == keyword)
        .map_or(text.len(), |at| at + keyword.len());
    text[start..].trim_ascii()
}

/// Turns an OBJ index (1-based, or negative from the end) into a 0-based one.
fn resolve(value: i64, count: usize, line: usize, word: &[u8], what: &str) -> Result<u32, IoError> {
    let index = match value {
        0 => None,
        v if v > 0 => Some(v - 1),
        v => (count as i64).checked_add(v).filter(|&i| i >= 0),
    };
    index.and_then(|i| u32::try_from(i).ok()).ok_or_else(|| {
        IoError::parse(
            Location::Line(line),
            format!(
                "{what} index {} is invalid: expected 1 to {count} or -1 to -{count}",
                show(word)
            ),
        )
    })
}

/// Writes a mesh as OBJ.
///
/// # Errors
/// Whatever the writer returns.
pub fn write(w: &mut dyn Write, mesh: &Mesh) -> std::io::Result<()> {
    // No attributes to write: the mesh is not copied into a file.
    write_with(w, mesh, &MeshFile::default())
}

/// Writes a mesh with its colours, normals, UVs, creases and corners as OBJ.
///
/// # Errors
/// Whatever the writer returns; [`std::io::ErrorKind::InvalidInput`] when an
/// attribute does not have one entry per vertex (or corner).
pub fn write_file(w: &mut dyn Write, file: &MeshFile) -> std::io::Result<()> {
    super::check_attribute_sizes(file)?;
    write_with(w, &file.mesh, file)
}

/// Writes `mesh` with the attributes `file` holds (checked for `mesh`, or
/// none at all).
fn write_with(w: &mut dyn Write, mesh: &Mesh, file: &MeshFile) -> std::io::Result<()> {
    writeln!(
        w,
        "# weft {}: {} vertices, {} faces",
        crate::VERSION,
        mesh.vertex_count(),
        mesh.face_count()
    )?;
    let positions = mesh.positions();
    write_in_blocks(w, positions.len(), |vertices, w| {
        // `v`, then a space and a coordinate each, and the line's end.
        let mut line = [0u8; 1 + 3 * (1 + F64_ROOM) + 1];
        line[0] = b'v';
        for i in vertices {
            let p = positions[i];
            // Most lines are put together on the stack and appended at once.
            if file.colours.is_none() {
                let mut end = Some(1);
                for c in [p.x, p.y, p.z] {
                    end = end.and_then(|at| {
                        line[at] = b' ';
                        put_f64(&mut line, at + 1, c)
                    });
                }
                if let Some(end) = end {
                    line[end] = b'\n';
                    push_fixed(w, &line, end + 1);
                    continue;
                }
            }
            w.extend_from_slice(b"v ");
            push_f64(w, p.x);
            w.push(b' ');
            push_f64(w, p.y);
            w.push(b' ');
            push_f64(w, p.z);
            if let Some(colours) = &file.colours {
                let [r, g, b, a] = colours.rgba[i];
                write!(w, " {r} {g} {b}")?;
                if colours.alpha {
                    write!(w, " {a}")?;
                }
            }
            w.push(b'\n');
        }
        Ok(())
    })?;
    if let Some(normals) = &file.normals {
        for n in normals {
            writeln!(w, "vn {} {} {}", n.x, n.y, n.z)?;
        }
    }
    if let Some(uvs) = &file.uvs {
        for [u, v] in &uvs.values {
            writeln!(w, "vt {u} {v}")?;
        }
    }
    let materials = file.materials.as_ref();
    if let Some(libraries) = materials.map(|m| &m.libraries).filter(|l| !l.is_empty()) {
        writeln!(w, "mtllib {}", libraries.join(" "))?;
    }
    if file.uvs.is_none() && file.normals.is_none() && materials.is_none() {
        return write_plain_faces(w, mesh).and_then(|()| write_tags(w, file));
    }
    write_in_blocks(w, mesh.face_count(), |faces, w| {
        // The material in force after the face before the block.
        let mut current = match (materials, faces.start) {
            (Some(m), f) if f > 0 => m.face_materials[f - 1],
            _ => NO_MATERIAL,
        };
        let mut corner = mesh.face_start(faces.start);
        for f in faces {
            if let Some(m) = materials {
                let material = m.face_materials[f];
                if material != current && material != NO_MATERIAL {
                    writeln!(w, "usemtl {}", m.names[material as usize])?;
                }
                current = material;
            }
            w.push(b'f');
            for &v in mesh.face(f) {
                let v = v as u64 + 1;
                match (&file.uvs, &file.normals) {
                    (None, None) => {
                        w.push(b' ');
                        push_u64(w, v);
                    }
                    (Some(uvs), None) => write!(w, " {v}/{}", uvs.indices[corner] as u64 + 1)?,
                    (None, Some(_)) => write!(w, " {v}//{v}")?,
                    (Some(uvs), Some(_)) => {
                        write!(w, " {v}/{}/{v}", uvs.indices[corner] as u64 + 1)?
                    }
                }
                corner += 1;
            }
            w.push(b'\n');
        }
        Ok(())
    })?;
    write_tags(w, file)
}

/// Faces with nothing but their vertices (`f 1 2 3`), each line put
/// together on the stack and appended at once: most meshes' faces.
fn write_plain_faces(w: &mut dyn Write, mesh: &Mesh) -> std::io::Result<()> {
    write_in_blocks(w, mesh.face_count(), |faces, w| {
        // `f`, then a space and at most 10 digits a corner (a `u32` index
        // plus one), and the line's end: triangles and quads in a line
        // short enough to be appended by a few moves, up to octagons in a
        // longer one.
        let mut short = [0u8; 48];
        let mut long = [0u8; 96];
        for f in faces {
            let face = mesh.face(f);
            match face.len() {
                ..=4 => push_face_line(w, &mut short, face),
                5..=8 => push_face_line(w, &mut long, face),
                _ => {
                    w.push(b'f');
                    for &v in face {
                        w.push(b' ');
                        push_u64(w, v as u64 + 1);
                    }
                    w.push(b'\n');
                }
            }
        }
        Ok(())
    })
}

/// Appends the `f` line of `face`, put together in `line`, which has room
/// for its corners.
#[inline(always)]
fn push_face_line<const N: usize>(w: &mut Vec<u8>, line: &mut [u8; N], face: &[u32]) {
    line[0] = b'f';
    let mut end = 1;
    for &v in face {
        line[end] = b' ';
        end = put_u64(line, end + 1, v as u64 + 1);
    }
    line[end] = b'\n';
    push_fixed(w, line, end + 1);
}

/// The creases, corners and holes of `file` as `l` and `t` lines.
fn write_tags(w: &mut dyn Write, file: &MeshFile) -> std::io::Result<()> {
    for c in &file.creases {
        let [a, b] = c.edge;
        if c.sharpness >= SHARPNESS_INFINITE {
            writeln!(w, "l {} {}", a as u64 + 1, b as u64 + 1)?;
        } else {
            writeln!(w, "t crease 2/1/0 {a} {b} {}", c.sharpness)?;
        }
    }
    for c in &file.corners {
        writeln!(w, "t corner 1/1/0 {} {}", c.vertex, c.sharpness)?;
    }
    if !file.holes.is_empty() {
        write!(w, "t hole {}/0/0", file.holes.len())?;
        for f in &file.holes {
            write!(w, " {f}")?;
        }
        writeln!(w)?;
    }
    Ok(())
}
