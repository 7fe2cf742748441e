//! Compiles the C++ side of the bridge and links OpenSubdiv (`osdCPU`) and
//! OpenMesh (`OpenMeshCore`, `OpenMeshTools`) from the system (Debian
//! `libosd-dev`, `libopenmesh-dev`).

fn main() {
    cxx_build::bridge("src/bridge.rs")
        .file("src/bridge.cc")
        .std("c++17")
        // Built as OpenSubdiv's users build it for speed, in every profile:
        // the benchmarks compare with this code, and the tests run it too.
        .opt_level(3)
        .flag_if_supported("-march=native")
        .define("NDEBUG", None)
        .flag_if_supported("-Wall")
        // GCC 12 reports a false positive inside OpenMesh's inlined vectors.
        .flag_if_supported("-Wno-maybe-uninitialized")
        .compile("weft_reference_bridge");
    for lib in ["osdCPU", "OpenMeshCore", "OpenMeshTools"] {
        println!("cargo:rustc-link-lib={lib}");
    }
    for file in ["src/bridge.rs", "src/bridge.cc", "include/bridge.h"] {
        println!("cargo:rerun-if-changed={file}");
    }
}
