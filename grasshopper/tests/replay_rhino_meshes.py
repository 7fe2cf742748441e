#!/usr/bin/env python3
"""Replays, call for call, what grasshopper/Weft.Grasshopper/RhinoMeshes.cs
does to a Rhino mesh, on the real openNURBS mesh code that rhino3dm carries,
and checks the results. RhinoCommon and rhino3dm wrap the same ON_Mesh; where
rhino3dm names a member differently, REPLAYED says which call stands in for
which, and the test fails when RhinoMeshes.cs uses a mesh member that is not
in that table (so the two change together).

usage: replay_rhino_meshes.py <RhinoMeshes.cs>   (rhino3dm importable)
Closing line: "rhino3dm replay: N passed, N failed".
"""
import re
import sys

import rhino3dm

from replay_checks import check, finish

# RhinoCommon member used by RhinoMeshes -> the rhino3dm call replaying it.
REPLAYED = {
    "new Mesh()": "rhino3dm.Mesh()",
    "Vertices.Count": "len(mesh.Vertices)  /  mesh.Vertices.SetCount(n) (the same m_V and m_dV resize)",
    "Vertices.UseDoublePrecisionVertices": "mesh.Vertices.UseDoublePrecisionVertices",
    "Faces.Count": "mesh.Faces.Count  /  AddFace per face for the setter (rhino3dm has no setter; m_F ends the same)",
    "GetUnsafeLock": "(none: the lock hands out m_dV, m_V and m_F as pointers)",
    "ReleaseUnsafeLock": "(none)",
    "VertexPoint3dArray": "Vertices.Point3dAt / SetPoint3dAt (m_dV; only there when the flag reads True)",
    "VertexPoint3fArray": "Vertices[i] (m_V)",
    "FacesArray": "Faces[i] / Faces.SetFace (m_F, four indices, C == D for a triangle)",
    "Normals.ComputeNormals": "mesh.Normals.ComputeNormals()",
    "Normals.SetNormals": "Normals.Clear() then Normals.Add per normal",
    "VertexColors.Count": "mesh.VertexColors.Count",
    "VertexColors.ToARGBArray": "VertexColors[i] (r, g, b, a)",
    "VertexColors.SetColors": "VertexColors.Clear() then VertexColors.Add per colour",
}
# Members rhino3dm 8.35's Python bindings do not expose: not replayed here;
# the n-gon layout itself is tested on arrays (tests/ConversionTests.cs).
NOT_BOUND = {
    "Ngons.Count", "Ngons.GetNgon", "Ngons.AddNgon", "MeshNgon.Create",
    "BoundaryVertexIndexList", "FaceIndexList",
}



def from_arrays(positions, faces, count_first=True):
    """RhinoMeshes.FromArrays: counts, then the double flag, then the arrays
    through the lock, then normals when there are faces. count_first=False is
    the old order (flag on the empty mesh), kept to show the test catches it."""
    mesh = rhino3dm.Mesh()
    vertex_count, face_count = len(positions) // 3, len(faces) // 4
    if vertex_count > 0:
        if count_first:
            mesh.Vertices.SetCount(vertex_count)
            mesh.Vertices.UseDoublePrecisionVertices = True
        else:
            mesh.Vertices.UseDoublePrecisionVertices = True
            mesh.Vertices.SetCount(vertex_count)
    for f in range(face_count):  # Faces.Count = n, then FacesArray writes each face
        mesh.Faces.AddFace(*faces[4 * f:4 * f + 4])
    if vertex_count > 0 and mesh.Vertices.UseDoublePrecisionVertices:  # VertexPoint3dArray would throw otherwise
        for i in range(vertex_count):
            mesh.Vertices.SetPoint3dAt(i, rhino3dm.Point3d(*positions[3 * i:3 * i + 3]))
    if face_count > 0:
        mesh.Normals.ComputeNormals()
    return mesh


def to_arrays(mesh):
    """RhinoMeshes.ToArrays: counts, then only the arrays the mesh has."""
    vertex_count, face_count = len(mesh.Vertices), mesh.Faces.Count
    positions, faces = [], []
    if vertex_count > 0 and mesh.Vertices.UseDoublePrecisionVertices:
        for i in range(vertex_count):
            p = mesh.Vertices.Point3dAt(i)
            positions += [p.X, p.Y, p.Z]
    elif vertex_count > 0:
        for i in range(vertex_count):
            p = mesh.Vertices[i]
            positions += [p.X, p.Y, p.Z]
    for f in range(face_count):
        faces += list(mesh.Faces[f])
    return positions, faces


def member_coverage(source):
    """Every mesh member RhinoMeshes.cs touches is replayed or named as unbound."""
    used = set(re.findall(r"\bmesh\.(Vertices\.\w+|Faces\.\w+|Normals\.\w+|VertexColors\.\w+|Ngons\.\w+)", source))
    used |= set(re.findall(r"\b(GetUnsafeLock|ReleaseUnsafeLock|VertexPoint3dArray|VertexPoint3fArray|FacesArray)\(", source))
    used |= {"MeshNgon." + m for m in re.findall(r"\bMeshNgon\.(\w+)\(", source)}
    used |= set(re.findall(r"\.(BoundaryVertexIndexList|FaceIndexList)\(", source))
    if "new Mesh()" in source:
        used.add("new Mesh()")
    return sorted(used - set(REPLAYED) - NOT_BOUND), sorted(used)


def method_body(source, name):
    start = re.search(r"static[^\n(]*\b" + name + r"\(", source).start()
    end = source.find("public static", start)
    return source[start:end if end > 0 else len(source)]


def guarded(body, call, count):
    """Each call of `call` sits under an `if` that tests `count > 0` (no lock on an empty array)."""
    spots = [m.start() for m in re.finditer(re.escape(call), body)]
    return bool(spots) and all(f"{count} > 0" in body[:at].rsplit("if (", 1)[-1].split(")")[0] for at in spots)


def main():
    print(f"rhino3dm {rhino3dm.__version__} (openNURBS mesh code, module {rhino3dm.__name__})")
    source = open(sys.argv[1], encoding="utf-8").read()
    missing, used = member_coverage(source)
    check(f"every mesh member RhinoMeshes.cs uses ({len(used)}) is replayed or named as unbound",
          not missing, "not replayed: " + ", ".join(missing))

    # A triangle stored as a quad with C == D, and a quad; one vertex off the float grid.
    positions = [0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0.123456789012345]
    faces = [0, 1, 2, 2, 2, 3, 0, 1]
    # The order FromArrays really uses, read from its source.
    body = method_body(source, "FromArrays")
    count_first = body.index("Vertices.Count = ") < body.index("UseDoublePrecisionVertices = true")
    mesh = from_arrays(positions, faces, count_first)
    check("FromArrays's order keeps double-precision vertices", mesh.Vertices.UseDoublePrecisionVertices,
          "RhinoMeshes.FromArrays sets the flag before the vertex count")
    for method in ("FromArrays", "ToArrays"):
        b = method_body(source, method)
        check(f"{method} asks the lock for faces only when there are some", guarded(b, "FacesArray(", "faceCount"))
        check(f"{method} asks the lock for vertices only when there are some",
              guarded(b, "VertexPoint3dArray(", "vertexCount") and (method == "FromArrays" or guarded(b, "VertexPoint3fArray(", "vertexCount")))
    check("FromArrays computes normals only when there are faces", guarded(body, "ComputeNormals(", "faceCount"))
    old = from_arrays(positions, faces, count_first=False)
    check("flag before count (the old order) loses them, as reported", not old.Vertices.UseDoublePrecisionVertices)
    back, back_faces = to_arrays(mesh)
    check("double positions come back exactly", back == [float(x) for x in positions], str(back))
    check("faces come back as written, the triangle with C == D", back_faces == faces, str(back_faces))
    check("openNURBS counts one triangle and one quad", (mesh.Faces.TriangleCount, mesh.Faces.QuadCount) == (1, 1),
          str((mesh.Faces.TriangleCount, mesh.Faces.QuadCount)))
    check("ComputeNormals gives one normal per vertex", len(mesh.Normals) == 4, str(len(mesh.Normals)))
    check("the mesh is valid", mesh.IsValid)

    # A float-precision input (a mesh from Rhino's own commands) is read through m_V.
    floats = rhino3dm.Mesh()
    floats.Vertices.SetCount(3)
    for i, (x, y, z) in enumerate([(0, 0, 0), (1, 0, 0), (0, 1, 0.1)]):
        floats.Vertices[i] = rhino3dm.Point3f(x, y, z)
    floats.Faces.AddFace(0, 1, 2)
    fp, ff = to_arrays(floats)
    check("a float mesh is read through the float array",
          not floats.Vertices.UseDoublePrecisionVertices and len(fp) == 9 and abs(fp[8] - 0.1) < 1e-7 and ff == [0, 1, 2, 2])

    # Empty result (Cull Adjacent removing every face): no count, no flag, no lock, no normals.
    empty = from_arrays([], [])
    check("an empty result is a mesh with no vertices and no faces", len(empty.Vertices) == 0 and empty.Faces.Count == 0)
    flagged = rhino3dm.Mesh()
    flagged.Vertices.UseDoublePrecisionVertices = True
    check("on an empty mesh the flag cannot be set, so the lock is never asked for",
          not flagged.Vertices.UseDoublePrecisionVertices)
    check("an empty mesh reads back as empty arrays", to_arrays(empty) == ([], []))

    # Vertices but no faces: the input is read without asking for faces.
    points_only = from_arrays([0, 0, 0, 1, 2, 3], [])
    pp, pf = to_arrays(points_only)
    check("a mesh without faces reads its vertices and no faces", pp == [0, 0, 0, 1, 2, 3] and pf == [])
    check("no normals are computed without faces", len(points_only.Normals) == 0)

    # Vertex colours: VertexColours reads them only when there is one per vertex; SetVertexColours sets all.
    mesh.VertexColors.Clear()
    for r, g, b in [(255, 0, 0), (0, 255, 0), (0, 0, 255), (10, 20, 30)]:
        mesh.VertexColors.Add(r, g, b)
    check("one colour per vertex", mesh.VertexColors.Count == len(mesh.Vertices))
    check("colours read back opaque, in order", mesh.VertexColors[3] == (10, 20, 30, 255), str(mesh.VertexColors[3]))

    # SetVertexNormals replaces the computed normals.
    mesh.Normals.Clear()
    for _ in range(4):
        mesh.Normals.Add(0, 0, 1)
    check("normals replaced one per vertex", len(mesh.Normals) == 4 and mesh.Normals[2].Z == 1)

    print("not replayed (rhino3dm has no binding): " + ", ".join(sorted(NOT_BOUND & set(used))))
    return finish("rhino3dm replay")


if __name__ == "__main__":
    sys.exit(main())
