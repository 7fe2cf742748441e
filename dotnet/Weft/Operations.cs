using System;
using System.Runtime.InteropServices;

namespace Weft
{
    /// <summary>
    /// How subdivision treats naked (boundary) edges; the values are the
    /// library's <c>naked_edges</c> argument.
    /// </summary>
    public enum NakedEdges : uint
    {
        /// <summary>The boundary polyline does not move: boundary vertices stay, new ones are edge midpoints.</summary>
        Fixed = 0,
        /// <summary>The boundary tends to a cubic B-spline; every boundary vertex moves.</summary>
        Smooth = 1,
        /// <summary>As Smooth, but a boundary vertex with only one face (a corner) stays.</summary>
        CornerFixed = 2,
    }

    /// <summary>
    /// The mesh operations of the C ABI. Each takes meshes that stay owned by
    /// the caller and returns a new <see cref="WeftMesh"/> the caller disposes;
    /// failures raise a <see cref="WeftException"/> with the library's status
    /// and message.
    /// </summary>
    public static class Operations
    {
        static Operations()
        {
            NativeLibraryLoader.EnsureLoaded();
        }

        /// <summary>Catmull-Clark subdivision, <paramref name="levels"/> times; all faces are quads after one level.</summary>
        public static WeftMesh CatmullClark(WeftMesh mesh, int levels, NakedEdges nakedEdges)
        {
            CheckMesh(mesh);
            WeftMeshHandle result;
            uint status = NativeMethods.weft_catmull_clark(mesh.Handle, Levels(levels), (uint)nakedEdges, out result);
            return WeftMesh.FromCall(status, result);
        }

        /// <summary>Loop subdivision of a triangle mesh, <paramref name="levels"/> times (fails with <see cref="WeftStatus.NotTriangles"/> otherwise).</summary>
        public static WeftMesh Loop(WeftMesh mesh, int levels, NakedEdges nakedEdges)
        {
            CheckMesh(mesh);
            WeftMeshHandle result;
            uint status = NativeMethods.weft_loop(mesh.Handle, Levels(levels), (uint)nakedEdges, out result);
            return WeftMesh.FromCall(status, result);
        }

        /// <summary>Splits quads along the shorter diagonal and n-gons by ear clipping.</summary>
        public static WeftMesh Triangulate(WeftMesh mesh)
        {
            CheckMesh(mesh);
            WeftMeshHandle result;
            uint status = NativeMethods.weft_triangulate(mesh.Handle, out result);
            return WeftMesh.FromCall(status, result);
        }

        /// <summary>Concatenates meshes (indices offset), in order.</summary>
        public static WeftMesh Join(params WeftMesh[] meshes)
        {
            if (meshes == null) throw new ArgumentNullException("meshes");
            var handles = new WeftMeshHandle[meshes.Length];
            var raw = new IntPtr[meshes.Length];
            var added = new bool[meshes.Length];
            try
            {
                for (int i = 0; i < meshes.Length; i++)
                {
                    if (meshes[i] == null) throw new ArgumentNullException("meshes", "mesh " + i + " is null");
                    handles[i] = meshes[i].Handle;
                    handles[i].DangerousAddRef(ref added[i]);
                    raw[i] = handles[i].DangerousGetHandle();
                }
                WeftMeshHandle result;
                uint status = NativeMethods.weft_join(raw, (UIntPtr)raw.Length, out result);
                return WeftMesh.FromCall(status, result);
            }
            finally
            {
                for (int i = 0; i < meshes.Length; i++)
                {
                    if (added[i]) handles[i].DangerousRelease();
                }
            }
        }

        /// <summary>Merges vertices closer than <paramref name="tolerance"/>; faces left with fewer than 3 distinct vertices are removed.</summary>
        public static WeftMesh Weld(WeftMesh mesh, double tolerance)
        {
            CheckMesh(mesh);
            WeftMeshHandle result;
            uint status = NativeMethods.weft_weld(mesh.Handle, tolerance, out result, IntPtr.Zero);
            return WeftMesh.FromCall(status, result);
        }

        /// <summary>Removes every face that has a twin with the same vertex set; <paramref name="removed"/> counts them.</summary>
        public static WeftMesh CullAdjacent(WeftMesh mesh, out long removed)
        {
            CheckMesh(mesh);
            WeftMeshHandle result;
            UIntPtr count;
            uint status = NativeMethods.weft_cull_adjacent(mesh.Handle, out result, out count);
            WeftMesh culled = WeftMesh.FromCall(status, result);
            removed = (long)count.ToUInt64();
            return culled;
        }

        /// <summary>Gives each connected piece one winding, flipping the fewest faces; <paramref name="flipped"/> counts them.</summary>
        public static WeftMesh UnifyOrientation(WeftMesh mesh, out long flipped)
        {
            CheckMesh(mesh);
            WeftMeshHandle result;
            UIntPtr count;
            uint status = NativeMethods.weft_unify_orientation(mesh.Handle, out result, out count);
            WeftMesh unified = WeftMesh.FromCall(status, result);
            flipped = (long)count.ToUInt64();
            return unified;
        }

        /// <summary>Reverses the winding of every face.</summary>
        public static WeftMesh Flip(WeftMesh mesh)
        {
            CheckMesh(mesh);
            WeftMeshHandle result;
            uint status = NativeMethods.weft_flip(mesh.Handle, out result);
            return WeftMesh.FromCall(status, result);
        }

        private static void CheckMesh(WeftMesh mesh)
        {
            if (mesh == null) throw new ArgumentNullException("mesh");
        }

        private static uint Levels(int levels)
        {
            if (levels < 0)
            {
                throw new WeftException(WeftStatus.InvalidArgument, "levels is " + levels + "; it must be 0 or more");
            }
            return (uint)levels;
        }
    }

    /// <summary>
    /// Exports whose C names are fixed by their issues but which are not yet
    /// in <c>include/weft.h</c> on main; each moves to NativeMethods.cs when
    /// the header declares it.
    /// </summary>
    internal static partial class NativeMethods
    {
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_catmull_clark(WeftMeshHandle mesh, uint levels, uint nakedEdges, out WeftMeshHandle outMesh);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_loop(WeftMeshHandle mesh, uint levels, uint nakedEdges, out WeftMeshHandle outMesh);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_triangulate(WeftMeshHandle mesh, out WeftMeshHandle outMesh);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_join(IntPtr[] meshes, UIntPtr count, out WeftMeshHandle outMesh);

        /// <summary><paramref name="outReport"/> is a <c>WeftWeldReport *</c>; NULL until its layout is in the header.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_weld(WeftMeshHandle mesh, double tolerance, out WeftMeshHandle outMesh, IntPtr outReport);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_cull_adjacent(WeftMeshHandle mesh, out WeftMeshHandle outMesh, out UIntPtr outRemoved);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_unify_orientation(WeftMeshHandle mesh, out WeftMeshHandle outMesh, out UIntPtr outFlipped);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_flip(WeftMeshHandle mesh, out WeftMeshHandle outMesh);
    }
}
