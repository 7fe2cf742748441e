using System;
using System.Collections.Generic;
using System.Drawing;
using Rhino.Geometry;

namespace Weft.Grasshopper
{
    /// <summary>
    /// Rhino meshes to and from <see cref="WeftMesh"/>: only the raw arrays
    /// cross here (through <c>GetUnsafeLock</c>, no per-element native calls);
    /// the face layout conversion is in <see cref="MeshArrays"/>.
    /// </summary>
    /// <remarks>
    /// grasshopper/tests/replay_rhino_meshes.py replays every call this class
    /// makes on a Rhino mesh, in the same order, on openNURBS (rhino3dm), and
    /// fails when a mesh member used here is missing from its list: change
    /// both together. openNURBS keeps double-precision vertices only on a
    /// mesh that has vertices, and the unsafe lock throws for arrays a mesh
    /// does not have, so counts come first and empty arrays are never locked.
    /// </remarks>
    public static class RhinoMeshes
    {
        /// <summary>
        /// Copies a Rhino mesh into Weft: double-precision vertices when the
        /// mesh has them, triangles as 3-vertex faces, n-gons as one polygon.
        /// </summary>
        public static unsafe PolygonArrays ToArrays(Mesh mesh)
        {
            double[] positions;
            int[] faces;
            int vertexCount = mesh.Vertices.Count;
            int faceCount = mesh.Faces.Count;
            positions = new double[3 * vertexCount];
            faces = new int[4 * faceCount];
            if (vertexCount > 0 || faceCount > 0)
            {
                MeshUnsafeLock data = mesh.GetUnsafeLock(false);
                try
                {
                    int length;
                    if (vertexCount > 0 && mesh.Vertices.UseDoublePrecisionVertices)
                    {
                        Point3d* points = data.VertexPoint3dArray(out length);
                        for (int i = 0; i < vertexCount; i++)
                        {
                            positions[3 * i] = points[i].X;
                            positions[3 * i + 1] = points[i].Y;
                            positions[3 * i + 2] = points[i].Z;
                        }
                    }
                    else if (vertexCount > 0)
                    {
                        Point3f* points = data.VertexPoint3fArray(out length);
                        for (int i = 0; i < vertexCount; i++)
                        {
                            positions[3 * i] = points[i].X;
                            positions[3 * i + 1] = points[i].Y;
                            positions[3 * i + 2] = points[i].Z;
                        }
                    }
                    if (faceCount > 0)
                    {
                        MeshFace* rhinoFaces = data.FacesArray(out length);
                        for (int f = 0; f < faceCount; f++)
                        {
                            faces[4 * f] = rhinoFaces[f].A;
                            faces[4 * f + 1] = rhinoFaces[f].B;
                            faces[4 * f + 2] = rhinoFaces[f].C;
                            faces[4 * f + 3] = rhinoFaces[f].D;
                        }
                    }
                }
                finally
                {
                    mesh.ReleaseUnsafeLock(data);
                }
            }
            var boundaries = new List<int[]>();
            var members = new List<int[]>();
            for (int n = 0; n < mesh.Ngons.Count; n++)
            {
                MeshNgon ngon = mesh.Ngons.GetNgon(n);
                boundaries.Add(ToInts(ngon.BoundaryVertexIndexList()));
                members.Add(ToInts(ngon.FaceIndexList()));
            }
            return MeshArrays.FromRhino(positions, faces, boundaries, members);
        }

        /// <summary>Creates the Weft mesh of a Rhino mesh; dispose it after use.</summary>
        public static WeftMesh ToWeft(Mesh mesh)
        {
            PolygonArrays arrays = ToArrays(mesh);
            return WeftMesh.Create(arrays.Positions, arrays.FaceSizes, arrays.FaceIndices);
        }

        /// <summary>
        /// Creates a double-precision Rhino mesh from a Weft mesh, with a
        /// <see cref="MeshNgon"/> over the triangles of each polygon of more than four corners.
        /// </summary>
        public static unsafe Mesh FromWeft(WeftMesh weft)
        {
            double[] positions = weft.GetPositions();
            uint[] sizes;
            uint[] indices;
            weft.GetFaces(out sizes, out indices);
            return FromArrays(positions, MeshArrays.ToRhino(positions, sizes, indices));
        }

        /// <summary>
        /// Creates a double-precision Rhino mesh from positions and faces
        /// already in Rhino's layout (a refined topology converted once).
        /// </summary>
        public static unsafe Mesh FromArrays(double[] positions, RhinoArrays rhino)
        {
            var mesh = new Mesh();
            int vertexCount = positions.Length / 3;
            int faceCount = rhino.Faces.Length / 4;
            if (vertexCount > 0)
            {
                // Count first: on an empty mesh openNURBS drops the double-precision flag.
                mesh.Vertices.Count = vertexCount;
                mesh.Vertices.UseDoublePrecisionVertices = true;
            }
            if (faceCount > 0)
            {
                mesh.Faces.Count = faceCount;
            }
            if (vertexCount > 0 || faceCount > 0)
            {
                MeshUnsafeLock data = mesh.GetUnsafeLock(true);
                try
                {
                    int length;
                    if (vertexCount > 0)
                    {
                        Point3d* points = data.VertexPoint3dArray(out length);
                        for (int i = 0; i < vertexCount; i++)
                        {
                            points[i] = new Point3d(positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]);
                        }
                    }
                    if (faceCount > 0)
                    {
                        MeshFace* faces = data.FacesArray(out length);
                        for (int f = 0; f < faceCount; f++)
                        {
                            faces[f] = new MeshFace(rhino.Faces[4 * f], rhino.Faces[4 * f + 1], rhino.Faces[4 * f + 2], rhino.Faces[4 * f + 3]);
                        }
                    }
                }
                finally
                {
                    mesh.ReleaseUnsafeLock(data);
                }
            }
            for (int n = 0; n < rhino.NgonBoundaries.Count; n++)
            {
                mesh.Ngons.AddNgon(MeshNgon.Create(rhino.NgonBoundaries[n], rhino.NgonFaces[n]));
            }
            if (faceCount > 0)
            {
                mesh.Normals.ComputeNormals();
            }
            return mesh;
        }

        /// <summary>The mesh's vertex colours as packed ARGB, or null when it has no colour per vertex.</summary>
        public static int[] VertexColours(Mesh mesh)
        {
            int count = mesh.Vertices.Count;
            if (count == 0 || mesh.VertexColors.Count != count) return null;
            return mesh.VertexColors.ToARGBArray();
        }

        /// <summary>Sets one colour per vertex from packed ARGB values (in one native call).</summary>
        public static void SetVertexColours(Mesh mesh, int[] argb)
        {
            var colours = new Color[argb.Length];
            for (int i = 0; i < argb.Length; i++) colours[i] = Color.FromArgb(argb[i]);
            mesh.VertexColors.SetColors(colours);
        }

        /// <summary>Replaces the vertex normals with x, y, z triples (in one native call).</summary>
        public static void SetVertexNormals(Mesh mesh, double[] normals)
        {
            var vectors = new Vector3f[normals.Length / 3];
            for (int i = 0; i < vectors.Length; i++)
            {
                vectors[i] = new Vector3f((float)normals[3 * i], (float)normals[3 * i + 1], (float)normals[3 * i + 2]);
            }
            mesh.Normals.SetNormals(vectors);
        }

        /// <summary>Vectors from x, y, z triples.</summary>
        public static List<Vector3d> ToVectors(double[] xyz)
        {
            var vectors = new List<Vector3d>(xyz.Length / 3);
            for (int i = 0; i + 2 < xyz.Length; i += 3) vectors.Add(new Vector3d(xyz[i], xyz[i + 1], xyz[i + 2]));
            return vectors;
        }

        /// <summary>The corners of a closed polyline as x, y, z triples, or null when the curve is no closed polyline.</summary>
        public static double[] ClosedPolylineCorners(Curve curve)
        {
            Polyline polyline;
            if (curve == null || !curve.TryGetPolyline(out polyline) || !polyline.IsClosed)
            {
                return null;
            }
            return Triples(polyline.Count, i => polyline[i]);
        }

        /// <summary>Points from x, y, z triples.</summary>
        public static List<Point3d> ToPoints(double[] xyz)
        {
            var points = new List<Point3d>(xyz.Length / 3);
            for (int i = 0; i + 2 < xyz.Length; i += 3) points.Add(new Point3d(xyz[i], xyz[i + 1], xyz[i + 2]));
            return points;
        }

        /// <summary>x, y, z triples of points.</summary>
        public static double[] FromPoints(IList<Point3d> points)
        {
            return Triples(points.Count, i => points[i]);
        }

        /// <summary>x, y, z triples of the <paramref name="count"/> points that <paramref name="point"/> gives by index.</summary>
        private static double[] Triples(int count, Func<int, Point3d> point)
        {
            var xyz = new double[3 * count];
            for (int i = 0; i < count; i++)
            {
                Point3d p = point(i);
                xyz[3 * i] = p.X;
                xyz[3 * i + 1] = p.Y;
                xyz[3 * i + 2] = p.Z;
            }
            return xyz;
        }

        /// <summary>Lines from segments of six doubles.</summary>
        public static List<Line> ToLines(double[] segments)
        {
            var lines = new List<Line>(segments.Length / 6);
            for (int i = 0; i + 5 < segments.Length; i += 6)
            {
                lines.Add(new Line(segments[i], segments[i + 1], segments[i + 2], segments[i + 3], segments[i + 4], segments[i + 5]));
            }
            return lines;
        }

        /// <summary>Segments of six doubles from lines.</summary>
        public static double[] FromLines(IList<Line> lines)
        {
            // A segment is its two end points' triples.
            return Triples(2 * lines.Count, i => i % 2 == 0 ? lines[i / 2].From : lines[i / 2].To);
        }

        /// <summary>Polyline curves from x, y, z arrays (a closed one repeats its first point).</summary>
        public static List<PolylineCurve> ToPolylineCurves(IList<double[]> polylines)
        {
            var curves = new List<PolylineCurve>(polylines.Count);
            foreach (double[] p in polylines) curves.Add(new PolylineCurve(ToPoints(p)));
            return curves;
        }

        /// <summary>A Weft plane from a Rhino plane.</summary>
        public static WeftPlane ToWeftPlane(Plane plane)
        {
            return new WeftPlane(
                new[] { plane.OriginX, plane.OriginY, plane.OriginZ },
                new[] { plane.XAxis.X, plane.XAxis.Y, plane.XAxis.Z },
                new[] { plane.YAxis.X, plane.YAxis.Y, plane.YAxis.Z });
        }

        private static int[] ToInts(uint[] values)
        {
            var result = new int[values.Length];
            for (int i = 0; i < values.Length; i++) result[i] = checked((int)values[i]);
            return result;
        }
    }
}
