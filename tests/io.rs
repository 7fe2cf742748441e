//! Mesh files: round trips through every format on named shapes, malformed
//! files that must name their line or byte offset, and arbitrary bytes that
//! must not panic.

use std::path::PathBuf;

use weft::io::{self, Format, IoError, Location, PlyEncoding, WriteOptions};
use weft::{shapes, DVec3, Mesh};

fn shapes_to_test() -> Vec<(&'static str, Mesh)> {
    let mut far = shapes::cube();
    // Coordinates that need every digit, far from the origin.
    for (i, p) in far.positions_mut().iter_mut().enumerate() {
        *p = *p * 0.1 + DVec3::new(1.0e6 + 1.0 / 3.0, -2.5e-7 * i as f64, std::f64::consts::PI);
    }
    vec![
        ("cube", shapes::cube()),
        ("far cube", far),
        ("torus", shapes::torus(12, 8)),
        ("icosahedron", shapes::icosahedron()),
        ("mixed polygons", shapes::mixed_polygons()),
        ("grid with hole", shapes::quad_grid_with_hole()),
    ]
}

fn encode(format: Format, mesh: &Mesh, options: &WriteOptions) -> Vec<u8> {
    let mut bytes = Vec::new();
    io::write_to(format, &mut bytes, mesh, options).unwrap();
    bytes
}

#[test]
fn exact_formats_round_trip_positions_and_polygons() {
    let cases = [
        (Format::Obj, PlyEncoding::Ascii),
        (Format::Off, PlyEncoding::Ascii),
        (Format::Ply, PlyEncoding::Ascii),
        (Format::Ply, PlyEncoding::BinaryLittleEndian),
        (Format::Ply, PlyEncoding::BinaryBigEndian),
    ];
    for (name, mesh) in shapes_to_test() {
        for (format, ply) in cases {
            let options = WriteOptions {
                ply,
                ..Default::default()
            };
            let bytes = encode(format, &mesh, &options);
            let back = io::parse_mesh(format, &bytes)
                .unwrap_or_else(|e| panic!("{name} as {format:?} {ply:?}: {e}"));
            assert_eq!(back, mesh, "{name} as {format:?} {ply:?}");
        }
    }
}

/// The triangles of a mesh as fans, for comparing with an STL soup.
fn fan_triangles(mesh: &Mesh) -> Vec<[DVec3; 3]> {
    let p = mesh.positions();
    mesh.faces()
        .flat_map(|f| (1..f.len() - 1).map(move |i| [f[0], f[i], f[i + 1]]))
        .map(|t| t.map(|v| p[v as usize]))
        .collect()
}

#[test]
fn stl_round_trips_triangles_unwelded() {
    for (name, mesh) in shapes_to_test() {
        let expected = fan_triangles(&mesh);
        for ascii in [true, false] {
            let options = WriteOptions {
                stl_ascii: ascii,
                ..Default::default()
            };
            let back = io::parse_mesh(Format::Stl, &encode(Format::Stl, &mesh, &options))
                .unwrap_or_else(|e| panic!("{name}, ascii {ascii}: {e}"));
            assert_eq!(back.face_count(), expected.len(), "{name}");
            assert_eq!(back.vertex_count(), 3 * expected.len(), "{name}");
            let got = fan_triangles(&back);
            for (t, (g, e)) in got.iter().zip(&expected).enumerate() {
                for k in 0..3 {
                    if ascii {
                        assert_eq!(g[k], e[k], "{name} triangle {t}");
                    } else {
                        // Binary STL stores f32.
                        let want = e[k].as_vec3().as_dvec3();
                        assert_eq!(g[k], want, "{name} triangle {t}");
                    }
                }
            }
            // Welding identical corners gives back the shared vertices.
            let (welded, dropped) = io::weld_identical(&back);
            assert_eq!(dropped, 0);
            let mut used: Vec<u32> = mesh.face_indices().to_vec();
            used.sort_unstable();
            used.dedup();
            assert_eq!(welded.vertex_count(), used.len(), "{name}");
        }
    }
}

#[test]
fn obj_reads_every_corner_form_and_negative_indices() {
    let text = b"# a quad and a triangle\r\n\
        mtllib x.mtl\no thing\ng group\n\
        v 0 0 0 1\nv 1 0 0 0.5 0.5 0.5\nv 1 1 0\nv 0 1 0\n\
        vt 0 0\nvn 0 0 1\ns off\n\
        f 1/1/1 2/1/1 3//1 4\n\
        f -4 -2 -1   # relative\n";
    let mesh = io::obj::parse(text).unwrap();
    assert_eq!(mesh.face_sizes(), &[4, 3]);
    assert_eq!(mesh.face(0), &[0, 1, 2, 3]);
    assert_eq!(mesh.face(1), &[0, 2, 3]);
    assert_eq!(mesh.positions()[1], DVec3::new(1.0, 0.0, 0.0));
}

#[test]
fn ply_skips_other_properties_and_elements_by_type() {
    let mut data = b"ply\r\nformat binary_big_endian 1.0\ncomment made by hand\n\
        element vertex 3\nproperty float x\nproperty uchar red\nproperty float y\nproperty float z\n\
        property list uchar short extra\n\
        element face 1\nproperty uchar flags\nproperty list int uint vertex_indices\n\
        element edge 1\nproperty int a\nproperty int b\nend_header\n"
        .to_vec();
    let vertex = |d: &mut Vec<u8>, x: f32, y: f32, z: f32| {
        d.extend(x.to_be_bytes());
        d.push(200);
        d.extend(y.to_be_bytes());
        d.extend(z.to_be_bytes());
        d.push(2);
        d.extend([0, 1, 0, 2]);
    };
    vertex(&mut data, 0.0, 0.0, 0.0);
    vertex(&mut data, 1.5, 0.0, 0.0);
    vertex(&mut data, 0.0, 2.0, -1.0);
    data.push(7);
    data.extend(3i32.to_be_bytes());
    for i in [0u32, 1, 2] {
        data.extend(i.to_be_bytes());
    }
    data.extend([0; 8]);
    let mesh = io::ply::parse(&data).unwrap();
    assert_eq!(mesh.face(0), &[0, 1, 2]);
    assert_eq!(mesh.positions()[2], DVec3::new(0.0, 2.0, -1.0));
}

fn error_at(format: Format, data: &[u8]) -> (Location, String) {
    let err = io::parse_mesh(format, data).expect_err("malformed input must fail");
    (
        err.location().expect("content errors have a place"),
        err.to_string(),
    )
}

#[test]
fn malformed_text_names_the_line() {
    let (at, msg) = error_at(Format::Obj, b"v 0 0 0\nv 1 0 0\nv 0 one 0\nf 1 2 3\n");
    assert_eq!(at, Location::Line(3));
    assert!(msg.contains("line 3") && msg.contains("\"one\""), "{msg}");

    let (at, msg) = error_at(Format::Obj, b"v 0 0 0\nv 1 0 0\nv 0 1 0\n\nf 1 2 4\n");
    assert_eq!(at, Location::Line(5));
    assert!(msg.contains("out of range"), "{msg}");

    let (at, _) = error_at(Format::Obj, b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -4\n");
    assert_eq!(at, Location::Line(4));
    let (at, msg) = error_at(Format::Obj, b"v 0 0 0\nv 1 0\n");
    assert_eq!(at, Location::Line(2));
    assert!(msg.contains("z is missing"), "{msg}");

    // A missing vertex: the header promises 4, the file has 3, so the face
    // line is read as the fourth vertex and the face is missing.
    let (at, msg) = error_at(Format::Off, b"OFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
    assert_eq!(at, Location::Line(6));
    assert!(
        msg.contains("end of file") && msg.contains("face 0"),
        "{msg}"
    );
    let (at, msg) = error_at(Format::Off, b"OFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n");
    assert_eq!(at, Location::Line(5));
    assert!(msg.contains("vertex 3 of 4"), "{msg}");
    let (at, msg) = error_at(Format::Off, b"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n");
    assert_eq!(at, Location::Line(5));
    assert!(
        msg.contains("end of file") && msg.contains("face 0"),
        "{msg}"
    );
    let (at, _) = error_at(Format::Off, b"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n");
    assert_eq!(at, Location::Line(6));

    let (at, msg) = error_at(
        Format::Ply,
        b"ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n\
          property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n\
          0 0 0\n1 0 0\n0 1 nan?\n3 0 1 2\n",
    );
    assert_eq!(at, Location::Line(12));
    assert!(msg.contains("property z of vertex 2"), "{msg}");
    let (at, msg) = error_at(
        Format::Ply,
        b"ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nend_header\n",
    );
    assert_eq!(at, Location::Line(3));
    assert!(msg.contains("x, y and z"), "{msg}");

    let (at, msg) = error_at(
        Format::Stl,
        b"solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertx 0 1 0\nendloop\nendfacet\nendsolid s\n",
    );
    assert_eq!(at, Location::Line(6));
    assert!(msg.contains("expected \"vertex\""), "{msg}");
}

#[test]
fn truncated_binary_names_the_byte_offset() {
    let mesh = shapes::cube();
    let stl = encode(Format::Stl, &mesh, &WriteOptions::default());
    assert_eq!(stl.len(), 84 + 12 * 50);
    let (at, msg) = error_at(Format::Stl, &stl[..84 + 5 * 50 + 20]);
    assert_eq!(at, Location::Byte(84 + 5 * 50));
    assert!(
        msg.contains("truncated") && msg.contains("12 triangles"),
        "{msg}"
    );
    let (at, _) = error_at(Format::Stl, &stl[..40]);
    assert_eq!(at, Location::Byte(40));

    let ply = encode(Format::Ply, &mesh, &WriteOptions::default());
    let body = ply.len() - (8 * 24 + 6 * 17);
    // Cut inside the faces: the error is at the first byte that is missing.
    let cut = body + 8 * 24 + 17 + 5;
    let (at, msg) = error_at(Format::Ply, &ply[..cut]);
    assert!(
        matches!(at, Location::Byte(b) if b >= body && b <= cut),
        "{at}"
    );
    assert!(msg.contains("byte"), "{msg}");
    // A bad index in the second face.
    let mut bad = ply.clone();
    let index_at = body + 8 * 24 + 17 + 1 + 4;
    bad[index_at..index_at + 4].copy_from_slice(&99u32.to_le_bytes());
    let (at, msg) = error_at(Format::Ply, &bad);
    assert_eq!(at, Location::Byte(body + 8 * 24 + 17));
    assert!(msg.contains("face 1") && msg.contains("99"), "{msg}");
}

#[test]
fn huge_counts_fail_without_allocating() {
    let (at, msg) = error_at(
        Format::Ply,
        b"ply\nformat binary_little_endian 1.0\nelement vertex 4000000000000\nproperty double x\n\
          property double y\nproperty double z\nend_header\n\0\0\0\0",
    );
    assert!(matches!(at, Location::Byte(_)));
    assert!(msg.contains("too short"), "{msg}");
    let mut stl = vec![0u8; 84];
    stl[80..84].copy_from_slice(&u32::MAX.to_le_bytes());
    let (_, msg) = error_at(Format::Stl, &stl);
    assert!(msg.contains("truncated"), "{msg}");
    let (at, _) = error_at(Format::Off, b"OFF\n999999999999 1 0\n0 0 0\n");
    assert_eq!(at, Location::Line(3));
}

/// A small deterministic generator (xorshift), so failures reproduce.
struct Bytes(u64);

impl Bytes {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }
}

#[test]
fn arbitrary_bytes_never_panic() {
    let mut random = Bytes(0x9e37_79b9_7f4a_7c15);
    let valid: Vec<(Format, Vec<u8>)> = [
        (Format::Obj, WriteOptions::default()),
        (Format::Off, WriteOptions::default()),
        (Format::Stl, WriteOptions::default()),
        (Format::Ply, WriteOptions::default()),
        (
            Format::Ply,
            WriteOptions {
                ply: PlyEncoding::Ascii,
                ..Default::default()
            },
        ),
    ]
    .into_iter()
    .map(|(f, o)| (f, encode(f, &shapes::mixed_polygons(), &o)))
    .collect();
    for round in 0..3000 {
        let (format, base) = &valid[round % valid.len()];
        let mut data = if round % 3 == 0 {
            let len = (random.next() % 300) as usize;
            (0..len).map(|_| random.next() as u8).collect()
        } else {
            // Valid files with a few bytes changed or cut short reach deeper.
            let mut d = base.clone();
            for _ in 0..1 + random.next() % 4 {
                let at = (random.next() as usize) % d.len();
                d[at] = random.next() as u8;
            }
            d
        };
        if round % 5 == 0 {
            let keep = (random.next() as usize) % (data.len() + 1);
            data.truncate(keep);
        }
        for f in [Format::Obj, Format::Off, Format::Stl, Format::Ply] {
            let _ = io::parse_mesh(f, &data);
        }
        let _ = format;
    }
}

fn temp_folder(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("weft-io-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

#[test]
fn files_are_chosen_by_extension_and_written_whole() {
    let dir = temp_folder("files");
    let mesh = shapes::torus(6, 4);
    for name in ["a.obj", "b.PLY", "c.Off", "d.stl"] {
        let path = dir.join(name);
        io::write_mesh(&path, &mesh).unwrap();
        let back = io::read_mesh_with(&path, &io::ReadOptions { weld: true }).unwrap();
        assert_eq!(back.vertex_count(), mesh.vertex_count(), "{name}");
        // STL splits each quad into two triangles.
        let factor = if name.ends_with("stl") { 2 } else { 1 };
        assert_eq!(back.face_count(), factor * mesh.face_count(), "{name}");
    }
    // No temporary files are left behind.
    let names: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(names.len(), 4, "{names:?}");

    let err = io::write_mesh(dir.join("x.dae"), &mesh).unwrap_err();
    assert!(matches!(err, IoError::UnknownFormat { .. }));
    let err = io::write_mesh(dir.join("missing/x.obj"), &mesh).unwrap_err();
    assert!(matches!(err, IoError::MissingFolder { .. }));
    assert!(err.to_string().contains("missing"), "{err}");
    let err = io::read_mesh(dir.join("nothing.obj")).unwrap_err();
    assert!(err.to_string().contains("nothing.obj"), "{err}");

    std::fs::write(dir.join("bad.obj"), "v 0 0 0\nf 1 2 3\n").unwrap();
    let err = io::read_mesh(dir.join("bad.obj")).unwrap_err();
    let msg = err.to_string();
    assert!(msg.contains("bad.obj") && msg.contains("line 2"), "{msg}");
    std::fs::remove_dir_all(&dir).unwrap();
}
