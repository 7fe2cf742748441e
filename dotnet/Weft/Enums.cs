namespace Weft
{
    /// <summary>How subdivision treats naked (boundary) edges (WEFT_NAKED_EDGES_*).</summary>
    public enum NakedEdges : uint
    {
        /// <summary>The boundary polyline does not move: boundary vertices stay, new ones are edge midpoints.</summary>
        Fixed = 0,
        /// <summary>The boundary tends to a cubic B-spline; every boundary vertex moves.</summary>
        Smooth = 1,
        /// <summary>As Smooth, but a boundary vertex with only one face (a corner) stays.</summary>
        CornerFixed = 2,
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
        /// <summary>Every crease loses one level of sharpness per level (OpenSubdiv CREASE_UNIFORM).</summary>
        Uniform = 0,
        /// <summary>A crease's sharpness is first averaged with its neighbours along the crease (OpenSubdiv CREASE_CHAIKIN).</summary>
        Chaikin = 1,
    }

    /// <summary>Where face-varying values (UVs) are interpolated linearly (WEFT_FACE_VARYING_*; OpenSubdiv's FVarLinearInterpolation).</summary>
    public enum FaceVaryingLinear : uint
    {
        /// <summary>Smooth everywhere (FVAR_LINEAR_NONE).</summary>
        Smooth = 0,
        /// <summary>Linear at their corners only (FVAR_LINEAR_CORNERS_ONLY).</summary>
        CornersOnly = 1,
        /// <summary>As corners only, and sharper at junctions of three or more regions (FVAR_LINEAR_CORNERS_PLUS1).</summary>
        CornersPlus1 = 2,
        /// <summary>As corners plus one, and sharper where boundaries meet (FVAR_LINEAR_CORNERS_PLUS2).</summary>
        CornersPlus2 = 3,
        /// <summary>Linear along every seam and boundary (FVAR_LINEAR_BOUNDARIES).</summary>
        Boundaries = 4,
        /// <summary>Linear everywhere (FVAR_LINEAR_ALL, OpenSubdiv's default).</summary>
        All = 5,
    }

    /// <summary>How the smoothing operations treat naked edges (WEFT_SMOOTH_NAKED_*).</summary>
    public enum SmoothNakedEdges : uint
    {
        /// <summary>Boundary vertices stay.</summary>
        Fixed = 0,
        /// <summary>Boundary vertices move along the boundary, averaged with their boundary neighbours only.</summary>
        Smooth = 1,
        /// <summary>As Smooth, but a boundary vertex with a single face (a corner) stays.</summary>
        CornerFixed = 2,
    }

    /// <summary>Which way LaplacianHC lets a vertex move (WEFT_SMOOTH_DIRECTION_*; Weaverbird's orientation input).</summary>
    public enum SmoothDirection : uint
    {
        /// <summary>Anywhere: the published algorithm.</summary>
        Free = 0,
        /// <summary>Only along the line of its original vertex normal: bumps flatten, nothing slides across the surface.</summary>
        AlongNormal = 1,
        /// <summary>Only within its original tangent plane: the vertices even out while the shape barely changes.</summary>
        Tangential = 2,
    }

    /// <summary>How Tile fills a chosen face (WEFT_TILE_FILL_*; Weaverbird's F numbers).</summary>
    public enum TileFill : uint
    {
        /// <summary>The face stays as it is.</summary>
        Skip = 0,
        /// <summary>The most robust triangulation: shorter diagonal, ear clipping (right for concave faces).</summary>
        Best = 1,
        /// <summary>A centroid and a triangle from it to each edge.</summary>
        TriangleFan = 2,
        /// <summary>Triangles all sharing the first corner.</summary>
        TriangleHand = 3,
        /// <summary>The quad stitch with each quad cut the same way.</summary>
        TriangleKnit = 4,
        /// <summary>A strip of triangles from the first corner whose diagonals zigzag.</summary>
        TriangleZigzag = 5,
        /// <summary>A strip of quads from the first corner; a triangle last when the corner count is odd.</summary>
        QuadStitch = 6,
        /// <summary>A centroid and a quad from it over every two edges.</summary>
        QuadFan = 7,
    }

    /// <summary>Which faces Tile fills (WEFT_TILE_FACES_*; Weaverbird's O numbers).</summary>
    public enum TileFaces : uint
    {
        /// <summary>Every face.</summary>
        All = 0,
        /// <summary>Every face but triangles.</summary>
        QuadsAndMore = 1,
        /// <summary>Pentagons and larger.</summary>
        PentagonsAndMore = 2,
        /// <summary>Triangles only.</summary>
        Triangles = 9,
        /// <summary>Quads only.</summary>
        Quads = 16,
    }

    /// <summary>How Offset Mesh and Mesh Thicken move a vertex (WEFT_OFFSET_*).</summary>
    public enum OffsetType : uint
    {
        /// <summary>By the distance along the vertex normal.</summary>
        Diagonal = 0,
        /// <summary>Along the vertex normal by the average of distance / cos of the angle to each face normal.</summary>
        HypotenuseAverage = 1,
        /// <summary>To where the moved face planes meet (least squares for more than three faces).</summary>
        PlanesIntersection = 2,
    }

    /// <summary>How Mesh Window and Picture Frame read their distances (WEFT_INSET_*).</summary>
    public enum InsetMode : uint
    {
        /// <summary>A share of the edges, in [0, 0.5).</summary>
        EdgeFraction = 0,
        /// <summary>A width in model units (parallelogram rule).</summary>
        Parallelogram = 1,
    }

    /// <summary>Where the dual's vertices go (WEFT_DUAL_*).</summary>
    public enum DualMode : uint
    {
        /// <summary>At each face's centroid.</summary>
        VertexAverage = 0,
        /// <summary>As VertexAverage, scaled to the input's bounding box size.</summary>
        KeepSize = 1,
    }

    /// <summary>The platonic solids (WEFT_PLATONIC_*).</summary>
    public enum PlatonicSolid : uint
    {
        /// <summary>4 triangles.</summary>
        Tetrahedron = 0,
        /// <summary>6 quads (the cube).</summary>
        Hexahedron = 1,
        /// <summary>8 triangles.</summary>
        Octahedron = 2,
        /// <summary>12 pentagons.</summary>
        Dodecahedron = 3,
        /// <summary>20 triangles.</summary>
        Icosahedron = 4,
    }

    /// <summary>Solids on a regular n-gon (WEFT_SIDED_*).</summary>
    public enum SidedSolid : uint
    {
        /// <summary>Two n-gons joined by n quads.</summary>
        Prism = 0,
        /// <summary>Two n-gons, one turned by half a side, joined by 2n triangles.</summary>
        Antiprism = 1,
        /// <summary>An n-gon base and n triangles to the apex.</summary>
        Pyramid = 2,
        /// <summary>Two pyramids base to base (2n triangles).</summary>
        Dipyramid = 3,
    }
}
