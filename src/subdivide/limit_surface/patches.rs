//! Which faces of a level are regular patches, and their control points.
//!
//! A Catmull-Clark quad is a bicubic B-spline patch when each of its corners
//! is smooth with four quads, a crease or boundary vertex with two quads on
//! the face's side of two infinitely sharp edges, or a corner with the face
//! alone; a Loop triangle is a box-spline patch when each corner is smooth
//! with six triangles or a crease or boundary vertex with three on its side.
//! Beyond an infinitely sharp edge the points are phantoms, reflections of
//! the points on the face's side (as OpenSubdiv's boundary patches), which
//! the crease rules (edge midpoint; vertex 3/4, 1/8, 1/8) reproduce exactly.
//! No edge at a corner may be semi-sharp: those faces are refined until the
//! sharpness has decayed.

use super::super::creases::{Rule, SHARPNESS_INFINITE};
use super::super::scheme::Scheme;
use super::super::subdivider::KeptLevel;

/// A control point as a combination of at most four points of the level.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub(super) struct Row {
    pub(super) points: [u32; 4],
    pub(super) weights: [f64; 4],
    pub(super) len: u8,
}

impl Row {
    fn point(p: u32) -> Row {
        Row {
            points: [p, 0, 0, 0],
            weights: [1.0, 0.0, 0.0, 0.0],
            len: 1,
        }
    }

    /// `Σ weight · row`, or `None` past four points.
    fn combine(terms: &[(f64, Row)]) -> Option<Row> {
        let mut out = Row::default();
        for &(w, row) in terms {
            for k in 0..row.len as usize {
                let (p, x) = (row.points[k], row.weights[k] * w);
                match (0..out.len as usize).find(|&j| out.points[j] == p) {
                    Some(j) => out.weights[j] += x,
                    None if out.len < 4 => {
                        out.points[out.len as usize] = p;
                        out.weights[out.len as usize] = x;
                        out.len += 1;
                    }
                    None => return None,
                }
            }
        }
        Some(out)
    }
}

/// How a corner of a regular patch sits.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Corner {
    Smooth,
    Crease,
    /// An infinitely sharp vertex with the face alone on its side.
    Sharp,
}

fn infinite(s: f32) -> bool {
    s >= SHARPNESS_INFINITE as f32
}

/// The corner of `level` at which face `f` holds the directed edge `a → b`.
fn corner_of_edge(level: &KeptLevel, a: u32, b: u32) -> Option<(usize, usize)> {
    let (faces, connectivity) = (&level.faces, &level.connectivity);
    let e = connectivity.find_edge(a, b)?;
    connectivity
        .edge_corners(e as usize)
        .iter()
        .map(|&c| (c as usize, connectivity.face_of(c as usize)))
        .find(|&(c, f)| faces.indices[c] == a && faces.indices[faces.next(c, f)] == b)
}

/// The face holding `a → b`, as its vertices from `a` on.
fn face_from(level: &KeptLevel, a: u32, b: u32, size: usize) -> Option<[u32; 4]> {
    let faces = &level.faces;
    let (mut c, f) = corner_of_edge(level, a, b)?;
    if faces.corners(f).len() != size {
        return None;
    }
    let mut out = [0; 4];
    for slot in out.iter_mut().take(size) {
        *slot = faces.indices[c];
        c = faces.next(c, f);
    }
    Some(out)
}

/// Classifies the corner `c` of face `g` (a corner index of `level`) for a
/// regular patch of `scheme`, or `None` when it is irregular.
pub(super) fn corner_kind(scheme: Scheme, level: &KeptLevel, g: usize, c: usize) -> Option<Corner> {
    let (faces, connectivity, sharpness) = (&level.faces, &level.connectivity, &level.sharpness);
    let v = faces.indices[c] as usize;
    let size = scheme.refined_face_size() as usize;
    let plain = |s: f32| s == 0.0 || infinite(s);
    if !plain(sharpness.vertices[v])
        || !sharpness
            .edges_at(v)
            .iter()
            .all(|&e| plain(sharpness.edges[e as usize]))
    {
        return None;
    }
    let sharp = |e: u32| infinite(sharpness.edges[e as usize]);
    // Walk across the edges at v from g both ways until a sharp edge.
    let (mut count, mut closed) = (1usize, false);
    let mut corner = c;
    for _ in 0..64 {
        let e = connectivity.corner_edges[corner];
        if sharp(e) {
            break;
        }
        let &[a, b] = connectivity.edge_corners(e as usize) else {
            return None;
        };
        let other = if a as usize == corner { b } else { a } as usize;
        let face = connectivity.face_of(other);
        corner = faces.next(other, face);
        if faces.indices[corner] as usize != v || faces.corners(face).len() != size {
            return None;
        }
        if face == g {
            closed = true;
            break;
        }
        count += 1;
    }
    if !closed {
        let (mut corner, mut face) = (c, g);
        for _ in 0..64 {
            let previous = faces.prev(corner, face);
            let e = connectivity.corner_edges[previous];
            if sharp(e) {
                break;
            }
            let &[a, b] = connectivity.edge_corners(e as usize) else {
                return None;
            };
            corner = if a as usize == previous { b } else { a } as usize;
            face = connectivity.face_of(corner);
            if faces.indices[corner] as usize != v || faces.corners(face).len() != size || face == g
            {
                return None;
            }
            count += 1;
        }
    }
    let rule = sharpness.rules[v];
    let valence = match scheme {
        Scheme::CatmullClark => 4,
        Scheme::Loop => 6,
    };
    if closed {
        let whole = sharpness.edges_at(v).len() == count
            && connectivity.vertex_corners(v).len() == count
            && sharpness.vertices[v] == 0.0;
        return (rule == Rule::Smooth && count == valence && whole).then_some(Corner::Smooth);
    }
    match (scheme, count, rule) {
        (Scheme::CatmullClark, 2, Rule::Crease) | (Scheme::Loop, 3, Rule::Crease) => {
            Some(Corner::Crease)
        }
        (Scheme::CatmullClark, 1, Rule::Corner) => Some(Corner::Sharp),
        _ => None,
    }
}

/// The control points of face `g` of `level` as a regular patch of
/// `scheme` (16 for Catmull-Clark, row by row along u; 12 for Loop in
/// OpenSubdiv's order), or `None` when it is not one.
pub(super) fn regular_patch(scheme: Scheme, level: &KeptLevel, g: usize) -> Option<Vec<Row>> {
    let faces = &level.faces;
    let size = scheme.refined_face_size() as usize;
    let corners: Vec<usize> = faces.corners(g).collect();
    if corners.len() != size {
        return None;
    }
    let mut kinds = [Corner::Smooth; 4];
    for (k, &c) in corners.iter().enumerate() {
        kinds[k] = corner_kind(scheme, level, g, c)?;
    }
    let mut sharp = [false; 4];
    for (k, &c) in corners.iter().enumerate() {
        sharp[k] = infinite(level.sharpness.edges[level.connectivity.corner_edges[c] as usize]);
    }
    let p: Vec<u32> = corners.iter().map(|&c| faces.indices[c]).collect();
    for k in 0..size {
        let (before, after) = (sharp[(k + size - 1) % size], sharp[k]);
        let fits = match kinds[k] {
            Corner::Smooth => !before && !after,
            // A Loop crease may also pass through the corner alone.
            Corner::Crease => (before != after) || (scheme == Scheme::Loop && !before && !after),
            Corner::Sharp => before && after,
        };
        if !fits {
            return None;
        }
    }
    match scheme {
        Scheme::CatmullClark => quad_grid(level, &p, &kinds, &sharp),
        Scheme::Loop => triangle_grid(level, &p, &kinds, &sharp),
    }
}

fn quad_grid(
    level: &KeptLevel,
    p: &[u32],
    kinds: &[Corner; 4],
    sharp: &[bool; 4],
) -> Option<Vec<Row>> {
    let mut g: [[Option<Row>; 4]; 4] = [[None; 4]; 4];
    let pt = |x: u32| Some(Row::point(x));
    g[1][1] = pt(p[0]);
    g[1][2] = pt(p[1]);
    g[2][2] = pt(p[2]);
    g[2][1] = pt(p[3]);
    // The quads across the face's smooth edges: (b, a, x, y) across a → b.
    let mut raw = [[u32::MAX; 4]; 4];
    let sides = [
        (p[1], p[0], [(0, 1), (0, 2)]),
        (p[2], p[1], [(1, 3), (2, 3)]),
        (p[3], p[2], [(3, 2), (3, 1)]),
        (p[0], p[3], [(2, 0), (1, 0)]),
    ];
    for (k, &(a, b, [x, y])) in sides.iter().enumerate() {
        if !sharp[k] {
            let q = face_from(level, a, b, 4)?;
            raw[x.0][x.1] = q[2];
            raw[y.0][y.1] = q[3];
        }
    }
    // Diagonal quads at smooth corners: (p_k, side point, diagonal, ...).
    let diagonals = [
        ((1, 0), (0, 0)),
        ((0, 2), (0, 3)),
        ((2, 3), (3, 3)),
        ((3, 1), (3, 0)),
    ];
    for (k, &(side, diagonal)) in diagonals.iter().enumerate() {
        if kinds[k] == Corner::Smooth {
            let q = face_from(level, p[k], raw[side.0][side.1], 4)?;
            raw[diagonal.0][diagonal.1] = q[2];
        }
    }
    for r in 0..4 {
        for c in 0..4 {
            if raw[r][c] != u32::MAX {
                g[r][c] = pt(raw[r][c]);
            }
        }
    }
    let mirror = |inner: Option<Row>, next: Option<Row>| match (inner, next) {
        (Some(a), Some(b)) => Row::combine(&[(2.0, a), (-1.0, b)]),
        _ => None,
    };
    for row in g.iter_mut() {
        if sharp[3] {
            row[0] = mirror(row[1], row[2]);
        }
        if sharp[1] {
            row[3] = mirror(row[2], row[1]);
        }
    }
    let [bottom, inner_bottom, inner_top, top] = &mut g;
    for (((b, ib), it), t) in bottom.iter_mut().zip(inner_bottom).zip(inner_top).zip(top) {
        if sharp[0] {
            *b = mirror(*ib, *it);
        }
        if sharp[2] {
            *t = mirror(*it, *ib);
        }
    }
    g.iter().flatten().copied().collect()
}

fn triangle_grid(
    level: &KeptLevel,
    p: &[u32],
    kinds: &[Corner; 4],
    sharp: &[bool; 4],
) -> Option<Vec<Row>> {
    let third = |a: u32, b: u32| face_from(level, a, b, 3).map(|t| t[2]);
    let mut q = [u32::MAX; 12];
    q[4] = p[0];
    q[5] = p[1];
    q[8] = p[2];
    if !sharp[0] {
        q[1] = third(p[1], p[0])?;
    }
    if !sharp[1] {
        q[9] = third(p[2], p[1])?;
    }
    if !sharp[2] {
        q[7] = third(p[0], p[2])?;
    }
    // Around each corner: counter-clockwise by `third(v, x)`, clockwise by
    // `third(x, v)`, as far as the corner's side reaches.
    match (kinds[0], sharp[0], sharp[2]) {
        (Corner::Smooth, _, _) => {
            q[3] = third(p[0], q[7])?;
            q[0] = third(p[0], q[3])?;
        }
        (_, true, false) => q[3] = third(p[0], q[7])?,
        (_, false, true) => q[0] = third(q[1], p[0])?,
        _ => {}
    }
    match (kinds[1], sharp[1], sharp[0]) {
        (Corner::Smooth, _, _) => {
            q[2] = third(p[1], q[1])?;
            q[6] = third(p[1], q[2])?;
        }
        (_, true, false) => q[2] = third(p[1], q[1])?,
        (_, false, true) => q[6] = third(q[9], p[1])?,
        _ => {}
    }
    match (kinds[2], sharp[2], sharp[1]) {
        (Corner::Smooth, _, _) => {
            q[11] = third(p[2], q[9])?;
            q[10] = third(p[2], q[11])?;
        }
        (_, true, false) => q[11] = third(p[2], q[9])?,
        (_, false, true) => q[10] = third(q[7], p[2])?,
        _ => {}
    }
    let mut rows: Vec<Option<Row>> = q
        .iter()
        .map(|&x| (x != u32::MAX).then(|| Row::point(x)))
        .collect();
    // Phantom = a + b - c: the reflection of c through the midpoint of a b.
    let phantom = |rows: &mut Vec<Option<Row>>, at: usize, a: usize, b: usize, c: usize| {
        rows[at] = match (rows[a], rows[b], rows[c]) {
            (Some(a), Some(b), Some(c)) => Row::combine(&[(1.0, a), (1.0, b), (-1.0, c)]),
            _ => None,
        };
    };
    if sharp[0] {
        phantom(&mut rows, 0, 3, 4, 7);
        phantom(&mut rows, 1, 4, 5, 8);
        phantom(&mut rows, 2, 5, 6, 9);
    }
    if sharp[1] {
        phantom(&mut rows, 6, 5, 2, 1);
        phantom(&mut rows, 9, 5, 8, 4);
        phantom(&mut rows, 11, 8, 10, 7);
    }
    if sharp[2] {
        phantom(&mut rows, 10, 8, 11, 9);
        phantom(&mut rows, 7, 8, 4, 5);
        phantom(&mut rows, 3, 4, 0, 1);
    }
    // A crease through a corner alone.
    if kinds[0] == Corner::Crease && !sharp[0] && !sharp[2] {
        phantom(&mut rows, 3, 4, 7, 8);
        phantom(&mut rows, 0, 4, 1, 5);
    }
    if kinds[1] == Corner::Crease && !sharp[1] && !sharp[0] {
        phantom(&mut rows, 2, 5, 1, 4);
        phantom(&mut rows, 6, 5, 9, 8);
    }
    if kinds[2] == Corner::Crease && !sharp[2] && !sharp[1] {
        phantom(&mut rows, 11, 8, 9, 5);
        phantom(&mut rows, 10, 8, 7, 4);
    }
    rows.into_iter().collect()
}
