#include <stdio.h>
#include "weft.h"

int main(void) {
  /* A unit cube: 8 vertices, 6 quads, counter-clockwise seen from outside. */
  const double positions[] = {0,0,0, 1,0,0, 0,1,0, 1,1,0, 0,0,1, 1,0,1, 0,1,1, 1,1,1};
  const uint32_t sizes[] = {4, 4, 4, 4, 4, 4};
  const uint32_t indices[] = {0,2,3,1, 4,5,7,6, 0,1,5,4, 2,6,7,3, 0,4,6,2, 1,3,7,5};
  WeftMesh *cage = NULL, *smooth = NULL;
  WeftMeshInfo info;

  if (weft_mesh_new(positions, 8, sizes, 6, indices, 24, &cage) != WEFT_STATUS_OK ||
      weft_catmull_clark(cage, 2, WEFT_NAKED_EDGES_FIXED, &smooth) != WEFT_STATUS_OK ||
      weft_mesh_info(smooth, &info) != WEFT_STATUS_OK) {
    fprintf(stderr, "weft: %s\n", weft_last_error_message());
    weft_mesh_free(cage);
    return 1;
  }
  /* Level 2 of a cube: 98 vertices, 96 quads, still closed. */
  printf("%zu vertices, %zu faces, closed: %d\n", info.vertex_count, info.face_count, info.is_closed);
  const double *p = weft_mesh_positions(smooth);
  printf("vertex 0 moved to (%.4f, %.4f, %.4f)\n", p[0], p[1], p[2]);
  weft_mesh_free(smooth);
  weft_mesh_free(cage);
  return info.vertex_count == 98 && info.face_count == 96 && info.is_closed ? 0 : 1;
}
