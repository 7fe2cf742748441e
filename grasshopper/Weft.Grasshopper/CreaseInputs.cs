using System;
using System.Collections.Generic;
using System.Globalization;

namespace Weft.Grasshopper
{
    /// <summary>
    /// One item of a crease input: a line matched to a cage edge by its end
    /// points, or the index of a cage edge as Mesh Edges (wbEdges) lists them.
    /// </summary>
    public struct CreaseItem
    {
        /// <summary>The line's end points (x, y, z, x, y, z), or null for an edge index.</summary>
        public double[] Line;
        /// <summary>The edge index when <see cref="Line"/> is null.</summary>
        public int EdgeIndex;

        /// <summary>A line from (x0, y0, z0) to (x1, y1, z1).</summary>
        public static CreaseItem FromLine(double x0, double y0, double z0, double x1, double y1, double z1)
        {
            return new CreaseItem { Line = new[] { x0, y0, z0, x1, y1, z1 } };
        }

        /// <summary>An edge index.</summary>
        public static CreaseItem FromEdge(int index)
        {
            return new CreaseItem { EdgeIndex = index };
        }
    }

    /// <summary>
    /// The conversions behind the creased subdivision components, on plain
    /// arrays so they run in tests without Rhino: crease lines and edge
    /// indices to vertex pairs, corner points to vertex indices, sharpness
    /// lists, and vertex colours to and from the doubles Weft carries.
    /// Every refusal is a <see cref="WeftException"/> naming the input and the
    /// item, which the component shows as an error balloon.
    /// </summary>
    public static class CreaseInputs
    {
        /// <summary>The default sharpness of the components: a hard crease or corner that never softens.</summary>
        public const double DefaultSharpness = SubdivisionOptions.SharpnessInfinite;

        /// <summary>
        /// Two vertex indices per crease item. A line matches the cage edge
        /// whose end points lie within <paramref name="tolerance"/> of the
        /// line's, in either direction (with several vertices in reach, any
        /// pair that is an edge). An edge index counts in
        /// <paramref name="edgePairs"/> (two vertices per edge, the order of
        /// <c>Toolbar.Edges</c> and Mesh Edges); it may be null when no item is
        /// an index.
        /// </summary>
        /// <exception cref="WeftException">An item matches no edge, or an index is out of range; the message names the item as <c>C[i]</c>.</exception>
        public static uint[] VertexPairs(double[] positions, uint[] faceSizes, uint[] faceIndices, uint[] edgePairs,
                                         IList<CreaseItem> items, double tolerance)
        {
            var pairs = new uint[2 * items.Count];
            VertexGrid grid = null;
            HashSet<ulong> edges = null;
            for (int i = 0; i < items.Count; i++)
            {
                CreaseItem item = items[i];
                if (item.Line == null)
                {
                    int edgeCount = edgePairs == null ? 0 : edgePairs.Length / 2;
                    if (item.EdgeIndex < 0 || item.EdgeIndex >= edgeCount)
                    {
                        throw new WeftException(WeftStatus.IndexOutOfRange, "C[" + i + "] is edge " + item.EdgeIndex + ", but the mesh has "
                            + edgeCount + " edges (numbered 0 to " + (edgeCount - 1) + " as Mesh Edges lists them)");
                    }
                    pairs[2 * i] = edgePairs[2 * item.EdgeIndex];
                    pairs[2 * i + 1] = edgePairs[2 * item.EdgeIndex + 1];
                    continue;
                }
                if (grid == null)
                {
                    grid = new VertexGrid(positions, tolerance);
                    edges = EdgeKeys(faceSizes, faceIndices);
                }
                double[] l = item.Line;
                List<int> starts = grid.Near(l[0], l[1], l[2]);
                List<int> ends = grid.Near(l[3], l[4], l[5]);
                bool found = false;
                for (int a = 0; a < starts.Count && !found; a++)
                {
                    for (int b = 0; b < ends.Count && !found; b++)
                    {
                        if (starts[a] != ends[b] && edges.Contains(Key((uint)starts[a], (uint)ends[b])))
                        {
                            pairs[2 * i] = (uint)starts[a];
                            pairs[2 * i + 1] = (uint)ends[b];
                            found = true;
                        }
                    }
                }
                if (!found)
                {
                    string why = starts.Count == 0 || ends.Count == 0
                        ? (starts.Count == 0 ? "its start" : "its end") + " is no vertex of the mesh"
                        : "its ends are vertices but not the ends of one edge";
                    throw new WeftException(WeftStatus.InvalidArgument, "C[" + i + "], the line from " + Point(l, 0) + " to " + Point(l, 3)
                        + ", matches no edge of the mesh within " + Number(tolerance) + ": " + why
                        + " (raise T, or give edge indices as Mesh Edges lists them)");
                }
            }
            return pairs;
        }

        /// <summary>
        /// The vertex nearest each point (x, y, z per point) within
        /// <paramref name="tolerance"/>.
        /// </summary>
        /// <exception cref="WeftException">A point with no vertex in reach; the message names it as <c>P[i]</c>.</exception>
        public static uint[] CornerVertices(double[] positions, double[] points, double tolerance)
        {
            var grid = new VertexGrid(positions, tolerance);
            var corners = new uint[points.Length / 3];
            for (int i = 0; i < corners.Length; i++)
            {
                List<int> near = grid.Near(points[3 * i], points[3 * i + 1], points[3 * i + 2]);
                if (near.Count == 0)
                {
                    throw new WeftException(WeftStatus.InvalidArgument, "P[" + i + "] at " + Point(points, 3 * i)
                        + " is no vertex of the mesh within " + Number(tolerance) + " (raise T, or place the point on a vertex)");
                }
                int best = near[0];
                double bestDistance = double.MaxValue;
                foreach (int v in near)
                {
                    double d = Distance2(positions, v, points[3 * i], points[3 * i + 1], points[3 * i + 2]);
                    if (d < bestDistance)
                    {
                        bestDistance = d;
                        best = v;
                    }
                }
                corners[i] = (uint)best;
            }
            return corners;
        }

        /// <summary>
        /// One sharpness per crease or corner from a list input: empty gives
        /// <see cref="DefaultSharpness"/> to all, one value is for all, else one
        /// value per item. 10 or more (or infinity) never softens.
        /// </summary>
        /// <exception cref="WeftException">A negative or NaN value, or a list of another length; the message names the input.</exception>
        public static double[] Sharpness(IList<double> values, int count, string nickname, string items)
        {
            var result = new double[count];
            if (values.Count > 1 && values.Count != count)
            {
                throw new WeftException(WeftStatus.CountMismatch, nickname + " has " + values.Count + " values for " + count + " " + items
                    + "; give one value for all or one per item");
            }
            for (int i = 0; i < values.Count; i++)
            {
                if (double.IsNaN(values[i]) || values[i] < 0)
                {
                    throw new WeftException(WeftStatus.InvalidArgument, nickname + "[" + i + "] is " + Number(values[i])
                        + "; sharpness must be 0 or more (0 smooth, 10 or more a hard crease or corner that never softens)");
                }
            }
            for (int i = 0; i < count; i++)
            {
                result[i] = values.Count == 0 ? DefaultSharpness : values[values.Count == 1 ? 0 : i];
            }
            return result;
        }

        /// <summary>Segments of six doubles (start x, y, z, end x, y, z) for vertex pairs, two indices each.</summary>
        public static double[] Segments(double[] positions, uint[] pairs)
        {
            var segments = new double[3 * pairs.Length];
            for (int i = 0; i < pairs.Length; i++)
            {
                Array.Copy(positions, 3 * (int)pairs[i], segments, 3 * i, 3);
            }
            return segments;
        }

        /// <summary>Colours as packed ARGB integers (Rhino's <c>ToARGBArray</c>) to red, green, blue, alpha doubles (0 to 255) per vertex.</summary>
        public static double[] ColoursToValues(int[] argb)
        {
            var values = new double[4 * argb.Length];
            for (int i = 0; i < argb.Length; i++)
            {
                uint c = unchecked((uint)argb[i]);
                values[4 * i] = (c >> 16) & 0xFF;
                values[4 * i + 1] = (c >> 8) & 0xFF;
                values[4 * i + 2] = c & 0xFF;
                values[4 * i + 3] = c >> 24;
            }
            return values;
        }

        /// <summary>Red, green, blue, alpha doubles per vertex back to packed ARGB, rounded and clamped to 0 to 255.</summary>
        public static int[] ValuesToColours(double[] values)
        {
            var argb = new int[values.Length / 4];
            for (int i = 0; i < argb.Length; i++)
            {
                uint r = Channel(values[4 * i]), g = Channel(values[4 * i + 1]), b = Channel(values[4 * i + 2]), a = Channel(values[4 * i + 3]);
                argb[i] = unchecked((int)((a << 24) | (r << 16) | (g << 8) | b));
            }
            return argb;
        }

        /// <summary>
        /// Vertex colours (packed ARGB, one per input vertex) carried through a weld whose
        /// <paramref name="vertexMap"/> gives, for each input vertex, its vertex of the
        /// welded mesh (<c>Subdivision.CreaseEdgesFromMesh</c>'s map): each welded vertex
        /// takes the colour of the first input vertex that became it.
        /// </summary>
        /// <exception cref="WeftException">A colour list and map of different lengths, or a map entry past <paramref name="weldedCount"/>.</exception>
        public static int[] ColoursThroughWeld(int[] colours, uint[] vertexMap, int weldedCount)
        {
            if (colours.Length != vertexMap.Length)
            {
                throw new WeftException(WeftStatus.CountMismatch, colours.Length + " vertex colours were given for a weld of "
                    + vertexMap.Length + " vertices; give one per vertex");
            }
            var welded = new int[weldedCount];
            var taken = new bool[weldedCount];
            for (int v = 0; v < vertexMap.Length; v++)
            {
                uint w = vertexMap[v];
                if (w >= (uint)weldedCount)
                {
                    throw new WeftException(WeftStatus.IndexOutOfRange, "vertex " + v + " maps to welded vertex " + w
                        + ", but the welded mesh has " + weldedCount + " vertices");
                }
                if (taken[w]) continue;
                welded[w] = colours[v];
                taken[w] = true;
            }
            return welded;
        }

        private static uint Channel(double value)
        {
            if (double.IsNaN(value) || value <= 0) return 0;
            if (value >= 255) return 255;
            return (uint)Math.Round(value);
        }

        /// <summary>The keys of every edge of the faces, either direction.</summary>
        private static HashSet<ulong> EdgeKeys(uint[] faceSizes, uint[] faceIndices)
        {
            var keys = new HashSet<ulong>();
            int start = 0;
            foreach (uint size in faceSizes)
            {
                for (int k = 0; k < size; k++)
                {
                    keys.Add(Key(faceIndices[start + k], faceIndices[start + (int)((k + 1) % size)]));
                }
                start += (int)size;
            }
            return keys;
        }

        private static ulong Key(uint a, uint b)
        {
            uint low = Math.Min(a, b), high = Math.Max(a, b);
            return ((ulong)low << 32) | high;
        }

        private static double Distance2(double[] positions, int v, double x, double y, double z)
        {
            double dx = positions[3 * v] - x, dy = positions[3 * v + 1] - y, dz = positions[3 * v + 2] - z;
            return dx * dx + dy * dy + dz * dz;
        }

        private static string Point(double[] xyz, int at)
        {
            return "(" + Number(xyz[at]) + ", " + Number(xyz[at + 1]) + ", " + Number(xyz[at + 2]) + ")";
        }

        private static string Number(double value)
        {
            return value.ToString("G6", CultureInfo.InvariantCulture);
        }

        /// <summary>The cage's vertices hashed into cells of the tolerance, for finding those near a point.</summary>
        private sealed class VertexGrid
        {
            private readonly double[] positions;
            private readonly double tolerance;
            private readonly double cell;
            private readonly Dictionary<long, List<int>> cells = new Dictionary<long, List<int>>();

            internal VertexGrid(double[] positions, double tolerance)
            {
                this.positions = positions;
                this.tolerance = tolerance > 0 ? tolerance : 0;
                cell = tolerance > 0 ? tolerance : 1e-9;
                for (int v = 0; v < positions.Length / 3; v++)
                {
                    long key = Key(Cell(positions[3 * v]), Cell(positions[3 * v + 1]), Cell(positions[3 * v + 2]));
                    List<int> bucket;
                    if (!cells.TryGetValue(key, out bucket))
                    {
                        bucket = new List<int>();
                        cells[key] = bucket;
                    }
                    bucket.Add(v);
                }
            }

            /// <summary>The vertices within the tolerance of (x, y, z), nearest first is not promised.</summary>
            internal List<int> Near(double x, double y, double z)
            {
                var found = new List<int>();
                long cx = Cell(x), cy = Cell(y), cz = Cell(z);
                for (long i = cx - 1; i <= cx + 1; i++)
                for (long j = cy - 1; j <= cy + 1; j++)
                for (long k = cz - 1; k <= cz + 1; k++)
                {
                    List<int> bucket;
                    if (!cells.TryGetValue(Key(i, j, k), out bucket)) continue;
                    foreach (int v in bucket)
                    {
                        if (Distance2(positions, v, x, y, z) <= tolerance * tolerance) found.Add(v);
                    }
                }
                return found;
            }

            private long Cell(double value)
            {
                double c = Math.Floor(value / cell);
                // Far-off or non-finite coordinates share a cell; the distance test still decides.
                if (double.IsNaN(c) || c > 1e15 || c < -1e15) return 0;
                return (long)c;
            }

            private static long Key(long i, long j, long k)
            {
                return ((i & 0x1FFFFF) << 42) | ((j & 0x1FFFFF) << 21) | (k & 0x1FFFFF);
            }
        }
    }
}
