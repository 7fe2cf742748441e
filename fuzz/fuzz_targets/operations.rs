//! Every operation of the C ABI on arbitrary valid meshes and arbitrary
//! arguments — out-of-range enumeration values, NaN, infinities and huge
//! numbers included — as a host would call it. Each call must return a
//! status; a success must hand back a valid mesh (the checking constructor
//! accepts its buffers: distinct in-range corners, finite coordinates).
//! Primitives get counts that are either small or past the size cap, so a
//! refusal must come before any allocation.
#![no_main]

use std::ptr::{null, null_mut};

use libfuzzer_sys::fuzz_target;
use weft::ffi::make::*;
use weft::ffi::mend::*;
use weft::ffi::mesh::*;
use weft::ffi::refiner::*;
use weft::ffi::subdivide::*;
use weft::ffi::toolbar::*;
use weft::ffi::WeftStatus;

/// Reads the fuzzer's bytes as a stream of small numbers.
struct Bytes<'a>(&'a [u8]);

impl Bytes<'_> {
    fn byte(&mut self) -> u8 {
        let (first, rest) = self.0.split_first().map_or((0, &[][..]), |(f, r)| (*f, r));
        self.0 = rest;
        first
    }

    fn small(&mut self, bound: u32) -> u32 {
        self.byte() as u32 % bound.max(1)
    }

    /// Mostly ordinary numbers, sometimes the values that break naive code.
    fn number(&mut self) -> f64 {
        match self.byte() % 16 {
            0 => f64::NAN,
            1 => f64::INFINITY,
            2 => f64::NEG_INFINITY,
            3 => 1e300,
            4 => -1e-300,
            5 => 0.0,
            _ => (self.byte() as f64 - 128.0) / 16.0,
        }
    }

    /// A count: small, or so large that any result would pass the size cap.
    fn count(&mut self) -> usize {
        match self.byte() % 8 {
            0 => usize::MAX,
            1 => 1 << 31,
            2 => 1_000_000_000,
            3 => usize::MAX / 3,
            _ => self.small(7) as usize,
        }
    }

    fn finite(&mut self) -> f64 {
        (self.byte() as f64 - 128.0) / 8.0 + self.byte() as f64 / 1024.0
    }
}

/// A valid mesh made from the bytes: up to 12 vertices and 10 faces of 3 to 6 corners.
/// The input's last byte picks the scale of the coordinates: mostly around
/// 1, sometimes near `f64::MAX`, near the smallest normal numbers, or far
/// from the origin.
fn build_mesh(bytes: &mut Bytes, scale_byte: u8) -> *mut WeftMesh {
    let (scale, shift) = match scale_byte % 16 {
        0 => (1e306, 0.0),
        1 => (1e153, 0.0),
        2 => (1e-300, 0.0),
        3 => (1.0, 1e9),
        _ => (1.0, 0.0),
    };
    let vertex_count = 3 + bytes.small(10) as usize;
    let positions: Vec<f64> = (0..vertex_count * 3).map(|_| bytes.finite() * scale + shift).collect();
    let mut sizes = Vec::new();
    let mut indices = Vec::new();
    for _ in 0..1 + bytes.small(10) {
        let size = 3 + bytes.small(4) as usize;
        let mut face: Vec<u32> = Vec::new();
        while face.len() < size.min(vertex_count) {
            let v = bytes.small(vertex_count as u32);
            if !face.contains(&v) {
                face.push(v);
            } else if bytes.0.is_empty() {
                face.push((0..vertex_count as u32).find(|c| !face.contains(c)).unwrap());
            }
        }
        sizes.push(face.len() as u32);
        indices.extend(face);
    }
    let mut mesh = null_mut();
    let status = unsafe {
        weft_mesh_new(
            positions.as_ptr(),
            vertex_count,
            sizes.as_ptr(),
            sizes.len(),
            indices.as_ptr(),
            indices.len(),
            &mut mesh,
        )
    };
    assert_eq!(status, WeftStatus::Ok, "a valid mesh was refused");
    mesh
}

/// Checks an operation's outcome and frees what it made.
fn settle(status: WeftStatus, out: *mut WeftMesh) {
    if status == WeftStatus::Ok {
        assert!(!out.is_null());
        let mut info = WeftMeshInfo::default();
        unsafe {
            assert_eq!(weft_mesh_info(out, &mut info), WeftStatus::Ok);
            assert_eq!(info.vertex_count, weft_mesh_vertex_count(out));
            assert_eq!(info.face_count, weft_mesh_face_count(out));
            let mut positions = vec![0.0; info.vertex_count * 3];
            assert_eq!(
                weft_mesh_copy_positions(out, positions.as_mut_ptr(), positions.len()),
                WeftStatus::Ok
            );
            let mut sizes = vec![0u32; weft_mesh_face_count(out)];
            let mut indices = vec![0u32; weft_mesh_index_count(out)];
            assert_eq!(
                weft_mesh_copy_faces(out, sizes.as_mut_ptr(), sizes.len(), indices.as_mut_ptr(), indices.len()),
                WeftStatus::Ok
            );
            let mut copy = null_mut();
            let status = weft_mesh_new(
                positions.as_ptr(),
                info.vertex_count,
                sizes.as_ptr(),
                sizes.len(),
                indices.as_ptr(),
                indices.len(),
                &mut copy,
            );
            assert_eq!(status, WeftStatus::Ok, "an operation returned an invalid mesh: {}", message());
            weft_mesh_free(copy);
            weft_mesh_free(out);
        }
    } else {
        assert!(out.is_null(), "an output was written on failure");
        assert_ne!(status, WeftStatus::InternalPanic, "a panic was caught: {}", message());
    }
}

fn message() -> String {
    unsafe { std::ffi::CStr::from_ptr(weft_last_error_message()).to_string_lossy().into_owned() }
}

/// Checks a status of an export that fills caller buffers.
fn settle_status(status: WeftStatus) {
    assert_ne!(status, WeftStatus::InternalPanic, "a panic was caught: {}", message());
}

/// The exports that are not a mesh-to-mesh operation: primitives with
/// hostile counts, join, queries that fill caller buffers, Voronoi with a
/// boundary. Returns the status and the mesh made, if any.
unsafe fn other_operation(op: u8, mesh: *mut WeftMesh, bytes: &mut Bytes) -> (WeftStatus, *mut WeftMesh) {
    let mut out = null_mut();
    let count = weft_mesh_vertex_count(mesh);
    let points = std::slice::from_raw_parts(weft_mesh_positions(mesh), count * 3).to_vec();
    let status = match op {
        0 => weft_plane_grid(bytes.number(), bytes.number(), bytes.count(), bytes.count(), &mut out),
        1 => weft_box(bytes.number(), 1.0, bytes.number(), bytes.count(), bytes.count(), bytes.count(), &mut out),
        2 => weft_uv_sphere(bytes.number(), bytes.count(), bytes.count(), &mut out),
        3 => weft_platonic(bytes.small(8), bytes.number(), &mut out),
        4 => weft_sided_solid(bytes.small(6), bytes.count(), bytes.number(), bytes.number(), &mut out),
        5 => {
            let parts = [mesh as *const WeftMesh, mesh, null()];
            weft_join(parts.as_ptr(), 1 + bytes.small(3) as usize, &mut out)
        }
        6 => {
            let mut nodes = vec![WeftTNode::default(); bytes.small(8) as usize];
            let mut found = 0;
            weft_find_t_nodes(mesh, bytes.number(), nodes.as_mut_ptr(), nodes.len(), &mut found)
        }
        7 => {
            let mut normals = vec![0.0; 3 * weft_mesh_vertex_count(mesh).max(weft_mesh_face_count(mesh))];
            let len = normals.len() - bytes.small(2) as usize;
            settle_status(weft_face_normals(mesh, normals.as_mut_ptr(), len));
            settle_status(weft_planarity(mesh, normals.as_mut_ptr(), len));
            weft_vertex_normals(mesh, normals.as_mut_ptr(), len)
        }
        8 => {
            let index_count = weft_mesh_index_count(mesh);
            let mut points = vec![0.0; 3 * index_count];
            let mut counts = vec![0usize; index_count];
            let mut closed = vec![false; index_count];
            let (mut total, mut lines) = (0, 0);
            weft_naked_boundaries(
                mesh,
                points.as_mut_ptr(),
                points.len() - bytes.small(2) as usize,
                counts.as_mut_ptr(),
                closed.as_mut_ptr(),
                counts.len(),
                &mut total,
                &mut lines,
            )
        }
        9 => {
            let components = bytes.small(4) as usize;
            let values: Vec<f64> = (0..count * components.max(1)).map(|_| bytes.number()).collect();
            let mut blurred = vec![0.0; values.len()];
            weft_blur_values(
                mesh,
                values.as_ptr(),
                values.len(),
                components,
                bytes.small(20),
                bytes.number(),
                bytes.small(5),
                blurred.as_mut_ptr(),
                blurred.len(),
            )
        }
        10 => {
            let mut edges = 0;
            settle_status(weft_mesh_edge_count(mesh, &mut edges));
            let mut pairs = vec![0u32; 2 * edges];
            settle_status(weft_mesh_copy_edges(mesh, pairs.as_mut_ptr(), pairs.len()));
            let mut segments = vec![0.0; 6 * edges];
            weft_mesh_copy_edge_segments(mesh, segments.as_mut_ptr(), segments.len())
        }
        11 => {
            let (scheme, levels) = (bytes.small(3), bytes.small(40));
            let mut faces = 0;
            let status = weft_subdivision_face_count(mesh, scheme, levels, &mut faces);
            settle_status(status);
            if status == WeftStatus::Ok && faces < 1 << 16 {
                let mut parents = vec![0u32; faces];
                weft_subdivision_parent_faces(mesh, scheme, levels, parents.as_mut_ptr(), parents.len())
            } else {
                status
            }
        }
        _ => {
            // Voronoi with a boundary polygon of hostile numbers.
            let boundary: Vec<f64> = (0..3 * bytes.small(7)).map(|_| bytes.number()).collect();
            let plane = WeftPlane { origin: [0.0; 3], x_axis: [1.0, 0.0, 0.0], y_axis: [0.0, 1.0, 0.0] };
            let mut cells = null_mut();
            let status =
                weft_voronoi(points.as_ptr(), count, &plane, boundary.as_ptr(), boundary.len() / 3, bytes.number(), &mut cells);
            if status == WeftStatus::Ok {
                let status = weft_cells_to_mesh(cells, &mut out);
                weft_cells_free(cells);
                status
            } else {
                assert!(cells.is_null());
                status
            }
        }
    };
    (status, out)
}

fuzz_target!(|data: &[u8]| {
    let mut bytes = Bytes(data);
    let mesh = build_mesh(&mut bytes, data.last().copied().unwrap_or(0));
    let (levels, mode) = (bytes.small(3), bytes.small(5));
    let mut out = null_mut();
    unsafe {
        // Operation bytes below 240 keep the meaning they had in the corpus.
        let op = bytes.byte();
        if op >= 240 {
            let (status, out) = other_operation(op - 240, mesh, &mut bytes);
            // The queries make no mesh.
            if out.is_null() {
                settle_status(status);
            } else {
                settle(status, out);
            }
            weft_mesh_free(mesh);
            return;
        }
        let status = match op % 30 {
            0 => weft_catmull_clark(mesh, levels, mode, &mut out),
            1 => weft_loop(mesh, levels, mode, &mut out),
            2 => weft_triangulate(mesh, &mut out),
            3 => weft_weld(mesh, bytes.number(), &mut out, null_mut()),
            4 => weft_repair_t_nodes(mesh, bytes.number(), &mut out, null_mut()),
            5 => weft_cull_adjacent(mesh, &mut out, null_mut()),
            6 => weft_unify_orientation(mesh, &mut out, null_mut()),
            7 => weft_flip(mesh, &mut out),
            8 => {
                let heights: Vec<f64> = (0..bytes.small(12)).map(|_| bytes.number()).collect();
                weft_stellate(mesh, heights.as_ptr(), heights.len(), &mut out)
            }
            9 => weft_split_polygons(mesh, levels, &mut out),
            10 => weft_split_triangles(mesh, levels, &mut out),
            11 => weft_constant_quads_split(mesh, levels, &mut out),
            12 => weft_midedge(mesh, levels, &mut out),
            13 => weft_inner_polygons(mesh, levels, bytes.number(), &mut out),
            14 => weft_sierpinski_triangles(mesh, levels, &mut out),
            15 => weft_laplacian_smooth(mesh, bytes.small(20), bytes.number(), mode, &mut out),
            16 => weft_laplacian_hc_smooth(mesh, bytes.small(20), bytes.number(), bytes.number(), mode, &mut out),
            17 => weft_offset_mesh(mesh, bytes.number(), bytes.small(5), &mut out),
            18 => weft_thicken_mesh(mesh, bytes.number(), bytes.small(5), &mut out),
            19 => {
                let distances: Vec<f64> = (0..bytes.small(12)).map(|_| bytes.number()).collect();
                weft_mesh_window(mesh, distances.as_ptr(), distances.len(), bytes.small(4), &mut out)
            }
            20 => {
                let distances: Vec<f64> = (0..bytes.small(12)).map(|_| bytes.number()).collect();
                weft_picture_frame(mesh, distances.as_ptr(), distances.len(), bytes.small(4), &mut out)
            }
            21 => weft_sierpinski_carpet(mesh, levels, &mut out),
            22 => weft_bevel_edges(mesh, bytes.number(), &mut out),
            23 => weft_bevel_vertices(mesh, bytes.number(), &mut out),
            24 => weft_dual(mesh, bytes.small(4), &mut out),
            25 => weft_reroute_faces(mesh, bytes.byte() as i64 - 128, &mut out),
            26 => {
                // Points of the mesh through Delaunay or Voronoi on an arbitrary plane.
                let count = weft_mesh_vertex_count(mesh);
                let points = std::slice::from_raw_parts(weft_mesh_positions(mesh), count * 3).to_vec();
                let plane = WeftPlane {
                    origin: [bytes.number(), 0.0, 0.0],
                    x_axis: [1.0, bytes.number(), 0.0],
                    y_axis: [bytes.number(), 1.0, bytes.number()],
                };
                if bytes.byte() % 2 == 0 {
                    weft_delaunay(points.as_ptr(), count, &plane, &mut out, null_mut())
                } else {
                    let mut cells = null_mut();
                    let status = weft_voronoi(points.as_ptr(), count, &plane, null(), 0, bytes.number(), &mut cells);
                    if status == WeftStatus::Ok {
                        let status = weft_cells_to_mesh(cells, &mut out);
                        weft_cells_free(cells);
                        status
                    } else {
                        assert!(cells.is_null());
                        status
                    }
                }
            }
            27 => {
                let count = weft_mesh_vertex_count(mesh);
                let points = std::slice::from_raw_parts(weft_mesh_positions(mesh), count * 3).to_vec();
                let (u, v) = (bytes.small(6) as usize, bytes.small(6) as usize);
                weft_mesh_from_grid(points.as_ptr(), count, u, v, bytes.byte() % 2 == 0, bytes.byte() % 2 == 0, bytes.byte() % 2 == 0, &mut out)
            }
            28 => {
                let segments: Vec<f64> = (0..6 * bytes.small(8)).map(|_| bytes.number()).collect();
                weft_mesh_from_lines(segments.as_ptr(), segments.len() / 6, bytes.number(), bytes.small(8), &mut out)
            }
            _ => {
                // The refiner: build, re-evaluate with moved positions, read its mesh.
                let mut refiner = null_mut();
                let status = weft_refiner_new(mesh, bytes.small(3), levels, mode, &mut refiner);
                if status == WeftStatus::Ok {
                    let count = weft_mesh_vertex_count(mesh);
                    let moved: Vec<f64> = std::slice::from_raw_parts(weft_mesh_positions(mesh), count * 3)
                        .iter()
                        .map(|p| p * 2.0 + 1.0)
                        .collect();
                    let mut evaluated = vec![0.0; weft_refiner_vertex_count(refiner) * 3];
                    assert_eq!(
                        weft_refiner_evaluate(refiner, moved.as_ptr(), count, evaluated.as_mut_ptr(), evaluated.len()),
                        WeftStatus::Ok
                    );
                    let status = weft_refiner_mesh(refiner, &mut out);
                    weft_refiner_free(refiner);
                    status
                } else {
                    status
                }
            }
        };
        settle(status, out);
        weft_mesh_free(mesh);
    }
});
