//! The size cap: a request whose result would pass [`weft::error::MAX_ELEMENTS`]
//! elements is refused with `ResultTooLarge` before anything is allocated, so
//! it fails at once, with a sentence, whatever the counts (near `usize::MAX`
//! included: counts are multiplied with overflow checks).

use std::time::{Duration, Instant};

use weft::error::MAX_ELEMENTS;
use weft::make::primitives::{box_grid, plane_grid, sided, uv_sphere, Sided};
use weft::mesh::shapes;
use weft::{DVec3, Error, Mesh, Result};

/// Runs the request, checks it is refused as too large in well under a
/// second (nothing of that size was built), and returns the sentence.
fn refused(request: impl FnOnce() -> Result<Mesh>) -> String {
    let start = Instant::now();
    let result = request();
    let elapsed = start.elapsed();
    let error = result.expect_err("a request past the cap was accepted");
    assert!(matches!(error, Error::ResultTooLarge(_)), "{error}");
    assert!(elapsed < Duration::from_secs(1), "refusal took {elapsed:?}");
    let message = error.to_string();
    assert!(message.contains(&MAX_ELEMENTS.to_string()), "{message}");
    message
}

#[test]
fn huge_box_is_refused() {
    let message = refused(|| box_grid(DVec3::ONE, 100_000, 100_000, 100_000));
    // 2 × 3 × 10^10 quads of 4 corners.
    assert!(message.contains("240000000000 face corners"), "{message}");
    let message = refused(|| box_grid(DVec3::ONE, usize::MAX, usize::MAX, usize::MAX));
    assert!(
        message.contains("more than 18446744073709551615"),
        "{message}"
    );
    // One huge count with two small ones.
    refused(|| box_grid(DVec3::ONE, 1, 1, 1_000_000_000));
}

#[test]
fn huge_sphere_grid_and_solid_are_refused() {
    refused(|| uv_sphere(1.0, usize::MAX, usize::MAX));
    refused(|| uv_sphere(1.0, 3, usize::MAX));
    refused(|| plane_grid(1.0, 1.0, usize::MAX, 2));
    refused(|| plane_grid(1.0, 1.0, 1 << 16, 1 << 16));
    refused(|| sided(Sided::Prism, usize::MAX, 1.0, 1.0));
    refused(|| sided(Sided::Dipyramid, 1 << 28, 1.0, 1.0));
}

#[test]
fn small_requests_still_succeed() {
    assert_eq!(plane_grid(1.0, 1.0, 3, 2).unwrap().face_count(), 6);
    assert_eq!(box_grid(DVec3::ONE, 1, 2, 3).unwrap().face_count(), 22);
    assert_eq!(uv_sphere(1.0, 3, 2).unwrap().face_count(), 6);
    assert_eq!(sided(Sided::Prism, 3, 1.0, 1.0).unwrap().face_count(), 5);
}

#[test]
fn deep_linear_subdivisions_are_refused() {
    let cube = shapes::cube();
    let message = refused(|| weft::toolbar::split::split_polygons(&cube, 20));
    assert!(message.contains("20 levels"), "{message}");
    refused(|| weft::toolbar::split::split_triangles(&shapes::icosahedron(), 20));
    refused(|| weft::toolbar::split::constant_quads_split(&cube, 20));
    refused(|| weft::toolbar::split::inner_polygons(&cube, 20, 0.2));
    refused(|| weft::toolbar::split::sierpinski_triangles(&shapes::icosahedron(), 20));
    refused(|| weft::toolbar::transform::sierpinski_carpet(&cube, 20));
}

#[test]
fn deep_subdivision_is_refused() {
    refused(|| {
        weft::subdivide::catmull_clark(&shapes::cube(), 16, weft::subdivide::NakedEdges::Fixed)
    });
}
