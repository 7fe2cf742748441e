//! The `weft` command: mesh files in and out, pictures, and Weft's operations.
//!
//! Exit codes: 0 success, 1 a failed operation (unreadable or malformed
//! input, an output that cannot be written), 2 bad usage (clap's own code).

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use clap::{Parser, Subcommand, ValueEnum};

#[path = "weft/carry.rs"]
mod carry;
#[path = "weft/demo.rs"]
mod demo;
#[path = "weft/progress.rs"]
mod progress;
#[path = "weft/toolbar.rs"]
mod toolbar;

use weft::io::render::{self, RenderOptions};
use weft::io::{self, Format, IoError, MeshFile, ReadOptions};
use weft::subdivide::{self, Creasing, FaceVaryingLinear, NakedEdges, Scheme, SubdivisionOptions};
use weft::{Mesh, Topology};

#[derive(Parser)]
#[command(
    name = "weft",
    version,
    about = "Subdivision surfaces and mesh mending on mesh files (OBJ, PLY, STL, OFF)",
    after_help = "Examples:\n  weft info part.obj\n  weft render part.obj part.png --size 1024x768\n  weft convert scan.stl scan.ply --weld"
)]
struct Cli {
    /// Merge the corners of STL triangles that sit at identical positions
    /// when reading (STL stores every triangle's corners separately).
    #[arg(long, global = true)]
    weld: bool,
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Counts, naked and non-manifold edges, components, closedness,
    /// orientation and the bounding box of a mesh.
    #[command(after_help = "Example:\n  weft info part.obj\n  weft info part.obj --json")]
    Info {
        /// The mesh file (.obj, .ply, .stl, .off).
        #[arg(value_parser = mesh_path)]
        input: PathBuf,
        /// Print one JSON object instead of text.
        #[arg(long)]
        json: bool,
        /// Distance from its best-fit plane under which a face counts as planar.
        #[arg(long, default_value_t = weft::mend::weld::DEFAULT_WELD_TOLERANCE, value_parser = tolerance)]
        planarity_tolerance: f64,
    },
    /// A shaded picture: front faces blue-grey (or in the file's vertex
    /// colours), back faces orange, edges drawn on coarse meshes, camera
    /// fitted in a three-quarter view.
    #[command(after_help = "Example:\n  weft render part.obj part.png --size 1024x768")]
    Render {
        /// The mesh file (.obj, .ply, .stl, .off).
        #[arg(value_parser = mesh_path)]
        input: PathBuf,
        /// The picture to write (.png).
        #[arg(value_parser = png_path)]
        output: PathBuf,
        /// Picture size in pixels, WIDTHxHEIGHT.
        #[arg(long, default_value = "800x600", value_parser = picture_size)]
        size: (u32, u32),
        /// Draw face edges always, or never (default: when the mesh has fewer than 4000 faces).
        #[arg(long, value_parser = ["always", "never", "auto"], default_value = "auto")]
        edges: String,
    },
    /// Subdivides a mesh: Catmull-Clark (any polygons, quads out) or Loop
    /// (triangles; other polygons are triangulated first), with creases and
    /// corners, carrying vertex colours and UVs.
    ///
    /// Creases come from three places, all used together: an OBJ input's
    /// `l` polylines (every segment a hard crease) and OpenSubdiv tags
    /// (`t crease 2/1/0 i j sharpness`, `t corner 1/1/0 v sharpness`, 0-based);
    /// a side file given with --creases; and --crease-angle. Vertex colours
    /// (OBJ `v x y z r g b`, PLY red green blue [alpha]) are interpolated like
    /// positions; UVs (OBJ `vt` with `f v/vt`, PLY per-vertex s t) face-varying.
    #[command(
        after_help = "Crease side file (--creases): one statement per line, vertex indices from 0 \
in the mesh file's vertex order, # starts a comment:\n  \
i j sharpness         the edge from vertex i to vertex j\n  \
crease i j sharpness  the same\n  \
corner v sharpness    vertex v\n\
A sharpness is a number of 0 or more (levels during which the crease stays sharp, then \
softens) or inf (10 or more): a hard crease, a corner that does not move. \
More in docs/creases.md.\n\n\
Examples:\n  weft subdivide cage.obj smooth.obj --scheme catmull-clark --levels 2 --naked-edges fixed\n  \
weft subdivide tri.ply tri3.ply --scheme loop --levels 3 --naked-edges corner-fixed\n  \
weft subdivide block.ply block3.obj --levels 3 --creases block-creases.txt --limit\n  \
weft subdivide scan.obj smooth.obj --levels 2 --crease-angle 60 --creasing chaikin"
    )]
    Subdivide {
        /// The mesh file to read (.obj, .ply, .stl, .off).
        #[arg(value_parser = mesh_path)]
        input: PathBuf,
        /// The mesh file to write (.obj, .ply, .stl, .off).
        #[arg(value_parser = mesh_path)]
        output: PathBuf,
        /// The subdivision scheme.
        #[arg(long, value_enum, default_value = "catmull-clark")]
        scheme: SchemeArg,
        /// How many times to subdivide (0 copies the mesh).
        #[arg(long, default_value_t = 1)]
        levels: u32,
        /// What happens along naked edges: fixed keeps the boundary polyline,
        /// smooth makes it a B-spline, corner-fixed is smooth but keeps corners.
        #[arg(long, value_enum, default_value = "fixed")]
        naked_edges: NakedEdgesArg,
        /// A crease side file (format below) with creases and corners to add.
        #[arg(long, value_name = "FILE")]
        creases: Option<PathBuf>,
        /// Weld vertices at identical positions and make hard creases of the
        /// seams that were unwelded and of edges whose faces fold more than
        /// this many degrees (180 creases only the seams).
        #[arg(long, value_name = "DEG", value_parser = angle)]
        crease_angle: Option<f64>,
        /// How semi-sharp creases soften: uniform takes one level off each
        /// edge, chaikin also averages sharpness along a crease.
        #[arg(long, value_enum, default_value = "uniform")]
        creasing: CreasingArg,
        /// Where UVs are interpolated linearly (OpenSubdiv's options; all is
        /// OpenSubdiv's default and keeps a texture's layout).
        #[arg(long, value_enum, default_value = "all")]
        uv_linear: UvLinearArg,
        /// Move the result onto the limit surface and write its normals
        /// (OBJ `vn`, PLY nx ny nz).
        #[arg(long)]
        limit: bool,
    },
    /// Joins meshes into one and merges vertices closer than the tolerance;
    /// faces that collapse are removed and counted.
    #[command(
        after_help = "Example:\n  weft weld panel-a.obj panel-b.obj panel-c.obj -o joined.obj --tolerance 0.01"
    )]
    Weld {
        /// The mesh files to join (.obj, .ply, .stl, .off).
        #[arg(required = true, value_parser = mesh_path)]
        inputs: Vec<PathBuf>,
        /// The mesh file to write (.obj, .ply, .stl, .off).
        #[arg(short, long, value_parser = mesh_path)]
        output: PathBuf,
        /// Vertices at most this far apart become one.
        #[arg(long, default_value_t = weft::mend::weld::DEFAULT_WELD_TOLERANCE, value_parser = tolerance)]
        tolerance: f64,
    },
    /// Removes every face that has a twin with the same vertices (either
    /// orientation), all copies: the walls inside joined boxes.
    #[command(
        name = "cull-adjacent",
        after_help = "Example:\n  weft weld boxes.obj -o welded.obj\n  weft cull-adjacent welded.obj hull.obj"
    )]
    CullAdjacent {
        /// The mesh file to read (.obj, .ply, .stl, .off).
        #[arg(value_parser = mesh_path)]
        input: PathBuf,
        /// The mesh file to write (.obj, .ply, .stl, .off).
        #[arg(value_parser = mesh_path)]
        output: PathBuf,
    },
    /// Reverses every face, or with --unify only the fewest faces that give
    /// each connected piece one consistent orientation.
    #[command(
        after_help = "Examples:\n  weft flip shell.obj shell-flipped.obj\n  weft flip joined.obj unified.obj --unify"
    )]
    Flip {
        /// The mesh file to read (.obj, .ply, .stl, .off).
        #[arg(value_parser = mesh_path)]
        input: PathBuf,
        /// The mesh file to write (.obj, .ply, .stl, .off).
        #[arg(value_parser = mesh_path)]
        output: PathBuf,
        /// Make the orientation consistent instead of flipping everything.
        #[arg(long)]
        unify: bool,
    },
    /// Lists the T-nodes (vertices lying inside another face's naked edge),
    /// and with --repair inserts each into its edge.
    #[command(
        name = "t-nodes",
        after_help = "Example:\n  weft t-nodes joined.obj --repair repaired.obj --tolerance 0.001"
    )]
    TNodes {
        /// The mesh file to read (.obj, .ply, .stl, .off).
        #[arg(value_parser = mesh_path)]
        input: PathBuf,
        /// Write the mesh with every T-node inserted into its edge here.
        #[arg(long, value_parser = mesh_path)]
        repair: Option<PathBuf>,
        /// How close to an edge a vertex must be.
        #[arg(long, default_value_t = weft::mend::weld::DEFAULT_WELD_TOLERANCE, value_parser = tolerance)]
        tolerance: f64,
    },
    /// Runs the design workflows on built-in inputs: each stage as a mesh
    /// file and a picture, a summary line each, and an index.html.
    ///
    /// When stderr is a terminal and the run takes more than half a second,
    /// a bar there shows which workflow of how many is running, and its stage.
    #[command(
        after_help = "Examples:\n  weft demo --out weft-demo\n  weft demo --only fading --image heights.png --out fading"
    )]
    Demo {
        /// The folder to write into (created when missing).
        #[arg(long, default_value = "weft-demo")]
        out: PathBuf,
        /// A picture for the fading pattern's pyramid heights: black low,
        /// white high, stretched over the panels. Any PNG: colour is read as
        /// its luminance (0.2126 R + 0.7152 G + 0.0722 B), transparency is
        /// ignored, 16-bit samples are rounded to 8 (default: a built-in
        /// gradient).
        #[arg(long, value_parser = png_path)]
        image: Option<PathBuf>,
        /// Run only these workflows (comma-separated; default: all).
        #[arg(long, value_enum, value_delimiter = ',')]
        only: Vec<demo::Workflow>,
    },
    /// Splits every face into triangles (quads along the shorter diagonal,
    /// n-gons by ear clipping); vertices stay as they are.
    #[command(after_help = "Example:\n  weft triangulate panels.obj panels-triangles.obj")]
    Triangulate {
        /// The mesh file to read (.obj, .ply, .stl, .off).
        #[arg(value_parser = mesh_path)]
        input: PathBuf,
        /// The mesh file to write (.obj, .ply, .stl, .off).
        #[arg(value_parser = mesh_path)]
        output: PathBuf,
    },
    /// Converts a mesh file; formats follow the extensions.
    #[command(
        after_help = "Example:\n  weft convert part.obj part.ply\n  weft convert scan.stl scan.obj --weld"
    )]
    Convert {
        /// The mesh file to read (.obj, .ply, .stl, .off).
        #[arg(value_parser = mesh_path)]
        input: PathBuf,
        /// The mesh file to write (.obj, .ply, .stl, .off).
        #[arg(value_parser = mesh_path)]
        output: PathBuf,
        /// Write PLY and STL as text instead of binary.
        #[arg(long)]
        ascii: bool,
        /// Write PLY as big-endian binary.
        #[arg(long, conflicts_with = "ascii")]
        big_endian: bool,
    },
    #[command(flatten)]
    Toolbar(toolbar::ToolbarCommand),
}

#[derive(Clone, Copy, ValueEnum)]
enum SchemeArg {
    CatmullClark,
    Loop,
}

#[derive(Clone, Copy, ValueEnum)]
enum CreasingArg {
    Uniform,
    Chaikin,
}

#[derive(Clone, Copy, ValueEnum)]
enum UvLinearArg {
    None,
    CornersOnly,
    #[value(name = "corners-plus1")]
    CornersPlus1,
    #[value(name = "corners-plus2")]
    CornersPlus2,
    Boundaries,
    All,
}

fn angle(text: &str) -> Result<f64, String> {
    text.parse::<f64>()
        .ok()
        .filter(|a| a.is_finite() && *a >= 0.0)
        .ok_or_else(|| "expected an angle in degrees, 0 or more, such as 60".to_string())
}

#[derive(Clone, Copy, ValueEnum)]
enum NakedEdgesArg {
    Fixed,
    Smooth,
    CornerFixed,
}

/// A mesh file argument: its extension must name a format.
fn mesh_path(text: &str) -> Result<PathBuf, String> {
    let path = PathBuf::from(text);
    Format::from_path(&path)
        .map(|_| path)
        .map_err(|_| "expected a mesh file ending in .obj, .ply, .stl or .off".to_string())
}

fn tolerance(text: &str) -> Result<f64, String> {
    text.parse::<f64>()
        .ok()
        .filter(|t| t.is_finite() && *t >= 0.0)
        .ok_or_else(|| "expected a distance of 0 or more, such as 0.001".to_string())
}

fn png_path(text: &str) -> Result<PathBuf, String> {
    let path = PathBuf::from(text);
    match path.extension().and_then(|e| e.to_str()) {
        Some(e) if e.eq_ignore_ascii_case("png") => Ok(path),
        _ => Err("expected a picture file ending in .png".to_string()),
    }
}

fn picture_size(text: &str) -> Result<(u32, u32), String> {
    let bad = || {
        format!(
            "expected WIDTHxHEIGHT with each side from 1 to {}, such as 800x600",
            render::MAX_SIDE
        )
    };
    let (w, h) = text.split_once(['x', 'X']).ok_or_else(bad)?;
    let side = |s: &str| {
        s.trim()
            .parse::<u32>()
            .ok()
            .filter(|&n| (1..=render::MAX_SIDE).contains(&n))
            .ok_or_else(bad)
    };
    Ok((side(w)?, side(h)?))
}

/// Why a command failed; each maps to an exit code.
enum Failure {
    /// Exit 1: the operation could not be done.
    Failed(String),
}

impl From<IoError> for Failure {
    fn from(e: IoError) -> Failure {
        Failure::Failed(e.to_string())
    }
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    match run(&cli) {
        Ok(()) => ExitCode::SUCCESS,
        Err(Failure::Failed(message)) => {
            eprintln!("weft: error: {message}");
            ExitCode::from(1)
        }
    }
}

impl Command {
    /// The files the command writes.
    fn outputs(&self) -> Vec<&Path> {
        match self {
            Command::Render { output, .. }
            | Command::Subdivide { output, .. }
            | Command::Weld { output, .. }
            | Command::CullAdjacent { output, .. }
            | Command::Flip { output, .. }
            | Command::Triangulate { output, .. }
            | Command::Convert { output, .. } => vec![output.as_path()],
            Command::TNodes { repair, .. } => repair.iter().map(PathBuf::as_path).collect(),
            // The demo creates its folder, and says so when it cannot.
            Command::Info { .. } | Command::Demo { .. } => Vec::new(),
            Command::Toolbar(command) => command.outputs(),
        }
    }
}

/// Fails before any work is done when an output's folder does not exist,
/// with the message writing it would give.
fn check_output_folders(command: &Command) -> Result<(), Failure> {
    for path in command.outputs() {
        let folder = match path.parent() {
            Some(p) if !p.as_os_str().is_empty() => p,
            _ => Path::new("."),
        };
        if !folder.is_dir() {
            return Err(IoError::MissingFolder {
                path: path.to_path_buf(),
                folder: folder.to_path_buf(),
            }
            .into());
        }
    }
    Ok(())
}

fn run(cli: &Cli) -> Result<(), Failure> {
    check_output_folders(&cli.command)?;
    match &cli.command {
        Command::Info {
            input,
            json,
            planarity_tolerance,
        } => {
            let file = read_file_or_mesh(cli, input)?;
            let mesh = &file.mesh;
            let mut report = with_progress("analysing", || describe(mesh, *planarity_tolerance));
            report.attributes = file.attribute_names();
            if *json {
                println!("{}", report.json(input));
            } else {
                print!("{}", report.text(input));
            }
            Ok(())
        }
        Command::Render {
            input,
            output,
            size,
            edges,
        } => {
            let file = read_file_or_mesh(cli, input)?;
            let mesh = &file.mesh;
            let options = RenderOptions {
                width: size.0,
                height: size.1,
                edges: match edges.as_str() {
                    "always" => Some(true),
                    "never" => Some(false),
                    _ => None,
                },
            };
            let image = with_progress("rendering", || match &file.colours {
                Some(colours) => render::render_coloured(mesh, &options, &colours.rgba),
                None => render::render(mesh, &options),
            })
            .map_err(|e| Failure::Failed(format!("{}: cannot render: {e}", input.display())))?;
            image.save_png(output)?;
            eprintln!(
                "{}: {} × {} picture of {} faces",
                output.display(),
                size.0,
                size.1,
                mesh.face_count()
            );
            Ok(())
        }
        Command::Subdivide {
            input,
            output,
            scheme,
            levels,
            naked_edges,
            creases,
            crease_angle,
            creasing,
            uv_linear,
            limit,
        } => {
            let mut file = read_file(cli, input)?;
            file.check_creases().map_err(|e| e.in_file(input))?;
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
            let scheme = match scheme {
                SchemeArg::CatmullClark => Scheme::CatmullClark,
                SchemeArg::Loop => Scheme::Loop,
            };
            let naked_edges = match naked_edges {
                NakedEdgesArg::Fixed => NakedEdges::Fixed,
                NakedEdgesArg::Smooth => NakedEdges::Smooth,
                NakedEdgesArg::CornerFixed => NakedEdges::CornerFixed,
            };
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
            if scheme == Scheme::Loop {
                if let Some((face, size)) = file.mesh.first_non_triangle() {
                    let before = file.mesh.face_count();
                    file = carry::triangulate(&file)
                        .map_err(|e| operation_failed(input, "triangulate", e))?;
                    eprintln!(
                        "{}: Loop needs triangles (face {face} has {size} corners): triangulated {before} faces into {}",
                        input.display(),
                        file.mesh.face_count()
                    );
                }
            }
            let carry = carry::Carry {
                scheme,
                levels: *levels,
                options: SubdivisionOptions {
                    naked_edges,
                    creasing: match creasing {
                        CreasingArg::Uniform => Creasing::Uniform,
                        CreasingArg::Chaikin => Creasing::Chaikin,
                    },
                    ..SubdivisionOptions::default()
                },
                uv_linear: match uv_linear {
                    UvLinearArg::None => FaceVaryingLinear::Smooth,
                    UvLinearArg::CornersOnly => FaceVaryingLinear::CornersOnly,
                    UvLinearArg::CornersPlus1 => FaceVaryingLinear::CornersPlus1,
                    UvLinearArg::CornersPlus2 => FaceVaryingLinear::CornersPlus2,
                    UvLinearArg::Boundaries => FaceVaryingLinear::Boundaries,
                    UvLinearArg::All => FaceVaryingLinear::All,
                },
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
            .map_err(|e| operation_failed(input, "subdivide", e))?;
            write_file(output, &refined, &io::WriteOptions::default())
        }
        Command::Weld {
            inputs,
            output,
            tolerance,
        } => {
            let meshes = inputs
                .iter()
                .map(|path| read(cli, path))
                .collect::<Result<Vec<_>, _>>()?;
            let parts: Vec<&Mesh> = meshes.iter().collect();
            let joined = weft::mend::weld::join(&parts)
                .map_err(|e| Failure::Failed(format!("cannot join the inputs: {e}")))?;
            let (welded, report) =
                with_progress("welding", || weft::mend::weld::weld(&joined, *tolerance))
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
        Command::CullAdjacent { input, output } => {
            let mesh = read(cli, input)?;
            let (culled, removed) =
                with_progress("culling", || weft::mend::cull::cull_adjacent(&mesh));
            eprintln!(
                "{}: removed {removed} of {} faces that had a twin",
                input.display(),
                mesh.face_count()
            );
            write(output, &culled, &io::WriteOptions::default())
        }
        Command::Flip {
            input,
            output,
            unify,
        } => {
            let mesh = read(cli, input)?;
            let flipped = if *unify {
                let (unified, count) =
                    with_progress("unifying", || weft::mend::orient::unify_orientation(&mesh));
                eprintln!(
                    "{}: flipped {count} of {} faces to unify the orientation{}",
                    input.display(),
                    mesh.face_count(),
                    if weft::mend::orient::is_orientable(&mesh) {
                        ""
                    } else {
                        " (the mesh is not orientable: some edges still disagree)"
                    }
                );
                unified
            } else {
                weft::mend::orient::flip(&mesh)
            };
            write(output, &flipped, &io::WriteOptions::default())
        }
        Command::TNodes {
            input,
            repair,
            tolerance,
        } => {
            let mesh = read(cli, input)?;
            let found = with_progress("searching", || {
                weft::mend::t_nodes::find_t_nodes(&mesh, *tolerance)
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
                let (repaired, inserted) =
                    weft::mend::t_nodes::repair_t_nodes(&mesh, *tolerance)
                        .map_err(|e| operation_failed(input, "repair T-nodes", e))?;
                eprintln!("inserted {inserted} vertices into edges");
                write(output, &repaired, &io::WriteOptions::default())?;
            }
            Ok(())
        }
        Command::Demo { out, image, only } => {
            demo::run(out, image.as_deref(), only).map_err(Failure::Failed)
        }
        Command::Triangulate { input, output } => {
            let file = read_file(cli, input)?;
            let triangles = with_progress("triangulating", || carry::triangulate(&file))
                .map_err(|e| operation_failed(input, "triangulate", e))?;
            write_file(output, &triangles, &io::WriteOptions::default())
        }
        Command::Convert {
            input,
            output,
            ascii,
            big_endian,
        } => {
            let file = read_file(cli, input)?;
            let options = io::WriteOptions {
                ply: if *ascii {
                    io::PlyEncoding::Ascii
                } else if *big_endian {
                    io::PlyEncoding::BinaryBigEndian
                } else {
                    io::PlyEncoding::BinaryLittleEndian
                },
                stl_ascii: *ascii,
            };
            write_file(output, &file, &options)
        }
        Command::Toolbar(command) => toolbar::run(cli, command),
    }
}

fn operation_failed(input: &Path, what: &str, error: weft::Error) -> Failure {
    Failure::Failed(format!("{}: cannot {what}: {error}", input.display()))
}

/// Reads a mesh for a command that does not carry colours, UVs or
/// creases: says on stderr what the output will lack.
fn read(cli: &Cli, path: &Path) -> Result<Mesh, Failure> {
    let file = read_file_or_mesh(cli, path)?;
    if file.has_attributes() {
        eprintln!(
            "{}: this command keeps only the mesh; its {} are not carried to the output",
            path.display(),
            file.attribute_names().join(", ")
        );
    }
    Ok(file.mesh)
}

/// As [`read_file`], but for a command that can do without colours, UVs
/// and creases: when only those are malformed, says so on stderr and goes
/// on with the mesh alone.
fn read_file_or_mesh(cli: &Cli, path: &Path) -> Result<MeshFile, Failure> {
    match read_file(cli, path) {
        Ok(file) => Ok(file),
        Err(Failure::Failed(attribute_problem)) => {
            let weld = cli.weld && Format::from_path(path).ok() == Some(Format::Stl);
            let mesh = io::read_mesh_with(path, &ReadOptions { weld })
                .map_err(|_| Failure::Failed(attribute_problem.clone()))?;
            eprintln!("weft: {attribute_problem}; reading on with the mesh alone");
            Ok(MeshFile::new(mesh))
        }
    }
}

/// Reads a mesh with its colours, UVs and creases, welding STL corners
/// when `--weld` was given.
fn read_file(cli: &Cli, path: &Path) -> Result<MeshFile, Failure> {
    let weld = cli.weld && Format::from_path(path).ok() == Some(Format::Stl);
    let label = format!("reading {}", path.display());
    let file = with_progress(&label, || io::read_mesh_file(path, &ReadOptions { weld }))?;
    Ok(file)
}

/// Writes a mesh with what its format holds of its colours, UVs, normals
/// and creases, saying on stderr what it cannot hold.
fn write_file(path: &Path, file: &MeshFile, options: &io::WriteOptions) -> Result<(), Failure> {
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

fn write(path: &Path, mesh: &Mesh, options: &io::WriteOptions) -> Result<(), Failure> {
    let label = format!("writing {}", path.display());
    with_progress(&label, || io::write_mesh_with(path, mesh, options))?;
    report_written(path, mesh);
    Ok(())
}

fn report_written(path: &Path, mesh: &Mesh) {
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

/// Runs `work`; when it takes longer than half a second and stderr is a
/// terminal, shows `label` and the time spent until it ends.
fn with_progress<T>(label: &str, work: impl FnOnce() -> T) -> T {
    progress::with_spinner(label, work)
}

/// What `weft info` reports.
struct Report {
    vertices: usize,
    faces: usize,
    triangles: usize,
    quads: usize,
    ngons: usize,
    edges: usize,
    naked_edges: usize,
    non_manifold_edges: usize,
    non_manifold_vertices: usize,
    components: usize,
    closed: bool,
    orientable: bool,
    oriented: bool,
    bounding_box: Option<([f64; 3], [f64; 3])>,
    /// The largest distance of a face's corners from its best-fit plane.
    max_planarity_deviation: f64,
    /// Faces further from planar than the tolerance.
    non_planar_faces: usize,
    planarity_tolerance: f64,
    /// What the file carries besides the mesh.
    attributes: Vec<&'static str>,
}

fn describe(mesh: &Mesh, planarity_tolerance: f64) -> Report {
    let deviations = weft::mesh::analysis::planarity_deviations(mesh);
    let info = Topology::new(mesh).info(mesh);
    let count = |size: u32| mesh.face_sizes().iter().filter(|&&s| s == size).count();
    let (triangles, quads) = (count(3), count(4));
    Report {
        vertices: info.vertex_count,
        faces: info.face_count,
        triangles,
        quads,
        ngons: info.face_count - triangles - quads,
        edges: info.edge_count,
        naked_edges: info.naked_edge_count,
        non_manifold_edges: info.non_manifold_edge_count,
        non_manifold_vertices: info.non_manifold_vertex_count,
        components: info.component_count,
        closed: info.is_closed,
        orientable: info.is_orientable,
        oriented: info.is_oriented,
        bounding_box: mesh
            .bounding_box()
            .map(|(lo, hi)| (lo.to_array(), hi.to_array())),
        max_planarity_deviation: deviations.iter().copied().fold(0.0, f64::max),
        non_planar_faces: deviations
            .iter()
            .filter(|&&d| d > planarity_tolerance)
            .count(),
        planarity_tolerance,
        attributes: Vec::new(),
    }
}

fn yes(b: bool) -> &'static str {
    if b {
        "yes"
    } else {
        "no"
    }
}

impl Report {
    fn text(&self, path: &Path) -> String {
        let mut s = format!("{}\n", path.display());
        let mut line = |name: &str, value: String| s.push_str(&format!("  {name:<22}{value}\n"));
        line("vertices", self.vertices.to_string());
        line(
            "faces",
            format!(
                "{} ({} triangles, {} quads, {} n-gons)",
                self.faces, self.triangles, self.quads, self.ngons
            ),
        );
        line("edges", self.edges.to_string());
        line("naked edges", self.naked_edges.to_string());
        line("non-manifold edges", self.non_manifold_edges.to_string());
        line(
            "non-manifold vertices",
            self.non_manifold_vertices.to_string(),
        );
        line("components", self.components.to_string());
        line("closed", yes(self.closed).to_string());
        line("orientable", yes(self.orientable).to_string());
        line("oriented", yes(self.oriented).to_string());
        line(
            "planarity",
            format!(
                "{} of {} faces beyond {} of their best-fit plane (largest deviation {:.3e})",
                self.non_planar_faces,
                self.faces,
                self.planarity_tolerance,
                self.max_planarity_deviation
            ),
        );
        line(
            "bounding box",
            match self.bounding_box {
                Some((lo, hi)) => format!(
                    "({}, {}, {}) to ({}, {}, {})",
                    lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]
                ),
                None => "none (no vertices)".to_string(),
            },
        );
        if !self.attributes.is_empty() {
            line("carried data", self.attributes.join(", "));
        }
        s
    }

    fn json(&self, path: &Path) -> String {
        let point = |p: [f64; 3]| format!("[{}, {}, {}]", p[0], p[1], p[2]);
        let bounding_box = match self.bounding_box {
            Some((lo, hi)) => format!("{{\"min\": {}, \"max\": {}}}", point(lo), point(hi)),
            None => "null".to_string(),
        };
        format!(
            "{{\"file\": {}, \"vertices\": {}, \"faces\": {}, \"triangles\": {}, \"quads\": {}, \
             \"ngons\": {}, \"edges\": {}, \"naked_edges\": {}, \"non_manifold_edges\": {}, \
             \"non_manifold_vertices\": {}, \"components\": {}, \"closed\": {}, \
             \"orientable\": {}, \"oriented\": {}, \"planarity\": {{\"tolerance\": {}, \
             \"non_planar_faces\": {}, \"max_deviation\": {}}}, \"bounding_box\": {bounding_box}, \
             \"carried\": [{}]}}",
            json_string(&path.to_string_lossy()),
            self.vertices,
            self.faces,
            self.triangles,
            self.quads,
            self.ngons,
            self.edges,
            self.naked_edges,
            self.non_manifold_edges,
            self.non_manifold_vertices,
            self.components,
            self.closed,
            self.orientable,
            self.oriented,
            self.planarity_tolerance,
            self.non_planar_faces,
            self.max_planarity_deviation,
            self.attributes
                .iter()
                .map(|name| json_string(name))
                .collect::<Vec<_>>()
                .join(", "),
        )
    }
}

fn json_string(s: &str) -> String {
    let mut out = String::from("\"");
    for c in s.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            c if (c as u32) < 0x20 => out.push_str(&format!("\\u{:04x}", c as u32)),
            c => out.push(c),
        }
    }
    out.push('"');
    out
}
