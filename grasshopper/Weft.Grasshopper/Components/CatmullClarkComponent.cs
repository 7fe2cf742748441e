using System;
using Grasshopper.Kernel;

namespace Weft.Grasshopper
{
    /// <summary>Catmull-Clark subdivision of triangles, quads and n-gons (Weaverbird's wbCatmullClark).</summary>
    public sealed class CatmullClarkComponent : WeftComponent
    {
        public CatmullClarkComponent()
            : base("Catmull-Clark Subdivision", "wbCatmullClark",
                   "Subdivides a mesh with the Catmull-Clark scheme; after one level every face is a quad. While the faces stay the same, moving the vertices only re-evaluates the planned subdivision.",
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

        // One plan per cage topology: moving the cage only re-evaluates positions.
        private readonly RefinerCache cache = new RefinerCache();

        protected override void Solve(IGH_DataAccess DA)
        {
            int levels = Get(DA, 1, 1);
            NakedEdges nakedEdges = ToNakedEdges(Get(DA, 2, 1));
            PolygonArrays cage = GetPolygons(DA, 0);
            if (cage == null) return;
            RefinedArrays refined = cache.Subdivide(cage.Positions, cage.FaceSizes, cage.FaceIndices, Scheme.CatmullClark, levels, nakedEdges);
            DA.SetData(0, RhinoMeshes.FromArrays(refined.Positions, refined.Rhino));
        }
    }
}
