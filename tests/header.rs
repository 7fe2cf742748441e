//! `include/weft.h` is generated from the Rust sources by cbindgen and
//! committed; this test regenerates it and fails on any difference.
//! Run with `WEFT_UPDATE_HEADER=1` to rewrite the committed header.

use std::path::Path;

#[test]
fn header_is_current() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let config = cbindgen::Config::from_file(root.join("cbindgen.toml")).expect("cbindgen.toml");
    let mut generated = Vec::new();
    cbindgen::Builder::new()
        .with_crate(root)
        .with_config(config)
        .generate()
        .expect("cbindgen parses the crate")
        .write(&mut generated);
    let generated = String::from_utf8(generated).expect("header is UTF-8");
    let path = root.join("include/weft.h");
    if std::env::var_os("WEFT_UPDATE_HEADER").is_some() {
        std::fs::write(&path, &generated).expect("write include/weft.h");
        return;
    }
    let committed = std::fs::read_to_string(&path).unwrap_or_default();
    assert!(
        committed == generated,
        "include/weft.h is out of date: run `WEFT_UPDATE_HEADER=1 cargo test --test header` and commit it"
    );
}

#[test]
fn header_version_macros_match_the_package() {
    let header = include_str!("../include/weft.h");
    for (name, value) in [
        ("WEFT_VERSION_MAJOR", env!("CARGO_PKG_VERSION_MAJOR")),
        ("WEFT_VERSION_MINOR", env!("CARGO_PKG_VERSION_MINOR")),
        ("WEFT_VERSION_PATCH", env!("CARGO_PKG_VERSION_PATCH")),
    ] {
        assert!(
            header.contains(&format!("#define {name} {value}")),
            "{name} in include/weft.h does not match Cargo.toml ({value})"
        );
    }
}

#[test]
fn readme_shows_the_c_example_as_it_is() {
    let readme = include_str!("../README.md");
    let example = include_str!("../examples/subdivide_cube.c");
    assert!(
        readme.contains(&format!("```c\n{example}```")),
        "README.md's C example differs from examples/subdivide_cube.c"
    );
}

/// Every constant of the ABI and its value, as C and C# hosts compile them
/// in. A value never changes once released; new constants are added here
/// as they are exported. The version macros follow `Cargo.toml` instead.
const PINNED_CONSTANTS: &[(&str, &str)] = &[
    ("WEFT_CREASING_UNIFORM", "0"),
    ("WEFT_CREASING_CHAIKIN", "1"),
    ("WEFT_FACE_VARYING_SMOOTH", "0"),
    ("WEFT_FACE_VARYING_CORNERS_ONLY", "1"),
    ("WEFT_FACE_VARYING_CORNERS_PLUS1", "2"),
    ("WEFT_FACE_VARYING_CORNERS_PLUS2", "3"),
    ("WEFT_FACE_VARYING_BOUNDARIES", "4"),
    ("WEFT_FACE_VARYING_ALL", "5"),
    ("WEFT_SHARPNESS_INFINITE", "10.0"),
    ("WEFT_TRIANGLES_CATMARK", "0"),
    ("WEFT_TRIANGLES_SMOOTH", "1"),
    ("WEFT_SUBDIVISION_OPTIONS_RESERVED", "8"),
    ("WEFT_MESH_ALLOW_REPEATED_VERTICES", "1"),
    ("WEFT_PATCH_DOUBLES", "48"),
    ("WEFT_PLATONIC_TETRAHEDRON", "0"),
    ("WEFT_PLATONIC_HEXAHEDRON", "1"),
    ("WEFT_PLATONIC_OCTAHEDRON", "2"),
    ("WEFT_PLATONIC_DODECAHEDRON", "3"),
    ("WEFT_PLATONIC_ICOSAHEDRON", "4"),
    ("WEFT_SIDED_PRISM", "0"),
    ("WEFT_SIDED_ANTIPRISM", "1"),
    ("WEFT_SIDED_PYRAMID", "2"),
    ("WEFT_SIDED_DIPYRAMID", "3"),
    ("WEFT_DEFAULT_WELD_TOLERANCE", "0.001"),
    ("WEFT_NAKED_EDGES_FIXED", "0"),
    ("WEFT_NAKED_EDGES_SMOOTH", "1"),
    ("WEFT_NAKED_EDGES_NONE", "3"),
    ("WEFT_NAKED_EDGES_CORNER_FIXED", "2"),
    ("WEFT_SCHEME_CATMULL_CLARK", "0"),
    ("WEFT_SCHEME_LOOP", "1"),
    ("WEFT_OFFSET_DIAGONAL", "0"),
    ("WEFT_OFFSET_HYPOTENUSE_AVERAGE", "1"),
    ("WEFT_OFFSET_PLANES_INTERSECTION", "2"),
    ("WEFT_INSET_EDGE_FRACTION", "0"),
    ("WEFT_INSET_PARALLELOGRAM", "1"),
    ("WEFT_SMOOTH_DIRECTION_FREE", "0"),
    ("WEFT_SMOOTH_DIRECTION_ALONG_NORMAL", "1"),
    ("WEFT_SMOOTH_DIRECTION_TANGENTIAL", "2"),
    ("WEFT_TILE_FILL_SKIP", "0"),
    ("WEFT_TILE_FILL_BEST", "1"),
    ("WEFT_TILE_FILL_TRIANGLE_FAN", "2"),
    ("WEFT_TILE_FILL_TRIANGLE_HAND", "3"),
    ("WEFT_TILE_FILL_TRIANGLE_KNIT", "4"),
    ("WEFT_TILE_FILL_TRIANGLE_ZIGZAG", "5"),
    ("WEFT_TILE_FILL_QUAD_STITCH", "6"),
    ("WEFT_TILE_FILL_QUAD_FAN", "7"),
    ("WEFT_TILE_FACES_ALL", "0"),
    ("WEFT_TILE_FACES_QUADS_AND_MORE", "1"),
    ("WEFT_TILE_FACES_PENTAGONS_AND_MORE", "2"),
    ("WEFT_TILE_FACES_TRIANGLES", "9"),
    ("WEFT_TILE_FACES_QUADS", "16"),
    ("WEFT_DUAL_VERTEX_AVERAGE", "0"),
    ("WEFT_DUAL_KEEP_SIZE", "1"),
    ("WEFT_STATUS_OK", "0"),
    ("WEFT_STATUS_NULL_POINTER", "1"),
    ("WEFT_STATUS_INVALID_ARGUMENT", "2"),
    ("WEFT_STATUS_INDEX_OUT_OF_RANGE", "3"),
    ("WEFT_STATUS_FACE_TOO_SMALL", "4"),
    ("WEFT_STATUS_REPEATED_INDEX", "5"),
    ("WEFT_STATUS_NON_FINITE_COORDINATE", "6"),
    ("WEFT_STATUS_COUNT_MISMATCH", "7"),
    ("WEFT_STATUS_INPUT_TOO_LARGE", "8"),
    ("WEFT_STATUS_NOT_TRIANGLES", "9"),
    ("WEFT_STATUS_RESULT_TOO_LARGE", "10"),
    ("WEFT_STATUS_OUT_OF_MEMORY", "11"),
    ("WEFT_STATUS_BUFFER_TOO_SMALL", "12"),
    ("WEFT_STATUS_DEGENERATE_INPUT", "13"),
    ("WEFT_STATUS_INTERNAL_PANIC", "14"),
];

/// The `#define WEFT_*` macros and `WEFT_*` enumerators of a header, with
/// their values as written (the include guard left out).
fn header_constants(header: &str) -> Vec<(String, String)> {
    let mut found = Vec::new();
    for line in header.lines() {
        let (name, value) = if let Some(rest) = line.strip_prefix("#define ") {
            match rest.split_once(' ') {
                Some((name, value)) => (name, value.trim()),
                None => continue,
            }
        } else if let Some((name, value)) = line.trim().split_once(" = ") {
            (name, value.trim_end_matches(',').trim())
        } else {
            continue;
        };
        if name.starts_with("WEFT_") {
            found.push((name.to_string(), value.to_string()));
        }
    }
    found
}

/// What is wrong with a header's constants against the pinned table: a
/// constant that is not pinned, a value that moved, a pinned one missing.
fn constant_problems(header: &str) -> Vec<String> {
    let package_version = [
        ("WEFT_VERSION_MAJOR", env!("CARGO_PKG_VERSION_MAJOR")),
        ("WEFT_VERSION_MINOR", env!("CARGO_PKG_VERSION_MINOR")),
        ("WEFT_VERSION_PATCH", env!("CARGO_PKG_VERSION_PATCH")),
    ];
    let found = header_constants(header);
    let mut problems = Vec::new();
    for (name, value) in &found {
        let pinned = PINNED_CONSTANTS
            .iter()
            .chain(package_version.iter())
            .find(|(pinned, _)| pinned == name);
        match pinned {
            None => problems.push(format!("{name} = {value} is not pinned in tests/header.rs")),
            Some((_, expected)) if expected != value => {
                problems.push(format!("{name} is {value} but was released as {expected}"))
            }
            Some(_) => {}
        }
    }
    for (name, _) in PINNED_CONSTANTS.iter().chain(package_version.iter()) {
        if !found.iter().any(|(n, _)| n == name) {
            problems.push(format!("{name} is pinned but no longer in the header"));
        }
    }
    problems
}

#[test]
fn every_exported_constant_is_pinned_to_its_released_value() {
    let header = include_str!("../include/weft.h");
    assert!(
        header_constants(header).len() >= PINNED_CONSTANTS.len(),
        "the header's constants were not all parsed"
    );
    let problems = constant_problems(header);
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

#[test]
fn the_constant_check_catches_a_new_a_moved_and_a_lost_constant() {
    let header = include_str!("../include/weft.h")
        .replace("#define WEFT_SCHEME_LOOP 1", "#define WEFT_SCHEME_LOOP 2")
        .replace(
            "WEFT_STATUS_INTERNAL_PANIC = 14,",
            "WEFT_STATUS_INTERNAL_PANIC = 14,\n  WEFT_STATUS_NEW = 15,",
        )
        .replace("#define WEFT_DUAL_KEEP_SIZE 1", "");
    let mut problems = constant_problems(&header);
    problems.sort();
    assert_eq!(
        problems,
        vec![
            "WEFT_DUAL_KEEP_SIZE is pinned but no longer in the header".to_string(),
            "WEFT_SCHEME_LOOP is 2 but was released as 1".to_string(),
            "WEFT_STATUS_NEW = 15 is not pinned in tests/header.rs".to_string(),
        ]
    );
}

#[test]
fn the_header_reads_in_the_order_of_the_families() {
    // One export of each family, in the order a reader meets them: the mesh,
    // subdivision, the refiner, creases, mending, making, the toolbar.
    let header = include_str!("../include/weft.h");
    let families = [
        "weft_mesh_new(",
        "weft_catmull_clark(",
        "weft_refiner_new(",
        "weft_subdivide_ex(",
        "weft_weld(",
        "weft_delaunay(",
        "weft_split_polygons(",
    ];
    let positions: Vec<usize> = families
        .iter()
        .map(|name| {
            header
                .find(name)
                .unwrap_or_else(|| panic!("{name} is not in the header"))
        })
        .collect();
    for (pair, names) in positions.windows(2).zip(families.windows(2)) {
        assert!(
            pair[0] < pair[1],
            "{} comes after {} in include/weft.h; order the modules in src/ffi/mod.rs",
            names[0],
            names[1]
        );
    }
}
