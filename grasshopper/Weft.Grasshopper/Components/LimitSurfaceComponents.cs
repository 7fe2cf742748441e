using System.Collections.Generic;
using System.Runtime.InteropServices;
using Grasshopper.Kernel;
using Rhino.Geometry;

namespace Weft.Grasshopper
{
    /// <summary>
    /// What the limit-surface components share: the cage M, the naked-edge
    /// mode S and the scheme K (after the component's own inputs), and the
    /// evaluator of the surface they describe.
    /// </summary>
    public abstract class LimitSurfaceComponent : WeftComponent
    {
        protected LimitSurfaceComponent(string name, string nickname, string description, string iconName)
            : base(name, nickname, description, "Subdivide", iconName)
        {
        }

        /// <summary>Registers S and K, optional, as inputs <paramref name="first"/> and the next.</summary>
        protected static void AddSurfaceOptions(GH_InputParamManager pManager, int first)
        {
            pManager.AddIntegerParameter("Smooth Naked Edges", "S", NakedEdgesDescription, GH_ParamAccess.item, 1);
            pManager.AddIntegerParameter("Scheme", "K", "0 Catmull-Clark (any polygons), 1 Loop (triangles only).", GH_ParamAccess.item, 0);
            pManager[first].Optional = true;
            pManager[first + 1].Optional = true;
        }

        /// <summary>The limit surface of the cage at input 0 with S and K at <paramref name="first"/>; null when M is empty.</summary>
        protected LimitSurfaceEvaluator Evaluator(IGH_DataAccess DA, int first)
        {
            NakedEdges nakedEdges = ToNakedEdges(Get(DA, first, 1));
            var scheme = ToMode(Get(DA, first + 1, 0), 2, "K", "0 (Catmull-Clark) or 1 (Loop)") == 0 ? Scheme.CatmullClark : Scheme.Loop;
            PolygonArrays cage = GetPolygons(DA, 0);
            if (cage == null) return null;
            using (WeftMesh mesh = WeftMesh.Create(cage.Positions, cage.FaceSizes, cage.FaceIndices))
            {
                return new LimitSurfaceEvaluator(mesh, scheme, new SubdivisionOptions(nakedEdges));
            }
        }
    }

    /// <summary>Points, normals and derivatives of the limit surface at face parameters.</summary>
    [Guid("e2f12242-597f-4dcf-9520-e4811a6c9ab6")]
    public sealed class EvaluateLimitSurfaceComponent : LimitSurfaceComponent
    {
        public EvaluateLimitSurfaceComponent()
            : base("Evaluate Limit Surface", "EvalLimit",
                   "Points of the exact limit surface of a subdivision cage anywhere: at face F, parameters (U, V). A quad's (u, v) runs from its first corner, u towards the second corner and v towards the last; a Loop triangle's is barycentric; other faces are laid out as OpenSubdiv's quad sub-faces. Gives the point, the unit normal and the derivatives by u and v.",
                   "evaluate_limit")
        {
        }

        protected override void RegisterInputParams(GH_InputParamManager pManager)
        {
            AddMeshInput(pManager, "M", "The cage mesh.");
            pManager.AddIntegerParameter("Face", "F", "The face of each sample (one for all, or one per sample).", GH_ParamAccess.list);
            pManager.AddNumberParameter("U", "U", "The u parameter of each sample.", GH_ParamAccess.list);
            pManager.AddNumberParameter("V", "V", "The v parameter of each sample (as many as U).", GH_ParamAccess.list);
            AddSurfaceOptions(pManager, 4);
        }

        protected override void RegisterOutputParams(GH_OutputParamManager pManager)
        {
            pManager.AddPointParameter("Points", "P", "The limit surface at each sample.", GH_ParamAccess.list);
            pManager.AddVectorParameter("Normals", "N", "The unit normal there (du × dv, outward for counter-clockwise faces).", GH_ParamAccess.list);
            pManager.AddVectorParameter("Du", "Du", "The derivative by u.", GH_ParamAccess.list);
            pManager.AddVectorParameter("Dv", "Dv", "The derivative by v.", GH_ParamAccess.list);
        }

        protected override void Solve(IGH_DataAccess DA)
        {
            int[] faces = GetList<int>(DA, 1);
            double[] u = GetList<double>(DA, 2);
            double[] v = GetList<double>(DA, 3);
            uint[] sampleFaces;
            double[] uvs;
            LimitSamples.Build(faces, u, v, out sampleFaces, out uvs);
            int count = sampleFaces.Length;
            var positions = new double[3 * count];
            var du = new double[3 * count];
            var dv = new double[3 * count];
            using (LimitSurfaceEvaluator surface = Evaluator(DA, 4))
            {
                if (surface == null) return;
                surface.Evaluate(sampleFaces, uvs, positions, du, dv);
            }
            List<Vector3d> dus = RhinoMeshes.ToVectors(du), dvs = RhinoMeshes.ToVectors(dv);
            var normals = new Vector3d[count];
            for (int i = 0; i < count; i++)
            {
                normals[i] = Vector3d.CrossProduct(dus[i], dvs[i]);
                normals[i].Unitize();
            }
            DA.SetDataList(0, RhinoMeshes.ToPoints(positions));
            DA.SetDataList(1, normals);
            DA.SetDataList(2, dus);
            DA.SetDataList(3, dvs);
        }
    }

    /// <summary>The nearest points of the limit surface to given points.</summary>
    [Guid("a798b670-a470-4caf-a438-d589782eebd4")]
    public sealed class PullToLimitSurfaceComponent : LimitSurfaceComponent
    {
        public PullToLimitSurfaceComponent()
            : base("Pull to Limit Surface", "PullLimit",
                   "The nearest point of the exact limit surface of a subdivision cage to each point: the point on the surface, its face and its (u, v) on that face (as Evaluate Limit Surface takes them).",
                   "pull_limit")
        {
        }

        protected override void RegisterInputParams(GH_InputParamManager pManager)
        {
            AddMeshInput(pManager, "M", "The cage mesh.");
            pManager.AddPointParameter("Points", "P", "The points to pull onto the limit surface.", GH_ParamAccess.list);
            AddSurfaceOptions(pManager, 2);
        }

        protected override void RegisterOutputParams(GH_OutputParamManager pManager)
        {
            pManager.AddPointParameter("Points", "P", "The nearest point of the limit surface to each point.", GH_ParamAccess.list);
            pManager.AddIntegerParameter("Face", "F", "The cage face it lies on.", GH_ParamAccess.list);
            pManager.AddPointParameter("UV", "UV", "Its (u, v) on that face, as a point (u, v, 0).", GH_ParamAccess.list);
        }

        protected override void Solve(IGH_DataAccess DA)
        {
            Point3d[] points = GetList<Point3d>(DA, 1);
            int count = points.Length;
            double[] xyz = RhinoMeshes.FromPoints(points);
            var faces = new uint[count];
            var uvs = new double[2 * count];
            var positions = new double[3 * count];
            using (LimitSurfaceEvaluator surface = Evaluator(DA, 2))
            {
                if (surface == null) return;
                surface.ClosestPoints(xyz, faces, uvs, positions);
            }
            var faceIndices = new int[count];
            var parameters = new Point3d[count];
            for (int i = 0; i < count; i++)
            {
                faceIndices[i] = (int)faces[i];
                parameters[i] = new Point3d(uvs[2 * i], uvs[2 * i + 1], 0);
            }
            DA.SetDataList(0, RhinoMeshes.ToPoints(positions));
            DA.SetDataList(1, faceIndices);
            DA.SetDataList(2, parameters);
        }
    }
}
