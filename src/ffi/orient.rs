//! Orientation exports: unify, turn outward, flip.

use crate::ffi::boundary::{counted_mesh_op, mesh_op, write_optional, WeftStatus};
use crate::ffi::mesh::WeftMesh;
use crate::mend::orient;

/// Gives every connected piece one consistent winding, flipping the fewest
/// of its faces, then turns each closed orientable piece to face outward.
/// A piece that cannot be oriented (a Möbius strip) is wound as consistently
/// as it can be; `weft_mesh_info` tells whether the mesh is orientable.
///
/// `mesh` must not be NULL.
/// `out_mesh` receives the result (free it with `weft_mesh_free`); it must
/// not be NULL and is written on success only.
/// `out_flipped` receives the number of faces reversed; it may be NULL.
///
/// # Safety
/// `mesh` is NULL or a live handle; `out_mesh` is NULL or writable; `out_flipped` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn weft_unify_orientation(
    mesh: *const WeftMesh,
    out_mesh: *mut *mut WeftMesh,
    out_flipped: *mut usize,
) -> WeftStatus {
    // SAFETY: `mesh`, `out_mesh` and `out_flipped` are as the `# Safety` section
    // above requires; each is checked for NULL before it is used.
    unsafe {
        counted_mesh_op(mesh, out_mesh, out_flipped, |m| {
            Ok(orient::unify_orientation(m))
        })
    }
}

/// What `weft_orient_outward` found and changed; a piece is a set of faces
/// connected through shared edges.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default)]
pub struct WeftOrientReport {
    /// Faces reversed.
    pub flipped_faces: usize,
    /// Connected pieces.
    pub pieces: usize,
    /// Closed pieces that enclosed a negative volume and were turned outward.
    pub turned_outward: usize,
    /// Pieces with a naked or non-manifold edge: unified, with no inside to
    /// face away from.
    pub open_pieces: usize,
    /// Pieces that no winding makes consistent (a Möbius strip).
    pub non_orientable_pieces: usize,
}

/// As `weft_unify_orientation` (one consistent winding per piece, closed
/// pieces turned to enclose a positive volume), reporting the pieces. The
/// triangles of an STL file share no vertices: weld them first
/// (`weft_weld`), or every triangle is an open piece of its own.
///
/// `mesh` must not be NULL.
/// `out_mesh` receives the result (free it with `weft_mesh_free`); it must
/// not be NULL and is written on success only.
/// `out_report` receives the pieces found and changed; it may be NULL.
///
/// # Safety
/// `mesh` is a live handle; `out_mesh` is writable; `out_report` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn weft_orient_outward(
    mesh: *const WeftMesh,
    out_mesh: *mut *mut WeftMesh,
    out_report: *mut WeftOrientReport,
) -> WeftStatus {
    // SAFETY: `mesh`, `out_mesh` and `out_report` are as the `# Safety` section
    // above requires; each is checked for NULL before it is used.
    unsafe {
        mesh_op(mesh, out_mesh, |mesh| {
            let (oriented, report) = orient::orient_outward(mesh);
            write_optional(
                out_report,
                WeftOrientReport {
                    flipped_faces: report.flipped_faces,
                    pieces: report.pieces,
                    turned_outward: report.turned_outward,
                    open_pieces: report.open_pieces,
                    non_orientable_pieces: report.non_orientable_pieces,
                },
            );
            Ok(oriented)
        })
    }
}

/// Reverses every face, keeping its first corner first ({a, b, c, d}
/// becomes {a, d, c, b}), so that flipping twice gives the input back.
///
/// `mesh` must not be NULL.
/// `out_mesh` receives the flipped mesh (free it with `weft_mesh_free`); it
/// must not be NULL and is written on success only.
///
/// # Safety
/// `mesh` is NULL or a live handle; `out_mesh` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn weft_flip(
    mesh: *const WeftMesh,
    out_mesh: *mut *mut WeftMesh,
) -> WeftStatus {
    // SAFETY: `mesh` and `out_mesh` are as the `# Safety` section
    // above requires; each is checked for NULL before it is used.
    unsafe { mesh_op(mesh, out_mesh, |mesh| Ok(orient::flip(mesh))) }
}
