"""The operations of include/weft.h over Mesh objects and numpy arrays.

Each wrapper checks and converts its arguments, calls the C function once
(ctypes releases the GIL for the call) and wraps what comes back; the
geometry is all in the library.
"""

import ctypes
import weakref
from collections import namedtuple

import numpy as np

from . import _arrays
from ._lib import WeftOrientReport, WeftPlane, WeftSubdivisionOptions, WeftWeldReport, lib
from ._mesh import Mesh, check_mesh, take_mesh

DEFAULT_WELD_TOLERANCE = 0.001
SHARPNESS_INFINITE = 10.0

# The string spellings of the C enumerations. A new C value is one entry.
NAKED_EDGES = {"fixed": 0, "smooth": 1, "corner-fixed": 2, "none": 3}
TRIANGLES = {"catmark": 0, "smooth": 1}
SCHEMES = {"catmull-clark": 0, "loop": 1}
CREASING = {"uniform": 0, "chaikin": 1}
FACE_VARYING = {"smooth": 0, "corners-only": 1, "corners-plus1": 2, "corners-plus2": 3, "boundaries": 4, "all": 5}
PLATONIC = {"tetrahedron": 0, "hexahedron": 1, "octahedron": 2, "dodecahedron": 3, "icosahedron": 4}
SIDED = {"prism": 0, "antiprism": 1, "pyramid": 2, "dipyramid": 3}
OFFSET = {"diagonal": 0, "hypotenuse-average": 1, "planes-intersection": 2}
INSET = {"edge-fraction": 0, "parallelogram": 1}
SMOOTH_DIRECTION = {"free": 0, "along-normal": 1, "tangential": 2}
TILE_FILL = {
    "skip": 0, "best": 1, "triangle-fan": 2, "triangle-hand": 3, "triangle-knit": 4,
    "triangle-zigzag": 5, "quad-stitch": 6, "quad-fan": 7,
}
TILE_FACES = {"all": 0, "quads-and-more": 1, "pentagons-and-more": 2, "triangles": 9, "quads": 16}
DUAL = {"vertex-average": 0, "keep-size": 1}

WeldReport = namedtuple("WeldReport", [name for name, _ in WeftWeldReport._fields_])
OrientReport = namedtuple("OrientReport", [name for name, _ in WeftOrientReport._fields_])
WeldReport.__doc__ = "What :func:`weld` changed: vertices merged, faces removed, unused vertices left out."

TNODE_DTYPE = np.dtype(
    [("vertex", np.uint32), ("edge_start", np.uint32), ("edge_end", np.uint32), ("face", np.uint32), ("parameter", np.float64)],
    align=True,
)


def _choice(value, name, table):
    if isinstance(value, str):
        key = value.lower().replace("_", "-").replace(" ", "-")
        if key in table:
            return table[key]
    raise ValueError(f"{name} is {value!r}; it must be one of {', '.join(repr(k) for k in table)}")


def _count(value, name, minimum=0):
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)):
        raise TypeError(f"{name} must be an integer, not {type(value).__name__}")
    if value < minimum or value > 0xFFFFFFFF:
        raise ValueError(f"{name} is {value}; it must be at least {minimum}")
    return int(value)


def _size(value, name):
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)):
        raise TypeError(f"{name} must be an integer, not {type(value).__name__}")
    if value < 0:
        raise ValueError(f"{name} is {value}; it must not be negative")
    return int(value)


def _number(value, name):
    if isinstance(value, (bool, str, bytes)):
        raise TypeError(f"{name} must be a number, not {type(value).__name__}")
    try:
        return float(value)
    except (TypeError, ValueError):
        raise TypeError(f"{name} must be a number, not {type(value).__name__}") from None


def _out():
    return ctypes.c_void_p()


def _mesh_op(function, mesh, *arguments):
    """Calls an operation of the form f(mesh, ..., WeftMesh **out) and wraps the result."""
    handle = check_mesh(mesh)
    out = _out()
    function(handle, *arguments, ctypes.byref(out))
    return take_mesh(out)


def _counted_mesh_op(function, mesh, report, *arguments):
    """Calls an operation of the form f(mesh, ..., WeftMesh **out, size_t *count):
    the new mesh, or with ``report`` ``(mesh, count)``."""
    handle = check_mesh(mesh)
    count = ctypes.c_size_t()
    out = _out()
    function(handle, *arguments, ctypes.byref(out), ctypes.byref(count))
    result = take_mesh(out)
    return (result, count.value) if report else result


def _segments(value, name, count):
    """Line segments given as an (n, 2, 3) or (n, 6) array-like, as an (n, 6)
    float array; ``count`` is the letter the error message uses for n."""
    array = _arrays._as_numeric(value, name)
    if array.ndim == 3:
        if array.shape[1:] != (2, 3):
            raise ValueError(f"{name} must have shape ({count}, 2, 3) or ({count}, 6), not {array.shape}")
        array = array.reshape(-1, 6)
    return _arrays.float_array(array, name, width=6)


def _plane(plane):
    """A WeftPlane from None (world XY) or (origin, x_axis, y_axis)."""
    if plane is None:
        return None
    try:
        origin, x_axis, y_axis = plane
    except (TypeError, ValueError):
        raise ValueError("plane must be None or (origin, x_axis, y_axis), three points of 3 numbers") from None
    parts = [_arrays.float_array(p, f"plane[{i}]") for i, p in enumerate((origin, x_axis, y_axis))]
    for i, part in enumerate(parts):
        if part.shape != (3,):
            raise ValueError(f"plane[{i}] must hold 3 numbers, not {part.size}")
    return ctypes.byref(WeftPlane(*((ctypes.c_double * 3)(*p) for p in parts)))


# Subdivision ---------------------------------------------------------------

def catmull_clark(mesh, levels=1, naked_edges="fixed"):
    """Subdivides a mesh with Catmull-Clark ``levels`` times, as OpenSubdiv's
    Catmark scheme; triangles, quads and n-gons may be mixed and every face
    of the result is a quad. ``naked_edges`` is ``"fixed"`` (the outline
    stays), ``"smooth"`` (it tends to a cubic B-spline) or
    ``"corner-fixed"`` (as smooth, keeping vertices of one face).

    The input's vertices keep their indices, then come one point per edge,
    then one per face::

        >>> s = weft.catmull_clark(weft.box(1, 1, 1), levels=2, naked_edges="smooth")
        >>> s.face_count
        96
    """
    return _mesh_op(lib.weft_catmull_clark, mesh, _count(levels, "levels"), _choice(naked_edges, "naked_edges", NAKED_EDGES))


def loop(mesh, levels=1, naked_edges="fixed"):
    """Subdivides a triangle mesh with Loop ``levels`` times (each triangle
    becomes 4), as OpenSubdiv's Loop scheme; ``naked_edges`` as in
    :func:`catmull_clark`. A face that is not a triangle is a
    :class:`WeftError` (NOT_TRIANGLES) naming it; :func:`triangulate` first::

        >>> weft.loop(weft.platonic("icosahedron"), levels=1).face_count
        80
    """
    return _mesh_op(lib.weft_loop, mesh, _count(levels, "levels"), _choice(naked_edges, "naked_edges", NAKED_EDGES))


class _Options:
    """A WeftSubdivisionOptions and the arrays its pointers point into."""

    def __init__(self, scheme, naked_edges, creases=None, corners=None, creasing="uniform", holes=None, triangles="catmark"):
        self.struct = WeftSubdivisionOptions()
        self.struct.scheme = _choice(scheme, "scheme", SCHEMES)
        self.struct.naked_edges = _choice(naked_edges, "naked_edges", NAKED_EDGES)
        self.struct.creasing = _choice(creasing, "creasing", CREASING)
        self.struct.triangles = _choice(triangles, "triangles", TRIANGLES)
        self.keep = []
        if holes is not None and len(holes):
            faces = _arrays.index_array(holes, "holes").reshape(-1)
            self.struct.hole_count = faces.size
            self.struct.hole_faces = faces.ctypes.data
            self.keep.append(faces)
        if creases is not None and len(creases):
            table = _arrays.float_array(creases, "creases", width=3)
            pairs = _arrays.index_array(_whole(table[:, :2], "creases"), "creases")
            sharpness = np.ascontiguousarray(table[:, 2])
            self.struct.crease_count = len(table)
            self.struct.crease_vertex_pairs = pairs.ctypes.data
            self.struct.crease_sharpness = sharpness.ctypes.data
            self.keep += [pairs, sharpness]
        if corners is not None and len(corners):
            table = _arrays.float_array(corners, "corners", width=2)
            vertices = _arrays.index_array(_whole(table[:, 0], "corners"), "corners")
            sharpness = np.ascontiguousarray(table[:, 1])
            self.struct.corner_count = len(table)
            self.struct.corner_vertices = vertices.ctypes.data
            self.struct.corner_sharpness = sharpness.ctypes.data
            self.keep += [vertices, sharpness]

    @property
    def ref(self):
        return ctypes.byref(self.struct)


def _table(values, name, rows="n"):
    """A float64 table of shape (rows,) or (rows, width), and its width."""
    array = _arrays._as_numeric(values, name)
    if array.ndim not in (1, 2):
        raise ValueError(f"{name} must have shape ({rows},) or ({rows}, width), not {array.shape}")
    width = 1 if array.ndim == 1 else array.shape[1]
    return _arrays.float_array(array, name, width=None if array.ndim == 1 else width), width


def _whole(values, name):
    """Vertex indices that came in a float table, checked to be whole numbers."""
    if not np.all(np.isfinite(values)) or not np.all(values == np.round(values)):
        raise ValueError(f"{name}: vertex indices must be whole numbers")
    return values.astype(np.int64)


def subdivide(mesh, scheme="catmull-clark", levels=1, naked_edges="fixed", creases=None, corners=None, creasing="uniform",
              holes=None, triangles="catmark"):
    """Subdivides a mesh with creases and sharp corners, as OpenSubdiv does
    with the same options.

    ``scheme`` is ``"catmull-clark"`` or ``"loop"``; ``naked_edges`` as in
    :func:`catmull_clark`. ``creases`` is a sequence of ``(i, j, sharpness)``
    (the ends of an edge of the mesh), ``corners`` of ``(vertex, sharpness)``;
    sharpness 0 is smooth, :data:`SHARPNESS_INFINITE` (10) or more a hard
    crease. ``creasing`` is ``"uniform"`` or ``"chaikin"``. ``holes`` lists
    faces left out of the result (OpenSubdiv's hole tags; their vertices and
    edges still shape the neighbours); ``triangles`` is ``"catmark"`` or
    ``"smooth"`` (OpenSubdiv's smooth-triangle weights for Catmull-Clark)::

        >>> cube = weft.box(1, 1, 1)
        >>> s = weft.subdivide(cube, levels=2, creases=[(0, 1, 10.0)], corners=[(2, 10.0)])
    """
    options = _Options(scheme, naked_edges, creases, corners, creasing, holes, triangles)
    return _mesh_op(lib.weft_subdivide_ex, mesh, options.ref, _count(levels, "levels"))


def subdivision_counts(mesh, scheme="catmull-clark", levels=1, naked_edges="fixed", holes=None):
    """(vertex_count, face_count, index_count) of the mesh ``levels`` steps
    of ``scheme`` make, without subdividing; holes (and ``naked_edges="none"``)
    leave their vertices but no faces::

        >>> weft.subdivision_counts(weft.box(1, 1, 1), levels=1)
        (26, 24, 96)
    """
    counts = [ctypes.c_size_t() for _ in range(3)]
    if naked_edges == "fixed" and holes is None:
        lib.weft_subdivision_counts(
            check_mesh(mesh), _choice(scheme, "scheme", SCHEMES), _count(levels, "levels"), *(ctypes.byref(c) for c in counts)
        )
    else:
        options = _Options(scheme, naked_edges, holes=holes)
        lib.weft_subdivision_counts_ex(check_mesh(mesh), options.ref, _count(levels, "levels"), *(ctypes.byref(c) for c in counts))
    return tuple(c.value for c in counts)


def subdivide_into(mesh, positions, face_indices, scheme="catmull-clark", levels=1, naked_edges="fixed"):
    """Subdivides into arrays of your own, for a script that subdivides again
    and again: the result of :func:`catmull_clark` or :func:`loop` (by
    ``scheme``), bit for bit, written into ``positions`` (a writable
    C-contiguous float64 array of shape (n, 3)) and ``face_indices`` (a
    writable C-contiguous uint32 array, flat or (f, k)) from their start.
    Size them with :func:`subdivision_counts`; from level 1 on every face
    is a quad (Catmull-Clark) or a triangle (Loop). Arrays too small are a
    :class:`WeftError` (BUFFER_TOO_SMALL) and are left as they were::

        >>> cube = weft.box(1, 1, 1)
        >>> n, f, k = weft.subdivision_counts(cube, levels=2)
        >>> positions, quads = np.empty((n, 3)), np.empty((f, 4), dtype=np.uint32)
        >>> weft.subdivide_into(cube, positions, quads, levels=2)
        >>> bool((positions == weft.catmull_clark(cube, levels=2).vertices).all())
        True
    """
    handle = check_mesh(mesh)
    _arrays.output_array(positions, "positions", np.float64, "(n, 3)", lambda a: a.ndim == 2 and a.shape[1] == 3)
    _arrays.output_array(face_indices, "face_indices", np.uint32, "(k,) or (f, k)", lambda a: a.ndim in (1, 2))
    scheme_value = _choice(scheme, "scheme", SCHEMES)
    levels = _count(levels, "levels")
    naked = _choice(naked_edges, "naked_edges", NAKED_EDGES)
    lib.weft_subdivide_into(
        handle, scheme_value, levels, naked, _arrays.address(positions), positions.size,
        _arrays.address(face_indices), face_indices.size,
    )


def subdivide_vertex_data(mesh, data, levels=1, scheme="catmull-clark", naked_edges="fixed", creases=None, corners=None,
                          creasing="uniform", holes=None, triangles="catmark"):
    """Carries per-vertex data (colours, weights: an (n,) or (n, width)
    array) through the subdivision :func:`subdivide` makes with the same
    options; each refined vertex gets the weighted sum its position gets::

        >>> weft.subdivide_vertex_data(weft.box(), np.random.rand(8, 3), levels=2).shape
        (98, 3)
    """
    options = _Options(scheme, naked_edges, creases, corners, creasing, holes, triangles)
    values, width = _table(data, "data")
    vertex_count, _, _ = subdivision_counts(mesh, scheme, levels, naked_edges, holes)
    out = np.empty((vertex_count, width) if values.ndim == 2 else vertex_count, dtype=np.float64)
    lib.weft_subdivide_vertex_data(
        check_mesh(mesh), options.ref, _count(levels, "levels"), _arrays.address(values), values.size, width,
        _arrays.address(out), out.size,
    )
    return out


def subdivide_face_varying(mesh, values, value_indices, levels=1, linear="smooth", scheme="catmull-clark",
                           naked_edges="fixed", creases=None, corners=None, creasing="uniform", holes=None,
                           triangles="catmark"):
    """Carries per-corner values (UVs) through the subdivision: ``values``
    is a (k,) or (k, width) array, ``value_indices`` the value of every face
    corner, face after face (as ``mesh.face_indices``). ``linear`` says where
    values are interpolated linearly: ``"smooth"``, ``"corners-only"``,
    ``"corners-plus1"``, ``"corners-plus2"``, ``"boundaries"`` or ``"all"``.
    Returns the refined mesh's per-corner values, face after face::

        >>> cube = weft.box()
        >>> weft.subdivide_face_varying(cube, np.random.rand(24, 2), np.arange(24), levels=2).shape
        (384, 2)
    """
    options = _Options(scheme, naked_edges, creases, corners, creasing, holes, triangles)
    table, width = _table(values, "values", rows="k")
    indices = _arrays.index_array(value_indices, "value_indices")
    if indices.ndim != 1:
        indices = indices.reshape(-1)
    _, _, index_count = subdivision_counts(mesh, scheme, levels, naked_edges, holes)
    out = np.empty((index_count, width) if table.ndim == 2 else index_count, dtype=np.float64)
    lib.weft_subdivide_face_varying(
        check_mesh(mesh), options.ref, _count(levels, "levels"), _choice(linear, "linear", FACE_VARYING),
        _arrays.address(table), len(table), width, _arrays.address(indices), indices.size, _arrays.address(out), out.size,
    )
    return out


def subdivide_limit(mesh, levels=1, scheme="catmull-clark", naked_edges="fixed", creases=None, corners=None,
                    creasing="uniform", holes=None, triangles="catmark"):
    """The vertices of :func:`subdivide` moved onto the limit surface, and
    the surface's unit normals there: ``(positions, normals)``, two (N, 3)
    arrays::

        >>> points, normals = weft.subdivide_limit(weft.box(1, 1, 1), levels=2)
    """
    options = _Options(scheme, naked_edges, creases, corners, creasing, holes, triangles)
    vertex_count, _, _ = subdivision_counts(mesh, scheme, levels, naked_edges, holes)
    positions = np.empty((vertex_count, 3), dtype=np.float64)
    normals = np.empty((vertex_count, 3), dtype=np.float64)
    lib.weft_subdivide_limit(
        check_mesh(mesh), options.ref, _count(levels, "levels"), _arrays.address(positions), _arrays.address(normals), positions.size
    )
    return positions, normals


def limit_patches(mesh, isolation=2, naked_edges="fixed", creases=None, corners=None, creasing="uniform", holes=None,
                  triangles="catmark"):
    """The Catmull-Clark limit surface as bicubic Bézier patches, one per
    face of ``mesh`` refined ``isolation`` levels (1 to 8), what ``weft
    nurbs`` writes as STEP: ``(control_points, cage_faces, errors)``.
    ``control_points[p, i, j]`` is patch p's control point i along u and j
    along v (a B-spline of degree 3 × 3, knots 0, 0, 0, 0, 1, 1, 1, 1), an
    (n, 4, 4, 3) array; ``cage_faces[p]`` the face of ``mesh`` it lies on;
    ``errors[p]`` its largest distance from the limit surface (0 to rounding
    where the surface is a bicubic B-spline, away from extraordinary
    vertices)::

        >>> control, faces, errors = weft.limit_patches(weft.box(1, 1, 1), isolation=2)
        >>> control.shape, int((errors < 1e-12).sum())
        ((96, 4, 4, 3), 72)
    """
    options = _Options("catmull-clark", naked_edges, creases, corners, creasing, holes, triangles)
    isolation = _count(isolation, "isolation")
    _, count, _ = subdivision_counts(mesh, "catmull-clark", isolation, naked_edges, holes)
    return _patches(count, lambda *buffers: lib.weft_limit_patches(check_mesh(mesh), options.ref, isolation, *buffers))


def _patches(count, call):
    """Runs a patch export into new arrays for ``count`` patches:
    ``(control_points, cage_faces, errors)``."""
    control = np.empty((count, 4, 4, 3), dtype=np.float64)
    faces = np.empty(count, dtype=np.uint32)
    errors = np.empty(count, dtype=np.float64)
    written = ctypes.c_size_t()
    call(_arrays.address(control), _arrays.address(faces), _arrays.address(errors), count, ctypes.byref(written),
         None, None)
    return control, faces, errors


def subdivision_face_count(mesh, scheme="catmull-clark", levels=1):
    """The number of faces ``levels`` steps of ``scheme`` make, without subdividing::

        >>> weft.subdivision_face_count(weft.box(), levels=2)
        96
    """
    count = ctypes.c_size_t()
    lib.weft_subdivision_face_count(check_mesh(mesh), _choice(scheme, "scheme", SCHEMES), _count(levels, "levels"), ctypes.byref(count))
    return count.value


def subdivision_parent_faces(mesh, scheme="catmull-clark", levels=1, naked_edges="fixed", holes=None):
    """For every face of the subdivided mesh, the index of the input face it
    comes from (a uint32 array); holes (and ``naked_edges="none"``) have no
    faces there::

        >>> weft.subdivision_parent_faces(weft.box(1, 1, 1), levels=1)[:8]
        array([0, 0, 0, 0, 1, 1, 1, 1], dtype=uint32)
    """
    if naked_edges == "fixed" and holes is None:
        out = np.empty(subdivision_face_count(mesh, scheme, levels), dtype=np.uint32)
        lib.weft_subdivision_parent_faces(check_mesh(mesh), _choice(scheme, "scheme", SCHEMES), _count(levels, "levels"), _arrays.address(out), out.size)
        return out
    options = _Options(scheme, naked_edges, holes=holes)
    out = np.empty(subdivision_counts(mesh, scheme, levels, naked_edges, holes)[1], dtype=np.uint32)
    lib.weft_subdivision_parent_faces_ex(check_mesh(mesh), options.ref, _count(levels, "levels"), _arrays.address(out), out.size)
    return out


class Refiner:
    """A subdivision planned once for a cage's topology, re-evaluated for new
    vertex positions at the cost of the arithmetic only (a slider dragged).

    Options as in :func:`subdivide`; ``r.mesh`` is the refined mesh at the
    cage's positions, ``r.evaluate(new_vertices)`` the refined positions for
    new cage positions (an (N, 3) array)::

        >>> cage = weft.box()
        >>> r = weft.Refiner(cage, scheme="catmull-clark", levels=3, naked_edges="smooth")
        >>> r.evaluate(cage.vertices * 2.0).shape
        (386, 3)
    """

    def __init__(self, cage, scheme="catmull-clark", levels=1, naked_edges="fixed", creases=None, corners=None,
                 creasing="uniform", holes=None, triangles="catmark"):
        handle = check_mesh(cage, "cage")
        out = _out()
        levels = _count(levels, "levels")
        if creases is None and corners is None and creasing == "uniform" and holes is None and triangles == "catmark":
            lib.weft_refiner_new(handle, _choice(scheme, "scheme", SCHEMES), levels, _choice(naked_edges, "naked_edges", NAKED_EDGES), ctypes.byref(out))
        else:
            options = _Options(scheme, naked_edges, creases, corners, creasing, holes, triangles)
            lib.weft_refiner_new_ex(handle, options.ref, levels, ctypes.byref(out))
        self._handle = out.value
        self._cage_vertex_count = cage.vertex_count
        self._finalizer = weakref.finalize(self, lib.weft_refiner_free, self._handle)

    @property
    def vertex_count(self):
        """The number of refined vertices."""
        return lib.weft_refiner_vertex_count(self._handle)

    @property
    def face_count(self):
        """The number of refined faces."""
        return lib.weft_refiner_face_count(self._handle)

    @property
    def mesh(self):
        """The refined mesh at the cage positions the refiner was built from."""
        out = _out()
        lib.weft_refiner_mesh(self._handle, ctypes.byref(out))
        return take_mesh(out)

    def evaluate(self, vertices, out=None):
        """The refined positions for new cage positions ``vertices`` (an
        (n, 3) array-like, n the cage's vertex count), as an (N, 3) float64
        array; pass ``out`` (a C-contiguous (N, 3) float64 array) to reuse
        a buffer."""
        positions = _arrays.float_array(vertices, "vertices", width=3)
        if out is None:
            out = np.empty((self.vertex_count, 3), dtype=np.float64)
        elif not (isinstance(out, np.ndarray) and out.dtype == np.float64 and out.flags.c_contiguous and out.flags.writeable):
            raise TypeError("out must be a writable, C-contiguous float64 numpy array")
        elif out.shape != (self.vertex_count, 3):
            raise ValueError(f"out must have shape ({self.vertex_count}, 3), not {out.shape}")
        lib.weft_refiner_evaluate(self._handle, _arrays.address(positions), positions.shape[0], _arrays.address(out), out.size)
        return out

    def __repr__(self):
        return f"weft.Refiner({self.vertex_count} vertices, {self.face_count} faces)"


class LimitSurface:
    """The limit surface of a cage, evaluated anywhere: positions and the
    derivatives by u and v at (face, u, v) samples, exact (bicubic B-spline
    or box-spline patches, local refinement around extraordinary vertices).

    Options as in :func:`subdivide`. A quad's (u, v) runs from its first
    corner, u towards the second and v towards the last; a Loop triangle's
    is barycentric (corner 1 at (1, 0), corner 2 at (0, 1)); other faces
    follow OpenSubdiv's Bfr quad sub-faces (see ``include/weft.h``)::

        >>> surface = weft.LimitSurface(weft.box(), scheme="catmull-clark")
        >>> p, du, dv = surface.evaluate([0, 0], [[0.5, 0.5], [0.0, 0.0]])
        >>> p.shape
        (2, 3)
    """

    def __init__(self, cage, scheme="catmull-clark", naked_edges="fixed", creases=None, corners=None,
                 creasing="uniform", holes=None, triangles="catmark"):
        handle = check_mesh(cage, "cage")
        options = _Options(scheme, naked_edges, creases, corners, creasing, holes, triangles)
        out = _out()
        lib.weft_limit_surface_new(handle, options.ref, ctypes.byref(out))
        # What the count of patches needs (see patches).
        self._cage, self._naked_edges, self._holes = cage, naked_edges, holes
        self._handle = out.value
        self._finalizer = weakref.finalize(self, lib.weft_limit_surface_free, self._handle)

    def evaluate(self, faces, uvs):
        """Positions, d/du and d/dv at sample i on face ``faces[i]`` at
        ``uvs[i]`` (an (n, 2) array-like), as three (n, 3) float64 arrays."""
        faces = _arrays.index_array(faces, "faces").reshape(-1)
        uvs = _arrays.float_array(uvs, "uvs", width=2)
        if uvs.shape[0] != faces.size:
            raise ValueError(f"{faces.size} faces but {uvs.shape[0]} (u, v) pairs")
        n = faces.size
        positions, du, dv = (np.empty((n, 3), dtype=np.float64) for _ in range(3))
        lib.weft_limit_surface_evaluate(self._handle, n, _arrays.address(faces), _arrays.address(uvs),
                                        _arrays.address(positions), _arrays.address(du), _arrays.address(dv))
        return positions, du, dv

    def closest_point(self, points):
        """The nearest point of the surface to each of ``points`` (an (n, 3)
        array-like): ``(faces, uvs, positions)``, an (n,) uint32 array, an
        (n, 2) and an (n, 3) float64 array; the positions are the surface
        evaluated at the faces and (u, v)."""
        queries = _arrays.float_array(points, "points", width=3)
        n = queries.shape[0]
        faces = np.empty(n, dtype=np.uint32)
        uvs = np.empty((n, 2), dtype=np.float64)
        positions = np.empty((n, 3), dtype=np.float64)
        lib.weft_limit_surface_closest_point(self._handle, n, _arrays.address(queries), _arrays.address(faces),
                                             _arrays.address(uvs), _arrays.address(positions))
        return faces, uvs, positions

    def patches(self, isolation=2):
        """The surface as bicubic Bézier patches, one per face of the cage
        refined ``isolation`` levels, as :func:`limit_patches` gives them
        (Catmull-Clark surfaces only)::

            >>> control, faces, errors = weft.LimitSurface(weft.box(), naked_edges="smooth").patches(1)
            >>> control.shape
            (24, 4, 4, 3)
        """
        isolation = _count(isolation, "isolation")
        _, count, _ = subdivision_counts(self._cage, "catmull-clark", isolation, self._naked_edges, self._holes)
        return _patches(count, lambda *buffers: lib.weft_limit_surface_patches(self._handle, isolation, *buffers))

    def __repr__(self):
        return "weft.LimitSurface()"


def crease_edges_from_mesh(mesh, angle_degrees=180.0, vertex_map=False):
    """Prepares a mesh whose creases are unwelded seams or sharp folds for
    creased subdivision, as Rhino's ToSubD: welds vertices at the same
    position and lists as creases the seams and every edge whose faces'
    normals differ by more than ``angle_degrees``. Returns ``(welded,
    pairs)``, pairs an (c, 2) uint32 array, or ``(welded, pairs, map)`` with
    ``vertex_map=True`` (the welded vertex each input vertex became)::

        >>> welded, pairs = weft.crease_edges_from_mesh(weft.triangulate(weft.box()), 30.0)
        >>> len(pairs)
        12
        >>> s = weft.subdivide(welded, levels=2, creases=[(i, j, 10.0) for i, j in pairs])
    """
    handle = check_mesh(mesh)
    angle = _number(angle_degrees, "angle_degrees")
    out = _out()
    pairs = np.empty(2 * mesh.index_count, dtype=np.uint32)
    count = ctypes.c_size_t()
    if vertex_map:
        mapping = np.empty(mesh.vertex_count, dtype=np.uint32)
        lib.weft_crease_edges_from_mesh_ex(
            handle, angle, ctypes.byref(out), _arrays.address(pairs), pairs.size, ctypes.byref(count), _arrays.address(mapping), mapping.size
        )
        return take_mesh(out), pairs[: 2 * count.value].reshape(-1, 2).copy(), mapping
    lib.weft_crease_edges_from_mesh(handle, angle, ctypes.byref(out), _arrays.address(pairs), pairs.size, ctypes.byref(count))
    return take_mesh(out), pairs[: 2 * count.value].reshape(-1, 2).copy()


# Mending -------------------------------------------------------------------

def join(meshes):
    """Joins meshes into one, offsetting each one's indices; faces keep their order::

        >>> both = weft.join([weft.box(1, 1, 1), weft.box(2, 2, 2)])
    """
    meshes = list(meshes)
    handles = (ctypes.c_void_p * max(len(meshes), 1))(*(check_mesh(m, f"meshes[{i}]") for i, m in enumerate(meshes)))
    out = _out()
    lib.weft_join(handles if meshes else None, len(meshes), ctypes.byref(out))
    return take_mesh(out)


def weld_relative_tolerance(mesh):
    """A weld tolerance suited to the mesh's size: a millionth of its
    bounding-box diagonal (0 for an empty mesh). It never collapses the
    faces of a small part or a dense scan, as an absolute 0.001 can::

        >>> round(weft.weld_relative_tolerance(weft.box()) * 1e6, 6)
        1.732051
    """
    tolerance = ctypes.c_double()
    lib.weft_weld_relative_tolerance(check_mesh(mesh), ctypes.byref(tolerance))
    return tolerance.value


def unused_vertex_count(mesh):
    """How many vertices no face uses (subdivision keeps them in place)::

        >>> weft.unused_vertex_count(weft.Mesh([(0, 0, 0), (1, 0, 0), (0, 1, 0), (5, 5, 5)], [[0, 1, 2]]))
        1
    """
    return lib.weft_mesh_unused_vertex_count(check_mesh(mesh))


def remove_unused_vertices(mesh, report=False):
    """Leaves out the vertices no face uses; the others keep their order.
    With ``report=True`` returns ``(mesh, removed)``::

        >>> weft.remove_unused_vertices(weft.Mesh([(0, 0, 0), (5, 5, 5), (1, 0, 0), (0, 1, 0)], [[0, 2, 3]])).faces
        [[0, 1, 2]]
    """
    return _counted_mesh_op(lib.weft_remove_unused_vertices, mesh, report)


def weld(meshes, tolerance=DEFAULT_WELD_TOLERANCE):
    """Joins meshes (one mesh or a sequence) and welds vertices at most
    ``tolerance`` apart, transitively; faces drop repeated corners and
    faces left with fewer than 3 are removed. Returns ``(mesh, report)``
    with a :class:`WeldReport`::

        >>> m1 = weft.box()
        >>> m2 = weft.Mesh(m1.vertices + [1.0, 0, 0], m1.faces)
        >>> w, report = weft.weld([m1, m2], tolerance=1e-6)
        >>> report.merged_vertex_count
        4
    """
    mesh = meshes if isinstance(meshes, Mesh) else join(meshes)
    handle = check_mesh(mesh)
    report = WeftWeldReport()
    out = _out()
    lib.weft_weld(handle, _number(tolerance, "tolerance"), ctypes.byref(out), ctypes.byref(report))
    return take_mesh(out), WeldReport(report.merged_vertex_count, report.removed_face_count, report.unused_vertex_count)


def find_t_nodes(mesh, tolerance=DEFAULT_WELD_TOLERANCE):
    """The T-nodes: vertices on the naked boundary lying inside another
    face's naked edge, the reason welding fails. A numpy structured array
    with fields ``vertex``, ``edge_start``, ``edge_end``, ``face`` and
    ``parameter`` (0 at edge_start, 1 at edge_end)::

        >>> coarse, fine = weft.plane_grid(2, 2), weft.plane_grid(2, 2, 2, 2)
        >>> m, _ = weft.weld([coarse, weft.Mesh(fine.vertices + [2.0, 0, 0], fine.faces)], 1e-9)
        >>> weft.find_t_nodes(m, 1e-6)["vertex"]
        array([6], dtype=uint32)
    """
    handle = check_mesh(mesh)
    tolerance = _number(tolerance, "tolerance")
    count = ctypes.c_size_t()
    lib.weft_find_t_nodes(handle, tolerance, None, 0, ctypes.byref(count))
    nodes = np.empty(count.value, dtype=TNODE_DTYPE)
    if count.value:
        lib.weft_find_t_nodes(handle, tolerance, nodes.ctypes.data, nodes.size, ctypes.byref(count))
    return nodes


def repair_t_nodes(mesh, tolerance=DEFAULT_WELD_TOLERANCE, report=False):
    """Inserts each T-node into the edge it lies on (the face becomes an
    n-gon), so both sides share the seam. With ``report=True`` returns
    ``(mesh, inserted)``::

        >>> coarse, fine = weft.plane_grid(2, 2), weft.plane_grid(2, 2, 2, 2)
        >>> m, _ = weft.weld([coarse, weft.Mesh(fine.vertices + [2.0, 0, 0], fine.faces)], 1e-9)
        >>> repaired, inserted = weft.repair_t_nodes(m, 1e-6, report=True)
        >>> inserted
        1
    """
    check_mesh(mesh)  # a wrong mesh is reported before a wrong tolerance, as elsewhere
    return _counted_mesh_op(lib.weft_repair_t_nodes, mesh, report, _number(tolerance, "tolerance"))


def cull_adjacent(mesh, report=False):
    """Removes every face that has a twin with the same vertices (either
    orientation, any start): all copies go, as the walls inside joined and
    welded boxes. Weld first. With ``report=True`` returns ``(mesh, removed)``::

        >>> w, _ = weft.weld([weft.box(), weft.Mesh(weft.box().vertices + [1.0, 0, 0], weft.box().faces)])
        >>> culled, removed = weft.cull_adjacent(w, report=True)
        >>> removed
        2
    """
    return _counted_mesh_op(lib.weft_cull_adjacent, mesh, report)


def unify(mesh, report=False):
    """Gives every connected piece one consistent winding, flipping the
    fewest faces, and turns closed pieces to face outward. With
    ``report=True`` returns ``(mesh, flipped)``::

        >>> box = weft.box()
        >>> one_flipped = weft.Mesh(box.vertices, [box.faces[0][::-1]] + box.faces[1:])
        >>> oriented, flipped = weft.unify(one_flipped, report=True)
        >>> flipped
        1
    """
    return _counted_mesh_op(lib.weft_unify_orientation, mesh, report)


unify_orientation = unify


def orient_outward(mesh):
    """As :func:`unify`, reporting the pieces: returns ``(mesh, report)``
    with an :class:`OrientReport` (faces flipped, pieces, closed pieces
    turned outward, open pieces, pieces that cannot be oriented). Weld the
    triangles of an STL first, or every triangle is a piece of its own::

        >>> box = weft.box()
        >>> oriented, report = weft.orient_outward(weft.flip(box))
        >>> report.turned_outward, report.open_pieces
        (1, 0)
    """
    report = WeftOrientReport()
    out = _out()
    lib.weft_orient_outward(check_mesh(mesh), ctypes.byref(out), ctypes.byref(report))
    return take_mesh(out), OrientReport(*(getattr(report, name) for name, _ in WeftOrientReport._fields_))


def flip(mesh):
    """Reverses every face, keeping its first corner first
    ({a, b, c, d} becomes {a, d, c, b})::

        >>> m = weft.box()
        >>> weft.flip(weft.flip(m)) == m
        True
    """
    return _mesh_op(lib.weft_flip, mesh)


def _mesh_doubles(function, mesh, count, width=None):
    """Calls an export of the form f(mesh, double *out, size_t len) that writes
    ``width`` doubles (one when None) for each of the mesh's ``count``
    (``"face_count"`` or ``"vertex_count"``) into a new array."""
    handle = check_mesh(mesh)
    rows = getattr(mesh, count)
    out = np.empty(rows if width is None else (rows, width), dtype=np.float64)
    function(handle, _arrays.address(out), out.size)
    return out


def face_normals(mesh):
    """The unit normal of each face (Newell's method): an (f, 3) array::

        >>> weft.face_normals(weft.box()).shape
        (6, 3)
    """
    return _mesh_doubles(lib.weft_face_normals, mesh, "face_count", 3)


def vertex_normals(mesh):
    """The angle-weighted unit normal of each vertex: an (n, 3) array::

        >>> weft.vertex_normals(weft.box()).shape
        (8, 3)
    """
    return _mesh_doubles(lib.weft_vertex_normals, mesh, "vertex_count", 3)


def planarity(mesh):
    """Per face, the largest distance of its corners from its best-fit
    plane (0 for triangles): an (f,) array; planar within ``t`` where ``<= t``::

        >>> float(weft.planarity(weft.box()).max())
        0.0
    """
    return _mesh_doubles(lib.weft_planarity, mesh, "face_count")


def naked_boundaries(mesh):
    """The naked edges chained into polylines: a list of ``(points, closed)``,
    points an (k, 3) array (a closed polyline does not repeat its start)::

        >>> [(len(p), closed) for p, closed in weft.naked_boundaries(weft.plane_grid(1, 1, 2, 2))]
        [(8, True)]
    """
    handle = check_mesh(mesh)
    total, lines = ctypes.c_size_t(), ctypes.c_size_t()
    lib.weft_naked_boundaries(handle, None, 0, None, None, 0, ctypes.byref(total), ctypes.byref(lines))
    points = np.empty((total.value, 3), dtype=np.float64)
    counts = np.empty(lines.value, dtype=np.uintp)
    closed = np.empty(lines.value, dtype=np.bool_)
    if lines.value:
        lib.weft_naked_boundaries(
            handle, _arrays.address(points), points.size, _arrays.address(counts), _arrays.address(closed), lines.value,
            ctypes.byref(total), ctypes.byref(lines),
        )
    ends = np.cumsum(counts)[:-1].astype(np.int64)
    return list(zip(np.split(points, ends), closed.tolist())) if lines.value else []


# Making --------------------------------------------------------------------

def delaunay(points, plane=None):
    """Triangulates points by the Delaunay criterion of their projections
    onto ``plane`` (None: world XY; else ``(origin, x_axis, y_axis)``); the
    vertices are the distinct input points in order (points whose
    projections coincide are merged, so ``len(points) - mesh.vertex_count``
    were merged)::

        >>> tri = weft.delaunay(np.random.rand(100, 3))
    """
    positions = _arrays.float_array(points, "points", width=3)
    out = _out()
    merged = ctypes.c_size_t()
    lib.weft_delaunay(_arrays.address(positions), positions.shape[0], _plane(plane), ctypes.byref(out), ctypes.byref(merged))
    return take_mesh(out)


class Cells:
    """Voronoi cells from :func:`voronoi`: one polygon per input point,
    empty for a point outside the boundary or repeating an earlier one.
    ``sizes`` holds each cell's corner count and ``corners`` all corners, a
    (k, 3) array (read-only views on the library's buffers); ``cells[i]``
    is cell i's (size, 3) array; :meth:`to_mesh` makes one n-gon per cell."""

    def __init__(self, handle):
        self._handle = handle
        self._finalizer = weakref.finalize(self, lib.weft_cells_free, handle)

    def __len__(self):
        return lib.weft_cells_count(self._handle)

    @property
    def sizes(self):
        return _arrays.view(lib.weft_cells_sizes(self._handle), len(self), ctypes.c_uint32, np.uint32, self)

    @property
    def corners(self):
        n = lib.weft_cells_corner_count(self._handle)
        return _arrays.view(lib.weft_cells_corners(self._handle), 3 * n, ctypes.c_double, np.float64, self, (n, 3))

    def __getitem__(self, index):
        sizes = self.sizes
        index = range(len(sizes))[index]
        start = int(sizes[:index].sum())
        return self.corners[start : start + int(sizes[index])]

    def copy_arrays(self):
        """(sizes, corners) as new writable arrays, filled by ``weft_cells_copy``."""
        sizes = np.empty(len(self), dtype=np.uint32)
        corners = np.empty((lib.weft_cells_corner_count(self._handle), 3), dtype=np.float64)
        lib.weft_cells_copy(self._handle, _arrays.address(sizes), sizes.size, _arrays.address(corners), corners.size)
        return sizes, corners

    def to_mesh(self):
        """One n-gon face per non-empty cell, in cell order; the cells share
        no vertices (:func:`weld` joins them)."""
        out = _out()
        lib.weft_cells_to_mesh(self._handle, ctypes.byref(out))
        return take_mesh(out)

    def __repr__(self):
        return f"weft.Cells({len(self)} cells)"


def voronoi(points, boundary=None, radius=0.0, plane=None):
    """The Voronoi cell of each point on ``plane`` (None: world XY), clipped
    to ``boundary`` (an (m, 3) polygon; None: the points' bounding rectangle
    grown by 10 %) and, when ``radius`` > 0, to a circle of that radius::

        >>> cells = weft.voronoi(np.random.rand(50, 3), radius=0.2)
        >>> skin = weft.weld(cells.to_mesh())[0]
    """
    positions = _arrays.float_array(points, "points", width=3)
    corners = None if boundary is None else _arrays.float_array(boundary, "boundary", width=3)
    out = _out()
    lib.weft_voronoi(
        _arrays.address(positions), positions.shape[0], _plane(plane), _arrays.address(corners),
        0 if corners is None else corners.shape[0], _number(radius, "radius"), ctypes.byref(out),
    )
    return Cells(out.value)


def mesh_from_grid(points, u_count=None, v_count=None, closed_u=False, closed_v=False, triangulate=False):
    """Connects a grid of points (a sampled surface) into quads (or
    triangles): ``points`` is a (v, u, 3) array, or (n, 3) with ``u_count``
    and ``v_count`` (u runs fastest)::

        >>> grid = weft.mesh_from_grid(np.random.rand(4, 5, 3))
    """
    array = _arrays._as_numeric(points, "points")
    if array.ndim == 3:
        if u_count is None and v_count is None:
            v_count, u_count = array.shape[:2]
        array = array.reshape(-1, array.shape[-1])
    positions = _arrays.float_array(array, "points", width=3)
    if u_count is None or v_count is None:
        raise ValueError("u_count and v_count are needed when points is an (n, 3) array")
    out = _out()
    lib.weft_mesh_from_grid(
        _arrays.address(positions), positions.shape[0], _size(u_count, "u_count"), _size(v_count, "v_count"),
        bool(closed_u), bool(closed_v), bool(triangulate), ctypes.byref(out),
    )
    return take_mesh(out)


def _per_face(values, name):
    array = np.atleast_1d(_arrays._as_numeric(values, name))
    return _arrays.float_array(array.reshape(-1) if array.ndim <= 1 else array, name)


def stellate(mesh, heights):
    """Raises a pyramid on every face: an apex at the centroid moved along
    the normal by the face's height (one number, or one per face)::

        >>> spiky = weft.stellate(weft.box(1, 1, 1), 0.3)
    """
    values = _per_face(heights, "heights")
    return _mesh_op(lib.weft_stellate, mesh, _arrays.address(values), values.size)


def plane_grid(size_x=1.0, size_y=1.0, u_count=1, v_count=1):
    """A flat rectangle on the XY plane, centred on the origin, facing +z, of u × v quads::

        >>> weft.plane_grid(2, 1, 4, 2).face_count
        8
    """
    out = _out()
    lib.weft_plane_grid(_number(size_x, "size_x"), _number(size_y, "size_y"), _size(u_count, "u_count"), _size(v_count, "v_count"), ctypes.byref(out))
    return take_mesh(out)


def box(size_x=1.0, size_y=1.0, size_z=1.0, u_count=1, v_count=1, w_count=1):
    """A closed, welded box centred on the origin, its sides divided into quads::

        >>> weft.box(1, 1, 1).face_count
        6
    """
    out = _out()
    lib.weft_box(
        _number(size_x, "size_x"), _number(size_y, "size_y"), _number(size_z, "size_z"),
        _size(u_count, "u_count"), _size(v_count, "v_count"), _size(w_count, "w_count"), ctypes.byref(out),
    )
    return take_mesh(out)


def uv_sphere(radius=1.0, u_count=16, v_count=8):
    """A sphere centred on the origin: quads, and a fan of triangles at each pole::

        >>> weft.uv_sphere(1.0, 8, 4).face_count
        32
    """
    out = _out()
    lib.weft_uv_sphere(_number(radius, "radius"), _size(u_count, "u_count"), _size(v_count, "v_count"), ctypes.byref(out))
    return take_mesh(out)


def platonic(kind, radius=1.0):
    """A platonic solid (``"tetrahedron"``, ``"hexahedron"``, ``"octahedron"``,
    ``"dodecahedron"`` or ``"icosahedron"``) with its vertices on the sphere of ``radius``::

        >>> weft.platonic("icosahedron").face_count
        20
    """
    out = _out()
    lib.weft_platonic(_choice(kind, "kind", PLATONIC), _number(radius, "radius"), ctypes.byref(out))
    return take_mesh(out)


def sided_solid(kind, sides, radius=1.0, height=1.0):
    """A ``"prism"``, ``"antiprism"``, ``"pyramid"`` or ``"dipyramid"`` on a regular n-gon::

        >>> weft.sided_solid("prism", 6).face_count
        8
    """
    out = _out()
    lib.weft_sided_solid(_choice(kind, "kind", SIDED), _size(sides, "sides"), _number(radius, "radius"), _number(height, "height"), ctypes.byref(out))
    return take_mesh(out)


def mesh_from_lines(segments, tolerance=DEFAULT_WELD_TOLERANCE, max_valence=4):
    """The faces a set of line segments encloses: ``segments`` is an (s, 2, 3)
    or (s, 6) array; endpoints within ``tolerance`` weld, faces of up to
    ``max_valence`` corners are kept::

        >>> weft.mesh_from_lines([[(0, 0, 0), (1, 0, 0)], [(1, 0, 0), (1, 1, 0)], [(1, 1, 0), (0, 0, 0)]]).face_count
        1
    """
    flat = _segments(segments, "segments", "s")
    out = _out()
    lib.weft_mesh_from_lines(_arrays.address(flat), flat.shape[0], _number(tolerance, "tolerance"), _count(max_valence, "max_valence"), ctypes.byref(out))
    return take_mesh(out)


# The toolbar ---------------------------------------------------------------

def triangulate(mesh, parent_faces=False):
    """Splits quads along the shorter diagonal and ear-clips n-gons; vertices
    are kept. With ``parent_faces=True`` returns ``(mesh, parents)``, the
    face each triangle was cut from (a uint32 array)::

        >>> weft.triangulate(weft.box()).face_count
        12
        >>> weft.triangulate(weft.box(), parent_faces=True)[1][:4]
        array([0, 0, 1, 1], dtype=uint32)
    """
    if not parent_faces:
        return _mesh_op(lib.weft_triangulate, mesh)
    handle = check_mesh(mesh)
    parents = np.empty(int((mesh.face_sizes.astype(np.int64) - 2).sum()), dtype=np.uint32)
    out = _out()
    lib.weft_triangulate_ex(handle, ctypes.byref(out), _arrays.address(parents))
    return take_mesh(out), parents


def as_triangles(mesh, report=False):
    """The mesh as triangles, as Loop and Split Triangles need it: the same
    mesh when every face is a triangle, else its triangulation. With
    ``report=True`` returns ``(mesh, split_faces)``, the number of faces
    that were not triangles::

        >>> weft.as_triangles(weft.box(), report=True)[1]
        6
    """
    return _counted_mesh_op(lib.weft_as_triangles, mesh, report)


def match_points_to_vertices(mesh, points, tolerance):
    """The nearest vertex within ``tolerance`` of each point (an (n, 3)
    array-like): a uint32 array. A point with no vertex in reach raises
    :class:`WeftError` naming it::

        >>> weft.match_points_to_vertices(weft.box(), [(0.5, 0.5, 0.5)], 1e-6)
        array([6], dtype=uint32)
    """
    handle = check_mesh(mesh)
    flat = _arrays.float_array(points, "points", width=3)
    out = np.empty(flat.shape[0], dtype=np.uint32)
    lib.weft_match_points_to_vertices(handle, flat.shape[0], _arrays.address(flat), _number(tolerance, "tolerance"), _arrays.address(out))
    return out


def match_lines_to_edges(mesh, lines, tolerance):
    """The edge of the mesh each line (two end points, an (l, 6) or
    (l, 2, 3) array-like) lies on, within ``tolerance`` at both ends: an
    (l, 2) uint32 array of vertex pairs in the lines' direction::

        >>> weft.match_lines_to_edges(weft.box(), [[(-0.5, -0.5, -0.5), (0.5, -0.5, -0.5)]], 1e-6)
        array([[0, 4]], dtype=uint32)
    """
    handle = check_mesh(mesh)
    flat = _segments(lines, "lines", "l")
    out = np.empty((flat.shape[0], 2), dtype=np.uint32)
    lib.weft_match_lines_to_edges(handle, flat.shape[0], _arrays.address(flat), _number(tolerance, "tolerance"), _arrays.address(out))
    return out


def _levels_operation(export, summary, example, faces):
    """The wrapper of one of the exports that take a mesh and a level count and
    make a mesh, named after it; its doctest subdivides ``example`` once and
    expects ``faces`` faces (all these exports share one signature, as
    Toolbar.Levels does in the C# wrapper)."""
    name = export.__name__[len("weft_"):]

    def operation(mesh, levels=1):
        return _mesh_op(export, mesh, _count(levels, "levels"))

    operation.__name__ = operation.__qualname__ = name
    operation.__doc__ = f"{summary}::\n\n    >>> weft.{name}({example}, 1).face_count\n    {faces}\n"
    return operation


split_polygons = _levels_operation(lib.weft_split_polygons, "Splits each n-gon into n quads through its edge midpoints and centroid, without smoothing", "weft.box()", 24)
split_triangles = _levels_operation(lib.weft_split_triangles, "Splits each triangle into four through its edge midpoints, without smoothing", 'weft.platonic("octahedron")', 32)
constant_quads_split = _levels_operation(lib.weft_constant_quads_split, "Splits quads into 4 quads, triangles into 4 triangles, n-gons into quads, without smoothing", "weft.box()", 24)
midedge = _levels_operation(lib.weft_midedge, "The mid-edge subdivision (Peters and Reif)", "weft.box()", 14)
sierpinski_triangles = _levels_operation(lib.weft_sierpinski_triangles, "A triangle in each corner of each face, the middle left open", 'weft.platonic("tetrahedron")', 12)
sierpinski_carpet = _levels_operation(lib.weft_sierpinski_carpet, "Cuts each quad into 3 × 3 and removes the middle one", "weft.box()", 48)


def inner_polygons(mesh, levels=1, pull=0.5):
    """Gives each face an inner face pulled towards its centroid, joined by quads::

        >>> weft.inner_polygons(weft.box(), 1, 0.3).face_count
        30
    """
    return _mesh_op(lib.weft_inner_polygons, mesh, _count(levels, "levels"), _number(pull, "pull"))


def laplacian_smooth(mesh, iterations=1, blend=0.5, naked_edges="fixed"):
    """Moves every vertex ``blend`` of the way to its neighbours' average, ``iterations`` times::

        >>> weft.laplacian_smooth(weft.uv_sphere(), iterations=5, blend=0.5).vertex_count
        114
    """
    return _mesh_op(
        lib.weft_laplacian_smooth, mesh, _count(iterations, "iterations"), _number(blend, "blend"),
        _choice(naked_edges, "naked_edges", NAKED_EDGES),
    )


def laplacian_hc_smooth(mesh, iterations=1, alpha=0.0, beta=0.6, naked_edges="fixed", direction="free", activation=None):
    """Volume-preserving Laplacian smoothing (HC, Vollmer, Mann and Müller
    1999). ``direction`` is ``"free"``, ``"along-normal"`` or
    ``"tangential"``; ``activation`` one weight in [0, 1] per vertex (None:
    all 1)::

        >>> weft.laplacian_hc_smooth(weft.uv_sphere(), iterations=10, beta=0.6).vertex_count
        114
    """
    arguments = (_count(iterations, "iterations"), _number(alpha, "alpha"), _number(beta, "beta"), _choice(naked_edges, "naked_edges", NAKED_EDGES))
    direction = _choice(direction, "direction", SMOOTH_DIRECTION)
    if activation is None and direction == 0:
        return _mesh_op(lib.weft_laplacian_hc_smooth, mesh, *arguments)
    weights = None if activation is None else _arrays.float_array(activation, "activation")
    return _mesh_op(
        lib.weft_laplacian_hc_smooth_ex, mesh, *arguments, direction, _arrays.address(weights), 0 if weights is None else weights.size
    )


def blur_values(mesh, values, iterations=1, blend=0.5, naked_edges="fixed"):
    """Blurs per-vertex values (an (n,) or (n, components) array) over the
    mesh; returns them in the same shape::

        >>> weft.blur_values(weft.box(), np.arange(8.0), iterations=2).shape
        (8,)
    """
    array, components = _table(values, "values")
    out = np.empty_like(array)
    lib.weft_blur_values(
        check_mesh(mesh), _arrays.address(array), array.size, components, _count(iterations, "iterations"), _number(blend, "blend"),
        _choice(naked_edges, "naked_edges", NAKED_EDGES), _arrays.address(out), out.size,
    )
    return out


def offset_mesh(mesh, distance, offset_type="diagonal"):
    """Moves every vertex ``distance`` along the normal (``offset_type``:
    ``"diagonal"``, ``"hypotenuse-average"``, ``"planes-intersection"``)::

        >>> weft.offset_mesh(weft.box(), 0.1).vertex_count
        8
    """
    return _mesh_op(lib.weft_offset_mesh, mesh, _number(distance, "distance"), _choice(offset_type, "offset_type", OFFSET))


def thicken_mesh(mesh, distance, offset_type="diagonal"):
    """A solid of a surface: it, its offset by ``distance``, and quads along the naked edges::

        >>> weft.thicken_mesh(weft.plane_grid(), 0.1).face_count
        6
    """
    return _mesh_op(lib.weft_thicken_mesh, mesh, _number(distance, "distance"), _choice(offset_type, "offset_type", OFFSET))


def mesh_window(mesh, distances, inset_mode="edge-fraction"):
    """Insets each face, keeping the frame of quads and the inner face
    (``distances``: one, or one per face; ``inset_mode``:
    ``"edge-fraction"`` or ``"parallelogram"``)::

        >>> weft.mesh_window(weft.box(), 0.2).face_count
        30
    """
    values = _per_face(distances, "distances")
    return _mesh_op(lib.weft_mesh_window, mesh, _arrays.address(values), values.size, _choice(inset_mode, "inset_mode", INSET))


def picture_frame(mesh, distances, inset_mode="edge-fraction"):
    """Insets each face and keeps only the frame: each face becomes a ring::

        >>> weft.picture_frame(weft.box(), 0.2).face_count
        24
    """
    values = _per_face(distances, "distances")
    return _mesh_op(lib.weft_picture_frame, mesh, _arrays.address(values), values.size, _choice(inset_mode, "inset_mode", INSET))


def bevel_edges(mesh, fraction=0.2):
    """Bevels every edge (Conway's expansion), ``fraction`` in (0, 1)::

        >>> weft.bevel_edges(weft.box(), 0.3).face_count
        26
    """
    return _mesh_op(lib.weft_bevel_edges, mesh, _number(fraction, "fraction"))


def bevel_vertices(mesh, fraction=0.2):
    """Cuts every vertex off (Conway's truncation), ``fraction`` in (0, 0.5)::

        >>> weft.bevel_vertices(weft.box(), 0.3).face_count
        14
    """
    return _mesh_op(lib.weft_bevel_vertices, mesh, _number(fraction, "fraction"))


def dual(mesh, mode="vertex-average"):
    """The dual mesh: a vertex per face, a face per interior vertex
    (``mode``: ``"vertex-average"`` or ``"keep-size"``)::

        >>> weft.dual(weft.box()).face_count
        8
    """
    return _mesh_op(lib.weft_dual, mesh, _choice(mode, "mode", DUAL))


def edges(mesh):
    """The unique edges as sorted (low, high) vertex pairs: an (e, 2) uint32 array::

        >>> weft.edges(weft.box()).shape
        (12, 2)
    """
    handle = check_mesh(mesh)
    count = ctypes.c_size_t()
    lib.weft_mesh_edge_count(handle, ctypes.byref(count))
    out = np.empty((count.value, 2), dtype=np.uint32)
    lib.weft_mesh_copy_edges(handle, _arrays.address(out), out.size)
    return out


def edge_segments(mesh):
    """The unique edges as line segments, in the order of :func:`edges`: an (e, 2, 3) array::

        >>> weft.edge_segments(weft.box()).shape
        (12, 2, 3)
    """
    handle = check_mesh(mesh)
    count = ctypes.c_size_t()
    lib.weft_mesh_edge_count(handle, ctypes.byref(count))
    out = np.empty((count.value, 2, 3), dtype=np.float64)
    lib.weft_mesh_copy_edge_segments(handle, _arrays.address(out), out.size)
    return out


def reroute_faces(mesh, shift=1):
    """Rotates every face's corner list to start ``shift`` corners later (negative goes back)::

        >>> weft.reroute_faces(weft.Mesh([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]]), 1).faces
        [[1, 2, 0]]
    """
    if isinstance(shift, bool) or not isinstance(shift, (int, np.integer)):
        raise TypeError(f"shift must be an integer, not {type(shift).__name__}")
    if not -(2**63) <= shift < 2**63:
        raise ValueError(f"shift is {shift}; it must fit 64 bits")
    return _mesh_op(lib.weft_reroute_faces, mesh, int(shift))


def tile(mesh, fill="best", faces="all"):
    """Re-fills the chosen faces by a pattern (``fill``: ``"skip"``,
    ``"best"``, ``"triangle-fan"``, ``"triangle-hand"``, ``"triangle-knit"``,
    ``"triangle-zigzag"``, ``"quad-stitch"``, ``"quad-fan"``; ``faces``:
    ``"all"``, ``"quads-and-more"``, ``"pentagons-and-more"``,
    ``"triangles"``, ``"quads"``)::

        >>> weft.tile(weft.box(), "triangle-fan", "quads").face_count
        24
    """
    return _mesh_op(lib.weft_tile, mesh, _choice(fill, "fill", TILE_FILL), _choice(faces, "faces", TILE_FACES))


def version():
    """The library's version, such as ``"0.1.0"``::

        >>> weft.version()
        '0.1.0'
    """
    return lib.weft_version().decode()

