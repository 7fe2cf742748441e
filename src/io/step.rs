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
/// its header and its product).
///
/// # Errors
/// What `w` reports.
pub fn write(w: &mut dyn Write, name: &str, patches: &[Bicubic]) -> io::Result<()> {
    let mut file = Entities::default();
    let mut faces = Vec::with_capacity(patches.len());
    let mut vertices: HashMap<[u64; 3], usize> = HashMap::new();
    let mut edges: HashMap<[[u64; 3]; 4], usize> = HashMap::new();
    for patch in patches {
        let rows: String = (0..4)
            .map(|i| {
                let points: Vec<String> = (0..4).map(|j| file.point(patch[i][j])).collect();
                format!("({})", points.join(","))
            })
            .collect::<Vec<_>>()
            .join(",");
        let surface = file.add(format!(
            "B_SPLINE_SURFACE_WITH_KNOTS('',3,3,({rows}),.UNSPECIFIED.,.F.,.F.,.F.,(4,4),(4,4),(0.,1.),(0.,1.),.UNSPECIFIED.)"
        ));
        // The boundary counter-clockwise seen from du × dv: v = 0 along u,
        // u = 1 along v, then back along v = 1 and u = 0.
        let boundary = [
            [patch[0][0], patch[1][0], patch[2][0], patch[3][0]],
            [patch[3][0], patch[3][1], patch[3][2], patch[3][3]],
            [patch[3][3], patch[2][3], patch[1][3], patch[0][3]],
            [patch[0][3], patch[0][2], patch[0][1], patch[0][0]],
        ];
        let oriented: Vec<String> = boundary
            .iter()
            .map(|curve| {
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
                        let [start, end] =
                            [along[0], along[3]].map(|p| file.vertex(&mut vertices, p));
                        let points: Vec<String> = along.iter().map(|&p| file.point(p)).collect();
                        let geometry = file.add(format!(
                            "B_SPLINE_CURVE_WITH_KNOTS('',3,({}),.UNSPECIFIED.,.F.,.F.,(4,4),(0.,1.),.UNSPECIFIED.)",
                            points.join(",")
                        ));
                        let edge = file.add(format!("EDGE_CURVE('',#{start},#{end},#{geometry},.T.)"));
                        edges.insert(key, edge);
                        edge
                    }
                };
                let sense = if forward { ".T." } else { ".F." };
                format!("#{}", file.add(format!("ORIENTED_EDGE('',*,*,#{edge},{sense})")))
            })
            .collect();
        let lp = file.add(format!("EDGE_LOOP('',({}))", oriented.join(",")));
        let bound = file.add(format!("FACE_OUTER_BOUND('',#{lp},.T.)"));
        faces.push(format!(
            "#{}",
            file.add(format!("ADVANCED_FACE('',(#{bound}),#{surface},.T.)"))
        ));
    }

    let shell = file.add(format!("OPEN_SHELL('',({}))", faces.join(",")));
    let model = file.add(format!("SHELL_BASED_SURFACE_MODEL('',(#{shell}))"));
    let context = file.add("APPLICATION_CONTEXT('automotive design')".into());
    file.add(format!(
        "APPLICATION_PROTOCOL_DEFINITION('international standard','automotive_design',2000,#{context})"
    ));
    let product_context = file.add(format!("PRODUCT_CONTEXT('',#{context},'mechanical')"));
    let name = step_string(name);
    let product = file.add(format!(
        "PRODUCT('{name}','{name}','',(#{product_context}))"
    ));
    let formation = file.add(format!("PRODUCT_DEFINITION_FORMATION('','',#{product})"));
    let definition_context = file.add(format!(
        "PRODUCT_DEFINITION_CONTEXT('part definition',#{context},'design')"
    ));
    let definition = file.add(format!(
        "PRODUCT_DEFINITION('design','',#{formation},#{definition_context})"
    ));
    let shape = file.add(format!("PRODUCT_DEFINITION_SHAPE('','',#{definition})"));
    let length = file.add("(LENGTH_UNIT()NAMED_UNIT(*)SI_UNIT(.MILLI.,.METRE.))".into());
    let angle = file.add("(NAMED_UNIT(*)PLANE_ANGLE_UNIT()SI_UNIT($,.RADIAN.))".into());
    let solid_angle = file.add("(NAMED_UNIT(*)SI_UNIT($,.STERADIAN.)SOLID_ANGLE_UNIT())".into());
    let uncertainty = file.add(format!(
        "UNCERTAINTY_MEASURE_WITH_UNIT(LENGTH_MEASURE(1.E-07),#{length},'distance_accuracy_value','confusion accuracy')"
    ));
    let geometric_context = file.add(format!(
        "(GEOMETRIC_REPRESENTATION_CONTEXT(3)GLOBAL_UNCERTAINTY_ASSIGNED_CONTEXT((#{uncertainty}))GLOBAL_UNIT_ASSIGNED_CONTEXT((#{length},#{angle},#{solid_angle}))REPRESENTATION_CONTEXT('',''))"
    ));
    let origin = file.point(DVec3::ZERO);
    let z = file.add("DIRECTION('',(0.,0.,1.))".into());
    let x = file.add("DIRECTION('',(1.,0.,0.))".into());
    let placement = file.add(format!("AXIS2_PLACEMENT_3D('',{origin},#{z},#{x})"));
    let representation = file.add(format!(
        "MANIFOLD_SURFACE_SHAPE_REPRESENTATION('{name}',(#{placement},#{model}),#{geometric_context})"
    ));
    file.add(format!(
        "SHAPE_DEFINITION_REPRESENTATION(#{shape},#{representation})"
    ));

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
    for (k, entity) in file.lines.iter().enumerate() {
        writeln!(w, "#{}={entity};", k + 1)?;
    }
    writeln!(w, "ENDSEC;")?;
    writeln!(w, "END-ISO-10303-21;")
}

/// The data section as it is built: entity k is `#k + 1`.
#[derive(Default)]
struct Entities {
    lines: Vec<String>,
}

impl Entities {
    fn add(&mut self, entity: String) -> usize {
        self.lines.push(entity);
        self.lines.len()
    }

    /// A new `CARTESIAN_POINT`, as the reference `#n` (control points are
    /// not shared: each curve and surface lists its own).
    fn point(&mut self, p: DVec3) -> String {
        let mut text = String::from("CARTESIAN_POINT('',(");
        for (k, x) in p.to_array().into_iter().enumerate() {
            if k > 0 {
                text.push(',');
            }
            let _ = write!(text, "{}", real(x));
        }
        text.push_str("))");
        format!("#{}", self.add(text))
    }

    /// The `VERTEX_POINT` at `p`, shared by every edge that ends there.
    fn vertex(&mut self, vertices: &mut HashMap<[u64; 3], usize>, p: DVec3) -> usize {
        if let Some(&v) = vertices.get(&bits(p)) {
            return v;
        }
        let point = self.point(p);
        let v = self.add(format!("VERTEX_POINT('',{point})"));
        vertices.insert(bits(p), v);
        v
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
