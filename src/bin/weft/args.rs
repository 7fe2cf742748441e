//! The arguments the commands share: the mesh file pair, the checked
//! numbers and paths, and the choices that name a library enumeration, each
//! mapped to it once.

use std::path::PathBuf;

use clap::ValueEnum;

use weft::io::{render, Format};
use weft::subdivide::{Creasing, FaceVaryingLinear, NakedEdges, Scheme, TriangleRule};

/// A mesh file in and a mesh file out, the arguments most commands share.
#[derive(clap::Args)]
pub struct InOut {
    /// The mesh file to read (.obj, .ply, .stl, .off).
    #[arg(value_parser = mesh_path)]
    pub input: PathBuf,
    /// The mesh file to write (.obj, .ply, .stl, .off).
    #[arg(value_parser = mesh_path)]
    pub output: PathBuf,
}

#[derive(Clone, Copy, ValueEnum)]
pub enum SchemeArg {
    CatmullClark,
    Loop,
}

#[derive(Clone, Copy, ValueEnum)]
pub enum CreasingArg {
    Uniform,
    Chaikin,
}

#[derive(Clone, Copy, ValueEnum)]
pub enum UvLinearArg {
    None,
    CornersOnly,
    #[value(name = "corners-plus1")]
    CornersPlus1,
    #[value(name = "corners-plus2")]
    CornersPlus2,
    Boundaries,
    All,
}

pub fn angle(text: &str) -> Result<f64, String> {
    text.parse::<f64>()
        .ok()
        .filter(|a| a.is_finite() && *a >= 0.0)
        .ok_or_else(|| "expected an angle in degrees, 0 or more, such as 60".to_string())
}

#[derive(Clone, Copy, ValueEnum)]
pub enum NakedEdgesArg {
    Fixed,
    Smooth,
    CornerFixed,
}

/// Subdivision's naked-edge modes: Weaverbird's three and OpenSubdiv's
/// boundary interpolation "none".
#[derive(Clone, Copy, ValueEnum)]
pub enum SubdivisionNakedEdgesArg {
    Fixed,
    Smooth,
    CornerFixed,
    None,
}

#[derive(Clone, Copy, ValueEnum)]
pub enum TrianglesArg {
    Catmark,
    Smooth,
}

/// A mesh file argument: its extension must name a format.
pub fn mesh_path(text: &str) -> Result<PathBuf, String> {
    let path = PathBuf::from(text);
    Format::from_path(&path)
        .map(|_| path)
        .map_err(|_| "expected a mesh file ending in .obj, .ply, .stl or .off".to_string())
}

pub fn step_path(text: &str) -> Result<PathBuf, String> {
    let path = PathBuf::from(text);
    match path.extension().and_then(|e| e.to_str()) {
        Some(e) if e.eq_ignore_ascii_case("step") || e.eq_ignore_ascii_case("stp") => Ok(path),
        _ => Err("expected a STEP file ending in .step or .stp".to_string()),
    }
}

pub fn tolerance(text: &str) -> Result<f64, String> {
    text.parse::<f64>()
        .ok()
        .filter(|t| t.is_finite() && *t >= 0.0)
        .ok_or_else(|| "expected a distance of 0 or more, such as 0.001".to_string())
}

pub fn png_path(text: &str) -> Result<PathBuf, String> {
    let path = PathBuf::from(text);
    match path.extension().and_then(|e| e.to_str()) {
        Some(e) if e.eq_ignore_ascii_case("png") => Ok(path),
        _ => Err("expected a picture file ending in .png".to_string()),
    }
}

pub fn picture_size(text: &str) -> Result<(u32, u32), String> {
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

impl From<SchemeArg> for Scheme {
    fn from(arg: SchemeArg) -> Scheme {
        match arg {
            SchemeArg::CatmullClark => Scheme::CatmullClark,
            SchemeArg::Loop => Scheme::Loop,
        }
    }
}

impl From<NakedEdgesArg> for NakedEdges {
    fn from(arg: NakedEdgesArg) -> NakedEdges {
        match arg {
            NakedEdgesArg::Fixed => NakedEdges::Fixed,
            NakedEdgesArg::Smooth => NakedEdges::Smooth,
            NakedEdgesArg::CornerFixed => NakedEdges::CornerFixed,
        }
    }
}

impl From<SubdivisionNakedEdgesArg> for NakedEdges {
    fn from(arg: SubdivisionNakedEdgesArg) -> NakedEdges {
        match arg {
            SubdivisionNakedEdgesArg::Fixed => NakedEdges::Fixed,
            SubdivisionNakedEdgesArg::Smooth => NakedEdges::Smooth,
            SubdivisionNakedEdgesArg::CornerFixed => NakedEdges::CornerFixed,
            SubdivisionNakedEdgesArg::None => NakedEdges::None,
        }
    }
}

impl From<TrianglesArg> for TriangleRule {
    fn from(arg: TrianglesArg) -> TriangleRule {
        match arg {
            TrianglesArg::Catmark => TriangleRule::Catmark,
            TrianglesArg::Smooth => TriangleRule::Smooth,
        }
    }
}

impl From<CreasingArg> for Creasing {
    fn from(arg: CreasingArg) -> Creasing {
        match arg {
            CreasingArg::Uniform => Creasing::Uniform,
            CreasingArg::Chaikin => Creasing::Chaikin,
        }
    }
}

impl From<UvLinearArg> for FaceVaryingLinear {
    fn from(arg: UvLinearArg) -> FaceVaryingLinear {
        match arg {
            UvLinearArg::None => FaceVaryingLinear::Smooth,
            UvLinearArg::CornersOnly => FaceVaryingLinear::CornersOnly,
            UvLinearArg::CornersPlus1 => FaceVaryingLinear::CornersPlus1,
            UvLinearArg::CornersPlus2 => FaceVaryingLinear::CornersPlus2,
            UvLinearArg::Boundaries => FaceVaryingLinear::Boundaries,
            UvLinearArg::All => FaceVaryingLinear::All,
        }
    }
}

/// `render --up`.
#[derive(Clone, Copy, ValueEnum)]
pub enum UpChoice {
    Z,
    Y,
}

impl UpChoice {
    pub fn up(self) -> render::Up {
        match self {
            UpChoice::Z => render::Up::Z,
            UpChoice::Y => render::Up::Y,
        }
    }
}

/// A value parser for a library enumeration: `table` spells each value as
/// the command line takes it, so `--help` lists the names and the argument
/// arrives as the library's own value, with no mirror enumeration.
pub fn choice<T: Clone + Send + Sync + 'static>(
    table: &'static [(&'static str, T)],
) -> impl clap::builder::TypedValueParser<Value = T> {
    use clap::builder::TypedValueParser;
    clap::builder::PossibleValuesParser::new(table.iter().map(|(name, _)| *name)).map(move |name| {
        let (_, value) = table
            .iter()
            .find(|(n, _)| *n == name)
            .expect("a listed name");
        value.clone()
    })
}

/// `render --view`.
pub const VIEWS: &[(&str, render::View)] = &[
    ("iso", render::View::Iso),
    ("top", render::View::Top),
    ("bottom", render::View::Bottom),
    ("front", render::View::Front),
    ("back", render::View::Back),
    ("left", render::View::Left),
    ("right", render::View::Right),
];
