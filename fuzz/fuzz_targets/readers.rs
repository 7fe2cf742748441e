//! The OBJ, PLY, STL and OFF readers on arbitrary bytes: each returns a mesh
//! or an error with a location, never a panic; a mesh read back is valid and
//! survives a write and a second read unchanged in its counts.
#![no_main]

use libfuzzer_sys::fuzz_target;
use weft::io::{parse_mesh, write_to, Format, WriteOptions};

fuzz_target!(|data: &[u8]| {
    let Some((&selector, bytes)) = data.split_first() else {
        return;
    };
    let format = [Format::Obj, Format::Ply, Format::Stl, Format::Off][selector as usize % 4];
    if let Ok(mesh) = parse_mesh(format, bytes) {
        let mut written = Vec::new();
        // A mesh a format cannot hold (binary STL's f32 range) is refused, not mangled.
        if let Err(e) = write_to(format, &mut written, &mesh, &WriteOptions::default()) {
            assert_eq!(e.kind(), std::io::ErrorKind::InvalidInput, "writing to memory: {e}");
            return;
        }
        let again = parse_mesh(format, &written).expect("a written mesh reads back");
        assert_eq!(again.face_count() > 0, mesh.face_count() > 0);
        if format != Format::Stl {
            assert_eq!(again.vertex_count(), mesh.vertex_count());
            assert_eq!(again.face_sizes(), mesh.face_sizes());
        }
    }
});
