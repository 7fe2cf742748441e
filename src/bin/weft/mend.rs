//! The mending commands: `weld` (join and weld), `cull-adjacent`, `flip`
//! and `t-nodes`.

use std::path::{Path, PathBuf};

use weft::io;
use weft::Mesh;

use crate::args::InOut;
use crate::files::{operation_failed, read, with_progress, write};
use crate::{Cli, Failure};

/// Joins the inputs and merges vertices closer than `tolerance`.
pub fn weld(cli: &Cli, inputs: &[PathBuf], output: &Path, tolerance: f64) -> Result<(), Failure> {
    let meshes = inputs
        .iter()
        .map(|path| read(cli, path))
        .collect::<Result<Vec<_>, _>>()?;
    let parts: Vec<&Mesh> = meshes.iter().collect();
    let joined = weft::weld::join(&parts)
        .map_err(|e| Failure::Failed(format!("cannot join the inputs: {e}")))?;
    let (welded, report) = with_progress("welding", || weft::weld::weld(&joined, tolerance))
        .map_err(|e| Failure::Failed(format!("cannot weld the inputs: {e}")))?;
    eprintln!(
        "joined {} meshes ({} vertices, {} faces); merged {} vertices, removed {} collapsed faces and {} unused vertices",
        meshes.len(),
        joined.vertex_count(),
        joined.face_count(),
        report.merged_vertex_count,
        report.removed_face_count,
        report.unused_vertex_count
    );
    write(output, &welded, &io::WriteOptions::default())
}

/// Removes every face that has a twin.
pub fn cull_adjacent(cli: &Cli, files: &InOut) -> Result<(), Failure> {
    let mesh = read(cli, &files.input)?;
    let (culled, removed) = with_progress("culling", || weft::cull::cull_adjacent(&mesh));
    eprintln!(
        "{}: removed {removed} of {} faces that had a twin",
        files.input.display(),
        mesh.face_count()
    );
    write(&files.output, &culled, &io::WriteOptions::default())
}

/// Flips every face, or with `unify` the fewest for one orientation.
pub fn flip(cli: &Cli, files: &InOut, unify: bool) -> Result<(), Failure> {
    let mesh = read(cli, &files.input)?;
    let flipped = if unify {
        let (unified, count) = with_progress("unifying", || weft::orient::unify_orientation(&mesh));
        eprintln!(
            "{}: flipped {count} of {} faces to unify the orientation{}",
            files.input.display(),
            mesh.face_count(),
            if weft::orient::is_orientable(&mesh) {
                ""
            } else {
                " (the mesh is not orientable: some edges still disagree)"
            }
        );
        unified
    } else {
        weft::orient::flip(&mesh)
    };
    write(&files.output, &flipped, &io::WriteOptions::default())
}

/// Lists the T-nodes, and with `repair` writes them inserted into their edges.
pub fn t_nodes(
    cli: &Cli,
    input: &Path,
    repair: Option<&Path>,
    tolerance: f64,
) -> Result<(), Failure> {
    let mesh = read(cli, input)?;
    let found = with_progress("searching", || {
        weft::t_nodes::find_t_nodes(&mesh, tolerance)
    })
    .map_err(|e| operation_failed(input, "search for T-nodes", e))?;
    println!(
        "{}: {} T-nodes within {tolerance}",
        input.display(),
        found.len()
    );
    for t in &found {
        println!(
            "  vertex {} lies on edge {}-{} of face {} at {:.4} of its length",
            t.vertex, t.edge[0], t.edge[1], t.face, t.parameter
        );
    }
    if let Some(output) = repair {
        let (repaired, inserted) = weft::t_nodes::repair_t_nodes(&mesh, tolerance)
            .map_err(|e| operation_failed(input, "repair T-nodes", e))?;
        eprintln!("inserted {inserted} vertices into edges");
        write(output, &repaired, &io::WriteOptions::default())?;
    }
    Ok(())
}
