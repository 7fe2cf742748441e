use super::*;

struct Lcg(u64);
impl Lcg {
    fn next(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
}

fn flat(cell: &[DVec3]) -> Vec<DVec2> {
    cell.iter().map(|p| p.truncate()).collect()
}

fn area_of(cells: &[Vec<DVec3>]) -> f64 {
    cells.iter().map(|c| signed_area(&flat(c))).sum()
}

/// Checks the cells (see [`check_cells`]) and that together they cover the
/// boundary's area exactly.
fn check_tiling(sites: &[DVec2], cells: &[Vec<DVec3>], boundary: &[DVec2]) {
    let total = check_cells(sites, cells, boundary);
    let expected = signed_area(boundary);
    assert!(
        (total - expected).abs() <= 1e-9 * expected,
        "{total} vs {expected}"
    );
}

/// Checks the properties every diagram must have; returns the cells' total area.
fn check_cells(sites: &[DVec2], cells: &[Vec<DVec3>], boundary: &[DVec2]) -> f64 {
    let scale = 10.0;
    // Points outside the boundary take no part in the diagram.
    let sites: Vec<DVec2> = (0..sites.len())
        .map(|i| {
            if cells[i].is_empty() {
                DVec2::splat(1e9)
            } else {
                sites[i]
            }
        })
        .collect();
    for (i, cell) in cells.iter().enumerate() {
        if cell.is_empty() {
            continue;
        }
        let ring = flat(cell);
        assert!(cell.iter().all(|p| p.z == 0.0));
        assert!(
            signed_area(&ring) > 0.0,
            "cell {i} is not counter-clockwise"
        );
        assert!(
            winding(&ring, sites[i]) == 1 || on_polygon(&ring, sites[i], 1e-9),
            "cell {i} does not contain its site"
        );
        for &v in &ring {
            if on_polygon(boundary, v, 1e-9 * scale) {
                continue;
            }
            let own = (v - sites[i]).length();
            let nearest = sites
                .iter()
                .map(|s| (v - *s).length())
                .fold(f64::INFINITY, f64::min);
            assert!(
                own - nearest <= 1e-9 * scale,
                "vertex {v} of cell {i} is nearer another site"
            );
            let equidistant = sites
                .iter()
                .filter(|s| ((v - **s).length() - own).abs() <= 1e-9 * scale)
                .count();
            assert!(
                equidistant >= 3,
                "inner vertex {v} of cell {i} separates only {equidistant} sites"
            );
        }
    }
    area_of(cells)
}

fn random_sites(seed: u64, n: usize, accept: impl Fn(DVec2) -> bool) -> Vec<DVec2> {
    let mut rng = Lcg(seed);
    let mut sites = Vec::new();
    while sites.len() < n {
        let p = DVec2::new(rng.next() * 10.0, rng.next() * 10.0);
        if accept(p) {
            sites.push(p);
        }
    }
    sites
}

fn lift(points: &[DVec2]) -> Vec<DVec3> {
    points.iter().map(|p| p.extend(0.0)).collect()
}

#[test]
fn default_boundary_is_tiled_by_cells_that_contain_their_sites() {
    for seed in 1..4 {
        let sites = random_sites(seed, 60, |_| true);
        let cells = voronoi(&lift(&sites), &Plane::xy(), None, None).unwrap();
        assert_eq!(cells.len(), 60);
        assert!(cells.iter().all(|c| c.len() >= 3));
        let (lo, hi) = bounds_2d(&sites);
        let margin = (hi - lo).max_element() * DEFAULT_MARGIN;
        let boundary = rectangle(lo - margin, hi + margin);
        check_tiling(&sites, &cells, &boundary);
    }
}

#[test]
fn a_convex_boundary_is_tiled_and_points_outside_get_empty_cells() {
    let boundary: Vec<DVec2> = (0..6)
        .map(|k| {
            let a = std::f64::consts::TAU * k as f64 / 6.0;
            DVec2::new(5.0 + 5.0 * a.cos(), 5.0 + 5.0 * a.sin())
        })
        .collect();
    let mut sites = random_sites(9, 40, |_| true);
    sites.push(DVec2::new(-3.0, 5.0));
    // Clockwise input is accepted.
    let reversed: Vec<DVec2> = boundary.iter().rev().copied().collect();
    let cells = voronoi(&lift(&sites), &Plane::xy(), Some(&lift(&reversed)), None).unwrap();
    let outside: Vec<usize> = (0..sites.len())
        .filter(|&i| winding(&boundary, sites[i]) == 0)
        .collect();
    assert!(outside.contains(&40) && outside.len() > 1);
    for (i, cell) in cells.iter().enumerate() {
        assert_eq!(cell.is_empty(), outside.contains(&i), "point {i}");
    }
    check_tiling(&sites, &cells, &boundary);
}

#[test]
fn an_l_shaped_boundary_is_tiled() {
    let boundary = vec![
        DVec2::new(0.0, 0.0),
        DVec2::new(10.0, 0.0),
        DVec2::new(10.0, 4.0),
        DVec2::new(4.0, 4.0),
        DVec2::new(4.0, 10.0),
        DVec2::new(0.0, 10.0),
    ];
    for seed in 1..4 {
        let sites = random_sites(seed, 50, |p| p.x < 4.0 || p.y < 4.0);
        let cells = voronoi(&lift(&sites), &Plane::xy(), Some(&lift(&boundary)), None).unwrap();
        assert!(cells.iter().all(|c| c.len() >= 3));
        check_tiling(&sites, &cells, &boundary);
    }
}

#[test]
fn a_cell_cut_in_two_by_the_notch_keeps_the_piece_with_its_site() {
    // A U shape: one site in each arm and one below. The bottom site's cell
    // reaches into both arms' lower parts; the arm sites' cells are cut by the notch.
    let boundary = vec![
        DVec2::new(0.0, 0.0),
        DVec2::new(9.0, 0.0),
        DVec2::new(9.0, 9.0),
        DVec2::new(6.0, 9.0),
        DVec2::new(6.0, 3.0),
        DVec2::new(3.0, 3.0),
        DVec2::new(3.0, 9.0),
        DVec2::new(0.0, 9.0),
    ];
    // Two sites whose bisector is horizontal: the upper site's cell covers both arms' tops.
    let sites = vec![DVec2::new(1.5, 1.5), DVec2::new(1.5, 7.5)];
    let cells = voronoi(&lift(&sites), &Plane::xy(), Some(&lift(&boundary)), None).unwrap();
    let upper = flat(&cells[1]);
    assert!(
        upper
            .iter()
            .all(|p| p.x <= 3.0 + 1e-12 && p.y >= 4.5 - 1e-12),
        "{upper:?}"
    );
    assert!((signed_area(&upper) - 3.0 * 4.5).abs() < 1e-9);
}

#[test]
fn cells_stay_within_the_radius() {
    let sites = random_sites(5, 30, |_| true);
    let radius = 1.2;
    let cells = voronoi(&lift(&sites), &Plane::xy(), None, Some(radius)).unwrap();
    let without = voronoi(&lift(&sites), &Plane::xy(), None, None).unwrap();
    let mut clipped = 0;
    for (i, cell) in cells.iter().enumerate() {
        assert!(cell.len() >= 3);
        for p in flat(cell) {
            assert!((p - sites[i]).length() <= radius * (1.0 + 1e-12));
        }
        let (a, b) = (signed_area(&flat(cell)), signed_area(&flat(&without[i])));
        assert!(a <= b * (1.0 + 1e-12));
        clipped += usize::from(a < b * (1.0 - 1e-9));
    }
    assert!(clipped > 0);
    // Alone, a point's cell is the 64-gon itself.
    let alone = voronoi(&[DVec3::ZERO], &Plane::xy(), None, Some(0.5)).unwrap();
    assert_eq!(alone[0].len(), CIRCLE_SEGMENTS);
}

#[test]
fn one_and_two_points() {
    let one = voronoi(&[DVec3::new(2.0, 3.0, 0.0)], &Plane::xy(), None, None).unwrap();
    assert_eq!(
        flat(&one[0]),
        rectangle(DVec2::new(1.0, 2.0), DVec2::new(3.0, 4.0))
    );
    let square = rectangle(DVec2::ZERO, DVec2::splat(4.0));
    let two = [DVec3::new(1.0, 2.0, 0.0), DVec3::new(3.0, 2.0, 0.0)];
    let cells = voronoi(&two, &Plane::xy(), Some(&lift(&square)), None).unwrap();
    assert_eq!(signed_area(&flat(&cells[0])), 8.0);
    assert_eq!(signed_area(&flat(&cells[1])), 8.0);
    assert!(flat(&cells[0]).iter().all(|p| p.x <= 2.0));
    // Collinear points give strips; duplicates give an empty cell.
    let line: Vec<DVec3> = [0.5, 1.5, 2.5, 2.5, 3.5]
        .iter()
        .map(|&x| DVec3::new(x, 2.0, 0.0))
        .collect();
    let cells = voronoi(&line, &Plane::xy(), Some(&lift(&square)), None).unwrap();
    assert!(cells[3].is_empty());
    assert_eq!(area_of(&cells), 16.0);
    assert!((signed_area(&flat(&cells[1])) - 4.0).abs() < 1e-12);
    // Alone in a concave boundary, a point's cell is the whole boundary.
    let l_shape = lift(&[
        DVec2::ZERO,
        DVec2::new(4.0, 0.0),
        DVec2::new(4.0, 1.0),
        DVec2::new(1.0, 1.0),
        DVec2::new(1.0, 4.0),
        DVec2::new(0.0, 4.0),
    ]);
    let alone = voronoi(
        &[DVec3::new(0.5, 0.5, 0.0)],
        &Plane::xy(),
        Some(&l_shape),
        None,
    )
    .unwrap();
    assert_eq!(alone[0].len(), 6);
    assert!((signed_area(&flat(&alone[0])) - 7.0).abs() < 1e-12);
    // No points at all.
    assert!(voronoi(&[], &Plane::xy(), None, None).unwrap().is_empty());
}

#[test]
fn cells_lie_on_a_tilted_plane_counter_clockwise_about_its_normal() {
    let origin = DVec3::new(10.0, 0.0, -5.0);
    let x = DVec3::new(1.0, 2.0, 2.0) / 3.0;
    let y = DVec3::new(-2.0, -1.0, 2.0) / 3.0;
    let plane = Plane::new(origin, x, y).unwrap();
    let n = plane.normal();
    let sites = random_sites(3, 20, |_| true);
    let points: Vec<DVec3> = sites
        .iter()
        .map(|s| origin + x * s.x + y * s.y + n * 3.0)
        .collect();
    let cells = voronoi(&points, &plane, None, None).unwrap();
    let flat_cells = voronoi(&lift(&sites), &Plane::xy(), None, None).unwrap();
    for (cell, flat_cell) in cells.iter().zip(&flat_cells) {
        assert_eq!(cell.len(), flat_cell.len());
        let mut newell = DVec3::ZERO;
        for k in 0..cell.len() {
            assert!(n.dot(cell[k] - origin).abs() < 1e-9);
            assert!((plane.to_plane(cell[k]) - flat_cell[k].truncate()).length() < 1e-9);
            newell += cell[k].cross(cell[(k + 1) % cell.len()]);
        }
        assert!(newell.dot(n) > 0.0);
    }
}

#[test]
fn bad_input_is_named() {
    let points = [DVec3::ZERO, DVec3::new(1.0, f64::INFINITY, 0.0)];
    let e = voronoi(&points, &Plane::xy(), None, None).unwrap_err();
    assert!(
        matches!(&e, Error::InvalidArgument(m) if m.contains("point 1")),
        "{e}"
    );
    let far = [
        DVec3::new(5.0, 0.0, 0.0),
        DVec3::ZERO,
        DVec3::new(1e100, 0.0, 0.0),
    ];
    let e = voronoi(&far, &Plane::xy(), None, None).unwrap_err();
    assert!(
        matches!(&e, Error::InvalidArgument(m) if m.contains("point 2")),
        "{e}"
    );
    let e = voronoi(&[DVec3::ZERO], &Plane::xy(), None, Some(-1.0)).unwrap_err();
    assert!(
        matches!(&e, Error::InvalidArgument(m) if m.contains("radius")),
        "{e}"
    );
    let bow_tie = lift(&[
        DVec2::ZERO,
        DVec2::new(2.0, 2.0),
        DVec2::new(2.0, 0.0),
        DVec2::new(0.0, 2.0),
    ]);
    let e = voronoi(&[DVec3::ZERO], &Plane::xy(), Some(&bow_tie), None).unwrap_err();
    assert!(
        matches!(&e, Error::InvalidArgument(m) if m.contains("edges 0 and 2")),
        "{e}"
    );
    let folded = lift(&[DVec2::ZERO, DVec2::X, DVec2::new(2.0, 0.0)]);
    let e = voronoi(&[DVec3::ZERO], &Plane::xy(), Some(&folded), None).unwrap_err();
    assert!(
        matches!(&e, Error::InvalidArgument(m) if m.contains("not a simple polygon")),
        "{e}"
    );
    let sliver = lift(&[DVec2::ZERO, DVec2::X, DVec2::new(0.5, 1e-20)]);
    let e = voronoi(&[DVec3::ZERO], &Plane::xy(), Some(&sliver), None).unwrap_err();
    assert!(matches!(e, Error::DegenerateInput(_)), "{e}");
    let two = lift(&[DVec2::ZERO, DVec2::X, DVec2::ZERO]);
    let e = voronoi(&[DVec3::ZERO], &Plane::xy(), Some(&two), None).unwrap_err();
    assert!(
        matches!(&e, Error::InvalidArgument(m) if m.contains("2 distinct")),
        "{e}"
    );
}

#[test]
fn cells_become_one_face_each() {
    let sites = random_sites(11, 12, |_| true);
    let mut points = lift(&sites);
    points.push(DVec3::new(100.0, 100.0, 0.0));
    let square = lift(&rectangle(DVec2::ZERO, DVec2::splat(10.0)));
    let cells = voronoi(&points, &Plane::xy(), Some(&square), None).unwrap();
    let mesh = cells_to_mesh(&cells).unwrap();
    assert_eq!(mesh.face_count(), 12);
    assert_eq!(
        mesh.vertex_count(),
        cells.iter().map(Vec::len).sum::<usize>()
    );
    assert_eq!(mesh.face(0).len(), cells[0].len());
}
