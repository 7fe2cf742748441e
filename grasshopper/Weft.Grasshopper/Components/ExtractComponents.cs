using System;
using System.Runtime.InteropServices;
using Grasshopper.Kernel;

namespace Weft.Grasshopper
{
    /// <summary>The dual mesh: a vertex at each face centroid, a face per interior vertex joining the faces around it; vertices on naked edges get no face.</summary>
    [Guid("d4a2bb2b-bd31-4737-ba82-83eb3e6ecd54")]
    public sealed class DualComponent : MeshOperationComponent
    {
        public DualComponent()
            : base("Dual Graph", "wbDual",
                   "The dual mesh: a vertex at each face centroid, a face per interior vertex joining the faces around it; vertices on naked edges get no face.",
                   "Extract", "dual", "The mesh.", "The dual mesh.")
        {
        }

        protected override void RegisterOptions(GH_InputParamManager pManager)
        {
            pManager.AddBooleanParameter("Keep Size", "K", "Scale the dual to the bounding box size of the input.", GH_ParamAccess.item, false);
        }

        protected override WeftMesh Apply(WeftMesh mesh, IGH_DataAccess DA)
        {
            return Toolbar.Dual(mesh, Get(DA, 1, false) ? DualMode.KeepSize : DualMode.VertexAverage);
        }
    }

    /// <summary>Rotates every face's corner list so it starts Shift corners later (negative goes back); winding and vertices are unchanged.</summary>
    [Guid("ab3b0057-745e-45f1-b503-104957dda0c9")]
    public sealed class RerouteFacesComponent : MeshOperationComponent
    {
        public RerouteFacesComponent()
            : base("Reroute Faces", "wbReroute",
                   "Rotates every face's corner list so it starts Shift corners later (negative goes back); winding and vertices are unchanged.",
                   "Extract", "reroute", "The mesh.", "The mesh with rotated faces.")
        {
        }

        protected override void RegisterOptions(GH_InputParamManager pManager)
        {
            pManager.AddIntegerParameter("Shift", "S", "Corners to shift by; wraps around each face.", GH_ParamAccess.item, 1);
        }

        protected override WeftMesh Apply(WeftMesh mesh, IGH_DataAccess DA)
        {
            return Toolbar.RerouteFaces(mesh, Get(DA, 1, 1));
        }
    }
}
