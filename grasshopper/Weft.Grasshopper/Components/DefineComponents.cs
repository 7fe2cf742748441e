using System;
using System.Runtime.InteropServices;
using Grasshopper.Kernel;

namespace Weft.Grasshopper
{
    /// <summary>What the primitives share: no mesh input, one mesh output.</summary>
    public abstract class PrimitiveComponent : WeftComponent
    {
        protected PrimitiveComponent(string name, string nickname, string description, string iconName)
            : base(name, nickname, description, "Define", iconName)
        {
        }

        protected override void RegisterOutputParams(GH_OutputParamManager pManager)
        {
            AddMeshOutput(pManager, "The primitive, centred on the origin.");
        }

        protected override void Solve(IGH_DataAccess DA)
        {
            using (WeftMesh mesh = Make(DA))
            {
                SetMesh(DA, 0, mesh);
            }
        }

        /// <summary>Reads the inputs and makes the mesh.</summary>
        protected abstract WeftMesh Make(IGH_DataAccess DA);
    }

    /// <summary>A flat grid of quads.</summary>
    [Guid("3425c242-7c05-42d5-9ceb-5de592193404")]
    public sealed class MeshPlaneComponent : PrimitiveComponent
    {
        public MeshPlaneComponent()
            : base("Mesh Plane", "wbPlane", "A flat rectangle of U x V quads on the XY plane, centred on the origin and facing +z.", "plane")
        {
        }

        protected override void RegisterInputParams(GH_InputParamManager pManager)
        {
            pManager.AddNumberParameter("Size X", "X", "Width.", GH_ParamAccess.item, 10.0);
            pManager.AddNumberParameter("Size Y", "Y", "Depth.", GH_ParamAccess.item, 10.0);
            pManager.AddIntegerParameter("U Count", "U", "Quads along x.", GH_ParamAccess.item, 10);
            pManager.AddIntegerParameter("V Count", "V", "Quads along y.", GH_ParamAccess.item, 10);
        }

        protected override WeftMesh Make(IGH_DataAccess DA)
        {
            return Making.PlaneGrid(Get(DA, 0, 10.0), Get(DA, 1, 10.0), Get(DA, 2, 10), Get(DA, 3, 10));
        }
    }

    /// <summary>A closed, welded box of quads.</summary>
    [Guid("5805bc68-165f-445c-9a1c-5e4ab6e8a771")]
    public sealed class MeshBoxComponent : PrimitiveComponent
    {
        public MeshBoxComponent()
            : base("Mesh Box", "wbBox", "A closed, welded box centred on the origin whose sides are divided into quads.", "box")
        {
        }

        protected override void RegisterInputParams(GH_InputParamManager pManager)
        {
            pManager.AddNumberParameter("Size X", "X", "Size along x.", GH_ParamAccess.item, 10.0);
            pManager.AddNumberParameter("Size Y", "Y", "Size along y.", GH_ParamAccess.item, 10.0);
            pManager.AddNumberParameter("Size Z", "Z", "Size along z.", GH_ParamAccess.item, 10.0);
            pManager.AddIntegerParameter("U Count", "U", "Divisions along x.", GH_ParamAccess.item, 1);
            pManager.AddIntegerParameter("V Count", "V", "Divisions along y.", GH_ParamAccess.item, 1);
            pManager.AddIntegerParameter("W Count", "W", "Divisions along z.", GH_ParamAccess.item, 1);
        }

        protected override WeftMesh Make(IGH_DataAccess DA)
        {
            return Making.Box(Get(DA, 0, 10.0), Get(DA, 1, 10.0), Get(DA, 2, 10.0), Get(DA, 3, 1), Get(DA, 4, 1), Get(DA, 5, 1));
        }
    }

    /// <summary>A UV sphere.</summary>
    [Guid("fd9f3268-0f3a-4b61-a0b8-f50aad87eb9f")]
    public sealed class MeshSphereComponent : PrimitiveComponent
    {
        public MeshSphereComponent()
            : base("Mesh Sphere", "wbSphere", "A sphere centred on the origin: U segments around z, V from pole to pole; each pole is one vertex with a fan of triangles, the rest are quads.", "sphere")
        {
        }

        protected override void RegisterInputParams(GH_InputParamManager pManager)
        {
            pManager.AddNumberParameter("Radius", "R", "Radius.", GH_ParamAccess.item, 5.0);
            pManager.AddIntegerParameter("U Count", "U", "Segments around z, at least 3.", GH_ParamAccess.item, 16);
            pManager.AddIntegerParameter("V Count", "V", "Segments from pole to pole, at least 2.", GH_ParamAccess.item, 8);
        }

        protected override WeftMesh Make(IGH_DataAccess DA)
        {
            return Making.UvSphere(Get(DA, 0, 5.0), Get(DA, 1, 16), Get(DA, 2, 8));
        }
    }

    /// <summary>The five platonic solids.</summary>
    [Guid("af0efa6e-c6e2-4e6a-ada7-9be3023a34c9")]
    public sealed class PlatonicComponent : PrimitiveComponent
    {
        public PlatonicComponent()
            : base("Platonic Solid", "wbPlatonic",
                   "A platonic solid centred on the origin with its vertices on the sphere of radius R. K: 0 tetrahedron, 1 cube, 2 octahedron, 3 dodecahedron, 4 icosahedron.", "platonic")
        {
        }

        protected override void RegisterInputParams(GH_InputParamManager pManager)
        {
            pManager.AddIntegerParameter("Kind", "K", "0 tetrahedron, 1 cube, 2 octahedron, 3 dodecahedron, 4 icosahedron.", GH_ParamAccess.item, 4);
            pManager.AddNumberParameter("Radius", "R", "Circumradius.", GH_ParamAccess.item, 5.0);
        }

        protected override WeftMesh Make(IGH_DataAccess DA)
        {
            uint kind = ToMode(Get(DA, 0, 4), 5, "K", "0 (tetrahedron), 1 (cube), 2 (octahedron), 3 (dodecahedron) or 4 (icosahedron)");
            return Making.Platonic((PlatonicSolid)kind, Get(DA, 1, 5.0));
        }
    }

    /// <summary>Prisms, antiprisms, pyramids and dipyramids.</summary>
    [Guid("e3954003-def5-4eee-b4c6-6c71c23a317e")]
    public sealed class SidedSolidComponent : PrimitiveComponent
    {
        public SidedSolidComponent()
            : base("Prism and Pyramid", "wbPrism",
                   "A prism, antiprism, pyramid or dipyramid on a regular n-gon of radius R about the z axis, H tall, centred on the origin.", "prism")
        {
        }

        protected override void RegisterInputParams(GH_InputParamManager pManager)
        {
            pManager.AddIntegerParameter("Kind", "K", "0 prism, 1 antiprism, 2 pyramid, 3 dipyramid.", GH_ParamAccess.item, 0);
            pManager.AddIntegerParameter("Sides", "N", "Sides of the base polygon, at least 3.", GH_ParamAccess.item, 6);
            pManager.AddNumberParameter("Radius", "R", "Circumradius of the base.", GH_ParamAccess.item, 5.0);
            pManager.AddNumberParameter("Height", "H", "Height.", GH_ParamAccess.item, 10.0);
        }

        protected override WeftMesh Make(IGH_DataAccess DA)
        {
            uint kind = ToMode(Get(DA, 0, 0), 4, "K", "0 (prism), 1 (antiprism), 2 (pyramid) or 3 (dipyramid)");
            return Making.Sided((SidedSolid)kind, Get(DA, 1, 6), Get(DA, 2, 5.0), Get(DA, 3, 10.0));
        }
    }
}
