using System.Runtime.InteropServices;
using System.Collections.Generic;
using Grasshopper.Kernel;
using Rhino.Geometry;

namespace Weft.Grasshopper
{
    /// <summary>
    /// What the make components share: a list of points first (input 0, P), and nothing
    /// done while it is empty; subclasses register their other inputs and implement <see cref="Make"/>.
    /// </summary>
    public abstract class PointsComponent : WeftComponent
    {
        private readonly string pointsDescription;

        protected PointsComponent(string name, string nickname, string description, string iconName, string pointsDescription)
            : base(name, nickname, description, "Make", iconName)
        {
            this.pointsDescription = pointsDescription;
        }

        protected sealed override void RegisterInputParams(GH_InputParamManager pManager)
        {
            pManager.AddPointParameter("Points", "P", pointsDescription, GH_ParamAccess.list);
            RegisterOptions(pManager);
        }

        /// <summary>Registers the inputs after P (index 1 on).</summary>
        protected abstract void RegisterOptions(GH_InputParamManager pManager);

        protected sealed override void Solve(IGH_DataAccess DA)
        {
            Point3d[] points = GetList<Point3d>(DA, 0);
            if (points.Length == 0) return;
            Make(points, DA);
        }

        /// <summary>Reads the other inputs from DA and sets the outputs.</summary>
        protected abstract void Make(Point3d[] points, IGH_DataAccess DA);

        /// <summary>Registers an optional plane input Pl, world XY when empty.</summary>
        protected static void AddPlaneInput(GH_InputParamManager pManager, string description)
        {
            int index = pManager.AddPlaneParameter("Plane", "Pl", description + "; world XY when empty.", GH_ParamAccess.item);
            pManager[index].Optional = true;
        }

        /// <summary>The plane input at <paramref name="index"/>, world XY when it is empty.</summary>
        protected static WeftPlane GetPlane(IGH_DataAccess DA, int index)
        {
            return RhinoMeshes.ToWeftPlane(Get(DA, index, Plane.WorldXY));
        }
    }

    /// <summary>Delaunay triangulation of points on a plane.</summary>
    [Guid("13ce556e-0ddf-4345-9979-16f3cfac83a8")]
    public sealed class DelaunayMeshComponent : PointsComponent
    {
        public DelaunayMeshComponent()
            : base("Delaunay Mesh", "DelMesh",
                   "Triangulates points by the Delaunay criterion of their projections onto a plane; the vertices are the original 3-D points (repeats merged), the triangles face the plane's normal.",
                   "delaunay", "The points.")
        {
        }

        protected override void RegisterOptions(GH_InputParamManager pManager)
        {
            AddPlaneInput(pManager, "The projection plane");
        }

        protected override void RegisterOutputParams(GH_OutputParamManager pManager)
        {
            AddMeshOutput(pManager, "The triangle mesh.");
        }

        protected override void Make(Point3d[] points, IGH_DataAccess DA)
        {
            int merged;
            using (WeftMesh mesh = Making.Delaunay(RhinoMeshes.FromPoints(points), GetPlane(DA, 1), out merged))
            {
                if (merged > 0) Remark(merged + " point(s) repeat an earlier one on the plane and were merged.");
                SetMesh(DA, 0, mesh);
            }
        }
    }

    /// <summary>Voronoi cells of points on a plane.</summary>
    [Guid("2bbae6ac-d726-4757-8bf9-97673baf061b")]
    public sealed class VoronoiComponent : PointsComponent
    {
        public VoronoiComponent()
            : base("Voronoi", "Voronoi",
                   "The Voronoi cell of each point on a plane, clipped to a boundary polygon and, when R is positive, to a circle of that radius around the point. A point outside the boundary gets no cell.",
                   "voronoi", "The cell centres.")
        {
        }

        protected override void RegisterOptions(GH_InputParamManager pManager)
        {
            pManager.AddCurveParameter("Boundary", "B", "A closed polyline; the points' bounding rectangle grown by 10 % when empty.", GH_ParamAccess.item);
            pManager[1].Optional = true;
            pManager.AddNumberParameter("Radius", "R", "Clip each cell to a circle of this radius; 0 for none.", GH_ParamAccess.item, 0.0);
            AddPlaneInput(pManager, "The plane of the cells");
        }

        protected override void RegisterOutputParams(GH_OutputParamManager pManager)
        {
            pManager.AddCurveParameter("Cells", "C", "One closed polyline per non-empty cell, in point order.", GH_ParamAccess.list);
            AddMeshOutput(pManager, "An n-gon face per cell, welded within the document tolerance.");
        }

        protected override void Make(Point3d[] points, IGH_DataAccess DA)
        {
            double[] boundary = null;
            Curve curve = null;
            if (DA.GetData(1, ref curve) && curve != null)
            {
                double[] corners = RhinoMeshes.ClosedPolylineCorners(curve);
                if (corners == null) throw new WeftException(WeftStatus.InvalidArgument, "B is not a closed polyline");
                boundary = FlatGeometry.OpenRing(corners);
            }
            using (VoronoiCells cells = Making.Voronoi(RhinoMeshes.FromPoints(points), GetPlane(DA, 3), boundary, Get(DA, 2, 0.0)))
            {
                uint[] sizes = cells.GetSizes();
                List<double[]> rings = FlatGeometry.SplitPolylines(cells.GetCorners(), FlatGeometry.ToInts(sizes), Closed(sizes.Length), true);
                DA.SetDataList(0, RhinoMeshes.ToPolylineCurves(rings));
                using (WeftMesh separate = cells.ToMesh())
                using (WeftMesh welded = Mending.Weld(separate, Tolerance()))
                {
                    SetMesh(DA, 1, welded);
                }
                if (rings.Count < sizes.Length) Remark((sizes.Length - rings.Count) + " point(s) outside the boundary or repeated have no cell.");
            }
        }

        private static bool[] Closed(int count)
        {
            var closed = new bool[count];
            for (int i = 0; i < count; i++) closed[i] = true;
            return closed;
        }
    }

    /// <summary>A mesh from a grid of points.</summary>
    [Guid("c020b000-bc6d-4dfa-90f0-57b79e0466a7")]
    public sealed class MeshFromGridComponent : PointsComponent
    {
        public MeshFromGridComponent()
            : base("Mesh from Grid", "MeshGrid",
                   "Connects a grid of points (a sampled surface, U points per row, rows one after another) into quads, or triangles along the shorter diagonal; a closed direction wraps around without repeating its first point.",
                   "mesh_grid", "The grid points, u running fastest.")
        {
        }

        protected override void RegisterOptions(GH_InputParamManager pManager)
        {
            pManager.AddIntegerParameter("U Count", "U", "Points per row.", GH_ParamAccess.item);
            pManager.AddBooleanParameter("Closed U", "CU", "Wrap the rows around.", GH_ParamAccess.item, false);
            pManager.AddBooleanParameter("Closed V", "CV", "Wrap the columns around.", GH_ParamAccess.item, false);
            pManager.AddBooleanParameter("Triangulate", "T", "Split each quad along its shorter diagonal.", GH_ParamAccess.item, false);
        }

        protected override void RegisterOutputParams(GH_OutputParamManager pManager)
        {
            AddMeshOutput(pManager, "The grid mesh.");
        }

        protected override void Make(Point3d[] points, IGH_DataAccess DA)
        {
            int u = 0;
            if (!DA.GetData(1, ref u)) return;
            if (u <= 0 || points.Length % u != 0)
            {
                throw new WeftException(WeftStatus.InvalidArgument, points.Length + " points do not make rows of U = " + u);
            }
            using (WeftMesh mesh = Making.MeshFromGrid(RhinoMeshes.FromPoints(points), u, points.Length / u,
                                                       Get(DA, 2, false), Get(DA, 3, false), Get(DA, 4, false)))
            {
                SetMesh(DA, 0, mesh);
            }
        }
    }
}
