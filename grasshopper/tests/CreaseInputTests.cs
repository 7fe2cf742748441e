using System;
using System.Collections.Generic;
using Weft.Grasshopper;

namespace Weft.Tests
{
    /// <summary>The creased components' conversions, run without Rhino: lines and edge indices to vertex pairs, points to corners, sharpness lists, colours, and the refiner cache with creases.</summary>
    public static class CreaseInputTests
    {
        private static Runner t;

        public static void Register(Runner runner)
        {
            t = runner;
            t.Run("crease lines match cage edges within the tolerance, either direction", LinesMatchEdges);
            t.Run("a crease line matching no edge is refused, naming its index", LineMatchesNothing);
            t.Run("edge indices count as Mesh Edges lists them; out of range refused", EdgeIndices);
            t.Run("corner points match the nearest vertex within the tolerance", CornerPoints);
            t.Run("sharpness lists: empty, one for all, one each; negative, NaN and wrong lengths refused", SharpnessLists);
            t.Run("colours to doubles and back, rounded and clamped", Colours);
            t.Run("colours carried through a creased subdivision stay where they were", ColoursThroughSubdivision);
            t.Run("colours carried through Crease Edges From Mesh's weld: the first of coincident vertices wins", ColoursThroughCreaseWeld);
            t.Run("refiner cache with creases: same creases reuse, other creases re-plan", CacheWithCreases);
            t.Run("crease segments are the pairs' end points", Segments);
            t.Run("limit samples: one face for all or one each, evaluated on the cube's limit surface", LimitSamplesOnCube);
        }

        private static void LimitSamplesOnCube()
        {
            uint[] faces;
            double[] uvs;
            LimitSamples.Build(new[] { 2 }, new[] { 0.0, 0.5 }, new[] { 0.0, 0.5 }, out faces, out uvs);
            t.Equal(2, faces.Length, "one sample per U");
            t.True(faces[0] == 2 && faces[1] == 2 && uvs[2] == 0.5 && uvs[3] == 0.5, "F broadcast, (u, v) paired");
            LimitSamples.Build(new[] { 0, 5 }, new[] { 0.25, 1.0 }, new[] { 0.75, 0.0 }, out faces, out uvs);
            t.True(faces[1] == 5 && uvs[0] == 0.25 && uvs[1] == 0.75, "one face each");
            var options = new SubdivisionOptions(NakedEdges.Smooth);
            using (WeftMesh cube = CubeMesh())
            using (var surface = new LimitSurfaceEvaluator(cube, Scheme.CatmullClark, options))
            {
                LimitSamples.Build(new[] { 0 }, new[] { 0.0 }, new[] { 0.0 }, out faces, out uvs);
                var position = new double[3];
                surface.Evaluate(faces, uvs, position, null, null);
                LimitSurface limit = Subdivision.SubdivideLimit(cube, Scheme.CatmullClark, 1, options);
                int corner = (int)UnitCube.Indices[0];
                double gap = 0;
                for (int k = 0; k < 3; k++) gap = Math.Max(gap, Math.Abs(position[k] - limit.Positions[3 * corner + k]));
                t.True(gap < 1e-12, "face 0 at (0, 0) is the limit of its first corner: " + gap);
            }
            foreach (var bad in new[] { Tuple.Create(new[] { 0, 1 }, 3, "F has 2 faces for 3 samples"),
                                        Tuple.Create(new[] { -1 }, 1, "F[0] is -1") })
            {
                try
                {
                    LimitSamples.Build(bad.Item1, new double[bad.Item2], new double[bad.Item2], out faces, out uvs);
                    t.True(false, bad.Item3 + " was accepted");
                }
                catch (WeftException e)
                {
                    t.True(e.Message.Contains(bad.Item3), e.Message);
                }
            }
        }

        private static uint[] Edges()
        {
            using (WeftMesh cube = CubeMesh())
            {
                return Toolbar.Edges(cube);
            }
        }

        private static WeftMesh CubeMesh()
        {
            return WeftMesh.Create(UnitCube.Positions, UnitCube.Sizes, UnitCube.Indices);
        }

        /// <summary>Crease items matched on the cube.</summary>
        private static uint[] Pairs(IList<CreaseItem> items, double tolerance)
        {
            using (WeftMesh cube = CubeMesh())
            {
                return CreaseInputs.VertexPairs(cube, items, tolerance);
            }
        }

        private static void LinesMatchEdges()
        {
            var items = new List<CreaseItem>
            {
                CreaseItem.FromLine(0, 0, 0, 1, 0, 0),            // edge 0-1
                CreaseItem.FromLine(1, 1, 1.004, 1, 1, 0),        // edge 7-3, reversed and off by 0.004
                CreaseItem.FromEdge(2),
            };
            uint[] edges = Edges();
            uint[] pairs = Pairs(items, 0.01);
            t.Sequence(new uint[] { 0, 1, 7, 3, edges[4], edges[5] }, pairs, "vertex pairs");
            // The pairs are accepted by the library as edges.
            using (WeftMesh cube = WeftMesh.Create(UnitCube.Positions, UnitCube.Sizes, UnitCube.Indices))
            {
                var options = new SubdivisionOptions(NakedEdges.Smooth).AddCreases(pairs, 10);
                using (WeftMesh refined = Subdivision.Subdivide(cube, Scheme.CatmullClark, 1, options))
                {
                    t.Equal(26, refined.VertexCount, "subdivided with the matched creases");
                }
            }
        }

        private static void LineMatchesNothing()
        {
            var diagonal = new List<CreaseItem> { CreaseItem.FromLine(0, 0, 0, 1, 0, 0), CreaseItem.FromLine(0, 0, 0, 1, 1, 0) };
            Fails(() => Pairs(diagonal, 0.01), WeftStatus.InvalidArgument,
                "C[1]: the line from (0, 0, 0) to (1, 1, 0) matches no edge of the mesh within 0.01");
            var far = new List<CreaseItem> { CreaseItem.FromLine(0, 0, 0, 1, 0, 0.02) };
            Fails(() => Pairs(far, 0.01), WeftStatus.InvalidArgument,
                "C[0]: the line from (0, 0, 0) to (1, 0, 0.02) matches no edge of the mesh within 0.01");
            // Edge indices and lines mixed: the refused line is named by its place in C, not among the lines.
            var mixed = new List<CreaseItem> { CreaseItem.FromEdge(0), CreaseItem.FromLine(0, 0, 0, 1, 0, 0), CreaseItem.FromEdge(1), CreaseItem.FromLine(0, 0, 0, 1, 1, 1) };
            Fails(() => Pairs(mixed, 0.01), WeftStatus.InvalidArgument, "C[3]: the line from (0, 0, 0) to (1, 1, 1)");
            // Tolerance 0 matches exact end points only.
            var exact = new List<CreaseItem> { CreaseItem.FromLine(0, 0, 0, 1, 0, 0) };
            t.Sequence(new uint[] { 0, 1 }, Pairs(exact, 0), "exact match");
        }

        private static void EdgeIndices()
        {
            uint[] edges = Edges();
            t.Equal(24, edges.Length, "12 edges");
            var items = new List<CreaseItem> { CreaseItem.FromEdge(11), CreaseItem.FromEdge(0) };
            t.Sequence(new[] { edges[22], edges[23], edges[0], edges[1] },
                Pairs(items, 0.01), "pairs of edges 11 and 0");
            var bad = new List<CreaseItem> { CreaseItem.FromEdge(0), CreaseItem.FromEdge(12) };
            Fails(() => Pairs(bad, 0.01), WeftStatus.IndexOutOfRange,
                "C[1] is edge 12, but the mesh has 12 edges (numbered 0 to 11");
            var negative = new List<CreaseItem> { CreaseItem.FromEdge(-1) };
            Fails(() => Pairs(negative, 0.01), WeftStatus.IndexOutOfRange, "C[0] is edge -1");
        }

        private static void CornerPoints()
        {
            // Two vertices 0.004 apart: the nearer one wins.
            double[] positions = { 0, 0, 0, 0.004, 0, 0, 1, 0, 0 };
            using (WeftMesh points = WeftMesh.Create(positions, new uint[0], new uint[0]))
            {
                t.Sequence(new uint[] { 1, 2, 0 },
                    CreaseInputs.CornerVertices(points, new[] { 0.003, 0, 0, 1, 0.005, 0, -0.001, 0, 0 }, 0.01), "nearest vertices");
                Fails(() => CreaseInputs.CornerVertices(points, new[] { 0.0, 0, 0, 0.5, 0, 0 }, 0.01), WeftStatus.InvalidArgument,
                    "P[1]: the point at (0.5, 0, 0) is no vertex of the mesh within 0.01");
            }
        }

        private static void SharpnessLists()
        {
            t.Sequence(new[] { 10.0, 10.0, 10.0 }, CreaseInputs.Sharpness(new double[0], 3, "CS", "creases"), "empty: hard");
            t.Sequence(new[] { 2.5, 2.5 }, CreaseInputs.Sharpness(new[] { 2.5 }, 2, "CS", "creases"), "one for all");
            t.Sequence(new[] { 0.0, 1, double.PositiveInfinity }, CreaseInputs.Sharpness(new[] { 0.0, 1, double.PositiveInfinity }, 3, "CS", "creases"), "one each");
            Fails(() => CreaseInputs.Sharpness(new[] { 1.0, -1, 2 }, 3, "CS", "creases"), WeftStatus.InvalidArgument,
                "CS[1] is -1; sharpness must be 0 or more");
            Fails(() => CreaseInputs.Sharpness(new[] { double.NaN }, 3, "PS", "corners"), WeftStatus.InvalidArgument, "PS[0] is NaN");
            Fails(() => CreaseInputs.Sharpness(new[] { 1.0, 2 }, 3, "CS", "creases"), WeftStatus.CountMismatch,
                "CS has 2 values for 3 creases; give one value for all or one per item");
        }

        private static void Colours()
        {
            int red = unchecked((int)0xFFFF0000), translucentBlue = 0x400000FF, grey = unchecked((int)0xFF808080);
            double[] values = CreaseInputs.ColoursToValues(new[] { red, translucentBlue, grey });
            t.Sequence(new double[] { 255, 0, 0, 255, 0, 0, 255, 64, 128, 128, 128, 255 }, values, "r, g, b, a per vertex");
            t.Sequence(new[] { red, translucentBlue, grey }, CreaseInputs.ValuesToColours(values), "round trip");
            t.Sequence(new[] { unchecked((int)0xFF7F0000) }, CreaseInputs.ValuesToColours(new[] { 127.4, -3, double.NaN, 300 }), "rounded and clamped");
        }

        private static void ColoursThroughSubdivision()
        {
            // Vertex 7 white, the rest black; vertex 7 a hard corner: it stays white, its neighbours turn grey.
            var argb = new int[8];
            for (int v = 0; v < 8; v++) argb[v] = unchecked((int)0xFF000000);
            argb[7] = -1;
            var options = new SubdivisionOptions(NakedEdges.Smooth).AddCorner(7, 10);
            using (WeftMesh cube = WeftMesh.Create(UnitCube.Positions, UnitCube.Sizes, UnitCube.Indices))
            {
                double[] values = Subdivision.SubdivideVertexData(cube, Scheme.CatmullClark, 1, options, CreaseInputs.ColoursToValues(argb), 4);
                int[] refined = CreaseInputs.ValuesToColours(values);
                t.Equal(26, refined.Length, "a colour per refined vertex");
                t.Equal(-1, refined[7], "the corner stays white");
                t.Equal(unchecked((int)0xFF000000), refined[0], "the far corner stays black");
                int r = (refined[20 + 5] >> 16) & 0xFF; // the face point of face 5 (x = 1), a quarter white
                t.Equal(64, r, "face 5's face point is a quarter white");
            }
        }

        private static void ColoursThroughCreaseWeld()
        {
            // Two quads side by side, not welded: vertices 1 and 4, 2 and 5 coincide on their shared edge.
            double[] positions = { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 1, 0, 0, 1, 1, 0, 2, 1, 0, 2, 0, 0 };
            uint[] sizes = { 4, 4 };
            uint[] indices = { 0, 1, 2, 3, 4, 7, 6, 5 };
            int red = unchecked((int)0xFFFF0000), green = unchecked((int)0xFF00FF00), blue = unchecked((int)0xFF0000FF);
            // The left quad red, the right quad blue, its corner 6 green.
            int[] colours = { red, red, red, red, blue, blue, green, blue };
            using (WeftMesh mesh = WeftMesh.Create(positions, sizes, indices))
            {
                uint[] pairs, map;
                using (WeftMesh welded = Subdivision.CreaseEdgesFromMesh(mesh, 180, out pairs, out map))
                {
                    t.Equal(6, welded.VertexCount, "two pairs welded");
                    t.Sequence(new uint[] { 0, 1, 2, 3, 1, 2, 4, 5 }, map, "the vertex map");
                    t.Equal(2, pairs.Length, "one crease");
                    t.True(pairs.Length == 2 && Math.Min(pairs[0], pairs[1]) == 1 && Math.Max(pairs[0], pairs[1]) == 2, "the seam is the crease");
                    int[] carried = CreaseInputs.ColoursThroughWeld(colours, map, welded.VertexCount);
                    // The shared edge keeps the left quad's red (its vertices come first); the right quad's own corners keep theirs.
                    t.Sequence(new[] { red, red, red, red, green, blue }, carried, "colours of the welded vertices");
                    double[] p = welded.GetPositions();
                    for (int v = 0; v < map.Length; v++)
                    {
                        for (int k = 0; k < 3; k++) t.Equal(positions[3 * v + k], p[3 * (int)map[v] + k], "vertex " + v + " welded in place");
                    }
                }
            }
            Fails(() => CreaseInputs.ColoursThroughWeld(new[] { red, red }, new uint[] { 0, 1, 1 }, 2), WeftStatus.CountMismatch,
                "2 vertex colours were given for a weld of 3 vertices");
            Fails(() => CreaseInputs.ColoursThroughWeld(new[] { red, red }, new uint[] { 0, 2 }, 2), WeftStatus.IndexOutOfRange,
                "vertex 1 maps to welded vertex 2, but the welded mesh has 2 vertices");
        }

        private static void CacheWithCreases()
        {
            using (var cache = new RefinerCache())
            {
                var options = new SubdivisionOptions(NakedEdges.Smooth).AddCrease(0, 1, 10).AddCorner(7, 10);
                RefinedArrays a = cache.Subdivide(UnitCube.Positions, UnitCube.Sizes, UnitCube.Indices, Scheme.CatmullClark, 1, options);
                t.Sequence(new[] { 1.0, 1.0, 1.0 }, new[] { a.Positions[21], a.Positions[22], a.Positions[23] }, "corner kept");
                var moved = (double[])UnitCube.Positions.Clone();
                moved[23] = 2;
                // The same creases built anew: reused.
                var same = new SubdivisionOptions(NakedEdges.Smooth).AddCrease(0, 1, 10).AddCorner(7, 10);
                RefinedArrays b = cache.Subdivide(moved, UnitCube.Sizes, UnitCube.Indices, Scheme.CatmullClark, 1, same);
                t.True(cache.LastReused, "same creases reuse the refiner");
                t.Equal(2.0, b.Positions[23], "the moved corner follows");
                // Changing the caller's options after the call does not fool the cache.
                same.AddCrease(1, 3, 10);
                cache.Subdivide(moved, UnitCube.Sizes, UnitCube.Indices, Scheme.CatmullClark, 1, same);
                t.False(cache.LastReused, "another crease re-plans");
                t.Equal(2, cache.PlanCount, "two plans");
                cache.Subdivide(moved, UnitCube.Sizes, UnitCube.Indices, Scheme.CatmullClark, 1, NakedEdges.Smooth);
                t.False(cache.LastReused, "the plain call re-plans");
                var bad = new SubdivisionOptions().AddCrease(0, 7, 10);
                Fails(() => cache.Subdivide(UnitCube.Positions, UnitCube.Sizes, UnitCube.Indices, Scheme.CatmullClark, 1, bad), WeftStatus.InvalidArgument,
                    "crease 0 joins vertices 0 and 7");
            }
        }

        private static void Segments()
        {
            t.Sequence(new double[] { 0, 0, 0, 1, 1, 1, 1, 0, 0, 0, 1, 0 }, CreaseInputs.Segments(UnitCube.Positions, new uint[] { 0, 7, 1, 2 }), "segments");
        }

        private static void Fails(Action action, WeftStatus status, string message)
        {
            WeftException e = t.Throws<WeftException>(action, status.ToString());
            if (e == null) return;
            t.Equal(status, e.Status, "status");
            t.True(e.Message.Contains(message), "message containing \"" + message + "\", got \"" + e.Message + "\"");
        }
    }
}
