#include <stdio.h>
#include <string.h>

#include "check.h"

int check_failures = 0;

const double cube_positions[24] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0, 0, 1, 1, 0, 1, 0, 1, 1, 1, 1, 1};
const uint32_t cube_sizes[6] = {4, 4, 4, 4, 4, 4};
const uint32_t cube_indices[24] = {0, 2, 3, 1, 4, 5, 7, 6, 0, 1, 5, 4, 2, 6, 7, 3, 0, 4, 6, 2, 1, 3, 7, 5};

WeftMesh *make_mesh(const double *positions, size_t vertex_count, const uint32_t *sizes, size_t face_count,
                    const uint32_t *indices, size_t index_count) {
  WeftMesh *mesh = NULL;
  CHECK_STATUS(weft_mesh_new(positions, vertex_count, sizes, face_count, indices, index_count, &mesh), WEFT_STATUS_OK);
  return mesh;
}

WeftSubdivisionOptions smooth_catmull_clark(void) {
  WeftSubdivisionOptions options;
  memset(&options, 0, sizeof options);
  options.scheme = WEFT_SCHEME_CATMULL_CLARK;
  options.naked_edges = WEFT_NAKED_EDGES_SMOOTH;
  options.creasing = WEFT_CREASING_UNIFORM;
  return options;
}

WeftMesh *unit_cube(void) { return make_mesh(cube_positions, 8, cube_sizes, 6, cube_indices, 24); }

void set_creases(WeftSubdivisionOptions *options, size_t count, const uint32_t *pairs, const double *sharpness) {
  options->crease_count = count;
  options->crease_vertex_pairs = pairs;
  options->crease_sharpness = sharpness;
}

void check_report(const char *file, int line, const char *what) {
  check_failures++;
  fprintf(stderr, "%s:%d: check failed: %s\n", file, line, what);
}

int check_contains(const char *file, int line, const char *message, const char *needle) {
  if (message != NULL && strstr(message, needle) != NULL) return 1;
  check_failures++;
  fprintf(stderr, "%s:%d: message \"%s\" does not contain \"%s\"\n", file, line,
          message ? message : "(null)", needle);
  return 0;
}

int check_summary(const char *program) {
  if (check_failures) fprintf(stderr, "%s: %d checks failed\n", program, check_failures);
  return check_failures ? 1 : 0;
}
