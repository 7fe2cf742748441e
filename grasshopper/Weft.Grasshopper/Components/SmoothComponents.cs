using System;
using System.Runtime.InteropServices;
using Grasshopper.Kernel;

namespace Weft.Grasshopper
{
    /// <summary>Moves every vertex towards the average of its neighbours, Thin of the way per iteration; the faces do not change.</summary>
    [Guid("7bfc3f38-9b17-4463-8c90-62030e52c82a")]
    public sealed class LaplacianComponent : MeshOperationComponent
    {
        public LaplacianComponent()
            : base("Laplacian Smoothing", "wbLaplacian",
                   "Moves every vertex towards the average of its neighbours, Thin of the way per iteration; the faces do not change.",
                   "Smooth", "laplacian", "The mesh to smooth.", "The smoothed mesh.")
        {
        }

        protected override void RegisterOptions(GH_InputParamManager pManager)
        {
            AddIterationsInput(pManager);
            pManager.AddNumberParameter("Thin", "T", "Blend towards the average per iteration, 0 to 1 (1 jumps to it).", GH_ParamAccess.item, 1.0);
            AddSmoothNakedInput(pManager);
        }

        protected override WeftMesh Apply(WeftMesh mesh, IGH_DataAccess DA)
        {
            return Toolbar.LaplacianSmooth(mesh, Get(DA, 1, 1), Get(DA, 2, 1.0), ToSmoothNaked(Get(DA, 3, 0)));
        }
    }

    /// <summary>Volume-preserving Laplacian smoothing (the HC algorithm of Vollmer, Mann and Mueller 1999), with an orientation (which way vertices may move) and a per-vertex activation.</summary>
    [Guid("2626e086-368f-4fc4-9b2e-f349dfec0d3b")]
    public sealed class LaplacianHcComponent : MeshOperationComponent
    {
        public LaplacianHcComponent()
            : base("LaplacianHC Smoothing", "wbLaplacianHC",
                   "Volume-preserving Laplacian smoothing (the HC algorithm of Vollmer, Mann and Mueller 1999): each iteration averages, then pushes every vertex back by Beta of its own displacement and 1 - Beta of its neighbours' displacement. Orientation O: 0 vertices move freely, 1 only along their original normal (bumps flatten, nothing slides across the surface), 2 only in their original tangent plane (the vertices even out, the shape stays). Activation V: one weight per vertex, 0 to 1 or true/false (0 stays and anchors its neighbours); empty moves every vertex.",
                   "Smooth", "laplacian_hc", "The mesh to smooth.", "The smoothed mesh.")
        {
        }

        protected override void RegisterOptions(GH_InputParamManager pManager)
        {
            AddIterationsInput(pManager);
            pManager.AddNumberParameter("Alpha", "A", "0 to 1: how much the push-back aims at the original positions rather than the previous iteration (0 is usual).", GH_ParamAccess.item, 0.0);
            pManager.AddNumberParameter("Beta", "B", "0 to 1: the share of a vertex's own displacement undone (above 0.5; 0.6 is a good start).", GH_ParamAccess.item, 0.6);
            AddSmoothNakedInput(pManager);
            pManager.AddIntegerParameter("Orientation", "O", "0: vertices move freely, 1: only along their original normal, 2: only in their original tangent plane.", GH_ParamAccess.item, 0);
            pManager.AddNumberParameter("Activation", "V", "One weight per vertex, 0 to 1 or true/false: how much of each step the vertex takes (0 stays). Empty: every vertex moves.", GH_ParamAccess.list);
            pManager[6].Optional = true;
        }

        protected override WeftMesh Apply(WeftMesh mesh, IGH_DataAccess DA)
        {
            var direction = (SmoothDirection)ToMode(Get(DA, 5, 0), 3, "O", "0 (free), 1 (along the normal) or 2 (tangential)");
            double[] activation = GetList<double>(DA, 6);
            return Toolbar.LaplacianHcSmooth(mesh, Get(DA, 1, 1), Get(DA, 2, 0.0), Get(DA, 3, 0.6), ToSmoothNaked(Get(DA, 4, 0)),
                                             direction, activation.Length == 0 ? null : activation);
        }
    }
}
