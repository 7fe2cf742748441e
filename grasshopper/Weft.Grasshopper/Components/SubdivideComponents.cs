using System;
using System.Runtime.InteropServices;
using Grasshopper.Kernel;

namespace Weft.Grasshopper
{
    /// <summary>Splits each n-gon into n quads through its edge midpoints and centroid, without smoothing: the topology of Catmull-Clark on the unchanged surface, welded. Takes Weaverbird's S input; a split moves no vertex, so every mode gives the same mesh.</summary>
    [Guid("387191f5-89ca-41c7-9d71-5ee42a29eae8")]
    public sealed class SplitPolygonsComponent : LevelsOptionOperationComponent<int>
    {
        public SplitPolygonsComponent()
            : base("Split Polygons Subdivision", "wbSplitPolygons",
                   "Splits each n-gon into n quads through its edge midpoints and centroid, without smoothing: the topology of Catmull-Clark on the unchanged surface, welded. S is Weaverbird's naked-edge input, kept so definitions connect as before: a split moves no vertex, naked or not, so 0, 1 and 2 give the same mesh.",
                   ItemOption.Integer("Smooth Naked Edges", "S", "0: fixed, 1: smooth, 2: corner fixed; a split moves no vertex, so all three give the same mesh.", 1),
                   Split, "Subdivide", "split_polygons")
        {
        }

        private static WeftMesh Split(WeftMesh mesh, int levels, int nakedEdges)
        {
            // Checked like every S input, though a linear split leaves naked vertices where they are.
            ToNakedEdges(nakedEdges);
            return Toolbar.SplitPolygons(mesh, levels);
        }
    }

    /// <summary>Splits each triangle into four through its edge midpoints, without smoothing; quads and n-gons are triangulated first.</summary>
    [Guid("9b6688e8-f916-4c44-ad53-1a69fc1a7766")]
    public sealed class SplitTrianglesComponent : MeshOperationComponent
    {
        public SplitTrianglesComponent()
            : base("Split Triangles Subdivision", "wbSplitTriangles",
                   "Splits each triangle into four through its edge midpoints, without smoothing; quads and n-gons are triangulated first.",
                   "Subdivide", "split_triangles", "The mesh to split.", "The split triangle mesh.")
        {
        }

        protected override void RegisterOptions(GH_InputParamManager pManager)
        {
            AddLevelsInput(pManager);
        }

        protected override WeftMesh Apply(WeftMesh mesh, IGH_DataAccess DA)
        {
            int split;
            using (WeftMesh triangles = Subdivision.AsTriangles(mesh, out split))
            {
                if (split > 0) Remark(split + " quad or n-gon face(s) were triangulated first.");
                return Toolbar.SplitTriangles(triangles, Get(DA, 1, 1));
            }
        }
    }

    /// <summary>Splits quads into four quads, triangles into four triangles and larger polygons into quads around their centroid, without smoothing.</summary>
    [Guid("4fa8597e-3f18-4428-b99a-9ad9c1861239")]
    public sealed class ConstantQuadsSplitComponent : LevelsOperationComponent
    {
        public ConstantQuadsSplitComponent()
            : base("Constant Quads Split Subdivision", "wbConstantQuads",
                   "Splits quads into four quads, triangles into four triangles and larger polygons into quads around their centroid, without smoothing.",
                   "Subdivide", "constant_quads", Toolbar.ConstantQuadsSplit)
        {
        }
    }

    /// <summary>The mid-edge subdivision (Peters and Reif): a face of edge midpoints per face and per vertex; boundary vertices stay so an open mesh keeps its outline.</summary>
    [Guid("57292c79-5b2c-4150-bfd8-b10883c48d0d")]
    public sealed class MidedgeComponent : LevelsOperationComponent
    {
        public MidedgeComponent()
            : base("Midedge Subdivision", "wbMidedge",
                   "The mid-edge subdivision (Peters and Reif): a face of edge midpoints per face and per vertex; boundary vertices stay so an open mesh keeps its outline.",
                   "Subdivide", "midedge", Toolbar.Midedge)
        {
        }
    }

    /// <summary>Gives each face an inner face, its corners pulled towards the centroid, joined to it by a quad per edge.</summary>
    [Guid("9696ea22-8f8c-4d47-a054-db59e8e4d0b4")]
    public sealed class InnerPolygonsComponent : LevelsOptionOperationComponent<double>
    {
        public InnerPolygonsComponent()
            : base("Inner Polygons Subdivision", "wbInnerPolygons",
                   "Gives each face an inner face, its corners pulled towards the centroid, joined to it by a quad per edge.",
                   ItemOption.Number("Pull", "P", "How far the inner corners move towards the centroid, strictly between 0 and 1.", 0.5),
                   Toolbar.InnerPolygons, "Subdivide", "inner_polygons")
        {
        }
    }

    /// <summary>Places a triangle in each corner of each face and leaves the middle open: one more hole per face and level.</summary>
    [Guid("2d93097a-a2eb-4a83-be1e-96c9ae65719a")]
    public sealed class SierpinskiTrianglesComponent : LevelsOperationComponent
    {
        public SierpinskiTrianglesComponent()
            : base("Sierpinski Triangles Subdivision", "wbSierpinskiTriangles",
                   "Places a triangle in each corner of each face and leaves the middle open: one more hole per face and level.",
                   "Subdivide", "sierpinski_triangles", Toolbar.SierpinskiTriangles)
        {
        }
    }
}
