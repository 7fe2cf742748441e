using System;
using System.Runtime.InteropServices;
using Grasshopper.Kernel;

namespace Weft.Grasshopper
{
    /// <summary>
    /// A mending check: one mesh (input 0, M) and a tolerance T (input 1, the document's
    /// when empty); subclasses register their outputs and implement <see cref="Check"/>.
    /// </summary>
    public abstract class MeshCheckComponent : MeshQueryComponent
    {
        private readonly string toleranceDescription;

        protected MeshCheckComponent(string name, string nickname, string description, string iconName, string toleranceDescription)
            : base(name, nickname, description, "Mend", iconName, "The mesh to check.")
        {
            this.toleranceDescription = toleranceDescription;
        }

        protected sealed override void RegisterOptions(GH_InputParamManager pManager)
        {
            AddToleranceInput(pManager, toleranceDescription);
        }

        protected sealed override void Query(WeftMesh mesh, IGH_DataAccess DA)
        {
            Check(mesh, GetTolerance(DA, 1), DA);
        }

        /// <summary>Checks the mesh within <paramref name="tolerance"/> and sets the outputs.</summary>
        protected abstract void Check(WeftMesh mesh, double tolerance, IGH_DataAccess DA);
    }

    /// <summary>Finds and repairs T-nodes.</summary>
    [Guid("670ccfc8-ec80-4d89-a198-5e0a31845f0f")]
    public sealed class TNodesComponent : MeshCheckComponent
    {
        public TNodesComponent()
            : base("T-Nodes", "TNodes",
                   "Finds the vertices that lie inside another face's naked edge (T-nodes) and repairs them by inserting each into that edge, so both sides share the seam.",
                   "t_nodes", "Distance from the edge")
        {
        }

        protected override void RegisterOutputParams(GH_OutputParamManager pManager)
        {
            AddMeshOutput(pManager, "The repaired mesh.");
            pManager.AddPointParameter("T-Nodes", "P", "The T-node vertices found.", GH_ParamAccess.list);
            pManager.AddIntegerParameter("Faces", "F", "The face whose edge each T-node lies on.", GH_ParamAccess.list);
        }

        protected override void Check(WeftMesh mesh, double tolerance, IGH_DataAccess DA)
        {
            WeftTNode[] nodes = Mending.FindTNodes(mesh, tolerance);
            double[] positions = mesh.GetPositions();
            var nodePositions = new double[3 * nodes.Length];
            var faces = new int[nodes.Length];
            for (int i = 0; i < nodes.Length; i++)
            {
                Array.Copy(positions, 3 * (int)nodes[i].Vertex, nodePositions, 3 * i, 3);
                faces[i] = (int)nodes[i].Face;
            }
            int inserted;
            using (WeftMesh repaired = Mending.RepairTNodes(mesh, tolerance, out inserted))
            {
                SetMesh(DA, 0, repaired);
            }
            DA.SetDataList(1, RhinoMeshes.ToPoints(nodePositions));
            DA.SetDataList(2, faces);
            if (inserted > 0) Remark(inserted + " T-node(s) inserted into their edges.");
        }
    }

    /// <summary>Per-face planarity.</summary>
    [Guid("d5dd8f4e-d687-4cf8-84eb-52e3beb7f54f")]
    public sealed class PlanarityComponent : MeshCheckComponent
    {
        public PlanarityComponent()
            : base("Planarity", "Planarity",
                   "Per face, the largest distance of a corner from the face's best-fit plane (0 for triangles), and whether it is within the tolerance: the planar-quad check for glass and panels.",
                   "planarity", "Largest deviation counted as planar")
        {
        }

        protected override void RegisterOutputParams(GH_OutputParamManager pManager)
        {
            pManager.AddNumberParameter("Deviation", "D", "Per face, the largest corner distance from its best-fit plane.", GH_ParamAccess.list);
            pManager.AddBooleanParameter("Planar", "P", "Per face, deviation within the tolerance.", GH_ParamAccess.list);
            pManager.AddNumberParameter("Maximum", "X", "The largest deviation of all faces.", GH_ParamAccess.item);
        }

        protected override void Check(WeftMesh mesh, double tolerance, IGH_DataAccess DA)
        {
            double[] deviations = Mending.Planarity(mesh);
            double max = 0;
            foreach (double d in deviations) max = Math.Max(max, d);
            DA.SetDataList(0, deviations);
            DA.SetDataList(1, FlatGeometry.WithinTolerance(deviations, tolerance));
            DA.SetData(2, max);
        }
    }
}
