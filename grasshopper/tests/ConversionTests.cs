using System;
using System.Collections.Generic;
using Weft.Grasshopper;

namespace Weft.Tests
{
    /// <summary>The Rhino ⇄ Weft array conversions, run without Rhino.</summary>
    public static class ConversionTests
    {
        private static Runner t;

        public static int Main()
        {
            t = new Runner();
            t.Run("Rhino triangle (C == D) becomes a 3-vertex face", RhinoTriangle);
            t.Run("Rhino n-gon becomes one polygon in place of its faces", RhinoNgon);
            t.Run("Weft polygons to Rhino faces and n-gons", WeftToRhino);
            t.Run("ear clipping of a non-convex polygon", EarClipConcave);
            t.Run("closed polylines share welded corners", Polylines);
            t.Run("concatenation offsets indices", Concatenate);
            t.Run("converted arrays make a valid Weft mesh", IntoWeft);
            return t.Finish();
        }

        private static readonly double[] Grid =
        {
            0, 0, 0, 1, 0, 0, 2, 0, 0, 0, 1, 0, 1, 1, 0, 2, 1, 0,
        };

        private static void RhinoTriangle()
        {
            // A quad and a triangle stored Rhino's way.
            int[] faces = { 0, 1, 4, 3, 1, 2, 5, 5 };
            PolygonArrays a = MeshArrays.FromRhino(Grid, faces, new List<int[]>(), new List<int[]>());
            t.Sequence(new uint[] { 4, 3 }, a.FaceSizes, "sizes");
            t.Sequence(new uint[] { 0, 1, 4, 3, 1, 2, 5 }, a.FaceIndices, "indices");
        }

        private static void RhinoNgon()
        {
            // Faces 1 and 2 form the n-gon 1-2-5-4 (a quad split in two), face 0 stays.
            int[] faces = { 0, 1, 4, 3, 1, 2, 5, 5, 1, 5, 4, 4 };
            var boundaries = new List<int[]> { new[] { 1, 2, 5, 4 } };
            var members = new List<int[]> { new[] { 2, 1 } };
            PolygonArrays a = MeshArrays.FromRhino(Grid, faces, boundaries, members);
            t.Sequence(new uint[] { 4, 4 }, a.FaceSizes, "sizes");
            t.Sequence(new uint[] { 0, 1, 4, 3, 1, 2, 5, 4 }, a.FaceIndices, "indices");
        }

        private static void WeftToRhino()
        {
            // A triangle, a quad and a regular hexagon.
            var positions = new List<double> { 0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0 };
            for (int i = 0; i < 6; i++)
            {
                positions.Add(5 + Math.Cos(i * Math.PI / 3));
                positions.Add(Math.Sin(i * Math.PI / 3));
                positions.Add(0);
            }
            uint[] sizes = { 3, 4, 6 };
            uint[] indices = { 0, 1, 2, 0, 1, 3, 2, 4, 5, 6, 7, 8, 9 };
            RhinoArrays r = MeshArrays.ToRhino(positions.ToArray(), sizes, indices);
            t.Equal(2 + 4, r.Faces.Length / 4, "Rhino faces: 1 + 1 + 4 triangles");
            t.Sequence(new[] { 0, 1, 2, 2, 0, 1, 3, 2 }, SubArray(r.Faces, 0, 8), "triangle and quad");
            t.Equal(1, r.NgonBoundaries.Count, "one n-gon");
            t.Sequence(new[] { 4, 5, 6, 7, 8, 9 }, r.NgonBoundaries[0], "n-gon boundary");
            t.Sequence(new[] { 2, 3, 4, 5 }, r.NgonFaces[0], "n-gon faces");
            // Round trip back to Weft polygons.
            PolygonArrays back = MeshArrays.FromRhino(positions.ToArray(), r.Faces, r.NgonBoundaries, r.NgonFaces);
            t.Sequence(sizes, back.FaceSizes, "sizes after the round trip");
            t.Sequence(indices, back.FaceIndices, "indices after the round trip");
        }

        private static void EarClipConcave()
        {
            // An L shape (counter-clockwise): a fan from vertex 0 would cover the notch.
            double[] p = { 0, 0, 0, 2, 0, 0, 2, 1, 0, 1, 1, 0, 1, 2, 0, 0, 2, 0 };
            int[] polygon = { 0, 1, 2, 3, 4, 5 };
            List<int[]> triangles = MeshArrays.EarClip(p, polygon);
            t.Equal(4, triangles.Count, "n - 2 triangles");
            double area = 0;
            foreach (int[] tri in triangles)
            {
                double signed = ((p[3 * tri[1]] - p[3 * tri[0]]) * (p[3 * tri[2] + 1] - p[3 * tri[0] + 1])
                                 - (p[3 * tri[1] + 1] - p[3 * tri[0] + 1]) * (p[3 * tri[2]] - p[3 * tri[0]])) / 2;
                t.True(signed > 0, "every triangle counter-clockwise like the polygon");
                area += signed;
            }
            t.True(Math.Abs(area - 3.0) < 1e-12, "triangles cover the L's area 3, got " + area);
        }

        private static void Polylines()
        {
            // Two unit squares sharing an edge, corners off by less than the tolerance, one closed with its start repeated.
            var lines = new List<double[]>
            {
                new double[] { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 0 },
                new double[] { 1.0000001, 0, 0, 2, 0, 0, 2, 1, 0, 1, 1.0000001, 0 },
            };
            PolygonArrays a = MeshArrays.FromPolylines(lines, 0.001);
            t.Equal(6, a.Positions.Length / 3, "6 distinct corners");
            t.Sequence(new uint[] { 4, 4 }, a.FaceSizes, "two quads");
            t.Sequence(new uint[] { 0, 1, 2, 3, 1, 4, 5, 2 }, a.FaceIndices, "shared corners reused");
        }

        private static void Concatenate()
        {
            var a = new PolygonArrays { Positions = new double[] { 0, 0, 0, 1, 0, 0, 0, 1, 0 }, FaceSizes = new uint[] { 3 }, FaceIndices = new uint[] { 0, 1, 2 } };
            PolygonArrays both = MeshArrays.Concatenate(new List<PolygonArrays> { a, a });
            t.Equal(6, both.Positions.Length / 3, "vertices");
            t.Sequence(new uint[] { 0, 1, 2, 3, 4, 5 }, both.FaceIndices, "offset indices");
        }

        private static void IntoWeft()
        {
            int[] faces = { 0, 1, 4, 3, 1, 2, 5, 5, 1, 5, 4, 4 };
            PolygonArrays a = MeshArrays.FromRhino(Grid, faces, new List<int[]>(), new List<int[]>());
            using (WeftMesh mesh = WeftMesh.Create(a.Positions, a.FaceSizes, a.FaceIndices))
            {
                WeftMeshInfo info = mesh.Info();
                t.Equal(3L, info.FaceCount, "faces");
                t.Equal(8L, info.EdgeCount, "edges");
                t.True(info.IsOriented, "consistently wound");
            }
        }

        private static int[] SubArray(int[] a, int start, int count)
        {
            var r = new int[Math.Min(count, Math.Max(0, a.Length - start))];
            Array.Copy(a, start, r, 0, r.Length);
            return r;
        }
    }
}
