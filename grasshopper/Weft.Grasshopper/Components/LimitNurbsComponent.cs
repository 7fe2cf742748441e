using System.Runtime.InteropServices;
using Grasshopper.Kernel;
using Rhino.Geometry;

namespace Weft.Grasshopper
{
    /// <summary>
    /// The Catmull-Clark limit surface of a mesh as NURBS surfaces, one per face of
    /// the mesh refined L levels: exact bicubic B-splines away from extraordinary
    /// vertices and crease ends, fitted approximations touching them (E says how
    /// far they are from the limit), watertight along every edge. Inputs as the
    /// creased Catmull-Clark component, with L the isolation levels and no X.
    /// </summary>
    [Guid("4a83c610-a7c4-4f87-8a1b-9e11a4a0069d")]
    public sealed class LimitNurbsComponent : CreasedSubdivisionComponent
    {
        public LimitNurbsComponent()
            : base(Scheme.CatmullClark, "Limit NURBS", "LimitNurbs",
                   "The Catmull-Clark limit surface of a mesh as NURBS surfaces (bicubic, one per face of the mesh refined L levels), with the creases, corners and holes of Creased Catmull-Clark. Surfaces away from extraordinary vertices and crease ends are the limit surface exactly; those touching one approximate it, and E gives the largest distance, which falls as L rises. Neighbouring surfaces share their edges exactly.",
                   "limit_nurbs")
        {
        }

        protected override void RegisterInputParams(GH_InputParamManager pManager)
        {
            AddSubdivisionInputs(pManager, "The cage mesh.",
                                 "Isolation levels, 1 to 8: one surface per face of the mesh refined this many times; more levels shrink the approximated surfaces around extraordinary vertices.");
            pManager[1].Optional = true;
            AddCreaseInputs(pManager);
            AddHoleAndTriangleInputs(pManager);
            pManager[9].Optional = true;
            pManager[10].Optional = true;
        }

        protected override void RegisterOutputParams(GH_OutputParamManager pManager)
        {
            pManager.AddSurfaceParameter("Surfaces", "N", "The NURBS surfaces, one per refined face, in the refined faces' order.", GH_ParamAccess.list);
            pManager.AddNumberParameter("Error", "E", "The largest distance of any surface from the limit surface (0 to rounding when every surface is exact).", GH_ParamAccess.item);
            pManager.AddIntegerParameter("Exact", "X", "How many of the surfaces are the limit surface exactly.", GH_ParamAccess.item);
        }

        protected override void Solve(IGH_DataAccess DA)
        {
            int isolation = Get(DA, 1, 2);
            int[] holes = GetList<int>(DA, 9);
            PolygonArrays cage = GetPolygons(DA, 0);
            if (cage == null) return;
            SubdivisionOptions options = ReadCreasedOptions(DA, cage, 10);
            AddHoles(options, holes, cage.FaceSizes.Length, cage.FaceSizes.Length, null);
            if (isolation < 1 || isolation > 8)
            {
                throw new WeftException(WeftStatus.InvalidArgument, "L is " + isolation + "; give 1 to 8 isolation levels");
            }
            using (WeftMesh mesh = WeftMesh.Create(cage.Positions, cage.FaceSizes, cage.FaceIndices))
            {
                FaceBudget.Check(mesh, Scheme.CatmullClark, isolation + 3, FaceBudget.MaxFaces);
                LimitPatches patches = Subdivision.LimitPatches(mesh, options, isolation);
                var surfaces = new NurbsSurface[patches.Count];
                for (int p = 0; p < patches.Count; p++) surfaces[p] = RhinoSurfaces.FromPatch(patches.ControlPoints, p);
                DA.SetDataList(0, surfaces);
                DA.SetData(1, patches.MaxError);
                DA.SetData(2, patches.ExactCount);
            }
        }
    }
}
