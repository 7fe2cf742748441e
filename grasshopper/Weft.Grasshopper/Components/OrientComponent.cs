using System;
using System.Runtime.InteropServices;
using Grasshopper.Kernel;

namespace Weft.Grasshopper
{
    /// <summary>Unifies the winding of each connected piece, or flips every face.</summary>
    [Guid("b8b331ec-ddfe-459f-be4b-e146759fce39")]
    public sealed class OrientComponent : WeftComponent
    {
        public OrientComponent()
            : base("Unify or Flip", "Orient",
                   "Gives each connected piece one winding (flipping the fewest faces), or flips every face.",
                   "Mend", "orient")
        {
        }

        protected override void RegisterInputParams(GH_InputParamManager pManager)
        {
            AddMeshInput(pManager, "M", "The mesh to orient.");
            pManager.AddBooleanParameter("Flip", "F", "Flip every face instead of unifying.", GH_ParamAccess.item, false);
        }

        protected override void RegisterOutputParams(GH_OutputParamManager pManager)
        {
            pManager.AddMeshParameter("Mesh", "M", "The oriented mesh.", GH_ParamAccess.item);
            pManager.AddIntegerParameter("Flipped", "N", "How many faces changed direction.", GH_ParamAccess.item);
        }

        protected override void Solve(IGH_DataAccess DA)
        {
            bool flipAll = false;
            DA.GetData(1, ref flipAll);
            using (WeftMesh mesh = GetMesh(DA, 0))
            {
                if (mesh == null) return;
                if (flipAll)
                {
                    using (WeftMesh result = Mending.Flip(mesh))
                    {
                        SetMesh(DA, 0, result);
                        DA.SetData(1, result.FaceCount);
                    }
                    return;
                }
                int flipped;
                using (WeftMesh result = Mending.UnifyOrientation(mesh, out flipped))
                {
                    SetMesh(DA, 0, result);
                    DA.SetData(1, (int)flipped);
                }
            }
        }
    }
}
