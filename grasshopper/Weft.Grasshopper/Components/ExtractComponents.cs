using System;
using System.Runtime.InteropServices;
using Grasshopper.Kernel;

namespace Weft.Grasshopper
{
    /// <summary>The dual mesh: a vertex at each face centroid, a face per interior vertex joining the faces around it; vertices on naked edges get no face.</summary>
    [Guid("d4a2bb2b-bd31-4737-ba82-83eb3e6ecd54")]
    public sealed class DualComponent : OptionOperationComponent<bool>
    {
        public DualComponent()
            : base("Dual Graph", "wbDual",
                   "The dual mesh: a vertex at each face centroid, a face per interior vertex joining the faces around it; vertices on naked edges get no face.",
                   ItemOption.Boolean("Keep Size", "K", "Scale the dual to the bounding box size of the input.", false),
                   (mesh, keepSize) => Toolbar.Dual(mesh, keepSize ? DualMode.KeepSize : DualMode.VertexAverage),
                   "Extract", "dual", "The mesh.", "The dual mesh.")
        {
        }
    }

    /// <summary>Rotates every face's corner list so it starts Shift corners later (negative goes back); winding and vertices are unchanged.</summary>
    [Guid("ab3b0057-745e-45f1-b503-104957dda0c9")]
    public sealed class RerouteFacesComponent : OptionOperationComponent<int>
    {
        public RerouteFacesComponent()
            : base("Reroute Faces", "wbReroute",
                   "Rotates every face's corner list so it starts Shift corners later (negative goes back); winding and vertices are unchanged.",
                   ItemOption.Integer("Shift", "S", "Corners to shift by; wraps around each face.", 1),
                   (mesh, shift) => Toolbar.RerouteFaces(mesh, shift),
                   "Extract", "reroute", "The mesh.", "The mesh with rotated faces.")
        {
        }
    }
}
