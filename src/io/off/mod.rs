//! Object File Format (OFF): a header, vertex lines, then face lines that
//! start with their corner count.
//!
//! Read: an optional `OFF` keyword (also its `COFF`, `NOFF`, … variants:
//! colours and normals after a vertex's x y z, or after a face's indices, are
//! ignored), the counts `vertices faces edges` on the same or the next line,
//! `#` comments. Write: `OFF`, the counts, round-trip exact coordinates.

use std::io::Write;

use glam::DVec3;

mod fast;

use super::blocks::write_in_blocks;
use super::decimal::{push_counted_face, push_point_line};
use super::text::{lines, parse_count, parse_f64, show, words};
use super::{build_mesh_with, IoError, Location};
use crate::mesh::{Mesh, MeshOptions};

/// Parses an OFF file.
///
/// # Errors
/// [`IoError::Parse`] naming the line of a missing or malformed header,
/// count, coordinate or index, or the line where the file ends too early;
/// [`IoError::InvalidMesh`] with the line of a face the mesh rejects.
pub fn parse(data: &[u8]) -> Result<Mesh, IoError> {
    parse_with(data, MeshOptions::default())
}

/// As [`parse`], accepting what `options` allows: on all threads, or row
/// by row for a file that has something to report.
pub(crate) fn parse_with(data: &[u8], options: MeshOptions) -> Result<Mesh, IoError> {
    match fast::read(data, fast::PIECE, options) {
        Some(mesh) => Ok(mesh),
        None => parse_rows(data, options),
    }
}

/// Reads an OFF file from disk a block at a time, never holding all its
/// bytes, as [`parse_with`] reads it; a file with something to report is
/// read whole, row by row.
///
/// # Errors
/// As [`parse`], naming the file; [`IoError::File`] when the file cannot be
/// read.
pub(crate) fn read_path(path: &std::path::Path, options: MeshOptions) -> Result<Mesh, IoError> {
    let failed = super::read_failed(path);
    let file = std::fs::File::open(path).map_err(failed)?;
    let streamed = fast::read_source(file, fast::BLOCK, fast::PIECE, options);
    if let Some(mesh) = streamed.map_err(failed)? {
        return Ok(mesh);
    }
    // The pieces have given up: the rows, not the pieces again.
    parse_rows(&super::read_bytes(path)?, options).map_err(|e| e.in_file(path))
}

/// As [`parse_with`], row by row.
fn parse_rows(data: &[u8], options: MeshOptions) -> Result<Mesh, IoError> {
    let mut rows = lines(data).filter(|(_, text)| words(text).next().is_some());
    let mut last_line = 1;
    let mut next_row = |what: &dyn std::fmt::Display| {
        let row = rows.next();
        if let Some((line, _)) = row {
            last_line = line;
        }
        row.ok_or_else(|| {
            IoError::parse(
                Location::Line(last_line),
                format!("unexpected end of file; expected {what}"),
            )
        })
    };

    let (mut line, text) = next_row(&"the OFF header")?;
    let mut header: Vec<&[u8]> = words(text).collect();
    if header[0].len() >= 3 && header[0][header[0].len() - 3..].eq_ignore_ascii_case(b"OFF") {
        header.remove(0);
        if header.is_empty() {
            let (l, text) = next_row(&"the vertex, face and edge counts")?;
            line = l;
            header = words(text).collect();
        }
    }
    if header.len() < 2 {
        return Err(IoError::parse(
            Location::Line(line),
            "expected the vertex and face counts",
        ));
    }
    let vertex_count = parse_count(header[0], line, "the vertex count")?;
    let face_count = parse_count(header[1], line, "the face count")?;
    // Each vertex and face takes at least two bytes: never reserve more than the file can hold.
    let room = data.len() / 2;

    let mut positions = Vec::with_capacity(vertex_count.min(room));
    let mut vertex_lines = Vec::with_capacity(vertex_count.min(room));
    for v in 0..vertex_count {
        let (line, text) = next_row(&format_args!("vertex {v} of {vertex_count}"))?;
        let mut w = words(text);
        let mut xyz = [0.0; 3];
        for (axis, value) in ["x", "y", "z"].iter().zip(&mut xyz) {
            let word = w.next().ok_or_else(|| {
                IoError::parse(
                    Location::Line(line),
                    format!("expected 3 coordinates for vertex {v}; {axis} is missing"),
                )
            })?;
            *value = parse_f64(word, line, format_args!("coordinate {axis} of vertex {v}"))?;
        }
        positions.push(DVec3::from_array(xyz));
        vertex_lines.push(line);
    }

    let mut face_sizes = Vec::with_capacity(face_count.min(room));
    let mut face_lines = Vec::with_capacity(face_count.min(room));
    let mut face_indices = Vec::new();
    for f in 0..face_count {
        let (line, text) = next_row(&format_args!("face {f} of {face_count}"))?;
        let mut w = words(text);
        let size_word = w.next().unwrap_or_default();
        let size = parse_count(
            size_word,
            line,
            format_args!("the corner count of face {f}"),
        )?;
        for corner in 0..size {
            let word = w.next().ok_or_else(|| {
                IoError::parse(
                    Location::Line(line),
                    format!("face {f} should have {size} indices; index {corner} is missing"),
                )
            })?;
            let index = parse_count(word, line, format_args!("index {corner} of face {f}"))?;
            let index = u32::try_from(index).map_err(|_| {
                IoError::parse(
                    Location::Line(line),
                    format!("index {} of face {f} is too large", show(word)),
                )
            })?;
            face_indices.push(index);
        }
        face_sizes.push(size as u32);
        face_lines.push(line);
    }
    build_mesh_with(
        (positions, face_sizes, face_indices),
        options,
        |v| Location::Line(vertex_lines[v]),
        |f| Location::Line(face_lines[f]),
    )
}

/// Writes a mesh as OFF.
///
/// # Errors
/// Whatever the writer returns.
pub fn write(w: &mut dyn Write, mesh: &Mesh) -> std::io::Result<()> {
    writeln!(w, "OFF")?;
    writeln!(w, "{} {} 0", mesh.vertex_count(), mesh.face_count())?;
    let positions = mesh.positions();
    write_in_blocks(w, positions.len(), |vertices, w| {
        for &p in &positions[vertices] {
            push_point_line(w, b"", p);
        }
        Ok(())
    })?;
    write_in_blocks(w, mesh.face_count(), |faces, w| {
        faces.for_each(|f| push_counted_face(w, mesh.face(f)));
        Ok(())
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Files the pieces must read as the rows do.
    const READABLE: [&[u8]; 6] = [
        b"OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n",
        // Comments, blank lines, CRLF, tabs, colours after vertices and faces.
        b"# made by hand\r\nCOFF # colours\r\n\r\n4\t2 0\r\n0 0 0 255 0 0 255\r\n# a comment row\r\n\
          1 0 0 0 255 0 255\r\n   \r\n1 1 0 0 0 255 255\r\n0 1 0 9 9 9 9\r\n\
          3 0 1 2 1 0 0\r\n3\t0 2 3   # last\r\nextra rows are not read\r\n",
        // The counts on the keyword's line, and no keyword at all.
        b"OFF 3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2",
        b"3 1 0\n-0.5 1e3 .25\n1 0 0\n0 1 0\n3 0 1 2\n",
        // A quad, a pentagon and a triangle, with numbers of every form.
        b"NOFF\n7 3 0\n0 0 0\n+1 0 0\n1 1 0\n0 1 0\n-1 1 0\n2 0.5e0 0\n2 1.000000000000000000001 0\n\
          4 0 1 2 3\n5 0 3 4 2 1\n3 1 5 6\n",
        b"OFF\n0 0 0\n",
    ];

    /// Files the row-by-row reader must report, each with its line.
    const BROKEN: [(&[u8], usize); 6] = [
        (b"OFF\n3 1 0\n0 0 0\n1 0\n0 1 0\n3 0 1 2\n", 4),
        (b"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 x\n", 6),
        (b"OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", 6),
        (b"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", 6),
        (b"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n-3 0 1 2\n", 6),
        (b"OFF\nthree 1 0\n", 2),
    ];

    #[test]
    fn pieces_read_as_the_rows_do_wherever_the_cuts_fall() {
        for text in READABLE {
            let rows = parse_rows(text, MeshOptions::default()).unwrap();
            for piece in [1, 2, 3, 5, 17, 100, fast::PIECE] {
                let read = fast::read(text, piece, MeshOptions::default());
                assert_eq!(
                    read.as_ref(),
                    Some(&rows),
                    "{}",
                    String::from_utf8_lossy(text)
                );
            }
        }
    }

    #[test]
    fn blocks_of_any_size_read_as_the_rows_do() {
        let options = MeshOptions::default();
        for text in READABLE {
            let rows = parse_rows(text, options).unwrap();
            // Blocks shorter than the counts' rows leave the file to the rows.
            let counts = fast::counts(text).unwrap().2;
            for block in [1, 2, 7, counts, 64, fast::BLOCK] {
                for piece in [1, 3, 100, fast::PIECE] {
                    let read = fast::read_source(text, block, piece, options).unwrap();
                    match read {
                        Some(read) => assert_eq!(read, rows),
                        None => assert!(block < counts, "block {block}"),
                    }
                }
            }
        }
    }

    #[test]
    fn what_the_rows_report_is_left_to_them() {
        for (text, line) in BROKEN {
            for piece in [1, 4, fast::PIECE] {
                assert!(fast::read(text, piece, MeshOptions::default()).is_none());
                for block in [1, 5, fast::BLOCK] {
                    let read = fast::read_source(text, block, piece, MeshOptions::default());
                    assert!(read.unwrap().is_none());
                }
            }
            let error = parse(text).unwrap_err();
            assert_eq!(error.location(), Some(Location::Line(line)), "{error}");
        }
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(256))]

        /// Files a few bytes away from well-formed ones: whatever the
        /// pieces and blocks read, the rows read the same.
        #[test]
        fn what_the_pieces_read_the_rows_read_alike(
            file in 0usize..READABLE.len(),
            edits in proptest::collection::vec((0usize..1000, 0u8..32, 0u8..3), 0..4),
            piece in 1usize..40,
            block in 1usize..200,
        ) {
            let options = MeshOptions::default();
            let text = crate::io::text::edited(READABLE[file], &edits);
            let rows = parse_rows(&text, options).ok();
            let streamed = fast::read_source(text.as_slice(), block, piece, options).unwrap();
            for read in [fast::read(&text, piece, options), streamed].into_iter().flatten() {
                proptest::prop_assert_eq!(Some(&read), rows.as_ref());
            }
        }
    }
}
