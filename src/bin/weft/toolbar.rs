//! The `weft` commands of Weaverbird's toolbar: linear subdivisions,
//! smoothing, offsets and insets, bevels, dual, reroute, stellate, tile, and the
//! Define panel's primitives. Each reads a mesh file (or, for `primitive`,
//! builds one), runs one library operation and writes the result.

use std::path::{Path, PathBuf};

use clap::Subcommand;

use weft::make::primitives::{Platonic, Sided};
use weft::make::stellate::Heights;
use weft::toolbar::extract::DualMode;
use weft::toolbar::smooth::{HcOptions, SmoothDirection};
use weft::toolbar::tile::{TileFaces, TileFill};
use weft::toolbar::transform::{InsetMode, OffsetType};
use weft::{DVec3, Mesh};

mod choices;

use choices::{
    DirectionArg, PrimitiveKind, SmoothMethod, INSET_MODES, OFFSET_TYPES, TILE_FACES, TILE_FILLS,
};

use crate::args::{choice, mesh_path, InOut, NakedEdgesArg};
use crate::files::{
    operation_failed, read, read_file_or_mesh, require_faces, with_progress, write, write_file,
};
use crate::{Cli, Failure};
use weft::io;
use weft::subdivide::NakedEdges;

/// How many times a repeated operation runs.
#[derive(clap::Args)]
pub(crate) struct Levels {
    /// How many times to apply it (0 copies the mesh; at most 20).
    #[arg(long, default_value_t = 1)]
    levels: u32,
}

/// The arguments of offset and thicken.
#[derive(clap::Args)]
pub(crate) struct Offsetting {
    #[command(flatten)]
    files: InOut,
    /// How far the offset surface lies, in model units (for thicken, the
    /// thickness); its sign picks the side.
    #[arg(long, allow_negative_numbers = true)]
    distance: f64,
    /// How far each vertex moves along its normal.
    #[arg(long = "type", value_parser = choice(OFFSET_TYPES), default_value = "diagonal")]
    offset_type: OffsetType,
}

/// The arguments of the insets (window and frame).
#[derive(clap::Args)]
pub(crate) struct Inset {
    #[command(flatten)]
    files: InOut,
    /// edge-fraction: a share of the edges in [0, 0.5); parallelogram: a
    /// width in model units.
    #[arg(long)]
    distance: f64,
    /// How the distance is read.
    #[arg(long, value_parser = choice(INSET_MODES), default_value = "edge-fraction")]
    mode: InsetMode,
}

/// A mesh file in, a mesh file out, and how many times the split runs.
#[derive(clap::Args)]
pub(crate) struct Split {
    #[command(flatten)]
    files: InOut,
    #[command(flatten)]
    levels: Levels,
}

#[derive(Subcommand)]
pub(crate) enum ToolbarCommand {
    /// Splits each n-gon into n quads through its edge midpoints and
    /// centroid, without smoothing (Weaverbird's Split Polygons).
    #[command(
        name = "split-polygons",
        after_help = "Example:\n  weft split-polygons cage.obj split.obj --levels 2"
    )]
    SplitPolygons(Split),
    /// Splits each triangle into four through its edge midpoints, without
    /// smoothing; other faces are triangulated first (Weaverbird's Split
    /// Triangles).
    #[command(
        name = "split-triangles",
        after_help = "Example:\n  weft split-triangles shell.obj finer.obj --levels 2"
    )]
    SplitTriangles(Split),
    /// Splits quads into four quads, triangles into four triangles and larger
    /// polygons into quads around their centroid (Weaverbird's Constant
    /// Quads Split).
    #[command(
        name = "quad-split",
        after_help = "Example:\n  weft quad-split panels.obj panels-4.obj --levels 1"
    )]
    QuadSplit(Split),
    /// The mid-edge subdivision (Peters and Reif): a face of edge midpoints
    /// per face and per vertex; boundary vertices stay.
    #[command(after_help = "Example:\n  weft midedge cube.obj cuboctahedron.obj")]
    Midedge(Split),
    /// Gives each face an inner face pulled towards its centroid, joined to
    /// it by a quad per edge (Weaverbird's Inner Polygons).
    #[command(
        name = "inner-polygons",
        after_help = "Example:\n  weft inner-polygons panels.obj inner.obj --pull 0.3"
    )]
    InnerPolygons {
        #[command(flatten)]
        files: InOut,
        #[command(flatten)]
        levels: Levels,
        /// How far the inner corners move towards the centroid, strictly
        /// between 0 and 1.
        #[arg(long, default_value_t = 0.5)]
        pull: f64,
    },
    /// Places a triangle in each corner of each face and leaves the middle
    /// open: one new hole per face and level (Weaverbird's Sierpinski
    /// Triangles).
    #[command(after_help = "Example:\n  weft sierpinski shell.obj lace.obj --levels 2")]
    Sierpinski(Split),
    /// Cuts each quad into 3 × 3 quads and removes the middle one; quads
    /// only (Weaverbird's Sierpinski Carpet).
    #[command(after_help = "Example:\n  weft carpet facade.obj carpet.obj --levels 2")]
    Carpet(Split),
    /// Moves vertices towards the average of their neighbours; the faces do
    /// not change. laplacian shrinks as it smooths; hc (Vollmer, Mann and
    /// Müller 1999) pushes back to keep the volume.
    #[command(
        after_help = "Examples:\n  weft smooth scan.obj smooth.obj --method hc --iterations 10\n  weft smooth panel.obj relaxed.obj --method hc --direction tangential --naked-edges smooth\n  weft smooth panel.obj soft.obj --method laplacian --blend 0.5 --naked-edges corner-fixed"
    )]
    Smooth {
        #[command(flatten)]
        files: InOut,
        /// The smoothing rule.
        #[arg(long, value_enum, default_value = "laplacian")]
        method: SmoothMethod,
        /// How many steps (at most 10000).
        #[arg(long, default_value_t = 1)]
        iterations: u32,
        /// Boundary vertices: fixed stay, smooth slide along the boundary,
        /// corner-fixed slide but keep corners.
        #[arg(long, value_enum, default_value = "fixed")]
        naked_edges: NakedEdgesArg,
        /// laplacian: how far towards the average per step, 0 to 1.
        #[arg(long, default_value_t = 1.0)]
        blend: f64,
        /// hc: how much the push-back aims at the original points, 0 to 1.
        #[arg(long, default_value_t = 0.0)]
        alpha: f64,
        /// hc: the share of a vertex's own displacement undone, 0 to 1.
        #[arg(long, default_value_t = 0.6)]
        beta: f64,
        /// hc: which way vertices may move: freely, only along their normal,
        /// or only in their tangent plane.
        #[arg(long, value_enum, default_value = "free")]
        direction: DirectionArg,
    },
    /// Moves every vertex by the distance along the surface normal
    /// (positive: to the front); the faces are kept (Weaverbird's Offset).
    #[command(
        after_help = "Example:\n  weft offset shell.obj outer.obj --distance 0.2 --type planes-intersection"
    )]
    Offset(Offsetting),
    /// A solid from a surface: the input, its offset, and a quad along every
    /// naked edge joining them (Weaverbird's Mesh Thicken).
    #[command(
        after_help = "Example:\n  weft thicken canopy.obj canopy-solid.obj --distance 0.05 --type hypotenuse-average"
    )]
    Thicken(Offsetting),
    /// Insets each face, keeping the frame of quads and the inner face
    /// (Weaverbird's Mesh Window).
    #[command(
        after_help = "Examples:\n  weft window facade.obj windows.obj --distance 0.2\n  weft window facade.obj windows.obj --distance 0.05 --mode parallelogram"
    )]
    Window(Inset),
    /// Insets each face and keeps only the frame: each face becomes a ring
    /// around a hole (Weaverbird's Picture Frame).
    #[command(
        after_help = "Example:\n  weft frame facade.obj lattice.obj --distance 0.1 --mode parallelogram"
    )]
    Frame(Inset),
    /// Bevels every edge: faces shrink towards their centroids, each inner
    /// edge becomes a quad and each inner vertex a face (Weaverbird's Bevel
    /// Edges).
    #[command(
        name = "bevel-edges",
        after_help = "Example:\n  weft bevel-edges cube.obj rhombicuboctahedron.obj --fraction 0.3"
    )]
    BevelEdges {
        #[command(flatten)]
        files: InOut,
        /// How far faces shrink, strictly between 0 and 1.
        #[arg(long, default_value_t = 0.25)]
        fraction: f64,
    },
    /// Cuts every vertex off at a share of each edge, adding a face per
    /// vertex (Weaverbird's Bevel Vertices).
    #[command(
        name = "bevel-vertices",
        after_help = "Example:\n  weft bevel-vertices cube.obj truncated.obj --fraction 0.2"
    )]
    BevelVertices {
        #[command(flatten)]
        files: InOut,
        /// Where each edge is cut, strictly between 0 and 0.5.
        #[arg(long, default_value_t = 0.25)]
        fraction: f64,
    },
    /// The dual mesh: a vertex per face, a face per inner vertex
    /// (Weaverbird's Dual).
    #[command(after_help = "Example:\n  weft dual cube.obj octahedron.obj --keep-size")]
    Dual {
        #[command(flatten)]
        files: InOut,
        /// Scale the dual to the input's bounding box size.
        #[arg(long)]
        keep_size: bool,
    },
    /// Makes each face start --shift corners later (Weaverbird's Reroute
    /// Faces).
    ///
    /// [a, b, c, d] shifted by 1 is [b, c, d, a]. The winding, the vertices
    /// and the order of the faces stay; only which corner comes first
    /// changes, which is what a definition reading each face's first vertex
    /// sees.
    #[command(
        after_help = "Examples:\n  weft reroute panels.obj rerouted.obj --shift 1\n  weft reroute panels.obj back.obj --shift -1"
    )]
    Reroute {
        #[command(flatten)]
        files: InOut,
        /// How many corners later each face starts (negative: earlier); it
        /// wraps around each face.
        #[arg(long, default_value_t = 1, allow_negative_numbers = true)]
        shift: i64,
    },
    /// Raises a pyramid on every face: an apex above its centroid along its
    /// normal and a fan of triangles (Weaverbird's Stellate/Cumulation).
    #[command(after_help = "Example:\n  weft stellate cells.obj spikes.obj --height -0.3")]
    Stellate {
        #[command(flatten)]
        files: InOut,
        /// The apex's distance from the face (negative: behind it).
        #[arg(long, allow_negative_numbers = true)]
        height: f64,
    },
    /// Re-fills chosen faces by a pattern of triangles or quads, keeping
    /// outlines and welded seams (Weaverbird's Tile).
    #[command(
        after_help = "Examples:\n  weft tile panels.obj fans.obj --fill triangle-fan\n  weft tile mixed.obj quads.obj --fill quad-stitch --faces pentagons-and-more"
    )]
    Tile {
        #[command(flatten)]
        files: InOut,
        /// The pattern of each chosen face.
        #[arg(long, value_parser = choice(TILE_FILLS), default_value = "best")]
        fill: TileFill,
        /// Which faces are filled; the others stay.
        #[arg(long, value_parser = choice(TILE_FACES), default_value = "all")]
        faces: TileFaces,
    },
    /// Builds one of the Define panel's meshes, centred on the origin:
    /// plane, box, sphere, the platonic solids, prisms and pyramids.
    #[command(
        after_help = "Examples:\n  weft primitive plane plane.obj --size 10 --divisions 4\n  weft primitive box box.obj --size 2 --divisions 3\n  weft primitive sphere ball.obj --radius 5 --divisions 16\n  weft primitive dodecahedron d12.off --radius 1\n  weft primitive antiprism a.obj --sides 8 --radius 2 --height 1"
    )]
    Primitive {
        /// What to build.
        #[arg(value_enum)]
        kind: PrimitiveKind,
        /// The mesh file to write (.obj, .ply, .stl, .off).
        #[arg(value_parser = mesh_path)]
        output: PathBuf,
        /// plane and box: the side length.
        #[arg(long, default_value_t = 10.0)]
        size: f64,
        /// plane and box: quads along each side (default 10 and 1); sphere:
        /// segments around, half as many from pole to pole (default 16).
        #[arg(long)]
        divisions: Option<usize>,
        /// sphere, platonic solids, prisms and pyramids: the circumradius.
        #[arg(long, default_value_t = 5.0)]
        radius: f64,
        /// prisms and pyramids: the corners of the base polygon.
        #[arg(long, default_value_t = 6)]
        sides: usize,
        /// prisms and pyramids: the height.
        #[arg(long, default_value_t = 10.0)]
        height: f64,
    },
}

/// Reads `files.input`, applies `op` (named `what` in messages) and writes
/// `files.output`.
fn apply(
    cli: &Cli,
    files: &InOut,
    what: &str,
    op: impl FnOnce(&Mesh) -> weft::Result<Mesh>,
) -> Result<(), Failure> {
    let mesh = read(cli, &files.input)?;
    let result =
        with_progress(what, || op(&mesh)).map_err(|e| operation_failed(&files.input, what, e))?;
    write(&files.output, &result, &io::WriteOptions::default())
}

/// As [`apply`], for the commands whose output faces are the input's, one
/// for one and in order (smoothing, offsetting, rerouting): the OBJ's
/// materials stay with their faces.
fn apply_keeping_faces(
    cli: &Cli,
    files: &InOut,
    what: &str,
    op: impl FnOnce(&Mesh) -> weft::Result<Mesh>,
) -> Result<(), Failure> {
    let file = read_file_or_mesh(cli, &files.input)?;
    require_faces(&files.input, &file.mesh)?;
    let dropped: Vec<&str> = file
        .attribute_names()
        .into_iter()
        .filter(|&name| name != "materials")
        .collect();
    if !dropped.is_empty() {
        eprintln!(
            "{}: this command keeps only the mesh and its materials; its {} are not carried to the output",
            files.input.display(),
            dropped.join(", ")
        );
    }
    let result = with_progress(what, || op(&file.mesh))
        .map_err(|e| operation_failed(&files.input, what, e))?;
    let mut out = io::MeshFile::new(result);
    if out.mesh.face_count() == file.mesh.face_count() {
        out.materials = file.materials.clone();
    }
    write_file(&files.output, &out, &io::WriteOptions::default())
}

/// The mesh as triangles for the commands that need them, saying how many
/// faces were triangulated when there were any.
fn triangles(input: &Path, mesh: &Mesh) -> weft::Result<Mesh> {
    let (triangles, split) = weft::mesh::triangulate::as_triangles(mesh)?;
    if split > 0 {
        eprintln!(
            "{}: splitting triangles needs triangles: triangulated {split} of {} faces into {} triangles",
            input.display(),
            mesh.face_count(),
            triangles.mesh.face_count()
        );
    }
    Ok(triangles.mesh)
}

impl ToolbarCommand {
    /// The file the command writes.
    pub(crate) fn outputs(&self) -> Vec<&Path> {
        use ToolbarCommand::*;
        match self {
            SplitPolygons(Split { files, .. })
            | SplitTriangles(Split { files, .. })
            | QuadSplit(Split { files, .. })
            | Midedge(Split { files, .. })
            | InnerPolygons { files, .. }
            | Sierpinski(Split { files, .. })
            | Carpet(Split { files, .. })
            | Smooth { files, .. }
            | Offset(Offsetting { files, .. })
            | Thicken(Offsetting { files, .. })
            | Window(Inset { files, .. })
            | Frame(Inset { files, .. })
            | BevelEdges { files, .. }
            | BevelVertices { files, .. }
            | Dual { files, .. }
            | Reroute { files, .. }
            | Stellate { files, .. }
            | Tile { files, .. } => vec![files.output.as_path()],
            Primitive { output, .. } => vec![output.as_path()],
        }
    }
}

pub(crate) fn run(cli: &Cli, command: &ToolbarCommand) -> Result<(), Failure> {
    use weft::toolbar::{extract, split, transform};
    match command {
        ToolbarCommand::SplitPolygons(Split { files, levels }) => {
            apply(cli, files, "split polygons", |m| {
                split::split_polygons(m, levels.levels)
            })
        }
        ToolbarCommand::SplitTriangles(Split { files, levels }) => {
            apply(cli, files, "split triangles", |m| {
                split::split_triangles(&triangles(&files.input, m)?, levels.levels)
            })
        }
        ToolbarCommand::QuadSplit(Split { files, levels }) => {
            apply(cli, files, "quad split", |m| {
                split::constant_quads_split(m, levels.levels)
            })
        }
        ToolbarCommand::Midedge(Split { files, levels }) => {
            apply(cli, files, "midedge", |m| split::midedge(m, levels.levels))
        }
        ToolbarCommand::InnerPolygons {
            files,
            levels,
            pull,
        } => apply(cli, files, "inner polygons", |m| {
            split::inner_polygons(m, levels.levels, *pull)
        }),
        ToolbarCommand::Sierpinski(Split { files, levels }) => {
            apply(cli, files, "sierpinski", |m| {
                split::sierpinski_triangles(m, levels.levels)
            })
        }
        ToolbarCommand::Carpet(Split { files, levels }) => apply(cli, files, "carpet", |m| {
            transform::sierpinski_carpet(m, levels.levels)
        }),
        ToolbarCommand::Smooth {
            files,
            method,
            iterations,
            naked_edges,
            blend,
            alpha,
            beta,
            direction,
        } => apply_keeping_faces(cli, files, "smooth", |m| match method {
            SmoothMethod::Laplacian => weft::toolbar::smooth::laplacian(
                m,
                *iterations,
                *blend,
                NakedEdges::from(*naked_edges),
            ),
            SmoothMethod::Hc => {
                let options = HcOptions {
                    alpha: *alpha,
                    beta: *beta,
                    naked: NakedEdges::from(*naked_edges),
                    direction: match direction {
                        DirectionArg::Free => SmoothDirection::Free,
                        DirectionArg::AlongNormal => SmoothDirection::AlongNormal,
                        DirectionArg::Tangential => SmoothDirection::Tangential,
                    },
                    activation: None,
                };
                weft::toolbar::smooth::laplacian_hc_with(m, *iterations, &options)
            }
        }),
        ToolbarCommand::Offset(Offsetting {
            files,
            distance,
            offset_type: kind,
        }) => apply_keeping_faces(cli, files, "offset", |m| {
            transform::offset(m, *distance, *kind)
        }),
        ToolbarCommand::Thicken(Offsetting {
            files,
            distance,
            offset_type: kind,
        }) => apply(cli, files, "thicken", |m| {
            transform::thicken(m, *distance, *kind)
        }),
        ToolbarCommand::Window(Inset {
            files,
            distance,
            mode,
        }) => apply(cli, files, "window", |m| {
            transform::window(m, &[*distance], *mode)
        }),
        ToolbarCommand::Frame(Inset {
            files,
            distance,
            mode,
        }) => apply(cli, files, "frame", |m| {
            transform::picture_frame(m, &[*distance], *mode)
        }),
        ToolbarCommand::BevelEdges { files, fraction } => apply(cli, files, "bevel edges", |m| {
            transform::bevel_edges(m, *fraction)
        }),
        ToolbarCommand::BevelVertices { files, fraction } => {
            apply(cli, files, "bevel vertices", |m| {
                transform::bevel_vertices(m, *fraction)
            })
        }
        ToolbarCommand::Dual { files, keep_size } => apply(cli, files, "dual", |m| {
            let mode = if *keep_size {
                DualMode::KeepSize
            } else {
                DualMode::VertexAverage
            };
            extract::dual(m, mode)
        }),
        ToolbarCommand::Reroute { files, shift } => {
            apply_keeping_faces(cli, files, "reroute", |m| {
                Ok(extract::reroute_faces(m, *shift))
            })
        }
        ToolbarCommand::Stellate { files, height } => apply(cli, files, "stellate", |m| {
            weft::make::stellate::stellate(m, Heights::One(*height))
        }),
        ToolbarCommand::Tile { files, fill, faces } => apply(cli, files, "tile", |m| {
            weft::toolbar::tile::tile(m, *fill, *faces)
        }),
        ToolbarCommand::Primitive {
            kind,
            output,
            size,
            divisions,
            radius,
            sides,
            height,
        } => {
            use weft::make::primitives as p;
            let size = *size;
            let built = match kind {
                PrimitiveKind::Plane => {
                    let n = divisions.unwrap_or(10);
                    p::plane_grid(size, size, n, n)
                }
                PrimitiveKind::Box => {
                    let n = divisions.unwrap_or(1);
                    p::box_grid(DVec3::splat(size), n, n, n)
                }
                PrimitiveKind::Sphere => {
                    let n = divisions.unwrap_or(16);
                    p::uv_sphere(*radius, n, n / 2)
                }
                PrimitiveKind::Tetrahedron => p::platonic(Platonic::Tetrahedron, *radius),
                PrimitiveKind::Cube => p::platonic(Platonic::Hexahedron, *radius),
                PrimitiveKind::Octahedron => p::platonic(Platonic::Octahedron, *radius),
                PrimitiveKind::Dodecahedron => p::platonic(Platonic::Dodecahedron, *radius),
                PrimitiveKind::Icosahedron => p::platonic(Platonic::Icosahedron, *radius),
                PrimitiveKind::Prism => p::sided(Sided::Prism, *sides, *radius, *height),
                PrimitiveKind::Antiprism => p::sided(Sided::Antiprism, *sides, *radius, *height),
                PrimitiveKind::Pyramid => p::sided(Sided::Pyramid, *sides, *radius, *height),
                PrimitiveKind::Dipyramid => p::sided(Sided::Dipyramid, *sides, *radius, *height),
            }
            .map_err(|e| Failure::Failed(format!("cannot build the primitive: {e}")))?;
            write(output, &built, &io::WriteOptions::default())
        }
    }
}
