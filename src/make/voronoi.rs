//! Voronoi cells of points on a plane, clipped to a boundary polygon and
//! optionally to a circle around each point.
//!
//! Each cell is built as the intersection of half-planes: the cell of site
//! `s` is the set of points nearer to `s` than to any of its Delaunay
//! neighbours (the Delaunay graph, from `spade`, holds every pair of sites
//! whose cells share an edge, so no other site can cut the cell). Starting
//! from the boundary (convex) or its bounding rectangle (concave), each
//! neighbour's bisector clips the polygon (Sutherland-Hodgman against one
//! half-plane at a time), then the circle does, as a convex polygon of
//! [`CIRCLE_SEGMENTS`] sides. A concave boundary is then intersected with the
//! convex cell by `geo`'s `BooleanOps`; its output vertices are snapped back
//! to the exactly computed candidates (cell corners, boundary corners,
//! edge crossings), so the result has the precision of `f64`, not of the
//! clipper's internal integer grid.

use geo::{BooleanOps, Coord, LineString, Polygon};
use glam::{DVec2, DVec3};
use spade::Triangulation;

use crate::buffers::try_vec;
use crate::error::{Error, Result, MAX_ELEMENTS};
use crate::make::delaunay::project_and_triangulate;
use crate::make::plane::{check_points, Plane};
use crate::mesh::{bounds_2d, Mesh};

/// Number of sides of the polygon that stands for the circle of a given
/// radius: its corners lie on the circle, so every cell vertex stays within
/// the radius (the polygon's area is 0.16 % below the circle's).
pub const CIRCLE_SEGMENTS: usize = 64;

/// How far the default boundary extends past the points' bounding rectangle,
/// on every side, as a fraction of the rectangle's larger side.
pub const DEFAULT_MARGIN: f64 = 0.1;

/// The Voronoi cell of each point, as a closed polygon on `plane`.
///
/// - `points` are projected onto `plane`; cells lie in the plane.
/// - `boundary` is a simple polygon (convex or not, either winding, not
///   repeating its first corner at the end, projected onto the plane); cells
///   are clipped to it. Without it the boundary is the rectangle (in plane
///   coordinates) around the points grown on every side by
///   [`DEFAULT_MARGIN`] of its larger side (by 1 unit when all points
///   coincide).
/// - `radius`, when given, clips each cell further to the
///   [`CIRCLE_SEGMENTS`]-gon inscribed in the circle of that radius around
///   its point.
///
/// Returns one polygon per input point, counter-clockwise seen from the
/// plane's normal, without a repeated closing corner. A point outside the
/// boundary takes no part in the diagram and gets an empty cell; so does a
/// point whose projection repeats an earlier one (the first keeps the cell),
/// so the cells never overlap. With a concave boundary a convex cell may meet
/// the boundary in more than one piece; the piece containing the point (or
/// nearest to it) is kept and the others are dropped, which leaves those
/// areas uncovered. With one point inside, its cell is the whole boundary.
///
/// # Errors
/// - [`Error::InvalidArgument`] naming a point or boundary corner with a
///   non-finite coordinate, a radius that is not a positive finite number, a
///   boundary of fewer than 3 corners or one that crosses itself (naming the
///   two edges).
/// - [`Error::DegenerateInput`] for a boundary of zero area.
/// - [`Error::ResultTooLarge`] for more than [`MAX_ELEMENTS`] points (one
///   cell each), before anything is allocated.
pub fn voronoi(
    points: &[DVec3],
    plane: &Plane,
    boundary: Option<&[DVec3]>,
    radius: Option<f64>,
) -> Result<Vec<Vec<DVec3>>> {
    if points.len() as u64 > MAX_ELEMENTS {
        return Err(Error::ResultTooLarge(format!(
            "{} points would make as many cells; the limit is {MAX_ELEMENTS}",
            points.len()
        )));
    }
    check_points(points, "point")?;
    if let Some(r) = radius {
        if !(r.is_finite() && r > 0.0) {
            return Err(Error::InvalidArgument(format!(
                "the radius is {r}; it must be a positive finite number"
            )));
        }
    }
    let sites: Vec<DVec2> = points.iter().map(|&p| plane.to_plane(p)).collect();
    // Name a point out of the triangulation's range by its index among all points.
    for (i, uv) in sites.iter().enumerate() {
        if !uv.is_finite() || uv.abs().max_element() > spade::MAX_ALLOWED_VALUE {
            return Err(Error::InvalidArgument(format!(
                "point {i} projects to ({}, {}), too far from the plane's origin for the triangulation",
                uv.x, uv.y
            )));
        }
    }
    let boundary = match boundary {
        Some(corners) => Boundary::from_corners(corners, plane)?,
        None => Boundary::around(&sites),
    };
    let inside: Vec<usize> = (0..sites.len())
        .filter(|&i| boundary.contains(sites[i]))
        .collect();
    let mut cells: Vec<Vec<DVec3>> = try_vec(points.len(), "the cells")?;
    cells.resize(points.len(), Vec::new());
    if inside.is_empty() {
        return Ok(cells);
    }
    // Delaunay of the projections of the points inside, on the XY plane of plane coordinates.
    let inside_points: Vec<DVec3> = inside.iter().map(|&i| sites[i].extend(0.0)).collect();
    let projected = project_and_triangulate(&inside_points, &Plane::xy())?;
    let triangulation = &projected.triangulation;
    let tolerance = boundary.scale * 1e-12;
    for vertex in triangulation.vertices() {
        let point = inside[projected.vertex_points[vertex.fix().index()]];
        let site = sites[point];
        let mut cell = boundary.convex_start.clone();
        for edge in vertex.out_edges() {
            let p = edge.to().position();
            let neighbour = DVec2::new(p.x, p.y);
            let normal = neighbour - site;
            let middle = (neighbour + site) * 0.5;
            cell = clip_half_plane(&cell, normal, middle.dot(normal), tolerance);
        }
        if let Some(r) = radius {
            for k in 0..CIRCLE_SEGMENTS {
                let a = circle_corner(site, r, k);
                let b = circle_corner(site, r, k + 1);
                let edge = b - a;
                // Keep the left of each counter-clockwise edge.
                let normal = DVec2::new(edge.y, -edge.x);
                cell = clip_half_plane(&cell, normal, normal.dot(a), tolerance);
            }
        }
        if !boundary.is_convex && cell.len() >= 3 {
            cell = boundary.intersect_concave(&cell, site, tolerance);
        }
        if cell.len() >= 3 && signed_area(&cell) > 0.0 {
            cells[point] = cell.iter().map(|&uv| plane.to_world(uv)).collect();
        }
    }
    Ok(cells)
}

/// A mesh with one n-gon face per non-empty cell, each with its own
/// vertices (cells share no vertices: weld the mesh to join them). Faces
/// follow the cells' order; empty cells are skipped.
///
/// # Errors
/// [`Error::InvalidMesh`] when a non-empty cell has fewer than 3 corners
/// (naming its face) or a non-finite corner (naming its vertex);
/// [`Error::ResultTooLarge`] when the cells have more than [`MAX_ELEMENTS`]
/// corners or faces.
pub fn cells_to_mesh(cells: &[Vec<DVec3>]) -> Result<Mesh> {
    let total: u64 = cells.iter().map(|c| c.len() as u64).sum();
    if total > MAX_ELEMENTS || cells.len() as u64 > MAX_ELEMENTS {
        return Err(Error::ResultTooLarge(format!(
            "{} cells with {total} corners in all would pass the limit of {MAX_ELEMENTS}",
            cells.len()
        )));
    }
    let total = total as usize;
    let mut positions = try_vec(total, "the cells' corners")?;
    let mut polygons = try_vec::<Vec<u32>>(cells.len(), "the cells' faces")?;
    for cell in cells.iter().filter(|c| !c.is_empty()) {
        let first = positions.len() as u32;
        positions.extend_from_slice(cell);
        polygons.push((first..first + cell.len() as u32).collect());
    }
    Ok(Mesh::from_polygons(positions, polygons)?)
}

/// The boundary in plane coordinates, counter-clockwise.
struct Boundary {
    corners: Vec<DVec2>,
    is_convex: bool,
    /// The boundary when convex, else its bounding rectangle: where clipping starts.
    convex_start: Vec<DVec2>,
    /// The larger side of the bounding rectangle: the length tolerances scale with.
    scale: f64,
}

impl Boundary {
    fn from_corners(corners: &[DVec3], plane: &Plane) -> Result<Boundary> {
        check_points(corners, "boundary corner")?;
        let mut ring: Vec<DVec2> = Vec::with_capacity(corners.len());
        for &c in corners {
            let uv = plane.to_plane(c);
            if ring.last() != Some(&uv) {
                ring.push(uv);
            }
        }
        while ring.len() > 1 && ring.first() == ring.last() {
            ring.pop();
        }
        if ring.len() < 3 {
            return Err(Error::InvalidArgument(format!(
                "the boundary has {} distinct corners on the plane; a polygon needs at least 3",
                ring.len()
            )));
        }
        check_simple(&ring)?;
        let area = signed_area(&ring);
        let (lo, hi) = bounds_2d(&ring);
        let scale = (hi - lo).max_element();
        if area.abs() <= scale * scale * 1e-14 {
            return Err(Error::DegenerateInput(
                "the boundary encloses no area on the plane".into(),
            ));
        }
        if area < 0.0 {
            ring.reverse();
        }
        let n = ring.len();
        let is_convex = (0..n).all(|i| {
            let (a, b, c) = (ring[i], ring[(i + 1) % n], ring[(i + 2) % n]);
            (b - a).perp_dot(c - b) >= -scale * scale * 1e-14
        });
        let convex_start = if is_convex {
            ring.clone()
        } else {
            rectangle(lo - DVec2::splat(scale), hi + DVec2::splat(scale))
        };
        Ok(Boundary {
            corners: ring,
            is_convex,
            convex_start,
            scale,
        })
    }

    fn around(sites: &[DVec2]) -> Boundary {
        let (lo, hi) = if sites.is_empty() {
            (DVec2::ZERO, DVec2::ZERO)
        } else {
            bounds_2d(sites)
        };
        let size = (hi - lo).max_element();
        let margin = if size > 0.0 {
            size * DEFAULT_MARGIN
        } else {
            1.0
        };
        let corners = rectangle(lo - DVec2::splat(margin), hi + DVec2::splat(margin));
        Boundary {
            convex_start: corners.clone(),
            corners,
            is_convex: true,
            scale: size + 2.0 * margin,
        }
    }

    /// Whether `p` lies inside or on the boundary (nonzero winding).
    fn contains(&self, p: DVec2) -> bool {
        on_polygon(&self.corners, p, self.scale * 1e-12) || winding(&self.corners, p) != 0
    }

    /// The piece of `cell ∩ boundary` containing (or nearest to) `site`.
    fn intersect_concave(&self, cell: &[DVec2], site: DVec2, tolerance: f64) -> Vec<DVec2> {
        // Exact candidates for the corners of the intersection.
        let mut candidates: Vec<DVec2> = Vec::new();
        let mut crossings = 0usize;
        let (n, m) = (cell.len(), self.corners.len());
        for i in 0..n {
            for j in 0..m {
                let crossing = segment_intersection(
                    cell[i],
                    cell[(i + 1) % n],
                    self.corners[j],
                    self.corners[(j + 1) % m],
                );
                if let Some(x) = crossing {
                    candidates.push(x);
                    crossings += 1;
                }
            }
        }
        if crossings == 0 && cell.iter().all(|&p| self.contains(p)) {
            return cell.to_vec();
        }
        candidates.extend_from_slice(cell);
        candidates.extend_from_slice(&self.corners);
        let pieces = to_geo(cell).intersection(&to_geo(&self.corners));
        let mut best: Option<(f64, Vec<DVec2>)> = None;
        for piece in pieces.iter() {
            let coords = &piece.exterior().0;
            let mut ring: Vec<DVec2> = Vec::with_capacity(coords.len());
            for c in coords.iter().take(coords.len().saturating_sub(1)) {
                let p = DVec2::new(c.x, c.y);
                let snapped = candidates
                    .iter()
                    .copied()
                    .min_by(|a, b| {
                        (*a - p)
                            .length_squared()
                            .total_cmp(&(*b - p).length_squared())
                    })
                    .filter(|q| (*q - p).length() <= self.scale * 1e-6)
                    .unwrap_or(p);
                if ring.last() != Some(&snapped) {
                    ring.push(snapped);
                }
            }
            while ring.len() > 1 && ring.first() == ring.last() {
                ring.pop();
            }
            if ring.len() < 3 {
                continue;
            }
            if signed_area(&ring) < 0.0 {
                ring.reverse();
            }
            let distance = if winding(&ring, site) != 0 || on_polygon(&ring, site, tolerance) {
                0.0
            } else {
                distance_to_polygon(&ring, site)
            };
            if best.as_ref().is_none_or(|(d, _)| distance < *d) {
                best = Some((distance, ring));
            }
        }
        best.map(|(_, ring)| ring).unwrap_or_default()
    }
}

fn to_geo(ring: &[DVec2]) -> Polygon<f64> {
    let coords: Vec<Coord<f64>> = ring.iter().map(|p| Coord { x: p.x, y: p.y }).collect();
    Polygon::new(LineString::new(coords), Vec::new())
}

fn rectangle(lo: DVec2, hi: DVec2) -> Vec<DVec2> {
    vec![lo, DVec2::new(hi.x, lo.y), hi, DVec2::new(lo.x, hi.y)]
}

fn circle_corner(center: DVec2, radius: f64, k: usize) -> DVec2 {
    let angle = std::f64::consts::TAU * (k % CIRCLE_SEGMENTS) as f64 / CIRCLE_SEGMENTS as f64;
    center + DVec2::new(angle.cos(), angle.sin()) * radius
}

/// The signed area (positive counter-clockwise), by the shoelace formula.
pub(crate) fn signed_area(ring: &[DVec2]) -> f64 {
    let n = ring.len();
    (0..n)
        .map(|i| ring[i].perp_dot(ring[(i + 1) % n]))
        .sum::<f64>()
        * 0.5
}

/// Keeps the part of a convex polygon where `normal · p <= offset`
/// (Sutherland-Hodgman against one half-plane); corners closer than
/// `tolerance` to the previous one are dropped.
fn clip_half_plane(polygon: &[DVec2], normal: DVec2, offset: f64, tolerance: f64) -> Vec<DVec2> {
    let n = polygon.len();
    let mut out: Vec<DVec2> = Vec::with_capacity(n + 1);
    let push = |p: DVec2, out: &mut Vec<DVec2>| {
        if out.last().is_none_or(|q| (*q - p).length() > tolerance) {
            out.push(p);
        }
    };
    for i in 0..n {
        let a = polygon[i];
        let b = polygon[(i + 1) % n];
        let fa = normal.dot(a) - offset;
        let fb = normal.dot(b) - offset;
        if fa <= 0.0 {
            push(a, &mut out);
        }
        if (fa < 0.0 && fb > 0.0) || (fa > 0.0 && fb < 0.0) {
            push(a + (b - a) * (fa / (fa - fb)), &mut out);
        }
    }
    while out.len() > 1 && (out[0] - out[out.len() - 1]).length() <= tolerance {
        out.pop();
    }
    if out.len() < 3 {
        out.clear();
    }
    out
}

/// The winding number of a closed ring around `p` (Sunday's crossing rule).
fn winding(ring: &[DVec2], p: DVec2) -> i32 {
    let n = ring.len();
    let mut w = 0;
    for i in 0..n {
        let (a, b) = (ring[i], ring[(i + 1) % n]);
        let side = (b - a).perp_dot(p - a);
        if a.y <= p.y {
            if b.y > p.y && side > 0.0 {
                w += 1;
            }
        } else if b.y <= p.y && side < 0.0 {
            w -= 1;
        }
    }
    w
}

fn point_segment_distance(p: DVec2, a: DVec2, b: DVec2) -> f64 {
    let ab = b - a;
    let t = if ab.length_squared() > 0.0 {
        ((p - a).dot(ab) / ab.length_squared()).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (a + ab * t - p).length()
}

fn distance_to_polygon(ring: &[DVec2], p: DVec2) -> f64 {
    let n = ring.len();
    (0..n)
        .map(|i| point_segment_distance(p, ring[i], ring[(i + 1) % n]))
        .fold(f64::INFINITY, f64::min)
}

fn on_polygon(ring: &[DVec2], p: DVec2, tolerance: f64) -> bool {
    distance_to_polygon(ring, p) <= tolerance
}

/// The crossing point of segments `ab` and `cd`, when they cross at a single point.
fn segment_intersection(a: DVec2, b: DVec2, c: DVec2, d: DVec2) -> Option<DVec2> {
    let r = b - a;
    let s = d - c;
    let denominator = r.perp_dot(s);
    if denominator == 0.0 {
        return None;
    }
    let t = (c - a).perp_dot(s) / denominator;
    let u = (c - a).perp_dot(r) / denominator;
    ((0.0..=1.0).contains(&t) && (0.0..=1.0).contains(&u)).then(|| a + r * t)
}

/// Whether two closed segments share a point (collinear overlaps included).
fn segments_touch(a: DVec2, b: DVec2, c: DVec2, d: DVec2) -> bool {
    let orient = |p: DVec2, q: DVec2, r: DVec2| (q - p).perp_dot(r - p);
    let (d1, d2) = (orient(c, d, a), orient(c, d, b));
    let (d3, d4) = (orient(a, b, c), orient(a, b, d));
    if ((d1 > 0.0 && d2 < 0.0) || (d1 < 0.0 && d2 > 0.0))
        && ((d3 > 0.0 && d4 < 0.0) || (d3 < 0.0 && d4 > 0.0))
    {
        return true;
    }
    let within = |p: DVec2, q: DVec2, r: DVec2| {
        r.x >= p.x.min(q.x) && r.x <= p.x.max(q.x) && r.y >= p.y.min(q.y) && r.y <= p.y.max(q.y)
    };
    (d1 == 0.0 && within(c, d, a))
        || (d2 == 0.0 && within(c, d, b))
        || (d3 == 0.0 && within(a, b, c))
        || (d4 == 0.0 && within(a, b, d))
}

/// Refuses a ring whose non-adjacent edges touch (a quadratic check: boundaries are small).
fn check_simple(ring: &[DVec2]) -> Result<()> {
    let n = ring.len();
    for i in 0..n {
        for j in i + 1..n {
            let adjacent = j == i + 1 || (i == 0 && j == n - 1);
            let (a, b) = (ring[i], ring[(i + 1) % n]);
            let (c, d) = (ring[j], ring[(j + 1) % n]);
            let crosses = if adjacent {
                // Adjacent edges meet at their shared corner; they must not fold back over each other.
                let (shared, p, q) = if j == i + 1 { (b, a, d) } else { (a, b, c) };
                (p - shared).perp_dot(q - shared) == 0.0 && (p - shared).dot(q - shared) > 0.0
            } else {
                segments_touch(a, b, c, d)
            };
            if crosses {
                return Err(Error::InvalidArgument(format!(
                    "the boundary is not a simple polygon: its edges {i} and {j} meet"
                )));
            }
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests;
