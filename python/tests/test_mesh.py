"""The Mesh class: construction from every accepted form, views, errors, pickle and copy."""

import copy
import gc
import pickle
import threading
import time
from pathlib import Path

import numpy as np
import pytest

import weft
from conftest import random_cage, same_bits

SQUARE = [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]]


def test_the_first_example_of_the_readme(tmp_path, monkeypatch, capsys):
    readme = (Path(__file__).resolve().parents[1] / "README.md").read_text(encoding="utf-8")
    example = readme.split("```python\n", 1)[1].split("```", 1)[0]
    monkeypatch.chdir(tmp_path)
    scope = {}
    exec(compile(example, "README.md", "exec"), scope)
    assert capsys.readouterr().out == "(25, 3) 16\n"
    s = scope["s"]
    assert s.vertices.dtype == np.float64 and not s.vertices.flags.owndata
    assert (s.face_sizes == 4).all() and s.face_sizes.dtype == np.uint32
    assert weft.read(tmp_path / "smooth.obj") == s


@pytest.mark.parametrize("dtype", [np.int8, np.int16, np.int32, np.int64, np.uint8, np.uint16, np.uint32, np.uint64])
def test_faces_as_an_array_of_any_integer_dtype(dtype):
    m = weft.Mesh(np.array(SQUARE, dtype=np.float32), np.array([[0, 1, 2], [0, 2, 3]], dtype=dtype))
    assert m.faces == [[0, 1, 2], [0, 2, 3]]
    assert same_bits(m.face_indices, np.array([0, 1, 2, 0, 2, 3], dtype=np.uint32))


def test_faces_of_mixed_sizes_from_lists_tuples_and_arrays():
    vertices = SQUARE + [[0.5, 2, 0]]
    m = weft.Mesh(vertices, [(0, 1, 2, 3), np.array([3, 2, 4])])
    assert m.face_count == 2 and m.index_count == 7
    assert m.face_sizes.tolist() == [4, 3]
    assert m.faces == [[0, 1, 2, 3], [3, 2, 4]]
    with pytest.raises(ValueError, match="mixes faces"):
        m.face_array()
    assert weft.Mesh(SQUARE, [[0, 1, 2, 3]]).face_array().tolist() == [[0, 1, 2, 3]]


def test_vertices_keep_every_bit_and_are_a_read_only_view():
    rng = np.random.default_rng(5)
    vertices = rng.normal(size=(50, 3)) * 1e7
    m = weft.Mesh(vertices, [[0, 1, 2]])
    assert same_bits(m.vertices, vertices)
    view = m.vertices
    assert not view.flags.writeable and not view.flags.owndata
    with pytest.raises(ValueError):
        view[0, 0] = 1.0


def test_a_view_keeps_its_mesh_alive():
    m = weft.box(1, 2, 3)
    expected = np.array(m.vertices)
    view = m.vertices
    faces = m.face_indices
    del m
    gc.collect()
    weft.catmull_clark(weft.box(), levels=2)  # reuse freed memory, were it freed
    assert same_bits(view, expected)
    assert faces.size == 24


def test_empty_mesh():
    m = weft.Mesh(np.zeros((0, 3)), [])
    assert m.vertex_count == 0 and m.face_count == 0
    assert m.vertices.shape == (0, 3) and m.faces == []
    assert weft.Mesh([], []).vertex_count == 0


@pytest.mark.parametrize(
    "faces, status, words",
    [
        ([[0, 1, 7]], weft.Status.INDEX_OUT_OF_RANGE, "7"),
        ([[0, 1]], weft.Status.FACE_TOO_SMALL, "face 0"),
        ([[0, 1, 2], [0, 1, 1]], weft.Status.REPEATED_INDEX, "face 1"),
    ],
)
def test_what_the_library_refuses_is_a_weft_error_with_its_message(faces, status, words):
    with pytest.raises(weft.WeftError) as caught:
        weft.Mesh(SQUARE, faces)
    assert caught.value.status == status
    assert words in caught.value.message
    assert caught.value.status_name == weft.Status.name_of(status)


@pytest.mark.parametrize("bad", [np.nan, np.inf, -np.inf])
def test_non_finite_coordinates_are_a_weft_error_naming_the_vertex(bad):
    vertices = np.array(SQUARE, dtype=float)
    vertices[2, 1] = bad
    with pytest.raises(weft.WeftError) as caught:
        weft.Mesh(vertices, [[0, 1, 2]])
    assert caught.value.status == weft.Status.NON_FINITE_COORDINATE
    assert "vertex 2" in caught.value.message


GRID = [[0, 0, 0], [1, 0, 0], [2, 0, 0], [0, 1, 0], [1, 1, 0], [2, 1, 0]]
REPEATING = [[0, 1, 1, 4, 3], [1, 2, 5, 4]]


def test_repeated_vertices_are_accepted_on_request_and_survive_pickle_and_copy():
    with pytest.raises(weft.WeftError) as caught:
        weft.Mesh(GRID, REPEATING)
    assert caught.value.status == weft.Status.REPEATED_INDEX and "face 0" in caught.value.message
    mesh = weft.Mesh(GRID, REPEATING, allow_repeated_vertices=True)
    assert mesh.faces == REPEATING
    flat = weft.Mesh.from_arrays(GRID, [5, 4], sum(REPEATING, []), allow_repeated_vertices=True)
    assert flat == mesh
    assert pickle.loads(pickle.dumps(mesh)) == mesh
    assert copy.copy(mesh) == mesh
    # 6 vertices, 8 edges (the degenerate 1-1 among them), 2 faces.
    smooth = weft.catmull_clark(mesh, levels=1)
    assert len(smooth.vertices) == 16 and smooth.face_count == 9
    # The point of the degenerate edge (the third edge) stays on vertex 1.
    assert smooth.vertices[6 + 2].tolist() == GRID[1]
    with pytest.raises(TypeError, match="allow_repeated_vertices"):
        weft.Mesh(GRID, REPEATING, allow_repeated_vertices=1)


def test_weft_error_pickles():
    error = weft.WeftError(weft.Status.NOT_TRIANGLES, "face 3 has 4 corners")
    again = pickle.loads(pickle.dumps(error))
    assert (again.status, again.message) == (error.status, error.message)


@pytest.mark.parametrize(
    "vertices, faces, error, words",
    [
        ([[0, 0], [1, 0], [0, 1]], [[0, 1, 2]], ValueError, "vertices must have shape"),
        (np.zeros((3, 3, 1)), [[0, 1, 2]], ValueError, "vertices must have shape"),
        ([["a", "b", "c"]] * 3, [[0, 1, 2]], TypeError, "vertices must hold real numbers"),
        (np.zeros((3, 3), dtype=complex), [[0, 1, 2]], TypeError, "vertices"),
        (np.ones((3, 3), dtype=bool), [[0, 1, 2]], TypeError, "vertices must hold real numbers"),
        (SQUARE, np.ones((1, 3), dtype=bool), TypeError, "faces must hold integers"),
        ([[0, 0, 0], [1, 0], [0, 1, 0]], [[0, 1, 2]], ValueError, "vertices"),
        (SQUARE, [[0, 1.5, 2]], TypeError, "faces\\[0\\] must hold integer"),
        (SQUARE, [[0, 1, 2], [0, "x", 3]], TypeError, "faces\\[1\\]"),
        (SQUARE, np.array([[0.0, 1.0, 2.0]]), TypeError, "faces must hold integers"),
        (SQUARE, [[0, -1, 2]], ValueError, "negative"),
        (SQUARE, np.array([[0, 2**33, 2]]), ValueError, "32-bit"),
        (SQUARE, np.array([0, 1, 2]), ValueError, "faces must be"),
        (SQUARE, 7, TypeError, "faces must be"),
        (SQUARE, [5], TypeError, "faces\\[0\\] must be a sequence"),
        (SQUARE, ["012"], TypeError, "faces\\[0\\]"),
    ],
)
def test_a_wrong_dtype_or_shape_names_the_argument(vertices, faces, error, words):
    with pytest.raises(error, match=words):
        weft.Mesh(vertices, faces)


def test_from_arrays_checks_its_arguments():
    m = weft.Mesh.from_arrays(SQUARE + [[2, 2, 0]], [3, 4], np.array([0, 1, 4, 0, 1, 2, 3], dtype=np.int64))
    assert m.faces == [[0, 1, 4], [0, 1, 2, 3]]
    with pytest.raises(weft.WeftError) as caught:
        weft.Mesh.from_arrays(SQUARE, [3, 4], [0, 1, 2])
    assert caught.value.status == weft.Status.COUNT_MISMATCH
    with pytest.raises(ValueError, match="face_sizes must be one-dimensional"):
        weft.Mesh.from_arrays(SQUARE, [[3]], [0, 1, 2])
    with pytest.raises(TypeError, match="face_indices must hold integers"):
        weft.Mesh.from_arrays(SQUARE, [3], [0.0, 1.0, 2.0])


def test_pickled_mesh_is_equal_bit_for_bit(cage):
    again = pickle.loads(pickle.dumps(cage))
    assert again == cage and again is not cage
    assert again.handle != cage.handle
    assert same_bits(again.vertices, cage.vertices)
    assert same_bits(again.face_indices, cage.face_indices)


@pytest.mark.parametrize("how", [copy.copy, copy.deepcopy])
def test_copied_mesh_is_equal_and_independent(how, mixed):
    twin = how(mixed)
    assert twin == mixed and twin.handle != mixed.handle
    del mixed
    gc.collect()
    assert twin.faces == [[0, 1, 4, 5], [1, 2, 3, 4], [4, 3, 6], [5, 4, 6]]


def test_copy_arrays_are_writable_copies(mixed):
    positions, sizes, indices = mixed.copy_arrays()
    assert positions.flags.writeable and positions.flags.owndata
    assert same_bits(positions, mixed.vertices) and same_bits(indices, mixed.face_indices)
    positions[0] = 99.0
    assert mixed.vertices[0, 0] == 0.0


def test_equality_compares_bits():
    a = weft.Mesh(SQUARE, [[0, 1, 2, 3]])
    assert a == weft.Mesh(np.array(SQUARE, dtype=np.int64), np.array([[0, 1, 2, 3]]))
    moved = np.array(SQUARE, dtype=float)
    moved[1, 0] = np.nextafter(1.0, 2.0)
    assert a != weft.Mesh(moved, [[0, 1, 2, 3]])
    assert a != weft.Mesh(SQUARE, [[1, 2, 3, 0]])
    assert a.__eq__("mesh") is NotImplemented


def test_info_reports_the_topology():
    info = weft.box(1, 1, 1).info()
    assert (info.vertex_count, info.edge_count, info.face_count) == (8, 12, 6)
    assert info.is_closed and info.is_orientable and info.is_oriented
    assert info.naked_edge_count == 0 and info.component_count == 1
    open_info = weft.plane_grid(1, 1, 2, 2).info()
    assert not open_info.is_closed and open_info.naked_edge_count == 8


def test_repr():
    assert repr(weft.box()) == "weft.Mesh(8 vertices, 6 faces)"


def test_the_gil_is_released_during_a_long_call():
    big = random_cage(3, 120, 120)
    window = {}

    def subdivide():
        # One call long enough to tell on a fast machine (level 3 of this
        # cage can finish in under 40 ms).
        window["start"] = time.perf_counter()
        weft.catmull_clark(big, levels=4)
        window["end"] = time.perf_counter()

    worker = threading.Thread(target=subdivide)
    ticks = []
    worker.start()
    while worker.is_alive():
        ticks.append(time.perf_counter())
        time.sleep(0.001)
    worker.join()
    start, end = window["start"], window["end"]
    margin = (end - start) * 0.2
    inside = [t for t in ticks if start + margin < t < end - margin]
    assert end - start > 0.05, "the call is too short to tell"
    assert inside, "no Python ran in another thread while Weft worked: the GIL was held"
