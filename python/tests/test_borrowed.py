"""Meshes that read the caller's arrays in place (copy=False)."""

import copy
import gc
import pickle

import numpy as np
import pytest

import weft
from conftest import random_cage, same_bits


def host_arrays(seed=3):
    cage = random_cage(seed, u=9, v=7)
    return np.array(cage.vertices), np.array(cage.face_array())


def test_a_borrowed_mesh_reads_the_arrays_in_place_and_gives_the_same_results():
    vertices, faces = host_arrays()
    copied = weft.Mesh(vertices, faces)
    borrowed = weft.Mesh(vertices, faces, copy=False)
    assert borrowed.is_borrowed and not copied.is_borrowed
    assert np.shares_memory(borrowed.vertices, vertices)
    assert np.shares_memory(borrowed.face_indices, faces)
    assert borrowed == copied
    for naked_edges in ("smooth", "corner-fixed"):
        ours = weft.subdivide(borrowed, levels=2, naked_edges=naked_edges, creases=[(0, 1, 2.0)])
        theirs = weft.subdivide(copied, levels=2, naked_edges=naked_edges, creases=[(0, 1, 2.0)])
        assert not ours.is_borrowed
        assert same_bits(ours.vertices, theirs.vertices) and same_bits(ours.face_indices, theirs.face_indices)
    triangles = weft.triangulate(borrowed)
    assert same_bits(weft.loop(triangles, levels=1).vertices, weft.loop(weft.triangulate(copied), levels=1).vertices)


def test_borrowed_arrays_are_read_only_until_the_last_mesh_borrowing_them_is_freed():
    vertices, faces = host_arrays()
    first = weft.Mesh(vertices, faces, copy=False)
    assert not vertices.flags.writeable and not faces.flags.writeable
    with pytest.raises(ValueError, match="read-only"):
        vertices[0, 0] = 5.0
    second = weft.Mesh.from_arrays(vertices, np.full(len(faces), 4), faces.reshape(-1), copy=False)
    del first
    gc.collect()
    assert not vertices.flags.writeable, "the second mesh still borrows the vertices"
    assert faces.flags.writeable, "the second mesh borrows a view of the faces, not the array itself"
    del second
    gc.collect()
    assert vertices.flags.writeable
    vertices[0, 0] = 5.0


def test_an_array_that_was_read_only_stays_read_only():
    vertices, faces = host_arrays()
    vertices.flags.writeable = False
    mesh = weft.Mesh(vertices, faces, copy=False)
    del mesh
    gc.collect()
    assert not vertices.flags.writeable and faces.flags.writeable


def test_a_borrowed_mesh_keeps_the_arrays_alive():
    vertices, faces = host_arrays()
    expected = vertices.copy()
    mesh = weft.Mesh(vertices, faces, copy=False)
    del vertices, faces
    gc.collect()
    assert same_bits(mesh.vertices, expected)
    assert len(weft.catmull_clark(mesh, levels=1).vertices) > len(expected)


def test_pickled_and_copied_borrowed_meshes_own_their_buffers():
    vertices, faces = host_arrays()
    mesh = weft.Mesh(vertices, faces, copy=False)
    for other in (copy.copy(mesh), copy.deepcopy(mesh), pickle.loads(pickle.dumps(mesh))):
        assert other == mesh and not other.is_borrowed
        assert not np.shares_memory(other.vertices, vertices)


def test_mixed_faces_borrow_their_indices_and_copy_their_sizes():
    vertices = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [-1, 0.5, 0]], dtype=np.float64)
    indices = np.array([0, 1, 2, 0, 2, 3, 4], dtype=np.uint32)
    sizes = [3, 4]
    mesh = weft.Mesh.from_arrays(vertices, sizes, indices, copy=False)
    assert mesh.faces == [[0, 1, 2], [0, 2, 3, 4]]
    assert np.shares_memory(mesh.face_indices, indices)
    assert mesh == weft.Mesh.from_arrays(vertices, sizes, indices)


@pytest.mark.parametrize(
    "change, name, words",
    [
        (lambda v, f: (v.tolist(), f), "vertices", "not list"),
        (lambda v, f: (v.astype(np.float32), f), "vertices", "not float32"),
        (lambda v, f: (v[::2], f), "vertices", "strided"),
        (lambda v, f: (np.asfortranarray(v), f), "vertices", "strided"),
        (lambda v, f: (v[:, :2].copy(), f), "vertices", "of shape (n, 3)"),
        (lambda v, f: (v, f.astype(np.int64)), "faces", "not int64"),
        (lambda v, f: (v, f.reshape(-1)), "faces", "of shape (f, k)"),
        (lambda v, f: (v, f[:, ::-1]), "faces", "strided"),
    ],
)
def test_arrays_that_would_need_a_copy_are_refused_by_name(change, name, words):
    vertices, faces = host_arrays()
    vertices, faces = change(vertices, faces)
    with pytest.raises(ValueError, match=f"copy=False needs {name} as") as caught:
        weft.Mesh(vertices, faces, copy=False)
    assert words in str(caught.value)


def test_what_the_library_refuses_leaves_the_arrays_writable():
    vertices, faces = host_arrays()
    faces[5, 2] = len(vertices) + 4
    with pytest.raises(weft.WeftError) as caught:
        weft.Mesh(vertices, faces, copy=False)
    assert caught.value.status == weft.Status.INDEX_OUT_OF_RANGE
    assert "face 5, corner 2" in caught.value.message
    assert vertices.flags.writeable and faces.flags.writeable
    vertices[3, 1] = np.nan
    faces[5, 2] = 0
    with pytest.raises(weft.WeftError, match="vertex 3"):
        weft.Mesh(vertices, faces, copy=False)
    with pytest.raises(TypeError, match="copy must be True or False"):
        weft.Mesh(vertices, faces, copy=0)


def test_meshes_borrowing_one_array_on_many_threads_give_it_back_writable():
    import threading

    vertices, faces = host_arrays()
    errors = []

    def borrow_and_free():
        try:
            for _ in range(50):
                mesh = weft.Mesh(vertices, faces, copy=False)
                assert not vertices.flags.writeable
                del mesh
        except Exception as error:  # reported below, on the test's thread
            errors.append(error)

    threads = [threading.Thread(target=borrow_and_free) for _ in range(4)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    gc.collect()
    assert not errors
    assert vertices.flags.writeable and faces.flags.writeable
