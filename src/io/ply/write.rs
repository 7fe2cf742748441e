//! Writing PLY: ASCII or binary of either byte order, with the vertex
//! colours, normals and texture coordinates a [`MeshFile`] holds.

use std::io::Write;

use crate::io::mesh_file::MeshFile;
use crate::io::{check_attribute_sizes, PlyEncoding};
use crate::mesh::Mesh;

/// Writes a mesh as PLY in the given encoding.
///
/// # Errors
/// Whatever the writer returns.
pub fn write(w: &mut dyn Write, mesh: &Mesh, encoding: PlyEncoding) -> std::io::Result<()> {
    // No attributes to write: the mesh is not copied into a file.
    write_with(w, mesh, &MeshFile::default(), encoding)
}

/// Writes a mesh with its vertex colours (`uchar`), normals and per-vertex
/// texture coordinates as PLY; UVs with seams and creases are left out (see
/// [`MeshFile::dropped_by`]).
///
/// # Errors
/// Whatever the writer returns; [`std::io::ErrorKind::InvalidInput`] when an
/// attribute does not have one entry per vertex (or corner).
pub fn write_file(
    w: &mut dyn Write,
    file: &MeshFile,
    encoding: PlyEncoding,
) -> std::io::Result<()> {
    check_attribute_sizes(file)?;
    write_with(w, &file.mesh, file, encoding)
}

/// Writes `mesh` with the attributes `file` holds (checked for `mesh`, or
/// none at all).
fn write_with(
    w: &mut dyn Write,
    mesh: &Mesh,
    file: &MeshFile,
    encoding: PlyEncoding,
) -> std::io::Result<()> {
    let format = match encoding {
        PlyEncoding::Ascii => "ascii",
        PlyEncoding::BinaryLittleEndian => "binary_little_endian",
        PlyEncoding::BinaryBigEndian => "binary_big_endian",
    };
    let wide = mesh.face_sizes().iter().any(|&s| s > 255);
    let uvs = file.uvs.as_ref().and_then(|uvs| uvs.per_vertex(mesh));
    let mut header = format!(
        "ply\nformat {format} 1.0\ncomment weft {}\nelement vertex {}\n\
         property double x\nproperty double y\nproperty double z\n",
        crate::VERSION,
        mesh.vertex_count(),
    );
    if file.normals.is_some() {
        header.push_str("property double nx\nproperty double ny\nproperty double nz\n");
    }
    if let Some(colours) = &file.colours {
        header.push_str("property uchar red\nproperty uchar green\nproperty uchar blue\n");
        if colours.alpha {
            header.push_str("property uchar alpha\n");
        }
    }
    if uvs.is_some() {
        header.push_str("property double s\nproperty double t\n");
    }
    header.push_str(&format!(
        "element face {}\nproperty list {} int vertex_indices\nend_header\n",
        mesh.face_count(),
        if wide { "int" } else { "uchar" },
    ));
    w.write_all(header.as_bytes())?;
    // Every number of vertex i after x y z, as doubles and bytes.
    let extras = |i: usize| -> (Vec<f64>, Vec<u8>, Option<[f64; 2]>) {
        let mut doubles = Vec::new();
        let mut bytes = Vec::new();
        if let Some(normals) = &file.normals {
            doubles.extend(normals[i].to_array());
        }
        if let Some(colours) = &file.colours {
            let channels = if colours.alpha { 4 } else { 3 };
            bytes.extend(
                colours.rgba[i][..channels]
                    .iter()
                    .map(|&c| (c.clamp(0.0, 1.0) * 255.0).round() as u8),
            );
        }
        (doubles, bytes, uvs.as_ref().map(|uvs| uvs[i]))
    };
    match encoding {
        PlyEncoding::Ascii => {
            for (i, p) in mesh.positions().iter().enumerate() {
                write!(w, "{} {} {}", p.x, p.y, p.z)?;
                let (doubles, bytes, uv) = extras(i);
                for d in doubles {
                    write!(w, " {d}")?;
                }
                for b in bytes {
                    write!(w, " {b}")?;
                }
                if let Some([s, t]) = uv {
                    write!(w, " {s} {t}")?;
                }
                w.write_all(b"\n")?;
            }
            for face in mesh.faces() {
                write!(w, "{}", face.len())?;
                for &v in face {
                    write!(w, " {v}")?;
                }
                w.write_all(b"\n")?;
            }
        }
        PlyEncoding::BinaryLittleEndian | PlyEncoding::BinaryBigEndian => {
            let big = encoding == PlyEncoding::BinaryBigEndian;
            let f64_bytes = |x: f64| {
                if big {
                    x.to_be_bytes()
                } else {
                    x.to_le_bytes()
                }
            };
            let u32_bytes = |x: u32| {
                if big {
                    x.to_be_bytes()
                } else {
                    x.to_le_bytes()
                }
            };
            for (i, p) in mesh.positions().iter().enumerate() {
                for c in p.to_array() {
                    w.write_all(&f64_bytes(c))?;
                }
                let (doubles, bytes, uv) = extras(i);
                for d in doubles {
                    w.write_all(&f64_bytes(d))?;
                }
                w.write_all(&bytes)?;
                for c in uv.into_iter().flatten() {
                    w.write_all(&f64_bytes(c))?;
                }
            }
            for face in mesh.faces() {
                if wide {
                    w.write_all(&u32_bytes(face.len() as u32))?;
                } else {
                    w.write_all(&[face.len() as u8])?;
                }
                for &v in face {
                    w.write_all(&u32_bytes(v))?;
                }
            }
        }
    }
    Ok(())
}
