//! The basis functions of the regular patches: the uniform bicubic
//! B-spline of Catmull-Clark (16 control points) and the quartic box spline
//! of Loop (12 control points; Stam, "Evaluation of Loop Subdivision
//! Surfaces", 1998), with their first derivatives.

/// Weights of the cubic B-spline segment over `[0, 1]` and their
/// derivatives, for the four control points in order.
#[inline]
fn cubic(t: f64) -> ([f64; 4], [f64; 4]) {
    let s = 1.0 - t;
    let t2 = t * t;
    let t3 = t2 * t;
    let w = [
        s * s * s / 6.0,
        (3.0 * t3 - 6.0 * t2 + 4.0) / 6.0,
        (-3.0 * t3 + 3.0 * t2 + 3.0 * t + 1.0) / 6.0,
        t3 / 6.0,
    ];
    let d = [
        -0.5 * s * s,
        0.5 * (3.0 * t2 - 4.0 * t),
        0.5 * (-3.0 * t2 + 2.0 * t + 1.0),
        0.5 * t2,
    ];
    (w, d)
}

/// Weights of the 16 points of a bicubic patch (row `r` of the grid runs
/// along u at the r-th v, so point `4 r + c` has u-index c) for the
/// position, the u and the v derivative at `(u, v)`.
pub(super) fn bicubic(u: f64, v: f64) -> [[f64; 16]; 3] {
    let (wu, du) = cubic(u);
    let (wv, dv) = cubic(v);
    let mut out = [[0.0; 16]; 3];
    for r in 0..4 {
        for c in 0..4 {
            out[0][4 * r + c] = wu[c] * wv[r];
            out[1][4 * r + c] = du[c] * wv[r];
            out[2][4 * r + c] = wu[c] * dv[r];
        }
    }
    out
}

/// The box spline's coefficients on the 15 monomials
/// `1, s, t, s², st, t², s³, s²t, st², t³, s⁴, s³t, s²t², st³, t⁴`, times 12,
/// for the 12 points in OpenSubdiv's order (rows of 3, 4, 3 and 2 points
/// from the side opposite corner 2; the triangle is points 4, 5 and 8).
const BOX: [[f64; 15]; 12] = [
    [
        1., -2., -4., 0., 6., 6., 2., 0., -6., -4., -1., -2., 0., 2., 1.,
    ],
    [
        1., 2., -2., 0., -6., 0., -4., 0., 6., 2., 2., 4., 0., -2., -1.,
    ],
    [0., 0., 0., 0., 0., 0., 2., 0., 0., 0., -1., -2., 0., 0., 0.],
    [
        1., -4., -2., 6., 6., 0., -4., -6., 0., 2., 1., 2., 0., -2., -1.,
    ],
    [
        6., 0., 0., -12., -12., -12., 8., 12., 12., 8., -1., -2., 0., -2., -1.,
    ],
    [
        1., 4., 2., 6., 6., 0., -4., -6., -12., -4., -1., -2., 0., 4., 2.,
    ],
    [0., 0., 0., 0., 0., 0., 0., 0., 0., 0., 1., 2., 0., 0., 0.],
    [
        1., -2., 2., 0., -6., 0., 2., 6., 0., -4., -1., -2., 0., 4., 2.,
    ],
    [
        1., 2., 4., 0., 6., 6., -4., -12., -6., -4., 2., 4., 0., -2., -1.,
    ],
    [
        0., 0., 0., 0., 0., 0., 2., 6., 6., 2., -1., -2., 0., -2., -1.,
    ],
    [0., 0., 0., 0., 0., 0., 0., 0., 0., 2., 0., 0., 0., -2., -1.],
    [0., 0., 0., 0., 0., 0., 0., 0., 0., 0., 0., 0., 0., 2., 1.],
];

/// Weights of the 12 points of a box-spline patch for the position, the s
/// and the t derivative at `(s, t)` (barycentric: corner 0 at (0, 0)).
pub(super) fn box_spline(s: f64, t: f64) -> [[f64; 12]; 3] {
    let (s2, t2) = (s * s, t * t);
    let monomials = [
        1.0,
        s,
        t,
        s2,
        s * t,
        t2,
        s2 * s,
        s2 * t,
        s * t2,
        t2 * t,
        s2 * s2,
        s2 * s * t,
        s2 * t2,
        s * t2 * t,
        t2 * t2,
    ];
    let by_s = [
        0.0,
        1.0,
        0.0,
        2.0 * s,
        t,
        0.0,
        3.0 * s2,
        2.0 * s * t,
        t2,
        0.0,
        4.0 * s2 * s,
        3.0 * s2 * t,
        2.0 * s * t2,
        t2 * t,
        0.0,
    ];
    let by_t = [
        0.0,
        0.0,
        1.0,
        0.0,
        s,
        2.0 * t,
        0.0,
        s2,
        2.0 * s * t,
        3.0 * t2,
        0.0,
        s2 * s,
        2.0 * s2 * t,
        3.0 * s * t2,
        4.0 * t2 * t,
    ];
    let mut out = [[0.0; 12]; 3];
    for (i, row) in BOX.iter().enumerate() {
        let dot = |m: &[f64; 15]| row.iter().zip(m).map(|(c, x)| c * x).sum::<f64>() / 12.0;
        out[0][i] = dot(&monomials);
        out[1][i] = dot(&by_s);
        out[2][i] = dot(&by_t);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn weights_sum_to_one_and_derivatives_to_zero() {
        for &(u, v) in &[(0.0, 0.0), (0.3, 0.6), (1.0, 1.0), (0.25, 0.5)] {
            let b = bicubic(u, v);
            assert!((b[0].iter().sum::<f64>() - 1.0).abs() < 1e-15);
            assert!(b[1].iter().sum::<f64>().abs() < 1e-15);
            assert!(b[2].iter().sum::<f64>().abs() < 1e-15);
            let l = box_spline(u * 0.5, v * 0.5);
            assert!((l[0].iter().sum::<f64>() - 1.0).abs() < 1e-15);
            assert!(l[1].iter().sum::<f64>().abs() < 1e-14);
            assert!(l[2].iter().sum::<f64>().abs() < 1e-14);
        }
    }

    #[test]
    fn box_spline_reproduces_the_plane_of_its_lattice() {
        // Point i of the lattice at (x, y); the patch is linear precision.
        let lattice: [(f64, f64); 12] = [
            (0., -1.),
            (1., -1.),
            (2., -1.),
            (-1., 0.),
            (0., 0.),
            (1., 0.),
            (2., 0.),
            (-1., 1.),
            (0., 1.),
            (1., 1.),
            (-1., 2.),
            (0., 2.),
        ];
        let (s, t) = (0.2, 0.3);
        let w = box_spline(s, t);
        let x: f64 = w[0].iter().zip(&lattice).map(|(w, p)| w * p.0).sum();
        let y: f64 = w[0].iter().zip(&lattice).map(|(w, p)| w * p.1).sum();
        assert!((x - s).abs() < 1e-15 && (y - t).abs() < 1e-15);
        let xs: f64 = w[1].iter().zip(&lattice).map(|(w, p)| w * p.0).sum();
        let yt: f64 = w[2].iter().zip(&lattice).map(|(w, p)| w * p.1).sum();
        assert!((xs - 1.0).abs() < 1e-14 && (yt - 1.0).abs() < 1e-14);
    }
}
