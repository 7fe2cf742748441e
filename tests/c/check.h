/* A tiny assertion kit for the C tests: CHECK counts failures and reports
 * the file and line; each test program returns check_summary(). */
#ifndef WEFT_TEST_CHECK_H
#define WEFT_TEST_CHECK_H

#include <stdio.h>

#include "weft.h"

extern int check_failures;
void check_report(const char *file, int line, const char *what);
int check_summary(const char *program);
/* True when `message` contains `needle` (and reports it otherwise). */
int check_contains(const char *file, int line, const char *message, const char *needle);

/* The unit cube: vertex i at (i & 1, (i >> 1) & 1, (i >> 2) & 1), six quads
 * wound outwards. */
extern const double cube_positions[24];
extern const uint32_t cube_sizes[6];
extern const uint32_t cube_indices[24];
/* The unit cube as a mesh (make_mesh). */
WeftMesh *unit_cube(void);
/* A mesh made from caller buffers with weft_mesh_new; a failure to make it
 * is a failed check (and NULL). */
WeftMesh *make_mesh(const double *positions, size_t vertex_count, const uint32_t *sizes, size_t face_count,
                    const uint32_t *indices, size_t index_count);
/* Catmull-Clark options, every other field 0: smooth naked edges, uniform
 * creasing, no creases, corners or holes. */
WeftSubdivisionOptions smooth_catmull_clark(void);
/* Gives `options` `count` creases: vertex pairs (two indices each) and their
 * sharpness. */
void set_creases(WeftSubdivisionOptions *options, size_t count, const uint32_t *pairs, const double *sharpness);

#define CHECK(cond) ((cond) ? (void)0 : check_report(__FILE__, __LINE__, #cond))
#define CHECK_STATUS(call, expected) \
  do { WeftStatus check_s_ = (call); if (check_s_ != (expected)) { \
    check_report(__FILE__, __LINE__, #call " returned an unexpected status"); \
    fprintf(stderr, "  got %u, message: %s\n", (unsigned)check_s_, weft_last_error_message()); } } while (0)
#define CHECK_MESSAGE(needle) check_contains(__FILE__, __LINE__, weft_last_error_message(), (needle))
/* A call refused with `expected` and a message that contains `needle`. */
#define CHECK_FAILS_WITH(call, expected, needle) \
  do { CHECK_STATUS(call, expected); CHECK_MESSAGE(needle); } while (0)

#endif
