using System;
using System.Collections.Generic;
using System.Globalization;
using System.Text.RegularExpressions;

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
        /// Two vertex indices per crease item. Lines are matched to cage edges by the library
        /// (<c>weft_match_lines_to_edges</c>: the edge whose ends lie within
        /// <paramref name="tolerance"/> of the line's, in either direction); an edge index
        /// counts in the order of <c>Toolbar.Edges</c> and Mesh Edges.
        /// </summary>
        /// <exception cref="WeftException">An item matches no edge, or an index is out of range; the message names the item as <c>C[i]</c>.</exception>
        public static uint[] VertexPairs(WeftMesh cage, IList<CreaseItem> items, double tolerance)
        {
            var pairs = new uint[2 * items.Count];
            var lineItems = new List<int>();
            uint[] edgePairs = null;
            for (int i = 0; i < items.Count; i++)
            {
                CreaseItem item = items[i];
                if (item.Line != null)
                {
                    lineItems.Add(i);
                    continue;
                }
                if (edgePairs == null) edgePairs = Toolbar.Edges(cage);
                int edgeCount = edgePairs.Length / 2;
                if (item.EdgeIndex < 0 || item.EdgeIndex >= edgeCount)
                {
                    throw new WeftException(WeftStatus.IndexOutOfRange, "C[" + i + "] is edge " + item.EdgeIndex + ", but the mesh has "
                        + edgeCount + " edges (numbered 0 to " + (edgeCount - 1) + " as Mesh Edges lists them)");
                }
                pairs[2 * i] = edgePairs[2 * item.EdgeIndex];
                pairs[2 * i + 1] = edgePairs[2 * item.EdgeIndex + 1];
            }
            if (lineItems.Count == 0) return pairs;
            var lines = new double[6 * lineItems.Count];
            for (int j = 0; j < lineItems.Count; j++) Array.Copy(items[lineItems[j]].Line, 0, lines, 6 * j, 6);
            uint[] matched;
            try
            {
                matched = Mending.MatchLinesToEdges(cage, lines, tolerance);
            }
            catch (WeftException)
            {
                throw FirstRefusal(lineItems, j => Mending.MatchLinesToEdges(cage, Slice(lines, 6 * j, 6), tolerance), "C", "line",
                                   " (raise T, or give edge indices as Mesh Edges lists them)");
            }
            for (int j = 0; j < lineItems.Count; j++)
            {
                pairs[2 * lineItems[j]] = matched[2 * j];
                pairs[2 * lineItems[j] + 1] = matched[2 * j + 1];
            }
            return pairs;
        }

        /// <summary>
        /// The vertex nearest each point (x, y, z per point) within <paramref name="tolerance"/>,
        /// found by the library (<c>weft_match_points_to_vertices</c>).
        /// </summary>
        /// <exception cref="WeftException">A point with no vertex in reach; the message names it as <c>P[i]</c>.</exception>
        public static uint[] CornerVertices(WeftMesh cage, double[] points, double tolerance)
        {
            try
            {
                return Mending.MatchPointsToVertices(cage, points, tolerance);
            }
            catch (WeftException)
            {
                var all = new List<int>();
                for (int i = 0; i < points.Length / 3; i++) all.Add(i);
                throw FirstRefusal(all, i => Mending.MatchPointsToVertices(cage, Slice(points, 3 * i, 3), tolerance), "P", "point",
                                   " (raise T, or place the point on a vertex)");
            }
        }

        /// <summary>
        /// After the library refused a batch: matches the items one by one to find the first it
        /// refuses, and gives its refusal naming the input item (C[i], P[i]) instead of the
        /// position in the batch. Runs only on the error path.
        /// </summary>
        private static WeftException FirstRefusal(List<int> inputIndices, Action<int> matchOne, string nickname, string noun, string hint)
        {
            for (int j = 0; j < inputIndices.Count; j++)
            {
                try
                {
                    matchOne(j);
                }
                catch (WeftException e)
                {
                    // The library's "invalid argument: line 0 from ..." becomes "C[i]: the line from ...".
                    string status = Regex.Replace(e.Status.ToString(), "(?<!^)([A-Z])", " $1").ToLowerInvariant() + ": ";
                    string message = e.Message.StartsWith(status, StringComparison.Ordinal) ? e.Message.Substring(status.Length) : e.Message;
                    message = Regex.Replace(message, @"\b" + noun + @" 0\b", "the " + noun);
                    return new WeftException(e.Status, nickname + "[" + inputIndices[j] + "]: " + message + hint);
                }
            }
            return new WeftException(WeftStatus.InvalidArgument, nickname + ": the library refused the " + noun + "s together but none alone" + hint);
        }

        private static double[] Slice(double[] values, int start, int count)
        {
            var slice = new double[count];
            Array.Copy(values, start, slice, 0, count);
            return slice;
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

        private static string Number(double value)
        {
            return value.ToString("G6", CultureInfo.InvariantCulture);
        }
    }
}
