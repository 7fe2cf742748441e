//! Semi-sharp and infinitely sharp creases and corners: the options a user
//! gives, and how sharpness passes from level to level, as OpenSubdiv 3.5's
//! `Sdc::Crease` and `Vtr::Refinement` do it (DeRose, Kass and Truong,
//! "Subdivision surfaces in character animation", 1998).
//!
//! Sharpness is a number of levels: an edge of sharpness s is refined with
//! the crease rule while s ≥ 1, loses 1 per level (Uniform) or is first
//! averaged with the other semi-sharp edges at each end (Chaikin), and the
//! level where it falls below 1 blends the crease and smooth masks by its
//! fractional part. Sharpness of [`SHARPNESS_INFINITE`] or more never
//! softens. As in OpenSubdiv, sharpness is kept at single precision, so the
//! same inputs give the same surface.

use super::level::{vertex_edges_of, Connectivity, Faces};
use super::rules::forced_sharpness;
use super::scheme::{NakedEdges, Scheme};
use crate::buffers::{try_vec, zeroed};
use crate::error::{Error, Result};
use crate::mesh::Mesh;

/// The sharpness OpenSubdiv treats as infinite (`Sdc::Crease::SHARPNESS_INFINITE`):
/// creases and corners at least this sharp never soften.
pub const SHARPNESS_INFINITE: f64 = 10.0;

const INFINITE: f32 = 10.0;

/// A creased edge: its two cage vertices (either order) and its sharpness.
pub type Crease = ([u32; 2], f64);

/// How semi-sharp creases soften from level to level (OpenSubdiv's
/// `Sdc::Options::CreasingMethod`). The values are stable (the C ABI uses them).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[repr(u32)]
pub enum Creasing {
    /// Every level takes 1 off every sharpness (`CREASE_UNIFORM`).
    #[default]
    Uniform = 0,
    /// Each half of a semi-sharp edge takes 3/4 of its sharpness plus 1/4 of
    /// the average of the other semi-sharp edges at its end, minus 1
    /// (`CREASE_CHAIKIN`): sharpness varies smoothly along a crease.
    Chaikin = 1,
}

/// Catmull-Clark's weights at triangles (OpenSubdiv's
/// `Sdc::Options::TriangleSubdivision`). Loop ignores it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum TriangleRule {
    /// Catmull-Clark's own weights (`TRI_SUB_CATMARK`).
    #[default]
    Catmark,
    /// "Smooth triangle" weights (`TRI_SUB_SMOOTH`): the point of a smooth
    /// edge beside a triangle takes more of the triangle's face point, which
    /// rounds triangle regions of mixed cages. Only the cage can have
    /// triangles, so only the first level changes.
    Smooth,
}

/// Everything besides the mesh that shapes a subdivision surface, as
/// OpenSubdiv's `Sdc::Options` and the crease and corner arrays of its
/// `Far::TopologyDescriptor`.
///
/// Naked edges are always infinitely sharp creases; the naked-edge mode says
/// which boundary vertices are also infinitely sharp corners (none, those
/// with one face, or all), and user creases and corners add to that.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct SubdivisionOptions {
    /// What happens along naked edges.
    pub naked_edges: NakedEdges,
    /// Creased edges as cage vertex pairs (either order) with their
    /// sharpness: 0 smooth, [`SHARPNESS_INFINITE`] or more (or `f64::INFINITY`)
    /// a hard crease. An edge given twice takes the last value.
    pub creases: Vec<Crease>,
    /// Sharp cage vertices with their sharpness; infinite is a corner that
    /// stays where it is.
    pub corners: Vec<(u32, f64)>,
    /// How semi-sharp creases soften.
    pub creasing: Creasing,
    /// Cage faces left out of the result (OpenSubdiv's hole tags): a hole
    /// is not refined and leaves no faces, but its vertices and edges shape
    /// its neighbours as before; vertices only holes use stay, unused.
    /// Given twice is the same as once.
    pub holes: Vec<u32>,
    /// Catmull-Clark's weights at triangles.
    pub triangles: TriangleRule,
}

impl SubdivisionOptions {
    /// Options with the naked-edge mode and nothing creased.
    pub fn new(naked_edges: NakedEdges) -> SubdivisionOptions {
        SubdivisionOptions {
            naked_edges,
            ..SubdivisionOptions::default()
        }
    }
}

/// A vertex's subdivision rule (`Sdc::Crease::Rule`), found from its own
/// sharpness and the number of sharp edges at it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Rule {
    Smooth,
    /// One sharp edge: refined with the smooth mask.
    Dart,
    Crease,
    Corner,
}

impl Rule {
    /// `Sdc::Crease::DetermineVertexVertexRule`.
    fn of(vertex_sharpness: f32, sharp_edges: u32) -> Rule {
        if is_sharp(vertex_sharpness) {
            return Rule::Corner;
        }
        match sharp_edges {
            0 => Rule::Smooth,
            1 => Rule::Dart,
            2 => Rule::Crease,
            _ => Rule::Corner,
        }
    }

    /// Whether the smooth mask applies.
    pub(crate) fn is_smooth(self) -> bool {
        matches!(self, Rule::Smooth | Rule::Dart)
    }
}

#[inline]
pub(crate) fn is_sharp(s: f32) -> bool {
    s > 0.0
}

#[inline]
fn is_semi_sharp(s: f32) -> bool {
    s > 0.0 && s < INFINITE
}

/// `Sdc::Crease::decrementSharpness`: one level less, never below 0.
#[inline]
fn decrement(s: f32) -> f32 {
    if s <= 0.0 {
        0.0
    } else if s >= INFINITE {
        INFINITE
    } else if s > 1.0 {
        s - 1.0
    } else {
        0.0
    }
}

/// The sharpness of every edge and vertex of one level, the rule of every
/// vertex, and the edges around every vertex.
#[derive(Debug, Clone)]
pub(crate) struct Sharpness {
    pub(crate) edges: Vec<f32>,
    pub(crate) vertices: Vec<f32>,
    pub(crate) rules: Vec<Rule>,
    /// `vertex_edges[vertex_edge_offsets[v]..vertex_edge_offsets[v + 1]]`: the edges at v.
    pub(crate) vertex_edge_offsets: Vec<u32>,
    pub(crate) vertex_edges: Vec<u32>,
}

impl Sharpness {
    /// A level's sharpness from its parts; the edges at each vertex as
    /// offsets and list ([`vertex_edges_of`]).
    fn new(
        edges: Vec<f32>,
        vertices: Vec<f32>,
        rules: Vec<Rule>,
        (vertex_edge_offsets, vertex_edges): (Vec<u32>, Vec<u32>),
    ) -> Sharpness {
        Sharpness {
            edges,
            vertices,
            rules,
            vertex_edge_offsets,
            vertex_edges,
        }
    }

    /// The edges at vertex `v`, ascending.
    #[inline]
    pub(crate) fn edges_at(&self, v: usize) -> &[u32] {
        &self.vertex_edges
            [self.vertex_edge_offsets[v] as usize..self.vertex_edge_offsets[v + 1] as usize]
    }

    /// The sharpness of the half of edge `e` at its end `v` after one level
    /// (`Sdc::Crease::SubdivideEdgeSharpnessAtVertex`).
    pub(crate) fn child_edge_sharpness(
        &self,
        creasing: Creasing,
        connectivity: &Connectivity,
        e: usize,
        v: usize,
    ) -> f32 {
        let s = self.edges[e];
        let around = self.edges_at(v);
        if creasing == Creasing::Uniform || around.len() < 2 {
            return decrement(s);
        }
        if !is_sharp(s) {
            return 0.0;
        }
        if s >= INFINITE {
            return INFINITE;
        }
        let _ = connectivity;
        let (mut sum, mut count) = (0.0f32, 0u32);
        for &other in around {
            let t = self.edges[other as usize];
            if is_semi_sharp(t) {
                sum += t;
                count += 1;
            }
        }
        let mut child = s;
        if count > 1 {
            let average = (sum - s) / (count - 1) as f32;
            child = 0.75 * s + 0.25 * average;
        }
        child -= 1.0;
        if is_sharp(child) {
            child
        } else {
            0.0
        }
    }
}

/// Sharpness of a user value: NaN and negative values are errors, values
/// of [`SHARPNESS_INFINITE`] or more are infinite.
fn user_sharpness(value: f64, what: impl Fn() -> String) -> Result<f32> {
    if value.is_nan() || value < 0.0 {
        return Err(Error::InvalidArgument(format!(
            "{} has sharpness {value}; sharpness must be 0 or more (use {SHARPNESS_INFINITE} or \
             infinity for a hard crease)",
            what()
        )));
    }
    Ok(value.min(SHARPNESS_INFINITE) as f32)
}

/// The sharpness of the cage: the user's creases and corners, then what the
/// topology and the naked-edge mode force (`Far::TopologyRefinerFactoryBase::
/// prepareComponentTagsAndSharpness`).
///
/// # Errors
/// [`Error::InvalidArgument`] naming a crease whose vertices are not an edge
/// of the cage, a corner past the vertex count, or a negative or NaN sharpness.
pub(crate) fn cage_sharpness(
    faces: &Faces,
    connectivity: &Connectivity,
    options: &SubdivisionOptions,
) -> Result<Sharpness> {
    let vertex_count = faces.vertex_count;
    let mut edges: Vec<f32> = zeroed(connectivity.edge_count(), "edge sharpness")?;
    let mut vertices: Vec<f32> = zeroed(vertex_count, "vertex sharpness")?;
    let (vertex_edge_offsets, vertex_edges) = vertex_edges_of(&connectivity.edges, vertex_count)?;
    for (i, &([a, b], value)) in options.creases.iter().enumerate() {
        let s = user_sharpness(value, || format!("crease {i} ({a}, {b})"))?;
        let Some(e) = connectivity.find_edge(a, b) else {
            return Err(Error::InvalidArgument(format!(
                "crease {i} joins vertices {a} and {b}, which are not an edge of the mesh"
            )));
        };
        edges[e as usize] = s;
    }
    for (i, &(v, value)) in options.corners.iter().enumerate() {
        let s = user_sharpness(value, || format!("corner {i} (vertex {v})"))?;
        if v as usize >= vertex_count {
            return Err(Error::InvalidArgument(format!(
                "corner {i} is vertex {v}, but the mesh has {vertex_count} vertices"
            )));
        }
        vertices[v as usize] = s;
    }

    let forced = forced_sharpness(faces, connectivity, options.naked_edges)?;
    for (s, &infinite) in edges.iter_mut().zip(&forced.edge_infinite) {
        if infinite {
            *s = INFINITE;
        }
    }
    for (s, &infinite) in vertices.iter_mut().zip(&forced.vertex_infinite) {
        if infinite {
            *s = INFINITE;
        }
    }
    let mut rules = try_vec(vertex_count, "vertex rules")?;
    for v in 0..vertex_count {
        let around =
            &vertex_edges[vertex_edge_offsets[v] as usize..vertex_edge_offsets[v + 1] as usize];
        let sharp_edges = around
            .iter()
            .filter(|&&e| is_sharp(edges[e as usize]))
            .count() as u32;
        rules.push(Rule::of(vertices[v], sharp_edges));
    }
    let around = (vertex_edge_offsets, vertex_edges);
    Ok(Sharpness::new(edges, vertices, rules, around))
}

/// The sharpness of the next level (`Vtr::Refinement::subdivideEdgeSharpness`,
/// `subdivideVertexSharpness`, `reclassifySemisharpVertices`): halves of an
/// edge take its subdivided sharpness at their end, edges inside a face are
/// smooth; a vertex's child loses one level of sharpness and is reclassified
/// when a semi-sharp feature around it decays; an edge point is a crease, a
/// dart or smooth by how many of its halves stay sharp.
pub(crate) fn child_sharpness(
    scheme: Scheme,
    creasing: Creasing,
    parent: &Sharpness,
    parent_faces: &Faces,
    parent_connectivity: &Connectivity,
    child: &Connectivity,
) -> Result<Sharpness> {
    let parent_vertices = parent_faces.vertex_count;
    let parent_edges = parent.edges.len();
    let face_points = scheme.face_point_count(parent_faces.face_count());
    let child_vertices = parent_vertices + parent_edges + face_points;

    // The sharpness of both halves of every parent edge, at its low and high end.
    let mut halves: Vec<[f32; 2]> = zeroed(parent_edges, "edge sharpness")?;
    for (e, &[a, b]) in parent_connectivity.edges.iter().enumerate() {
        halves[e] = [
            parent.child_edge_sharpness(creasing, parent_connectivity, e, a as usize),
            parent.child_edge_sharpness(creasing, parent_connectivity, e, b as usize),
        ];
    }
    let mut edges = try_vec(child.edge_count(), "edge sharpness")?;
    edges.extend(child.edges.iter().map(|&[low, high]| {
        let (low, high) = (low as usize, high as usize);
        if low < parent_vertices && high >= parent_vertices && high < parent_vertices + parent_edges
        {
            let e = high - parent_vertices;
            let end = (parent_connectivity.edges[e][1] as usize == low) as usize;
            halves[e][end]
        } else {
            0.0
        }
    }));
    let around = vertex_edges_of(&child.edges, child_vertices)?;

    let mut vertices: Vec<f32> = zeroed(child_vertices, "vertex sharpness")?;
    let mut rules = try_vec(child_vertices, "vertex rules")?;
    for (v, (&parent_sharpness, slot)) in parent.vertices.iter().zip(&mut vertices).enumerate() {
        let sharpness = decrement(parent_sharpness);
        *slot = sharpness;
        let around = parent.edges_at(v);
        let semi_sharp_edges = around
            .iter()
            .any(|&e| is_semi_sharp(parent.edges[e as usize]));
        let decayed = is_semi_sharp(parent_sharpness) && !is_semi_sharp(sharpness);
        let reclassify = (semi_sharp_edges || decayed) && !is_sharp(sharpness);
        rules.push(if reclassify {
            let sharp_halves = around
                .iter()
                .filter(|&&e| {
                    let end = (parent_connectivity.edges[e as usize][1] as usize == v) as usize;
                    is_sharp(halves[e as usize][end])
                })
                .count() as u32;
            Rule::of(0.0, sharp_halves)
        } else {
            parent.rules[v]
        });
    }
    for (e, &s) in parent.edges.iter().enumerate() {
        rules.push(if is_semi_sharp(s) {
            let sharp_halves = halves[e].iter().filter(|&&h| is_sharp(h)).count() as u32;
            Rule::of(0.0, sharp_halves)
        } else if is_sharp(s) {
            Rule::Crease
        } else {
            Rule::Smooth
        });
    }
    rules.extend(std::iter::repeat_n(Rule::Smooth, face_points));
    Ok(Sharpness::new(edges, vertices, rules, around))
}

/// The sharpness every edge at `v` will have after one level
/// (`Sdc::Crease::SubdivideEdgeSharpnessesAroundVertex`), in the order of
/// [`Sharpness::edges_at`].
pub(crate) fn child_sharpness_around(
    parent: &Sharpness,
    creasing: Creasing,
    connectivity: &Connectivity,
    v: usize,
    out: &mut Vec<f32>,
) {
    out.clear();
    out.extend(
        parent
            .edges_at(v)
            .iter()
            .map(|&e| parent.child_edge_sharpness(creasing, connectivity, e as usize, v)),
    );
}

/// `Sdc::Crease::ComputeFractionalWeightAtVertex`: the weight of the parent's
/// mask when a vertex passes from one rule to another — the average
/// sharpness of the features that decay to smooth at this level, at most 1.
pub(crate) fn fractional_weight(
    parent_vertex: f32,
    child_vertex: f32,
    parent_edges: impl Iterator<Item = f32>,
    child_edges: &[f32],
) -> f32 {
    let (mut sum, mut count) = (0.0f32, 0u32);
    if is_sharp(parent_vertex) && !is_sharp(child_vertex) {
        sum = parent_vertex;
        count = 1;
    }
    for (p, &c) in parent_edges.zip(child_edges) {
        if is_sharp(p) && !is_sharp(c) {
            sum += p;
            count += 1;
        }
    }
    if count == 0 {
        return 0.0;
    }
    (sum / count as f32).min(1.0)
}

/// Creases for Rhino's "ToSubD" conversion of a mesh whose creases are
/// unwelded seams: welds vertices at exactly the same position, and returns
/// the welded mesh with an infinitely sharp crease on every edge that was
/// naked before welding and has two faces after, and on every edge whose two
/// faces meet at a dihedral angle of more than `angle_degrees` (the angle
/// between their normals; pass 180 or more to skip this test).
///
/// Positions equal as numbers weld (`-0.0` with `0.0`).
///
/// # Errors
/// [`Error::InvalidArgument`] when `angle_degrees` is NaN or negative;
/// [`Error::OutOfMemory`].
pub fn creases_from_mesh(mesh: &Mesh, angle_degrees: f64) -> Result<CreasedMesh> {
    if angle_degrees.is_nan() || angle_degrees < 0.0 {
        return Err(Error::InvalidArgument(format!(
            "the crease angle is {angle_degrees} degrees; it must be 0 or more"
        )));
    }
    let topology = crate::mesh::topology::Topology::try_new(mesh)?;
    // Adding 0.0 turns -0.0 into 0.0, so equal numbers have equal bits.
    let bits = |p: glam::DVec3| {
        [
            (p.x + 0.0).to_bits(),
            (p.y + 0.0).to_bits(),
            (p.z + 0.0).to_bits(),
        ]
    };
    let mut was_naked = std::collections::HashSet::new();
    for e in 0..topology.edge_count() {
        if topology.is_naked_edge(e) {
            let [a, b] = topology.edges()[e];
            let (p, q) = (mesh.positions()[a as usize], mesh.positions()[b as usize]);
            was_naked.insert((bits(p), bits(q)));
        }
    }
    // Weld vertices at identical positions, keeping the first index.
    let mut first = std::collections::HashMap::new();
    let mut remap = try_vec(mesh.vertex_count(), "weld map")?;
    let mut positions = Vec::new();
    for p in mesh.positions() {
        let index = *first.entry(bits(*p)).or_insert_with(|| {
            positions.push(*p);
            positions.len() as u32 - 1
        });
        remap.push(index);
    }
    let faces: Vec<Vec<u32>> = mesh
        .faces()
        .map(|f| f.iter().map(|&v| remap[v as usize]).collect())
        .collect();
    let welded = Mesh::from_polygons(positions, faces)?;
    let topology = crate::mesh::topology::Topology::try_new(&welded)?;
    let cos_limit = angle_degrees.to_radians().cos();
    let normal = |f: usize| {
        let face = welded.face(f);
        let mut n = glam::DVec3::ZERO;
        for (i, &a) in face.iter().enumerate() {
            let p = welded.positions()[a as usize];
            let q = welded.positions()[face[(i + 1) % face.len()] as usize];
            n += p.cross(q);
        }
        n.normalize_or_zero()
    };
    let mut creases = Vec::new();
    for e in 0..topology.edge_count() {
        let faces: Vec<usize> = topology.edge_faces(e).map(|f| f as usize).collect();
        if faces.len() != 2 {
            continue;
        }
        let [a, b] = topology.edges()[e];
        let p = bits(welded.positions()[a as usize]);
        let q = bits(welded.positions()[b as usize]);
        let seam = was_naked.contains(&(p, q)) || was_naked.contains(&(q, p));
        let folded = angle_degrees < 180.0 && normal(faces[0]).dot(normal(faces[1])) < cos_limit;
        if seam || folded {
            creases.push(([a, b], SHARPNESS_INFINITE));
        }
    }
    Ok(CreasedMesh {
        mesh: welded,
        creases,
        vertex_map: remap,
    })
}

/// What [`creases_from_mesh`] makes.
#[derive(Debug, Clone)]
pub struct CreasedMesh {
    /// The welded mesh.
    pub mesh: Mesh,
    /// Its infinitely sharp creases, as vertex pairs of `mesh`.
    pub creases: Vec<Crease>,
    /// For each vertex of the input, its vertex in `mesh`: so colours,
    /// creases and corners given on the input can follow.
    pub vertex_map: Vec<u32>,
}
