//! What the OpenSubdiv comparisons share: Weft's meshes and options in the
//! reference's terms, and the matching of refined vertices and faces.

#![allow(dead_code)]

use weft::subdivide::{
    parent_faces_with, refined_counts_with, subdivide_with, Creasing, FaceVaryingLinear,
    NakedEdges, Scheme, Subdivider, SubdivisionOptions, TriangleRule,
};
use weft::{DVec3, Mesh};
use weft_reference::{
    boundary_vertices, opensubdiv_refine_face_varying, BoundaryInterpolation, CreasingMethod,
    FVarLinear, Limit, OsdOptions, OsdRefiner, RefMesh,
};

pub fn to_ref(mesh: &Mesh) -> RefMesh {
    RefMesh {
        positions: mesh.positions().iter().flat_map(|p| p.to_array()).collect(),
        face_sizes: mesh.face_sizes().to_vec(),
        face_indices: mesh.face_indices().to_vec(),
    }
}

/// OpenSubdiv's options for Weft's scheme and options on `cage`.
pub fn osd_options(scheme: Scheme, options: &SubdivisionOptions, cage: &RefMesh) -> OsdOptions {
    let scheme = match scheme {
        Scheme::CatmullClark => weft_reference::Scheme::CatmullClark,
        Scheme::Loop => weft_reference::Scheme::Loop,
    };
    let boundary = match options.naked_edges {
        NakedEdges::CornerFixed => BoundaryInterpolation::EdgeAndCorner,
        NakedEdges::None => BoundaryInterpolation::None,
        NakedEdges::Smooth | NakedEdges::Fixed => BoundaryInterpolation::EdgeOnly,
    };
    let mut osd = OsdOptions::new(scheme, boundary);
    osd.holes = options.holes.clone();
    osd.smooth_triangles = options.triangles == TriangleRule::Smooth;
    osd.creasing = match options.creasing {
        Creasing::Uniform => CreasingMethod::Uniform,
        Creasing::Chaikin => CreasingMethod::Chaikin,
    };
    for &(edge, s) in &options.creases {
        osd.crease_edges.push(edge);
        osd.crease_sharpness.push(s.min(10.0) as f32);
    }
    for &(v, s) in &options.corners {
        osd.corner_vertices.push(v);
        osd.corner_sharpness.push(s.min(10.0) as f32);
    }
    if options.naked_edges == NakedEdges::Fixed {
        // The last value given for a vertex wins: the boundary's infinite one.
        for v in boundary_vertices(cage) {
            osd.corner_vertices.push(v);
            osd.corner_sharpness.push(10.0);
        }
    }
    osd
}

/// Moves every vertex a little along z (grids are flat otherwise), so the
/// creases and normals have something to show.
pub fn bumped(mesh: Mesh) -> Mesh {
    let positions = mesh
        .positions()
        .iter()
        .map(|p| *p + DVec3::new(0.0, 0.0, 0.3 * (1.7 * p.x).sin() * (1.3 * p.y + 0.4).cos()))
        .collect();
    Mesh::new(
        positions,
        mesh.face_sizes().to_vec(),
        mesh.face_indices().to_vec(),
    )
    .unwrap()
}

/// Ours → theirs vertex map by position (within the tolerance, one to one).
pub fn vertex_map(ours: &Mesh, theirs: &RefMesh, what: &str) -> Vec<usize> {
    assert_eq!(
        ours.vertex_count(),
        theirs.vertex_count(),
        "{what}: vertex counts"
    );
    assert_eq!(
        ours.face_count(),
        theirs.face_count(),
        "{what}: face counts"
    );
    let tol = tolerance(ours);
    let theirs: Vec<DVec3> = (0..theirs.vertex_count())
        .map(|v| DVec3::from_array(theirs.position(v)))
        .collect();
    let mut by_x: Vec<usize> = (0..theirs.len()).collect();
    by_x.sort_by(|&a, &b| theirs[a].x.total_cmp(&theirs[b].x));
    let mut taken = vec![false; theirs.len()];
    ours.positions()
        .iter()
        .enumerate()
        .map(|(v, p)| {
            let start = by_x.partition_point(|&r| theirs[r].x < p.x - tol);
            let found: Vec<usize> = by_x[start..]
                .iter()
                .take_while(|&&r| theirs[r].x <= p.x + tol)
                .copied()
                .filter(|&r| (theirs[r] - *p).length() <= tol)
                .collect();
            let nearest = theirs.iter().map(|q| (*q - *p).length()).fold(f64::INFINITY, f64::min);
            assert!(
                found.len() == 1,
                "{what}: vertex {v} at {p} has {} reference vertices within {tol:e} (nearest {nearest:e})",
                found.len()
            );
            assert!(!taken[found[0]], "{what}: reference vertex {} matched twice", found[0]);
            taken[found[0]] = true;
            found[0]
        })
        .collect()
}

/// For every face of ours, OpenSubdiv's face with the same vertices and
/// the rotation `r` such that our corner k is its corner (k + r) mod n.
pub fn face_map(ours: &Mesh, theirs: &RefMesh, vertices: &[usize]) -> Vec<(usize, usize)> {
    let mut index = std::collections::HashMap::new();
    for (f, face) in theirs.faces().enumerate() {
        let mut key = face.to_vec();
        key.sort_unstable();
        index.insert(key, f);
    }
    let their_faces: Vec<&[u32]> = theirs.faces().collect();
    ours.faces()
        .map(|face| {
            let mapped: Vec<u32> = face.iter().map(|&v| vertices[v as usize] as u32).collect();
            let mut key = mapped.clone();
            key.sort_unstable();
            let f = index[&key];
            let r = their_faces[f].iter().position(|&v| v == mapped[0]).unwrap();
            (f, r)
        })
        .collect()
}

pub fn tolerance(mesh: &Mesh) -> f64 {
    let (lo, hi) = mesh.bounding_box().unwrap();
    1e-9 * (hi - lo).length()
}

pub fn assert_rows_close(
    ours: &[f64],
    theirs: &[f64],
    width: usize,
    map: &[usize],
    tol: f64,
    what: &str,
) {
    for (v, &r) in map.iter().enumerate() {
        if r == usize::MAX {
            continue;
        }
        for k in 0..width {
            let (a, b) = (ours[v * width + k], theirs[r * width + k]);
            assert!(
                (a - b).abs() <= tol,
                "{what}: vertex {v} component {k}: {a} vs OpenSubdiv {b}"
            );
        }
    }
}

/// The one-shot driver, the counts and the parent faces with `options`
/// agree with `subdivider` and its mesh `ours`.
pub fn assert_drivers_agree(
    cage: &Mesh,
    (scheme, levels, options): (Scheme, u32, &SubdivisionOptions),
    subdivider: &Subdivider,
    ours: &Mesh,
    what: &str,
) {
    assert_eq!(
        &subdivide_with(cage, scheme, levels, options).unwrap(),
        ours,
        "{what}: one-shot"
    );
    let counts = refined_counts_with(cage, scheme, levels, options).unwrap();
    assert_eq!(
        (counts.vertex_count, counts.face_count, counts.index_count),
        (ours.vertex_count(), ours.face_count(), ours.index_count()),
        "{what}: counts"
    );
    assert_eq!(
        parent_faces_with(cage, scheme, levels, options).unwrap(),
        subdivider.parent_faces(),
        "{what}: parent faces"
    );
}

/// OpenSubdiv's limit at every refined vertex (its refiner built with the
/// full topology the limit needs).
pub fn opensubdiv_limit_at_vertices(cage: &RefMesh, osd: &OsdOptions, levels: u32) -> Limit {
    let full = OsdOptions {
        full_topology: true,
        ..osd.clone()
    };
    let refiner = OsdRefiner::new(cage, &full, levels).unwrap();
    refiner.limit(&cage.positions).unwrap()
}

/// Face-varying values refined by both with one linear rule: `(rule, ours
/// per refined corner, their values, their value of each refined corner)`.
pub type RefinedValues = (FaceVaryingLinear, Vec<f64>, Vec<f64>, Vec<u32>);

/// A face-varying value per cage vertex (two numbers), refined by Weft and
/// by OpenSubdiv with each linear rule.
pub fn face_varying_both(
    cage: &Mesh,
    osd: &OsdOptions,
    levels: u32,
    subdivider: &Subdivider,
) -> Vec<RefinedValues> {
    let values: Vec<f64> = cage
        .positions()
        .iter()
        .flat_map(|p| [p.x + 0.3 * p.z, p.y - 0.2 * p.z])
        .collect();
    let indices = cage.face_indices().to_vec();
    let reference_cage = to_ref(cage);
    [
        (FaceVaryingLinear::Smooth, FVarLinear::None),
        (FaceVaryingLinear::All, FVarLinear::All),
    ]
    .into_iter()
    .map(|(linear, their_linear)| {
        let ours = subdivider
            .face_varying(&values, 2, &indices, linear)
            .unwrap();
        let with_fvar = OsdOptions {
            fvar_linear: their_linear,
            ..osd.clone()
        };
        let (theirs, their_indices) =
            opensubdiv_refine_face_varying(&reference_cage, &with_fvar, levels, &values, &indices)
                .unwrap();
        (linear, ours, theirs, their_indices)
    })
    .collect()
}
