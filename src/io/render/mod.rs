//! A shaded picture of a mesh: a small software rasterizer that writes PNG.
//!
//! The camera looks at the bounding box from a three-quarter view above, or
//! along one of the six axis directions ([`View`]), with z or y up ([`Up`]),
//! and fits the mesh to the picture. Faces are lit by a fixed light
//! beside the camera (Lambert shading plus ambient); front faces are blue-grey
//! and back faces orange, so a flipped face stands out. Coarse meshes get
//! their face edges drawn as thin dark lines (polygon edges only, not the
//! fan diagonals used to fill n-gons). Naked edges (edges of one face) are
//! always drawn, in red and a little wider, so open seams show even on dense
//! meshes. Each pixel averages 2 × 2 samples.

use std::io::Write;
use std::path::Path;

use glam::DVec3;

use super::{write_atomically, IoError};
use crate::buffers::try_vec;
use crate::error::Error;
use crate::mesh::topology::Edges;
use crate::mesh::{floor_to_i64, Mesh};

mod tiles;

use tiles::{NearestDepth, OpenTiles, Tiles, BIN, TILE};

/// Largest picture side, in pixels.
pub const MAX_SIDE: u32 = 4096;

/// Meshes with fewer faces than this get their edges drawn by default.
pub const EDGE_FACE_LIMIT: usize = 4000;

/// Pixels of picture per face below which face edges are not drawn by
/// default: denser edges merge into dark moiré instead of showing faces.
pub const EDGE_PIXELS_PER_FACE: usize = 300;

/// Where the camera looks from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum View {
    /// A three-quarter view from the front, right and above.
    #[default]
    Iso,
    /// From above, looking down the up axis.
    Top,
    /// From below.
    Bottom,
    /// From the front: from -y when z is up, from +z when y is up.
    Front,
    /// From the back.
    Back,
    /// From the left (-x).
    Left,
    /// From the right (+x).
    Right,
}

/// Which axis of the model points up.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Up {
    /// z up, as in Rhino and most CAD.
    #[default]
    Z,
    /// y up, as in many scans, game and film formats.
    Y,
}

/// A cut through the mesh: faces whose centroid lies on the side `normal`
/// points to are left out, so that what is inside shows.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Section {
    /// A point of the cutting plane.
    pub point: DVec3,
    /// The plane's normal, towards the part left out.
    pub normal: DVec3,
}

/// How to draw a picture.
#[derive(Debug, Clone, PartialEq)]
pub struct RenderOptions {
    /// Width in pixels, 1 to [`MAX_SIDE`].
    pub width: u32,
    /// Height in pixels, 1 to [`MAX_SIDE`].
    pub height: u32,
    /// Draw face edges; `None` draws them when the mesh has fewer than
    /// [`EDGE_FACE_LIMIT`] faces and the picture has at least
    /// [`EDGE_PIXELS_PER_FACE`] pixels per face.
    pub edges: Option<bool>,
    /// Where the camera looks from.
    pub view: View,
    /// Which axis of the model points up.
    pub up: Up,
    /// A cut-away: the faces beyond this plane are not drawn.
    pub section: Option<Section>,
    /// Edges drawn wide in violet (creases, say), as vertex pairs in either
    /// order; pairs that are not edges of the mesh are ignored.
    pub marked_edges: Vec<[u32; 2]>,
}

impl Default for RenderOptions {
    fn default() -> Self {
        RenderOptions {
            width: 800,
            height: 600,
            edges: None,
            view: View::Iso,
            up: Up::Z,
            section: None,
            marked_edges: Vec::new(),
        }
    }
}

/// An 8-bit RGB picture, rows from the top.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Image {
    pub width: u32,
    pub height: u32,
    /// `3 × width × height` bytes.
    pub pixels: Vec<u8>,
}

impl Image {
    /// The colour at column `x`, row `y`.
    pub fn pixel(&self, x: u32, y: u32) -> [u8; 3] {
        let i = 3 * (y as usize * self.width as usize + x as usize);
        [self.pixels[i], self.pixels[i + 1], self.pixels[i + 2]]
    }

    /// Encodes the picture as PNG.
    ///
    /// # Errors
    /// Whatever the writer returns.
    pub fn write_png(&self, w: &mut dyn Write) -> std::io::Result<()> {
        let mut encoder = png::Encoder::new(w, self.width, self.height);
        encoder.set_color(png::ColorType::Rgb);
        encoder.set_depth(png::BitDepth::Eight);
        let mut writer = encoder.write_header().map_err(std::io::Error::other)?;
        writer
            .write_image_data(&self.pixels)
            .map_err(std::io::Error::other)?;
        writer.finish().map_err(std::io::Error::other)
    }

    /// Saves the picture as a PNG file (written whole or not at all).
    ///
    /// # Errors
    /// As [`super::write_atomically`].
    pub fn save_png(&self, path: impl AsRef<Path>) -> Result<(), IoError> {
        write_atomically(path.as_ref(), |w| self.write_png(w))
    }
}

/// The background, a light grey.
pub const BACKGROUND: [f32; 3] = [0.96, 0.96, 0.95];
const FRONT: [f32; 3] = [0.60, 0.70, 0.84];
const BACK: [f32; 3] = [0.93, 0.50, 0.28];
const EDGE: [f32; 3] = [0.13, 0.14, 0.17];
const NAKED_EDGE: [f32; 3] = [0.85, 0.08, 0.10];
const MARKED_EDGE: [f32; 3] = [0.42, 0.12, 0.78];
/// Half the width of an edge line, in supersampled pixels.
const EDGE_HALF_WIDTH: f64 = 0.85;
/// Half the width of a naked edge line, in supersampled pixels.
const NAKED_HALF_WIDTH: f64 = 1.7;

/// How a side of a fan triangle is drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Side {
    /// Inside the polygon (a fan diagonal), or edges are off.
    Hidden,
    /// An edge asked to stand out ([`RenderOptions::marked_edges`]).
    Marked,
    /// A polygon edge.
    Edge,
    /// A polygon edge that only this face has.
    Naked,
}

/// Which corners' edges are drawn as marked or naked lines.
enum Outlines {
    /// Whether each corner's edge is naked, when no edge is marked.
    Naked(Vec<bool>),
    /// The mesh's edges, to find the marked ones.
    Edges { edges: Edges, marked: Vec<bool> },
}

impl Outlines {
    fn of(mesh: &Mesh, marked_edges: &[[u32; 2]]) -> Result<Outlines, Error> {
        if marked_edges.is_empty() {
            return Ok(Outlines::Naked(Edges::naked_corners(mesh)?));
        }
        let edges = Edges::try_new(mesh)?;
        let mut marked = vec![false; edges.edge_count()];
        for &[a, b] in marked_edges {
            if let Some(e) = edges.find_edge(a, b) {
                marked[e] = true;
            }
        }
        Ok(Outlines::Edges { edges, marked })
    }

    /// How the edge from `corner` stands out, if it does.
    fn of_corner(&self, corner: usize) -> Option<Side> {
        match self {
            Outlines::Naked(naked) => naked[corner].then_some(Side::Naked),
            Outlines::Edges { edges, marked } => {
                let edge = edges.corner_edges()[corner] as usize;
                if marked[edge] {
                    Some(Side::Marked)
                } else {
                    edges.is_naked_edge(edge).then_some(Side::Naked)
                }
            }
        }
    }
}

const SAMPLES: usize = 2;

/// Meshes with at least this many faces are drawn on two threads.
const PARALLEL_FACES: usize = 100_000;

/// The camera: an eye, its axes, and the map from view directions to pixels.
struct Camera {
    eye: DVec3,
    right: DVec3,
    up: DVec3,
    forward: DVec3,
    scale: f64,
    center: (f64, f64),
    size: (f64, f64),
}

impl Camera {
    fn fit(mesh: &Mesh, width: usize, height: usize, view: View, up: Up) -> Camera {
        let (lo, hi) = mesh.bounding_box().unwrap_or((DVec3::ZERO, DVec3::ONE));
        let target = (lo + hi) / 2.0;
        let radius = ((hi - lo).length() / 2.0).max(1e-9);
        // The model's right, front (towards a viewer in front) and up axes.
        let (model_right, model_up) = match up {
            Up::Z => (DVec3::X, DVec3::Z),
            Up::Y => (DVec3::X, DVec3::Y),
        };
        let model_front = model_right.cross(model_up);
        let toward_eye = match view {
            View::Iso => (model_right * 0.95 + model_front * 1.45 + model_up * 1.05).normalize(),
            View::Top => model_up,
            View::Bottom => -model_up,
            View::Front => model_front,
            View::Back => -model_front,
            View::Left => -model_right,
            View::Right => model_right,
        };
        // Looking along the up axis, the picture's top is the model's back.
        let screen_up = match view {
            View::Top | View::Bottom => -model_front,
            _ => model_up,
        };
        let eye = target + toward_eye * radius * 3.0;
        let forward = -toward_eye;
        let right = forward.cross(screen_up).normalize();
        let up = right.cross(forward);
        let mut camera = Camera {
            eye,
            right,
            up,
            forward,
            scale: 1.0,
            center: (0.0, 0.0),
            size: (width as f64, height as f64),
        };
        // Fit the projected vertices, with a margin, into the picture.
        let (mut min, mut max) = ((f64::MAX, f64::MAX), (f64::MIN, f64::MIN));
        for &p in mesh.positions() {
            let (x, y, _) = camera.project_unscaled(p);
            min = (min.0.min(x), min.1.min(y));
            max = (max.0.max(x), max.1.max(y));
        }
        if min.0 <= max.0 {
            let extent = ((max.0 - min.0) / camera.size.0).max((max.1 - min.1) / camera.size.1);
            camera.scale = 0.86 / extent.max(1e-12);
            camera.center = ((min.0 + max.0) / 2.0, (min.1 + max.1) / 2.0);
        }
        camera
    }

    fn project_unscaled(&self, p: DVec3) -> (f64, f64, f64) {
        let d = p - self.eye;
        let depth = d.dot(self.forward).max(1e-12);
        (d.dot(self.right) / depth, d.dot(self.up) / depth, depth)
    }

    /// Pixel coordinates (x right, y down) and depth.
    fn project(&self, p: DVec3) -> (f64, f64, f64) {
        let (x, y, depth) = self.project_unscaled(p);
        (
            self.size.0 / 2.0 + (x - self.center.0) * self.scale,
            self.size.1 / 2.0 - (y - self.center.1) * self.scale,
            depth,
        )
    }
}

/// Draws a mesh.
///
/// # Errors
/// [`Error::InvalidArgument`] for a width or height outside 1 to
/// [`MAX_SIDE`]; [`Error::OutOfMemory`] when the picture cannot be allocated.
pub fn render(mesh: &Mesh, options: &RenderOptions) -> Result<Image, Error> {
    render_with(mesh, options, None, true)
}

/// Draws a mesh whose front faces take the average of their vertices'
/// colours (RGBA from 0 to 1, alpha ignored), one per vertex; back faces
/// stay orange.
///
/// # Errors
/// As [`render`]; [`Error::InvalidArgument`] when there is not one colour per vertex.
pub fn render_coloured(
    mesh: &Mesh,
    options: &RenderOptions,
    colours: &[[f64; 4]],
) -> Result<Image, Error> {
    if colours.len() != mesh.vertex_count() {
        return Err(Error::InvalidArgument(format!(
            "{} colours for {} vertices",
            colours.len(),
            mesh.vertex_count()
        )));
    }
    render_with(mesh, options, Some(colours), true)
}

/// Draws a mesh; without `hide_tiles`, every face in order into a plain
/// z-buffer (what the tests hold the hidden tiles to).
fn render_with(
    mesh: &Mesh,
    options: &RenderOptions,
    colours: Option<&[[f64; 4]]>,
    hide_tiles: bool,
) -> Result<Image, Error> {
    for (name, side) in [("width", options.width), ("height", options.height)] {
        if side == 0 || side > MAX_SIDE {
            return Err(Error::InvalidArgument(format!(
                "picture {name} {side} is outside 1 to {MAX_SIDE}"
            )));
        }
    }
    let (w, h) = (
        options.width as usize * SAMPLES,
        options.height as usize * SAMPLES,
    );
    let mut canvas = Canvas::new(w, h)?;

    let camera = Camera::fit(mesh, w, h, options.view, options.up);
    let light = (camera.up * 0.7 - camera.right * 0.45 - camera.forward * 0.75).normalize();
    let fill = (camera.right * 0.6 - camera.forward * 0.4).normalize();
    let pixels = options.width as usize * options.height as usize;
    let edges = options.edges.unwrap_or(
        mesh.face_count() < EDGE_FACE_LIMIT && mesh.face_count() * EDGE_PIXELS_PER_FACE <= pixels,
    );

    let outlines = Outlines::of(mesh, &options.marked_edges)?;
    let side = |corner: usize| match outlines.of_corner(corner) {
        Some(outline) => outline,
        None if edges => Side::Edge,
        None => Side::Hidden,
    };

    // Draws a run of faces into a canvas. Large triangles wait in a batch
    // and are drawn nearest first, so that those behind find their tiles
    // hidden; the samples' keys make the order of drawing immaterial.
    let draw = |faces: std::ops::Range<usize>, canvas: &mut Canvas| {
        let mut corners = Vec::new();
        let mut screen = Vec::new();
        let mut batch = Batch::default();
        for f in faces {
            let first = mesh.face_start(f);
            corners.clear();
            corners.extend(mesh.face_positions(f));
            screen.clear();
            screen.extend(corners.iter().map(|&p| camera.project(p)));
            // A face that holds no sample's centre draws nothing.
            if covered_samples(&screen, (w, h)).is_none() {
                continue;
            }
            let normal = crate::mesh::analysis::newell_vector(&corners).normalize_or_zero();
            let centroid = corners.iter().sum::<DVec3>() / corners.len() as f64;
            if let Some(cut) = &options.section {
                if (centroid - cut.point).dot(cut.normal) > 0.0 {
                    continue;
                }
            }
            let front = normal.dot(camera.eye - centroid) >= 0.0;
            let face_colour = colours.map(|colours| {
                let face = mesh.face(f);
                let mut sum = [0.0f64; 3];
                for &v in face {
                    for (k, total) in sum.iter_mut().enumerate() {
                        *total += colours[v as usize][k].clamp(0.0, 1.0);
                    }
                }
                sum.map(|c| (c / face.len() as f64) as f32)
            });
            let (base, facing) = if front {
                (face_colour.unwrap_or(FRONT), normal)
            } else {
                (BACK, -normal)
            };
            let lambert = if facing == DVec3::ZERO {
                0.5
            } else {
                0.7 * facing.dot(light).max(0.0) + 0.22 * facing.dot(fill).max(0.0)
            };
            let shade = (0.34 + lambert) as f32;
            let shaded = base.map(|c| (c * shade).min(1.0));

            let n = screen.len();
            for i in 1..n - 1 {
                // Side k of the fan triangle (0, i, i + 1) is opposite its corner k:
                // the polygon's edges from corner i, from corner n − 1 (when
                // i + 1 is the last corner) and from corner 0 (when i is 1).
                let sides = [
                    side(first + i),
                    if i + 1 == n - 1 {
                        side(first + n - 1)
                    } else {
                        Side::Hidden
                    },
                    if i == 1 { side(first) } else { Side::Hidden },
                ];
                let triangle = [screen[0], screen[i], screen[i + 1]];
                let Some(bounds) = covered_samples(&triangle, (w, h)) else {
                    continue;
                };
                let paint = Paint {
                    shaded,
                    sides,
                    // Unique and rising in the order of drawing; past
                    // u32::MAX (four billion corners) ties keep the first drawn.
                    order: u32::try_from(first + i).unwrap_or(u32::MAX),
                };
                let area = doubled_area(triangle);
                let nearest = (hide_tiles && worth_hiding(area, bounds))
                    .then(|| NearestDepth::of(triangle, area))
                    .flatten();
                match nearest {
                    Some(nearest) => batch.push(
                        canvas,
                        Waiting {
                            triangle,
                            bounds,
                            paint,
                            nearest,
                        },
                    ),
                    None => fill_triangle(canvas, triangle, bounds, &paint, None),
                }
            }
        }
        batch.draw(canvas);
    };
    // Large meshes: the first half of the faces into the canvas, the
    // second into a canvas of its own, side by side; then each sample
    // takes the second's where its key is lower, as drawing every face into
    // one canvas would.
    let faces = mesh.face_count();
    if faces >= PARALLEL_FACES && rayon::current_num_threads() > 1 {
        let mut second = Canvas::new(w, h)?;
        let half = faces / 2;
        rayon::join(
            || draw(0..half, &mut canvas),
            || draw(half..faces, &mut second),
        );
        for (i, &key) in second.keys.iter().enumerate() {
            if key < canvas.keys[i] {
                canvas.color[i] = second.color[i];
            }
        }
    } else {
        draw(0..faces, &mut canvas);
    }
    let color = canvas.color;

    // Average each 2 × 2 block of samples.
    let mut pixels = try_vec(
        options.width as usize * options.height as usize * 3,
        "the picture",
    )?;
    for y in 0..options.height as usize {
        for x in 0..options.width as usize {
            let mut sum = [0.0f32; 3];
            for sy in 0..SAMPLES {
                for sx in 0..SAMPLES {
                    let c = color[(y * SAMPLES + sy) * w + x * SAMPLES + sx];
                    for k in 0..3 {
                        sum[k] += c[k];
                    }
                }
            }
            let n = (SAMPLES * SAMPLES) as f32;
            pixels.extend(sum.map(|s| (s / n * 255.0).round().clamp(0.0, 255.0) as u8));
        }
    }
    Ok(Image {
        width: options.width,
        height: options.height,
        pixels,
    })
}

/// How far outside a polygon's bounds a sample's centre may lie and still
/// be tested: far more than the rounding of the inside test, so that
/// leaving out the samples beyond it changes no pixel.
const BOUNDS_MARGIN: f64 = 1e-6;

/// The columns and rows of the samples whose centres (at `x + 0.5`,
/// `y + 0.5`) may lie inside the polygon `corners`, within the picture of
/// `w` × `h` samples; `None` when there are none, as for most faces of a
/// mesh with many faces to a pixel.
fn covered_samples(
    corners: &[(f64, f64, f64)],
    (w, h): (usize, usize),
) -> Option<([usize; 2], [usize; 2])> {
    let (low, high) = screen_box(corners);
    let span = |low: f64, high: f64, count: usize| -> Option<[usize; 2]> {
        let first = (low - 0.5 - BOUNDS_MARGIN).max(0.0);
        let last = (high - 0.5 + BOUNDS_MARGIN).min(count as f64 - 1.0);
        // `max` and `min` drop a NaN: neither is one.
        if first > last {
            return None;
        }
        // Both are at least 0 now, so truncating `last` floors it.
        let (first, last) = (ceil_of_non_negative(first), last as usize);
        (first <= last).then_some([first, last])
    };
    Some((span(low.0, high.0, w)?, span(low.1, high.1, h)?))
}

/// The samples drawn so far.
struct Canvas {
    w: usize,
    color: Vec<[f32; 3]>,
    /// Each sample's key: the `f32` depth's bits above the order of the
    /// triangle drawn there. The lowest key wins, the nearest and then the
    /// first in order, so faces drawn in any order give the picture of
    /// drawing them in order with a strict depth test.
    keys: Vec<u64>,
    tiles: Tiles,
}

impl Canvas {
    fn new(w: usize, h: usize) -> Result<Canvas, Error> {
        let mut color = try_vec(w * h, "the picture")?;
        color.resize(w * h, BACKGROUND);
        let mut keys = try_vec(w * h, "the depth buffer")?;
        keys.resize(w * h, u64::MAX);
        Ok(Canvas {
            w,
            color,
            keys,
            tiles: Tiles::new(w, h)?,
        })
    }
}

/// How a triangle is painted, and its place in the order of drawing.
#[derive(Debug, Clone, Copy)]
struct Paint {
    shaded: [f32; 3],
    sides: [Side; 3],
    order: u32,
}

/// A large triangle waiting to be drawn nearest first.
struct Waiting {
    triangle: [(f64, f64, f64); 3],
    bounds: ([usize; 2], [usize; 2]),
    paint: Paint,
    nearest: NearestDepth,
}

/// Large triangles waiting to be drawn, bin by bin, each bin's nearest
/// first.
#[derive(Default)]
struct Batch {
    triangles: Vec<Waiting>,
    /// Their bins in all.
    bins: usize,
    /// Each triangle's bins, keyed by the bin and its nearest depth there.
    order: Vec<(u64, u32)>,
}

/// A batch is drawn once it holds this many triangle bins, so that it stays
/// small beside the picture.
const BATCH_BINS: usize = 1 << 20;

impl Batch {
    /// Adds a triangle, drawing the batch when it is full.
    fn push(&mut self, canvas: &mut Canvas, waiting: Waiting) {
        let (columns, rows) = waiting.bounds;
        self.bins +=
            (columns[1] / BIN - columns[0] / BIN + 1) * (rows[1] / BIN - rows[0] / BIN + 1);
        self.triangles.push(waiting);
        if self.bins >= BATCH_BINS || self.triangles.len() > u32::MAX as usize {
            self.draw(canvas);
        }
    }

    /// Draws the waiting triangles and empties the batch.
    fn draw(&mut self, canvas: &mut Canvas) {
        let bins_across = canvas.w.div_ceil(BIN);
        let within = |[low, high]: [usize; 2], bin: usize| {
            [low.max(bin * BIN), high.min(bin * BIN + BIN - 1)]
        };
        self.order.clear();
        for (k, waiting) in self.triangles.iter().enumerate() {
            let (columns, rows) = waiting.bounds;
            for by in rows[0] / BIN..=rows[1] / BIN {
                for bx in columns[0] / BIN..=columns[1] / BIN {
                    let near = waiting.nearest.over(within(columns, bx), within(rows, by));
                    let bin = (by * bins_across + bx) as u64;
                    self.order.push(((bin << 32) | u64::from(near), k as u32));
                }
            }
        }
        self.order.sort_unstable();
        for &(key, k) in &self.order {
            let bin = (key >> 32) as usize;
            let (bx, by) = (bin % bins_across, bin / bins_across);
            let waiting = &self.triangles[k as usize];
            let (columns, rows) = waiting.bounds;
            let bounds = (within(columns, bx), within(rows, by));
            let nearest = Some(&waiting.nearest);
            fill_triangle(canvas, waiting.triangle, bounds, &waiting.paint, nearest);
        }
        self.triangles.clear();
        self.bins = 0;
    }
}

/// Whether a triangle of doubled area `doubled_area` covers enough samples,
/// and enough of each tile of its bounds, for its tiles to be worth
/// testing: finding a tile's farthest depth reads the whole tile.
fn worth_hiding(doubled_area: f64, (columns, rows): ([usize; 2], [usize; 2])) -> bool {
    let samples = doubled_area.abs() / 2.0;
    let tiles = (columns[1] / TILE - columns[0] / TILE + 1) * (rows[1] / TILE - rows[0] / TILE + 1);
    samples >= (TILE * TILE) as f64 && samples >= (TILE * tiles) as f64
}

/// The key of a sample at depth `z` of the triangle drawn `order`th, or
/// `None` for a depth past `f32`'s range (coordinates beyond about 1e38)
/// or NaN, which draws nothing.
#[inline]
fn depth_key(z: f64, order: u32) -> Option<u64> {
    let z = z as f32;
    // Depths are positive, and positive floats order as their bits.
    (z < f32::INFINITY).then(|| (u64::from(z.to_bits()) << 32) | u64::from(order))
}

/// Fills one triangle, z-buffered, within `bounds` (from [`covered_samples`],
/// or a part of them), drawing the sides marked in `paint` as lines; with
/// its `nearest` depth, skipping the tiles where everything drawn is nearer.
fn fill_triangle(
    canvas: &mut Canvas,
    triangle: [(f64, f64, f64); 3],
    (columns, rows): ([usize; 2], [usize; 2]),
    paint: &Paint,
    nearest: Option<&NearestDepth>,
) {
    let open = match nearest {
        Some(nearest) => {
            let bounds = (columns, rows);
            match canvas.tiles.open(nearest, &canvas.keys, canvas.w, bounds) {
                Some(open) => Some(open),
                None => return,
            }
        }
        None => None,
    };
    let open = open.as_ref();
    if rows[1] - rows[0] <= columns[1] - columns[0] {
        let spans = RowSpans::of(triangle, columns);
        let span = |py: f64| spans.columns(py);
        fill_samples(canvas, triangle, paint, rows, span, false, open);
    } else {
        // Taller than wide: down each column, by the spans of the triangle
        // mirrored in the diagonal (whose inside test is this one's, negated).
        let spans = RowSpans::of(triangle.map(|(x, y, z)| (y, x, z)), rows);
        let span = |px: f64| spans.columns(px);
        fill_samples(canvas, triangle, paint, columns, span, true, open);
    }
}

/// The lowest and highest screen x and y of `corners` (NaN coordinates
/// left out: `min` and `max` drop them).
fn screen_box(corners: &[(f64, f64, f64)]) -> ((f64, f64), (f64, f64)) {
    let (mut low, mut high) = (
        (f64::INFINITY, f64::INFINITY),
        (f64::NEG_INFINITY, f64::NEG_INFINITY),
    );
    for &(x, y, _) in corners {
        low = (low.0.min(x), low.1.min(y));
        high = (high.0.max(x), high.1.max(y));
    }
    (low, high)
}

/// Twice the signed area of the triangle's projection, as the inside test
/// divides by it.
fn doubled_area([a, b, c]: [(f64, f64, f64); 3]) -> f64 {
    (b.0 - a.0) * (c.1 - a.1) - (b.1 - a.1) * (c.0 - a.0)
}

/// [`fill_triangle`] over the samples of the rows `[first, last]`
/// (inclusive) and in each row those of the columns `span` gives for its
/// centres' y, or `down_columns`, of those columns and in each the rows
/// `span` gives for its centres' x. They must lie in the picture. Given
/// `open` tiles, the others are skipped.
fn fill_samples(
    canvas: &mut Canvas,
    [a, b, c]: [(f64, f64, f64); 3],
    paint: &Paint,
    [first, last]: [usize; 2],
    span: impl Fn(f64) -> Option<[usize; 2]>,
    down_columns: bool,
    open: Option<&OpenTiles>,
) {
    let area = doubled_area([a, b, c]);
    if !area.is_finite() || area.abs() < 1e-12 {
        return;
    }
    let w = canvas.w;
    let sides = paint.sides;
    // Length of the side opposite each corner, for distances to the sides:
    // worked out at the first pixel drawn, since most faces of a dense mesh
    // cover none.
    let side = |p: (f64, f64, f64), q: (f64, f64, f64)| (q.0 - p.0).hypot(q.1 - p.1);
    let mut side_lengths = None;
    let inverse_depth = [1.0 / a.2, 1.0 / b.2, 1.0 / c.2];
    for line in first..=last {
        if open.is_some_and(|open| !open.line(line, down_columns)) {
            continue;
        }
        let Some([start, end]) = span(line as f64 + 0.5) else {
            continue;
        };
        let mut chunk = start;
        while chunk <= end {
            // Up to the end of the tile.
            let chunk_end = end.min(chunk | (TILE - 1));
            let (x, y) = match down_columns {
                false => (chunk, line),
                true => (line, chunk),
            };
            if open.is_some_and(|open| !open.at(x, y)) {
                chunk = chunk_end + 1;
                continue;
            }
            for across in chunk..=chunk_end {
                let (x, y) = match down_columns {
                    false => (across, line),
                    true => (line, across),
                };
                let centre = (x as f64 + 0.5, y as f64 + 0.5);
                let Some((weights, z)) = sample_depth([a, b, c], area, inverse_depth, centre)
                else {
                    continue;
                };
                let i = y * w + x;
                let Some(key) = depth_key(z, paint.order) else {
                    continue;
                };
                if key >= canvas.keys[i] {
                    continue;
                }
                canvas.keys[i] = key;
                canvas.tiles.mark(x, y);
                let lengths: &[f64; 3] =
                    side_lengths.get_or_insert_with(|| [side(b, c), side(c, a), side(a, b)]);
                // Distance to side k: twice the area of (pixel, side) over its length.
                let distance = |k: usize| weights[k] * area.abs() / lengths[k].max(1e-12);
                let wide =
                    |kind: Side| (0..3).any(|k| sides[k] == kind && distance(k) < NAKED_HALF_WIDTH);
                let line = if wide(Side::Marked) {
                    Some(MARKED_EDGE)
                } else if wide(Side::Naked) {
                    Some(NAKED_EDGE)
                } else if (0..3).any(|k| sides[k] == Side::Edge && distance(k) < EDGE_HALF_WIDTH) {
                    Some(EDGE)
                } else {
                    None
                };
                let shaded = paint.shaded;
                canvas.color[i] = match line {
                    Some(ink) => [0, 1, 2].map(|k| shaded[k] * 0.15 + ink[k] * 0.85),
                    None => shaded,
                };
            }
            chunk = chunk_end + 1;
        }
    }
}

/// The barycentric weights of the sample centre `(px, py)` in the triangle
/// whose doubled signed area is `area`, and its depth, when it lies inside.
#[inline(always)]
fn sample_depth(
    [a, b, c]: [(f64, f64, f64); 3],
    area: f64,
    inverse_depth: [f64; 3],
    (px, py): (f64, f64),
) -> Option<([f64; 3], f64)> {
    let wa = ((b.0 - px) * (c.1 - py) - (b.1 - py) * (c.0 - px)) / area;
    let wb = ((c.0 - px) * (a.1 - py) - (c.1 - py) * (a.0 - px)) / area;
    let wc = 1.0 - wa - wb;
    if wa < 0.0 || wb < 0.0 || wc < 0.0 {
        return None;
    }
    let z = 1.0 / (wa * inverse_depth[0] + wb * inverse_depth[1] + wc * inverse_depth[2]);
    Some(([wa, wb, wc], z))
}

/// Where a triangle's side lets a row's samples in: the centres on one
/// side of where the side's line crosses the row, widened by `margin`.
#[derive(Debug, Clone, Copy)]
struct SideBound {
    /// The side's first corner and its x per unit of y along the side.
    start: (f64, f64),
    slope: f64,
    /// Whether the samples inside lie right of the crossing (else left).
    right: bool,
    margin: f64,
}

/// The columns of each row worth testing against a triangle: a superset of
/// the samples [`fill_samples`]' test lets in, so that a thin triangle
/// costs its rows, not its bounding box (a fan of slivers around one
/// vertex spans the picture with every face).
#[derive(Debug, Clone, Copy)]
struct RowSpans {
    sides: [Option<SideBound>; 3],
    columns: [usize; 2],
}

impl RowSpans {
    /// The spans of the triangle `corners` within the columns `[x0, x1]`.
    fn of(corners: [(f64, f64, f64); 3], [x0, x1]: [usize; 2]) -> RowSpans {
        let area = doubled_area(corners);
        let mut spans = RowSpans {
            sides: [None; 3],
            columns: [x0, x1],
        };
        let (low, high) = screen_box(&corners);
        // Far-off corners (behind the camera's plane, say): test every column.
        let reach = [low.0, low.1, high.0, high.1].map(f64::abs);
        if reach.into_iter().fold(0.0, f64::max) >= 1e9 {
            return spans;
        }
        // How far the test's rounding may move a side's sign, as a multiple
        // of the side's rise: each barycentric weight's products span at most
        // the bounding box (plus a sample), and the third weight is one minus
        // the other two.
        let (width, height) = (high.0 - low.0 + 1.0, high.1 - low.1 + 1.0);
        let rounding = 64.0 * f64::EPSILON * (width * height + area.abs());
        for (k, side) in spans.sides.iter_mut().enumerate() {
            // Side k is opposite corner k: the weight of corner k is zero on it.
            let (p, q) = (corners[(k + 1) % 3], corners[(k + 2) % 3]);
            let rise = p.1 - q.1;
            if rise == 0.0 {
                continue;
            }
            let slope = (q.0 - p.0) / rise;
            let margin = rounding / rise.abs()
                + 16.0 * f64::EPSILON * (p.0.abs() + height * slope.abs() + width)
                + 1e-6;
            // A side whose crossing is this uncertain bounds nothing.
            if margin < width {
                *side = Some(SideBound {
                    start: (p.0, p.1),
                    slope,
                    right: (area > 0.0) == (rise > 0.0),
                    margin,
                });
            }
        }
        spans
    }

    /// The first and last columns of the row of centres at `py` that may lie
    /// inside, or `None`.
    fn columns(&self, py: f64) -> Option<[usize; 2]> {
        let [x0, x1] = self.columns;
        // Bounds on the centre's x, `px = x + 0.5`.
        let (mut low, mut high) = (x0 as f64 + 0.5, x1 as f64 + 0.5);
        for side in self.sides.iter().flatten() {
            let crossing = side.start.0 + (side.start.1 - py) * side.slope;
            match side.right {
                true => low = low.max(crossing - side.margin),
                false => high = high.min(crossing + side.margin),
            }
        }
        if low > high {
            return None;
        }
        // `low` is at least `x0 + 0.5`, so both are at least 0.
        let (first, last) = (
            ceil_of_non_negative(low - 0.5),
            (high - 0.5) as i64 as usize,
        );
        (first <= last).then_some([first, last])
    }
}

/// `value.ceil() as usize` for a value of at least 0, through
/// [`floor_to_i64`]: the call to `ceil` cost a fifth of drawing a fan of
/// thin triangles.
#[inline]
fn ceil_of_non_negative(value: f64) -> usize {
    (-floor_to_i64(-value)) as usize
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_random::units;

    /// Renders on one thread, every face in order without tiles (a plain
    /// z-buffer with a strict depth test), and on two threads with tiles.
    fn in_order_and_with_tiles(
        mesh: &Mesh,
        options: &RenderOptions,
        colours: Option<&[[f64; 4]]>,
    ) -> (Image, Image) {
        let pool = |threads| {
            rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .unwrap()
        };
        let in_order = pool(1).install(|| render_with(mesh, options, colours, false).unwrap());
        let tiled = pool(2).install(|| render_with(mesh, options, colours, true).unwrap());
        (in_order, tiled)
    }

    /// A book: `pages` triangles on the edge from the origin to (1, 0, 0),
    /// at angles drawn at random over half a turn, in any order.
    fn book(pages: usize, next: &mut impl FnMut() -> f64) -> Mesh {
        let mut positions = vec![DVec3::ZERO, DVec3::X];
        let mut faces = Vec::new();
        for page in 0..pages {
            let angle = std::f64::consts::PI * next();
            let reach = 0.6 + 0.6 * next();
            let along = 0.2 + 0.6 * next();
            positions.push(DVec3::new(along, reach * angle.cos(), reach * angle.sin()));
            faces.push([0, 1, page as u32 + 2]);
        }
        Mesh::from_polygons(positions, faces).unwrap()
    }

    /// Large faces crossing one another, each drawn twice on vertices of its
    /// own (so the two tie in depth at most samples and the first in order
    /// must win), with quads and pentagons among them.
    fn crossing_faces(faces: usize, next: &mut impl FnMut() -> f64) -> Mesh {
        let mut positions = Vec::new();
        let mut polygons: Vec<Vec<u32>> = Vec::new();
        for face in 0..faces {
            let corners = 3 + face % 3;
            let centre = DVec3::new(next(), next(), next()) * 2.0;
            let (u, v) = (
                DVec3::new(next() - 0.5, next() - 0.5, next() - 0.5).normalize(),
                DVec3::new(next() - 0.5, next() - 0.5, next() - 0.5).normalize(),
            );
            let size = 0.5 + 1.5 * next();
            let ring: Vec<DVec3> = (0..corners)
                .map(|k| {
                    let t = std::f64::consts::TAU * k as f64 / corners as f64;
                    centre + (u * t.cos() + v * t.sin()) * size
                })
                .collect();
            // The copy turns the other way (its back shows where the first's
            // front does) from another corner, so its fan's triangles differ
            // and are sorted apart from the first's.
            let mut copy = ring.clone();
            copy.reverse();
            copy.rotate_left(1);
            for ring in [ring, copy] {
                let first = positions.len() as u32;
                positions.extend(&ring);
                polygons.push((first..first + corners as u32).collect());
            }
        }
        Mesh::from_polygons(positions, polygons).unwrap()
    }

    /// Skipping hidden tiles, drawing large triangles bin by bin nearest
    /// first, and the two threads' halves change no pixel: books seen from
    /// every side, crossing faces whose copies tie in depth, under vertex
    /// colours and marked edges, at picture sizes that cut tiles and bins.
    #[test]
    fn hidden_tiles_change_no_pixel() {
        let mut next = units(0x7a11_b00c_5eed_0001);
        let views = [
            View::Iso,
            View::Top,
            View::Bottom,
            View::Front,
            View::Back,
            View::Left,
            View::Right,
        ];
        let mut differing_from_background = 0;
        for case in 0..28 {
            let mesh = match case % 2 {
                0 => book([30, 400, 3000][case % 3], &mut next),
                _ => crossing_faces([5, 40, 200][case % 3], &mut next),
            };
            let colours: Vec<[f64; 4]> = (0..mesh.vertex_count())
                .map(|_| [next(), next(), next(), 1.0])
                .collect();
            let options = RenderOptions {
                width: 20 + (next() * 230.0) as u32,
                height: 20 + (next() * 170.0) as u32,
                view: views[case % 7],
                edges: Some(case % 4 == 1),
                marked_edges: if case % 5 == 0 { vec![[0, 1]] } else { vec![] },
                ..RenderOptions::default()
            };
            let colours = (case % 3 == 2).then_some(colours.as_slice());
            let (in_order, tiled) = in_order_and_with_tiles(&mesh, &options, colours);
            assert!(in_order == tiled, "case {case}: {options:?}");
            let background = BACKGROUND.map(|c| (c * 255.0).round() as u8);
            differing_from_background += in_order
                .pixels
                .chunks_exact(3)
                .filter(|p| *p != background)
                .count();
        }
        assert!(differing_from_background > 50_000);
    }

    /// A book of more pages than are drawn on one thread: its two halves
    /// merged give the picture of drawing every page in order.
    #[test]
    fn the_halves_of_a_large_book_merge_to_the_picture_in_order() {
        let mut next = units(0x0b00_c0f0_0000_1234);
        let mesh = book(PARALLEL_FACES + 10, &mut next);
        let options = RenderOptions {
            width: 48,
            height: 40,
            ..RenderOptions::default()
        };
        let (in_order, tiled) = in_order_and_with_tiles(&mesh, &options, None);
        assert!(in_order == tiled);
    }

    /// Triangles of every size from a hundredth of a sample to most of the
    /// picture, thin ones, and ones partly or wholly outside it: drawn
    /// within [`covered_samples`] they paint exactly what they paint when
    /// every sample of the picture is tested.
    #[test]
    fn covered_samples_leave_out_no_sample_a_triangle_paints() {
        let (w, h) = (37, 23);
        let mut next = units(0x9e37_79b9_7f4a_7c15u64);
        let (mut painted, mut skipped) = (0, 0);
        for case in 0..20_000 {
            let size = [0.01, 0.3, 1.0, 2.5, 12.0, 40.0][case % 6];
            let (cx, cy) = (next() * 50.0 - 6.0, next() * 36.0 - 6.0);
            let triangle: [(f64, f64, f64); 3] = std::array::from_fn(|_| {
                let [x, y, z, snap] = [next(), next(), next(), next()];
                let (x, y) = (cx + (x - 0.5) * size, cy + (y - 0.5) * size);
                // Corners on sample centres and halfway between, now and then.
                match snap < 0.2 {
                    true => ((x * 2.0).round() / 2.0, (y * 2.0).round() / 2.0, 1.0 + z),
                    false => (x, y, 1.0 + z),
                }
            });
            match covered_samples(&triangle, (w, h)) {
                None => skipped += 1,
                Some(_) if paints_as_every_sample(triangle, (w, h), case) => painted += 1,
                Some(_) => {}
            }
        }
        // The cases reach both sides of the test.
        assert!(
            painted > 1000 && skipped > 1000,
            "{painted} painted, {skipped} skipped"
        );
    }

    /// Fills `triangle` as a picture does and as testing every sample
    /// does, asserts both paint the same, and says whether it painted.
    fn paints_as_every_sample(
        triangle: [(f64, f64, f64); 3],
        (w, h): (usize, usize),
        case: usize,
    ) -> bool {
        let paint = Paint {
            shaded: FRONT,
            sides: [Side::Edge, Side::Naked, Side::Hidden],
            order: 7,
        };
        let mut within = Canvas::new(w, h).unwrap();
        let mut everywhere = Canvas::new(w, h).unwrap();
        if let Some(bounds) = covered_samples(&triangle, (w, h)) {
            fill_triangle(&mut within, triangle, bounds, &paint, None);
        }
        let every_column = |_| Some([0, w - 1]);
        fill_samples(
            &mut everywhere,
            triangle,
            &paint,
            [0, h - 1],
            every_column,
            false,
            None,
        );
        assert_eq!(within.color, everywhere.color, "case {case}: {triangle:?}");
        assert_eq!(within.keys, everywhere.keys, "case {case}: {triangle:?}");
        within.keys.iter().any(|&key| key != u64::MAX)
    }

    /// The triangles that make a row's span narrower than its bounds, and
    /// those whose sides' crossings are uncertain: slivers of a fan around
    /// one vertex (down to a millionth of a radian), sides that rise a
    /// trillionth of a sample over the picture, corners on sample centres,
    /// and corners far outside the picture.
    #[test]
    fn row_spans_leave_out_no_sample_a_sliver_paints() {
        let (w, h) = (61, 47);
        let mut next = units(0x2545_f491_4f6c_dd1du64);
        let mut painted = 0;
        for case in 0..40_000 {
            let centre = (next() * 70.0 - 5.0, next() * 55.0 - 4.0, 1.0 + next());
            let triangle = match case % 5 {
                0 => {
                    let radius = [2.0, 15.0, 40.0, 90.0][(case / 5) % 4];
                    let turn = [1e-6, 1e-3, 0.02, 0.3][(case / 20) % 4];
                    let angle = next() * std::f64::consts::TAU;
                    let mut rim = |angle: f64| {
                        let (y, x) = angle.sin_cos();
                        (centre.0 + radius * x, centre.1 + radius * y, 1.0 + next())
                    };
                    [centre, rim(angle), rim(angle + turn)]
                }
                1 => {
                    let rise = [0.0, 1e-12, 1e-7, 1e-3][(case / 5) % 4];
                    let y = (next() * 47.0).round() + 0.5 * ((case / 20) % 2) as f64;
                    let (x0, x1) = (next() * 80.0 - 10.0, next() * 80.0 - 10.0);
                    [(x0, y, 1.5), (x1, y + rise, 1.2), centre]
                }
                2 => {
                    // Corners on sample centres: the test's ties.
                    let on = |_| {
                        (
                            (next() * 61.0).floor() + 0.5,
                            (next() * 47.0).floor() + 0.5,
                            1.0 + next(),
                        )
                    };
                    std::array::from_fn(on)
                }
                3 => {
                    // A side through a sample's centre, to within rounding:
                    // the inside test and the crossing round apart there.
                    let at = ((next() * 61.0).floor() + 0.5, (next() * 47.0).floor() + 0.5);
                    let (y, x) = (next() * std::f64::consts::TAU).sin_cos();
                    let (back, on) = (1.0 + 30.0 * next(), 1.0 + 30.0 * next());
                    let a = (at.0 - back * x, at.1 - back * y, 1.0 + next());
                    let b = (at.0 + on * x, at.1 + on * y, 1.0 + next());
                    [a, b, (centre.0, centre.1, 1.5)]
                }
                _ => {
                    let far = [1e5, 1e8, 1e10, 1e15][(case / 5) % 4];
                    let angle = next() * std::f64::consts::TAU;
                    let (y, x) = angle.sin_cos();
                    let corner = (centre.0 + far * x, centre.1 + far * y, 2.0);
                    [
                        centre,
                        corner,
                        (centre.0 + 3.0 * next(), centre.1 + 3.0 * next(), 1.0),
                    ]
                }
            };
            if paints_as_every_sample(triangle, (w, h), case) {
                painted += 1;
            }
        }
        assert!(painted > 15_000, "{painted} painted");
    }

    /// A thin triangle's rows are tested only near it.
    #[test]
    fn row_spans_of_a_sliver_are_narrow() {
        let sliver = [(10.2, 5.3, 1.0), (90.7, 60.1, 1.0), (90.9, 60.0, 1.0)];
        let spans = RowSpans::of(sliver, [0, 99]);
        let mut tested = 0;
        for y in 5..61 {
            let py = y as f64 + 0.5;
            // Where the side from the first corner crosses the row.
            let along = 10.2 + (py - 5.3) * (90.7 - 10.2) / (60.1 - 5.3);
            if let Some([first, last]) = spans.columns(py) {
                assert!(
                    (first as f64 + 0.5 - along).abs() < 1.0,
                    "row {y}: {first}, {along}"
                );
                tested += last - first + 1;
            }
        }
        // Its bounding box holds 81 × 55 centres.
        assert!((5..=55).contains(&tested), "{tested} samples tested");
        // Outside the rows the triangle spans: none.
        assert_eq!(spans.columns(2.5), None);
    }

    #[test]
    fn ceil_of_non_negative_is_ceil() {
        let cases = [
            0.0,
            1e-300,
            0.25,
            0.5,
            1.0 - f64::EPSILON,
            1.0,
            1.5,
            2.0,
            4096.5,
            1e15 + 0.5,
            2f64.powi(53),
        ];
        for value in cases.into_iter().chain((0..1000).map(|k| k as f64 / 7.0)) {
            assert_eq!(
                ceil_of_non_negative(value),
                value.ceil() as usize,
                "{value:e}"
            );
        }
    }

    #[test]
    fn covered_samples_are_the_centres_within_the_bounds() {
        let at = |x: f64, y: f64| (x, y, 1.0);
        // Centres at 2.5 and 3.5 lie within [2.5, 3.6]; 4.5 does not.
        assert_eq!(
            covered_samples(&[at(2.5, 0.2), at(3.6, 0.9)], (10, 10)),
            Some(([2, 3], [0, 0]))
        );
        // Between two centres, and off the picture.
        assert_eq!(
            covered_samples(&[at(2.6, 0.6), at(3.4, 1.4)], (10, 10)),
            None
        );
        assert_eq!(
            covered_samples(&[at(-3.0, 2.0), at(-0.6, 4.0)], (10, 10)),
            None
        );
        assert_eq!(
            covered_samples(&[at(9.6, 2.0), at(20.0, 4.0)], (10, 10)),
            None
        );
        // Clipped to the picture.
        assert_eq!(
            covered_samples(&[at(-5.0, -5.0), at(50.0, 50.0)], (10, 8)),
            Some(([0, 9], [0, 7]))
        );
    }
}
