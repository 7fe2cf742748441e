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
