/* The limit surface anywhere through the C ABI: evaluation at corners equals
 * the limit at the vertices, derivatives are optional, closest points lie on
 * the surface, and every bad sample
 * (a face out of range, a parameter outside its face or not finite, a NULL
 * buffer) is refused with its own status, a message naming the sample and
 * the face, and nothing written. */
#include <math.h>
#include <string.h>

#include "check.h"

static int near(double a, double b) { return fabs(a - b) < 1e-12; }

static void test_corners_are_the_vertex_limit(void) {
  WeftMesh *mesh = unit_cube();
  WeftSubdivisionOptions options = smooth_catmull_clark();
  WeftLimitSurface *surface = NULL;
  double limit[3 * 26], normals[3 * 26];
  /* Corner 0 of face 0 is cage vertex cube_indices[0]. */
  const uint32_t faces[] = {0, 0};
  const double uvs[] = {0.0, 0.0, 0.5, 0.5};
  double p[6], du[6], dv[6], only[6];
  uint32_t v = cube_indices[0];
  CHECK_STATUS(weft_limit_surface_new(mesh, &options, &surface), WEFT_STATUS_OK);
  CHECK_STATUS(weft_subdivide_limit(mesh, &options, 1, limit, normals, 3 * 26), WEFT_STATUS_OK);
  CHECK_STATUS(weft_limit_surface_evaluate(surface, 2, faces, uvs, p, du, dv), WEFT_STATUS_OK);
  CHECK(near(p[0], limit[3 * v]) && near(p[1], limit[3 * v + 1]) && near(p[2], limit[3 * v + 2]));
  {
    double n[3] = {du[1] * dv[2] - du[2] * dv[1], du[2] * dv[0] - du[0] * dv[2], du[0] * dv[1] - du[1] * dv[0]};
    double length = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    CHECK(length > 0);
    CHECK(near(n[0] / length, normals[3 * v]) && near(n[1] / length, normals[3 * v + 1]) &&
          near(n[2] / length, normals[3 * v + 2]));
  }
  /* The derivatives may be left out. */
  CHECK_STATUS(weft_limit_surface_evaluate(surface, 2, faces, uvs, only, NULL, NULL), WEFT_STATUS_OK);
  CHECK(memcmp(only, p, sizeof p) == 0);
  /* No sample: nothing to read or write. */
  CHECK_STATUS(weft_limit_surface_evaluate(surface, 0, NULL, NULL, NULL, NULL, NULL), WEFT_STATUS_OK);
  weft_limit_surface_free(surface);
  weft_limit_surface_free(NULL);
  weft_mesh_free(mesh);
}

static void test_bad_samples_are_refused(void) {
  WeftMesh *mesh = unit_cube();
  WeftSubdivisionOptions options = smooth_catmull_clark();
  WeftLimitSurface *surface = NULL, *untouched = (WeftLimitSurface *)&options;
  const uint32_t faces[] = {0, 6};
  const uint32_t good_faces[] = {0, 1};
  const double uvs[] = {0.5, 0.5, 0.5, 0.5};
  const double outside[] = {0.5, 0.5, 1.25, 0.5};
  const double nan_uv[] = {0.5, 0.5, NAN, 0.5};
  double p[6], du[6];
  size_t i;
  CHECK_FAILS_WITH(weft_limit_surface_new(NULL, &options, &surface), WEFT_STATUS_NULL_POINTER, "cage");
  CHECK_FAILS_WITH(weft_limit_surface_new(mesh, NULL, &surface), WEFT_STATUS_NULL_POINTER, "options");
  CHECK_FAILS_WITH(weft_limit_surface_new(mesh, &options, NULL), WEFT_STATUS_NULL_POINTER, "out_surface");
  options.scheme = WEFT_SCHEME_LOOP;
  CHECK_STATUS(weft_limit_surface_new(mesh, &options, &untouched), WEFT_STATUS_NOT_TRIANGLES);
  CHECK(untouched == (WeftLimitSurface *)&options);
  options.scheme = WEFT_SCHEME_CATMULL_CLARK;
  CHECK_STATUS(weft_limit_surface_new(mesh, &options, &surface), WEFT_STATUS_OK);

  for (i = 0; i < 6; ++i) p[i] = du[i] = -7.0;
  CHECK_FAILS_WITH(weft_limit_surface_evaluate(surface, 2, faces, uvs, p, du, NULL),
                   WEFT_STATUS_INDEX_OUT_OF_RANGE, "sample 1: face 6 is out of range");
  CHECK_FAILS_WITH(weft_limit_surface_evaluate(surface, 2, good_faces, outside, p, du, NULL),
                   WEFT_STATUS_INVALID_ARGUMENT, "sample 1: (u, v) = (1.25, 0.5) is outside the domain of face 1");
  CHECK_FAILS_WITH(weft_limit_surface_evaluate(surface, 2, good_faces, nan_uv, p, du, NULL),
                   WEFT_STATUS_NON_FINITE_COORDINATE, "sample 1 on face 1");
  CHECK_FAILS_WITH(weft_limit_surface_evaluate(surface, 2, NULL, uvs, p, NULL, NULL),
                   WEFT_STATUS_NULL_POINTER, "faces");
  CHECK_FAILS_WITH(weft_limit_surface_evaluate(surface, 2, good_faces, NULL, p, NULL, NULL),
                   WEFT_STATUS_NULL_POINTER, "uvs");
  CHECK_FAILS_WITH(weft_limit_surface_evaluate(surface, 2, good_faces, uvs, NULL, NULL, NULL),
                   WEFT_STATUS_NULL_POINTER, "out_positions");
  CHECK_FAILS_WITH(weft_limit_surface_evaluate(NULL, 2, good_faces, uvs, p, NULL, NULL),
                   WEFT_STATUS_NULL_POINTER, "surface");
  /* Nothing was written by any refused call. */
  for (i = 0; i < 6; ++i) CHECK(p[i] == -7.0 && du[i] == -7.0);
  weft_limit_surface_free(surface);
  weft_mesh_free(mesh);
}

static void test_closest_points(void) {
  WeftMesh *mesh = unit_cube();
  WeftSubdivisionOptions options = smooth_catmull_clark();
  WeftLimitSurface *surface = NULL;
  /* Above the middle of the top face and beside the middle of the front. */
  const double points[] = {0.5, 0.5, 3.0, 0.5, -2.0, 0.5};
  const double bad[] = {0.5, 0.5, 3.0, 0.5, NAN, 0.5};
  uint32_t faces[2] = {99, 99};
  double uvs[4] = {-1, -1, -1, -1}, p[6], again[6];
  size_t i;
  CHECK_STATUS(weft_limit_surface_new(mesh, &options, &surface), WEFT_STATUS_OK);
  CHECK_STATUS(weft_limit_surface_closest_point(surface, 2, points, faces, uvs, p), WEFT_STATUS_OK);
  /* The points are the surface at the faces and parameters found... */
  CHECK_STATUS(weft_limit_surface_evaluate(surface, 2, faces, uvs, again, NULL, NULL), WEFT_STATUS_OK);
  for (i = 0; i < 6; ++i) CHECK(again[i] == p[i]);
  /* ...and by symmetry right below and beside the queries. */
  CHECK(near(p[0], 0.5) && near(p[1], 0.5) && p[2] > 0.5 && p[2] < 1.0);
  CHECK(near(p[3], 0.5) && near(p[5], 0.5) && p[4] > 0.0 && p[4] < 0.5);
  faces[0] = 99;
  CHECK_FAILS_WITH(weft_limit_surface_closest_point(surface, 2, bad, faces, uvs, p),
                   WEFT_STATUS_NON_FINITE_COORDINATE, "point 1");
  CHECK(faces[0] == 99);
  CHECK_FAILS_WITH(weft_limit_surface_closest_point(surface, 2, NULL, faces, uvs, p), WEFT_STATUS_NULL_POINTER,
                   "points");
  CHECK_FAILS_WITH(weft_limit_surface_closest_point(surface, 2, points, faces, NULL, p), WEFT_STATUS_NULL_POINTER,
                   "out_uvs");
  CHECK_FAILS_WITH(weft_limit_surface_closest_point(NULL, 2, points, faces, uvs, p), WEFT_STATUS_NULL_POINTER,
                   "surface");
  weft_limit_surface_free(surface);
  weft_mesh_free(mesh);
}

int main(void) {
  test_corners_are_the_vertex_limit();
  test_bad_samples_are_refused();
  test_closest_points();
  return check_summary("test_limit_surface");
}
