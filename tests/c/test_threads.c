/* Every export is safe to call from several threads at once, on distinct
 * meshes and on the same const mesh, and the last error is per thread. */
#include <pthread.h>
#include <string.h>

#include "check.h"

#define THREADS 8
#define ROUNDS 200

static const double positions[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0, 0, 1, 1, 0, 1, 0, 1, 1, 1, 1, 1};
static const uint32_t sizes[] = {4, 4, 4, 4, 4, 4};
static const uint32_t indices[] = {0, 2, 3, 1, 4, 5, 7, 6, 0, 1, 5, 4, 2, 6, 7, 3, 0, 4, 6, 2, 1, 3, 7, 5};
static const WeftMesh *shared_mesh;

struct result {
  int failures;
};

static void *hammer(void *arg) {
  struct result *result = arg;
  static const uint32_t bad[] = {0, 1, 99};
  static const uint32_t tri[] = {3};
  int round;
  for (round = 0; round < ROUNDS; round++) {
    WeftMesh *own = NULL;
    WeftMeshInfo info;
    if (weft_mesh_new(positions, 8, sizes, 6, indices, 24, &own) != WEFT_STATUS_OK) result->failures++;
    if (weft_mesh_info(own, &info) != WEFT_STATUS_OK || info.edge_count != 12) result->failures++;
    if (weft_mesh_info(shared_mesh, &info) != WEFT_STATUS_OK || !info.is_closed) result->failures++;
    weft_mesh_free(own);
    /* Each thread fails in its own way; its message must be its own. */
    if (round % 2 == 0) {
      if (weft_mesh_new(positions, 8, tri, 1, bad, 3, &own) != WEFT_STATUS_INDEX_OUT_OF_RANGE) result->failures++;
      if (strstr(weft_last_error_message(), "vertex index 99") == NULL) result->failures++;
    } else {
      if (weft_mesh_info(NULL, &info) != WEFT_STATUS_NULL_POINTER) result->failures++;
      if (strstr(weft_last_error_message(), "mesh is NULL") == NULL) result->failures++;
    }
  }
  return NULL;
}

int main(void) {
  pthread_t threads[THREADS];
  struct result results[THREADS];
  WeftMesh *mesh = NULL;
  int i;
  CHECK_STATUS(weft_mesh_new(positions, 8, sizes, 6, indices, 24, &mesh), WEFT_STATUS_OK);
  shared_mesh = mesh;
  for (i = 0; i < THREADS; i++) {
    results[i].failures = 0;
    CHECK(pthread_create(&threads[i], NULL, hammer, &results[i]) == 0);
  }
  for (i = 0; i < THREADS; i++) {
    CHECK(pthread_join(threads[i], NULL) == 0);
    CHECK(results[i].failures == 0);
  }
  /* This thread has had no failure: its message is still empty. */
  CHECK(strcmp(weft_last_error_message(), "") == 0);
  weft_mesh_free(mesh);
  return check_summary("test_threads");
}
