using System;
using System.Runtime.InteropServices;
using System.Text;

namespace Weft
{
    /// <summary>
    /// A Weft call failed. <see cref="Status"/> is the library's status code and
    /// <see cref="Exception.Message"/> its sentence naming what and where
    /// (face k, vertex i).
    /// </summary>
    [Serializable]
    public class WeftException : Exception
    {
        /// <summary>The status the library returned.</summary>
        public WeftStatus Status { get; private set; }

        /// <summary>Creates an exception for a status and its message.</summary>
        public WeftException(WeftStatus status, string message)
            : base(message)
        {
            Status = status;
        }

        /// <summary>
        /// Throws when <paramref name="status"/> (the raw value a native call
        /// returned) is not OK, with the calling thread's last error message.
        /// </summary>
        internal static void Check(uint status)
        {
            if (status != (uint)WeftStatus.Ok)
            {
                throw new WeftException((WeftStatus)status, LastErrorMessage());
            }
        }

        /// <summary>The library's message for the last failure on the calling thread, or "" when none failed.</summary>
        public static string LastErrorMessage()
        {
            NativeLibraryLoader.EnsureLoaded();
            return Utf8.FromNative(NativeMethods.weft_last_error_message());
        }
    }

    /// <summary>
    /// UTF-8 strings from native memory. .NET Framework 4.8 has no
    /// <c>Marshal.PtrToStringUTF8</c>, so the bytes are decoded here.
    /// </summary>
    internal static class Utf8
    {
        /// <summary>Copies a NUL-terminated UTF-8 string; NULL gives "".</summary>
        internal static string FromNative(IntPtr text)
        {
            if (text == IntPtr.Zero)
            {
                return string.Empty;
            }
            int length = 0;
            while (Marshal.ReadByte(text, length) != 0)
            {
                length++;
            }
            var bytes = new byte[length];
            Marshal.Copy(text, bytes, 0, length);
            return Encoding.UTF8.GetString(bytes);
        }
    }
}
