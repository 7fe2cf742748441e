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
            return Runner.RunAll(Register, CreaseInputTests.Register);
        }

        public static void Register(Runner runner)
        {
            t = runner;
            t.Run("Rhino triangle (C == D) becomes a 3-vertex face", RhinoTriangle);
            t.Run("Rhino n-gon becomes one polygon in place of its faces", RhinoNgon);
            t.Run("Weft polygons to Rhino faces and n-gons", WeftToRhino);
            t.Run("a concave n-gon becomes Rhino triangles covering it, cut by the library", ConcaveNgonToRhino);
            t.Run("closed polylines share welded corners", Polylines);
            t.Run("joining offsets indices (weft_join)", Concatenate);
            t.Run("converted arrays make a valid Weft mesh", IntoWeft);
            t.Run("refiner cache: a moved cage re-evaluates, new faces re-plan", RefinerCacheReuse);
            t.Run("refiner cache: a failed plan leaves no refiner and raises the library's error", RefinerCacheError);
            t.Run("refiner cache: holes and the triangle rule are part of the plan", RefinerCacheHoles);
            t.Run("refiner pool: one refiner per branch, so alternating topologies plan once each", RefinerPoolPerBranch);
            t.Run("refiner pool: branches a solution no longer has are freed, Dispose frees all", RefinerPoolFrees);
            t.Run("face budget: a level too many is refused, naming the level that fits", FaceBudgetRefuses);
            t.Run("tolerance: no document or a broken one falls back to the stated default", ToleranceFallback);
            t.Run("face polylines are closed rings of the face corners", FacePolylines);
            t.Run("split polylines: closed ones repeat their first point, empty ones skipped", SplitPolylines);
            t.Run("planarity flags and open rings", PlanarityAndRings);
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

        private static void ConcaveNgonToRhino()
        {
            // An L shape (counter-clockwise): a fan from vertex 0 would cover the notch.
            double[] p = { 0, 0, 0, 2, 0, 0, 2, 1, 0, 1, 1, 0, 1, 2, 0, 0, 2, 0 };
            RhinoArrays r = MeshArrays.ToRhino(p, new uint[] { 6 }, new uint[] { 0, 1, 2, 3, 4, 5 });
            t.Equal(4, r.Faces.Length / 4, "n - 2 triangles");
            t.Sequence(new[] { 0, 1, 2, 3 }, r.NgonFaces[0], "all four in the n-gon");
            double area = 0;
            for (int f = 0; f < r.Faces.Length / 4; f++)
            {
                int a = r.Faces[4 * f], b = r.Faces[4 * f + 1], c = r.Faces[4 * f + 2];
                t.Equal(c, r.Faces[4 * f + 3], "a triangle as Rhino stores it (C == D)");
                double signed = ((p[3 * b] - p[3 * a]) * (p[3 * c + 1] - p[3 * a + 1]) - (p[3 * b + 1] - p[3 * a + 1]) * (p[3 * c] - p[3 * a])) / 2;
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
            PolygonArrays both = MeshArrays.Join(new List<PolygonArrays> { a, a });
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

        private static void RefinerCacheHoles()
        {
            using (var cache = new RefinerCache())
            {
                var holed = new SubdivisionOptions(NakedEdges.Smooth).AddHole(2);
                RefinedArrays first = cache.Subdivide(UnitCube.Positions, UnitCube.Sizes, UnitCube.Indices, Scheme.CatmullClark, 2, holed);
                t.Equal(96 - 16, first.FaceSizes.Length, "the hole's 16 children are gone");
                t.Equal(98, first.Positions.Length / 3, "every vertex stays");
                RefinedArrays again = cache.Subdivide(UnitCube.Positions, UnitCube.Sizes, UnitCube.Indices, Scheme.CatmullClark, 2, holed.Clone());
                t.True(cache.LastReused, "the same holes reuse the plan");
                var smooth = new SubdivisionOptions(NakedEdges.Smooth) { Triangles = TriangleRule.Smooth }.AddHole(2);
                cache.Subdivide(UnitCube.Positions, UnitCube.Sizes, UnitCube.Indices, Scheme.CatmullClark, 2, smooth);
                t.False(cache.LastReused, "another triangle rule plans again");
                RefinedArrays none = cache.Subdivide(UnitCube.Positions, UnitCube.Sizes, UnitCube.Indices, Scheme.CatmullClark, 1,
                                                     new SubdivisionOptions(NakedEdges.None));
                t.Equal(24, none.FaceSizes.Length, "a closed cube has no boundary, so none leaves every face");
                t.Equal(again.FaceSizes.Length, first.FaceSizes.Length, "reused faces");
            }
        }

        private static void RefinerCacheReuse()
        {
            using (var cache = new RefinerCache())
            {
                RefinedArrays first = cache.Subdivide(UnitCube.Positions, UnitCube.Sizes, UnitCube.Indices, Scheme.CatmullClark, 2, NakedEdges.Smooth);
                t.False(cache.LastReused, "the first call plans");
                t.Equal(96, first.FaceSizes.Length, "faces");
                t.Equal(96, first.Rhino.Faces.Length / 4, "Rhino faces converted");

                // A slider moves the cage: same faces, new positions.
                var moved = (double[])UnitCube.Positions.Clone();
                for (int i = 0; i < moved.Length; i++) moved[i] = 3 * moved[i] + 1;
                RefinedArrays second = cache.Subdivide(moved, UnitCube.Sizes, UnitCube.Indices, Scheme.CatmullClark, 2, NakedEdges.Smooth);
                t.True(cache.LastReused, "the refiner is reused");
                t.Equal(1, cache.PlanCount, "planned once");
                using (var cage = WeftMesh.Create(moved, UnitCube.Sizes, UnitCube.Indices))
                using (var fresh = Subdivision.CatmullClark(cage, 2, NakedEdges.Smooth))
                {
                    double[] expected = fresh.GetPositions();
                    double worst = 0;
                    for (int i = 0; i < expected.Length; i++) worst = Math.Max(worst, Math.Abs(expected[i] - second.Positions[i]));
                    t.True(worst < 1e-12, "re-evaluated positions equal a fresh subdivision, off by " + worst);
                }

                // A new level count, then new faces: both plan again.
                cache.Subdivide(moved, UnitCube.Sizes, UnitCube.Indices, Scheme.CatmullClark, 1, NakedEdges.Smooth);
                t.False(cache.LastReused, "new levels re-plan");
                var flipped = (uint[])UnitCube.Indices.Clone();
                Array.Reverse(flipped, 0, 4);
                RefinedArrays third = cache.Subdivide(moved, UnitCube.Sizes, flipped, Scheme.CatmullClark, 1, NakedEdges.Smooth);
                t.False(cache.LastReused, "new faces re-plan");
                t.Equal(3, cache.PlanCount, "planned three times");
                t.Equal(24, third.FaceSizes.Length, "one level");
            }
        }

        private static void RefinerPoolPerBranch()
        {
            var flipped = (uint[])UnitCube.Indices.Clone();
            Array.Reverse(flipped, 0, 4);
            // One cache for a two-branch tree (the old way) re-plans on every branch.
            using (var single = new RefinerCache())
            {
                for (int solution = 0; solution < 2; solution++)
                {
                    single.Subdivide(UnitCube.Positions, UnitCube.Sizes, UnitCube.Indices, Scheme.CatmullClark, 1, NakedEdges.Smooth);
                    single.Subdivide(UnitCube.Positions, UnitCube.Sizes, flipped, Scheme.CatmullClark, 1, NakedEdges.Smooth);
                }
                t.Equal(4, single.PlanCount, "one shared cache plans every branch of every solution");
            }
            using (var pool = new RefinerPool())
            {
                for (int solution = 0; solution < 3; solution++)
                {
                    pool.BeginSolution();
                    pool.For(0).Subdivide(UnitCube.Positions, UnitCube.Sizes, UnitCube.Indices, Scheme.CatmullClark, 1, NakedEdges.Smooth);
                    pool.For(1).Subdivide(UnitCube.Positions, UnitCube.Sizes, flipped, Scheme.CatmullClark, 1, NakedEdges.Smooth);
                    pool.EndSolution();
                }
                t.Equal(1, pool.For(0).PlanCount, "branch 0 planned once in three solutions");
                t.Equal(1, pool.For(1).PlanCount, "branch 1 planned once in three solutions");
                t.True(pool.For(1).LastReused, "branch 1 reused its refiner");
            }
        }

        private static void RefinerPoolFrees()
        {
            var pool = new RefinerPool();
            pool.BeginSolution();
            for (int branch = 0; branch < 3; branch++) pool.For(branch).Subdivide(UnitCube.Positions, UnitCube.Sizes, UnitCube.Indices, Scheme.CatmullClark, 1, NakedEdges.Smooth);
            pool.EndSolution();
            t.Equal(3, pool.Count, "three branches, three caches");
            pool.BeginSolution();
            pool.For(0).Subdivide(UnitCube.Positions, UnitCube.Sizes, UnitCube.Indices, Scheme.CatmullClark, 1, NakedEdges.Smooth);
            pool.EndSolution();
            t.Equal(1, pool.Count, "a one-branch solution frees the other two");
            t.True(pool.For(0).LastReused, "the remaining branch keeps its refiner");
            pool.Dispose();
            t.Equal(0, pool.Count, "Dispose frees every refiner");
            try
            {
                pool.For(-1);
                t.Fail("a negative branch was accepted");
            }
            catch (ArgumentOutOfRangeException e)
            {
                t.True(e.Message.Contains("branch"), "the error names the branch: " + e.Message);
            }
        }

        private static void FaceBudgetRefuses()
        {
            using (var cube = WeftMesh.Create(UnitCube.Positions, UnitCube.Sizes, UnitCube.Indices))
            {
                // 6 quads: 24 faces at L = 1, 6 * 4^L after that.
                t.Equal(96L, FaceBudget.FacesAt(cube, Scheme.CatmullClark, 2), "faces at L = 2");
                FaceBudget.Check(cube, Scheme.CatmullClark, 5, 6144);
                try
                {
                    FaceBudget.Check(cube, Scheme.CatmullClark, 9, 6144);
                    t.Fail("L = 9 (1,572,864 faces) passed a budget of 6,144");
                }
                catch (WeftException e)
                {
                    t.Equal(WeftStatus.ResultTooLarge, e.Status, "status");
                    t.True(e.Message.Contains("L = 9") && e.Message.Contains("L = 5 is the highest level that fits"), e.Message);
                }
                // 20 levels overflow every count: refused, not crashed.
                try
                {
                    FaceBudget.Check(cube, Scheme.CatmullClark, 20, FaceBudget.MaxFaces);
                    t.Fail("L = 20 passed the default budget");
                }
                catch (WeftException e)
                {
                    t.True(e.Message.Contains("L = 9 is the highest level that fits"), e.Message);
                }
            }
        }

        private static void ToleranceFallback()
        {
            bool fellBack;
            t.Equal(0.01, Tolerances.Choose(0.01, out fellBack), "a document tolerance is used");
            t.False(fellBack, "no fallback with a document");
            foreach (double broken in new[] { double.NaN, 0.0, -1.0, double.PositiveInfinity })
            {
                t.Equal(Tolerances.Default, Tolerances.Choose(broken, out fellBack), "fallback for " + broken);
                t.True(fellBack, "fell back for " + broken);
            }
            t.True(Tolerances.Default > 0, "the default is a positive tolerance");
        }

        private static void RefinerCacheError()
        {
            using (var cache = new RefinerCache())
            {
                try
                {
                    cache.Subdivide(UnitCube.Positions, UnitCube.Sizes, UnitCube.Indices, Scheme.Loop, 1, NakedEdges.Smooth);
                    t.Fail("Loop on quads should fail");
                }
                catch (WeftException e)
                {
                    t.Equal(WeftStatus.NotTriangles, e.Status, "status");
                    t.True(e.Message.Contains("face 0 has 4 vertices"), "message names the face: " + e.Message);
                }
                t.Equal(0, cache.PlanCount, "nothing planned");
                PolygonArrays triangles;
                int split;
                using (WeftMesh cube = WeftMesh.Create(UnitCube.Positions, UnitCube.Sizes, UnitCube.Indices))
                using (WeftMesh asTriangles = Subdivision.AsTriangles(cube, out split))
                {
                    triangles = MeshArrays.FromWeft(asTriangles);
                }
                t.Equal(6, split, "six quads split");
                RefinedArrays loop = cache.Subdivide(triangles.Positions, triangles.FaceSizes, triangles.FaceIndices, Scheme.Loop, 1, NakedEdges.Smooth);
                t.Equal(48, loop.FaceSizes.Length, "Loop after triangulation: 12 × 4 triangles");
            }
        }

        private static void FacePolylines()
        {
            List<double[]> rings = FlatGeometry.FacePolylines(UnitCube.Positions, UnitCube.Sizes, UnitCube.Indices);
            t.Equal(6, rings.Count, "one per face");
            // Face 0 is 0, 2, 3, 1 and back to 0.
            t.Sequence(new double[] { 0, 0, 0, 0, 1, 0, 1, 1, 0, 1, 0, 0, 0, 0, 0 }, rings[0], "face 0's ring");
        }

        private static void SplitPolylines()
        {
            double[] points = { 0, 0, 0, 1, 0, 0, 1, 1, 0, 5, 5, 5, 6, 6, 6 };
            List<double[]> parts = FlatGeometry.SplitPolylines(points, new[] { 3, 0, 2 }, new[] { true, true, false }, true);
            t.Equal(2, parts.Count, "the empty one skipped");
            t.Equal(12, parts[0].Length, "closed: 3 points and the first again");
            t.Equal(0.0, parts[0][9], "the first point repeated");
            t.Sequence(new double[] { 5, 5, 5, 6, 6, 6 }, parts[1], "the open one as it is");
            t.Equal(3, FlatGeometry.SplitPolylines(points, new[] { 3, 0, 2 }, null, false).Count, "kept when not skipping");
        }

        private static void PlanarityAndRings()
        {
            bool[] flags = FlatGeometry.WithinTolerance(new[] { 0.0, 0.01, 0.2 }, 0.01);
            t.Sequence(new[] { true, true, false }, flags, "within the tolerance");
            double[] ring = { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 0, 0 };
            t.Equal(9, FlatGeometry.OpenRing(ring).Length, "the repeated corner dropped");
            t.Equal(9, FlatGeometry.OpenRing(new double[] { 0, 0, 0, 1, 0, 0, 1, 1, 0 }).Length, "an open ring unchanged");
            t.Sequence(new[] { 3, 0 }, FlatGeometry.ToInts(new uint[] { 3, 0 }), "ints");
        }
    }
}
