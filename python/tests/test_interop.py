"""Round trips through trimesh, COMPAS and rhino3dm, and mesh files."""

import os
import sys

import numpy as np
import pytest

import weft
from conftest import same_bits


def test_trimesh_round_trip(mixed):
    trimesh = pytest.importorskip("trimesh")
    sphere = trimesh.creation.icosphere(subdivisions=2)
    m = weft.from_trimesh(sphere)
    assert same_bits(m.vertices, np.asarray(sphere.vertices, dtype=np.float64))
    assert m.face_indices.reshape(-1, 3).tolist() == sphere.faces.tolist()
    back = weft.to_trimesh(m)
    assert same_bits(np.asarray(back.vertices), m.vertices) and back.faces.tolist() == sphere.faces.tolist()
    assert weft.from_trimesh(back) == m
    # Quads and n-gons are triangulated by the library on the way out.
    tm = weft.to_trimesh(mixed)
    assert weft.from_trimesh(tm) == weft.triangulate(mixed)
    with pytest.raises(TypeError, match="trimesh.Trimesh"):
        weft.from_trimesh("sphere")


def test_compas_round_trip(mixed, pentagon_mesh):
    pytest.importorskip("compas")
    from compas.datastructures import Mesh as CompasMesh

    for mesh in (mixed, pentagon_mesh, weft.catmull_clark(weft.box(), levels=1)):
        cm = weft.to_compas(mesh)
        assert isinstance(cm, CompasMesh)
        assert cm.number_of_vertices() == mesh.vertex_count and cm.number_of_faces() == mesh.face_count
        back = weft.from_compas(cm)
        assert back == mesh
    hexahedron = CompasMesh.from_polyhedron(6)
    assert weft.from_compas(hexahedron).info().is_closed
    with pytest.raises(TypeError, match="compas.datastructures.Mesh"):
        weft.from_compas(42)


def rhino_mesh(rhino3dm):
    rm = rhino3dm.Mesh()
    for point in [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0.5, 2.0, 1e8 + 0.123456789)]:
        rm.Vertices.AddPoint3d(*point)
    rm.Faces.AddFace(0, 1, 2, 3)
    rm.Faces.AddFace(3, 2, 4)  # stored by Rhino as a quad with C == D
    return rm


def test_rhino3dm_triangles_are_quads_with_c_equal_d():
    rhino3dm = pytest.importorskip("rhino3dm")
    rm = rhino_mesh(rhino3dm)
    assert rm.Faces[1] == (3, 2, 4, 4)
    m = weft.from_rhino3dm(rm)
    assert m.faces == [[0, 1, 2, 3], [3, 2, 4]]
    assert m.vertices[4, 2] == 1e8 + 0.123456789  # double precision kept
    back = weft.to_rhino3dm(m)
    assert [back.Faces[i] for i in range(back.Faces.Count)] == [(0, 1, 2, 3), (3, 2, 4, 4)]
    assert weft.from_rhino3dm(back) == m
    with pytest.raises(TypeError, match="rhino3dm.Mesh"):
        weft.from_rhino3dm(m)


def test_rhino3dm_splits_ngons_into_triangles_in_place(pentagon_mesh):
    pytest.importorskip("rhino3dm")
    rm = weft.to_rhino3dm(pentagon_mesh)
    back = weft.from_rhino3dm(rm)
    assert back.face_sizes.tolist() == [3, 3, 3, 3, 3]
    assert back.faces[:3] == weft.triangulate(weft.Mesh(pentagon_mesh.vertices, [pentagon_mesh.faces[0]])).faces
    assert back.faces[3:] == pentagon_mesh.faces[1:]
    assert same_bits(back.vertices, pentagon_mesh.vertices)


@pytest.mark.parametrize("extension", ["obj", "ply", "off", "3dm", "OBJ"])
def test_files_round_trip(tmp, extension, mixed):
    if extension == "3dm":
        pytest.importorskip("rhino3dm")
    path = tmp / f"mesh.{extension}"
    weft.write(mixed, path)
    assert weft.read(path) == mixed
    assert weft.read(str(path)) == mixed
    assert not [p for p in os.listdir(tmp) if "partial" in p]


def test_stl_holds_triangles_unwelded(tmp, mixed):
    weft.write(mixed, tmp / "m.stl")
    triangles = weft.read(tmp / "m.stl")
    assert triangles.face_count == weft.triangulate(mixed).face_count
    assert triangles.vertex_count == 3 * triangles.face_count
    assert weft.weld(triangles, 0.0)[0].vertex_count == mixed.vertex_count


def test_3dm_with_several_meshes_reads_them_joined(tmp, mixed):
    pytest.importorskip("rhino3dm")
    weft.write([mixed, weft.box()], tmp / "two.3dm")
    assert weft.read(tmp / "two.3dm") == weft.join([mixed, weft.box()])


def test_file_errors_name_the_file_and_line(tmp):
    bad = tmp / "bad.obj"
    bad.write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 x\n")
    with pytest.raises(weft.WeftError) as caught:
        weft.read(bad)
    assert "bad.obj" in caught.value.message and "line 4" in caught.value.message
    out_of_range = tmp / "range.obj"
    out_of_range.write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n")
    with pytest.raises(weft.WeftError) as caught:
        weft.read(out_of_range)
    assert caught.value.status == weft.Status.INDEX_OUT_OF_RANGE and "line 4" in caught.value.message
    short = tmp / "short.ply"
    short.write_bytes(b"ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty double x\nproperty double y\nproperty double z\nend_header\n\0\0")
    with pytest.raises(weft.WeftError, match="short.ply.*byte"):
        weft.read(short)
    with pytest.raises(weft.WeftError, match="missing.obj"):
        weft.read(tmp / "missing.obj")
    with pytest.raises(weft.WeftError, match="unknown mesh format"):
        weft.read(tmp / "mesh.dxf")
    with pytest.raises(weft.WeftError, match="does not exist"):
        weft.write(weft.box(), tmp / "no-such-folder" / "box.obj")
    with pytest.raises(FileNotFoundError, match="missing.3dm"):
        weft.read(tmp / "missing.3dm")
    with pytest.raises(FileNotFoundError, match="does not exist"):
        weft.write(weft.box(), tmp / "no-such-folder" / "box.3dm")
    (tmp / "nothing.3dm").write_bytes(b"not a 3dm file")
    with pytest.raises(ValueError, match="nothing.3dm"):
        weft.read(tmp / "nothing.3dm")




def test_a_failed_write_leaves_no_partial_file(tmp):
    target = tmp / "box.obj"
    weft.write(weft.box(), target)
    before = target.read_bytes()
    (tmp / "dir.obj").mkdir()
    with pytest.raises(weft.WeftError, match="dir.obj"):
        weft.write(weft.box(2, 2, 2), tmp / "dir.obj")
    assert target.read_bytes() == before
    assert sorted(os.listdir(tmp)) == ["box.obj", "dir.obj"]


def test_missing_optional_packages_are_named(monkeypatch):
    # None in sys.modules makes an import fail as if the package were not installed.
    for module in ("trimesh", "compas", "compas.datastructures", "rhino3dm"):
        monkeypatch.setitem(sys.modules, module, None)
    for call, package in [
        (lambda: weft.to_trimesh(weft.box()), "trimesh"),
        (lambda: weft.from_trimesh(None), "trimesh"),
        (lambda: weft.to_compas(weft.box()), "compas"),
        (lambda: weft.from_compas(None), "compas"),
        (lambda: weft.to_rhino3dm(weft.box()), "rhino3dm"),
        (lambda: weft.from_rhino3dm(None), "rhino3dm"),
        (lambda: weft.read("x.3dm"), "rhino3dm"),
        (lambda: weft.write(weft.box(), "x.3dm"), "rhino3dm"),
    ]:
        with pytest.raises(ImportError, match=f"pip install {package}"):
            call()
