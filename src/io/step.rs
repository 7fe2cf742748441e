//! STEP (ISO 10303-21, AP214 "automotive design") export of bicubic
//! patches: each patch a `B_SPLINE_SURFACE_WITH_KNOTS` in its Bézier form
//! (degree 3 × 3, knots 0 and 1 of multiplicity 4), bounded by an
//! `ADVANCED_FACE` whose four edges are the patch's boundary curves; the
//! faces form one `OPEN_SHELL` of a `SHELL_BASED_SURFACE_MODEL` in a
//! `MANIFOLD_SURFACE_SHAPE_REPRESENTATION`, which Rhino, FreeCAD and
//! OpenCASCADE-based tools read as a surface model.
//!
//! Patches that meet at an edge share its `EDGE_CURVE` and its two
//! `VERTEX_POINT`s (found by the boundary curves' control points, which
//! patches fitted along a shared edge hold bit for bit), so the shell is
//! stitched, not a heap of loose faces. Coordinates are written with 17
//! significant digits, which read back to the same doubles. Lengths are
//! declared in millimetres; Weft's coordinates are unitless, so a host
//! reading them as another unit only rescales.

use std::collections::HashMap;
use std::fmt::Write as _;
use std::io::{self, Write};

use glam::DVec3;
use rayon::prelude::*;

/// A bicubic Bézier patch: `control[i][j]`, i along u, j along v.
pub type Bicubic = [[DVec3; 4]; 4];

/// Writes `patches` as an AP214 STEP file named `name` (the name goes in
/// its header and its product). The entities are numbered first, in file
/// order, then formatted on all threads a batch of patches at a time, so
/// memory holds the numbering and one batch's text, not the file's.
///
/// # Errors
/// What `w` reports.
pub fn write(w: &mut dyn Write, name: &str, patches: &[Bicubic]) -> io::Result<()> {
    write_in_batches(w, name, patches, BATCH_PATCHES)
}

/// Patches formatted at once, on all threads, before their text is written:
/// about 3.4 KB each, so memory holds about 14 MB of text.
const BATCH_PATCHES: usize = 4096;

/// Patches one thread formats at a time.
const CHUNK_PATCHES: usize = 256;

/// [`write`], formatting `batch` patches at a time.
fn write_in_batches(
    w: &mut dyn Write,
    name: &str,
    patches: &[Bicubic],
    batch: usize,
) -> io::Result<()> {
    let name = step_string(name);
    writeln!(w, "ISO-10303-21;")?;
    writeln!(w, "HEADER;")?;
    writeln!(
        w,
        "FILE_DESCRIPTION(('limit surface as bicubic patches'),'2;1');"
    )?;
    writeln!(
        w,
        "FILE_NAME('{name}','',(''),(''),'Weft {}','Weft','');",
        env!("CARGO_PKG_VERSION")
    )?;
    writeln!(
        w,
        "FILE_SCHEMA(('AUTOMOTIVE_DESIGN {{ 1 0 10303 214 1 1 1 1 }}'));"
    )?;
    writeln!(w, "ENDSEC;")?;
    writeln!(w, "DATA;")?;
    let (plans, count) = plan(patches);
    let chunk = CHUNK_PATCHES.min(batch).max(1);
    for (patches, plans) in patches.chunks(batch.max(1)).zip(plans.chunks(batch.max(1))) {
        let texts: Vec<String> = patches
            .par_chunks(chunk)
            .zip(plans.par_chunks(chunk))
            .map(|(patches, plans)| {
                let mut text = String::with_capacity(3500 * patches.len());
                for (patch, plan) in patches.iter().zip(plans) {
                    write_patch(&mut text, patch, plan);
                }
                text
            })
            .collect();
        for text in texts {
            w.write_all(text.as_bytes())?;
        }
    }

    let mut file = Entities { w, count };
    let mut faces = String::new();
    for plan in &plans {
        if !faces.is_empty() {
            faces.push(',');
        }
        let _ = write!(faces, "#{}", plan.face);
    }
    let shell = file.add(&format!("OPEN_SHELL('',({faces}))"))?;
    let model = file.add(&format!("SHELL_BASED_SURFACE_MODEL('',(#{shell}))"))?;
    let context = file.add("APPLICATION_CONTEXT('automotive design')")?;
    file.add(&format!(
        "APPLICATION_PROTOCOL_DEFINITION('international standard','automotive_design',2000,#{context})"
    ))?;
    let product_context = file.add(&format!("PRODUCT_CONTEXT('',#{context},'mechanical')"))?;
    let product = file.add(&format!(
        "PRODUCT('{name}','{name}','',(#{product_context}))"
    ))?;
    let formation = file.add(&format!("PRODUCT_DEFINITION_FORMATION('','',#{product})"))?;
    let definition_context = file.add(&format!(
        "PRODUCT_DEFINITION_CONTEXT('part definition',#{context},'design')"
    ))?;
    let definition = file.add(&format!(
        "PRODUCT_DEFINITION('design','',#{formation},#{definition_context})"
    ))?;
    let shape = file.add(&format!("PRODUCT_DEFINITION_SHAPE('','',#{definition})"))?;
    let length = file.add("(LENGTH_UNIT()NAMED_UNIT(*)SI_UNIT(.MILLI.,.METRE.))")?;
    let angle = file.add("(NAMED_UNIT(*)PLANE_ANGLE_UNIT()SI_UNIT($,.RADIAN.))")?;
    let solid_angle = file.add("(NAMED_UNIT(*)SI_UNIT($,.STERADIAN.)SOLID_ANGLE_UNIT())")?;
    let uncertainty = file.add(&format!(
        "UNCERTAINTY_MEASURE_WITH_UNIT(LENGTH_MEASURE(1.E-07),#{length},'distance_accuracy_value','confusion accuracy')"
    ))?;
    let geometric_context = file.add(&format!(
        "(GEOMETRIC_REPRESENTATION_CONTEXT(3)GLOBAL_UNCERTAINTY_ASSIGNED_CONTEXT((#{uncertainty}))GLOBAL_UNIT_ASSIGNED_CONTEXT((#{length},#{angle},#{solid_angle}))REPRESENTATION_CONTEXT('',''))"
    ))?;
    let origin = file.point(DVec3::ZERO)?;
    let z = file.add("DIRECTION('',(0.,0.,1.))")?;
    let x = file.add("DIRECTION('',(1.,0.,0.))")?;
    let placement = file.add(&format!("AXIS2_PLACEMENT_3D('',{origin},#{z},#{x})"))?;
    let representation = file.add(&format!(
        "MANIFOLD_SURFACE_SHAPE_REPRESENTATION('{name}',(#{placement},#{model}),#{geometric_context})"
    ))?;
    file.add(&format!(
        "SHAPE_DEFINITION_REPRESENTATION(#{shape},#{representation})"
    ))?;
    let w = file.w;
    writeln!(w, "ENDSEC;")?;
    writeln!(w, "END-ISO-10303-21;")
}

/// The patch's boundary counter-clockwise seen from du × dv: v = 0 along u,
/// u = 1 along v, then back along v = 1 and u = 0.
fn boundary(patch: &Bicubic) -> [[DVec3; 4]; 4] {
    [
        [patch[0][0], patch[1][0], patch[2][0], patch[3][0]],
        [patch[3][0], patch[3][1], patch[3][2], patch[3][3]],
        [patch[3][3], patch[2][3], patch[1][3], patch[0][3]],
        [patch[0][3], patch[0][2], patch[0][1], patch[0][0]],
    ]
}

/// Where one patch's entities go. Each patch writes, in order: its 16
/// control points and its surface; for each side, a new edge's entities
/// (a new vertex's point and `VERTEX_POINT` at each end, the curve's 4
/// points, the curve and its `EDGE_CURVE`) and the side's
/// `ORIENTED_EDGE`; then its loop, bound and face.
#[derive(Debug, Clone, Copy)]
struct Plan {
    /// The number of its first entity.
    first: usize,
    sides: [Side; 4],
    /// Its `ADVANCED_FACE`.
    face: usize,
}

/// One side of a patch: its `EDGE_CURVE`, run forward or backward, and
/// whether this patch makes it.
#[derive(Debug, Clone, Copy, Default)]
struct Side {
    edge: usize,
    forward: bool,
    /// Made here: the `VERTEX_POINT` at each end of the curve (as it runs
    /// in the file), and whether this patch makes it too.
    made: Option<[(usize, bool); 2]>,
}

/// Numbers every patch's entities in the order the file lists them,
/// sharing the edges and vertices patches meet at (found by their control
/// points' bits, which patches meeting at an edge hold exactly); returns
/// the plans and the number of entities.
fn plan(patches: &[Bicubic]) -> (Vec<Plan>, usize) {
    // A closed shell of quads has as many vertices as faces and twice as
    // many edges.
    let mut vertices: HashMap<[u64; 3], usize> = HashMap::with_capacity(patches.len() + 4);
    let mut edges: HashMap<[[u64; 3]; 4], usize> = HashMap::with_capacity(2 * patches.len() + 4);
    let mut count = 0;
    let plans = patches
        .iter()
        .map(|patch| {
            let first = count + 1;
            count += 17;
            let sides = boundary(patch).map(|curve| {
                let key = curve.map(bits);
                let mut reversed = key;
                reversed.reverse();
                let (key, forward) = if key <= reversed {
                    (key, true)
                } else {
                    (reversed, false)
                };
                let mut side = Side {
                    forward,
                    ..Side::default()
                };
                side.edge = match edges.get(&key) {
                    Some(&edge) => edge,
                    None => {
                        let mut vertex = |p: [u64; 3]| match vertices.get(&p) {
                            Some(&v) => (v, false),
                            None => {
                                count += 2;
                                vertices.insert(p, count);
                                (count, true)
                            }
                        };
                        side.made = Some([vertex(key[0]), vertex(key[3])]);
                        count += 6;
                        edges.insert(key, count);
                        count
                    }
                };
                count += 1;
                side
            });
            count += 3;
            Plan {
                first,
                sides,
                face: count,
            }
        })
        .collect();
    (plans, count)
}

/// Text of entities numbered from `next` on.
struct Numbered<'t> {
    text: &'t mut String,
    next: usize,
}

impl Numbered<'_> {
    /// Writes the next entity; returns its number.
    fn entity(&mut self, body: std::fmt::Arguments) -> usize {
        let _ = writeln!(self.text, "#{}={body};", self.next);
        self.next += 1;
        self.next - 1
    }
}

/// Writes the entities of `patch` as `plan` numbers them.
fn write_patch(text: &mut String, patch: &Bicubic, plan: &Plan) {
    let mut out = Numbered {
        text,
        next: plan.first,
    };
    for row in patch {
        for &p in row {
            out.entity(format_args!("{}", Point(p)));
        }
    }
    let row = |i: usize| {
        let first = plan.first + 4 * i;
        [first, first + 1, first + 2, first + 3]
    };
    let ([a, b, c, d], [e, f, g, h]) = (row(0), row(1));
    let ([i, j, k, l], [m, n, o, p]) = (row(2), row(3));
    let surface = out.entity(format_args!(
        "B_SPLINE_SURFACE_WITH_KNOTS('',3,3,((#{a},#{b},#{c},#{d}),(#{e},#{f},#{g},#{h}),(#{i},#{j},#{k},#{l}),(#{m},#{n},#{o},#{p})),.UNSPECIFIED.,.F.,.F.,.F.,(4,4),(4,4),(0.,1.),(0.,1.),.UNSPECIFIED.)"
    ));
    let mut oriented = [0; 4];
    for ((side, curve), oriented) in plan.sides.iter().zip(boundary(patch)).zip(&mut oriented) {
        if let Some(ends) = side.made {
            let mut along = curve;
            if !side.forward {
                along.reverse();
            }
            for ((v, made), p) in ends.into_iter().zip([along[0], along[3]]) {
                if made {
                    let point = out.entity(format_args!("{}", Point(p)));
                    let vertex = out.entity(format_args!("VERTEX_POINT('',#{point})"));
                    debug_assert_eq!(vertex, v);
                }
            }
            let [a, b, c, d] = along.map(|p| out.entity(format_args!("{}", Point(p))));
            let geometry = out.entity(format_args!(
                "B_SPLINE_CURVE_WITH_KNOTS('',3,(#{a},#{b},#{c},#{d}),.UNSPECIFIED.,.F.,.F.,(4,4),(0.,1.),.UNSPECIFIED.)"
            ));
            let [start, end] = ends.map(|(v, _)| v);
            let edge = out.entity(format_args!(
                "EDGE_CURVE('',#{start},#{end},#{geometry},.T.)"
            ));
            debug_assert_eq!(edge, side.edge);
        }
        let sense = if side.forward { ".T." } else { ".F." };
        let edge = side.edge;
        *oriented = out.entity(format_args!("ORIENTED_EDGE('',*,*,#{edge},{sense})"));
    }
    let [a, b, c, d] = oriented;
    let lp = out.entity(format_args!("EDGE_LOOP('',(#{a},#{b},#{c},#{d}))"));
    let bound = out.entity(format_args!("FACE_OUTER_BOUND('',#{lp},.T.)"));
    let face = out.entity(format_args!("ADVANCED_FACE('',(#{bound}),#{surface},.T.)"));
    debug_assert_eq!(face, plan.face);
}

/// A `CARTESIAN_POINT` entity's body.
struct Point(DVec3);

impl std::fmt::Display for Point {
    fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        let [x, y, z] = self.0.to_array();
        // "1.0000000000000000E0", "-2.5000000000000000E-5": STEP's REAL
        // form, 17 significant digits, which read back to the same double.
        write!(f, "CARTESIAN_POINT('',({x:.16E},{y:.16E},{z:.16E}))")
    }
}

/// The entities after the patches: entity k is `#k`.
struct Entities<'w> {
    w: &'w mut dyn Write,
    count: usize,
}

impl Entities<'_> {
    fn add(&mut self, entity: &str) -> io::Result<usize> {
        self.count += 1;
        writeln!(self.w, "#{}={entity};", self.count)?;
        Ok(self.count)
    }

    /// A new `CARTESIAN_POINT`, as the reference `#n`.
    fn point(&mut self, p: DVec3) -> io::Result<String> {
        Ok(format!("#{}", self.add(&Point(p).to_string())?))
    }
}

fn bits(p: DVec3) -> [u64; 3] {
    // -0 and 0 are one place.
    p.to_array().map(|x| (x + 0.0).to_bits())
}

/// A STEP string: apostrophes doubled, non-ASCII left out.
fn step_string(text: &str) -> String {
    text.chars()
        .filter(|c| c.is_ascii() && !c.is_ascii_control())
        .collect::<String>()
        .replace('\'', "''")
        .replace('\\', "\\\\")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reals_read_back_to_the_same_doubles() {
        for x in [
            0.0,
            -0.0,
            1.0,
            -2.5,
            1e-300,
            123456.789,
            std::f64::consts::PI,
            f64::MAX,
        ] {
            let text = Point(DVec3::splat(x)).to_string();
            let reals = text
                .strip_prefix("CARTESIAN_POINT('',(")
                .and_then(|rest| rest.strip_suffix("))"))
                .unwrap();
            for real in reals.split(',') {
                assert!(real.contains('.') && real.contains('E'), "{text}");
                assert_eq!(real.parse::<f64>().unwrap(), x, "{text}");
            }
        }
    }

    #[test]
    fn two_patches_share_their_common_edge() {
        let patch = |shift: f64| -> Bicubic {
            std::array::from_fn(|i| {
                std::array::from_fn(|j| DVec3::new(shift + i as f64 / 3.0, j as f64 / 3.0, 0.0))
            })
        };
        let mut out = Vec::new();
        write(&mut out, "two", &[patch(0.0), patch(1.0)]).unwrap();
        let text = String::from_utf8(out).unwrap();
        assert_eq!(text.matches("ADVANCED_FACE(").count(), 2);
        // 4 + 4 edges, one shared; 6 corners.
        assert_eq!(text.matches("EDGE_CURVE(").count(), 7);
        assert_eq!(text.matches("VERTEX_POINT(").count(), 6);
        assert_eq!(text.matches("ORIENTED_EDGE(").count(), 8);
        assert!(text.starts_with("ISO-10303-21;\nHEADER;"));
        assert!(text.ends_with("ENDSEC;\nEND-ISO-10303-21;\n"));
    }

    /// An `n` × `m` sheet of patches over a wavy surface, each patch's
    /// control points computed from its grid position so that neighbours
    /// share their edges bit for bit.
    fn sheet(n: usize, m: usize) -> Vec<Bicubic> {
        let mut patches = Vec::new();
        for i in 0..n {
            for j in 0..m {
                patches.push(std::array::from_fn(|a| {
                    std::array::from_fn(|b| {
                        let (x, y) = (i as f64 + a as f64 / 3.0, j as f64 + b as f64 / 3.0);
                        DVec3::new(x, y, (0.7 * x).sin() * (1.3 * y).cos())
                    })
                }));
            }
        }
        patches
    }

    #[test]
    fn batches_of_any_size_write_the_same_file() {
        let patches = sheet(7, 5);
        let mut whole = Vec::new();
        write_in_batches(&mut whole, "sheet", &patches, usize::MAX).unwrap();
        for batch in [1, 2, 3, 16, 35] {
            let mut out = Vec::new();
            write_in_batches(&mut out, "sheet", &patches, batch).unwrap();
            assert!(out == whole, "batches of {batch}");
        }
    }

    #[test]
    fn every_reference_names_an_earlier_entity_of_its_kind() {
        let (n, m) = (6, 4);
        let patches = sheet(n, m);
        let mut out = Vec::new();
        write_in_batches(&mut out, "sheet", &patches, 5).unwrap();
        let text = String::from_utf8(out).unwrap();
        let mut kinds: Vec<&str> = vec![""];
        let mut count = HashMap::new();
        for line in text.lines().filter(|l| l.starts_with('#')) {
            let (id, body) = line.split_once('=').unwrap();
            assert_eq!(id[1..].parse::<usize>().unwrap(), kinds.len(), "{line}");
            let kind = body.split('(').next().unwrap();
            let refs: Vec<&str> = body
                .split('#')
                .skip(1)
                .map(|r| {
                    let end = r.find(|c: char| !c.is_ascii_digit()).unwrap_or(r.len());
                    let at: usize = r[..end].parse().unwrap();
                    assert!(at < kinds.len(), "{line}");
                    kinds[at]
                })
                .collect();
            let expected: &[&str] = match kind {
                "B_SPLINE_SURFACE_WITH_KNOTS" => &["CARTESIAN_POINT"; 16],
                "VERTEX_POINT" => &["CARTESIAN_POINT"],
                "B_SPLINE_CURVE_WITH_KNOTS" => &["CARTESIAN_POINT"; 4],
                "EDGE_CURVE" => &["VERTEX_POINT", "VERTEX_POINT", "B_SPLINE_CURVE_WITH_KNOTS"],
                "ORIENTED_EDGE" => &["EDGE_CURVE"],
                "EDGE_LOOP" => &["ORIENTED_EDGE"; 4],
                "FACE_OUTER_BOUND" => &["EDGE_LOOP"],
                "ADVANCED_FACE" => &["FACE_OUTER_BOUND", "B_SPLINE_SURFACE_WITH_KNOTS"],
                "OPEN_SHELL" => &["ADVANCED_FACE"; 24],
                _ => &[],
            };
            if !expected.is_empty() {
                assert_eq!(refs, expected, "{line}");
            }
            *count.entry(kind).or_insert(0) += 1;
            kinds.push(kind);
        }
        assert_eq!(count["ADVANCED_FACE"], n * m);
        assert_eq!(count["VERTEX_POINT"], (n + 1) * (m + 1));
        assert_eq!(count["EDGE_CURVE"], n * (m + 1) + m * (n + 1));
        assert_eq!(count["ORIENTED_EDGE"], 4 * n * m);
    }

    #[test]
    fn names_are_quoted() {
        assert_eq!(step_string("it's ü"), "it''s ");
    }
}
