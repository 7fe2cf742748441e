using System;

namespace Weft.Tests
{
    /// <summary>Join, weld, T-nodes, cull, orientation, normals, planarity, naked boundaries.</summary>
    public static class MendingTests
    {
        private static Runner t;

        public static void Register(Runner runner)
        {
            t = runner;
            t.Run("join two cubes", JoinCubes);
            t.Run("join refuses a null or disposed mesh", JoinErrors);
            t.Run("weld two touching cubes, with a report", WeldCubes);
            t.Run("weld refuses a negative tolerance", WeldErrors);
            t.Run("points matched to the nearest vertex within the tolerance", MatchPoints);
            t.Run("lines matched to edges within the tolerance, in the line's direction", MatchLines);
            t.Run("find and repair a T-node", TNodes);
            t.Run("T-nodes refuse a negative tolerance", TNodeErrors);
            t.Run("cull the wall between two welded cubes", CullAdjacent);
            t.Run("unify orientation of a cube with a flipped face, and flip", Orientation);
            t.Run("orientation operations refuse a null or disposed mesh", OrientationErrors);
            t.Run("face and vertex normals of a cube", Normals);
            t.Run("planarity of a twisted quad", Planarity);
            t.Run("naked boundaries of a grid and a cube", NakedBoundaries);
            t.Run("normals, planarity and boundaries refuse a disposed mesh", QueryErrors);
        }

        private static void MatchPoints()
        {
            using (var cube = Shapes.Cube())
            {
                double[] corners = cube.GetPositions();
                var points = new[] { corners[21] + 0.004, corners[22], corners[23], corners[0], corners[1], corners[2] - 0.004 };
                t.Sequence(new uint[] { 7, 0 }, Mending.MatchPointsToVertices(cube, points, 0.01), "vertices 7 and 0");
                t.Equal(0, Mending.MatchPointsToVertices(cube, new double[0], 0.01).Length, "no points, no vertices");
                var far = new[] { corners[0], corners[1], corners[2], corners[0] + 0.5, corners[1], corners[2] };
                var e = t.Throws<WeftException>(() => Mending.MatchPointsToVertices(cube, far, 0.01), "a point far from every vertex");
                if (e != null)
                {
                    t.Equal(WeftStatus.InvalidArgument, e.Status, "status");
                    t.True(e.Message.Contains("point 1"), "names the point: " + e.Message);
                }
                t.Throws<WeftException>(() => Mending.MatchPointsToVertices(cube, new double[] { 0, 0 }, 0.01), "not three doubles per point");
                t.Throws<WeftException>(() => Mending.MatchPointsToVertices(cube, points, -1), "a negative tolerance");
            }
        }

        private static void MatchLines()
        {
            using (var cube = Shapes.Cube())
            {
                uint[] edges = Toolbar.Edges(cube);
                double[] p = cube.GetPositions();
                uint a = edges[2], b = edges[3];
                // Edge 1 given backwards, its ends 0.004 off.
                var lines = new[] { p[3 * b], p[3 * b + 1], p[3 * b + 2] + 0.004, p[3 * a], p[3 * a + 1], p[3 * a + 2] };
                t.Sequence(new[] { b, a }, Mending.MatchLinesToEdges(cube, lines, 0.01), "the edge, in the line's direction");
                var diagonal = new[] { p[0], p[1], p[2], p[21], p[22], p[23] };
                var e = t.Throws<WeftException>(() => Mending.MatchLinesToEdges(cube, diagonal, 0.01), "a line through the cube");
                if (e != null)
                {
                    t.Equal(WeftStatus.InvalidArgument, e.Status, "status");
                    t.True(e.Message.Contains("line 0") && e.Message.Contains("matches no edge"), "names the line: " + e.Message);
                }
                t.Throws<WeftException>(() => Mending.MatchLinesToEdges(cube, new double[] { 0, 0, 0 }, 0.01), "not six doubles per line");
            }
        }

        private static void JoinCubes()
        {
            using (var a = Shapes.Cube())
            using (var b = Shapes.Cube())
            using (var joined = Mending.Join(a, b))
            {
                t.Equal(16, joined.VertexCount, "vertices");
                t.Equal(12, joined.FaceCount, "faces");
                t.Equal(8u, joined.GetFaceIndices()[24], "second cube's first index offset by 8");
                t.Equal(2L, joined.Info().ComponentCount, "two pieces");
            }
            using (var empty = Mending.Join())
            {
                t.Equal(0, empty.VertexCount, "joining nothing gives the empty mesh");
            }
        }

        private static void JoinErrors()
        {
            using (var a = Shapes.Cube())
            {
                t.Throws<ArgumentNullException>(() => Mending.Join(a, null), "a null mesh");
                var gone = Shapes.Cube();
                gone.Dispose();
                t.Throws<ObjectDisposedException>(() => Mending.Join(a, gone), "a disposed mesh");
                t.False(a.IsDisposed, "the live mesh is still usable");
                t.Equal(8, a.VertexCount, "and intact");
            }
        }

        private static void WeldCubes()
        {
            using (var a = Shapes.Cube())
            using (var b = Shapes.CubeAt(1))
            using (var joined = Mending.Join(a, b))
            {
                WeftWeldReport report;
                using (var welded = Mending.Weld(joined, Mending.DefaultWeldTolerance, out report))
                {
                    t.Equal(12, welded.VertexCount, "the shared square's four vertices merged");
                    t.Equal(4L, report.MergedVertexCount, "merged");
                    t.Equal(0L, report.RemovedFaceCount, "no face removed");
                    t.Equal(0L, report.UnusedVertexCount, "no unused vertex");
                    t.Equal(1L, welded.Info().ComponentCount, "one piece");
                }
            }
        }

        private static void WeldErrors()
        {
            using (var cube = Shapes.Cube())
            {
                Shapes.Fails(() => Mending.Weld(cube, -1), WeftStatus.InvalidArgument, "tolerance is -1");
                Shapes.Fails(() => Mending.Weld(cube, double.NaN), WeftStatus.InvalidArgument, "tolerance");
            }
        }

        // A tall quad on the left, two unit quads on the right: vertex 6 lies
        // in the middle of the tall quad's edge 1 → 2.
        private static WeftMesh TJunction()
        {
            double[] positions = { 0, 0, 0, 1, 0, 0, 1, 2, 0, 0, 2, 0, 2, 0, 0, 2, 1, 0, 1, 1, 0, 2, 2, 0 };
            uint[] indices = { 0, 1, 2, 3, 1, 4, 5, 6, 6, 5, 7, 2 };
            return WeftMesh.Create(positions, Shapes.Repeat(4, 3), indices);
        }

        private static void TNodes()
        {
            using (var mesh = TJunction())
            {
                WeftTNode[] nodes = Mending.FindTNodes(mesh, Mending.DefaultWeldTolerance);
                t.Equal(1, nodes.Length, "one T-node");
                if (nodes.Length == 1)
                {
                    t.Equal(6u, nodes[0].Vertex, "vertex");
                    t.Equal(0u, nodes[0].Face, "face");
                    t.Equal(1u, nodes[0].EdgeStart, "edge start");
                    t.Equal(2u, nodes[0].EdgeEnd, "edge end");
                    t.True(Math.Abs(nodes[0].Parameter - 0.5) < 1e-12, "halfway, got " + nodes[0].Parameter);
                }
                int inserted;
                using (var repaired = Mending.RepairTNodes(mesh, Mending.DefaultWeldTolerance, out inserted))
                {
                    t.Equal(1, inserted, "inserted");
                    t.Sequence(new uint[] { 0, 1, 6, 2, 3 }, Shapes.Face(repaired, 0), "the tall quad became a pentagon");
                    t.Equal(0, Mending.FindTNodes(repaired, Mending.DefaultWeldTolerance).Length, "no T-node left");
                }
            }
            using (var cube = Shapes.Cube())
            {
                t.Equal(0, Mending.FindTNodes(cube, 0.001).Length, "a closed cube has none");
            }
        }

        private static void TNodeErrors()
        {
            using (var mesh = TJunction())
            {
                int inserted;
                Shapes.Fails(() => Mending.FindTNodes(mesh, -0.5), WeftStatus.InvalidArgument, "tolerance is -0.5");
                Shapes.Fails(() => Mending.RepairTNodes(mesh, -1, out inserted), WeftStatus.InvalidArgument, "tolerance is -1");
            }
        }

        private static void CullAdjacent()
        {
            using (var a = Shapes.Cube())
            using (var b = Shapes.CubeAt(1))
            using (var joined = Mending.Join(a, b))
            using (var welded = Mending.Weld(joined, 0.001))
            {
                int removed;
                using (var culled = Mending.CullAdjacent(welded, out removed))
                {
                    t.Equal(2, removed, "both copies of the shared wall");
                    t.Equal(10, culled.FaceCount, "faces left");
                    t.True(culled.Info().IsClosed, "one closed box");
                }
            }
        }

        private static void Orientation()
        {
            var indices = (uint[])UnitCube.Indices.Clone();
            Array.Reverse(indices, 0, 4);
            using (var broken = WeftMesh.Create(UnitCube.Positions, UnitCube.Sizes, indices))
            {
                t.False(broken.Info().IsOriented, "one face flipped");
                int flipped;
                using (var unified = Mending.UnifyOrientation(broken, out flipped))
                {
                    t.Equal(1, flipped, "faces reversed");
                    t.True(unified.Info().IsOriented, "oriented");
                    t.True(Mending.FaceNormals(unified)[2] < -0.99, "the bottom faces down again");
                }
            }
            using (var cube = Shapes.Cube())
            using (var flipped = Mending.Flip(cube))
            {
                t.Sequence(new uint[] { 0, 1, 3, 2 }, Shapes.Face(flipped, 0), "{a, b, c, d} becomes {a, d, c, b}");
                t.True(Mending.FaceNormals(flipped)[2] > 0.99, "the bottom faces up");
                WeftOrientReport report;
                using (var outward = Mending.OrientOutward(flipped, out report))
                {
                    t.Equal(1L, report.TurnedOutward, "the inside-out cube is turned outward");
                    t.Equal(6L, report.FlippedFaces, "every face reversed");
                    t.Equal(0L, report.OpenPieces, "the cube is closed");
                    t.True(Mending.FaceNormals(outward)[2] < -0.99, "the bottom faces down again");
                }
                t.True(Math.Abs(Mending.RelativeWeldTolerance(cube) - Math.Sqrt(3.0) * 1e-6) < 1e-15, "a millionth of the diagonal");
                t.Equal(0L, Mending.UnusedVertexCount(cube), "every vertex used");
            }
        }

        private static void OrientationErrors()
        {
            int n;
            t.Throws<ArgumentNullException>(() => Mending.Flip(null), "flip null");
            t.Throws<ArgumentNullException>(() => Mending.UnifyOrientation(null, out n), "unify null");
            t.Throws<ArgumentNullException>(() => Mending.CullAdjacent(null, out n), "cull null");
            var gone = Shapes.Cube();
            gone.Dispose();
            t.Throws<ObjectDisposedException>(() => Mending.Flip(gone), "flip disposed");
            t.Throws<ObjectDisposedException>(() => Mending.CullAdjacent(gone, out n), "cull disposed");
        }

        private static void Normals()
        {
            using (var cube = Shapes.Cube())
            {
                double[] faces = Mending.FaceNormals(cube);
                t.Equal(18, faces.Length, "3 per face");
                Shapes.Near(new[] { 0.0, 0.0, -1.0 }, new[] { faces[0], faces[1], faces[2] }, 1e-12, "bottom normal");
                Shapes.Near(new[] { 0.0, 0.0, 1.0 }, new[] { faces[3], faces[4], faces[5] }, 1e-12, "top normal");
                double[] vertices = Mending.VertexNormals(cube);
                double s = -1 / Math.Sqrt(3);
                Shapes.Near(new[] { s, s, s }, new[] { vertices[0], vertices[1], vertices[2] }, 1e-12, "vertex 0's normal");
            }
        }

        private static void Planarity()
        {
            double[] twisted = { 0, 0, 0, 1, 0, 0, 1, 1, 1, 0, 1, 0, 2, 0, 0 };
            uint[] indices = { 0, 1, 2, 3, 1, 4, 2 };
            using (var mesh = WeftMesh.Create(twisted, new uint[] { 4, 3 }, indices))
            {
                double[] deviations = Mending.Planarity(mesh);
                t.Equal(2, deviations.Length, "one per face");
                t.True(deviations[0] > 0.1, "the twisted quad is not planar, got " + deviations[0]);
                t.Equal(0.0, deviations[1], "a triangle is planar");
            }
            using (var cube = Shapes.Cube())
            {
                foreach (double d in Mending.Planarity(cube)) t.True(Math.Abs(d) < 1e-12, "cube faces planar");
            }
        }

        private static void NakedBoundaries()
        {
            using (var grid = Shapes.Grid(0))
            {
                PolylineSet boundaries = Mending.NakedBoundaries(grid);
                t.Equal(1, boundaries.Count, "one border");
                t.Equal(8, boundaries.PointCounts[0], "eight boundary vertices");
                t.True(boundaries.Closed[0], "closed");
                t.Equal(24, boundaries.Points.Length, "3 doubles per point");
            }
            using (var cube = Shapes.Cube())
            {
                t.Equal(0, Mending.NakedBoundaries(cube).Count, "a closed cube has no border");
            }
        }

        private static void QueryErrors()
        {
            var gone = Shapes.Cube();
            gone.Dispose();
            t.Throws<ObjectDisposedException>(() => Mending.FaceNormals(gone), "face normals");
            t.Throws<ObjectDisposedException>(() => Mending.VertexNormals(gone), "vertex normals");
            t.Throws<ObjectDisposedException>(() => Mending.Planarity(gone), "planarity");
            t.Throws<ObjectDisposedException>(() => Mending.NakedBoundaries(gone), "naked boundaries");
        }
    }
}
