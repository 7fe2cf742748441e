/* Creases, corners, carried data, face-varying values, the limit surface and
 * the refiner with options through the C ABI, and every bad argument with
 * its own status and message. */
#include <math.h>
#include <string.h>

#include "check.h"

/* The twelve edges of the cube. */
static const uint32_t cube_edges[] = {0, 1, 0, 2, 0, 4, 1, 3, 1, 5, 2, 3,
                                      2, 6, 3, 7, 4, 5, 4, 6, 5, 7, 6, 7};

static int near(double a, double b) { return fabs(a - b) < 1e-12; }

static void test_creases_and_corners(void) {
  WeftMesh *mesh = unit_cube(), *out = NULL, *plain = NULL;
  WeftSubdivisionOptions options = smooth_catmull_clark();
  /* The four edges of face 0 infinitely sharp, vertex 7 a corner. */
  const uint32_t pairs[] = {0, 2, 2, 3, 3, 1, 1, 0};
  const double sharpness[] = {INFINITY, 10.0, 12.0, INFINITY};
  const uint32_t corners[] = {7};
  const double corner_sharpness[] = {INFINITY};
  const double *p;
  set_creases(&options, 4, pairs, sharpness);
  options.corner_count = 1;
  options.corner_vertices = corners;
  options.corner_sharpness = corner_sharpness;
  CHECK_STATUS(weft_subdivide_ex(mesh, &options, 1, &out), WEFT_STATUS_OK);
  CHECK(weft_mesh_vertex_count(out) == 26 && weft_mesh_face_count(out) == 24);
  p = weft_mesh_positions(out);
  /* Vertex 0 follows its crease: 3/4 itself + 1/8 each of vertices 1 and 2. */
  CHECK(near(p[0], 0.125) && near(p[1], 0.125) && near(p[2], 0.0));
  /* The corner stays. */
  CHECK(near(p[21], 1.0) && near(p[22], 1.0) && near(p[23], 1.0));
  weft_mesh_free(out);

  /* Sharpness 0 everywhere is the plain scheme. */
  {
    const double zeros[] = {0, 0, 0, 0};
    options.crease_sharpness = zeros;
    options.corner_count = 0;
    options.corner_vertices = NULL;
    options.corner_sharpness = NULL;
    CHECK_STATUS(weft_subdivide_ex(mesh, &options, 2, &out), WEFT_STATUS_OK);
    CHECK_STATUS(weft_catmull_clark(mesh, 2, WEFT_NAKED_EDGES_SMOOTH, &plain), WEFT_STATUS_OK);
    {
      size_t i, n = 3 * weft_mesh_vertex_count(out);
      int same = n == 3 * weft_mesh_vertex_count(plain);
      for (i = 0; same && i < n; ++i) same = near(weft_mesh_positions(out)[i], weft_mesh_positions(plain)[i]);
      CHECK(same);
    }
    weft_mesh_free(out);
    weft_mesh_free(plain);
  }
  weft_mesh_free(mesh);
}

static void test_counts_and_vertex_data(void) {
  WeftMesh *mesh = unit_cube(), *out = NULL;
  WeftSubdivisionOptions options = smooth_catmull_clark();
  const uint32_t pairs[] = {0, 1};
  const double sharpness[] = {1.5};
  double data[16], refined[2 * 98];
  size_t vertices = 0, faces = 0, indices = 0, v;
  int ok = 1;
  for (v = 0; v < 8; ++v) {
    data[2 * v] = cube_positions[3 * v];
    data[2 * v + 1] = 1.0;
  }
  set_creases(&options, 1, pairs, sharpness);
  CHECK_STATUS(weft_subdivision_counts(mesh, WEFT_SCHEME_CATMULL_CLARK, 2, &vertices, &faces, &indices), WEFT_STATUS_OK);
  CHECK(vertices == 98 && faces == 96 && indices == 384);
  CHECK_STATUS(weft_subdivide_vertex_data(mesh, &options, 2, data, 16, 2, refined, 2 * 98), WEFT_STATUS_OK);
  CHECK_STATUS(weft_subdivide_ex(mesh, &options, 2, &out), WEFT_STATUS_OK);
  /* Column 0 is x, refined like the positions; column 1 stays 1. */
  for (v = 0; v < 98; ++v) {
    ok &= near(refined[2 * v], weft_mesh_positions(out)[3 * v]);
    ok &= near(refined[2 * v + 1], 1.0);
  }
  CHECK(ok);
  weft_mesh_free(out);

  /* Too small: an error, and nothing written. */
  refined[0] = -7.0;
  CHECK_STATUS(weft_subdivide_vertex_data(mesh, &options, 2, data, 16, 2, refined, 2 * 98 - 1), WEFT_STATUS_BUFFER_TOO_SMALL);
  CHECK_MESSAGE("out_data has room for 195 elements but 196 are needed");
  CHECK(refined[0] == -7.0);
  CHECK_STATUS(weft_subdivide_vertex_data(mesh, &options, 2, data, 15, 2, refined, 2 * 98), WEFT_STATUS_COUNT_MISMATCH);
  CHECK_STATUS(weft_subdivide_vertex_data(mesh, &options, 2, data, 16, 0, refined, 2 * 98), WEFT_STATUS_INVALID_ARGUMENT);
  weft_mesh_free(mesh);
}

static void test_face_varying(void) {
  WeftMesh *mesh = unit_cube();
  WeftSubdivisionOptions options = smooth_catmull_clark();
  double uvs[16], out[2 * 96];
  uint32_t bad[24];
  size_t v;
  for (v = 0; v < 8; ++v) {
    uvs[2 * v] = cube_positions[3 * v] + 0.5 * cube_positions[3 * v + 2];
    uvs[2 * v + 1] = cube_positions[3 * v + 1];
  }
  /* One value per vertex, linear everywhere: level 1 keeps the cage's values
   * at its vertices and averages them at face points. */
  CHECK_STATUS(weft_subdivide_face_varying(mesh, &options, 1, WEFT_FACE_VARYING_ALL, uvs, 8, 2, cube_indices, 24, out, 2 * 96),
               WEFT_STATUS_OK);
  /* Child 0 of face 0 is [vertex 0, edge point, face point, edge point]. */
  CHECK(near(out[0], uvs[0]) && near(out[1], uvs[1]));
  CHECK(near(out[4], 0.5) && near(out[5], 0.5));
  CHECK_STATUS(weft_subdivide_face_varying(mesh, &options, 1, WEFT_FACE_VARYING_ALL, uvs, 8, 2, cube_indices, 24, out, 10),
               WEFT_STATUS_BUFFER_TOO_SMALL);
  memcpy(bad, cube_indices, sizeof bad);
  bad[5] = 8;
  CHECK_STATUS(weft_subdivide_face_varying(mesh, &options, 1, WEFT_FACE_VARYING_ALL, uvs, 8, 2, bad, 24, out, 2 * 96),
               WEFT_STATUS_INDEX_OUT_OF_RANGE);
  CHECK_MESSAGE("face corner 5 uses value 8");
  CHECK_STATUS(weft_subdivide_face_varying(mesh, &options, 1, WEFT_FACE_VARYING_ALL, uvs, 8, 2, cube_indices, 23, out, 2 * 96),
               WEFT_STATUS_COUNT_MISMATCH);
  CHECK_STATUS(weft_subdivide_face_varying(mesh, &options, 1, 6, uvs, 8, 2, cube_indices, 24, out, 2 * 96),
               WEFT_STATUS_INVALID_ARGUMENT);
  weft_mesh_free(mesh);
}

static void test_limit(void) {
  WeftMesh *mesh = unit_cube();
  WeftSubdivisionOptions options = smooth_catmull_clark();
  double sharpness[12], positions[3 * 26], normals[3 * 26];
  size_t i;
  /* Every edge infinitely sharp: the limit is the cube itself, its faces flat. */
  for (i = 0; i < 12; ++i) sharpness[i] = WEFT_SHARPNESS_INFINITE;
  set_creases(&options, 12, cube_edges, sharpness);
  CHECK_STATUS(weft_subdivide_limit(mesh, &options, 1, positions, normals, 3 * 26), WEFT_STATUS_OK);
  /* The point of face 0 (z = 0, index 8 + 12) stays in its plane; its normal points out (-z). */
  CHECK(near(positions[3 * 20], 0.5) && near(positions[3 * 20 + 1], 0.5) && near(positions[3 * 20 + 2], 0.0));
  CHECK(near(normals[3 * 20], 0.0) && near(normals[3 * 20 + 1], 0.0) && near(normals[3 * 20 + 2], -1.0));
  /* Normals are optional. */
  CHECK_STATUS(weft_subdivide_limit(mesh, &options, 1, positions, NULL, 3 * 26), WEFT_STATUS_OK);
  positions[0] = -7.0;
  CHECK_STATUS(weft_subdivide_limit(mesh, &options, 1, positions, normals, 3 * 26 - 1), WEFT_STATUS_BUFFER_TOO_SMALL);
  CHECK(positions[0] == -7.0);
  CHECK_STATUS(weft_subdivide_limit(mesh, &options, 1, NULL, normals, 3 * 26), WEFT_STATUS_NULL_POINTER);
  weft_mesh_free(mesh);
}

static void test_refiner(void) {
  WeftMesh *mesh = unit_cube(), *moved_mesh = NULL, *expected = NULL;
  WeftRefiner *refiner = NULL;
  WeftSubdivisionOptions options = smooth_catmull_clark();
  const uint32_t pairs[] = {0, 2, 2, 3};
  const double sharpness[] = {2.5, 0.5};
  double moved[24], out[3 * 98];
  size_t i;
  int same = 1;
  options.creasing = WEFT_CREASING_CHAIKIN;
  set_creases(&options, 2, pairs, sharpness);
  CHECK_STATUS(weft_refiner_new_ex(mesh, &options, 2, &refiner), WEFT_STATUS_OK);
  CHECK(weft_refiner_vertex_count(refiner) == 98);
  for (i = 0; i < 24; ++i) moved[i] = cube_positions[i] * (1.0 + 0.1 * (double)(i % 3));
  CHECK_STATUS(weft_refiner_evaluate(refiner, moved, 8, out, 3 * 98), WEFT_STATUS_OK);
  CHECK_STATUS(weft_mesh_new(moved, 8, cube_sizes, 6, cube_indices, 24, &moved_mesh), WEFT_STATUS_OK);
  CHECK_STATUS(weft_subdivide_ex(moved_mesh, &options, 2, &expected), WEFT_STATUS_OK);
  for (i = 0; i < 3 * 98; ++i) same &= near(out[i], weft_mesh_positions(expected)[i]);
  CHECK(same);
  weft_mesh_free(expected);
  weft_mesh_free(moved_mesh);
  weft_refiner_free(refiner);
  weft_mesh_free(mesh);
}

static void test_errors(void) {
  WeftMesh *mesh = unit_cube(), *out = NULL;
  WeftRefiner *refiner = NULL;
  WeftSubdivisionOptions options = smooth_catmull_clark();
  const uint32_t unknown[] = {0, 7};
  const uint32_t pairs[] = {0, 1};
  const double negative[] = {-1.0};
  double nan_value[1];
  const uint32_t far_corner[] = {8};
  const double one[] = {1.0};
  nan_value[0] = NAN;

  set_creases(&options, 1, unknown, one);
  CHECK_STATUS(weft_subdivide_ex(mesh, &options, 1, &out), WEFT_STATUS_INVALID_ARGUMENT);
  CHECK_MESSAGE("crease 0 joins vertices 0 and 7, which are not an edge of the mesh");
  CHECK(out == NULL);
  CHECK_STATUS(weft_refiner_new_ex(mesh, &options, 1, &refiner), WEFT_STATUS_INVALID_ARGUMENT);
  CHECK(refiner == NULL);

  options.crease_vertex_pairs = pairs;
  options.crease_sharpness = negative;
  CHECK_STATUS(weft_subdivide_ex(mesh, &options, 1, &out), WEFT_STATUS_INVALID_ARGUMENT);
  CHECK_MESSAGE("crease 0 (0, 1) has sharpness -1");
  options.crease_sharpness = nan_value;
  CHECK_STATUS(weft_subdivide_ex(mesh, &options, 1, &out), WEFT_STATUS_INVALID_ARGUMENT);
  CHECK_MESSAGE("sharpness NaN");

  options.crease_sharpness = NULL;
  CHECK_STATUS(weft_subdivide_ex(mesh, &options, 1, &out), WEFT_STATUS_NULL_POINTER);
  CHECK_MESSAGE("crease_sharpness is NULL");

  options = smooth_catmull_clark();
  options.corner_count = 1;
  options.corner_vertices = far_corner;
  options.corner_sharpness = one;
  CHECK_STATUS(weft_subdivide_ex(mesh, &options, 1, &out), WEFT_STATUS_INVALID_ARGUMENT);
  CHECK_MESSAGE("corner 0 is vertex 8, but the mesh has 8 vertices");

  options = smooth_catmull_clark();
  options.creasing = 7;
  CHECK_STATUS(weft_subdivide_ex(mesh, &options, 1, &out), WEFT_STATUS_INVALID_ARGUMENT);
  CHECK_MESSAGE("creasing is 7");
  options = smooth_catmull_clark();
  options.scheme = WEFT_SCHEME_LOOP;
  CHECK_STATUS(weft_subdivide_ex(mesh, &options, 1, &out), WEFT_STATUS_NOT_TRIANGLES);
  CHECK_STATUS(weft_subdivide_ex(mesh, NULL, 1, &out), WEFT_STATUS_NULL_POINTER);
  CHECK_MESSAGE("options is NULL");
  options = smooth_catmull_clark();
  CHECK_STATUS(weft_subdivide_ex(NULL, &options, 1, &out), WEFT_STATUS_NULL_POINTER);
  CHECK_STATUS(weft_subdivide_ex(mesh, &options, 1, NULL), WEFT_STATUS_NULL_POINTER);
  CHECK(out == NULL);
  weft_mesh_free(mesh);
}

static void test_crease_edges_from_mesh(void) {
  /* Two quads sharing an unwelded edge (vertices 1, 4 and 2, 5 coincide). */
  static const double p[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 1, 0, 0, 1, 1, 0, 2, 1, 0, 2, 0, 0};
  static const uint32_t sizes[] = {4, 4};
  static const uint32_t faces[] = {0, 1, 2, 3, 4, 7, 6, 5};
  WeftMesh *mesh = NULL, *welded = NULL, *cube_mesh = unit_cube();
  uint32_t pairs[16];
  size_t count = 99;
  CHECK_STATUS(weft_mesh_new(p, 8, sizes, 2, faces, 8, &mesh), WEFT_STATUS_OK);
  CHECK_STATUS(weft_crease_edges_from_mesh(mesh, 180.0, &welded, pairs, 16, &count), WEFT_STATUS_OK);
  CHECK(count == 1 && weft_mesh_vertex_count(welded) == 6);
  CHECK((pairs[0] == 1 && pairs[1] == 2) || (pairs[0] == 2 && pairs[1] == 1));
  weft_mesh_free(welded);
  welded = NULL;
  /* Every edge of a cube folds by 90 degrees. */
  {
    uint32_t cube_pairs[48];
    CHECK_STATUS(weft_crease_edges_from_mesh(cube_mesh, 45.0, &welded, cube_pairs, 48, &count), WEFT_STATUS_OK);
    CHECK(count == 12);
    weft_mesh_free(welded);
    welded = NULL;
    count = 99;
    CHECK_STATUS(weft_crease_edges_from_mesh(cube_mesh, 45.0, &welded, cube_pairs, 23, &count), WEFT_STATUS_BUFFER_TOO_SMALL);
    CHECK(count == 99 && welded == NULL);
    CHECK_STATUS(weft_crease_edges_from_mesh(cube_mesh, NAN, &welded, cube_pairs, 48, &count), WEFT_STATUS_INVALID_ARGUMENT);
  }
  weft_mesh_free(cube_mesh);
  weft_mesh_free(mesh);
}

/* The cube as six separate quads: corner c of the cube's faces is vertex c,
 * at the position of cube vertex cube_indices[c]. */
static WeftMesh *unwelded_cube(double *positions) {
  uint32_t indices[24];
  WeftMesh *mesh = NULL;
  int c;
  for (c = 0; c < 24; ++c) {
    memcpy(positions + 3 * c, cube_positions + 3 * cube_indices[c], 3 * sizeof(double));
    indices[c] = (uint32_t)c;
  }
  CHECK_STATUS(weft_mesh_new(positions, 24, cube_sizes, 6, indices, 24, &mesh), WEFT_STATUS_OK);
  return mesh;
}

static void test_crease_edges_vertex_map(void) {
  double positions[72];
  WeftMesh *pieces = unwelded_cube(positions), *welded = NULL, *plain = NULL;
  uint32_t pairs[48], plain_pairs[48], map[24];
  /* A colour per input vertex, from its position: the weld must keep it. */
  double colour[24], welded_colour[8];
  int hit[8] = {0};
  size_t count = 99, plain_count = 0, v, first_new = 0;
  const double *welded_positions;
  for (v = 0; v < 24; ++v) colour[v] = positions[3 * v] + 2 * positions[3 * v + 1] + 4 * positions[3 * v + 2];

  CHECK_STATUS(weft_crease_edges_from_mesh_ex(pieces, 180.0, &welded, pairs, 48, &count, map, 24), WEFT_STATUS_OK);
  CHECK(weft_mesh_vertex_count(welded) == 8 && count == 12);
  welded_positions = weft_mesh_positions(welded);
  for (v = 0; v < 24; ++v) {
    CHECK(map[v] < 8);
    if (map[v] >= 8) continue;
    /* Each input vertex went to the welded vertex at its position... */
    CHECK(memcmp(welded_positions + 3 * map[v], positions + 3 * v, 3 * sizeof(double)) == 0);
    /* ...which is numbered in order of first use: the first of its position keeps the lowest free index. */
    if (!hit[map[v]]) {
      CHECK(map[v] == first_new);
      first_new++;
      hit[map[v]] = 1;
    }
    welded_colour[map[v]] = colour[v];
  }
  CHECK(first_new == 8);
  /* Carried through the map, every input vertex finds its own colour on the welded mesh. */
  for (v = 0; v < 24; ++v) CHECK(map[v] < 8 && welded_colour[map[v]] == colour[v]);

  /* The same weld and creases as without the map. */
  CHECK_STATUS(weft_crease_edges_from_mesh(pieces, 180.0, &plain, plain_pairs, 48, &plain_count), WEFT_STATUS_OK);
  CHECK(plain_count == count && memcmp(plain_pairs, pairs, 2 * count * sizeof(uint32_t)) == 0);
  CHECK(memcmp(weft_mesh_positions(plain), welded_positions, 24 * sizeof(double)) == 0);
  CHECK(memcmp(weft_mesh_face_indices(plain), weft_mesh_face_indices(welded), 24 * sizeof(uint32_t)) == 0);
  weft_mesh_free(plain);
  weft_mesh_free(welded);
  welded = NULL;

  /* A welded mesh maps to itself. */
  {
    WeftMesh *whole = unit_cube();
    CHECK_STATUS(weft_crease_edges_from_mesh_ex(whole, 45.0, &welded, pairs, 48, &count, map, 8), WEFT_STATUS_OK);
    CHECK(count == 12);
    for (v = 0; v < 8; ++v) CHECK(map[v] == v);
    weft_mesh_free(welded);
    welded = NULL;
    weft_mesh_free(whole);
  }

  /* Too small a map, or none: refused before any work, nothing written. */
  map[0] = 77;
  count = 99;
  CHECK_STATUS(weft_crease_edges_from_mesh_ex(pieces, 180.0, &welded, pairs, 48, &count, map, 23),
               WEFT_STATUS_BUFFER_TOO_SMALL);
  CHECK_MESSAGE("out_vertex_map has room for 23 elements but 24 are needed");
  CHECK(map[0] == 77 && count == 99 && welded == NULL);
  CHECK_STATUS(weft_crease_edges_from_mesh_ex(pieces, 180.0, &welded, pairs, 48, &count, NULL, 0),
               WEFT_STATUS_BUFFER_TOO_SMALL);
  CHECK_MESSAGE("out_vertex_map has room for 0 elements but 24 are needed");
  CHECK_STATUS(weft_crease_edges_from_mesh_ex(pieces, 180.0, &welded, pairs, 48, &count, NULL, 24),
               WEFT_STATUS_NULL_POINTER);
  CHECK_MESSAGE("out_vertex_map is NULL");
  /* The other buffers and arguments as without the map. */
  CHECK_STATUS(weft_crease_edges_from_mesh_ex(pieces, 180.0, &welded, pairs, 23, &count, map, 24),
               WEFT_STATUS_BUFFER_TOO_SMALL);
  CHECK_MESSAGE("out_pairs has room for 23 elements but 24 are needed");
  CHECK(map[0] == 77);
  CHECK_STATUS(weft_crease_edges_from_mesh_ex(pieces, -1.0, &welded, pairs, 48, &count, map, 24),
               WEFT_STATUS_INVALID_ARGUMENT);
  CHECK_MESSAGE("the crease angle is -1 degrees");
  CHECK_STATUS(weft_crease_edges_from_mesh_ex(NULL, 180.0, &welded, pairs, 48, &count, map, 24),
               WEFT_STATUS_NULL_POINTER);
  CHECK_MESSAGE("mesh is NULL");
  CHECK_STATUS(weft_crease_edges_from_mesh_ex(pieces, 180.0, NULL, pairs, 48, &count, map, 24),
               WEFT_STATUS_NULL_POINTER);
  CHECK_MESSAGE("out_welded is NULL");
  CHECK_STATUS(weft_crease_edges_from_mesh_ex(pieces, 180.0, &welded, pairs, 48, NULL, map, 24),
               WEFT_STATUS_NULL_POINTER);
  CHECK_MESSAGE("out_crease_count is NULL");
  CHECK(map[0] == 77 && count == 99 && welded == NULL);
  /* An empty mesh needs no map. */
  {
    WeftMesh *empty = NULL;
    CHECK_STATUS(weft_mesh_new(NULL, 0, NULL, 0, NULL, 0, &empty), WEFT_STATUS_OK);
    CHECK_STATUS(weft_crease_edges_from_mesh_ex(empty, 180.0, &welded, NULL, 0, &count, NULL, 0), WEFT_STATUS_OK);
    CHECK(count == 0 && weft_mesh_vertex_count(welded) == 0);
    weft_mesh_free(welded);
    weft_mesh_free(empty);
  }
  weft_mesh_free(pieces);
}

/* Holes leave their children out, keep every vertex, and the counts and
 * parent faces with the same options say so; boundary "none" holes the
 * faces at the boundary; the smooth-triangle rule and the reserved fields
 * are checked. */
static void test_holes_and_options(void) {
  WeftMesh *mesh = unit_cube(), *out = NULL, *plain = NULL;
  WeftSubdivisionOptions options = smooth_catmull_clark();
  const uint32_t holes[] = {1, 4, 1};
  const uint32_t far_hole[] = {6};
  size_t vertices = 0, faces = 0, indices = 0;
  uint32_t parents[96];
  size_t i;
  int no_hole_child = 1;

  options.hole_count = 3;
  options.hole_faces = holes;
  CHECK_STATUS(weft_subdivide_ex(mesh, &options, 2, &out), WEFT_STATUS_OK);
  CHECK_STATUS(weft_catmull_clark(mesh, 2, WEFT_NAKED_EDGES_SMOOTH, &plain), WEFT_STATUS_OK);
  CHECK(weft_mesh_vertex_count(out) == weft_mesh_vertex_count(plain));
  CHECK(weft_mesh_face_count(out) == 96 - 2 * 16);
  CHECK_STATUS(weft_subdivision_counts_ex(mesh, &options, 2, &vertices, &faces, &indices), WEFT_STATUS_OK);
  CHECK(vertices == 98 && faces == 64 && indices == 256);
  CHECK_STATUS(weft_subdivision_parent_faces_ex(mesh, &options, 2, parents, 63), WEFT_STATUS_BUFFER_TOO_SMALL);
  CHECK_STATUS(weft_subdivision_parent_faces_ex(mesh, &options, 2, parents, 96), WEFT_STATUS_OK);
  for (i = 0; i < 64; ++i) no_hole_child &= parents[i] != 1 && parents[i] != 4;
  CHECK(no_hole_child && parents[0] == 0 && parents[16] == 2);
  weft_mesh_free(out);
  weft_mesh_free(plain);
  out = NULL;

  options.hole_faces = far_hole;
  options.hole_count = 1;
  CHECK_STATUS(weft_subdivide_ex(mesh, &options, 1, &out), WEFT_STATUS_INVALID_ARGUMENT);
  CHECK_MESSAGE("hole 0 is face 6, but the mesh has 6 faces");
  CHECK(out == NULL);
  options.hole_faces = NULL;
  CHECK_STATUS(weft_subdivide_ex(mesh, &options, 1, &out), WEFT_STATUS_NULL_POINTER);
  CHECK_MESSAGE("hole_faces");
  options.hole_count = 0;

  options.triangles = 2;
  CHECK_STATUS(weft_subdivide_ex(mesh, &options, 1, &out), WEFT_STATUS_INVALID_ARGUMENT);
  CHECK_MESSAGE("WEFT_TRIANGLES_SMOOTH");
  options.triangles = WEFT_TRIANGLES_SMOOTH;
  CHECK_STATUS(weft_subdivide_ex(mesh, &options, 1, &out), WEFT_STATUS_OK);
  weft_mesh_free(out);
  options.reserved[WEFT_SUBDIVISION_OPTIONS_RESERVED - 1] = 1;
  CHECK_STATUS(weft_subdivide_ex(mesh, &options, 1, &out), WEFT_STATUS_INVALID_ARGUMENT);
  CHECK_MESSAGE("reserved[7] is 1; it must be 0");
  options.reserved[WEFT_SUBDIVISION_OPTIONS_RESERVED - 1] = 0;
  options.reserved_flags = 4;
  CHECK_STATUS(weft_subdivide_ex(mesh, &options, 1, &out), WEFT_STATUS_INVALID_ARGUMENT);
  CHECK_MESSAGE("reserved_flags is 4");
  weft_mesh_free(mesh);

  /* A 2 x 2 grid has no face away from the boundary: "none" leaves nothing,
   * and keeps all 9 vertices and their refined points. */
  {
    const double grid_positions[] = {0, 0, 0, 1, 0, 0, 2, 0, 0, 0, 1, 0, 1, 1, 0, 2, 1, 0, 0, 2, 0, 1, 2, 0, 2, 2, 0};
    const uint32_t grid_sizes[] = {4, 4, 4, 4};
    const uint32_t grid_indices[] = {0, 1, 4, 3, 1, 2, 5, 4, 3, 4, 7, 6, 4, 5, 8, 7};
    WeftMesh *grid = make_mesh(grid_positions, 9, grid_sizes, 4, grid_indices, 16);
    CHECK_STATUS(weft_catmull_clark(grid, 1, WEFT_NAKED_EDGES_NONE, &out), WEFT_STATUS_OK);
    CHECK(weft_mesh_face_count(out) == 0 && weft_mesh_vertex_count(out) == 9 + 12 + 4);
    weft_mesh_free(out);
    CHECK_STATUS(weft_laplacian_smooth(grid, 1, 0.5, WEFT_NAKED_EDGES_NONE, &out), WEFT_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("only subdivision makes");
    weft_mesh_free(grid);
  }
}

int main(void) {
  test_crease_edges_from_mesh();
  test_crease_edges_vertex_map();
  test_creases_and_corners();
  test_counts_and_vertex_data();
  test_face_varying();
  test_limit();
  test_refiner();
  test_errors();
  test_holes_and_options();
  return check_summary("test_creases");
}
