using System;
using System.Runtime.InteropServices;
using Grasshopper.Kernel;

namespace Weft.Grasshopper
{
    /// <summary>
    /// Laplacian and LaplacianHC: the iterations L, the component's amounts (a
    /// table of number inputs, read for it), the naked-edge mode S, then any
    /// inputs of its own after S.
    /// </summary>
    public abstract class SmoothingComponent : MeshOperationComponent
    {
        private readonly ItemOption<double>[] amounts;

        protected SmoothingComponent(string name, string nickname, string description, ItemOption<double>[] amounts, string iconName)
            : base(name, nickname, description, "Smooth", iconName, "The mesh to smooth.", "The smoothed mesh.")
        {
            this.amounts = amounts;
        }

        /// <summary>The index of the first input after S.</summary>
        protected int AfterNakedEdges
        {
            get { return amounts.Length + 3; }
        }

        protected sealed override void RegisterOptions(GH_InputParamManager pManager)
        {
            AddIterationsInput(pManager);
            foreach (ItemOption<double> amount in amounts) amount.Register(pManager);
            AddSmoothNakedInput(pManager);
            RegisterAfterNakedEdges(pManager);
        }

        /// <summary>Registers the inputs after S; none by default.</summary>
        protected virtual void RegisterAfterNakedEdges(GH_InputParamManager pManager)
        {
        }

        protected sealed override WeftMesh Apply(WeftMesh mesh, IGH_DataAccess DA)
        {
            var values = new double[amounts.Length];
            for (int i = 0; i < amounts.Length; i++) values[i] = amounts[i].Read(DA, 2 + i);
            return Smooth(mesh, Get(DA, 1, 1), values, ToSmoothNaked(Get(DA, AfterNakedEdges - 1, 0)), DA);
        }

        /// <summary>The smoothing itself, given L, the amounts in table order and S; DA for the inputs after S.</summary>
        protected abstract WeftMesh Smooth(WeftMesh mesh, int iterations, double[] amounts, SmoothNakedEdges nakedEdges, IGH_DataAccess DA);
    }

    /// <summary>Moves every vertex towards the average of its neighbours, Thin of the way per iteration; the faces do not change.</summary>
    [Guid("7bfc3f38-9b17-4463-8c90-62030e52c82a")]
    public sealed class LaplacianComponent : SmoothingComponent
    {
        public LaplacianComponent()
            : base("Laplacian Smoothing", "wbLaplacian",
                   "Moves every vertex towards the average of its neighbours, Thin of the way per iteration; the faces do not change.",
                   new[] { ItemOption.Number("Thin", "T", "Blend towards the average per iteration, 0 to 1 (1 jumps to it).", 1.0) },
                   "laplacian")
        {
        }

        protected override WeftMesh Smooth(WeftMesh mesh, int iterations, double[] amounts, SmoothNakedEdges nakedEdges, IGH_DataAccess DA)
        {
            return Toolbar.LaplacianSmooth(mesh, iterations, amounts[0], nakedEdges);
        }
    }

    /// <summary>Volume-preserving Laplacian smoothing (the HC algorithm of Vollmer, Mann and Mueller 1999), with an orientation (which way vertices may move) and a per-vertex activation.</summary>
    [Guid("2626e086-368f-4fc4-9b2e-f349dfec0d3b")]
    public sealed class LaplacianHcComponent : SmoothingComponent
    {
        public LaplacianHcComponent()
            : base("LaplacianHC Smoothing", "wbLaplacianHC",
                   "Volume-preserving Laplacian smoothing (the HC algorithm of Vollmer, Mann and Mueller 1999): each iteration averages, then pushes every vertex back by Beta of its own displacement and 1 - Beta of its neighbours' displacement. Orientation O: 0 vertices move freely, 1 only along their original normal (bumps flatten, nothing slides across the surface), 2 only in their original tangent plane (the vertices even out, the shape stays). Activation V: one weight per vertex, 0 to 1 or true/false (0 stays and anchors its neighbours); empty moves every vertex.",
                   new[]
                   {
                       ItemOption.Number("Alpha", "A", "0 to 1: how much the push-back aims at the original positions rather than the previous iteration (0 is usual).", 0.0),
                       ItemOption.Number("Beta", "B", "0 to 1: the share of a vertex's own displacement undone (above 0.5; 0.6 is a good start).", 0.6),
                   },
                   "laplacian_hc")
        {
        }

        protected override void RegisterAfterNakedEdges(GH_InputParamManager pManager)
        {
            pManager.AddIntegerParameter("Orientation", "O", "0: vertices move freely, 1: only along their original normal, 2: only in their original tangent plane.", GH_ParamAccess.item, 0);
            int activation = pManager.AddNumberParameter("Activation", "V", "One weight per vertex, 0 to 1 or true/false: how much of each step the vertex takes (0 stays). Empty: every vertex moves.", GH_ParamAccess.list);
            pManager[activation].Optional = true;
        }

        protected override WeftMesh Smooth(WeftMesh mesh, int iterations, double[] amounts, SmoothNakedEdges nakedEdges, IGH_DataAccess DA)
        {
            var direction = (SmoothDirection)ToMode(Get(DA, AfterNakedEdges, 0), 3, "O", "0 (free), 1 (along the normal) or 2 (tangential)");
            double[] activation = GetList<double>(DA, AfterNakedEdges + 1);
            return Toolbar.LaplacianHcSmooth(mesh, iterations, amounts[0], amounts[1], nakedEdges, direction, activation.Length == 0 ? null : activation);
        }
    }
}
