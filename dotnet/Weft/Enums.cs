// Generated from include/weft.h by dotnet/generate.py; do not edit (dotnet/test.sh checks it is current).
namespace Weft
{
    /// <summary>How subdivision treats naked (boundary) edges (WEFT_NAKED_EDGES_*).</summary>
    public enum NakedEdges : uint
    {
        /// <summary>Naked edges stay where they are: boundary vertices do not move, new boundary vertices are edge midpoints.</summary>
        Fixed = 0,
        /// <summary>Naked edges tend to a cubic B-spline; every boundary vertex moves (OpenSubdiv VTX_BOUNDARY_EDGE_ONLY).</summary>
        Smooth = 1,
        /// <summary>As smooth, but a boundary vertex with a single face stays (OpenSubdiv VTX_BOUNDARY_EDGE_AND_CORNER).</summary>
        CornerFixed = 2,
        /// <summary>No boundary surface: the faces at every vertex on a naked edge are left out as holes, the rest refined as smooth (OpenSubdiv VTX_BOUNDARY_NONE; beyond Weaverbird's three modes; subdivision only).</summary>
        None = 3,
    }

    /// <summary>A subdivision scheme (WEFT_SCHEME_*).</summary>
    public enum Scheme : uint
    {
        /// <summary>Catmull-Clark: any polygons in, quads out.</summary>
        CatmullClark = 0,
        /// <summary>Loop: triangles in, triangles out.</summary>
        Loop = 1,
    }

    /// <summary>How semi-sharp creases soften from level to level (WEFT_CREASING_*; OpenSubdiv's crease method).</summary>
    public enum Creasing : uint
    {
        /// <summary>Semi-sharp creases lose one level of sharpness per level (OpenSubdiv CREASE_UNIFORM).</summary>
        Uniform = 0,
        /// <summary>Semi-sharp creases are averaged with their neighbours first (OpenSubdiv CREASE_CHAIKIN).</summary>
        Chaikin = 1,
    }

    /// <summary>Catmull-Clark's weights at triangles (WEFT_TRIANGLES_*; OpenSubdiv's TriangleSubdivision).</summary>
    public enum TriangleRule : uint
    {
        /// <summary>Catmull-Clark's own weights at triangles (OpenSubdiv TRI_SUB_CATMARK).</summary>
        Catmark = 0,
        /// <summary>"Smooth triangle" weights, which round triangle regions of mixed cages (OpenSubdiv TRI_SUB_SMOOTH).</summary>
        Smooth = 1,
    }

    /// <summary>Where face-varying values (UVs) are interpolated linearly (WEFT_FACE_VARYING_*; OpenSubdiv's FVarLinearInterpolation).</summary>
    public enum FaceVaryingLinear : uint
    {
        /// <summary>Face-varying values are smooth everywhere (OpenSubdiv FVAR_LINEAR_NONE).</summary>
        Smooth = 0,
        /// <summary>Face-varying values are linear at their corners only (FVAR_LINEAR_CORNERS_ONLY).</summary>
        CornersOnly = 1,
        /// <summary>As corners only, and sharper at junctions of three or more regions (FVAR_LINEAR_CORNERS_PLUS1).</summary>
        CornersPlus1 = 2,
        /// <summary>As corners plus one, and sharper where boundaries meet (FVAR_LINEAR_CORNERS_PLUS2).</summary>
        CornersPlus2 = 3,
        /// <summary>Face-varying values are linear along every seam and boundary (FVAR_LINEAR_BOUNDARIES).</summary>
        Boundaries = 4,
        /// <summary>Face-varying values are linear everywhere (FVAR_LINEAR_ALL, OpenSubdiv's default).</summary>
        All = 5,
    }

    /// <summary>Which way LaplacianHC lets a vertex move (WEFT_SMOOTH_DIRECTION_*; Weaverbird's orientation input).</summary>
    public enum SmoothDirection : uint
    {
        /// <summary>Smoothing direction: vertices move freely (the published HC algorithm).</summary>
        Free = 0,
        /// <summary>Smoothing direction: each vertex moves only along the line of its original vertex normal, so nothing slides across the surface.</summary>
        AlongNormal = 1,
        /// <summary>Smoothing direction: each vertex moves only within the plane through its original position across its original normal (relaxation).</summary>
        Tangential = 2,
    }

    /// <summary>The pattern Tile fills a face with (WEFT_TILE_FILL_*; Weaverbird's numbers).</summary>
    public enum TileFill : uint
    {
        /// <summary>Tile fill: the chosen faces stay as they are.</summary>
        Skip = 0,
        /// <summary>Tile fill: the most robust triangulation (a quad along its shorter diagonal, larger polygons ear-clipped, right for concave faces).</summary>
        Best = 1,
        /// <summary>Tile fill: a centroid and a triangle from it to each edge.</summary>
        TriangleFan = 2,
        /// <summary>Tile fill: triangles all sharing the face's first corner.</summary>
        TriangleHand = 3,
        /// <summary>Tile fill: the quad stitch with each quad cut the same way.</summary>
        TriangleKnit = 4,
        /// <summary>Tile fill: a strip of triangles from the first corner whose diagonals zigzag.</summary>
        TriangleZigzag = 5,
        /// <summary>Tile fill: a strip of quads from the first corner, a triangle last when the corner count is odd.</summary>
        QuadStitch = 6,
        /// <summary>Tile fill: a centroid and a quad from it over every two edges.</summary>
        QuadFan = 7,
    }

    /// <summary>Which faces Tile fills (WEFT_TILE_FACES_*; Weaverbird's numbers).</summary>
    public enum TileFaces : uint
    {
        /// <summary>Tile faces: every face is filled.</summary>
        All = 0,
        /// <summary>Tile faces: every face but triangles.</summary>
        QuadsAndMore = 1,
        /// <summary>Tile faces: pentagons and larger.</summary>
        PentagonsAndMore = 2,
        /// <summary>Tile faces: triangles only (Weaverbird's number 9).</summary>
        Triangles = 9,
        /// <summary>Tile faces: quads only (Weaverbird's number 16).</summary>
        Quads = 16,
    }

    /// <summary>How Mesh Offset and Mesh Thicken place the offset vertices (WEFT_OFFSET_*).</summary>
    public enum OffsetType : uint
    {
        /// <summary>Offset type: each vertex moves by the distance along its vertex normal.</summary>
        Diagonal = 0,
        /// <summary>Offset type: along the vertex normal by the average of distance / cos of the angle to each face normal.</summary>
        HypotenuseAverage = 1,
        /// <summary>Offset type: to where the moved face planes meet (least squares for more than three faces).</summary>
        PlanesIntersection = 2,
    }

    /// <summary>How Mesh Window and Picture Frame measure the inset (WEFT_INSET_*).</summary>
    public enum InsetMode : uint
    {
        /// <summary>Inset mode: the distance is a share of the edges, in [0, 0.5).</summary>
        EdgeFraction = 0,
        /// <summary>Inset mode: the distance is a width in model units (parallelogram rule).</summary>
        Parallelogram = 1,
    }

    /// <summary>Where the dual mesh puts its vertices (WEFT_DUAL_*).</summary>
    public enum DualMode : uint
    {
        /// <summary>Dual mode: a vertex at each face's centroid.</summary>
        VertexAverage = 0,
        /// <summary>Dual mode: as VERTEX_AVERAGE, scaled to the input's bounding box size.</summary>
        KeepSize = 1,
    }

    /// <summary>A Platonic solid (WEFT_PLATONIC_*).</summary>
    public enum PlatonicSolid : uint
    {
        /// <summary>Platonic solid for <c>weft_platonic</c>: the tetrahedron (4 triangles).</summary>
        Tetrahedron = 0,
        /// <summary>Platonic solid for <c>weft_platonic</c>: the cube (6 quads).</summary>
        Hexahedron = 1,
        /// <summary>Platonic solid for <c>weft_platonic</c>: the octahedron (8 triangles).</summary>
        Octahedron = 2,
        /// <summary>Platonic solid for <c>weft_platonic</c>: the dodecahedron (12 pentagons).</summary>
        Dodecahedron = 3,
        /// <summary>Platonic solid for <c>weft_platonic</c>: the icosahedron (20 triangles).</summary>
        Icosahedron = 4,
    }

    /// <summary>A solid built on a regular polygon (WEFT_SIDED_*).</summary>
    public enum SidedSolid : uint
    {
        /// <summary>Solid for <c>weft_sided_solid</c>: two n-gons joined by n quads.</summary>
        Prism = 0,
        /// <summary>Solid for <c>weft_sided_solid</c>: two n-gons, one turned by half a side, joined by 2n triangles.</summary>
        Antiprism = 1,
        /// <summary>Solid for <c>weft_sided_solid</c>: an n-gon base and n triangles to the apex.</summary>
        Pyramid = 2,
        /// <summary>Solid for <c>weft_sided_solid</c>: two pyramids base to base (2n triangles).</summary>
        Dipyramid = 3,
    }

    /// <summary>The header's other constants.</summary>
    internal static class NativeConstants
    {
        /// <summary>Major version of the library this header belongs to.</summary>
        internal const uint VersionMajor = 0;
        /// <summary>Minor version of the library this header belongs to.</summary>
        internal const uint VersionMinor = 1;
        /// <summary>Patch version of the library this header belongs to.</summary>
        internal const uint VersionPatch = 0;
        /// <summary><c>weft_mesh_new_ex</c> flag: accept faces that name a vertex more than once (<c>0 1 1 2</c>, <c>0 1 2 1 3</c>). Subdivision treats them as OpenSubdiv does, as non-manifold topology: a degenerate edge <c>[v, v]</c>, and each further time a face meets a vertex pair, get an edge of their own, infinitely sharp. Other operations take such faces as they are.</summary>
        internal const uint MeshAllowRepeatedVertices = 1;
        /// <summary>The sharpness at and above which a crease or corner never softens.</summary>
        internal const double SharpnessInfinite = 10.0;
        /// <summary>How many reserved fields end a <c>WeftSubdivisionOptions</c>.</summary>
        internal const uint SubdivisionOptionsReserved = 8;
        /// <summary>Doubles per patch in <c>weft_limit_patches</c>'s control points: 4 × 4 points of 3.</summary>
        internal const uint PatchDoubles = 48;
        /// <summary>An absolute weld tolerance: 0.001 model units, Rhino's default absolute tolerance (a millimetre in a model in metres). It can collapse the faces of small or dense meshes: without a tolerance of the host's own, prefer <c>weft_weld_relative_tolerance</c>.</summary>
        internal const double DefaultWeldTolerance = 0.001;
    }
}
