//! Writing PLY: ASCII or binary of either byte order, with the vertex
//! colours, normals and texture coordinates a [`MeshFile`] holds.

use std::io::Write;

use crate::io::blocks::write_in_blocks;
use crate::io::decimal::{push_counted_face, push_f64, push_u64};
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
    let positions = mesh.positions();
    let colours = file
        .colours
        .as_ref()
        .map(|c| (&c.rgba, if c.alpha { 4 } else { 3 }));
    // A colour channel as the byte written.
    let byte = |c: f64| (c.clamp(0.0, 1.0) * 255.0).round() as u8;
    if encoding == PlyEncoding::Ascii {
        write_in_blocks(w, positions.len(), |vertices, w| {
            for i in vertices {
                let p = positions[i];
                push_f64(w, p.x);
                for c in [p.y, p.z]
                    .into_iter()
                    .chain(file.normals.iter().flat_map(|n| n[i].to_array()))
                {
                    w.push(b' ');
                    push_f64(w, c);
                }
                if let Some((rgba, channels)) = colours {
                    for &c in &rgba[i][..channels] {
                        w.push(b' ');
                        push_u64(w, byte(c).into());
                    }
                }
                for c in uvs.iter().flat_map(|uvs| uvs[i]) {
                    w.push(b' ');
                    push_f64(w, c);
                }
                w.push(b'\n');
            }
            Ok(())
        })?;
        return write_in_blocks(w, mesh.face_count(), |faces, w| {
            faces.for_each(|f| push_counted_face(w, mesh.face(f)));
            Ok(())
        });
    }
    let big = encoding == PlyEncoding::BinaryBigEndian;
    let push_double = |w: &mut Vec<u8>, x: f64| {
        w.extend_from_slice(&if big {
            x.to_be_bytes()
        } else {
            x.to_le_bytes()
        });
    };
    let push_int = |w: &mut Vec<u8>, x: u32| {
        w.extend_from_slice(&if big {
            x.to_be_bytes()
        } else {
            x.to_le_bytes()
        });
    };
    write_in_blocks(w, positions.len(), |vertices, w| {
        for i in vertices {
            for c in positions[i].to_array() {
                push_double(w, c);
            }
            for c in file.normals.iter().flat_map(|n| n[i].to_array()) {
                push_double(w, c);
            }
            if let Some((rgba, channels)) = colours {
                w.extend(rgba[i][..channels].iter().map(|&c| byte(c)));
            }
            for c in uvs.iter().flat_map(|uvs| uvs[i]) {
                push_double(w, c);
            }
        }
        Ok(())
    })?;
    write_in_blocks(w, mesh.face_count(), |faces, w| {
        for f in faces {
            let face = mesh.face(f);
            if wide {
                push_int(w, face.len() as u32);
            } else {
                w.push(face.len() as u8);
            }
            for &v in face {
                push_int(w, v);
            }
        }
        Ok(())
    })
}
