using System;
using Grasshopper.Kernel;

namespace Weft.Grasshopper
{
    /// <summary>Loop subdivision (Weaverbird's wbLoop); quads and n-gons are triangulated first.</summary>
    public sealed class LoopComponent : WeftComponent
    {
        public LoopComponent()
            : base("Loop Subdivision", "wbLoop",
                   "Subdivides a triangle mesh with the Loop scheme; quads and n-gons are triangulated first.",
                   "Subdivide", "loop")
        {
        }

        public override Guid ComponentGuid
        {
            get { return new Guid("57a9011b-8439-44ee-bf53-c3ea93793bc6"); }
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

        // One plan per (triangulated) cage topology: moving the cage only re-evaluates positions.
        private readonly RefinerCache cache = new RefinerCache();

        protected override void Solve(IGH_DataAccess DA)
        {
            int levels = Get(DA, 1, 1);
            NakedEdges nakedEdges = ToNakedEdges(Get(DA, 2, 1));
            PolygonArrays cage = GetPolygons(DA, 0);
            if (cage == null) return;
            int others = CountNonTriangles(cage.FaceSizes);
            if (others > 0)
            {
                Remark(others + " quad or n-gon face(s) were triangulated before subdividing.");
                cage = MeshArrays.Triangulate(cage);
            }
            RefinedArrays refined = cache.Subdivide(cage.Positions, cage.FaceSizes, cage.FaceIndices, Scheme.Loop, levels, nakedEdges);
            DA.SetData(0, RhinoMeshes.FromArrays(refined.Positions, refined.Rhino));
        }

        /// <summary>Faces that are not triangles.</summary>
        public static int CountNonTriangles(uint[] faceSizes)
        {
            int count = 0;
            foreach (uint size in faceSizes)
            {
                if (size != 3) count++;
            }
            return count;
        }
    }
}
