using System;
using Grasshopper.Kernel;

namespace Weft.Grasshopper
{
    /// <summary>Moves every vertex towards the average of its neighbours, Thin of the way per iteration; the faces do not change.</summary>
    public sealed class LaplacianComponent : MeshOperationComponent
    {
        public LaplacianComponent()
            : base("Laplacian Smoothing", "wbLaplacian",
                   "Moves every vertex towards the average of its neighbours, Thin of the way per iteration; the faces do not change.",
                   "Smooth", "laplacian", "The mesh to smooth.", "The smoothed mesh.")
        {
        }

        public override Guid ComponentGuid
        {
            get { return new Guid("7bfc3f38-9b17-4463-8c90-62030e52c82a"); }
        }

        protected override void RegisterOptions(GH_InputParamManager pManager)
        {
            pManager.AddIntegerParameter("Level", "L", "Iterations.", GH_ParamAccess.item, 1);
            pManager.AddNumberParameter("Thin", "T", "Blend towards the average per iteration, 0 to 1 (1 jumps to it).", GH_ParamAccess.item, 1.0);
            AddSmoothNakedInput(pManager);
        }

        protected override WeftMesh Apply(WeftMesh mesh, IGH_DataAccess DA)
        {
            return Toolbar.LaplacianSmooth(mesh, Get(DA, 1, 1), Get(DA, 2, 1.0), ToSmoothNaked(Get(DA, 3, 0)));
        }
    }

    /// <summary>Volume-preserving Laplacian smoothing (the HC algorithm of Vollmer, Mann and Mueller 1999): each iteration averages, then pushes every vertex back by Beta of its own displacement and 1 - Beta of its neighbours' displacement.</summary>
    public sealed class LaplacianHcComponent : MeshOperationComponent
    {
        public LaplacianHcComponent()
            : base("LaplacianHC Smoothing", "wbLaplacianHC",
                   "Volume-preserving Laplacian smoothing (the HC algorithm of Vollmer, Mann and Mueller 1999): each iteration averages, then pushes every vertex back by Beta of its own displacement and 1 - Beta of its neighbours' displacement.",
                   "Smooth", "laplacian_hc", "The mesh to smooth.", "The smoothed mesh.")
        {
        }

        public override Guid ComponentGuid
        {
            get { return new Guid("2626e086-368f-4fc4-9b2e-f349dfec0d3b"); }
        }

        protected override void RegisterOptions(GH_InputParamManager pManager)
        {
            pManager.AddIntegerParameter("Level", "L", "Iterations.", GH_ParamAccess.item, 1);
            pManager.AddNumberParameter("Alpha", "A", "0 to 1: how much the push-back aims at the original positions rather than the previous iteration (0 is usual).", GH_ParamAccess.item, 0.0);
            pManager.AddNumberParameter("Beta", "B", "0 to 1: the share of a vertex's own displacement undone (above 0.5; 0.6 is a good start).", GH_ParamAccess.item, 0.6);
            AddSmoothNakedInput(pManager);
        }

        protected override WeftMesh Apply(WeftMesh mesh, IGH_DataAccess DA)
        {
            return Toolbar.LaplacianHcSmooth(mesh, Get(DA, 1, 1), Get(DA, 2, 0.0), Get(DA, 3, 0.6), ToSmoothNaked(Get(DA, 4, 0)));
        }
    }
}
