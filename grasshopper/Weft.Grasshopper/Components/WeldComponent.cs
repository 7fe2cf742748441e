using System;
using System.Runtime.InteropServices;
using Grasshopper.Kernel;

namespace Weft.Grasshopper
{
    /// <summary>Merges vertices at most a tolerance apart.</summary>
    [Guid("0eff4233-4741-4c91-8cfc-8b88979bddb7")]
    public sealed class WeldComponent : MeshOperationComponent
    {
        public WeldComponent()
            : base("Weld", "Weld",
                   "Merges vertices at most the tolerance apart; faces that collapse below three vertices are removed.",
                   "Mend", "weld", "The mesh to weld.", "The welded mesh.")
        {
        }

        protected override void RegisterOptions(GH_InputParamManager pManager)
        {
            AddToleranceInput(pManager, "Welding distance");
        }

        protected override WeftMesh Apply(WeftMesh mesh, IGH_DataAccess DA)
        {
            double tolerance = GetTolerance(DA, 1);
            WeftWeldReport report;
            WeftMesh welded = Mending.Weld(mesh, tolerance, out report);
            WarnOfCollapse(report, mesh.FaceCount, tolerance);
            return welded;
        }
    }
}
