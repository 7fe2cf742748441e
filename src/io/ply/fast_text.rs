//! Text PLY bodies read on all threads. Where every element stands on a
//! line of its own (as every writer puts it), a line's place is its rank
//! among the lines that hold a word: the body is cut at line ends into
//! pieces, each piece's lines counted on all threads, then each piece read
//! knowing the rank of its first line, a round of pieces at a time. A line
//! that does not hold exactly its element's values, anything the
//! value-by-value reader would report, and a mesh it refuses make the body
//! go to that reader, so errors and their lines are its own.

use std::io::Read;

use glam::DVec3;
use memchr::memchr;

use super::{file_of, parse_header, roles, Element, Encoding, Property, Roles};
use crate::io::blocks::{after_last_line, read_blocks};
use crate::io::build_mesh_with;
use crate::io::mesh_file::{Colours, MeshFile};
use crate::io::text::{read_ranked, words};
use crate::io::Location;
use crate::mesh::MeshOptions;

/// Bytes a piece holds at least (it ends at the next line end).
pub(super) const PIECE: usize = 1 << 20;

/// Bytes read from a file at a time.
pub(super) const BLOCK: usize = 16 << 20;

/// What an element's lines are to the mesh.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Kind {
    Vertices,
    Faces,
    /// Read (so that a malformed value goes to the value-by-value reader)
    /// and left.
    Other,
}

/// An element that has properties, and the ranks of its lines.
struct Lines {
    element: Element,
    roles: Roles,
    kind: Kind,
    end: usize,
}

/// The file of a text body, read in pieces of `piece` bytes; `None` where
/// the value-by-value reader must read it (see the module doc).
pub(super) fn read(
    body: &[u8],
    elements: &[Element],
    strict: bool,
    options: MeshOptions,
    piece: usize,
) -> Option<MeshFile> {
    let mut reader = Reader::new(elements, strict)?;
    reader.read(body, piece)?;
    reader.file(options)
}

/// Reads a text PLY file from `source` through two buffers of `block`
/// bytes cut at line ends, each read as [`read`] reads a body; `Ok(None)`
/// for a binary file (read whole) and where the value-by-value reader must
/// read it.
///
/// # Errors
/// Whatever `source` returns.
pub(super) fn read_source(
    source: impl Read + Send,
    block: usize,
    piece: usize,
    strict: bool,
    options: MeshOptions,
) -> std::io::Result<Option<MeshFile>> {
    // A header longer than a block leaves the file to the whole reading.
    let header = |text: &[u8]| {
        let (encoding, elements, body, _) = parse_header(text).ok()?;
        (encoding == Encoding::Ascii).then_some(())?;
        Some((Reader::new(&elements, strict)?, text.len() - body.len()))
    };
    let read = |reader: &mut Reader, text: &[u8], _| reader.read(text, piece);
    let reader = read_blocks(source, block, after_last_line, header, read)?;
    Ok(reader.and_then(|reader| reader.file(options)))
}

/// A text body read so far.
struct Reader {
    layout: Vec<Lines>,
    /// Lines the elements take.
    total: usize,
    /// Lines read so far.
    rank: usize,
    strict: bool,
    read: Piece,
}

impl Reader {
    /// A reader of `elements`; `None` for elements the value-by-value
    /// reader refuses, and for two vertex or face elements.
    fn new(elements: &[Element], strict: bool) -> Option<Reader> {
        let mut layout: Vec<Lines> = Vec::new();
        let mut total = 0usize;
        for element in elements {
            let roles = roles(element, strict).ok()?;
            if element.properties.is_empty() {
                continue;
            }
            let kind = match (element.name.as_slice(), roles.index_list) {
                (b"vertex", _) => Kind::Vertices,
                (_, Some(_)) => Kind::Faces,
                _ => Kind::Other,
            };
            if kind != Kind::Other && layout.iter().any(|l| l.kind == kind) {
                return None;
            }
            total = total.checked_add(element.count)?;
            layout.push(Lines {
                element: element.clone(),
                roles,
                kind,
                end: total,
            });
        }
        Some(Reader {
            layout,
            total,
            rank: 0,
            strict,
            read: Piece::default(),
        })
    }

    /// Reads `text`, whole lines, in pieces of `piece` bytes on all threads.
    fn read(&mut self, text: &[u8], piece: usize) -> Option<()> {
        let (layout, total, strict) = (&self.layout, self.total, self.strict);
        let all = &mut self.read;
        read_ranked(
            text,
            piece,
            &mut self.rank,
            |p| rows(p).count(),
            |text, first| read_piece(text, first, layout, total, strict),
            |piece| {
                all.positions.extend_from_slice(&piece.positions);
                all.colours.extend_from_slice(&piece.colours);
                all.uvs.extend_from_slice(&piece.uvs);
                all.sizes.extend_from_slice(&piece.sizes);
                all.indices.extend_from_slice(&piece.indices);
            },
        )
    }

    /// The file read; `None` when lines are missing or the mesh is refused.
    fn file(self, options: MeshOptions) -> Option<MeshFile> {
        if self.rank < self.total {
            return None;
        }
        let vertex_roles = self.layout.iter().find(|l| l.kind == Kind::Vertices);
        let vertex_roles = vertex_roles.map(|l| l.roles);
        let all = self.read;
        // Lines are not kept: a mesh refused is read again value by value,
        // which names them.
        let mesh = build_mesh_with(
            (all.positions, all.sizes, all.indices),
            options,
            |_| Location::Line(0),
            |_| Location::Line(0),
        )
        .ok()?;
        let colours = vertex_roles.filter(|r| r.colours).map(|r| Colours {
            rgba: all.colours,
            alpha: r.alpha,
        });
        let uvs = vertex_roles.filter(|r| r.uvs).map(|_| all.uvs);
        Some(file_of(mesh, colours, uvs))
    }
}

/// The lines of `text` that hold a word.
fn rows(text: &[u8]) -> impl Iterator<Item = &[u8]> {
    let mut rest = text;
    std::iter::from_fn(move || loop {
        if rest.is_empty() {
            return None;
        }
        let end = memchr(b'\n', rest).map_or(rest.len(), |at| at + 1);
        let (line, tail) = rest.split_at(end);
        rest = tail;
        if line.iter().any(|b| !b.is_ascii_whitespace()) {
            return Some(line);
        }
    })
}

/// What a piece's lines hold, element by element.
#[derive(Default)]
struct Piece {
    positions: Vec<DVec3>,
    colours: Vec<[f64; 4]>,
    uvs: Vec<[f64; 2]>,
    sizes: Vec<u32>,
    indices: Vec<u32>,
}

/// Reads the lines of `text`, the first of rank `first`, up to rank
/// `total`; `None` at the first the value-by-value reader would report or
/// that holds more than its element.
fn read_piece(
    text: &[u8],
    first: usize,
    layout: &[Lines],
    total: usize,
    strict: bool,
) -> Option<Piece> {
    let mut piece = Piece::default();
    let mut e = layout.partition_point(|l| l.end <= first);
    for (rank, line) in (first..total).zip(rows(text)) {
        while layout[e].end <= rank {
            e += 1;
        }
        read_line(line, &layout[e], strict, &mut piece)?;
    }
    Some(piece)
}

/// Reads one element's values from `line`, as the value-by-value reader
/// reads them, into `piece`.
fn read_line(line: &[u8], lines: &Lines, strict: bool, piece: &mut Piece) -> Option<()> {
    let roles = &lines.roles;
    let mut values = words(line);
    let mut xyz = [0.0; 3];
    let mut rgba = [0.0, 0.0, 0.0, 1.0];
    let mut st = [0.0; 2];
    for (p, (_, property)) in lines.element.properties.iter().enumerate() {
        match *property {
            Property::Scalar(ty) => {
                let value = ty.value_of_word(values.next()?)?;
                if let Some(axis) = roles.axes.iter().position(|&a| a == Some(p)) {
                    xyz[axis] = value;
                } else if let Some(k) = roles
                    .channels
                    .iter()
                    .position(|c| c.is_some_and(|(q, _)| q == p))
                {
                    let scale = roles.channels[k].map_or(1.0, |(_, s)| s);
                    rgba[k] = value / scale;
                } else if let Some(k) = roles.uv_axes.iter().position(|&a| a == Some(p)) {
                    st[k] = value;
                }
            }
            Property::List { count, item } => {
                let n = count.value_of_word(values.next()?)?;
                if n < 0.0 {
                    return None;
                }
                let keep = roles.index_list == Some(p);
                for _ in 0..n as usize {
                    let value = item.value_of_word(values.next()?)?;
                    if keep {
                        if value < 0.0 || value > u32::MAX as f64 {
                            return None;
                        }
                        piece.indices.push(value as u32);
                    }
                }
                if keep {
                    piece.sizes.push(n as u32);
                }
            }
        }
    }
    if values.next().is_some() {
        return None;
    }
    if lines.kind == Kind::Vertices {
        if roles.colours {
            if strict && rgba.iter().any(|c| !c.is_finite()) {
                return None;
            }
            piece.colours.push(rgba);
        }
        if roles.uvs {
            piece.uvs.push(st);
        }
        piece.positions.push(DVec3::from_array(xyz));
    }
    Some(())
}

#[cfg(test)]
mod tests {
    use super::super::{parse_header, read_body, write::write, Encoding, Text};
    use super::*;
    use crate::io::text::Tokens;
    use crate::io::PlyEncoding;
    use crate::mesh::{shapes, Mesh};

    /// The file the value-by-value reader makes of a text PLY, or its error.
    fn by_values(data: &[u8], strict: bool) -> Result<MeshFile, String> {
        let (encoding, elements, body, line) = parse_header(data).unwrap();
        assert_eq!(encoding, Encoding::Ascii);
        let mut source = Text(Tokens::new(body, line));
        read_body(&mut source, &elements, strict, MeshOptions::default()).map_err(|e| e.to_string())
    }

    fn in_pieces(data: &[u8], strict: bool, piece: usize) -> Option<MeshFile> {
        let (_, elements, body, _) = parse_header(data).unwrap();
        read(body, &elements, strict, MeshOptions::default(), piece)
    }

    /// Each coordinate's and colour channel's bits (so -0 and 0 differ).
    fn bits(file: &MeshFile) -> Vec<u64> {
        let positions = file.mesh.positions().iter().flat_map(|p| p.to_array());
        let colours = file
            .colours
            .iter()
            .flat_map(|c| c.rgba.iter().flatten().copied());
        positions.chain(colours).map(f64::to_bits).collect()
    }

    fn text_ply(mesh: &Mesh) -> String {
        let mut bytes = Vec::new();
        write(&mut bytes, mesh, PlyEncoding::Ascii).unwrap();
        String::from_utf8(bytes).unwrap()
    }

    const HEADER: &str = "ply\nformat ascii 1.0\ncomment made by hand\n";

    /// Text bodies as writers put them, and some they might: property types
    /// of every kind, colours (integer and float, with alpha), UVs, other
    /// elements before, between and after, blank lines, CRLF, tabs, words
    /// after the last element, `-0`.
    fn files() -> Vec<String> {
        let mut torus = shapes::triangle_torus(7, 5);
        torus.positions_mut()[0].x = -0.0;
        let ours = text_ply(&torus);
        let coloured = format!(
            "{HEADER}element vertex 4\nproperty float x\nproperty double y\nproperty int z\n\
             property uchar red\nproperty uchar green\nproperty uchar blue\nproperty float s\nproperty float t\n\
             element edge 2\nproperty int vertex1\nproperty int vertex2\n\
             element face 2\nproperty uchar intensity\nproperty list uchar uint vertex_indices\nproperty float quality\n\
             element material 1\nproperty list int float weights\nend_header\n\
             0.1 -0 3 255 0 12 0.5 0.25\n1e3 2.5 -4 1 2 3 1 0\n\n1 1 1 0 0 0 0.125 1\r\n-1.5\t2 7 9 9 9 0 0\n\
             0 1\n2 3\n\
             7 3 0 1 2 1.5\n8 4 0 2 3 1 -2.5\n\
             3 0.5 0.25 1e-3\nthese words are not read\n"
        );
        let alpha = format!(
            "{HEADER}element vertex 3\nproperty double x\nproperty double y\nproperty double z\n\
             property float red\nproperty float green\nproperty float blue\nproperty float alpha\n\
             element face 1\nproperty list int int vertex_index\nend_header\n\
             0 0 0 1 0.5 0 0.25\n1 0 0 0 0 0 1\n0 1 0 1 1 1 1\n3 0 1 2\n"
        );
        let crlf = ours.replace('\n', "\r\n");
        let blank = ours
            .replace("end_header\n", "end_header\n\n  \n")
            .replace('\n', "\n\t\n");
        vec![ours, coloured, alpha, crlf, blank]
    }

    #[test]
    fn pieces_of_any_size_read_as_the_values_do() {
        for (i, file) in files().iter().enumerate() {
            for strict in [false, true] {
                let expected = by_values(file.as_bytes(), strict).unwrap();
                for piece in [1, 2, 13, 100, 4096, PIECE] {
                    let read = in_pieces(file.as_bytes(), strict, piece)
                        .unwrap_or_else(|| panic!("file {i}, piece {piece}"));
                    assert_eq!(read, expected, "file {i}, piece {piece}");
                    assert_eq!(bits(&read), bits(&expected), "file {i}, piece {piece}");
                }
            }
        }
        assert!(by_values(files()[1].as_bytes(), true)
            .unwrap()
            .uvs
            .is_some());
        // From a stream in blocks of any size: those shorter than the
        // header leave the file to the values.
        for (i, file) in files().iter().enumerate() {
            let header = file.find("end_header").unwrap() + 12;
            for strict in [false, true] {
                let expected = by_values(file.as_bytes(), strict).unwrap();
                for block in [1, 9, 100, header, 1000, BLOCK] {
                    for piece in [1, 50, PIECE] {
                        let options = MeshOptions::default();
                        let read = read_source(file.as_bytes(), block, piece, strict, options);
                        match read.unwrap() {
                            Some(read) => {
                                assert_eq!(read, expected, "file {i}, block {block}");
                                assert_eq!(bits(&read), bits(&expected), "file {i}");
                            }
                            None => assert!(block < header, "file {i}, block {block}"),
                        }
                    }
                }
            }
        }
        // A binary file is left to the whole reading.
        let mut binary = Vec::new();
        write(
            &mut binary,
            &shapes::cube(),
            PlyEncoding::BinaryLittleEndian,
        )
        .unwrap();
        let options = MeshOptions::default();
        assert!(read_source(binary.as_slice(), BLOCK, PIECE, true, options)
            .unwrap()
            .is_none());
        // More pieces than a round, in order.
        let bytes = text_ply(&shapes::torus(30, 20));
        let (_, elements, body, _) = parse_header(bytes.as_bytes()).unwrap();
        assert!(body.len() / 100 > 2 * crate::io::text::ROUND);
        let read = read(body, &elements, true, MeshOptions::default(), 100).unwrap();
        assert_eq!(Ok(read), by_values(bytes.as_bytes(), true));
    }

    /// `file` with line `n` of its body (counted from 0) made `with(line)`.
    fn body_line(file: &str, n: usize, with: impl Fn(&str) -> String) -> String {
        let (header, body) = file.split_at(file.find("end_header\n").unwrap() + 11);
        let mut lines: Vec<String> = body.lines().map(str::to_string).collect();
        lines[n] = with(&lines[n]);
        format!("{header}{}\n", lines.join("\n"))
    }

    #[test]
    fn files_on_disk_read_as_their_bytes_do() {
        let dir = tempfile::Builder::new()
            .prefix("weft-ply-")
            .tempdir()
            .unwrap();
        let path = |name: &str| dir.path().join(format!("{name}.ply"));
        let text = text_ply(&shapes::torus(12, 9));
        let mut binary = Vec::new();
        write(
            &mut binary,
            &shapes::torus(12, 9),
            PlyEncoding::BinaryBigEndian,
        )
        .unwrap();
        let broken = body_line(&text, 3, |_| "0 0 zero".into());
        for (name, bytes) in [
            ("text", text.as_bytes()),
            ("binary", &binary),
            ("broken", broken.as_bytes()),
        ] {
            std::fs::write(path(name), bytes).unwrap();
        }
        let read = |name| super::super::read_path(&path(name), true, MeshOptions::default());
        let whole = |bytes| super::super::read(bytes, true, MeshOptions::default()).unwrap();
        assert_eq!(read("text").unwrap(), whole(text.as_bytes()));
        assert_eq!(read("binary").unwrap(), whole(&binary));
        let error = read("broken").unwrap_err().to_string();
        assert!(
            error.contains(&path("broken").display().to_string()),
            "{error}"
        );
        assert!(
            error.contains("line 14:") && error.contains("\"zero\""),
            "{error}"
        );
    }

    #[test]
    fn bodies_with_anything_to_report_are_left_to_the_values() {
        let files = files();
        let (ours, coloured) = (&files[0], &files[1]);
        let face = shapes::triangle_torus(7, 5).vertex_count();
        let float_red = coloured
            .replacen("property uchar red", "property float red", 1)
            .replacen("0.1 -0 3 255", "0.1 -0 3 inf", 1);
        // (case, file, left to the values only when strict)
        let cases = [
            // An element over two lines, or two on one: read alike by the
            // values, left to them.
            (
                "split",
                body_line(ours, face, |l| l.replacen(' ', "\n", 1)),
                false,
            ),
            (
                "joined",
                body_line(ours, face, |l| format!("{l} {l}")),
                false,
            ),
            ("short", ours[..ours.len() - 4].to_string(), false),
            (
                "bad number",
                body_line(ours, 0, |l| format!("0x{l}")),
                false,
            ),
            (
                "float index",
                body_line(ours, face, |_| "3 0 1.5 2".into()),
                false,
            ),
            (
                "negative index",
                body_line(ours, face, |_| "3 0 -1 2".into()),
                false,
            ),
            (
                "negative length",
                body_line(ours, face, |_| "-3 0 1 2".into()),
                false,
            ),
            (
                "index past the vertices",
                body_line(ours, face, |_| "3 0 1 9999".into()),
                false,
            ),
            ("non-finite colour", float_red, true),
        ];
        // Two elements of one name: refused by the header, before either reader.
        let second_faces = "element face 0\nproperty list uchar int vertex_indices\nend_header";
        let two_face_elements = ours.replacen("end_header", second_faces, 1);
        let refused = parse_header(two_face_elements.as_bytes()).unwrap_err();
        assert!(
            refused.to_string().contains("a second element \"face\""),
            "{refused}"
        );
        for (name, file, strict_only) in &cases {
            for strict in [false, true] {
                let values = by_values(file.as_bytes(), strict);
                for piece in [1, 64, PIECE] {
                    let read = in_pieces(file.as_bytes(), strict, piece);
                    match (strict || !strict_only, &read) {
                        (true, None) => {}
                        (false, Some(read)) => assert_eq!(Ok(read.clone()), values),
                        _ => panic!("{name}, strict {strict}, piece {piece}: {read:?}"),
                    }
                }
                // The whole reading gives what the values give.
                let whole = super::super::read(file.as_bytes(), strict, MeshOptions::default());
                assert_eq!(whole.map_err(|e| e.to_string()), values, "{name}");
            }
        }
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(256))]

        /// Bodies a few bytes away from well-formed ones: whatever the
        /// pieces read, the values read the same.
        #[test]
        fn what_the_pieces_read_the_values_read_alike(
            file in 0usize..5,
            edits in proptest::collection::vec((0usize..100_000, 0u8..32, 0u8..3), 0..4),
            piece in 1usize..300,
            block in 1usize..2000,
            strict: bool,
        ) {
            let file = files()[file].clone();
            let header_end = file.find("end_header").unwrap();
            let (header, body) = file.split_at(header_end + file[header_end..].find('\n').unwrap() + 1);
            let body = crate::io::text::edited(body.as_bytes(), &edits);
            let bytes = [header.as_bytes(), &body].concat();
            let streamed = read_source(bytes.as_slice(), block, piece, strict, MeshOptions::default());
            for read in [in_pieces(&bytes, strict, piece), streamed.unwrap()].into_iter().flatten() {
                let values = by_values(&bytes, strict);
                proptest::prop_assert_eq!(Ok(read.clone()), values.clone());
                proptest::prop_assert_eq!(bits(&read), bits(&values.unwrap()));
            }
        }
    }
}
