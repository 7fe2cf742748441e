//! What real files showed: failures reproduced on meshes built here.

use weft::io::render::{render, RenderOptions, Up, View};
use weft::io::{parse_mesh, Format};
use weft::make::primitives::uv_sphere;
use weft::mend::weld::{relative_tolerance, weld, DEFAULT_WELD_TOLERANCE};
use weft::mesh::shapes;
use weft::{DVec3, Mesh};

#[path = "support/folder.rs"]
mod folder;
use folder::folder;

#[test]
fn the_relative_tolerance_keeps_every_face_of_a_small_dense_sphere() {
    // A 5 cm sphere of 2048 faces: near its poles, vertices lie closer than
    // the absolute 0.001, which collapses faces there.
    let sphere = uv_sphere(0.025, 64, 32).unwrap();
    assert_eq!(sphere.face_count(), 2048);
    let (_, absolute) = weld(&sphere, DEFAULT_WELD_TOLERANCE).unwrap();
    assert!(absolute.removed_face_count > 0, "{absolute:?}");

    let tolerance = relative_tolerance(&sphere);
    let diagonal = 0.05 * 3f64.sqrt();
    assert!((tolerance - diagonal * 1e-6).abs() < 1e-12, "{tolerance}");
    let (welded, relative) = weld(&sphere, tolerance).unwrap();
    assert_eq!(relative.removed_face_count, 0, "{relative:?}");
    assert_eq!(welded.face_count(), sphere.face_count());
}

#[test]
fn the_relative_tolerance_still_joins_split_corners() {
    // Each face of a grid with its own corners, 1e-9 apart from its
    // neighbours': a file's round-off, which the relative tolerance merges.
    let grid = shapes::quad_grid(20, 20);
    let mut positions = Vec::new();
    for (k, &v) in grid.face_indices().iter().enumerate() {
        positions.push(grid.positions()[v as usize] + DVec3::splat((k % 3) as f64 * 1e-9));
    }
    let indices = (0..grid.index_count() as u32).collect();
    let loose = Mesh::new(positions, grid.face_sizes().to_vec(), indices).unwrap();
    let (welded, report) = weld(&loose, relative_tolerance(&loose)).unwrap();
    assert_eq!(welded.vertex_count(), grid.vertex_count());
    assert_eq!(report.removed_face_count, 0);
    assert_eq!(relative_tolerance(&Mesh::default()), 0.0);
}

#[test]
fn a_ply_whose_magic_is_in_capitals_is_read() {
    let text = "PLY\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n\
                property float z\nelement face 1\nproperty list uchar int vertex_indices\n\
                end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
    let mesh = parse_mesh(Format::Ply, text.as_bytes()).unwrap();
    assert_eq!((mesh.vertex_count(), mesh.face_count()), (3, 1));
    let wrong = parse_mesh(Format::Ply, text.replacen("PLY", "PLX", 1).as_bytes());
    assert!(wrong.unwrap_err().to_string().contains("\"ply\""));
}

/// One square facing +z (or +y with `y_up`), seen in the middle of the picture.
fn centre_of_square(view: View, up: Up, y_up: bool) -> [u8; 3] {
    let p = |x: f64, y: f64| if y_up { [x, 0.0, -y] } else { [x, y, 0.0] };
    let corners = [p(0.0, 0.0), p(1.0, 0.0), p(1.0, 1.0), p(0.0, 1.0)];
    let square = Mesh::new(
        corners.iter().map(|&c| DVec3::from_array(c)).collect(),
        vec![4],
        vec![0, 1, 2, 3],
    )
    .unwrap();
    let options = RenderOptions {
        width: 60,
        height: 60,
        edges: Some(false),
        view,
        up,
        ..RenderOptions::default()
    };
    render(&square, &options).unwrap().pixel(30, 30)
}

/// Front faces are blue-grey (blue above red), back faces orange.
fn is_front(rgb: [u8; 3]) -> bool {
    rgb[2] > rgb[0]
}

#[test]
fn the_camera_looks_from_the_view_asked_for_with_either_axis_up() {
    assert!(is_front(centre_of_square(View::Top, Up::Z, false)));
    assert!(!is_front(centre_of_square(View::Bottom, Up::Z, false)));
    assert!(is_front(centre_of_square(View::Iso, Up::Z, false)));
    // A Y-up scan seen with z up is seen from its side; with y up, from above.
    assert!(is_front(centre_of_square(View::Top, Up::Y, true)));
    assert!(!is_front(centre_of_square(View::Bottom, Up::Y, true)));
    assert!(is_front(centre_of_square(View::Iso, Up::Y, true)));
}

#[test]
fn face_edges_are_drawn_by_default_only_where_faces_have_room() {
    let options = |edges| RenderOptions {
        edges,
        ..RenderOptions::default()
    };
    // 800 × 600 with 2500 faces: 192 pixels a face, too few for edges.
    let dense = shapes::quad_grid(50, 50);
    let by_default = render(&dense, &options(None)).unwrap();
    assert!(by_default == render(&dense, &options(Some(false))).unwrap());
    assert!(by_default != render(&dense, &options(Some(true))).unwrap());
    // 400 faces: 1200 pixels a face.
    let coarse = shapes::quad_grid(20, 20);
    let by_default = render(&coarse, &options(None)).unwrap();
    assert!(by_default == render(&coarse, &options(Some(true))).unwrap());
}

#[test]
fn an_inset_wider_than_a_face_is_refused_naming_the_face() {
    use weft::toolbar::transform::{picture_frame, window, InsetMode};
    // A triangle's inset turns over past a third of its edges.
    let triangle = Mesh::new(
        vec![DVec3::ZERO, DVec3::X, DVec3::Y],
        vec![3],
        vec![0, 1, 2],
    )
    .unwrap();
    assert!(picture_frame(&triangle, &[0.3], InsetMode::EdgeFraction).is_ok());
    let error = picture_frame(&triangle, &[0.4], InsetMode::EdgeFraction).unwrap_err();
    let message = error.to_string();
    assert!(message.contains("face 0"), "{message}");
    assert!(message.contains("at most 0.333"), "{message}");
    // A unit square takes a frame of width up to half its side.
    let square = shapes::quad_grid(1, 1);
    assert!(window(&square, &[0.45], InsetMode::Parallelogram).is_ok());
    let message = window(&square, &[0.6], InsetMode::Parallelogram)
        .unwrap_err()
        .to_string();
    assert!(message.contains("at most 0.5"), "{message}");
}

/// `count` unit cubes in a row, every third inside out, as one mesh with
/// each triangle's corners of its own (as STL stores them).
fn boxes_as_stl_triangles(count: usize) -> Mesh {
    let cube = weft::mesh::triangulate::triangulate(&shapes::cube())
        .unwrap()
        .mesh;
    let mut positions = Vec::new();
    let mut sizes = Vec::new();
    for b in 0..count {
        let offset = DVec3::new(2.0 * b as f64, 0.0, 0.0);
        for face in cube.faces() {
            let mut corners: Vec<DVec3> = face
                .iter()
                .map(|&v| cube.positions()[v as usize] + offset)
                .collect();
            if b % 3 == 1 {
                corners.reverse();
            }
            positions.extend(corners);
            sizes.push(3);
        }
    }
    let indices = (0..positions.len() as u32).collect();
    Mesh::new(positions, sizes, indices).unwrap()
}

#[test]
fn welded_boxes_some_inside_out_are_all_turned_outward() {
    use weft::mend::orient::{orient_outward, signed_volume};
    let stl = boxes_as_stl_triangles(9);
    // Unwelded, every triangle is an open piece of its own: nothing to turn.
    let (_, unwelded) = orient_outward(&stl);
    assert_eq!(
        (
            unwelded.pieces,
            unwelded.open_pieces,
            unwelded.turned_outward
        ),
        (108, 108, 0)
    );

    let (welded, _) = weld(&stl, relative_tolerance(&stl)).unwrap();
    let (outward, report) = orient_outward(&welded);
    assert_eq!(report.pieces, 9);
    assert_eq!(report.turned_outward, 3);
    assert_eq!(report.open_pieces, 0);
    assert_eq!(report.flipped_faces, 3 * 12);
    assert!((signed_volume(&outward) - 9.0).abs() < 1e-9);
}

/// An OBJ of two quads in two materials, one face before any `usemtl`, and
/// two vertices no face uses.
const MATERIAL_OBJ: &str = "mtllib panels.mtl\n\
    v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nv 1 1 0\nv 2 1 0\nv 0 2 0\nv 1 2 0\nv 5 5 5\nv 6 6 6\n\
    f 1 2 5 4\n\
    usemtl glass pane\nf 2 3 6 5\n\
    usemtl steel\nf 4 5 8 7\n";

#[test]
fn obj_materials_are_read_and_written_back() {
    use weft::io::{parse_mesh_file, write_file_to, WriteOptions, NO_MATERIAL};
    let file = parse_mesh_file(Format::Obj, MATERIAL_OBJ.as_bytes()).unwrap();
    let materials = file.materials.as_ref().expect("materials are read");
    assert_eq!(materials.libraries, ["panels.mtl"]);
    assert_eq!(materials.names, ["glass pane", "steel"]);
    assert_eq!(materials.face_materials, [NO_MATERIAL, 0, 1]);
    assert_eq!(file.mesh.vertex_count(), 10, "bare vertices stay in place");

    let mut bytes = Vec::new();
    write_file_to(Format::Obj, &mut bytes, &file, &WriteOptions::default()).unwrap();
    let text = String::from_utf8(bytes.clone()).unwrap();
    assert!(text.contains("mtllib panels.mtl\n"), "{text}");
    assert!(
        text.contains("usemtl glass pane\nf 2 3 6 5\nusemtl steel\n"),
        "{text}"
    );
    let again = parse_mesh_file(Format::Obj, &bytes).unwrap();
    assert_eq!(again.materials, file.materials);
}

#[test]
fn subdivided_and_triangulated_faces_keep_their_parents_materials() {
    let dir = folder("materials");
    let input = dir.join("panels.obj");
    std::fs::write(&input, MATERIAL_OBJ).unwrap();
    let weft = env!("CARGO_BIN_EXE_weft");
    let run = |args: &[&str]| {
        let out = std::process::Command::new(weft)
            .args(args)
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "{args:?}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
    };
    let subdivided = dir.join("smooth.obj");
    let triangles = dir.join("triangles.obj");
    let (i, s, t) = (
        input.to_str().unwrap(),
        subdivided.to_str().unwrap(),
        triangles.to_str().unwrap(),
    );
    run(&[&["subdivide", i, s][..], &SMOOTH_TWICE].concat());
    run(&["triangulate", i, t]);
    let read = |path: &std::path::Path| {
        weft::io::parse_mesh_file(Format::Obj, &std::fs::read(path).unwrap()).unwrap()
    };
    use weft::io::NO_MATERIAL;
    let smooth = read(&subdivided);
    let m = smooth.materials.expect("subdivide keeps the materials");
    assert_eq!(m.libraries, ["panels.mtl"]);
    // Each quad has 16 children at level 2, contiguous and in face order.
    let expected: Vec<u32> = [NO_MATERIAL, 0, 1].iter().flat_map(|&x| [x; 16]).collect();
    assert_eq!(m.face_materials, expected);
    let m = read(&triangles)
        .materials
        .expect("triangulate keeps the materials");
    assert_eq!(m.face_materials, [NO_MATERIAL, NO_MATERIAL, 0, 0, 1, 1]);
}

fn violet_pixels(image: &weft::io::render::Image) -> usize {
    let (w, h) = (image.width, image.height);
    (0..h)
        .flat_map(|y| (0..w).map(move |x| (x, y)))
        .filter(|&(x, y)| {
            let [r, g, b] = image.pixel(x, y);
            b > 150 && g < 80 && r > 60
        })
        .count()
}

#[test]
fn marked_edges_stand_out_and_a_section_shows_what_is_inside() {
    use weft::io::render::Section;
    let cube = shapes::cube();
    let plain = render(&cube, &RenderOptions::default()).unwrap();
    assert_eq!(violet_pixels(&plain), 0);
    let options = RenderOptions {
        marked_edges: vec![[0, 1], [1, 3], [7, 99]],
        ..RenderOptions::default()
    };
    assert!(violet_pixels(&render(&cube, &options).unwrap()) > 100);

    let cut = |point: DVec3| RenderOptions {
        section: Some(Section {
            point,
            normal: DVec3::X,
        }),
        ..RenderOptions::default()
    };
    // Cutting at the middle leaves out the face at x = 1 only.
    let half = render(&cube, &cut(DVec3::splat(0.5))).unwrap();
    assert!(half != plain);
    // Cutting below everything leaves an empty picture.
    let none = render(&cube, &cut(DVec3::splat(-1.0))).unwrap();
    let background = none.pixel(0, 0);
    assert!((0..none.height).all(|y| (0..none.width).all(|x| none.pixel(x, y) == background)));
}

/// The subdivision most of these files went through: Catmull-Clark twice,
/// the naked edges smoothed.
const SMOOTH_TWICE: [&str; 6] = [
    "--scheme",
    "catmull-clark",
    "--levels",
    "2",
    "--naked-edges",
    "smooth",
];

/// Runs `weft` with `args` in `dir`; returns (exit code, stderr).
fn weft_in(dir: &std::path::Path, args: &[&str]) -> (i32, String) {
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_weft"))
        .current_dir(dir)
        .args(args)
        .output()
        .unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

fn write_obj(path: &std::path::Path, mesh: &Mesh) {
    weft::io::write_mesh(path, mesh).unwrap();
}

#[test]
fn weld_by_default_keeps_a_small_sphere_and_refuses_to_collapse_faces() {
    let dir = folder("weld");
    write_obj(&dir.join("sphere.obj"), &uv_sphere(0.025, 64, 32).unwrap());
    let (code, err) = weft_in(&dir, &["weld", "sphere.obj", "-o", "welded.obj"]);
    assert_eq!(code, 0, "{err}");
    assert!(err.contains("removed 0 collapsed faces"), "{err}");
    let welded = weft::io::read_mesh(dir.join("welded.obj")).unwrap();
    assert_eq!(welded.face_count(), 2048);

    let coarse = [
        "weld",
        "sphere.obj",
        "-o",
        "coarse.obj",
        "--tolerance",
        "0.001",
    ];
    let (code, err) = weft_in(&dir, &coarse);
    assert_eq!(code, 1, "{err}");
    assert!(
        err.contains("would collapse") && err.contains("of 2048 faces"),
        "{err}"
    );
    assert!(
        err.contains("median edge") && err.contains("tolerance 0.001"),
        "{err}"
    );
    assert!(
        !dir.join("coarse.obj").exists(),
        "a refused weld writes nothing"
    );

    let (code, err) = weft_in(&dir, &[&coarse[..], &["--allow-collapse"]].concat());
    assert_eq!(code, 0, "{err}");
    assert!(
        weft::io::read_mesh(dir.join("coarse.obj"))
            .unwrap()
            .face_count()
            < 2048
    );

    // A negative number reaches Weft's own check, not the parser's advice.
    let (code, err) = weft_in(
        &dir,
        &["weld", "sphere.obj", "-o", "x.obj", "--tolerance", "-1"],
    );
    assert_eq!(code, 2);
    assert!(err.contains("expected a distance of 0 or more"), "{err}");
    assert!(!err.contains("-- -1"), "{err}");
}

#[test]
fn info_counts_unused_vertices_and_cull_adjacent_drops_them() {
    let dir = folder("unused");
    std::fs::write(dir.join("panels.obj"), MATERIAL_OBJ).unwrap();
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_weft"))
        .current_dir(&dir)
        .args(["info", "panels.obj", "--json"])
        .output()
        .unwrap();
    let json = String::from_utf8_lossy(&out.stdout);
    assert!(json.contains("\"unused_vertices\": 2"), "{json}");
    // Two boxes sharing a wall: culling removes the wall's two copies and
    // the vertices only they used (none here), and the two bare vertices.
    let boxes = weft::mend::weld::join(&[&shapes::cube(), &{
        let mut b = shapes::cube();
        b.positions_mut().iter_mut().for_each(|p| p.x += 1.0);
        b
    }])
    .unwrap();
    let (welded, _) = weld(&boxes, 1e-9).unwrap();
    let mut positions = welded.positions().to_vec();
    positions.push(DVec3::splat(9.0));
    let bare = Mesh::new(
        positions,
        welded.face_sizes().to_vec(),
        welded.face_indices().to_vec(),
    )
    .unwrap();
    write_obj(&dir.join("boxes.obj"), &bare);
    let (code, err) = weft_in(&dir, &["cull-adjacent", "boxes.obj", "hull.obj"]);
    assert_eq!(code, 0, "{err}");
    assert!(
        err.contains("removed 2 of 12 faces") && err.contains("1 vertices no face uses"),
        "{err}"
    );
    let hull = weft::io::read_mesh(dir.join("hull.obj")).unwrap();
    assert_eq!(weft::mend::weld::unused_vertex_count(&hull), 0);
    assert_eq!(hull.vertex_count(), 12);
}

#[test]
fn flip_outward_turns_welded_stl_boxes_outward() {
    use weft::mend::orient::signed_volume;
    let dir = folder("outward");
    let stl = boxes_as_stl_triangles(6);
    weft::io::write_mesh(dir.join("boxes.stl"), &stl).unwrap();
    let (code, err) = weft_in(&dir, &["flip", "boxes.stl", "plain.obj", "--outward"]);
    assert_eq!(code, 0, "{err}");
    assert!(err.contains("add --weld"), "{err}");
    let (code, err) = weft_in(
        &dir,
        &["flip", "boxes.stl", "out.obj", "--outward", "--weld"],
    );
    assert_eq!(code, 0, "{err}");
    assert!(
        err.contains("6 pieces: turned 2 closed ones outward"),
        "{err}"
    );
    let out = weft::io::read_mesh(dir.join("out.obj")).unwrap();
    assert!(
        (signed_volume(&out) - 6.0).abs() < 1e-6,
        "{}",
        signed_volume(&out)
    );
}

#[test]
fn odd_input_gets_a_clear_answer() {
    let dir = folder("odd");
    let subdivide_once = |input: &str| {
        let args = [
            "subdivide",
            input,
            "out.obj",
            "--scheme",
            "catmull-clark",
            "--levels",
            "1",
            "--naked-edges",
            "smooth",
        ];
        weft_in(&dir, &args)
    };
    std::fs::write(
        dir.join("points.obj"),
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2 3\n",
    )
    .unwrap();
    let (code, err) = subdivide_once("points.obj");
    assert_eq!(code, 1, "{err}");
    assert!(err.contains("has no faces"), "{err}");
    assert!(!dir.join("out.obj").exists());

    // One face of a grid turned over: subdivision warns and names the fix.
    let grid = shapes::quad_grid(2, 1);
    let mut faces: Vec<Vec<u32>> = grid.faces().map(|f| f.to_vec()).collect();
    faces[0].reverse();
    write_obj(
        &dir.join("mixed.obj"),
        &Mesh::from_polygons(grid.positions().to_vec(), faces).unwrap(),
    );
    let (code, err) = subdivide_once("mixed.obj");
    assert_eq!(code, 0, "{err}");
    assert!(
        err.contains("disagree on their orientation") && err.contains("--unify"),
        "{err}"
    );

    let (code, err) = weft_in(
        &dir,
        &[
            "render",
            "mixed.obj",
            "top.png",
            "--view",
            "top",
            "--up",
            "y",
        ],
    );
    assert_eq!(code, 0, "{err}");
    assert!(dir.join("top.png").exists());
}

#[test]
fn crease_angle_on_an_stl_creases_folds_not_every_seam() {
    let dir = folder("crease-angle");
    let cube = weft::mesh::triangulate::triangulate(&shapes::cube())
        .unwrap()
        .mesh;
    let mut positions = Vec::new();
    for &v in cube.face_indices() {
        positions.push(cube.positions()[v as usize]);
    }
    let split = Mesh::new(positions, cube.face_sizes().to_vec(), (0..36).collect()).unwrap();
    weft::io::write_mesh(dir.join("cube.stl"), &split).unwrap();
    let run = |out: &str, weld: bool| {
        let mut args = vec!["subdivide", "cube.stl", out];
        args.extend(SMOOTH_TWICE);
        args.extend(["--crease-angle", "30"]);
        if weld {
            args.push("--weld");
        }
        weft_in(&dir, &args)
    };
    let (code, err) = run("plain.obj", false);
    assert_eq!(code, 0, "{err}");
    assert!(
        err.contains("welded") && err.contains("12 edges creased"),
        "{err}"
    );
    let (code, err) = run("welded.obj", true);
    assert_eq!(code, 0, "{err}");
    assert_eq!(
        std::fs::read(dir.join("plain.obj")).unwrap(),
        std::fs::read(dir.join("welded.obj")).unwrap()
    );
}

#[test]
fn smoothing_and_rerouting_keep_the_faces_materials() {
    let dir = folder("toolbar-materials");
    std::fs::write(dir.join("panels.obj"), MATERIAL_OBJ).unwrap();
    for (out, args) in [
        (
            "smooth.obj",
            vec!["smooth", "panels.obj", "smooth.obj", "--iterations", "2"],
        ),
        (
            "reroute.obj",
            vec!["reroute", "panels.obj", "reroute.obj", "--shift", "1"],
        ),
    ] {
        let (code, err) = weft_in(&dir, &args);
        assert_eq!(code, 0, "{err}");
        let file =
            weft::io::parse_mesh_file(Format::Obj, &std::fs::read(dir.join(out)).unwrap()).unwrap();
        let materials = file.materials.expect("materials kept");
        assert_eq!(materials.names, ["glass pane", "steel"], "{out}");
        assert_eq!(
            materials.face_materials,
            [weft::io::NO_MATERIAL, 0, 1],
            "{out}"
        );
    }
}
