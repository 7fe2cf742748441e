"""Conversions to and from trimesh, COMPAS and rhino3dm, and mesh files.

The three packages are optional: each converter imports its package when
first called and says which to install when it is missing.
"""

import ctypes
import importlib
import os
import tempfile

import numpy as np

from ._lib import lib
from ._mesh import Mesh, check_mesh, take_mesh
from ._ops import _out, join, triangulate


def _require(module, package, what):
    try:
        return importlib.import_module(module)
    except ImportError:
        raise ImportError(f"{what} needs the {package} package: pip install {package}") from None


# trimesh -------------------------------------------------------------------

def from_trimesh(tm):
    """A Mesh from a ``trimesh.Trimesh`` (its vertices and triangles, as they are)::

        >>> import trimesh
        >>> weft.from_trimesh(trimesh.creation.icosphere()).face_count
        1280
    """
    _require("trimesh", "trimesh", "weft.from_trimesh")
    try:
        vertices, faces = tm.vertices, tm.faces
    except AttributeError:
        raise TypeError(f"tm must be a trimesh.Trimesh, not {type(tm).__name__}") from None
    return Mesh(np.asarray(vertices), np.asarray(faces))


def to_trimesh(mesh, **kwargs):
    """A ``trimesh.Trimesh`` of the mesh; quads and n-gons are triangulated
    first (:func:`weft.triangulate`). Keyword arguments go to ``Trimesh``
    (``process`` defaults to False, so vertices keep their order)::

        >>> tm = weft.to_trimesh(weft.catmull_clark(weft.box(), levels=2))
    """
    trimesh = _require("trimesh", "trimesh", "weft.to_trimesh")
    check_mesh(mesh)
    if mesh.face_count and not (mesh.face_sizes == 3).all():
        mesh = triangulate(mesh)
    kwargs.setdefault("process", False)
    return trimesh.Trimesh(vertices=np.array(mesh.vertices), faces=mesh.face_indices.reshape(-1, 3).astype(np.int64), **kwargs)


# COMPAS --------------------------------------------------------------------

def from_compas(cm):
    """A Mesh from a ``compas.datastructures.Mesh``; vertices are numbered
    in the COMPAS mesh's vertex order, faces keep their sizes (n-gons stay n-gons)::

        >>> from compas.datastructures import Mesh as CompasMesh
        >>> weft.from_compas(CompasMesh.from_polyhedron(6)).face_count
        6
    """
    _require("compas", "compas", "weft.from_compas")
    try:
        vertices, faces = cm.to_vertices_and_faces()
    except AttributeError:
        raise TypeError(f"cm must be a compas.datastructures.Mesh, not {type(cm).__name__}") from None
    return Mesh(np.asarray(vertices, dtype=np.float64).reshape(-1, 3), faces)


def to_compas(mesh):
    """A ``compas.datastructures.Mesh`` with the same vertices (keys 0..n-1) and faces::

        >>> cm = weft.to_compas(weft.box(1, 1, 1))
    """
    datastructures = _require("compas.datastructures", "compas", "weft.to_compas")
    check_mesh(mesh)
    return datastructures.Mesh.from_vertices_and_faces(mesh.vertices.tolist(), mesh.faces)


# rhino3dm ------------------------------------------------------------------

def from_rhino3dm(rm):
    """A Mesh from a ``rhino3dm.Mesh``, at double precision. Rhino stores a
    triangle as a quad whose last two corners are equal (C == D): it comes
    as a 3-vertex face. rhino3dm 8 does not expose Rhino's n-gon list
    (``MeshNgonList``) to Python, so an n-gon comes as the triangles and
    quads Rhino stores it as (``weft.weld`` and the subdivisions see one
    surface either way)::

        >>> weft.from_rhino3dm(weft.to_rhino3dm(weft.box())) == weft.box()
        True
    """
    rhino3dm = _require("rhino3dm", "rhino3dm", "weft.from_rhino3dm")
    if not isinstance(rm, rhino3dm.Mesh):
        raise TypeError(f"rm must be a rhino3dm.Mesh, not {type(rm).__name__}")
    vertex_list = rm.Vertices
    points = [vertex_list.Point3dAt(i) for i in range(len(vertex_list))]
    vertices = np.array([(p.X, p.Y, p.Z) for p in points], dtype=np.float64).reshape(-1, 3)
    corners = np.array([rm.Faces[i] for i in range(rm.Faces.Count)], dtype=np.int64).reshape(-1, 4)
    triangle = corners[:, 2] == corners[:, 3]
    sizes = np.where(triangle, 3, 4).astype(np.uint32)
    keep = np.ones(corners.shape, dtype=bool)
    keep[:, 3] = ~triangle
    faces = corners[keep]
    return Mesh.from_arrays(vertices, sizes, faces)


def to_rhino3dm(mesh):
    """A ``rhino3dm.Mesh`` of the mesh at double precision: triangles and
    quads as Rhino faces (a triangle as C == D). Rhino faces have at most
    four corners and rhino3dm 8 cannot make n-gons, so each n-gon is split
    into triangles by :func:`weft.triangulate` (its triangles consecutive,
    vertices unchanged)::

        >>> rm = weft.to_rhino3dm(weft.catmull_clark(weft.box(), levels=1))
    """
    rhino3dm = _require("rhino3dm", "rhino3dm", "weft.to_rhino3dm")
    check_mesh(mesh)
    sizes = mesh.face_sizes
    if (sizes > 4).any():
        mesh = _triangulate_ngons(mesh)
        sizes = mesh.face_sizes
    rm = rhino3dm.Mesh()
    vertex_list = rm.Vertices
    for x, y, z in mesh.vertices.tolist():
        vertex_list.AddPoint3d(x, y, z)
    face_list = rm.Faces
    starts = np.concatenate(([0], np.cumsum(sizes, dtype=np.int64)[:-1])).tolist()
    indices = mesh.face_indices.tolist()
    for start, size in zip(starts, sizes.tolist()):
        face_list.AddFace(*indices[start : start + size])
    return rm


def _triangulate_ngons(mesh):
    """The mesh with each face of more than four corners replaced, in place,
    by its triangles from the library (the faces are only regrouped here)."""
    sizes, indices = mesh.face_sizes, mesh.face_indices
    ngon = sizes > 4
    starts = np.concatenate(([0], np.cumsum(sizes, dtype=np.int64)[:-1]))
    corner_is_ngon = np.repeat(ngon, sizes)
    ngons = Mesh.from_arrays(mesh.vertices, sizes[ngon], indices[corner_is_ngon])
    triangles = triangulate(ngons).face_indices.reshape(-1, 3)
    new_sizes, new_indices, next_triangle = [], [], 0
    for f, (start, size) in enumerate(zip(starts.tolist(), sizes.tolist())):
        if ngon[f]:
            new_sizes += [3] * (size - 2)
            new_indices.append(triangles[next_triangle : next_triangle + size - 2].reshape(-1))
            next_triangle += size - 2
        else:
            new_sizes.append(size)
            new_indices.append(indices[start : start + size])
    return Mesh.from_arrays(mesh.vertices, new_sizes, np.concatenate(new_indices))


# Files ---------------------------------------------------------------------

def _path_bytes(path):
    try:
        text = os.fsdecode(os.fspath(path))
    except TypeError:
        raise TypeError(f"path must be a str or os.PathLike, not {type(path).__name__}") from None
    try:
        return text, text.encode("utf-8")
    except UnicodeEncodeError:
        raise ValueError(f"path {text!r} is not valid UTF-8") from None


def _is_3dm(text):
    return text.lower().endswith(".3dm")


def read(path):
    """Reads a mesh file, the format chosen by the extension as ``weft``
    does: ``.obj``, ``.ply``, ``.stl``, ``.off`` (by the library: an error is
    a :class:`WeftError` naming the file and the line or byte offset), and
    ``.3dm`` through rhino3dm (every mesh object of the file, joined). STL
    corners come unwelded (``weft.weld(m, 0.0)`` joins them)::

        >>> import os, tempfile
        >>> path = os.path.join(tempfile.mkdtemp(), "cage.obj")
        >>> weft.write(weft.box(), path)
        >>> weft.read(path) == weft.box()
        True
    """
    text, encoded = _path_bytes(path)
    if _is_3dm(text):
        rhino3dm = _require("rhino3dm", "rhino3dm", "reading .3dm files")
        if not os.path.isfile(text):
            raise FileNotFoundError(f"{text}: no such file")
        model = rhino3dm.File3dm.Read(text)
        if model is None:
            raise ValueError(f"{text}: rhino3dm cannot read it as a .3dm file")
        meshes = [from_rhino3dm(o.Geometry) for o in model.Objects if isinstance(o.Geometry, rhino3dm.Mesh)]
        if not meshes:
            raise ValueError(f"{text}: the file holds no mesh objects")
        return meshes[0] if len(meshes) == 1 else join(meshes)
    out = _out()
    lib.weft_read_mesh_file(encoded, ctypes.byref(out))
    return take_mesh(out)


def write(mesh, path):
    """Writes a mesh file, the format chosen by the extension as ``weft``
    does: ``.obj``, ``.ply`` (binary), ``.stl`` (binary; polygons as fans),
    ``.off``, and ``.3dm`` through rhino3dm (one mesh object, or one per mesh
    when ``mesh`` is a list). The file is written under a temporary name and
    renamed into place, so a failed write leaves no partial file::

        >>> import os, tempfile
        >>> path = os.path.join(tempfile.mkdtemp(), "smooth.ply")
        >>> weft.write(weft.catmull_clark(weft.box(), levels=2), path)
        >>> weft.read(path).face_count
        96
    """
    text, encoded = _path_bytes(path)
    if _is_3dm(text):
        rhino3dm = _require("rhino3dm", "rhino3dm", "writing .3dm files")
        meshes = list(mesh) if isinstance(mesh, (list, tuple)) else [mesh]
        model = rhino3dm.File3dm()
        for m in meshes:
            model.Objects.AddMesh(to_rhino3dm(m))
        folder = os.path.dirname(os.path.abspath(text))
        if not os.path.isdir(folder):
            raise FileNotFoundError(f"{text}: the folder {folder} does not exist")
        handle, temporary = tempfile.mkstemp(dir=folder, prefix="." + os.path.basename(text), suffix=".partial")
        os.close(handle)
        try:
            if not model.Write(temporary, 8):
                raise OSError(f"{text}: rhino3dm could not write the file")
            os.replace(temporary, text)
        finally:
            if os.path.exists(temporary):
                os.remove(temporary)
        return
    lib.weft_write_mesh_file(check_mesh(mesh), encoded)
