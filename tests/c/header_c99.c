/* Compiles the public header as strict C99 with every warning an error and
 * uses each declared type, so a non-C construct in weft.h fails the build. */
#include "weft.h"

int weft_header_c99_check(void);

int weft_header_c99_check(void) {
  WeftMeshInfo info = {0};
  WeftStatus status = WEFT_STATUS_OK;
  WeftMesh *mesh = NULL;
  (void)info;
  (void)mesh;
  return (int)status + WEFT_VERSION_MAJOR * 0;
}
