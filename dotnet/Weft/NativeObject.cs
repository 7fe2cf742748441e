using System;
using System.Runtime.InteropServices;

namespace Weft
{
    /// <summary>
    /// What the wrapper's disposable objects share: one native handle, freed by
    /// <see cref="Dispose"/> (or, if that is forgotten, by the handle's finalizer)
    /// and refused by every call after that.
    /// </summary>
    /// <typeparam name="THandle">The SafeHandle that frees the native object.</typeparam>
    public abstract class NativeObject<THandle> : IDisposable where THandle : SafeHandle
    {
        private readonly THandle handle;
        private readonly string disposedMessage;

        // Internal: only the wrapper's own types own native handles.
        internal NativeObject(THandle handle, string disposedMessage)
        {
            this.handle = handle;
            this.disposedMessage = disposedMessage;
        }

        /// <summary>True once <see cref="Dispose"/> has run.</summary>
        public bool IsDisposed
        {
            get { return handle.IsClosed; }
        }

        /// <summary>Frees the native object; later calls are ignored.</summary>
        public void Dispose()
        {
            handle.Dispose();
        }

        /// <summary>The native handle, for wrapper methods; refused after Dispose.</summary>
        internal THandle Handle
        {
            get
            {
                if (handle.IsClosed) throw new ObjectDisposedException(GetType().Name, disposedMessage);
                return handle;
            }
        }
    }
}
