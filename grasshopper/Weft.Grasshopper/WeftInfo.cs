using System;
using System.Drawing;
using System.IO;
using System.Reflection;
using Grasshopper.Kernel;

// A normal load from the file, so Assembly.Location names the plug-in's folder
// (Grasshopper's COFF option loads from bytes and leaves it empty).
[assembly: GH_Loading(GH_LoadingDemand.ForceDirect)]

namespace Weft.Grasshopper
{
    /// <summary>The plug-in's identity in Grasshopper.</summary>
    public sealed class WeftInfo : GH_AssemblyInfo
    {
        public override string Name
        {
            get { return "Weft"; }
        }

        public override string Description
        {
            get { return "Subdivision surfaces (Catmull-Clark, Loop) and mesh making and mending, in native code."; }
        }

        /// <summary>The plug-in's id; never changes.</summary>
        public static readonly Guid PluginId = new Guid("545d14d6-68b0-4670-a93e-78b63feb4f98");

        public override Guid Id
        {
            get { return PluginId; }
        }

        public override string AuthorName
        {
            get { return "The Weft authors"; }
        }

        public override string AuthorContact
        {
            get { return "https://github.com/weft-mesh/weft"; }
        }

        public override string Version
        {
            get { return "0.1.0"; }
        }

        public override Bitmap Icon
        {
            get { return Icons.Load("weft"); }
        }
    }

    /// <summary>
    /// Loads the native library by full path before any component runs:
    /// .NET Framework looks in Rhino's folder, not the plug-in's.
    /// </summary>
    public sealed class WeftPriority : GH_AssemblyPriority
    {
        public override GH_LoadingInstruction PriorityLoad()
        {
            // Should the assembly still have been loaded from bytes, Grasshopper knows the .gha's path.
            GH_ComponentServer server = global::Grasshopper.Instances.ComponentServer;
            GH_AssemblyInfo info = server == null ? null : server.FindAssembly(WeftInfo.PluginId);
            if (info != null && !string.IsNullOrEmpty(info.Location))
            {
                NativeLibraryLoader.AddSearchFolder(Path.GetDirectoryName(info.Location));
            }
            NativeLibraryLoader.EnsureLoaded();
            return GH_LoadingInstruction.Proceed;
        }
    }

    /// <summary>The 24 × 24 component icons, embedded as PNG resources.</summary>
    internal static class Icons
    {
        /// <summary>The icon named <paramref name="name"/>, or null when it is missing.</summary>
        internal static Bitmap Load(string name)
        {
            Stream stream = typeof(Icons).Assembly.GetManifestResourceStream("Weft.Grasshopper.Icons." + name + ".png");
            return stream == null ? null : new Bitmap(stream);
        }
    }
}
