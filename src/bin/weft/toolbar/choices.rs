//! The choices of the toolbar commands, each a clap value named as the
//! command line spells it, and their library enumerations.

use clap::ValueEnum;

use weft::toolbar::transform::{InsetMode, OffsetType};

#[derive(Clone, Copy, ValueEnum)]
pub(crate) enum SmoothMethod {
    Laplacian,
    Hc,
}

#[derive(Clone, Copy, ValueEnum)]
pub(crate) enum DirectionArg {
    Free,
    AlongNormal,
    Tangential,
}

#[derive(Clone, Copy, ValueEnum)]
pub(crate) enum OffsetArg {
    Diagonal,
    HypotenuseAverage,
    PlanesIntersection,
}

#[derive(Clone, Copy, ValueEnum)]
pub(crate) enum InsetArg {
    EdgeFraction,
    Parallelogram,
}

#[derive(Clone, Copy, ValueEnum)]
pub(crate) enum FillArg {
    Skip,
    Best,
    TriangleFan,
    TriangleHand,
    TriangleKnit,
    TriangleZigzag,
    QuadStitch,
    QuadFan,
}

#[derive(Clone, Copy, ValueEnum)]
pub(crate) enum FacesArg {
    All,
    QuadsAndMore,
    PentagonsAndMore,
    Triangles,
    Quads,
}

#[derive(Clone, Copy, ValueEnum)]
pub(crate) enum PrimitiveKind {
    Plane,
    Box,
    Sphere,
    Tetrahedron,
    Cube,
    Octahedron,
    Dodecahedron,
    Icosahedron,
    Prism,
    Antiprism,
    Pyramid,
    Dipyramid,
}

pub(crate) fn offset_type(arg: OffsetArg) -> OffsetType {
    match arg {
        OffsetArg::Diagonal => OffsetType::Diagonal,
        OffsetArg::HypotenuseAverage => OffsetType::HypotenuseAverage,
        OffsetArg::PlanesIntersection => OffsetType::PlanesIntersection,
    }
}

pub(crate) fn inset_mode(arg: InsetArg) -> InsetMode {
    match arg {
        InsetArg::EdgeFraction => InsetMode::EdgeFraction,
        InsetArg::Parallelogram => InsetMode::Parallelogram,
    }
}
