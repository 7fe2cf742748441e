using System;
using System.Collections.Generic;
using System.IO;
using System.Reflection;
using System.Runtime.InteropServices;

namespace Weft
{
    /// <summary>
    /// Makes <c>[DllImport("weft")]</c> find the native library that ships
    /// beside this assembly, wherever the host process lives.
    /// </summary>
    /// <remarks>
    /// Inside Rhino the process's folder is Rhino's, not the plug-in's, so the
    /// default search misses the library. On .NET 7+ a resolver picks
    /// <c>runtimes/&lt;rid&gt;/native/</c> (win-x64, osx-arm64, osx-x64, linux-x64)
    /// or the assembly's own folder. On .NET Framework and Mono the library is
    /// loaded by full path once (<c>LoadLibrary</c> on Windows, <c>dlopen</c>
    /// elsewhere); later DllImports bind to the module already loaded.
    /// </remarks>
    public static class NativeLibraryLoader
    {
        private static readonly object Gate = new object();
        private static readonly List<string> extraFolders = new List<string>();
        private static bool attempted;

        /// <summary>The full path the library was loaded from, or null when the default search was left to find it.</summary>
        public static string LoadedFrom { get; private set; }

        /// <summary>Installs the resolver or preloads the library; safe to call many times.</summary>
        public static void EnsureLoaded()
        {
            lock (Gate)
            {
                if (attempted)
                {
                    return;
                }
                attempted = true;
#if NETCOREAPP
                NativeLibrary.SetDllImportResolver(typeof(NativeLibraryLoader).Assembly, Resolve);
#else
                Preload();
#endif
            }
        }

        /// <summary>
        /// Adds a folder to look in after the assembly's own: the host's word for where the
        /// plug-in lives, for when the assembly was loaded from bytes and has no location
        /// (Grasshopper's COFF loading). Retries the preload if it found nothing before.
        /// </summary>
        public static void AddSearchFolder(string folder)
        {
            if (string.IsNullOrEmpty(folder)) return;
            lock (Gate)
            {
                if (!extraFolders.Contains(folder)) extraFolders.Add(folder);
#if !NETCOREAPP
                if (attempted && LoadedFrom == null) Preload();
#endif
            }
        }

        /// <summary>The runtime identifier of this process: win-x64, osx-arm64, osx-x64, linux-x64 or linux-arm64.</summary>
        public static string RuntimeIdentifier()
        {
            string os;
            if (RuntimeInformation.IsOSPlatform(OSPlatform.Windows))
            {
                os = "win";
            }
            else if (RuntimeInformation.IsOSPlatform(OSPlatform.OSX))
            {
                os = "osx";
            }
            else
            {
                os = "linux";
            }
            string arch = RuntimeInformation.ProcessArchitecture == Architecture.Arm64 ? "arm64" : "x64";
            return os + "-" + arch;
        }

        /// <summary>The platform's file name for the library: weft.dll, libweft.dylib or libweft.so.</summary>
        public static string FileName()
        {
            if (RuntimeInformation.IsOSPlatform(OSPlatform.Windows))
            {
                return "weft.dll";
            }
            if (RuntimeInformation.IsOSPlatform(OSPlatform.OSX))
            {
                return "libweft.dylib";
            }
            return "libweft.so";
        }

        /// <summary>
        /// Where to look, best first: the per-platform runtimes folder, then beside the
        /// assembly, then the same two in each folder given to <see cref="AddSearchFolder"/>.
        /// </summary>
        public static IList<string> CandidatePaths()
        {
            var folders = new List<string>();
            string location = typeof(NativeLibraryLoader).Assembly.Location;
            if (!string.IsNullOrEmpty(location))
            {
                folders.Add(Path.GetDirectoryName(location));
            }
            lock (Gate)
            {
                folders.AddRange(extraFolders);
            }
            var paths = new List<string>();
            string file = FileName();
            foreach (string folder in folders)
            {
                paths.Add(Path.Combine(Path.Combine(Path.Combine(Path.Combine(folder, "runtimes"), RuntimeIdentifier()), "native"), file));
                paths.Add(Path.Combine(folder, file));
            }
            return paths;
        }

#if NETCOREAPP
        private static IntPtr Resolve(string libraryName, Assembly assembly, DllImportSearchPath? searchPath)
        {
            if (libraryName != NativeMethods.Library)
            {
                return IntPtr.Zero;
            }
            foreach (string path in CandidatePaths())
            {
                IntPtr module;
                if (File.Exists(path) && NativeLibrary.TryLoad(path, out module))
                {
                    LoadedFrom = path;
                    return module;
                }
            }
            // Fall back to the default search (PATH, LD_LIBRARY_PATH, ...).
            return IntPtr.Zero;
        }
#else
        private static void Preload()
        {
            foreach (string path in CandidatePaths())
            {
                if (!File.Exists(path))
                {
                    continue;
                }
                bool loaded;
                try
                {
                    loaded = RuntimeInformation.IsOSPlatform(OSPlatform.Windows)
                        ? Kernel32.LoadLibraryW(path) != IntPtr.Zero
                        : Dl.Open(path) != IntPtr.Zero;
                }
                catch (DllNotFoundException)
                {
                    loaded = false;
                }
                catch (EntryPointNotFoundException)
                {
                    loaded = false;
                }
                if (loaded)
                {
                    LoadedFrom = path;
                    return;
                }
            }
        }

        private static class Kernel32
        {
            [DllImport("kernel32", CharSet = CharSet.Unicode, SetLastError = true)]
            internal static extern IntPtr LoadLibraryW(string path);
        }

        /// <summary>dlopen lives in libdl on older glibc and in libSystem on macOS.</summary>
        private static class Dl
        {
            private const int RtldNow = 2;
            private const int RtldGlobal = 0x100;

            [DllImport("libdl.so.2", EntryPoint = "dlopen")]
            private static extern IntPtr DlopenLinux(string path, int flags);

            [DllImport("libSystem.dylib", EntryPoint = "dlopen")]
            private static extern IntPtr DlopenMac(string path, int flags);

            internal static IntPtr Open(string path)
            {
                if (RuntimeInformation.IsOSPlatform(OSPlatform.OSX))
                {
                    return DlopenMac(path, RtldNow);
                }
                return DlopenLinux(path, RtldNow | RtldGlobal);
            }
        }
#endif
    }
}
