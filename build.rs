//! Link settings for the shared library only (`cargo:rustc-cdylib-link-arg`):
//! on ELF systems a versioned soname (`libweft.so.0`) and a version script
//! that exports the `weft_*` functions and hides everything else; on macOS
//! an `@rpath` install name with compatibility and current versions.

use std::env;
use std::fs;
use std::path::PathBuf;

fn main() {
    println!("cargo:rerun-if-changed=build.rs");
    let major = env::var("CARGO_PKG_VERSION_MAJOR").expect("cargo sets CARGO_PKG_VERSION_MAJOR");
    let minor = env::var("CARGO_PKG_VERSION_MINOR").expect("cargo sets CARGO_PKG_VERSION_MINOR");
    let version = env::var("CARGO_PKG_VERSION").expect("cargo sets CARGO_PKG_VERSION");
    let os = env::var("CARGO_CFG_TARGET_OS").unwrap_or_default();
    let family = env::var("CARGO_CFG_TARGET_FAMILY").unwrap_or_default();

    if os == "macos" || os == "ios" {
        println!("cargo:rustc-cdylib-link-arg=-Wl,-install_name,@rpath/libweft.{major}.dylib");
        // The compatibility version is the oldest release with this ABI.
        println!("cargo:rustc-cdylib-link-arg=-Wl,-compatibility_version,{major}.{minor}.0");
        println!("cargo:rustc-cdylib-link-arg=-Wl,-current_version,{version}");
    } else if family == "unix" {
        println!("cargo:rustc-cdylib-link-arg=-Wl,-soname,libweft.so.{major}");
        let script =
            PathBuf::from(env::var("OUT_DIR").expect("cargo sets OUT_DIR")).join("weft.map");
        fs::write(&script, "{\n  global:\n    weft_*;\n  local:\n    *;\n};\n")
            .expect("the build directory is writable");
        println!(
            "cargo:rustc-cdylib-link-arg=-Wl,--version-script={}",
            script.display()
        );
        link_soname_in_build_tree(&major);
    }
}

/// A program linked against the build tree's `libweft.so` asks for
/// `libweft.so.<major>` at run time; this symlink beside it lets such a
/// program (the C tests, the README's by-hand build) run with
/// `LD_LIBRARY_PATH` set to the build directory, as without a soname.
fn link_soname_in_build_tree(major: &str) {
    // OUT_DIR is <profile dir>/build/<package>-<hash>/out.
    let out_dir = PathBuf::from(env::var("OUT_DIR").expect("cargo sets OUT_DIR"));
    let Some(profile_dir) = out_dir.ancestors().nth(3) else {
        return;
    };
    let link = profile_dir.join(format!("libweft.so.{major}"));
    if fs::symlink_metadata(&link).is_ok() {
        return;
    }
    #[cfg(unix)]
    if let Err(error) = std::os::unix::fs::symlink("libweft.so", &link) {
        println!("cargo:warning=could not link {}: {error}", link.display());
    }
}
