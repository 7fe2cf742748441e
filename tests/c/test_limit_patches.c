/* The limit surface as bicubic patches through the C ABI: counts, the
 * layout of the control points, shared edges, errors, and every refusal
 * writing nothing. */
#include <math.h>
#include <string.h>

#include "check.h"

/* Control point (i, j) of patch p. */
static const double *control(const double *points, size_t p, int i, int j) {
  return points + WEFT_PATCH_DOUBLES * p + 12 * i + 3 * j;
}

static void test_patches_of_a_cube(void) {
  WeftMesh *cube = unit_cube();
  WeftSubdivisionOptions options = smooth_catmull_clark();
  static double points[WEFT_PATCH_DOUBLES * 24];
  uint32_t faces[24];
  double errors[24], max_error = -1;
  size_t vertices = 0, refined_faces = 0, indices = 0, count = 0, exact = 99, p;
  int corner_on_limit = 1, faces_in_order = 1, errors_bounded = 1;
  double limit[3 * 26];

  CHECK_STATUS(weft_subdivision_counts_ex(cube, &options, 1, &vertices, &refined_faces, &indices), WEFT_STATUS_OK);
  CHECK(refined_faces == 24);
  CHECK_STATUS(weft_limit_patches(cube, &options, 1, points, faces, errors, 24, &count, &max_error, &exact),
               WEFT_STATUS_OK);
  /* At isolation 1 every face of the cube touches a corner of valence 3. */
  CHECK(count == 24 && exact == 0 && max_error > 1e-4 && max_error < 1e-2);
  /* Corner 0 of patch p is the limit point of refined face p's first corner. */
  CHECK_STATUS(weft_subdivide_limit(cube, &options, 1, limit, NULL, 3 * 26), WEFT_STATUS_OK);
  {
    WeftMesh *refined = NULL;
    const uint32_t *corners;
    CHECK_STATUS(weft_subdivide_ex(cube, &options, 1, &refined), WEFT_STATUS_OK);
    corners = weft_mesh_face_indices(refined);
    for (p = 0; p < 24; ++p) {
      const double *c = control(points, p, 0, 0), *l = limit + 3 * corners[4 * p];
      corner_on_limit &= fabs(c[0] - l[0]) + fabs(c[1] - l[1]) + fabs(c[2] - l[2]) < 1e-14;
      faces_in_order &= faces[p] == p / 4;
      errors_bounded &= errors[p] <= max_error && errors[p] > 0;
    }
    weft_mesh_free(refined);
  }
  CHECK(corner_on_limit && faces_in_order && errors_bounded);
  /* Patches 0 and 1 (children 0 and 1 of face 0) share an edge, bit for
   * bit: child 0's corners 1 and 2 are child 1's corners 3 and 2. */
  CHECK(memcmp(control(points, 0, 3, 0), control(points, 1, 0, 3), 3 * sizeof(double)) == 0);
  CHECK(memcmp(control(points, 0, 3, 3), control(points, 1, 3, 3), 3 * sizeof(double)) == 0);

  /* Refusals: nothing written. */
  points[0] = 42;
  count = 7;
  CHECK_FAILS_WITH(weft_limit_patches(cube, &options, 1, points, NULL, NULL, 23, &count, NULL, NULL),
                   WEFT_STATUS_BUFFER_TOO_SMALL, "room for 23 elements but 24 are needed");
  CHECK_FAILS_WITH(weft_limit_patches(cube, &options, 0, points, NULL, NULL, 24, &count, NULL, NULL),
                   WEFT_STATUS_INVALID_ARGUMENT, "isolation is 0");
  CHECK_FAILS_WITH(weft_limit_patches(cube, &options, 9, points, NULL, NULL, 24, &count, NULL, NULL),
                   WEFT_STATUS_INVALID_ARGUMENT, "isolation is 9");
  options.scheme = WEFT_SCHEME_LOOP;
  CHECK_FAILS_WITH(weft_limit_patches(cube, &options, 1, points, NULL, NULL, 24, &count, NULL, NULL),
                   WEFT_STATUS_INVALID_ARGUMENT, "WEFT_SCHEME_CATMULL_CLARK");
  options.scheme = WEFT_SCHEME_CATMULL_CLARK;
  CHECK_FAILS_WITH(weft_limit_patches(NULL, &options, 1, points, NULL, NULL, 24, &count, NULL, NULL),
                   WEFT_STATUS_NULL_POINTER, "cage");
  CHECK_FAILS_WITH(weft_limit_patches(cube, &options, 1, NULL, NULL, NULL, 24, &count, NULL, NULL),
                   WEFT_STATUS_NULL_POINTER, "out_control_points");
  CHECK_FAILS_WITH(weft_limit_patches(cube, &options, 1, points, NULL, NULL, 24, NULL, NULL, NULL),
                   WEFT_STATUS_NULL_POINTER, "out_patch_count");
  CHECK(points[0] == 42 && count == 7);

  /* The same patches from a limit surface handle; a Loop surface has none. */
  {
    WeftLimitSurface *surface = NULL;
    static double again[WEFT_PATCH_DOUBLES * 24];
    size_t again_count = 0;
    CHECK_STATUS(weft_limit_surface_new(cube, &options, &surface), WEFT_STATUS_OK);
    CHECK_STATUS(weft_limit_surface_patches(surface, 1, again, NULL, NULL, 24, &again_count, NULL, NULL), WEFT_STATUS_OK);
    CHECK_STATUS(weft_limit_patches(cube, &options, 1, points, NULL, NULL, 24, &count, NULL, NULL), WEFT_STATUS_OK);
    CHECK(again_count == 24 && memcmp(again, points, sizeof again) == 0);
    CHECK_FAILS_WITH(weft_limit_surface_patches(NULL, 1, again, NULL, NULL, 24, &again_count, NULL, NULL),
                     WEFT_STATUS_NULL_POINTER, "surface");
    weft_limit_surface_free(surface);
  }
  weft_mesh_free(cube);
}

int main(void) {
  test_patches_of_a_cube();
  return check_summary("test_limit_patches");
}
