using System;

namespace Weft.Tests
{
    /// <summary>Weaverbird's toolbar: linear subdivisions, smoothing, transforms, extract.</summary>
    public static class ToolbarTests
    {
        private static Runner t;

        public static void Register(Runner runner)
        {
            t = runner;
            t.Run("split polygons of a cube", SplitPolygons);
            t.Run("split triangles of an octahedron", SplitTriangles);
            t.Run("constant quads split of mixed faces", ConstantQuadsSplit);
            t.Run("midedge of a cube is a cuboctahedron", Midedge);
            t.Run("inner polygons of a cube", InnerPolygons);
            t.Run("Sierpinski triangles of an octahedron", SierpinskiTriangles);
            t.Run("linear subdivisions refuse more than 20 levels and non-triangles", LinearErrors);
            t.Run("Laplacian smoothing flattens a raised centre", Laplacian);
            t.Run("LaplacianHC keeps more of the bump than Laplacian", LaplacianHc);
            t.Run("LaplacianHC activation and direction", LaplacianHcInputs);
            t.Run("blur moves a peak to its neighbours", Blur);
            t.Run("tile a cube by fans and hands", Tile);
            t.Run("smoothing refuses bad modes, betas and value counts", SmoothingErrors);
            t.Run("offset a grid along +z", Offset);
            t.Run("thicken a grid into a closed solid", Thicken);
            t.Run("mesh window and picture frame of a cube", WindowAndFrame);
            t.Run("offsets and insets refuse bad types and distance counts", TransformErrors);
            t.Run("Sierpinski carpet of a quad", SierpinskiCarpet);
            t.Run("bevel edges and vertices of a cube", Bevels);
            t.Run("carpet and bevels refuse non-quads and bad fractions", CarpetBevelErrors);
            t.Run("dual of a cube is an octahedron", Dual);
            t.Run("edges of a cube", Edges);
            t.Run("reroute faces of a cube", Reroute);
            t.Run("mesh from lines", MeshFromLines);
            t.Run("dual, edges, reroute and mesh from lines refuse bad input", ExtractErrors);
        }

        private static void SplitPolygons()
        {
            using (var cube = Shapes.Cube())
            using (var split = Toolbar.SplitPolygons(cube, 1))
            {
                ClosedWithCounts(split, 26, "V + E + F", 24, "a quad per corner");
                // No smoothing: every vertex stays on the unit cube.
                double[] p = split.GetPositions();
                bool onCube = true;
                foreach (double c in p) onCube &= c >= -1e-12 && c <= 1 + 1e-12;
                t.True(onCube, "every vertex within the cube");
                Shapes.Near(new[] { 0.5, 0.5, 0.0 }, Shapes.Vertex(split, 20), 1e-12, "face 0's centroid");
            }
        }

        /// <summary>Checks a result is closed and has the given numbers of vertices and faces, each with what it counts.</summary>
        private static void ClosedWithCounts(WeftMesh mesh, int vertices, string whatVertices, int faces, string whatFaces)
        {
            t.Equal(vertices, mesh.VertexCount, whatVertices);
            t.Equal(faces, mesh.FaceCount, whatFaces);
            t.True(mesh.Info().IsClosed, "closed");
        }

        private static void SplitTriangles()
        {
            using (var octa = Shapes.Octahedron())
            using (var split = Toolbar.SplitTriangles(octa, 2))
            {
                t.Equal(128, split.FaceCount, "16 per triangle");
                t.True(split.Info().IsClosed, "closed");
                Shapes.Near(new[] { 1.0, 0.0, 0.0 }, Shapes.Vertex(split, 0), 1e-12, "original vertices stay");
            }
        }

        private static void ConstantQuadsSplit()
        {
            // A quad and a triangle side by side.
            double[] positions = { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 2, 0, 0 };
            using (var mesh = WeftMesh.Create(positions, new uint[] { 4, 3 }, new uint[] { 0, 1, 2, 3, 1, 4, 2 }))
            using (var split = Toolbar.ConstantQuadsSplit(mesh, 1))
            {
                t.Equal(8, split.FaceCount, "4 quads and 4 triangles");
                uint[] sizes = split.GetFaceSizes();
                int quads = 0, triangles = 0;
                foreach (uint s in sizes) { if (s == 4) quads++; if (s == 3) triangles++; }
                t.Equal(4, quads, "quads");
                t.Equal(4, triangles, "triangles");
            }
        }

        private static void Midedge()
        {
            using (var cube = Shapes.Cube())
            using (var mid = Toolbar.Midedge(cube, 1))
            {
                ClosedWithCounts(mid, 12, "a vertex per edge", 14, "a face per face and per vertex");
            }
        }

        private static void InnerPolygons()
        {
            using (var cube = Shapes.Cube())
            using (var inner = Toolbar.InnerPolygons(cube, 1, 0.5))
            {
                ClosedWithCounts(inner, 8 + 24, "an inner corner per face corner", 30, "an inner face and four quads per face");
            }
        }

        private static void SierpinskiTriangles()
        {
            using (var octa = Shapes.Octahedron())
            using (var sierpinski = Toolbar.SierpinskiTriangles(octa, 1))
            {
                t.Equal(24, sierpinski.FaceCount, "three corner triangles per face");
                t.Equal(24L, sierpinski.Info().NakedEdgeCount, "a hole of three naked edges per face");
            }
        }

        private static void LinearErrors()
        {
            using (var cube = Shapes.Cube())
            {
                Shapes.Fails(() => Toolbar.SplitPolygons(cube, 21), WeftStatus.InvalidArgument, "levels is 21");
                Shapes.Fails(() => Toolbar.ConstantQuadsSplit(cube, 21), WeftStatus.InvalidArgument, "levels is 21");
                Shapes.Fails(() => Toolbar.Midedge(cube, 21), WeftStatus.InvalidArgument, "levels is 21");
                Shapes.Fails(() => Toolbar.SierpinskiTriangles(cube, 21), WeftStatus.InvalidArgument, "levels is 21");
                Shapes.Fails(() => Toolbar.SplitTriangles(cube, 1), WeftStatus.NotTriangles, "face 0 has 4 vertices");
                Shapes.Fails(() => Toolbar.InnerPolygons(cube, 1, 1.0), WeftStatus.InvalidArgument, "pull is 1");
                Shapes.Fails(() => Toolbar.Midedge(cube, -2), WeftStatus.InvalidArgument, "levels is -2");
            }
        }

        private static void Laplacian()
        {
            using (var grid = Shapes.Grid(1))
            using (var smooth = Toolbar.LaplacianSmooth(grid, 1, 1, SmoothNakedEdges.Fixed))
            {
                // The centre's four neighbours are on the boundary at z = 0.
                Shapes.Near(new[] { 1.0, 1.0, 0.0 }, Shapes.Vertex(smooth, 4), 1e-12, "the centre jumps to its neighbours' average");
                Shapes.Near(new[] { 2.0, 2.0, 0.0 }, Shapes.Vertex(smooth, 8), 1e-12, "a fixed corner stays");
                t.Sequence(grid.GetFaceIndices(), smooth.GetFaceIndices(), "faces unchanged");
            }
            using (var grid = Shapes.Grid(1))
            using (var none = Toolbar.LaplacianSmooth(grid, 0, 0.5, SmoothNakedEdges.Smooth))
            {
                t.Sequence(grid.GetPositions(), none.GetPositions(), "0 iterations change nothing");
            }
        }

        private static void LaplacianHc()
        {
            using (var grid = Shapes.Grid(1))
            using (var hc = Toolbar.LaplacianHcSmooth(grid, 1, 0, 0.6, SmoothNakedEdges.Fixed))
            {
                double z = Shapes.Vertex(hc, 4)[2];
                t.True(z > 0 && z < 1, "the centre keeps part of its height, got " + z);
                t.Equal(9, hc.VertexCount, "vertices");
            }
        }

        private static void LaplacianHcInputs()
        {
            using (var grid = Shapes.Grid(1))
            {
                var activation = new double[9];
                using (var still = Toolbar.LaplacianHcSmooth(grid, 3, 0, 0.6, SmoothNakedEdges.Smooth, SmoothDirection.Free, activation))
                {
                    t.Sequence(grid.GetPositions(), still.GetPositions(), "no active vertex, no change");
                }
                activation[4] = 1;
                using (var centre = Toolbar.LaplacianHcSmooth(grid, 1, 0, 0.6, SmoothNakedEdges.Smooth, SmoothDirection.Free, activation))
                {
                    t.True(Shapes.Vertex(centre, 4)[2] < 1, "the active centre moves down");
                    t.Equal(Shapes.Vertex(grid, 1)[0], Shapes.Vertex(centre, 1)[0], "an inactive side vertex stays");
                }
                using (var flat = Toolbar.LaplacianHcSmooth(grid, 2, 0, 0.6, SmoothNakedEdges.Fixed, SmoothDirection.Tangential, null))
                {
                    t.True(Math.Abs(Shapes.Vertex(flat, 4)[2] - 1) < 1e-12, "tangentially the centre keeps its height");
                }
                Shapes.Fails(() => Toolbar.LaplacianHcSmooth(grid, 1, 0, 0.6, SmoothNakedEdges.Fixed, SmoothDirection.Free, new double[8]),
                             WeftStatus.InvalidArgument, "activation has 8 values but the mesh has 9 vertices");
                Shapes.Fails(() => Toolbar.LaplacianHcSmooth(grid, 1, 0, 0.6, SmoothNakedEdges.Fixed, (SmoothDirection)3, null),
                             WeftStatus.InvalidArgument, "direction is 3");
            }
        }

        private static void Tile()
        {
            using (var cube = Shapes.Cube())
            {
                using (var fan = Toolbar.Tile(cube, TileFill.TriangleFan, TileFaces.All))
                {
                    t.Equal(14, fan.VertexCount, "a centroid per face");
                    t.Equal(24, fan.FaceCount, "four triangles per quad");
                    WeftMeshInfo info = fan.Info();
                    t.True(info.IsClosed, "still closed: the seams stay welded");
                }
                using (var stitch = Toolbar.Tile(cube, TileFill.QuadStitch, TileFaces.Quads))
                {
                    t.Equal(6, stitch.FaceCount, "a quad's stitch is the quad");
                }
                using (var kept = Toolbar.Tile(cube, TileFill.TriangleHand, TileFaces.Triangles))
                {
                    t.Equal(6, kept.FaceCount, "no triangle to fill: the quads stay");
                }
                Shapes.Fails(() => Toolbar.Tile(cube, (TileFill)8, TileFaces.All), WeftStatus.InvalidArgument, "fill is 8");
                Shapes.Fails(() => Toolbar.Tile(cube, TileFill.Best, (TileFaces)3), WeftStatus.InvalidArgument, "faces is 3");
            }
        }

        private static void Blur()
        {
            using (var grid = Shapes.Grid(0))
            {
                var values = new double[9];
                values[4] = 1;
                double[] blurred = Toolbar.BlurValues(grid, values, 1, 1, 1, SmoothNakedEdges.Fixed);
                t.Equal(9, blurred.Length, "one value per vertex");
                t.True(Math.Abs(blurred[4]) < 1e-12, "the peak takes its neighbours' average 0, got " + blurred[4]);
                t.Equal(0.0, blurred[0], "a fixed boundary value stays");
                double[] colours = Toolbar.BlurValues(grid, new double[27], 3, 2, 0.5, SmoothNakedEdges.Smooth);
                t.Equal(27, colours.Length, "three components per vertex");
            }
        }

        private static void SmoothingErrors()
        {
            using (var grid = Shapes.Grid(0))
            {
                Shapes.Fails(() => Toolbar.LaplacianSmooth(grid, 3, 0.5, (SmoothNakedEdges)7), WeftStatus.InvalidArgument, "naked_edges is 7");
                Shapes.Fails(() => Toolbar.LaplacianHcSmooth(grid, 3, 0, 2, SmoothNakedEdges.Smooth), WeftStatus.InvalidArgument, "beta is 2");
                Shapes.Fails(() => Toolbar.BlurValues(grid, new double[8], 1, 1, 0.5, SmoothNakedEdges.Fixed), WeftStatus.InvalidArgument, "8 values");
                Shapes.Fails(() => Toolbar.LaplacianSmooth(grid, -1, 0.5, SmoothNakedEdges.Fixed), WeftStatus.InvalidArgument, "iterations is -1");
            }
        }

        private static void Offset()
        {
            using (var grid = Shapes.Grid(0))
            using (var offset = Toolbar.OffsetMesh(grid, 0.5, OffsetType.Diagonal))
            {
                double[] p = offset.GetPositions();
                bool lifted = true;
                for (int v = 0; v < 9; v++) lifted &= Math.Abs(p[3 * v + 2] - 0.5) < 1e-12;
                t.True(lifted, "every vertex at z = 0.5");
                t.Equal(4, offset.FaceCount, "faces kept");
            }
        }

        private static void Thicken()
        {
            using (var grid = Shapes.Grid(0))
            using (var solid = Toolbar.ThickenMesh(grid, 0.25, OffsetType.PlanesIntersection))
            {
                t.Equal(18, solid.VertexCount, "the surface and its offset");
                t.Equal(4 + 4 + 8, solid.FaceCount, "both sides and a quad per naked edge");
                WeftMeshInfo info = solid.Info();
                t.True(info.IsClosed && info.IsOriented, "closed and oriented");
                Shapes.Near(new[] { 1.0, 1.0, 0.25 }, Shapes.Vertex(solid, 9 + 4), 1e-12, "vertex v's offset is v + 9");
            }
        }

        private static void WindowAndFrame()
        {
            using (var cube = Shapes.Cube())
            {
                using (var window = Toolbar.MeshWindow(cube, new[] { 0.25 }, InsetMode.EdgeFraction))
                {
                    t.Equal(30, window.FaceCount, "four frame quads and an inner face per face");
                    t.True(window.Info().IsClosed, "closed");
                }
                using (var frame = Toolbar.PictureFrame(cube, new[] { 0.1 }, InsetMode.Parallelogram))
                {
                    t.Equal(24, frame.FaceCount, "four frame quads per face");
                    t.Equal(6, Mending.NakedBoundaries(frame).Count, "a hole per face");
                }
                var perFace = new[] { 0.1, 0.2, 0.1, 0.2, 0.1, 0.2 };
                using (var window = Toolbar.MeshWindow(cube, perFace, InsetMode.EdgeFraction))
                {
                    t.Equal(30, window.FaceCount, "one distance per face");
                }
            }
        }

        private static void TransformErrors()
        {
            using (var cube = Shapes.Cube())
            {
                Shapes.Fails(() => Toolbar.OffsetMesh(cube, 1, (OffsetType)3), WeftStatus.InvalidArgument, "offset_type is 3");
                Shapes.Fails(() => Toolbar.ThickenMesh(cube, double.PositiveInfinity, OffsetType.Diagonal), WeftStatus.InvalidArgument, "distance");
                Shapes.Fails(() => Toolbar.MeshWindow(cube, new[] { 0.1, 0.2 }, InsetMode.EdgeFraction), WeftStatus.InvalidArgument,
                    "2 distances were given for a mesh of 6 faces");
                Shapes.Fails(() => Toolbar.PictureFrame(cube, new[] { 0.5 }, InsetMode.EdgeFraction), WeftStatus.InvalidArgument, "0.5");
            }
        }

        private static void SierpinskiCarpet()
        {
            using (var quad = Making.PlaneGrid(3, 3, 1, 1))
            using (var carpet = Toolbar.SierpinskiCarpet(quad, 2))
            {
                t.Equal(64, carpet.FaceCount, "8 × 8 quads");
                t.Equal(1 + 1 + 8, Mending.NakedBoundaries(carpet).Count, "the outline and nine holes");
            }
        }

        private static void Bevels()
        {
            using (var cube = Shapes.Cube())
            {
                using (var edges = Toolbar.BevelEdges(cube, 0.25))
                {
                    ClosedWithCounts(edges, 24, "vertices", 26, "rhombicuboctahedron: 6 + 12 + 8 faces");
                }
                using (var vertices = Toolbar.BevelVertices(cube, 0.25))
                {
                    t.Equal(14, vertices.FaceCount, "6 octagons and 8 triangles");
                    t.Equal(24, vertices.VertexCount, "vertices");
                    t.Equal(8u, vertices.GetFaceSizes()[0], "an octagon first");
                }
            }
        }

        private static void CarpetBevelErrors()
        {
            using (var octa = Shapes.Octahedron())
            using (var cube = Shapes.Cube())
            {
                Shapes.Fails(() => Toolbar.SierpinskiCarpet(octa, 1), WeftStatus.InvalidArgument, "needs a quad mesh");
                Shapes.Fails(() => Toolbar.BevelEdges(cube, 0), WeftStatus.InvalidArgument, "fraction is 0");
                Shapes.Fails(() => Toolbar.BevelVertices(cube, 0.5), WeftStatus.InvalidArgument, "fraction is 0.5");
            }
        }

        private static void Dual()
        {
            using (var cube = Shapes.Cube())
            {
                using (var dual = Toolbar.Dual(cube, DualMode.VertexAverage))
                {
                    t.Equal(6, dual.VertexCount, "a vertex per face");
                    t.Equal(8, dual.FaceCount, "a face per vertex");
                    t.Sequence(Shapes.Repeat(3, 8), dual.GetFaceSizes(), "triangles");
                    Shapes.Near(new[] { 0.5, 0.5, 0.0 }, Shapes.Vertex(dual, 0), 1e-12, "face 0's centroid");
                }
                using (var kept = Toolbar.Dual(cube, DualMode.KeepSize))
                {
                    Shapes.Near(new[] { 0.5, 0.5, 0.0 }, Shapes.Vertex(kept, 0), 1e-12, "scaled to the cube's box");
                }
            }
        }

        private static void Edges()
        {
            using (var cube = Shapes.Cube())
            {
                t.Equal(12, Toolbar.EdgeCount(cube), "edges");
                uint[] pairs = Toolbar.Edges(cube);
                t.Equal(24, pairs.Length, "two indices per edge");
                t.Sequence(new uint[] { 0, 1 }, new[] { pairs[0], pairs[1] }, "the first edge, sorted");
                double[] segments = Toolbar.EdgeSegments(cube);
                t.Equal(72, segments.Length, "six doubles per edge");
                Shapes.Near(new double[] { 0, 0, 0, 1, 0, 0 }, new[] { segments[0], segments[1], segments[2], segments[3], segments[4], segments[5] }, 0, "the first segment");
            }
        }

        private static void Reroute()
        {
            using (var cube = Shapes.Cube())
            {
                using (var once = Toolbar.RerouteFaces(cube, 1))
                {
                    t.Sequence(new uint[] { 2, 3, 1, 0 }, Shapes.Face(once, 0), "shifted by one");
                }
                using (var back = Toolbar.RerouteFaces(cube, -5))
                {
                    t.Sequence(new uint[] { 1, 0, 2, 3 }, Shapes.Face(back, 0), "-5 wraps to -1");
                }
            }
        }

        private static void MeshFromLines()
        {
            // A unit square with one diagonal, and a dangling segment.
            double[] segments =
            {
                0, 0, 0, 1, 0, 0, 1, 0, 0, 1, 1, 0, 1, 1, 0, 0, 1, 0, 0, 1, 0, 0, 0, 0,
                0, 0, 0, 1, 1, 0, 1, 1, 0, 3, 3, 0,
            };
            using (var mesh = Toolbar.MeshFromLines(segments, 1e-6, 4))
            {
                t.Equal(2, mesh.FaceCount, "two triangles");
                t.Sequence(new uint[] { 3, 3 }, mesh.GetFaceSizes(), "triangles");
            }
            using (var mesh = Toolbar.MeshFromLines(new double[] { 0, 0, 0, 1, 0, 0, 1, 0, 0, 1, 1, 0, 1, 1, 0, 0, 1, 0, 0, 1, 0, 0, 0, 0 }, 1e-6, 4))
            {
                t.Equal(1, mesh.FaceCount, "one quad");
            }
        }

        private static void ExtractErrors()
        {
            using (var cube = Shapes.Cube())
            {
                Shapes.Fails(() => Toolbar.Dual(cube, (DualMode)5), WeftStatus.InvalidArgument, "dual_mode is 5");
                Shapes.Fails(() => Toolbar.MeshFromLines(new double[] { 0, 0, 0, 1, 0, 0 }, 0, 2), WeftStatus.InvalidArgument, "max_valence is 2");
                Shapes.Fails(() => Toolbar.MeshFromLines(new double[] { 0, 0, 0, 1, 0 }, 0, 4), WeftStatus.CountMismatch, "6 per segment");
                t.Throws<ArgumentNullException>(() => Toolbar.RerouteFaces(null, 1), "reroute null");
                var gone = Shapes.Cube();
                gone.Dispose();
                t.Throws<ObjectDisposedException>(() => Toolbar.Edges(gone), "edges of a disposed mesh");
            }
        }
    }
}
