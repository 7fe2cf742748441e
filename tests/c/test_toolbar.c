/* The toolbar exports through the C ABI: each one's success path on a named
 * shape with its counts, and one error path with its status and message. */
#include <math.h>
#include <string.h>

#include "check.h"

static const double tetra_positions[] = {1, 1, 1, 1, -1, -1, -1, 1, -1, -1, -1, 1};
static const uint32_t tetra_sizes[] = {3, 3, 3, 3};
static const uint32_t tetra_indices[] = {0, 1, 2, 0, 3, 1, 0, 2, 3, 1, 3, 2};
/* A 2 x 2 grid of unit quads in z = 0. */
static const double grid_positions[] = {0, 0, 0, 1, 0, 0, 2, 0, 0, 0, 1, 0, 1, 1, 0,
                                        2, 1, 0, 0, 2, 0, 1, 2, 0, 2, 2, 0};
static const uint32_t grid_sizes[] = {4, 4, 4, 4};
static const uint32_t grid_indices[] = {0, 1, 4, 3, 1, 2, 5, 4, 3, 4, 7, 6, 4, 5, 8, 7};

static WeftMesh *tetra(void) { return make_mesh(tetra_positions, 4, tetra_sizes, 4, tetra_indices, 12); }
static WeftMesh *grid(void) { return make_mesh(grid_positions, 9, grid_sizes, 4, grid_indices, 16); }

/* Checks a result's counts and frees it. */
static void expect(WeftMesh *mesh, size_t vertices, size_t faces) {
  CHECK(mesh != NULL);
  CHECK(weft_mesh_vertex_count(mesh) == vertices);
  CHECK(weft_mesh_face_count(mesh) == faces);
  weft_mesh_free(mesh);
}

static void test_subdivisions(void) {
  WeftMesh *c = unit_cube(), *t = tetra(), *out = NULL, *untouched = (WeftMesh *)&out;
  CHECK_STATUS(weft_split_polygons(c, 1, &out), WEFT_STATUS_OK);
  expect(out, 26, 24);
  CHECK_STATUS(weft_split_polygons(c, 21, &out), WEFT_STATUS_INVALID_ARGUMENT);
  CHECK_MESSAGE("levels is 21");
  CHECK_STATUS(weft_split_polygons(c, 20, &out), WEFT_STATUS_RESULT_TOO_LARGE);
  CHECK_STATUS(weft_split_triangles(t, 1, &out), WEFT_STATUS_OK);
  expect(out, 10, 16);
  out = untouched;
  CHECK_STATUS(weft_split_triangles(c, 1, &out), WEFT_STATUS_NOT_TRIANGLES);
  CHECK_MESSAGE("face 0 has 4 vertices");
  CHECK(out == untouched);
  CHECK_STATUS(weft_constant_quads_split(c, 1, &out), WEFT_STATUS_OK);
  expect(out, 26, 24);
  CHECK_STATUS(weft_constant_quads_split(NULL, 1, &out), WEFT_STATUS_NULL_POINTER);
  CHECK_MESSAGE("mesh is NULL");
  CHECK_STATUS(weft_midedge(c, 1, &out), WEFT_STATUS_OK);
  expect(out, 12, 14);
  CHECK_STATUS(weft_midedge(c, 1, NULL), WEFT_STATUS_NULL_POINTER);
  CHECK_MESSAGE("out_mesh is NULL");
  CHECK_STATUS(weft_inner_polygons(c, 1, 0.5, &out), WEFT_STATUS_OK);
  expect(out, 32, 30);
  CHECK_STATUS(weft_inner_polygons(c, 1, 1.0, &out), WEFT_STATUS_INVALID_ARGUMENT);
  CHECK_MESSAGE("pull is 1");
  CHECK_STATUS(weft_sierpinski_triangles(t, 2, &out), WEFT_STATUS_OK);
  expect(out, 34, 36);
  CHECK_STATUS(weft_sierpinski_triangles(t, 99, &out), WEFT_STATUS_INVALID_ARGUMENT);
  weft_mesh_free(c);
  weft_mesh_free(t);
}

static void test_smoothing(void) {
  WeftMesh *g = grid(), *out = NULL;
  double values[9] = {0, 0, 0, 0, 1, 0, 0, 0, 0}, blurred[9];
  CHECK_STATUS(weft_laplacian_smooth(g, 3, 0.5, WEFT_NAKED_EDGES_FIXED, &out), WEFT_STATUS_OK);
  CHECK(memcmp(weft_mesh_positions(out), grid_positions, sizeof grid_positions) == 0);
  weft_mesh_free(out);
  CHECK_STATUS(weft_laplacian_smooth(g, 3, 0.5, 7, &out), WEFT_STATUS_INVALID_ARGUMENT);
  CHECK_MESSAGE("naked_edges is 7");
  CHECK_STATUS(weft_laplacian_hc_smooth(g, 3, 0.0, 0.6, WEFT_NAKED_EDGES_SMOOTH, &out), WEFT_STATUS_OK);
  expect(out, 9, 4);
  CHECK_STATUS(weft_laplacian_hc_smooth(g, 3, 0.0, 2.0, WEFT_NAKED_EDGES_SMOOTH, &out), WEFT_STATUS_INVALID_ARGUMENT);
  CHECK_MESSAGE("beta is 2");
  {
    /* Only the middle vertex is active; the side vertex 1 may slide but is inactive. */
    double activation[9] = {0, 0, 0, 0, 1, 0, 0, 0, 0};
    WeftMesh *bumped = NULL;
    double p[27];
    memcpy(p, grid_positions, sizeof p);
    p[4 * 3 + 2] = 1.0; /* lift the middle vertex: its normal is +z */
    bumped = make_mesh(p, 9, grid_sizes, 4, grid_indices, 16);
    CHECK_STATUS(weft_laplacian_hc_smooth_ex(bumped, 1, 0.0, 0.6, WEFT_NAKED_EDGES_SMOOTH, WEFT_SMOOTH_DIRECTION_FREE,
                                             activation, 9, &out),
                 WEFT_STATUS_OK);
    CHECK(memcmp(weft_mesh_positions(out), p, 4 * 3 * sizeof(double)) == 0);
    CHECK(weft_mesh_positions(out)[4 * 3 + 2] < 1.0);
    weft_mesh_free(out);
    /* Tangentially the middle vertex stays in its plane z = 1. */
    CHECK_STATUS(weft_laplacian_hc_smooth_ex(bumped, 2, 0.0, 0.6, WEFT_NAKED_EDGES_FIXED,
                                             WEFT_SMOOTH_DIRECTION_TANGENTIAL, NULL, 0, &out),
                 WEFT_STATUS_OK);
    CHECK(fabs(weft_mesh_positions(out)[4 * 3 + 2] - 1.0) < 1e-12);
    weft_mesh_free(out);
    out = NULL;
    CHECK_STATUS(weft_laplacian_hc_smooth_ex(bumped, 1, 0.0, 0.6, WEFT_NAKED_EDGES_FIXED, WEFT_SMOOTH_DIRECTION_FREE,
                                             activation, 8, &out),
                 WEFT_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("activation has 8 values but the mesh has 9 vertices");
    CHECK(out == NULL);
    CHECK_STATUS(weft_laplacian_hc_smooth_ex(bumped, 1, 0.0, 0.6, WEFT_NAKED_EDGES_FIXED, 3, NULL, 0, &out),
                 WEFT_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("direction is 3");
    CHECK_STATUS(weft_laplacian_hc_smooth_ex(bumped, 1, 0.0, 0.6, WEFT_NAKED_EDGES_FIXED, WEFT_SMOOTH_DIRECTION_FREE,
                                             NULL, 9, &out),
                 WEFT_STATUS_NULL_POINTER);
    weft_mesh_free(bumped);
  }
  CHECK_STATUS(weft_blur_values(g, values, 9, 1, 1, 0.5, WEFT_NAKED_EDGES_CORNER_FIXED, blurred, 9), WEFT_STATUS_OK);
  CHECK(blurred[4] == 0.5 && blurred[0] == 0.0);
  blurred[0] = -1.0;
  CHECK_STATUS(weft_blur_values(g, values, 8, 1, 1, 0.5, WEFT_NAKED_EDGES_FIXED, blurred, 9), WEFT_STATUS_INVALID_ARGUMENT);
  CHECK_MESSAGE("8 values");
  CHECK_STATUS(weft_blur_values(g, values, 9, 1, 1, 0.5, WEFT_NAKED_EDGES_FIXED, blurred, 4), WEFT_STATUS_BUFFER_TOO_SMALL);
  CHECK(blurred[0] == -1.0);
  weft_mesh_free(g);
}

static void test_transforms(void) {
  WeftMesh *c = unit_cube(), *g = grid(), *out = NULL;
  WeftMeshInfo info;
  double two[2] = {0.1, 0.2}, one = 0.1;
  CHECK_STATUS(weft_offset_mesh(c, 0.5, WEFT_OFFSET_PLANES_INTERSECTION, &out), WEFT_STATUS_OK);
  CHECK(fabs(weft_mesh_positions(out)[0] + 0.5) < 1e-12);
  expect(out, 8, 6);
  CHECK_STATUS(weft_offset_mesh(c, 0.5, 3, &out), WEFT_STATUS_INVALID_ARGUMENT);
  CHECK_MESSAGE("offset_type is 3");
  CHECK_STATUS(weft_thicken_mesh(g, 0.2, WEFT_OFFSET_DIAGONAL, &out), WEFT_STATUS_OK);
  CHECK_STATUS(weft_mesh_info(out, &info), WEFT_STATUS_OK);
  CHECK(info.is_closed && info.is_oriented && info.face_count == 16);
  weft_mesh_free(out);
  CHECK_STATUS(weft_thicken_mesh(g, NAN, WEFT_OFFSET_DIAGONAL, &out), WEFT_STATUS_INVALID_ARGUMENT);
  CHECK_STATUS(weft_mesh_window(c, &one, 1, WEFT_INSET_PARALLELOGRAM, &out), WEFT_STATUS_OK);
  expect(out, 32, 30);
  CHECK_STATUS(weft_mesh_window(c, two, 2, WEFT_INSET_EDGE_FRACTION, &out), WEFT_STATUS_INVALID_ARGUMENT);
  CHECK_MESSAGE("2 distances were given for a mesh of 6 faces");
  CHECK_STATUS(weft_picture_frame(c, &one, 1, WEFT_INSET_EDGE_FRACTION, &out), WEFT_STATUS_OK);
  expect(out, 32, 24);
  CHECK_STATUS(weft_picture_frame(c, NULL, 1, WEFT_INSET_EDGE_FRACTION, &out), WEFT_STATUS_NULL_POINTER);
  CHECK_STATUS(weft_sierpinski_carpet(g, 1, &out), WEFT_STATUS_OK);
  expect(out, 9 + 2 * 12 + 16, 32);
  {
    WeftMesh *t = tetra();
    CHECK_STATUS(weft_sierpinski_carpet(t, 1, &out), WEFT_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("needs a quad mesh");
    weft_mesh_free(t);
  }
  CHECK_STATUS(weft_bevel_edges(c, 0.25, &out), WEFT_STATUS_OK);
  expect(out, 24, 26);
  CHECK_STATUS(weft_bevel_edges(c, 0.0, &out), WEFT_STATUS_INVALID_ARGUMENT);
  CHECK_STATUS(weft_bevel_vertices(c, 0.25, &out), WEFT_STATUS_OK);
  expect(out, 24, 14);
  CHECK_STATUS(weft_bevel_vertices(c, 0.5, &out), WEFT_STATUS_INVALID_ARGUMENT);
  CHECK_MESSAGE("fraction is 0.5");
  weft_mesh_free(c);
  weft_mesh_free(g);
}

static void test_extract(void) {
  WeftMesh *c = unit_cube(), *out = NULL;
  size_t count = 0;
  uint32_t pairs[24];
  double segments[72];
  /* The 3 x 3 grid of lines x = 0, 1, 2 and y = 0, 1, 2, cut at crossings. */
  double lines[12 * 6];
  size_t k = 0;
  int i, j;
  CHECK_STATUS(weft_dual(c, WEFT_DUAL_VERTEX_AVERAGE, &out), WEFT_STATUS_OK);
  expect(out, 6, 8);
  CHECK_STATUS(weft_dual(c, 2, &out), WEFT_STATUS_INVALID_ARGUMENT);
  CHECK_STATUS(weft_mesh_edge_count(c, &count), WEFT_STATUS_OK);
  CHECK(count == 12);
  CHECK_STATUS(weft_mesh_edge_count(c, NULL), WEFT_STATUS_NULL_POINTER);
  CHECK_STATUS(weft_mesh_copy_edges(c, pairs, 24), WEFT_STATUS_OK);
  CHECK(pairs[0] == 0 && pairs[1] == 1);
  CHECK_STATUS(weft_mesh_copy_edges(c, pairs, 23), WEFT_STATUS_BUFFER_TOO_SMALL);
  CHECK_MESSAGE("out_pairs has room for 23 elements but 24 are needed");
  CHECK_STATUS(weft_mesh_copy_edge_segments(c, segments, 72), WEFT_STATUS_OK);
  CHECK(segments[3] == 1.0 && segments[0] == 0.0);
  CHECK_STATUS(weft_mesh_copy_edge_segments(c, NULL, 0), WEFT_STATUS_BUFFER_TOO_SMALL);
  CHECK_STATUS(weft_reroute_faces(c, 1, &out), WEFT_STATUS_OK);
  CHECK(weft_mesh_face_indices(out)[0] == cube_indices[1]);
  CHECK(weft_mesh_face_indices(out)[3] == cube_indices[0]);
  weft_mesh_free(out);
  CHECK_STATUS(weft_reroute_faces(NULL, 1, &out), WEFT_STATUS_NULL_POINTER);
  for (i = 0; i < 3; i++) {
    for (j = 0; j < 2; j++) {
      double a[12] = {i, j, 0, i, j + 1, 0, j, i, 0, j + 1, i, 0};
      memcpy(lines + k, a, sizeof a);
      k += 12;
    }
  }
  CHECK_STATUS(weft_mesh_from_lines(lines, 12, 1e-9, 4, &out), WEFT_STATUS_OK);
  expect(out, 9, 4);
  CHECK_STATUS(weft_mesh_from_lines(lines, 12, 1e-9, 2, &out), WEFT_STATUS_INVALID_ARGUMENT);
  CHECK_MESSAGE("max_valence is 2");
  CHECK_STATUS(weft_mesh_from_lines(NULL, 0, 0.0, 4, &out), WEFT_STATUS_OK);
  expect(out, 0, 0);
  weft_mesh_free(c);
}

static void test_tile(void) {
  WeftMesh *c = unit_cube(), *g = grid(), *out = NULL, *untouched = (WeftMesh *)&out;
  WeftMeshInfo info;
  uint32_t corners[4];
  CHECK_STATUS(weft_tile(c, WEFT_TILE_FILL_TRIANGLE_FAN, WEFT_TILE_FACES_ALL, &out), WEFT_STATUS_OK);
  CHECK_STATUS(weft_mesh_info(out, &info), WEFT_STATUS_OK);
  CHECK(info.vertex_count == 14 && info.face_count == 24 && info.is_closed && info.is_oriented);
  /* The first face's centroid comes right after the cube's 8 vertices. */
  CHECK(weft_mesh_positions(out)[8 * 3 + 0] == 0.5 && weft_mesh_positions(out)[8 * 3 + 2] == 0.0);
  weft_mesh_free(out);
  CHECK_STATUS(weft_tile(c, WEFT_TILE_FILL_TRIANGLE_HAND, WEFT_TILE_FACES_QUADS, &out), WEFT_STATUS_OK);
  CHECK_STATUS(weft_mesh_info(out, &info), WEFT_STATUS_OK);
  CHECK(info.vertex_count == 8 && info.face_count == 12 && info.is_closed && info.is_oriented);
  weft_mesh_free(out);
  /* Only triangles chosen: the quads of the grid stay as they are. */
  CHECK_STATUS(weft_tile(g, WEFT_TILE_FILL_QUAD_FAN, WEFT_TILE_FACES_TRIANGLES, &out), WEFT_STATUS_OK);
  CHECK(weft_mesh_face_count(out) == 4 && weft_mesh_vertex_count(out) == 9);
  memcpy(corners, weft_mesh_face_indices(out), sizeof corners);
  CHECK(memcmp(corners, grid_indices, sizeof corners) == 0);
  weft_mesh_free(out);
  out = untouched;
  CHECK_STATUS(weft_tile(c, 8, WEFT_TILE_FACES_ALL, &out), WEFT_STATUS_INVALID_ARGUMENT);
  CHECK_MESSAGE("fill is 8");
  CHECK_STATUS(weft_tile(c, WEFT_TILE_FILL_BEST, 3, &out), WEFT_STATUS_INVALID_ARGUMENT);
  CHECK_MESSAGE("faces is 3");
  CHECK(out == untouched);
  weft_mesh_free(c);
  weft_mesh_free(g);
}

int main(void) {
  test_subdivisions();
  test_smoothing();
  test_transforms();
  test_extract();
  test_tile();
  return check_summary("test_toolbar");
}
