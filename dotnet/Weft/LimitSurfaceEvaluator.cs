using System;

namespace Weft
{
    /// <summary>
    /// The limit surface of a cage, prepared once and evaluated anywhere (the
    /// vertices alone: <see cref="Subdivision.SubdivideLimit(WeftMesh, Scheme, int, SubdivisionOptions)"/>):
    /// positions and the derivatives by u and v at (face, u, v) samples,
    /// exact, and the nearest point of the surface to any point. Dispose it to
    /// free the native surface. Parameters per face are those of
    /// <c>weft_limit_surface_evaluate</c> in <c>weft.h</c>: a quad's (u, v)
    /// from its first corner (u towards the second, v towards the last), a
    /// Loop triangle's barycentric, other faces OpenSubdiv's quad sub-faces.
    /// </summary>
    public sealed class LimitSurfaceEvaluator : NativeObject<WeftLimitSurfaceHandle>
    {
        private const string Disposed = "The limit surface was disposed and its native memory freed.";

        static LimitSurfaceEvaluator()
        {
            NativeLibraryLoader.EnsureLoaded();
        }

        /// <summary>
        /// Prepares the limit surface of <paramref name="cage"/> subdivided with
        /// <paramref name="scheme"/> and <paramref name="options"/> (null: the
        /// defaults of <see cref="SubdivisionOptions"/>).
        /// </summary>
        /// <exception cref="WeftException">As <see cref="Subdivision.Subdivide"/>.</exception>
        public LimitSurfaceEvaluator(WeftMesh cage, Scheme scheme, SubdivisionOptions options)
            : base(Prepare(cage, scheme, options), Disposed)
        {
        }

        private static WeftLimitSurfaceHandle Prepare(WeftMesh cage, Scheme scheme, SubdivisionOptions options)
        {
            WeftMeshHandle handle = Arguments.Mesh(cage, "cage");
            WeftLimitSurfaceHandle created;
            uint status;
            using (SubdivisionOptions.Pinned pinned = SubdivisionOptions.Pin(options, scheme))
            {
                NativeSubdivisionOptions native = pinned.Native;
                status = NativeMethods.weft_limit_surface_new(handle, ref native, out created);
            }
            if (status != (uint)WeftStatus.Ok)
            {
                string message = WeftException.LastErrorMessage();
                if (created != null) created.Dispose();
                throw new WeftException((WeftStatus)status, message);
            }
            return created;
        }

        /// <summary>
        /// Evaluates the surface at sample i, on face <paramref name="faces"/>[i] at
        /// (<paramref name="uvs"/>[2 i], <paramref name="uvs"/>[2 i + 1]), into
        /// <paramref name="positions"/> (3 doubles per sample) and, when not null,
        /// <paramref name="du"/> and <paramref name="dv"/> (3 doubles per sample each).
        /// </summary>
        /// <exception cref="WeftException"><see cref="WeftStatus.IndexOutOfRange"/>, <see cref="WeftStatus.NonFiniteCoordinate"/>, <see cref="WeftStatus.InvalidArgument"/> (outside the face, a hole), naming the sample.</exception>
        public void Evaluate(uint[] faces, double[] uvs, double[] positions, double[] du, double[] dv)
        {
            Arguments.NotNull(faces, "faces");
            Arguments.NotNull(uvs, "uvs");
            Arguments.NotNull(positions, "positions");
            int count = faces.Length;
            if (uvs.Length != 2 * count)
                throw new ArgumentException("uvs must hold 2 doubles per face index", "uvs");
            CheckRoom(positions, count, "positions");
            if (du != null) CheckRoom(du, count, "du");
            if (dv != null) CheckRoom(dv, count, "dv");
            WeftException.Check(NativeMethods.weft_limit_surface_evaluate(
                Handle, (UIntPtr)count, faces, uvs, positions, du, dv));
        }

        /// <summary>
        /// The nearest point of the surface to each of <paramref name="points"/>
        /// (3 doubles each): its face into <paramref name="faces"/>, its (u, v)
        /// into <paramref name="uvs"/> (2 doubles each) and its position into
        /// <paramref name="positions"/> (3 doubles each).
        /// </summary>
        /// <exception cref="WeftException"><see cref="WeftStatus.NonFiniteCoordinate"/> naming the point.</exception>
        public void ClosestPoints(double[] points, uint[] faces, double[] uvs, double[] positions)
        {
            UIntPtr count = Arguments.Triples(points, "points");
            int n = (int)count;
            Arguments.NotNull(faces, "faces");
            Arguments.NotNull(uvs, "uvs");
            Arguments.NotNull(positions, "positions");
            if (faces.Length < n) throw new ArgumentException("faces must have room for one index per point", "faces");
            if (uvs.Length < 2 * n) throw new ArgumentException("uvs must have room for 2 doubles per point", "uvs");
            CheckRoom(positions, n, "positions");
            WeftException.Check(NativeMethods.weft_limit_surface_closest_point(
                Handle, count, points, faces, uvs, positions));
        }

        private static void CheckRoom(double[] buffer, int count, string name)
        {
            if (buffer.Length < 3 * count)
                throw new ArgumentException(name + " must have room for 3 doubles per sample", name);
        }
    }
}
