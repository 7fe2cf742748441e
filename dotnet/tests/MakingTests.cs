using System;

namespace Weft.Tests
{
    /// <summary>Delaunay, Voronoi, mesh from grid, stellate and the primitives.</summary>
    public static class MakingTests
    {
        private static Runner t;

        public static void Register(Runner runner)
        {
            t = runner;
            t.Run("Delaunay of a square and its centre", DelaunaySquare);
            t.Run("Delaunay refuses collinear points and a degenerate plane", DelaunayErrors);
            t.Run("Voronoi of two points in a rectangle", VoronoiTwoPoints);
            t.Run("Voronoi refuses a bad radius; cells copy refuses a small buffer", VoronoiErrors);
            t.Run("mesh from grid: open, closed, triangulated", MeshFromGrid);
            t.Run("mesh from grid refuses counts that do not match", MeshFromGridErrors);
            t.Run("stellate a cube", StellateCube);
            t.Run("stellate refuses a wrong height count", StellateErrors);
            t.Run("plane grid", PlaneGrid);
            t.Run("box and UV sphere are closed", BoxAndSphere);
            t.Run("platonic solids", Platonic);
            t.Run("sided solids", Sided);
            t.Run("primitives refuse bad sizes, counts and kinds", PrimitiveErrors);
        }

        private static readonly double[] SquareAndCentre = { 0, 0, 0, 2, 0, 0, 2, 2, 0, 0, 2, 0, 1, 1, 0 };

        private static void DelaunaySquare()
        {
            var points = new double[SquareAndCentre.Length + 3];
            SquareAndCentre.CopyTo(points, 0);
            points[15] = 2; // a repeat of point 1
            int merged;
            using (var mesh = Making.Delaunay(points, WeftPlane.WorldXY, out merged))
            {
                t.Equal(1, merged, "merged points");
                t.Equal(5, mesh.VertexCount, "distinct points");
                t.Equal(4, mesh.FaceCount, "triangles");
                double[] normals = Mending.FaceNormals(mesh);
                t.True(Math.Abs(normals[2] - 1) < 1e-12, "triangles face +z, got " + normals[2]);
            }
            // Seen from below (y axis reversed), the triangles face -z.
            var below = new WeftPlane(new double[] { 0, 0, 0 }, new double[] { 1, 0, 0 }, new double[] { 0, -1, 0 });
            using (var mesh = Making.Delaunay(SquareAndCentre, below, out merged))
            {
                t.True(Math.Abs(Mending.FaceNormals(mesh)[2] + 1) < 1e-12, "triangles face -z");
            }
        }

        private static void DelaunayErrors()
        {
            Shapes.Fails(() => Making.Delaunay(new double[] { 0, 0, 0, 1, 0, 0, 2, 0, 0 }), WeftStatus.DegenerateInput, "collinear");
            var flat = new WeftPlane(new double[] { 0, 0, 0 }, new double[] { 1, 0, 0 }, new double[] { 2, 0, 0 });
            int merged;
            Shapes.Fails(() => Making.Delaunay(SquareAndCentre, flat, out merged), WeftStatus.DegenerateInput, "parallel");
            Shapes.Fails(() => Making.Delaunay(new double[] { 0, 0 }), WeftStatus.CountMismatch, "not 3 per point");
        }

        private static readonly double[] Rectangle = { -1, -1, 0, 2, -1, 0, 2, 1, 0, -1, 1, 0 };

        private static void VoronoiTwoPoints()
        {
            using (var cells = Making.Voronoi(new double[] { 0, 0, 0, 1, 0, 0 }, null, Rectangle, 0))
            {
                t.Equal(2, cells.Count, "a cell per point");
                t.Sequence(new uint[] { 4, 4 }, cells.GetSizes(), "cell sizes");
                t.Equal(8, cells.CornerCount, "corners");
                double[] corners = cells.GetCorners();
                double maxX = double.MinValue;
                for (int i = 0; i < 4; i++) maxX = Math.Max(maxX, corners[3 * i]);
                t.True(Math.Abs(maxX - 0.5) < 1e-12, "the first cell ends at the bisector x = 0.5, got " + maxX);
                var sizes = new uint[2];
                var copied = new double[24];
                cells.CopyTo(sizes, copied);
                t.Sequence(corners, copied, "copied corners");
                using (var mesh = cells.ToMesh())
                {
                    t.Equal(2, mesh.FaceCount, "one face per cell");
                    t.Equal(8, mesh.VertexCount, "cells share no vertices");
                }
                cells.Dispose();
                t.Throws<ObjectDisposedException>(() => cells.ToMesh(), "cells after dispose");
            }
            // A point outside the boundary gets an empty cell.
            using (var cells = Making.Voronoi(new double[] { 0, 0, 0, 5, 5, 0 }, WeftPlane.WorldXY, Rectangle, 0))
            {
                t.Sequence(new uint[] { 4, 0 }, cells.GetSizes(), "the outside point's cell is empty");
            }
        }

        private static void VoronoiErrors()
        {
            Shapes.Fails(() => Making.Voronoi(new double[] { 0, 0, 0, 1, 0, 0 }, null, null, -1), WeftStatus.InvalidArgument, "radius");
            double[] bowTie = { 0, 0, 0, 1, 1, 0, 1, 0, 0, 0, 1, 0 };
            Shapes.Fails(() => Making.Voronoi(new double[] { 0.5, 0.2, 0 }, null, bowTie, 0), WeftStatus.InvalidArgument, "not a simple polygon");
            using (var cells = Making.Voronoi(new double[] { 0, 0, 0, 1, 0, 0 }, null, Rectangle, 0))
            {
                Shapes.Fails(() => cells.CopyTo(new uint[2], new double[23]), WeftStatus.BufferTooSmall, "out_corners");
            }
        }

        private static double[] GridPoints(int u, int v)
        {
            var points = new double[3 * u * v];
            for (int j = 0; j < v; j++)
                for (int i = 0; i < u; i++)
                {
                    points[3 * (j * u + i)] = i;
                    points[3 * (j * u + i) + 1] = j;
                }
            return points;
        }

        private static void MeshFromGrid()
        {
            using (var open = Making.MeshFromGrid(GridPoints(4, 3), 4, 3, false, false, false))
            {
                t.Equal(6, open.FaceCount, "3 × 2 quads");
                t.Sequence(new uint[] { 0, 1, 5, 4 }, Shapes.Face(open, 0), "the first quad runs u then v");
                t.Equal(10, open.Info().NakedEdgeCount, "naked edges of the open grid");
            }
            using (var closed = Making.MeshFromGrid(GridPoints(4, 3), 4, 3, true, false, false))
            {
                t.Equal(8, closed.FaceCount, "4 × 2 quads when closed in u");
                t.Sequence(new uint[] { 3, 0, 4, 7 }, Shapes.Face(closed, 3), "the wrapping quad");
            }
            using (var triangles = Making.MeshFromGrid(GridPoints(4, 3), 4, 3, false, false, true))
            {
                t.Equal(12, triangles.FaceCount, "two triangles per quad");
            }
        }

        private static void MeshFromGridErrors()
        {
            Shapes.Fails(() => Making.MeshFromGrid(GridPoints(4, 3), 3, 3, false, false, false), WeftStatus.InvalidArgument, "3 × 3");
            Shapes.Fails(() => Making.MeshFromGrid(GridPoints(4, 3), -4, 3, false, false, false), WeftStatus.InvalidArgument, "uCount is -4");
        }

        private static void StellateCube()
        {
            using (var cube = Shapes.Cube())
            using (var star = Making.Stellate(cube, 1.0))
            {
                t.Equal(8 + 6, star.VertexCount, "an apex per face");
                t.Equal(24, star.FaceCount, "four triangles per quad");
                Shapes.Near(new[] { 0.5, 0.5, -1.0 }, Shapes.Vertex(star, 8), 1e-12, "apex of the bottom face, below it");
                t.True(star.Info().IsClosed, "closed");
            }
        }

        private static void StellateErrors()
        {
            using (var cube = Shapes.Cube())
            {
                Shapes.Fails(() => Making.Stellate(cube, 1, 2, 3, 4, 5), WeftStatus.InvalidArgument, "5 heights were given for a mesh of 6 faces");
                Shapes.Fails(() => Making.Stellate(cube, 1, 1, 1, 1, 1, double.NaN), WeftStatus.InvalidArgument, "face 5");
            }
        }

        private static void PlaneGrid()
        {
            using (var plane = Making.PlaneGrid(4, 2, 4, 2))
            {
                t.Equal(15, plane.VertexCount, "5 × 3 vertices");
                t.Equal(8, plane.FaceCount, "4 × 2 quads");
                Shapes.Near(new[] { -2.0, -1.0, 0.0 }, Shapes.Vertex(plane, 0), 1e-12, "a corner, centred on the origin");
                t.True(Math.Abs(Mending.FaceNormals(plane)[2] - 1) < 1e-12, "faces +z");
            }
        }

        private static void BoxAndSphere()
        {
            using (var box = Making.Box(1, 2, 3, 2, 2, 2))
            {
                t.Equal(24, box.FaceCount, "4 quads per side");
                t.Equal(26, box.VertexCount, "welded");
                WeftMeshInfo info = box.Info();
                t.True(info.IsClosed && info.IsOriented, "closed and oriented");
            }
            using (var sphere = Making.UvSphere(2, 8, 4))
            {
                t.Equal(8 * 3 + 2, sphere.VertexCount, "rings and poles");
                t.Equal(32, sphere.FaceCount, "faces");
                t.True(sphere.Info().IsClosed, "closed");
                double[] p = sphere.GetPositions();
                for (int v = 0; v < sphere.VertexCount; v++)
                {
                    double r = Math.Sqrt(p[3 * v] * p[3 * v] + p[3 * v + 1] * p[3 * v + 1] + p[3 * v + 2] * p[3 * v + 2]);
                    if (Math.Abs(r - 2) > 1e-12) { t.Fail("vertex " + v + " at radius " + r); break; }
                }
            }
        }

        private static void Platonic()
        {
            int[] faces = { 4, 6, 8, 12, 20 };
            int[] vertices = { 4, 8, 6, 20, 12 };
            for (int k = 0; k < 5; k++)
            {
                using (var solid = Making.Platonic((PlatonicSolid)k, 3))
                {
                    t.Equal(faces[k], solid.FaceCount, ((PlatonicSolid)k) + " faces");
                    t.Equal(vertices[k], solid.VertexCount, ((PlatonicSolid)k) + " vertices");
                    t.True(solid.Info().IsClosed, ((PlatonicSolid)k) + " closed");
                    double[] v0 = Shapes.Vertex(solid, 0);
                    t.True(Math.Abs(Math.Sqrt(v0[0] * v0[0] + v0[1] * v0[1] + v0[2] * v0[2]) - 3) < 1e-12, "vertex 0 on the sphere of radius 3");
                }
            }
            using (var dodecahedron = Making.Platonic(PlatonicSolid.Dodecahedron, 1))
            {
                t.Sequence(Shapes.Repeat(5, 12), dodecahedron.GetFaceSizes(), "pentagons");
            }
        }

        private static void Sided()
        {
            using (var prism = Making.Sided(SidedSolid.Prism, 6, 1, 2))
            {
                t.Equal(12, prism.VertexCount, "prism vertices");
                t.Equal(8, prism.FaceCount, "two hexagons and six quads");
            }
            using (var antiprism = Making.Sided(SidedSolid.Antiprism, 5, 1, 2))
            {
                t.Equal(12, antiprism.FaceCount, "two pentagons and ten triangles");
            }
            using (var pyramid = Making.Sided(SidedSolid.Pyramid, 4, 1, 2))
            {
                t.Equal(5, pyramid.VertexCount, "pyramid vertices");
                t.True(pyramid.Info().IsClosed, "closed");
            }
            using (var dipyramid = Making.Sided(SidedSolid.Dipyramid, 3, 1, 2))
            {
                t.Equal(6, dipyramid.FaceCount, "six triangles");
            }
        }

        private static void PrimitiveErrors()
        {
            Shapes.Fails(() => Making.PlaneGrid(1, -1, 2, 2), WeftStatus.InvalidArgument, "size_y");
            Shapes.Fails(() => Making.Box(1, 1, 1, 0, 1, 1), WeftStatus.InvalidArgument, "u_count");
            Shapes.Fails(() => Making.UvSphere(1, 8, 1), WeftStatus.InvalidArgument, "v_count is 1");
            Shapes.Fails(() => Making.Platonic((PlatonicSolid)5, 1), WeftStatus.InvalidArgument, "kind is 5");
            Shapes.Fails(() => Making.Platonic(PlatonicSolid.Hexahedron, 0), WeftStatus.InvalidArgument, "radius is 0");
            Shapes.Fails(() => Making.Sided(SidedSolid.Prism, 2, 1, 1), WeftStatus.InvalidArgument, "sides is 2");
        }
    }
}
