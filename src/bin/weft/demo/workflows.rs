//! The workflows of `weft demo`, each a chain of Weft's operations on
//! built-in inputs, as a designer builds it on the canvas.

use std::collections::HashMap;

use weft::io::{self, render};
use weft::make::plane::Plane;
use weft::make::stellate::{stellate, Heights};
use weft::subdivide::{
    catmull_clark, loop_subdivision, subdivide_with, FaceVaryingLinear, NakedEdges, Scheme,
    Subdivider, SubdivisionOptions, SHARPNESS_INFINITE,
};
use weft::{DVec3, Error, Mesh};

use super::{op, Demo, Gray, Step};

/// A gently curved surface over the xy plane.
fn surface(x: f64, y: f64) -> DVec3 {
    DVec3::new(
        x,
        y,
        0.7 * (0.55 * x).sin() * (0.45 * y).cos() + 0.04 * x * y,
    )
}

/// The surface sampled on a `u_count` × `v_count` grid over `[x0, x1] × [y0, y1]`.
fn surface_patch(
    x0: f64,
    x1: f64,
    u_count: usize,
    y0: f64,
    y1: f64,
    v_count: usize,
    triangles: bool,
) -> Step<Mesh> {
    let mut points = Vec::with_capacity(u_count * v_count);
    for j in 0..v_count {
        for i in 0..u_count {
            let x = x0 + (x1 - x0) * i as f64 / (u_count - 1) as f64;
            let y = y0 + (y1 - y0) * j as f64 / (v_count - 1) as f64;
            points.push(surface(x, y));
        }
    }
    op(
        "mesh from grid",
        weft::make::grid::mesh_from_grid(&points, u_count, v_count, false, false, triangles),
    )
}

/// A small deterministic generator (xorshift), so the demo is the same every run.
struct Random(u64);

impl Random {
    fn unit(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
}

pub fn loop_levels(demo: &mut Demo) -> Step<()> {
    demo.section("Loop subdivision of a triangle mesh");
    let cage = surface_patch(0.0, 6.0, 7, 0.0, 5.0, 6, true)?;
    demo.save("loop-0-cage", "the triangle mesh (level 0)", &cage)?;
    for level in 1..=3 {
        let refined = op("Loop", loop_subdivision(&cage, level, NakedEdges::Fixed))?;
        demo.save(
            &format!("loop-{level}"),
            &format!("Loop level {level}, naked edges fixed"),
            &refined,
        )?;
    }
    demo.section("Loop level 3 in each naked-edge mode");
    demo.reuse("loop-3", "naked edges fixed: the boundary polyline stays");
    for (mode, name, note) in [
        (
            NakedEdges::Smooth,
            "smooth",
            "the boundary becomes a B-spline and pulls in",
        ),
        (
            NakedEdges::CornerFixed,
            "corner-fixed",
            "smooth, but the four corners stay",
        ),
    ] {
        let refined = op("Loop", loop_subdivision(&cage, 3, mode))?;
        demo.save(
            &format!("loop-3-{name}"),
            &format!("naked edges {name}: {note}"),
            &refined,
        )?;
    }
    demo.section("A triangle mesh with a hole comes out rounded");
    let holed = weft::mesh::shapes::triangle_grid_with_hole();
    demo.save("hole-0-cage", "a triangle grid with a square hole", &holed)?;
    let rounded = op("Loop", loop_subdivision(&holed, 3, NakedEdges::Smooth))?;
    demo.save(
        "hole-3-smooth",
        "Loop level 3, naked edges smooth: the hole is rounded",
        &rounded,
    )?;
    Ok(())
}

pub fn surfaces(demo: &mut Demo) -> Step<()> {
    demo.section("Three surface meshes, one flipped: join, weld, Catmull-Clark");
    let mut parts = Vec::new();
    for (k, x0) in [0.0, 3.0, 6.0].into_iter().enumerate() {
        let part = surface_patch(x0, x0 + 3.0, 4, 0.0, 5.0, 6, false)?;
        parts.push(if k == 1 {
            weft::mend::orient::flip(&part)
        } else {
            part
        });
    }
    let refs: Vec<&Mesh> = parts.iter().collect();
    let joined = op("join", weft::mend::weld::join(&refs))?;
    demo.save(
        "surfaces-joined",
        "three surface meshes joined; the middle one is flipped",
        &joined,
    )?;
    let (welded, report) = op(
        "weld",
        weft::mend::weld::weld(&joined, weft::mend::weld::DEFAULT_WELD_TOLERANCE),
    )?;
    let (unified, flipped) = weft::mend::orient::unify_orientation(&welded);
    demo.save(
        "surfaces-welded",
        &format!(
            "welded ({} vertices merged), orientation unified ({flipped} faces flipped)",
            report.merged_vertex_count
        ),
        &unified,
    )?;
    let smooth = op(
        "Catmull-Clark",
        catmull_clark(&unified, 3, NakedEdges::Fixed),
    )?;
    demo.save(
        "surfaces-smooth",
        "Catmull-Clark level 3: one smooth surface",
        &smooth,
    )?;
    Ok(())
}

pub fn t_nodes(demo: &mut Demo) -> Step<()> {
    demo.section("Mismatched U/V counts: T-nodes found and repaired");
    // The middle strip has 9 rows of faces, its neighbours 5: their seams
    // meet only every few rows, and the vertices between lie on the
    // neighbours' edges.
    let parts = [
        surface_patch(0.0, 3.0, 4, 0.0, 5.0, 6, false)?,
        surface_patch(3.0, 6.0, 4, 0.0, 5.0, 10, false)?,
        surface_patch(6.0, 9.0, 4, 0.0, 5.0, 6, false)?,
    ];
    let welded = join_and_weld(&parts)?;
    // The seams are curved: a vertex of one strip lies on the curve, off the
    // straight edge of the other by up to about 0.02.
    let tolerance = 0.05;
    let found = op(
        "T-nodes",
        weft::mend::t_nodes::find_t_nodes(&welded, tolerance),
    )?;
    demo.save(
        "t-nodes-welded",
        &format!(
            "joined and welded: {} T-nodes along the seams (tolerance {tolerance}); naked edges in red",
            found.len()
        ),
        &welded,
    )?;
    // Smooth naked edges: a seam that is still a boundary pulls open.
    let cracked = op(
        "Catmull-Clark",
        catmull_clark(&welded, 2, NakedEdges::Smooth),
    )?;
    demo.save(
        "t-nodes-unrepaired-smooth",
        "Catmull-Clark level 2 without repair: the seams stay naked edges (red), three \
         surfaces smoothed side by side, not one",
        &cracked,
    )?;
    let (repaired, inserted) = op(
        "T-node repair",
        weft::mend::t_nodes::repair_t_nodes(&welded, tolerance),
    )?;
    let smooth = op(
        "Catmull-Clark",
        catmull_clark(&repaired, 2, NakedEdges::Smooth),
    )?;
    demo.save(
        "t-nodes-repaired-smooth",
        &format!(
            "{inserted} T-nodes inserted into their edges, then Catmull-Clark level 2: one \
             surface, no seams left. The faint rings along the old seams are the repaired \
             faces, now n-gons with the inserted corners: Catmull-Clark puts an extraordinary point \
             at each, as it does at any n-gon"
        ),
        &smooth,
    )?;
    Ok(())
}

pub fn voronoi_skin(demo: &mut Demo) -> Step<()> {
    demo.section("Voronoi skin");
    let mut random = Random(0x5eed_1234_abcd_0001);
    let points: Vec<DVec3> = (0..36)
        .map(|_| DVec3::new(10.0 * random.unit(), 8.0 * random.unit(), 0.0))
        .collect();
    let cells = op(
        "Voronoi",
        weft::make::voronoi::voronoi(&points, &Plane::xy(), None, None),
    )?;
    let cell_mesh = op("Voronoi cells", weft::make::voronoi::cells_to_mesh(&cells))?;
    // Shown welded, so that neighbouring cells share their edges and only
    // the outline is naked (red).
    let (shown, _) = op(
        "weld",
        weft::mend::weld::weld(&cell_mesh, weft::mend::weld::relative_tolerance(&cell_mesh)),
    )?;
    demo.save(
        "voronoi-cells",
        "Voronoi cells of 36 points on a plane, welded: the outline is their only naked edge",
        &shown,
    )?;
    // A pyramid per cell, apex below: the cell's centroid moved down.
    let pyramids = op("stellate", stellate(&cell_mesh, Heights::One(-0.9)))?;
    let (welded, report) = op(
        "weld",
        weft::mend::weld::weld(&pyramids, weft::mend::weld::DEFAULT_WELD_TOLERANCE),
    )?;
    demo.save(
        "voronoi-pyramids",
        &format!(
            "a pyramid per cell, welded ({} vertices merged)",
            report.merged_vertex_count
        ),
        &welded,
    )?;
    let skin = op(
        "Catmull-Clark",
        catmull_clark(&welded, 2, NakedEdges::Fixed),
    )?;
    demo.save(
        "voronoi-skin",
        "Catmull-Clark level 2: the Voronoi skin",
        &skin,
    )?;
    Ok(())
}

pub fn fading_pattern(demo: &mut Demo, gray: &Gray) -> Step<()> {
    demo.section("Fading pattern from a grayscale image");
    // Diamonds on the surface: vertices at the lattice points whose
    // coordinates add up to an even number, a diamond around every odd one;
    // the lattice is taller than wide, so each panel is a rhombus standing
    // on its point, not a square turned by 45°.
    let (n, m, spacing, rise) = (16usize, 16usize, 0.5, 0.75);
    let mut index = vec![u32::MAX; (n + 1) * (m + 1)];
    let mut positions = Vec::new();
    for j in 0..=m {
        for i in 0..=n {
            if (i + j) % 2 == 0 {
                index[j * (n + 1) + i] = positions.len() as u32;
                positions.push(surface(i as f64 * spacing, j as f64 * rise));
            }
        }
    }
    let mut diamonds = Vec::new();
    let mut heights = Vec::new();
    for j in 1..m {
        for i in 1..n {
            if (i + j) % 2 == 1 {
                let at = |i: usize, j: usize| index[j * (n + 1) + i];
                diamonds.push([at(i + 1, j), at(i, j + 1), at(i - 1, j), at(i, j - 1)]);
                let g = gray.sample(i as f64 / n as f64, j as f64 / m as f64);
                heights.push(0.05 + 0.6 * g);
            }
        }
    }
    let panels = op(
        "diamond panels",
        Mesh::from_polygons(positions, diamonds).map_err(Error::from),
    )?;
    demo.save(
        "fading-panels",
        "diamond panels on a surface: rhombi half again as tall as they are wide",
        &panels,
    )?;
    let pyramids = op("stellate", stellate(&panels, Heights::PerFace(&heights)))?;
    let (welded, _) = op(
        "weld",
        weft::mend::weld::weld(&pyramids, weft::mend::weld::DEFAULT_WELD_TOLERANCE),
    )?;
    demo.save(
        "fading-pyramids",
        "pyramids whose height follows the image, welded",
        &welded,
    )?;
    let smooth = op(
        "Catmull-Clark",
        catmull_clark(&welded, 2, NakedEdges::Fixed),
    )?;
    demo.save(
        "fading-smooth",
        "Catmull-Clark level 2: the fading pattern",
        &smooth,
    )?;
    Ok(())
}

pub fn boxes(demo: &mut Demo) -> Step<()> {
    demo.section("Aggregation of boxes: join, weld, cull inner faces, Catmull-Clark");
    // A ring of eight boxes round an empty middle, with towers on it.
    let cells = [
        (0, 0, 0),
        (1, 0, 0),
        (2, 0, 0),
        (2, 1, 0),
        (2, 2, 0),
        (1, 2, 0),
        (0, 2, 0),
        (0, 1, 0),
        (0, 0, 1),
        (1, 0, 1),
        (0, 0, 2),
        (2, 2, 1),
        (2, 2, 2),
    ];
    let cubes: Vec<Mesh> = cells
        .iter()
        .map(|&(x, y, z)| {
            let mut cube = weft::mesh::shapes::cube();
            for p in cube.positions_mut() {
                *p += DVec3::new(x as f64, y as f64, z as f64);
            }
            cube
        })
        .collect();
    let welded = join_and_weld(&cubes)?;
    // Cut away above the middle of the first layer: the walls inside show.
    let cut = render::Section {
        point: DVec3::new(0.0, 0.0, 0.6),
        normal: DVec3::Z,
    };
    demo.save_cut(
        "boxes-welded",
        &format!(
            "{} boxes joined and welded, seen cut away above the middle of the first layer: \
             every wall between two boxes is still there, twice",
            cells.len()
        ),
        &welded,
        cut,
    )?;
    // The walls inside, hidden from outside: one face of each twin pair.
    let walls = inner_walls(&welded)?;
    let (culled, removed) = weft::mend::cull::cull_adjacent(&welded);
    let (culled, _) = weft::mend::weld::remove_unused_vertices(&culled);
    demo.save(
        "boxes-inner",
        &format!(
            "inside them, {} walls between touching boxes, each two twin faces: the {removed} \
             faces that culling removes",
            walls.face_count()
        ),
        &walls,
    )?;
    demo.save_cut(
        "boxes-culled",
        &format!(
            "culled, cut away as above: the walls inside are gone, one closed shell of {} faces \
             is left",
            culled.face_count()
        ),
        &culled,
        cut,
    )?;
    let smooth = op(
        "Catmull-Clark",
        catmull_clark(&culled, 3, NakedEdges::Fixed),
    )?;
    demo.save("boxes-smooth", "Catmull-Clark level 3", &smooth)?;
    Ok(())
}

/// One face of every set of faces on the same vertices: the walls between
/// joined boxes, shown once each, by the copy that faces the pictures'
/// three-quarter view from the front, right and above.
fn inner_walls(mesh: &Mesh) -> Step<Mesh> {
    let toward_viewer = DVec3::new(0.95, -1.45, 1.05);
    let mut copies: HashMap<Vec<u32>, Vec<usize>> = HashMap::new();
    for (f, face) in mesh.faces().enumerate() {
        let mut key = face.to_vec();
        key.sort_unstable();
        copies.entry(key).or_default().push(f);
    }
    let mut shown: Vec<usize> = copies
        .values()
        .filter(|faces| faces.len() > 1)
        .map(|faces| {
            faces
                .iter()
                .copied()
                .find(|&f| weft::mesh::analysis::face_normal(mesh, f).dot(toward_viewer) > 0.0)
                .unwrap_or(faces[0])
        })
        .collect();
    shown.sort_unstable();
    let walls = op(
        "inner walls",
        Mesh::from_polygons(
            mesh.positions().to_vec(),
            shown.iter().map(|&f| mesh.face(f)),
        )
        .map_err(Error::from),
    )?;
    Ok(weft::mend::weld::remove_unused_vertices(&walls).0)
}

/// An L-shaped block of three cubes (joined, welded, inner faces culled),
/// `height` tall.
fn l_block(height: f64) -> Step<Mesh> {
    let cubes: Vec<Mesh> = [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0)]
        .iter()
        .map(|&(x, y)| {
            let mut cube = weft::mesh::shapes::cube();
            for p in cube.positions_mut() {
                *p = DVec3::new(p.x + x, p.y + y, p.z * height);
            }
            cube
        })
        .collect();
    let welded = join_and_weld(&cubes)?;
    let (culled, _) = weft::mend::cull::cull_adjacent(&welded);
    Ok(weft::mend::weld::remove_unused_vertices(&culled).0)
}

pub fn creases(demo: &mut Demo) -> Step<()> {
    demo.section("Creases: the same block, Catmull-Clark level 3, without and with creases");
    let height = 0.8;
    let cage = l_block(height)?;
    // The edges of the cage: (vertex, vertex) for each.
    let topology = weft::Topology::new(&cage);
    let at = |v: u32| cage.positions()[v as usize];
    let is_top = |f: u32| cage.face(f as usize).iter().all(|&v| at(v).z == height);
    let mut options = SubdivisionOptions::new(NakedEdges::Fixed);
    for (e, &[a, b]) in topology.edges().iter().enumerate() {
        let (p, q) = (at(a), at(b));
        let top_faces = topology.edge_faces(e).filter(|&f| is_top(f)).count();
        let vertical = p.x == q.x && p.y == q.y;
        if top_faces == 1 {
            // The top's outline.
            options.creases.push(([a, b], SHARPNESS_INFINITE));
        } else if vertical && p.y == 0.0 {
            // The upright edges of the front wall: semi-sharp.
            options.creases.push(([a, b], 2.0));
        }
    }
    let mut carried = io::MeshFile::new(cage.clone());
    carried.creases = options
        .creases
        .iter()
        .map(|&(edge, sharpness)| io::FileCrease {
            edge,
            sharpness,
            line: 0,
        })
        .collect();
    let hard = options
        .creases
        .iter()
        .filter(|c| c.1 >= SHARPNESS_INFINITE)
        .count();
    demo.save_file(
        "creases-cage",
        &format!(
            "the cage: an L-shaped block of three boxes; its OBJ marks {hard} hard creases (l) and {} semi-sharp ones (t crease)",
            options.creases.len() - hard
        ),
        &carried,
    )?;
    let smooth = op("Catmull-Clark", catmull_clark(&cage, 3, NakedEdges::Fixed))?;
    demo.save("creases-none", "no creases: everything rounds off", &smooth)?;
    let creased = op(
        "Catmull-Clark with creases",
        subdivide_with(&cage, Scheme::CatmullClark, 3, &options),
    )?;
    demo.save(
        "creases-sharp",
        "the top's outline infinitely sharp (a hard rim), the front wall's upright edges \
         semi-sharp (sharpness 2: rounded a little)",
        &creased,
    )?;

    // Carried data: a colour per cage vertex (its position as RGB) and a UV
    // square per face, through the same creased subdivision.
    let subdivider = op(
        "Catmull-Clark with creases",
        Subdivider::new(&cage, Scheme::CatmullClark, 3, &options),
    )?;
    let rgba: Vec<f64> = cage
        .positions()
        .iter()
        .flat_map(|p| [p.x / 2.0, p.y / 2.0, 0.25 + 0.75 * p.z / height, 1.0])
        .collect();
    let refined_rgba = op("carry colours", subdivider.vertex_data(&rgba, 4))?;
    let square = [0.0, 0.0, 1.0, 0.0, 1.0, 1.0, 0.0, 1.0];
    let uv_indices: Vec<u32> = cage.face_sizes().iter().flat_map(|&n| 0..n).collect();
    let refined_uvs = op(
        "carry UVs",
        subdivider.face_varying(&square, 2, &uv_indices, FaceVaryingLinear::All),
    )?;
    let mut coloured = io::MeshFile::new(creased);
    coloured.colours = Some(io::Colours {
        rgba: refined_rgba
            .chunks_exact(4)
            .map(|c| [c[0], c[1], c[2], c[3]])
            .collect(),
        alpha: false,
    });
    coloured.uvs = Some(io::Uvs {
        values: refined_uvs.chunks_exact(2).map(|c| [c[0], c[1]]).collect(),
        indices: (0..refined_uvs.len() as u32 / 2).collect(),
    });
    demo.save_file(
        "creases-colours",
        "vertex colours (each cage vertex's position as RGB) and a UV square per cage face \
         carried through the creased subdivision; the OBJ holds both",
        &coloured,
    )?;
    Ok(())
}

/// The parts joined into one mesh and welded at the default tolerance, as a
/// designer's Join and Weld components do.
fn join_and_weld(parts: &[Mesh]) -> Step<Mesh> {
    let refs: Vec<&Mesh> = parts.iter().collect();
    let joined = op("join", weft::mend::weld::join(&refs))?;
    let (welded, _) = op(
        "weld",
        weft::mend::weld::weld(&joined, weft::mend::weld::DEFAULT_WELD_TOLERANCE),
    )?;
    Ok(welded)
}
