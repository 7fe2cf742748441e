//! Hidden tiles: which squares of samples a large triangle cannot reach
//! because everything drawn there is nearer, so that a stack of large faces
//! (the pages of a book seen from its spine) costs its visible samples, not
//! every sample of every page.
//!
//! Each tile keeps a bound on the farthest depth drawn in it, and each
//! triangle a bound on the nearest depth it can have over a tile. Both are
//! conservative, so a tile is skipped only when the sample test would have
//! drawn nothing in it: the picture is the same bit for bit.

use crate::buffers::try_vec;
use crate::error::Error;

/// Side of a tile, in samples; a power of two.
pub(super) const TILE: usize = 8;

/// Side of a bin, in samples: large triangles are drawn bin by bin, each
/// bin's nearest first.
pub(super) const BIN: usize = 64;

/// The farthest depth drawn in each tile, refreshed only when asked after a
/// sample in it changed.
pub(super) struct Tiles {
    /// Tiles in a row of the picture.
    across: usize,
    /// An upper bound on the depth bits of every sample in each tile.
    farthest: Vec<u32>,
    /// Whether a sample of the tile was drawn since `farthest` was found.
    changed: Vec<bool>,
}

/// Tiles of a bin.
const BIN_TILES: usize = BIN / TILE;

/// Which tiles of one bin a triangle may draw in.
pub(super) struct OpenTiles {
    /// The first tile's column and row.
    origin: (usize, usize),
    open: [[bool; BIN_TILES]; BIN_TILES],
    open_row: [bool; BIN_TILES],
    open_column: [bool; BIN_TILES],
}

impl OpenTiles {
    /// Whether the tile of sample (`x`, `y`) is open.
    #[inline]
    pub(super) fn at(&self, x: usize, y: usize) -> bool {
        self.open[y / TILE - self.origin.1][x / TILE - self.origin.0]
    }

    /// Whether any tile on the row (or, `down_columns`, the column) of
    /// samples `line` is open.
    #[inline]
    pub(super) fn line(&self, line: usize, down_columns: bool) -> bool {
        match down_columns {
            false => self.open_row[line / TILE - self.origin.1],
            true => self.open_column[line / TILE - self.origin.0],
        }
    }
}

impl Tiles {
    /// Tiles over a picture of `w` × `h` samples with nothing drawn.
    pub(super) fn new(w: usize, h: usize) -> Result<Tiles, Error> {
        let (across, down) = (w.div_ceil(TILE), h.div_ceil(TILE));
        let mut farthest = try_vec(across * down, "the depth tiles")?;
        farthest.resize(across * down, u32::MAX);
        let mut changed = try_vec(across * down, "the depth tiles")?;
        changed.resize(across * down, false);
        Ok(Tiles {
            across,
            farthest,
            changed,
        })
    }

    /// Notes that the sample at column `x`, row `y` was drawn.
    #[inline]
    pub(super) fn mark(&mut self, x: usize, y: usize) {
        self.changed[(y / TILE) * self.across + x / TILE] = true;
    }

    /// The tiles of the `columns` and `rows` (inclusive, within one bin)
    /// where a triangle whose depth is at least `nearest` may draw, or
    /// `None` when everything drawn there is nearer.
    pub(super) fn open(
        &mut self,
        nearest: &NearestDepth,
        keys: &[u64],
        w: usize,
        (columns, rows): ([usize; 2], [usize; 2]),
    ) -> Option<OpenTiles> {
        debug_assert!(columns[0] / BIN == columns[1] / BIN && rows[0] / BIN == rows[1] / BIN);
        let mut tiles = OpenTiles {
            origin: (columns[0] / TILE, rows[0] / TILE),
            open: [[false; BIN_TILES]; BIN_TILES],
            open_row: [false; BIN_TILES],
            open_column: [false; BIN_TILES],
        };
        let mut any = false;
        for ty in rows[0] / TILE..=rows[1] / TILE {
            for tx in columns[0] / TILE..=columns[1] / TILE {
                let tile = ty * self.across + tx;
                let xs = [
                    (tx * TILE).max(columns[0]),
                    (tx * TILE + TILE - 1).min(columns[1]),
                ];
                let ys = [
                    (ty * TILE).max(rows[0]),
                    (ty * TILE + TILE - 1).min(rows[1]),
                ];
                let near = nearest.over(xs, ys);
                let mut hidden = near > self.farthest[tile];
                if !hidden && self.changed[tile] {
                    self.changed[tile] = false;
                    let x1 = (tx * TILE + TILE).min(w);
                    self.farthest[tile] = (ty * TILE..ty * TILE + TILE)
                        .map_while(|y| keys.get(y * w + tx * TILE..y * w + x1))
                        .flatten()
                        .map(|&key| (key >> 32) as u32)
                        .max()
                        .unwrap_or(u32::MAX);
                    hidden = near > self.farthest[tile];
                }
                if !hidden {
                    let (i, j) = (ty - tiles.origin.1, tx - tiles.origin.0);
                    tiles.open[i][j] = true;
                    tiles.open_row[i] = true;
                    tiles.open_column[j] = true;
                    any = true;
                }
            }
        }
        any.then_some(tiles)
    }
}

/// A lower bound on the depth a triangle's sample test can give, as the
/// bits of the `f32` it is stored as (positive floats order as their bits).
#[derive(Debug, Clone, Copy)]
pub(super) struct NearestDepth {
    /// The inverse depth, affine in the picture: its value at the first
    /// corner and its rise per sample across and down.
    at: (f64, f64),
    inverse: f64,
    rise: (f64, f64),
    /// How far the sample test's inverse depth may lie above this plane's:
    /// the barycentric weights' and the plane's rounding, with a wide margin.
    slack: f64,
}

impl NearestDepth {
    /// The bound for the triangle `corners` (screen x, y and depth), whose
    /// doubled signed area is `area`; `None` when its depths are not all
    /// positive and finite or its rounding is too wide to bound anything.
    pub(super) fn of(corners: [(f64, f64, f64); 3], area: f64) -> Option<NearestDepth> {
        let inverse = corners.map(|c| 1.0 / c.2);
        let good = |d: f64| d.is_finite() && d > 0.0;
        if !corners.iter().all(|c| good(c.2)) || !inverse.into_iter().all(good) {
            return None;
        }
        if !area.is_finite() || area == 0.0 {
            return None;
        }
        let [a, b, c] = corners;
        // The weight of each corner rises across by the other two's
        // difference in y over the area, and down by their difference in x.
        let rise = (
            ((b.1 - c.1) * inverse[0] + (c.1 - a.1) * inverse[1] + (a.1 - b.1) * inverse[2]) / area,
            ((c.0 - b.0) * inverse[0] + (a.0 - c.0) * inverse[1] + (b.0 - a.0) * inverse[2]) / area,
        );
        let (low, high) = super::screen_box(&corners);
        // The weights' products span at most the box and a bin beside it,
        // and a weight there is at most that over the area; the area's own
        // rounding scales the weight.
        let margin = 2.0 * BIN as f64;
        let reach = (high.0 - low.0 + margin) * (high.1 - low.1 + margin);
        let ratio = reach / area.abs() + 1.0;
        let largest = inverse.into_iter().fold(0.0, f64::max);
        let slack = largest * (4096.0 * f64::EPSILON * (ratio + ratio * ratio) + 1e-9);
        if !(rise.0.is_finite() && rise.1.is_finite() && slack < 0.5 * largest) {
            return None;
        }
        Some(NearestDepth {
            at: (a.0, a.1),
            inverse: inverse[0],
            rise,
            slack,
        })
    }

    /// A lower bound on the stored depth bits of any sample centre in the
    /// columns and rows given (inclusive, within a bin of the triangle's
    /// box) that the triangle covers.
    pub(super) fn over(&self, columns: [usize; 2], rows: [usize; 2]) -> u32 {
        let inverse = self.largest_inverse(columns, rows);
        if !(inverse > 0.0 && inverse.is_finite()) {
            return 0;
        }
        // `as f32` rounds to nearest, which keeps order: a depth at least
        // this one is stored as at least its bits.
        let depth = (1.0 / inverse) * (1.0 - 1e-12);
        (depth as f32).to_bits()
    }

    /// An upper bound on the inverse depth the sample test works out at any
    /// centre in the columns and rows given that the triangle covers.
    fn largest_inverse(&self, [x0, x1]: [usize; 2], [y0, y1]: [usize; 2]) -> f64 {
        // The inverse depth is affine, so over the box of centres it is
        // largest at the corner its rise points to.
        let px = if self.rise.0 > 0.0 { x1 } else { x0 } as f64 + 0.5;
        let py = if self.rise.1 > 0.0 { y1 } else { y0 } as f64 + 0.5;
        let most = self.inverse + self.rise.0 * (px - self.at.0) + self.rise.1 * (py - self.at.1);
        most + self.slack
    }
}

#[cfg(test)]
mod tests {
    use super::super::{depth_key, doubled_area, sample_depth};
    use super::*;
    use crate::test_random::units;

    /// Every sample a triangle covers in a box within one bin is stored at
    /// least as deep as the bound over the box, and the bound is close: on
    /// triangles from broad to long and thin, with depths from near equal to
    /// a thousand apart, over whole bins, tiles and single samples.
    #[test]
    fn no_sample_is_nearer_than_the_bound_over_its_box() {
        let mut next = units(0x51a7_e5ee_d0f0_0d01);
        let (mut samples, mut tight) = (0, 0);
        for case in 0..6_000 {
            let depth = |next: &mut dyn FnMut() -> f64| match case % 3 {
                0 => 5.0 + 1e-7 * next(),
                1 => 1.0 + 3.0 * next(),
                _ => 0.5 + 1000.0 * next() * next(),
            };
            let stretch = [1.0, 4.0, 30.0][(case / 3) % 3];
            let (cx, cy) = (40.0 + 150.0 * next(), 40.0 + 150.0 * next());
            let (y, x) = (next() * std::f64::consts::TAU).sin_cos();
            let triangle: [(f64, f64, f64); 3] = std::array::from_fn(|_| {
                let (u, v) = (next() - 0.5, (next() - 0.5) / stretch);
                let size = 120.0;
                let z = depth(&mut next);
                (cx + size * (u * x - v * y), cy + size * (u * y + v * x), z)
            });
            let area = doubled_area(triangle);
            let Some(nearest) = NearestDepth::of(triangle, area) else {
                continue;
            };
            let inverse_depth = triangle.map(|c| 1.0 / c.2);
            let bin = ((cx as usize) / BIN * BIN, (cy as usize) / BIN * BIN);
            let side = [BIN, TILE, 1][case % 3];
            let (x0, y0) = (
                bin.0 + (next() * (BIN - side + 1) as f64) as usize,
                bin.1 + (next() * (BIN - side + 1) as f64) as usize,
            );
            let (columns, rows) = ([x0, x0 + side - 1], [y0, y0 + side - 1]);
            let (bound, largest) = (
                nearest.over(columns, rows),
                nearest.largest_inverse(columns, rows),
            );
            let mut most = 0.0f64;
            for y in rows[0]..=rows[1] {
                for x in columns[0]..=columns[1] {
                    let centre = (x as f64 + 0.5, y as f64 + 0.5);
                    if let Some((w, z)) = sample_depth(triangle, area, inverse_depth, centre) {
                        // The sum the test takes the inverse of, bit for bit.
                        let inverse = w[0] * inverse_depth[0]
                            + w[1] * inverse_depth[1]
                            + w[2] * inverse_depth[2];
                        assert!(inverse <= largest, "case {case}: {triangle:?} at {x}, {y}");
                        let stored = (depth_key(z, 0).unwrap() >> 32) as u32;
                        assert!(stored >= bound, "case {case}: {triangle:?} at {x}, {y}");
                        most = most.max(inverse);
                        samples += 1;
                    }
                }
            }
            // Within a millionth of the largest sample over a box it fills.
            if most > 0.0 && largest / most - 1.0 < 1e-6 {
                tight += 1;
            }
        }
        assert!(samples > 300_000, "{samples} samples");
        assert!(tight > 1_000, "{tight} tight bounds");
    }

    /// A tile is hidden from a triangle behind everything drawn in it, and
    /// open to one that may be nearer, or when drawing there changed.
    #[test]
    fn tiles_hide_what_lies_behind_what_was_drawn() {
        let (w, h) = (100, 70);
        let mut tiles = Tiles::new(w, h).unwrap();
        let mut keys = vec![u64::MAX; w * h];
        let flat = |z: f64| {
            let corners = [(-50.0, -50.0, z), (400.0, -50.0, z), (-50.0, 400.0, z)];
            NearestDepth::of(corners, doubled_area(corners)).unwrap()
        };
        // The bin from (64, 64): only its first 36 columns and 6 rows lie in
        // the picture.
        let bin = ([64, 99], [64, 69]);
        let first_bin = ([0, 63], [0, 63]);
        assert!(tiles.open(&flat(3.0), &keys, w, bin).is_some());
        // Everything at depth 2 in the first bin's tiles but one sample.
        for y in 0..64 {
            for x in 0..64 {
                if (x, y) != (13, 21) {
                    keys[y * w + x] = depth_key(2.0, 5).unwrap();
                    tiles.mark(x, y);
                }
            }
        }
        let open = tiles.open(&flat(3.0), &keys, w, first_bin).unwrap();
        for y in 0..64 {
            for x in 0..64 {
                assert_eq!(open.at(x, y), (x / 8, y / 8) == (1, 2), "{x}, {y}");
            }
            assert_eq!(open.line(y, false), y / 8 == 2);
            assert_eq!(open.line(y, true), y / 8 == 1);
        }
        // Nearer: every tile open.
        let open = tiles.open(&flat(1.5), &keys, w, first_bin).unwrap();
        assert!((0..64).all(|x| open.at(x, x)));
        // Drawn at the missing sample: all hidden.
        keys[21 * w + 13] = depth_key(2.5, 9).unwrap();
        tiles.mark(13, 21);
        assert!(tiles.open(&flat(3.0), &keys, w, first_bin).is_none());
        // Equally deep: open, since a triangle drawn earlier in order wins.
        assert!(tiles
            .open(&flat(2.5), &keys, w, ([8, 15], [16, 23]))
            .is_some());
    }
}
