using System;
using System.Runtime.InteropServices;
using Grasshopper.Kernel;

namespace Weft.Grasshopper
{
    /// <summary>Splits quads along the shorter diagonal and n-gons by ear clipping.</summary>
    [Guid("09a3b686-debf-4bac-a987-93bbb3c72184")]
    public sealed class TriangulateComponent : WeftComponent
    {
        public TriangulateComponent()
            : base("Triangulate", "Triangulate",
                   "Splits every quad along its shorter diagonal and every n-gon into triangles.",
                   "Mend", "triangulate")
        {
        }

        protected override void RegisterInputParams(GH_InputParamManager pManager)
        {
            AddMeshInput(pManager, "M", "The mesh to triangulate.");
        }

        protected override void RegisterOutputParams(GH_OutputParamManager pManager)
        {
            pManager.AddMeshParameter("Mesh", "M", "The triangle mesh.", GH_ParamAccess.item);
        }

        protected override void Solve(IGH_DataAccess DA)
        {
            using (WeftMesh mesh = GetMesh(DA, 0))
            {
                if (mesh == null) return;
                using (WeftMesh result = Subdivision.Triangulate(mesh))
                {
                    SetMesh(DA, 0, result);
                }
            }
        }
    }
}
