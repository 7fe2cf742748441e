//! Arbitrary buffers into `weft_mesh_new`, as a careless host would pass them:
//! any counts (within the bytes given), any indices, any doubles. Every call
//! must return a status; a success must read back exactly what went in. The
//! same buffers lent to `weft_mesh_new_borrowed` give the same status and
//! message, and a mesh that reads them in place.
#![no_main]

use libfuzzer_sys::fuzz_target;
use weft::ffi::mesh::*;
use weft::ffi::WeftStatus;

fuzz_target!(|data: &[u8]| {
    if data.len() < 3 {
        return;
    }
    let (vertex_count, face_count) = (data[0] as usize % 16, data[1] as usize % 8);
    let mut rest = &data[2..];
    let mut take = |n: usize| {
        let (head, tail) = rest.split_at(n.min(rest.len()));
        rest = tail;
        head
    };
    let positions: Vec<f64> = take(vertex_count * 3 * 2)
        .chunks(2)
        .map(|c| match c[0] % 8 {
            0 => f64::NAN,
            1 => f64::INFINITY,
            2 => 1e308,
            _ => c.iter().map(|&b| b as f64).sum::<f64>() - 200.0,
        })
        .collect();
    let face_sizes: Vec<u32> = take(face_count).iter().map(|&b| (b % 7) as u32).collect();
    let face_indices: Vec<u32> = take(64)
        .iter()
        .map(|&b| if b == 255 { u32::MAX } else { (b % 20) as u32 })
        .collect();
    let vertex_count = positions.len() / 3;
    let mut borrowed = std::ptr::null_mut();
    let borrowed_status = unsafe {
        weft_mesh_new_borrowed(
            positions.as_ptr(),
            vertex_count,
            face_sizes.as_ptr(),
            face_sizes.len(),
            face_indices.as_ptr(),
            face_indices.len(),
            0,
            &mut borrowed,
        )
    };
    let borrowed_message = unsafe { std::ffi::CStr::from_ptr(weft_last_error_message()) }.to_owned();
    let mut mesh = std::ptr::null_mut();
    let status = unsafe {
        weft_mesh_new(
            positions.as_ptr(),
            vertex_count,
            face_sizes.as_ptr(),
            face_sizes.len(),
            face_indices.as_ptr(),
            face_indices.len(),
            &mut mesh,
        )
    };
    assert_eq!(status, borrowed_status);
    if status == WeftStatus::Ok {
        unsafe {
            assert!(weft_mesh_is_borrowed(borrowed) && !weft_mesh_is_borrowed(mesh));
            if vertex_count > 0 {
                assert_eq!(weft_mesh_positions(borrowed), positions.as_ptr());
            }
            let sizes = |m| std::slice::from_raw_parts(weft_mesh_face_sizes(m), face_sizes.len());
            if !face_sizes.is_empty() {
                assert_eq!(sizes(borrowed), sizes(mesh));
            }
            weft_mesh_free(borrowed);
            assert_eq!(weft_mesh_vertex_count(mesh), vertex_count);
            assert_eq!(weft_mesh_index_count(mesh), face_indices.len());
            let mut info = WeftMeshInfo::default();
            assert_eq!(weft_mesh_info(mesh, &mut info), WeftStatus::Ok);
            assert_eq!(info.face_count, face_sizes.len());
            weft_mesh_free(mesh);
        }
    } else {
        assert!(mesh.is_null() && borrowed.is_null());
        let message = unsafe { std::ffi::CStr::from_ptr(weft_last_error_message()) };
        assert!(!message.to_bytes().is_empty());
        assert_eq!(message, borrowed_message.as_c_str());
    }
});
