using System;
using System.Runtime.InteropServices;
using Grasshopper.Kernel;

namespace Weft.Grasshopper
{
    /// <summary>Merges vertices closer than a tolerance.</summary>
    [Guid("0eff4233-4741-4c91-8cfc-8b88979bddb7")]
    public sealed class WeldComponent : WeftComponent
    {
        public WeldComponent()
            : base("Weld", "Weld",
                   "Merges vertices closer than the tolerance; faces that collapse below three vertices are removed.",
                   "Mend", "weld")
        {
        }

        protected override void RegisterInputParams(GH_InputParamManager pManager)
        {
            AddMeshInput(pManager, "M", "The mesh to weld.");
            AddToleranceInput(pManager, "Welding distance");
        }

        protected override void RegisterOutputParams(GH_OutputParamManager pManager)
        {
            pManager.AddMeshParameter("Mesh", "M", "The welded mesh.", GH_ParamAccess.item);
        }

        protected override void Solve(IGH_DataAccess DA)
        {
            double tolerance = GetTolerance(DA, 1);
            using (WeftMesh mesh = GetMesh(DA, 0))
            {
                if (mesh == null) return;
                using (WeftMesh result = Mending.Weld(mesh, tolerance))
                {
                    SetMesh(DA, 0, result);
                }
            }
        }
    }
}
