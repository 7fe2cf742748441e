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
        /// ear clipping in its best-fit plane, registered as one n-gon.
        /// </summary>
        public static RhinoArrays ToRhino(double[] positions, uint[] faceSizes, uint[] faceIndices)
        {
            var result = new RhinoArrays();
            var faces = new List<int>(faceIndices.Length + faceSizes.Length);
            int start = 0;
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
                    foreach (int[] t in EarClip(positions, polygon))
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

        /// <summary>
        /// Triangles (n − 2 of them, same winding) covering a simple polygon,
        /// found by ear clipping in the plane of its Newell normal; falls back
        /// to a fan when no ear is found (a self-intersecting polygon).
        /// </summary>
        public static List<int[]> EarClip(double[] positions, int[] polygon)
        {
            int n = polygon.Length;
            // Newell normal, then drop its largest axis to work in 2-D.
            double nx = 0, ny = 0, nz = 0;
            for (int i = 0; i < n; i++)
            {
                int a = 3 * polygon[i], b = 3 * polygon[(i + 1) % n];
                nx += (positions[a + 1] - positions[b + 1]) * (positions[a + 2] + positions[b + 2]);
                ny += (positions[a + 2] - positions[b + 2]) * (positions[a] + positions[b]);
                nz += (positions[a] - positions[b]) * (positions[a + 1] + positions[b + 1]);
            }
            int u = 0, v = 1;
            double sign = nz;
            if (Math.Abs(nx) >= Math.Abs(ny) && Math.Abs(nx) >= Math.Abs(nz)) { u = 1; v = 2; sign = nx; }
            else if (Math.Abs(ny) >= Math.Abs(nz)) { u = 2; v = 0; sign = ny; }
            double orientation = sign >= 0 ? 1 : -1;

            var remaining = new List<int>(polygon);
            var triangles = new List<int[]>(n - 2);
            while (remaining.Count > 3)
            {
                int m = remaining.Count;
                int ear = -1;
                for (int i = 0; i < m && ear < 0; i++)
                {
                    int p = remaining[(i + m - 1) % m], c = remaining[i], q = remaining[(i + 1) % m];
                    if (orientation * Cross(positions, u, v, p, c, q) <= 0) continue; // reflex or flat
                    bool empty = true;
                    for (int j = 0; j < m && empty; j++)
                    {
                        int w = remaining[j];
                        if (w == p || w == c || w == q) continue;
                        if (orientation * Cross(positions, u, v, p, c, w) >= 0
                            && orientation * Cross(positions, u, v, c, q, w) >= 0
                            && orientation * Cross(positions, u, v, q, p, w) >= 0)
                        {
                            empty = false;
                        }
                    }
                    if (empty) ear = i;
                }
                if (ear < 0) ear = 1; // no ear: cut a fan corner so the loop ends
                int mm = remaining.Count;
                triangles.Add(new[] { remaining[(ear + mm - 1) % mm], remaining[ear], remaining[(ear + 1) % mm] });
                remaining.RemoveAt(ear);
            }
            triangles.Add(new[] { remaining[0], remaining[1], remaining[2] });
            return triangles;
        }

        private static double Cross(double[] p, int u, int v, int a, int b, int c)
        {
            double abu = p[3 * b + u] - p[3 * a + u], abv = p[3 * b + v] - p[3 * a + v];
            double acu = p[3 * c + u] - p[3 * a + u], acv = p[3 * c + v] - p[3 * a + v];
            return abu * acv - abv * acu;
        }

        /// <summary>
        /// Builds polygons from closed polylines (each a list of x, y, z
        /// corners, with or without the closing point repeated), merging
        /// corners closer than <paramref name="tolerance"/> through a grid
        /// hash, so neighbouring polygons share vertices.
        /// </summary>
        public static PolygonArrays FromPolylines(IList<double[]> polylines, double tolerance)
        {
            double cell = tolerance > 0 ? tolerance : 1e-9;
            var grid = new Dictionary<long, List<int>>();
            var positions = new List<double>();
            var sizes = new List<uint>();
            var indices = new List<uint>();
            foreach (double[] line in polylines)
            {
                int count = line.Length / 3;
                if (count > 1 && line[0] == line[3 * count - 3] && line[1] == line[3 * count - 2] && line[2] == line[3 * count - 1])
                {
                    count--; // closing point repeated
                }
                var face = new List<uint>(count);
                for (int i = 0; i < count; i++)
                {
                    uint vertex = FindOrAdd(grid, positions, line[3 * i], line[3 * i + 1], line[3 * i + 2], cell, tolerance);
                    if (face.Count == 0 || face[face.Count - 1] != vertex) face.Add(vertex);
                }
                if (face.Count > 1 && face[0] == face[face.Count - 1]) face.RemoveAt(face.Count - 1);
                sizes.Add((uint)face.Count);
                indices.AddRange(face);
            }
            return new PolygonArrays { Positions = positions.ToArray(), FaceSizes = sizes.ToArray(), FaceIndices = indices.ToArray() };
        }

        private static uint FindOrAdd(Dictionary<long, List<int>> grid, List<double> positions, double x, double y, double z, double cell, double tolerance)
        {
            long cx = (long)Math.Floor(x / cell), cy = (long)Math.Floor(y / cell), cz = (long)Math.Floor(z / cell);
            for (long i = cx - 1; i <= cx + 1; i++)
            for (long j = cy - 1; j <= cy + 1; j++)
            for (long k = cz - 1; k <= cz + 1; k++)
            {
                List<int> bucket;
                if (!grid.TryGetValue(Key(i, j, k), out bucket)) continue;
                foreach (int v in bucket)
                {
                    double dx = positions[3 * v] - x, dy = positions[3 * v + 1] - y, dz = positions[3 * v + 2] - z;
                    if (dx * dx + dy * dy + dz * dz <= tolerance * tolerance) return (uint)v;
                }
            }
            int index = positions.Count / 3;
            positions.Add(x);
            positions.Add(y);
            positions.Add(z);
            List<int> own;
            long key = Key(cx, cy, cz);
            if (!grid.TryGetValue(key, out own))
            {
                own = new List<int>();
                grid[key] = own;
            }
            own.Add(index);
            return (uint)index;
        }

        private static long Key(long i, long j, long k)
        {
            // 21 bits per axis is plenty to keep distinct neighbouring cells apart.
            return ((i & 0x1FFFFF) << 42) | ((j & 0x1FFFFF) << 21) | (k & 0x1FFFFF);
        }
        /// <summary>Puts several polygon sets into one, offsetting each set's indices past the vertices before it.</summary>
        public static PolygonArrays Concatenate(IList<PolygonArrays> parts)
        {
            var positions = new List<double>();
            var sizes = new List<uint>();
            var indices = new List<uint>();
            foreach (PolygonArrays part in parts)
            {
                uint offset = (uint)(positions.Count / 3);
                positions.AddRange(part.Positions);
                sizes.AddRange(part.FaceSizes);
                foreach (uint i in part.FaceIndices) indices.Add(i + offset);
            }
            return new PolygonArrays { Positions = positions.ToArray(), FaceSizes = sizes.ToArray(), FaceIndices = indices.ToArray() };
        }

        /// <summary>The arrays of the triangulated mesh (quads split along the shorter diagonal, n-gons ear-clipped in Weft); positions are shared.</summary>
        public static PolygonArrays Triangulate(PolygonArrays polygons)
        {
            using (WeftMesh mesh = WeftMesh.Create(polygons.Positions, polygons.FaceSizes, polygons.FaceIndices))
            using (WeftMesh triangles = Subdivision.Triangulate(mesh))
            {
                var result = new PolygonArrays { Positions = polygons.Positions };
                triangles.GetFaces(out result.FaceSizes, out result.FaceIndices);
                return result;
            }
        }
    }
}
