using System;

namespace Weft
{
    /// <summary>
    /// The rest of Weaverbird's toolbar: linear subdivisions, smoothing,
    /// offsets and insets, bevels, dual, edges, reroute and mesh from lines.
    /// Meshes passed in stay owned by the caller; new ones are the caller's to
    /// dispose; failures raise a <see cref="WeftException"/>.
    /// </summary>
    public static class Toolbar
    {
        static Toolbar()
        {
            NativeLibraryLoader.EnsureLoaded();
        }

        private delegate uint LevelsCall(WeftMeshHandle mesh, uint levels, out WeftMeshHandle result);
        private delegate uint OffsetCall(WeftMeshHandle mesh, double distance, uint offsetType, out WeftMeshHandle result);
        private delegate uint InsetCall(WeftMeshHandle mesh, double[] distances, UIntPtr distanceCount, uint insetMode, out WeftMeshHandle result);

        /// <summary>One of the exports that take a mesh and a level count and make a mesh.</summary>
        private static WeftMesh Levels(LevelsCall call, WeftMesh mesh, int levels)
        {
            WeftMeshHandle result;
            uint status = call(Arguments.Mesh(mesh, "mesh"), Arguments.Unsigned(levels, "levels"), out result);
            return WeftMesh.FromCall(status, result);
        }

        /// <summary>Mesh Offset or Mesh Thicken.</summary>
        private static WeftMesh Offset(OffsetCall call, WeftMesh mesh, double distance, OffsetType offsetType)
        {
            WeftMeshHandle result;
            uint status = call(Arguments.Mesh(mesh, "mesh"), distance, (uint)offsetType, out result);
            return WeftMesh.FromCall(status, result);
        }

        /// <summary>Mesh Window or Picture Frame.</summary>
        private static WeftMesh Inset(InsetCall call, WeftMesh mesh, double[] distances, InsetMode insetMode)
        {
            WeftMeshHandle h = Arguments.Mesh(mesh, "mesh");
            Arguments.NotNull(distances, "distances");
            WeftMeshHandle result;
            uint status = call(h, distances, (UIntPtr)distances.Length, (uint)insetMode, out result);
            return WeftMesh.FromCall(status, result);
        }

        /// <summary>Splits each n-gon into n quads through its edge midpoints and centroid, without smoothing (Weaverbird's Split Polygons: Catmull-Clark's topology, welded). <paramref name="levels"/> is 0 to 20.</summary>
        public static WeftMesh SplitPolygons(WeftMesh mesh, int levels)
        {
            return Levels(NativeMethods.weft_split_polygons, mesh, levels);
        }

        /// <summary>Splits each triangle into four through its edge midpoints, without smoothing (fails with <see cref="WeftStatus.NotTriangles"/> on other faces). <paramref name="levels"/> is 0 to 20.</summary>
        public static WeftMesh SplitTriangles(WeftMesh mesh, int levels)
        {
            return Levels(NativeMethods.weft_split_triangles, mesh, levels);
        }

        /// <summary>Splits quads into four quads, triangles into four triangles and larger polygons into quads around their centroid, without smoothing. <paramref name="levels"/> is 0 to 20.</summary>
        public static WeftMesh ConstantQuadsSplit(WeftMesh mesh, int levels)
        {
            return Levels(NativeMethods.weft_constant_quads_split, mesh, levels);
        }

        /// <summary>The mid-edge subdivision (Peters and Reif): a face of edge midpoints per face and per vertex; boundary vertices stay. <paramref name="levels"/> is 0 to 20.</summary>
        public static WeftMesh Midedge(WeftMesh mesh, int levels)
        {
            return Levels(NativeMethods.weft_midedge, mesh, levels);
        }

        /// <summary>Places a triangle in each corner of each face and leaves the middle open: one new hole per face and level. <paramref name="levels"/> is 0 to 20.</summary>
        public static WeftMesh SierpinskiTriangles(WeftMesh mesh, int levels)
        {
            return Levels(NativeMethods.weft_sierpinski_triangles, mesh, levels);
        }

        /// <summary>Cuts each quad into 3 × 3 quads and removes the middle one (quads only). <paramref name="levels"/> is 0 to 20.</summary>
        public static WeftMesh SierpinskiCarpet(WeftMesh mesh, int levels)
        {
            return Levels(NativeMethods.weft_sierpinski_carpet, mesh, levels);
        }

        /// <summary>Gives each face an inner face pulled towards its centroid by <paramref name="pull"/> (strictly between 0 and 1), joined by a quad per edge, <paramref name="levels"/> times.</summary>
        public static WeftMesh InnerPolygons(WeftMesh mesh, int levels, double pull)
        {
            WeftMeshHandle result;
            uint status = NativeMethods.weft_inner_polygons(Arguments.Mesh(mesh, "mesh"), Arguments.Unsigned(levels, "levels"), pull, out result);
            return WeftMesh.FromCall(status, result);
        }

        /// <summary>Laplacian smoothing: each iteration moves every vertex <paramref name="blend"/> (0 to 1) of the way to its neighbours' average.</summary>
        public static WeftMesh LaplacianSmooth(WeftMesh mesh, int iterations, double blend, SmoothNakedEdges nakedEdges)
        {
            WeftMeshHandle result;
            uint status = NativeMethods.weft_laplacian_smooth(
                Arguments.Mesh(mesh, "mesh"), Arguments.Unsigned(iterations, "iterations"), blend, (uint)nakedEdges, out result);
            return WeftMesh.FromCall(status, result);
        }

        /// <summary>
        /// Volume-preserving HC smoothing (Vollmer, Mann and Müller 1999):
        /// <paramref name="alpha"/> aims the push-back at the original positions,
        /// <paramref name="beta"/> is the share of a vertex's own displacement undone (both 0 to 1).
        /// </summary>
        public static WeftMesh LaplacianHcSmooth(WeftMesh mesh, int iterations, double alpha, double beta, SmoothNakedEdges nakedEdges)
        {
            WeftMeshHandle result;
            uint status = NativeMethods.weft_laplacian_hc_smooth(
                Arguments.Mesh(mesh, "mesh"), Arguments.Unsigned(iterations, "iterations"), alpha, beta, (uint)nakedEdges, out result);
            return WeftMesh.FromCall(status, result);
        }

        /// <summary>
        /// HC smoothing with Weaverbird's orientation and activation inputs:
        /// <paramref name="direction"/> restricts each vertex to its normal line or
        /// tangent plane; <paramref name="activation"/> holds one weight in [0, 1]
        /// per vertex (0 stays, 1 takes the full step), or is null to move every vertex.
        /// </summary>
        public static WeftMesh LaplacianHcSmooth(WeftMesh mesh, int iterations, double alpha, double beta, SmoothNakedEdges nakedEdges,
                                                 SmoothDirection direction, double[] activation)
        {
            WeftMeshHandle h = Arguments.Mesh(mesh, "mesh");
            WeftMeshHandle result;
            uint status = NativeMethods.weft_laplacian_hc_smooth_ex(
                h, Arguments.Unsigned(iterations, "iterations"), alpha, beta, (uint)nakedEdges, (uint)direction,
                activation, (UIntPtr)(activation == null ? 0 : activation.Length), out result);
            return WeftMesh.FromCall(status, result);
        }

        /// <summary>
        /// Re-fills the faces chosen by <paramref name="faces"/> with the pattern of
        /// <paramref name="fill"/> (Weaverbird's Tile): outlines, windings and the
        /// input's vertices are kept, so seams stay welded; fan centroids follow the input's vertices.
        /// </summary>
        public static WeftMesh Tile(WeftMesh mesh, TileFill fill, TileFaces faces)
        {
            WeftMeshHandle result;
            uint status = NativeMethods.weft_tile(Arguments.Mesh(mesh, "mesh"), (uint)fill, (uint)faces, out result);
            return WeftMesh.FromCall(status, result);
        }

        /// <summary>
        /// Blurs per-vertex values (<paramref name="components"/> per vertex,
        /// vertex after vertex) over the mesh; returns the blurred values in
        /// the same layout.
        /// </summary>
        public static double[] BlurValues(WeftMesh mesh, double[] values, int components, int iterations, double blend, SmoothNakedEdges nakedEdges)
        {
            WeftMeshHandle h = Arguments.Mesh(mesh, "mesh");
            Arguments.NotNull(values, "values");
            var blurred = new double[values.Length];
            WeftException.Check(NativeMethods.weft_blur_values(
                h, values, (UIntPtr)values.Length, Arguments.Size(components, "components"),
                Arguments.Unsigned(iterations, "iterations"), blend, (uint)nakedEdges, blurred, (UIntPtr)blurred.Length));
            return blurred;
        }

        /// <summary>Moves every vertex by <paramref name="distance"/> along the surface normal (positive: to the front); faces are kept.</summary>
        public static WeftMesh OffsetMesh(WeftMesh mesh, double distance, OffsetType offsetType)
        {
            return Offset(NativeMethods.weft_offset_mesh, mesh, distance, offsetType);
        }

        /// <summary>A solid of a surface: the input, its offset (vertex v's is vertex VertexCount + v) and a quad along every naked edge.</summary>
        public static WeftMesh ThickenMesh(WeftMesh mesh, double distance, OffsetType offsetType)
        {
            return Offset(NativeMethods.weft_thicken_mesh, mesh, distance, offsetType);
        }

        /// <summary>Insets each face and keeps the frame of quads and the inner face; one distance for all faces or one per face.</summary>
        public static WeftMesh MeshWindow(WeftMesh mesh, double[] distances, InsetMode insetMode)
        {
            return Inset(NativeMethods.weft_mesh_window, mesh, distances, insetMode);
        }

        /// <summary>Insets each face and keeps only the frame of quads: each face becomes a ring around a hole.</summary>
        public static WeftMesh PictureFrame(WeftMesh mesh, double[] distances, InsetMode insetMode)
        {
            return Inset(NativeMethods.weft_picture_frame, mesh, distances, insetMode);
        }

        /// <summary>Bevels every edge (Conway's expansion): faces shrink by <paramref name="fraction"/> (strictly between 0 and 1).</summary>
        public static WeftMesh BevelEdges(WeftMesh mesh, double fraction)
        {
            WeftMeshHandle result;
            uint status = NativeMethods.weft_bevel_edges(Arguments.Mesh(mesh, "mesh"), fraction, out result);
            return WeftMesh.FromCall(status, result);
        }

        /// <summary>Cuts every interior vertex off at <paramref name="fraction"/> (strictly between 0 and 0.5) of each edge (Conway's truncation).</summary>
        public static WeftMesh BevelVertices(WeftMesh mesh, double fraction)
        {
            WeftMeshHandle result;
            uint status = NativeMethods.weft_bevel_vertices(Arguments.Mesh(mesh, "mesh"), fraction, out result);
            return WeftMesh.FromCall(status, result);
        }

        /// <summary>The dual mesh: a vertex per face, a face per interior vertex.</summary>
        public static WeftMesh Dual(WeftMesh mesh, DualMode dualMode)
        {
            WeftMeshHandle result;
            uint status = NativeMethods.weft_dual(Arguments.Mesh(mesh, "mesh"), (uint)dualMode, out result);
            return WeftMesh.FromCall(status, result);
        }

        /// <summary>The number of unique edges.</summary>
        public static int EdgeCount(WeftMesh mesh)
        {
            UIntPtr count;
            WeftException.Check(NativeMethods.weft_mesh_edge_count(Arguments.Mesh(mesh, "mesh"), out count));
            return Arguments.ToInt(count);
        }

        /// <summary>The unique edges as sorted vertex index pairs (low, high).</summary>
        public static uint[] Edges(WeftMesh mesh)
        {
            var pairs = new uint[checked(2 * EdgeCount(mesh))];
            WeftException.Check(NativeMethods.weft_mesh_copy_edges(mesh.Handle, pairs, (UIntPtr)pairs.Length));
            return pairs;
        }

        /// <summary>The unique edges as segments (start x, y, z, end x, y, z), in the order of <see cref="Edges"/>.</summary>
        public static double[] EdgeSegments(WeftMesh mesh)
        {
            var segments = new double[checked(6 * EdgeCount(mesh))];
            WeftException.Check(NativeMethods.weft_mesh_copy_edge_segments(mesh.Handle, segments, (UIntPtr)segments.Length));
            return segments;
        }

        /// <summary>Rotates every face's corner list to start <paramref name="shift"/> corners later (negative goes back).</summary>
        public static WeftMesh RerouteFaces(WeftMesh mesh, long shift)
        {
            WeftMeshHandle result;
            uint status = NativeMethods.weft_reroute_faces(Arguments.Mesh(mesh, "mesh"), shift, out result);
            return WeftMesh.FromCall(status, result);
        }

        /// <summary>
        /// The faces a set of segments (six doubles each) encloses: endpoints
        /// within <paramref name="tolerance"/> welded, dangling segments ignored,
        /// faces of at most <paramref name="maxValence"/> corners (at least 3).
        /// </summary>
        public static WeftMesh MeshFromLines(double[] segments, double tolerance, int maxValence)
        {
            Arguments.NotNull(segments, "segments");
            if (segments.Length % 6 != 0)
            {
                throw new WeftException(WeftStatus.CountMismatch, "segments holds " + segments.Length + " doubles, which is not 6 per segment");
            }
            WeftMeshHandle result;
            uint status = NativeMethods.weft_mesh_from_lines(
                segments, (UIntPtr)(segments.Length / 6), tolerance, Arguments.Unsigned(maxValence, "maxValence"), out result);
            return WeftMesh.FromCall(status, result);
        }
    }
}
