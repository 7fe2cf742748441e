using System;
using System.Runtime.InteropServices;
using System.Collections.Generic;
using Grasshopper.Kernel;
using Rhino.Geometry;

namespace Weft.Grasshopper
{
    /// <summary>
    /// Subdivision with creases and corners (OpenSubdiv's rules), vertex
    /// colours carried through, and optionally the limit surface: what
    /// Weaverbird's Catmull-Clark and Loop lack. Inputs after M, L, S as in
    /// the plain components: C creases (lines or edge indices), CS their
    /// sharpness, P corner points, PS their sharpness, R the creasing rule,
    /// T the matching tolerance, X the limit switch, H hole faces and TR
    /// Catmull-Clark's triangle rule (the last two after Weaverbird's
    /// order, so older definitions keep their wires).
    /// </summary>
    public abstract class CreasedSubdivisionComponent : SubdivisionComponent
    {
        protected CreasedSubdivisionComponent(Scheme scheme, string name, string nickname, string description, string iconName)
            : base(scheme, name, nickname, description, iconName)
        {
        }

        protected override void RegisterInputParams(GH_InputParamManager pManager)
        {
            AddSubdivisionInputs(pManager, "The mesh to subdivide; its vertex colours, when it has one per vertex, are carried through.",
                                 "Subdivision levels (0 returns the input, or its limit surface with X).");
            AddCreaseInputs(pManager);
            pManager.AddBooleanParameter("Limit", "X", "Project the vertices onto the limit surface and use its normals (smooth shading, offsets).", GH_ParamAccess.item, false);
            AddHoleAndTriangleInputs(pManager);
            pManager[9].Optional = true;
            pManager[10].Optional = true;
        }

        /// <summary>Registers C, CS, P, PS, R and T (inputs 3 to 8), all optional.</summary>
        protected static void AddCreaseInputs(GH_InputParamManager pManager)
        {
            pManager.AddGenericParameter("Creases", "C",
                "Creased edges: lines whose end points are the edge's vertices (within T), or edge indices as Mesh Edges (wbEdges) lists them.",
                GH_ParamAccess.list);
            pManager.AddNumberParameter("Crease Sharpness", "CS",
                "One sharpness for all creases or one per crease: 0 smooth, s > 0 sharp for s levels then softening, 10 or more a hard crease that never softens (the default).",
                GH_ParamAccess.list);
            pManager.AddPointParameter("Corners", "P", "Points on the vertices (within T) to keep sharp.", GH_ParamAccess.list);
            pManager.AddNumberParameter("Corner Sharpness", "PS",
                "One sharpness for all corners or one per corner, as for creases; 10 or more (the default) pins the vertex where it is.",
                GH_ParamAccess.list);
            pManager.AddIntegerParameter("Rule", "R", "How semi-sharp creases soften: 0 uniform, 1 Chaikin (averaged along the crease).", GH_ParamAccess.item, 0);
            AddToleranceInput(pManager, "How far a crease line's ends or a corner point may be from a vertex");
            for (int i = 3; i <= 8; i++) pManager[i].Optional = true;
        }

        /// <summary>Registers H (hole faces) and TR (the triangle rule), the two inputs after Weaverbird's order.</summary>
        protected static void AddHoleAndTriangleInputs(GH_InputParamManager pManager)
        {
            pManager.AddIntegerParameter("Holes", "H",
                "Faces of M (indices) to leave out of the result, as OpenSubdiv's hole tags: they leave no faces, but their vertices and edges still shape their neighbours.",
                GH_ParamAccess.list);
            pManager.AddIntegerParameter("Triangle Rule", "TR",
                "Catmull-Clark's weights at triangles: 0 its own, 1 OpenSubdiv's smooth triangles, which round triangle regions of mixed meshes. Loop ignores it.",
                GH_ParamAccess.item, 0);
        }

        protected override void RegisterOutputParams(GH_OutputParamManager pManager)
        {
            AddMeshOutput(pManager, "The subdivided mesh, with the input's vertex colours carried through.");
            pManager.AddVectorParameter("Normals", "N", "The limit surface's unit normal at each vertex when X is true; empty otherwise.", GH_ParamAccess.list);
        }

        protected override void Solve(IGH_DataAccess DA)
        {
            int levels = Get(DA, 1, 1);
            bool limit = Get(DA, 9, false);
            int[] holes = GetList<int>(DA, 10);

            int[] colours;
            PolygonArrays cage = GetPolygons(DA, 0, out colours);
            if (cage == null) return;
            SubdivisionOptions options = ReadCreasedOptions(DA, cage, 11);

            uint[] triangleParents;
            int inputFaces = cage.FaceSizes.Length;
            cage = PrepareCage(cage, levels, out triangleParents);
            AddHoles(options, holes, inputFaces, cage.FaceSizes.Length, triangleParents);

            RefinedArrays refined = Refiner(DA).Subdivide(cage.Positions, cage.FaceSizes, cage.FaceIndices, Scheme, levels, options);
            double[] positions = refined.Positions;
            LimitSurface surface = null;
            int[] refinedColours = null;
            if (limit || colours != null)
            {
                using (WeftMesh mesh = WeftMesh.Create(cage.Positions, cage.FaceSizes, cage.FaceIndices))
                {
                    if (limit)
                    {
                        surface = Subdivision.SubdivideLimit(mesh, Scheme, levels, options);
                        positions = surface.Positions;
                    }
                    if (colours != null)
                    {
                        double[] values = Subdivision.SubdivideVertexData(mesh, Scheme, levels, options, CreaseInputs.ColoursToValues(colours), 4);
                        refinedColours = CreaseInputs.ValuesToColours(values);
                    }
                }
            }
            Mesh result = RhinoMeshes.FromArrays(positions, refined.Rhino);
            if (surface != null) RhinoMeshes.SetVertexNormals(result, surface.Normals);
            if (refinedColours != null) RhinoMeshes.SetVertexColours(result, refinedColours);
            DA.SetData(0, result);
            if (surface != null) DA.SetDataList(1, RhinoMeshes.ToVectors(surface.Normals));
        }

        /// <summary>
        /// The options of inputs S, C, CS, P, PS, R, T (2 to 8) and TR (at <paramref name="trianglesIndex"/>)
        /// for <paramref name="cage"/>: crease lines and corner points matched to its vertices.
        /// </summary>
        protected SubdivisionOptions ReadCreasedOptions(IGH_DataAccess DA, PolygonArrays cage, int trianglesIndex)
        {
            NakedEdges nakedEdges = ToNakedEdges(Get(DA, 2, 1));
            var creaseItems = new List<object>();
            DA.GetDataList(3, creaseItems);
            double[] creaseSharpness = GetList<double>(DA, 4);
            Point3d[] cornerPoints = GetList<Point3d>(DA, 5);
            double[] cornerSharpness = GetList<double>(DA, 6);
            var rule = (Creasing)ToMode(Get(DA, 7, 0), 2, "R", "0 (uniform) or 1 (Chaikin)");
            double tolerance = GetTolerance(DA, 8);
            var triangles = (TriangleRule)ToMode(Get(DA, trianglesIndex, 0), 2, "TR", "0 (Catmull-Clark's weights) or 1 (smooth triangles)");

            var options = new SubdivisionOptions(nakedEdges) { Creasing = rule, Triangles = triangles };
            CreaseItem[] items = ToCreaseItems(creaseItems);
            using (WeftMesh mesh = WeftMesh.Create(cage.Positions, cage.FaceSizes, cage.FaceIndices))
            {
                if (items.Length > 0)
                {
                    uint[] pairs = CreaseInputs.VertexPairs(mesh, items, tolerance);
                    double[] sharpness = CreaseInputs.Sharpness(creaseSharpness, items.Length, "CS", "creases");
                    for (int i = 0; i < items.Length; i++) options.AddCrease((int)pairs[2 * i], (int)pairs[2 * i + 1], sharpness[i]);
                }
                else if (creaseSharpness.Length > 1)
                {
                    Warn("CS has values but C names no crease.");
                }
                if (cornerPoints.Length > 0)
                {
                    uint[] corners = CreaseInputs.CornerVertices(mesh, RhinoMeshes.FromPoints(cornerPoints), tolerance);
                    double[] sharpness = CreaseInputs.Sharpness(cornerSharpness, corners.Length, "PS", "corners");
                    for (int i = 0; i < corners.Length; i++) options.AddCorner((int)corners[i], sharpness[i]);
                }
            }
            return options;
        }

        /// <summary>
        /// Adds the hole faces of H; when Loop triangulated the cage (<paramref name="triangleParents"/>
        /// not null), the triangles cut from a hole are the holes. An index past M's faces is refused.
        /// </summary>
        protected static void AddHoles(SubdivisionOptions options, int[] holes, int inputFaces, int cageFaces, uint[] triangleParents)
        {
            var isHole = new bool[inputFaces];
            for (int i = 0; i < holes.Length; i++)
            {
                if (holes[i] < 0 || holes[i] >= inputFaces)
                {
                    throw new WeftException(WeftStatus.InvalidArgument,
                        "H item " + i + " is face " + holes[i] + ", but M has " + inputFaces + " faces");
                }
                isHole[holes[i]] = true;
            }
            if (holes.Length == 0) return;
            for (int f = 0; f < cageFaces; f++)
            {
                int input = triangleParents == null ? f : (int)triangleParents[f];
                if (isHole[input]) options.AddHole(f);
            }
        }

        /// <summary>Each item of C as a line or an edge index; anything else is refused, naming the item.</summary>
        private static CreaseItem[] ToCreaseItems(List<object> items)
        {
            var result = new CreaseItem[items.Count];
            for (int i = 0; i < items.Count; i++)
            {
                Line line = Line.Unset;
                double number = 0;
                if (GH_Convert.ToLine(items[i], ref line, GH_Conversion.Both) && line.IsValid)
                {
                    result[i] = CreaseItem.FromLine(line.FromX, line.FromY, line.FromZ, line.ToX, line.ToY, line.ToZ);
                }
                else if (GH_Convert.ToDouble(items[i], out number, GH_Conversion.Primary) && number == Math.Floor(number)
                         && number >= int.MinValue && number <= int.MaxValue)
                {
                    result[i] = CreaseItem.FromEdge((int)number);
                }
                else
                {
                    throw new WeftException(WeftStatus.InvalidArgument,
                        "C[" + i + "] is neither a line nor a whole edge index; give lines on cage edges or indices as Mesh Edges lists them");
                }
            }
            return result;
        }
    }

    /// <summary>Catmull-Clark subdivision with creases, corners, carried vertex colours and the limit surface.</summary>
    [Guid("9c520a22-89ba-426d-b4f9-492aafbe20e4")]
    public sealed class CreasedCatmullClarkComponent : CreasedSubdivisionComponent
    {
        public CreasedCatmullClarkComponent()
            : base(Scheme.CatmullClark, "Creased Catmull-Clark Subdivision", "CreasedCC",
                   "Subdivides a mesh with the Catmull-Clark scheme as OpenSubdiv does, with creased edges (lines or edge indices, each with a sharpness: 10 or more is a hard crease, less softens after that many levels) and sharp corners (points on vertices). Vertex colours are carried through; X projects onto the limit surface and gives its normals. While the faces and creases stay the same, moving the vertices only re-evaluates the planned subdivision.",
                   "creased_catmull_clark")
        {
        }
    }

    /// <summary>Loop subdivision with creases, corners, carried vertex colours and the limit surface; quads and n-gons are triangulated first.</summary>
    [Guid("51ceb365-5b0c-4e44-9fea-d6d16c374538")]
    public sealed class CreasedLoopComponent : CreasedSubdivisionComponent
    {
        public CreasedLoopComponent()
            : base(Scheme.Loop, "Creased Loop Subdivision", "CreasedLoop",
                   "Subdivides a triangle mesh with the Loop scheme as OpenSubdiv does, with creased edges (lines or edge indices, each with a sharpness: 10 or more is a hard crease) and sharp corners (points on vertices); quads and n-gons are triangulated first, keeping their edges. Vertex colours are carried through; X projects onto the limit surface and gives its normals.",
                   "creased_loop")
        {
        }
    }

    /// <summary>Welds a mesh's unwelded seams and finds its sharp folds, as creases for the creased subdivisions (as Rhino's ToSubD does).</summary>
    [Guid("e3eefc28-e467-4442-912b-a7c25348b2c1")]
    public sealed class CreaseEdgesFromMeshComponent : WeftComponent
    {
        public CreaseEdgesFromMeshComponent()
            : base("Crease Edges From Mesh", "CreaseEdges",
                   "Prepares a mesh for creased subdivision as Rhino's ToSubD does: welds vertices at exactly the same position and gives as creases every edge that was unwelded (naked) before and every fold whose faces' normals differ by more than A degrees. Connect M and C to a creased subdivision.",
                   "Subdivide", "crease_edges")
        {
        }

        protected override void RegisterInputParams(GH_InputParamManager pManager)
        {
            AddMeshInput(pManager, "M", "The mesh whose seams and folds become creases; its vertex colours, when it has one per vertex, are carried onto the welded mesh.");
            pManager.AddNumberParameter("Angle", "A", "Folds sharper than this many degrees become creases; 180 or more: only unwelded seams.", GH_ParamAccess.item, 180.0);
        }

        protected override void RegisterOutputParams(GH_OutputParamManager pManager)
        {
            AddMeshOutput(pManager, "The welded mesh, with the input's vertex colours (each welded vertex the first of its coincident vertices' colour).");
            pManager.AddLineParameter("Creases", "C", "The crease edges as lines, for C of a creased subdivision.", GH_ParamAccess.list);
            pManager.AddIntegerParameter("Start", "A", "The first vertex of each crease (of the welded mesh).", GH_ParamAccess.list);
            pManager.AddIntegerParameter("End", "B", "The second vertex of each crease.", GH_ParamAccess.list);
        }

        protected override void Solve(IGH_DataAccess DA)
        {
            double angle = Get(DA, 1, 180.0);
            int[] colours;
            PolygonArrays input = GetPolygons(DA, 0, out colours);
            if (input == null) return;
            using (WeftMesh mesh = WeftMesh.Create(input.Positions, input.FaceSizes, input.FaceIndices))
            {
                uint[] pairs;
                uint[] vertexMap = null;
                using (WeftMesh welded = colours == null
                    ? Subdivision.CreaseEdgesFromMesh(mesh, angle, out pairs)
                    : Subdivision.CreaseEdgesFromMesh(mesh, angle, out pairs, out vertexMap))
                {
                    double[] positions = welded.GetPositions();
                    Mesh result = RhinoMeshes.FromWeft(welded);
                    if (vertexMap != null)
                    {
                        // The weld merged coincident vertices: their colours follow its vertex map.
                        RhinoMeshes.SetVertexColours(result, CreaseInputs.ColoursThroughWeld(colours, vertexMap, welded.VertexCount));
                    }
                    DA.SetData(0, result);
                    DA.SetDataList(1, RhinoMeshes.ToLines(CreaseInputs.Segments(positions, pairs)));
                    var starts = new List<int>(pairs.Length / 2);
                    var ends = new List<int>(pairs.Length / 2);
                    for (int i = 0; i + 1 < pairs.Length; i += 2)
                    {
                        starts.Add((int)pairs[i]);
                        ends.Add((int)pairs[i + 1]);
                    }
                    DA.SetDataList(2, starts);
                    DA.SetDataList(3, ends);
                }
            }
        }
    }
}
