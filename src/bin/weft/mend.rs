//! The mending commands: `weld` (join and weld), `cull-adjacent`, `flip`
//! and `t-nodes`.

use std::path::{Path, PathBuf};

use weft::io;
use weft::Mesh;

use crate::args::InOut;
use crate::files::{
    operation_failed, read, read_to_weld, suggest_weld, suggest_weld_if_apart, with_progress,
    write, write_stdout,
};
use crate::{Cli, Failure};

/// Faces whose sides give the median edge length of the hint.
const EDGE_SAMPLES: usize = 100_000;

/// Joins the inputs and merges vertices at most `tolerance` apart (by
/// default relative to the mesh's size); refuses, writing nothing, when
/// faces would collapse, unless `allow_collapse`.
pub fn weld(
    cli: &Cli,
    inputs: &[PathBuf],
    output: &Path,
    tolerance: Option<f64>,
    allow_collapse: bool,
) -> Result<(), Failure> {
    let (mut meshes, mut merged_copies) = (Vec::with_capacity(inputs.len()), 0);
    for path in inputs {
        let (mesh, merged) = read_to_weld(cli, path)?;
        meshes.push(mesh);
        merged_copies += merged;
    }
    // One input is its own join: no copy of it.
    let joined = if meshes.len() == 1 {
        meshes.pop().unwrap_or_default()
    } else {
        let parts: Vec<&Mesh> = meshes.iter().collect();
        weft::mend::weld::join(&parts)
            .map_err(|e| Failure::Failed(format!("cannot join the inputs: {e}")))?
    };
    let input_count = inputs.len();
    let tolerance = tolerance.unwrap_or_else(|| weft::mend::weld::relative_tolerance(&joined));
    // The vertices of the files, copies merged while reading included.
    let (vertex_count, face_count) = (joined.vertex_count() + merged_copies, joined.face_count());
    // Read before the weld takes the mesh: the hint if faces would collapse.
    let edge_length = weft::mesh::analysis::median_edge_length_sampled(&joined, EDGE_SAMPLES);
    let (welded, report) = with_progress("welding", || {
        weft::mend::weld::weld_owned(joined, tolerance)
    })
    .map_err(|e| Failure::Failed(format!("cannot weld the inputs: {e}")))?;
    if report.removed_face_count > 0 && !allow_collapse {
        return Err(Failure::Failed(format!(
            "welding at tolerance {tolerance} would collapse {} of {face_count} faces (the median \
             edge is about {edge_length:.6} long); nothing was written. Give a smaller \
             --tolerance, or --allow-collapse to remove them",
            report.removed_face_count,
        )));
    }
    eprintln!(
        "joined {} meshes ({} vertices, {} faces); welded at tolerance {tolerance}: merged {} vertices, removed {} collapsed faces and {} unused vertices",
        input_count,
        vertex_count,
        face_count,
        report.merged_vertex_count + merged_copies,
        report.removed_face_count,
        report.unused_vertex_count
    );
    write(output, &welded, &io::WriteOptions::default())
}

/// Removes every face that has a twin.
pub fn cull_adjacent(cli: &Cli, files: &InOut) -> Result<(), Failure> {
    let mesh = read(cli, &files.input)?;
    suggest_weld_if_apart(cli, &files.input, &mesh);
    let faces = mesh.face_count();
    let (culled, removed) =
        with_progress("culling", || weft::mend::cull::cull_adjacent_owned(mesh));
    // The culled faces' vertices go with them; bare vertices of the input too.
    let (culled, unused) = weft::mend::weld::remove_unused_vertices_owned(culled);
    eprintln!(
        "{}: removed {removed} of {faces} faces that had a twin, and {unused} vertices no face uses",
        files.input.display(),
    );
    write(&files.output, &culled, &io::WriteOptions::default())
}

/// Flips every face, or with `unify` the fewest for one orientation.
pub fn flip(cli: &Cli, files: &InOut, unify: bool, outward: bool) -> Result<(), Failure> {
    let mesh = read(cli, &files.input)?;
    if !(unify || outward) {
        let flipped = weft::mend::orient::flip_owned(mesh);
        return write(&files.output, &flipped, &io::WriteOptions::default());
    }
    // Unifying turns closed pieces outward too: both are `orient_outward`,
    // whose report says what each piece was.
    let label = if outward { "orienting" } else { "unifying" };
    let (input, faces) = (files.input.display(), mesh.face_count());
    let (oriented, report) =
        with_progress(label, || weft::mend::orient::orient_outward_owned(mesh));
    if outward {
        eprintln!(
            "{input}: {} pieces: turned {} closed ones outward, {} open (unified only), {} not orientable; flipped {} of {faces} faces",
            report.pieces,
            report.turned_outward,
            report.open_pieces,
            report.non_orientable_pieces,
            report.flipped_faces,
        );
    } else {
        eprintln!(
            "{input}: flipped {} of {faces} faces to unify the orientation{}",
            report.flipped_faces,
            if report.non_orientable_pieces == 0 {
                ""
            } else {
                " (the mesh is not orientable: some edges still disagree)"
            }
        );
    }
    // Every face an open piece of its own: no two faces share an edge.
    if report.open_pieces == faces && faces > 1 {
        suggest_weld(&files.input);
    }
    write(&files.output, &oriented, &io::WriteOptions::default())
}

/// Lists the T-nodes, and with `repair` writes them inserted into their edges.
pub fn t_nodes(
    cli: &Cli,
    input: &Path,
    repair: Option<&Path>,
    tolerance: Option<f64>,
) -> Result<(), Failure> {
    let mesh = read(cli, input)?;
    suggest_weld_if_apart(cli, input, &mesh);
    let tolerance = tolerance.unwrap_or_else(|| weft::mend::weld::relative_tolerance(&mesh));
    // With --repair, one search gives both the list and the repaired mesh.
    let (found, repaired) = match repair {
        Some(_) => {
            let repair = with_progress("searching", || {
                weft::mend::t_nodes::repair_t_nodes_owned(mesh, tolerance)
            })
            .map_err(|e| operation_failed(input, "repair T-nodes", e))?;
            (repair.t_nodes, Some((repair.mesh, repair.inserted)))
        }
        None => (
            with_progress("searching", || {
                weft::mend::t_nodes::find_t_nodes(&mesh, tolerance)
            })
            .map_err(|e| operation_failed(input, "search for T-nodes", e))?,
            None,
        ),
    };
    write_stdout(|out| {
        writeln!(
            out,
            "{}: {} T-nodes within {tolerance}",
            input.display(),
            found.len()
        )?;
        for t in &found {
            writeln!(
                out,
                "  vertex {} lies on edge {}-{} of face {} at {} of its length",
                t.vertex,
                t.edge[0],
                t.edge[1],
                t.face,
                FourDecimals(t.parameter)
            )?;
        }
        Ok(())
    })?;
    if let (Some(output), Some((repaired, inserted))) = (repair, repaired) {
        eprintln!("inserted {inserted} vertices into edges");
        write(output, &repaired, &io::WriteOptions::default())?;
    }
    Ok(())
}

/// A number from 0 to 1 to four decimals, as `{:.4}` writes it. That
/// rounds the number's exact value, ties to even, at several times the
/// cost of this listing's other fields; here the product with 10^4 is
/// rounded instead, and `{:.4}` is left the numbers near a tie.
struct FourDecimals(f64);

impl std::fmt::Display for FourDecimals {
    fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        let scaled = self.0 * 10_000.0;
        // The product is within 10^-12 of the exact one below 10^4.
        let near_tie = (scaled - scaled.floor() - 0.5).abs() < 1e-6;
        if !(0.0..=10_000.0).contains(&scaled) || near_tie {
            return write!(f, "{:.4}", self.0);
        }
        let ten_thousandths = scaled.round() as u32;
        write!(
            f,
            "{}.{:04}",
            ten_thousandths / 10_000,
            ten_thousandths % 10_000
        )
    }
}

#[cfg(test)]
mod tests {
    use super::FourDecimals;

    proptest::proptest! {
        #[test]
        fn four_decimals_are_those_of_the_standard_format(
            t in 0.0f64..=1.0,
            tie in 0u32..20_000,
            ulps in -3i64..=3,
        ) {
            // Ties and their neighbours: (2k + 1) / 20000, exact where 5^4
            // divides 2k + 1.
            let tie = (2 * tie + 1) as f64 / 20_000.0;
            let near_tie = f64::from_bits(tie.to_bits().wrapping_add_signed(ulps));
            for x in [t, near_tie, 0.03125, 0.09375, 0.0, 1.0, 0.99995, 0.00005] {
                proptest::prop_assert_eq!(FourDecimals(x).to_string(), format!("{x:.4}"));
            }
        }
    }
}
