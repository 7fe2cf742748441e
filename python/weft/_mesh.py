"""The Mesh class: a WeftMesh handle with numpy views on its buffers."""

import ctypes
import threading
import weakref
from collections import namedtuple

import numpy as np

from . import _arrays
from ._lib import WeftMeshInfo, lib

__all__ = ["Mesh", "MeshInfo"]

MeshInfo = namedtuple("MeshInfo", [name for name, _ in WeftMeshInfo._fields_])
MeshInfo.__doc__ = """Counts and flags of a mesh's topology (see :meth:`Mesh.info`)."""


class Mesh:
    """An immutable polygon mesh owned by the Weft library.

    ``vertices`` is an (n, 3) array-like of real numbers (any float or
    integer dtype; stored as float64). ``faces`` is a list of vertex-index
    sequences of mixed sizes, or an (f, k) array of any integer dtype;
    counter-clockwise seen from the front is the front face::

        >>> m = weft.Mesh([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], [[0, 1, 2, 3]])
        >>> m.face_count, len(m.vertices)
        (1, 4)

    The arrays are copied into the library once; ``vertices``,
    ``face_sizes`` and ``face_indices`` are then read-only numpy views on the
    library's own buffers (no copy), valid as long as any of them or the
    mesh is alive. The library frees the mesh when the last goes.

    Raises :class:`TypeError` or :class:`ValueError` (naming the argument)
    for a wrong dtype or shape, and :class:`weft.WeftError` for what the
    library refuses: an index out of range, a face of fewer than three
    vertices, a repeated index, a NaN or infinite coordinate.

    With ``allow_repeated_vertices=True``, faces that name a vertex more
    than once (``[0, 1, 1, 2]``) are accepted, and subdivision treats them
    as OpenSubdiv does, as non-manifold topology::

        >>> grid = [[0, 0, 0], [1, 0, 0], [2, 0, 0], [0, 1, 0], [1, 1, 0], [2, 1, 0]]
        >>> m = weft.Mesh(grid, [[0, 1, 1, 4, 3], [1, 2, 5, 4]], allow_repeated_vertices=True)
        >>> len(weft.catmull_clark(m, levels=1).vertices)
        16

    With ``copy=False`` the mesh reads the caller's arrays where they are
    (the C ABI's ``weft_mesh_new_borrowed``): a million vertices and faces
    cross in the few milliseconds their checks take, with no copy.
    ``vertices`` must then be a C-contiguous float64 (n, 3) numpy array and
    ``faces`` a C-contiguous uint32 (f, k) array, else :class:`ValueError`
    (as numpy's ``copy=False``). The mesh borrows both: they are made
    read-only while it lives (their writeable flag comes back when it is
    freed), and must not be changed through any other view::

        >>> vertices = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], dtype=np.float64)
        >>> m = weft.Mesh(vertices, np.array([[0, 1, 2, 3]], dtype=np.uint32), copy=False)
        >>> np.shares_memory(m.vertices, vertices), vertices.flags.writeable
        (True, False)
        >>> del m
        >>> vertices.flags.writeable
        True

    Meshes pickle, and ``copy.copy`` / ``copy.deepcopy`` give an equal mesh
    with buffers of its own; ``==`` compares vertices and faces bit for bit.
    """

    __slots__ = ("_handle", "_finalizer", "__weakref__")

    def __init__(self, vertices, faces, allow_repeated_vertices=False, copy=True):
        _check_copy(copy)
        if not copy:
            positions = _arrays.lent_array(vertices, "vertices", np.float64, 2, 3)
            faces = _arrays.lent_array(faces, "faces", np.uint32, 2)
            sizes = np.full(faces.shape[0], faces.shape[1], dtype=np.uint32)
            self._adopt(*_borrowed_handle(positions, sizes, faces, allow_repeated_vertices))
            return
        positions = _arrays.float_array(vertices, "vertices", width=3)
        sizes, indices = _arrays.faces_arrays(faces)
        self._adopt(_new_handle(positions, sizes, indices, allow_repeated_vertices))

    @classmethod
    def from_arrays(cls, vertices, face_sizes, face_indices, allow_repeated_vertices=False, copy=True):
        """A mesh from flat buffers, as the C ABI takes them: ``face_sizes``
        holds the corner count of each face and ``face_indices`` their
        concatenation (integers of any dtype)::

            >>> vertices = [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [-1, 0.5, 0]]
            >>> weft.Mesh.from_arrays(vertices, [3, 4], [0, 1, 2, 0, 2, 3, 4]).faces
            [[0, 1, 2], [0, 2, 3, 4]]

        ``allow_repeated_vertices`` as for :class:`Mesh`. With
        ``copy=False`` the mesh borrows ``vertices`` and ``face_indices``
        (a C-contiguous float64 (n, 3) and a one-dimensional uint32 array)
        as :class:`Mesh` does; ``face_sizes`` is read once.
        """
        _check_copy(copy)
        if not copy:
            positions = _arrays.lent_array(vertices, "vertices", np.float64, 2, 3)
            indices = _arrays.lent_array(face_indices, "face_indices", np.uint32, 1)
            sizes = _arrays.index_array(face_sizes, "face_sizes")
            if sizes.ndim != 1:
                raise ValueError(f"face_sizes must be one-dimensional, not of shape {sizes.shape}")
            return cls._from_handle(*_borrowed_handle(positions, sizes, indices, allow_repeated_vertices))
        positions = _arrays.float_array(vertices, "vertices", width=3)
        sizes = _arrays.index_array(face_sizes, "face_sizes")
        indices = _arrays.index_array(face_indices, "face_indices")
        if sizes.ndim != 1:
            raise ValueError(f"face_sizes must be one-dimensional, not of shape {sizes.shape}")
        if indices.ndim != 1:
            raise ValueError(f"face_indices must be one-dimensional, not of shape {indices.shape}")
        return cls._from_handle(_new_handle(positions, sizes, indices, allow_repeated_vertices))

    @classmethod
    def _from_handle(cls, handle, lent=()):
        """Takes ownership of a WeftMesh * the library handed out (reading
        the arrays `lent`, if any)."""
        mesh = cls.__new__(cls)
        mesh._adopt(handle, lent)
        return mesh

    def _adopt(self, handle, lent=()):
        self._handle = handle
        if lent:
            self._finalizer = weakref.finalize(self, _free_borrowed, handle, lent)
        else:
            self._finalizer = weakref.finalize(self, lib.weft_mesh_free, handle)

    @property
    def is_borrowed(self):
        """Whether the mesh reads arrays it was lent (``copy=False``)."""
        return bool(lib.weft_mesh_is_borrowed(self._handle))

    @property
    def handle(self):
        """The ``WeftMesh *`` as an integer, for calls through :data:`weft.lib`;
        valid while this mesh is alive."""
        return self._handle

    @property
    def vertex_count(self):
        return lib.weft_mesh_vertex_count(self._handle)

    @property
    def face_count(self):
        return lib.weft_mesh_face_count(self._handle)

    @property
    def index_count(self):
        """The number of face corners (the sum of the face sizes)."""
        return lib.weft_mesh_index_count(self._handle)

    @property
    def vertices(self):
        """The positions: a read-only (n, 3) float64 view on the library's buffer."""
        n = self.vertex_count
        return _arrays.view(lib.weft_mesh_positions(self._handle), 3 * n, ctypes.c_double, np.float64, self, (n, 3))

    @property
    def face_sizes(self):
        """The corner count of each face: a read-only uint32 view."""
        return _arrays.view(lib.weft_mesh_face_sizes(self._handle), self.face_count, ctypes.c_uint32, np.uint32, self)

    @property
    def face_indices(self):
        """The faces' vertex indices one face after another: a read-only uint32 view."""
        return _arrays.view(lib.weft_mesh_face_indices(self._handle), self.index_count, ctypes.c_uint32, np.uint32, self)

    @property
    def faces(self):
        """The faces as a list of lists of vertex indices (a copy)."""
        sizes = self.face_sizes
        if len(sizes) == 0:
            return []
        if (sizes == sizes[0]).all():
            return self.face_indices.reshape(-1, int(sizes[0])).tolist()
        ends = np.cumsum(sizes, dtype=np.int64)[:-1]
        return [face.tolist() for face in np.split(self.face_indices, ends)]

    def face_array(self):
        """The faces as an (f, k) uint32 array when all have k corners;
        ValueError for mixed sizes (use ``faces`` or ``face_sizes``)."""
        sizes = self.face_sizes
        if len(sizes) == 0:
            return np.zeros((0, 3), dtype=np.uint32)
        if not (sizes == sizes[0]).all():
            raise ValueError(f"the mesh mixes faces of {sorted(set(sizes.tolist()))} corners; it has no (f, k) array")
        return self.face_indices.reshape(-1, int(sizes[0]))

    def info(self):
        """Counts and flags of the topology: edges, naked and non-manifold
        edges, components, closed, orientable, oriented::

            >>> weft.box(1, 1, 1).info().is_closed
            True
        """
        info = WeftMeshInfo()
        lib.weft_mesh_info(self._handle, ctypes.byref(info))
        return MeshInfo(*(getattr(info, name) for name in MeshInfo._fields))

    def copy_arrays(self):
        """(vertices, face_sizes, face_indices) as new writable arrays of
        their own, filled by the library's ``weft_mesh_copy_*``."""
        positions = np.empty((self.vertex_count, 3), dtype=np.float64)
        sizes = np.empty(self.face_count, dtype=np.uint32)
        indices = np.empty(self.index_count, dtype=np.uint32)
        lib.weft_mesh_copy_positions(self._handle, _arrays.address(positions), positions.size)
        lib.weft_mesh_copy_faces(self._handle, _arrays.address(sizes), sizes.size, _arrays.address(indices), indices.size)
        return positions, sizes, indices

    # The mesh was valid when made: accept its repeated vertices, if any, again.
    def __reduce__(self):
        return (Mesh.from_arrays, (*self.copy_arrays(), True))

    def __copy__(self):
        return Mesh.from_arrays(*self.copy_arrays(), allow_repeated_vertices=True)

    def __deepcopy__(self, memo):
        return self.__copy__()

    def __eq__(self, other):
        if not isinstance(other, Mesh):
            return NotImplemented
        return (
            np.array_equal(self.face_sizes, other.face_sizes)
            and np.array_equal(self.face_indices, other.face_indices)
            and self.vertices.shape == other.vertices.shape
            and self.vertices.tobytes() == other.vertices.tobytes()
        )

    __hash__ = None

    def __repr__(self):
        return f"weft.Mesh({self.vertex_count} vertices, {self.face_count} faces)"


def _check_copy(copy):
    if not isinstance(copy, bool):
        raise TypeError(f"copy must be True or False, not {copy!r}")


# Arrays lent to meshes, by id: [array, meshes borrowing it, writeable before];
# meshes are made and freed on any thread.
_lent = {}
_lent_lock = threading.Lock()


def _borrowed_handle(positions, sizes, indices, allow_repeated_vertices):
    """A handle reading `positions` and `indices` in place, and the arrays
    it borrows, made read-only until the last mesh borrowing them is freed."""
    handle = _new_handle(positions, sizes, indices, allow_repeated_vertices, lib.weft_mesh_new_borrowed)
    lent = (positions, indices)
    with _lent_lock:
        for array in lent:
            entry = _lent.setdefault(id(array), [array, 0, array.flags.writeable])
            entry[1] += 1
            array.flags.writeable = False
    return handle, lent


def _free_borrowed(handle, lent):
    lib.weft_mesh_free(handle)
    with _lent_lock:
        for array in lent:
            entry = _lent[id(array)]
            entry[1] -= 1
            if entry[1] == 0:
                del _lent[id(array)]
                if entry[2]:
                    array.flags.writeable = True


def _check_repeats_flag(allow_repeated_vertices):
    if not isinstance(allow_repeated_vertices, bool):
        raise TypeError(f"allow_repeated_vertices must be True or False, not {allow_repeated_vertices!r}")


def _new_handle(positions, sizes, indices, allow_repeated_vertices=False, make_ex=None):
    """A WeftMesh * from the three arrays: by `make_ex` (a function taking
    ``weft_mesh_new_ex``'s arguments) when given, else copied by
    ``weft_mesh_new`` or, accepting repeated vertices, ``weft_mesh_new_ex``."""
    _check_repeats_flag(allow_repeated_vertices)
    handle = ctypes.c_void_p()
    buffers = (
        _arrays.address(positions),
        positions.shape[0],
        _arrays.address(sizes),
        sizes.size,
        _arrays.address(indices),
        indices.size,
    )
    flags = 1 if allow_repeated_vertices else 0  # WEFT_MESH_ALLOW_REPEATED_VERTICES
    if make_ex is None and not flags:
        lib.weft_mesh_new(*buffers, ctypes.byref(handle))
    else:
        (make_ex or lib.weft_mesh_new_ex)(*buffers, flags, ctypes.byref(handle))
    return handle.value


def take_mesh(out):
    """A Mesh owning the handle an operation wrote into ``out`` (a c_void_p)."""
    return Mesh._from_handle(out.value)


def check_mesh(value, name="mesh"):
    if not isinstance(value, Mesh):
        raise TypeError(f"{name} must be a weft.Mesh, not {type(value).__name__} (make one with weft.Mesh(vertices, faces))")
    return value._handle
