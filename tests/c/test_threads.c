/* Every export is safe to call from several threads at once. Threads run
 * real operations (Catmull-Clark, Loop, weld, cull, T-nodes, the refiner's
 * evaluate, info) on one shared const mesh and one shared refiner, and on
 * meshes of their own, and every result must equal, bit for bit, what one
 * thread computed before they started. Meanwhile every thread fails in
 * its own way: the last error message it reads must be its own. */
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"

#define THREADS 8
#define ROUNDS 25

/* Two triangles; vertex 4 lies on edge 1-2 of the first: one T-node. */
static const double t_node_positions[] = {0, 0, 0, 2, 0, 0, 2, 2, 0, 4, 0, 0, 2, 0.5, 0};
static const uint32_t t_node_sizes[] = {3, 3};
static const uint32_t t_node_indices[] = {0, 1, 2, 4, 3, 2};

/* The inputs of the operations, all made from the cube scaled by `scale`
 * and moved by `shift` along x. */
struct inputs {
  double cage[24];
  WeftMesh *cube, *triangles, *joined, *t_nodes;
};

/* What the operations give. */
struct outcome {
  WeftMesh *subdivided, *looped, *welded, *culled;
  WeftWeldReport report;
  size_t culled_count, node_count;
  WeftTNode nodes[4];
  WeftMeshInfo info;
  double refined[3 * 98];
};

static WeftMesh *shared_mesh;
static const struct inputs *shared_inputs;
static const WeftRefiner *shared_refiner;
static struct inputs own_inputs[THREADS];
static struct outcome shared_reference, own_reference[THREADS];

static pthread_mutex_t gate_lock = PTHREAD_MUTEX_INITIALIZER;
static pthread_cond_t gate_open = PTHREAD_COND_INITIALIZER;
static int at_gate = 0;

/* Holds each thread until all have arrived, so that they run at once. */
static void wait_at_gate(void) {
  pthread_mutex_lock(&gate_lock);
  if (++at_gate == THREADS) pthread_cond_broadcast(&gate_open);
  while (at_gate < THREADS) pthread_cond_wait(&gate_open, &gate_lock);
  pthread_mutex_unlock(&gate_lock);
}

static void make_inputs(struct inputs *in, double scale, double shift) {
  double positions[24], t_nodes[15];
  WeftMesh *first = NULL, *second = NULL;
  const WeftMesh *pair[2];
  int i;
  for (i = 0; i < 24; ++i) {
    in->cage[i] = cube_positions[i] * scale + (i % 3 == 0 ? shift : 0);
    positions[i] = in->cage[i] + (i % 3 == 0 ? scale : 0);
  }
  for (i = 0; i < 15; ++i) t_nodes[i] = t_node_positions[i] * scale + (i % 3 == 0 ? shift : 0);
  CHECK_STATUS(weft_mesh_new(in->cage, 8, cube_sizes, 6, cube_indices, 24, &in->cube), WEFT_STATUS_OK);
  CHECK_STATUS(weft_triangulate(in->cube, &in->triangles), WEFT_STATUS_OK);
  /* Two cubes side by side: the weld joins them, the cull removes their shared wall. */
  CHECK_STATUS(weft_mesh_new(in->cage, 8, cube_sizes, 6, cube_indices, 24, &first), WEFT_STATUS_OK);
  CHECK_STATUS(weft_mesh_new(positions, 8, cube_sizes, 6, cube_indices, 24, &second), WEFT_STATUS_OK);
  pair[0] = first;
  pair[1] = second;
  CHECK_STATUS(weft_join(pair, 2, &in->joined), WEFT_STATUS_OK);
  CHECK_STATUS(weft_mesh_new(t_nodes, 5, t_node_sizes, 2, t_node_indices, 6, &in->t_nodes), WEFT_STATUS_OK);
  weft_mesh_free(first);
  weft_mesh_free(second);
}

static void free_inputs(struct inputs *in) {
  weft_mesh_free(in->cube);
  weft_mesh_free(in->triangles);
  weft_mesh_free(in->joined);
  weft_mesh_free(in->t_nodes);
}

/* Runs every operation on `in` (the refiner at `in`'s cage); returns the
 * number of calls that did not succeed. */
static int run_operations(const struct inputs *in, const WeftRefiner *refiner, struct outcome *out) {
  int failures = 0;
  memset(out, 0, sizeof *out);
  failures += weft_catmull_clark(in->cube, 2, WEFT_NAKED_EDGES_SMOOTH, &out->subdivided) != WEFT_STATUS_OK;
  failures += weft_loop(in->triangles, 2, WEFT_NAKED_EDGES_CORNER_FIXED, &out->looped) != WEFT_STATUS_OK;
  failures += weft_weld(in->joined, WEFT_DEFAULT_WELD_TOLERANCE, &out->welded, &out->report) != WEFT_STATUS_OK;
  failures += weft_cull_adjacent(out->welded, &out->culled, &out->culled_count) != WEFT_STATUS_OK;
  failures += weft_find_t_nodes(in->t_nodes, 1e-6, out->nodes, 4, &out->node_count) != WEFT_STATUS_OK;
  failures += weft_refiner_evaluate(refiner, in->cage, 8, out->refined, 3 * 98) != WEFT_STATUS_OK;
  failures += weft_mesh_info(out->culled, &out->info) != WEFT_STATUS_OK;
  return failures;
}

static void free_outcome(struct outcome *out) {
  weft_mesh_free(out->subdivided);
  weft_mesh_free(out->looped);
  weft_mesh_free(out->welded);
  weft_mesh_free(out->culled);
}

static int same_mesh(const WeftMesh *a, const WeftMesh *b) {
  size_t v = weft_mesh_vertex_count(a), f = weft_mesh_face_count(a), c = weft_mesh_index_count(a);
  return a != NULL && b != NULL && v == weft_mesh_vertex_count(b) && f == weft_mesh_face_count(b) &&
         c == weft_mesh_index_count(b) &&
         memcmp(weft_mesh_positions(a), weft_mesh_positions(b), 3 * v * sizeof(double)) == 0 &&
         memcmp(weft_mesh_face_sizes(a), weft_mesh_face_sizes(b), f * sizeof(uint32_t)) == 0 &&
         memcmp(weft_mesh_face_indices(a), weft_mesh_face_indices(b), c * sizeof(uint32_t)) == 0;
}

/* The number of ways `got` differs from `expected`, bit for bit. */
static int differences(const struct outcome *got, const struct outcome *expected) {
  int count = 0;
  size_t i;
  count += !same_mesh(got->subdivided, expected->subdivided);
  count += !same_mesh(got->looped, expected->looped);
  count += !same_mesh(got->welded, expected->welded);
  count += !same_mesh(got->culled, expected->culled);
  count += got->report.merged_vertex_count != expected->report.merged_vertex_count ||
           got->report.removed_face_count != expected->report.removed_face_count ||
           got->report.unused_vertex_count != expected->report.unused_vertex_count;
  count += got->culled_count != expected->culled_count;
  count += got->node_count != expected->node_count;
  for (i = 0; i < got->node_count && i < 4; ++i) {
    const WeftTNode *a = &got->nodes[i], *b = &expected->nodes[i];
    count += a->vertex != b->vertex || a->edge_start != b->edge_start || a->edge_end != b->edge_end ||
             a->face != b->face || memcmp(&a->parameter, &b->parameter, sizeof a->parameter) != 0;
  }
  count += memcmp(got->refined, expected->refined, sizeof got->refined) != 0;
  count += got->info.vertex_count != expected->info.vertex_count ||
           got->info.edge_count != expected->info.edge_count || got->info.face_count != expected->info.face_count ||
           got->info.is_closed != expected->info.is_closed || got->info.is_oriented != expected->info.is_oriented;
  return count;
}

struct job {
  int index;
  int failures;
};

static void *work(void *arg) {
  struct job *job = arg;
  const int t = job->index;
  static const uint32_t bad[] = {0, 1, 99};
  static const uint32_t tri[] = {3};
  char mismatch[96], tolerance[32];
  double scratch[3 * 98];
  int round;
  snprintf(mismatch, sizeof mismatch, "vertex_count is %d but the refiner's cage has 8 vertices", 9 + t);
  snprintf(tolerance, sizeof tolerance, "tolerance is -%d", t + 1);
  wait_at_gate();
  for (round = 0; round < ROUNDS; round++) {
    struct outcome shared, own;
    WeftMesh *copy = NULL, *welded = NULL;
    WeftMeshInfo info;

    /* A failure of this thread's own, before the work: its sentence names this thread's count. */
    if (weft_refiner_evaluate(shared_refiner, own_inputs[t].cage, (size_t)(9 + t), scratch, 3 * 98) !=
        WEFT_STATUS_COUNT_MISMATCH)
      job->failures++;

    /* The work, on the shared mesh and refiner and on this thread's own meshes. */
    job->failures += run_operations(shared_inputs, shared_refiner, &shared);
    job->failures += differences(&shared, &shared_reference);
    job->failures += run_operations(&own_inputs[t], shared_refiner, &own);
    job->failures += differences(&own, &own_reference[t]);
    free_outcome(&shared);
    free_outcome(&own);
    if (weft_mesh_new(cube_positions, 8, cube_sizes, 6, cube_indices, 24, &copy) != WEFT_STATUS_OK) job->failures++;
    if (weft_mesh_info(copy, &info) != WEFT_STATUS_OK || info.edge_count != 12) job->failures++;
    if (weft_mesh_info(shared_mesh, &info) != WEFT_STATUS_OK || !info.is_closed) job->failures++;
    weft_mesh_free(copy);

    /* Successes, and other threads' failures all the while, left this thread's sentence alone. */
    if (strstr(weft_last_error_message(), mismatch) == NULL) job->failures++;
    /* A second failure replaces it, again with this thread's own words. */
    if (weft_weld(shared_mesh, -(double)(t + 1), &welded, NULL) != WEFT_STATUS_INVALID_ARGUMENT || welded != NULL)
      job->failures++;
    if (strstr(weft_last_error_message(), tolerance) == NULL) job->failures++;
    if (strstr(weft_last_error_message(), "vertex_count") != NULL) job->failures++;
    if (round % 2 == 0) {
      if (weft_mesh_new(cube_positions, 8, tri, 1, bad, 3, &copy) != WEFT_STATUS_INDEX_OUT_OF_RANGE) job->failures++;
      if (strstr(weft_last_error_message(), "vertex index 99") == NULL) job->failures++;
    } else {
      if (weft_mesh_info(NULL, &info) != WEFT_STATUS_NULL_POINTER) job->failures++;
      if (strstr(weft_last_error_message(), "mesh is NULL") == NULL) job->failures++;
    }
  }
  return NULL;
}

int main(void) {
  pthread_t threads[THREADS];
  struct job jobs[THREADS];
  struct inputs shared;
  WeftRefiner *refiner = NULL;
  int i;

  /* One thread first: the inputs, the shared refiner and every reference result. */
  make_inputs(&shared, 1.0, 0.0);
  shared_inputs = &shared;
  shared_mesh = shared.cube;
  CHECK_STATUS(weft_refiner_new(shared.cube, WEFT_SCHEME_CATMULL_CLARK, 2, WEFT_NAKED_EDGES_SMOOTH, &refiner),
               WEFT_STATUS_OK);
  CHECK(weft_refiner_vertex_count(refiner) == 98);
  shared_refiner = refiner;
  CHECK(run_operations(&shared, refiner, &shared_reference) == 0);
  /* The references are what the operations mean: two cubes welded into 12 vertices, their wall culled, one T-node. */
  CHECK(weft_mesh_vertex_count(shared_reference.subdivided) == 98);
  CHECK(weft_mesh_face_count(shared_reference.looped) == 12 * 16);
  CHECK(shared_reference.report.merged_vertex_count == 4 && shared_reference.culled_count == 2);
  CHECK(shared_reference.info.is_closed && shared_reference.info.face_count == 10);
  CHECK(shared_reference.node_count == 1 && shared_reference.nodes[0].vertex == 4);
  /* The refiner evaluated at the cage it was built on is the one-shot subdivision. */
  CHECK(memcmp(shared_reference.refined, weft_mesh_positions(shared_reference.subdivided),
               sizeof shared_reference.refined) == 0);
  for (i = 0; i < THREADS; i++) {
    make_inputs(&own_inputs[i], 1.25 + 0.5 * i, 10.0 * i);
    CHECK(run_operations(&own_inputs[i], refiner, &own_reference[i]) == 0);
    /* Each thread's results are its own: a mix-up between threads would show. */
    CHECK(memcmp(own_reference[i].refined, shared_reference.refined, sizeof shared_reference.refined) != 0);
    CHECK(memcmp(own_reference[i].refined, weft_mesh_positions(own_reference[i].subdivided),
                 sizeof own_reference[i].refined) == 0);
  }

  for (i = 0; i < THREADS; i++) {
    jobs[i].index = i;
    jobs[i].failures = 0;
    CHECK(pthread_create(&threads[i], NULL, work, &jobs[i]) == 0);
  }
  for (i = 0; i < THREADS; i++) {
    CHECK(pthread_join(threads[i], NULL) == 0);
    if (jobs[i].failures != 0) fprintf(stderr, "thread %d: %d failures\n", i, jobs[i].failures);
    CHECK(jobs[i].failures == 0);
  }
  /* This thread has had no failure: its message is still empty. */
  CHECK(strcmp(weft_last_error_message(), "") == 0);

  for (i = 0; i < THREADS; i++) {
    free_outcome(&own_reference[i]);
    free_inputs(&own_inputs[i]);
  }
  free_outcome(&shared_reference);
  weft_refiner_free(refiner);
  free_inputs(&shared);
  return check_summary("test_threads");
}
