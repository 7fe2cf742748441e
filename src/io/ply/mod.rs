//! Stanford PLY, ASCII and binary (little and big endian).
//!
//! Read: the `vertex` element's `x`, `y`, `z` (any numeric type, float and
//! double usual), its colour `red`, `green`, `blue` and optional `alpha`
//! (integer types scaled from 0 to the type's maximum, float types taken
//! as 0 to 1; `diffuse_red`… also accepted), its texture coordinates `s t`,
//! `u v` or `texture_u texture_v` (one per vertex, as face-varying UVs
//! without seams), and the `face` element's `vertex_indices` (or
//! `vertex_index`) list with any integer count and index types; every other
//! property and element is skipped by its declared type. Write: `double`
//! coordinates, so positions round-trip exactly; `uchar` colours, `double`
//! normals `nx ny nz` and texture coordinates `s t` when present (UVs only
//! when no vertex has two, see [`super::MeshFile::dropped_by`]); a `uchar`
//! corner count (`int` when a face has more than 255 corners) with `int`
//! indices.

use glam::DVec3;

mod binary;
mod fast_text;
mod write;

pub use write::{write, write_file};

use super::mesh_file::{Colours, MeshFile, Uvs};
use super::text::{f64_of, i64_of, show, words, Lazy, Tokens};
use super::{build_mesh_with, IoError, Location};
use crate::mesh::{Mesh, MeshOptions};

/// A PLY scalar type.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Scalar {
    I8,
    U8,
    I16,
    U16,
    I32,
    U32,
    F32,
    F64,
}

impl Scalar {
    fn parse(word: &[u8]) -> Option<Scalar> {
        Some(match word {
            b"char" | b"int8" => Scalar::I8,
            b"uchar" | b"uint8" => Scalar::U8,
            b"short" | b"int16" => Scalar::I16,
            b"ushort" | b"uint16" => Scalar::U16,
            b"int" | b"int32" => Scalar::I32,
            b"uint" | b"uint32" => Scalar::U32,
            b"float" | b"float32" => Scalar::F32,
            b"double" | b"float64" => Scalar::F64,
            _ => return None,
        })
    }

    fn size(self) -> usize {
        match self {
            Scalar::I8 | Scalar::U8 => 1,
            Scalar::I16 | Scalar::U16 => 2,
            Scalar::I32 | Scalar::U32 | Scalar::F32 => 4,
            Scalar::F64 => 8,
        }
    }

    /// The value `bytes` (exactly [`Scalar::size`] of them) hold, as `f64`
    /// (exact for every PLY integer type).
    #[inline]
    fn value_of(self, bytes: &[u8], big_endian: bool) -> f64 {
        let size = self.size();
        let mut b = [0u8; 8];
        b[..size].copy_from_slice(&bytes[..size]);
        if big_endian {
            b[..size].reverse();
        }
        match self {
            Scalar::I8 => b[0] as i8 as f64,
            Scalar::U8 => b[0] as f64,
            Scalar::I16 => i16::from_le_bytes([b[0], b[1]]) as f64,
            Scalar::U16 => u16::from_le_bytes([b[0], b[1]]) as f64,
            Scalar::I32 => i32::from_le_bytes([b[0], b[1], b[2], b[3]]) as f64,
            Scalar::U32 => u32::from_le_bytes([b[0], b[1], b[2], b[3]]) as f64,
            Scalar::F32 => f32::from_le_bytes([b[0], b[1], b[2], b[3]]) as f64,
            Scalar::F64 => f64::from_le_bytes(b),
        }
    }

    /// The value of a word of text, read as `f64` (an integer type's as
    /// an integer, exactly); `None` when the word is not one.
    #[inline]
    fn value_of_word(self, word: &[u8]) -> Option<f64> {
        if self.is_integer() {
            i64_of(word).map(|i| i as f64)
        } else {
            f64_of(word)
        }
    }

    fn is_integer(self) -> bool {
        !matches!(self, Scalar::F32 | Scalar::F64)
    }

    /// What a colour channel of this type is divided by to fall in 0 to 1.
    fn colour_scale(self) -> f64 {
        match self {
            Scalar::I8 => i8::MAX as f64,
            Scalar::U8 => u8::MAX as f64,
            Scalar::I16 => i16::MAX as f64,
            Scalar::U16 => u16::MAX as f64,
            Scalar::I32 => i32::MAX as f64,
            Scalar::U32 => u32::MAX as f64,
            Scalar::F32 | Scalar::F64 => 1.0,
        }
    }
}

#[derive(Debug, Clone)]
enum Property {
    Scalar(Scalar),
    List { count: Scalar, item: Scalar },
}

#[derive(Debug, Clone)]
struct Element {
    name: Vec<u8>,
    count: usize,
    properties: Vec<(Vec<u8>, Property)>,
    line: usize,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Encoding {
    Ascii,
    Binary { big_endian: bool },
}

/// Where the values come from: words of text or bytes.
trait Values {
    /// Reads one value of type `ty` as `f64` (exact for every PLY integer type).
    fn read(&mut self, ty: Scalar, what: &dyn Fn() -> String) -> Result<f64, IoError>;
    /// Where the next value is.
    fn location(&mut self) -> Location;
    /// Whether `count` more values of at least `size` bytes could still be in the input.
    fn has_room(&mut self, count: usize, size: usize) -> bool;
}

struct Text<'a>(Tokens<'a>);

impl Values for Text<'_> {
    fn read(&mut self, ty: Scalar, what: &dyn Fn() -> String) -> Result<f64, IoError> {
        let (word, line) = self.0.expect_word(Lazy(what))?;
        ty.value_of_word(word).ok_or_else(|| {
            let kind = if ty.is_integer() {
                "an integer"
            } else {
                "a number"
            };
            IoError::parse(
                Location::Line(line),
                format!("expected {kind} for {}, found {}", what(), show(word)),
            )
        })
    }

    fn location(&mut self) -> Location {
        Location::Line(self.0.line())
    }

    fn has_room(&mut self, count: usize, _size: usize) -> bool {
        // A value and its separator take at least two characters.
        count <= self.0.remaining() / 2 + 1
    }
}

struct Binary<'a> {
    data: &'a [u8],
    pos: usize,
    big_endian: bool,
}

impl Values for Binary<'_> {
    fn read(&mut self, ty: Scalar, what: &dyn Fn() -> String) -> Result<f64, IoError> {
        let size = ty.size();
        let bytes = self.data.get(self.pos..self.pos + size).ok_or_else(|| {
            IoError::parse(
                Location::Byte(self.pos),
                format!(
                    "file ends after {} bytes; expected {size} more for {}",
                    self.data.len(),
                    what()
                ),
            )
        })?;
        self.pos += size;
        Ok(ty.value_of(bytes, self.big_endian))
    }

    fn location(&mut self) -> Location {
        Location::Byte(self.pos)
    }

    fn has_room(&mut self, count: usize, size: usize) -> bool {
        count
            .checked_mul(size)
            .is_some_and(|n| n <= self.data.len() - self.pos)
    }
}

/// Parses a PLY file, ASCII or binary.
///
/// # Errors
/// [`IoError::Parse`] naming the header line, the body line (ASCII) or the
/// byte offset (binary) where the file stops following its header;
/// [`IoError::InvalidMesh`] with the place of a face the mesh rejects.
pub fn parse(data: &[u8]) -> Result<Mesh, IoError> {
    // The mesh alone: incomplete colours or UVs do not matter.
    read(data, false, MeshOptions::default()).map(|file| file.mesh)
}

/// Parses a PLY file, ASCII or binary, with its vertex colours and texture
/// coordinates.
///
/// # Errors
/// As [`parse`]; also a vertex element with some colour channels but not
/// red, green and blue, or one texture coordinate without the other.
pub fn parse_file(data: &[u8]) -> Result<MeshFile, IoError> {
    read(data, true, MeshOptions::default())
}

/// Reads a PLY file; `strict` refuses incomplete colours or UVs instead of
/// ignoring them; the mesh accepts what `options` allows.
pub(crate) fn read(data: &[u8], strict: bool, options: MeshOptions) -> Result<MeshFile, IoError> {
    read_with(data, strict, options, true)
}

/// [`read`], a text body in pieces on all threads first when
/// `text_in_pieces`, else value by value.
fn read_with(
    data: &[u8],
    strict: bool,
    options: MeshOptions,
    text_in_pieces: bool,
) -> Result<MeshFile, IoError> {
    let (encoding, elements, body, body_line) = parse_header(data)?;
    match encoding {
        Encoding::Ascii => {
            if text_in_pieces {
                let read = fast_text::read(body, &elements, strict, options, fast_text::PIECE);
                if let Some(file) = read {
                    return Ok(file);
                }
            }
            let mut values = Text(Tokens::new(body, body_line));
            read_body(&mut values, &elements, strict, options)
        }
        Encoding::Binary { big_endian } => {
            let offset = data.len() - body.len();
            if let Some(read) =
                binary::read_in_bulk(data, offset, big_endian, &elements, strict, options)
            {
                return read;
            }
            let mut source = Binary {
                data,
                pos: offset,
                big_endian,
            };
            read_body(&mut source, &elements, strict, options)
        }
    }
}

/// Reads a PLY file from disk: text a block at a time, never holding all
/// its bytes, as [`read`] reads it; binary whole, as [`read`] reads it; a
/// text file with something to report whole, value by value.
///
/// # Errors
/// As [`read`], naming the file; [`IoError::File`] when the file cannot be
/// read.
pub(crate) fn read_path(
    path: &std::path::Path,
    strict: bool,
    options: MeshOptions,
) -> Result<MeshFile, IoError> {
    use std::io::{Read, Seek};
    let failed = super::read_failed(path);
    let mut file = std::fs::File::open(path).map_err(failed)?;
    // A binary file is known by its header, before any block is read.
    let mut head = Vec::new();
    file.by_ref()
        .take(1 << 16)
        .read_to_end(&mut head)
        .map_err(failed)?;
    let binary = parse_header(&head).is_ok_and(|(encoding, ..)| encoding != Encoding::Ascii);
    if !binary {
        file.rewind().map_err(failed)?;
        let streamed =
            fast_text::read_source(file, fast_text::BLOCK, fast_text::PIECE, strict, options);
        if let Some(file) = streamed.map_err(failed)? {
            return Ok(file);
        }
    }
    // Binary, or the pieces have given up: not the pieces again.
    read_with(&super::read_bytes(path)?, strict, options, false).map_err(|e| e.in_file(path))
}

fn header_error(line: usize, message: impl Into<String>) -> IoError {
    IoError::parse(Location::Line(line), message)
}

type Header<'a> = (Encoding, Vec<Element>, &'a [u8], usize);

fn parse_header(data: &[u8]) -> Result<Header<'_>, IoError> {
    let mut pos = 0;
    let mut line = 0;
    let mut encoding = None;
    let mut elements: Vec<Element> = Vec::new();
    loop {
        line += 1;
        let Some(length) = data[pos..].iter().position(|&b| b == b'\n') else {
            return Err(header_error(
                line,
                "unexpected end of file in the header; expected \"end_header\"",
            ));
        };
        let text = &data[pos..pos + length];
        pos += length + 1;
        let w: Vec<&[u8]> = words(text).collect();
        if line == 1 {
            // Some writers put the magic in capitals ("PLY"); readers accept it.
            if !w
                .first()
                .is_some_and(|magic| magic.eq_ignore_ascii_case(b"ply"))
            {
                return Err(header_error(1, "expected \"ply\" on the first line"));
            }
            continue;
        }
        match w.first().copied() {
            None | Some(b"comment") | Some(b"obj_info") => {}
            Some(b"format") => {
                encoding = Some(match w.get(1).copied() {
                    Some(b"ascii") => Encoding::Ascii,
                    Some(b"binary_little_endian") => Encoding::Binary { big_endian: false },
                    Some(b"binary_big_endian") => Encoding::Binary { big_endian: true },
                    _ => {
                        return Err(header_error(
                            line,
                            "expected \"format ascii\", \"format binary_little_endian\" or \"format binary_big_endian\"",
                        ))
                    }
                });
            }
            Some(b"element") => {
                let (Some(name), Some(count)) = (w.get(1), w.get(2)) else {
                    return Err(header_error(line, "expected \"element NAME COUNT\""));
                };
                let count = super::text::parse_count(count, line, "the element count")?;
                // Two elements of one name would both be read as it (two
                // vertex lists, one with colours): the file is refused.
                if let Some(first) = elements.iter().find(|e| e.name == *name) {
                    return Err(header_error(
                        line,
                        format!(
                            "a second element {} (the first is on line {})",
                            show(name),
                            first.line
                        ),
                    ));
                }
                elements.push(Element {
                    name: name.to_vec(),
                    count,
                    properties: Vec::new(),
                    line,
                });
            }
            Some(b"property") => {
                let Some(element) = elements.last_mut() else {
                    return Err(header_error(line, "expected \"element\" before \"property\""));
                };
                let scalar = |word: Option<&&[u8]>| {
                    word.and_then(|w| Scalar::parse(w)).ok_or_else(|| {
                        header_error(
                            line,
                            format!(
                                "expected a property type (char, uchar, short, ushort, int, uint, float, double), found {}",
                                show(word.copied().unwrap_or_default())
                            ),
                        )
                    })
                };
                let (property, name) = if w.get(1) == Some(&&b"list"[..]) {
                    let count = scalar(w.get(2))?;
                    let item = scalar(w.get(3))?;
                    if !count.is_integer() {
                        return Err(header_error(line, "a list's count type must be an integer type"));
                    }
                    (Property::List { count, item }, w.get(4))
                } else {
                    (Property::Scalar(scalar(w.get(1))?), w.get(2))
                };
                let Some(name) = name else {
                    return Err(header_error(line, "expected a property name"));
                };
                element.properties.push((name.to_vec(), property));
            }
            Some(b"end_header") => break,
            Some(other) => {
                return Err(header_error(
                    line,
                    format!("expected a header line (format, element, property, comment or end_header), found {}", show(other)),
                ))
            }
        }
    }
    let encoding =
        encoding.ok_or_else(|| header_error(line, "the header has no \"format\" line"))?;
    Ok((encoding, elements, &data[pos..], line + 1))
}

fn read_body(
    source: &mut dyn Values,
    elements: &[Element],
    strict: bool,
    options: MeshOptions,
) -> Result<MeshFile, IoError> {
    let mut positions = Vec::new();
    let mut vertex_locations = Vec::new();
    let mut face_sizes = Vec::new();
    let mut face_indices = Vec::new();
    let mut face_locations = Vec::new();
    let mut colours: Vec<[f64; 4]> = Vec::new();
    let mut has_colours = false;
    let mut has_alpha = false;
    let mut uvs: Vec<[f64; 2]> = Vec::new();
    let mut has_uvs = false;
    for element in elements {
        let is_vertex = element.name == b"vertex";
        let Roles {
            axes,
            channels,
            uv_axes,
            index_list,
            colours: element_colours,
            alpha,
            uvs: element_uvs,
        } = roles(element, strict)?;
        if is_vertex {
            has_colours = element_colours;
            has_alpha = alpha;
            has_uvs = element_uvs;
        }
        let min_size: usize = element
            .properties
            .iter()
            .map(|(_, p)| match p {
                Property::Scalar(s) => s.size(),
                Property::List { count, .. } => count.size(),
            })
            .sum();
        if !source.has_room(element.count, min_size.max(1)) && min_size > 0 {
            let location = source.location();
            return Err(IoError::parse(
                location,
                format!(
                    "the header promises {} {} elements but the file is too short for them",
                    element.count,
                    String::from_utf8_lossy(&element.name)
                ),
            ));
        }
        if element.properties.is_empty() {
            continue;
        }
        // The check above bounds the count by the file's size; capping what is
        // reserved up front keeps a lying header from claiming much more.
        let reserve = element.count.min(1 << 20);
        if is_vertex {
            positions.reserve(reserve);
            vertex_locations.reserve(reserve);
        } else if index_list.is_some() {
            face_sizes.reserve(reserve);
            face_locations.reserve(reserve);
        }
        let name = String::from_utf8_lossy(&element.name);
        for i in 0..element.count {
            let start = source.location();
            let mut xyz = [0.0; 3];
            let mut rgba = [0.0, 0.0, 0.0, 1.0];
            let mut st = [0.0; 2];
            for (p, (property_name, property)) in element.properties.iter().enumerate() {
                let what = || {
                    format!(
                        "property {} of {name} {i}",
                        String::from_utf8_lossy(property_name)
                    )
                };
                match *property {
                    Property::Scalar(ty) => {
                        let value = source.read(ty, &what)?;
                        if let Some(axis) = axes.iter().position(|&a| a == Some(p)) {
                            xyz[axis] = value;
                        } else if let Some(k) =
                            channels.iter().position(|c| c.is_some_and(|(q, _)| q == p))
                        {
                            let scale = channels[k].map_or(1.0, |(_, s)| s);
                            rgba[k] = value / scale;
                        } else if let Some(k) = uv_axes.iter().position(|&a| a == Some(p)) {
                            st[k] = value;
                        }
                    }
                    Property::List { count, item } => {
                        let location = source.location();
                        let n = source.read(count, &|| format!("the length of {}", what()))?;
                        if n < 0.0 || !source.has_room(n as usize, item.size()) {
                            return Err(IoError::parse(
                                location,
                                format!("list length {n} of {} is negative or longer than the rest of the file", what()),
                            ));
                        }
                        let n = n as usize;
                        let keep = index_list == Some(p);
                        for k in 0..n {
                            let location = source.location();
                            let value =
                                source.read(item, &|| format!("entry {k} of {}", what()))?;
                            if keep {
                                if value < 0.0 || value > u32::MAX as f64 {
                                    return Err(IoError::parse(
                                        location,
                                        format!("vertex index {value} of face {i} is out of range"),
                                    ));
                                }
                                face_indices.push(value as u32);
                            }
                        }
                        if keep {
                            face_sizes.push(n as u32);
                            face_locations.push(start);
                        }
                    }
                }
            }
            if is_vertex {
                if strict && has_colours && rgba.iter().any(|c| !c.is_finite()) {
                    return Err(IoError::parse(
                        start,
                        format!("the colour of vertex {i} is not finite"),
                    ));
                }
                positions.push(DVec3::from_array(xyz));
                vertex_locations.push(start);
                if has_colours {
                    colours.push(rgba);
                }
                if has_uvs {
                    uvs.push(st);
                }
            }
        }
    }
    let mesh = build_mesh_with(
        (positions, face_sizes, face_indices),
        options,
        |v| vertex_locations[v],
        |f| face_locations[f],
    )?;
    let colours = has_colours.then_some(Colours {
        rgba: colours,
        alpha: has_alpha,
    });
    Ok(file_of(mesh, colours, has_uvs.then_some(uvs)))
}

/// The file of a mesh read with its vertices' colours and texture
/// coordinates.
fn file_of(mesh: Mesh, colours: Option<Colours>, uvs: Option<Vec<[f64; 2]>>) -> MeshFile {
    let uvs = uvs.map(|uvs| Uvs::from_per_vertex(&mesh, uvs));
    let mut file = MeshFile::new(mesh);
    file.colours = colours;
    file.uvs = uvs;
    file
}

/// What an element's properties are to the reader.
#[derive(Debug, Clone, Copy)]
struct Roles {
    /// The properties `x`, `y` and `z` of a vertex.
    axes: [Option<usize>; 3],
    /// Red, green, blue and alpha, each with what it is divided by.
    channels: [Option<(usize, f64)>; 4],
    /// The two texture coordinates.
    uv_axes: [Option<usize>; 2],
    /// The list of a face's vertex indices.
    index_list: Option<usize>,
    /// A vertex element with red, green and blue; with alpha too.
    colours: bool,
    alpha: bool,
    /// A vertex element with both texture coordinates.
    uvs: bool,
}

/// The roles of `element`'s properties; an error for a vertex element
/// without `x`, `y` and `z`, face indices that are not integers, and, when
/// `strict`, incomplete colours or texture coordinates.
fn roles(element: &Element, strict: bool) -> Result<Roles, IoError> {
    let is_vertex = element.name == b"vertex";
    let is_face = element.name == b"face";
    let mut axes = [None; 3];
    // red, green, blue, alpha with their scale; s and t.
    let mut channels: [Option<(usize, f64)>; 4] = [None; 4];
    let mut uv_axes: [Option<usize>; 2] = [None; 2];
    let mut index_list = None;
    for (p, (name, property)) in element.properties.iter().enumerate() {
        match (property, name.as_slice()) {
            (Property::Scalar(_), b"x") if is_vertex => axes[0] = Some(p),
            (Property::Scalar(_), b"y") if is_vertex => axes[1] = Some(p),
            (Property::Scalar(_), b"z") if is_vertex => axes[2] = Some(p),
            (Property::Scalar(ty), name) if is_vertex && colour_channel(name).is_some() => {
                channels[colour_channel(name).unwrap_or(0)] = Some((p, ty.colour_scale()));
            }
            (Property::Scalar(_), b"s" | b"u" | b"texture_u" | b"texture_s") if is_vertex => {
                uv_axes[0] = Some(p)
            }
            (Property::Scalar(_), b"t" | b"v" | b"texture_v" | b"texture_t") if is_vertex => {
                uv_axes[1] = Some(p)
            }
            (Property::List { item, .. }, b"vertex_indices" | b"vertex_index") if is_face => {
                if !item.is_integer() {
                    return Err(header_error(
                        element.line,
                        "face indices must have an integer type",
                    ));
                }
                index_list = Some(p);
            }
            _ => {}
        }
    }
    if is_vertex && axes.iter().any(Option::is_none) {
        return Err(header_error(
            element.line,
            "the vertex element needs properties x, y and z",
        ));
    }
    let (mut colours, mut alpha, mut uvs) = (false, false, false);
    if is_vertex {
        let rgb = channels[..3].iter().filter(|c| c.is_some()).count();
        let incomplete = rgb != 0 && rgb != 3 || rgb == 0 && channels[3].is_some();
        if incomplete && strict {
            return Err(header_error(
                element.line,
                "a vertex colour needs the properties red, green and blue (alpha is optional)",
            ));
        }
        let half_uv = uv_axes[0].is_some() != uv_axes[1].is_some();
        if half_uv && strict {
            return Err(header_error(
                element.line,
                "texture coordinates need two properties: s and t (or u and v)",
            ));
        }
        colours = rgb == 3;
        alpha = colours && channels[3].is_some();
        uvs = !half_uv && uv_axes[0].is_some();
    }
    Ok(Roles {
        axes,
        channels,
        uv_axes,
        index_list,
        colours,
        alpha,
        uvs,
    })
}

/// Which colour channel (red 0, green 1, blue 2, alpha 3) a property names.
fn colour_channel(name: &[u8]) -> Option<usize> {
    let name = name.strip_prefix(b"diffuse_").unwrap_or(name);
    match name {
        b"red" => Some(0),
        b"green" => Some(1),
        b"blue" => Some(2),
        b"alpha" => Some(3),
        _ => None,
    }
}
