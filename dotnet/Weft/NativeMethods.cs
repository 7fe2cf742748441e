using System;
using System.Runtime.InteropServices;

namespace Weft
{
    /// <summary>
    /// Counts and flags of a mesh's topology, laid out as <c>WeftMeshInfo</c>
    /// in <c>include/weft.h</c>: seven <c>size_t</c> then three C <c>bool</c>s
    /// (one byte each), kept as bytes so the struct stays blittable.
    /// </summary>
    [StructLayout(LayoutKind.Sequential)]
    internal struct NativeMeshInfo
    {
        public UIntPtr VertexCount;
        public UIntPtr EdgeCount;
        public UIntPtr FaceCount;
        public UIntPtr NakedEdgeCount;
        public UIntPtr NonManifoldEdgeCount;
        public UIntPtr NonManifoldVertexCount;
        public UIntPtr ComponentCount;
        public byte IsClosed;
        public byte IsOrientable;
        public byte IsOriented;
    }

    /// <summary>
    /// The exports of <c>include/weft.h</c>, one for one, in the header's order.
    /// <c>size_t</c> is <see cref="UIntPtr"/>, <c>WeftStatus</c> is
    /// <see cref="uint"/>, a <c>WeftMesh *</c> is a <see cref="WeftMeshHandle"/>
    /// (or an <see cref="IntPtr"/> where the handle is not owned here).
    /// Call these only through <see cref="WeftMesh"/> and <see cref="Operations"/>,
    /// which load the native library first.
    /// </summary>
    internal static partial class NativeMethods
    {
        /// <summary>The library's file name without prefix or extension.</summary>
        internal const string Library = "weft";

        /// <summary><c>const char *weft_version(void)</c>; static, never freed.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern IntPtr weft_version();

        /// <summary><c>const char *weft_last_error_message(void)</c>; thread-local, copy it.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern IntPtr weft_last_error_message();

        /// <summary><c>weft_mesh_new</c>: copies the buffers into a new mesh.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_mesh_new(
            double[] positions, UIntPtr vertexCount,
            uint[] faceSizes, UIntPtr faceCount,
            uint[] faceIndices, UIntPtr indexCount,
            out WeftMeshHandle outMesh);

        /// <summary><c>weft_mesh_free</c>: NULL is ignored. Only <see cref="WeftMeshHandle"/> calls it.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern void weft_mesh_free(IntPtr mesh);

        /// <summary><c>weft_mesh_vertex_count</c>.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern UIntPtr weft_mesh_vertex_count(WeftMeshHandle mesh);

        /// <summary><c>weft_mesh_face_count</c>.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern UIntPtr weft_mesh_face_count(WeftMeshHandle mesh);

        /// <summary><c>weft_mesh_index_count</c>.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern UIntPtr weft_mesh_index_count(WeftMeshHandle mesh);

        /// <summary><c>weft_mesh_positions</c>: borrowed from the mesh.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern IntPtr weft_mesh_positions(WeftMeshHandle mesh);

        /// <summary><c>weft_mesh_face_sizes</c>: borrowed from the mesh.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern IntPtr weft_mesh_face_sizes(WeftMeshHandle mesh);

        /// <summary><c>weft_mesh_face_indices</c>: borrowed from the mesh.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern IntPtr weft_mesh_face_indices(WeftMeshHandle mesh);

        /// <summary><c>weft_mesh_copy_positions</c>: into a caller buffer of <paramref name="capacity"/> doubles.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_mesh_copy_positions(
            WeftMeshHandle mesh, [Out] double[] outPositions, UIntPtr capacity);

        /// <summary><c>weft_mesh_copy_faces</c>: into caller buffers.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_mesh_copy_faces(
            WeftMeshHandle mesh,
            [Out] uint[] outFaceSizes, UIntPtr sizesCapacity,
            [Out] uint[] outFaceIndices, UIntPtr indicesCapacity);

        /// <summary><c>weft_mesh_info</c>.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_mesh_info(WeftMeshHandle mesh, out NativeMeshInfo outInfo);
    }
}
