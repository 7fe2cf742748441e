//! Weft as a C host calls it: the exports of `include/weft.h`, declared here
//! as a C program would declare them, so the timings include the ABI's
//! checks and conversions and nothing of the Rust API.

use std::ptr;

use weft::Mesh;

/// `WeftMesh`, opaque.
#[repr(C)]
pub struct WeftMesh {
    _private: [u8; 0],
}

/// `WEFT_NAKED_EDGES_SMOOTH`.
pub const NAKED_EDGES_SMOOTH: u32 = 1;

extern "C" {
    fn weft_mesh_new(
        positions: *const f64,
        vertex_count: usize,
        face_sizes: *const u32,
        face_count: usize,
        face_indices: *const u32,
        index_count: usize,
        out_mesh: *mut *mut WeftMesh,
    ) -> u32;
    fn weft_mesh_free(mesh: *mut WeftMesh);
    fn weft_mesh_vertex_count(mesh: *const WeftMesh) -> usize;
    fn weft_mesh_index_count(mesh: *const WeftMesh) -> usize;
    fn weft_catmull_clark(
        mesh: *const WeftMesh,
        levels: u32,
        naked_edges: u32,
        out_mesh: *mut *mut WeftMesh,
    ) -> u32;
    fn weft_loop(
        mesh: *const WeftMesh,
        levels: u32,
        naked_edges: u32,
        out_mesh: *mut *mut WeftMesh,
    ) -> u32;
}

/// A mesh handle of the library, freed on drop.
pub struct Handle(*mut WeftMesh);

// The library's meshes are immutable after construction and may be read
// from any thread (weft.h: "all functions may be called from several
// threads at once").
unsafe impl Send for Handle {}
unsafe impl Sync for Handle {}

impl Handle {
    /// The mesh, copied into the library through `weft_mesh_new`.
    pub fn new(mesh: &Mesh) -> Handle {
        let positions: Vec<f64> = mesh.positions().iter().flat_map(|p| p.to_array()).collect();
        let mut out = ptr::null_mut();
        // SAFETY: each buffer holds the count passed beside it; `out` is a
        // valid place for the handle.
        let status = unsafe {
            weft_mesh_new(
                positions.as_ptr(),
                mesh.vertex_count(),
                mesh.face_sizes().as_ptr(),
                mesh.face_count(),
                mesh.face_indices().as_ptr(),
                mesh.index_count(),
                &mut out,
            )
        };
        assert_eq!(status, 0, "weft_mesh_new");
        Handle(out)
    }

    /// Bytes of the positions and face indices: what a host must receive.
    pub fn output_bytes(&self) -> usize {
        // SAFETY: the handle is live until dropped.
        unsafe { 24 * weft_mesh_vertex_count(self.0) + 4 * weft_mesh_index_count(self.0) }
    }
}

impl Drop for Handle {
    fn drop(&mut self) {
        // SAFETY: the handle came from the library and is freed once.
        unsafe { weft_mesh_free(self.0) }
    }
}

/// `weft_catmull_clark` (or `weft_loop` when `loop_scheme`) with smooth
/// naked edges, the output mesh handed back as the library allocated it.
pub fn subdivide(cage: &Handle, loop_scheme: bool, levels: u32) -> Handle {
    let mut out = ptr::null_mut();
    // SAFETY: `cage` is live; `out` is a valid place for the handle.
    let status = unsafe {
        if loop_scheme {
            weft_loop(cage.0, levels, NAKED_EDGES_SMOOTH, &mut out)
        } else {
            weft_catmull_clark(cage.0, levels, NAKED_EDGES_SMOOTH, &mut out)
        }
    };
    assert_eq!(status, 0, "weft subdivides through the C ABI");
    Handle(out)
}
