//! Face-varying data (UVs): values per face corner, where corners of one
//! vertex may use different values (a seam), refined as OpenSubdiv's
//! `PrimvarRefiner::InterpolateFaceVarying` does with its
//! `Sdc::Options::FVarLinearInterpolation` (`Vtr::FVarLevel` tags).
//!
//! Each level, every distinct value at a vertex (a *sibling*, whose *span*
//! is the fan of faces around the vertex that share it) makes one child
//! value; an edge makes one child value, or one per face where it is a seam
//! or naked; a Catmull-Clark face makes one (the average). A value whose
//! vertex has no seam is refined with the vertex's own mask (creases
//! included). A value on a seam follows the seam as a crease (3/4 itself,
//! 1/8 each neighbour along the seam; at the end of a seam, a dart, the
//! neighbours on either side of the seam edge); it stays where the linear
//! option, an infinitely sharp vertex or an infinitely sharp edge inside its
//! span makes it a corner, and a semi-sharp span is a corner until its
//! sharpness decays, then blends. Seam and naked edges make midpoints.

use super::creases::{fractional_weight, Sharpness, SHARPNESS_INFINITE};
use super::level::{Connectivity, Faces};
use super::scale;
use super::scheme::Scheme;
use super::stencils::{edge_weights, vertex_mask};
use super::subdivider::{KeptLevel, Subdivider};
use crate::error::{Error, Result};

/// Where face-varying values are interpolated linearly (OpenSubdiv's
/// `FVarLinearInterpolation`); the values are stable (the C ABI uses them).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[repr(u32)]
pub enum FaceVaryingLinear {
    /// Smooth everywhere; seams are followed like naked edges (`FVAR_LINEAR_NONE`).
    Smooth = 0,
    /// As smooth, but a value on a single face at a seam or boundary (a UV
    /// corner) stays (`FVAR_LINEAR_CORNERS_ONLY`).
    CornersOnly = 1,
    /// As corners only, and every value where three or more UV regions meet
    /// stays (`FVAR_LINEAR_CORNERS_PLUS1`).
    CornersPlus1 = 2,
    /// As corners plus one, and both values of a two-region vertex stay when
    /// one is a corner, as does the end of a seam (`FVAR_LINEAR_CORNERS_PLUS2`).
    CornersPlus2 = 3,
    /// Linear along every seam and naked edge (`FVAR_LINEAR_BOUNDARIES`).
    Boundaries = 4,
    /// Linear everywhere, OpenSubdiv's default (`FVAR_LINEAR_ALL`).
    #[default]
    All = 5,
}

impl Subdivider {
    /// Refines per-face-corner values: `values` holds `width` numbers per
    /// value, `value_indices` the value of every cage face corner (face after
    /// face). Returns `width` numbers per refined face corner, face after face
    /// in the order of [`Subdivider::face_indices`].
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] when `width` is 0, `values` is not a whole
    /// number of values, `value_indices` does not have one index per cage
    /// corner, an index is past the values, or a value is NaN or infinite;
    /// [`Error::DegenerateInput`] naming the refined face corner when a
    /// value lies beyond the largest `f64` (values near `f64::MAX` are
    /// refined at an exactly scaled-down size, so the sums never overflow).
    pub fn face_varying(
        &self,
        values: &[f64],
        width: usize,
        value_indices: &[u32],
        linear: FaceVaryingLinear,
    ) -> Result<Vec<f64>> {
        if width == 0 || values.len() % width != 0 {
            return Err(Error::InvalidArgument(format!(
                "{} numbers are not a whole number of values of width {width}",
                values.len()
            )));
        }
        let count = values.len() / width;
        if value_indices.len() != self.cage_corner_count() {
            return Err(Error::InvalidArgument(format!(
                "{} face-varying indices for {} face corners",
                value_indices.len(),
                self.cage_corner_count()
            )));
        }
        if let Some(c) = value_indices.iter().position(|&i| i as usize >= count) {
            return Err(Error::InvalidArgument(format!(
                "face corner {c} uses value {}, but there are {count} values",
                value_indices[c]
            )));
        }
        if let Some(i) = values.iter().position(|x| !x.is_finite()) {
            return Err(Error::InvalidArgument(format!(
                "face-varying value {} has a non-finite number {} at component {}",
                i / width,
                values[i],
                i % width
            )));
        }
        // Values near the top of the f64 range are refined at an exactly
        // scaled-down size (see `scale.rs`); ordinary values as they are.
        let scale = scale::for_values(values);
        let mut values = match scale {
            Some(scale) => values.iter().map(|x| x * scale.down).collect(),
            None => values.to_vec(),
        };
        let mut indices = value_indices.to_vec();
        for pair in self.levels.windows(2) {
            (values, indices) =
                self.refine_face_varying(&pair[0], &pair[1], &values, width, &indices, linear);
        }
        // Holes leave their corners out.
        if let Some(visible) = &self.visible {
            indices = visible
                .corners
                .iter()
                .map(|&c| indices[c as usize])
                .collect();
        }
        let mut out = Vec::with_capacity(indices.len() * width);
        for &i in &indices {
            out.extend_from_slice(&values[i as usize * width..(i as usize + 1) * width]);
        }
        if let Some(scale) = scale {
            scale::restore_values(&mut out, width, scale, "the value", "refined face corner")?;
        }
        Ok(out)
    }

    fn refine_face_varying(
        &self,
        parent: &KeptLevel,
        child: &KeptLevel,
        values: &[f64],
        width: usize,
        indices: &[u32],
        linear: FaceVaryingLinear,
    ) -> (Vec<f64>, Vec<u32>) {
        let faces = &parent.faces;
        let connectivity = &parent.connectivity;
        let sharpness = &parent.sharpness;
        let face_of = |c: usize| connectivity.face_of(c);
        let value = |i: u32| &values[i as usize * width..(i as usize + 1) * width];
        let mut out: Vec<f64> = Vec::new();
        // Appends Σ weight · value and returns the new value's index.
        let emit = |out: &mut Vec<f64>, terms: &[(f64, u32)], face_sums: &[(f64, usize)]| {
            let start = out.len();
            out.resize(start + width, 0.0);
            for &(w, i) in terms {
                for (o, x) in out[start..].iter_mut().zip(value(i)) {
                    *o += w * x;
                }
            }
            for &(w, f) in face_sums {
                let corners = faces.offsets[f] as usize..faces.offsets[f + 1] as usize;
                let share = w / corners.len() as f64;
                for c in corners {
                    for (o, x) in out[start..].iter_mut().zip(value(indices[c])) {
                        *o += share * x;
                    }
                }
            }
            (start / width) as u32
        };

        // Is edge e a seam or naked (its faces disagree on a value at an end)?
        let seam = |e: usize| -> bool {
            match *connectivity.edge_corners(e) {
                [c1, c2] => {
                    let (c1, c2) = (c1 as usize, c2 as usize);
                    let n1 = faces.next(c1, face_of(c1));
                    let n2 = faces.next(c2, face_of(c2));
                    faces.indices[c1] != faces.indices[n2]
                        || indices[c1] != indices[n2]
                        || indices[n1] != indices[c2]
                }
                _ => true,
            }
        };

        // Vertex children, one per sibling, in the order of their first corner.
        let mut vertex_child = vec![0u32; faces.corner_count()];
        let mut scratch = Vec::new();
        let mut siblings: Vec<u32> = Vec::new();
        for v in 0..faces.vertex_count {
            let corners = connectivity.vertex_corners(v);
            siblings.clear();
            for &c in corners {
                if !siblings.contains(&indices[c as usize]) {
                    siblings.push(indices[c as usize]);
                }
            }
            let edges = sharpness.edges_at(v);
            let naked = edges
                .iter()
                .any(|&e| connectivity.edge_corners(e as usize).len() == 1);
            let seamed = siblings.len() > 1
                || edges
                    .iter()
                    .any(|&e| connectivity.edge_corners(e as usize).len() == 2 && seam(e as usize));
            let plus = matches!(
                linear,
                FaceVaryingLinear::CornersPlus1 | FaceVaryingLinear::CornersPlus2
            );
            // Values OpenSubdiv makes corners all at once
            // (`FVarLevel::completeTopologyFromFaceValues`): at an infinitely
            // sharp vertex, where three or more regions meet (Plus1, Plus2),
            // at the end of a seam inside the mesh (Plus2).
            let mut all_sharp = sharpness.vertices[v] >= SHARPNESS_INFINITE as f32
                || (plus && siblings.len() > 2)
                || (linear == FaceVaryingLinear::CornersPlus2 && siblings.len() == 1 && !naked);
            let spans: Vec<Span> = siblings
                .iter()
                .map(|&sibling| span_of(faces, connectivity, sharpness, indices, v, sibling))
                .collect();
            if plus && spans.len() == 2 {
                all_sharp |= spans.iter().any(|span| span.infinite_edges > 0);
                if linear == FaceVaryingLinear::CornersPlus2 {
                    all_sharp |= spans.iter().any(|span| span.corners.len() == 1);
                }
            }
            for (&sibling, span) in siblings.iter().zip(&spans) {
                let fan = &span.corners;
                let corner = (naked || seamed) && fan.len() == 1;
                let stays = match linear {
                    FaceVaryingLinear::All => true,
                    FaceVaryingLinear::Boundaries => naked || seamed,
                    FaceVaryingLinear::Smooth => false,
                    _ => corner,
                } || (seamed && (all_sharp || span.infinite_edges > 0));
                let index = if stays {
                    emit(&mut out, &[(1.0, sibling)], &[])
                } else if !seamed {
                    let mask = vertex_mask(
                        self.scheme,
                        &self.options,
                        connectivity,
                        sharpness,
                        &child.sharpness,
                        v,
                        &mut scratch,
                    );
                    let mut terms = vec![(mask.vertex, sibling)];
                    for (&e, &w) in edges.iter().zip(&mask.edges) {
                        if w != 0.0 {
                            terms.push((w, far_value(faces, connectivity, indices, e, v)));
                        }
                    }
                    let face_sums: Vec<(f64, usize)> = if self.scheme == Scheme::CatmullClark {
                        corners
                            .iter()
                            .zip(&mask.faces)
                            .filter(|(_, &w)| w != 0.0)
                            .map(|(&c, &w)| (w, face_of(c as usize)))
                            .collect()
                    } else {
                        Vec::new()
                    };
                    emit(&mut out, &terms, &face_sums)
                } else {
                    // A crease along the seam, towards the far values of the
                    // span's two bounding edges (both sides of the one seam
                    // edge at the end of a seam); a semi-sharp span is a
                    // corner until its sharpness decays, then blends.
                    let ends = if siblings.len() == 1 {
                        let seams: Vec<u32> = edges
                            .iter()
                            .copied()
                            .filter(|&e| {
                                connectivity.edge_corners(e as usize).len() == 2 && seam(e as usize)
                            })
                            .collect();
                        match seams[..] {
                            [e] => far_values(faces, connectivity, indices, e, v).to_vec(),
                            _ => Vec::new(),
                        }
                    } else {
                        fan_ends(faces, connectivity, indices, fan)
                    };
                    let parent_vertex = sharpness.vertices[v];
                    let child_vertex = child.sharpness.vertices[v];
                    let parent_edges: Vec<f32> = span
                        .interior_edges
                        .iter()
                        .map(|&e| sharpness.edges[e as usize])
                        .collect();
                    let child_edges: Vec<f32> = span
                        .interior_edges
                        .iter()
                        .map(|&e| {
                            sharpness.child_edge_sharpness(
                                self.options.creasing,
                                connectivity,
                                e as usize,
                                v,
                            )
                        })
                        .collect();
                    let semi_sharp = parent_vertex > 0.0 || parent_edges.iter().any(|&s| s > 0.0);
                    let still_sharp = child_vertex > 0.0 || child_edges.iter().any(|&s| s > 0.0);
                    match ends[..] {
                        [a, b] if !(semi_sharp && still_sharp) => {
                            let corner_weight = if semi_sharp {
                                f64::from(fractional_weight(
                                    parent_vertex,
                                    child_vertex,
                                    parent_edges.iter().copied(),
                                    &child_edges,
                                ))
                            } else {
                                0.0
                            };
                            let crease_weight = 1.0 - corner_weight;
                            let end = crease_weight * 0.125;
                            emit(
                                &mut out,
                                &[
                                    (end, a),
                                    (end, b),
                                    (crease_weight * 0.75 + corner_weight, sibling),
                                ],
                                &[],
                            )
                        }
                        _ => emit(&mut out, &[(1.0, sibling)], &[]),
                    }
                };
                for &c in fan {
                    vertex_child[c] = index;
                }
            }
        }

        // Edge children: one per face on seams and naked edges, else one.
        let mut edge_child = vec![0u32; faces.corner_count()];
        for e in 0..connectivity.edge_count() {
            let corners = connectivity.edge_corners(e);
            let ends_of = |c: usize| (indices[c], indices[faces.next(c, face_of(c))]);
            if seam(e) || linear == FaceVaryingLinear::All {
                for &c in corners {
                    let (x, y) = ends_of(c as usize);
                    edge_child[c as usize] = emit(&mut out, &[(0.5, x), (0.5, y)], &[]);
                }
                continue;
            }
            let c1 = corners[0] as usize;
            let (x, y) = ends_of(c1);
            let weights = edge_weights(
                self.scheme,
                self.options.triangles,
                faces,
                connectivity,
                sharpness,
                &child.sharpness,
                e,
            );
            let index = match weights {
                None => emit(&mut out, &[(0.5, x), (0.5, y)], &[]),
                Some((end, wing)) => match self.scheme {
                    Scheme::CatmullClark => emit(
                        &mut out,
                        &[(end, x), (end, y)],
                        &[
                            (wing, face_of(corners[0] as usize)),
                            (wing, face_of(corners[1] as usize)),
                        ],
                    ),
                    Scheme::Loop => {
                        let opposite = |c: usize| {
                            let f = face_of(c);
                            indices[faces.next(faces.next(c, f), f)]
                        };
                        emit(
                            &mut out,
                            &[
                                (end, x),
                                (end, y),
                                (wing, opposite(corners[0] as usize)),
                                (wing, opposite(corners[1] as usize)),
                            ],
                            &[],
                        )
                    }
                },
            };
            for &c in corners {
                edge_child[c as usize] = index;
            }
        }

        // Face children (Catmull-Clark) and the child corners' values.
        let child_faces = &child.faces;
        let mut child_indices = vec![0u32; child_faces.corner_count()];
        match self.scheme {
            Scheme::CatmullClark => {
                for f in 0..faces.face_count() {
                    let centre = emit(&mut out, &[], &[(1.0, f)]);
                    for c in faces.offsets[f] as usize..faces.offsets[f + 1] as usize {
                        let previous = faces.prev(c, f);
                        child_indices[4 * c..4 * c + 4].copy_from_slice(&[
                            vertex_child[c],
                            edge_child[c],
                            centre,
                            edge_child[previous],
                        ]);
                    }
                }
            }
            Scheme::Loop => {
                for f in 0..faces.face_count() {
                    let c = 3 * f;
                    let e = [edge_child[c], edge_child[c + 1], edge_child[c + 2]];
                    let v = [vertex_child[c], vertex_child[c + 1], vertex_child[c + 2]];
                    child_indices[12 * f..12 * f + 12].copy_from_slice(&[
                        v[0], e[0], e[2], v[1], e[1], e[0], v[2], e[2], e[1], e[0], e[1], e[2],
                    ]);
                }
            }
        }
        (out, child_indices)
    }
}

/// The value at the far end of edge `e` from `v`, seen from the edge's
/// first face (the edge is no seam, so every face agrees).
fn far_value(faces: &Faces, connectivity: &Connectivity, indices: &[u32], e: u32, v: usize) -> u32 {
    let c = connectivity.edge_corners(e as usize)[0] as usize;
    let f = connectivity.face_of(c);
    if faces.indices[c] as usize == v {
        indices[faces.next(c, f)]
    } else {
        indices[c]
    }
}

/// The values at the far end of edge `e` from `v`, seen from its two faces.
fn far_values(
    faces: &Faces,
    connectivity: &Connectivity,
    indices: &[u32],
    e: u32,
    v: usize,
) -> [u32; 2] {
    let mut out = [0; 2];
    for (slot, &c) in out.iter_mut().zip(connectivity.edge_corners(e as usize)) {
        let c = c as usize;
        let f = connectivity.face_of(c);
        *slot = if faces.indices[c] as usize == v {
            indices[faces.next(c, f)]
        } else {
            indices[c]
        };
    }
    out
}

/// The far values of the seam or naked edges that bound a fan of corners
/// sharing one value at a vertex.
fn fan_ends(
    faces: &Faces,
    connectivity: &Connectivity,
    indices: &[u32],
    fan: &[usize],
) -> Vec<u32> {
    let face_of = |c: usize| connectivity.face_of(c);
    let mut ends = Vec::new();
    for &c in fan {
        let f = face_of(c);
        let (next, previous) = (faces.next(c, f), faces.prev(c, f));
        // The edge leaving c and the edge arriving at c.
        for (edge, far) in [
            (connectivity.corner_edges[c], indices[next]),
            (connectivity.corner_edges[previous], indices[previous]),
        ] {
            let e = edge as usize;
            let corners = connectivity.edge_corners(e);
            let other_side_differs = match *corners {
                [c1, c2] => {
                    // The other face's corner at the same vertex.
                    let other = if c1 as usize == c || c1 as usize == previous {
                        c2
                    } else {
                        c1
                    } as usize;
                    let of = face_of(other);
                    let at_vertex = if faces.indices[other] == faces.indices[c] {
                        other
                    } else {
                        faces.next(other, of)
                    };
                    indices[at_vertex] != indices[c]
                }
                _ => true,
            };
            if other_side_differs {
                ends.push(far);
            }
        }
    }
    ends
}

/// The faces around a vertex that share one of its values, and the edges
/// between two of them (`FVarLevel::gatherValueSpans`).
struct Span {
    /// The corners at the vertex with this value.
    corners: Vec<usize>,
    /// Edges at the vertex whose two faces both use this value there.
    interior_edges: Vec<u32>,
    /// How many of those are infinitely sharp.
    infinite_edges: usize,
}

fn span_of(
    faces: &Faces,
    connectivity: &Connectivity,
    sharpness: &Sharpness,
    indices: &[u32],
    v: usize,
    sibling: u32,
) -> Span {
    let corners: Vec<usize> = connectivity
        .vertex_corners(v)
        .iter()
        .map(|&c| c as usize)
        .filter(|&c| indices[c] == sibling)
        .collect();
    let at_vertex = |c: usize| {
        let f = connectivity.face_of(c);
        if faces.indices[c] as usize == v {
            c
        } else {
            faces.next(c, f)
        }
    };
    let interior_edges: Vec<u32> = sharpness
        .edges_at(v)
        .iter()
        .copied()
        .filter(|&e| match *connectivity.edge_corners(e as usize) {
            [c1, c2] => {
                let (a, b) = (at_vertex(c1 as usize), at_vertex(c2 as usize));
                let (na, nb) = (
                    faces.next(c1 as usize, connectivity.face_of(c1 as usize)),
                    faces.next(c2 as usize, connectivity.face_of(c2 as usize)),
                );
                // Both faces use the value here, and agree at the far end
                // too (a seam inside the span, at a dart, bounds it instead).
                let far_a = if a == c1 as usize { na } else { c1 as usize };
                let far_b = if b == c2 as usize { nb } else { c2 as usize };
                faces.indices[a] as usize == v
                    && faces.indices[b] as usize == v
                    && indices[a] == sibling
                    && indices[b] == sibling
                    && indices[far_a] == indices[far_b]
            }
            _ => false,
        })
        .collect();
    let infinite_edges = interior_edges
        .iter()
        .filter(|&&e| sharpness.edges[e as usize] >= SHARPNESS_INFINITE as f32)
        .count();
    Span {
        corners,
        interior_edges,
        infinite_edges,
    }
}
