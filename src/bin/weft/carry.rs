//! Vertex colours, UVs and creases carried through the commands that change
//! a mesh: subdivision (colours as per-vertex data, UVs face-varying, the
//! limit surface), triangulation and the welding of unwelded creases.

use std::collections::HashMap;

use weft::io::{Colours, FileCorner, FileCrease, MeshFile, Uvs};
use weft::subdivide::{
    creases_from_mesh, CreasedMesh, FaceVaryingLinear, Scheme, Subdivider, SubdivisionOptions,
};

/// `file` as triangles (see [`weft::mesh::triangulate::as_triangles`]) and the
/// number of faces that were split; colours and creases keep their vertices, UVs
/// follow each triangle's corners back to its polygon's.
pub fn as_triangles(file: &MeshFile) -> weft::Result<(MeshFile, usize)> {
    let (triangulation, split) = weft::mesh::triangulate::as_triangles(&file.mesh)?;
    let uvs = file.uvs.as_ref().map(|uvs| {
        let offsets = file.mesh.face_offsets();
        let mut indices = Vec::with_capacity(triangulation.mesh.index_count());
        for (t, &f) in triangulation.parent_faces.iter().enumerate() {
            let face = file.mesh.face(f as usize);
            let start = offsets[f as usize] as usize;
            for &v in triangulation.mesh.face(t) {
                // A face never repeats a vertex, so the corner is unique.
                let k = face.iter().position(|&x| x == v).unwrap_or(0);
                indices.push(uvs.indices[start + k]);
            }
        }
        Uvs {
            values: uvs.values.clone(),
            indices,
        }
    });
    let materials = file
        .materials
        .as_ref()
        .map(|m| m.inherited(&triangulation.parent_faces));
    // A hole's triangles are holes.
    let holes = (0..triangulation.parent_faces.len() as u32)
        .filter(|&t| {
            file.holes
                .binary_search(&triangulation.parent_faces[t as usize])
                .is_ok()
        })
        .collect();
    let file = MeshFile {
        mesh: triangulation.mesh,
        uvs,
        materials,
        holes,
        ..file.clone()
    };
    Ok((file, split))
}

/// Welds vertices at identical positions and adds a hard crease on every
/// seam that was unwelded and every edge folded more than `angle_degrees`
/// ([`creases_from_mesh`]). Colours take the first welded vertex's; creases
/// and corners follow their vertices; UVs stay with their corners. Returns
/// the file and how many creases were found.
pub fn crease_by_angle(file: &MeshFile, angle_degrees: f64) -> weft::Result<(MeshFile, usize)> {
    let CreasedMesh {
        mesh: welded,
        creases: found,
        vertex_map: remap,
    } = creases_from_mesh(&file.mesh, angle_degrees)?;
    let colours = file.colours.as_ref().map(|colours| {
        let mut rgba = vec![[0.0; 4]; welded.vertex_count()];
        for (v, &to) in remap.iter().enumerate().rev() {
            rgba[to as usize] = colours.rgba[v];
        }
        Colours {
            rgba,
            alpha: colours.alpha,
        }
    });
    let mut creases: Vec<FileCrease> = file
        .creases
        .iter()
        .map(|c| FileCrease {
            edge: c.edge.map(|v| remap[v as usize]),
            ..*c
        })
        .collect();
    creases.extend(found.iter().map(|&(edge, sharpness)| FileCrease {
        edge,
        sharpness,
        line: 0,
    }));
    let corners = file
        .corners
        .iter()
        .map(|c| FileCorner {
            vertex: remap[c.vertex as usize],
            ..*c
        })
        .collect();
    Ok((
        MeshFile {
            mesh: welded,
            colours,
            uvs: file.uvs.clone(),
            normals: None,
            creases,
            corners,
            materials: file.materials.clone(),
            holes: file.holes.clone(),
        },
        found.len(),
    ))
}

/// How `subdivide` treats what the file carries.
pub struct Carry {
    pub scheme: Scheme,
    pub levels: u32,
    pub options: SubdivisionOptions,
    pub uv_linear: FaceVaryingLinear,
    /// Project onto the limit surface and add limit normals.
    pub limit: bool,
}

/// Subdivides `file` with its creases and corners (`carry.options` holds
/// the naked-edge mode and creasing; the file's creases are added), its
/// colours as per-vertex data and its UVs face-varying; with `carry.limit`
/// the vertices go to the limit surface and get its normals.
pub fn subdivide(file: &MeshFile, carry: &Carry) -> weft::Result<MeshFile> {
    let options = with_file_tags(carry.options.clone(), file);
    let subdivider = Subdivider::new(&file.mesh, carry.scheme, carry.levels, &options)?;
    let mut out = MeshFile::new(subdivider.mesh()?);
    if let Some(colours) = &file.colours {
        let flat: Vec<f64> = colours.rgba.iter().flatten().copied().collect();
        let refined = subdivider.vertex_data(&flat, 4)?;
        out.colours = Some(Colours {
            rgba: refined
                .chunks_exact(4)
                .map(|c| [c[0], c[1], c[2], c[3]])
                .collect(),
            alpha: colours.alpha,
        });
    }
    if let Some(uvs) = &file.uvs {
        let flat: Vec<f64> = uvs.values.iter().flatten().copied().collect();
        let corners = subdivider.face_varying(&flat, 2, &uvs.indices, carry.uv_linear)?;
        out.uvs = Some(shared_values(&corners));
    }
    if let Some(materials) = &file.materials {
        out.materials = Some(materials.inherited(&subdivider.parent_faces()));
    }
    if carry.limit {
        let limit = subdivider.limit()?;
        out.mesh.positions_mut().copy_from_slice(&limit.positions);
        out.normals = Some(limit.normals);
    }
    Ok(out)
}

/// Per-corner UVs as a list of distinct values and an index per corner.
fn shared_values(corners: &[f64]) -> Uvs {
    let mut seen = HashMap::new();
    let mut uvs = Uvs::default();
    for uv in corners.chunks_exact(2) {
        let value = [uv[0], uv[1]];
        let next = uvs.values.len() as u32;
        let index = *seen
            .entry([value[0].to_bits(), value[1].to_bits()])
            .or_insert_with(|| {
                uvs.values.push(value);
                next
            });
        uvs.indices.push(index);
    }
    uvs
}

/// Whether the plain subdivision does it all (nothing carried, creased or
/// holed, Catmull-Clark's own triangle weights).
pub fn is_plain(file: &MeshFile, carry: &Carry) -> bool {
    !file.has_attributes()
        && carry.options.creases.is_empty()
        && carry.options.corners.is_empty()
        && carry.options.holes.is_empty()
        && carry.options.triangles == weft::subdivide::TriangleRule::Catmark
        && !carry.limit
}

/// `options` with the creases, corners and holes `file` carries added.
pub fn with_file_tags(mut options: SubdivisionOptions, file: &MeshFile) -> SubdivisionOptions {
    options.creases.extend(file.subdivision_creases());
    options.corners.extend(file.subdivision_corners());
    options.holes.extend(&file.holes);
    options
}
