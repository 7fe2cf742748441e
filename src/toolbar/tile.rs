//! Tile: Weaverbird's wbTile, which re-tessellates chosen faces of a mesh by
//! a fill strategy (fans, strips and stitches of triangles or quads).
//!
//! Weaverbird documents the strategies by one line each; the patterns below
//! are Weft's reading of those lines, and every one keeps the face's outline,
//! its winding and the input's vertices, so neighbouring faces stay welded
//! to it and a closed mesh stays closed.

use glam::DVec3;

use crate::buffers::try_vec;
use crate::error::{Error, Result, MAX_ELEMENTS};
use crate::mesh::triangulate::triangulate;
use crate::mesh::Mesh;

/// How a chosen face is filled (Weaverbird's F input, same numbers).
/// Corners are named by their place in the face, `v0` its first corner.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TileFill {
    /// 0: the face stays as it is.
    Skip,
    /// 1: the most robust triangulation: a quad along its shorter diagonal,
    /// a larger polygon ear-clipped in its best-fit plane, so concave faces
    /// come out right (as [`crate::mesh::triangulate`]).
    Best,
    /// 2: a new vertex at the centroid and a triangle from it to each edge.
    TriangleFan,
    /// 3: triangles all sharing `v0` (a fan from the first corner).
    TriangleHand,
    /// 4: the strip of [`TileFill::QuadStitch`] with each quad cut by its
    /// diagonal from the second corner to the fourth, so every diagonal runs
    /// the same way, as in a knit.
    TriangleKnit,
    /// 5: a strip of triangles from `v0` across the face, advancing one
    /// corner on each side in turn, so the diagonals zigzag.
    TriangleZigzag,
    /// 6: a strip of quads across the face from `v0`, each taking the next
    /// corner on both sides; a face with an odd corner count ends with a
    /// triangle.
    QuadStitch,
    /// 7: a new vertex at the centroid and a quad from it over every two
    /// edges; a face with an odd corner count ends with a triangle.
    QuadFan,
}

/// Which faces are filled (Weaverbird's O input, same numbers); the others
/// are kept as they are.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TileFaces {
    /// 0: every face.
    All,
    /// 1: every face but triangles.
    QuadsAndMore,
    /// 2: pentagons and larger.
    PentagonsAndMore,
    /// 9: triangles only.
    Triangles,
    /// 16: quads only.
    Quads,
}

impl TileFaces {
    /// Whether a face of `corners` corners is chosen.
    pub fn includes(self, corners: usize) -> bool {
        match self {
            TileFaces::All => true,
            TileFaces::QuadsAndMore => corners >= 4,
            TileFaces::PentagonsAndMore => corners >= 5,
            TileFaces::Triangles => corners == 3,
            TileFaces::Quads => corners == 4,
        }
    }
}

/// Fills every face chosen by `faces` with the pattern of `fill`
/// (Weaverbird's Tile). The input's vertices keep their indices; the fans'
/// centroids follow, one per filled face in face order. The faces made from
/// face f are contiguous, in face order, and wound as f.
///
/// # Errors
/// [`Error::ResultTooLarge`] when the result would pass
/// [`MAX_ELEMENTS`]; [`Error::DegenerateInput`] when a centroid overflows
/// `f64`; [`Error::OutOfMemory`].
pub fn tile(mesh: &Mesh, fill: TileFill, faces: TileFaces) -> Result<Mesh> {
    let chosen = |f: usize| fill != TileFill::Skip && faces.includes(mesh.face(f).len());
    let (mut vertex_count, mut face_count, mut index_count) =
        (mesh.vertex_count() as u64, 0u64, 0u64);
    for (f, face) in mesh.faces().enumerate() {
        let n = face.len() as u64;
        let (added, made, corners) = if chosen(f) {
            counts(fill, n)
        } else {
            (0, 1, n)
        };
        vertex_count += added;
        face_count += made;
        index_count += corners;
    }
    if vertex_count > MAX_ELEMENTS || face_count > MAX_ELEMENTS || index_count > MAX_ELEMENTS {
        return Err(Error::ResultTooLarge(format!(
            "tile would make {vertex_count} vertices, {face_count} faces and {index_count} face indices; the limit is {MAX_ELEMENTS} of each"
        )));
    }
    let mut positions = try_vec::<DVec3>(vertex_count as usize, "tile")?;
    positions.extend_from_slice(mesh.positions());
    let mut sizes = try_vec::<u32>(face_count as usize, "tile")?;
    let mut indices = try_vec::<u32>(index_count as usize, "tile")?;
    let best = match fill {
        TileFill::Best => Some(best_triangles(mesh, &chosen)?),
        _ => None,
    };
    let mut best_next = 0;
    for (f, face) in mesh.faces().enumerate() {
        if !chosen(f) {
            sizes.push(face.len() as u32);
            indices.extend_from_slice(face);
            continue;
        }
        let mut emit = |corners: &[u32]| {
            sizes.push(corners.len() as u32);
            indices.extend_from_slice(corners);
        };
        match fill {
            TileFill::Skip => unreachable!("skipped faces are never chosen"),
            TileFill::Best => {
                let triangles = best.as_ref().expect("triangulated above");
                for t in 0..face.len() - 2 {
                    emit(&triangles[3 * (best_next + t)..3 * (best_next + t) + 3]);
                }
                best_next += face.len() - 2;
            }
            TileFill::TriangleFan | TileFill::QuadFan => {
                let n = face.len();
                let centroid = mesh.face_positions(f).sum::<DVec3>() / n as f64;
                let c = positions.len() as u32;
                positions.push(centroid);
                if fill == TileFill::TriangleFan {
                    for i in 0..n {
                        emit(&[c, face[i], face[(i + 1) % n]]);
                    }
                } else {
                    for i in (0..n - 1).step_by(2) {
                        emit(&[c, face[i], face[i + 1], face[(i + 2) % n]]);
                    }
                    if n % 2 == 1 {
                        emit(&[c, face[n - 1], face[0]]);
                    }
                }
            }
            TileFill::TriangleHand => {
                for i in 1..face.len() - 1 {
                    emit(&[face[0], face[i], face[i + 1]]);
                }
            }
            TileFill::QuadStitch | TileFill::TriangleKnit => {
                for piece in stitch(face.len()) {
                    let corners: Vec<u32> = piece.iter().map(|&i| face[i]).collect();
                    match (fill, corners.as_slice()) {
                        (TileFill::TriangleKnit, &[a, b, c, d]) => {
                            emit(&[a, b, d]);
                            emit(&[b, c, d]);
                        }
                        _ => emit(&corners),
                    }
                }
            }
            TileFill::TriangleZigzag => {
                let (mut lo, mut hi) = (1, face.len() - 1);
                emit(&[face[0], face[lo], face[hi]]);
                let mut forward = true;
                while hi - lo > 1 {
                    if forward {
                        emit(&[face[lo], face[lo + 1], face[hi]]);
                        lo += 1;
                    } else {
                        emit(&[face[lo], face[hi - 1], face[hi]]);
                        hi -= 1;
                    }
                    forward = !forward;
                }
            }
        }
    }
    Mesh::new(positions, sizes, indices).map_err(|e| {
        Error::DegenerateInput(format!(
            "tile cannot make a valid mesh from this input: {e}"
        ))
    })
}

/// New vertices, faces and face indices of one filled face of `n` corners.
fn counts(fill: TileFill, n: u64) -> (u64, u64, u64) {
    match fill {
        TileFill::Skip => (0, 1, n),
        TileFill::Best
        | TileFill::TriangleHand
        | TileFill::TriangleKnit
        | TileFill::TriangleZigzag => (0, n - 2, 3 * (n - 2)),
        TileFill::TriangleFan => (1, n, 3 * n),
        TileFill::QuadStitch => {
            let quads = (n - 2) / 2;
            let triangles = n % 2;
            (0, quads + triangles, 4 * quads + 3 * triangles)
        }
        TileFill::QuadFan => {
            let quads = n / 2;
            let triangles = n % 2;
            (1, quads + triangles, 4 * quads + 3 * triangles)
        }
    }
}

/// The quad stitch of a face of `n` corners, as corner places: the quad of
/// its first three corners and its last, then quads taking the next corner
/// on each side, and a closing triangle when `n` is odd. Each piece lists
/// its corners in the face's order, so it keeps the face's winding.
fn stitch(n: usize) -> Vec<Vec<usize>> {
    if n == 3 {
        return vec![vec![0, 1, 2]];
    }
    let mut pieces = vec![vec![0, 1, 2, n - 1]];
    let (mut lo, mut hi) = (2, n - 1);
    while hi - lo >= 3 {
        pieces.push(vec![lo, lo + 1, hi - 1, hi]);
        lo += 1;
        hi -= 1;
    }
    if hi - lo == 2 {
        pieces.push(vec![lo, lo + 1, hi]);
    }
    pieces
}

/// The triangles of the chosen faces, in face order, from one run of
/// [`triangulate`] over just those faces.
fn best_triangles(mesh: &Mesh, chosen: &dyn Fn(usize) -> bool) -> Result<Vec<u32>> {
    let mut sizes = Vec::new();
    let mut indices = Vec::new();
    let picked_faces = mesh.faces().enumerate().filter(|&(f, _)| chosen(f));
    for face in picked_faces.map(|(_, face)| face) {
        sizes.push(face.len() as u32);
        indices.extend_from_slice(face);
    }
    let picked = Mesh::from_valid_parts(mesh.positions().to_vec(), sizes, indices);
    Ok(triangulate(&picked)?.mesh.face_indices().to_vec())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn stitch_takes_a_corner_on_each_side() {
        assert_eq!(stitch(3), [vec![0, 1, 2]]);
        assert_eq!(stitch(4), [vec![0, 1, 2, 3]]);
        assert_eq!(stitch(5), [vec![0, 1, 2, 4], vec![2, 3, 4]]);
        assert_eq!(
            stitch(8),
            [vec![0, 1, 2, 7], vec![2, 3, 6, 7], vec![3, 4, 5, 6]]
        );
        for n in 3..20u64 {
            let (_, faces, indices) = counts(TileFill::QuadStitch, n);
            let pieces = stitch(n as usize);
            assert_eq!(pieces.len() as u64, faces, "{n}");
            assert_eq!(pieces.iter().map(Vec::len).sum::<usize>() as u64, indices);
        }
    }
}
