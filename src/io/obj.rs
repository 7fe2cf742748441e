//! Wavefront OBJ: `v` lines and `f` lines; polygons are kept as polygons.
//!
//! Read: `f` corners as `v`, `v/vt`, `v/vt/vn` or `v//vn`, positive (1-based)
//! or negative (relative to the vertices read so far) indices; a `v` line may
//! carry a fourth `w` or colour values after x y z, which are ignored, as are
//! comments, `vt`, `vn`, `o`, `g`, `s`, materials, lines and any other
//! statement. Write: `v x y z` with round-trip exact numbers, `f` with
//! 1-based indices.

use std::io::Write;

use glam::DVec3;

use super::text::{lines, parse_f64, parse_i64, show, words};
use super::{build_mesh, IoError, Location};
use crate::mesh::Mesh;

/// Parses an OBJ file.
///
/// # Errors
/// [`IoError::Parse`] for a line that is not what OBJ expects (a missing or
/// non-numeric coordinate, an index of 0 or one reaching before the first
/// vertex); [`IoError::InvalidMesh`] for a face the mesh rejects (an index
/// past the last vertex, fewer than 3 corners, a repeated vertex), each with
/// its line.
pub fn parse(data: &[u8]) -> Result<Mesh, IoError> {
    let mut positions = Vec::new();
    let mut vertex_lines = Vec::new();
    let mut face_sizes = Vec::new();
    let mut face_indices = Vec::new();
    let mut face_lines = Vec::new();
    for (line, text) in lines(data) {
        let mut w = words(text);
        match w.next() {
            Some(b"v") => {
                let mut xyz = [0.0; 3];
                for (axis, value) in ["x", "y", "z"].iter().zip(&mut xyz) {
                    let word = w.next().ok_or_else(|| {
                        IoError::parse(
                            Location::Line(line),
                            format!("expected 3 coordinates after \"v\"; {axis} is missing"),
                        )
                    })?;
                    *value = parse_f64(word, line, &format!("coordinate {axis}"))?;
                }
                positions.push(DVec3::from_array(xyz));
                vertex_lines.push(line);
            }
            Some(b"f") => {
                let mut size = 0u32;
                for corner in w {
                    let index = corner.split(|&b| b == b'/').next().unwrap_or(corner);
                    let value = parse_i64(index, line, "a vertex index")?;
                    face_indices.push(resolve(value, positions.len(), line, corner)?);
                    size = size.saturating_add(1);
                }
                face_sizes.push(size);
                face_lines.push(line);
            }
            _ => {}
        }
    }
    build_mesh(
        positions,
        face_sizes,
        face_indices,
        |v| Location::Line(vertex_lines[v]),
        |f| Location::Line(face_lines[f]),
    )
}

/// Turns an OBJ index (1-based, or negative from the end) into a 0-based one.
fn resolve(value: i64, vertex_count: usize, line: usize, word: &[u8]) -> Result<u32, IoError> {
    let index = match value {
        0 => None,
        v if v > 0 => Some(v - 1),
        v => (vertex_count as i64).checked_add(v).filter(|&i| i >= 0),
    };
    index.and_then(|i| u32::try_from(i).ok()).ok_or_else(|| {
        IoError::parse(
            Location::Line(line),
            format!(
                "vertex index {} is invalid: expected 1 to {vertex_count} or -1 to -{vertex_count}",
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
    writeln!(
        w,
        "# weft {}: {} vertices, {} faces",
        crate::VERSION,
        mesh.vertex_count(),
        mesh.face_count()
    )?;
    for p in mesh.positions() {
        writeln!(w, "v {} {} {}", p.x, p.y, p.z)?;
    }
    for face in mesh.faces() {
        w.write_all(b"f")?;
        for &v in face {
            write!(w, " {}", v as u64 + 1)?;
        }
        w.write_all(b"\n")?;
    }
    Ok(())
}
