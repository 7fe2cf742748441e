using System;
using Grasshopper.Kernel;

namespace Weft.Grasshopper
{
    /// <summary>Catmull-Clark subdivision of triangles, quads and n-gons (Weaverbird's wbCatmullClark).</summary>
    public sealed class CatmullClarkComponent : WeftComponent
    {
        public CatmullClarkComponent()
            : base("Catmull-Clark Subdivision", "wbCatmullClark",
                   "Subdivides a mesh with the Catmull-Clark scheme; after one level every face is a quad.",
                   "Subdivide", "catmull_clark")
        {
        }

        public override Guid ComponentGuid
        {
            get { return new Guid("91930430-9fe1-4b0d-88d0-669bbe778098"); }
        }

        protected override void RegisterInputParams(GH_InputParamManager pManager)
        {
            AddMeshInput(pManager, "M", "The mesh to subdivide.");
            pManager.AddIntegerParameter("Level", "L", "Subdivision levels (0 returns the input).", GH_ParamAccess.item, 1);
            pManager.AddIntegerParameter("Smooth Naked Edges", "S", "0: fixed, 1: smooth, 2: corner fixed.", GH_ParamAccess.item, 1);
        }

        protected override void RegisterOutputParams(GH_OutputParamManager pManager)
        {
            pManager.AddMeshParameter("Mesh", "M", "The subdivided mesh.", GH_ParamAccess.item);
        }

        protected override void Solve(IGH_DataAccess DA)
        {
            int levels = 1, mode = 1;
            DA.GetData(1, ref levels);
            DA.GetData(2, ref mode);
            NakedEdges nakedEdges = ToNakedEdges(mode);
            using (WeftMesh mesh = GetMesh(DA, 0))
            {
                if (mesh == null) return;
                using (WeftMesh result = Operations.CatmullClark(mesh, levels, nakedEdges))
                {
                    SetMesh(DA, 0, result);
                }
            }
        }
    }
}
