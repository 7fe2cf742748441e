//! The little linear algebra the geometry needs: best-fit planes and
//! planes-intersection offsets both come down to a symmetric 3×3 eigenproblem.

use glam::{DMat3, DVec3};

/// Eigenvalues (ascending) and unit eigenvectors of a symmetric 3×3 matrix,
/// by cyclic Jacobi rotations (exact enough and never fails to converge).
#[allow(clippy::needless_range_loop)] // indices mirror the rotation formulas
pub(crate) fn symmetric_eigen(m: DMat3) -> ([f64; 3], [DVec3; 3]) {
    let mut a = m.to_cols_array_2d(); // a[col][row]; symmetric, so either way
    let mut v = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    for _ in 0..50 {
        let off = a[0][1].abs() + a[0][2].abs() + a[1][2].abs();
        if off < 1e-300 {
            break;
        }
        for (p, q) in [(0, 1), (0, 2), (1, 2)] {
            if a[p][q].abs() < 1e-300 {
                continue;
            }
            let theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
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
    (values, vectors)
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
    fn eigen_of_a_diagonal_matrix_is_exact() {
        let m = DMat3::from_diagonal(DVec3::new(3.0, 0.5, 2.0));
        let (values, vectors) = symmetric_eigen(m);
        assert_eq!(values, [0.5, 2.0, 3.0]);
        assert_eq!(vectors[0].abs(), DVec3::Y);
    }
}
