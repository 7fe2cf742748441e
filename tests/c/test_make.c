/* The making tools through the C ABI: Delaunay, Voronoi cells, mesh from a
 * grid, stellate and the primitives, each with its success and error paths. */
#include <math.h>
#include <string.h>

#include "check.h"

static double cell_area(const double *corners, uint32_t size) {
  double area = 0.0;
  uint32_t k;
  for (k = 0; k < size; ++k) {
    const double *a = corners + 3 * k, *b = corners + 3 * ((k + 1) % size);
    area += a[0] * b[1] - b[0] * a[1];
  }
  return 0.5 * area;
}

static void test_delaunay(void) {
  /* A square with its centre, and a repeat of the first corner raised. */
  const double points[] = {0, 0, 0, 2, 0, 0, 2, 2, 0, 0, 2, 0, 1, 1, 5, 0, 0, 3};
  const WeftPlane plane = {{0, 0, -1}, {2, 0, 0}, {0, 3, 0}};
  const WeftPlane flipped = {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}};
  const WeftPlane parallel = {{0, 0, 0}, {1, 0, 0}, {-2, 0, 0}};
  const double line[] = {0, 0, 0, 1, 1, 0, 2, 2, 0, 3, 3, 0};
  double bad[] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  WeftMesh *mesh = NULL;
  size_t merged = 99;
  const double *positions;
  const uint32_t *indices;
  size_t f;
  CHECK_STATUS(weft_delaunay(points, 6, &plane, &mesh, &merged), WEFT_STATUS_OK);
  CHECK(merged == 1);
  CHECK(weft_mesh_vertex_count(mesh) == 5 && weft_mesh_face_count(mesh) == 4);
  positions = weft_mesh_positions(mesh);
  indices = weft_mesh_face_indices(mesh);
  CHECK(positions[14] == 5.0); /* the centre keeps its height */
  for (f = 0; f < 4; ++f) {
    const double *a = positions + 3 * indices[3 * f], *b = positions + 3 * indices[3 * f + 1],
                 *c = positions + 3 * indices[3 * f + 2];
    CHECK((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]) > 0.0);
  }
  weft_mesh_free(mesh);
  /* Seen from below, the triangles turn the other way; out_merged may be NULL. */
  mesh = NULL;
  CHECK_STATUS(weft_delaunay(points, 5, &flipped, &mesh, NULL), WEFT_STATUS_OK);
  positions = weft_mesh_positions(mesh);
  indices = weft_mesh_face_indices(mesh);
  {
    const double *a = positions + 3 * indices[0], *b = positions + 3 * indices[1], *c = positions + 3 * indices[2];
    CHECK((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]) < 0.0);
  }
  weft_mesh_free(mesh);
  /* NULL plane is the XY plane. */
  mesh = NULL;
  CHECK_STATUS(weft_delaunay(points, 5, NULL, &mesh, NULL), WEFT_STATUS_OK);
  CHECK(weft_mesh_face_count(mesh) == 4);
  weft_mesh_free(mesh);

  mesh = NULL;
  CHECK_STATUS(weft_delaunay(line, 4, NULL, &mesh, &merged), WEFT_STATUS_DEGENERATE_INPUT);
  CHECK_MESSAGE("collinear");
  CHECK(mesh == NULL);
  CHECK_STATUS(weft_delaunay(points, 2, NULL, &mesh, NULL), WEFT_STATUS_DEGENERATE_INPUT);
  CHECK_MESSAGE("at least 3 distinct points");
  CHECK_STATUS(weft_delaunay(points, 5, &parallel, &mesh, NULL), WEFT_STATUS_DEGENERATE_INPUT);
  CHECK_MESSAGE("parallel");
  bad[4] = NAN;
  CHECK_STATUS(weft_delaunay(bad, 3, NULL, &mesh, NULL), WEFT_STATUS_NON_FINITE_COORDINATE);
  CHECK_MESSAGE("point 1");
  CHECK_STATUS(weft_delaunay(NULL, 3, NULL, &mesh, NULL), WEFT_STATUS_NULL_POINTER);
  CHECK_STATUS(weft_delaunay(points, 5, NULL, NULL, NULL), WEFT_STATUS_NULL_POINTER);
  CHECK_MESSAGE("out_mesh is NULL");
  CHECK(mesh == NULL);
}

static void test_voronoi(void) {
  const double points[] = {1, 1, 0, 3, 1, 0, 1, 3, 0, 3, 3, 0, 9, 9, 0};
  const double square[] = {0, 0, 0, 4, 0, 0, 4, 4, 0, 0, 4, 0};
  const double l_shape[] = {0, 0, 0, 4, 0, 0, 4, 2, 0, 2, 2, 0, 2, 4, 0, 0, 4, 0};
  const double bow_tie[] = {0, 0, 0, 4, 4, 0, 4, 0, 0, 0, 4, 0};
  WeftCells *cells = NULL;
  WeftMesh *mesh = NULL, *skin = NULL;
  uint32_t sizes[5];
  double corners[3 * 40];
  const uint32_t *view;
  size_t i, offset = 0;
  double total = 0.0;
  CHECK_STATUS(weft_voronoi(points, 5, NULL, square, 4, 0.0, &cells), WEFT_STATUS_OK);
  CHECK(weft_cells_count(cells) == 5);
  view = weft_cells_sizes(cells);
  CHECK(view[4] == 0); /* outside the boundary */
  CHECK(weft_cells_corner_count(cells) == 16);
  CHECK_STATUS(weft_cells_copy(cells, sizes, 5, corners, 48), WEFT_STATUS_OK);
  CHECK(memcmp(corners, weft_cells_corners(cells), 48 * sizeof(double)) == 0);
  for (i = 0; i < 5; ++i) {
    double area = cell_area(corners + 3 * offset, sizes[i]);
    CHECK(i == 4 || fabs(area - 4.0) < 1e-12);
    total += area;
    offset += sizes[i];
  }
  CHECK(fabs(total - 16.0) < 1e-12);
  sizes[0] = 77;
  CHECK_STATUS(weft_cells_copy(cells, sizes, 5, corners, 47), WEFT_STATUS_BUFFER_TOO_SMALL);
  CHECK_MESSAGE("out_corners");
  CHECK(sizes[0] == 77);
  CHECK_STATUS(weft_cells_copy(NULL, sizes, 5, corners, 48), WEFT_STATUS_NULL_POINTER);

  /* Cells to one n-gon face each, then a pyramid on each: the skin's first steps. */
  CHECK_STATUS(weft_cells_to_mesh(cells, &mesh), WEFT_STATUS_OK);
  CHECK(weft_mesh_face_count(mesh) == 4 && weft_mesh_vertex_count(mesh) == 16);
  {
    const double depth = -0.5;
    WeftMeshInfo info;
    CHECK_STATUS(weft_stellate(mesh, &depth, 1, &skin), WEFT_STATUS_OK);
    CHECK(weft_mesh_face_count(skin) == 16 && weft_mesh_vertex_count(skin) == 20);
    CHECK(weft_mesh_positions(skin)[3 * 16 + 2] == -0.5);
    CHECK_STATUS(weft_mesh_info(skin, &info), WEFT_STATUS_OK);
    CHECK(info.component_count == 4 && info.is_oriented && info.naked_edge_count == 16);
  }
  weft_mesh_free(skin);
  weft_mesh_free(mesh);
  weft_cells_free(cells);

  /* Default boundary, a radius, and a concave boundary. */
  cells = NULL;
  CHECK_STATUS(weft_voronoi(points, 4, NULL, NULL, 0, 0.15, &cells), WEFT_STATUS_OK);
  CHECK(weft_cells_count(cells) == 4 && weft_cells_sizes(cells)[0] == 64);
  weft_cells_free(cells);
  cells = NULL;
  CHECK_STATUS(weft_voronoi(points, 5, NULL, l_shape, 6, 0.0, &cells), WEFT_STATUS_OK);
  view = weft_cells_sizes(cells);
  CHECK(view[0] > 0 && view[1] > 0 && view[2] > 0 && view[3] == 0 && view[4] == 0);
  weft_cells_free(cells);
  weft_cells_free(NULL);
  CHECK(weft_cells_count(NULL) == 0 && weft_cells_sizes(NULL) == NULL && weft_cells_corners(NULL) == NULL);

  cells = NULL;
  CHECK_STATUS(weft_voronoi(points, 4, NULL, bow_tie, 4, 0.0, &cells), WEFT_STATUS_INVALID_ARGUMENT);
  CHECK_MESSAGE("not a simple polygon");
  CHECK_STATUS(weft_voronoi(points, 4, NULL, square, 4, -1.0, &cells), WEFT_STATUS_INVALID_ARGUMENT);
  CHECK_MESSAGE("radius");
  CHECK_STATUS(weft_voronoi(points, 4, NULL, square, 2, 0.0, &cells), WEFT_STATUS_INVALID_ARGUMENT);
  CHECK_STATUS(weft_voronoi(points, 4, NULL, NULL, 4, 0.0, &cells), WEFT_STATUS_NULL_POINTER);
  CHECK_STATUS(weft_voronoi(points, 4, NULL, NULL, 0, 0.0, NULL), WEFT_STATUS_NULL_POINTER);
  CHECK(cells == NULL);
  CHECK_STATUS(weft_cells_to_mesh(NULL, &mesh), WEFT_STATUS_NULL_POINTER);
}

static void test_mesh_from_grid(void) {
  double points[3 * 12];
  WeftMesh *mesh = NULL;
  WeftMeshInfo info;
  int u, v;
  for (v = 0; v < 3; ++v)
    for (u = 0; u < 4; ++u) {
      double *p = points + 3 * (v * 4 + u);
      p[0] = cos(u * 1.5707963267948966);
      p[1] = sin(u * 1.5707963267948966);
      p[2] = v;
    }
  CHECK_STATUS(weft_mesh_from_grid(points, 12, 4, 3, true, false, false, &mesh), WEFT_STATUS_OK);
  CHECK(weft_mesh_face_count(mesh) == 8 && weft_mesh_vertex_count(mesh) == 12);
  CHECK(weft_mesh_face_indices(mesh)[12] == 3 && weft_mesh_face_indices(mesh)[13] == 0);
  CHECK_STATUS(weft_mesh_info(mesh, &info), WEFT_STATUS_OK);
  CHECK(info.naked_edge_count == 8 && info.is_oriented && info.component_count == 1);
  weft_mesh_free(mesh);
  mesh = NULL;
  CHECK_STATUS(weft_mesh_from_grid(points, 12, 4, 3, false, false, true, &mesh), WEFT_STATUS_OK);
  CHECK(weft_mesh_face_count(mesh) == 12 && weft_mesh_index_count(mesh) == 36);
  weft_mesh_free(mesh);
  mesh = NULL;
  CHECK_STATUS(weft_mesh_from_grid(points, 11, 4, 3, false, false, false, &mesh), WEFT_STATUS_INVALID_ARGUMENT);
  CHECK_MESSAGE("11 points");
  CHECK_MESSAGE("4 × 3");
  CHECK_STATUS(weft_mesh_from_grid(points, 12, 6, 2, false, true, false, &mesh), WEFT_STATUS_INVALID_ARGUMENT);
  CHECK_MESSAGE("closed in v");
  points[7] = INFINITY;
  CHECK_STATUS(weft_mesh_from_grid(points, 12, 4, 3, false, false, false, &mesh), WEFT_STATUS_NON_FINITE_COORDINATE);
  CHECK_MESSAGE("point 2");
  CHECK_STATUS(weft_mesh_from_grid(points, 12, 4, 3, false, false, false, NULL), WEFT_STATUS_NULL_POINTER);
  CHECK(mesh == NULL);
}

static void test_stellate(void) {
  WeftMesh *cube = NULL, *out = NULL;
  const double heights[] = {1, 1, 1, 1, 1, NAN};
  const double one = 0.5;
  WeftMeshInfo info;
  CHECK_STATUS(weft_platonic(WEFT_PLATONIC_HEXAHEDRON, sqrt(3.0), &cube), WEFT_STATUS_OK);
  CHECK_STATUS(weft_stellate(cube, heights, 5, &out), WEFT_STATUS_INVALID_ARGUMENT);
  CHECK_MESSAGE("5 heights were given for a mesh of 6 faces");
  CHECK_STATUS(weft_stellate(cube, heights, 6, &out), WEFT_STATUS_INVALID_ARGUMENT);
  CHECK_MESSAGE("face 5");
  CHECK_STATUS(weft_stellate(cube, heights, 0, &out), WEFT_STATUS_INVALID_ARGUMENT);
  CHECK_STATUS(weft_stellate(NULL, &one, 1, &out), WEFT_STATUS_NULL_POINTER);
  CHECK_STATUS(weft_stellate(cube, NULL, 6, &out), WEFT_STATUS_NULL_POINTER);
  CHECK(out == NULL);
  CHECK_STATUS(weft_stellate(cube, &one, 1, NULL), WEFT_STATUS_NULL_POINTER);
  CHECK_STATUS(weft_stellate(cube, &one, 1, &out), WEFT_STATUS_OK);
  CHECK(weft_mesh_vertex_count(out) == 14 && weft_mesh_face_count(out) == 24);
  CHECK_STATUS(weft_mesh_info(out, &info), WEFT_STATUS_OK);
  CHECK(info.is_closed && info.is_oriented);
  {
    /* Each apex stands half a unit out from the middle of a face of the cube [-1, 1]^3. */
    const double *apex = weft_mesh_positions(out) + 3 * 8;
    CHECK(fabs(sqrt(apex[0] * apex[0] + apex[1] * apex[1] + apex[2] * apex[2]) - 1.5) < 1e-12);
  }
  weft_mesh_free(out);
  weft_mesh_free(cube);
}

static void check_closed(WeftMesh *mesh, size_t vertices, size_t faces) {
  WeftMeshInfo info;
  CHECK(mesh != NULL);
  CHECK(weft_mesh_vertex_count(mesh) == vertices && weft_mesh_face_count(mesh) == faces);
  CHECK_STATUS(weft_mesh_info(mesh, &info), WEFT_STATUS_OK);
  CHECK(info.is_closed && info.is_oriented && info.component_count == 1);
  CHECK(info.vertex_count + info.face_count - info.edge_count == 2);
  weft_mesh_free(mesh);
}

static void test_primitives(void) {
  static const size_t platonic_counts[5][2] = {{4, 4}, {8, 6}, {6, 8}, {20, 12}, {12, 20}};
  /* Each sided solid, the sides of its base, and the counts it must have. */
  static const struct {
    uint32_t kind;
    size_t sides, vertices, faces;
  } sided[4] = {{WEFT_SIDED_PRISM, 6, 12, 8},
                {WEFT_SIDED_ANTIPRISM, 6, 12, 14},
                {WEFT_SIDED_PYRAMID, 5, 6, 6},
                {WEFT_SIDED_DIPYRAMID, 5, 7, 10}};
  WeftMesh *mesh = NULL;
  WeftMeshInfo info;
  uint32_t kind;
  for (kind = 0; kind < 5; ++kind) {
    mesh = NULL;
    CHECK_STATUS(weft_platonic(kind, 1.0, &mesh), WEFT_STATUS_OK);
    check_closed(mesh, platonic_counts[kind][0], platonic_counts[kind][1]);
  }
  for (kind = 0; kind < 4; ++kind) {
    mesh = NULL;
    CHECK_STATUS(weft_sided_solid(sided[kind].kind, sided[kind].sides, 1.0, 2.0, &mesh), WEFT_STATUS_OK);
    check_closed(mesh, sided[kind].vertices, sided[kind].faces);
  }
  mesh = NULL;
  CHECK_STATUS(weft_box(1.0, 2.0, 3.0, 2, 2, 2, &mesh), WEFT_STATUS_OK);
  check_closed(mesh, 26, 24);
  mesh = NULL;
  CHECK_STATUS(weft_uv_sphere(1.0, 6, 4, &mesh), WEFT_STATUS_OK);
  check_closed(mesh, 20, 24);
  mesh = NULL;
  CHECK_STATUS(weft_plane_grid(2.0, 1.0, 2, 1, &mesh), WEFT_STATUS_OK);
  CHECK_STATUS(weft_mesh_info(mesh, &info), WEFT_STATUS_OK);
  CHECK(info.vertex_count == 6 && info.face_count == 2 && info.naked_edge_count == 6);
  weft_mesh_free(mesh);

  mesh = NULL;
  CHECK_STATUS(weft_platonic(5, 1.0, &mesh), WEFT_STATUS_INVALID_ARGUMENT);
  CHECK_MESSAGE("kind is 5");
  CHECK_STATUS(weft_platonic(WEFT_PLATONIC_ICOSAHEDRON, 0.0, &mesh), WEFT_STATUS_INVALID_ARGUMENT);
  CHECK_MESSAGE("radius is 0");
  CHECK_STATUS(weft_sided_solid(9, 5, 1.0, 1.0, &mesh), WEFT_STATUS_INVALID_ARGUMENT);
  CHECK_STATUS(weft_sided_solid(WEFT_SIDED_PRISM, 2, 1.0, 1.0, &mesh), WEFT_STATUS_INVALID_ARGUMENT);
  CHECK_MESSAGE("sides is 2");
  CHECK_STATUS(weft_box(1.0, NAN, 1.0, 1, 1, 1, &mesh), WEFT_STATUS_INVALID_ARGUMENT);
  CHECK_MESSAGE("size_y");
  CHECK_STATUS(weft_uv_sphere(1.0, 3, 1, &mesh), WEFT_STATUS_INVALID_ARGUMENT);
  CHECK_MESSAGE("v_count is 1");
  CHECK_STATUS(weft_plane_grid(1.0, 1.0, 0, 1, &mesh), WEFT_STATUS_INVALID_ARGUMENT);
  CHECK_STATUS(weft_plane_grid(1.0, 1.0, (size_t)1 << 20, (size_t)1 << 20, &mesh), WEFT_STATUS_RESULT_TOO_LARGE);
  CHECK_STATUS(weft_uv_sphere(1.0, 8, 8, NULL), WEFT_STATUS_NULL_POINTER);
  CHECK(mesh == NULL);
}

int main(void) {
  test_delaunay();
  test_voronoi();
  test_mesh_from_grid();
  test_stellate();
  test_primitives();
  return check_summary("test_make");
}
