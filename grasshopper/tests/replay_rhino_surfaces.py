#!/usr/bin/env python3
"""Replays, call for call, what grasshopper/Weft.Grasshopper/RhinoSurfaces.cs
does to build a Rhino NURBS surface from one of Weft's bicubic patches, on
the openNURBS surface code that rhino3dm carries, and checks that the
surface is the patch: Bernstein-weighted control points, i along u and j
along v, over [0, 1]². The test fails when RhinoSurfaces.cs uses a member
not in REPLAYED (so the two change together).

usage: replay_rhino_surfaces.py <RhinoSurfaces.cs>   (rhino3dm importable)
Closing line: "rhino3dm surface replay: N passed, N failed".
"""
import re
import sys

import rhino3dm

from replay_checks import check, finish

# RhinoCommon member used by RhinoSurfaces -> the rhino3dm call replaying it.
REPLAYED = {
    "NurbsSurface.Create": "rhino3dm.NurbsSurface.Create(3, False, 4, 4, 4, 4)",
    "KnotsU.CreateUniformKnots": "surface.KnotsU.CreateUniformKnots(1.0) (ON_MakeClampedUniformKnotVector)",
    "KnotsV.CreateUniformKnots": "surface.KnotsV.CreateUniformKnots(1.0)",
    "Points.SetPoint": "surface.Points[i, j] = Point4d(x, y, z, 1) (ON_NurbsSurface::SetCV, non-rational)",
}



def bernstein(t):
    s = 1 - t
    return [s * s * s, 3 * t * s * s, 3 * t * t * s, t * t * t]


def from_patch(control):
    """RhinoSurfaces.FromPatch on one patch: control[i][j] = (x, y, z)."""
    surface = rhino3dm.NurbsSurface.Create(3, False, 4, 4, 4, 4)
    surface.KnotsU.CreateUniformKnots(1.0)
    surface.KnotsV.CreateUniformKnots(1.0)
    for i in range(4):
        for j in range(4):
            surface.Points[i, j] = rhino3dm.Point4d(*control[i][j], 1.0)
    return surface


def main():
    source = open(sys.argv[1], encoding="utf-8").read()
    used = set(re.findall(r"\b(NurbsSurface\.Create|Knots[UV]\.\w+|Points\.\w+)\(", source))
    unknown = sorted(used - set(REPLAYED))
    check("every surface member RhinoSurfaces.cs uses is replayed here", not unknown, ", ".join(unknown))

    # A warped patch: every control point different, none on a plane.
    control = [[(i + 0.1 * j * j, j - 0.2 * i, 0.3 * ((i * 7 + j * 3) % 5) - 0.1 * i * j) for j in range(4)] for i in range(4)]
    surface = from_patch(control)
    check("the surface is valid", surface.IsValid)
    knots = [surface.KnotsU[k] for k in range(len(surface.KnotsU))]
    check("clamped uniform knots 0, 0, 0, 1, 1, 1 (the Bézier form)", knots == [0, 0, 0, 1, 1, 1], str(knots))
    check("its domain is [0, 1] in u and v", surface.Domain(0).T0 == 0 and surface.Domain(1).T1 == 1)
    worst = 0.0
    for a in range(9):
        for b in range(9):
            u, v = a / 8, b / 8
            bu, bv = bernstein(u), bernstein(v)
            expected = [sum(bu[i] * bv[j] * control[i][j][k] for i in range(4) for j in range(4)) for k in range(3)]
            p = surface.PointAt(u, v)
            worst = max(worst, abs(p.X - expected[0]), abs(p.Y - expected[1]), abs(p.Z - expected[2]))
    check("openNURBS evaluates it as the Bézier patch, i along u and j along v", worst < 1e-12, f"{worst:.3e}")
    corner = surface.PointAt(1, 0)
    check("corner (1, 0) is control point [3][0]", (corner.X, corner.Y, corner.Z) == control[3][0], str(corner))

    return finish("rhino3dm surface replay")


if __name__ == "__main__":
    sys.exit(main())
