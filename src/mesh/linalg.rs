//! The little linear algebra the geometry needs: best-fit planes and
//! planes-intersection offsets both come down to a symmetric 3×3 eigenproblem.

use glam::{DMat3, DVec3};

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
            if apq.abs() < 1e-300 {
                continue;
            }
            let small = 100.0 * apq.abs();
            if small + a[p][p].abs() == a[p][p].abs() && small + a[q][q].abs() == a[q][q].abs() {
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

    #[test]
    fn eigen_of_best_fit_planes_converges_in_a_few_sweeps() {
        // Covariances of four to six corners, nearly flat in a tilted
        // plane, at scales from 1e-6 to 1e3, as a planarity check meets them.
        let mut state = 0x2545_F491_4F6C_DD1Du64;
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        let tilt = DMat3::from_rotation_y(0.4) * DMat3::from_rotation_x(1.1);
        for i in 0..2000 {
            let scale = [1e-6, 1.0, 1e3][i % 3];
            let corners: Vec<DVec3> = (0..4 + i % 3)
                .map(|_| tilt * DVec3::new(next(), next(), 1e-3 * next()) * scale)
                .collect();
            let centroid = corners.iter().sum::<DVec3>() / corners.len() as f64;
            let m = corners.iter().fold(DMat3::ZERO, |m, &p| {
                let d = p - centroid;
                m + DMat3::from_cols(d * d.x, d * d.y, d * d.z)
            });
            let (values, vectors, sweeps) = jacobi(m);
            assert!(sweeps <= 8, "{sweeps} sweeps for {m:?}");
            for (value, vector) in values.iter().zip(vectors) {
                assert!((m * vector - vector * *value).length() <= 1e-13 * values[2]);
            }
            // The normal: the least spread, along the tilted z.
            assert!(vectors[0].dot(tilt * DVec3::Z).abs() > 0.99);
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
