using System;
using System.Runtime.InteropServices;
using Grasshopper.Kernel;

namespace Weft.Grasshopper
{
    /// <summary>Splits quads along the shorter diagonal and n-gons by ear clipping.</summary>
    [Guid("09a3b686-debf-4bac-a987-93bbb3c72184")]
    public sealed class TriangulateComponent : MeshOperationComponent
    {
        public TriangulateComponent()
            : base("Triangulate", "Triangulate",
                   "Splits every quad along its shorter diagonal and every n-gon into triangles.",
                   "Mend", "triangulate", "The mesh to triangulate.", "The triangle mesh.")
        {
        }

        protected override WeftMesh Apply(WeftMesh mesh, IGH_DataAccess DA)
        {
            return Subdivision.Triangulate(mesh);
        }
    }
}
