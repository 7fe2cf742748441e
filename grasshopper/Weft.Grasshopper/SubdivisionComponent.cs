using System;
using Grasshopper.Kernel;

namespace Weft.Grasshopper
{
    /// <summary>
    /// What the Catmull-Clark and Loop components share: one refiner per
    /// branch (moving a cage only re-evaluates it), freed when the component
    /// leaves its document or the document closes; Loop cages triangulated
    /// first (with a remark); and the face budget checked before planning.
    /// </summary>
    public abstract class SubdivisionComponent : WeftComponent
    {
        private readonly RefinerPool refiners = new RefinerPool();

        /// <summary>The scheme this component subdivides with.</summary>
        protected readonly Scheme Scheme;

        protected SubdivisionComponent(Scheme scheme, string name, string nickname, string description, string iconName)
            : base(name, nickname, description, "Subdivide", iconName)
        {
            Scheme = scheme;
        }

        protected override void BeforeSolveInstance()
        {
            base.BeforeSolveInstance();
            refiners.BeginSolution();
        }

        protected override void AfterSolveInstance()
        {
            refiners.EndSolution();
            base.AfterSolveInstance();
        }

        public override void RemovedFromDocument(GH_Document document)
        {
            refiners.Dispose();
            base.RemovedFromDocument(document);
        }

        public override void DocumentContextChanged(GH_Document document, GH_DocumentContext context)
        {
            if (context == GH_DocumentContext.Close || context == GH_DocumentContext.Unloaded)
            {
                refiners.Dispose();
            }
            base.DocumentContextChanged(document, context);
        }

        /// <summary>
        /// The cage as the scheme takes it (triangles for Loop, with a remark saying how
        /// many faces were split), after checking that <paramref name="levels"/> fit the face budget.
        /// </summary>
        protected PolygonArrays PrepareCage(PolygonArrays cage, int levels)
        {
            uint[] parentFaces;
            return PrepareCage(cage, levels, out parentFaces);
        }

        /// <summary>
        /// As <see cref="PrepareCage(PolygonArrays, int)"/>, with the face of
        /// <paramref name="cage"/> each triangle was cut from when Loop triangulated it
        /// (null when the cage was taken as it is).
        /// </summary>
        protected PolygonArrays PrepareCage(PolygonArrays cage, int levels, out uint[] parentFaces)
        {
            parentFaces = null;
            using (WeftMesh mesh = WeftMesh.Create(cage.Positions, cage.FaceSizes, cage.FaceIndices))
            {
                if (Scheme != Scheme.Loop)
                {
                    FaceBudget.Check(mesh, Scheme, levels, FaceBudget.MaxFaces);
                    return cage;
                }
                int split;
                using (WeftMesh triangles = Subdivision.AsTriangles(mesh, out split))
                {
                    FaceBudget.Check(triangles, Scheme, levels, FaceBudget.MaxFaces);
                    if (split == 0) return cage;
                }
                // Triangulating keeps the vertices, so creases and corners still name the same ones.
                Remark(split + " quad or n-gon face(s) were triangulated before subdividing.");
                using (WeftMesh triangles = Subdivision.Triangulate(mesh, out parentFaces))
                {
                    return MeshArrays.FromWeft(triangles);
                }
            }
        }

        /// <summary>Registers Weaverbird's first three inputs: the mesh M, the levels L (1) and the naked-edge mode S (1).</summary>
        protected static void AddSubdivisionInputs(GH_InputParamManager pManager, string meshDescription, string levelsDescription)
        {
            AddMeshInput(pManager, "M", meshDescription);
            pManager.AddIntegerParameter("Level", "L", levelsDescription, GH_ParamAccess.item, 1);
            pManager.AddIntegerParameter("Smooth Naked Edges", "S", NakedEdgesDescription, GH_ParamAccess.item, 1);
        }

        /// <summary>The refiner cache of the branch being solved.</summary>
        protected RefinerCache Refiner(IGH_DataAccess DA)
        {
            return refiners.For(DA.Iteration);
        }
    }

    /// <summary>Catmull-Clark or Loop subdivision with Weaverbird's inputs M, L, S.</summary>
    public abstract class PlainSubdivisionComponent : SubdivisionComponent
    {
        protected PlainSubdivisionComponent(Scheme scheme, string name, string nickname, string description, string iconName)
            : base(scheme, name, nickname, description, iconName)
        {
        }

        protected override void RegisterInputParams(GH_InputParamManager pManager)
        {
            AddSubdivisionInputs(pManager, "The mesh to subdivide.", "Subdivision levels (0 returns the input).");
        }

        protected override void RegisterOutputParams(GH_OutputParamManager pManager)
        {
            pManager.AddMeshParameter("Mesh", "M", "The subdivided mesh.", GH_ParamAccess.item);
        }

        protected override void Solve(IGH_DataAccess DA)
        {
            int levels = Get(DA, 1, 1);
            NakedEdges nakedEdges = ToNakedEdges(Get(DA, 2, 1));
            PolygonArrays cage = GetPolygons(DA, 0);
            if (cage == null) return;
            cage = PrepareCage(cage, levels);
            RefinedArrays refined = Refiner(DA).Subdivide(cage.Positions, cage.FaceSizes, cage.FaceIndices, Scheme, levels, nakedEdges);
            DA.SetData(0, RhinoMeshes.FromArrays(refined.Positions, refined.Rhino));
        }
    }
}
