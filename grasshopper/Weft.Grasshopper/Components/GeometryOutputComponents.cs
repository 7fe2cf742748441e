using System.Runtime.InteropServices;
using Grasshopper.Kernel;
using Rhino.Geometry;

namespace Weft.Grasshopper
{
    /// <summary>Blurs per-vertex values over the mesh (Weaverbird's wbBlur blurs vertex colours; here any values, e.g. colour channels).</summary>
    [Guid("440c78b1-633d-4b19-a675-8e41bd51c69d")]
    public sealed class BlurComponent : MeshQueryComponent
    {
        public BlurComponent()
            : base("Blur", "wbBlur",
                   "Blurs per-vertex values over the mesh: each iteration moves every value Blend of the way towards its neighbours' average. C values per vertex, vertex after vertex (3 for R, G, B). The mesh is unchanged.",
                   "Smooth", "blur", "The mesh whose vertices carry the values.")
        {
        }

        protected override void RegisterOptions(GH_InputParamManager pManager)
        {
            pManager.AddNumberParameter("Values", "V", "C values per vertex, vertex after vertex.", GH_ParamAccess.list);
            pManager.AddIntegerParameter("Components", "C", "Values per vertex.", GH_ParamAccess.item, 1);
            AddIterationsInput(pManager);
            pManager.AddNumberParameter("Blend", "B", "0 to 1 per iteration.", GH_ParamAccess.item, 1.0);
            AddSmoothNakedInput(pManager);
        }

        protected override void RegisterOutputParams(GH_OutputParamManager pManager)
        {
            pManager.AddNumberParameter("Values", "V", "The blurred values, in the same layout.", GH_ParamAccess.list);
        }

        protected override void Query(WeftMesh mesh, IGH_DataAccess DA)
        {
            double[] values = GetList<double>(DA, 1);
            DA.SetDataList(0, Toolbar.BlurValues(mesh, values, Get(DA, 2, 1), Get(DA, 3, 1), Get(DA, 4, 1.0), ToSmoothNaked(Get(DA, 5, 0))));
        }
    }

    /// <summary>The vertices of a mesh as points.</summary>
    [Guid("a119335b-605c-4507-8740-0fbda0c60284")]
    public sealed class VerticesComponent : MeshQueryComponent
    {
        public VerticesComponent()
            : base("Mesh Vertices", "wbVertices", "The vertices of the mesh as points, in vertex order (n-gon meshes and polylines as Weft reads them).",
                   "Extract", "vertices", "The mesh.")
        {
        }

        protected override void RegisterOutputParams(GH_OutputParamManager pManager)
        {
            pManager.AddPointParameter("Vertices", "V", "One point per vertex.", GH_ParamAccess.list);
        }

        protected override void Query(WeftMesh mesh, IGH_DataAccess DA)
        {
            DA.SetDataList(0, RhinoMeshes.ToPoints(mesh.GetPositions()));
        }
    }

    /// <summary>Each face as a closed polyline.</summary>
    [Guid("d31d61fb-8a2d-4e99-9246-8e709e6c6e8d")]
    public sealed class FacePolylinesComponent : MeshQueryComponent
    {
        public FacePolylinesComponent()
            : base("Face Polylines", "wbFacePolylines", "Each face (triangle, quad or n-gon) as a closed polyline, in face order.",
                   "Extract", "face_polylines", "The mesh.")
        {
        }

        protected override void RegisterOutputParams(GH_OutputParamManager pManager)
        {
            pManager.AddCurveParameter("Polylines", "P", "One closed polyline per face.", GH_ParamAccess.list);
        }

        protected override void Query(WeftMesh mesh, IGH_DataAccess DA)
        {
            PolygonArrays arrays = MeshArrays.FromWeft(mesh);
            DA.SetDataList(0, RhinoMeshes.ToPolylineCurves(FlatGeometry.FacePolylines(arrays.Positions, arrays.FaceSizes, arrays.FaceIndices)));
        }
    }

    /// <summary>The unique edges as lines and vertex index pairs.</summary>
    [Guid("05435dfc-e4c5-4ecf-a185-477ae2958e5b")]
    public sealed class MeshEdgesComponent : MeshQueryComponent
    {
        public MeshEdgesComponent()
            : base("Mesh Edges", "wbEdges", "The unique edges of the mesh as lines, sorted by their lower then higher vertex index, with those indices.",
                   "Extract", "edges", "The mesh.")
        {
        }

        protected override void RegisterOutputParams(GH_OutputParamManager pManager)
        {
            pManager.AddLineParameter("Edges", "E", "One line per edge, from its lower to its higher vertex.", GH_ParamAccess.list);
            pManager.AddIntegerParameter("Start", "A", "The lower vertex index of each edge.", GH_ParamAccess.list);
            pManager.AddIntegerParameter("End", "B", "The higher vertex index of each edge.", GH_ParamAccess.list);
        }

        protected override void Query(WeftMesh mesh, IGH_DataAccess DA)
        {
            uint[] pairs = Toolbar.Edges(mesh);
            var starts = new int[pairs.Length / 2];
            var ends = new int[pairs.Length / 2];
            for (int e = 0; e < starts.Length; e++)
            {
                starts[e] = (int)pairs[2 * e];
                ends[e] = (int)pairs[2 * e + 1];
            }
            DA.SetDataList(0, RhinoMeshes.ToLines(Toolbar.EdgeSegments(mesh)));
            DA.SetDataList(1, starts);
            DA.SetDataList(2, ends);
        }
    }

    /// <summary>The naked edges chained into polylines.</summary>
    [Guid("85083928-29d2-4fd6-aa5f-bc6b84a0e2e0")]
    public sealed class NakedBoundaryComponent : MeshQueryComponent
    {
        public NakedBoundaryComponent()
            : base("Naked Boundary", "wbNakedBoundary",
                   "The naked edges chained into polylines: each border of a manifold mesh is one closed polyline; polylines stop at vertices with one or three or more naked edges.",
                   "Extract", "naked_boundary", "The mesh.")
        {
        }

        protected override void RegisterOutputParams(GH_OutputParamManager pManager)
        {
            pManager.AddCurveParameter("Boundaries", "B", "The naked boundary polylines.", GH_ParamAccess.list);
            pManager.AddBooleanParameter("Closed", "C", "Whether each polyline is closed.", GH_ParamAccess.list);
        }

        protected override void Query(WeftMesh mesh, IGH_DataAccess DA)
        {
            PolylineSet set = Mending.NakedBoundaries(mesh);
            DA.SetDataList(0, RhinoMeshes.ToPolylineCurves(FlatGeometry.SplitPolylines(set.Points, set.PointCounts, set.Closed, false)));
            DA.SetDataList(1, set.Closed);
        }
    }

    /// <summary>Faces from lines.</summary>
    [Guid("cc07b8b1-5e40-4bd9-bf7e-de3149a6332b")]
    public sealed class MeshFromLinesComponent : WeftComponent
    {
        public MeshFromLinesComponent()
            : base("Mesh From Lines", "wbMeshFromLines",
                   "Builds the faces a set of lines encloses: endpoints within the tolerance are welded, dangling lines ignored, and the smallest cycles, seen in their best-fit plane, become faces of at most V corners.",
                   "Extract", "mesh_from_lines")
        {
        }

        protected override void RegisterInputParams(GH_InputParamManager pManager)
        {
            pManager.AddLineParameter("Lines", "L", "The lines.", GH_ParamAccess.list);
            AddToleranceInput(pManager, "Welding distance");
            pManager.AddIntegerParameter("Max Valence", "V", "The largest face size kept, at least 3.", GH_ParamAccess.item, 4);
        }

        protected override void RegisterOutputParams(GH_OutputParamManager pManager)
        {
            AddMeshOutput(pManager, "The mesh of the enclosed faces.");
        }

        protected override void Solve(IGH_DataAccess DA)
        {
            Line[] lines = GetList<Line>(DA, 0);
            if (lines.Length == 0) return;
            using (WeftMesh mesh = Toolbar.MeshFromLines(RhinoMeshes.FromLines(lines), GetTolerance(DA, 1), Get(DA, 2, 4)))
            {
                if (mesh.FaceCount == 0) Warn("The lines enclose no face.");
                SetMesh(DA, 0, mesh);
            }
        }
    }
}
