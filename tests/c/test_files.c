/* Mesh files through the C ABI: each format written and read back, and
 * every error with the file, line or byte it names. The files go into
 * tests/c/build, which run.sh makes. */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "check.h"

#define FOLDER "tests/c/build/"

static const double exact_cube_positions[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0,
                                        0, 0, 1, 1, 0, 1, 0, 1, 1, 1, 1, 1.0000000000000002};
static const uint32_t exact_cube_sizes[] = {4, 4, 4, 4, 4, 4};
static const uint32_t exact_cube_indices[] = {0, 2, 3, 1, 4, 5, 7, 6, 0, 1, 5, 4,
                                        2, 6, 7, 3, 0, 4, 6, 2, 1, 3, 7, 5};

static WeftMesh *make_exact_cube(void) {
  WeftMesh *mesh = NULL;
  CHECK_STATUS(weft_mesh_new(exact_cube_positions, 8, exact_cube_sizes, 6, exact_cube_indices, 24, &mesh), WEFT_STATUS_OK);
  return mesh;
}

static void write_text(const char *path, const char *text) {
  FILE *file = fopen(path, "wb");
  CHECK(file != NULL);
  if (file) {
    fputs(text, file);
    fclose(file);
  }
}

static void test_round_trips(void) {
  static const char *const paths[] = {FOLDER "files-cube.obj", FOLDER "files-cube.ply", FOLDER "files-cube.off",
                                      FOLDER "files-cube.OBJ"};
  WeftMesh *cube = make_exact_cube();
  for (size_t i = 0; i < sizeof paths / sizeof paths[0]; i++) {
    WeftMesh *back = NULL;
    CHECK_STATUS(weft_write_mesh_file(cube, paths[i]), WEFT_STATUS_OK);
    CHECK_STATUS(weft_read_mesh_file(paths[i], &back), WEFT_STATUS_OK);
    CHECK(weft_mesh_vertex_count(back) == 8 && weft_mesh_face_count(back) == 6);
    CHECK(back && memcmp(weft_mesh_positions(back), exact_cube_positions, sizeof exact_cube_positions) == 0);
    CHECK(back && memcmp(weft_mesh_face_indices(back), exact_cube_indices, sizeof exact_cube_indices) == 0);
    weft_mesh_free(back);
  }
  /* STL holds triangles, one vertex per corner. */
  WeftMesh *triangles = NULL;
  CHECK_STATUS(weft_write_mesh_file(cube, FOLDER "files-cube.stl"), WEFT_STATUS_OK);
  CHECK_STATUS(weft_read_mesh_file(FOLDER "files-cube.stl", &triangles), WEFT_STATUS_OK);
  CHECK(weft_mesh_face_count(triangles) == 12 && weft_mesh_vertex_count(triangles) == 36);
  weft_mesh_free(triangles);
  weft_mesh_free(cube);
}

static void test_errors(void) {
  WeftMesh *cube = make_exact_cube(), *untouched = (WeftMesh *)&untouched, *mesh = untouched;
  CHECK_STATUS(weft_read_mesh_file(NULL, &mesh), WEFT_STATUS_NULL_POINTER);
  CHECK_MESSAGE("path is NULL");
  CHECK_STATUS(weft_read_mesh_file(FOLDER "files-cube.obj", NULL), WEFT_STATUS_NULL_POINTER);
  CHECK_MESSAGE("out_mesh is NULL");
  CHECK_STATUS(weft_write_mesh_file(NULL, FOLDER "files-null.obj"), WEFT_STATUS_NULL_POINTER);
  CHECK_MESSAGE("mesh is NULL");
  CHECK_STATUS(weft_write_mesh_file(cube, NULL), WEFT_STATUS_NULL_POINTER);
  CHECK_STATUS(weft_read_mesh_file(FOLDER "files-missing.obj", &mesh), WEFT_STATUS_INVALID_ARGUMENT);
  CHECK_MESSAGE("files-missing.obj: cannot read");
  CHECK_STATUS(weft_read_mesh_file(FOLDER "files-cube.dxf", &mesh), WEFT_STATUS_INVALID_ARGUMENT);
  CHECK_MESSAGE("unknown mesh format");
  CHECK_STATUS(weft_read_mesh_file("tests/c/build/\xff.obj", &mesh), WEFT_STATUS_INVALID_ARGUMENT);
  CHECK_MESSAGE("path is not UTF-8 (byte 14");
  write_text(FOLDER "files-bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 x\n");
  CHECK_STATUS(weft_read_mesh_file(FOLDER "files-bad.obj", &mesh), WEFT_STATUS_INVALID_ARGUMENT);
  CHECK_MESSAGE("files-bad.obj: line 4");
  write_text(FOLDER "files-range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n");
  CHECK_STATUS(weft_read_mesh_file(FOLDER "files-range.obj", &mesh), WEFT_STATUS_INDEX_OUT_OF_RANGE);
  CHECK_MESSAGE("files-range.obj: line 4");
  CHECK(mesh == untouched);
  CHECK_STATUS(weft_write_mesh_file(cube, FOLDER "no-such-folder/cube.obj"), WEFT_STATUS_INVALID_ARGUMENT);
  CHECK_MESSAGE("does not exist");
  /* A write the system refuses (a folder is in the way) leaves no partial file. */
  char partial[256];
  FILE *leftover;
  mkdir(FOLDER "files-folder.obj", 0755);
  CHECK_STATUS(weft_write_mesh_file(cube, FOLDER "files-folder.obj"), WEFT_STATUS_INVALID_ARGUMENT);
  CHECK_MESSAGE("files-folder.obj: cannot replace");
  snprintf(partial, sizeof partial, FOLDER ".files-folder.obj.%ld.partial", (long)getpid());
  leftover = fopen(partial, "rb");
  CHECK(leftover == NULL);
  if (leftover) fclose(leftover);
  weft_mesh_free(cube);
}

int main(void) {
  test_round_trips();
  test_errors();
  return check_summary("test_files");
}
