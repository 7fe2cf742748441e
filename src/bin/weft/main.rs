//! The `weft` command: mesh files in and out, pictures, and Weft's operations.
//!
//! Exit codes: 0 success, 1 a failed operation (unreadable or malformed
//! input, an output that cannot be written), 2 bad usage (clap's own code).

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use clap::{CommandFactory, FromArgMatches, Parser, Subcommand};

mod args;
mod carry;
mod demo;
mod evaluate;
mod files;
mod info;
mod mend;
mod nurbs;
mod progress;
mod subdivide;
mod toolbar;

use weft::io::render::{self, RenderOptions};
use weft::io::{self, IoError};

use args::{mesh_path, picture_size, png_path, tolerance, InOut};
use files::{
    operation_failed, read_file, read_file_or_mesh, suggest_weld, with_progress, write_file,
};

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
    /// Accept faces that name a vertex more than once (`f 1 2 2 3`), which
    /// are refused as broken input otherwise; subdivision treats them as
    /// OpenSubdiv does, as non-manifold topology.
    #[arg(long, global = true)]
    allow_repeated_vertices: bool,
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
    /// fitted in a three-quarter view or along an axis, z or y up.
    #[command(
        after_help = "Examples:\n  weft render part.obj part.png --size 1024x768\n  weft render scan.ply scan-top.png --view top --up y"
    )]
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
        /// Draw face edges always, or never (default: when the mesh has
        /// fewer than 4000 faces and each has 300 pixels of the picture).
        #[arg(long, value_parser = ["always", "never", "auto"], default_value = "auto")]
        edges: String,
        /// Where the camera looks from: a three-quarter view from the
        /// front, right and above, or along an axis.
        #[arg(long, value_parser = args::choice(args::VIEWS), default_value = "iso")]
        view: weft::io::render::View,
        /// Which axis of the model points up (scans often have y up).
        #[arg(long, value_enum, default_value = "z")]
        up: args::UpChoice,
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
    Subdivide(subdivide::Subdivide),
    /// Writes the Catmull-Clark limit surface of a cage as bicubic B-spline
    /// patches in a STEP file (AP214), one per face of the cage refined
    /// --isolation levels, with the options of `subdivide`; prints how many
    /// patches are exact and the largest error of the others.
    #[command(
        after_help = "Patches away from extraordinary vertices and crease ends are the limit surface \
exactly (bicubic B-splines); the few touching one are fitted to exact limit points, watertight \
with their neighbours, and their largest distance from the limit is reported.\n\n\
Examples:\n  weft nurbs cage.obj part.step --isolation 2 --naked-edges smooth\n  \
weft nurbs block.obj block.step --isolation 3 --creases block-creases.txt"
    )]
    Nurbs(nurbs::Nurbs),
    /// Points of a cage's limit surface at given face parameters, with its
    /// unit normals, one line per sample (`x y z nx ny nz`), with the
    /// options of `subdivide`: exact, at any parameter of any face.
    #[command(
        after_help = "Samples file (--samples): one sample per line, `face u v`, the face 0-based. A quad's \
(u, v) runs from its first corner, u towards the second corner and v towards the last; a Loop \
triangle's is barycentric (corner 0 at (0, 0), 1 at (1, 0), 2 at (0, 1)); other faces are laid out \
as OpenSubdiv's Bfr quad sub-faces (see weft.h, weft_limit_surface_evaluate).\n\n\
Examples:\n  weft evaluate cage.obj --samples uv.txt -o points.txt --naked-edges smooth\n  \
weft evaluate tri.obj --samples uv.txt --scheme loop"
    )]
    Evaluate(evaluate::Evaluate),
    /// Joins meshes into one and merges vertices at most the tolerance
    /// apart; fails, writing nothing, if faces would collapse.
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
        /// Vertices at most this far apart become one (default: a millionth
        /// of the joined mesh's bounding-box diagonal). 0 merges exact
        /// duplicates only; either way, vertices no face uses are left out.
        #[arg(long, value_parser = tolerance)]
        tolerance: Option<f64>,
        /// Write the result even when faces collapse (by default the weld
        /// fails and writes nothing, naming how many would collapse).
        #[arg(long)]
        allow_collapse: bool,
    },
    /// Removes every face that has a twin with the same vertices (either
    /// orientation), all copies: the walls inside joined boxes.
    #[command(
        name = "cull-adjacent",
        after_help = "Example:\n  weft weld boxes.obj -o welded.obj\n  weft cull-adjacent welded.obj hull.obj"
    )]
    CullAdjacent {
        #[command(flatten)]
        files: InOut,
    },
    /// Reverses every face, or with --unify only the fewest faces that give
    /// each connected piece one consistent orientation.
    #[command(
        after_help = "Examples:\n  weft flip shell.obj shell-flipped.obj\n  weft flip joined.obj unified.obj --unify\n  weft flip boxes.stl boxes-out.obj --outward --weld"
    )]
    Flip {
        #[command(flatten)]
        files: InOut,
        /// Make the orientation consistent instead of flipping everything.
        #[arg(long)]
        unify: bool,
        /// Unify, then turn every closed piece to face outward (positive
        /// signed volume); open pieces are unified and reported. STL
        /// triangles share no corners: add --weld.
        #[arg(long, conflicts_with = "unify")]
        outward: bool,
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
        /// How close to an edge a vertex must be (default: a millionth of
        /// the mesh's bounding-box diagonal, as `weld`).
        #[arg(long, value_parser = tolerance)]
        tolerance: Option<f64>,
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
        #[command(flatten)]
        files: InOut,
    },
    /// Converts a mesh file; formats follow the extensions.
    #[command(
        after_help = "Example:\n  weft convert part.obj part.ply\n  weft convert scan.stl scan.obj --weld"
    )]
    Convert {
        #[command(flatten)]
        files: InOut,
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

/// Why a command failed; each maps to an exit code.
enum Failure {
    /// Exit 1: the operation could not be done.
    Failed(String),
}

impl From<IoError> for Failure {
    fn from(e: IoError) -> Failure {
        match &e {
            IoError::InvalidMesh {
                source: weft::MeshError::RepeatedIndex { .. },
                ..
            } => Failure::Failed(format!(
                "{e}; --allow-repeated-vertices accepts such faces (OpenSubdiv's non-manifold cages)"
            )),
            _ => Failure::Failed(e.to_string()),
        }
    }
}

/// `command` and its subcommands with negative numbers taken as option
/// values, so `--tolerance -1` reaches Weft's own message.
fn with_negative_numbers(command: clap::Command) -> clap::Command {
    let names: Vec<String> = command
        .get_subcommands()
        .map(|sub| sub.get_name().to_owned())
        .collect();
    names
        .into_iter()
        .fold(command.allow_negative_numbers(true), |command, name| {
            command.mut_subcommand(name, with_negative_numbers)
        })
}

fn main() -> ExitCode {
    let matches = with_negative_numbers(Cli::command()).get_matches();
    let cli = match Cli::from_arg_matches(&matches) {
        Ok(cli) => cli,
        Err(e) => e.exit(),
    };
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
            Command::Render { output, .. } | Command::Weld { output, .. } => vec![output.as_path()],
            Command::Subdivide(subdivide::Subdivide { files, .. })
            | Command::CullAdjacent { files }
            | Command::Flip { files, .. }
            | Command::Triangulate { files }
            | Command::Convert { files, .. } => vec![files.output.as_path()],
            Command::Nurbs(nurbs::Nurbs { output, .. }) => vec![output.as_path()],
            Command::Evaluate(evaluate::Evaluate { output, .. }) => {
                output.iter().map(PathBuf::as_path).collect()
            }
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
            let mut report =
                with_progress("analysing", || info::describe(mesh, *planarity_tolerance))
                    .map_err(|e| Failure::Failed(format!("{}: {e}", input.display())))?;
            report.attributes = file.attribute_names();
            if *json {
                println!("{}", report.json(input));
            } else {
                print!("{}", report.text(input));
            }
            if report.faces_share_no_edge() && !cli.weld {
                suggest_weld(input);
            }
            Ok(())
        }
        Command::Render {
            input,
            output,
            size,
            edges,
            view,
            up,
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
                view: *view,
                up: up.up(),
                ..RenderOptions::default()
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
        Command::Subdivide(args) => subdivide::run(cli, args),
        Command::Nurbs(args) => nurbs::run(cli, args),
        Command::Evaluate(args) => evaluate::run(cli, args),
        Command::Weld {
            inputs,
            output,
            tolerance,
            allow_collapse,
        } => mend::weld(cli, inputs, output, *tolerance, *allow_collapse),
        Command::CullAdjacent { files } => mend::cull_adjacent(cli, files),
        Command::Flip {
            files,
            unify,
            outward,
        } => mend::flip(cli, files, *unify, *outward),
        Command::TNodes {
            input,
            repair,
            tolerance,
        } => mend::t_nodes(cli, input, repair.as_deref(), *tolerance),
        Command::Demo { out, image, only } => {
            demo::run(out, image.as_deref(), only).map_err(Failure::Failed)
        }
        Command::Triangulate { files } => {
            let file = read_file(cli, &files.input)?;
            files::require_faces(&files.input, &file.mesh)?;
            let (triangles, _) = with_progress("triangulating", || carry::as_triangles(&file))
                .map_err(|e| operation_failed(&files.input, "triangulate", e))?;
            write_file(&files.output, &triangles, &io::WriteOptions::default())
        }
        Command::Convert {
            files,
            ascii,
            big_endian,
        } => {
            let file = read_file(cli, &files.input)?;
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
            write_file(&files.output, &file, &options)
        }
        Command::Toolbar(command) => toolbar::run(cli, command),
    }
}
