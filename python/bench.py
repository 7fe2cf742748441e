"""What crossing between Python and Weft costs, and weft.catmull_clark
against the same call made from C.

    python python/bench.py            # after pip install ./python

1. A mesh of about 1 M vertices and 1 M quads crosses each way: numpy
   arrays into weft.Mesh (weft_mesh_new copies and checks them), against
   the bare weft_mesh_new call on the same buffers through ctypes; and back
   out, as views (m.vertices, m.face_indices) and as copies.
2. weft.catmull_clark on a 100k-quad cage, two levels, against a C program
   (compiled here with cc against the same libweft) making the same call.

Each figure is the median of several runs. Not part of the tests.
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

import weft

RUNS = int(os.environ.get("WEFT_BENCH_RUNS", "9"))

C_PROGRAM = r"""
#include <stdio.h>
#include <stdlib.h>
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

int main(int argc, char **argv) {
    size_t side = (size_t)atol(argv[1]);
    unsigned levels = (unsigned)atoi(argv[2]);
    int runs = atoi(argv[3]);
    WeftMesh *cage = NULL;
    if (weft_plane_grid(1.0, 1.0, side, side, &cage) != WEFT_STATUS_OK) return 1;
    double *times = malloc(sizeof(double) * (size_t)runs);
    for (int r = 0; r < runs; r++) {
        WeftMesh *out = NULL;
        double start = now();
        if (weft_catmull_clark(cage, levels, WEFT_NAKED_EDGES_SMOOTH, &out) != WEFT_STATUS_OK) return 1;
        times[r] = now() - start;
        weft_mesh_free(out);
    }
    qsort(times, (size_t)runs, sizeof(double), compare);
    printf("%.6f\n", times[runs / 2]);
    weft_mesh_free(cage);
    free(times);
    return 0;
}
"""


def median_time(call, runs=RUNS):
    times = []
    for _ in range(runs):
        start = time.perf_counter()
        call()
        times.append(time.perf_counter() - start)
    return statistics.median(times)


def grid_arrays(side):
    """The vertices and quads of a side × side grid, made with numpy."""
    u, v = np.meshgrid(np.arange(side + 1, dtype=np.float64), np.arange(side + 1, dtype=np.float64))
    vertices = np.column_stack([u.ravel(), v.ravel(), np.sin(u.ravel()) * np.cos(v.ravel())])
    i = np.arange(side, dtype=np.int64)
    corner = (i[None, :] + (side + 1) * i[:, None]).ravel()
    faces = np.column_stack([corner, corner + 1, corner + side + 2, corner + side + 1])
    return vertices, faces


def crossing():
    side = 1000
    vertices, faces = grid_arrays(side)
    faces32 = faces.astype(np.uint32)
    sizes = np.full(len(faces), 4, dtype=np.uint32)
    print(f"crossing: {len(vertices):,} vertices, {len(faces):,} quads")

    def bare():
        out = ctypes.c_void_p()
        weft.lib.weft_mesh_new(vertices.ctypes.data, len(vertices), sizes.ctypes.data, len(sizes), faces32.ctypes.data, faces32.size, ctypes.byref(out))
        weft.lib.weft_mesh_free(out.value)

    rows = [
        ("into Weft: weft_mesh_new through ctypes (bare)", bare),
        ("into Weft: weft.Mesh(vertices, faces uint32 (f, 4))", lambda: weft.Mesh(vertices, faces32)),
        ("into Weft: weft.Mesh(vertices, faces int64 (f, 4))", lambda: weft.Mesh(vertices, faces)),
    ]
    mesh = weft.Mesh(vertices, faces32)
    rows += [
        ("out of Weft: views m.vertices + m.face_sizes + m.face_indices", lambda: (mesh.vertices, mesh.face_sizes, mesh.face_indices)),
        ("out of Weft: copies np.array(m.vertices) + np.array(m.face_indices)", lambda: (np.array(mesh.vertices), np.array(mesh.face_indices))),
        ("out of Weft: m.face_array() ((f, 4) view)", mesh.face_array),
    ]
    for label, call in rows:
        print(f"  {label:70s} {median_time(call) * 1e3:9.3f} ms")


def catmull_clark_against_c():
    side, levels = 316, 2
    cage = weft.plane_grid(1.0, 1.0, side, side)
    print(f"catmull_clark: {cage.face_count:,}-quad cage, {levels} levels, smooth naked edges")
    root = Path(__file__).resolve().parent.parent
    library = Path(weft.__file__).with_name("libweft.so")
    with tempfile.TemporaryDirectory() as folder:
        source, program = Path(folder) / "bench.c", Path(folder) / "bench"
        source.write_text(C_PROGRAM)
        subprocess.run(
            ["cc", "-O2", "-std=c99", "-D_POSIX_C_SOURCE=199309L", f"-I{root / 'include'}", str(source), "-o", str(program),
             str(library), f"-Wl,-rpath,{library.parent}"],
            check=True,
        )
        results = {"C": [], "Python": []}
        # Alternate the two so that load from elsewhere falls on both alike.
        for _ in range(3):
            results["C"].append(float(subprocess.run([str(program), str(side), str(levels), str(RUNS)], check=True, capture_output=True, text=True).stdout))
            results["Python"].append(median_time(lambda: weft.catmull_clark(cage, levels=levels, naked_edges="smooth")))
    c, python = statistics.median(results["C"]), statistics.median(results["Python"])
    print(f"  {'C:      weft_catmull_clark':70s} {c * 1e3:9.1f} ms")
    print(f"  {'Python: weft.catmull_clark':70s} {python * 1e3:9.1f} ms  ({(python / c - 1) * 100:+.1f} %)")


if __name__ == "__main__":
    print(f"weft {weft.version()}, Python {sys.version.split()[0]}, numpy {np.__version__}, {os.cpu_count()} cores")
    crossing()
    catmull_clark_against_c()
