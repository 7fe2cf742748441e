//! Mesh files: round trips through every format on named shapes, malformed
//! files that must name their line or byte offset, and arbitrary bytes that
//! must not panic.

use weft::io::{self, Format, IoError, Location, PlyEncoding, WriteOptions};
use weft::mend::weld;
use weft::mesh::shapes;
use weft::{DVec3, Mesh};

#[path = "support/folder.rs"]
mod folder;
use folder::folder;

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

/// Each PLY encoding with the options that write it.
fn ply_encodings() -> impl Iterator<Item = (PlyEncoding, WriteOptions)> {
    [
        PlyEncoding::Ascii,
        PlyEncoding::BinaryLittleEndian,
        PlyEncoding::BinaryBigEndian,
    ]
    .into_iter()
    .map(|ply| {
        let options = WriteOptions {
            ply,
            ..WriteOptions::default()
        };
        (ply, options)
    })
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
            let (welded, report) = weld::weld(&back, 0.0).unwrap();
            assert_eq!(report.removed_face_count, 0);
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
    // The format, the text, the line the error names and words its message holds.
    let cases: [(Format, &[u8], usize, &[&str]); 16] = [
        (
            Format::Obj,
            b"v 0 0 0\nv 1 0 0\nv 0 one 0\nf 1 2 3\n",
            3,
            &["line 3", "\"one\""],
        ),
        (
            Format::Obj,
            b"v 0 0 0\nv 1 0 0\nv 0 1 0\n\nf 1 2 4\n",
            5,
            &["out of range"],
        ),
        (Format::Obj, b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -4\n", 4, &[]),
        (Format::Obj, b"v 0 0 0\nv 1 0\n", 2, &["z is missing"]),
        // A missing vertex: the header promises 4, the file has 3, so the face
        // line is read as the fourth vertex and the face is missing.
        (
            Format::Off,
            b"OFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
            6,
            &["end of file", "face 0"],
        ),
        (
            Format::Off,
            b"OFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n",
            5,
            &["vertex 3 of 4"],
        ),
        (
            Format::Off,
            b"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n",
            5,
            &["end of file", "face 0"],
        ),
        (
            Format::Off,
            b"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n",
            6,
            &[],
        ),
        (
            Format::Off,
            b"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 x\n",
            6,
            &["index 2 of face 0", "\"x\""],
        ),
        (
            Format::Off,
            b"OFF\n3 1 0\n0 0 0\n1 o 0\n0 1 0\n3 0 1 2\n",
            4,
            &["coordinate y of vertex 1", "\"o\""],
        ),
        (
            Format::Off,
            b"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\nthree 0 1 2\n",
            6,
            &["the corner count of face 0"],
        ),
        (
            Format::Ply,
            b"ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n\
              property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n\
              0 0 0\n1 0 0\n0 1 nan?\n3 0 1 2\n",
            12,
            &["property z of vertex 2"],
        ),
        (
            Format::Ply,
            b"ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nend_header\n",
            3,
            &["x, y and z"],
        ),
        (
            // Two vertex elements, one with colours: refused, not read as
            // one list of vertices with colours for half of them.
            Format::Ply,
            b"ply\nformat binary_little_endian 1.0\nelement vertex 1\nproperty float x\n\
              property float y\nproperty float z\nelement vertex 1\nproperty float x\n\
              property float y\nproperty float z\nproperty uchar red\nproperty uchar green\n\
              property uchar blue\nend_header\n",
            7,
            &["a second element \"vertex\" (the first is on line 3)"],
        ),
        (
            Format::Ply,
            b"ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n\
              property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n\
              0 0 0\n1 0 0\n0 1 0\n3 0 1\n",
            14,
            &["end of file", "entry 2 of property vertex_indices of face 0"],
        ),
        (
            Format::Stl,
            b"solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertx 0 1 0\nendloop\nendfacet\nendsolid s\n",
            6,
            &["expected \"vertex\""],
        ),
    ];
    for (format, text, line, words) in cases {
        let (at, msg) = error_at(format, text);
        assert_eq!(at, Location::Line(line), "{msg}");
        for word in words {
            assert!(msg.contains(word), "{word:?} not in {msg}");
        }
    }
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
    .chain([Format::Obj, Format::Ply].map(|f| {
        let mut bytes = Vec::new();
        let options = WriteOptions {
            ply: PlyEncoding::Ascii,
            ..Default::default()
        };
        io::write_file_to(f, &mut bytes, &decorated_cube(), &options).unwrap();
        (f, bytes)
    }))
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
        // What reads with its attributes writes and reads back alike.
        for f in [Format::Obj, Format::Ply] {
            if let Ok(file) = io::parse_mesh_file(f, &data) {
                let mut out = Vec::new();
                io::write_file_to(f, &mut out, &file, &WriteOptions::default()).unwrap();
                let again = io::parse_mesh_file(f, &out).unwrap();
                assert_eq!(again.mesh.vertex_count(), file.mesh.vertex_count());
                assert_eq!(again.colours.is_some(), file.colours.is_some());
            }
        }
        let _ = format;
    }
}

#[test]
fn files_are_chosen_by_extension_and_written_whole() {
    let dir = folder("files");
    let mesh = shapes::torus(6, 4);
    for name in ["a.obj", "b.PLY", "c.Off", "d.stl"] {
        let path = dir.join(name);
        io::write_mesh(&path, &mesh).unwrap();
        let back = io::read_mesh_with(
            &path,
            &io::ReadOptions {
                weld: true,
                ..Default::default()
            },
        )
        .unwrap();
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
}

/// A cube with a colour per vertex, UVs with a seam, normals, creases and corners.
fn decorated_cube() -> io::MeshFile {
    let mesh = shapes::cube();
    let colours = io::Colours {
        rgba: (0..8)
            .map(|i| [i as f64 / 7.0, 1.0 - i as f64 / 7.0, 0.25, 0.5])
            .collect(),
        alpha: true,
    };
    // Each face maps to the unit square: corners of one vertex differ (seams).
    let uvs = io::Uvs {
        values: vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]],
        indices: (0..24).map(|c| c % 4).collect(),
    };
    let normals = mesh
        .positions()
        .iter()
        .map(|p| (*p - DVec3::splat(0.5)).normalize())
        .collect();
    io::MeshFile {
        mesh,
        colours: Some(colours),
        uvs: Some(uvs),
        normals: Some(normals),
        creases: vec![
            io::FileCrease {
                edge: [0, 1],
                sharpness: 10.0,
                line: 0,
            },
            io::FileCrease {
                edge: [1, 3],
                sharpness: 2.5,
                line: 0,
            },
        ],
        corners: vec![io::FileCorner {
            vertex: 7,
            sharpness: 10.0,
            line: 0,
        }],
        materials: None,
        holes: vec![2, 4],
    }
}

/// Line numbers are where a reader found things; compare without them.
fn without_lines(mut file: io::MeshFile) -> io::MeshFile {
    file.creases.iter_mut().for_each(|c| c.line = 0);
    file.corners.iter_mut().for_each(|c| c.line = 0);
    file
}

#[test]
fn obj_round_trips_colours_uvs_and_creases() {
    let file = decorated_cube();
    let mut bytes = Vec::new();
    io::write_file_to(Format::Obj, &mut bytes, &file, &WriteOptions::default()).unwrap();
    let text = String::from_utf8(bytes.clone()).unwrap();
    assert!(
        text.contains("\nv 1 0 0 0.14285714285714285 0.8571428571428572 0.25 0.5\n"),
        "{text}"
    );
    assert!(text.contains("\nl 1 2\n"), "{text}");
    assert!(text.contains("\nt crease 2/1/0 1 3 2.5\n"), "{text}");
    assert!(text.contains("\nt corner 1/1/0 7 10\n"), "{text}");
    assert!(text.contains("\nt hole 2/0/0 2 4\n"), "{text}");
    assert!(text.contains("\nf 1/1/1 3/2/3 4/3/4 2/4/2\n"), "{text}");
    let read = io::parse_mesh_file(Format::Obj, &bytes).unwrap();
    // Normals are written, never read.
    let expected = io::MeshFile {
        normals: None,
        ..file
    };
    assert_eq!(without_lines(read), expected);
}

#[test]
fn ply_round_trips_colours_and_per_vertex_uvs() {
    let mut file = decorated_cube();
    file.creases.clear();
    file.corners.clear();
    file.holes.clear();
    file.normals = None;
    // uchar colours: values k/255 come back exactly.
    for (i, c) in file.colours.as_mut().unwrap().rgba.iter_mut().enumerate() {
        *c = [i as f64 / 255.0, 1.0, 0.0, 128.0 / 255.0];
    }
    // Per-vertex UVs: what PLY can hold.
    let per_vertex: Vec<[f64; 2]> = file
        .mesh
        .positions()
        .iter()
        .map(|p| [p.x, p.y + 0.5])
        .collect();
    file.uvs = Some(io::Uvs::from_per_vertex(&file.mesh, per_vertex.clone()));
    assert!(file.dropped_by(Format::Ply).is_empty());
    for (encoding, options) in ply_encodings() {
        let mut bytes = Vec::new();
        io::write_file_to(Format::Ply, &mut bytes, &file, &options).unwrap();
        let read = io::parse_mesh_file(Format::Ply, &bytes).unwrap();
        assert_eq!(read.colours, file.colours, "{encoding:?}");
        assert_eq!(
            read.uvs.as_ref().unwrap().per_vertex(&read.mesh).unwrap(),
            per_vertex
        );
        assert_eq!(read.mesh, file.mesh);
    }
    // UVs with seams do not fit; the writer leaves them out and says which.
    let seams = decorated_cube();
    assert_eq!(
        seams.dropped_by(Format::Ply),
        ["UVs", "creases", "corners", "holes"]
    );
    assert_eq!(
        seams.dropped_by(Format::Off),
        [
            "vertex colours",
            "UVs",
            "normals",
            "creases",
            "corners",
            "holes"
        ]
    );
    assert!(seams.dropped_by(Format::Obj).is_empty());
}

#[test]
fn ply_reads_float_and_integer_colours_and_writes_normals() {
    let text = b"ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n\
        property float z\nproperty float red\nproperty float green\nproperty float blue\n\
        element face 1\nproperty list uchar int vertex_indices\nend_header\n\
        0 0 0 0.5 0.25 1\n1 0 0 0 0 0\n0 1 0 1 1 1\n3 0 1 2\n";
    let file = io::parse_mesh_file(Format::Ply, text).unwrap();
    let colours = file.colours.unwrap();
    assert!(!colours.alpha);
    assert_eq!(colours.rgba[0], [0.5, 0.25, 1.0, 1.0]);
    let text = b"ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n\
        property float z\nproperty ushort red\nproperty ushort green\nproperty ushort blue\n\
        element face 1\nproperty list uchar int vertex_indices\nend_header\n\
        0 0 0 65535 0 0\n1 0 0 0 0 0\n0 1 0 0 0 0\n3 0 1 2\n";
    let file = io::parse_mesh_file(Format::Ply, text).unwrap();
    assert_eq!(file.colours.unwrap().rgba[0], [1.0, 0.0, 0.0, 1.0]);

    let mut with_normals = io::MeshFile::new(shapes::tetrahedron());
    with_normals.normals = Some(vec![DVec3::Z; 4]);
    let mut bytes = Vec::new();
    let options = WriteOptions {
        ply: PlyEncoding::Ascii,
        ..WriteOptions::default()
    };
    io::write_file_to(Format::Ply, &mut bytes, &with_normals, &options).unwrap();
    let text = String::from_utf8(bytes).unwrap();
    assert!(
        text.contains("property double nx\nproperty double ny\nproperty double nz\n"),
        "{text}"
    );
    assert!(text.contains("\n1 1 1 0 0 1\n"), "{text}");
}

/// The mesh alone reads; with its attributes the file is refused at `line`
/// with a message that says `expected`.
fn assert_attribute_error(format: Format, data: &[u8], line: usize, expected: &str) {
    io::parse_mesh(format, data).expect("the mesh alone reads");
    let err = io::parse_mesh_file(format, data).expect_err("malformed attributes must fail");
    let msg = err.to_string();
    assert_eq!(err.location(), Some(Location::Line(line)), "{msg}");
    assert!(msg.contains(expected), "{msg}");
}

#[test]
fn malformed_attributes_name_their_line() {
    // (file, line named, what the message says)
    let obj_cases: [(&[u8], usize, &str); 8] = [
        (
            b"v 0 0 0 1 0 0\nv 1 0 0\nv 0 1 0 0 0 1\nf 1 2 3\n",
            2,
            "every vertex must have a colour",
        ),
        (
            b"v 0 0 0 1 0 red\nv 1 0 0 1 0 0\nv 0 1 0 0 0 1\nf 1 2 3\n",
            1,
            "expected a number for blue",
        ),
        (
            b"v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\nf 1/1 2/1 3/1\nf 2 4 3\n",
            7,
            "every corner must name one",
        ),
        (
            b"v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/2 3/1\n",
            5,
            "texture coordinate index 2 is past the last \"vt\" (1)",
        ),
        (
            b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nt corner 1/1/0 3 inf\n",
            5,
            "vertex 3 is past the last vertex",
        ),
        (
            b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nl 1\n",
            5,
            "at least 2 vertex indices",
        ),
        (
            b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nt crease 2/1/0 0 1 sharp\n",
            5,
            "expected a sharpness",
        ),
        (
            b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nt corner 1/1/0 0\n",
            5,
            "t corner 1/1/0 v sharpness",
        ),
    ];
    for (data, line, expected) in obj_cases {
        assert_attribute_error(Format::Obj, data, line, expected);
    }
    let ply = b"ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n\
        property float z\nproperty uchar red\nproperty uchar green\n\
        element face 1\nproperty list uchar int vertex_indices\nend_header\n\
        0 0 0 1 1\n1 0 0 1 1\n0 1 0 1 1\n3 0 1 2\n";
    assert_attribute_error(Format::Ply, ply, 3, "red, green and blue");
}

/// Each crease as its edge, sharpness and line, to compare with a list.
fn crease_rows(creases: &[io::FileCrease]) -> Vec<([u32; 2], f64, usize)> {
    creases
        .iter()
        .map(|c| (c.edge, c.sharpness, c.line))
        .collect()
}

#[test]
fn obj_polylines_and_tags_become_creases_and_corners() {
    let text = b"v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n\
        l 1 2 3   # two hard creases\n\
        t crease 3/1/0 2 3 0 1.5\n\
        t crease 3/2/0 0 3 2 2 3\n\
        t corner 2/1/0 0 2 inf\n\
        t interpolateboundary 1/0/0 1\n";
    let file = io::parse_mesh_file(Format::Obj, text).unwrap();
    let creases = crease_rows(&file.creases);
    assert_eq!(
        creases,
        [
            ([0, 1], 10.0, 6),
            ([1, 2], 10.0, 6),
            ([2, 3], 1.5, 7),
            ([3, 0], 1.5, 7),
            ([0, 3], 2.0, 8),
            ([3, 2], 3.0, 8),
        ]
    );
    let corners: Vec<(u32, f64)> = file
        .corners
        .iter()
        .map(|c| (c.vertex, c.sharpness))
        .collect();
    assert_eq!(corners, [(0, 10.0), (2, 10.0)]);
    file.check_creases().unwrap();

    // A polyline that is not along the mesh's edges is refused where it is used.
    let text = b"v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\nl 1 3\n";
    let file = io::parse_mesh_file(Format::Obj, text).unwrap();
    let err = file.check_creases().unwrap_err();
    assert_eq!(err.location(), Some(Location::Line(6)));
    assert!(err.to_string().contains("vertex 0 to vertex 2"), "{err}");
}

#[test]
fn crease_side_files_parse_and_name_bad_lines() {
    let text = b"# creases of a cube\n0 1 inf\n\n1 3 2.5   # semi-sharp\ncrease 3 2 Infinity\nCORNER 7 inf\ncorner 6 0.5\n";
    let file = io::creases::parse(text).unwrap();
    let creases = crease_rows(&file.creases);
    assert_eq!(
        creases,
        [([0, 1], 10.0, 2), ([1, 3], 2.5, 4), ([3, 2], 10.0, 5)]
    );
    let corners: Vec<(u32, f64, usize)> = file
        .corners
        .iter()
        .map(|c| (c.vertex, c.sharpness, c.line))
        .collect();
    assert_eq!(corners, [(7, 10.0, 6), (6, 0.5, 7)]);

    // Written and read back, the same.
    let mut bytes = Vec::new();
    io::creases::write(&mut bytes, &file).unwrap();
    let again = io::creases::parse(&bytes).unwrap();
    assert_eq!(again.creases.len(), 3);
    assert_eq!(again.corners[1].sharpness, 0.5);

    for (text, line, expected) in [
        (
            &b"0 1 inf\n0 1\n"[..],
            2,
            "a crease takes two vertices and a sharpness",
        ),
        (b"0 1 -2\n", 1, "expected a sharpness"),
        (b"0 1 nan\n", 1, "expected a sharpness"),
        (b"\n\nedge 0 1 2\n", 3, "expected \"i j sharpness\""),
        (
            b"corner 1\n",
            1,
            "a corner takes one vertex and a sharpness",
        ),
        (b"0 -1 inf\n", 1, "expected a non-negative integer"),
        (b"2 2 inf\n", 1, "two different vertices"),
    ] {
        let err = io::creases::parse(text).unwrap_err();
        assert_eq!(err.location(), Some(Location::Line(line)), "{err}");
        assert!(err.to_string().contains(expected), "{err}");
    }
}

#[test]
fn render_coloured_paints_faces_in_their_vertices_colours() {
    use weft::io::render::{render, render_coloured, RenderOptions};
    let cube = shapes::cube();
    let options = RenderOptions {
        width: 80,
        height: 60,
        edges: Some(false),
        ..RenderOptions::default()
    };
    let red = vec![[1.0, 0.0, 0.0, 1.0]; 8];
    let image = render_coloured(&cube, &options, &red).unwrap();
    let [r, g, b] = image.pixel(40, 30);
    assert!(r > 100 && g < 20 && b < 20, "{:?}", [r, g, b]);
    let plain = render(&cube, &options).unwrap();
    let [r, g, b] = plain.pixel(40, 30);
    assert!(b > r && b > g, "{:?}", [r, g, b]);
    assert!(render_coloured(&cube, &options, &red[..7]).is_err());
}

/// A large mesh is drawn on two threads, half the faces each; the picture
/// must be exactly the one drawn on one thread, also where faces of the two
/// halves lie at the same depth (the earlier face stays) and where a later
/// face hides an earlier one.
#[test]
fn render_on_two_threads_equals_one_thread() {
    use weft::io::render::{render, RenderOptions, View};
    use weft::mesh::shapes;
    let grid = shapes::quad_grid(300, 200);
    let n = grid.vertex_count() as u32;
    // The same grid again, reversed (back faces, another colour) and
    // lifted a little on one side so that it crosses the first.
    let mut positions = grid.positions().to_vec();
    positions.extend(grid.positions().iter().map(|p| {
        let lift = if p.x > 150.0 { 0.5 } else { 0.0 };
        glam::DVec3::new(p.x, p.y, p.z + lift)
    }));
    let mut faces: Vec<Vec<u32>> = grid.faces().map(|f| f.to_vec()).collect();
    faces.extend(
        grid.faces()
            .map(|f| f.iter().rev().map(|&v| v + n).collect::<Vec<u32>>()),
    );
    let mesh = weft::Mesh::from_polygons(positions, faces).unwrap();
    assert!(mesh.face_count() >= 100_000);
    for view in [View::Iso, View::Top, View::Bottom] {
        let options = RenderOptions {
            width: 320,
            height: 240,
            view,
            ..RenderOptions::default()
        };
        let draw = |threads: usize| {
            rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .unwrap()
                .install(|| render(&mesh, &options).unwrap())
        };
        assert_eq!(draw(1), draw(2), "{view:?}");
    }
}

#[test]
fn obj_face_lines_are_written_as_the_formatter_writes_them() {
    // Indices of every digit count, and faces from 3 to 12 corners (past
    // the 8 a line is put together for on the stack), over many rounds of
    // the parallel writer, vertices and faces.
    let positions: Vec<DVec3> = (0..1_000_001)
        .map(|i| DVec3::new(i as f64, 0.0, 1.0))
        .collect();
    let kinds: Vec<Vec<u32>> = vec![
        vec![0, 1, 2],
        vec![9, 10, 99, 100],
        (0..5).map(|i| i * 200_000).collect(),
        vec![
            999, 1000, 9_999, 10_000, 99_999, 100_000, 999_999, 1_000_000,
        ],
        (0..9).map(|i| i * 111_111).collect(),
        (0..12).map(|i| 1_000_000 - i * 7).collect(),
    ];
    let faces: Vec<Vec<u32>> = kinds.iter().cycle().take(6 * 50_000).cloned().collect();
    let mesh = Mesh::from_polygons(positions, faces.clone()).unwrap();
    let text = String::from_utf8(encode(Format::Obj, &mesh, &WriteOptions::default())).unwrap();
    let vertices = text.lines().filter(|l| l.starts_with('v'));
    assert!(vertices
        .enumerate()
        .all(|(i, line)| line == format!("v {i} 0 1")));
    let written: Vec<&str> = text.lines().filter(|l| l.starts_with('f')).collect();
    let expected: Vec<String> = faces
        .iter()
        .map(|f| {
            let corners: Vec<String> = f.iter().map(|v| format!("{}", v + 1)).collect();
            format!("f {}", corners.join(" "))
        })
        .collect();
    assert_eq!(written, expected);
    assert!(text.ends_with(
        "f 1000001 999994 999987 999980 999973 999966 999959 999952 999945 999938 999931 999924\n"
    ));
}

#[test]
fn off_is_written_as_the_formatter_writes_it() {
    // Coordinates of every form the formatter writes (negative zero, tiny,
    // huge, integers, long decimals) and faces of 3 to 12 corners, over
    // many rounds of the parallel writer.
    let values = [
        -0.0,
        1e-300,
        5e-324,
        1e21,
        123456789.0,
        -0.1,
        1.0 / 3.0,
        2.5,
        -7.0,
    ];
    let positions: Vec<DVec3> = (0..200_000)
        .map(|i| {
            let v = |k: usize| values[(i * 7 + k) % values.len()] * (1 + i % 5) as f64;
            DVec3::new(v(0), v(1), v(2))
        })
        .collect();
    let faces: Vec<Vec<u32>> = (0..200_000u32)
        .map(|f| {
            (0..3 + f % 10)
                .map(|k| (f * 13 + k * 1_009) % 200_000)
                .collect()
        })
        .collect();
    let mesh = Mesh::from_polygons(positions.clone(), faces.clone()).unwrap();
    let text = String::from_utf8(encode(Format::Off, &mesh, &WriteOptions::default())).unwrap();
    let mut expected = format!("OFF\n{} {} 0\n", positions.len(), faces.len());
    for p in &positions {
        expected += &format!("{} {} {}\n", p.x, p.y, p.z);
    }
    for face in &faces {
        let corners: Vec<String> = face.iter().map(u32::to_string).collect();
        expected += &format!("{} {}\n", face.len(), corners.join(" "));
    }
    assert!(
        text == expected,
        "the OFF text differs from the formatter's"
    );
    assert_eq!(io::parse_mesh(Format::Off, text.as_bytes()).unwrap(), mesh);
}

#[test]
fn ply_and_stl_are_written_as_the_formatter_and_byte_order_say() {
    // 150,000 vertices with normals, colours with alpha and texture
    // coordinates, and faces of 3 to 12 corners: many rounds of the
    // parallel writer, checked against the plainest writing of each format.
    let count = 150_000u32;
    let positions: Vec<DVec3> = (0..count)
        .map(|i| DVec3::new(i as f64 / 7.0, -(i as f64) * 1e-9, (i % 13) as f64 * 1e20))
        .collect();
    let faces: Vec<Vec<u32>> = (0..count)
        .map(|f| (0..3 + f % 10).map(|k| (f + k * 11) % count).collect())
        .collect();
    let mesh = Mesh::from_polygons(positions.clone(), faces.clone()).unwrap();
    let normals: Vec<DVec3> = (0..count)
        .map(|i| DVec3::new(0.0, (i as f64).sin(), 1.0))
        .collect();
    let rgba: Vec<[f64; 4]> = (0..count)
        .map(|i| [(i % 256) as f64 / 255.0, 0.5, 1.5, -0.25])
        .collect();
    let uvs: Vec<[f64; 2]> = (0..count).map(|i| [i as f64 / 3.0, 0.75]).collect();
    let mut file = io::MeshFile::new(mesh.clone());
    file.normals = Some(normals.clone());
    file.colours = Some(io::Colours {
        rgba: rgba.clone(),
        alpha: true,
    });
    file.uvs = Some(io::Uvs::from_per_vertex(&mesh, uvs.clone()));
    let byte = |c: f64| (c.clamp(0.0, 1.0) * 255.0).round() as u8;
    for (encoding, options) in ply_encodings() {
        let mut written = Vec::new();
        io::write_file_to(Format::Ply, &mut written, &file, &options).unwrap();
        let body_at = written
            .windows(11)
            .position(|w| w == b"end_header\n")
            .unwrap()
            + 11;
        let mut expected = Vec::new();
        let big = encoding == PlyEncoding::BinaryBigEndian;
        let double = |out: &mut Vec<u8>, x: f64| {
            out.extend(if big {
                x.to_be_bytes()
            } else {
                x.to_le_bytes()
            })
        };
        for i in 0..count as usize {
            let (p, n, [s, t]) = (positions[i], normals[i], uvs[i]);
            let bytes = rgba[i].map(byte);
            if encoding == PlyEncoding::Ascii {
                let [r, g, b, a] = bytes;
                expected.extend(
                    format!(
                        "{} {} {} {} {} {} {r} {g} {b} {a} {s} {t}\n",
                        p.x, p.y, p.z, n.x, n.y, n.z
                    )
                    .bytes(),
                );
            } else {
                p.to_array()
                    .into_iter()
                    .for_each(|c| double(&mut expected, c));
                n.to_array()
                    .into_iter()
                    .for_each(|c| double(&mut expected, c));
                expected.extend(bytes);
                double(&mut expected, s);
                double(&mut expected, t);
            }
        }
        for face in &faces {
            if encoding == PlyEncoding::Ascii {
                let corners: Vec<String> = face.iter().map(u32::to_string).collect();
                expected.extend(format!("{} {}\n", face.len(), corners.join(" ")).bytes());
            } else {
                expected.push(face.len() as u8);
                for &v in face {
                    expected.extend(if big {
                        v.to_be_bytes()
                    } else {
                        v.to_le_bytes()
                    });
                }
            }
        }
        assert!(written[body_at..] == expected[..], "{encoding:?}");
    }
    // STL: each face's fan, normal first, in `f32` or as text.
    let triangles: Vec<[DVec3; 3]> = faces
        .iter()
        .flat_map(|face| {
            let p = |k: usize| positions[face[k] as usize];
            (1..face.len() - 1).map(move |k| [p(0), p(k), p(k + 1)])
        })
        .collect();
    let normal = |[a, b, c]: [DVec3; 3]| (b - a).cross(c - a).normalize_or_zero();
    let small = Mesh::from_polygons(
        positions
            .iter()
            .map(|p| DVec3::new(p.x, p.y, p.z * 1e-20))
            .collect(),
        faces.clone(),
    )
    .unwrap();
    let small_triangles: Vec<[DVec3; 3]> = triangles
        .iter()
        .map(|t| t.map(|p| DVec3::new(p.x, p.y, p.z * 1e-20)))
        .collect();
    let binary = encode(Format::Stl, &small, &WriteOptions::default());
    let mut expected = Vec::new();
    for &t in &small_triangles {
        for v in std::iter::once(normal(t)).chain(t) {
            v.to_array()
                .into_iter()
                .for_each(|c| expected.extend((c as f32).to_le_bytes()));
        }
        expected.extend([0, 0]);
    }
    assert_eq!(&binary[80..84], &(triangles.len() as u32).to_le_bytes());
    assert!(binary[84..] == expected[..], "binary STL");
    let options = WriteOptions {
        stl_ascii: true,
        ..Default::default()
    };
    let text = String::from_utf8(encode(Format::Stl, &mesh, &options)).unwrap();
    let mut expected = String::from("solid weft\n");
    for &t in &triangles {
        let n = normal(t);
        expected += &format!("  facet normal {} {} {}\n    outer loop\n", n.x, n.y, n.z);
        for p in t {
            expected += &format!("      vertex {} {} {}\n", p.x, p.y, p.z);
        }
        expected += "    endloop\n  endfacet\n";
    }
    expected += "endsolid weft\n";
    assert!(text == expected, "text STL");
}

#[test]
fn stl_read_to_weld_welds_as_the_soup_and_counts_every_merge() {
    let dir = folder("read-to-weld");
    for (name, mesh) in [
        ("cube", shapes::cube()),
        ("torus", shapes::triangle_torus(40, 30)),
    ] {
        let (stl, obj) = (
            dir.join(format!("{name}.stl")),
            dir.join(format!("{name}.obj")),
        );
        io::write_mesh(&stl, &mesh).unwrap();
        io::write_mesh(&obj, &mesh).unwrap();
        let soup = io::read_mesh(&stl).unwrap();
        let read = io::read_mesh_to_weld(&stl, &io::ReadOptions::default()).unwrap();
        assert!(read.merged_copies > 0, "{name}");
        assert_eq!(
            read.mesh.vertex_count() + read.merged_copies,
            soup.vertex_count()
        );
        for tolerance in [0.0, 0.1] {
            let (welded, report) = weld::weld(&read.mesh, tolerance).unwrap();
            let (expected, expected_report) = weld::weld(&soup, tolerance).unwrap();
            assert_eq!(welded, expected, "{name} at {tolerance}");
            assert_eq!(
                report.merged_vertex_count + read.merged_copies,
                expected_report.merged_vertex_count
            );
        }
        // With the weld at tolerance 0: the welded mesh, every merge counted.
        let options = io::ReadOptions {
            weld: true,
            ..Default::default()
        };
        let welded = io::read_mesh_to_weld(&stl, &options).unwrap();
        let (expected, report) = weld::weld(&soup, 0.0).unwrap();
        assert_eq!(welded.mesh, expected);
        assert_eq!(welded.merged_copies, report.merged_vertex_count);
        assert_eq!(io::read_mesh_with(&stl, &options).unwrap(), expected);
        // Other formats are read as they are, nothing merged.
        let plain = io::read_mesh_to_weld(&obj, &io::ReadOptions::default()).unwrap();
        assert_eq!(
            (plain.mesh, plain.merged_copies),
            (io::read_mesh(&obj).unwrap(), 0)
        );
    }
}
