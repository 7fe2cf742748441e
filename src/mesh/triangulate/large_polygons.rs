//! Ear clipping for polygons of many corners (a T-node repair can give a
//! face a million): the search of every corner for the first ear, each
//! tested against every corner, is quadratic at best and cubic at worst.
//! Here the corners are a ring of links, clipped in one walk around it,
//! and an ear is tested only against the corners that are not convex,
//! filed in a grid: in a simple polygon a triangle that holds a corner
//! holds one of those (and flat corners count among them, since a corner
//! on the triangle's side blocks it).

use glam::DVec2;

use super::inside_triangle;
use crate::mesh::bounds_2d;

/// Corners from which a polygon is clipped here.
pub(super) const LARGE: usize = 1024;

/// The ring of remaining corners, the grid of those that are not convex,
/// and for each corner the last corner found inside its ear.
struct Ring<'a> {
    points: &'a [DVec2],
    epsilon: f64,
    prev: Vec<u32>,
    next: Vec<u32>,
    removed: Vec<bool>,
    /// The grid's cell of each corner filed in it.
    filed: Vec<Option<u32>>,
    cells: Vec<Vec<u32>>,
    low: DVec2,
    cell_size: f64,
    /// Room for rounding around a triangle's cells: far more than it.
    margin: f64,
    side: usize,
    blocker: Vec<u32>,
}

impl Ring<'_> {
    /// The ring of `points`, the corners that are not convex filed in a
    /// grid of `side` × `side` cells over their bounding box.
    fn new(points: &[DVec2], epsilon: f64, side: usize) -> Ring<'_> {
        let n = points.len();
        let (low, high) = bounds_2d(points);
        let side = side.max(1);
        let extent = (high - low).max_element();
        let cell_size = match extent / side as f64 {
            size if size > 0.0 && size.is_finite() => size,
            _ => 1.0,
        };
        let mut ring = Ring {
            points,
            epsilon,
            prev: (0..n as u32)
                .map(|i| (i + n as u32 - 1) % n as u32)
                .collect(),
            next: (0..n as u32).map(|i| (i + 1) % n as u32).collect(),
            removed: vec![false; n],
            filed: vec![None; n],
            cells: vec![Vec::new(); side * side],
            low,
            cell_size,
            margin: 1e-9 * extent.max(f64::MIN_POSITIVE),
            side,
            blocker: vec![u32::MAX; n],
        };
        for i in 0..n {
            ring.file_if_not_convex(i);
        }
        ring
    }

    fn turn(&self, i: usize) -> f64 {
        let (a, b, c) = self.corner(i);
        (b - a).perp_dot(c - b)
    }

    fn corner(&self, i: usize) -> (DVec2, DVec2, DVec2) {
        let p = |k: u32| self.points[k as usize];
        (p(self.prev[i]), self.points[i], p(self.next[i]))
    }

    /// The grid's column or row of a coordinate.
    fn cell_along(&self, x: f64, low: f64) -> usize {
        (((x - low) / self.cell_size).max(0.0) as usize).min(self.side - 1)
    }

    fn cell_of(&self, p: DVec2) -> u32 {
        let (x, y) = (
            self.cell_along(p.x, self.low.x),
            self.cell_along(p.y, self.low.y),
        );
        (y * self.side + x) as u32
    }

    /// Files corner `i` when it is not convex (and not filed yet).
    fn file_if_not_convex(&mut self, i: usize) {
        if self.filed[i].is_none() && self.turn(i) <= self.epsilon {
            let cell = self.cell_of(self.points[i]);
            self.cells[cell as usize].push(i as u32);
            self.filed[i] = Some(cell);
        }
    }

    /// Whether a remaining corner other than `i` and its neighbours lies in
    /// or on the triangle of `i`'s corner; the one found is kept, to be
    /// tried first next time.
    fn blocked(&mut self, i: usize) -> bool {
        match self.blocker_of(i) {
            Some(k) => {
                self.blocker[i] = k;
                true
            }
            None => false,
        }
    }

    fn blocker_of(&self, i: usize) -> Option<u32> {
        let (a, b, c) = self.corner(i);
        let own = [self.prev[i], i as u32, self.next[i]];
        let blocks =
            |k: u32| !own.contains(&k) && inside_triangle(self.points[k as usize], a, b, c);
        // The corner that blocked it last, most often still there.
        let last = self.blocker[i];
        if last != u32::MAX && !self.removed[last as usize] && blocks(last) {
            return Some(last);
        }
        let (low, high) = (a.min(b).min(c), a.max(b).max(c));
        let (y0, y1) = (
            self.cell_along(low.y - self.margin, self.low.y),
            self.cell_along(high.y + self.margin, self.low.y),
        );
        // Row by row, the cells the triangle's sides reach within the row:
        // a thin triangle's cells, not its bounding box's.
        (y0..=y1).find_map(|y| {
            let row_low = self.low.y + y as f64 * self.cell_size - self.margin;
            let row_high = row_low + self.cell_size + 2.0 * self.margin;
            let (left, right) = [(a, b), (b, c), (c, a)]
                .into_iter()
                .filter_map(|(p, q)| x_extent_within(p, q, row_low, row_high))
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, r), (sl, sr)| {
                    (l.min(sl), r.max(sr))
                });
            if left > right {
                return None;
            }
            let x0 = self.cell_along(left - self.margin, self.low.x);
            let x1 = self.cell_along(right + self.margin, self.low.x);
            self.cells[y * self.side + x0..=y * self.side + x1]
                .iter()
                .find_map(|cell| cell.iter().copied().find(|&k| blocks(k)))
        })
    }

    /// Takes corner `i` out of the ring and the grid.
    fn unlink(&mut self, i: usize) {
        let (p, n) = (self.prev[i], self.next[i]);
        self.next[p as usize] = n;
        self.prev[n as usize] = p;
        self.removed[i] = true;
        if let Some(cell) = self.filed[i].take() {
            let cell = &mut self.cells[cell as usize];
            let at = cell.iter().position(|&k| k as usize == i).expect("filed");
            cell.swap_remove(at);
        }
        self.file_if_not_convex(p as usize);
        self.file_if_not_convex(n as usize);
    }
}

/// Clips the polygon `points` (counter-clockwise, more than 3 corners) into
/// its n − 2 triangles, each as its corners' indices (previous, ear, next),
/// given to `triangle`. A corner turning by at most `epsilon` is not an
/// ear; when a whole walk around the ring finds none (a polygon that
/// crosses itself), the corner that turns most is cut, as the search of
/// every corner does.
pub(super) fn clip(points: &[DVec2], epsilon: f64, mut triangle: impl FnMut([usize; 3])) {
    let n = points.len();
    // About one corner a cell.
    let mut ring = Ring::new(points, epsilon, (n as f64).sqrt().ceil() as usize);
    let (mut remaining, mut current, mut misses) = (n, 0, 0);
    while remaining > 3 {
        let ear = match ring.turn(current) > epsilon && !ring.blocked(current) {
            true => current,
            false if misses < remaining => {
                current = ring.next[current] as usize;
                misses += 1;
                continue;
            }
            false => {
                // No ear in a whole walk: the corner that turns most.
                let mut best = current;
                let mut k = ring.next[current] as usize;
                while k != current {
                    if ring.turn(k) > ring.turn(best) {
                        best = k;
                    }
                    k = ring.next[k] as usize;
                }
                best
            }
        };
        let (before, after) = (ring.prev[ear] as usize, ring.next[ear] as usize);
        triangle([before, ear, after]);
        ring.unlink(ear);
        remaining -= 1;
        misses = 0;
        // The corner before may have become an ear.
        current = before;
    }
    let (before, after) = (ring.prev[current] as usize, ring.next[current] as usize);
    triangle([before, current, after]);
}

/// The least and greatest x of the segment from `p` to `q` between the
/// heights `low` and `high`, or `None` where it does not reach them.
fn x_extent_within(p: DVec2, q: DVec2, low: f64, high: f64) -> Option<(f64, f64)> {
    let (p, q) = if p.y <= q.y { (p, q) } else { (q, p) };
    if q.y < low || p.y > high {
        return None;
    }
    let rise = q.y - p.y;
    if rise <= 0.0 {
        return Some((p.x.min(q.x), p.x.max(q.x)));
    }
    let at = |t: f64| p.x + t.clamp(0.0, 1.0) * (q.x - p.x);
    let (from, to) = (at((low - p.y) / rise), at((high - p.y) / rise));
    Some((from.min(to), from.max(to)))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_random::units;

    fn shoelace(points: &[DVec2]) -> f64 {
        let n = points.len();
        (0..n)
            .map(|i| points[i].perp_dot(points[(i + 1) % n]))
            .sum::<f64>()
            / 2.0
    }

    fn counter_clockwise(mut points: Vec<DVec2>) -> Vec<DVec2> {
        if shoelace(&points) < 0.0 {
            points.reverse();
        }
        points
    }

    /// Clips `points` and checks the triangles tile the polygon: n − 2 of
    /// them, none turned over, none holding a corner not its own in it or
    /// on its sides, every corner used, and their areas adding up to the
    /// polygon's.
    fn assert_tiles(points: &[DVec2], what: &str) {
        let scale = points
            .iter()
            .fold(0.0f64, |m, p| m.max(p.abs().max_element()));
        let epsilon = 1e-12 * scale * scale;
        let mut triangles = Vec::new();
        clip(points, epsilon, |t| triangles.push(t));
        assert_eq!(triangles.len(), points.len() - 2, "{what}");
        let mut used = vec![false; points.len()];
        let mut total = 0.0;
        for [a, b, c] in triangles {
            let (pa, pb, pc) = (points[a], points[b], points[c]);
            let area = (pb - pa).perp_dot(pc - pa) / 2.0;
            assert!(
                area >= -epsilon,
                "{what}: triangle {a} {b} {c} turned over ({area:e})"
            );
            total += area;
            let held = (0..points.len())
                .find(|&k| ![a, b, c].contains(&k) && inside_triangle(points[k], pa, pb, pc));
            assert_eq!(held, None, "{what}: triangle {a} {b} {c} holds a corner");
            for k in [a, b, c] {
                used[k] = true;
            }
        }
        assert!(used.iter().all(|&u| u), "{what}: a corner unused");
        let expected = shoelace(points);
        assert!(
            (total - expected).abs() <= 1e-9 * expected.abs(),
            "{what}: {total} against {expected}"
        );
    }

    /// A tall ear blocked only by a reflex corner near its top, in a grid
    /// of many rows: found however far from the ear's corner it lies.
    #[test]
    fn a_blocker_is_found_in_any_row_of_the_triangle() {
        // The corner at (4, 0) has the ear (0, 0), (4, 0), (2, 10), which
        // holds the notch at (2, 9).
        let points =
            [(0.0, 0.0), (4.0, 0.0), (2.0, 10.0), (2.0, 9.0)].map(|(x, y)| DVec2::new(x, y));
        for side in [1, 2, 5, 40] {
            let mut ring = Ring::new(&points, 1e-12, side);
            assert!(ring.blocked(1), "{side} cells a side");
            assert_eq!(ring.blocker[1], 3);
            // The tip's ear has the notch for a corner: nothing else blocks it.
            assert!(!ring.blocked(2), "{side} cells a side");
        }
    }

    #[test]
    fn large_polygons_are_tiled() {
        let mut next = units(0x1f83_d9ab_fb41_bd6bu64);
        let tau = std::f64::consts::TAU;
        // A star of random spikes.
        let n = 3000;
        let star: Vec<DVec2> = (0..n)
            .map(|i| {
                let (y, x) = (tau * i as f64 / n as f64).sin_cos();
                DVec2::new(x, y) * (0.2 + next())
            })
            .collect();
        assert_tiles(&star, "star");
        // A comb of 400 teeth: deep notches, many corners on one line.
        let mut comb = Vec::new();
        for tooth in 0..400 {
            let x = tooth as f64;
            comb.extend([(x, 0.0), (x + 0.5, 0.0), (x + 0.5, 300.0), (x + 0.9, 300.0)]);
        }
        comb.extend([(400.0, 0.0), (400.0, -1.0), (0.0, -1.0)]);
        let comb: Vec<DVec2> = comb.into_iter().map(|(x, y)| DVec2::new(x, y)).collect();
        assert_tiles(&counter_clockwise(comb), "comb");
        // A triangle with 1,500 corners along one side (a T-node repair's).
        let mut repaired: Vec<DVec2> = (0..=1500)
            .map(|i| DVec2::new(i as f64 / 1500.0, 0.0))
            .collect();
        repaired.push(DVec2::new(0.5, 1.0));
        assert_tiles(&repaired, "repaired triangle");
        // A spiral corridor, concave all the way round.
        let turns = 6.0;
        let m = 800;
        let arm = |r0: f64| -> Vec<DVec2> {
            (0..m)
                .map(|i| {
                    let t = i as f64 / m as f64;
                    let (y, x) = (tau * turns * t).sin_cos();
                    DVec2::new(x, y) * (r0 + 10.0 * t)
                })
                .collect()
        };
        let spiral: Vec<DVec2> = arm(1.0)
            .into_iter()
            .chain(arm(1.5).into_iter().rev())
            .collect();
        assert_tiles(&counter_clockwise(spiral), "spiral");
    }
}
