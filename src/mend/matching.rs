//! Picked points and lines matched to a mesh's vertices and edges: how a
//! host turns the points and lines a designer draws into the vertex indices
//! that creases and corners are given by. The vertices are found through
//! the weld's spatial hash, never by comparing every pair.

use glam::DVec3;

use super::weld::{within, Cell, CellGrid, CellMap};
use crate::buffers::try_vec;
use crate::error::{Error, Result};
use crate::mesh::{check_tolerance, Mesh};

/// A mesh's vertices in the weld's grid, for finding those within a
/// tolerance of given points (the crease and corner inputs of a canvas
/// given as points and lines rather than indices).
struct VertexLookup<'a> {
    positions: &'a [DVec3],
    tolerance: f64,
    grid: CellGrid,
    /// Vertices sorted by cell; `cells` maps a cell to its range here.
    sorted: Vec<u32>,
    cells: CellMap<(u32, u32)>,
}

impl<'a> VertexLookup<'a> {
    fn new(positions: &'a [DVec3], tolerance: f64) -> Result<VertexLookup<'a>> {
        check_tolerance(tolerance)?;
        let grid = CellGrid::new(positions.iter().copied(), tolerance);
        let entries = grid.sorted_cells(positions, "the vertex cells")?;
        let mut sorted = try_vec::<u32>(positions.len(), "the vertex cells")?;
        sorted.extend(entries.iter().map(|&(_, v)| v));
        let mut cells = CellMap::default();
        let mut start = 0;
        while start < entries.len() {
            let key = entries[start].0;
            let end = start + entries[start..].partition_point(|e| e.0 == key);
            cells.insert(key, (start as u32, end as u32));
            start = end;
        }
        Ok(VertexLookup {
            positions,
            tolerance,
            grid,
            sorted,
            cells,
        })
    }

    /// Fills `found` with the vertices at most the tolerance from `p` and
    /// their distances, nearest first (the lower index first on a tie).
    fn near(&self, p: DVec3, found: &mut Vec<(f64, u32)>) {
        found.clear();
        let Cell(centre) = self.grid.cell(p);
        for dx in -1..=1 {
            for dy in -1..=1 {
                for dz in -1..=1 {
                    // A cell past the end of i64 holds no vertex (vertex
                    // cells stay far inside it, see `CellGrid::new`).
                    let (Some(x), Some(y), Some(z)) = (
                        centre[0].checked_add(dx),
                        centre[1].checked_add(dy),
                        centre[2].checked_add(dz),
                    ) else {
                        continue;
                    };
                    let Some(&(start, end)) = self.cells.get(&Cell([x, y, z])) else {
                        continue;
                    };
                    for &v in &self.sorted[start as usize..end as usize] {
                        let q = self.positions[v as usize];
                        if within(p, q, self.tolerance) {
                            found.push((distance(p, q), v));
                        }
                    }
                }
            }
        }
        found.sort_unstable_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
    }
}

/// The distance from `p` to `q`, scaled as [`within`] scales it so that it
/// neither underflows nor overflows.
fn distance(p: DVec3, q: DVec3) -> f64 {
    let d = p - q;
    let unit = d.abs().max_element();
    if unit == 0.0 {
        0.0
    } else {
        unit * (d / unit).length()
    }
}

fn check_finite_point(p: DVec3, what: &str) -> Result<()> {
    if p.is_finite() {
        Ok(())
    } else {
        Err(Error::InvalidArgument(format!(
            "{what} is ({}, {}, {}); its coordinates must be finite",
            p.x, p.y, p.z
        )))
    }
}

/// For each point, the vertex of `mesh` nearest to it within `tolerance`
/// (the lower index when two are equally near), found through the weld's
/// spatial hash: the way a host turns picked points into the vertex indices
/// that corners and creases are given by.
///
/// # Errors
/// [`Error::InvalidArgument`] when `tolerance` is negative, NaN or infinite,
/// when a point has a non-finite coordinate, or when a point has no vertex
/// within `tolerance` (the message names the point's index, its coordinates
/// and the tolerance); [`Error::OutOfMemory`] when the lookup cannot be
/// allocated.
pub fn match_points_to_vertices(mesh: &Mesh, points: &[DVec3], tolerance: f64) -> Result<Vec<u32>> {
    let lookup = VertexLookup::new(mesh.positions(), tolerance)?;
    let mut vertices = try_vec::<u32>(points.len(), "the matched vertices")?;
    let mut found = Vec::new();
    for (i, &p) in points.iter().enumerate() {
        check_finite_point(p, &format!("point {i}"))?;
        lookup.near(p, &mut found);
        let Some(&(_, v)) = found.first() else {
            return Err(Error::InvalidArgument(format!(
                "point {i} at ({}, {}, {}) is no vertex of the mesh within {tolerance}",
                p.x, p.y, p.z
            )));
        };
        vertices.push(v);
    }
    Ok(vertices)
}

/// For each line (its two end points), the edge of `mesh` whose end points
/// lie within `tolerance` of the line's, in either direction, as the pair of
/// its vertices in the line's direction (the vertex near the line's start
/// first). When several vertices are within reach of an end, the pair that
/// is an edge and is nearest (the smallest sum of the two distances) wins.
///
/// # Errors
/// [`Error::InvalidArgument`] when `tolerance` is negative, NaN or infinite,
/// when an end point has a non-finite coordinate, or when a line matches no
/// edge (the message names the line's index, its end points, the tolerance
/// and which end found no vertex); [`Error::OutOfMemory`] when the lookup
/// cannot be allocated.
pub fn match_lines_to_edges(
    mesh: &Mesh,
    lines: &[[DVec3; 2]],
    tolerance: f64,
) -> Result<Vec<[u32; 2]>> {
    let lookup = VertexLookup::new(mesh.positions(), tolerance)?;
    let mut pairs = try_vec::<[u32; 2]>(lines.len(), "the matched edges")?;
    if lines.is_empty() {
        return Ok(pairs);
    }
    let topology = crate::mesh::topology::Topology::new(mesh);
    let (mut starts, mut ends) = (Vec::new(), Vec::new());
    for (i, &[a, b]) in lines.iter().enumerate() {
        check_finite_point(a, &format!("the start of line {i}"))?;
        check_finite_point(b, &format!("the end of line {i}"))?;
        lookup.near(a, &mut starts);
        lookup.near(b, &mut ends);
        let mut best: Option<(f64, [u32; 2])> = None;
        for &(da, va) in &starts {
            for &(db, vb) in &ends {
                let nearer = best.is_none_or(|(d, _)| da + db < d);
                if va != vb && nearer && topology.find_edge(va, vb).is_some() {
                    best = Some((da + db, [va, vb]));
                }
            }
        }
        let Some((_, pair)) = best else {
            let why = if starts.is_empty() {
                "its start is no vertex of the mesh"
            } else if ends.is_empty() {
                "its end is no vertex of the mesh"
            } else {
                "its ends are vertices but not the ends of one edge"
            };
            return Err(Error::InvalidArgument(format!(
                "line {i} from ({}, {}, {}) to ({}, {}, {}) matches no edge of the mesh within {tolerance}: {why}",
                a.x, a.y, a.z, b.x, b.y, b.z
            )));
        };
        pairs.push(pair);
    }
    Ok(pairs)
}
