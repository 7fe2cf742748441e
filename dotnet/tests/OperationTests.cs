using System;

namespace Weft.Tests
{
    /// <summary>
    /// Tests of the operations, each compiled in only once its export is
    /// declared in include/weft.h (test.sh defines HAVE_WEFT_…).
    /// </summary>
    public static class OperationTests
    {
        // Unused until the first operation's export lands.
#pragma warning disable 414
        private static Runner t;
#pragma warning restore 414

        public static void Register(Runner runner)
        {
            t = runner;
#if HAVE_WEFT_CATMULL_CLARK
            t.Run("Catmull-Clark of a cube", CatmullClarkCube);
#endif
#if HAVE_WEFT_LOOP
            t.Run("Loop needs triangles", LoopNeedsTriangles);
#endif
#if HAVE_WEFT_JOIN
            t.Run("join two cubes", JoinCubes);
#endif
        }

        private static WeftMesh Cube()
        {
            return WeftMesh.Create(WrapperTests.CubePositions, WrapperTests.CubeSizes, WrapperTests.CubeIndices);
        }

#if HAVE_WEFT_CATMULL_CLARK
        private static void CatmullClarkCube()
        {
            using (var cube = Cube())
            using (var once = Operations.CatmullClark(cube, 1, NakedEdges.Smooth))
            {
                // V + E + F vertices, one quad per corner.
                t.Equal(8 + 12 + 6, once.VertexCount, "vertices after one level");
                t.Equal(24, once.FaceCount, "faces after one level");
                t.True(once.Info().IsClosed, "still closed");
            }
        }
#endif

#if HAVE_WEFT_LOOP
        private static void LoopNeedsTriangles()
        {
            using (var cube = Cube())
            {
                WeftException e = t.Throws<WeftException>(() => Operations.Loop(cube, 1, NakedEdges.Smooth), "Loop on quads");
                if (e != null) t.Equal(WeftStatus.NotTriangles, e.Status, "status");
            }
        }
#endif

#if HAVE_WEFT_JOIN
        private static void JoinCubes()
        {
            using (var a = Cube())
            using (var b = Cube())
            using (var joined = Operations.Join(a, b))
            {
                t.Equal(16, joined.VertexCount, "vertices");
                t.Equal(12, joined.FaceCount, "faces");
                t.Equal(8u, joined.GetFaceIndices()[24], "second cube's first index offset by 8");
            }
        }
#endif
    }
}
