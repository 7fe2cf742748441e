/* The mesh handle through the C ABI: construction, accessors, copies, info
 * on named shapes, and every construction error with its own status. */
#include <math.h>
#include <string.h>

#include "check.h"



static void test_construction_and_accessors(void) {
  WeftMesh *mesh = unit_cube();
  double positions[24];
  uint32_t sizes[6], indices[24];
  CHECK(weft_mesh_vertex_count(mesh) == 8);
  CHECK(weft_mesh_face_count(mesh) == 6);
  CHECK(weft_mesh_index_count(mesh) == 24);
  CHECK(memcmp(weft_mesh_positions(mesh), cube_positions, sizeof cube_positions) == 0);
  CHECK(memcmp(weft_mesh_face_sizes(mesh), cube_sizes, sizeof cube_sizes) == 0);
  CHECK(memcmp(weft_mesh_face_indices(mesh), cube_indices, sizeof cube_indices) == 0);
  CHECK_STATUS(weft_mesh_copy_positions(mesh, positions, 24), WEFT_STATUS_OK);
  CHECK(memcmp(positions, cube_positions, sizeof positions) == 0);
  CHECK_STATUS(weft_mesh_copy_faces(mesh, sizes, 6, indices, 24), WEFT_STATUS_OK);
  CHECK(memcmp(indices, cube_indices, sizeof indices) == 0);
  /* Too small: an error, and nothing written. */
  positions[0] = -7.0;
  CHECK_STATUS(weft_mesh_copy_positions(mesh, positions, 23), WEFT_STATUS_BUFFER_TOO_SMALL);
  CHECK_MESSAGE("out_positions has room for 23 elements but 24 are needed");
  CHECK(positions[0] == -7.0);
  CHECK_STATUS(weft_mesh_copy_faces(mesh, sizes, 6, indices, 3), WEFT_STATUS_BUFFER_TOO_SMALL);
  CHECK_MESSAGE("out_face_indices");
  weft_mesh_free(mesh);
  weft_mesh_free(NULL);
  CHECK(weft_mesh_vertex_count(NULL) == 0);
  CHECK(weft_mesh_positions(NULL) == NULL);
}

static void test_empty_mesh(void) {
  WeftMesh *mesh = NULL;
  WeftMeshInfo info;
  CHECK_STATUS(weft_mesh_new(NULL, 0, NULL, 0, NULL, 0, &mesh), WEFT_STATUS_OK);
  CHECK(mesh != NULL);
  CHECK(weft_mesh_vertex_count(mesh) == 0 && weft_mesh_positions(mesh) == NULL);
  CHECK_STATUS(weft_mesh_info(mesh, &info), WEFT_STATUS_OK);
  CHECK(info.face_count == 0 && !info.is_closed && info.component_count == 0);
  weft_mesh_free(mesh);
}

static void test_info(void) {
  WeftMesh *cube = unit_cube(), *grid = NULL, *fin = NULL;
  WeftMeshInfo info;
  /* A 2 x 1 open quad grid. */
  static const double grid_positions[] = {0, 0, 0, 1, 0, 0, 2, 0, 0, 0, 1, 0, 1, 1, 0, 2, 1, 0};
  static const uint32_t grid_sizes[] = {4, 4};
  static const uint32_t grid_indices[] = {0, 1, 4, 3, 1, 2, 5, 4};
  /* Three triangles on the edge 0-1. */
  static const double fin_positions[] = {0, 0, 0, 1, 0, 0, 0.5, 1, 0, 0.5, -1, 0, 0.5, 0, 1};
  static const uint32_t fin_sizes[] = {3, 3, 3};
  static const uint32_t fin_indices[] = {0, 1, 2, 1, 0, 3, 0, 1, 4};

  CHECK_STATUS(weft_mesh_info(cube, &info), WEFT_STATUS_OK);
  CHECK(info.vertex_count == 8 && info.edge_count == 12 && info.face_count == 6);
  CHECK(info.naked_edge_count == 0 && info.non_manifold_edge_count == 0);
  CHECK(info.component_count == 1 && info.is_closed && info.is_orientable && info.is_oriented);

  CHECK_STATUS(weft_mesh_new(grid_positions, 6, grid_sizes, 2, grid_indices, 8, &grid), WEFT_STATUS_OK);
  CHECK_STATUS(weft_mesh_info(grid, &info), WEFT_STATUS_OK);
  CHECK(info.edge_count == 7 && info.naked_edge_count == 6 && !info.is_closed);

  CHECK_STATUS(weft_mesh_new(fin_positions, 5, fin_sizes, 3, fin_indices, 9, &fin), WEFT_STATUS_OK);
  CHECK_STATUS(weft_mesh_info(fin, &info), WEFT_STATUS_OK);
  CHECK(info.non_manifold_edge_count == 1 && info.non_manifold_vertex_count == 2);
  CHECK(info.naked_edge_count == 6 && !info.is_closed);

  CHECK_STATUS(weft_mesh_info(NULL, &info), WEFT_STATUS_NULL_POINTER);
  CHECK_MESSAGE("mesh is NULL");
  CHECK_STATUS(weft_mesh_info(cube, NULL), WEFT_STATUS_NULL_POINTER);
  CHECK_MESSAGE("out_info is NULL");
  weft_mesh_free(cube);
  weft_mesh_free(grid);
  weft_mesh_free(fin);
}

static void test_construction_errors(void) {
  static const double square[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
  WeftMesh *untouched = (WeftMesh *)&check_failures; /* a sentinel that must not be overwritten */
  WeftMesh *mesh = untouched;
  double bad[12];
  static const uint32_t tri[] = {3}, two[] = {2}, tri_tri[] = {3, 3};
  static const uint32_t out_of_range[] = {0, 1, 9};
  static const uint32_t repeated[] = {0, 1, 1};
  static const uint32_t ok[] = {0, 1, 2};

  CHECK_STATUS(weft_mesh_new(square, 4, tri, 1, out_of_range, 3, &mesh), WEFT_STATUS_INDEX_OUT_OF_RANGE);
  CHECK_MESSAGE("face 0, corner 2: vertex index 9 is out of range (the mesh has 4 vertices)");
  CHECK(mesh == untouched);

  CHECK_STATUS(weft_mesh_new(square, 4, two, 1, ok, 2, &mesh), WEFT_STATUS_FACE_TOO_SMALL);
  CHECK_MESSAGE("face 0 has 2 vertices");

  CHECK_STATUS(weft_mesh_new(square, 4, tri, 1, repeated, 3, &mesh), WEFT_STATUS_REPEATED_INDEX);
  CHECK_MESSAGE("face 0 uses vertex 1 twice");

  memcpy(bad, square, sizeof bad);
  bad[7] = NAN;
  CHECK_STATUS(weft_mesh_new(bad, 4, tri, 1, ok, 3, &mesh), WEFT_STATUS_NON_FINITE_COORDINATE);
  CHECK_MESSAGE("vertex 2 has a non-finite coordinate");
  bad[7] = INFINITY;
  CHECK_STATUS(weft_mesh_new(bad, 4, tri, 1, ok, 3, &mesh), WEFT_STATUS_NON_FINITE_COORDINATE);

  CHECK_STATUS(weft_mesh_new(square, 4, tri_tri, 2, ok, 3, &mesh), WEFT_STATUS_COUNT_MISMATCH);
  CHECK_MESSAGE("the face sizes add up to 6 indices but 3 indices were given");

  CHECK_STATUS(weft_mesh_new(square, (size_t)1 << 32, tri, 1, ok, 3, &mesh), WEFT_STATUS_INPUT_TOO_LARGE);
  CHECK_MESSAGE("vertex count 4294967296 exceeds the limit");

  CHECK_STATUS(weft_mesh_new(NULL, 4, tri, 1, ok, 3, &mesh), WEFT_STATUS_NULL_POINTER);
  CHECK_MESSAGE("positions is NULL but its length is 12");
  CHECK_STATUS(weft_mesh_new(square, 4, tri, 1, NULL, 3, &mesh), WEFT_STATUS_NULL_POINTER);
  CHECK_MESSAGE("face_indices is NULL");
  CHECK_STATUS(weft_mesh_new(square, 4, tri, 1, ok, 3, NULL), WEFT_STATUS_NULL_POINTER);
  CHECK_MESSAGE("out_mesh is NULL");
  CHECK(mesh == untouched);
}

/* Faces that name a vertex twice: refused by default, accepted on request
 * and subdivided (a degenerate edge keeps its point on its vertex). */
static void test_repeated_vertices(void) {
  static const double grid[] = {0, 0, 0, 1, 0, 0, 2, 0, 0, 0, 1, 0, 1, 1, 0, 2, 1, 0};
  static const uint32_t sizes[] = {5, 4};
  static const uint32_t faces[] = {0, 1, 1, 4, 3, 1, 2, 5, 4};
  WeftMesh *mesh = NULL, *out = NULL;
  size_t vertices = 0, refined_faces = 0, indices = 0;
  CHECK_FAILS_WITH(weft_mesh_new_ex(grid, 6, sizes, 2, faces, 9, 0, &mesh), WEFT_STATUS_REPEATED_INDEX,
                   "face 0 uses vertex 1 twice");
  CHECK_FAILS_WITH(weft_mesh_new_ex(grid, 6, sizes, 2, faces, 9, 6, &mesh), WEFT_STATUS_INVALID_ARGUMENT,
                   "unknown bits 0x6");
  CHECK(mesh == NULL);
  CHECK_STATUS(weft_mesh_new_ex(grid, 6, sizes, 2, faces, 9, WEFT_MESH_ALLOW_REPEATED_VERTICES, &mesh),
               WEFT_STATUS_OK);
  CHECK(weft_mesh_face_count(mesh) == 2 && weft_mesh_index_count(mesh) == 9);
  /* 6 vertices, 8 edges (the degenerate [1, 1] one of them), 2 faces. */
  CHECK_STATUS(weft_subdivision_counts(mesh, WEFT_SCHEME_CATMULL_CLARK, 1, &vertices, &refined_faces, &indices),
               WEFT_STATUS_OK);
  CHECK(vertices == 16 && refined_faces == 9 && indices == 36);
  CHECK_STATUS(weft_catmull_clark(mesh, 1, WEFT_NAKED_EDGES_SMOOTH, &out), WEFT_STATUS_OK);
  CHECK(weft_mesh_vertex_count(out) == 16);
  /* Edge points follow the vertices in edge order; [1, 1] is the third edge. */
  CHECK(memcmp(weft_mesh_positions(out) + 3 * 8, grid + 3, 3 * sizeof(double)) == 0);
  CHECK(memcmp(weft_mesh_positions(out) + 3 * 1, grid + 3, 3 * sizeof(double)) == 0);
  weft_mesh_free(out);
  weft_mesh_free(mesh);
}

/* A mesh that reads the caller's arrays in place: the same mesh and results
 * as a copied one, the same errors, the caller's arrays never written, and
 * every mesh made from it, the cage returned at level 0 too, with buffers of
 * its own. */
static void test_borrowed_mesh(void) {
  double positions[24];
  uint32_t indices[24];
  static const uint32_t mixed_sizes[] = {3, 4}, mixed[] = {0, 1, 3, 1, 2, 6, 3}, tri[] = {3};
  static const uint32_t out_of_range[] = {0, 1, 9};
  WeftMesh *borrowed = NULL, *copied = unit_cube(), *clone = NULL, *smooth = NULL, *expected = NULL;
  memcpy(positions, cube_positions, sizeof positions);
  memcpy(indices, cube_indices, sizeof indices);
  CHECK_STATUS(weft_mesh_new_borrowed(positions, 8, cube_sizes, 6, indices, 24, 0, &borrowed), WEFT_STATUS_OK);
  CHECK(weft_mesh_is_borrowed(borrowed) && !weft_mesh_is_borrowed(copied) && !weft_mesh_is_borrowed(NULL));
  CHECK(weft_mesh_positions(borrowed) == positions && weft_mesh_face_indices(borrowed) == indices);
  CHECK(memcmp(weft_mesh_face_sizes(borrowed), cube_sizes, sizeof cube_sizes) == 0);
  CHECK_STATUS(weft_catmull_clark(borrowed, 2, WEFT_NAKED_EDGES_SMOOTH, &smooth), WEFT_STATUS_OK);
  CHECK_STATUS(weft_catmull_clark(copied, 2, WEFT_NAKED_EDGES_SMOOTH, &expected), WEFT_STATUS_OK);
  CHECK(weft_mesh_vertex_count(smooth) == weft_mesh_vertex_count(expected) && !weft_mesh_is_borrowed(smooth));
  CHECK(memcmp(weft_mesh_positions(smooth), weft_mesh_positions(expected),
               3 * sizeof(double) * weft_mesh_vertex_count(expected)) == 0);
  /* Level 0 gives the cage back, as a mesh of its own. */
  CHECK_STATUS(weft_catmull_clark(borrowed, 0, WEFT_NAKED_EDGES_SMOOTH, &clone), WEFT_STATUS_OK);
  CHECK(!weft_mesh_is_borrowed(clone) && weft_mesh_positions(clone) != positions);
  CHECK(memcmp(positions, cube_positions, sizeof positions) == 0 && memcmp(indices, cube_indices, sizeof indices) == 0);
  weft_mesh_free(borrowed);
  /* The clone outlives the borrowed mesh and the caller's arrays. */
  memset(positions, 0, sizeof positions);
  CHECK(weft_mesh_positions(clone)[3] == 1.0);
  weft_mesh_free(clone);
  weft_mesh_free(smooth);
  weft_mesh_free(expected);
  weft_mesh_free(copied);

  /* Mixed sizes: the sizes are copied and may be freed after the call. */
  {
    uint32_t sizes[2] = {3, 4};
    CHECK_STATUS(weft_mesh_new_borrowed(cube_positions, 8, sizes, 2, mixed, 7, 0, &borrowed), WEFT_STATUS_OK);
    sizes[0] = sizes[1] = 0;
    CHECK(memcmp(weft_mesh_face_sizes(borrowed), mixed_sizes, sizeof mixed_sizes) == 0);
    CHECK(weft_mesh_face_indices(borrowed) == mixed);
    weft_mesh_free(borrowed);
  }

  borrowed = NULL;
  CHECK_FAILS_WITH(weft_mesh_new_borrowed(cube_positions, 4, tri, 1, out_of_range, 3, 0, &borrowed),
                   WEFT_STATUS_INDEX_OUT_OF_RANGE, "face 0, corner 2: vertex index 9 is out of range");
  CHECK_FAILS_WITH(weft_mesh_new_borrowed(cube_positions, 8, cube_sizes, 6, cube_indices, 23, 0, &borrowed),
                   WEFT_STATUS_COUNT_MISMATCH, "add up to 24 indices but 23");
  CHECK_FAILS_WITH(weft_mesh_new_borrowed(cube_positions, 8, cube_sizes, 6, cube_indices, 24, 2, &borrowed),
                   WEFT_STATUS_INVALID_ARGUMENT, "unknown bits 0x2");
  CHECK_FAILS_WITH(weft_mesh_new_borrowed(NULL, 8, cube_sizes, 6, cube_indices, 24, 0, &borrowed),
                   WEFT_STATUS_NULL_POINTER, "positions is NULL");
  /* A pointer that is not aligned for doubles is refused, not read. */
  CHECK_FAILS_WITH(weft_mesh_new_borrowed((const double *)((const char *)positions + 1), 2, tri, 1, mixed, 3, 0,
                                          &borrowed),
                   WEFT_STATUS_INVALID_ARGUMENT, "positions at");
  CHECK_MESSAGE("is not aligned to 8 bytes");
  CHECK(borrowed == NULL);
}

static void test_version(void) {
  char expected[32];
  snprintf(expected, sizeof expected, "%d.%d.%d", WEFT_VERSION_MAJOR, WEFT_VERSION_MINOR, WEFT_VERSION_PATCH);
  CHECK(strcmp(weft_version(), expected) == 0);
}

int main(void) {
  test_construction_and_accessors();
  test_empty_mesh();
  test_info();
  test_construction_errors();
  test_repeated_vertices();
  test_borrowed_mesh();
  test_version();
  return check_summary("test_mesh");
}
