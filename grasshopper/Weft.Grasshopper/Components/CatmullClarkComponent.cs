using System;
using System.Runtime.InteropServices;

namespace Weft.Grasshopper
{
    /// <summary>Catmull-Clark subdivision of triangles, quads and n-gons (Weaverbird's wbCatmullClark).</summary>
    [Guid("91930430-9fe1-4b0d-88d0-669bbe778098")]
    public sealed class CatmullClarkComponent : PlainSubdivisionComponent
    {
        public CatmullClarkComponent()
            : base(Scheme.CatmullClark, "Catmull-Clark Subdivision", "wbCatmullClark",
                   "Subdivides a mesh with the Catmull-Clark scheme; after one level every face is a quad. While the faces stay the same, moving the vertices only re-evaluates the planned subdivision.",
                   "catmull_clark")
        {
        }
    }
}
