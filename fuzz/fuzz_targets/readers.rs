//! The OBJ, PLY, STL and OFF readers on arbitrary bytes: each returns a mesh
//! or an error with a location, never a panic; a mesh read back is valid and
//! survives a write and a second read unchanged in its counts; so does a
//! mesh read with its colours, UVs and creases (OBJ, PLY).
#![no_main]

use libfuzzer_sys::fuzz_target;
use weft::io::{parse_mesh, parse_mesh_file, write_file_to, write_to, Format, WriteOptions};

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
    if matches!(format, Format::Obj | Format::Ply) {
        if let Ok(file) = parse_mesh_file(format, bytes) {
            let mut written = Vec::new();
            write_file_to(format, &mut written, &file, &WriteOptions::default())
                .expect("a file read with its attributes writes");
            let again = parse_mesh_file(format, &written).expect("and reads back");
            assert_eq!(again.mesh.vertex_count(), file.mesh.vertex_count());
            assert_eq!(again.colours.is_some(), file.colours.is_some());
        }
    }
});
