using System;
using System.Runtime.InteropServices;

namespace Weft
{
    /// <summary>
    /// Owns one native <c>WeftMesh *</c> and frees it with the library's own
    /// <c>weft_mesh_free</c> (never another runtime's allocator), once, from
    /// <c>Dispose</c> or the finalizer.
    /// </summary>
    public sealed class WeftMeshHandle : SafeHandle
    {
        /// <summary>An empty handle; the marshaler fills it from an out-parameter.</summary>
        public WeftMeshHandle()
            : base(IntPtr.Zero, true)
        {
        }

        /// <summary>True while no mesh is held (NULL).</summary>
        public override bool IsInvalid
        {
            get { return handle == IntPtr.Zero; }
        }

        /// <summary>Frees the mesh; SafeHandle guarantees a single call.</summary>
        protected override bool ReleaseHandle()
        {
            NativeMethods.weft_mesh_free(handle);
            return true;
        }
    }
}
