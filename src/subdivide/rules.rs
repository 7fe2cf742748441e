//! The boundary, sharpness and non-manifold rules, in one place, as
//! OpenSubdiv 3.5 applies them (`Far::TopologyRefinerFactoryBase::
//! prepareComponentTagsAndSharpness`, `Vtr::Level::completeTopologyFromFaceVertices`,
//! `Vtr::Refinement::propagate*Tags*`, `Sdc::Crease::DetermineVertexVertexRule`).
//!
//! On the cage (level 0):
//! - an edge is *sharp* (infinitely) when it has one face (naked), three or
//!   more faces, two faces that run it in the same direction, or comes of a
//!   face repeating a vertex (degenerate, or one of a pair's several edges;
//!   OpenSubdiv calls all but the first non-manifold);
//! - a vertex is *non-manifold* when it lies on a non-manifold edge, has no
//!   face, or its faces do not form one fan;
//! - a vertex is *infinitely sharp* when it has no face; in
//!   [`NakedEdges::Fixed`] when it lies on a naked edge; in
//!   [`NakedEdges::CornerFixed`] when it has one face and two edges; and when
//!   it is non-manifold, except on an interior non-manifold crease (two
//!   non-manifold edges, no naked edge, more faces than edges);
//! - its rule is Corner when sharp, else by its sharp edges: 0 or 1 smooth
//!   (a dart uses the smooth mask), 2 crease, more corner.
//!
//! On refined levels nothing is re-derived: child edges of a sharp edge are
//! sharp, edges inside a face are smooth; a vertex's child keeps its rule, an
//! edge's child is a crease when the edge is sharp (else smooth), a face's
//! child is smooth. (Re-deriving would differ from OpenSubdiv: the point on a
//! non-manifold edge is a crease, not a corner.)

use rayon::prelude::*;

use super::level::{Connectivity, Faces};
use super::scheme::{NakedEdges, Scheme, VertexRule};
use crate::buffers::{par_map, try_vec, zeroed, CHUNK};
use crate::error::Result;

/// Sharpness of every edge and rule of every vertex of one level.
#[derive(Debug, Clone)]
pub(crate) struct Tags {
    pub(crate) edge_sharp: Vec<bool>,
    pub(crate) vertex_rules: Vec<VertexRule>,
}

/// Tags of the cage, from its connectivity and the naked-edge mode.
pub(crate) fn cage_tags(
    faces: &Faces,
    connectivity: &Connectivity,
    naked_edges: NakedEdges,
) -> Result<Tags> {
    let forced = forced_sharpness(faces, connectivity, naked_edges)?;
    let mut vertex_rules = try_vec(faces.vertex_count, "vertex tags")?;
    for (v, &sharp) in forced.vertex_infinite.iter().enumerate() {
        vertex_rules.push(if sharp {
            VertexRule::Corner
        } else {
            match forced.sharp_edge_counts[v] {
                0 | 1 => VertexRule::Smooth,
                2 => VertexRule::Crease,
                _ => VertexRule::Corner,
            }
        });
    }
    Ok(Tags {
        edge_sharp: forced.edge_infinite,
        vertex_rules,
    })
}

/// What the topology and the naked-edge mode make infinitely sharp on the
/// cage, before any crease or corner given by the user.
pub(crate) struct ForcedSharpness {
    /// Naked and non-manifold edges.
    pub(crate) edge_infinite: Vec<bool>,
    /// Corners of the naked-edge mode, non-manifold and isolated vertices.
    pub(crate) vertex_infinite: Vec<bool>,
    /// Per vertex, how many of its edges are in `edge_infinite`.
    pub(crate) sharp_edge_counts: Vec<u32>,
}

/// Finds the edges and vertices the topology makes infinitely sharp (see the
/// module doc).
pub(crate) fn forced_sharpness(
    faces: &Faces,
    connectivity: &Connectivity,
    naked_edges: NakedEdges,
) -> Result<ForcedSharpness> {
    let vertex_count = faces.vertex_count;
    let edge_count = connectivity.edge_count();
    let mut edge_sharp = zeroed(edge_count, "edge tags")?;
    // Per vertex: incident edges, naked edges, non-manifold edges, sharp edges.
    let mut counts: Vec<[u32; 4]> = zeroed(vertex_count, "vertex tags")?;
    for (e, &[a, b]) in connectivity.edges.iter().enumerate() {
        let corners = connectivity.edge_corners(e);
        let naked = corners.len() == 1;
        let same_direction = corners.len() == 2
            && faces.indices[corners[0] as usize] == faces.indices[corners[1] as usize];
        // A degenerate edge, or one of a pair's several edges (a face
        // meeting the pair twice), as OpenSubdiv marks them.
        let repeated = a == b
            || (e > 0 && connectivity.edges[e - 1] == [a, b])
            || connectivity.edges.get(e + 1) == Some(&[a, b]);
        let non_manifold = corners.len() > 2 || same_direction || repeated;
        let sharp = naked || non_manifold;
        edge_sharp[e] = sharp;
        for v in [a, b] {
            let count = &mut counts[v as usize];
            count[0] += 1;
            count[1] += naked as u32;
            count[2] += non_manifold as u32;
            count[3] += sharp as u32;
        }
    }

    // The fans are walked vertex by vertex, each on its own: in parallel.
    let vertex_infinite = par_map(vertex_count, "vertex tags", |v| {
        let [edges, naked, non_manifold_edges, _] = counts[v];
        let face_count = connectivity.vertex_corners(v).len() as u32;
        let non_manifold = face_count == 0
            || non_manifold_edges > 0
            || !is_one_fan(faces, connectivity, v, edges, face_count);
        let topological_corner = face_count == 1 && edges == 2;
        let interior_non_manifold_crease =
            non_manifold_edges == 2 && naked == 0 && face_count > edges;
        face_count == 0
            || (naked_edges == NakedEdges::Fixed && naked > 0)
            || (naked_edges == NakedEdges::CornerFixed && topological_corner)
            || (non_manifold && !interior_non_manifold_crease)
    })?;
    let sharp_edge_counts = par_map(vertex_count, "vertex tags", |v| counts[v][3])?;
    Ok(ForcedSharpness {
        edge_infinite: edge_sharp,
        vertex_infinite,
        sharp_edge_counts,
    })
}

/// Whether the faces around `v` (all of whose edges are manifold and
/// consistently oriented) form a single fan, open or closed: walk across
/// edges from the first face in both directions and count the faces met.
fn is_one_fan(
    faces: &Faces,
    connectivity: &Connectivity,
    v: usize,
    edge_count: u32,
    face_count: u32,
) -> bool {
    if edge_count < 2 || edge_count > face_count + 1 {
        return false;
    }
    let corners = connectivity.vertex_corners(v);
    let start = corners[0] as usize;
    let face_of = |c: usize| connectivity.face_of(c);
    let mut seen = 1u32;
    // Clockwise: across the edge arriving at v.
    let mut c = start;
    let mut closed = false;
    loop {
        let incoming = connectivity.corner_edges[faces.prev(c, face_of(c))] as usize;
        let Some(other) = other_corner(connectivity, incoming, faces.prev(c, face_of(c))) else {
            break;
        };
        // The neighbour runs the edge v -> u, so its corner is at v.
        c = other;
        if c == start {
            closed = true;
            break;
        }
        seen += 1;
        if seen > face_count {
            return false;
        }
    }
    if !closed {
        // Counter-clockwise: across the edge leaving v.
        let mut c = start;
        loop {
            let outgoing = connectivity.corner_edges[c] as usize;
            let Some(other) = other_corner(connectivity, outgoing, c) else {
                break;
            };
            c = faces.next(other, face_of(other));
            seen += 1;
            if seen > face_count {
                return false;
            }
        }
    }
    seen == face_count
}

/// The other corner on a two-face edge, or `None` on a naked edge.
fn other_corner(connectivity: &Connectivity, edge: usize, corner: usize) -> Option<usize> {
    match *connectivity.edge_corners(edge) {
        [c1, c2] => Some(if c1 as usize == corner { c2 } else { c1 } as usize),
        _ => None,
    }
}

/// Tags of the next level, propagated from the level `parent` whose
/// connectivity is `parent_connectivity`; `child` is the next level's edges.
pub(crate) fn child_tags(
    scheme: Scheme,
    parent: &Tags,
    parent_faces: &Faces,
    child: &Connectivity,
) -> Result<Tags> {
    let parent_vertices = parent_faces.vertex_count;
    let parent_edges = parent.edge_sharp.len();
    let mut edge_sharp = try_vec(child.edge_count(), "edge tags")?;
    // A child edge from the parent's vertex a to the point of parent edge e is
    // [a, V + e]; every other child edge has both ends at new points.
    edge_sharp.par_extend(
        child
            .edges
            .par_iter()
            .with_min_len(CHUNK)
            .map(|&[low, high]| {
                (low as usize) < parent_vertices
                    && parent.edge_sharp[high as usize - parent_vertices]
            }),
    );
    let face_points = scheme.face_point_count(parent_faces.face_count());
    let mut vertex_rules = try_vec(parent_vertices + parent_edges + face_points, "vertex tags")?;
    vertex_rules.par_extend(parent.vertex_rules.par_iter().with_min_len(CHUNK).copied());
    vertex_rules.par_extend(
        parent
            .edge_sharp
            .par_iter()
            .with_min_len(CHUNK)
            .map(|&sharp| {
                if sharp {
                    VertexRule::Crease
                } else {
                    VertexRule::Smooth
                }
            }),
    );
    vertex_rules
        .par_extend(rayon::iter::repeat_n(VertexRule::Smooth, face_points).with_min_len(CHUNK));
    Ok(Tags {
        edge_sharp,
        vertex_rules,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::shapes;
    use crate::subdivide::scheme::loop_smooth_weights;

    fn tags_of(mesh: &crate::Mesh, naked: NakedEdges) -> Tags {
        let faces = Faces::of_mesh(mesh);
        let connectivity = Connectivity::new(&faces).unwrap();
        cage_tags(&faces, &connectivity, naked).unwrap()
    }

    #[test]
    fn grid_corners_and_boundaries() {
        let grid = shapes::quad_grid(2, 2);
        // Vertex 0 is a one-face corner, 1 a boundary vertex, 4 interior.
        let smooth = tags_of(&grid, NakedEdges::Smooth).vertex_rules;
        assert_eq!(
            [smooth[0], smooth[1], smooth[4]],
            [VertexRule::Crease, VertexRule::Crease, VertexRule::Smooth]
        );
        let corner = tags_of(&grid, NakedEdges::CornerFixed).vertex_rules;
        assert_eq!(
            [corner[0], corner[1]],
            [VertexRule::Corner, VertexRule::Crease]
        );
        let fixed = tags_of(&grid, NakedEdges::Fixed).vertex_rules;
        assert_eq!(
            [fixed[0], fixed[1], fixed[4]],
            [VertexRule::Corner, VertexRule::Corner, VertexRule::Smooth]
        );
    }

    #[test]
    fn non_manifold_vertices_are_corners() {
        let bow_tie = tags_of(&shapes::bow_tie(), NakedEdges::Smooth);
        assert_eq!(bow_tie.vertex_rules[0], VertexRule::Corner);
        assert_eq!(bow_tie.vertex_rules[2], VertexRule::Crease);
        let fin = tags_of(&shapes::fin(), NakedEdges::Smooth);
        assert_eq!(fin.vertex_rules[0], VertexRule::Corner);
        assert!(fin.edge_sharp.iter().all(|&s| s));
    }

    #[test]
    fn loop_weights_sum_to_one() {
        for n in 3..12 {
            let (v, e) = loop_smooth_weights(n);
            assert!((v + e * n as f64 - 1.0).abs() < 1e-15);
        }
        assert_eq!(loop_smooth_weights(6), (0.625, 0.0625));
    }
}
