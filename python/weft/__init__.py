"""Weft: subdivision surfaces (Catmull-Clark, Loop) and mesh making and
mending tools, from Python, on numpy arrays.

    >>> import weft, numpy as np
    >>> m = weft.Mesh([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], [[0, 1, 2, 3]])
    >>> s = weft.catmull_clark(m, levels=2, naked_edges="smooth")
    >>> s.vertices.shape, s.face_count
    ((25, 3), 16)

The package calls the Weft library through its C ABI (``include/weft.h``)
with ctypes: arrays cross as numpy buffers, results are read-only views on
the library's buffers, and ctypes releases the GIL during every call, so
other threads run while Weft works. Errors the library reports raise
:class:`WeftError` with its message; a wrong dtype, shape or option raises
``TypeError`` or ``ValueError`` naming the argument.

:data:`lib` is the ctypes library itself, every function of ``weft.h``
declared (argument types set, a failing status raised as WeftError), for
what the wrappers do not cover.
"""

from ._lib import Status, WeftError, lib
from ._mesh import Mesh, MeshInfo
from ._ops import (
    DEFAULT_WELD_TOLERANCE,
    SHARPNESS_INFINITE,
    TNODE_DTYPE,
    Cells,
    OrientReport,
    LimitSurface,
    Refiner,
    WeldReport,
    as_triangles,
    bevel_edges,
    bevel_vertices,
    blur_values,
    box,
    catmull_clark,
    constant_quads_split,
    crease_edges_from_mesh,
    cull_adjacent,
    delaunay,
    dual,
    edge_segments,
    edges,
    face_normals,
    find_t_nodes,
    flip,
    inner_polygons,
    join,
    laplacian_hc_smooth,
    laplacian_smooth,
    limit_patches,
    loop,
    match_lines_to_edges,
    match_points_to_vertices,
    mesh_from_grid,
    mesh_from_lines,
    mesh_window,
    midedge,
    naked_boundaries,
    orient_outward,
    offset_mesh,
    picture_frame,
    planarity,
    plane_grid,
    platonic,
    repair_t_nodes,
    remove_unused_vertices,
    reroute_faces,
    sided_solid,
    sierpinski_carpet,
    sierpinski_triangles,
    split_polygons,
    split_triangles,
    stellate,
    subdivide,
    subdivide_face_varying,
    subdivide_into,
    subdivide_limit,
    subdivide_vertex_data,
    subdivision_counts,
    subdivision_face_count,
    subdivision_parent_faces,
    thicken_mesh,
    tile,
    triangulate,
    unify,
    unify_orientation,
    unused_vertex_count,
    uv_sphere,
    version,
    vertex_normals,
    voronoi,
    weld,
    weld_relative_tolerance,
)
from ._interop import from_compas, from_rhino3dm, from_trimesh, read, to_compas, to_rhino3dm, to_trimesh, write

__version__ = "0.1.0"
