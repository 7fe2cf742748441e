"""Reads the STEP files `weft nurbs` wrote with OpenCASCADE (the OCP
bindings of cadquery-ocp) and checks them against Weft's limit surface:

    python check_occ.py SURFACE.step LIMIT.obj PATCHES [GRID]

SURFACE.step must load as PATCHES B-spline faces forming one shell in which
every edge has two faces (the cages here are closed); the surface of every
face, evaluated by OpenCASCADE on a GRID x GRID grid of its parameters
(default 5: steps of 1/4), must lie within 1e-9 of the cage's size of a
limit point in LIMIT.obj (`weft subdivide --limit`, levels enough that the
grid's parameters are its vertices). Prints the largest distance.
"""

import sys

import numpy as np
from OCP.BRep import BRep_Tool
from OCP.GeomAbs import GeomAbs_BSplineSurface
from OCP.GeomAdaptor import GeomAdaptor_Surface
from OCP.IFSelect import IFSelect_RetDone
from OCP.STEPControl import STEPControl_Reader
from OCP.TopAbs import TopAbs_EDGE, TopAbs_FACE
from OCP.collections import IndexedDataMap_TopoDS_Shape_List_TopoDS_Shape_TopTools_ShapeMapHasher as EdgeFaces
from OCP.TopExp import TopExp, TopExp_Explorer
from OCP.TopoDS import TopoDS


def read_limit_points(path):
    points = [line.split()[1:4] for line in open(path) if line.startswith("v ")]
    return np.array(points, dtype=float)


def main(step_path, limit_path, patch_count, grid=5):
    reader = STEPControl_Reader()
    if reader.ReadFile(step_path) != IFSelect_RetDone:
        sys.exit(f"{step_path}: OpenCASCADE could not read it")
    reader.TransferRoots()
    shape = reader.OneShape()

    faces = []
    explorer = TopExp_Explorer(shape, TopAbs_FACE)
    while explorer.More():
        faces.append(TopoDS.Face(explorer.Current()))
        explorer.Next()
    if len(faces) != patch_count:
        sys.exit(f"{step_path}: {len(faces)} faces read, {patch_count} written")

    edge_faces = EdgeFaces()
    TopExp.MapShapesAndAncestors_s(shape, TopAbs_EDGE, TopAbs_FACE, edge_faces)
    open_edges = sum(1 for k in range(1, edge_faces.Extent() + 1) if edge_faces.FindFromIndex(k).Size() != 2)
    if open_edges:
        sys.exit(f"{step_path}: {open_edges} of {edge_faces.Extent()} edges do not join two faces")

    limit = read_limit_points(limit_path)
    size = np.linalg.norm(limit.max(axis=0) - limit.min(axis=0))
    worst = 0.0
    for f, face in enumerate(faces):
        surface = BRep_Tool.Surface_s(face)
        if GeomAdaptor_Surface(surface).GetType() != GeomAbs_BSplineSurface:
            sys.exit(f"{step_path}: face {f} is not a B-spline surface")
        u0, u1, v0, v1 = surface.Bounds()
        for a in range(grid):
            for b in range(grid):
                u = u0 + (u1 - u0) * a / (grid - 1)
                v = v0 + (v1 - v0) * b / (grid - 1)
                p = surface.Value(u, v)
                distance = np.sqrt(((limit - np.array([p.X(), p.Y(), p.Z()])) ** 2).sum(axis=1)).min()
                worst = max(worst, distance)
    print(f"{step_path}: {len(faces)} B-spline faces, one closed shell; largest distance from the limit {worst:.2e} ({worst / size:.2e} of the size)")
    if worst > 1e-9 * size:
        sys.exit(f"{step_path}: a surface point lies {worst:.3e} from the limit surface")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2], int(sys.argv[3]), *(int(a) for a in sys.argv[4:]))
