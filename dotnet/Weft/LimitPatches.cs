using System;

namespace Weft
{
    /// <summary>
    /// The Catmull-Clark limit surface as bicubic Bézier patches (what
    /// <c>weft nurbs</c> writes as STEP): one patch per face of the cage refined
    /// <see cref="Isolation"/> levels, in the refined faces' order.
    /// </summary>
    public sealed class LimitPatches
    {
        /// <summary>The number of patches.</summary>
        public int Count { get; internal set; }
        /// <summary>The isolation levels the cage was refined.</summary>
        public int Isolation { get; internal set; }
        /// <summary>
        /// 48 doubles per patch: control point i along u and j along v of patch p is
        /// x, y, z at <c>48 p + 12 i + 3 j</c>; a B-spline surface of degree 3 × 3 with
        /// knots 0, 0, 0, 0, 1, 1, 1, 1 in each direction (Rhino's NurbsSurface of order
        /// 4 × 4 with knots 0, 0, 0, 1, 1, 1). u runs from the refined face's first corner
        /// towards its second, v towards its last.
        /// </summary>
        public double[] ControlPoints { get; internal set; }
        /// <summary>For every patch, the cage face it lies on.</summary>
        public uint[] CageFaces { get; internal set; }
        /// <summary>
        /// For every patch, its largest distance from the limit surface: 0 to rounding
        /// where the surface is a bicubic B-spline (away from extraordinary vertices,
        /// crease ends and corners); falls as the isolation rises elsewhere.
        /// </summary>
        public double[] Errors { get; internal set; }
        /// <summary>The largest of <see cref="Errors"/>.</summary>
        public double MaxError { get; internal set; }
        /// <summary>How many patches are exact: an error within 1e-12 of the cage's bounding-box diagonal.</summary>
        public int ExactCount { get; internal set; }
    }

    public static partial class Subdivision
    {
        /// <summary>
        /// The Catmull-Clark limit surface of <paramref name="mesh"/> with
        /// <paramref name="options"/> as one bicubic patch per face of the mesh refined
        /// <paramref name="isolation"/> levels (1 to 8); see <see cref="Weft.LimitPatches"/>.
        /// </summary>
        /// <exception cref="WeftException">
        /// <see cref="WeftStatus.InvalidArgument"/> for an isolation outside 1 to 8; as
        /// <see cref="Subdivide"/> for the options.
        /// </exception>
        public static LimitPatches LimitPatches(WeftMesh mesh, SubdivisionOptions options, int isolation)
        {
            WeftMeshHandle handle = Arguments.Mesh(mesh, "mesh");
            uint levels = Arguments.Unsigned(isolation, "isolation");
            SubdivisionCounts counts = Counts(mesh, Scheme.CatmullClark, isolation, options);
            int count = counts.FaceCount;
            var points = new double[checked(NativeConstants.PatchDoubles * count)];
            var faces = new uint[count];
            var errors = new double[count];
            UIntPtr written, exact;
            var maxError = new double[1];
            uint status;
            using (SubdivisionOptions.Pinned pinned = SubdivisionOptions.Pin(options, Scheme.CatmullClark))
            {
                NativeSubdivisionOptions native = pinned.Native;
                status = NativeMethods.weft_limit_patches(
                    handle, ref native, levels, points, faces, errors, (UIntPtr)count, out written, maxError, out exact);
            }
            WeftException.Check(status);
            return new LimitPatches
            {
                Count = Arguments.ToInt(written),
                Isolation = isolation,
                ControlPoints = points,
                CageFaces = faces,
                Errors = errors,
                MaxError = maxError[0],
                ExactCount = Arguments.ToInt(exact),
            };
        }
    }
}
