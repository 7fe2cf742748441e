using System;
using System.Collections.Generic;

namespace Weft.Grasshopper
{
    /// <summary>A polygon mesh as Weft takes it: 3 doubles per vertex, face sizes, concatenated indices.</summary>
    public sealed class PolygonArrays
    {
        /// <summary>x, y, z per vertex.</summary>
        public double[] Positions;
        /// <summary>Corner count of each face.</summary>
        public uint[] FaceSizes;
        /// <summary>The faces' vertex indices, one face after another.</summary>
        public uint[] FaceIndices;
    }

    /// <summary>
    /// A mesh as Rhino stores it: four indices per face (C == D for a
    /// triangle), and n-gons as a boundary over a set of those faces.
    /// </summary>
    public sealed class RhinoArrays
    {
        /// <summary>A, B, C, D per face.</summary>
        public int[] Faces;
        /// <summary>Boundary vertex indices of each n-gon, in order.</summary>
        public List<int[]> NgonBoundaries = new List<int[]>();
        /// <summary>The Rhino faces that make up each n-gon.</summary>
        public List<int[]> NgonFaces = new List<int[]>();
    }

    /// <summary>
    /// Conversions between Rhino's face layout and Weft's polygons, on plain
    /// arrays so they run in tests without Rhino.
    /// </summary>
    public static class MeshArrays
    {
        /// <summary>
        /// Turns Rhino faces into Weft polygons: a face with C == D becomes a
        /// triangle, every other face a quad, and each n-gon (boundary of at
        /// least 3 vertices) one polygon in place of its faces, at the position
        /// of its first face. A face claimed by two n-gons goes to the first.
        /// </summary>
        public static PolygonArrays FromRhino(double[] positions, int[] faces, IList<int[]> ngonBoundaries, IList<int[]> ngonFaces)
        {
            if (faces.Length % 4 != 0) throw new ArgumentException("faces must hold 4 indices per face", "faces");
            int faceCount = faces.Length / 4;
            // For each Rhino face: -1 when it stands alone, else the n-gon it belongs to.
            var owner = new int[faceCount];
            for (int f = 0; f < faceCount; f++) owner[f] = -1;
            var firstFace = new int[ngonBoundaries == null ? 0 : ngonBoundaries.Count];
            for (int n = 0; n < firstFace.Length; n++)
            {
                firstFace[n] = -1;
                if (ngonBoundaries[n] == null || ngonBoundaries[n].Length < 3) continue;
                foreach (int f in ngonFaces[n])
                {
                    if (f < 0 || f >= faceCount || owner[f] != -1) continue;
                    owner[f] = n;
                    if (firstFace[n] == -1 || f < firstFace[n]) firstFace[n] = f;
                }
            }
            var sizes = new List<uint>(faceCount);
            var indices = new List<uint>(faces.Length);
            for (int f = 0; f < faceCount; f++)
            {
                int n = owner[f];
                if (n == -1)
                {
                    int a = faces[4 * f], b = faces[4 * f + 1], c = faces[4 * f + 2], d = faces[4 * f + 3];
                    indices.Add((uint)a);
                    indices.Add((uint)b);
                    indices.Add((uint)c);
                    if (c == d)
                    {
                        sizes.Add(3);
                    }
                    else
                    {
                        indices.Add((uint)d);
                        sizes.Add(4);
                    }
                }
                else if (firstFace[n] == f)
                {
                    foreach (int v in ngonBoundaries[n]) indices.Add((uint)v);
                    sizes.Add((uint)ngonBoundaries[n].Length);
                }
            }
            return new PolygonArrays { Positions = positions, FaceSizes = sizes.ToArray(), FaceIndices = indices.ToArray() };
        }

        /// <summary>
        /// Turns Weft polygons into Rhino faces: triangles as (a, b, c, c),
        /// quads as they are, and each larger polygon split into triangles by
        /// the library (<c>weft_triangulate_ex</c>, ear clipping in its
        /// best-fit plane), registered as one n-gon.
        /// </summary>
        public static RhinoArrays ToRhino(double[] positions, uint[] faceSizes, uint[] faceIndices)
        {
            List<int[]>[] ngonTriangles = TriangulateNgons(positions, faceSizes, faceIndices);
            var result = new RhinoArrays();
            var faces = new List<int>(faceIndices.Length + faceSizes.Length);
            int start = 0, ngon = 0;
            foreach (uint size in faceSizes)
            {
                int n = (int)size;
                if (n == 3 || n == 4)
                {
                    for (int k = 0; k < n; k++) faces.Add((int)faceIndices[start + k]);
                    if (n == 3) faces.Add((int)faceIndices[start + 2]);
                }
                else
                {
                    var polygon = new int[n];
                    for (int k = 0; k < n; k++) polygon[k] = (int)faceIndices[start + k];
                    var members = new List<int>();
                    foreach (int[] t in ngonTriangles[ngon++])
                    {
                        members.Add(faces.Count / 4);
                        faces.Add(t[0]);
                        faces.Add(t[1]);
                        faces.Add(t[2]);
                        faces.Add(t[2]);
                    }
                    result.NgonBoundaries.Add(polygon);
                    result.NgonFaces.Add(members.ToArray());
                }
                start += n;
            }
            result.Faces = faces.ToArray();
            return result;
        }

        /// <summary>The triangles of each face of more than four corners, in face order, cut by the library.</summary>
        private static List<int[]>[] TriangulateNgons(double[] positions, uint[] faceSizes, uint[] faceIndices)
        {
            var sizes = new List<uint>();
            var indices = new List<uint>();
            int start = 0;
            foreach (uint size in faceSizes)
            {
                if (size > 4)
                {
                    sizes.Add(size);
                    for (int k = 0; k < size; k++) indices.Add(faceIndices[start + k]);
                }
                start += (int)size;
            }
            var groups = new List<int[]>[sizes.Count];
            for (int i = 0; i < groups.Length; i++) groups[i] = new List<int[]>();
            if (groups.Length == 0) return groups;
            // Only the n-gons, over all the vertices: triangulation keeps vertex indices.
            using (WeftMesh ngons = WeftMesh.Create(positions, sizes.ToArray(), indices.ToArray()))
            {
                uint[] parents;
                using (WeftMesh triangles = Subdivision.Triangulate(ngons, out parents))
                {
                    uint[] triangleSizes, corners;
                    triangles.GetFaces(out triangleSizes, out corners);
                    for (int t = 0; t < parents.Length; t++)
                    {
                        groups[parents[t]].Add(new[] { (int)corners[3 * t], (int)corners[3 * t + 1], (int)corners[3 * t + 2] });
                    }
                }
            }
            return groups;
        }

        /// <summary>
        /// Builds one mesh from closed polylines (each a list of x, y, z
        /// corners, with or without the closing point repeated): each polyline
        /// becomes a face of its own corners (<c>weft_mesh_new</c>), then the
        /// library welds corners at most <paramref name="tolerance"/> apart
        /// (<c>weft_weld</c>), so neighbouring polygons share vertices.
        /// </summary>
        public static PolygonArrays FromPolylines(IList<double[]> polylines, double tolerance)
        {
            var positions = new List<double>();
            var sizes = new List<uint>(polylines.Count);
            var indices = new List<uint>();
            foreach (double[] line in polylines)
            {
                int count = line.Length / 3;
                if (count > 1 && line[0] == line[3 * count - 3] && line[1] == line[3 * count - 2] && line[2] == line[3 * count - 1])
                {
                    count--; // closing point repeated
                }
                uint first = (uint)(positions.Count / 3);
                for (int i = 0; i < 3 * count; i++) positions.Add(line[i]);
                for (int i = 0; i < count; i++) indices.Add(first + (uint)i);
                sizes.Add((uint)count);
            }
            using (WeftMesh separate = WeftMesh.Create(positions.ToArray(), sizes.ToArray(), indices.ToArray()))
            using (WeftMesh welded = Mending.Weld(separate, tolerance))
            {
                return FromWeft(welded);
            }
        }

        /// <summary>Joins several polygon sets into one mesh (<c>weft_join</c>: each set's vertices after the ones before).</summary>
        public static PolygonArrays Join(IList<PolygonArrays> parts)
        {
            var meshes = new WeftMesh[parts.Count];
            try
            {
                for (int i = 0; i < parts.Count; i++)
                {
                    meshes[i] = WeftMesh.Create(parts[i].Positions, parts[i].FaceSizes, parts[i].FaceIndices);
                }
                using (WeftMesh joined = Mending.Join(meshes))
                {
                    return FromWeft(joined);
                }
            }
            finally
            {
                foreach (WeftMesh mesh in meshes)
                {
                    if (mesh != null) mesh.Dispose();
                }
            }
        }

        /// <summary>A Weft mesh's arrays.</summary>
        public static PolygonArrays FromWeft(WeftMesh mesh)
        {
            var result = new PolygonArrays { Positions = mesh.GetPositions() };
            mesh.GetFaces(out result.FaceSizes, out result.FaceIndices);
            return result;
        }
    }
}
