// Loads the wrapper from a package folder, as Grasshopper does, and makes one
// mesh through the native library found beside it (check.sh runs it on Mono
// with no library path set). Prints where the library came from.
using System;
using Weft;

public static class LoadProbe
{
    public static int Main()
    {
        using (WeftMesh mesh = WeftMesh.Create(new double[] { 0, 0, 0, 1, 0, 0, 0, 1, 0 }, new uint[] { 3 }, new uint[] { 0, 1, 2 }))
        {
            Console.WriteLine("made a " + mesh.FaceCount + "-face mesh; library from " + (NativeLibraryLoader.LoadedFrom ?? "the default search"));
            return mesh.FaceCount == 1 ? 0 : 1;
        }
    }
}
