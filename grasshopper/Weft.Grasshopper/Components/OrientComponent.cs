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
                   "Gives each connected piece one winding (flipping the fewest faces), or flips every face.",
                   "Mend", "orient", "The mesh to orient.")
        {
        }

        protected override void RegisterOptions(GH_InputParamManager pManager)
        {
            pManager.AddBooleanParameter("Flip", "F", "Flip every face instead of unifying.", GH_ParamAccess.item, false);
        }

        protected override void RegisterOutputParams(GH_OutputParamManager pManager)
        {
            pManager.AddMeshParameter("Mesh", "M", "The oriented mesh.", GH_ParamAccess.item);
            pManager.AddIntegerParameter("Flipped", "N", "How many faces changed direction.", GH_ParamAccess.item);
        }

        protected override void Query(WeftMesh mesh, IGH_DataAccess DA)
        {
            bool flipAll = Get(DA, 1, false);
            int flipped = 0;
            using (WeftMesh result = flipAll ? Mending.Flip(mesh) : Mending.UnifyOrientation(mesh, out flipped))
            {
                SetMesh(DA, 0, result);
                DA.SetData(1, flipAll ? result.FaceCount : flipped);
            }
        }
    }
}
