using System;

namespace Weft
{
    /// <summary>
    /// Catmull-Clark and Loop subdivision, the parent-face map and
    /// triangulation. Each method returns a new <see cref="WeftMesh"/> the
    /// caller disposes; failures raise a <see cref="WeftException"/>.
    /// </summary>
    public static partial class Subdivision
    {
        static Subdivision()
        {
            NativeLibraryLoader.EnsureLoaded();
        }

        /// <summary>Catmull-Clark subdivision, <paramref name="levels"/> times (0 copies); every face is a quad after one level.</summary>
        public static WeftMesh CatmullClark(WeftMesh mesh, int levels, NakedEdges nakedEdges)
        {
            WeftMeshHandle result;
            uint status = NativeMethods.weft_catmull_clark(
                Arguments.Mesh(mesh, "mesh"), Arguments.Unsigned(levels, "levels"), (uint)nakedEdges, out result);
            return WeftMesh.FromCall(status, result);
        }

        /// <summary>Loop subdivision of a triangle mesh (fails with <see cref="WeftStatus.NotTriangles"/> otherwise).</summary>
        public static WeftMesh Loop(WeftMesh mesh, int levels, NakedEdges nakedEdges)
        {
            WeftMeshHandle result;
            uint status = NativeMethods.weft_loop(
                Arguments.Mesh(mesh, "mesh"), Arguments.Unsigned(levels, "levels"), (uint)nakedEdges, out result);
            return WeftMesh.FromCall(status, result);
        }

        /// <summary>Splits quads along the shorter diagonal and n-gons by ear clipping; vertices keep their indices.</summary>
        public static WeftMesh Triangulate(WeftMesh mesh)
        {
            WeftMeshHandle result;
            uint status = NativeMethods.weft_triangulate(Arguments.Mesh(mesh, "mesh"), out result);
            return WeftMesh.FromCall(status, result);
        }

        /// <summary>
        /// Triangulates as <see cref="Triangulate(WeftMesh)"/> and gives, for each triangle, the index
        /// of the face of <paramref name="mesh"/> it was cut from.
        /// </summary>
        public static WeftMesh Triangulate(WeftMesh mesh, out uint[] parentFaces)
        {
            WeftMeshHandle handle = Arguments.Mesh(mesh, "mesh");
            var parents = new uint[checked(mesh.IndexCount - 2 * mesh.FaceCount)];
            WeftMeshHandle result;
            uint status = NativeMethods.weft_triangulate_ex(handle, out result, parents);
            WeftMesh triangles = WeftMesh.FromCall(status, result);
            parentFaces = parents;
            return triangles;
        }

        /// <summary>
        /// The mesh as triangles, for Loop and Split Triangles: a copy when every face is a
        /// triangle, else <see cref="Triangulate(WeftMesh)"/>. <paramref name="splitFaces"/> is
        /// the number of faces that were not triangles.
        /// </summary>
        public static WeftMesh AsTriangles(WeftMesh mesh, out int splitFaces)
        {
            return WeftMesh.FromCountingCall(NativeMethods.weft_as_triangles, mesh, out splitFaces);
        }

        /// <summary>
        /// Subdivides into arrays the caller keeps from call to call: the result of
        /// <see cref="CatmullClark"/> or <see cref="Loop"/> (by <paramref name="scheme"/>), bit for
        /// bit, its positions (x, y, z per vertex) written to the start of <paramref name="positions"/>
        /// and its face indices to the start of <paramref name="faceIndices"/>. Size them once from
        /// <see cref="Counts(WeftMesh, Scheme, int)"/>; from level 1 on every face is a quad
        /// (Catmull-Clark) or a triangle (Loop).
        /// </summary>
        /// <exception cref="WeftException">
        /// As <see cref="CatmullClark"/> and <see cref="Loop"/>; <see cref="WeftStatus.BufferTooSmall"/>
        /// when an array is shorter than the result, and then nothing is written.
        /// </exception>
        public static void SubdivideInto(WeftMesh mesh, Scheme scheme, int levels, NakedEdges nakedEdges, double[] positions, uint[] faceIndices)
        {
            WeftMeshHandle handle = Arguments.Mesh(mesh, "mesh");
            uint steps = Arguments.Unsigned(levels, "levels");
            Arguments.NotNull(positions, "positions");
            Arguments.NotNull(faceIndices, "faceIndices");
            WeftException.Check(NativeMethods.weft_subdivide_into(
                handle, (uint)scheme, steps, (uint)nakedEdges, positions, (UIntPtr)positions.Length,
                faceIndices, (UIntPtr)faceIndices.Length));
        }

        /// <summary>The number of faces <paramref name="levels"/> steps of <paramref name="scheme"/> make from <paramref name="cage"/>, without subdividing.</summary>
        public static int FaceCount(WeftMesh cage, Scheme scheme, int levels)
        {
            UIntPtr count;
            WeftException.Check(NativeMethods.weft_subdivision_face_count(
                Arguments.Mesh(cage, "cage"), (uint)scheme, Arguments.Unsigned(levels, "levels"), out count));
            return Arguments.ToInt(count);
        }

        /// <summary>For each face of the subdivided mesh, the index of the cage face it comes from.</summary>
        public static uint[] ParentFaces(WeftMesh cage, Scheme scheme, int levels)
        {
            var parents = new uint[FaceCount(cage, scheme, levels)];
            WeftException.Check(NativeMethods.weft_subdivision_parent_faces(
                cage.Handle, (uint)scheme, (uint)levels, parents, (UIntPtr)parents.Length));
            return parents;
        }
    }

    /// <summary>
    /// The subdivision of one cage topology, planned once: moving the cage's
    /// vertices costs only <see cref="Evaluate"/>, which writes into a caller
    /// buffer and allocates nothing. Dispose it to free the native plan.
    /// </summary>
    public sealed class Refiner : NativeObject<WeftRefinerHandle>
    {
        private const string Disposed = "The refiner was disposed and its native memory freed.";

        static Refiner()
        {
            NativeLibraryLoader.EnsureLoaded();
        }

        /// <summary>
        /// Plans <paramref name="levels"/> steps of <paramref name="scheme"/> on the faces of
        /// <paramref name="cage"/> (which may be disposed afterwards).
        /// </summary>
        /// <exception cref="WeftException">An unknown scheme or mode, Loop on a non-triangle (<see cref="WeftStatus.NotTriangles"/>), a result too large.</exception>
        public Refiner(WeftMesh cage, Scheme scheme, int levels, NakedEdges nakedEdges)
            : base(Plan(cage, scheme, levels, nakedEdges), Disposed)
        {
            CageVertexCount = cage.VertexCount;
        }

        /// <summary>
        /// Plans <paramref name="levels"/> steps of <paramref name="scheme"/> on the faces of
        /// <paramref name="cage"/> with the naked-edge mode, creases and corners of
        /// <paramref name="options"/> (null: the defaults of <see cref="SubdivisionOptions"/>).
        /// The options are copied: changing them later does not change the plan.
        /// </summary>
        /// <exception cref="WeftException">As <see cref="Subdivision.Subdivide"/>.</exception>
        public Refiner(WeftMesh cage, Scheme scheme, int levels, SubdivisionOptions options)
            : base(Plan(cage, scheme, levels, options), Disposed)
        {
            CageVertexCount = cage.VertexCount;
        }

        private static WeftRefinerHandle Plan(WeftMesh cage, Scheme scheme, int levels, NakedEdges nakedEdges)
        {
            WeftRefinerHandle created;
            uint status = NativeMethods.weft_refiner_new(
                Arguments.Mesh(cage, "cage"), (uint)scheme, Arguments.Unsigned(levels, "levels"), (uint)nakedEdges, out created);
            return Take(status, created);
        }

        private static WeftRefinerHandle Plan(WeftMesh cage, Scheme scheme, int levels, SubdivisionOptions options)
        {
            WeftRefinerHandle created;
            uint status = SubdivisionOptions.Call(NativeMethods.weft_refiner_new_ex, cage, "cage", options, scheme, levels, out created);
            return Take(status, created);
        }

        private static WeftRefinerHandle Take(uint status, WeftRefinerHandle created)
        {
            if (status != (uint)WeftStatus.Ok)
            {
                string message = WeftException.LastErrorMessage();
                if (created != null) created.Dispose();
                throw new WeftException((WeftStatus)status, message);
            }
            return created;
        }

        /// <summary>The number of cage vertices <see cref="Evaluate"/> expects.</summary>
        public int CageVertexCount { get; private set; }

        /// <summary>The number of refined vertices; <see cref="Evaluate"/> writes 3 doubles for each.</summary>
        public int VertexCount
        {
            get { return Arguments.ToInt(NativeMethods.weft_refiner_vertex_count(Handle)); }
        }

        /// <summary>The number of refined faces.</summary>
        public int FaceCount
        {
            get { return Arguments.ToInt(NativeMethods.weft_refiner_face_count(Handle)); }
        }

        /// <summary>
        /// Computes the refined positions of new cage positions (3 doubles per
        /// cage vertex) into <paramref name="refinedPositions"/> (at least
        /// 3 × <see cref="VertexCount"/> doubles). No allocation: the arrays
        /// are pinned for the call.
        /// </summary>
        /// <exception cref="WeftException"><see cref="WeftStatus.CountMismatch"/>, <see cref="WeftStatus.BufferTooSmall"/>, <see cref="WeftStatus.NonFiniteCoordinate"/>.</exception>
        public void Evaluate(double[] cagePositions, double[] refinedPositions)
        {
            UIntPtr vertexCount = Arguments.Triples(cagePositions, "cagePositions");
            Arguments.NotNull(refinedPositions, "refinedPositions");
            WeftException.Check(NativeMethods.weft_refiner_evaluate(
                Handle, cagePositions, vertexCount, refinedPositions, (UIntPtr)refinedPositions.Length));
        }

        /// <summary>The refined mesh at the cage positions the refiner was built from.</summary>
        public WeftMesh Mesh()
        {
            WeftMeshHandle result;
            uint status = NativeMethods.weft_refiner_mesh(Handle, out result);
            return WeftMesh.FromCall(status, result);
        }
    }
}
