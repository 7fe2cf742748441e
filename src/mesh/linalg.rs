//! The little linear algebra the geometry needs: best-fit planes and
//! planes-intersection offsets both come down to a symmetric 3×3 eigenproblem.

use glam::{DMat3, DVec3};

/// The scatter of `points` about `centre` (the sum of each offset's outer
/// product with itself), in the points' order: the matrix whose least
/// eigenvector is their best-fit plane's normal.
pub(crate) fn covariance(points: &[DVec3], centre: DVec3) -> DMat3 {
    points.iter().fold(DMat3::ZERO, |m, &p| {
        let d = p - centre;
        m + DMat3::from_cols(d * d.x, d * d.y, d * d.z)
    })
}

/// Eigenvalues (ascending) and unit eigenvectors of a symmetric 3×3 matrix,
/// by cyclic Jacobi rotations (exact enough and never fails to converge).
///
/// Each rotation zeroes its entry outright, and an entry too small to
/// change either diagonal entry it sits between is zeroed without one:
/// left to the rotations' round-off, entries stall near 1e-16 of the
/// diagonal and the sweeps run to their cap.
pub(crate) fn symmetric_eigen(m: DMat3) -> ([f64; 3], [DVec3; 3]) {
    let (values, vectors, _) = jacobi(m);
    (values, vectors)
}

/// The unit eigenvector of the smallest eigenvalue of a symmetric 3×3
/// matrix: the normal of a best-fit plane. Worked out directly (the
/// eigenvalues by the trigonometric formula for a cubic's three real
/// roots, the vector as the longest cross product of two rows of the
/// matrix less that eigenvalue), and by [`symmetric_eigen`] where the two
/// least eigenvalues lie within a hundredth of the spread of all three,
/// where the cross products lose the digits the rotations keep.
pub(crate) fn least_spread_direction(m: DMat3) -> DVec3 {
    if nearly_diagonal(m) {
        // A face in an axis plane: the rotations have nothing to turn, and
        // give the axis of the least diagonal entry (the first of equals).
        let diagonal = [m.x_axis.x, m.y_axis.y, m.z_axis.z];
        let least = (0..3).min_by(|&i, &j| diagonal[i].total_cmp(&diagonal[j]));
        return DVec3::AXES[least.unwrap_or(2)];
    }
    direct_least_spread(m).unwrap_or_else(|| symmetric_eigen(m).1[0])
}

/// Whether every entry above the diagonal is too small to change either
/// diagonal entry it sits between: [`symmetric_eigen`] zeroes them all
/// without a rotation.
fn nearly_diagonal(m: DMat3) -> bool {
    let a = m.to_cols_array_2d();
    [(0, 1), (0, 2), (1, 2)]
        .into_iter()
        .all(|(p, q)| negligible(a[p][q], a[p][p], a[q][q]))
}

/// Whether `apq` is too small to change `app` or `aqq`, or too small to
/// rotate at all.
#[inline]
fn negligible(apq: f64, app: f64, aqq: f64) -> bool {
    let small = 100.0 * apq.abs();
    apq.abs() < 1e-300 || small + app.abs() == app.abs() && small + aqq.abs() == aqq.abs()
}

/// [`least_spread_direction`] without the rotations: `None` for a zero or
/// non-finite matrix, and where the two smallest eigenvalues lie too close.
fn direct_least_spread(m: DMat3) -> Option<DVec3> {
    let a = m.to_cols_array_2d();
    // Scaled to entries of at most 1: squares and cubes neither overflow
    // nor underflow.
    let entry_scale = a.iter().flatten().fold(0.0f64, |l, x| l.max(x.abs()));
    if !(entry_scale > 0.0 && entry_scale.is_finite()) {
        return None;
    }
    let k = 1.0 / entry_scale;
    let [a00, a01, a02, a11, a12, a22] =
        [a[0][0], a[0][1], a[0][2], a[1][1], a[1][2], a[2][2]].map(|x| x * k);
    // The eigenvalues are q + 2p cos(φ + 2πj/3) (j = 0, 1, 2), with B = (A − qI)/p.
    let q = (a00 + a11 + a22) / 3.0;
    let (b00, b11, b22) = (a00 - q, a11 - q, a22 - q);
    let p = ((b00 * b00 + b11 * b11 + b22 * b22 + 2.0 * (a01 * a01 + a02 * a02 + a12 * a12)) / 6.0)
        .sqrt();
    if p == 0.0 {
        return None;
    }
    let det = b00 * (b11 * b22 - a12 * a12) - a01 * (a01 * b22 - a12 * a02)
        + a02 * (a01 * a12 - b11 * a02);
    let phi = (det / (2.0 * p * p * p)).clamp(-1.0, 1.0).acos() / 3.0;
    let largest = q + 2.0 * p * phi.cos();
    let smallest = q + 2.0 * p * (phi + 2.0 * std::f64::consts::FRAC_PI_3).cos();
    let middle = 3.0 * q - largest - smallest;
    if middle - smallest < 1e-2 * (largest - smallest) || smallest.is_nan() {
        return None;
    }
    let rows = [
        DVec3::new(a00 - smallest, a01, a02),
        DVec3::new(a01, a11 - smallest, a12),
        DVec3::new(a02, a12, a22 - smallest),
    ];
    let crosses = [
        rows[0].cross(rows[1]),
        rows[0].cross(rows[2]),
        rows[1].cross(rows[2]),
    ];
    let longest = crosses
        .into_iter()
        .max_by(|x, y| x.length_squared().total_cmp(&y.length_squared()))?;
    longest.try_normalize()
}

/// [`symmetric_eigen`], and how many sweeps it took.
#[allow(clippy::needless_range_loop)] // indices mirror the rotation formulas
fn jacobi(m: DMat3) -> ([f64; 3], [DVec3; 3], usize) {
    let mut a = m.to_cols_array_2d(); // a[col][row]; symmetric, so either way
    let mut v = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    let mut sweeps = 0;
    while sweeps < 50 {
        let off = a[0][1].abs() + a[0][2].abs() + a[1][2].abs();
        if off < 1e-300 {
            break;
        }
        sweeps += 1;
        for (p, q) in [(0, 1), (0, 2), (1, 2)] {
            let apq = a[p][q];
            if negligible(apq, a[p][p], a[q][q]) {
                a[p][q] = 0.0;
                a[q][p] = 0.0;
                continue;
            }
            let theta = (a[q][q] - a[p][p]) / (2.0 * apq);
            let t = theta.signum() / (theta.abs() + (theta * theta + 1.0).sqrt());
            let t = if theta == 0.0 { 1.0 } else { t };
            let c = 1.0 / (t * t + 1.0).sqrt();
            let s = t * c;
            for k in 0..3 {
                let (akp, akq) = (a[k][p], a[k][q]);
                a[k][p] = c * akp - s * akq;
                a[k][q] = s * akp + c * akq;
            }
            for k in 0..3 {
                let (apk, aqk) = (a[p][k], a[q][k]);
                a[p][k] = c * apk - s * aqk;
                a[q][k] = s * apk + c * aqk;
            }
            a[p][q] = 0.0;
            a[q][p] = 0.0;
            for row in &mut v {
                let (vp, vq) = (row[p], row[q]);
                row[p] = c * vp - s * vq;
                row[q] = s * vp + c * vq;
            }
        }
    }
    let mut order = [0usize, 1, 2];
    order.sort_by(|&i, &j| a[i][i].total_cmp(&a[j][j]));
    let values = order.map(|i| a[i][i]);
    let vectors = order.map(|i| DVec3::new(v[0][i], v[1][i], v[2][i]));
    (values, vectors, sweeps)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn eigen_of_a_rotated_diagonal_matrix() {
        let r = DMat3::from_rotation_y(0.3) * DMat3::from_rotation_x(0.7);
        let m = r * DMat3::from_diagonal(DVec3::new(3.0, 1.0, 2.0)) * r.transpose();
        let (values, vectors) = symmetric_eigen(m);
        for (value, expected) in values.iter().zip([1.0, 2.0, 3.0]) {
            assert!((value - expected).abs() < 1e-12);
        }
        for (value, vector) in values.iter().zip(vectors) {
            assert!((m * vector - vector * *value).length() < 1e-12);
        }
    }

    proptest::proptest! {
        #[test]
        fn eigen_of_best_fit_planes_converges_in_a_few_sweeps(
            corners in proptest::collection::vec((0.0..1.0f64, 0.0..1.0f64, 0.0..1e-3f64), 4..7),
            scale in proptest::sample::select(vec![1e-6, 1.0, 1e3]),
        ) {
            // Four to six corners nearly flat in a tilted plane, as a
            // planarity check meets them.
            let tilt = DMat3::from_rotation_y(0.4) * DMat3::from_rotation_x(1.1);
            let corners: Vec<DVec3> = corners
                .into_iter()
                .map(|(x, y, z)| tilt * DVec3::new(x, y, z) * scale)
                .collect();
            let centroid = corners.iter().sum::<DVec3>() / corners.len() as f64;
            let m = covariance(&corners, centroid);
            let (values, vectors, sweeps) = jacobi(m);
            proptest::prop_assert!(sweeps <= 8, "{} sweeps", sweeps);
            for (value, vector) in values.iter().zip(vectors) {
                proptest::prop_assert!((m * vector - vector * *value).length() <= 1e-13 * values[2]);
            }
        }

        #[test]
        fn least_spread_direction_is_the_rotations_smallest_eigenvector(
            angles in (0.0..6.3f64, 0.0..6.3f64, 0.0..6.3f64),
            (first, second, least) in (0.0..1.0f64, 0.0..1.0f64, 0.0..1.0f64),
            flatness in proptest::sample::select(vec![0.0, 1e-9, 1e-3, 0.3]),
            close in proptest::bool::weighted(0.2),
            scale in proptest::sample::select(vec![1e-200, 1e-6, 1.0, 1e200]),
        ) {
            let least = flatness * least;
            // With `close`, the two least spreads within a thousandth.
            let second = if close { least + 1e-3 * second * first } else { second };
            let r = DMat3::from_rotation_z(angles.0)
                * DMat3::from_rotation_y(angles.1)
                * DMat3::from_rotation_x(angles.2);
            let m = r * DMat3::from_diagonal(DVec3::new(first, second, least) * scale) * r.transpose();
            let normal = least_spread_direction(m);
            let (values, vectors) = symmetric_eigen(m);
            proptest::prop_assert!((normal.length() - 1.0).abs() < 1e-14);
            if direct_least_spread(m).is_some() {
                // Close to the rotations' vector, as far as the gap to the
                // next eigenvalue allows.
                let along = normal * normal.dot(vectors[0]).signum();
                let gap = values[2] / (values[1] - values[0]);
                proptest::prop_assert!((along - vectors[0]).length() <= 1e-14 * (1.0 + gap));
                proptest::prop_assert!(
                    (m * (normal / values[2])).length()
                        <= values[0].abs() / values[2] + 2e-14 * (1.0 + gap)
                );
            } else {
                proptest::prop_assert_eq!(normal, vectors[0]);
            }
        }
    }

    #[test]
    fn least_spread_is_direct_where_the_spreads_are_apart() {
        let r = DMat3::from_rotation_z(0.3) * DMat3::from_rotation_x(1.2);
        let turned = |d: DVec3| r * DMat3::from_diagonal(d) * r.transpose();
        assert!(direct_least_spread(turned(DVec3::new(1.0, 0.5, 0.0))).is_some());
        assert!(direct_least_spread(turned(DVec3::new(1.0, 0.02, 0.01))).is_some());
        // The two least within a hundredth of the spread: the rotations.
        assert!(direct_least_spread(turned(DVec3::new(1.0, 0.009, 0.0))).is_none());
        assert!(direct_least_spread(turned(DVec3::ONE)).is_none());
        let line = DMat3::from_cols(DVec3::X, DVec3::ZERO, DVec3::ZERO);
        assert!(direct_least_spread(line).is_none());
        assert!(direct_least_spread(DMat3::ZERO).is_none());
        // Already diagonal (a face in an axis plane), no spread (a single
        // point): the rotations' answer, which makes no rotation.
        assert_eq!(
            least_spread_direction(DMat3::ZERO),
            symmetric_eigen(DMat3::ZERO).1[0]
        );
        let flat = DMat3::from_diagonal(DVec3::new(2.0, 1.0, 0.0));
        assert_eq!(least_spread_direction(flat), DVec3::Z);
        for diagonal in [
            DVec3::new(0.0, 1.0, 0.0),
            DVec3::ONE,
            DVec3::new(3.0, 1.0, 2.0),
        ] {
            let mut m = DMat3::from_diagonal(diagonal);
            assert_eq!(least_spread_direction(m), symmetric_eigen(m).1[0]);
            // Entries too small to turn anything.
            m.x_axis.y = 1e-30;
            m.y_axis.x = 1e-30;
            assert_eq!(least_spread_direction(m), symmetric_eigen(m).1[0]);
        }
    }

    #[test]
    fn eigen_of_a_diagonal_matrix_is_exact() {
        let m = DMat3::from_diagonal(DVec3::new(3.0, 0.5, 2.0));
        let (values, vectors) = symmetric_eigen(m);
        assert_eq!(values, [0.5, 2.0, 3.0]);
        assert_eq!(vectors[0].abs(), DVec3::Y);
    }
}
