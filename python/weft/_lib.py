"""Loading libweft and declaring its C functions for ctypes.

Every function of ``include/weft.h`` has one line in ``_SIGNATURES``; a
function that returns a ``WeftStatus`` raises :class:`WeftError` on
failure by itself (its ``errcheck``), so wrappers never test statuses.

ctypes releases the GIL for the length of every foreign call, so other
Python threads run while Weft subdivides.
"""

import ctypes
import os
import sys
from ctypes import POINTER, Structure, c_bool, c_char_p, c_double, c_int64, c_size_t, c_uint32, c_void_p
from pathlib import Path

__all__ = ["WeftError", "lib", "Status"]


class Status:
    """The ``WEFT_STATUS_*`` values of ``include/weft.h``."""

    OK = 0
    NULL_POINTER = 1
    INVALID_ARGUMENT = 2
    INDEX_OUT_OF_RANGE = 3
    FACE_TOO_SMALL = 4
    REPEATED_INDEX = 5
    NON_FINITE_COORDINATE = 6
    COUNT_MISMATCH = 7
    INPUT_TOO_LARGE = 8
    NOT_TRIANGLES = 9
    RESULT_TOO_LARGE = 10
    OUT_OF_MEMORY = 11
    BUFFER_TOO_SMALL = 12
    DEGENERATE_INPUT = 13
    INTERNAL_PANIC = 14

    @classmethod
    def name_of(cls, status):
        for name, value in vars(cls).items():
            if value == status and name.isupper():
                return name
        return "UNKNOWN_STATUS"


class WeftError(Exception):
    """A call into Weft failed.

    ``status`` is the library's ``WEFT_STATUS_*`` value (see :class:`weft.Status`),
    ``status_name`` its name, ``message`` the library's sentence, which names
    the face, vertex or argument at fault::

        >>> try:
        ...     weft.Mesh([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 5]])
        ... except weft.WeftError as error:
        ...     print(error.status_name)
        INDEX_OUT_OF_RANGE
    """

    def __init__(self, status, message):
        self.status = int(status)
        self.status_name = Status.name_of(self.status)
        self.message = message
        super().__init__(f"{message} ({self.status_name})")

    def __reduce__(self):
        return (WeftError, (self.status, self.message))


class WeftSubdivisionOptions(Structure):
    _fields_ = [
        ("scheme", c_uint32),
        ("naked_edges", c_uint32),
        ("creasing", c_uint32),
        ("crease_count", c_size_t),
        ("crease_vertex_pairs", c_void_p),
        ("crease_sharpness", c_void_p),
        ("corner_count", c_size_t),
        ("corner_vertices", c_void_p),
        ("corner_sharpness", c_void_p),
        ("hole_count", c_size_t),
        ("hole_faces", c_void_p),
        ("triangles", c_uint32),
        ("reserved_flags", c_uint32),
        ("reserved", c_size_t * 8),
    ]


class WeftPlane(Structure):
    _fields_ = [("origin", c_double * 3), ("x_axis", c_double * 3), ("y_axis", c_double * 3)]


class WeftWeldReport(Structure):
    _fields_ = [
        ("merged_vertex_count", c_size_t),
        ("removed_face_count", c_size_t),
        ("unused_vertex_count", c_size_t),
    ]


class WeftOrientReport(Structure):
    _fields_ = [
        ("flipped_faces", c_size_t),
        ("pieces", c_size_t),
        ("turned_outward", c_size_t),
        ("open_pieces", c_size_t),
        ("non_orientable_pieces", c_size_t),
    ]


class WeftMeshInfo(Structure):
    _fields_ = [
        ("vertex_count", c_size_t),
        ("edge_count", c_size_t),
        ("face_count", c_size_t),
        ("naked_edge_count", c_size_t),
        ("non_manifold_edge_count", c_size_t),
        ("non_manifold_vertex_count", c_size_t),
        ("component_count", c_size_t),
        ("is_closed", c_bool),
        ("is_orientable", c_bool),
        ("is_oriented", c_bool),
    ]


# Short names for the signature table. Buffers and handles cross as
# c_void_p: numpy arrays pass their address (``array.ctypes.data``), which
# costs no conversion per element.
S = c_uint32  # WeftStatus, checked by _check_status
P = c_void_p  # a buffer or a handle
OUT = POINTER(c_void_p)  # WeftMesh ** and other handle out-parameters
Z, ZP = c_size_t, POINTER(c_size_t)
U, D, B, I64 = c_uint32, c_double, c_bool, c_int64
OPTIONS = POINTER(WeftSubdivisionOptions)
PLANE = POINTER(WeftPlane)

# name: (return type, argument types), in the order of include/weft.h.
_SIGNATURES = {
    "weft_subdivide_ex": (S, [P, OPTIONS, U, OUT]),
    "weft_subdivision_counts": (S, [P, U, U, ZP, ZP, ZP]),
    "weft_subdivision_counts_ex": (S, [P, OPTIONS, U, ZP, ZP, ZP]),
    "weft_subdivision_parent_faces_ex": (S, [P, OPTIONS, U, P, Z]),
    "weft_subdivide_vertex_data": (S, [P, OPTIONS, U, P, Z, Z, P, Z]),
    "weft_subdivide_face_varying": (S, [P, OPTIONS, U, U, P, Z, Z, P, Z, P, Z]),
    "weft_subdivide_limit": (S, [P, OPTIONS, U, P, P, Z]),
    "weft_refiner_new_ex": (S, [P, OPTIONS, U, OUT]),
    "weft_limit_surface_new": (S, [P, OPTIONS, OUT]),
    "weft_limit_surface_evaluate": (S, [P, Z, P, P, P, P, P]),
    "weft_limit_surface_closest_point": (S, [P, Z, P, P, P, P]),
    "weft_limit_surface_free": (None, [P]),
    "weft_crease_edges_from_mesh": (S, [P, D, OUT, P, Z, ZP]),
    "weft_crease_edges_from_mesh_ex": (S, [P, D, OUT, P, Z, ZP, P, Z]),
    "weft_limit_patches": (S, [P, OPTIONS, U, P, P, P, Z, ZP, POINTER(D), ZP]),
    "weft_limit_surface_patches": (S, [P, U, P, P, P, Z, ZP, POINTER(D), ZP]),
    "weft_read_mesh_file": (S, [c_char_p, OUT]),
    "weft_write_mesh_file": (S, [P, c_char_p]),
    "weft_delaunay": (S, [P, Z, PLANE, OUT, ZP]),
    "weft_voronoi": (S, [P, Z, PLANE, P, Z, D, OUT]),
    "weft_cells_count": (Z, [P]),
    "weft_cells_corner_count": (Z, [P]),
    "weft_cells_sizes": (P, [P]),
    "weft_cells_corners": (P, [P]),
    "weft_cells_copy": (S, [P, P, Z, P, Z]),
    "weft_cells_to_mesh": (S, [P, OUT]),
    "weft_cells_free": (None, [P]),
    "weft_mesh_from_grid": (S, [P, Z, Z, Z, B, B, B, OUT]),
    "weft_stellate": (S, [P, P, Z, OUT]),
    "weft_plane_grid": (S, [D, D, Z, Z, OUT]),
    "weft_box": (S, [D, D, D, Z, Z, Z, OUT]),
    "weft_uv_sphere": (S, [D, Z, Z, OUT]),
    "weft_platonic": (S, [U, D, OUT]),
    "weft_sided_solid": (S, [U, Z, D, D, OUT]),
    "weft_match_points_to_vertices": (S, [P, Z, P, D, P]),
    "weft_match_lines_to_edges": (S, [P, Z, P, D, P]),
    "weft_join": (S, [P, Z, OUT]),
    "weft_mesh_unused_vertex_count": (Z, [P]),
    "weft_remove_unused_vertices": (S, [P, OUT, ZP]),
    "weft_weld_relative_tolerance": (S, [P, POINTER(D)]),
    "weft_weld": (S, [P, D, OUT, POINTER(WeftWeldReport)]),
    "weft_find_t_nodes": (S, [P, D, P, Z, ZP]),
    "weft_repair_t_nodes": (S, [P, D, OUT, ZP]),
    "weft_cull_adjacent": (S, [P, OUT, ZP]),
    "weft_unify_orientation": (S, [P, OUT, ZP]),
    "weft_orient_outward": (S, [P, OUT, POINTER(WeftOrientReport)]),
    "weft_flip": (S, [P, OUT]),
    "weft_face_normals": (S, [P, P, Z]),
    "weft_vertex_normals": (S, [P, P, Z]),
    "weft_planarity": (S, [P, P, Z]),
    "weft_naked_boundaries": (S, [P, P, Z, P, P, Z, ZP, ZP]),
    "weft_version": (c_char_p, []),
    "weft_last_error_message": (c_char_p, []),
    "weft_mesh_new": (S, [P, Z, P, Z, P, Z, OUT]),
    "weft_mesh_new_ex": (S, [P, Z, P, Z, P, Z, U, OUT]),
    "weft_mesh_new_borrowed": (S, [P, Z, P, Z, P, Z, U, OUT]),
    "weft_mesh_is_borrowed": (B, [P]),
    "weft_mesh_free": (None, [P]),
    "weft_mesh_vertex_count": (Z, [P]),
    "weft_mesh_face_count": (Z, [P]),
    "weft_mesh_index_count": (Z, [P]),
    "weft_mesh_positions": (P, [P]),
    "weft_mesh_face_sizes": (P, [P]),
    "weft_mesh_face_indices": (P, [P]),
    "weft_mesh_copy_positions": (S, [P, P, Z]),
    "weft_mesh_copy_faces": (S, [P, P, Z, P, Z]),
    "weft_mesh_info": (S, [P, POINTER(WeftMeshInfo)]),
    "weft_refiner_new": (S, [P, U, U, U, OUT]),
    "weft_refiner_evaluate": (S, [P, P, Z, P, Z]),
    "weft_refiner_mesh": (S, [P, OUT]),
    "weft_refiner_vertex_count": (Z, [P]),
    "weft_refiner_face_count": (Z, [P]),
    "weft_refiner_free": (None, [P]),
    "weft_catmull_clark": (S, [P, U, U, OUT]),
    "weft_loop": (S, [P, U, U, OUT]),
    "weft_subdivide_into": (S, [P, U, U, U, P, Z, P, Z]),
    "weft_subdivision_face_count": (S, [P, U, U, ZP]),
    "weft_subdivision_parent_faces": (S, [P, U, U, P, Z]),
    "weft_triangulate": (S, [P, OUT]),
    "weft_triangulate_ex": (S, [P, OUT, P]),
    "weft_as_triangles": (S, [P, OUT, ZP]),
    "weft_split_polygons": (S, [P, U, OUT]),
    "weft_split_triangles": (S, [P, U, OUT]),
    "weft_constant_quads_split": (S, [P, U, OUT]),
    "weft_midedge": (S, [P, U, OUT]),
    "weft_inner_polygons": (S, [P, U, D, OUT]),
    "weft_sierpinski_triangles": (S, [P, U, OUT]),
    "weft_laplacian_smooth": (S, [P, U, D, U, OUT]),
    "weft_laplacian_hc_smooth": (S, [P, U, D, D, U, OUT]),
    "weft_laplacian_hc_smooth_ex": (S, [P, U, D, D, U, U, P, Z, OUT]),
    "weft_blur_values": (S, [P, P, Z, Z, U, D, U, P, Z]),
    "weft_offset_mesh": (S, [P, D, U, OUT]),
    "weft_thicken_mesh": (S, [P, D, U, OUT]),
    "weft_mesh_window": (S, [P, P, Z, U, OUT]),
    "weft_picture_frame": (S, [P, P, Z, U, OUT]),
    "weft_sierpinski_carpet": (S, [P, U, OUT]),
    "weft_bevel_edges": (S, [P, D, OUT]),
    "weft_bevel_vertices": (S, [P, D, OUT]),
    "weft_dual": (S, [P, U, OUT]),
    "weft_mesh_edge_count": (S, [P, ZP]),
    "weft_mesh_copy_edges": (S, [P, P, Z]),
    "weft_mesh_copy_edge_segments": (S, [P, P, Z]),
    "weft_reroute_faces": (S, [P, I64, OUT]),
    "weft_mesh_from_lines": (S, [P, Z, D, U, OUT]),
    "weft_tile": (S, [P, U, U, OUT]),
}


def _library_path():
    override = os.environ.get("WEFT_LIBRARY")
    if override:
        return Path(override)
    if sys.platform == "win32":
        name = "weft.dll"
    elif sys.platform == "darwin":
        name = "libweft.dylib"
    else:
        name = "libweft.so"
    return Path(__file__).with_name(name)


def _load():
    path = _library_path()
    try:
        library = ctypes.CDLL(str(path))
    except OSError as error:
        raise ImportError(
            f"weft: cannot load the Weft library {path} ({error}); reinstall the package "
            "(pip install ./python builds it with cargo) or point WEFT_LIBRARY at a libweft"
        ) from error
    missing = []
    for name, (restype, argtypes) in _SIGNATURES.items():
        try:
            function = getattr(library, name)
        except AttributeError:
            missing.append(name)
            continue
        function.restype = restype
        function.argtypes = argtypes
        if restype is S:
            function.errcheck = _check_status
    if missing:
        raise ImportError(
            f"weft: the library {path} lacks {', '.join(missing)}; it is older than this "
            "package: reinstall the package"
        )
    return library


def _check_status(status, function, arguments):
    if status != Status.OK:
        raw = lib.weft_last_error_message()
        message = raw.decode("utf-8", "replace") if raw else ""
        raise WeftError(status, message or f"{function.__name__} failed")
    return status


lib = _load()
