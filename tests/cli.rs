//! The `weft` command, run as a program: each command's success path, and
//! its failures with their exit codes and messages.

use std::path::Path;
use std::process::{Command, Output};

use weft::io;
use weft::mesh::shapes;

#[path = "support/folder.rs"]
mod folder;
use folder::folder;

fn weft(dir: &Path, args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_weft"))
        .current_dir(dir)
        .args(args)
        .output()
        .expect("the weft binary runs")
}

fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// Every one of `expected` appears in `text`.
#[track_caller]
fn assert_mentions(text: &str, expected: &[&str]) {
    for expected in expected {
        assert!(text.contains(expected), "missing {expected:?} in\n{text}");
    }
}

#[track_caller]
fn assert_exit(o: &Output, code: i32) {
    assert_eq!(
        o.status.code(),
        Some(code),
        "stdout:\n{}\nstderr:\n{}",
        stdout(o),
        stderr(o)
    );
}

/// Runs `weft` in `dir`, checks that it exits 0, and gives its stdout.
#[track_caller]
fn succeeds(dir: &Path, args: &[&str]) -> String {
    let o = weft(dir, args);
    assert_exit(&o, 0);
    stdout(&o)
}

#[test]
fn info_reports_counts_and_properties() {
    let dir = folder("info");
    io::write_mesh(dir.join("torus.obj"), &shapes::torus(8, 6)).unwrap();
    io::write_mesh(dir.join("hole.ply"), &shapes::quad_grid_with_hole()).unwrap();

    let text = succeeds(&dir, &["info", "torus.obj"]);
    assert_mentions(
        &text,
        &[
            "vertices              48",
            "faces                 48 (0 triangles, 48 quads, 0 n-gons)",
            "edges                 96",
            "naked edges           0",
            "closed                yes",
            "orientable            yes",
        ],
    );

    // Mixed sizes are counted face by face; one size from the layout.
    let counted = [
        (
            "mixed.obj",
            "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nv 1 1 0\nv 2 1 0\nv 1 2 0\n\
             f 1 2 5 4\nf 2 3 6 5\nf 4 5 7\nf 5 6 7\n",
            "faces                 4 (2 triangles, 2 quads, 0 n-gons)",
        ),
        (
            "pentagon.obj",
            "v 0 0 0\nv 1 0 0\nv 2 1 0\nv 1 2 0\nv 0 1 0\nv 3 0 0\nf 1 2 3 4 5\nf 2 6 3\n",
            "faces                 2 (1 triangles, 0 quads, 1 n-gons)",
        ),
    ];
    for (name, text, line) in counted {
        std::fs::write(dir.join(name), text).unwrap();
        assert_mentions(&succeeds(&dir, &["info", name]), &[line]);
    }
    io::write_mesh(dir.join("icosahedron.obj"), &shapes::icosahedron()).unwrap();
    let text = succeeds(&dir, &["info", "icosahedron.obj"]);
    assert_mentions(
        &text,
        &["faces                 20 (20 triangles, 0 quads, 0 n-gons)"],
    );

    let json = succeeds(&dir, &["info", "hole.ply", "--json"]);
    assert!(
        json.trim_start().starts_with('{') && json.trim_end().ends_with('}'),
        "{json}"
    );
    assert!(json.contains("\"faces\": 12"), "{json}");
    assert!(json.contains("\"naked_edges\": 24"), "{json}");
    assert!(json.contains("\"closed\": false"), "{json}");
    assert!(
        json.contains("\"bounding_box\": {\"min\": [0, 0, 0], \"max\": [4, 4, 0]}"),
        "{json}"
    );
}

#[test]
fn mending_faces_that_share_no_vertex_suggests_weld() {
    // Twin faces, T-nodes and a consistent winding are all found through
    // shared vertices: an STL file's triangles have none until welded.
    let dir = folder("mend-soup");
    io::write_mesh(dir.join("cube.stl"), &shapes::cube()).unwrap();
    let hint = "cube.stl: no two faces share an edge, as in an STL file: add --weld";
    let commands: [&[&str]; 3] = [
        &["cull-adjacent", "cube.stl", "culled.obj"],
        &["t-nodes", "cube.stl"],
        &["flip", "--unify", "cube.stl", "unified.obj"],
    ];
    for args in commands {
        let o = weft(&dir, args);
        assert_exit(&o, 0);
        assert!(stderr(&o).contains(hint), "{args:?}: {}", stderr(&o));
        let welded = [args, &["--weld"]].concat();
        let o = weft(&dir, &welded);
        assert_exit(&o, 0);
        assert!(
            !stderr(&o).contains("share an edge"),
            "{welded:?}: {}",
            stderr(&o)
        );
    }
}

#[test]
fn info_of_faces_that_share_no_edge_suggests_weld() {
    let dir = folder("info-soup");
    io::write_mesh(dir.join("cube.stl"), &shapes::cube()).unwrap();
    io::write_mesh(dir.join("cube.obj"), &shapes::cube()).unwrap();
    let hint = "cube.stl: no two faces share an edge, as in an STL file: add --weld";

    let o = weft(&dir, &["info", "cube.stl"]);
    assert_exit(&o, 0);
    assert_mentions(
        &stdout(&o),
        &["components            12", "naked edges           36"],
    );
    assert_mentions(&stderr(&o), &[hint]);
    // The report on stdout stays one JSON object; the hint goes to stderr.
    let o = weft(&dir, &["info", "cube.stl", "--json"]);
    assert!(stdout(&o).trim().ends_with('}') && stderr(&o).contains(hint));

    for args in [&["info", "cube.stl", "--weld"][..], &["info", "cube.obj"]] {
        let o = weft(&dir, args);
        assert_exit(&o, 0);
        assert!(
            !stderr(&o).contains("share an edge"),
            "{args:?}: {}",
            stderr(&o)
        );
    }
    assert_mentions(
        &succeeds(&dir, &["info", "cube.stl", "--weld"]),
        &["components            1", "closed                yes"],
    );
}

#[test]
fn convert_keeps_the_mesh_and_welds_stl_on_request() {
    let dir = folder("convert");
    let cube = shapes::cube();
    io::write_mesh(dir.join("cube.obj"), &cube).unwrap();

    let o = weft(&dir, &["convert", "cube.obj", "cube.off"]);
    assert_exit(&o, 0);
    assert_eq!(io::read_mesh(dir.join("cube.off")).unwrap(), cube);
    let o = weft(&dir, &["convert", "cube.off", "cube.ply", "--ascii"]);
    assert_exit(&o, 0);
    assert!(std::fs::read(dir.join("cube.ply"))
        .unwrap()
        .starts_with(b"ply\nformat ascii"));
    assert_eq!(io::read_mesh(dir.join("cube.ply")).unwrap(), cube);

    let o = weft(&dir, &["convert", "cube.obj", "cube.stl"]);
    assert_exit(&o, 0);
    assert!(stderr(&o).contains("triangle fans"), "{}", stderr(&o));
    let o = weft(&dir, &["convert", "cube.stl", "soup.obj"]);
    assert_exit(&o, 0);
    let soup = io::read_mesh(dir.join("soup.obj")).unwrap();
    assert_eq!((soup.vertex_count(), soup.face_count()), (36, 12));
    let o = weft(&dir, &["convert", "--weld", "cube.stl", "welded.obj"]);
    assert_exit(&o, 0);
    let welded = io::read_mesh(dir.join("welded.obj")).unwrap();
    assert_eq!((welded.vertex_count(), welded.face_count()), (8, 12));
}

#[test]
fn render_writes_a_picture_of_the_requested_size() {
    let dir = folder("render");
    io::write_mesh(dir.join("torus.obj"), &shapes::torus(16, 8)).unwrap();
    let o = weft(
        &dir,
        &["render", "torus.obj", "torus.png", "--size", "160x120"],
    );
    assert_exit(&o, 0);

    let decoder = png::Decoder::new(std::io::BufReader::new(
        std::fs::File::open(dir.join("torus.png")).unwrap(),
    ));
    let mut reader = decoder.read_info().unwrap();
    let mut pixels = vec![0; reader.output_buffer_size().unwrap()];
    let frame = reader.next_frame(&mut pixels).unwrap();
    assert_eq!((frame.width, frame.height), (160, 120));
    assert_eq!(frame.color_type, png::ColorType::Rgb);
    let at = |x: usize, y: usize| {
        let i = 3 * (y * 160 + x);
        [pixels[i], pixels[i + 1], pixels[i + 2]]
    };
    let background = at(0, 0);
    let differing = (0..120)
        .flat_map(|y| (0..160).map(move |x| (x, y)))
        .filter(|&(x, y)| at(x, y) != background)
        .count();
    // The torus covers a good part of the picture, and not all of it.
    assert!(differing > 160 * 120 / 5, "{differing} pixels differ");
    assert!(differing < 160 * 120 * 9 / 10, "{differing} pixels differ");
    // The hole in the middle shows the background; the ring in front does not.
    assert_eq!(at(80, 58), background);
    assert_ne!(at(80, 100), background);
}

#[test]
fn flipped_faces_show_in_another_tone() {
    let dir = folder("flipped");
    let grid = shapes::quad_grid(3, 3);
    let polygons: Vec<Vec<u32>> = grid
        .faces()
        .enumerate()
        .map(|(f, face)| {
            let mut face = face.to_vec();
            if f == 4 {
                face.reverse();
            }
            face
        })
        .collect();
    let flipped = weft::Mesh::from_polygons(grid.positions().to_vec(), polygons).unwrap();
    io::write_mesh(dir.join("grid.obj"), &flipped).unwrap();
    let o = weft(
        &dir,
        &[
            "render", "grid.obj", "grid.png", "--size", "120x90", "--edges", "never",
        ],
    );
    assert_exit(&o, 0);
    let decoder = png::Decoder::new(std::io::BufReader::new(
        std::fs::File::open(dir.join("grid.png")).unwrap(),
    ));
    let mut reader = decoder.read_info().unwrap();
    let mut pixels = vec![0; reader.output_buffer_size().unwrap()];
    reader.next_frame(&mut pixels).unwrap();
    let (mut warm, mut cool) = (0, 0);
    for c in pixels.chunks(3) {
        let (r, b) = (c[0] as i32, c[2] as i32);
        if r > b + 60 {
            warm += 1;
        } else if b > r + 30 {
            cool += 1;
        }
    }
    // One face of nine is seen from the back, in the warm tone; the others
    // in the cool one. Perspective makes the far faces smaller.
    let share = warm as f64 / (warm + cool) as f64;
    assert!(
        (0.06..0.2).contains(&share),
        "{warm} warm, {cool} cool pixels"
    );
}

#[test]
fn bad_usage_exits_with_2() {
    let dir = folder("usage");
    io::write_mesh(dir.join("cube.obj"), &shapes::cube()).unwrap();
    for args in [
        &["render", "cube.obj", "cube.png", "--size", "0x10"][..],
        &["render", "cube.obj", "cube.png", "--size", "big"],
        &["render", "cube.obj", "cube.jpg"],
        &["info"],
        &["info", "cube.obj", "--colour"],
        &["convert", "cube.obj", "cube.dae"],
        &["frobnicate"],
    ] {
        let o = weft(&dir, args);
        assert_exit(&o, 2);
        assert!(stderr(&o).contains("error"), "{args:?}: {}", stderr(&o));
    }
    let o = weft(&dir, &["render", "cube.obj", "cube.png", "--size", "0x10"]);
    assert!(stderr(&o).contains("WIDTHxHEIGHT"), "{}", stderr(&o));
}

/// Every subcommand of `weft`, as `weft --help` lists them.
const COMMANDS: [&str; 31] = [
    "info",
    "render",
    "subdivide",
    "nurbs",
    "evaluate",
    "weld",
    "cull-adjacent",
    "flip",
    "t-nodes",
    "demo",
    "triangulate",
    "convert",
    "split-polygons",
    "split-triangles",
    "quad-split",
    "midedge",
    "inner-polygons",
    "sierpinski",
    "carpet",
    "smooth",
    "offset",
    "thicken",
    "window",
    "frame",
    "bevel-edges",
    "bevel-vertices",
    "dual",
    "reroute",
    "stellate",
    "tile",
    "primitive",
];

#[test]
fn help_on_every_command_has_an_example() {
    let dir = folder("help");
    let text = succeeds(&dir, &["--help"]);
    // The commands `weft --help` lists, in its order, are exactly these.
    let listed: Vec<&str> = text
        .split("Commands:\n")
        .nth(1)
        .expect("a command list")
        .lines()
        .take_while(|l| l.starts_with("  "))
        .filter_map(|l| l.split_whitespace().next())
        .filter(|&c| c != "help")
        .collect();
    assert_eq!(listed, COMMANDS, "{text}");

    for command in COMMANDS {
        let text = succeeds(&dir, &[command, "--help"]);
        let examples = text
            .split_once("\nExample")
            .map(|(_, rest)| rest)
            .unwrap_or_else(|| panic!("{command}: no example in\n{text}"));
        assert!(
            examples.contains(&format!("\n  weft {command} ")),
            "{command}: the example does not run weft {command}:\n{text}"
        );
        // `weft help COMMAND` shows the same.
        let o = weft(&dir, &["help", command]);
        assert_exit(&o, 0);
        assert_eq!(stdout(&o), text, "{command}");
    }
}

#[test]
fn failed_operations_exit_with_1_and_name_the_file() {
    let dir = folder("failures");
    io::write_mesh(dir.join("cube.obj"), &shapes::cube()).unwrap();
    std::fs::write(
        dir.join("bad.obj"),
        "v 0 0 0\nv 1 0 0\nv 0 1 zero\nf 1 2 3\n",
    )
    .unwrap();
    std::fs::write(dir.join("short.stl"), [0u8; 50]).unwrap();

    let o = weft(&dir, &["info", "missing.obj"]);
    assert_exit(&o, 1);
    assert!(stderr(&o).contains("missing.obj"), "{}", stderr(&o));

    let o = weft(&dir, &["info", "bad.obj"]);
    assert_exit(&o, 1);
    let message = stderr(&o);
    assert!(
        message.contains("bad.obj") && message.contains("line 3"),
        "{message}"
    );

    let o = weft(&dir, &["convert", "short.stl", "out.obj"]);
    assert_exit(&o, 1);
    assert!(
        stderr(&o).contains("short.stl") && stderr(&o).contains("byte"),
        "{}",
        stderr(&o)
    );
    assert!(!dir.join("out.obj").exists());

    for args in [
        &["convert", "cube.obj", "nowhere/cube.ply"][..],
        &["render", "cube.obj", "nowhere/cube.png"],
    ] {
        let o = weft(&dir, args);
        assert_exit(&o, 1);
        assert!(stderr(&o).contains("nowhere"), "{args:?}: {}", stderr(&o));
    }

    // A folder given as the input is unreadable as a file.
    std::fs::create_dir_all(dir.join("folder.obj")).unwrap();
    let o = weft(&dir, &["render", "folder.obj", "x.png"]);
    assert_exit(&o, 1);
    assert!(stderr(&o).contains("folder.obj"), "{}", stderr(&o));
    assert!(!dir.join("x.png").exists());
}

/// A command that reads a mesh file: its arguments, with `IN` for the input
/// and `OUT` for the output (named with `out`'s extension), and a bad use of
/// one of its options with the option the message must name.
struct Reader {
    args: &'static [&'static str],
    out: Option<&'static str>,
    bad: &'static [&'static str],
    named: &'static str,
}

const fn reader(
    args: &'static [&'static str],
    out: Option<&'static str>,
    bad: &'static [&'static str],
    named: &'static str,
) -> Reader {
    Reader {
        args,
        out,
        bad,
        named,
    }
}

/// Every command that reads a mesh file.
const READERS: [Reader; 29] = [
    reader(
        &["info", "IN"],
        None,
        &["--planarity-tolerance", "flat"],
        "--planarity-tolerance",
    ),
    reader(
        &["render", "IN", "OUT", "--size", "40x30"],
        Some("png"),
        &["--edges", "some"],
        "--edges",
    ),
    reader(
        &["convert", "IN", "OUT"],
        Some("ply"),
        &["--ascii", "--big-endian"],
        "--ascii",
    ),
    reader(
        &["subdivide", "IN", "OUT", "--levels", "1"],
        Some("obj"),
        &["--scheme", "butterfly"],
        "--scheme",
    ),
    reader(
        &["evaluate", "IN", "--samples", "uv.txt", "-o", "OUT"],
        Some("txt"),
        &["--samples"],
        "--samples",
    ),
    reader(
        &["nurbs", "IN", "OUT", "--isolation", "1"],
        Some("step"),
        &["--isolation", "0"],
        "--isolation",
    ),
    reader(
        &["weld", "IN", "-o", "OUT"],
        Some("obj"),
        &["--tolerance", "wide"],
        "--tolerance",
    ),
    reader(
        &["cull-adjacent", "IN", "OUT"],
        Some("obj"),
        &["--tolerance", "1"],
        "--tolerance",
    ),
    reader(
        &["triangulate", "IN", "OUT"],
        Some("off"),
        &["--scheme", "loop"],
        "--scheme",
    ),
    reader(
        &["flip", "IN", "OUT"],
        Some("obj"),
        &["--unify=yes"],
        "--unify",
    ),
    reader(
        &["t-nodes", "IN", "--repair", "OUT"],
        Some("obj"),
        &["--tolerance", "nan"],
        "--tolerance",
    ),
    reader(
        &["split-polygons", "IN", "OUT"],
        Some("obj"),
        &["--levels", "many"],
        "--levels",
    ),
    reader(
        &["split-triangles", "IN", "OUT"],
        Some("obj"),
        &["--levels", "many"],
        "--levels",
    ),
    reader(
        &["quad-split", "IN", "OUT"],
        Some("obj"),
        &["--levels", "many"],
        "--levels",
    ),
    reader(
        &["midedge", "IN", "OUT"],
        Some("obj"),
        &["--levels", "many"],
        "--levels",
    ),
    reader(
        &["inner-polygons", "IN", "OUT"],
        Some("obj"),
        &["--pull", "half"],
        "--pull",
    ),
    reader(
        &["sierpinski", "IN", "OUT"],
        Some("obj"),
        &["--levels", "many"],
        "--levels",
    ),
    reader(
        &["carpet", "IN", "OUT"],
        Some("obj"),
        &["--levels", "many"],
        "--levels",
    ),
    reader(
        &["smooth", "IN", "OUT"],
        Some("obj"),
        &["--method", "taubin"],
        "--method",
    ),
    reader(
        &["offset", "IN", "OUT", "--distance", "0.1"],
        Some("obj"),
        &["--type", "round"],
        "--type",
    ),
    reader(
        &["thicken", "IN", "OUT", "--distance", "0.1"],
        Some("obj"),
        &["--type", "round"],
        "--type",
    ),
    reader(
        &["window", "IN", "OUT", "--distance", "0.2"],
        Some("obj"),
        &["--mode", "round"],
        "--mode",
    ),
    reader(
        &["frame", "IN", "OUT", "--distance", "0.2"],
        Some("obj"),
        &["--mode", "round"],
        "--mode",
    ),
    reader(
        &["bevel-edges", "IN", "OUT"],
        Some("obj"),
        &["--fraction", "some"],
        "--fraction",
    ),
    reader(
        &["bevel-vertices", "IN", "OUT"],
        Some("obj"),
        &["--fraction", "some"],
        "--fraction",
    ),
    reader(
        &["dual", "IN", "OUT"],
        Some("obj"),
        &["--keep-size=1"],
        "--keep-size",
    ),
    reader(
        &["reroute", "IN", "OUT", "--shift", "1"],
        Some("obj"),
        &["--shift", "half"],
        "--shift",
    ),
    reader(
        &["stellate", "IN", "OUT", "--height", "0.2"],
        Some("obj"),
        &["--apex", "1"],
        "--apex",
    ),
    reader(
        &["tile", "IN", "OUT"],
        Some("obj"),
        &["--fill", "hexagon"],
        "--fill",
    ),
];

/// The names in a folder, sorted.
fn listing(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    names
}

/// Each command that reads a mesh file, on a good file, then on a malformed
/// text file and a malformed binary one, a missing file, an unreadable one,
/// with its output in a missing folder or in place of a folder, and with a
/// bad option: exit 0, 1 or 2, a message that names the file or option and
/// the problem, and no file left behind by a failure.
#[test]
fn every_reading_command_fails_cleanly() {
    let dir = folder("readers");
    io::write_mesh(dir.join("cube.obj"), &shapes::cube()).unwrap();
    std::fs::write(
        dir.join("bad.obj"),
        "v 0 0 0\nv 1 0 0\nv 0 1 zero\nf 1 2 3\n",
    )
    .unwrap();
    std::fs::write(dir.join("short.stl"), [0u8; 50]).unwrap();
    // A folder cannot be read as a file: it stands in for an unreadable file,
    // since permissions do not stop a test run as root.
    std::fs::create_dir(dir.join("folder.obj")).unwrap();
    std::fs::write(dir.join("uv.txt"), "0 0.5 0.5\n").unwrap();
    for ext in ["obj", "ply", "off", "png", "step", "txt"] {
        std::fs::create_dir(dir.join(format!("taken.{ext}"))).unwrap();
    }
    let before = listing(&dir);
    let covered: Vec<&str> = READERS.iter().map(|r| r.args[0]).collect();
    for command in COMMANDS {
        assert!(
            covered.contains(&command) || ["demo", "primitive"].contains(&command),
            "{command} reads a mesh file and is not in READERS"
        );
    }

    for reader in &READERS {
        let command = reader.args[0];
        let run = |input: &str, output: &str, extra: &[&str]| {
            let mut args: Vec<&str> = reader
                .args
                .iter()
                .map(|&a| match a {
                    "IN" => input,
                    "OUT" => output,
                    a => a,
                })
                .collect();
            args.extend_from_slice(extra);
            weft(&dir, &args)
        };
        let out_name = |stem: &str| reader.out.map(|ext| format!("{stem}.{ext}"));
        let out = out_name("out").unwrap_or_default();

        // Success, so that each failure below is the one it names.
        let o = run("cube.obj", &out, &[]);
        assert_exit(&o, 0);
        if reader.out.is_some() {
            assert!(dir.join(&out).is_file(), "{command}: no {out}");
            std::fs::remove_file(dir.join(&out)).unwrap();
        }
        assert_eq!(listing(&dir), before, "{command}");

        let failures = [
            ("bad.obj", out.clone(), "bad.obj: line 3: ".to_string()),
            ("short.stl", out.clone(), "short.stl: byte 50: ".to_string()),
            (
                "missing.obj",
                out.clone(),
                "missing.obj: cannot read: ".to_string(),
            ),
            (
                "folder.obj",
                out.clone(),
                "folder.obj: cannot read: ".to_string(),
            ),
        ];
        let mut failures = failures.to_vec();
        if let (Some(nowhere), Some(taken)) = (out_name("nowhere/out"), out_name("taken")) {
            failures.push((
                "cube.obj",
                nowhere.clone(),
                format!("{nowhere}: the folder nowhere does not exist"),
            ));
            failures.push((
                "cube.obj",
                taken.clone(),
                format!("{taken}: cannot replace: "),
            ));
        }
        for (input, output, expected) in &failures {
            let o = run(input, output, &[]);
            assert_exit(&o, 1);
            let message = stderr(&o);
            assert!(
                message.contains(&format!("weft: error: {expected}")),
                "{command} {input} {output}: expected {expected:?} in\n{message}"
            );
            assert_eq!(
                listing(&dir),
                before,
                "{command} {input} {output} left a file"
            );
        }
        // A missing folder is found before any work: nothing is printed first.
        if let Some(nowhere) = out_name("nowhere/out") {
            let o = run("cube.obj", &nowhere, &[]);
            assert_eq!(stdout(&o), "", "{command}");
            assert_eq!(stderr(&o).lines().count(), 1, "{command}: {}", stderr(&o));
        }

        let o = run("cube.obj", &out, reader.bad);
        assert_exit(&o, 2);
        let message = stderr(&o);
        assert!(
            message.starts_with("error: ") && message.contains(reader.named),
            "{command} {:?}: {message}",
            reader.bad
        );
        assert_eq!(listing(&dir), before, "{command} {:?}", reader.bad);
    }
}

#[test]
fn primitive_and_demo_outputs_fail_cleanly() {
    let dir = folder("writers");
    std::fs::create_dir(dir.join("taken.obj")).unwrap();
    let before = listing(&dir);
    for (args, expected) in [
        (
            &["primitive", "cube", "nowhere/cube.obj"][..],
            "nowhere/cube.obj: the folder nowhere does not exist",
        ),
        (
            &["primitive", "cube", "taken.obj"],
            "taken.obj: cannot replace: ",
        ),
        (
            &["demo", "--out", "nowhere/demo", "--only", "boxes"],
            "nowhere/demo: cannot create the folder: ",
        ),
    ] {
        let o = weft(&dir, args);
        assert_exit(&o, 1);
        assert!(
            stderr(&o).contains(&format!("weft: error: {expected}")),
            "{args:?}: {}",
            stderr(&o)
        );
        assert_eq!(listing(&dir), before, "{args:?}");
    }
    for (args, named) in [
        (
            &["primitive", "cube", "c.obj", "--radius", "big"][..],
            "--radius",
        ),
        (&["primitive", "cube", "c.png"], "<OUTPUT>"),
        (&["demo", "--only", "everything"], "--only"),
        (&["demo", "--out"], "--out"),
    ] {
        let o = weft(&dir, args);
        assert_exit(&o, 2);
        assert!(stderr(&o).contains(named), "{args:?}: {}", stderr(&o));
        assert_eq!(listing(&dir), before, "{args:?}");
    }
}

#[test]
fn subdivide_runs_each_scheme_and_mode() {
    let dir = folder("subdivide");
    io::write_mesh(dir.join("cube.obj"), &shapes::cube()).unwrap();
    io::write_mesh(dir.join("grid.off"), &shapes::triangle_grid(2, 2)).unwrap();

    let o = weft(
        &dir,
        &[
            "subdivide",
            "cube.obj",
            "cc.ply",
            "--scheme",
            "catmull-clark",
            "--levels",
            "2",
            "--naked-edges",
            "fixed",
        ],
    );
    assert_exit(&o, 0);
    let cc = io::read_mesh(dir.join("cc.ply")).unwrap();
    // Level 1: 8 + 12 + 6 vertices, 24 quads; level 2: 26 + 48 + 24, 96 quads.
    assert_eq!((cc.vertex_count(), cc.face_count()), (98, 96));
    assert!(cc.is_quad_mesh());

    // A corner of the grid with one face: corner-fixed keeps it, smooth moves it.
    let grid = shapes::triangle_grid(2, 2);
    let lone = (0..grid.vertex_count() as u32)
        .find(|v| grid.faces().filter(|f| f.contains(v)).count() == 1)
        .unwrap() as usize;
    for mode in ["fixed", "smooth", "corner-fixed"] {
        let out = format!("loop-{mode}.obj");
        let o = weft(
            &dir,
            &[
                "subdivide",
                "grid.off",
                &out,
                "--scheme",
                "loop",
                "--levels",
                "1",
                "--naked-edges",
                mode,
            ],
        );
        assert_exit(&o, 0);
        let refined = io::read_mesh(dir.join(&out)).unwrap();
        assert_eq!(refined.face_count(), 32, "{mode}");
        let corner = refined.positions()[lone];
        assert_eq!(
            corner == grid.positions()[lone],
            mode != "smooth",
            "{mode}: {corner}"
        );
    }

    // Loop on quads triangulates first and says so.
    let o = weft(
        &dir,
        &[
            "subdivide",
            "cube.obj",
            "cube-loop.obj",
            "--scheme",
            "loop",
            "--levels",
            "1",
        ],
    );
    assert_exit(&o, 0);
    assert!(stderr(&o).contains("triangulated"), "{}", stderr(&o));
    assert_eq!(
        io::read_mesh(dir.join("cube-loop.obj"))
            .unwrap()
            .face_count(),
        48
    );

    let o = weft(
        &dir,
        &["subdivide", "cube.obj", "x.obj", "--scheme", "butterfly"],
    );
    assert_exit(&o, 2);
    let o = weft(&dir, &["subdivide", "cube.obj", "x.obj", "--levels", "-1"]);
    assert_exit(&o, 2);
    let o = weft(&dir, &["subdivide", "cube.obj", "x.obj", "--levels", "40"]);
    assert_exit(&o, 1);
    assert!(
        stderr(&o).contains("cube.obj") && stderr(&o).contains("too large"),
        "{}",
        stderr(&o)
    );
    assert!(!dir.join("x.obj").exists());
}

#[test]
fn nurbs_writes_the_limit_surface_as_step_and_reports_its_error() {
    let dir = folder("nurbs");
    io::write_mesh(dir.join("cube.obj"), &shapes::cube()).unwrap();
    let text = succeeds(
        &dir,
        &[
            "nurbs",
            "cube.obj",
            "cube.step",
            "--isolation",
            "2",
            "--naked-edges",
            "smooth",
        ],
    );
    assert_mentions(
        &text,
        &[
            "isolation levels  2",
            "patches           96",
            "exact             72",
            "approximate       24",
            "largest error     ",
        ],
    );
    let step = std::fs::read_to_string(dir.join("cube.step")).unwrap();
    assert!(step.starts_with("ISO-10303-21;") && step.contains("AUTOMOTIVE_DESIGN"));
    assert_eq!(step.matches("B_SPLINE_SURFACE_WITH_KNOTS(").count(), 96);
    // More isolation, a smaller error.
    let error = |text: &str| -> f64 {
        let line = text.lines().find(|l| l.contains("largest error")).unwrap();
        line.split_whitespace().nth(2).unwrap().parse().unwrap()
    };
    let finer = succeeds(
        &dir,
        &["nurbs", "cube.obj", "cube3.step", "--isolation", "3"],
    );
    assert!(error(&finer) < 0.6 * error(&text), "{text}\n{finer}");

    // Loop has no tensor-product patches; a hole past the faces: nothing written.
    let before = listing(&dir);
    for (args, expected) in [
        (
            &["--scheme", "loop"][..],
            "NURBS patches need --scheme catmull-clark",
        ),
        (&["--hole", "6"][..], "--hole 6: cube.obj has 6 faces"),
    ] {
        let mut all = vec!["nurbs", "cube.obj", "other.step"];
        all.extend_from_slice(args);
        let o = weft(&dir, &all);
        assert_exit(&o, 1);
        assert_mentions(&stderr(&o), &[expected]);
        assert_eq!(listing(&dir), before, "{args:?}");
    }
    let o = weft(&dir, &["nurbs", "cube.obj", "cube.obj"]);
    assert_exit(&o, 2);
    assert_mentions(
        &stderr(&o),
        &["expected a STEP file ending in .step or .stp"],
    );
}

#[test]
fn faces_repeating_a_vertex_are_read_on_request_and_subdivided() {
    let dir = folder("repeated");
    // A pentagon with the degenerate edge 2-2 beside a quad.
    let obj = "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nv 1 1 0\nv 2 1 0\nf 1 2 2 5 4\nf 2 3 6 5\n";
    std::fs::write(dir.join("cage.obj"), obj).unwrap();
    let off = "OFF\n6 2 0\n0 0 0\n1 0 0\n2 0 0\n0 1 0\n1 1 0\n2 1 0\n5 0 1 1 4 3\n4 1 2 5 4\n";
    std::fs::write(dir.join("cage.off"), off).unwrap();
    for input in ["cage.obj", "cage.off"] {
        let o = weft(&dir, &["subdivide", input, "out.obj"]);
        assert_exit(&o, 1);
        assert_mentions(
            &stderr(&o),
            &[
                "face 0 uses vertex 1 twice",
                "--allow-repeated-vertices accepts such faces",
            ],
        );
        assert!(!dir.join("out.obj").exists());
        succeeds(
            &dir,
            &[
                "subdivide",
                input,
                "out.obj",
                "--levels",
                "2",
                "--naked-edges",
                "smooth",
                "--allow-repeated-vertices",
            ],
        );
        // 6 vertices, 8 edges (the degenerate one too), 2 faces; then 36 quads.
        let refined = io::read_mesh(dir.join("out.obj")).unwrap();
        assert_eq!(
            (refined.vertex_count(), refined.face_count()),
            (50, 36),
            "{input}"
        );
        let allowing = io::ReadOptions {
            allow_repeated_vertices: true,
            ..Default::default()
        };
        let cage = io::read_mesh_with(dir.join(input), &allowing).unwrap();
        assert_eq!(cage.face(0), &[0, 1, 1, 4, 3], "{input}");
        let expected = weft::subdivide::subdivide(
            &cage,
            weft::subdivide::Scheme::CatmullClark,
            2,
            weft::subdivide::NakedEdges::Smooth,
        )
        .unwrap();
        assert_eq!(refined.face_indices(), expected.face_indices(), "{input}");
        std::fs::remove_file(dir.join("out.obj")).unwrap();
    }
    // Written back, a file with such faces reads again with the flag.
    succeeds(
        &dir,
        &[
            "convert",
            "cage.obj",
            "again.ply",
            "--allow-repeated-vertices",
        ],
    );
    let text = succeeds(&dir, &["info", "again.ply", "--allow-repeated-vertices"]);
    assert_mentions(&text, &["faces                 2"]);
}

#[test]
fn evaluate_gives_limit_points_and_normals_and_refuses_bad_samples() {
    let dir = folder("evaluate");
    let cube = shapes::cube();
    io::write_mesh(dir.join("cube.obj"), &cube).unwrap();
    // Face 2's first corner, then its centre and a point on an edge.
    std::fs::write(
        dir.join("uv.txt"),
        "# face u v\n2 0 0\n2 0.5 0.5  # the centre\n\n2 0.25 0\n",
    )
    .unwrap();
    let text = succeeds(
        &dir,
        &[
            "evaluate",
            "cube.obj",
            "--samples",
            "uv.txt",
            "--naked-edges",
            "smooth",
        ],
    );
    let rows: Vec<Vec<f64>> = text
        .lines()
        .map(|l| l.split_whitespace().map(|x| x.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows.len(), 3, "{text}");
    // The corner is the limit point of the cage vertex, as subdivide --limit gives it.
    succeeds(
        &dir,
        &[
            "subdivide",
            "cube.obj",
            "limit.obj",
            "--levels",
            "1",
            "--limit",
            "--naked-edges",
            "smooth",
        ],
    );
    let limit = io::read_mesh(dir.join("limit.obj")).unwrap();
    let corner = limit.positions()[cube.face(2)[0] as usize];
    for (k, &x) in corner.to_array().iter().enumerate() {
        assert!((rows[0][k] - x).abs() < 1e-12, "{text}");
    }
    for row in &rows {
        let n = (row[3] * row[3] + row[4] * row[4] + row[5] * row[5]).sqrt();
        assert!((n - 1.0).abs() < 1e-12, "unit normals: {text}");
    }
    // Written to a file, the same lines.
    succeeds(
        &dir,
        &[
            "evaluate",
            "cube.obj",
            "--samples",
            "uv.txt",
            "-o",
            "points.txt",
            "--naked-edges",
            "smooth",
        ],
    );
    assert_eq!(
        std::fs::read_to_string(dir.join("points.txt")).unwrap(),
        text
    );

    let before = listing(&dir);
    for (samples, expected) in [
        ("9 0 0\n", "sample 0: face 9 is out of range"),
        (
            "0 0 0\n1 1.5 0\n",
            "sample 1: (u, v) = (1.5, 0) is outside the domain of face 1",
        ),
        ("0 nan 0\n", "sample 0"),
        ("0 x 0\n", "line 1: \"x\" is not a number"),
        ("0 0\n", "line 1: 2 values"),
        ("# nothing\n", "holds no sample"),
    ] {
        std::fs::write(dir.join("bad.txt"), samples).unwrap();
        let o = weft(
            &dir,
            &[
                "evaluate",
                "cube.obj",
                "--samples",
                "bad.txt",
                "-o",
                "out.txt",
            ],
        );
        assert_exit(&o, 1);
        assert_mentions(&stderr(&o), &["bad.txt: ", expected]);
        assert!(!dir.join("out.txt").exists(), "{samples:?}");
    }
    std::fs::remove_file(dir.join("bad.txt")).unwrap();
    assert_eq!(listing(&dir), before);
}

#[test]
fn subdivide_takes_holes_boundary_none_and_smooth_triangles() {
    let dir = folder("subdivide-options");
    // A 2 x 2 grid, face 1 a hole, a tag Weft does not know, a bare vertex.
    let grid = "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nv 1 1 0.5\nv 2 1 0\nv 0 2 0\nv 1 2 0\nv 2 2 0\nv 5 5 5\n\
                f 1 2 5 4\nf 2 3 6 5\nf 4 5 8 7\nf 5 6 9 8\nt hole 1/0/0 1\nt vertexedit 1/0/0 3\n";
    std::fs::write(dir.join("grid.obj"), grid).unwrap();
    succeeds(
        &dir,
        &[
            "subdivide",
            "grid.obj",
            "holed.obj",
            "--naked-edges",
            "smooth",
        ],
    );
    let holed = io::read_mesh(dir.join("holed.obj")).unwrap();
    // 9 + 12 + 4 refined points and the bare vertex stay; face 1 has no children.
    assert_eq!((holed.vertex_count(), holed.face_count()), (26, 12));
    assert_eq!(holed.positions()[9], weft::DVec3::new(5.0, 5.0, 5.0));
    // The tag round-trips through copy, and --hole adds to it.
    succeeds(&dir, &["convert", "grid.obj", "copy.obj"]);
    assert!(std::fs::read_to_string(dir.join("copy.obj"))
        .unwrap()
        .contains("t hole 1/0/0 1\n"));
    succeeds(
        &dir,
        &[
            "subdivide",
            "grid.obj",
            "two.obj",
            "--hole",
            "3",
            "--levels",
            "2",
        ],
    );
    assert_eq!(
        io::read_mesh(dir.join("two.obj")).unwrap().face_count(),
        2 * 16
    );
    // An STL is welded first for --crease-angle; the holes survive the re-read.
    io::write_mesh(dir.join("cube.stl"), &shapes::cube()).unwrap();
    let o = weft(
        &dir,
        &[
            "subdivide",
            "cube.stl",
            "cube.obj",
            "--crease-angle",
            "30",
            "--hole",
            "0",
        ],
    );
    assert_exit(&o, 0);
    assert_mentions(&stderr(&o), &["welded"]);
    // 12 triangles, 3 quads each, less the hole's.
    assert_eq!(
        io::read_mesh(dir.join("cube.obj")).unwrap().face_count(),
        36 - 3
    );
    let o = weft(&dir, &["subdivide", "grid.obj", "x.obj", "--hole", "4"]);
    assert_exit(&o, 1);
    assert_mentions(&stderr(&o), &["--hole 4", "4 faces"]);
    // Every face of a 2 x 2 grid touches the boundary: none leaves nothing,
    // which is refused rather than written as an empty file.
    let o = weft(
        &dir,
        &["subdivide", "grid.obj", "x.obj", "--naked-edges", "none"],
    );
    assert_exit(&o, 1);
    assert_mentions(
        &stderr(&o),
        &["left no face", "--naked-edges none", "nothing written"],
    );
    assert!(!dir.join("x.obj").exists());
    io::write_mesh(dir.join("big.obj"), &shapes::quad_grid(4, 4)).unwrap();
    succeeds(
        &dir,
        &["subdivide", "big.obj", "none.obj", "--naked-edges", "none"],
    );
    assert_eq!(
        io::read_mesh(dir.join("none.obj")).unwrap().face_count(),
        4 * 4
    );
    // Smooth triangles move the points beside the prism's triangles only.
    io::write_mesh(dir.join("prism.obj"), &shapes::mixed_polygons()).unwrap();
    succeeds(&dir, &["subdivide", "prism.obj", "catmark.obj"]);
    succeeds(
        &dir,
        &[
            "subdivide",
            "prism.obj",
            "smooth.obj",
            "--triangles",
            "smooth",
        ],
    );
    let (a, b) = (
        io::read_mesh(dir.join("catmark.obj")).unwrap(),
        io::read_mesh(dir.join("smooth.obj")).unwrap(),
    );
    assert_eq!(a.face_indices(), b.face_indices());
    assert_ne!(a.positions(), b.positions());
    let o = weft(
        &dir,
        &["subdivide", "prism.obj", "x.obj", "--triangles", "round"],
    );
    assert_exit(&o, 2);
}

#[test]
fn triangulate_splits_polygons() {
    let dir = folder("triangulate");
    io::write_mesh(dir.join("mixed.obj"), &shapes::mixed_polygons()).unwrap();
    let o = weft(&dir, &["triangulate", "mixed.obj", "tri.obj"]);
    assert_exit(&o, 0);
    let mixed = shapes::mixed_polygons();
    let tri = io::read_mesh(dir.join("tri.obj")).unwrap();
    let expected: u32 = mixed.face_sizes().iter().map(|s| s - 2).sum();
    assert_eq!(tri.face_count(), expected as usize);
    assert!(tri.is_triangle_mesh());
    assert_eq!(tri.positions(), mixed.positions());
    let o = weft(&dir, &["triangulate", "mixed.obj", "missing/tri.obj"]);
    assert_exit(&o, 1);
    assert!(stderr(&o).contains("missing"), "{}", stderr(&o));
}

#[test]
fn weld_joins_inputs_and_cull_removes_twins() {
    let dir = folder("weld");
    let cube = shapes::cube();
    let mut shifted = cube.clone();
    for p in shifted.positions_mut() {
        p.x += 1.0 + 1e-4; // a seam within the tolerance given below
    }
    io::write_mesh(dir.join("a.obj"), &cube).unwrap();
    io::write_mesh(dir.join("b.stl"), &shifted).unwrap();

    // An explicit tolerance is absolute (the default, a millionth of the
    // diagonal, would keep this seam open).
    let o = weft(
        &dir,
        &[
            "weld",
            "a.obj",
            "b.stl",
            "-o",
            "boxes.ply",
            "--tolerance",
            "0.001",
        ],
    );
    assert_exit(&o, 0);
    let boxes = io::read_mesh(dir.join("boxes.ply")).unwrap();
    // Two cubes sharing a face: 12 vertices; the STL cube came as 12 triangles.
    assert_eq!((boxes.vertex_count(), boxes.face_count()), (12, 6 + 12));
    // The STL's 36 corners are counted as the file holds them, though its
    // copies were merged while reading: 8 + 36 vertices, 32 merged.
    assert_mentions(
        &stderr(&o),
        &[
            "joined 2 meshes (44 vertices, 18 faces)",
            "merged 32 vertices",
        ],
    );
    // With --weld the STL is welded as it is read, and counted so.
    let o = weft(&dir, &["weld", "b.stl", "-o", "one.obj", "--weld"]);
    assert_exit(&o, 0);
    assert_mentions(
        &stderr(&o),
        &[
            "joined 1 meshes (8 vertices, 12 faces)",
            "merged 0 vertices",
        ],
    );

    let o = weft(
        &dir,
        &[
            "weld",
            "a.obj",
            "b.stl",
            "-o",
            "apart.obj",
            "--tolerance",
            "0",
        ],
    );
    assert_exit(&o, 0);
    assert_eq!(
        io::read_mesh(dir.join("apart.obj")).unwrap().vertex_count(),
        16
    );

    // Two cubes with quads on the shared wall: culling removes both walls.
    let mut quads = shapes::cube();
    for p in quads.positions_mut() {
        p.x += 1.0;
    }
    io::write_mesh(dir.join("c.obj"), &quads).unwrap();
    let o = weft(&dir, &["weld", "a.obj", "c.obj", "-o", "pair.obj"]);
    assert_exit(&o, 0);
    let o = weft(&dir, &["cull-adjacent", "pair.obj", "hull.obj"]);
    assert_exit(&o, 0);
    assert!(stderr(&o).contains("removed 2 of 12"), "{}", stderr(&o));
    let hull = io::read_mesh(dir.join("hull.obj")).unwrap();
    assert_eq!(hull.face_count(), 10);
    let o = weft(&dir, &["info", "hull.obj"]);
    assert!(
        stdout(&o).contains("closed                yes"),
        "{}",
        stdout(&o)
    );

    let o = weft(&dir, &["weld", "-o", "x.obj"]);
    assert_exit(&o, 2);
    let o = weft(&dir, &["weld", "a.obj", "-o", "x.obj", "--tolerance", "-1"]);
    assert_exit(&o, 2);
    let o = weft(&dir, &["weld", "a.obj", "gone.obj", "-o", "x.obj"]);
    assert_exit(&o, 1);
    assert!(stderr(&o).contains("gone.obj"), "{}", stderr(&o));
    assert!(!dir.join("x.obj").exists());
}

#[test]
fn flip_reverses_or_unifies() {
    let dir = folder("flip");
    let grid = shapes::quad_grid(3, 3);
    let polygons: Vec<Vec<u32>> = grid
        .faces()
        .enumerate()
        .map(|(f, face)| {
            let mut face = face.to_vec();
            if f == 4 || f == 7 {
                face.reverse();
            }
            face
        })
        .collect();
    let mixed = weft::Mesh::from_polygons(grid.positions().to_vec(), polygons).unwrap();
    io::write_mesh(dir.join("mixed.obj"), &mixed).unwrap();

    let o = weft(&dir, &["flip", "mixed.obj", "unified.obj", "--unify"]);
    assert_exit(&o, 0);
    assert!(stderr(&o).contains("flipped 2 of 9"), "{}", stderr(&o));
    let unified = io::read_mesh(dir.join("unified.obj")).unwrap();
    assert_eq!(unified.positions(), grid.positions());
    for (f, face) in unified.faces().enumerate() {
        assert_same_cycle(face, grid.face(f).to_vec(), f);
    }

    let o = weft(&dir, &["flip", "unified.obj", "down.obj"]);
    assert_exit(&o, 0);
    let down = io::read_mesh(dir.join("down.obj")).unwrap();
    for (f, face) in down.faces().enumerate() {
        let mut expected = grid.face(f).to_vec();
        expected.reverse();
        assert_same_cycle(face, expected, f);
    }
}

/// The same cycle of vertices, whatever corner it starts at.
#[track_caller]
fn assert_same_cycle(face: &[u32], mut expected: Vec<u32>, f: usize) {
    let start = expected.iter().position(|v| *v == face[0]);
    assert!(start.is_some(), "face {f}: {face:?} vs {expected:?}");
    expected.rotate_left(start.unwrap());
    assert_eq!(face, expected.as_slice(), "face {f}");
}

#[test]
fn t_nodes_are_listed_and_repaired() {
    let dir = folder("t-nodes");
    // A tall quad beside two short ones: vertex 5 at (1, 1) lies on the
    // tall quad's edge from (1, 0) to (1, 2).
    std::fs::write(
        dir.join("t.obj"),
        "v 0 0 0\nv 1 0 0\nv 1 2 0\nv 0 2 0\nv 2 0 0\nv 1 1 0\nv 2 1 0\nv 2 2 0\n\
         f 1 2 3 4\nf 2 5 7 6\nf 6 7 8 3\n",
    )
    .unwrap();
    let text = succeeds(&dir, &["t-nodes", "t.obj", "--repair", "fixed.obj"]);
    assert!(text.contains("1 T-nodes"), "{text}");
    assert!(
        text.contains("vertex 5 lies on edge 1-2 of face 0"),
        "{text}"
    );
    let fixed = io::read_mesh(dir.join("fixed.obj")).unwrap();
    assert_eq!(fixed.face(0), &[0, 1, 5, 2, 3]);
    let o = weft(&dir, &["info", "fixed.obj", "--json"]);
    // The outline of the 2 × 2 square, and the seam is gone.
    assert!(stdout(&o).contains("\"naked_edges\": 7"), "{}", stdout(&o));

    let o = weft(&dir, &["t-nodes", "fixed.obj"]);
    assert_exit(&o, 0);
    assert!(stdout(&o).contains("0 T-nodes"), "{}", stdout(&o));
    let o = weft(&dir, &["t-nodes", "t.obj", "--tolerance", "nan"]);
    assert_exit(&o, 2);
}

/// Runs `weft` in `dir` with its standard output a pipe whose reading end
/// is closed before it writes.
fn weft_into_closed_pipe(dir: &Path, args: &[&str]) -> Output {
    let mut child = Command::new(env!("CARGO_BIN_EXE_weft"))
        .current_dir(dir)
        .args(args)
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .expect("the weft binary runs");
    drop(child.stdout.take());
    child.wait_with_output().unwrap()
}

#[test]
fn listings_into_a_closed_pipe_fail_by_name_without_a_panic() {
    let dir = folder("closed-pipe");
    // One tall quad beside a column of `rows` quads: rows - 1 T-nodes,
    // a listing far longer than a pipe's buffer.
    let rows = 4000;
    let mut obj = format!("v 0 0 0\nv 0 {rows} 0\n");
    for i in 0..=rows {
        obj += &format!("v 1 {i} 0\nv 2 {i} 0\n");
    }
    obj += &format!("f 1 3 {} 2\n", 3 + 2 * rows);
    for i in 0..rows {
        let (a, b) = (3 + 2 * i, 5 + 2 * i);
        obj += &format!("f {a} {} {} {b}\n", a + 1, b + 1);
    }
    std::fs::write(dir.join("column.obj"), obj).unwrap();
    let listed = succeeds(&dir, &["t-nodes", "column.obj"]);
    assert!(
        listed.contains(&format!("{} T-nodes", rows - 1)),
        "{listed}"
    );
    assert!(listed.len() > 1 << 17);
    let samples: String = (0..rows).map(|i| format!("{} 0.5 0.5\n", i + 1)).collect();
    std::fs::write(dir.join("uv.txt"), samples).unwrap();
    for args in [
        &["t-nodes", "column.obj"][..],
        &["evaluate", "column.obj", "--samples", "uv.txt"],
    ] {
        let o = weft_into_closed_pipe(&dir, args);
        assert_exit(&o, 1);
        assert_mentions(&stderr(&o), &["cannot write to standard output"]);
        assert!(!stderr(&o).contains("panicked"), "{}", stderr(&o));
    }
}

#[test]
fn demo_writes_every_workflow_with_an_index() {
    let dir = folder("demo");
    let o = weft(&dir, &["demo", "--out", "pictures"]);
    assert_exit(&o, 0);
    let out = dir.join("pictures");
    let index = std::fs::read_to_string(out.join("index.html")).unwrap();
    let lines: Vec<String> = stdout(&o).lines().map(str::to_string).collect();
    let mut pictures = 0;
    for name in [
        "loop-1",
        "loop-2",
        "loop-3",
        "loop-3-smooth",
        "loop-3-corner-fixed",
        "hole-3-smooth",
        "surfaces-joined",
        "surfaces-smooth",
        "t-nodes-welded",
        "t-nodes-repaired-smooth",
        "voronoi-skin",
        "fading-smooth",
        "boxes-inner",
        "boxes-culled",
        "boxes-smooth",
        "creases-cage",
        "creases-none",
        "creases-sharp",
        "creases-colours",
    ] {
        assert!(
            index.contains(&format!("src=\"{name}.png\"")),
            "{name} missing from the index"
        );
        assert!(
            lines.iter().any(|l| l.starts_with(&format!("{name}: "))),
            "no summary line for {name}"
        );
        let mesh = io::read_mesh(out.join(format!("{name}.obj"))).unwrap();
        assert!(mesh.face_count() > 0, "{name}");
        let decoder = png::Decoder::new(std::io::BufReader::new(
            std::fs::File::open(out.join(format!("{name}.png"))).unwrap(),
        ));
        let info = decoder.read_info().unwrap();
        assert_eq!((info.info().width, info.info().height), (800, 600));
        pictures += 1;
    }
    assert_eq!(pictures, 19);
    // Nothing but the summary lines: stderr is not a terminal here.
    assert_eq!(stderr(&o), "");
    // The cage's OBJ carries its creases: subdividing it again gives the creased block.
    let o = weft(
        &out,
        &[
            "subdivide",
            "creases-cage.obj",
            "again.obj",
            "--levels",
            "3",
        ],
    );
    assert_exit(&o, 0);
    let again = io::read_mesh(out.join("again.obj")).unwrap();
    assert_eq!(again, io::read_mesh(out.join("creases-sharp.obj")).unwrap());
    assert_ne!(again, io::read_mesh(out.join("creases-none.obj")).unwrap());
    let coloured =
        io::read_mesh_file(out.join("creases-colours.obj"), &Default::default()).unwrap();
    assert_eq!(coloured.colours.unwrap().rgba.len(), again.vertex_count());
    assert_eq!(coloured.uvs.unwrap().indices.len(), again.index_count());
    // The culled boxes are one closed shell; the repaired surfaces one piece.
    let o = weft(&out, &["info", "boxes-culled.obj", "--json"]);
    assert!(stdout(&o).contains("\"closed\": true"), "{}", stdout(&o));
    // The inner walls shown are one of each twin pair the culling removed.
    let walls = io::read_mesh(out.join("boxes-inner.obj")).unwrap();
    let welded = io::read_mesh(out.join("boxes-welded.obj")).unwrap();
    let culled = io::read_mesh(out.join("boxes-culled.obj")).unwrap();
    assert_eq!(
        2 * walls.face_count(),
        welded.face_count() - culled.face_count()
    );
    let o = weft(&out, &["info", "t-nodes-repaired-smooth.obj", "--json"]);
    assert!(stdout(&o).contains("\"components\": 1"), "{}", stdout(&o));
}

#[test]
fn demo_failures_name_the_folder_or_picture() {
    let dir = folder("demo-failures");
    let o = weft(&dir, &["demo", "--out", "no/such/folder"]);
    assert_exit(&o, 1);
    assert!(stderr(&o).contains("no/such/folder"), "{}", stderr(&o));
    std::fs::write(dir.join("fake.png"), b"not a picture").unwrap();
    let o = weft(&dir, &["demo", "--image", "fake.png"]);
    assert_exit(&o, 1);
    assert!(stderr(&o).contains("fake.png"), "{}", stderr(&o));
    let o = weft(&dir, &["demo", "--image", "heights.jpg"]);
    assert_exit(&o, 2);
}

/// Runs `weft ARGS` in `dir`, expects success, and reads the mesh it wrote.
fn run_and_read(dir: &Path, args: &[&str], output: &str) -> weft::Mesh {
    let o = weft(dir, args);
    assert_exit(&o, 0);
    io::read_mesh(dir.join(output)).unwrap()
}

fn counts(mesh: &weft::Mesh) -> (usize, usize) {
    (mesh.vertex_count(), mesh.face_count())
}

#[test]
fn toolbar_subdivisions_have_their_counts() {
    let dir = folder("toolbar-split");
    io::write_mesh(dir.join("cube.obj"), &shapes::cube()).unwrap();
    io::write_mesh(dir.join("tetra.obj"), &shapes::tetrahedron()).unwrap();
    let run = |args: &[&str]| counts(&run_and_read(&dir, args, args[2]));
    assert_eq!(
        run(&["split-polygons", "cube.obj", "a.obj", "--levels", "2"]),
        (98, 96)
    );
    assert_eq!(run(&["quad-split", "cube.obj", "b.obj"]), (26, 24));
    assert_eq!(run(&["midedge", "cube.obj", "c.obj"]), (12, 14));
    assert_eq!(
        run(&["inner-polygons", "cube.obj", "d.obj", "--pull", "0.3"]),
        (32, 30)
    );
    assert_eq!(
        run(&["sierpinski", "tetra.obj", "e.obj", "--levels", "2"]),
        (34, 36)
    );
    assert_eq!(run(&["split-triangles", "tetra.obj", "f.obj"]), (10, 16));
    // Quads are triangulated first, and the command says so.
    let o = weft(&dir, &["split-triangles", "cube.obj", "g.obj"]);
    assert_exit(&o, 0);
    assert!(
        stderr(&o).contains("triangulated 6 of 6 faces into 12 triangles"),
        "{}",
        stderr(&o)
    );
    assert_eq!(counts(&io::read_mesh(dir.join("g.obj")).unwrap()), (26, 48));

    let o = weft(
        &dir,
        &["inner-polygons", "cube.obj", "h.obj", "--pull", "1"],
    );
    assert_exit(&o, 1);
    assert!(stderr(&o).contains("pull is 1"), "{}", stderr(&o));
    let o = weft(
        &dir,
        &["split-polygons", "cube.obj", "i.obj", "--levels", "21"],
    );
    assert_exit(&o, 1);
    assert!(stderr(&o).contains("levels is 21"), "{}", stderr(&o));
    assert!(!dir.join("i.obj").exists());
    let o = weft(&dir, &["midedge", "cube.obj"]);
    assert_exit(&o, 2);
}

#[test]
fn smooth_moves_a_raised_centre_by_each_method() {
    let dir = folder("toolbar-smooth");
    let mut grid = shapes::quad_grid(2, 2);
    grid.positions_mut()[4].z = 1.0;
    io::write_mesh(dir.join("bump.obj"), &grid).unwrap();
    let centre = |file: &str| io::read_mesh(dir.join(file)).unwrap().positions()[4].z;
    // Laplacian with blend 1 takes the centre to its neighbours' average, 0.
    run_and_read(
        &dir,
        &["smooth", "bump.obj", "l.obj", "--method", "laplacian"],
        "l.obj",
    );
    assert_eq!(centre("l.obj"), 0.0);
    // HC pushes back: the centre keeps part of its height.
    run_and_read(
        &dir,
        &[
            "smooth",
            "bump.obj",
            "h.obj",
            "--method",
            "hc",
            "--iterations",
            "1",
        ],
        "h.obj",
    );
    let z = centre("h.obj");
    assert!(z > 0.0 && z < 1.0, "{z}");
    // Tangential smoothing keeps the centre in its plane z = 1.
    run_and_read(
        &dir,
        &[
            "smooth",
            "bump.obj",
            "t.obj",
            "--method",
            "hc",
            "--iterations",
            "3",
            "--direction",
            "tangential",
        ],
        "t.obj",
    );
    assert!((centre("t.obj") - 1.0).abs() < 1e-12);
    // Corner-fixed naked edges let the boundary slide but keep the corners.
    let mut skew = shapes::quad_grid(2, 2);
    skew.positions_mut()[1].x = 0.6;
    io::write_mesh(dir.join("skew.obj"), &skew).unwrap();
    let moved = run_and_read(
        &dir,
        &[
            "smooth",
            "skew.obj",
            "s.obj",
            "--iterations",
            "2",
            "--naked-edges",
            "corner-fixed",
            "--blend",
            "0.5",
        ],
        "s.obj",
    );
    assert!(moved.positions()[1].x > 0.6 && moved.positions()[1].y == 0.0);
    assert_eq!(moved.positions()[0], skew.positions()[0]);

    let o = weft(
        &dir,
        &[
            "smooth", "bump.obj", "x.obj", "--method", "hc", "--beta", "2",
        ],
    );
    assert_exit(&o, 1);
    assert!(stderr(&o).contains("beta is 2"), "{}", stderr(&o));
    let o = weft(&dir, &["smooth", "bump.obj", "x.obj", "--method", "taubin"]);
    assert_exit(&o, 2);
}

#[test]
fn toolbar_transforms_keep_their_defining_properties() {
    let dir = folder("toolbar-transform");
    io::write_mesh(dir.join("cube.obj"), &shapes::cube()).unwrap();
    io::write_mesh(dir.join("grid.obj"), &shapes::quad_grid(2, 2)).unwrap();
    io::write_mesh(dir.join("tetra.obj"), &shapes::tetrahedron()).unwrap();
    let info = |m: &weft::Mesh| weft::Topology::new(m).info(m);

    let inner = run_and_read(
        &dir,
        &[
            "offset",
            "cube.obj",
            "o.obj",
            "--distance",
            "-0.25",
            "--type",
            "planes-intersection",
        ],
        "o.obj",
    );
    let (lo, hi) = inner.bounding_box().unwrap();
    assert!(
        (lo - weft::DVec3::splat(0.25)).length() < 1e-12
            && (hi - weft::DVec3::splat(0.75)).length() < 1e-12
    );
    let solid = run_and_read(
        &dir,
        &["thicken", "grid.obj", "t.obj", "--distance", "0.1"],
        "t.obj",
    );
    assert!(info(&solid).is_closed);
    assert_eq!(counts(&solid), (18, 4 + 4 + 8));
    assert_eq!(
        counts(&run_and_read(
            &dir,
            &["window", "cube.obj", "w.obj", "--distance", "0.2"],
            "w.obj"
        )),
        (32, 30)
    );
    let frame = run_and_read(
        &dir,
        &[
            "frame",
            "cube.obj",
            "f.obj",
            "--distance",
            "0.1",
            "--mode",
            "parallelogram",
        ],
        "f.obj",
    );
    assert_eq!(counts(&frame), (32, 24));
    assert_eq!(info(&frame).naked_edge_count, 24);
    assert_eq!(
        counts(&run_and_read(
            &dir,
            &["carpet", "grid.obj", "c.obj"],
            "c.obj"
        ))
        .1,
        4 * 8
    );
    assert_eq!(
        counts(&run_and_read(
            &dir,
            &["bevel-edges", "cube.obj", "be.obj"],
            "be.obj"
        )),
        (24, 26)
    );
    assert_eq!(
        counts(&run_and_read(
            &dir,
            &["bevel-vertices", "cube.obj", "bv.obj"],
            "bv.obj"
        )),
        (24, 14)
    );
    assert_eq!(
        counts(&run_and_read(&dir, &["dual", "cube.obj", "d.obj"], "d.obj")),
        (6, 8)
    );
    let spikes = run_and_read(
        &dir,
        &["stellate", "cube.obj", "s.obj", "--height", "-0.5"],
        "s.obj",
    );
    assert_eq!(counts(&spikes), (14, 24));
    assert_eq!(spikes.positions()[8], weft::DVec3::new(0.5, 0.5, 0.5));
    let fans = run_and_read(
        &dir,
        &["tile", "cube.obj", "ti.obj", "--fill", "triangle-fan"],
        "ti.obj",
    );
    assert_eq!(counts(&fans), (14, 24));
    assert!(info(&fans).is_closed && info(&fans).is_oriented);
    let kept = run_and_read(
        &dir,
        &[
            "tile",
            "cube.obj",
            "k.obj",
            "--fill",
            "quad-fan",
            "--faces",
            "triangles",
        ],
        "k.obj",
    );
    assert_eq!(counts(&kept), (8, 6));

    let o = weft(&dir, &["carpet", "tetra.obj", "x.obj"]);
    assert_exit(&o, 1);
    assert!(stderr(&o).contains("needs a quad mesh"), "{}", stderr(&o));
    let o = weft(&dir, &["window", "cube.obj", "x.obj", "--distance", "0.5"]);
    assert_exit(&o, 1);
    let o = weft(&dir, &["offset", "cube.obj", "x.obj"]);
    assert_exit(&o, 2);
    assert!(stderr(&o).contains("--distance"), "{}", stderr(&o));
    let o = weft(&dir, &["tile", "cube.obj", "x.obj", "--fill", "hexagon"]);
    assert_exit(&o, 2);
}

#[test]
fn primitive_builds_the_define_panel() {
    let dir = folder("toolbar-primitive");
    let run = |args: &[&str]| run_and_read(&dir, args, args[2]);
    assert_eq!(
        counts(&run(&[
            "primitive",
            "dodecahedron",
            "d.obj",
            "--radius",
            "1"
        ])),
        (20, 12)
    );
    assert_eq!(
        counts(&run(&[
            "primitive",
            "box",
            "b.off",
            "--size",
            "2",
            "--divisions",
            "2"
        ])),
        (26, 24)
    );
    assert_eq!(
        counts(&run(&["primitive", "plane", "p.obj", "--divisions", "3"])),
        (16, 9)
    );
    assert_eq!(
        counts(&run(&["primitive", "antiprism", "a.obj", "--sides", "5"])),
        (10, 12)
    );
    let ball = run(&["primitive", "sphere", "s.obj", "--radius", "2"]);
    assert!(ball
        .positions()
        .iter()
        .all(|p| (p.length() - 2.0).abs() < 1e-9));
    assert!(weft::Topology::new(&ball).info(&ball).is_closed);

    let o = weft(&dir, &["primitive", "prism", "x.obj", "--sides", "2"]);
    assert_exit(&o, 1);
    assert!(stderr(&o).contains("sides is 2"), "{}", stderr(&o));
    let o = weft(&dir, &["primitive", "torus", "x.obj"]);
    assert_exit(&o, 2);
}

/// The cube of `shapes::cube` as OBJ text with `extra` lines after it and,
/// when given, one colour for every vertex.
fn cube_obj(colour: Option<[f64; 3]>, extra: &str) -> String {
    let cube = shapes::cube();
    let mut text = String::new();
    for p in cube.positions() {
        text.push_str(&format!("v {} {} {}", p.x, p.y, p.z));
        if let Some([r, g, b]) = colour {
            text.push_str(&format!(" {r} {g} {b}"));
        }
        text.push('\n');
    }
    for face in cube.faces() {
        let corners: Vec<String> = face.iter().map(|v| (v + 1).to_string()).collect();
        text.push_str(&format!("f {}\n", corners.join(" ")));
    }
    text + extra
}

#[test]
fn subdivide_uses_a_crease_side_file() {
    let dir = folder("creases");
    io::write_mesh(dir.join("cube.ply"), &shapes::cube()).unwrap();
    // The edge from (0,0,0) to (1,0,0), hard, with both ends pinned.
    std::fs::write(
        dir.join("edge.txt"),
        "# one hard edge\n0 1 inf\ncorner 0 inf\ncorner 1 inf   # both ends stay\n",
    )
    .unwrap();
    let o = weft(
        &dir,
        &[
            "subdivide",
            "cube.ply",
            "creased.ply",
            "--levels",
            "3",
            "--creases",
            "edge.txt",
        ],
    );
    assert_exit(&o, 0);
    assert!(
        stderr(&o).contains("edge.txt: 1 creases and 2 corners"),
        "{}",
        stderr(&o)
    );
    let creased = io::read_mesh(dir.join("creased.ply")).unwrap();
    // The corners stay put (the cage's vertices keep their indices).
    assert_eq!(creased.positions()[0], weft::DVec3::ZERO);
    assert_eq!(creased.positions()[1], weft::DVec3::X);
    // The crease stays on the cage edge: 2³ + 1 vertices on the segment.
    let on_edge = |m: &weft::Mesh| {
        m.positions()
            .iter()
            .filter(|p| p.y.abs() < 1e-12 && p.z.abs() < 1e-12 && (0.0..=1.0).contains(&p.x))
            .count()
    };
    assert_eq!(on_edge(&creased), 9);
    let o = weft(
        &dir,
        &["subdivide", "cube.ply", "smooth.ply", "--levels", "3"],
    );
    assert_exit(&o, 0);
    assert_eq!(on_edge(&io::read_mesh(dir.join("smooth.ply")).unwrap()), 0);

    // Bad lines: exit 1, the file, the line and what was expected.
    for (text, expected) in [
        ("0 1 inf\n3 2\n", "bad.txt: line 2: expected \"i j sharpness\""),
        ("# fine\n0 1 soft\n", "bad.txt: line 2: expected a sharpness"),
        ("\n0 7 inf\n", "bad.txt: line 2: the crease from vertex 0 to vertex 7 cannot be used: they are not joined by an edge"),
        ("corner 8 inf\n", "bad.txt: line 1: corner vertex 8 is past the last vertex"),
    ] {
        std::fs::write(dir.join("bad.txt"), text).unwrap();
        let o = weft(&dir, &["subdivide", "cube.ply", "x.ply", "--creases", "bad.txt"]);
        assert_exit(&o, 1);
        assert!(stderr(&o).contains(expected), "{text:?}: {}", stderr(&o));
        assert!(!dir.join("x.ply").exists());
    }
    let o = weft(
        &dir,
        &["subdivide", "cube.ply", "x.ply", "--creases", "missing.txt"],
    );
    assert_exit(&o, 1);
    assert!(
        stderr(&o).contains("missing.txt: cannot read"),
        "{}",
        stderr(&o)
    );
    for bad in [
        ["--crease-angle", "-3"],
        ["--creasing", "sharp"],
        ["--uv-linear", "some"],
    ] {
        let o = weft(&dir, &["subdivide", "cube.ply", "x.ply", bad[0], bad[1]]);
        assert_exit(&o, 2);
    }
}

#[test]
fn obj_polylines_crease_and_the_angle_finds_folds() {
    let dir = folder("obj-creases");
    // The bottom face's four edges creased: the bottom stays flat at z = 0.
    std::fs::write(dir.join("cube.obj"), cube_obj(None, "l 1 3 4 2 1\n")).unwrap();
    std::fs::write(dir.join("plain.obj"), cube_obj(None, "")).unwrap();
    let flat = |name: &str| {
        let mesh = io::read_mesh(dir.join(name)).unwrap();
        mesh.positions().iter().filter(|p| p.z == 0.0).count()
    };
    let o = weft(
        &dir,
        &["subdivide", "cube.obj", "creased.obj", "--levels", "2"],
    );
    assert_exit(&o, 0);
    assert_eq!(flat("creased.obj"), 25);
    let o = weft(
        &dir,
        &["subdivide", "plain.obj", "smooth.obj", "--levels", "2"],
    );
    assert_exit(&o, 0);
    assert_eq!(flat("smooth.obj"), 0);

    // Every cube edge folds 90°: with a 60° crease angle the cube stays a cube.
    let o = weft(
        &dir,
        &[
            "subdivide",
            "plain.obj",
            "angle.obj",
            "--levels",
            "2",
            "--crease-angle",
            "60",
        ],
    );
    assert_exit(&o, 0);
    assert!(stderr(&o).contains("12 edges creased"), "{}", stderr(&o));
    let boxy = io::read_mesh(dir.join("angle.obj")).unwrap();
    for p in boxy.positions() {
        let on_face = p.to_array().iter().any(|&c| c == 0.0 || c == 1.0);
        assert!(on_face, "{p} left the cube's faces");
    }

    // A polyline off the mesh's edges is an error naming the OBJ line.
    std::fs::write(dir.join("diagonal.obj"), cube_obj(None, "l 1 4\n")).unwrap();
    let o = weft(&dir, &["subdivide", "diagonal.obj", "x.obj"]);
    assert_exit(&o, 1);
    assert!(
        stderr(&o).contains("diagonal.obj: line 15: the crease from vertex 0 to vertex 3"),
        "{}",
        stderr(&o)
    );
}

#[test]
fn colours_and_uvs_are_carried_through() {
    let dir = folder("carried");
    // A constant colour stays constant.
    std::fs::write(dir.join("grey.obj"), cube_obj(Some([0.25, 0.5, 0.75]), "")).unwrap();
    let o = weft(
        &dir,
        &["subdivide", "grey.obj", "grey2.obj", "--levels", "2"],
    );
    assert_exit(&o, 0);
    let file = io::read_mesh_file(dir.join("grey2.obj"), &Default::default()).unwrap();
    let colours = file.colours.expect("colours written");
    assert_eq!(colours.rgba.len(), 98);
    for c in &colours.rgba {
        for (got, want) in c.iter().zip([0.25, 0.5, 0.75, 1.0]) {
            assert!((got - want).abs() < 1e-12, "{c:?}");
        }
    }

    let o = weft(&dir, &["info", "grey.obj"]);
    assert!(
        stdout(&o).contains("carried data          vertex colours\n"),
        "{}",
        stdout(&o)
    );
    let o = weft(&dir, &["info", "grey.obj", "--json"]);
    assert!(
        stdout(&o).contains("\"carried\": [\"vertex colours\"]}"),
        "{}",
        stdout(&o)
    );

    // A PLY with colours: every output vertex has one, between its cage's.
    let mut coloured = io::MeshFile::new(shapes::cube());
    coloured.colours = Some(io::Colours {
        rgba: (0..8).map(|i| [(i % 2) as f64, 0.0, 1.0, 1.0]).collect(),
        alpha: false,
    });
    io::write_mesh_file(dir.join("cube.ply"), &coloured, &Default::default()).unwrap();
    let o = weft(
        &dir,
        &["subdivide", "cube.ply", "cube2.ply", "--levels", "2"],
    );
    assert_exit(&o, 0);
    let file = io::read_mesh_file(dir.join("cube2.ply"), &Default::default()).unwrap();
    let colours = file.colours.expect("colours written");
    assert_eq!(colours.rgba.len(), file.mesh.vertex_count());
    assert!(colours.rgba.iter().any(|c| c[0] > 0.1 && c[0] < 0.9));
    assert!(colours.rgba.iter().all(|c| c[1] == 0.0 && c[2] == 1.0));

    // UVs: a round trip through convert, and through subdivision.
    let uv_cube = cube_obj(None, "")
        .lines()
        .filter(|l| !l.starts_with('f'))
        .collect::<Vec<_>>()
        .join("\n")
        + "\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
        + &shapes::cube()
            .faces()
            .map(|f| {
                let c: Vec<String> = f
                    .iter()
                    .enumerate()
                    .map(|(k, v)| format!("{}/{}", v + 1, k + 1))
                    .collect();
                format!("f {}\n", c.join(" "))
            })
            .collect::<String>();
    std::fs::write(dir.join("uv.obj"), uv_cube).unwrap();
    let o = weft(&dir, &["convert", "uv.obj", "uv-copy.obj"]);
    assert_exit(&o, 0);
    let original = io::read_mesh_file(dir.join("uv.obj"), &Default::default()).unwrap();
    let copy = io::read_mesh_file(dir.join("uv-copy.obj"), &Default::default()).unwrap();
    assert_eq!(copy.uvs, original.uvs);
    assert_eq!(copy.uvs.as_ref().unwrap().indices.len(), 24);

    let o = weft(&dir, &["subdivide", "uv.obj", "uv2.obj", "--levels", "1"]);
    assert_exit(&o, 0);
    let refined = io::read_mesh_file(dir.join("uv2.obj"), &Default::default()).unwrap();
    let uvs = refined.uvs.expect("UVs written");
    assert_eq!(uvs.indices.len(), refined.mesh.index_count());
    // Each face is its own UV square: face points at its middle, linear edges.
    let mut values = uvs.values.clone();
    values.sort_by(|a, b| a.partial_cmp(b).unwrap());
    values.dedup();
    assert_eq!(values.len(), 9, "{values:?}");
    assert!(values.contains(&[0.5, 0.5]) && values.contains(&[0.5, 0.0]));

    // Loop triangulates and keeps the UVs with their corners.
    let o = weft(
        &dir,
        &["subdivide", "uv.obj", "uv-loop.obj", "--scheme", "loop"],
    );
    assert_exit(&o, 0);
    let looped = io::read_mesh_file(dir.join("uv-loop.obj"), &Default::default()).unwrap();
    assert_eq!(looped.uvs.unwrap().indices.len(), 48 * 3);

    // Commands that drop them, and formats that cannot hold them, say so.
    let o = weft(&dir, &["weld", "uv.obj", "-o", "welded.obj"]);
    assert_exit(&o, 0);
    assert!(
        stderr(&o).contains("uv.obj: this command keeps only the mesh; its UVs are not carried"),
        "{}",
        stderr(&o)
    );
    let o = weft(&dir, &["subdivide", "uv.obj", "uv.off"]);
    assert_exit(&o, 0);
    assert!(
        stderr(&o).contains("uv.off: this format cannot hold the UVs"),
        "{}",
        stderr(&o)
    );
    let o = weft(&dir, &["triangulate", "grey.obj", "grey-tri.obj"]);
    assert_exit(&o, 0);
    let tri = io::read_mesh_file(dir.join("grey-tri.obj"), &Default::default()).unwrap();
    assert_eq!(tri.colours.unwrap().rgba.len(), 8);
}

#[test]
fn limit_writes_unit_normals() {
    let dir = folder("limit");
    io::write_mesh(dir.join("torus.obj"), &shapes::torus(8, 6)).unwrap();
    let o = weft(
        &dir,
        &[
            "subdivide",
            "torus.obj",
            "limit.obj",
            "--levels",
            "2",
            "--limit",
        ],
    );
    assert_exit(&o, 0);
    let text = std::fs::read_to_string(dir.join("limit.obj")).unwrap();
    let normals: Vec<[f64; 3]> = text
        .lines()
        .filter_map(|l| l.strip_prefix("vn "))
        .map(|l| {
            let n: Vec<f64> = l.split_whitespace().map(|w| w.parse().unwrap()).collect();
            [n[0], n[1], n[2]]
        })
        .collect();
    let mesh = io::read_mesh(dir.join("limit.obj")).unwrap();
    assert_eq!(normals.len(), mesh.vertex_count());
    for n in &normals {
        let length = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
        assert!((length - 1.0).abs() < 1e-12, "{n:?}");
    }
    assert!(text
        .lines()
        .any(|l| l.starts_with("f ") && l.contains("//")));
    // The limit differs from the refined points.
    let o = weft(
        &dir,
        &["subdivide", "torus.obj", "refined.obj", "--levels", "2"],
    );
    assert_exit(&o, 0);
    let refined = io::read_mesh(dir.join("refined.obj")).unwrap();
    assert_ne!(refined.positions(), mesh.positions());

    let o = weft(
        &dir,
        &[
            "subdivide",
            "torus.obj",
            "limit.ply",
            "--levels",
            "1",
            "--limit",
        ],
    );
    assert_exit(&o, 0);
    let bytes = std::fs::read(dir.join("limit.ply")).unwrap();
    let header = String::from_utf8_lossy(&bytes[..400]);
    assert!(header.contains("property double nx"), "{header}");
}

/// Mesh-only commands read past malformed UVs, saying where they are;
/// subdivide, which would carry them, refuses the file at that line.
#[test]
fn malformed_uvs_stop_only_the_commands_that_carry_them() {
    let dir = folder("malformed-uvs");
    let text = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\n\
                f 1/1 2/2 3/3\nf 1 3 4\n";
    std::fs::write(dir.join("mixed.obj"), text).unwrap();

    let o = weft(&dir, &["flip", "mixed.obj", "flipped.obj"]);
    assert_exit(&o, 0);
    assert!(stderr(&o).contains("line 9"), "{}", stderr(&o));
    assert!(stderr(&o).contains("mesh alone"), "{}", stderr(&o));
    let flipped = io::read_mesh(dir.join("flipped.obj")).unwrap();
    assert_same_cycle(flipped.face(0), vec![2, 1, 0], 0);
    assert_same_cycle(flipped.face(1), vec![3, 2, 0], 1);

    let o = weft(&dir, &["info", "mixed.obj"]);
    assert_exit(&o, 0);
    assert!(
        stdout(&o).contains("faces                 2"),
        "{}",
        stdout(&o)
    );

    let o = weft(
        &dir,
        &[
            "subdivide",
            "mixed.obj",
            "smooth.obj",
            "--scheme",
            "loop",
            "--levels",
            "1",
        ],
    );
    assert_exit(&o, 1);
    assert!(stderr(&o).contains("mixed.obj: line 9"), "{}", stderr(&o));
    assert!(!dir.join("smooth.obj").exists());
}

/// The value after `"key": ` in one-line JSON.
fn json_number(json: &str, key: &str) -> f64 {
    let start = json
        .find(&format!("\"{key}\": "))
        .unwrap_or_else(|| panic!("no {key} in {json}"))
        + key.len()
        + 4;
    let rest = &json[start..];
    let end = rest.find([',', '}']).unwrap();
    rest[..end].parse().unwrap()
}

#[test]
fn info_reports_non_manifold_fins_and_vertices() {
    let dir = folder("info-non-manifold");
    // A fin: three quads on the edge from (0,0,0) to (0,1,0), whose two
    // vertices are therefore non-manifold too.
    std::fs::write(
        dir.join("fin.obj"),
        "v 0 0 0\nv 0 1 0\nv 1 0 0\nv 1 1 0\nv -1 0 0\nv -1 1 0\nv 0 0 1\nv 0 1 1\n\
         f 1 3 4 2\nf 1 2 6 5\nf 2 1 7 8\n",
    )
    .unwrap();
    // A bow tie: two triangles that share only a vertex.
    std::fs::write(
        dir.join("bowtie.obj"),
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv -1 0 0\nv 0 -1 0\nf 1 2 3\nf 1 4 5\n",
    )
    .unwrap();

    let text = succeeds(&dir, &["info", "fin.obj"]);
    assert_mentions(
        &text,
        &[
            "fin.obj\n",
            "  faces                 3 (0 triangles, 3 quads, 0 n-gons)\n",
            "  edges                 10\n",
            "  naked edges           9\n",
            "  non-manifold edges    1\n",
            "  non-manifold vertices 2\n",
            "  closed                no\n",
        ],
    );
    let json = succeeds(&dir, &["info", "fin.obj", "--json"]);
    assert_eq!(json_number(&json, "non_manifold_edges"), 1.0, "{json}");
    assert_eq!(json_number(&json, "non_manifold_vertices"), 2.0, "{json}");
    assert_eq!(json_number(&json, "naked_edges"), 9.0, "{json}");
    assert!(json.contains("\"closed\": false"), "{json}");

    let text = succeeds(&dir, &["info", "bowtie.obj"]);
    assert!(
        text.contains("  non-manifold edges    0\n  non-manifold vertices 1\n"),
        "{text}"
    );
    let o = weft(&dir, &["info", "bowtie.obj", "--json"]);
    let json = stdout(&o);
    assert_eq!(json_number(&json, "non_manifold_edges"), 0.0, "{json}");
    assert_eq!(json_number(&json, "non_manifold_vertices"), 1.0, "{json}");

    // A closed, manifold mesh has none.
    io::write_mesh(dir.join("cube.obj"), &shapes::cube()).unwrap();
    let json = stdout(&weft(&dir, &["info", "cube.obj", "--json"]));
    assert_eq!(json_number(&json, "non_manifold_edges"), 0.0, "{json}");
    assert_eq!(json_number(&json, "non_manifold_vertices"), 0.0, "{json}");
}

#[test]
fn info_reports_planarity() {
    let dir = folder("info-planarity");
    // Two unit quads side by side; the first has its corner (0, 1) raised by
    // 0.2, which puts each of its corners 0.05 from its best-fit plane.
    std::fs::write(
        dir.join("bent.obj"),
        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0.2\nv 2 0 0\nv 2 1 0\nf 1 2 3 4\nf 2 5 6 3\n",
    )
    .unwrap();
    let text = succeeds(&dir, &["info", "bent.obj"]);
    let line = text
        .lines()
        .find(|l| l.trim_start().starts_with("planarity"))
        .unwrap_or_else(|| panic!("no planarity line in\n{text}"));
    assert!(
        line.contains("1 of 2 faces beyond 0.001 of their best-fit plane (largest deviation 5."),
        "{line}"
    );
    let json = succeeds(&dir, &["info", "bent.obj", "--json"]);
    assert!(
        json.contains("\"planarity\": {\"tolerance\": 0.001, \"non_planar_faces\": 1, "),
        "{json}"
    );
    let deviation = json_number(&json, "max_deviation");
    assert!((deviation - 0.05).abs() < 1e-3, "{deviation}");

    // Under a looser tolerance the face counts as planar.
    let o = weft(
        &dir,
        &["info", "bent.obj", "--planarity-tolerance", "0.1", "--json"],
    );
    assert_exit(&o, 0);
    let json = stdout(&o);
    assert_eq!(json_number(&json, "non_planar_faces"), 0.0, "{json}");
    assert_eq!(json_number(&json, "tolerance"), 0.1, "{json}");
    let text = stdout(&weft(
        &dir,
        &["info", "bent.obj", "--planarity-tolerance", "0.1"],
    ));
    assert!(
        text.contains("0 of 2 faces beyond 0.1 of their best-fit plane"),
        "{text}"
    );

    // A flat mesh: no face beyond, and a deviation of 0.
    io::write_mesh(dir.join("flat.obj"), &shapes::quad_grid(2, 2)).unwrap();
    let json = stdout(&weft(&dir, &["info", "flat.obj", "--json"]));
    assert_eq!(json_number(&json, "non_planar_faces"), 0.0, "{json}");
    assert_eq!(json_number(&json, "max_deviation"), 0.0, "{json}");
}

#[test]
fn reroute_rotates_where_each_face_starts() {
    let dir = folder("reroute");
    std::fs::write(
        dir.join("mixed.obj"),
        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nf 1 2 3 4\nf 2 5 3\n",
    )
    .unwrap();
    let input = io::read_mesh(dir.join("mixed.obj")).unwrap();
    for (shift, quad, triangle) in [
        ("1", [1, 2, 3, 0], [4, 2, 1]),
        ("-1", [3, 0, 1, 2], [2, 1, 4]),
        ("5", [1, 2, 3, 0], [2, 1, 4]),
        ("0", [0, 1, 2, 3], [1, 4, 2]),
    ] {
        let out = format!("shift{shift}.obj");
        let rerouted = run_and_read(
            &dir,
            &["reroute", "mixed.obj", &out, "--shift", shift],
            &out,
        );
        assert_eq!(rerouted.face(0), &quad, "--shift {shift}");
        assert_eq!(rerouted.face(1), &triangle, "--shift {shift}");
        // Only the first corner moves: the vertices and the winding stay.
        assert_eq!(rerouted.positions(), input.positions());
        assert_same_cycle(rerouted.face(0), input.face(0).to_vec(), 0);
        assert_same_cycle(rerouted.face(1), input.face(1).to_vec(), 1);
    }
    // The default shift is 1.
    let default = run_and_read(&dir, &["reroute", "mixed.obj", "d.obj"], "d.obj");
    assert_eq!(default.face(0), &[1, 2, 3, 0]);

    let o = weft(&dir, &["reroute", "mixed.obj", "x.obj", "--shift", "1.5"]);
    assert_exit(&o, 2);
    assert!(stderr(&o).contains("'1.5' for '--shift"), "{}", stderr(&o));
    let o = weft(&dir, &["reroute", "gone.obj", "x.obj"]);
    assert_exit(&o, 1);
    assert!(
        stderr(&o).contains("weft: error: gone.obj: cannot read"),
        "{}",
        stderr(&o)
    );
    assert!(!dir.join("x.obj").exists());
}

/// Writes a PNG of `width` × `height` pixels of `colour` type and `depth`
/// from its samples, row by row from the top.
fn write_png(
    path: &Path,
    (width, height): (u32, u32),
    colour: png::ColorType,
    depth: png::BitDepth,
    samples: &[u8],
) {
    let file = std::io::BufWriter::new(std::fs::File::create(path).unwrap());
    let mut encoder = png::Encoder::new(file, width, height);
    encoder.set_color(colour);
    encoder.set_depth(depth);
    let mut writer = encoder.write_header().unwrap();
    writer.write_image_data(samples).unwrap();
}

/// Runs the fading pattern alone into `out`, with `image` when given, and
/// reads its pyramids.
fn fading_pyramids(dir: &Path, out: &str, image: Option<&str>) -> weft::Mesh {
    let mut args = vec!["demo", "--only", "fading", "--out", out];
    if let Some(image) = image {
        args.extend(["--image", image]);
    }
    let o = weft(dir, &args);
    assert_exit(&o, 0);
    let text = stdout(&o);
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines.len(), 4, "three stages and the index: {lines:?}");
    assert!(lines[1].starts_with("fading-pyramids: "), "{lines:?}");
    io::read_mesh(dir.join(out).join("fading-pyramids.obj")).unwrap()
}

/// How far each vertex of `mesh` is from the same vertex of `base`.
fn moved(mesh: &weft::Mesh, base: &weft::Mesh) -> Vec<f64> {
    assert_eq!(counts(mesh), counts(base));
    assert_eq!(mesh.face_sizes(), base.face_sizes());
    mesh.positions()
        .iter()
        .zip(base.positions())
        .map(|(p, q)| (*p - *q).length())
        .collect()
}

/// The fading pattern's pyramids are 0.05 + 0.6 × the picture's value
/// high (0 black, 1 white), so against an all-black picture every apex
/// moves by 0.6 × its value along its panel's normal, and nothing else moves.
#[test]
fn demo_image_sets_the_fading_heights() {
    let dir = folder("demo-image");
    use png::{BitDepth, ColorType};
    write_png(
        &dir.join("black.png"),
        (4, 4),
        ColorType::Grayscale,
        BitDepth::Eight,
        &[0; 16],
    );
    // Left half white, right half black.
    let half: Vec<u8> = (0..2)
        .flat_map(|_| [255, 255, 255, 255, 0, 0, 0, 0])
        .collect();
    write_png(
        &dir.join("half.png"),
        (8, 2),
        ColorType::Grayscale,
        BitDepth::Eight,
        &half,
    );

    let black = fading_pyramids(&dir, "black", Some("black.png"));
    let built_in = fading_pyramids(&dir, "built-in", None);
    let halves = fading_pyramids(&dir, "half", Some("half.png"));
    // The panels do not depend on the picture.
    for out in ["built-in", "half"] {
        assert_eq!(
            io::read_mesh(dir.join(out).join("fading-panels.obj")).unwrap(),
            io::read_mesh(dir.join("black").join("fading-panels.obj")).unwrap()
        );
    }
    let apexes = 112; // one per diamond panel

    // The built-in gradient rises from left to right: every apex but the
    // darkest moves, the ones on the right most.
    let from_black = moved(&built_in, &black);
    assert_eq!(from_black.iter().filter(|&&d| d > 1e-9).count(), apexes);
    assert!(from_black.iter().all(|&d| d <= 0.6 + 1e-9));

    // The halves: apexes on the left (x < 4) rise by 0.6, the others stay.
    let from_black = moved(&halves, &black);
    let (mut left, mut right) = (0, 0);
    for (d, p) in from_black.iter().zip(black.positions()) {
        if *d > 1e-9 {
            assert!((d - 0.6).abs() < 1e-9 && p.x < 4.0, "{p} moved by {d}");
            left += 1;
        } else if p.x > 4.0 {
            right += 1;
        }
    }
    assert!(left > 30, "{left} apexes on the left rose");
    assert!(right > 30, "{right} vertices on the right stayed");
    assert!(moved(&halves, &built_in).iter().any(|&d| d > 0.1));

    // Any PNG is read as luminance (0.2126 R + 0.7152 G + 0.0722 B), alpha
    // ignored, 16-bit samples rounded to 8; a single pixel covers everything.
    let green_rgba: Vec<u8> = (0..4).flat_map(|_| [0, 255, 0, 0]).collect();
    write_png(
        &dir.join("green.png"),
        (2, 2),
        ColorType::Rgba,
        BitDepth::Eight,
        &green_rgba,
    );
    write_png(
        &dir.join("white16.png"),
        (1, 1),
        ColorType::Grayscale,
        BitDepth::Sixteen,
        &[255, 255],
    );
    for (image, value) in [("green.png", 0.7152), ("white16.png", 1.0)] {
        let mesh = fading_pyramids(&dir, image.trim_end_matches(".png"), Some(image));
        let from_black = moved(&mesh, &black);
        let risen: Vec<f64> = from_black.iter().copied().filter(|&d| d > 1e-9).collect();
        assert_eq!(risen.len(), apexes, "{image}");
        for d in risen {
            assert!((d - 0.6 * value).abs() < 1e-9, "{image}: {d}");
        }
    }

    // A file that is not a whole PNG: exit 1, its name and the problem, and
    // no folder made.
    let mut truncated = std::fs::read(dir.join("half.png")).unwrap();
    truncated.truncate(40);
    std::fs::write(dir.join("truncated.png"), &truncated).unwrap();
    std::fs::write(dir.join("text.png"), "P2 2 2 255\n0 0 0 0\n").unwrap();
    std::fs::create_dir(dir.join("folder.png")).unwrap();
    for (image, expected) in [
        ("truncated.png", "truncated.png: "),
        ("text.png", "text.png: not a PNG picture"),
        ("missing.png", "missing.png: cannot read"),
        ("folder.png", "folder.png: "),
    ] {
        let o = weft(
            &dir,
            &[
                "demo", "--only", "fading", "--image", image, "--out", "never",
            ],
        );
        assert_exit(&o, 1);
        assert!(
            stderr(&o).contains(&format!("weft: error: {expected}")),
            "{image}: {}",
            stderr(&o)
        );
        assert!(!dir.join("never").exists(), "{image}");
    }
}

/// With stderr a pipe, as here, no progress is drawn: stderr holds only the
/// commands' own messages, however long the work takes.
#[test]
fn progress_stays_off_stderr_when_it_is_not_a_terminal() {
    let dir = folder("progress-pipe");
    let start = std::time::Instant::now();
    let o = weft(&dir, &["demo", "--only", "loop,boxes", "--out", "demo"]);
    assert_exit(&o, 0);
    assert_eq!(stderr(&o), "", "took {:?}", start.elapsed());
    assert!(stdout(&o).contains("\nboxes-smooth: "), "{}", stdout(&o));

    io::write_mesh(dir.join("torus.obj"), &shapes::torus(8, 6)).unwrap();
    let o = weft(
        &dir,
        &["subdivide", "torus.obj", "fine.ply", "--levels", "5"],
    );
    assert_exit(&o, 0);
    assert_eq!(stderr(&o), "fine.ply: 49152 vertices, 49152 faces\n");
}

/// On a terminal (util-linux's `script` gives the command one), work that
/// takes over half a second shows a bar of k/N workflows and the stage.
#[test]
fn progress_shows_a_bar_on_a_terminal() {
    let dir = folder("progress-terminal");
    let command = format!(
        "'{}' demo --only loop,boxes --out demo",
        env!("CARGO_BIN_EXE_weft")
    );
    let start = std::time::Instant::now();
    let o = Command::new("script")
        .current_dir(&dir)
        .args(["-q", "-e", "-c", &command, "/dev/null"])
        .stdin(std::process::Stdio::null())
        .output()
        .expect("this test needs util-linux's script to run weft on a terminal");
    let elapsed = start.elapsed();
    assert_exit(&o, 0);
    let screen = stdout(&o);
    // The summary lines are whole, between the bar's redraws.
    assert!(
        screen.contains("boxes-smooth: Catmull-Clark level 3 (3200 vertices, 3200 faces)\r\n"),
        "{screen}"
    );
    // A run this long shows the bar; a shorter one (an optimised build on
    // a fast machine) need not.
    if elapsed > std::time::Duration::from_secs(1) {
        assert!(
            screen.contains("[1/2] ") && screen.contains(" Loop subdivision: loop-"),
            "{screen}"
        );
        assert!(
            screen.contains("[2/2] ") && screen.contains(" aggregation of boxes: boxes-"),
            "{screen}"
        );
    }
}

/// `convert` through every format and encoding and back: polygons and f64
/// coordinates far from the origin survive OBJ, OFF and PLY exactly; STL
/// (f32 triangles) gives back the triangulated mesh once welded.
#[test]
fn convert_round_trips_through_every_format() {
    let dir = folder("round-trip");
    let mut mesh = shapes::mixed_polygons();
    for p in mesh.positions_mut() {
        *p += weft::DVec3::new(2_500_000.0, -1_000_000.0, 0.1);
    }
    io::write_mesh(dir.join("part.obj"), &mesh).unwrap();
    for (file, options, header) in [
        ("a.off", &[][..], &b"OFF"[..]),
        ("b.ply", &[], b"ply\nformat binary_little_endian 1.0"),
        (
            "c.ply",
            &["--big-endian"],
            b"ply\nformat binary_big_endian 1.0",
        ),
        ("d.ply", &["--ascii"], b"ply\nformat ascii 1.0"),
        ("e.obj", &[], b"#"),
    ] {
        let mut args = vec!["convert", "part.obj", file];
        args.extend_from_slice(options);
        let o = weft(&dir, &args);
        assert_exit(&o, 0);
        let bytes = std::fs::read(dir.join(file)).unwrap();
        assert!(bytes.starts_with(header), "{file}: {:?}", &bytes[..20]);
        let back = format!("{file}.obj");
        let o = weft(&dir, &["convert", file, &back]);
        assert_exit(&o, 0);
        assert_eq!(io::read_mesh(dir.join(&back)).unwrap(), mesh, "{file}");
    }

    let mut cube = shapes::cube();
    for p in cube.positions_mut() {
        *p = *p * 4.0 - weft::DVec3::splat(1024.0);
    }
    io::write_mesh(dir.join("cube.obj"), &cube).unwrap();
    for (file, options, header) in [
        ("f.stl", &[][..], &b""[..]),
        ("g.stl", &["--ascii"], b"solid"),
    ] {
        let mut args = vec!["convert", "cube.obj", file];
        args.extend_from_slice(options);
        assert_exit(&weft(&dir, &args), 0);
        let bytes = std::fs::read(dir.join(file)).unwrap();
        assert!(bytes.starts_with(header), "{file}");
        assert_eq!(bytes.starts_with(b"solid"), file == "g.stl", "{file}");
        let back = format!("{file}.obj");
        assert_exit(&weft(&dir, &["convert", "--weld", file, &back]), 0);
        let welded = io::read_mesh(dir.join(&back)).unwrap();
        assert_eq!(counts(&welded), (8, 12), "{file}");
        let mut got: Vec<[f64; 3]> = welded.positions().iter().map(|p| p.to_array()).collect();
        let mut want: Vec<[f64; 3]> = cube.positions().iter().map(|p| p.to_array()).collect();
        got.sort_by(|a, b| a.partial_cmp(b).unwrap());
        want.sort_by(|a, b| a.partial_cmp(b).unwrap());
        assert_eq!(got, want, "{file}");
        let info = weft::Topology::new(&welded).info(&welded);
        assert!(info.is_closed && info.is_oriented, "{file}");
    }
}

/// A vertex whose faces would make too many patches to fit together is
/// refused, naming the cage file and the vertex, and nothing is written.
#[test]
fn nurbs_refuses_a_vertex_whose_faces_make_too_many_patches_to_fit_together() {
    let dir = folder("nurbs-crowded");
    io::write_mesh(dir.join("fan.obj"), &shapes::fan(1500)).unwrap();
    let o = weft(&dir, &["nurbs", "fan.obj", "fan.step", "--isolation", "4"]);
    assert_exit(&o, 1);
    assert_mentions(
        &stderr(&o),
        &[
            "fan.obj",
            "vertex 0 has 1500 faces",
            "use a lower isolation",
        ],
    );
    assert!(!dir.join("fan.step").exists());
    // Fewer levels fit.
    let text = succeeds(&dir, &["nurbs", "fan.obj", "fan.step", "--isolation", "1"]);
    assert_mentions(&text, &["patches           4500"]);
}

/// A cage with a vertex of more faces than the limit surface takes is
/// refused, naming the cage file and the vertex, and nothing is written.
#[test]
fn evaluate_refuses_a_vertex_of_too_many_faces() {
    let dir = folder("evaluate-crowded");
    let fan = shapes::fan(1100);
    io::write_mesh(dir.join("fan.obj"), &fan).unwrap();
    std::fs::write(dir.join("uv.txt"), "0 0.25 0.25\n").unwrap();
    let o = weft(
        &dir,
        &[
            "evaluate",
            "fan.obj",
            "--samples",
            "uv.txt",
            "-o",
            "out.txt",
        ],
    );
    assert_exit(&o, 1);
    assert_mentions(
        &stderr(&o),
        &[
            "fan.obj",
            "cage vertex 0 has 1100 faces",
            "at most 1024",
            "nothing written",
        ],
    );
    assert!(!dir.join("out.txt").exists());
}
