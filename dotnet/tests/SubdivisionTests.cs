using System;
using System.Linq;

namespace Weft.Tests
{
    /// <summary>Catmull-Clark, Loop, triangulation, parent faces and the refiner.</summary>
    public static class SubdivisionTests
    {
        private static Runner t;

        public static void Register(Runner runner)
        {
            t = runner;
            t.Run("Catmull-Clark of a cube", CatmullClarkCube);
            t.Run("Catmull-Clark refuses an unknown naked-edge mode and negative levels", CatmullClarkErrors);
            t.Run("Loop of an octahedron", LoopOctahedron);
            t.Run("Loop needs triangles", LoopNeedsTriangles);
            t.Run("triangulate a cube", TriangulateCube);
            t.Run("triangulate with parent faces: a quad, a hexagon and a triangle", TriangulateWithParents);
            t.Run("as triangles: a copy of a triangle mesh, the triangulation of others, with the split count", AsTriangles);
            t.Run("triangulate a disposed mesh is refused", TriangulateDisposed);
            t.Run("subdivision face count and parent faces", FaceCountAndParents);
            t.Run("subdivision into the caller's arrays", SubdivideIntoCallerArrays);
            t.Run("face count refuses an unknown scheme", FaceCountUnknownScheme);
            t.Run("refiner re-evaluated with moved positions equals a fresh subdivision", RefinerMatchesFresh);
            t.Run("refiner mesh equals Catmull-Clark", RefinerMesh);
            t.Run("refiner errors: wrong count, small buffer, Loop on quads, after dispose", RefinerErrors);
        }

        private static void CatmullClarkCube()
        {
            using (var cube = Shapes.Cube())
            using (var once = Subdivision.CatmullClark(cube, 1, NakedEdges.Smooth))
            {
                t.Equal(8 + 12 + 6, once.VertexCount, "vertices after one level");
                t.Equal(24, once.FaceCount, "faces after one level");
                t.True(once.Info().IsClosed, "still closed");
                // Face points come last: face 0's (the bottom) is its centroid.
                Shapes.Near(new[] { 0.5, 0.5, 0.0 }, Shapes.Vertex(once, 20), 1e-12, "face point of face 0");
            }
        }

        private static void CatmullClarkErrors()
        {
            using (var cube = Shapes.Cube())
            {
                Shapes.Fails(() => Subdivision.CatmullClark(cube, 1, (NakedEdges)7), WeftStatus.InvalidArgument, "naked_edges is 7");
                Shapes.Fails(() => Subdivision.CatmullClark(cube, -1, NakedEdges.Smooth), WeftStatus.InvalidArgument, "levels is -1");
            }
        }

        private static void LoopOctahedron()
        {
            using (var octa = Shapes.Octahedron())
            using (var once = Subdivision.Loop(octa, 1, NakedEdges.Smooth))
            {
                t.Equal(6 + 12, once.VertexCount, "vertices");
                t.Equal(32, once.FaceCount, "faces");
                t.True(once.Info().IsClosed, "closed");
            }
        }

        private static void LoopNeedsTriangles()
        {
            using (var cube = Shapes.Cube())
            {
                Shapes.Fails(() => Subdivision.Loop(cube, 1, NakedEdges.Smooth), WeftStatus.NotTriangles,
                    "face 0 has 4 vertices but this operation needs a triangle mesh; triangulate the mesh first");
            }
        }

        private static void TriangulateCube()
        {
            using (var cube = Shapes.Cube())
            using (var triangles = Subdivision.Triangulate(cube))
            {
                t.Equal(12, triangles.FaceCount, "two triangles per quad");
                t.Equal(8, triangles.VertexCount, "vertices kept");
                t.Sequence(Shapes.Repeat(3, 12), triangles.GetFaceSizes(), "all triangles");
                t.True(triangles.Info().IsClosed, "closed");
            }
        }

        private static void TriangulateWithParents()
        {
            // A quad, a regular hexagon and a triangle: 2 + 4 + 1 triangles.
            var positions = new System.Collections.Generic.List<double> { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0 };
            for (int i = 0; i < 6; i++) positions.AddRange(new[] { 5 + Math.Cos(i * Math.PI / 3), Math.Sin(i * Math.PI / 3), 0 });
            positions.AddRange(new double[] { 0, 0, 3, 1, 0, 3, 0, 1, 3 });
            using (var mesh = WeftMesh.Create(positions.ToArray(), new uint[] { 4, 6, 3 }, new uint[] { 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12 }))
            {
                uint[] parents;
                using (var triangles = Subdivision.Triangulate(mesh, out parents))
                {
                    t.Equal(7, triangles.FaceCount, "2 + 4 + 1 triangles");
                    t.Sequence(new uint[] { 0, 0, 1, 1, 1, 1, 2 }, parents, "each triangle's face");
                    uint[] indices = triangles.GetFaceIndices();
                    for (int f = 0; f < parents.Length; f++)
                    {
                        for (int k = 0; k < 3; k++)
                        {
                            uint v = indices[3 * f + k];
                            bool inParent = parents[f] == 0 ? v < 4 : parents[f] == 1 ? v >= 4 && v < 10 : v >= 10;
                            t.True(inParent, "triangle " + f + "'s corner " + v + " is a corner of face " + parents[f]);
                        }
                    }
                }
            }
        }

        private static void AsTriangles()
        {
            int split;
            using (var octahedron = Shapes.Octahedron())
            using (var copy = Subdivision.AsTriangles(octahedron, out split))
            {
                t.Equal(0, split, "nothing split on a triangle mesh");
                t.Sequence(octahedron.GetFaceIndices(), copy.GetFaceIndices(), "the same triangles");
            }
            using (var cube = Shapes.Cube())
            using (var triangles = Subdivision.AsTriangles(cube, out split))
            using (var expected = Subdivision.Triangulate(cube))
            {
                t.Equal(6, split, "six quads split");
                t.Sequence(expected.GetFaceIndices(), triangles.GetFaceIndices(), "as weft_triangulate cuts them");
            }
        }

        private static void TriangulateDisposed()
        {
            var cube = Shapes.Cube();
            cube.Dispose();
            t.Throws<ObjectDisposedException>(() => Subdivision.Triangulate(cube), "disposed mesh");
            t.Throws<ArgumentNullException>(() => Subdivision.Triangulate(null), "null mesh");
        }

        private static void FaceCountAndParents()
        {
            using (var cube = Shapes.Cube())
            {
                t.Equal(96, Subdivision.FaceCount(cube, Scheme.CatmullClark, 2), "6 × 4 × 4 faces");
                uint[] parents = Subdivision.ParentFaces(cube, Scheme.CatmullClark, 1);
                t.Equal(24, parents.Length, "one parent per face");
                t.Equal(0u, parents[3], "quad 3 comes from face 0");
                t.Equal(1u, parents[4], "quad 4 comes from face 1");
                t.Equal(5u, parents[23], "the last quad comes from face 5");
            }
            using (var octa = Shapes.Octahedron())
            {
                t.Equal(128, Subdivision.FaceCount(octa, Scheme.Loop, 2), "8 × 16 triangles");
            }
        }

        private static void SubdivideIntoCallerArrays()
        {
            using (var cube = Shapes.Cube())
            using (var octa = Shapes.Octahedron())
            {
                SubdivideInto(cube, Scheme.CatmullClark);
                SubdivideInto(octa, Scheme.Loop);
                t.Throws<ArgumentNullException>(() => Subdivision.SubdivideInto(cube, Scheme.CatmullClark, 1, NakedEdges.Fixed, null, new uint[96]), "null positions");
            }
        }

        private static void SubdivideInto(WeftMesh cage, Scheme scheme)
        {
            SubdivisionCounts counts = Subdivision.Counts(cage, scheme, 2);
            var positions = new double[3 * counts.VertexCount];
            var indices = new uint[counts.IndexCount];
            using (WeftMesh expected = scheme == Scheme.Loop
                ? Subdivision.Loop(cage, 2, NakedEdges.Smooth)
                : Subdivision.CatmullClark(cage, 2, NakedEdges.Smooth))
            {
                for (int round = 0; round < 2; round++)
                {
                    Subdivision.SubdivideInto(cage, scheme, 2, NakedEdges.Smooth, positions, indices);
                    t.True(positions.SequenceEqual(expected.GetPositions()), scheme + ": the positions, bit for bit");
                    t.True(indices.SequenceEqual(expected.GetFaceIndices()), scheme + ": the faces");
                }
            }
            var shortIndices = new uint[counts.IndexCount - 1];
            Shapes.Fails(() => Subdivision.SubdivideInto(cage, scheme, 2, NakedEdges.Smooth, positions, shortIndices),
                WeftStatus.BufferTooSmall, "face_indices has room for");
            t.True(shortIndices.All(i => i == 0), scheme + ": a short array is left as it was");
        }

        private static void FaceCountUnknownScheme()
        {
            using (var cube = Shapes.Cube())
            {
                Shapes.Fails(() => Subdivision.FaceCount(cube, (Scheme)2, 1), WeftStatus.InvalidArgument, "scheme is 2");
                Shapes.Fails(() => Subdivision.ParentFaces(cube, Scheme.Loop, 1), WeftStatus.NotTriangles, "face 0 has 4 vertices");
            }
        }

        private static void RefinerMatchesFresh()
        {
            // The cage moved: scaled by 2 and one corner lifted.
            var moved = (double[])UnitCube.Positions.Clone();
            for (int i = 0; i < moved.Length; i++) moved[i] *= 2;
            moved[3 * 7 + 2] += 0.75;
            using (var cube = Shapes.Cube())
            using (var refiner = new Refiner(cube, Scheme.CatmullClark, 2, NakedEdges.Smooth))
            using (var movedCube = WeftMesh.Create(moved, UnitCube.Sizes, UnitCube.Indices))
            using (var fresh = Subdivision.CatmullClark(movedCube, 2, NakedEdges.Smooth))
            {
                t.Equal(fresh.VertexCount, refiner.VertexCount, "refined vertex count");
                t.Equal(fresh.FaceCount, refiner.FaceCount, "refined face count");
                t.Equal(8, refiner.CageVertexCount, "cage vertex count");
                var output = new double[3 * refiner.VertexCount];
                refiner.Evaluate(moved, output);
                Shapes.Near(fresh.GetPositions(), output, 1e-12, "refined positions");
                // Back to the original cage: the same buffer, re-evaluated.
                refiner.Evaluate(UnitCube.Positions, output);
                using (var original = Subdivision.CatmullClark(cube, 2, NakedEdges.Smooth))
                {
                    Shapes.Near(original.GetPositions(), output, 1e-12, "re-evaluated positions");
                }
            }
            using (var octa = Shapes.Octahedron())
            using (var refiner = new Refiner(octa, Scheme.Loop, 1, NakedEdges.Smooth))
            {
                double[] positions = octa.GetPositions();
                for (int i = 0; i < positions.Length; i++) positions[i] *= 3;
                var output = new double[3 * refiner.VertexCount];
                refiner.Evaluate(positions, output);
                using (var big = WeftMesh.Create(positions, octa.GetFaceSizes(), octa.GetFaceIndices()))
                using (var fresh = Subdivision.Loop(big, 1, NakedEdges.Smooth))
                {
                    Shapes.Near(fresh.GetPositions(), output, 1e-12, "Loop refined positions");
                }
            }
        }

        private static void RefinerMesh()
        {
            using (var cube = Shapes.Cube())
            using (var refiner = new Refiner(cube, Scheme.CatmullClark, 1, NakedEdges.Smooth))
            using (var mesh = refiner.Mesh())
            using (var fresh = Subdivision.CatmullClark(cube, 1, NakedEdges.Smooth))
            {
                t.Sequence(fresh.GetFaceIndices(), mesh.GetFaceIndices(), "faces");
                Shapes.Near(fresh.GetPositions(), mesh.GetPositions(), 1e-12, "positions");
            }
        }

        private static void RefinerErrors()
        {
            using (var cube = Shapes.Cube())
            {
                var refiner = new Refiner(cube, Scheme.CatmullClark, 1, NakedEdges.Smooth);
                var output = new double[3 * refiner.VertexCount];
                var seven = new double[21];
                Shapes.Fails(() => refiner.Evaluate(seven, output), WeftStatus.CountMismatch, "vertex_count is 7");
                Shapes.Fails(() => refiner.Evaluate(UnitCube.Positions, new double[output.Length - 1]),
                    WeftStatus.BufferTooSmall, "out_positions has room for 77 elements but 78 are needed");
                var nan = (double[])UnitCube.Positions.Clone();
                nan[4] = double.NaN;
                Shapes.Fails(() => refiner.Evaluate(nan, output), WeftStatus.NonFiniteCoordinate, "vertex 1");
                refiner.Dispose();
                refiner.Dispose();
                t.True(refiner.IsDisposed, "disposed");
                t.Throws<ObjectDisposedException>(() => refiner.Evaluate(UnitCube.Positions, output), "evaluate after dispose");
                Shapes.Fails(() => new Refiner(cube, Scheme.Loop, 1, NakedEdges.Smooth), WeftStatus.NotTriangles, "face 0 has 4 vertices");
                Shapes.Fails(() => new Refiner(cube, Scheme.CatmullClark, 14, NakedEdges.Smooth), WeftStatus.ResultTooLarge, "level");
            }
        }
    }
}
