using System;
using System.Runtime.InteropServices;
using Grasshopper.Kernel;

namespace Weft.Grasshopper
{
    /// <summary>Unifies the winding of each connected piece, or flips every face.</summary>
    [Guid("b8b331ec-ddfe-459f-be4b-e146759fce39")]
    public sealed class OrientComponent : MeshQueryComponent
    {
        public OrientComponent()
            : base("Unify or Flip", "Orient",
                   "Gives each connected piece one winding (flipping the fewest faces) and turns closed pieces outward, or flips every face.",
                   "Mend", "orient", "The mesh to orient.")
        {
        }

        protected override void RegisterOptions(GH_InputParamManager pManager)
        {
            pManager.AddBooleanParameter("Flip", "F", "Flip every face instead of unifying.", GH_ParamAccess.item, false);
        }

        protected override void RegisterOutputParams(GH_OutputParamManager pManager)
        {
            AddMeshOutput(pManager, "The oriented mesh.");
            pManager.AddIntegerParameter("Flipped", "N", "How many faces changed direction.", GH_ParamAccess.item);
        }

        protected override void Query(WeftMesh mesh, IGH_DataAccess DA)
        {
            bool flipAll = Get(DA, 1, false);
            if (flipAll)
            {
                using (WeftMesh result = Mending.Flip(mesh))
                {
                    SetMesh(DA, 0, result);
                    DA.SetData(1, result.FaceCount);
                }
                return;
            }
            // Unify, and turn every closed piece outward; say which pieces had no inside.
            WeftOrientReport report;
            using (WeftMesh result = Mending.OrientOutward(mesh, out report))
            {
                if (report.OpenPieces > 0)
                {
                    AddRuntimeMessage(GH_RuntimeMessageLevel.Remark, report.OpenPieces + " of " + report.Pieces
                        + " pieces are open (a naked or non-manifold edge): unified, but with no inside to face away from.");
                }
                if (report.NonOrientablePieces > 0)
                {
                    AddRuntimeMessage(GH_RuntimeMessageLevel.Warning, report.NonOrientablePieces
                        + " pieces cannot be oriented (a Möbius strip): wound as consistently as they can be.");
                }
                SetMesh(DA, 0, result);
                DA.SetData(1, (int)report.FlippedFaces);
            }
        }
    }
}
