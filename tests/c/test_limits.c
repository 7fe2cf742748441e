/* The size cap through the C ABI: a request whose result would pass
 * 2^31 - 1 elements fails with WEFT_STATUS_RESULT_TOO_LARGE (or, for an
 * input count past the cap, WEFT_STATUS_INPUT_TOO_LARGE) and a sentence,
 * before anything is allocated or a buffer is read; the output stays NULL. */
#include <stdint.h>
#include <time.h>

#include "check.h"

/* The call is refused with `expected`, leaves the output NULL, and the
 * message names the limit. */
#define CHECK_REFUSED(call, out, expected) \
  do { (out) = NULL; CHECK_STATUS((call), (expected)); CHECK((out) == NULL); \
    CHECK_MESSAGE("2147483647"); } while (0)

static void test_primitives(void) {
  WeftMesh *mesh = NULL;
  clock_t start = clock();
  CHECK_REFUSED(weft_box(1, 1, 1, 100000, 100000, 100000, &mesh), mesh, WEFT_STATUS_RESULT_TOO_LARGE);
  CHECK_MESSAGE("240000000000 face corners");
  CHECK_REFUSED(weft_box(1, 1, 1, SIZE_MAX, SIZE_MAX, SIZE_MAX, &mesh), mesh, WEFT_STATUS_RESULT_TOO_LARGE);
  CHECK_REFUSED(weft_box(1, 1, 1, 1, 1, 1000000000, &mesh), mesh, WEFT_STATUS_RESULT_TOO_LARGE);
  CHECK_REFUSED(weft_uv_sphere(1, SIZE_MAX, SIZE_MAX, &mesh), mesh, WEFT_STATUS_RESULT_TOO_LARGE);
  CHECK_REFUSED(weft_uv_sphere(1, 3, SIZE_MAX, &mesh), mesh, WEFT_STATUS_RESULT_TOO_LARGE);
  CHECK_REFUSED(weft_plane_grid(1, 1, SIZE_MAX, 2, &mesh), mesh, WEFT_STATUS_RESULT_TOO_LARGE);
  CHECK_REFUSED(weft_sided_solid(WEFT_SIDED_PRISM, SIZE_MAX, 1, 1, &mesh), mesh, WEFT_STATUS_RESULT_TOO_LARGE);
  /* Nothing of that size was built: all of it takes well under a second. */
  CHECK((double)(clock() - start) / CLOCKS_PER_SEC < 1.0);
  /* What fits is still made. */
  CHECK_STATUS(weft_box(1, 1, 1, 1, 2, 3, &mesh), WEFT_STATUS_OK);
  CHECK(weft_mesh_face_count(mesh) == 22);
  weft_mesh_free(mesh);
}

static void test_point_counts(void) {
  /* Counts past the cap with a buffer of three points: refused before the
   * buffer is read (under AddressSanitizer a read would be caught). */
  const double points[] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  const size_t huge = (size_t)1 << 32;
  WeftMesh *mesh = NULL;
  WeftCells *cells = NULL;
  CHECK_REFUSED(weft_delaunay(points, huge, NULL, &mesh, NULL), mesh, WEFT_STATUS_INPUT_TOO_LARGE);
  CHECK_REFUSED(weft_delaunay(points, SIZE_MAX, NULL, &mesh, NULL), mesh, WEFT_STATUS_INPUT_TOO_LARGE);
  CHECK_REFUSED(weft_voronoi(points, huge, NULL, NULL, 0, 0, &cells), cells, WEFT_STATUS_INPUT_TOO_LARGE);
  CHECK_REFUSED(weft_voronoi(points, 3, NULL, points, huge, 0, &cells), cells, WEFT_STATUS_INPUT_TOO_LARGE);
  CHECK_REFUSED(weft_mesh_from_grid(points, huge, 1 << 16, 1 << 16, false, false, false, &mesh), mesh,
                WEFT_STATUS_INPUT_TOO_LARGE);
  CHECK_REFUSED(weft_mesh_new(points, huge, NULL, 0, NULL, 0, &mesh), mesh, WEFT_STATUS_INPUT_TOO_LARGE);
  /* A grid whose u × v overflows is refused as not matching the points given. */
  mesh = NULL;
  CHECK_STATUS(weft_mesh_from_grid(points, 3, SIZE_MAX, SIZE_MAX, false, false, false, &mesh),
               WEFT_STATUS_INVALID_ARGUMENT);
  CHECK(mesh == NULL);
  CHECK_MESSAGE("more than memory can hold");
}

static void test_levels(void) {
  WeftMesh *cube = NULL, *mesh = NULL;
  CHECK_STATUS(weft_box(2, 2, 2, 1, 1, 1, &cube), WEFT_STATUS_OK);
  CHECK_REFUSED(weft_split_polygons(cube, 20, &mesh), mesh, WEFT_STATUS_RESULT_TOO_LARGE);
  CHECK_REFUSED(weft_constant_quads_split(cube, 20, &mesh), mesh, WEFT_STATUS_RESULT_TOO_LARGE);
  CHECK_REFUSED(weft_sierpinski_carpet(cube, 20, &mesh), mesh, WEFT_STATUS_RESULT_TOO_LARGE);
  CHECK_REFUSED(weft_catmull_clark(cube, 16, WEFT_NAKED_EDGES_FIXED, &mesh), mesh, WEFT_STATUS_RESULT_TOO_LARGE);
  /* More levels than any result could hold is an argument error. */
  mesh = NULL;
  CHECK_STATUS(weft_split_polygons(cube, 1000, &mesh), WEFT_STATUS_INVALID_ARGUMENT);
  CHECK(mesh == NULL);
  weft_mesh_free(cube);
}

static void test_huge_coordinates(void) {
  /* Three faces with coordinates near 1.6e307: Catmull-Clark's sums pass
   * the largest double. The result is refused, naming the vertex, rather
   * than handed out with infinite coordinates. */
  const double corners[] = {-15.5, -15.873046875, -15.62109375, -15.369140625, -15.1171875, -14.4892578125,
                            -14.865234375, -14.298828125, -14.109375, -13.857421875, -13.4482421875, -15.5,
                            -11.7490234375, -15.6171875, -15.494140625, 15.263671875, -15.1162109375,
                            -14.7470703125};
  const uint32_t sizes[] = {4, 3, 6};
  const uint32_t indices[] = {2, 5, 4, 3, 2, 3, 4, 2, 1, 0, 3, 4, 5};
  double positions[18];
  WeftMesh *cage = NULL, *mesh = NULL;
  WeftRefiner *refiner = NULL;
  size_t i;
  for (i = 0; i < 18; ++i) positions[i] = corners[i] * 1e306;
  CHECK_STATUS(weft_mesh_new(positions, 6, sizes, 3, indices, 13, &cage), WEFT_STATUS_OK);
  CHECK_STATUS(weft_catmull_clark(cage, 2, WEFT_NAKED_EDGES_FIXED, &mesh), WEFT_STATUS_DEGENERATE_INPUT);
  CHECK(mesh == NULL);
  CHECK_MESSAGE("vertex");
  CHECK_STATUS(weft_refiner_new(cage, WEFT_SCHEME_CATMULL_CLARK, 2, WEFT_NAKED_EDGES_FIXED, &refiner), WEFT_STATUS_OK);
  weft_refiner_free(refiner);
  /* At an ordinary scale the same cage subdivides. */
  weft_mesh_free(cage);
  CHECK_STATUS(weft_mesh_new(corners, 6, sizes, 3, indices, 13, &cage), WEFT_STATUS_OK);
  CHECK_STATUS(weft_catmull_clark(cage, 2, WEFT_NAKED_EDGES_FIXED, &mesh), WEFT_STATUS_OK);
  CHECK(weft_mesh_face_count(mesh) == 52);
  weft_mesh_free(mesh);
  weft_mesh_free(cage);
}

int main(void) {
  test_primitives();
  test_point_counts();
  test_levels();
  test_huge_coordinates();
  return check_summary("test_limits");
}
