//! Weft as a C host calls it: the exports of `include/weft.h`, called
//! through their C signatures, so the timings include the ABI's checks and
//! conversions and nothing of the Rust API.

use std::ptr;

use weft::ffi::creases::weft_subdivision_counts;
use weft::ffi::mesh::{
    weft_mesh_free, weft_mesh_index_count, weft_mesh_new, weft_mesh_vertex_count,
};
use weft::ffi::subdivide::{
    weft_catmull_clark, weft_loop, weft_subdivide_into, WEFT_NAKED_EDGES_SMOOTH,
    WEFT_SCHEME_CATMULL_CLARK, WEFT_SCHEME_LOOP,
};
use weft::ffi::{WeftMesh, WeftStatus};
use weft::Mesh;

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
        assert_eq!(status, WeftStatus::Ok, "weft_mesh_new");
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

/// A host's own output buffers for `weft_subdivide_into`, sized once by
/// `weft_subdivision_counts` and kept from call to call.
pub struct Buffers {
    positions: Vec<f64>,
    indices: Vec<u32>,
}

fn scheme_value(loop_scheme: bool) -> u32 {
    if loop_scheme {
        WEFT_SCHEME_LOOP
    } else {
        WEFT_SCHEME_CATMULL_CLARK
    }
}

impl Buffers {
    pub fn new(cage: &Handle, loop_scheme: bool, levels: u32) -> Buffers {
        let (mut n, mut f, mut k) = (0, 0, 0);
        // SAFETY: `cage` is live; the counts are valid places.
        let status = unsafe {
            weft_subdivision_counts(
                cage.0,
                scheme_value(loop_scheme),
                levels,
                &mut n,
                &mut f,
                &mut k,
            )
        };
        assert_eq!(status, WeftStatus::Ok, "weft_subdivision_counts");
        let mut buffers = Buffers {
            positions: vec![0.0; 3 * n],
            indices: vec![0; k],
        };
        if std::env::var_os("WEFT_BENCH_HUGE").is_some() {
            weft_pages::advise_huge_pages(&mut buffers.positions);
            weft_pages::advise_huge_pages(&mut buffers.indices);
        }
        // Written once here, as a host's buffers are once it has used them.
        buffers.positions.fill(1.0);
        buffers.indices.fill(1);
        buffers
    }
}

/// `weft_subdivide_into` the host's `buffers`, smooth naked edges.
pub fn subdivide_into(cage: &Handle, loop_scheme: bool, levels: u32, buffers: &mut Buffers) {
    // SAFETY: `cage` is live; each buffer holds the capacity passed beside it.
    let status = unsafe {
        weft_subdivide_into(
            cage.0,
            scheme_value(loop_scheme),
            levels,
            WEFT_NAKED_EDGES_SMOOTH,
            buffers.positions.as_mut_ptr(),
            buffers.positions.len(),
            buffers.indices.as_mut_ptr(),
            buffers.indices.len(),
        )
    };
    assert_eq!(
        status,
        WeftStatus::Ok,
        "weft subdivides into a host's buffers"
    );
}

/// `weft_catmull_clark` (or `weft_loop` when `loop_scheme`) with smooth
/// naked edges, the output mesh handed back as the library allocated it.
pub fn subdivide(cage: &Handle, loop_scheme: bool, levels: u32) -> Handle {
    let mut out = ptr::null_mut();
    // SAFETY: `cage` is live; `out` is a valid place for the handle.
    let status = unsafe {
        if loop_scheme {
            weft_loop(cage.0, levels, WEFT_NAKED_EDGES_SMOOTH, &mut out)
        } else {
            weft_catmull_clark(cage.0, levels, WEFT_NAKED_EDGES_SMOOTH, &mut out)
        }
    };
    assert_eq!(status, WeftStatus::Ok, "weft subdivides through the C ABI");
    Handle(out)
}
