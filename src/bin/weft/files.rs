//! Reading and writing mesh files for the commands: STL welding on
//! `--weld`, what an output drops said on stderr, progress on long steps.

use std::io::{BufWriter, Write};
use std::path::Path;

use weft::io::{self, Format, MeshFile, ReadOptions};
use weft::Mesh;

use crate::{progress, Cli, Failure};

pub fn operation_failed(input: &Path, what: &str, error: weft::Error) -> Failure {
    Failure::Failed(format!("{}: cannot {what}: {error}", input.display()))
}

/// Refuses a file without faces (points and curves only, say) for a
/// command that works on faces, before anything is written.
pub fn require_faces(path: &Path, mesh: &Mesh) -> Result<(), Failure> {
    if mesh.face_count() == 0 {
        return Err(Failure::Failed(format!(
            "{}: has no faces ({} vertices and nothing joining them: points or curves only?); \
             nothing to do, nothing written",
            path.display(),
            mesh.vertex_count()
        )));
    }
    Ok(())
}

/// Reads a mesh for a command that does not carry colours, UVs or
/// creases and works on faces: says on stderr what the output will lack.
pub fn read(cli: &Cli, path: &Path) -> Result<Mesh, Failure> {
    let file = read_file_or_mesh(cli, path)?;
    require_faces(path, &file.mesh)?;
    if file.has_attributes() {
        eprintln!(
            "{}: this command keeps only the mesh; its {} are not carried to the output",
            path.display(),
            file.attribute_names().join(", ")
        );
    }
    Ok(file.mesh)
}

/// Reads a mesh that is welded next, as [`read`] does, but a binary STL
/// file with the copies of each position merged while reading (see
/// `io::read_mesh_to_weld`); with the mesh, how many vertices were merged.
pub fn read_to_weld(cli: &Cli, path: &Path) -> Result<(Mesh, usize), Failure> {
    // With --weld the reading welds at tolerance 0 and the mesh is counted
    // as read, as before; the copies are merged while reading all the same.
    if cli.weld || Format::from_path(path).ok() != Some(Format::Stl) {
        return read(cli, path).map(|mesh| (mesh, 0));
    }
    let label = format!("reading {}", path.display());
    let options = read_options(cli, false);
    let read = with_progress(&label, || io::read_mesh_to_weld(path, &options))?;
    require_faces(path, &read.mesh)?;
    Ok((read.mesh, read.merged_copies))
}

/// As [`read_file`], but for a command that can do without colours, UVs
/// and creases: when only those are malformed, says so on stderr and goes
/// on with the mesh alone.
pub fn read_file_or_mesh(cli: &Cli, path: &Path) -> Result<MeshFile, Failure> {
    match read_file(cli, path) {
        Ok(file) => Ok(file),
        Err(Failure::Failed(attribute_problem)) => {
            let weld = cli.weld && Format::from_path(path).ok() == Some(Format::Stl);
            let options = read_options(cli, weld);
            let mesh = io::read_mesh_with(path, &options)
                .map_err(|_| Failure::Failed(attribute_problem.clone()))?;
            eprintln!("weft: {attribute_problem}; reading on with the mesh alone");
            Ok(MeshFile::new(mesh))
        }
    }
}

/// Reads a mesh with its colours, UVs and creases, welding STL corners
/// when `--weld` was given.
pub fn read_file(cli: &Cli, path: &Path) -> Result<MeshFile, Failure> {
    let weld = cli.weld && Format::from_path(path).ok() == Some(Format::Stl);
    read_file_welded(cli, path, weld)
}

/// Reads a mesh with its colours, UVs and creases, merging corners at
/// identical positions when `weld` (what `--weld` does for STL).
pub fn read_file_welded(cli: &Cli, path: &Path, weld: bool) -> Result<MeshFile, Failure> {
    let label = format!("reading {}", path.display());
    let options = read_options(cli, weld);
    let file = with_progress(&label, || io::read_mesh_file(path, &options))?;
    Ok(file)
}

/// The reading options of the command line, welding STL corners when `weld`.
fn read_options(cli: &Cli, weld: bool) -> ReadOptions {
    ReadOptions {
        weld,
        allow_repeated_vertices: cli.allow_repeated_vertices,
    }
}

/// Writes a mesh with what its format holds of its colours, UVs, normals
/// and creases, saying on stderr what it cannot hold.
pub fn write_file(path: &Path, file: &MeshFile, options: &io::WriteOptions) -> Result<(), Failure> {
    let format = Format::from_path(path)?;
    let dropped = file.dropped_by(format);
    if !dropped.is_empty() {
        eprintln!(
            "{}: this format cannot hold the {}; written without them (OBJ keeps them all)",
            path.display(),
            dropped.join(", ")
        );
    }
    let label = format!("writing {}", path.display());
    with_progress(&label, || io::write_mesh_file(path, file, options))?;
    report_written(path, &file.mesh);
    Ok(())
}

pub fn write(path: &Path, mesh: &Mesh, options: &io::WriteOptions) -> Result<(), Failure> {
    let label = format!("writing {}", path.display());
    with_progress(&label, || io::write_mesh_with(path, mesh, options))?;
    report_written(path, mesh);
    Ok(())
}

pub fn report_written(path: &Path, mesh: &Mesh) {
    let note = if Format::from_path(path).ok() == Some(Format::Stl) && !mesh.is_triangle_mesh() {
        " (polygons written as triangle fans)"
    } else {
        ""
    };
    eprintln!(
        "{}: {} vertices, {} faces{note}",
        path.display(),
        mesh.vertex_count(),
        mesh.face_count()
    );
}

/// Says on stderr that no two faces of the mesh read from `path` share an
/// edge, as an STL file's are read, and suggests `--weld`.
pub fn suggest_weld(path: &Path) {
    eprintln!(
        "{}: no two faces share an edge, as in an STL file: add --weld to join the corners first",
        path.display()
    );
}

/// [`suggest_weld`] when the mesh read from `path` without `--weld` has
/// faces whose corners name no vertex twice (an STL file as stored): a
/// command that looks for shared edges or vertices finds none there.
pub fn suggest_weld_if_apart(cli: &Cli, path: &Path, mesh: &Mesh) {
    if !cli.weld && mesh.face_count() > 1 && mesh.corners_share_no_vertex() {
        suggest_weld(path);
    }
}

/// Runs `work`; when it takes longer than half a second and stderr is a
/// terminal, shows `label` and the time spent until it ends.
pub fn with_progress<T>(label: &str, work: impl FnOnce() -> T) -> T {
    progress::with_spinner(label, work)
}

/// Writes a listing to standard output through one buffer: a line each
/// would be a write each. A closed pipe (`| head`) is a failure named as
/// such, not a panic.
pub fn write_stdout(
    write: impl FnOnce(&mut dyn Write) -> std::io::Result<()>,
) -> Result<(), Failure> {
    let stdout = std::io::stdout();
    let mut out = BufWriter::new(stdout.lock());
    write(&mut out)
        .and_then(|()| out.flush())
        .map_err(|e| Failure::Failed(format!("cannot write to standard output: {e}")))
}
