"""What crossing between Python and Weft costs, and weft.catmull_clark
against the same call made from C.

    python python/bench.py            # after pip install ./python

1. A mesh of about 1 M vertices and 1 M quads crosses each way: numpy
   arrays into weft.Mesh (weft_mesh_new copies and checks them; with
   copy=False, weft_mesh_new_borrowed only checks them), against
   weft_mesh_new on the same buffers from C (the second call of a fresh
   process, as the Python rows are, and the steady state of many calls,
   whose memory the allocator has already faulted in) and through bare
   ctypes; and back out, as views (m.vertices, m.face_indices) and as
   copies.
2. weft.catmull_clark on a 100k-quad cage, two levels, against a C program
   making the same call.

The C program is compiled here with cc against the installed package's
libweft. Each figure is the median of WEFT_BENCH_RUNS (9) rounds, the rows
interleaved within a round. Not part of the tests.
"""

import ctypes
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

# This file sits beside the source folder weft/, which has no library in
# it: import the installed package instead.
sys.path = [p for p in sys.path if Path(p or ".").resolve() != Path(__file__).resolve().parent]
import weft  # noqa: E402

RUNS = int(os.environ.get("WEFT_BENCH_RUNS", "9"))

C_PROGRAM = r"""
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "weft.h"

static double now(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + t.tv_nsec * 1e-9;
}

static int compare(const void *a, const void *b) {
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* bench new SIDE RUNS: weft_mesh_new on the buffers of a SIDE x SIDE grid.
   bench borrowed SIDE RUNS: weft_mesh_new_borrowed on the same buffers.
   bench catmull-clark SIDE LEVELS RUNS: weft_catmull_clark on that grid.
   Prints the median time in seconds. */
int main(int argc, char **argv) {
    if (argc < 4) return 2;
    int borrowing = strcmp(argv[1], "borrowed") == 0;
    int making = borrowing || strcmp(argv[1], "new") == 0;
    size_t side = (size_t)atol(argv[2]);
    unsigned levels = making ? 0 : (unsigned)atoi(argv[3]);
    int runs = atoi(argv[making ? 3 : 4]);
    WeftMesh *cage = NULL;
    if (weft_plane_grid(1.0, 1.0, side, side, &cage) != WEFT_STATUS_OK) return 1;
    size_t n = weft_mesh_vertex_count(cage), f = weft_mesh_face_count(cage), k = weft_mesh_index_count(cage);
    double *positions = malloc(sizeof(double) * 3 * n), *times = malloc(sizeof(double) * (size_t)runs);
    uint32_t *sizes = malloc(sizeof(uint32_t) * f), *indices = malloc(sizeof(uint32_t) * k);
    weft_mesh_copy_positions(cage, positions, 3 * n);
    weft_mesh_copy_faces(cage, sizes, f, indices, k);
    /* One untimed call first, as the Python process is warm too (thread pool, pages). */
    for (int r = -1; r < runs; r++) {
        WeftMesh *out = NULL;
        double start = now();
        WeftStatus status = borrowing ? weft_mesh_new_borrowed(positions, n, sizes, f, indices, k, 0, &out)
                            : making  ? weft_mesh_new(positions, n, sizes, f, indices, k, &out)
                                      : weft_catmull_clark(cage, levels, WEFT_NAKED_EDGES_SMOOTH, &out);
        if (r >= 0) times[r] = now() - start;
        if (status != WEFT_STATUS_OK) return 1;
        weft_mesh_free(out);
    }
    qsort(times, (size_t)runs, sizeof(double), compare);
    printf("%.6f\n", times[runs / 2]);
    return 0;
}
"""


def timed(call):
    start = time.perf_counter()
    call()
    return time.perf_counter() - start


def steady(call, count):
    """The median time of `count` calls in a row, as the C program's steady rows."""
    return statistics.median(timed(call) for _ in range(count))


def compile_c(folder):
    root = Path(__file__).resolve().parent.parent
    library = Path(weft.__file__).with_name("libweft.so")
    source, program = Path(folder) / "bench.c", Path(folder) / "bench"
    source.write_text(C_PROGRAM)
    # The library names itself by its soname (libweft.so.0): the program
    # finds it under that name beside itself.
    (Path(folder) / "libweft.so.0").symlink_to(library)
    subprocess.run(
        ["cc", "-O2", "-std=c99", "-D_POSIX_C_SOURCE=199309L", f"-I{root / 'include'}", str(source), "-o", str(program),
         str(library), f"-Wl,-rpath,{folder}"],
        check=True,
    )
    return str(program)


def run_c(program, *arguments):
    done = subprocess.run([program, *map(str, arguments)], check=True, capture_output=True, text=True)
    return float(done.stdout)


def report(rows, rounds):
    """Runs every row once per round, the rows interleaved so that load from
    elsewhere falls on all alike; prints each row's median in ms."""
    times = {label: [] for label, _ in rows}
    for _ in range(rounds):
        for label, call in rows:
            times[label].append(call())
    for label, _ in rows:
        print(f"  {label:66s} {statistics.median(times[label]) * 1e3:9.3f} ms")
    return {label: statistics.median(values) for label, values in times.items()}


def crossing(program):
    side = 1000
    grid = weft.plane_grid(1.0, 1.0, side, side)
    vertices, sizes, indices = grid.copy_arrays()
    faces32 = indices.reshape(-1, 4)
    faces64 = faces32.astype(np.int64)
    print(f"crossing: {len(vertices):,} vertices, {len(faces32):,} quads")

    def bare():
        out = ctypes.c_void_p()
        weft.lib.weft_mesh_new(vertices.ctypes.data, len(vertices), sizes.ctypes.data, len(sizes), indices.ctypes.data, indices.size, ctypes.byref(out))
        weft.lib.weft_mesh_free(out.value)

    mesh = weft.Mesh(vertices, faces32)
    rows = [
        ("into Weft: weft_mesh_new from C", lambda: run_c(program, "new", side, 1)),
        ("into Weft: weft_mesh_new from C, steady (21 calls, one process)", lambda: run_c(program, "new", side, 21)),
        ("into Weft: weft_mesh_new through ctypes", lambda: timed(bare)),
        ("into Weft: weft.Mesh(vertices, faces uint32 (f, 4))", lambda: timed(lambda: weft.Mesh(vertices, faces32))),
        ("into Weft: weft.Mesh(vertices, faces int64 (f, 4))", lambda: timed(lambda: weft.Mesh(vertices, faces64))),
        ("into Weft, borrowed: weft_mesh_new_borrowed from C", lambda: run_c(program, "borrowed", side, 1)),
        ("into Weft, borrowed: the same, steady (21 calls)", lambda: run_c(program, "borrowed", side, 21)),
        ("into Weft, borrowed: weft.Mesh(vertices, faces uint32, copy=False)", lambda: timed(lambda: weft.Mesh(vertices, faces32, copy=False))),
        ("into Weft, borrowed: the same, steady (median of 21 calls in a row)", lambda: steady(lambda: weft.Mesh(vertices, faces32, copy=False), 21)),
        ("out of Weft: views m.vertices, m.face_sizes, m.face_indices", lambda: timed(lambda: (mesh.vertices, mesh.face_sizes, mesh.face_indices))),
        ("out of Weft: m.face_array() ((f, 4) view)", lambda: timed(mesh.face_array)),
        ("out of Weft: copies np.array(m.vertices), np.array(m.face_indices)", lambda: timed(lambda: (np.array(mesh.vertices), np.array(mesh.face_indices)))),
    ]
    report(rows, RUNS)


def catmull_clark_against_c(program):
    side, levels = 316, 2
    cage = weft.plane_grid(1.0, 1.0, side, side)
    print(f"catmull_clark: {cage.face_count:,}-quad cage, {levels} levels, smooth naked edges")
    rows = [
        ("C:      weft_catmull_clark", lambda: run_c(program, "catmull-clark", side, levels, 1)),
        ("Python: weft.catmull_clark", lambda: timed(lambda: weft.catmull_clark(cage, levels=levels, naked_edges="smooth"))),
    ]
    medians = report(rows, RUNS)
    c, python = medians[rows[0][0]], medians[rows[1][0]]
    print(f"  Python / C: {python / c:.3f} ({(python / c - 1) * 100:+.1f} %)")


if __name__ == "__main__":
    print(f"weft {weft.version()}, Python {sys.version.split()[0]}, numpy {np.__version__}, {os.cpu_count()} cores")
    with tempfile.TemporaryDirectory() as folder:
        program = compile_c(folder)
        crossing(program)
        catmull_clark_against_c(program)
