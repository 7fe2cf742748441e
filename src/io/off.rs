//! Object File Format (OFF): a header, vertex lines, then face lines that
//! start with their corner count.
//!
//! Read: an optional `OFF` keyword (also its `COFF`, `NOFF`, … variants:
//! colours and normals after a vertex's x y z, or after a face's indices, are
//! ignored), the counts `vertices faces edges` on the same or the next line,
//! `#` comments. Write: `OFF`, the counts, round-trip exact coordinates.

use std::io::Write;

use glam::DVec3;

use super::blocks::write_in_blocks;
use super::decimal::{push_counted_face, push_f64};
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

/// As [`parse`], accepting what `options` allows.
pub(crate) fn parse_with(data: &[u8], options: MeshOptions) -> Result<Mesh, IoError> {
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
        for p in &positions[vertices] {
            push_f64(w, p.x);
            w.push(b' ');
            push_f64(w, p.y);
            w.push(b' ');
            push_f64(w, p.z);
            w.push(b'\n');
        }
        Ok(())
    })?;
    write_in_blocks(w, mesh.face_count(), |faces, w| {
        faces.for_each(|f| push_counted_face(w, mesh.face(f)));
        Ok(())
    })
}
