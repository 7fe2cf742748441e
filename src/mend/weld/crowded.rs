//! Crowded cells of the weld: cells whose sites do not all lie within the
//! tolerance of each other, as when the tolerance is many times the
//! spacing of the vertices. Comparing every pair of their sites, and
//! keeping every close pair to join, costs the square of their count in
//! time and memory (a 180,000-vertex sphere welded at a fifth of its
//! radius kept 2 GB of pairs). Each such cell is split instead into groups
//! whose sites do lie within the tolerance of each other: a group is one
//! cluster without a comparison, and two groups need one close pair to
//! join, or none when their boxes lie too far apart.

use glam::DVec3;
use rayon::prelude::*;

use super::within;
use crate::buffers::split_by_offsets;

/// Sites `start..end` of the weld's sites, one cell's or part of one, with
/// their bounding box.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Group {
    pub(super) start: u32,
    pub(super) end: u32,
    pub(super) low: DVec3,
    pub(super) high: DVec3,
    /// Every two sites lie within the tolerance: always, but where the
    /// box could not be split (rounding at the ends of the `f64` range).
    pub(super) tight: bool,
}

impl Group {
    /// The group of `sites`, which begin at `start`.
    fn of(sites: &[u32], start: u32, positions: &[DVec3], tolerance: f64) -> Group {
        let first = positions[sites[0] as usize];
        let (low, high) = sites.iter().fold((first, first), |(low, high), &v| {
            let p = positions[v as usize];
            (low.min(p), high.max(p))
        });
        Group {
            start,
            end: start + sites.len() as u32,
            low,
            high,
            tight: sites.len() == 1 || within(low, high, tolerance),
        }
    }

    /// Whether the two groups' boxes lie farther apart than the tolerance,
    /// with room for the rounding of [`within`]: then no site of one lies
    /// within the tolerance of a site of the other. (Each of the gap's
    /// coordinates is at most that of any two sites' difference, rounded
    /// alike; the lengths round within a few units in the last place.)
    pub(super) fn apart(&self, other: &Group, tolerance: f64) -> bool {
        let gap = (other.low - self.high)
            .max(self.low - other.high)
            .max(DVec3::ZERO);
        !within(DVec3::ZERO, gap, tolerance * (1.0 + 16.0 * f64::EPSILON))
    }

    /// Whether every site of one lies within the tolerance of every site
    /// of the other, with room for the rounding of [`within`].
    pub(super) fn all_within(&self, other: &Group, tolerance: f64) -> bool {
        let reach = (other.high - self.low).max(self.high - other.low);
        within(DVec3::ZERO, reach, tolerance * (1.0 - 16.0 * f64::EPSILON))
    }
}

/// Sites of two groups few enough to compare pair by pair.
pub(super) const COMPARED: usize = 1024;

/// The first site of `a`, with the first of `b`, at most the tolerance apart.
pub(super) fn first_close_pair(
    a: &[u32],
    b: &[u32],
    positions: &[DVec3],
    tolerance: f64,
) -> Option<(u32, u32)> {
    a.iter().find_map(|&u| {
        let p = positions[u as usize];
        let v = b
            .iter()
            .find(|&&v| within(p, positions[v as usize], tolerance))?;
        Some((u, *v))
    })
}

/// A site of `a` and one of `b` at most the tolerance apart, when there is
/// one: the pairs of sites near enough, and few enough, compared one by
/// one, the others ruled out or in by their boxes after splitting the
/// larger side's at its median (both are reordered).
pub(super) fn close_pair(
    a: &mut [u32],
    b: &mut [u32],
    positions: &[DVec3],
    tolerance: f64,
) -> Option<(u32, u32)> {
    if a.is_empty() || b.is_empty() {
        return None;
    }
    if a.len() * b.len() <= COMPARED {
        return first_close_pair(a, b, positions, tolerance);
    }
    let (group_a, group_b) = (
        Group::of(a, 0, positions, tolerance),
        Group::of(b, 0, positions, tolerance),
    );
    if group_a.apart(&group_b, tolerance) {
        return None;
    }
    if group_a.all_within(&group_b, tolerance) {
        return Some((a[0], b[0]));
    }
    let (larger, smaller, larger_box, swapped) = match a.len() >= b.len() {
        true => (a, b, group_a, false),
        false => (b, a, group_b, true),
    };
    let extent = larger_box.high - larger_box.low;
    let axis = match (
        extent.x >= extent.y,
        extent.x >= extent.z,
        extent.y >= extent.z,
    ) {
        (true, true, _) => 0,
        (false, _, true) => 1,
        _ => 2,
    };
    let middle = larger.len() / 2;
    larger.select_nth_unstable_by(middle, |&u, &v| {
        positions[u as usize][axis].total_cmp(&positions[v as usize][axis])
    });
    let (low, high) = larger.split_at_mut(middle);
    let found = close_pair(low, smaller, positions, tolerance)
        .or_else(|| close_pair(high, smaller, positions, tolerance))?;
    Some(match swapped {
        false => found,
        true => (found.1, found.0),
    })
}

/// The cells that are not tight, each with its groups; the others are one
/// group each.
pub(super) struct Crowded {
    /// Per cell, whether its sites all lie within the tolerance of each other.
    pub(super) tight: Vec<bool>,
    /// The cells that are not, in order, and their groups.
    cells: Vec<(usize, Vec<Group>)>,
}

impl Crowded {
    /// Finds the cells that are not tight among the cells whose sites are
    /// `sites[cell_starts[k]..cell_starts[k + 1]]`, and splits each into
    /// groups, reordering its sites so that each group's are consecutive.
    pub(super) fn split(
        sites: &mut [u32],
        cell_starts: &[u32],
        positions: &[DVec3],
        tolerance: f64,
    ) -> Crowded {
        const CELLS: usize = 1024;
        let parts: Vec<Crowded> = split_by_offsets(sites, cell_starts, CELLS)
            .into_par_iter()
            .map(|(cells, part)| {
                let base = cell_starts[cells.start];
                let mut tight = Vec::with_capacity(cells.len());
                let mut crowded = Vec::new();
                for k in cells {
                    let (start, end) = (cell_starts[k], cell_starts[k + 1]);
                    let here = &mut part[(start - base) as usize..(end - base) as usize];
                    if here.len() == 1 {
                        tight.push(true);
                        continue;
                    }
                    let group = Group::of(here, start, positions, tolerance);
                    tight.push(group.tight);
                    if !group.tight {
                        let mut groups = Vec::new();
                        split_into_groups(here, group, positions, tolerance, &mut groups);
                        crowded.push((k, groups));
                    }
                }
                Crowded {
                    tight,
                    cells: crowded,
                }
            })
            .collect();
        let mut all = Crowded {
            tight: Vec::with_capacity(cell_starts.len().saturating_sub(1)),
            cells: Vec::new(),
        };
        for part in parts {
            all.tight.extend(part.tight);
            all.cells.extend(part.cells);
        }
        all
    }

    /// The groups of cell `k`, which is not tight.
    pub(super) fn groups(&self, k: usize) -> &[Group] {
        let at = self
            .cells
            .binary_search_by_key(&k, |cell| cell.0)
            .expect("a cell that is not tight has groups");
        &self.cells[at].1
    }
}

/// Splits `sites`, whose group is `group`, into tight groups, appended to
/// `groups`: by the octants of their bounding box, each half as wide, until
/// each is tight. A cell as wide as the tolerance takes one split (an
/// octant's diagonal is under nine tenths of the tolerance).
fn split_into_groups(
    sites: &mut [u32],
    group: Group,
    positions: &[DVec3],
    tolerance: f64,
    groups: &mut Vec<Group>,
) {
    if group.tight {
        groups.push(group);
        return;
    }
    // Halves without overflow near the ends of the range.
    let middle = group.low * 0.5 + group.high * 0.5;
    let octant = |v: &u32| {
        let p = positions[*v as usize];
        usize::from(p.x >= middle.x)
            | usize::from(p.y >= middle.y) << 1
            | usize::from(p.z >= middle.z) << 2
    };
    sites.sort_unstable_by_key(octant);
    let mut first = 0;
    while first < sites.len() {
        let corner = octant(&sites[first]);
        let end = first
            + sites[first..]
                .iter()
                .take_while(|v| octant(v) == corner)
                .count();
        if end - first == sites.len() {
            // No octant smaller: the box's sides are a unit in the last place.
            groups.push(group);
            return;
        }
        let part = &mut sites[first..end];
        let part_group = Group::of(part, group.start + first as u32, positions, tolerance);
        split_into_groups(part, part_group, positions, tolerance, groups);
        first = end;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_random::units;

    /// Sites scattered through a cell as wide as the tolerance split into
    /// tight groups that hold each site once.
    #[test]
    fn groups_are_tight_and_hold_every_site_once() {
        let tolerance = 0.25;
        let mut next = units(0x853c_49e6_748f_ea9bu64);
        let positions: Vec<DVec3> = (0..500)
            .map(|_| DVec3::new(next(), next(), next()) * tolerance + 3.0)
            .collect();
        let mut sites: Vec<u32> = (0..500).collect();
        let mut groups = Vec::new();
        let whole = Group::of(&sites, 7, &positions, tolerance);
        split_into_groups(&mut sites, whole, &positions, tolerance, &mut groups);
        assert!(
            groups.len() > 1 && groups.len() <= 8,
            "{} groups",
            groups.len()
        );
        let mut next_start = 7;
        for group in &groups {
            assert_eq!(group.start, next_start);
            next_start = group.end;
            let members = &sites[(group.start - 7) as usize..(group.end - 7) as usize];
            assert!(group.tight);
            for &a in members {
                for &b in members {
                    assert!(within(
                        positions[a as usize],
                        positions[b as usize],
                        tolerance
                    ));
                }
            }
        }
        assert_eq!(next_start, 507);
        let mut sorted = sites.clone();
        sorted.sort_unstable();
        assert_eq!(sorted, (0..500).collect::<Vec<u32>>());
    }

    /// The close pair is found, or not, as comparing every pair finds it:
    /// two clouds of points whose nearest pair lies just within, at, or
    /// just beyond the tolerance.
    #[test]
    fn close_pair_is_found_when_and_only_when_there_is_one() {
        let mut next = units(0x2b99_2ddf_a232_49d6u64);
        for case in 0..60 {
            let count = [3, 40, 700][case % 3];
            let shift = DVec3::new(1.0 + next(), next() - 0.5, next() - 0.5);
            let mut cloud = |centre: DVec3| -> Vec<DVec3> {
                (0..count)
                    .map(|_| centre + DVec3::new(next(), next(), next()) - 0.5)
                    .collect()
            };
            let positions: Vec<DVec3> = [cloud(DVec3::ZERO), cloud(shift)].concat();
            let (a, b): (Vec<u32>, Vec<u32>) = (
                (0..count as u32).collect(),
                (count as u32..2 * count as u32).collect(),
            );
            let nearest = a
                .iter()
                .flat_map(|&u| b.iter().map(move |&v| (u, v)))
                .map(|(u, v)| positions[u as usize].distance(positions[v as usize]))
                .fold(f64::INFINITY, f64::min);
            for tolerance in [nearest * 0.999, nearest, nearest * 1.001] {
                let any = a.iter().any(|&u| {
                    let p = positions[u as usize];
                    b.iter()
                        .any(|&v| within(p, positions[v as usize], tolerance))
                });
                let (mut a, mut b) = (a.clone(), b.clone());
                match close_pair(&mut a, &mut b, &positions, tolerance) {
                    Some((u, v)) => {
                        assert!(u < count as u32 && v >= count as u32, "case {case}");
                        let (p, q) = (positions[u as usize], positions[v as usize]);
                        assert!(within(p, q, tolerance), "case {case}");
                    }
                    None => assert!(!any, "case {case}: a pair within {tolerance} missed"),
                }
                if tolerance > nearest {
                    assert!(any, "case {case}");
                }
            }
        }
    }

    /// Boxes are apart only when no two of their points are within.
    #[test]
    fn groups_apart_only_beyond_the_tolerance() {
        let group = |low: DVec3, high: DVec3| Group {
            start: 0,
            end: 1,
            low,
            high,
            tight: true,
        };
        let a = group(DVec3::ZERO, DVec3::ONE);
        let just_in = group(DVec3::new(2.0, 0.5, 0.5), DVec3::new(3.0, 1.0, 1.0));
        let just_out = group(DVec3::new(2.0 + 1e-9, 0.5, 0.5), DVec3::new(3.0, 1.0, 1.0));
        let diagonal = group(DVec3::splat(1.0 + 0.6), DVec3::splat(2.0));
        assert!(!a.apart(&just_in, 1.0));
        assert!(a.apart(&just_out, 1.0));
        // The corners are 0.6 × √3 ≈ 1.04 apart.
        assert!(a.apart(&diagonal, 1.0));
        assert!(!a.apart(&diagonal, 1.04));
        assert!(!a.apart(&a, 0.0));
        // The far corners of `a` and `just_in` are √(9 + 2) apart.
        assert!(a.all_within(&just_in, 3.32) && !a.all_within(&just_in, 3.31));
        assert!(!a.all_within(&a, 1.7) && a.all_within(&a, 1.74));
    }
}
