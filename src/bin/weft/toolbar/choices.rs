//! The choices of the toolbar commands, each a clap value named as the
//! command line spells it, and their library enumerations.

use clap::ValueEnum;

use weft::toolbar::tile::{TileFaces, TileFill};
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

/// `offset --type` and `thicken --type`.
pub(crate) const OFFSET_TYPES: &[(&str, OffsetType)] = &[
    ("diagonal", OffsetType::Diagonal),
    ("hypotenuse-average", OffsetType::HypotenuseAverage),
    ("planes-intersection", OffsetType::PlanesIntersection),
];

/// `window --mode` and `picture-frame --mode`.
pub(crate) const INSET_MODES: &[(&str, InsetMode)] = &[
    ("edge-fraction", InsetMode::EdgeFraction),
    ("parallelogram", InsetMode::Parallelogram),
];

/// `tile --fill`.
pub(crate) const TILE_FILLS: &[(&str, TileFill)] = &[
    ("skip", TileFill::Skip),
    ("best", TileFill::Best),
    ("triangle-fan", TileFill::TriangleFan),
    ("triangle-hand", TileFill::TriangleHand),
    ("triangle-knit", TileFill::TriangleKnit),
    ("triangle-zigzag", TileFill::TriangleZigzag),
    ("quad-stitch", TileFill::QuadStitch),
    ("quad-fan", TileFill::QuadFan),
];

/// `tile --faces`.
pub(crate) const TILE_FACES: &[(&str, TileFaces)] = &[
    ("all", TileFaces::All),
    ("quads-and-more", TileFaces::QuadsAndMore),
    ("pentagons-and-more", TileFaces::PentagonsAndMore),
    ("triangles", TileFaces::Triangles),
    ("quads", TileFaces::Quads),
];
