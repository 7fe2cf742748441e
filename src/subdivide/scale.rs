//! Subdivision near the top of the `f64` range. Every rule is an affine
//! combination of points (and a limit tangent a linear one), so it commutes
//! with scaling by a power of two, which is exact. Input whose largest
//! magnitude passes [`SAFE_MAGNITUDE`] is scaled down before the rules run
//! and the result scaled back: the sums inside the rules cannot overflow,
//! and only a result that itself lies beyond the `f64` range is refused.
//! Ordinary input is never scaled, so its arithmetic stays exactly as it was.

use glam::DVec3;

use crate::error::{Error, Result};

/// 2^960 (about 9.7e288): a face may have 2^31 corners and a rule sums them with weights of
/// at most a few units, so intermediate sums of points below this stay well
/// under `f64::MAX` (about 2^1024).
pub(crate) const SAFE_MAGNITUDE: f64 = f64::from_bits((1023 + 960) << 52);

/// Exactly 2^k, for k in the normal range.
fn power_of_two(k: i32) -> f64 {
    debug_assert!((-1022..=1023).contains(&k));
    f64::from_bits(((1023 + k) as u64) << 52)
}

/// The factor that scales `largest` (a finite magnitude) to at most
/// [`SAFE_MAGNITUDE`], or `None` when no scaling is needed.
fn factor_for(largest: f64) -> Option<Scale> {
    if largest.is_nan() || largest <= SAFE_MAGNITUDE {
        return None;
    }
    // A finite value above 2^960 has a biased exponent of 1983 to 2046.
    let exponent = ((largest.to_bits() >> 52) & 0x7ff) as i32 - 1023;
    let k = exponent.min(1023) - 959;
    Some(Scale {
        down: power_of_two(-k),
        up: power_of_two(k),
    })
}

/// A pair of exact powers of two, inverse to each other.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Scale {
    pub(crate) down: f64,
    pub(crate) up: f64,
}

/// The scale for points whose largest coordinate magnitude passes
/// [`SAFE_MAGNITUDE`]; `None` for ordinary points.
pub(crate) fn for_points(points: &[DVec3]) -> Option<Scale> {
    let largest = points
        .iter()
        .map(|p| p.abs().max_element())
        .fold(0.0, f64::max);
    factor_for(largest)
}

/// As [`for_points`], for flat values.
pub(crate) fn for_values(values: &[f64]) -> Option<Scale> {
    factor_for(values.iter().map(|v| v.abs()).fold(0.0, f64::max))
}

/// `points` scaled down.
pub(crate) fn scaled_points(points: &[DVec3], scale: Scale) -> Vec<DVec3> {
    points.iter().map(|&p| p * scale.down).collect()
}

/// Scales `points` back up in place; a point that lands beyond the `f64`
/// range is refused, naming it.
///
/// # Errors
/// [`Error::DegenerateInput`] naming the first such vertex and `what` made it.
pub(crate) fn restore_points(points: &mut [DVec3], scale: Scale, what: &str) -> Result<()> {
    for (v, p) in points.iter_mut().enumerate() {
        let scaled = *p * scale.up;
        if !scaled.is_finite() {
            return Err(beyond_range(what, "refined vertex", v));
        }
        *p = scaled;
    }
    Ok(())
}

/// Scales `values` back up in place, `width` numbers per `item` (a refined
/// vertex or face corner).
///
/// # Errors
/// As [`restore_points`].
pub(crate) fn restore_values(
    values: &mut [f64],
    width: usize,
    scale: Scale,
    what: &str,
    item: &str,
) -> Result<()> {
    for (i, x) in values.iter_mut().enumerate() {
        let scaled = *x * scale.up;
        if !scaled.is_finite() {
            return Err(beyond_range(what, item, i / width.max(1)));
        }
        *x = scaled;
    }
    Ok(())
}

fn beyond_range(what: &str, item: &str, index: usize) -> Error {
    Error::DegenerateInput(format!(
        "{what} of {item} {index} lies beyond the largest double; \
         the input spans too much of the f64 range"
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ordinary_magnitudes_are_not_scaled() {
        assert_eq!(for_values(&[1.0, -1e288, 9e288]), None);
        assert_eq!(for_values(&[SAFE_MAGNITUDE]), None);
        assert_eq!(for_points(&[DVec3::new(0.0, -1e250, 3.0)]), None);
    }

    #[test]
    fn large_magnitudes_scale_below_the_bound_exactly() {
        for largest in [1e290, 1e300, 1e306, f64::MAX, -f64::MAX] {
            let scale = for_values(&[1.0, largest]).unwrap();
            assert_eq!(scale.down * scale.up, 1.0);
            let scaled = largest * scale.down;
            assert!(scaled.abs() <= SAFE_MAGNITUDE, "{largest}");
            assert!(scaled.abs() > SAFE_MAGNITUDE / 2.0, "{largest}");
            assert_eq!(scaled * scale.up, largest);
        }
    }

    #[test]
    fn a_result_beyond_the_range_names_its_vertex() {
        let scale = for_values(&[f64::MAX]).unwrap();
        let mut points = [DVec3::ONE, DVec3::new(0.0, SAFE_MAGNITUDE * 4.0, 0.0)];
        let error = restore_points(&mut points, scale, "the position").unwrap_err();
        assert!(error.to_string().contains("refined vertex 1"), "{error}");
    }
}
