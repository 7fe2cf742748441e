/* The size cap through the C ABI: a request whose result would pass
 * 2^31 - 1 elements fails with WEFT_STATUS_RESULT_TOO_LARGE (or, for an
 * input count past the cap, WEFT_STATUS_INPUT_TOO_LARGE) and a sentence,
 * before anything is allocated or a buffer is read; the output stays NULL. */
#include <math.h>
#include <stdint.h>
#include <string.h>
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

static void test_counts_before_buffers(void) {
  /* A count the call refuses is refused before the buffer it describes is
   * viewed: every buffer here is far shorter than its count claims (under
   * AddressSanitizer a read past it would be caught). */
  static const double square[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
  static const uint32_t tri[] = {3};
  static const uint32_t corners[] = {0, 1, 2};
  const size_t huge = (size_t)1 << 32, big = (size_t)1 << 20;
  double values[4] = {0.1, 0.1, 0.1, 0.1}, out_values[4] = {0};
  WeftSubdivisionOptions options;
  WeftMesh *mesh = NULL, *cube = NULL;
  memset(&options, 0, sizeof options);

  CHECK_REFUSED(weft_mesh_new(square, 4, tri, huge, corners, 3, &mesh), mesh, WEFT_STATUS_INPUT_TOO_LARGE);
  CHECK_MESSAGE("invalid mesh: face count 4294967296 exceeds the limit of 2147483647");
  CHECK_REFUSED(weft_mesh_new(square, 4, tri, 1, corners, huge, &mesh), mesh, WEFT_STATUS_INPUT_TOO_LARGE);
  CHECK_MESSAGE("invalid mesh: index count 4294967296 exceeds the limit of 2147483647");
  CHECK_REFUSED(weft_mesh_new(square, SIZE_MAX, tri, 1, corners, 3, &mesh), mesh, WEFT_STATUS_INPUT_TOO_LARGE);
  CHECK_MESSAGE("invalid mesh: vertex count");
  /* A grid whose u x v disagrees with a point count within the cap. */
  CHECK_STATUS(weft_mesh_from_grid(square, big, 2, 2, false, false, false, &mesh), WEFT_STATUS_INVALID_ARGUMENT);
  CHECK_MESSAGE("1048576 points were given but a grid of u_count");
  CHECK_MESSAGE("needs 4");
  CHECK(mesh == NULL);

  CHECK_STATUS(weft_box(1, 1, 1, 1, 1, 1, &cube), WEFT_STATUS_OK);
  CHECK_STATUS(weft_stellate(cube, values, big, &mesh), WEFT_STATUS_INVALID_ARGUMENT);
  CHECK_MESSAGE("1048576 heights were given for a mesh of 6 faces; give one per face");
  CHECK_STATUS(weft_mesh_window(cube, values, big, WEFT_INSET_EDGE_FRACTION, &mesh), WEFT_STATUS_INVALID_ARGUMENT);
  CHECK_MESSAGE("1048576 distances were given for a mesh of 6 faces");
  CHECK_STATUS(weft_picture_frame(cube, values, big, WEFT_INSET_EDGE_FRACTION, &mesh), WEFT_STATUS_INVALID_ARGUMENT);
  CHECK_MESSAGE("1048576 distances were given for a mesh of 6 faces");
  CHECK_STATUS(weft_laplacian_hc_smooth_ex(cube, 1, 0.0, 0.6, WEFT_NAKED_EDGES_FIXED, WEFT_SMOOTH_DIRECTION_FREE,
                                           values, big, &mesh),
               WEFT_STATUS_INVALID_ARGUMENT);
  CHECK_MESSAGE("activation has 1048576 values but the mesh has 8 vertices");
  CHECK(mesh == NULL);
  CHECK_STATUS(weft_blur_values(cube, values, big, 1, 1, 0.5, WEFT_NAKED_EDGES_FIXED, out_values, 4),
               WEFT_STATUS_INVALID_ARGUMENT);
  CHECK_MESSAGE("1048576 values were given but the mesh's 8 vertices with 1 components need 8");
  CHECK_STATUS(weft_subdivide_vertex_data(cube, &options, 1, values, big, 1, out_values, 4),
               WEFT_STATUS_COUNT_MISMATCH);
  CHECK_MESSAGE("data holds 1048576 doubles but 8 vertices of width 1 need 8");
  CHECK_STATUS(weft_subdivide_face_varying(cube, &options, 1, WEFT_FACE_VARYING_ALL, values, 4, 1, corners, big,
                                           out_values, 4),
               WEFT_STATUS_COUNT_MISMATCH);
  CHECK_MESSAGE("value_indices holds 1048576 indices but the mesh has 24 face corners");
  /* Nothing was written to the too-short output either. */
  CHECK(out_values[0] == 0.0 && out_values[3] == 0.0);
  weft_mesh_free(cube);
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

/* Refines the cage `corners` scaled by `scale` through every subdivision
 * export, into the four outputs (3 * 59 doubles each): Catmull-Clark at
 * level 2, the refiner's evaluate, the creased refiner's evaluate, and the
 * creased limit positions (normals into `normals`). */
static void refine_all(const double *corners, double scale, double *plain, double *refined, double *creased,
                       double *limit, double *normals) {
  const uint32_t sizes[] = {4, 3, 6};
  const uint32_t indices[] = {2, 5, 4, 3, 2, 3, 4, 2, 1, 0, 3, 4, 5};
  const uint32_t pairs[] = {2, 3, 3, 4};
  const double sharpness[] = {1.5, WEFT_SHARPNESS_INFINITE};
  double positions[18];
  WeftSubdivisionOptions options = {0};
  WeftMesh *cage = NULL, *mesh = NULL;
  WeftRefiner *refiner = NULL;
  size_t i, vertices = 0, faces = 0, corner_count = 0;
  for (i = 0; i < 18; ++i) positions[i] = corners[i] * scale;
  CHECK_STATUS(weft_mesh_new(positions, 6, sizes, 3, indices, 13, &cage), WEFT_STATUS_OK);
  CHECK_STATUS(weft_catmull_clark(cage, 2, WEFT_NAKED_EDGES_SMOOTH, &mesh), WEFT_STATUS_OK);
  CHECK(weft_mesh_vertex_count(mesh) == 59);
  CHECK(weft_mesh_face_count(mesh) == 52);
  CHECK_STATUS(weft_mesh_copy_positions(mesh, plain, 3 * 59), WEFT_STATUS_OK);
  weft_mesh_free(mesh);

  CHECK_STATUS(weft_refiner_new(cage, WEFT_SCHEME_CATMULL_CLARK, 2, WEFT_NAKED_EDGES_SMOOTH, &refiner),
               WEFT_STATUS_OK);
  CHECK(weft_refiner_vertex_count(refiner) == 59);
  CHECK_STATUS(weft_refiner_evaluate(refiner, positions, 6, refined, 3 * 59), WEFT_STATUS_OK);
  weft_refiner_free(refiner);

  options.scheme = WEFT_SCHEME_CATMULL_CLARK;
  options.naked_edges = WEFT_NAKED_EDGES_SMOOTH;
  set_creases(&options, 2, pairs, sharpness);
  CHECK_STATUS(weft_refiner_new_ex(cage, &options, 2, &refiner), WEFT_STATUS_OK);
  CHECK_STATUS(weft_refiner_evaluate(refiner, positions, 6, creased, 3 * 59), WEFT_STATUS_OK);
  weft_refiner_free(refiner);
  CHECK_STATUS(weft_subdivision_counts(cage, WEFT_SCHEME_CATMULL_CLARK, 2, &vertices, &faces, &corner_count),
               WEFT_STATUS_OK);
  CHECK(vertices == 59);
  CHECK_STATUS(weft_subdivide_limit(cage, &options, 2, limit, normals, 3 * 59), WEFT_STATUS_OK);
  weft_mesh_free(cage);
}

static void test_huge_coordinates(void) {
  /* Three faces with coordinates up to 2^1023: Catmull-Clark's sums would
   * pass the largest double. Subdivision runs at an exactly scaled-down
   * size, so every result is the ordinary cage's result times 2^1019, bit
   * for bit, and the limit normals are the same. */
  static const double corners[] = {-15.5, -15.873046875, -15.62109375, -15.369140625, -15.1171875, -14.4892578125,
                                   -14.865234375, -14.298828125, -14.109375, -13.857421875, -13.4482421875, -15.5,
                                   -11.7490234375, -15.6171875, -15.494140625, 15.263671875, -15.1162109375,
                                   -14.7470703125};
  static double small[5][3 * 59], huge[5][3 * 59];
  const double scale = ldexp(1.0, 1019);
  size_t i, k, exact = 0, unit = 0;
  refine_all(corners, 1.0, small[0], small[1], small[2], small[3], small[4]);
  refine_all(corners, scale, huge[0], huge[1], huge[2], huge[3], huge[4]);
  for (k = 0; k < 4; ++k) {
    for (i = 0; i < 3 * 59; ++i) exact += huge[k][i] == small[k][i] * scale;
  }
  CHECK(exact == 4 * 3 * 59);
  CHECK(memcmp(small[1], small[0], sizeof small[0]) == 0);
  CHECK(memcmp(huge[4], small[4], sizeof small[4]) == 0);
  for (i = 0; i < 59; ++i) {
    const double *n = &huge[4][3 * i];
    unit += fabs(n[0] * n[0] + n[1] * n[1] + n[2] * n[2] - 1.0) < 1e-12;
  }
  CHECK(unit > 30);
}

int main(void) {
  test_primitives();
  test_point_counts();
  test_counts_before_buffers();
  test_levels();
  test_huge_coordinates();
  return check_summary("test_limits");
}
