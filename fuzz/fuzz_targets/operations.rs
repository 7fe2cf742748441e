//! Every operation of the C ABI on arbitrary valid meshes and arbitrary
//! arguments — out-of-range enumeration values, NaN, infinities and huge
//! numbers included — as a host would call it. Each call must return a
//! status; a success must hand back a valid mesh (the checking constructor
//! accepts its buffers: distinct in-range corners, finite coordinates).
//! One input in eight builds its mesh with faces that may name a vertex
//! more than once (`WEFT_MESH_ALLOW_REPEATED_VERTICES`); every operation
//! must then work on those too, and its results are checked allowing them.
//! Primitives get counts that are either small or past the size cap, so a
//! refusal must come before any allocation. Exports that fill caller
//! buffers get capacities that are sometimes one short, and must then write
//! nothing; on success every number they write must be finite.
#![no_main]

use std::ptr::{null, null_mut};
use std::sync::atomic::{AtomicU32, Ordering};

use libfuzzer_sys::fuzz_target;
use weft::ffi::crease_edges::*;
use weft::ffi::limit_patches::*;
use weft::ffi::limit_surface::*;
use weft::ffi::creases::*;
use weft::ffi::make::*;
use weft::ffi::mend::*;
use weft::ffi::mesh::*;
use weft::ffi::orient::*;
use weft::ffi::refiner::*;
use weft::ffi::subdivide::*;
use weft::ffi::extract::*;
use weft::ffi::toolbar::*;
use weft::ffi::transform::*;
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

/// The flags the input's mesh was built with, for checking results alike.
static MESH_FLAGS: AtomicU32 = AtomicU32::new(0);

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
    // The top bits of the scale byte are free: 7 of them in 8 keep the
    // corpus's meshes as they were.
    let repeats = scale_byte >> 5 == 7;
    let flags = if repeats { WEFT_MESH_ALLOW_REPEATED_VERTICES } else { 0 };
    MESH_FLAGS.store(flags, Ordering::Relaxed);
    let vertex_count = 3 + bytes.small(10) as usize;
    let positions: Vec<f64> = (0..vertex_count * 3).map(|_| bytes.finite() * scale + shift).collect();
    let mut sizes = Vec::new();
    let mut indices = Vec::new();
    for _ in 0..1 + bytes.small(10) {
        let size = 3 + bytes.small(4) as usize;
        let mut face: Vec<u32> = Vec::new();
        while face.len() < size.min(vertex_count) {
            let v = bytes.small(vertex_count as u32);
            if repeats || !face.contains(&v) {
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
        weft_mesh_new_ex(
            positions.as_ptr(),
            vertex_count,
            sizes.as_ptr(),
            sizes.len(),
            indices.as_ptr(),
            indices.len(),
            flags,
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
            let status = weft_mesh_new_ex(
                positions.as_ptr(),
                info.vertex_count,
                sizes.as_ptr(),
                sizes.len(),
                indices.as_ptr(),
                indices.len(),
                MESH_FLAGS.load(Ordering::Relaxed),
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
        12 => {
            // Voronoi with a boundary polygon of hostile numbers.
            let boundary: Vec<f64> = (0..3 * bytes.small(7)).map(|_| bytes.number()).collect();
            let plane = WeftPlane { origin: [0.0; 3], x_axis: [1.0, 0.0, 0.0], y_axis: [0.0, 1.0, 0.0] };
            let radius = bytes.number();
            cells_to_mesh(&mut out, |cells| {
                weft_voronoi(points.as_ptr(), count, &plane, boundary.as_ptr(), boundary.len() / 3, radius, cells)
            })
        }
        _ => extended_operation(bytes.small(EXTENDED_OPERATIONS), mesh, bytes, &mut out),
    };
    (status, out)
}

/// Number of operations [`extended_operation`] chooses from.
const EXTENDED_OPERATIONS: u32 = 13;

/// A capacity for a buffer that needs `needed` elements: mostly exact,
/// sometimes one short (the call must then fail and write nothing), or 0.
fn capacity(bytes: &mut Bytes, needed: usize) -> usize {
    match bytes.byte() % 8 {
        0 => needed.saturating_sub(1),
        1 => 0,
        2 => needed + 3,
        _ => needed,
    }
}

/// A buffer of `len` elements filled with a marker, to see what a call wrote.
fn marked(len: usize) -> Vec<f64> {
    vec![-7.5; len]
}

/// Asserts that a call that failed wrote nothing, and one that succeeded
/// wrote only finite numbers into its first `written` elements.
fn check_written(status: WeftStatus, buffer: &[f64], written: usize, what: &str) {
    settle_status(status);
    if status == WeftStatus::Ok {
        if let Some(i) = buffer[..written].iter().position(|x| !x.is_finite()) {
            panic!("{what} wrote {} at {i}", buffer[i]);
        }
    } else {
        assert!(buffer.iter().all(|&x| x == -7.5), "{what} wrote on failure ({status:?})");
    }
}

/// A vertex index: mostly one of the mesh's, sometimes past them.
fn vertex_index(bytes: &mut Bytes, count: usize) -> u32 {
    match bytes.byte() % 16 {
        0 => u32::MAX,
        1 => count as u32 + bytes.small(3),
        _ => bytes.small(count as u32),
    }
}

/// A sharpness: the hostile numbers, infinitely sharp, or semi-sharp.
fn sharpness(bytes: &mut Bytes) -> f64 {
    match bytes.byte() % 4 {
        0 => WEFT_SHARPNESS_INFINITE,
        1 => bytes.small(40) as f64 / 8.0,
        _ => bytes.number(),
    }
}

/// Subdivision options from the bytes: arbitrary enumeration values, creases
/// on edges of the mesh or on arbitrary vertex pairs, corners, any sharpness.
struct Options {
    pairs: Vec<u32>,
    crease_sharpness: Vec<f64>,
    corners: Vec<u32>,
    corner_sharpness: Vec<f64>,
    holes: Vec<u32>,
    raw: WeftSubdivisionOptions,
}

unsafe fn options(mesh: *mut WeftMesh, bytes: &mut Bytes) -> Options {
    let count = weft_mesh_vertex_count(mesh);
    let sizes = std::slice::from_raw_parts(weft_mesh_face_sizes(mesh), weft_mesh_face_count(mesh));
    let indices = std::slice::from_raw_parts(weft_mesh_face_indices(mesh), weft_mesh_index_count(mesh));
    let mut pairs = Vec::new();
    let mut crease_sharpness = Vec::new();
    for _ in 0..bytes.small(6) {
        if bytes.byte() % 4 == 0 {
            pairs.push(vertex_index(bytes, count));
            pairs.push(vertex_index(bytes, count));
        } else {
            // An edge of the mesh: corner c and the next corner of its face.
            let f = bytes.small(sizes.len() as u32) as usize;
            let start: usize = sizes[..f].iter().map(|&n| n as usize).sum();
            let n = sizes[f] as usize;
            let c = bytes.small(n as u32) as usize;
            pairs.push(indices[start + c]);
            pairs.push(indices[start + (c + 1) % n]);
        }
        crease_sharpness.push(sharpness(bytes));
    }
    let mut corners = Vec::new();
    let mut corner_sharpness = Vec::new();
    for _ in 0..bytes.small(4) {
        corners.push(vertex_index(bytes, count));
        corner_sharpness.push(sharpness(bytes));
    }
    // Hole faces, now and then one past the last.
    let holes: Vec<u32> = (0..bytes.small(3)).map(|_| bytes.small(sizes.len() as u32 + 1)).collect();
    let mut raw = WeftSubdivisionOptions {
        scheme: match bytes.byte() % 8 {
            0 => 2 + bytes.small(4),
            n => u32::from(n % 2),
        },
        naked_edges: bytes.small(5),
        creasing: bytes.small(3),
        crease_count: 0,
        crease_vertex_pairs: null(),
        crease_sharpness: null(),
        corner_count: 0,
        corner_vertices: null(),
        corner_sharpness: null(),
        hole_count: 0,
        hole_faces: null(),
        triangles: bytes.small(3),
        reserved_flags: 0,
        reserved: [0; WEFT_SUBDIVISION_OPTIONS_RESERVED],
    };
    // Now and then a reserved field set: refused.
    if bytes.byte() % 32 == 0 {
        raw.reserved[bytes.small(WEFT_SUBDIVISION_OPTIONS_RESERVED as u32) as usize] = 1;
    }
    let mut options = Options { pairs, crease_sharpness, corners, corner_sharpness, holes, raw };
    options.raw.hole_count = options.holes.len();
    options.raw.hole_faces = options.holes.as_ptr();
    options.raw.crease_count = options.crease_sharpness.len();
    options.raw.corner_count = options.corners.len();
    // Sometimes a count with a NULL array: refused, never read.
    if bytes.byte() % 16 != 0 {
        options.raw.crease_vertex_pairs = options.pairs.as_ptr();
        options.raw.crease_sharpness = options.crease_sharpness.as_ptr();
    }
    options.raw.corner_vertices = options.corners.as_ptr();
    options.raw.corner_sharpness = options.corner_sharpness.as_ptr();
    options
}

/// The refined vertex, face and face-index counts of a subdivision with
/// `options`, when small enough to allocate buffers for.
unsafe fn counts(mesh: *mut WeftMesh, options: &WeftSubdivisionOptions, levels: u32) -> Option<(usize, usize, usize)> {
    let (mut v, mut f, mut i) = (0, 0, 0);
    let status = weft_subdivision_counts_ex(mesh, options, levels, &mut v, &mut f, &mut i);
    settle_status(status);
    (status == WeftStatus::Ok && i < 1 << 16).then_some((v, f, i))
}

/// Calls `export` with an output buffer for a creased export: `pick` says
/// how many values the counts need (any number when the counts are
/// refused), the room is sometimes short or long (see `capacity`); checks
/// what the export wrote.
unsafe fn with_output(
    mesh: *mut WeftMesh,
    options: &Options,
    levels: u32,
    bytes: &mut Bytes,
    (what, pick): (&str, impl Fn((usize, usize, usize)) -> usize),
    export: impl FnOnce(*mut f64, usize) -> WeftStatus,
) -> WeftStatus {
    let needed = counts(mesh, &options.raw, levels).map_or(bytes.small(64) as usize, pick);
    let mut result = marked(capacity(bytes, needed));
    let status = export(result.as_mut_ptr(), result.len());
    check_written(status, &result, needed, what);
    status
}

/// Makes Voronoi cells with `make` and, when it succeeds, their mesh into
/// `out`; a failure must leave no cells.
unsafe fn cells_to_mesh(out: &mut *mut WeftMesh, make: impl FnOnce(&mut *mut WeftCells) -> WeftStatus) -> WeftStatus {
    let mut cells = null_mut();
    let status = make(&mut cells);
    if status != WeftStatus::Ok {
        assert!(cells.is_null(), "failed cells left a handle");
        return status;
    }
    let status = weft_cells_to_mesh(cells, out);
    weft_cells_free(cells);
    status
}

/// Levels for the creased exports: mostly 0 to 2, sometimes so many that
/// even one triangle passes the size cap (3 · 4^19 faces), which must be
/// refused before anything is allocated. (Levels in between are within the
/// cap but need gigabytes, past the fuzzer's memory limit.)
fn levels(bytes: &mut Bytes) -> u32 {
    match bytes.byte() % 16 {
        0 => 20 + bytes.small(30),
        _ => bytes.small(3),
    }
}

/// The exports added with creases, carried data, the limit, the limit
/// surface and its patches, the toolbar's Tile and LaplacianHC inputs, and
/// the read-only accessors. Returns the
/// status; a mesh made goes to `out`.
unsafe fn extended_operation(op: u32, mesh: *mut WeftMesh, bytes: &mut Bytes, out: &mut *mut WeftMesh) -> WeftStatus {
    let count = weft_mesh_vertex_count(mesh);
    match op {
        0 => weft_tile(mesh, bytes.small(5), bytes.small(5), out),
        1 => {
            let activation: Vec<f64> = (0..count + bytes.small(3) as usize - 1)
                .map(|_| match bytes.byte() % 4 {
                    0 => bytes.number(),
                    _ => bytes.small(5) as f64 / 4.0,
                })
                .collect();
            let (pointer, len) = match bytes.byte() % 8 {
                0 => (null(), 0),
                _ => (activation.as_ptr(), activation.len()),
            };
            weft_laplacian_hc_smooth_ex(
                mesh,
                bytes.small(20),
                bytes.number(),
                bytes.number(),
                bytes.small(5),
                bytes.small(4),
                pointer,
                len,
                out,
            )
        }
        2 => {
            let options = options(mesh, bytes);
            weft_subdivide_ex(mesh, &options.raw, levels(bytes), out)
        }
        3 => {
            // Per-vertex data of any width, any numbers, any capacity.
            let options = options(mesh, bytes);
            let levels = levels(bytes);
            let width = bytes.small(5) as usize;
            let data_len = (count * width + bytes.small(3) as usize).saturating_sub(1);
            let data: Vec<f64> = (0..data_len).map(|_| bytes.number() * 1e-3 + bytes.finite()).collect();
            let wanted = ("weft_subdivide_vertex_data", |c: (usize, usize, usize)| c.0 * width);
            with_output(mesh, &options, levels, bytes, wanted, |out, room| {
                weft_subdivide_vertex_data(mesh, &options.raw, levels, data.as_ptr(), data.len(), width, out, room)
            })
        }
        4 => {
            // Face-varying values: indices sometimes past the values, lengths off by one.
            let options = options(mesh, bytes);
            let levels = levels(bytes);
            let width = 1 + bytes.small(3) as usize;
            let value_count = bytes.small(12) as usize;
            let values: Vec<f64> = (0..value_count * width).map(|_| bytes.finite()).collect();
            let index_count = (weft_mesh_index_count(mesh) + bytes.small(3) as usize).saturating_sub(1);
            let indices: Vec<u32> = (0..index_count).map(|_| bytes.small(value_count as u32 + 1)).collect();
            let linear = bytes.small(8);
            let wanted = ("weft_subdivide_face_varying", |c: (usize, usize, usize)| c.2 * width);
            with_output(mesh, &options, levels, bytes, wanted, |out, room| {
                let (values, indices) = ((values.as_ptr(), value_count), (indices.as_ptr(), indices.len()));
                weft_subdivide_face_varying(
                    mesh, &options.raw, levels, linear, values.0, values.1, width, indices.0, indices.1, out, room,
                )
            })
        }
        5 => {
            // The limit, with or without normals.
            let options = options(mesh, bytes);
            let levels = levels(bytes);
            let needed = counts(mesh, &options.raw, levels).map_or(bytes.small(64) as usize, |c| 3 * c.0);
            let room = capacity(bytes, needed);
            let mut positions = marked(room);
            let mut normals = marked(room);
            let normals_pointer = if bytes.byte() % 4 == 0 { null_mut() } else { normals.as_mut_ptr() };
            let status =
                weft_subdivide_limit(mesh, &options.raw, levels, positions.as_mut_ptr(), normals_pointer, room);
            check_written(status, &positions, needed, "weft_subdivide_limit positions");
            if !normals_pointer.is_null() {
                check_written(status, &normals, needed, "weft_subdivide_limit normals");
            }
            status
        }
        6 => {
            // The creased refiner: evaluate at hostile cage positions, then its mesh.
            let options = options(mesh, bytes);
            let mut refiner = null_mut();
            let status = weft_refiner_new_ex(mesh, &options.raw, levels(bytes), &mut refiner);
            if status != WeftStatus::Ok {
                assert!(refiner.is_null());
                return status;
            }
            evaluate_hostile(refiner, mesh, bytes);
            let faces = weft_refiner_face_count(refiner);
            let status = weft_refiner_mesh(refiner, out);
            if status == WeftStatus::Ok {
                assert_eq!(weft_mesh_face_count(*out), faces);
            }
            weft_refiner_free(refiner);
            status
        }
        7 => {
            // Creases from seams and folds, then subdivided with them.
            let index_count = weft_mesh_index_count(mesh);
            let room = capacity(bytes, 2 * index_count);
            let mut pairs = vec![u32::MAX; room];
            let mut welded = null_mut();
            let mut found = usize::MAX;
            let angle = match bytes.byte() % 2 {
                0 => bytes.number(),
                _ => bytes.small(200) as f64,
            };
            // With the weld's vertex map (weft_crease_edges_from_mesh_ex) or without.
            let mut map = match bytes.byte() % 3 {
                0 => None,
                _ => Some(vec![u32::MAX; capacity(bytes, count)]),
            };
            let status = match map.as_mut() {
                None => weft_crease_edges_from_mesh(mesh, angle, &mut welded, pairs.as_mut_ptr(), room, &mut found),
                Some(map) => weft_crease_edges_from_mesh_ex(
                    mesh,
                    angle,
                    &mut welded,
                    pairs.as_mut_ptr(),
                    room,
                    &mut found,
                    map.as_mut_ptr(),
                    map.len(),
                ),
            };
            settle_status(status);
            if status != WeftStatus::Ok {
                assert!(welded.is_null() && found == usize::MAX);
                assert!(pairs.iter().all(|&p| p == u32::MAX), "written on failure");
                assert!(map.iter().flatten().all(|&v| v == u32::MAX), "map written on failure");
                return status;
            }
            if let Some(map) = &map {
                // Every input vertex maps to a welded vertex at exactly its position, and every welded vertex is someone's.
                let welded_count = weft_mesh_vertex_count(welded);
                let input = std::slice::from_raw_parts(weft_mesh_positions(mesh), 3 * count);
                let output = std::slice::from_raw_parts(weft_mesh_positions(welded), 3 * welded_count);
                let mut used = vec![false; welded_count];
                for (v, &w) in map[..count].iter().enumerate() {
                    let w = w as usize;
                    assert!(w < welded_count, "vertex {v} maps to {w} of {welded_count}");
                    assert!(input[3 * v..3 * v + 3] == output[3 * w..3 * w + 3], "vertex {v} moved to {w}");
                    used[w] = true;
                }
                assert!(used.iter().all(|&u| u), "a welded vertex no input vertex maps to");
                assert!(map[count..].iter().all(|&v| v == u32::MAX), "map written past the vertex count");
            }
            let sharp = vec![WEFT_SHARPNESS_INFINITE; found];
            let raw = WeftSubdivisionOptions {
                scheme: 0,
                naked_edges: bytes.small(3),
                creasing: 0,
                crease_count: found,
                crease_vertex_pairs: pairs.as_ptr(),
                crease_sharpness: sharp.as_ptr(),
                corner_count: 0,
                corner_vertices: null(),
                corner_sharpness: null(),
                hole_count: 0,
                hole_faces: null(),
                triangles: 0,
                reserved_flags: 0,
                reserved: [0; WEFT_SUBDIVISION_OPTIONS_RESERVED],
            };
            let status = weft_subdivide_ex(welded, &raw, bytes.small(3), out);
            assert_eq!(status, WeftStatus::Ok, "creases from the mesh refused: {}", message());
            weft_mesh_free(welded);
            status
        }
        8 => {
            // Voronoi cells through every accessor, copied into buffers of any room.
            let points = std::slice::from_raw_parts(weft_mesh_positions(mesh), count * 3).to_vec();
            let plane = WeftPlane { origin: [0.0; 3], x_axis: [1.0, 0.0, 0.0], y_axis: [0.0, 1.0, 0.0] };
            let mut cells = null_mut();
            let status = weft_voronoi(points.as_ptr(), count, &plane, null(), 0, bytes.number(), &mut cells);
            if status != WeftStatus::Ok {
                assert!(cells.is_null());
                return status;
            }
            let (n, corners) = (weft_cells_count(cells), weft_cells_corner_count(cells));
            let sizes = weft_cells_sizes(cells);
            if !sizes.is_null() {
                let sizes = std::slice::from_raw_parts(sizes, n);
                assert_eq!(sizes.iter().map(|&s| s as usize).sum::<usize>(), corners);
            }
            let points = weft_cells_corners(cells);
            if !points.is_null() {
                let points = std::slice::from_raw_parts(points, 3 * corners);
                assert!(points.iter().all(|x| x.is_finite()), "a cell corner is not finite");
            }
            let mut out_sizes = vec![u32::MAX; capacity(bytes, n)];
            let mut out_corners = marked(capacity(bytes, 3 * corners));
            let status = weft_cells_copy(
                cells,
                out_sizes.as_mut_ptr(),
                out_sizes.len(),
                out_corners.as_mut_ptr(),
                out_corners.len(),
            );
            check_written(status, &out_corners, 3 * corners, "weft_cells_copy");
            if status != WeftStatus::Ok {
                assert!(out_sizes.iter().all(|&s| s == u32::MAX));
            }
            weft_cells_free(cells);
            status
        }
        9 => {
            // The limit surface as patches: isolation 0 to 3 (deeper ones need
            // gigabytes on these cages), or past the cap for every cage, as
            // in `levels` (9 to 11 are within it for ten hexagons, whose
            // patches' buffers alone take gigabytes).
            let options = options(mesh, bytes);
            let isolation = match bytes.byte() % 8 {
                0 => 20 + bytes.small(30),
                _ => bytes.small(4),
            };
            let (mut vertices, mut faces, mut indices) = (0, 0, 0);
            let counted = weft_subdivision_counts_ex(mesh, &options.raw, isolation, &mut vertices, &mut faces, &mut indices);
            let room = capacity(bytes, if counted == WeftStatus::Ok { faces } else { 4 });
            let mut control = marked(48 * room);
            let mut errors = marked(room);
            let (mut written, mut max_error, mut exact) = (0usize, -7.5, 0usize);
            let status = weft_limit_patches(
                mesh,
                &options.raw,
                isolation,
                control.as_mut_ptr(),
                null_mut(),
                errors.as_mut_ptr(),
                room,
                &mut written,
                &mut max_error,
                &mut exact,
            );
            check_written(status, &control, 48 * written, "weft_limit_patches control points");
            check_written(status, &errors, written, "weft_limit_patches errors");
            if status == WeftStatus::Ok {
                assert_eq!(written, faces);
                assert!(exact <= written && max_error >= 0.0);
            }
            status
        }
        10 => {
            // The limit surface anywhere: samples on any face (or past them),
            // at any parameter (NaN, outside the face); closest points to
            // hostile points.
            let options = options(mesh, bytes);
            let mut surface = null_mut();
            let status = weft_limit_surface_new(mesh, &options.raw, &mut surface);
            if status != WeftStatus::Ok {
                assert!(surface.is_null());
                return status;
            }
            let n = bytes.small(6) as usize;
            let faces: Vec<u32> = (0..n).map(|_| bytes.small(weft_mesh_face_count(mesh) as u32 + 2)).collect();
            let uvs: Vec<f64> = (0..2 * n)
                .map(|_| match bytes.byte() % 8 {
                    0 => bytes.number(),
                    _ => bytes.small(9) as f64 / 8.0,
                })
                .collect();
            let (mut positions, mut du) = (marked(3 * n), marked(3 * n));
            let status = weft_limit_surface_evaluate(surface, n, faces.as_ptr(), uvs.as_ptr(), positions.as_mut_ptr(), du.as_mut_ptr(), null_mut());
            check_written(status, &positions, 3 * n, "weft_limit_surface_evaluate positions");
            check_written(status, &du, 3 * n, "weft_limit_surface_evaluate du");
            let points: Vec<f64> = (0..3 * n).map(|_| bytes.number()).collect();
            let (mut closest_faces, mut closest_uvs, mut closest) = (vec![u32::MAX; n], marked(2 * n), marked(3 * n));
            let status = weft_limit_surface_closest_point(
                surface,
                n,
                points.as_ptr(),
                closest_faces.as_mut_ptr(),
                closest_uvs.as_mut_ptr(),
                closest.as_mut_ptr(),
            );
            check_written(status, &closest, 3 * n, "weft_limit_surface_closest_point positions");
            // Its patches, at an isolation shallow enough for the fuzzer's memory.
            let room = capacity(bytes, 4 * weft_mesh_index_count(mesh));
            let mut control = marked(48 * room);
            let mut written = 0usize;
            let status = weft_limit_surface_patches(surface, 1, control.as_mut_ptr(), null_mut(), null_mut(), room, &mut written, null_mut(), null_mut());
            check_written(status, &control, 48 * written, "weft_limit_surface_patches");
            weft_limit_surface_free(surface);
            status
        }
        11 => {
            // Into caller buffers: the allocating call's result, bit for bit,
            // and nothing written when a buffer is short.
            let (scheme, levels, naked_edges) = (bytes.small(3), bytes.small(4), bytes.small(5));
            let (mut vertices, mut faces, mut indices) = (0, 0, 0);
            let options = WeftSubdivisionOptions { scheme, naked_edges, ..std::mem::zeroed() };
            let counted = weft_subdivision_counts_ex(mesh, &options, levels, &mut vertices, &mut faces, &mut indices);
            if counted != WeftStatus::Ok || indices > 1 << 20 {
                return counted;
            }
            let mut positions = marked(capacity(bytes, 3 * vertices));
            let mut face_indices = vec![u32::MAX; capacity(bytes, indices)];
            let status = weft_subdivide_into(mesh, scheme, levels, naked_edges, positions.as_mut_ptr(), positions.len(), face_indices.as_mut_ptr(), face_indices.len());
            let mut expected = null_mut();
            let made = match scheme {
                0 => weft_catmull_clark(mesh, levels, naked_edges, &mut expected),
                _ => weft_loop(mesh, levels, naked_edges, &mut expected),
            };
            if status == WeftStatus::Ok {
                assert_eq!(made, WeftStatus::Ok, "weft_subdivide_into succeeded where the allocating call did not");
                let n = 3 * weft_mesh_vertex_count(expected);
                let k = weft_mesh_index_count(expected);
                // An empty mesh's accessors give NULL.
                if n > 0 {
                    let want = std::slice::from_raw_parts(weft_mesh_positions(expected), n);
                    assert!(positions[..n].iter().zip(want).all(|(a, b)| a.to_bits() == b.to_bits()), "weft_subdivide_into positions");
                }
                if k > 0 {
                    assert_eq!(&face_indices[..k], std::slice::from_raw_parts(weft_mesh_face_indices(expected), k));
                }
            } else if status == WeftStatus::BufferTooSmall {
                assert!(positions.len() < 3 * vertices || face_indices.len() < indices);
                assert!(positions.iter().all(|&x| x == -7.5) && face_indices.iter().all(|&i| i == u32::MAX), "weft_subdivide_into wrote into a short buffer");
            } else if status != WeftStatus::DegenerateInput {
                assert_eq!(status, made, "weft_subdivide_into and the allocating call disagree: {}", message());
            }
            weft_mesh_free(expected);
            status
        }
        _ => {
            // The read-only accessors agree with the copies.
            assert!(!weft_version().is_null());
            let faces = weft_mesh_face_count(mesh);
            let sizes = std::slice::from_raw_parts(weft_mesh_face_sizes(mesh), faces);
            let indices = std::slice::from_raw_parts(weft_mesh_face_indices(mesh), weft_mesh_index_count(mesh));
            assert_eq!(sizes.iter().map(|&s| s as usize).sum::<usize>(), indices.len());
            assert!(indices.iter().all(|&i| (i as usize) < count));
            assert!(weft_mesh_face_sizes(null()).is_null());
            let (scheme, levels) = (bytes.small(3), levels(bytes));
            let mut refiner = null_mut();
            let naked_edges = bytes.small(5);
            let status = weft_refiner_new(mesh, scheme, levels, naked_edges, &mut refiner);
            if status == WeftStatus::Ok {
                // All zeros is the default options (the header's rule); "none" leaves holes.
                let options = WeftSubdivisionOptions { scheme, naked_edges, ..std::mem::zeroed() };
                let (mut vertices, mut faces, mut indices) = (0, 0, 0);
                let counted = weft_subdivision_counts_ex(mesh, &options, levels, &mut vertices, &mut faces, &mut indices);
                assert_eq!(counted, WeftStatus::Ok);
                assert_eq!(weft_refiner_face_count(refiner), faces);
                assert_eq!(weft_refiner_vertex_count(refiner), vertices);
                evaluate_hostile(refiner, mesh, bytes);
                weft_refiner_free(refiner);
            } else {
                assert!(refiner.is_null());
            }
            assert_eq!(weft_refiner_face_count(null()), 0);
            status
        }
    }
}

/// `weft_refiner_evaluate` with cage positions scaled toward `f64::MAX`,
/// sometimes with a NaN, a wrong vertex count or an output one short.
unsafe fn evaluate_hostile(refiner: *mut WeftRefiner, mesh: *mut WeftMesh, bytes: &mut Bytes) {
    let count = weft_mesh_vertex_count(mesh);
    let factor = match bytes.byte() % 4 {
        0 => 1e300,
        1 => 1e-300,
        _ => 1.0,
    };
    let mut cage: Vec<f64> =
        std::slice::from_raw_parts(weft_mesh_positions(mesh), count * 3).iter().map(|p| p * factor).collect();
    if bytes.byte() % 8 == 0 {
        let i = bytes.small(cage.len() as u32) as usize;
        cage[i] = bytes.number();
    }
    let given = match bytes.byte() % 8 {
        0 => count.saturating_sub(1),
        _ => count,
    };
    let needed = 3 * weft_refiner_vertex_count(refiner);
    let mut result = marked(capacity(bytes, needed));
    let status = weft_refiner_evaluate(refiner, cage.as_ptr(), given, result.as_mut_ptr(), result.len());
    // A refined point beyond the largest double leaves the buffer unspecified.
    if status != WeftStatus::DegenerateInput {
        check_written(status, &result, needed, "weft_refiner_evaluate");
    }
    if given == count && result.len() >= needed && cage.iter().all(|c| c.is_finite()) {
        assert_eq!(status, WeftStatus::Ok, "weft_refiner_evaluate refused: {}", message());
    }
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
                    let radius = bytes.number();
                    cells_to_mesh(&mut out, |cells| weft_voronoi(points.as_ptr(), count, &plane, null(), 0, radius, cells))
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
