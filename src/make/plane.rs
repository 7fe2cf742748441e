//! A plane given by an origin and two axes, as designers draw it in a host:
//! the frame Delaunay and Voronoi project their points onto.

use glam::{DVec2, DVec3};

use crate::error::{Error, Result};

/// A plane: an origin and two in-plane axes; the normal is `x_axis × y_axis`.
///
/// The axes need not be unit length or exactly orthogonal: [`Plane::new`]
/// orthonormalises them (Gram-Schmidt, keeping the direction of `x_axis` and
/// the side of `y_axis`), so the front side stays the side `x × y` points to.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Plane {
    origin: DVec3,
    x_axis: DVec3,
    y_axis: DVec3,
}

impl Plane {
    /// The plane through `origin` spanned by `x_axis` and `y_axis`.
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] for a non-finite coordinate;
    /// [`Error::DegenerateInput`] when an axis has zero length or the two are
    /// parallel.
    pub fn new(origin: DVec3, x_axis: DVec3, y_axis: DVec3) -> Result<Plane> {
        for (name, v) in [("origin", origin), ("x axis", x_axis), ("y axis", y_axis)] {
            if !v.is_finite() {
                return Err(Error::InvalidArgument(format!(
                    "the plane's {name} has a non-finite coordinate ({}, {}, {})",
                    v.x, v.y, v.z
                )));
            }
        }
        let x_length = x_axis.length();
        let y_length = y_axis.length();
        if x_length == 0.0 || !x_length.is_finite() {
            return Err(Error::DegenerateInput(
                "the plane's x axis has zero length".into(),
            ));
        }
        if y_length == 0.0 || !y_length.is_finite() {
            return Err(Error::DegenerateInput(
                "the plane's y axis has zero length".into(),
            ));
        }
        let x = x_axis / x_length;
        let y_rejected = y_axis / y_length - x * x.dot(y_axis / y_length);
        // Sine of the angle between the axes; below this they are parallel for f64 purposes.
        if y_rejected.length() < 1e-12 {
            return Err(Error::DegenerateInput(
                "the plane's x and y axes are parallel".into(),
            ));
        }
        Ok(Plane {
            origin,
            x_axis: x,
            y_axis: y_rejected.normalize(),
        })
    }

    /// The world XY plane through the origin.
    pub fn xy() -> Plane {
        Plane {
            origin: DVec3::ZERO,
            x_axis: DVec3::X,
            y_axis: DVec3::Y,
        }
    }

    /// The origin.
    pub fn origin(&self) -> DVec3 {
        self.origin
    }

    /// The unit x axis.
    pub fn x_axis(&self) -> DVec3 {
        self.x_axis
    }

    /// The unit y axis, orthogonal to the x axis.
    pub fn y_axis(&self) -> DVec3 {
        self.y_axis
    }

    /// The unit normal, `x_axis × y_axis`: the front side.
    pub fn normal(&self) -> DVec3 {
        self.x_axis.cross(self.y_axis)
    }

    /// The plane coordinates of `point`'s orthogonal projection.
    pub fn to_plane(&self, point: DVec3) -> DVec2 {
        let d = point - self.origin;
        DVec2::new(d.dot(self.x_axis), d.dot(self.y_axis))
    }

    /// The point of the plane at plane coordinates `uv`.
    pub fn to_world(&self, uv: DVec2) -> DVec3 {
        self.origin + self.x_axis * uv.x + self.y_axis * uv.y
    }
}

/// Checks that every point is finite, naming the first that is not.
pub(crate) fn check_points(points: &[DVec3], what: &str) -> Result<()> {
    match points.iter().position(|p| !p.is_finite()) {
        Some(i) => {
            let p = points[i];
            Err(Error::InvalidArgument(format!(
                "{what} {i} has a non-finite coordinate ({}, {}, {})",
                p.x, p.y, p.z
            )))
        }
        None => Ok(()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn skewed_axes_are_orthonormalised_keeping_the_front_side() {
        let plane = Plane::new(
            DVec3::ONE,
            DVec3::new(2.0, 0.0, 0.0),
            DVec3::new(1.0, 3.0, 0.0),
        )
        .unwrap();
        assert_eq!(plane.x_axis(), DVec3::X);
        assert!((plane.y_axis() - DVec3::Y).length() < 1e-15);
        assert!((plane.normal() - DVec3::Z).length() < 1e-15);
        let p = DVec3::new(3.0, 5.0, 7.0);
        let uv = plane.to_plane(p);
        assert_eq!(uv, DVec2::new(2.0, 4.0));
        assert_eq!(plane.to_world(uv), DVec3::new(3.0, 5.0, 1.0));
    }

    #[test]
    fn degenerate_axes_are_refused() {
        let zero = Plane::new(DVec3::ZERO, DVec3::ZERO, DVec3::Y);
        assert!(matches!(zero, Err(Error::DegenerateInput(m)) if m.contains("x axis")));
        let parallel = Plane::new(DVec3::ZERO, DVec3::X, DVec3::X * -3.0);
        assert!(matches!(parallel, Err(Error::DegenerateInput(m)) if m.contains("parallel")));
        let nan = Plane::new(DVec3::ZERO, DVec3::X, DVec3::new(0.0, f64::NAN, 0.0));
        assert!(matches!(nan, Err(Error::InvalidArgument(_))));
    }
}
