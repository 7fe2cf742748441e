//! The local refinement behind every cage face: a graph whose nodes are
//! faces of some level with the faces around their corners, refined one
//! level at a time by the subdivider itself until each child is a regular
//! patch (`patches.rs`).
//!
//! A node's surface depends only on the faces around its corners (its
//! 1-ring), and the 1-ring of each of its children lies among the children
//! of those faces, so a node is a small mesh: those faces in their level's
//! order, vertices numbered as first met, with the sharpness of its level
//! as explicit creases and corners. One level of [`Subdivider`] on it gives
//! every child's points as weights of the node's (all rules apply: naked
//! edges, creases, Chaikin, the triangle rule, non-manifold tags). Nodes
//! with the same small mesh are the same node, so the chain of faces around
//! an extraordinary vertex closes into a loop after a few levels, and
//! evaluation follows it as deep as a sample needs. A node's expansion
//! depends on its small mesh alone, so it is made once for all the faces
//! whose graphs meet that small mesh, and they share its weights.

use std::collections::HashMap;
use std::sync::{Arc, Mutex};

use glam::DVec3;

use super::super::creases::{Rule, SubdivisionOptions, SHARPNESS_INFINITE};
use super::super::limit::summed;
use super::super::scheme::{NakedEdges, Scheme};
use super::super::stencils::LevelStencils;
use super::super::subdivider::{KeptLevel, Subdivider};
use super::patches::{corner_kind, regular_patch, Row};
use crate::error::{Error, Result};
use crate::mesh::Mesh;

/// The most nodes one cage face may need (semi-sharp creases of sharpness
/// near 10 come closest).
const MAX_NODES: usize = 1 << 16;

/// Rows of weights: row r is `Σ weights[k] · point(sources[k])` over
/// `offsets[r]..offsets[r + 1]`.
#[derive(Debug, Clone, Default)]
pub(super) struct Sparse {
    pub(super) offsets: Vec<u32>,
    pub(super) sources: Vec<u32>,
    pub(super) weights: Vec<f64>,
}

impl Sparse {
    /// From rows of `(point, weight)`.
    pub(super) fn from_rows<'a>(rows: impl Iterator<Item = &'a [(u32, f64)]>) -> Sparse {
        let mut out = Sparse {
            offsets: vec![0],
            ..Sparse::default()
        };
        for row in rows {
            for &(point, w) in row {
                out.sources.push(point);
                out.weights.push(w);
            }
            out.offsets.push(out.sources.len() as u32);
        }
        out
    }

    /// Rows `rows` of this one, in that order.
    fn rows_of(&self, rows: &[u32]) -> Sparse {
        let mut out = Sparse {
            offsets: vec![0],
            ..Sparse::default()
        };
        for &r in rows {
            let range = self.offsets[r as usize] as usize..self.offsets[r as usize + 1] as usize;
            out.sources.extend_from_slice(&self.sources[range.clone()]);
            out.weights.extend_from_slice(&self.weights[range]);
            out.offsets.push(out.sources.len() as u32);
        }
        out
    }

    /// One level's stencils as weights of the parent's points alone: the
    /// face points a row reads put in. Each weight is summed in the order
    /// the stencils sum its point's terms, so the weights are the bits the
    /// stencils give for unit points; zeros are left out.
    pub(super) fn of_stencils(stencils: &LevelStencils) -> Sparse {
        let parent = stencils.parent_count;
        let terms_of = |r: usize| {
            let range = stencils.offsets[r] as usize..stencils.offsets[r + 1] as usize;
            stencils.sources[range.clone()]
                .iter()
                .zip(&stencils.weights[range])
                .map(|(&s, &w)| (s as usize, w))
        };
        // The rows that read only the parent, which the others read.
        let first = stencils.first_independent;
        let mut independent = Vec::with_capacity(stencils.child_count() - first);
        for r in first..stencils.child_count() {
            independent.push(summed(terms_of(r).map(|(s, w)| (s as u32, w)).collect()));
        }
        let mut rows = Vec::with_capacity(first);
        for r in 0..first {
            let mut terms = Vec::new();
            for (s, w) in terms_of(r) {
                match s.checked_sub(parent) {
                    None => terms.push((s as u32, w)),
                    Some(child) => {
                        let read = &independent[child - first];
                        terms.extend(read.iter().map(|&(point, x)| (point, w * x)));
                    }
                }
            }
            rows.push(summed(terms));
        }
        Sparse::from_rows(rows.iter().chain(&independent).map(Vec::as_slice))
    }

    pub(super) fn rows(&self) -> usize {
        self.offsets.len() - 1
    }

    /// Row `r` applied to `points`.
    #[inline]
    pub(super) fn apply(&self, r: usize, points: &[DVec3]) -> DVec3 {
        let range = self.offsets[r] as usize..self.offsets[r + 1] as usize;
        let mut sum = DVec3::ZERO;
        for (&s, &w) in self.sources[range.clone()].iter().zip(&self.weights[range]) {
            sum += points[s as usize] * w;
        }
        sum
    }
}

/// A child of a node: its node and its points from the parent's.
#[derive(Debug, Clone)]
pub(super) struct Child {
    pub(super) node: u32,
    pub(super) points: Arc<Sparse>,
}

/// The limit at a corner of a node: position, first and second tangent
/// (rows 0, 1, 2), and whether the corner is irregular (an extraordinary
/// vertex, a crease end or a corner) with nothing semi-sharp left at it,
/// where evaluation stops.
#[derive(Debug, Clone)]
pub(super) struct CornerLimit {
    pub(super) irregular: bool,
    pub(super) masks: Sparse,
}

#[derive(Debug, Clone)]
pub(super) enum Kind {
    /// A regular patch's control points.
    Patch(Arc<Vec<Row>>),
    /// Refined once more: the children in the order of the face's corners
    /// (Loop: the three corner triangles, then the middle one).
    Refine {
        children: Vec<Child>,
        corners: Arc<Vec<Option<CornerLimit>>>,
    },
}

#[derive(Debug, Clone)]
pub(super) struct Node {
    pub(super) point_count: usize,
    /// The node's points at the corners of its face, in the face's order.
    pub(super) corners: Vec<u32>,
    pub(super) kind: Kind,
}

/// The graph of one cage face: the cage vertices of its root's points and
/// its nodes, the root first.
#[derive(Debug, Clone)]
pub(super) struct FaceGraph {
    pub(super) vertices: Vec<u32>,
    pub(super) nodes: Vec<Node>,
}

impl FaceGraph {
    pub(super) fn largest(&self) -> usize {
        self.nodes.iter().map(|n| n.point_count).max().unwrap_or(0)
    }
}

/// A node's small mesh, which of its faces is the node's, its options and
/// its identity.
struct Local {
    mesh: Mesh,
    face: usize,
    options: SubdivisionOptions,
    key: Vec<u64>,
}

/// Face `g` of `level` with the faces around its corners as a small mesh,
/// and the level's vertex of each of its vertices. The faces keep the
/// level's order, so each vertex's edges are walked from the same face as
/// in the whole level (Chaikin's sums of sharpness add in the same order).
fn extract(level: &KeptLevel, g: usize, base: &SubdivisionOptions) -> (Local, Vec<u32>) {
    let (faces, connectivity, sharpness) = (&level.faces, &level.connectivity, &level.sharpness);
    let mut around: Vec<usize> = faces
        .face(g)
        .iter()
        .flat_map(|&v| connectivity.vertex_corners(v as usize).iter())
        .map(|&c| connectivity.face_of(c as usize))
        .collect();
    around.sort_unstable();
    around.dedup();
    let face = around.iter().position(|&f| f == g).unwrap_or(0);
    let mut map: Vec<u32> = Vec::new();
    let local = |v: u32, map: &mut Vec<u32>| match map.iter().position(|&w| w == v) {
        Some(i) => i as u32,
        None => {
            map.push(v);
            map.len() as u32 - 1
        }
    };
    let (mut sizes, mut indices) = (Vec::new(), Vec::new());
    let (mut seen, mut creases) = (Vec::new(), Vec::new());
    let mut key = Vec::new();
    for f in around {
        let corners = faces.corners(f);
        sizes.push(corners.len() as u32);
        for c in corners {
            indices.push(local(faces.indices[c], &mut map));
            let e = connectivity.corner_edges[c];
            let s = sharpness.edges[e as usize];
            if s > 0.0 && !seen.contains(&e) {
                seen.push(e);
                let [a, b] = connectivity.edges[e as usize];
                creases.push(([local(a, &mut map), local(b, &mut map)], s));
            }
        }
    }
    let corners: Vec<(u32, f32)> = map
        .iter()
        .enumerate()
        .map(|(i, &v)| (i as u32, sharpness.vertices[v as usize]))
        .filter(|&(_, s)| s > 0.0)
        .collect();
    key.push(face as u64);
    key.extend(sizes.iter().map(|&s| u64::from(s)));
    key.push(u64::MAX);
    key.extend(indices.iter().map(|&i| u64::from(i)));
    for &([a, b], s) in &creases {
        key.extend([
            u64::MAX,
            u64::from(a.min(b)) << 32 | u64::from(a.max(b)),
            u64::from(s.to_bits()),
        ]);
    }
    for &(v, s) in &corners {
        key.extend([u64::MAX - 1, u64::from(v), u64::from(s.to_bits())]);
    }
    let options = SubdivisionOptions {
        naked_edges: NakedEdges::Smooth,
        creases: creases.iter().map(|&(e, s)| (e, f64::from(s))).collect(),
        corners: corners.iter().map(|&(v, s)| (v, f64::from(s))).collect(),
        creasing: base.creasing,
        holes: Vec::new(),
        triangles: base.triangles,
    };
    let positions = vec![DVec3::ZERO; map.len()];
    let mesh = Mesh::from_valid_parts(positions, sizes, indices);
    (
        Local {
            mesh,
            face,
            options,
            key,
        },
        map,
    )
}

/// What one node becomes: a patch, or its children's small meshes and
/// points and its corners' limits. It depends on the node's small mesh
/// alone, so the faces whose graphs meet the same small mesh share it
/// (see [`Expansions`]).
enum Expanded {
    Patch(Arc<Vec<Row>>),
    Refine(
        Vec<(Arc<Local>, Arc<Sparse>)>,
        Arc<Vec<Option<CornerLimit>>>,
    ),
}

/// The nodes expanded so far by any face, by their small mesh's identity:
/// a cage whose faces' neighbourhoods repeat (a grid, a pattern) expands
/// each kind of neighbourhood once, and its faces' graphs share the
/// weights. Kept while the faces' graphs are built.
#[derive(Default)]
pub(super) struct Expansions {
    by_key: Mutex<HashMap<Vec<u64>, Arc<Expanded>>>,
}

impl Expansions {
    /// How many nodes have been expanded.
    #[cfg(test)]
    pub(super) fn len(&self) -> usize {
        self.by_key.lock().map_or(0, |by_key| by_key.len())
    }

    /// The expansion of `local`'s node, made here when no face has made it.
    fn of(&self, scheme: Scheme, local: &Local) -> Result<Arc<Expanded>> {
        let known = |expansions: &Self| {
            let by_key = expansions.by_key.lock();
            let by_key = by_key.unwrap_or_else(|poisoned| poisoned.into_inner());
            by_key.get(&local.key).cloned()
        };
        if let Some(expanded) = known(self) {
            return Ok(expanded);
        }
        let expanded = Arc::new(expand(scheme, local)?);
        let mut by_key = self
            .by_key
            .lock()
            .unwrap_or_else(|poisoned| poisoned.into_inner());
        // Another face may have made the same one meanwhile: keep the first.
        Ok(by_key.entry(local.key.clone()).or_insert(expanded).clone())
    }
}

fn expand(scheme: Scheme, local: &Local) -> Result<Expanded> {
    let zero = Subdivider::new(&local.mesh, scheme, 0, &local.options)?;
    let level = &zero.levels[0];
    let g = local.face;
    if let Some(rows) = regular_patch(scheme, level, g) {
        return Ok(Expanded::Patch(Arc::new(rows)));
    }
    let own = local.mesh.face(g).to_vec();
    let corner_count = own.len();
    let size = scheme.refined_face_size();
    let mut corners = vec![None; corner_count];
    if local.mesh.face_sizes().iter().all(|&s| s == size) {
        // The limit masks at the face's corners alone, as weights of its points.
        let masks = zero.cage_limit_weights(own.iter().map(|&v| v as usize))?;
        for (k, slot) in corners.iter_mut().enumerate() {
            let c = level.faces.corners(g).start + k;
            // Stop at an irregular corner once nothing at it is semi-sharp:
            // the masks are exact from that level on.
            let v = level.faces.indices[c] as usize;
            let sharpness = &level.sharpness;
            let settled = |s: f32| s == 0.0 || s >= SHARPNESS_INFINITE as f32;
            let decayed = settled(sharpness.vertices[v])
                && sharpness
                    .edges_at(v)
                    .iter()
                    .all(|&e| settled(sharpness.edges[e as usize]));
            // Catmull-Clark's masks have no smooth limit at two faces (they
            // keep the point where it is); such a point is approached.
            let two_faces = scheme == Scheme::CatmullClark
                && sharpness.rules[v].is_smooth()
                && level.connectivity.vertex_corners(v).len() == 2;
            // A corner's masks are its first two edges, which turn from
            // level to level: a corner is approached too.
            let corner = sharpness.rules[v] == Rule::Corner;
            let irregular =
                decayed && !two_faces && !corner && corner_kind(scheme, level, g, c).is_none();
            let masks = Sparse::from_rows(masks[k].iter().map(Vec::as_slice));
            *slot = Some(CornerLimit { irregular, masks });
        }
    }
    let one = Subdivider::new(&local.mesh, scheme, 1, &local.options)?;
    let weights = Sparse::of_stencils(&one.stencils[0]);
    let refined = &one.levels[1];
    let children = match scheme {
        Scheme::CatmullClark => corner_count,
        Scheme::Loop => 4,
    };
    // The children of face g start after those of the faces before it.
    let first = match scheme {
        Scheme::CatmullClark => local.mesh.face_sizes()[..g].iter().sum::<u32>() as usize,
        Scheme::Loop => 4 * g,
    };
    let mut out = Vec::with_capacity(children);
    for j in 0..children {
        let (child, map) = extract(refined, first + j, &local.options);
        let points = weights.rows_of(&map);
        out.push((Arc::new(child), Arc::new(points)));
    }
    Ok(Expanded::Refine(out, Arc::new(corners)))
}

/// The graph of cage face `f`; `cage` is the cage's level (sharpness with
/// the naked-edge mode and the user's creases applied).
///
/// # Errors
/// What [`Subdivider::new`] refuses of a node's small mesh (out of memory);
/// [`Error::InvalidArgument`] when the face needs more than 65536 nodes.
pub(super) fn face_graph(
    scheme: Scheme,
    cage: &KeptLevel,
    f: usize,
    options: &SubdivisionOptions,
    expansions: &Expansions,
) -> Result<FaceGraph> {
    if let Some(rows) = regular_patch(scheme, cage, f) {
        // A regular cage face: its patch on its own points.
        let mut vertices: Vec<u32> = Vec::new();
        let rows = rows
            .into_iter()
            .map(|mut row| {
                for p in row.points.iter_mut().take(row.len as usize) {
                    *p = match vertices.iter().position(|v| v == p) {
                        Some(i) => i as u32,
                        None => {
                            vertices.push(*p);
                            vertices.len() as u32 - 1
                        }
                    };
                }
                row
            })
            .collect();
        let node = Node {
            point_count: vertices.len(),
            corners: Vec::new(),
            kind: Kind::Patch(Arc::new(rows)),
        };
        return Ok(FaceGraph {
            vertices,
            nodes: vec![node],
        });
    }
    let (root, vertices) = extract(cage, f, options);
    let mut ids: HashMap<Vec<u64>, u32> = HashMap::new();
    let mut nodes: Vec<Option<Node>> = vec![None];
    ids.insert(root.key.clone(), 0);
    let mut pending = vec![(0u32, Arc::new(root))];
    while let Some((id, local)) = pending.pop() {
        let point_count = local.mesh.vertex_count();
        let corners = local.mesh.face(local.face).to_vec();
        let kind = match &*expansions.of(scheme, &local)? {
            Expanded::Patch(rows) => Kind::Patch(rows.clone()),
            Expanded::Refine(children, corners) => {
                let mut out = Vec::with_capacity(children.len());
                for (child, points) in children {
                    let node = match ids.get(&child.key) {
                        Some(&node) => node,
                        None => {
                            if nodes.len() >= MAX_NODES {
                                return Err(Error::InvalidArgument(format!(
                                    "the limit surface of face {f} needs more than {MAX_NODES} \
                                     local refinements (semi-sharp creases near sharpness 10 \
                                     around it need the most)"
                                )));
                            }
                            let node = nodes.len() as u32;
                            nodes.push(None);
                            ids.insert(child.key.clone(), node);
                            pending.push((node, child.clone()));
                            node
                        }
                    };
                    out.push(Child {
                        node,
                        points: points.clone(),
                    });
                }
                Kind::Refine {
                    children: out,
                    corners: corners.clone(),
                }
            }
        };
        nodes[id as usize] = Some(Node {
            point_count,
            corners,
            kind,
        });
    }
    let nodes = nodes
        .into_iter()
        .map(|n| n.expect("every node is expanded"))
        .collect();
    Ok(FaceGraph { vertices, nodes })
}
