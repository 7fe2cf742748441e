"""The package's results equal the `weft` command's bit for bit: the same
cage goes through the command and through Python, and the command's output
file, read back, equals the Python result."""

import subprocess

import numpy as np
import pytest

import weft
from conftest import random_cage, same_bits


def run(cli, *arguments):
    done = subprocess.run([cli, *map(str, arguments)], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    return done


def assert_same(a, b):
    assert same_bits(a.vertices, b.vertices)
    assert same_bits(a.face_sizes, b.face_sizes)
    assert same_bits(a.face_indices, b.face_indices)


@pytest.mark.parametrize("naked_edges", ["fixed", "smooth", "corner-fixed"])
@pytest.mark.parametrize("extension", ["ply", "obj"])
def test_catmull_clark_equals_the_command(cli, tmp, naked_edges, extension, mixed):
    cage = weft.join([random_cage(7), weft.Mesh(np.array(mixed.vertices) + 5.0, mixed.faces)])
    source, output = tmp / f"cage.{extension}", tmp / f"smooth.{extension}"
    weft.write(cage, source)
    assert weft.read(source) == cage
    run(cli, "subdivide", source, output, "--scheme", "catmull-clark", "--levels", 2, "--naked-edges", naked_edges)
    assert_same(weft.read(output), weft.catmull_clark(cage, levels=2, naked_edges=naked_edges))


@pytest.mark.parametrize("naked_edges", ["fixed", "smooth", "corner-fixed"])
def test_loop_equals_the_command(cli, tmp, naked_edges):
    cage = weft.triangulate(random_cage(11))
    source, output = tmp / "tri.ply", tmp / "tri3.ply"
    weft.write(cage, source)
    run(cli, "subdivide", source, output, "--scheme", "loop", "--levels", 3, "--naked-edges", naked_edges)
    assert_same(weft.read(output), weft.loop(cage, levels=3, naked_edges=naked_edges))


def test_creased_subdivision_equals_the_command(cli, tmp):
    cage = weft.box(2, 1, 1, 2, 1, 1)
    edges = weft.edges(cage)[:3]
    side = tmp / "creases.txt"
    side.write_text("".join(f"{i} {j} {s}\n" for (i, j), s in zip(edges.tolist(), [10.0, 1.5, 0.5])) + "corner 0 inf\n")
    source, output = tmp / "box.ply", tmp / "box2.ply"
    weft.write(cage, source)
    run(cli, "subdivide", source, output, "--levels", 2, "--creases", side, "--creasing", "chaikin")
    ours = weft.subdivide(
        cage, levels=2, creasing="chaikin",
        creases=[(i, j, s) for (i, j), s in zip(edges.tolist(), [10.0, 1.5, 0.5])], corners=[(0, np.inf)],
    )
    assert_same(weft.read(output), ours)


def test_weld_cull_and_flip_equal_the_command(cli, tmp):
    a = weft.box(1, 1, 1)
    b = weft.Mesh(np.array(a.vertices) + [1.0, 0, 0], a.faces)
    paths = [tmp / "a.ply", tmp / "b.ply"]
    for mesh, path in zip([a, b], paths):
        weft.write(mesh, path)
    run(cli, "weld", *paths, "-o", tmp / "w.ply", "--tolerance", 1e-6)
    welded, report = weft.weld([a, b], tolerance=1e-6)
    assert_same(weft.read(tmp / "w.ply"), welded)
    assert report.merged_vertex_count == 4
    run(cli, "cull-adjacent", tmp / "w.ply", tmp / "c.ply")
    assert_same(weft.read(tmp / "c.ply"), weft.cull_adjacent(welded))
    run(cli, "flip", tmp / "c.ply", tmp / "f.ply")
    assert_same(weft.read(tmp / "f.ply"), weft.flip(weft.cull_adjacent(welded)))
    mixed_up = weft.join([a, weft.flip(b)])
    weft.write(mixed_up, tmp / "m.ply")
    run(cli, "flip", tmp / "m.ply", tmp / "u.ply", "--unify")
    assert_same(weft.read(tmp / "u.ply"), weft.unify(mixed_up))


def test_t_node_repair_equals_the_command(cli, tmp):
    coarse = weft.plane_grid(2, 2, 1, 1)
    fine = weft.Mesh(np.array(weft.plane_grid(2, 2, 2, 2).vertices) + [2.0, 0, 0], weft.plane_grid(2, 2, 2, 2).faces)
    joined, _ = weft.weld([coarse, fine], 1e-9)
    weft.write(joined, tmp / "t.ply")
    done = run(cli, "t-nodes", tmp / "t.ply", "--repair", tmp / "r.ply")
    nodes = weft.find_t_nodes(joined, 1e-6)
    assert f"{len(nodes)} T-nodes" in done.stdout and len(nodes) == 1
    assert_same(weft.read(tmp / "r.ply"), weft.repair_t_nodes(joined))


def test_the_c_functions_agree_with_each_other(cage):
    # The one-shot functions and the refiner share one evaluation: equal bit
    # for bit. weft_subdivide_ex (creases and corners) evaluates through the
    # creased rules, equal to the last bits of a double.
    for scheme, mesh, one_shot in [("catmull-clark", cage, weft.catmull_clark), ("loop", weft.triangulate(cage), weft.loop)]:
        for naked_edges in ["fixed", "smooth", "corner-fixed"]:
            expected = one_shot(mesh, levels=2, naked_edges=naked_edges)
            refiner = weft.Refiner(mesh, scheme=scheme, levels=2, naked_edges=naked_edges)
            assert_same(refiner.mesh, expected)
            assert same_bits(refiner.evaluate(mesh.vertices), expected.vertices)
            creased_path = weft.subdivide(mesh, scheme=scheme, levels=2, naked_edges=naked_edges)
            assert same_bits(creased_path.face_indices, expected.face_indices)
            assert np.allclose(creased_path.vertices, expected.vertices, rtol=0, atol=1e-14)


def test_a_raw_call_through_weft_lib_gives_the_wrapper_result(cage):
    import ctypes

    out = ctypes.c_void_p()
    weft.lib.weft_catmull_clark(cage.handle, 2, 1, ctypes.byref(out))
    try:
        count = weft.lib.weft_mesh_vertex_count(out.value)
        raw = np.empty(3 * count)
        weft.lib.weft_mesh_copy_positions(out.value, raw.ctypes.data, raw.size)
    finally:
        weft.lib.weft_mesh_free(out.value)
    assert same_bits(raw.reshape(-1, 3), weft.catmull_clark(cage, 2, "smooth").vertices)
