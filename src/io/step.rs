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

/// A bicubic Bézier patch: `control[i][j]`, i along u, j along v.
pub type Bicubic = [[DVec3; 4]; 4];

/// Writes `patches` as an AP214 STEP file named `name` (the name goes in
/// its header and its product). Each entity is written as it is made, so
/// memory holds the shared edges and vertices, not the file's text.
///
/// # Errors
/// What `w` reports.
pub fn write<'a>(
    w: &mut dyn Write,
    name: &str,
    patches: impl IntoIterator<Item = &'a Bicubic>,
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
    let mut file = Entities { w, count: 0 };
    let mut faces = String::new();
    let mut vertices: HashMap<[u64; 3], usize> = HashMap::new();
    let mut edges: HashMap<[[u64; 3]; 4], usize> = HashMap::new();
    for patch in patches {
        let mut rows = Vec::with_capacity(4);
        for row in patch {
            let mut points = Vec::with_capacity(4);
            for &p in row {
                points.push(file.point(p)?);
            }
            rows.push(format!("({})", points.join(",")));
        }
        let surface = file.add(&format!(
            "B_SPLINE_SURFACE_WITH_KNOTS('',3,3,({}),.UNSPECIFIED.,.F.,.F.,.F.,(4,4),(4,4),(0.,1.),(0.,1.),.UNSPECIFIED.)",
            rows.join(",")
        ))?;
        // The boundary counter-clockwise seen from du × dv: v = 0 along u,
        // u = 1 along v, then back along v = 1 and u = 0.
        let boundary = [
            [patch[0][0], patch[1][0], patch[2][0], patch[3][0]],
            [patch[3][0], patch[3][1], patch[3][2], patch[3][3]],
            [patch[3][3], patch[2][3], patch[1][3], patch[0][3]],
            [patch[0][3], patch[0][2], patch[0][1], patch[0][0]],
        ];
        let mut oriented = Vec::with_capacity(4);
        for curve in &boundary {
            let key = curve.map(bits);
            let mut reversed = key;
            reversed.reverse();
            let (key, forward) = if key <= reversed {
                (key, true)
            } else {
                (reversed, false)
            };
            let edge = match edges.get(&key) {
                Some(&edge) => edge,
                None => {
                    let mut along = *curve;
                    if !forward {
                        along.reverse();
                    }
                    let start = file.vertex(&mut vertices, along[0])?;
                    let end = file.vertex(&mut vertices, along[3])?;
                    let mut points = Vec::with_capacity(4);
                    for &p in &along {
                        points.push(file.point(p)?);
                    }
                    let geometry = file.add(&format!(
                        "B_SPLINE_CURVE_WITH_KNOTS('',3,({}),.UNSPECIFIED.,.F.,.F.,(4,4),(0.,1.),.UNSPECIFIED.)",
                        points.join(",")
                    ))?;
                    let edge =
                        file.add(&format!("EDGE_CURVE('',#{start},#{end},#{geometry},.T.)"))?;
                    edges.insert(key, edge);
                    edge
                }
            };
            let sense = if forward { ".T." } else { ".F." };
            let oriented_edge = file.add(&format!("ORIENTED_EDGE('',*,*,#{edge},{sense})"))?;
            oriented.push(format!("#{oriented_edge}"));
        }
        let lp = file.add(&format!("EDGE_LOOP('',({}))", oriented.join(",")))?;
        let bound = file.add(&format!("FACE_OUTER_BOUND('',#{lp},.T.)"))?;
        let face = file.add(&format!("ADVANCED_FACE('',(#{bound}),#{surface},.T.)"))?;
        if !faces.is_empty() {
            faces.push(',');
        }
        let _ = write!(faces, "#{face}");
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

/// The data section as it is written: entity k is `#k`.
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

    /// A new `CARTESIAN_POINT`, as the reference `#n` (control points are
    /// not shared: each curve and surface lists its own).
    fn point(&mut self, p: DVec3) -> io::Result<String> {
        let mut text = String::from("CARTESIAN_POINT('',(");
        for (k, x) in p.to_array().into_iter().enumerate() {
            if k > 0 {
                text.push(',');
            }
            let _ = write!(text, "{}", real(x));
        }
        text.push_str("))");
        Ok(format!("#{}", self.add(&text)?))
    }

    /// The `VERTEX_POINT` at `p`, shared by every edge that ends there.
    fn vertex(&mut self, vertices: &mut HashMap<[u64; 3], usize>, p: DVec3) -> io::Result<usize> {
        if let Some(&v) = vertices.get(&bits(p)) {
            return Ok(v);
        }
        let point = self.point(p)?;
        let v = self.add(&format!("VERTEX_POINT('',{point})"))?;
        vertices.insert(bits(p), v);
        Ok(v)
    }
}

fn bits(p: DVec3) -> [u64; 3] {
    // -0 and 0 are one place.
    p.to_array().map(|x| (x + 0.0).to_bits())
}

/// A STEP REAL with 17 significant digits (reads back to the same double).
fn real(x: f64) -> String {
    // "1.0000000000000000E0", "-2.5000000000000000E-5": STEP's REAL form.
    format!("{x:.16E}")
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
            let text = real(x);
            assert!(text.contains('.') && text.contains('E'), "{text}");
            assert_eq!(text.parse::<f64>().unwrap(), x, "{text}");
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

    #[test]
    fn names_are_quoted() {
        assert_eq!(step_string("it's ü"), "it''s ");
    }
}
