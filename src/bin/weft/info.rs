//! `weft info`: what a mesh is made of, as text or as one JSON object, both
//! printed from one table of rows so the two never disagree.

use std::path::Path;

use rayon::prelude::*;
use weft::mesh::analysis;
use weft::{Mesh, MeshInfo};

/// What `weft info` reports.
pub struct Report {
    vertices: usize,
    /// Vertices no face uses.
    unused_vertices: usize,
    faces: usize,
    triangles: usize,
    quads: usize,
    ngons: usize,
    edges: usize,
    naked_edges: usize,
    non_manifold_edges: usize,
    non_manifold_vertices: usize,
    components: usize,
    closed: bool,
    orientable: bool,
    oriented: bool,
    bounding_box: Option<([f64; 3], [f64; 3])>,
    /// The largest distance of a face's corners from its best-fit plane.
    max_planarity_deviation: f64,
    /// Faces further from planar than the tolerance.
    non_planar_faces: usize,
    planarity_tolerance: f64,
    /// What the file carries besides the mesh.
    pub attributes: Vec<&'static str>,
}

pub fn describe(mesh: &Mesh, planarity_tolerance: f64) -> weft::Result<Report> {
    // The topology beside the per-face and per-vertex counts; each side
    // splits its own work over the threads rayon has free.
    let (info, (planarity, unused_vertices)) = rayon::join(
        || MeshInfo::of(mesh),
        || {
            rayon::join(
                || analysis::planarity(mesh, planarity_tolerance),
                || weft::mend::weld::unused_vertex_count(mesh),
            )
        },
    );
    let planarity = planarity?;
    // A mesh of one face size answers without writing out its sizes.
    let count = |size: u32| match mesh.uniform_face_size() {
        Some(uniform) => usize::from(uniform == size as usize) * mesh.face_count(),
        None => mesh.face_sizes().par_iter().filter(|&&s| s == size).count(),
    };
    let (triangles, quads) = (count(3), count(4));
    Ok(Report {
        vertices: info.vertex_count,
        unused_vertices,
        faces: info.face_count,
        triangles,
        quads,
        ngons: info.face_count - triangles - quads,
        edges: info.edge_count,
        naked_edges: info.naked_edge_count,
        non_manifold_edges: info.non_manifold_edge_count,
        non_manifold_vertices: info.non_manifold_vertex_count,
        components: info.component_count,
        closed: info.is_closed,
        orientable: info.is_orientable,
        oriented: info.is_oriented,
        bounding_box: mesh
            .bounding_box()
            .map(|(lo, hi)| (lo.to_array(), hi.to_array())),
        max_planarity_deviation: planarity.largest_deviation,
        non_planar_faces: planarity.faces_beyond,
        planarity_tolerance,
        attributes: Vec::new(),
    })
}

/// One fact of the report: its line of text (none when the text leaves it
/// out) and its JSON members.
struct Row {
    label: &'static str,
    text: Option<String>,
    json: Vec<(&'static str, String)>,
}

/// A row whose text and JSON show the same number.
fn count(label: &'static str, key: &'static str, value: usize) -> Row {
    Row {
        label,
        text: Some(value.to_string()),
        json: vec![(key, value.to_string())],
    }
}

/// A row of a yes/no fact: "yes"/"no" in text, true/false in JSON.
fn flag(label: &'static str, value: bool) -> Row {
    Row {
        label,
        text: Some(if value { "yes" } else { "no" }.to_string()),
        json: vec![(label, value.to_string())],
    }
}

impl Report {
    /// Whether no two faces share an edge (each face a piece of its own
    /// with only naked edges), as the faces of an STL file are read.
    pub fn faces_share_no_edge(&self) -> bool {
        self.faces > 1 && self.components == self.faces && self.naked_edges == self.edges
    }

    fn rows(&self) -> Vec<Row> {
        let point = |p: [f64; 3]| format!("[{}, {}, {}]", p[0], p[1], p[2]);
        vec![
            count("vertices", "vertices", self.vertices),
            count("unused vertices", "unused_vertices", self.unused_vertices),
            Row {
                label: "faces",
                text: Some(format!(
                    "{} ({} triangles, {} quads, {} n-gons)",
                    self.faces, self.triangles, self.quads, self.ngons
                )),
                json: vec![
                    ("faces", self.faces.to_string()),
                    ("triangles", self.triangles.to_string()),
                    ("quads", self.quads.to_string()),
                    ("ngons", self.ngons.to_string()),
                ],
            },
            count("edges", "edges", self.edges),
            count("naked edges", "naked_edges", self.naked_edges),
            count(
                "non-manifold edges",
                "non_manifold_edges",
                self.non_manifold_edges,
            ),
            count(
                "non-manifold vertices",
                "non_manifold_vertices",
                self.non_manifold_vertices,
            ),
            count("components", "components", self.components),
            flag("closed", self.closed),
            flag("orientable", self.orientable),
            flag("oriented", self.oriented),
            Row {
                label: "planarity",
                text: Some(format!(
                    "{} of {} faces beyond {} of their best-fit plane (largest deviation {:.3e})",
                    self.non_planar_faces,
                    self.faces,
                    self.planarity_tolerance,
                    self.max_planarity_deviation
                )),
                json: vec![(
                    "planarity",
                    format!(
                        "{{\"tolerance\": {}, \"non_planar_faces\": {}, \"max_deviation\": {}}}",
                        self.planarity_tolerance,
                        self.non_planar_faces,
                        self.max_planarity_deviation
                    ),
                )],
            },
            Row {
                label: "bounding box",
                text: Some(match self.bounding_box {
                    Some((lo, hi)) => format!(
                        "({}, {}, {}) to ({}, {}, {})",
                        lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]
                    ),
                    None => "none (no vertices)".to_string(),
                }),
                json: vec![(
                    "bounding_box",
                    match self.bounding_box {
                        Some((lo, hi)) => {
                            format!("{{\"min\": {}, \"max\": {}}}", point(lo), point(hi))
                        }
                        None => "null".to_string(),
                    },
                )],
            },
            Row {
                label: "carried data",
                text: (!self.attributes.is_empty()).then(|| self.attributes.join(", ")),
                json: vec![(
                    "carried",
                    format!(
                        "[{}]",
                        self.attributes
                            .iter()
                            .map(|name| json_string(name))
                            .collect::<Vec<_>>()
                            .join(", ")
                    ),
                )],
            },
        ]
    }

    pub fn text(&self, path: &Path) -> String {
        let mut s = format!("{}\n", path.display());
        for row in self.rows() {
            if let Some(value) = row.text {
                s.push_str(&format!("  {:<22}{value}\n", row.label));
            }
        }
        s
    }

    pub fn json(&self, path: &Path) -> String {
        let mut members = vec![format!(
            "\"file\": {}",
            json_string(&path.to_string_lossy())
        )];
        for row in self.rows() {
            members.extend(
                row.json
                    .into_iter()
                    .map(|(key, value)| format!("\"{key}\": {value}")),
            );
        }
        format!("{{{}}}", members.join(", "))
    }
}

fn json_string(s: &str) -> String {
    let mut out = String::from("\"");
    for c in s.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            c if (c as u32) < 0x20 => out.push_str(&format!("\\u{:04x}", c as u32)),
            c => out.push(c),
        }
    }
    out.push('"');
    out
}
