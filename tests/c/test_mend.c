/* The mending exports through the C ABI: join, weld, T-nodes, cull,
 * orientation, normals, planarity and naked boundaries, each with its
 * success and its error paths (NULL, bad tolerance, buffer too small). */
#include <math.h>
#include <string.h>

#include "check.h"


/* The unit cube moved by `dx` along x. */
static WeftMesh *make_cube(double dx) {
  double positions[24];
  WeftMesh *mesh = NULL;
  int i;
  for (i = 0; i < 8; ++i) {
    positions[3 * i] = (i & 1) + dx;
    positions[3 * i + 1] = (i >> 1) & 1;
    positions[3 * i + 2] = (i >> 2) & 1;
  }
  CHECK_STATUS(weft_mesh_new(positions, 8, cube_sizes, 6, cube_indices, 24, &mesh), WEFT_STATUS_OK);
  return mesh;
}

static int near(double a, double b) { return fabs(a - b) < 1e-9; }

static void test_join_weld_cull(void) {
  WeftMesh *a = make_cube(0.0), *b = make_cube(1.0), *joined = NULL, *welded = NULL, *culled = NULL;
  const WeftMesh *pair[2];
  const WeftMesh *with_null[2];
  WeftWeldReport report = {99, 99, 99};
  WeftMeshInfo info;
  size_t removed = 0;
  pair[0] = a;
  pair[1] = b;
  with_null[0] = a;
  with_null[1] = NULL;

  CHECK_STATUS(weft_join(pair, 2, &joined), WEFT_STATUS_OK);
  CHECK(weft_mesh_vertex_count(joined) == 16 && weft_mesh_face_count(joined) == 12);
  CHECK(weft_mesh_face_indices(joined)[24] == 8);

  CHECK_STATUS(weft_weld(joined, WEFT_DEFAULT_WELD_TOLERANCE, &welded, &report), WEFT_STATUS_OK);
  CHECK(weft_mesh_vertex_count(welded) == 12);
  CHECK(report.merged_vertex_count == 4 && report.removed_face_count == 0 && report.unused_vertex_count == 0);

  CHECK_STATUS(weft_cull_adjacent(welded, &culled, &removed), WEFT_STATUS_OK);
  CHECK(removed == 2 && weft_mesh_face_count(culled) == 10);
  CHECK_STATUS(weft_mesh_info(culled, &info), WEFT_STATUS_OK);
  CHECK(info.is_closed && info.component_count == 1 && info.is_oriented);
  weft_mesh_free(culled);
  culled = NULL;
  /* The counts are optional. */
  CHECK_STATUS(weft_cull_adjacent(welded, &culled, NULL), WEFT_STATUS_OK);
  CHECK(weft_mesh_face_count(culled) == 10);
  weft_mesh_free(culled);
  weft_mesh_free(welded);
  welded = NULL;
  CHECK_STATUS(weft_weld(joined, 0.0, &welded, NULL), WEFT_STATUS_OK);
  CHECK(weft_mesh_vertex_count(welded) == 12);
  weft_mesh_free(welded);
  welded = NULL;

  /* Errors: nothing written. */
  CHECK_STATUS(weft_join(with_null, 2, &welded), WEFT_STATUS_NULL_POINTER);
  CHECK_MESSAGE("meshes[1]");
  CHECK(welded == NULL);
  CHECK_STATUS(weft_join(NULL, 2, &welded), WEFT_STATUS_NULL_POINTER);
  CHECK_STATUS(weft_join(pair, 2, NULL), WEFT_STATUS_NULL_POINTER);
  CHECK_STATUS(weft_join(NULL, 0, &welded), WEFT_STATUS_OK);
  CHECK(welded != NULL && weft_mesh_vertex_count(welded) == 0);
  weft_mesh_free(welded);
  welded = NULL;

  report.merged_vertex_count = 99;
  CHECK_STATUS(weft_weld(joined, -1.0, &welded, &report), WEFT_STATUS_INVALID_ARGUMENT);
  CHECK_MESSAGE("tolerance is -1");
  CHECK(welded == NULL && report.merged_vertex_count == 99);
  CHECK_STATUS(weft_weld(joined, NAN, &welded, &report), WEFT_STATUS_INVALID_ARGUMENT);
  CHECK_MESSAGE("tolerance");
  CHECK_STATUS(weft_weld(joined, INFINITY, &welded, NULL), WEFT_STATUS_INVALID_ARGUMENT);
  CHECK_STATUS(weft_weld(NULL, 0.001, &welded, NULL), WEFT_STATUS_NULL_POINTER);
  CHECK_MESSAGE("mesh is NULL");
  CHECK_STATUS(weft_weld(joined, 0.001, NULL, NULL), WEFT_STATUS_NULL_POINTER);
  CHECK(welded == NULL);
  CHECK_STATUS(weft_cull_adjacent(NULL, &culled, &removed), WEFT_STATUS_NULL_POINTER);
  CHECK_STATUS(weft_cull_adjacent(joined, NULL, &removed), WEFT_STATUS_NULL_POINTER);
  weft_mesh_free(joined);
  weft_mesh_free(a);
  weft_mesh_free(b);
}

/* Two triangles; vertex 4 lies a quarter of the way along edge 1-2 of the first. */
static WeftMesh *make_t_node_pair(void) {
  static const double positions[] = {0, 0, 0, 2, 0, 0, 2, 2, 0, 4, 0, 0, 2, 0.5, 0};
  static const uint32_t sizes[] = {3, 3};
  static const uint32_t indices[] = {0, 1, 2, 4, 3, 2};
  WeftMesh *mesh = NULL;
  CHECK_STATUS(weft_mesh_new(positions, 5, sizes, 2, indices, 6, &mesh), WEFT_STATUS_OK);
  return mesh;
}

static void test_t_nodes(void) {
  WeftMesh *mesh = make_t_node_pair(), *repaired = NULL;
  WeftTNode nodes[2];
  size_t count = 99, inserted = 0;
  uint32_t face[4];

  CHECK_STATUS(weft_find_t_nodes(mesh, 1e-6, NULL, 0, &count), WEFT_STATUS_OK);
  CHECK(count == 1);
  nodes[0].vertex = 77;
  count = 99;
  CHECK_STATUS(weft_find_t_nodes(mesh, 1e-6, nodes, 0, &count), WEFT_STATUS_BUFFER_TOO_SMALL);
  CHECK_MESSAGE("out_nodes has room for 0 elements but 1 are needed");
  CHECK(nodes[0].vertex == 77 && count == 99);
  CHECK_STATUS(weft_find_t_nodes(mesh, 1e-6, nodes, 2, &count), WEFT_STATUS_OK);
  CHECK(count == 1);
  CHECK(nodes[0].vertex == 4 && nodes[0].edge_start == 1 && nodes[0].edge_end == 2 && nodes[0].face == 0);
  CHECK(near(nodes[0].parameter, 0.25));
  CHECK_STATUS(weft_find_t_nodes(mesh, NAN, NULL, 0, &count), WEFT_STATUS_INVALID_ARGUMENT);
  CHECK_STATUS(weft_find_t_nodes(mesh, -0.5, NULL, 0, &count), WEFT_STATUS_INVALID_ARGUMENT);
  CHECK_MESSAGE("tolerance is -0.5");
  CHECK_STATUS(weft_find_t_nodes(mesh, 1e-6, nodes, 2, NULL), WEFT_STATUS_NULL_POINTER);
  CHECK_MESSAGE("out_count is NULL");
  CHECK_STATUS(weft_find_t_nodes(NULL, 1e-6, nodes, 2, &count), WEFT_STATUS_NULL_POINTER);

  CHECK_STATUS(weft_repair_t_nodes(mesh, 1e-6, &repaired, &inserted), WEFT_STATUS_OK);
  CHECK(inserted == 1 && weft_mesh_face_count(repaired) == 2 && weft_mesh_index_count(repaired) == 7);
  memcpy(face, weft_mesh_face_indices(repaired), sizeof face);
  CHECK(face[0] == 0 && face[1] == 1 && face[2] == 4 && face[3] == 2);
  weft_mesh_free(repaired);
  repaired = NULL;
  CHECK_STATUS(weft_repair_t_nodes(mesh, 1e-6, &repaired, NULL), WEFT_STATUS_OK);
  weft_mesh_free(repaired);
  repaired = NULL;
  CHECK_STATUS(weft_repair_t_nodes(mesh, NAN, &repaired, &inserted), WEFT_STATUS_INVALID_ARGUMENT);
  CHECK_STATUS(weft_repair_t_nodes(mesh, -1.0, &repaired, &inserted), WEFT_STATUS_INVALID_ARGUMENT);
  CHECK_STATUS(weft_repair_t_nodes(NULL, 1e-6, &repaired, &inserted), WEFT_STATUS_NULL_POINTER);
  CHECK_STATUS(weft_repair_t_nodes(mesh, 1e-6, NULL, &inserted), WEFT_STATUS_NULL_POINTER);
  CHECK(repaired == NULL);
  weft_mesh_free(mesh);
}

static void test_orientation(void) {
  static const uint32_t one_flipped[] = {0, 1, 3, 2, 4, 5, 7, 6, 0, 1, 5, 4,
                                         2, 6, 7, 3, 0, 4, 6, 2, 1, 3, 7, 5};
  WeftMesh *cube = make_cube(0.0), *scrambled = NULL, *fixed = NULL, *flipped = NULL;
  WeftMeshInfo info;
  size_t count = 0;
  const uint32_t *indices;
  CHECK_STATUS(weft_mesh_new(weft_mesh_positions(cube), 8, cube_sizes, 6, one_flipped, 24, &scrambled),
               WEFT_STATUS_OK);
  CHECK_STATUS(weft_unify_orientation(scrambled, &fixed, &count), WEFT_STATUS_OK);
  CHECK(count == 1);
  CHECK(memcmp(weft_mesh_face_indices(fixed), cube_indices, sizeof cube_indices) == 0);
  CHECK_STATUS(weft_mesh_info(fixed, &info), WEFT_STATUS_OK);
  CHECK(info.is_oriented && info.is_orientable);
  weft_mesh_free(fixed);
  fixed = NULL;
  CHECK_STATUS(weft_unify_orientation(scrambled, &fixed, NULL), WEFT_STATUS_OK);
  weft_mesh_free(fixed);
  fixed = NULL;

  CHECK_STATUS(weft_flip(cube, &flipped), WEFT_STATUS_OK);
  indices = weft_mesh_face_indices(flipped);
  CHECK(indices[0] == 0 && indices[1] == 1 && indices[2] == 3 && indices[3] == 2);
  weft_mesh_free(flipped);
  flipped = NULL;

  CHECK_STATUS(weft_unify_orientation(NULL, &fixed, &count), WEFT_STATUS_NULL_POINTER);
  CHECK_STATUS(weft_unify_orientation(cube, NULL, &count), WEFT_STATUS_NULL_POINTER);
  CHECK_STATUS(weft_flip(NULL, &flipped), WEFT_STATUS_NULL_POINTER);
  CHECK_STATUS(weft_flip(cube, NULL), WEFT_STATUS_NULL_POINTER);
  CHECK(fixed == NULL && flipped == NULL);
  weft_mesh_free(scrambled);
  weft_mesh_free(cube);
}

/* The signed volume a closed mesh encloses (positive when its faces face
 * out): the tetrahedra from the vertices' centroid to fans of triangles
 * about each face's first corner. Measured from the centroid, every face
 * of a cube counts, and a reversed one counts against. */
static double signed_volume(const WeftMesh *mesh) {
  const double *p = weft_mesh_positions(mesh);
  const uint32_t *sizes = weft_mesh_face_sizes(mesh), *indices = weft_mesh_face_indices(mesh);
  double volume = 0, o[3] = {0, 0, 0};
  size_t f, start = 0, k, v, n = weft_mesh_vertex_count(mesh);
  for (v = 0; v < n; ++v) {
    for (k = 0; k < 3; ++k) o[k] += p[3 * v + k] / (double)n;
  }
  for (f = 0; f < weft_mesh_face_count(mesh); start += sizes[f], ++f) {
    const double *pa = p + 3 * indices[start];
    for (k = 1; k + 1 < sizes[f]; ++k) {
      const double *pb = p + 3 * indices[start + k], *pc = p + 3 * indices[start + k + 1];
      double a[3], b[3], c[3];
      int i;
      for (i = 0; i < 3; ++i) {
        a[i] = pa[i] - o[i];
        b[i] = pb[i] - o[i];
        c[i] = pc[i] - o[i];
      }
      volume += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
                 a[2] * (b[0] * c[1] - b[1] * c[0])) / 6.0;
    }
  }
  return volume;
}

/* Whether every edge of the mesh is run once in each direction: every
 * directed edge appears once, and so does its reverse. */
static int every_edge_consistent(const WeftMesh *mesh) {
  const uint32_t *sizes = weft_mesh_face_sizes(mesh), *indices = weft_mesh_face_indices(mesh);
  uint32_t from[64], to[64];
  size_t n = 0, f, k, i, j, start = 0;
  for (f = 0; f < weft_mesh_face_count(mesh); start += sizes[f], ++f) {
    for (k = 0; k < sizes[f] && n < 64; ++k, ++n) {
      from[n] = indices[start + k];
      to[n] = indices[start + (k + 1) % sizes[f]];
    }
  }
  for (i = 0; i < n; ++i) {
    size_t same = 0, reverse = 0;
    for (j = 0; j < n; ++j) {
      same += from[j] == from[i] && to[j] == to[i];
      reverse += from[j] == to[i] && to[j] == from[i];
    }
    if (same != 1 || reverse != 1) return 0;
  }
  return n > 0;
}

/* Whether `face` runs the corners `expected` (both of `size`) from some start. */
static int same_face_up_to_rotation(const uint32_t *face, const uint32_t *expected, size_t size) {
  size_t shift, k;
  for (shift = 0; shift < size; ++shift) {
    for (k = 0; k < size && face[(k + shift) % size] == expected[k]; ++k) {
    }
    if (k == size) return 1;
  }
  return 0;
}

static void test_three_flipped_faces(void) {
  /* The three faces at vertex 0 (-z, -y, -x) reversed, first corner kept. */
  static const uint32_t three_flipped[] = {0, 1, 3, 2, 4, 5, 7, 6, 0, 4, 5, 1,
                                           2, 6, 7, 3, 0, 2, 6, 4, 1, 3, 7, 5};
  WeftMesh *cube = make_cube(0.0), *scrambled = NULL, *fixed = NULL;
  WeftMeshInfo info;
  size_t flipped = 0, f;
  CHECK_STATUS(weft_mesh_new(weft_mesh_positions(cube), 8, cube_sizes, 6, three_flipped, 24, &scrambled),
               WEFT_STATUS_OK);
  CHECK_STATUS(weft_mesh_info(scrambled, &info), WEFT_STATUS_OK);
  CHECK(info.is_orientable && !info.is_oriented && info.is_closed);
  CHECK(!every_edge_consistent(scrambled));
  /* Half the faces wrong: the volume cancels out. */
  CHECK(near(signed_volume(scrambled), 0.0));

  CHECK_STATUS(weft_unify_orientation(scrambled, &fixed, &flipped), WEFT_STATUS_OK);
  CHECK(flipped == 3);
  CHECK(every_edge_consistent(fixed));
  /* Facing out: the unit cube's volume, positive. */
  CHECK(near(signed_volume(fixed), 1.0));
  CHECK_STATUS(weft_mesh_info(fixed, &info), WEFT_STATUS_OK);
  CHECK(info.is_oriented && info.is_orientable && info.is_closed);
  /* Each face is the unflipped cube's, up to where it starts. */
  CHECK(weft_mesh_face_count(fixed) == 6 && weft_mesh_index_count(fixed) == 24);
  for (f = 0; f < 6; ++f) {
    CHECK(same_face_up_to_rotation(weft_mesh_face_indices(fixed) + 4 * f, cube_indices + 4 * f, 4));
  }
  /* The positions are untouched. */
  CHECK(memcmp(weft_mesh_positions(fixed), weft_mesh_positions(cube), 24 * sizeof(double)) == 0);
  weft_mesh_free(fixed);
  weft_mesh_free(scrambled);
  weft_mesh_free(cube);
}

/* A band of `n` quads around a circle of radius 2, its two rows of
 * vertices (2i the outer edge at angle i, 2i + 1 the inner) joined back on
 * themselves, with a half twist (a Möbius strip) or without (an annulus). */
static WeftMesh *make_band(int twisted) {
  enum { n = 12 };
  double positions[6 * n];
  uint32_t sizes[n], indices[4 * n];
  WeftMesh *mesh = NULL;
  int i;
  for (i = 0; i < n; ++i) {
    double theta = 2.0 * 3.14159265358979323846 * i / n, half = twisted ? theta / 2 : 0;
    int side;
    for (side = 0; side < 2; ++side) {
      double w = side == 0 ? 0.5 : -0.5, r = 2.0 + w * cos(half);
      positions[6 * i + 3 * side] = r * cos(theta);
      positions[6 * i + 3 * side + 1] = r * sin(theta);
      positions[6 * i + 3 * side + 2] = w * sin(half);
    }
    sizes[i] = 4;
    indices[4 * i] = (uint32_t)(2 * i);
    indices[4 * i + 1] = (uint32_t)(2 * i + 1);
    if (i + 1 < n) {
      indices[4 * i + 2] = (uint32_t)(2 * i + 3);
      indices[4 * i + 3] = (uint32_t)(2 * i + 2);
    } else {
      /* Round the circle, a half twist brings the outer edge back as the inner one. */
      indices[4 * i + 2] = twisted ? 0 : 1;
      indices[4 * i + 3] = twisted ? 1 : 0;
    }
  }
  CHECK_STATUS(weft_mesh_new(positions, 2 * n, sizes, n, indices, 4 * n, &mesh), WEFT_STATUS_OK);
  return mesh;
}

static void test_mobius_strip(void) {
  WeftMesh *strip = make_band(1), *annulus = make_band(0), *unified = NULL;
  WeftMeshInfo info;
  size_t flipped = 99;
  CHECK_STATUS(weft_mesh_info(strip, &info), WEFT_STATUS_OK);
  CHECK(!info.is_orientable && !info.is_oriented && !info.is_closed);
  /* One border of 2n edges, one piece, manifold. */
  CHECK(info.naked_edge_count == 24 && info.edge_count == 36 && info.component_count == 1);
  CHECK(info.non_manifold_edge_count == 0 && info.non_manifold_vertex_count == 0);
  /* No winding makes it orientable: unify does what it can, and says so. */
  CHECK_STATUS(weft_unify_orientation(strip, &unified, &flipped), WEFT_STATUS_OK);
  CHECK_STATUS(weft_mesh_info(unified, &info), WEFT_STATUS_OK);
  CHECK(!info.is_orientable && !info.is_oriented);
  weft_mesh_free(unified);
  /* The same band without the twist is orientable and already oriented. */
  CHECK_STATUS(weft_mesh_info(annulus, &info), WEFT_STATUS_OK);
  CHECK(info.is_orientable && info.is_oriented && !info.is_closed);
  CHECK(info.naked_edge_count == 24 && info.edge_count == 36 && info.component_count == 1);
  weft_mesh_free(annulus);
  weft_mesh_free(strip);
}

static void test_normals_and_planarity(void) {
  /* z = xy on the unit square: (15 - sqrt 33) / (4 sqrt(66 + 2 sqrt 33)) from its plane. */
  static const double hypar_positions[] = {0, 0, 0, 1, 0, 0, 1, 1, 1, 0, 1, 0};
  static const uint32_t quad_size[] = {4};
  static const uint32_t quad_indices[] = {0, 1, 2, 3};
  WeftMesh *cube = make_cube(0.0), *hypar = NULL;
  double normals[24], deviations[6];
  double s = sqrt(33.0);
  int i;
  CHECK_STATUS(weft_face_normals(cube, normals, 18), WEFT_STATUS_OK);
  CHECK(normals[0] == 0.0 && normals[1] == 0.0 && normals[2] == -1.0);
  CHECK(normals[15] == 1.0 && normals[16] == 0.0 && normals[17] == 0.0);
  normals[0] = 5.0;
  CHECK_STATUS(weft_face_normals(cube, normals, 17), WEFT_STATUS_BUFFER_TOO_SMALL);
  CHECK(normals[0] == 5.0);
  CHECK_STATUS(weft_face_normals(cube, NULL, 0), WEFT_STATUS_BUFFER_TOO_SMALL);
  CHECK_STATUS(weft_face_normals(NULL, normals, 18), WEFT_STATUS_NULL_POINTER);

  CHECK_STATUS(weft_vertex_normals(cube, normals, 24), WEFT_STATUS_OK);
  for (i = 0; i < 3; ++i) {
    CHECK(near(normals[i], -1.0 / sqrt(3.0)));
    CHECK(near(normals[21 + i], 1.0 / sqrt(3.0)));
  }
  CHECK_STATUS(weft_vertex_normals(cube, normals, 23), WEFT_STATUS_BUFFER_TOO_SMALL);
  CHECK_MESSAGE("out_normals has room for 23 elements but 24 are needed");
  CHECK_STATUS(weft_vertex_normals(NULL, normals, 24), WEFT_STATUS_NULL_POINTER);

  CHECK_STATUS(weft_planarity(cube, deviations, 6), WEFT_STATUS_OK);
  for (i = 0; i < 6; ++i) CHECK(deviations[i] < 1e-12);
  CHECK_STATUS(weft_mesh_new(hypar_positions, 4, quad_size, 1, quad_indices, 4, &hypar), WEFT_STATUS_OK);
  CHECK_STATUS(weft_planarity(hypar, deviations, 1), WEFT_STATUS_OK);
  CHECK(near(deviations[0], (15.0 - s) / (4.0 * sqrt(66.0 + 2.0 * s))));
  CHECK_STATUS(weft_planarity(cube, deviations, 5), WEFT_STATUS_BUFFER_TOO_SMALL);
  CHECK_STATUS(weft_planarity(NULL, deviations, 6), WEFT_STATUS_NULL_POINTER);
  weft_mesh_free(hypar);
  weft_mesh_free(cube);
}

static void test_naked_boundaries(void) {
  /* A 2 x 1 quad grid: one closed border of 6 points, counter-clockwise. */
  static const double grid_positions[] = {0, 0, 0, 1, 0, 0, 2, 0, 0, 0, 1, 0, 1, 1, 0, 2, 1, 0};
  static const uint32_t grid_sizes[] = {4, 4};
  static const uint32_t grid_indices[] = {0, 1, 4, 3, 1, 2, 5, 4};
  static const double expected[] = {0, 0, 0, 1, 0, 0, 2, 0, 0, 2, 1, 0, 1, 1, 0, 0, 1, 0};
  WeftMesh *grid = NULL, *cube = make_cube(0.0);
  double points[18];
  size_t counts[1] = {0}, total = 0, polylines = 0;
  bool closed[1] = {false};
  CHECK_STATUS(weft_mesh_new(grid_positions, 6, grid_sizes, 2, grid_indices, 8, &grid), WEFT_STATUS_OK);
  CHECK_STATUS(weft_naked_boundaries(grid, NULL, 0, NULL, NULL, 0, &total, &polylines), WEFT_STATUS_OK);
  CHECK(total == 6 && polylines == 1);
  CHECK_STATUS(weft_naked_boundaries(grid, points, 18, counts, closed, 1, &total, &polylines), WEFT_STATUS_OK);
  CHECK(counts[0] == 6 && closed[0]);
  CHECK(memcmp(points, expected, sizeof expected) == 0);
  /* out_closed is optional. */
  CHECK_STATUS(weft_naked_boundaries(grid, points, 18, counts, NULL, 1, &total, &polylines), WEFT_STATUS_OK);

  counts[0] = 42;
  CHECK_STATUS(weft_naked_boundaries(grid, points, 17, counts, closed, 1, &total, &polylines),
               WEFT_STATUS_BUFFER_TOO_SMALL);
  CHECK_MESSAGE("out_points");
  CHECK(counts[0] == 42);
  CHECK_STATUS(weft_naked_boundaries(grid, points, 18, counts, closed, 0, &total, &polylines),
               WEFT_STATUS_BUFFER_TOO_SMALL);
  CHECK_MESSAGE("out_point_counts");
  CHECK_STATUS(weft_naked_boundaries(grid, points, 18, NULL, closed, 1, &total, &polylines),
               WEFT_STATUS_NULL_POINTER);
  CHECK_STATUS(weft_naked_boundaries(grid, NULL, 0, NULL, NULL, 0, NULL, &polylines), WEFT_STATUS_NULL_POINTER);
  CHECK_STATUS(weft_naked_boundaries(grid, NULL, 0, NULL, NULL, 0, &total, NULL), WEFT_STATUS_NULL_POINTER);
  CHECK_STATUS(weft_naked_boundaries(NULL, NULL, 0, NULL, NULL, 0, &total, &polylines), WEFT_STATUS_NULL_POINTER);

  /* A closed mesh has no naked boundary: empty buffers suffice. */
  CHECK_STATUS(weft_naked_boundaries(cube, NULL, 0, NULL, NULL, 0, &total, &polylines), WEFT_STATUS_OK);
  CHECK(total == 0 && polylines == 0);
  weft_mesh_free(cube);
  weft_mesh_free(grid);
}

/* The argument checks both matching calls share: a bad tolerance, NULL
 * buffers, and nothing written on failure (out[0] stays 99). */
typedef WeftStatus (*MatchCall)(const WeftMesh *, size_t, const double *, double, uint32_t *);

static void check_match_refusals(MatchCall match, WeftMesh *cube, const double *input, const char *input_name,
                                 const char *out_name, uint32_t *out) {
  char message[64];
  CHECK_FAILS_WITH(match(cube, 1, input, -1.0, out), WEFT_STATUS_INVALID_ARGUMENT, "tolerance is -1");
  CHECK_FAILS_WITH(match(cube, 1, input, NAN, out), WEFT_STATUS_INVALID_ARGUMENT, "tolerance is NaN");
  CHECK_FAILS_WITH(match(cube, 1, input, INFINITY, out), WEFT_STATUS_INVALID_ARGUMENT, "tolerance is inf");
  CHECK_FAILS_WITH(match(NULL, 1, input, 0.1, out), WEFT_STATUS_NULL_POINTER, "mesh is NULL");
  snprintf(message, sizeof message, "%s is NULL", input_name);
  CHECK_FAILS_WITH(match(cube, 1, NULL, 0.1, out), WEFT_STATUS_NULL_POINTER, message);
  snprintf(message, sizeof message, "%s is NULL", out_name);
  CHECK_FAILS_WITH(match(cube, 1, input, 0.1, NULL), WEFT_STATUS_NULL_POINTER, message);
  CHECK(out[0] == 99);
  CHECK_STATUS(match(cube, 0, NULL, 0.1, NULL), WEFT_STATUS_OK);
}

/* Points and lines matched to the cube's vertices and edges. */
static void test_match_points_and_lines(void) {
  WeftMesh *cube = make_cube(0.0);
  const double points[] = {1.01, 0.99, 0.0, 0.0, 0.02, 1.0, 0.5, 0.5, 0.5};
  /* Edge 3-1 from vertex 3's side, edge 0-2 reversed, then the diagonal 0-3. */
  const double lines[] = {1.0, 1.01, 0.0, 0.99, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.01,
                          0.0, 0.0, 0.0, 1.0, 1.0, 0.0};
  const double bad_point[] = {0.0, NAN, 0.0};
  uint32_t vertices[3] = {99, 99, 99}, pairs[6] = {99, 99, 99, 99, 99, 99};

  CHECK_STATUS(weft_match_points_to_vertices(cube, 2, points, 0.05, vertices), WEFT_STATUS_OK);
  CHECK(vertices[0] == 3 && vertices[1] == 4 && vertices[2] == 99);
  vertices[0] = 99;
  CHECK_FAILS_WITH(weft_match_points_to_vertices(cube, 3, points, 0.05, vertices), WEFT_STATUS_INVALID_ARGUMENT,
                   "point 2 at (0.5, 0.5, 0.5) is no vertex of the mesh within 0.05");
  CHECK_FAILS_WITH(weft_match_points_to_vertices(cube, 1, bad_point, 0.1, vertices), WEFT_STATUS_NON_FINITE_COORDINATE,
                   "points: point 0 has a non-finite coordinate");
  check_match_refusals(weft_match_points_to_vertices, cube, points, "points", "out_vertices", vertices);

  CHECK_STATUS(weft_match_lines_to_edges(cube, 2, lines, 0.05, pairs), WEFT_STATUS_OK);
  CHECK(pairs[0] == 3 && pairs[1] == 1 && pairs[2] == 2 && pairs[3] == 0 && pairs[4] == 99);
  pairs[0] = 99;
  CHECK_FAILS_WITH(weft_match_lines_to_edges(cube, 3, lines, 0.05, pairs), WEFT_STATUS_INVALID_ARGUMENT,
                   "line 2 from (0, 0, 0) to (1, 1, 0) matches no edge of the mesh within 0.05");
  CHECK_MESSAGE("its ends are vertices but not the ends of one edge");
  check_match_refusals(weft_match_lines_to_edges, cube, lines, "lines", "out_vertex_pairs", pairs);
  weft_mesh_free(cube);
}

/* Two cubes, the second inside out, joined: orienting outward turns the
 * second and reports both pieces closed; the relative weld tolerance is a
 * millionth of the bounding-box diagonal. */
static void test_orient_outward_and_relative_tolerance(void) {
  WeftMesh *a = make_cube(0.0), *b = make_cube(3.0), *flipped = NULL, *joined = NULL,
           *outward = NULL;
  const WeftMesh *pair[2];
  WeftOrientReport report;
  double tolerance = -1.0;
  memset(&report, 0xff, sizeof report);
  CHECK_STATUS(weft_flip(b, &flipped), WEFT_STATUS_OK);
  pair[0] = a;
  pair[1] = flipped;
  CHECK_STATUS(weft_join(pair, 2, &joined), WEFT_STATUS_OK);
  CHECK_STATUS(weft_orient_outward(joined, &outward, &report), WEFT_STATUS_OK);
  CHECK(report.pieces == 2 && report.turned_outward == 1 && report.flipped_faces == 6);
  CHECK(report.open_pieces == 0 && report.non_orientable_pieces == 0);
  CHECK_STATUS(weft_orient_outward(NULL, &outward, &report), WEFT_STATUS_NULL_POINTER);
  CHECK_STATUS(weft_orient_outward(joined, NULL, NULL), WEFT_STATUS_NULL_POINTER);

  CHECK_STATUS(weft_weld_relative_tolerance(joined, &tolerance), WEFT_STATUS_OK);
  CHECK(near(tolerance, sqrt(16.0 + 1.0 + 1.0) * 1e-6));
  CHECK_STATUS(weft_weld_relative_tolerance(joined, NULL), WEFT_STATUS_NULL_POINTER);
  CHECK_STATUS(weft_weld_relative_tolerance(NULL, &tolerance), WEFT_STATUS_NULL_POINTER);
  {
    /* A triangle and a vertex no face uses. */
    const double positions[] = {0, 0, 0, 9, 9, 9, 1, 0, 0, 0, 1, 0};
    const uint32_t sizes[] = {3}, indices[] = {0, 2, 3};
    WeftMesh *bare = NULL, *compact = NULL;
    size_t removed = 0;
    CHECK_STATUS(weft_mesh_new(positions, 4, sizes, 1, indices, 3, &bare), WEFT_STATUS_OK);
    CHECK(weft_mesh_unused_vertex_count(bare) == 1 && weft_mesh_unused_vertex_count(NULL) == 0);
    CHECK_STATUS(weft_remove_unused_vertices(bare, &compact, &removed), WEFT_STATUS_OK);
    CHECK(removed == 1 && weft_mesh_vertex_count(compact) == 3);
    CHECK(weft_mesh_face_indices(compact)[1] == 1 && weft_mesh_positions(compact)[3] == 1.0);
    CHECK_STATUS(weft_remove_unused_vertices(NULL, &compact, NULL), WEFT_STATUS_NULL_POINTER);
    weft_mesh_free(bare);
    weft_mesh_free(compact);
  }
  weft_mesh_free(a);
  weft_mesh_free(b);
  weft_mesh_free(flipped);
  weft_mesh_free(joined);
  weft_mesh_free(outward);
}

int main(void) {
  test_join_weld_cull();
  test_t_nodes();
  test_orientation();
  test_three_flipped_faces();
  test_mobius_strip();
  test_normals_and_planarity();
  test_naked_boundaries();
  test_match_points_and_lines();
  test_orient_outward_and_relative_tolerance();
  return check_summary("test_mend");
}
