using System;
using System.Collections.Generic;

namespace Weft.Grasshopper
{
    /// <summary>
    /// The array work behind the extract and making components (face
    /// polylines, boundary pieces, cells, per-face values), on plain arrays
    /// so it runs in tests without Rhino.
    /// </summary>
    public static class FlatGeometry
    {
        /// <summary>
        /// Each face as a closed polyline: its corners' x, y, z and the first
        /// corner again at the end (Rhino's closed polyline form).
        /// </summary>
        public static List<double[]> FacePolylines(double[] positions, uint[] faceSizes, uint[] faceIndices)
        {
            var polylines = new List<double[]>(faceSizes.Length);
            int start = 0;
            foreach (uint size in faceSizes)
            {
                var points = new double[3 * (size + 1)];
                for (int c = 0; c <= size; c++)
                {
                    uint v = faceIndices[start + (int)(c % size)];
                    points[3 * c] = positions[3 * v];
                    points[3 * c + 1] = positions[3 * v + 1];
                    points[3 * c + 2] = positions[3 * v + 2];
                }
                polylines.Add(points);
                start += (int)size;
            }
            return polylines;
        }

        /// <summary>
        /// Splits concatenated polylines (points after one another, a count per
        /// polyline) into one array each; a closed one gets its first point
        /// repeated at the end, an empty one is skipped when <paramref name="skipEmpty"/>.
        /// </summary>
        public static List<double[]> SplitPolylines(double[] points, int[] pointCounts, bool[] closed, bool skipEmpty)
        {
            var polylines = new List<double[]>(pointCounts.Length);
            int start = 0;
            for (int i = 0; i < pointCounts.Length; i++)
            {
                int n = pointCounts[i];
                bool close = closed != null && closed[i] && n > 0;
                if (n == 0 && skipEmpty) continue;
                var p = new double[3 * (n + (close ? 1 : 0))];
                Array.Copy(points, 3 * start, p, 0, 3 * n);
                if (close) Array.Copy(points, 3 * start, p, 3 * n, 3);
                polylines.Add(p);
                start += n;
            }
            return polylines;
        }

        /// <summary>The corner counts of Voronoi cells as ints, for <see cref="SplitPolylines"/>.</summary>
        public static int[] ToInts(uint[] values)
        {
            var ints = new int[values.Length];
            for (int i = 0; i < values.Length; i++) ints[i] = checked((int)values[i]);
            return ints;
        }

        /// <summary>
        /// Whether each face is planar: its deviation from the best-fit plane
        /// at most <paramref name="tolerance"/>.
        /// </summary>
        public static bool[] WithinTolerance(double[] deviations, double tolerance)
        {
            var flags = new bool[deviations.Length];
            for (int i = 0; i < deviations.Length; i++) flags[i] = deviations[i] <= tolerance;
            return flags;
        }

        /// <summary>Drops a repeated closing point (a closed polyline's last corner equal to its first).</summary>
        public static double[] OpenRing(double[] corners)
        {
            int n = corners.Length / 3;
            if (n > 1 && corners[0] == corners[3 * n - 3] && corners[1] == corners[3 * n - 2] && corners[2] == corners[3 * n - 1])
            {
                var open = new double[3 * (n - 1)];
                Array.Copy(corners, open, open.Length);
                return open;
            }
            return corners;
        }
    }
}
