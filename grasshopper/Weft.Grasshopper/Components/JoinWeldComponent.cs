using System.Runtime.InteropServices;
using Grasshopper.Kernel;

namespace Weft.Grasshopper
{
    /// <summary>Joins meshes and optionally welds them (Weaverbird's wbJoin).</summary>
    [Guid("925c212d-9b67-4d93-b7dd-e07cda6ad9c5")]
    public sealed class JoinWeldComponent : WeftComponent
    {
        public JoinWeldComponent()
            : base("Join Meshes and Weld", "wbJoin",
                   "Joins meshes into one and merges the vertices at most the tolerance apart.",
                   "Mend", "join")
        {
        }

        protected override void RegisterInputParams(GH_InputParamManager pManager)
        {
            AddMeshInput(pManager, "M+", "The meshes to join.");
            pManager.AddBooleanParameter("Weld", "W", "Merge vertices at most the tolerance apart.", GH_ParamAccess.item, true);
            AddToleranceInput(pManager, "Welding distance");
        }

        protected override void RegisterOutputParams(GH_OutputParamManager pManager)
        {
            AddMeshOutput(pManager, "The joined mesh.");
        }

        protected override void Solve(IGH_DataAccess DA)
        {
            bool weld = Get(DA, 1, true);
            double tolerance = weld ? GetTolerance(DA, 2) : 0;
            using (WeftMesh joined = GetMesh(DA, 0))
            {
                if (joined == null) return;
                if (!weld)
                {
                    SetMesh(DA, 0, joined);
                    return;
                }
                WeftWeldReport report;
                using (WeftMesh welded = Mending.Weld(joined, tolerance, out report))
                {
                    WarnOfCollapse(report, joined.FaceCount, tolerance);
                    SetMesh(DA, 0, welded);
                }
            }
        }
    }
}
