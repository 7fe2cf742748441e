/* Subdivision through the C ABI: Catmull-Clark and Loop on a cube and an
 * open grid in each naked-edge mode, parent faces, triangulation, the
 * refiner, and every bad argument with its own status and message. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"

static const double cube_positions[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0,
                                        0, 0, 1, 1, 0, 1, 0, 1, 1, 1, 1, 1};
static const uint32_t cube_sizes[] = {4, 4, 4, 4, 4, 4};
static const uint32_t cube_indices[] = {0, 2, 3, 1, 4, 5, 7, 6, 0, 1, 5, 4,
                                        2, 6, 7, 3, 0, 4, 6, 2, 1, 3, 7, 5};

/* A 2 x 2 grid of unit quads in z = 0, vertex (i, j) = 3 j + i, bent up
 * in the middle so that smoothing moves its border. */
static const double grid_positions[] = {0, 0, 0, 1, 0, 0.5, 2, 0, 0, 0, 1, 0.5, 1, 1, 1,
                                        2, 1, 0.5, 0, 2, 0, 1, 2, 0.5, 2, 2, 0};
static const uint32_t grid_sizes[] = {4, 4, 4, 4};
static const uint32_t grid_indices[] = {0, 1, 4, 3, 1, 2, 5, 4, 3, 4, 7, 6, 4, 5, 8, 7};

static WeftMesh *make(const double *p, size_t nv, const uint32_t *s, size_t nf, const uint32_t *i, size_t ni) {
  WeftMesh *mesh = NULL;
  CHECK_STATUS(weft_mesh_new(p, nv, s, nf, i, ni, &mesh), WEFT_STATUS_OK);
  return mesh;
}

static WeftMesh *cube(void) { return make(cube_positions, 8, cube_sizes, 6, cube_indices, 24); }
static WeftMesh *grid(void) { return make(grid_positions, 9, grid_sizes, 4, grid_indices, 16); }

static int same_point(const double *a, const double *b) {
  return fabs(a[0] - b[0]) < 1e-12 && fabs(a[1] - b[1]) < 1e-12 && fabs(a[2] - b[2]) < 1e-12;
}

static void test_cube(void) {
  WeftMesh *mesh = cube(), *out = NULL;
  const double *p;
  size_t f;
  CHECK_STATUS(weft_catmull_clark(mesh, 2, WEFT_NAKED_EDGES_SMOOTH, &out), WEFT_STATUS_OK);
  /* Level 1: 8 + 12 + 6 vertices, 24 quads; level 2: 26 + 48 + 24, 96 quads. */
  CHECK(weft_mesh_vertex_count(out) == 98);
  CHECK(weft_mesh_face_count(out) == 96);
  for (f = 0; f < weft_mesh_face_count(out); ++f) CHECK(weft_mesh_face_sizes(out)[f] == 4);
  weft_mesh_free(out);

  CHECK_STATUS(weft_catmull_clark(mesh, 1, WEFT_NAKED_EDGES_FIXED, &out), WEFT_STATUS_OK);
  p = weft_mesh_positions(out);
  /* A cube has no naked edges: corner 0 goes to 2/9 (2/9, 2/9) in every mode. */
  CHECK(fabs(p[0] - 2.0 / 9.0) < 1e-15 && fabs(p[1] - 2.0 / 9.0) < 1e-15 && fabs(p[2] - 2.0 / 9.0) < 1e-15);
  /* The first child of face 0 starts at its first corner; its third vertex is face point 0 (index 20). */
  CHECK(weft_mesh_face_indices(out)[0] == 0 && weft_mesh_face_indices(out)[2] == 20);
  weft_mesh_free(out);

  CHECK_STATUS(weft_catmull_clark(mesh, 0, WEFT_NAKED_EDGES_SMOOTH, &out), WEFT_STATUS_OK);
  CHECK(weft_mesh_vertex_count(out) == 8 && memcmp(weft_mesh_positions(out), cube_positions, sizeof cube_positions) == 0);
  weft_mesh_free(out);
  weft_mesh_free(mesh);
}

static void test_grid_modes(void) {
  WeftMesh *mesh = grid(), *fixed = NULL, *smooth = NULL, *corner = NULL;
  CHECK_STATUS(weft_catmull_clark(mesh, 2, WEFT_NAKED_EDGES_FIXED, &fixed), WEFT_STATUS_OK);
  CHECK_STATUS(weft_catmull_clark(mesh, 2, WEFT_NAKED_EDGES_SMOOTH, &smooth), WEFT_STATUS_OK);
  CHECK_STATUS(weft_catmull_clark(mesh, 2, WEFT_NAKED_EDGES_CORNER_FIXED, &corner), WEFT_STATUS_OK);
  CHECK(weft_mesh_face_count(fixed) == 64);
  {
    const double *pf = weft_mesh_positions(fixed), *ps = weft_mesh_positions(smooth),
                 *pc = weft_mesh_positions(corner);
    int v;
    /* Fixed: every boundary vertex (all but 4) stays. */
    for (v = 0; v < 9; ++v)
      if (v != 4) CHECK(same_point(pf + 3 * v, grid_positions + 3 * v));
    /* Corner fixed: the one-face corners 0, 2, 6, 8 stay; side vertex 1 moves. */
    CHECK(same_point(pc + 0, grid_positions + 0));
    CHECK(same_point(pc + 24, grid_positions + 24));
    CHECK(!same_point(pc + 3, grid_positions + 3));
    /* Smooth: the corners move too. */
    CHECK(!same_point(ps + 0, grid_positions + 0));
    CHECK(!same_point(ps + 3, grid_positions + 3));
  }
  weft_mesh_free(fixed);
  weft_mesh_free(smooth);
  weft_mesh_free(corner);
  weft_mesh_free(mesh);
}

static void test_loop_and_triangulate(void) {
  WeftMesh *mesh = grid(), *triangles = NULL, *out = NULL;
  uint32_t parents[32];
  size_t count = 0;
  CHECK_STATUS(weft_loop(mesh, 1, WEFT_NAKED_EDGES_SMOOTH, &out), WEFT_STATUS_NOT_TRIANGLES);
  CHECK_MESSAGE("face 0 has 4 vertices");
  CHECK_MESSAGE("triangulate");
  CHECK(out == NULL);
  CHECK_STATUS(weft_triangulate(mesh, &triangles), WEFT_STATUS_OK);
  CHECK(weft_mesh_face_count(triangles) == 8 && weft_mesh_vertex_count(triangles) == 9);
  CHECK_STATUS(weft_loop(triangles, 1, WEFT_NAKED_EDGES_FIXED, &out), WEFT_STATUS_OK);
  /* 9 vertices + 16 edges; 32 triangles. */
  CHECK(weft_mesh_vertex_count(out) == 25 && weft_mesh_face_count(out) == 32);
  CHECK(same_point(weft_mesh_positions(out), grid_positions));
  weft_mesh_free(out);

  CHECK_STATUS(weft_subdivision_face_count(triangles, WEFT_SCHEME_LOOP, 1, &count), WEFT_STATUS_OK);
  CHECK(count == 32);
  CHECK_STATUS(weft_subdivision_parent_faces(triangles, WEFT_SCHEME_LOOP, 1, parents, 32), WEFT_STATUS_OK);
  CHECK(parents[0] == 0 && parents[3] == 0 && parents[4] == 1 && parents[31] == 7);
  parents[0] = 99;
  CHECK_STATUS(weft_subdivision_parent_faces(triangles, WEFT_SCHEME_LOOP, 1, parents, 31), WEFT_STATUS_BUFFER_TOO_SMALL);
  CHECK_MESSAGE("out_parents has room for 31 elements but 32 are needed");
  CHECK(parents[0] == 99);
  CHECK_STATUS(weft_subdivision_parent_faces(mesh, WEFT_SCHEME_CATMULL_CLARK, 1, parents, 32), WEFT_STATUS_OK);
  CHECK(parents[0] == 0 && parents[15] == 3);
  weft_mesh_free(triangles);
  weft_mesh_free(mesh);
}

static void test_refiner(void) {
  WeftMesh *mesh = cube(), *one_shot = NULL, *moved_cube = NULL, *from_refiner = NULL;
  WeftRefiner *refiner = NULL;
  double moved[24], *out;
  size_t n, i;
  CHECK_STATUS(weft_refiner_new(mesh, WEFT_SCHEME_CATMULL_CLARK, 2, WEFT_NAKED_EDGES_SMOOTH, &refiner), WEFT_STATUS_OK);
  n = weft_refiner_vertex_count(refiner);
  CHECK(n == 98 && weft_refiner_face_count(refiner) == 96);
  CHECK_STATUS(weft_refiner_mesh(refiner, &from_refiner), WEFT_STATUS_OK);
  CHECK_STATUS(weft_catmull_clark(mesh, 2, WEFT_NAKED_EDGES_SMOOTH, &one_shot), WEFT_STATUS_OK);
  CHECK(memcmp(weft_mesh_positions(from_refiner), weft_mesh_positions(one_shot), 3 * n * sizeof(double)) == 0);
  weft_mesh_free(one_shot);
  weft_mesh_free(from_refiner);

  for (i = 0; i < 24; ++i) moved[i] = 2.0 * cube_positions[i] + (double)(i % 5);
  out = malloc(3 * n * sizeof(double));
  CHECK_STATUS(weft_refiner_evaluate(refiner, moved, 8, out, 3 * n), WEFT_STATUS_OK);
  moved_cube = make(moved, 8, cube_sizes, 6, cube_indices, 24);
  CHECK_STATUS(weft_catmull_clark(moved_cube, 2, WEFT_NAKED_EDGES_SMOOTH, &one_shot), WEFT_STATUS_OK);
  CHECK(memcmp(out, weft_mesh_positions(one_shot), 3 * n * sizeof(double)) == 0);
  CHECK_STATUS(weft_refiner_evaluate(refiner, moved, 7, out, 3 * n), WEFT_STATUS_COUNT_MISMATCH);
  CHECK_MESSAGE("vertex_count is 7");
  CHECK_STATUS(weft_refiner_evaluate(refiner, moved, 8, out, 3 * n - 1), WEFT_STATUS_BUFFER_TOO_SMALL);
  CHECK_STATUS(weft_refiner_evaluate(NULL, moved, 8, out, 3 * n), WEFT_STATUS_NULL_POINTER);
  free(out);
  weft_mesh_free(one_shot);
  weft_mesh_free(moved_cube);
  weft_refiner_free(refiner);
  weft_refiner_free(NULL);
  weft_mesh_free(mesh);
}

static void test_bad_arguments(void) {
  WeftMesh *mesh = cube(), *out = NULL;
  WeftRefiner *refiner = NULL;
  CHECK_STATUS(weft_catmull_clark(mesh, 16, WEFT_NAKED_EDGES_SMOOTH, &out), WEFT_STATUS_RESULT_TOO_LARGE);
  CHECK_MESSAGE("level 14 would make 1610612736 faces");
  CHECK_STATUS(weft_loop(mesh, 1, WEFT_NAKED_EDGES_SMOOTH, &out), WEFT_STATUS_NOT_TRIANGLES);
  CHECK_MESSAGE("face 0 has 4 vertices but this operation needs a triangle mesh; triangulate the mesh first");
  CHECK_STATUS(weft_catmull_clark(mesh, 1, 7, &out), WEFT_STATUS_INVALID_ARGUMENT);
  CHECK_MESSAGE("naked_edges is 7");
  CHECK_STATUS(weft_catmull_clark(NULL, 1, WEFT_NAKED_EDGES_SMOOTH, &out), WEFT_STATUS_NULL_POINTER);
  CHECK_MESSAGE("mesh is NULL");
  CHECK_STATUS(weft_loop(NULL, 1, WEFT_NAKED_EDGES_SMOOTH, &out), WEFT_STATUS_NULL_POINTER);
  CHECK_STATUS(weft_catmull_clark(mesh, 1, WEFT_NAKED_EDGES_SMOOTH, NULL), WEFT_STATUS_NULL_POINTER);
  CHECK_MESSAGE("out_mesh is NULL");
  CHECK_STATUS(weft_triangulate(NULL, &out), WEFT_STATUS_NULL_POINTER);
  CHECK(out == NULL);
  CHECK_STATUS(weft_refiner_new(mesh, 2, 1, WEFT_NAKED_EDGES_SMOOTH, &refiner), WEFT_STATUS_INVALID_ARGUMENT);
  CHECK_MESSAGE("scheme is 2");
  CHECK_STATUS(weft_refiner_new(mesh, WEFT_SCHEME_LOOP, 1, WEFT_NAKED_EDGES_SMOOTH, &refiner), WEFT_STATUS_NOT_TRIANGLES);
  CHECK(refiner == NULL);
  weft_mesh_free(mesh);
}

int main(void) {
  test_cube();
  test_grid_modes();
  test_loop_and_triangulate();
  test_refiner();
  test_bad_arguments();
  return check_summary("test_subdivide");
}
