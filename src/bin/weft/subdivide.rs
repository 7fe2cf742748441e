//! `weft subdivide`: Catmull-Clark or Loop on a mesh file, with its creases,
//! corners, vertex colours and UVs carried, and the limit surface on request.

use std::path::{Path, PathBuf};

use weft::io::{self, MeshFile};
use weft::subdivide::{self, NakedEdges, Scheme, SubdivisionOptions};

use crate::args::{
    angle, CreasingArg, InOut, SchemeArg, SubdivisionNakedEdgesArg, TrianglesArg, UvLinearArg,
};
use crate::files::{
    operation_failed, read_file, read_file_welded, require_faces, with_progress, write_file,
};
use crate::{carry, Cli, Failure};

/// The arguments of `weft subdivide`.
#[derive(clap::Args)]
pub struct Subdivide {
    #[command(flatten)]
    pub files: InOut,
    #[command(flatten)]
    pub cage: Cage,
    /// How many times to subdivide (0 copies the mesh).
    #[arg(long, default_value_t = 1)]
    pub levels: u32,
    /// Where UVs are interpolated linearly (OpenSubdiv's options; all is
    /// OpenSubdiv's default and keeps a texture's layout).
    #[arg(long, value_enum, default_value = "all")]
    pub uv_linear: UvLinearArg,
    /// Move the result onto the limit surface and write its normals
    /// (OBJ `vn`, PLY nx ny nz).
    #[arg(long)]
    pub limit: bool,
}

/// How a cage is read and subdivided: what `subdivide` and `nurbs` share.
#[derive(clap::Args)]
pub struct Cage {
    /// The subdivision scheme.
    #[arg(long, value_enum, default_value = "catmull-clark")]
    pub scheme: SchemeArg,
    /// What happens along naked edges: fixed keeps the boundary polyline,
    /// smooth makes it a B-spline, corner-fixed is smooth but keeps corners;
    /// none (OpenSubdiv's, beyond Weaverbird's three) leaves every face at
    /// the boundary out as a hole and refines the rest as smooth.
    #[arg(long, value_enum, default_value = "fixed")]
    pub naked_edges: SubdivisionNakedEdgesArg,
    /// Catmull-Clark's weights at triangles: catmark, or OpenSubdiv's
    /// smooth-triangle weights, which round triangle regions of mixed cages.
    #[arg(long, value_enum, default_value = "catmark")]
    pub triangles: TrianglesArg,
    /// A face (0-based) to leave out of the result, as OBJ `t hole` tags
    /// do; its vertices and edges still shape its neighbours. Repeatable.
    #[arg(long = "hole", value_name = "FACE")]
    pub holes: Vec<u32>,
    /// A crease side file (format below) with creases and corners to add.
    #[arg(long, value_name = "FILE")]
    pub creases: Option<PathBuf>,
    /// Weld vertices at identical positions and make hard creases of the
    /// seams that were unwelded and of edges whose faces fold more than
    /// this many degrees (180 creases only the seams).
    #[arg(long, value_name = "DEG", value_parser = angle)]
    pub crease_angle: Option<f64>,
    /// How semi-sharp creases soften: uniform takes one level off each
    /// edge, chaikin also averages sharpness along a crease.
    #[arg(long, value_enum, default_value = "uniform")]
    pub creasing: CreasingArg,
}

pub fn run(cli: &Cli, args: &Subdivide) -> Result<(), Failure> {
    let Subdivide {
        files,
        cage,
        levels,
        uv_linear,
        limit,
    } = args;
    let (file, options) = read_cage(cli, &files.input, cage)?;
    let scheme = Scheme::from(cage.scheme);
    let naked_edges = options.naked_edges;
    let carry = carry::Carry {
        scheme,
        levels: *levels,
        options,
        uv_linear: (*uv_linear).into(),
        limit: *limit,
    };
    let refined = if carry::is_plain(&file, &carry) {
        with_progress("subdividing", || {
            subdivide::subdivide(&file.mesh, scheme, *levels, naked_edges)
        })
        .map(MeshFile::new)
    } else {
        with_progress("subdividing", || carry::subdivide(&file, &carry))
    }
    .map_err(|e| operation_failed(&files.input, "subdivide", e))?;
    if refined.mesh.face_count() == 0 {
        // Holes everywhere: an empty file would pass for a result.
        let why = match naked_edges {
            NakedEdges::None => {
                "with --naked-edges none every face touching a naked edge is a hole"
            }
            _ => "every face is a hole",
        };
        return Err(Failure::Failed(format!(
            "{}: subdivision left no face: {why}; nothing written",
            files.input.display()
        )));
    }
    write_file(&files.output, &refined, &io::WriteOptions::default())
}

/// Reads a cage as `cage` says: holes checked and added, the side file's
/// creases, the crease angle's weld and creases, triangles for Loop; gives
/// the file and the options of its naked edges, creasing and triangles (the
/// file's creases, corners and holes stay in the file).
pub fn read_cage(
    cli: &Cli,
    input: &Path,
    cage: &Cage,
) -> Result<(MeshFile, SubdivisionOptions), Failure> {
    let Cage {
        scheme,
        naked_edges,
        triangles,
        holes,
        creases,
        crease_angle,
        creasing,
    } = cage;
    let mut file = read_file(cli, input)?;
    require_faces(input, &file.mesh)?;
    if crease_angle.is_some()
        && !file.has_attributes()
        && file.mesh.face_count() > 1
        && file.mesh.corners_share_no_vertex()
    {
        // Every corner its own vertex (STL, an unwelded OBJ): every edge
        // would be a seam, and so a crease. Joined first, as --weld does.
        let before = file.mesh.vertex_count();
        file = read_file_welded(cli, input, true)?;
        eprintln!(
            "{}: no two faces share a vertex, as the format stores them: welded {} corners at identical positions first (as --weld), so that only folds crease",
            input.display(),
            before - file.mesh.vertex_count()
        );
    }
    // After any re-read above, which keeps the faces in their order.
    if let Some(&face) = holes
        .iter()
        .find(|&&f| f as usize >= file.mesh.face_count())
    {
        return Err(Failure::Failed(format!(
            "--hole {face}: {} has {} faces (0 to {})",
            input.display(),
            file.mesh.face_count(),
            file.mesh.face_count() - 1
        )));
    }
    file.holes.extend(holes);
    file.holes.sort_unstable();
    file.holes.dedup();
    file.check_creases().map_err(|e| e.in_file(input))?;
    let info = weft::Topology::try_new(&file.mesh)
        .map_err(|e| operation_failed(input, "read the topology of", e))?
        .info(&file.mesh);
    if info.is_orientable && !info.is_oriented {
        eprintln!(
            "{}: warning: neighbouring faces disagree on their orientation, which subdivision reads as creases; `weft flip {} FIXED.obj --unify` makes it consistent",
            input.display(),
            input.display()
        );
    }
    if let Some(side) = creases {
        let side_file = io::creases::read(side)?;
        io::check_creases(&file.mesh, &side_file.creases, &side_file.corners)
            .map_err(|e| e.in_file(side))?;
        eprintln!(
            "{}: {} creases and {} corners",
            side.display(),
            side_file.creases.len(),
            side_file.corners.len()
        );
        file.creases.extend(side_file.creases);
        file.corners.extend(side_file.corners);
    }
    if let Some(angle) = crease_angle {
        let before = file.mesh.vertex_count();
        let (welded, found) = carry::crease_by_angle(&file, *angle)
            .map_err(|e| operation_failed(input, "find creases", e))?;
        file = welded;
        eprintln!(
            "{}: welded {} vertices at identical positions; {found} edges creased (unwelded seams and folds over {angle}°)",
            input.display(),
            before - file.mesh.vertex_count()
        );
    }
    if Scheme::from(*scheme) == Scheme::Loop {
        let before = file.mesh.face_count();
        let split;
        (file, split) =
            carry::as_triangles(&file).map_err(|e| operation_failed(input, "triangulate", e))?;
        if split > 0 {
            eprintln!(
                "{}: Loop needs triangles: triangulated {split} of {before} faces into {} triangles",
                input.display(),
                file.mesh.face_count()
            );
        }
    }
    let options = SubdivisionOptions {
        naked_edges: NakedEdges::from(*naked_edges),
        creasing: (*creasing).into(),
        triangles: (*triangles).into(),
        ..SubdivisionOptions::default()
    };
    Ok((file, options))
}
