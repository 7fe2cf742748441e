using System;
using System.Runtime.InteropServices;
using Grasshopper.Kernel;

namespace Weft.Grasshopper
{
    /// <summary>Mesh Offset and Mesh Thicken: a distance D (default 1) and the offset type T (default 0).</summary>
    public abstract class OffsetOperationComponent : MeshOperationComponent
    {
        private readonly string distanceDescription;
        private readonly Func<WeftMesh, double, OffsetType, WeftMesh> operation;

        protected OffsetOperationComponent(string name, string nickname, string description, string subcategory, string iconName,
                                           string inputDescription, string outputDescription, string distanceDescription,
                                           Func<WeftMesh, double, OffsetType, WeftMesh> operation)
            : base(name, nickname, description, subcategory, iconName, inputDescription, outputDescription)
        {
            this.distanceDescription = distanceDescription;
            this.operation = operation;
        }

        protected sealed override void RegisterOptions(GH_InputParamManager pManager)
        {
            pManager.AddNumberParameter("Distance", "D", distanceDescription, GH_ParamAccess.item, 1.0);
            pManager.AddIntegerParameter("Type", "T", "0: distance on diagonals, 1: hypotenuse average, 2: planes intersection.", GH_ParamAccess.item, 0);
        }

        protected sealed override WeftMesh Apply(WeftMesh mesh, IGH_DataAccess DA)
        {
            return operation(mesh, Get(DA, 1, 1.0), ToOffsetType(Get(DA, 2, 0)));
        }
    }

    /// <summary>Mesh Window and Picture Frame: distances D (one or one per face, default 0.25) and the parallelogram switch P.</summary>
    public abstract class InsetOperationComponent : MeshOperationComponent
    {
        private readonly Func<WeftMesh, double[], InsetMode, WeftMesh> operation;

        protected InsetOperationComponent(string name, string nickname, string description, string subcategory, string iconName,
                                          string inputDescription, string outputDescription, Func<WeftMesh, double[], InsetMode, WeftMesh> operation)
            : base(name, nickname, description, subcategory, iconName, inputDescription, outputDescription)
        {
            this.operation = operation;
        }

        protected sealed override void RegisterOptions(GH_InputParamManager pManager)
        {
            pManager.AddNumberParameter("Distance", "D", "One value for every face, or one per face.", GH_ParamAccess.list, 0.25);
            pManager.AddBooleanParameter("Parallelogram", "P", "False: the distance is a share of the edges; true: a width in model units.", GH_ParamAccess.item, false);
        }

        protected sealed override WeftMesh Apply(WeftMesh mesh, IGH_DataAccess DA)
        {
            return operation(mesh, GetList<double>(DA, 1), Get(DA, 2, false) ? InsetMode.Parallelogram : InsetMode.EdgeFraction);
        }
    }

    /// <summary>Moves every vertex along the surface normal by the distance (positive: to the front); the faces are kept.</summary>
    [Guid("20b3cd73-71a1-49e5-9004-fbe578f8ae30")]
    public sealed class OffsetMeshComponent : OffsetOperationComponent
    {
        public OffsetMeshComponent()
            : base("Mesh Offset", "wbOffset",
                   "Moves every vertex along the surface normal by the distance (positive: to the front); the faces are kept.",
                   "Transform", "offset", "The mesh to offset.", "The offset mesh.",
                   "Offset distance in model units.", Toolbar.OffsetMesh)
        {
        }
    }

    /// <summary>Makes a solid of a surface: the mesh, its offset by the distance and a quad along every naked edge, wound outwards.</summary>
    [Guid("c92cfeec-84b7-427c-b29c-3b47762eb1c3")]
    public sealed class ThickenMeshComponent : OffsetOperationComponent
    {
        public ThickenMeshComponent()
            : base("Mesh Thicken", "wbThicken",
                   "Makes a solid of a surface: the mesh, its offset by the distance and a quad along every naked edge, wound outwards.",
                   "Transform", "thicken", "The surface to thicken.", "The closed solid.",
                   "Thickness in model units; its sign says on which side the offset lies.", Toolbar.ThickenMesh)
        {
        }
    }

    /// <summary>Insets each face and keeps both the frame of quads and the inner face. The distance is a share of the edges (0 to 0.5) or, with P, a width in model units (parallelogram rule); one for all faces or one per face.</summary>
    [Guid("76df0bd7-7249-4d0f-9bba-cc399cd903af")]
    public sealed class MeshWindowComponent : InsetOperationComponent
    {
        public MeshWindowComponent()
            : base("Mesh Window", "wbWindow",
                   "Insets each face and keeps both the frame of quads and the inner face. The distance is a share of the edges (0 to 0.5) or, with P, a width in model units (parallelogram rule); one for all faces or one per face.",
                   "Transform", "window", "The mesh to inset.", "The mesh with frames and inner faces.",
                   Toolbar.MeshWindow)
        {
        }
    }

    /// <summary>Insets each face and keeps only the frame of quads: each face becomes a ring around a new hole. Distances as in Mesh Window.</summary>
    [Guid("ebd21dd1-6f0a-4091-be85-9286bac2e0a7")]
    public sealed class PictureFrameComponent : InsetOperationComponent
    {
        public PictureFrameComponent()
            : base("Picture Frame", "wbFrame",
                   "Insets each face and keeps only the frame of quads: each face becomes a ring around a new hole. Distances as in Mesh Window.",
                   "Transform", "frame", "The mesh to frame.", "The frames.",
                   Toolbar.PictureFrame)
        {
        }
    }

    /// <summary>Cuts each quad into 3 x 3 quads and removes the middle one; every face must be a quad.</summary>
    [Guid("2d64bf47-9892-4930-a712-7799f2af31dd")]
    public sealed class SierpinskiCarpetComponent : LevelsOperationComponent
    {
        public SierpinskiCarpetComponent()
            : base("Sierpinski Carpet", "wbCarpet",
                   "Cuts each quad into 3 x 3 quads and removes the middle one; every face must be a quad.",
                   "Transform", "carpet", Toolbar.SierpinskiCarpet)
        {
        }
    }

    /// <summary>Bevels every edge: faces shrink towards their centroids, each edge between two faces becomes a quad and each interior vertex a face (a cube gives a rhombicuboctahedron).</summary>
    [Guid("71aaa89f-1f79-487f-a310-0b8b420abd23")]
    public sealed class BevelEdgesComponent : FractionOperationComponent
    {
        public BevelEdgesComponent()
            : base("Bevel Edges", "wbBevelEdges",
                   "Bevels every edge: faces shrink towards their centroids, each edge between two faces becomes a quad and each interior vertex a face (a cube gives a rhombicuboctahedron).",
                   "bevel_edges", "How far faces shrink, strictly between 0 and 1.", Toolbar.BevelEdges)
        {
        }
    }

    /// <summary>Cuts every interior vertex off at a fraction of each edge, adding a face per vertex (a cube gives 6 octagons and 8 triangles); boundary vertices stay.</summary>
    [Guid("591f1608-34de-4308-8f95-c1b645f53a76")]
    public sealed class BevelVerticesComponent : FractionOperationComponent
    {
        public BevelVerticesComponent()
            : base("Bevel Vertices", "wbBevelVertices",
                   "Cuts every interior vertex off at a fraction of each edge, adding a face per vertex (a cube gives 6 octagons and 8 triangles); boundary vertices stay.",
                   "bevel_vertices", "Share of each edge cut off, strictly between 0 and 0.5.", Toolbar.BevelVertices)
        {
        }
    }

    /// <summary>Raises a pyramid on every face: a new vertex at the face centroid moved along its normal by the height (negative: inwards), and a fan of triangles.</summary>
    [Guid("aeb8e2e1-76f3-4829-a658-34d4cb51c63b")]
    public sealed class StellateComponent : MeshOperationComponent
    {
        public StellateComponent()
            : base("Stellate/Cumulation", "wbStellate",
                   "Raises a pyramid on every face: a new vertex at the face centroid moved along its normal by the height (negative: inwards), and a fan of triangles.",
                   "Transform", "stellate", "The mesh to stellate.", "The stellated mesh.")
        {
        }

        protected override void RegisterOptions(GH_InputParamManager pManager)
        {
            pManager.AddNumberParameter("Height", "H", "One height for every face, or one per face.", GH_ParamAccess.list, 1.0);
        }

        protected override WeftMesh Apply(WeftMesh mesh, IGH_DataAccess DA)
        {
            return Making.Stellate(mesh, GetList<double>(DA, 1));
        }
    }
}
