using System;
using System.Runtime.InteropServices;

namespace Weft
{
    /// <summary>
    /// Owns one native <c>WeftRefiner *</c> and frees it with the library's
    /// <c>weft_refiner_free</c>, once, from <c>Dispose</c> or the finalizer.
    /// </summary>
    public sealed class WeftRefinerHandle : SafeHandle
    {
        /// <summary>An empty handle; the marshaler fills it from an out-parameter.</summary>
        public WeftRefinerHandle()
            : base(IntPtr.Zero, true)
        {
        }

        /// <summary>True while no refiner is held (NULL).</summary>
        public override bool IsInvalid
        {
            get { return handle == IntPtr.Zero; }
        }

        /// <summary>Frees the refiner; SafeHandle guarantees a single call.</summary>
        protected override bool ReleaseHandle()
        {
            NativeMethods.weft_refiner_free(handle);
            return true;
        }
    }

    /// <summary>
    /// Owns one native <c>WeftLimitSurface *</c> and frees it with the
    /// library's <c>weft_limit_surface_free</c>, once, from <c>Dispose</c> or
    /// the finalizer.
    /// </summary>
    public sealed class WeftLimitSurfaceHandle : SafeHandle
    {
        /// <summary>An empty handle; the marshaler fills it from an out-parameter.</summary>
        public WeftLimitSurfaceHandle()
            : base(IntPtr.Zero, true)
        {
        }

        /// <summary>True while no surface is held (NULL).</summary>
        public override bool IsInvalid
        {
            get { return handle == IntPtr.Zero; }
        }

        /// <summary>Frees the surface; SafeHandle guarantees a single call.</summary>
        protected override bool ReleaseHandle()
        {
            NativeMethods.weft_limit_surface_free(handle);
            return true;
        }
    }

    /// <summary>
    /// Owns one native <c>WeftCells *</c> (Voronoi cells) and frees it with
    /// the library's <c>weft_cells_free</c>, once.
    /// </summary>
    public sealed class WeftCellsHandle : SafeHandle
    {
        /// <summary>An empty handle; the marshaler fills it from an out-parameter.</summary>
        public WeftCellsHandle()
            : base(IntPtr.Zero, true)
        {
        }

        /// <summary>True while no cells are held (NULL).</summary>
        public override bool IsInvalid
        {
            get { return handle == IntPtr.Zero; }
        }

        /// <summary>Frees the cells; SafeHandle guarantees a single call.</summary>
        protected override bool ReleaseHandle()
        {
            NativeMethods.weft_cells_free(handle);
            return true;
        }
    }
}
