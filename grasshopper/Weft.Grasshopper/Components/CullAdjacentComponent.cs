using System;
using System.Runtime.InteropServices;
using Grasshopper.Kernel;

namespace Weft.Grasshopper
{
    /// <summary>Removes faces that have a twin over the same vertices: the inner walls of joined boxes.</summary>
    [Guid("04050a87-1f12-4935-9270-6d7fecab09c4")]
    public sealed class CullAdjacentComponent : MeshQueryComponent
    {
        public CullAdjacentComponent()
            : base("Cull Adjacent Faces", "CullAdj",
                   "Removes every face that shares all its vertices with another face (both copies go). Weld first.",
                   "Mend", "cull", "The welded mesh to clean.")
        {
        }

        protected override void RegisterOutputParams(GH_OutputParamManager pManager)
        {
            AddMeshOutput(pManager, "The mesh without its adjacent face pairs.");
            pManager.AddIntegerParameter("Removed", "N", "How many faces were removed.", GH_ParamAccess.item);
        }

        protected override void Query(WeftMesh mesh, IGH_DataAccess DA)
        {
            int removed;
            using (WeftMesh culled = Mending.CullAdjacent(mesh, out removed))
            {
                SetMesh(DA, 0, culled);
                DA.SetData(1, removed);
            }
        }
    }
}
