using System;
using System.Threading;

namespace Weft.Tests
{
    /// <summary>Tests of the C# wrapper against the real native library.</summary>
    public static class WrapperTests
    {
        private static Runner t;

        // A square, a triangle on its right and a pentagon above it: mixed sizes.
        private static readonly double[] MixedPositions =
        {
            0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 2, 0.5, 0,
            1.5, 2, 0.25, 0.5, 2.5, -0.125,
        };
        private static readonly uint[] MixedSizes = { 4, 3, 5 };
        private static readonly uint[] MixedIndices = { 0, 1, 2, 3, 1, 4, 2, 3, 2, 4, 5, 6 };

        private static readonly double[] Square = { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0 };

        public static int Main()
        {
            return Runner.RunAll(Register, HeaderTests.Register, SubdivisionTests.Register, MakingTests.Register,
                                 MendingTests.Register, ToolbarTests.Register, CreaseTests.Register);
        }

        public static void Register(Runner runner)
        {
            t = runner;
            Shapes.T = t;
            t.Run("version is the crate's", Version);
            t.Run("a folder named by the host is searched after the assembly's", SearchFolderFallback);
            t.Run("round trip of mixed polygons", RoundTrip);
            t.Run("empty mesh", EmptyMesh);
            t.Run("info on a cube", InfoOnCube);
            t.Run("info on an open grid and a fin", InfoOnOpenAndNonManifold);
            t.Run("error: index out of range", ErrorIndexOutOfRange);
            t.Run("error: face too small", ErrorFaceTooSmall);
            t.Run("error: repeated index", ErrorRepeatedIndex);
            t.Run("repeated vertices accepted on request and subdivided", RepeatedVerticesAllowed);
            t.Run("error: NaN and infinite coordinates", ErrorNonFinite);
            t.Run("error: face sizes and index count disagree", ErrorCountMismatch);
            t.Run("error: positions not 3 per vertex", ErrorPositionsNotTriples);
            t.Run("error: null buffers", ErrorNullBuffers);
            t.Run("error message belongs to the failing thread", ErrorMessagePerThread);
            t.Run("dispose twice", DisposeTwice);
            t.Run("use after dispose refused", UseAfterDispose);
            t.Run("finalizer frees undisposed meshes", FinalizerFrees);
            t.Run("library located", LibraryLocated);
        }

        private static void Version()
        {
            string version = WeftMesh.LibraryVersion;
            t.Equal("0.1.0", version, "weft_version()");
        }

        private static void RoundTrip()
        {
            using (var mesh = WeftMesh.Create(MixedPositions, MixedSizes, MixedIndices))
            {
                t.Equal(7, mesh.VertexCount, "vertex count");
                t.Equal(3, mesh.FaceCount, "face count");
                t.Equal(12, mesh.IndexCount, "index count");
                t.Sequence(MixedPositions, mesh.GetPositions(), "positions");
                t.Sequence(MixedSizes, mesh.GetFaceSizes(), "face sizes");
                t.Sequence(MixedIndices, mesh.GetFaceIndices(), "face indices");
                uint[] sizes;
                uint[] indices;
                mesh.GetFaces(out sizes, out indices);
                t.Sequence(MixedSizes, sizes, "GetFaces sizes");
                t.Sequence(MixedIndices, indices, "GetFaces indices");
            }
            // The wrapper copies: changing the caller's buffer later changes nothing.
            var positions = (double[])UnitCube.Positions.Clone();
            using (var mesh = WeftMesh.Create(positions, UnitCube.Sizes, UnitCube.Indices))
            {
                positions[0] = 42;
                t.Equal(0.0, mesh.GetPositions()[0], "first coordinate after the caller's buffer changed");
            }
        }

        private static void EmptyMesh()
        {
            using (var mesh = WeftMesh.Create(new double[0], new uint[0], new uint[0]))
            {
                t.Equal(0, mesh.VertexCount, "vertex count");
                t.Equal(0, mesh.FaceCount, "face count");
                t.Equal(0, mesh.GetPositions().Length, "positions length");
                t.Equal(0, mesh.GetFaceIndices().Length, "indices length");
                WeftMeshInfo info = mesh.Info();
                t.Equal(0L, info.EdgeCount, "edges");
                t.True(!info.IsClosed, "an empty mesh is not closed");
            }
        }

        private static void InfoOnCube()
        {
            using (var cube = WeftMesh.Create(UnitCube.Positions, UnitCube.Sizes, UnitCube.Indices))
            {
                WeftMeshInfo info = cube.Info();
                t.Equal(8L, info.VertexCount, "vertices");
                t.Equal(12L, info.EdgeCount, "edges");
                t.Equal(6L, info.FaceCount, "faces");
                t.Equal(0L, info.NakedEdgeCount, "naked edges");
                t.Equal(0L, info.NonManifoldEdgeCount, "non-manifold edges");
                t.Equal(0L, info.NonManifoldVertexCount, "non-manifold vertices");
                t.Equal(1L, info.ComponentCount, "components");
                t.True(info.IsClosed, "closed");
                t.True(info.IsOrientable, "orientable");
                t.True(info.IsOriented, "oriented");
            }
            // One face reversed: still orientable, no longer oriented.
            var flipped = (uint[])UnitCube.Indices.Clone();
            Array.Reverse(flipped, 0, 4);
            using (var cube = WeftMesh.Create(UnitCube.Positions, UnitCube.Sizes, flipped))
            {
                WeftMeshInfo info = cube.Info();
                t.True(info.IsOrientable, "orientable with one face flipped");
                t.True(!info.IsOriented, "not oriented with one face flipped");
                t.True(info.IsClosed, "closed with one face flipped");
            }
        }

        private static void InfoOnOpenAndNonManifold()
        {
            double[] grid = { 0, 0, 0, 1, 0, 0, 2, 0, 0, 0, 1, 0, 1, 1, 0, 2, 1, 0 };
            using (var mesh = WeftMesh.Create(grid, new uint[] { 4, 4 }, new uint[] { 0, 1, 4, 3, 1, 2, 5, 4 }))
            {
                WeftMeshInfo info = mesh.Info();
                t.Equal(7L, info.EdgeCount, "grid edges");
                t.Equal(6L, info.NakedEdgeCount, "grid naked edges");
                t.True(!info.IsClosed, "grid is open");
            }
            double[] fin = { 0, 0, 0, 1, 0, 0, 0.5, 1, 0, 0.5, -1, 0, 0.5, 0, 1 };
            using (var mesh = WeftMesh.Create(fin, new uint[] { 3, 3, 3 }, new uint[] { 0, 1, 2, 1, 0, 3, 0, 1, 4 }))
            {
                WeftMeshInfo info = mesh.Info();
                t.Equal(1L, info.NonManifoldEdgeCount, "fin non-manifold edges");
                t.Equal(2L, info.NonManifoldVertexCount, "fin non-manifold vertices");
            }
        }

        private static void ExpectFailure(Action action, WeftStatus status, string message)
        {
            WeftException e = t.Throws<WeftException>(action, status.ToString());
            if (e == null) return;
            t.Equal(status, e.Status, "status");
            t.True(e.Message.Contains(message), "message containing \"" + message + "\", got \"" + e.Message + "\"");
        }

        private static void ErrorIndexOutOfRange()
        {
            ExpectFailure(
                () => WeftMesh.Create(Square, new uint[] { 3 }, new uint[] { 0, 1, 9 }),
                WeftStatus.IndexOutOfRange,
                "face 0, corner 2: vertex index 9 is out of range (the mesh has 4 vertices)");
        }

        private static void ErrorFaceTooSmall()
        {
            ExpectFailure(
                () => WeftMesh.Create(Square, new uint[] { 4, 2 }, new uint[] { 0, 1, 2, 3, 0, 1 }),
                WeftStatus.FaceTooSmall,
                "face 1 has 2 vertices");
        }

        private static void ErrorRepeatedIndex()
        {
            ExpectFailure(
                () => WeftMesh.Create(Square, new uint[] { 3 }, new uint[] { 0, 1, 1 }),
                WeftStatus.RepeatedIndex,
                "face 0 uses vertex 1 twice");
        }

        private static void RepeatedVerticesAllowed()
        {
            // A pentagon with the degenerate edge 1-1 beside a quad.
            var positions = new double[] { 0, 0, 0, 1, 0, 0, 2, 0, 0, 0, 1, 0, 1, 1, 0, 2, 1, 0 };
            var sizes = new uint[] { 5, 4 };
            var indices = new uint[] { 0, 1, 1, 4, 3, 1, 2, 5, 4 };
            ExpectFailure(() => WeftMesh.Create(positions, sizes, indices, false), WeftStatus.RepeatedIndex,
                          "face 0 uses vertex 1 twice");
            using (var mesh = WeftMesh.Create(positions, sizes, indices, true))
            using (var smooth = Subdivision.CatmullClark(mesh, 1, NakedEdges.Smooth))
            {
                t.Equal(9, mesh.IndexCount, "indices kept");
                // 6 vertices, 8 edges (one degenerate), 2 faces; 5 + 4 children.
                t.Equal(16, smooth.VertexCount, "refined vertices");
                t.Equal(9, smooth.FaceCount, "refined faces");
            }
        }

        private static void ErrorNonFinite()
        {
            var bad = (double[])Square.Clone();
            bad[7] = double.NaN;
            ExpectFailure(
                () => WeftMesh.Create(bad, new uint[] { 3 }, new uint[] { 0, 1, 2 }),
                WeftStatus.NonFiniteCoordinate,
                "vertex 2 has a non-finite coordinate");
            bad[7] = 0;
            bad[9] = double.PositiveInfinity;
            ExpectFailure(
                () => WeftMesh.Create(bad, new uint[] { 3 }, new uint[] { 0, 1, 2 }),
                WeftStatus.NonFiniteCoordinate,
                "vertex 3 has a non-finite coordinate");
        }

        private static void ErrorCountMismatch()
        {
            ExpectFailure(
                () => WeftMesh.Create(Square, new uint[] { 3, 3 }, new uint[] { 0, 1, 2 }),
                WeftStatus.CountMismatch,
                "the face sizes add up to 6 indices but 3 indices were given");
        }

        private static void ErrorPositionsNotTriples()
        {
            ExpectFailure(
                () => WeftMesh.Create(new double[] { 0, 0, 0, 1 }, new uint[0], new uint[0]),
                WeftStatus.CountMismatch,
                "positions holds 4 doubles, which is not 3 per vertex");
        }

        private static void ErrorNullBuffers()
        {
            t.Throws<ArgumentNullException>(() => WeftMesh.Create(null, new uint[0], new uint[0]), "null positions");
            t.Throws<ArgumentNullException>(() => WeftMesh.Create(Square, null, new uint[0]), "null face sizes");
            t.Throws<ArgumentNullException>(() => WeftMesh.Create(Square, new uint[0], null), "null face indices");
        }

        private static void ErrorMessagePerThread()
        {
            // A failure on another thread must not replace this thread's message.
            WeftException here = t.Throws<WeftException>(
                () => WeftMesh.Create(Square, new uint[] { 3 }, new uint[] { 0, 1, 1 }), "repeated index");
            string other = null;
            var thread = new Thread(() =>
            {
                try
                {
                    WeftMesh.Create(Square, new uint[] { 3 }, new uint[] { 0, 1, 9 });
                }
                catch (WeftException e)
                {
                    other = e.Message;
                }
            });
            thread.Start();
            thread.Join();
            t.True(other != null && other.Contains("vertex index 9"), "the other thread's own message, got \"" + other + "\"");
            t.True(WeftException.LastErrorMessage().Contains("uses vertex 1 twice"), "this thread's message unchanged, got \"" + WeftException.LastErrorMessage() + "\"");
            t.True(here != null, "an exception on this thread");
        }

        private static void DisposeTwice()
        {
            var mesh = WeftMesh.Create(UnitCube.Positions, UnitCube.Sizes, UnitCube.Indices);
            t.True(!mesh.IsDisposed, "live before Dispose");
            mesh.Dispose();
            mesh.Dispose();
            t.True(mesh.IsDisposed, "disposed after Dispose");
        }

        private static void UseAfterDispose()
        {
            var mesh = WeftMesh.Create(UnitCube.Positions, UnitCube.Sizes, UnitCube.Indices);
            mesh.Dispose();
            t.Throws<ObjectDisposedException>(() => { int n = mesh.VertexCount; }, "VertexCount");
            t.Throws<ObjectDisposedException>(() => mesh.GetPositions(), "GetPositions");
            t.Throws<ObjectDisposedException>(() => mesh.GetFaceIndices(), "GetFaceIndices");
            t.Throws<ObjectDisposedException>(() => mesh.Info(), "Info");
        }

        private static void FinalizerFrees()
        {
            for (int i = 0; i < 200; i++)
            {
                WeftMesh.Create(UnitCube.Positions, UnitCube.Sizes, UnitCube.Indices);
            }
            GC.Collect();
            GC.WaitForPendingFinalizers();
            GC.Collect();
            using (var mesh = WeftMesh.Create(UnitCube.Positions, UnitCube.Sizes, UnitCube.Indices))
            {
                t.Equal(8, mesh.VertexCount, "a new mesh after the finalizers ran");
            }
        }

        private static void LibraryLocated()
        {
            // On this machine the library sits beside the assembly (test.sh copies it), so the preload path is the one Rhino uses.
            string from = NativeLibraryLoader.LoadedFrom;
            t.True(from != null && from.EndsWith(NativeLibraryLoader.FileName()), "the library loaded by full path, got \"" + from + "\"");
        }

        private static void SearchFolderFallback()
        {
            // Grasshopper's COFF loading leaves Assembly.Location empty; the host then names the plug-in's folder.
            string folder = System.IO.Path.Combine(System.IO.Path.GetTempPath(), "weft-plugin-folder");
            string file = NativeLibraryLoader.FileName();
            t.False(NativeLibraryLoader.CandidatePaths().Contains(System.IO.Path.Combine(folder, file)), "not searched before it is added");
            NativeLibraryLoader.AddSearchFolder(folder);
            NativeLibraryLoader.AddSearchFolder(folder);
            NativeLibraryLoader.AddSearchFolder("");
            System.Collections.Generic.IList<string> paths = NativeLibraryLoader.CandidatePaths();
            string runtimes = System.IO.Path.Combine(System.IO.Path.Combine(System.IO.Path.Combine(System.IO.Path.Combine(folder, "runtimes"), NativeLibraryLoader.RuntimeIdentifier()), "native"), file);
            int beside = paths.IndexOf(System.IO.Path.Combine(folder, file));
            t.True(beside > 0 && paths.IndexOf(runtimes) == beside - 1, "the added folder's runtimes path, then beside: " + string.Join(", ", paths));
            t.Equal(1, System.Linq.Enumerable.Count(paths, p => p == runtimes), "a folder added twice is searched once");
            t.True(paths.IndexOf(runtimes) >= 2, "after the assembly's own folder");
        }
    }
}
