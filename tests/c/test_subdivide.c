/* Subdivision through the C ABI: Catmull-Clark on a cube and an open grid,
 * Loop on a closed octahedron and an open triangle grid, each in every
 * naked-edge mode, level 0 as an exact copy, parent faces, triangulation,
 * the refiner, and every bad argument with its own status and message. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"


/* A 2 x 2 grid of unit quads in z = 0, vertex (i, j) = 3 j + i, bent up
 * in the middle so that smoothing moves its border. */
static const double grid_positions[] = {0, 0, 0, 1, 0, 0.5, 2, 0, 0, 0, 1, 0.5, 1, 1, 1,
                                        2, 1, 0.5, 0, 2, 0, 1, 2, 0.5, 2, 2, 0};
static const uint32_t grid_sizes[] = {4, 4, 4, 4};
static const uint32_t grid_indices[] = {0, 1, 4, 3, 1, 2, 5, 4, 3, 4, 7, 6, 4, 5, 8, 7};

/* The octahedron of the unit axis points, every triangle wound outwards:
 * vertex 0 is +x, 1 -x, 2 +y, 3 -y, 4 +z, 5 -z. */
static const double octahedron_positions[] = {1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1};
static const uint32_t octahedron_sizes[] = {3, 3, 3, 3, 3, 3, 3, 3};
static const uint32_t octahedron_indices[] = {0, 2, 4, 1, 4, 2, 0, 4, 3, 1, 3, 4,
                                              0, 5, 2, 1, 2, 5, 0, 3, 5, 1, 5, 3};

/* The bent grid above, each quad split along its (i, j)-(i+1, j+1)
 * diagonal: corners 2 and 6 have one triangle, corners 0 and 8 two. */
static const uint32_t tri_grid_sizes[] = {3, 3, 3, 3, 3, 3, 3, 3};
static const uint32_t tri_grid_indices[] = {0, 1, 4, 0, 4, 3, 1, 2, 5, 1, 5, 4,
                                            3, 4, 7, 3, 7, 6, 4, 5, 8, 4, 8, 7};
/* Its border, counter-clockwise: the original boundary polyline. */
static const uint32_t tri_grid_border[] = {0, 1, 2, 5, 8, 7, 6, 3};

static WeftMesh *grid(void) { return make_mesh(grid_positions, 9, grid_sizes, 4, grid_indices, 16); }
static WeftMesh *octahedron(void) {
  return make_mesh(octahedron_positions, 6, octahedron_sizes, 8, octahedron_indices, 24);
}
static WeftMesh *tri_grid(void) { return make_mesh(grid_positions, 9, tri_grid_sizes, 8, tri_grid_indices, 24); }

static int compare_edges(const void *a, const void *b) {
  const uint32_t *x = a, *y = b;
  if (x[0] != y[0]) return x[0] < y[0] ? -1 : 1;
  if (x[1] != y[1]) return x[1] < y[1] ? -1 : 1;
  return 0;
}

/* The index of the new vertex Loop (and Catmull-Clark) makes on edge a-b of
 * a cage of `vertex_count` vertices: the cage's vertices come first, then
 * one point per edge, edges sorted by lower then higher vertex. */
static size_t edge_point(const uint32_t *triangles, size_t triangle_count, size_t vertex_count, uint32_t a,
                         uint32_t b) {
  uint32_t edges[3 * 64][2], key[2];
  size_t n = 0, unique = 0, i, k;
  for (i = 0; i < triangle_count; ++i) {
    for (k = 0; k < 3; ++k) {
      uint32_t p = triangles[3 * i + k], q = triangles[3 * i + (k + 1) % 3];
      edges[n][0] = p < q ? p : q;
      edges[n][1] = p < q ? q : p;
      ++n;
    }
  }
  qsort(edges, n, sizeof edges[0], compare_edges);
  key[0] = a < b ? a : b;
  key[1] = a < b ? b : a;
  for (i = 0; i < n; ++i) {
    if (i > 0 && compare_edges(edges[i], edges[i - 1]) == 0) continue;
    if (compare_edges(edges[i], key) == 0) return vertex_count + unique;
    ++unique;
  }
  return (size_t)-1;
}

/* Whether p lies on segment a-b (within round-off). */
static int on_segment(const double *p, const double *a, const double *b) {
  double ab[3], ap[3], t = 0, len2 = 0, d2 = 0;
  int k;
  for (k = 0; k < 3; ++k) {
    ab[k] = b[k] - a[k];
    ap[k] = p[k] - a[k];
    t += ab[k] * ap[k];
    len2 += ab[k] * ab[k];
  }
  t /= len2;
  if (t < -1e-12 || t > 1 + 1e-12) return 0;
  for (k = 0; k < 3; ++k) d2 += (ap[k] - t * ab[k]) * (ap[k] - t * ab[k]);
  return d2 < 1e-24;
}

/* How many of the naked-boundary points of `mesh` lie on the tri grid's
 * original border polyline; their total goes to `total`. */
static size_t border_points_on_polyline(const WeftMesh *mesh, size_t *total) {
  double points[3 * 64];
  size_t counts[4], polylines = 0, i, k, on = 0;
  *total = 0;
  CHECK_STATUS(weft_naked_boundaries(mesh, points, 3 * 64, counts, NULL, 4, total, &polylines), WEFT_STATUS_OK);
  CHECK(polylines == 1);
  for (i = 0; i < *total && i < 64; ++i) {
    for (k = 0; k < 8; ++k) {
      if (on_segment(points + 3 * i, grid_positions + 3 * tri_grid_border[k],
                     grid_positions + 3 * tri_grid_border[(k + 1) % 8])) {
        ++on;
        break;
      }
    }
  }
  return on;
}

/* Whether two meshes have the same counts, positions and faces, bit for bit. */
static int identical(const WeftMesh *a, const WeftMesh *b) {
  size_t v = weft_mesh_vertex_count(a), f = weft_mesh_face_count(a), c = weft_mesh_index_count(a);
  return v == weft_mesh_vertex_count(b) && f == weft_mesh_face_count(b) && c == weft_mesh_index_count(b) &&
         memcmp(weft_mesh_positions(a), weft_mesh_positions(b), 3 * v * sizeof(double)) == 0 &&
         memcmp(weft_mesh_face_sizes(a), weft_mesh_face_sizes(b), f * sizeof(uint32_t)) == 0 &&
         memcmp(weft_mesh_face_indices(a), weft_mesh_face_indices(b), c * sizeof(uint32_t)) == 0;
}

static int same_point(const double *a, const double *b) {
  return fabs(a[0] - b[0]) < 1e-12 && fabs(a[1] - b[1]) < 1e-12 && fabs(a[2] - b[2]) < 1e-12;
}

static void test_cube(void) {
  WeftMesh *mesh = unit_cube(), *out = NULL;
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

static void test_loop_closed(void) {
  WeftMesh *mesh = octahedron(), *once = NULL, *twice = NULL;
  WeftMeshInfo info;
  const double *p;
  size_t e02;
  CHECK_STATUS(weft_loop(mesh, 1, WEFT_NAKED_EDGES_SMOOTH, &once), WEFT_STATUS_OK);
  /* V + E = 6 + 12 vertices, 4F = 32 triangles, 2E + 3F = 48 edges. */
  CHECK(weft_mesh_vertex_count(once) == 18 && weft_mesh_face_count(once) == 32);
  CHECK(weft_mesh_index_count(once) == 96);
  CHECK_STATUS(weft_mesh_info(once, &info), WEFT_STATUS_OK);
  CHECK(info.edge_count == 48 && info.naked_edge_count == 0 && info.non_manifold_edge_count == 0);
  CHECK(info.component_count == 1 && info.is_closed && info.is_orientable && info.is_oriented);
  p = weft_mesh_positions(once);
  /* A vertex of valence 4 keeps 1 - 4 * 31/256 of itself; its neighbours sum to 0. */
  CHECK(same_point(p, (const double[]){132.0 / 256.0, 0, 0}));
  /* The edge point of 0-2 is 3/8 of each end and 1/8 of +z and -z. */
  e02 = edge_point(octahedron_indices, 8, 6, 0, 2);
  CHECK(e02 == 6);
  CHECK(same_point(p + 3 * e02, (const double[]){0.375, 0.375, 0}));
  /* Triangle 0 becomes triangles 0 to 3, the first at its first corner. */
  CHECK(weft_mesh_face_indices(once)[0] == 0);

  CHECK_STATUS(weft_loop(mesh, 2, WEFT_NAKED_EDGES_FIXED, &twice), WEFT_STATUS_OK);
  /* 18 + 48 vertices, 128 triangles; a closed mesh is the same in every mode. */
  CHECK(weft_mesh_vertex_count(twice) == 66 && weft_mesh_face_count(twice) == 128);
  CHECK_STATUS(weft_mesh_info(twice, &info), WEFT_STATUS_OK);
  CHECK(info.is_closed && info.is_orientable && info.is_oriented && info.component_count == 1);
  CHECK(info.edge_count == 192 && info.vertex_count - info.edge_count + info.face_count == 2);
  weft_mesh_free(once);
  {
    WeftMesh *smooth = NULL;
    CHECK_STATUS(weft_loop(mesh, 2, WEFT_NAKED_EDGES_SMOOTH, &smooth), WEFT_STATUS_OK);
    CHECK(identical(smooth, twice));
    weft_mesh_free(smooth);
  }
  weft_mesh_free(twice);
  weft_mesh_free(mesh);
}

static void test_loop_open_modes(void) {
  WeftMesh *mesh = tri_grid(), *fixed = NULL, *smooth = NULL, *corner = NULL, *fixed2 = NULL, *smooth2 = NULL;
  WeftMeshInfo info;
  const double *pf, *ps, *pc;
  size_t k, v, on, total;
  CHECK_STATUS(weft_loop(mesh, 1, WEFT_NAKED_EDGES_FIXED, &fixed), WEFT_STATUS_OK);
  CHECK_STATUS(weft_loop(mesh, 1, WEFT_NAKED_EDGES_SMOOTH, &smooth), WEFT_STATUS_OK);
  CHECK_STATUS(weft_loop(mesh, 1, WEFT_NAKED_EDGES_CORNER_FIXED, &corner), WEFT_STATUS_OK);
  /* 9 vertices + 16 edges; 32 triangles; the border of 8 edges becomes 16. */
  CHECK(weft_mesh_vertex_count(fixed) == 25 && weft_mesh_face_count(fixed) == 32);
  CHECK_STATUS(weft_mesh_info(fixed, &info), WEFT_STATUS_OK);
  CHECK(info.naked_edge_count == 16 && !info.is_closed && info.is_oriented);
  pf = weft_mesh_positions(fixed);
  ps = weft_mesh_positions(smooth);
  pc = weft_mesh_positions(corner);

  /* Fixed: every original boundary vertex stays, the interior one moves. */
  for (v = 0; v < 9; ++v) {
    if (v != 4) CHECK(same_point(pf + 3 * v, grid_positions + 3 * v));
  }
  CHECK(!same_point(pf + 12, grid_positions + 12));
  /* In every mode a new boundary point is its edge's midpoint: on the original polyline. */
  for (k = 0; k < 8; ++k) {
    uint32_t a = tri_grid_border[k], b = tri_grid_border[(k + 1) % 8];
    size_t e = edge_point(tri_grid_indices, 8, 9, a, b);
    double mid[3];
    int i;
    for (i = 0; i < 3; ++i) mid[i] = 0.5 * (grid_positions[3 * a + i] + grid_positions[3 * b + i]);
    CHECK(e < 25);
    if (e >= 25) continue;
    CHECK(same_point(pf + 3 * e, mid));
    CHECK(same_point(ps + 3 * e, mid));
    CHECK(same_point(pc + 3 * e, mid));
  }
  /* Two levels of Fixed keep all 32 border points on the original polyline... */
  CHECK_STATUS(weft_loop(mesh, 2, WEFT_NAKED_EDGES_FIXED, &fixed2), WEFT_STATUS_OK);
  on = border_points_on_polyline(fixed2, &total);
  CHECK(total == 32 && on == 32);
  /* ...while Smooth rounds it off: none of its border points is left on it. */
  CHECK_STATUS(weft_loop(mesh, 2, WEFT_NAKED_EDGES_SMOOTH, &smooth2), WEFT_STATUS_OK);
  on = border_points_on_polyline(smooth2, &total);
  CHECK(total == 32 && on == 0);

  /* Corner fixed: the one-face corners 2 and 6 stay; the two-face corner 0
   * and side vertex 1 follow the B-spline rule 1/8, 3/4, 1/8 along the border. */
  CHECK(same_point(pc + 6, grid_positions + 6));
  CHECK(same_point(pc + 18, grid_positions + 18));
  CHECK(same_point(pc + 0, (const double[]){0.125, 0.125, 0.125}));
  CHECK(same_point(pc + 3, (const double[]){1.0, 0.0, 0.375}));
  /* Smooth: every boundary vertex moves, the one-face corners too. */
  CHECK(same_point(ps + 6, (const double[]){1.875, 0.125, 0.125}));
  CHECK(same_point(ps + 18, (const double[]){0.125, 1.875, 0.125}));
  for (v = 0; v < 9; ++v) CHECK(!same_point(ps + 3 * v, grid_positions + 3 * v));
  /* Away from the one-face corners, corner fixed and smooth agree. */
  CHECK(same_point(pc + 0, ps + 0) && same_point(pc + 3, ps + 3) && same_point(pc + 24, ps + 24));

  weft_mesh_free(fixed);
  weft_mesh_free(smooth);
  weft_mesh_free(corner);
  weft_mesh_free(fixed2);
  weft_mesh_free(smooth2);
  weft_mesh_free(mesh);
}

static void test_level_zero_is_a_copy(void) {
  WeftMesh *meshes[3];
  const uint32_t modes[] = {WEFT_NAKED_EDGES_FIXED, WEFT_NAKED_EDGES_SMOOTH, WEFT_NAKED_EDGES_CORNER_FIXED};
  size_t i, m;
  meshes[0] = tri_grid();
  meshes[1] = octahedron();
  meshes[2] = grid();
  for (i = 0; i < 3; ++i) {
    for (m = 0; m < 3; ++m) {
      WeftMesh *out = NULL;
      /* Loop needs triangles: the quad grid is Catmull-Clark's only. */
      if (i < 2) {
        CHECK_STATUS(weft_loop(meshes[i], 0, modes[m], &out), WEFT_STATUS_OK);
        CHECK(out != NULL && out != meshes[i] && identical(out, meshes[i]));
        weft_mesh_free(out);
        out = NULL;
      }
      CHECK_STATUS(weft_catmull_clark(meshes[i], 0, modes[m], &out), WEFT_STATUS_OK);
      CHECK(out != NULL && out != meshes[i] && identical(out, meshes[i]));
      weft_mesh_free(out);
    }
  }
  /* The copy outlives its source. */
  {
    WeftMesh *out = NULL;
    CHECK_STATUS(weft_loop(meshes[0], 0, WEFT_NAKED_EDGES_SMOOTH, &out), WEFT_STATUS_OK);
    weft_mesh_free(meshes[0]);
    CHECK(weft_mesh_vertex_count(out) == 9 && memcmp(weft_mesh_positions(out), grid_positions, sizeof grid_positions) == 0);
    CHECK(memcmp(weft_mesh_face_indices(out), tri_grid_indices, sizeof tri_grid_indices) == 0);
    weft_mesh_free(out);
  }
  weft_mesh_free(meshes[1]);
  weft_mesh_free(meshes[2]);
}

static void test_refiner(void) {
  WeftMesh *mesh = unit_cube(), *one_shot = NULL, *moved_cube = NULL, *from_refiner = NULL;
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
  moved_cube = make_mesh(moved, 8, cube_sizes, 6, cube_indices, 24);
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
  WeftMesh *mesh = unit_cube(), *out = NULL;
  WeftRefiner *refiner = NULL;
  CHECK_STATUS(weft_catmull_clark(mesh, 16, WEFT_NAKED_EDGES_SMOOTH, &out), WEFT_STATUS_RESULT_TOO_LARGE);
  CHECK_MESSAGE("16 levels of subdivision: level 14 would make 1610612736 faces");
  CHECK_MESSAGE("use at most 13 levels");
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

  /* Loop's own: too many levels of a triangle mesh, an unknown naked-edge mode. */
  mesh = octahedron();
  CHECK_STATUS(weft_loop(mesh, 20, WEFT_NAKED_EDGES_SMOOTH, &out), WEFT_STATUS_RESULT_TOO_LARGE);
  CHECK_MESSAGE("result too large: 20 levels of subdivision: level 14 would make 2147483648 faces");
  CHECK_MESSAGE("past the limit of 2147483647");
  CHECK(out == NULL);
  CHECK_MESSAGE("use at most 13 levels");
  CHECK_STATUS(weft_loop(mesh, 1, 7, &out), WEFT_STATUS_INVALID_ARGUMENT);
  CHECK_MESSAGE("naked_edges is 7; it must be WEFT_NAKED_EDGES_FIXED (0), WEFT_NAKED_EDGES_SMOOTH (1), "
                "WEFT_NAKED_EDGES_CORNER_FIXED (2) or WEFT_NAKED_EDGES_NONE (3)");
  CHECK(out == NULL);
  CHECK_STATUS(weft_loop(mesh, 1, WEFT_NAKED_EDGES_SMOOTH, NULL), WEFT_STATUS_NULL_POINTER);
  CHECK_MESSAGE("out_mesh is NULL");
  weft_mesh_free(mesh);
}

/* A quad, a triangle and a pentagon: 2 + 1 + 3 triangles. */
static void test_triangulate_with_parents_and_as_triangles(void) {
  const double positions[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 2, 0, 0, 2, 1, 0, 3, 1, 0, 2.5, 2, 0};
  const uint32_t sizes[] = {4, 3, 5};
  const uint32_t indices[] = {0, 1, 2, 3, 1, 4, 5, 2, 1, 5, 6, 7};
  const uint32_t expected_parents[] = {0, 0, 1, 2, 2, 2};
  WeftMesh *mesh = make_mesh(positions, 8, sizes, 3, indices, 12), *triangles = NULL, *again = NULL, *copy = NULL;
  uint32_t parents[7] = {99, 99, 99, 99, 99, 99, 99};
  size_t split = 99;

  CHECK_STATUS(weft_triangulate_ex(mesh, &triangles, parents), WEFT_STATUS_OK);
  CHECK(weft_mesh_face_count(triangles) == weft_mesh_index_count(mesh) - 2 * weft_mesh_face_count(mesh));
  CHECK(memcmp(parents, expected_parents, sizeof expected_parents) == 0 && parents[6] == 99);
  CHECK_STATUS(weft_triangulate(mesh, &again), WEFT_STATUS_OK);
  CHECK(identical(triangles, again));
  weft_mesh_free(again);
  again = NULL;
  CHECK_STATUS(weft_triangulate_ex(mesh, &again, NULL), WEFT_STATUS_OK);
  CHECK(identical(triangles, again));
  weft_mesh_free(again);
  again = NULL;
  parents[0] = 99;
  CHECK_STATUS(weft_triangulate_ex(mesh, NULL, parents), WEFT_STATUS_NULL_POINTER);
  CHECK_MESSAGE("out_mesh is NULL");
  CHECK_STATUS(weft_triangulate_ex(NULL, &again, parents), WEFT_STATUS_NULL_POINTER);
  CHECK(again == NULL && parents[0] == 99);

  CHECK_STATUS(weft_as_triangles(mesh, &again, &split), WEFT_STATUS_OK);
  CHECK(split == 2 && identical(triangles, again));
  CHECK_STATUS(weft_as_triangles(triangles, &copy, &split), WEFT_STATUS_OK);
  CHECK(split == 0 && identical(triangles, copy));
  weft_mesh_free(copy);
  copy = NULL;
  CHECK_STATUS(weft_as_triangles(triangles, &copy, NULL), WEFT_STATUS_OK);
  CHECK(identical(triangles, copy));
  split = 99;
  CHECK_STATUS(weft_as_triangles(NULL, &copy, &split), WEFT_STATUS_NULL_POINTER);
  CHECK_MESSAGE("mesh is NULL");
  CHECK_STATUS(weft_as_triangles(mesh, NULL, &split), WEFT_STATUS_NULL_POINTER);
  CHECK(split == 99);
  weft_mesh_free(copy);
  weft_mesh_free(again);
  weft_mesh_free(triangles);
  weft_mesh_free(mesh);
}

/* weft_subdivide_into writes what weft_catmull_clark and weft_loop make,
 * bit for bit, into the caller's buffers, again and again into the same
 * ones; a buffer one value short is refused and left untouched. */
static void check_into(const WeftMesh *cage, uint32_t scheme, uint32_t levels, uint32_t naked_edges) {
  size_t n = 0, f = 0, k = 0, round;
  WeftMesh *expected = NULL;
  WeftStatus made = scheme == WEFT_SCHEME_LOOP ? weft_loop(cage, levels, naked_edges, &expected)
                                                : weft_catmull_clark(cage, levels, naked_edges, &expected);
  CHECK_STATUS(made, WEFT_STATUS_OK);
  CHECK_STATUS(weft_subdivision_counts(cage, scheme, levels, &n, &f, &k), WEFT_STATUS_OK);
  CHECK(n == weft_mesh_vertex_count(expected) && k == weft_mesh_index_count(expected));
  double *positions = malloc(sizeof(double) * (3 * n + 1));
  uint32_t *indices = malloc(sizeof(uint32_t) * (k + 1));
  for (round = 0; round < 2; ++round) {
    positions[3 * n] = -5.0;
    indices[k] = 77;
    CHECK_STATUS(weft_subdivide_into(cage, scheme, levels, naked_edges, positions, 3 * n + 1, indices, k + 1),
                 WEFT_STATUS_OK);
    CHECK(memcmp(positions, weft_mesh_positions(expected), sizeof(double) * 3 * n) == 0);
    CHECK(memcmp(indices, weft_mesh_face_indices(expected), sizeof(uint32_t) * k) == 0);
    CHECK(positions[3 * n] == -5.0 && indices[k] == 77);
  }
  memset(positions, 0, sizeof(double) * 3 * n);
  CHECK_STATUS(weft_subdivide_into(cage, scheme, levels, naked_edges, positions, 3 * n - 1, indices, k),
               WEFT_STATUS_BUFFER_TOO_SMALL);
  CHECK_MESSAGE("positions has room for");
  CHECK(positions[0] == 0.0 && positions[3 * n - 2] == 0.0);
  CHECK_STATUS(weft_subdivide_into(cage, scheme, levels, naked_edges, positions, 3 * n, indices, k - 1),
               WEFT_STATUS_BUFFER_TOO_SMALL);
  CHECK_MESSAGE("face_indices has room for");
  CHECK(positions[0] == 0.0);
  free(positions);
  free(indices);
  weft_mesh_free(expected);
}

static void test_subdivide_into_caller_buffers(void) {
  WeftMesh *open_grid = grid(), *closed = octahedron(), *triangles = tri_grid();
  uint32_t levels, mode;
  for (levels = 0; levels <= 3; ++levels) {
    for (mode = WEFT_NAKED_EDGES_FIXED; mode <= WEFT_NAKED_EDGES_CORNER_FIXED; ++mode) {
      check_into(open_grid, WEFT_SCHEME_CATMULL_CLARK, levels, mode);
      check_into(closed, WEFT_SCHEME_CATMULL_CLARK, levels, mode);
      check_into(closed, WEFT_SCHEME_LOOP, levels, mode);
      check_into(triangles, WEFT_SCHEME_LOOP, levels, mode);
    }
  }
  double positions[3 * 100];
  uint32_t indices[400];
  CHECK_STATUS(weft_subdivide_into(open_grid, WEFT_SCHEME_LOOP, 1, WEFT_NAKED_EDGES_FIXED, positions, 300, indices,
                                   400),
               WEFT_STATUS_NOT_TRIANGLES);
  CHECK_STATUS(weft_subdivide_into(open_grid, 7, 1, WEFT_NAKED_EDGES_FIXED, positions, 300, indices, 400),
               WEFT_STATUS_INVALID_ARGUMENT);
  CHECK_STATUS(weft_subdivide_into(open_grid, WEFT_SCHEME_CATMULL_CLARK, 1, WEFT_NAKED_EDGES_FIXED, NULL, 300,
                                   indices, 400),
               WEFT_STATUS_NULL_POINTER);
  CHECK_STATUS(weft_subdivide_into(NULL, WEFT_SCHEME_CATMULL_CLARK, 1, WEFT_NAKED_EDGES_FIXED, positions, 300,
                                   indices, 400),
               WEFT_STATUS_NULL_POINTER);
  weft_mesh_free(open_grid);
  weft_mesh_free(closed);
  weft_mesh_free(triangles);
}

int main(void) {
  test_cube();
  test_grid_modes();
  test_loop_and_triangulate();
  test_triangulate_with_parents_and_as_triangles();
  test_loop_closed();
  test_loop_open_modes();
  test_level_zero_is_a_copy();
  test_refiner();
  test_bad_arguments();
  test_subdivide_into_caller_buffers();
  return check_summary("test_subdivide");
}
