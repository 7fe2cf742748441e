using System;
using System.Runtime.InteropServices;
using Grasshopper.Kernel;

namespace Weft.Grasshopper
{
    /// <summary>Re-fills chosen faces by a pattern of triangles or quads (Weaverbird's Tile, with its F and O numbers).</summary>
    [Guid("290dc0bc-489c-40a8-8bf0-ccf792d4a8c6")]
    public sealed class TileComponent : MeshOperationComponent
    {
        public TileComponent()
            : base("Tile", "wbTile",
                   "Re-fills chosen faces by a pattern of triangles or quads; outlines, windings and vertices are kept, so seams stay welded and closed meshes closed. " +
                   "F: 0 skip, 1 best (shorter diagonal, ear clipping: right for concave faces), 2 triangle fan (from the centroid), 3 triangle hand (all from corner 0), " +
                   "4 triangle knit (the quad stitch, each quad cut the same way), 5 triangle zigzag (a strip from corner 0), 6 quad stitch (a strip of quads from corner 0, a triangle last when odd), " +
                   "7 quad fan (from the centroid over every two edges). O: 0 all faces, 1 quads and more, 2 pentagons and more, 9 triangles, 16 quads.",
                   "Define", "tile", "The mesh whose faces to fill.", "The mesh after filling.")
        {
        }

        protected override void RegisterOptions(GH_InputParamManager pManager)
        {
            pManager.AddIntegerParameter("FillStrategy", "F", "0 skip, 1 best, 2 triangle fan, 3 triangle hand, 4 triangle knit, 5 triangle zigzag, 6 quad stitch, 7 quad fan.", GH_ParamAccess.item, 1);
            pManager.AddIntegerParameter("Opt-in", "O", "The faces to fill: 0 all, 1 quads and more, 2 pentagons and more, 9 triangles, 16 quads.", GH_ParamAccess.item, 0);
        }

        protected override WeftMesh Apply(WeftMesh mesh, IGH_DataAccess DA)
        {
            int fill = Get(DA, 1, 1);
            int faces = Get(DA, 2, 0);
            if (fill < 0 || fill > 7)
            {
                throw new WeftException(WeftStatus.InvalidArgument, "F is " + fill + "; use 0 to 7");
            }
            if (faces != 0 && faces != 1 && faces != 2 && faces != 9 && faces != 16)
            {
                throw new WeftException(WeftStatus.InvalidArgument, "O is " + faces + "; use 0 (all), 1 (quads and more), 2 (pentagons and more), 9 (triangles) or 16 (quads)");
            }
            return Toolbar.Tile(mesh, (TileFill)fill, (TileFaces)faces);
        }
    }
}
