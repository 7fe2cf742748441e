using System;
using System.Runtime.InteropServices;

namespace Weft
{
    /// <summary>
    /// Counts and flags of a mesh's topology, laid out as <c>WeftMeshInfo</c>
    /// in <c>include/weft.h</c>: seven <c>size_t</c> then three one-byte C
    /// <c>bool</c>s.
    /// </summary>
    [StructLayout(LayoutKind.Sequential)]
    internal struct NativeMeshInfo
    {
        public UIntPtr VertexCount;
        public UIntPtr EdgeCount;
        public UIntPtr FaceCount;
        public UIntPtr NakedEdgeCount;
        public UIntPtr NonManifoldEdgeCount;
        public UIntPtr NonManifoldVertexCount;
        public UIntPtr ComponentCount;
        [MarshalAs(UnmanagedType.U1)] public bool IsClosed;
        [MarshalAs(UnmanagedType.U1)] public bool IsOrientable;
        [MarshalAs(UnmanagedType.U1)] public bool IsOriented;
    }

    /// <summary>
    /// Laid out as <c>WeftSubdivisionOptions</c>: three <c>uint32_t</c>
    /// enumerations, then a count and two array pointers for the creases and
    /// for the corners. The pointers address arrays pinned by
    /// <see cref="SubdivisionOptions"/> for the length of one call.
    /// </summary>
    [StructLayout(LayoutKind.Sequential)]
    internal struct NativeSubdivisionOptions
    {
        public uint Scheme;
        public uint NakedEdges;
        public uint Creasing;
        public UIntPtr CreaseCount;
        public IntPtr CreaseVertexPairs;
        public IntPtr CreaseSharpness;
        public UIntPtr CornerCount;
        public IntPtr CornerVertices;
        public IntPtr CornerSharpness;
    }

    /// <summary>
    /// The exports of <c>include/weft.h</c>, one for one, in the header's
    /// order (a test compares the two). <c>size_t</c> is
    /// <see cref="UIntPtr"/>, <c>WeftStatus</c> is <see cref="uint"/>, C
    /// <c>bool</c> is a one-byte <see cref="bool"/> (or <see cref="byte"/> in
    /// arrays), owned handles are SafeHandles; a nullable struct pointer is an
    /// array of one element or null. Call these only through the wrapper
    /// classes, which load the native library first.
    /// </summary>
    internal static class NativeMethods
    {
        /// <summary>The library's file name without prefix or extension.</summary>
        internal const string Library = "weft";

        private const CallingConvention Cdecl = CallingConvention.Cdecl;

        // ---- creases, carried data and the limit surface ----

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_subdivide_ex(
            WeftMeshHandle mesh, ref NativeSubdivisionOptions options, uint levels, out WeftMeshHandle outMesh);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_subdivision_counts(
            WeftMeshHandle mesh, uint scheme, uint levels,
            out UIntPtr outVertexCount, out UIntPtr outFaceCount, out UIntPtr outIndexCount);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_subdivide_vertex_data(
            WeftMeshHandle mesh, ref NativeSubdivisionOptions options, uint levels,
            double[] data, UIntPtr dataLen, UIntPtr width, [Out] double[] outData, UIntPtr capacity);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_subdivide_face_varying(
            WeftMeshHandle mesh, ref NativeSubdivisionOptions options, uint levels, uint faceVaryingLinear,
            double[] values, UIntPtr valueCount, UIntPtr width, uint[] valueIndices, UIntPtr indexCount,
            [Out] double[] outValues, UIntPtr capacity);

        /// <summary>A null <paramref name="outNormals"/> skips the normals.</summary>
        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_subdivide_limit(
            WeftMeshHandle mesh, ref NativeSubdivisionOptions options, uint levels,
            [Out] double[] outPositions, [Out] double[] outNormals, UIntPtr capacity);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_refiner_new_ex(
            WeftMeshHandle cage, ref NativeSubdivisionOptions options, uint levels, out WeftRefinerHandle outRefiner);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_crease_edges_from_mesh(
            WeftMeshHandle mesh, double angleDegrees, out WeftMeshHandle outWelded,
            [Out] uint[] outPairs, UIntPtr capacity, out UIntPtr outCreaseCount);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_crease_edges_from_mesh_ex(
            WeftMeshHandle mesh, double angleDegrees, out WeftMeshHandle outWelded,
            [Out] uint[] outPairs, UIntPtr capacity, out UIntPtr outCreaseCount,
            [Out] uint[] outVertexMap, UIntPtr vertexMapCapacity);

        // ---- making ----

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_delaunay(
            double[] points, UIntPtr pointCount, WeftPlane[] plane, out WeftMeshHandle outMesh, out UIntPtr outMerged);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_voronoi(
            double[] points, UIntPtr pointCount, WeftPlane[] plane,
            double[] boundary, UIntPtr boundaryCount, double radius, out WeftCellsHandle outCells);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern UIntPtr weft_cells_count(WeftCellsHandle cells);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern UIntPtr weft_cells_corner_count(WeftCellsHandle cells);

        /// <summary>Borrowed from the cells; valid until they are freed.</summary>
        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern IntPtr weft_cells_sizes(WeftCellsHandle cells);

        /// <summary>Borrowed from the cells; valid until they are freed.</summary>
        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern IntPtr weft_cells_corners(WeftCellsHandle cells);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_cells_copy(
            WeftCellsHandle cells, [Out] uint[] outSizes, UIntPtr sizesCapacity,
            [Out] double[] outCorners, UIntPtr cornersCapacity);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_cells_to_mesh(WeftCellsHandle cells, out WeftMeshHandle outMesh);

        /// <summary>Only <see cref="WeftCellsHandle"/> calls it.</summary>
        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern void weft_cells_free(IntPtr cells);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_mesh_from_grid(
            double[] points, UIntPtr pointCount, UIntPtr uCount, UIntPtr vCount,
            [MarshalAs(UnmanagedType.U1)] bool closedU, [MarshalAs(UnmanagedType.U1)] bool closedV,
            [MarshalAs(UnmanagedType.U1)] bool triangulate, out WeftMeshHandle outMesh);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_stellate(
            WeftMeshHandle mesh, double[] heights, UIntPtr heightCount, out WeftMeshHandle outMesh);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_plane_grid(
            double sizeX, double sizeY, UIntPtr uCount, UIntPtr vCount, out WeftMeshHandle outMesh);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_box(
            double sizeX, double sizeY, double sizeZ, UIntPtr uCount, UIntPtr vCount, UIntPtr wCount,
            out WeftMeshHandle outMesh);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_uv_sphere(double radius, UIntPtr uCount, UIntPtr vCount, out WeftMeshHandle outMesh);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_platonic(uint kind, double radius, out WeftMeshHandle outMesh);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_sided_solid(
            uint kind, UIntPtr sides, double radius, double height, out WeftMeshHandle outMesh);

        // ---- mending ----

        /// <summary><paramref name="meshes"/> holds raw handles the caller keeps alive (AddRef) for the call.</summary>
        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_join(IntPtr[] meshes, UIntPtr count, out WeftMeshHandle outMesh);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_weld(
            WeftMeshHandle mesh, double tolerance, out WeftMeshHandle outMesh, out WeftWeldReport outReport);

        /// <summary>A null <paramref name="outNodes"/> asks for the count only.</summary>
        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_find_t_nodes(
            WeftMeshHandle mesh, double tolerance, [Out] WeftTNode[] outNodes, UIntPtr capacity, out UIntPtr outCount);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_repair_t_nodes(
            WeftMeshHandle mesh, double tolerance, out WeftMeshHandle outMesh, out UIntPtr outInserted);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_cull_adjacent(WeftMeshHandle mesh, out WeftMeshHandle outMesh, out UIntPtr outRemoved);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_unify_orientation(WeftMeshHandle mesh, out WeftMeshHandle outMesh, out UIntPtr outFlipped);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_flip(WeftMeshHandle mesh, out WeftMeshHandle outMesh);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_face_normals(WeftMeshHandle mesh, [Out] double[] outNormals, UIntPtr capacity);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_vertex_normals(WeftMeshHandle mesh, [Out] double[] outNormals, UIntPtr capacity);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_planarity(WeftMeshHandle mesh, [Out] double[] outDeviations, UIntPtr capacity);

        /// <summary>A null <paramref name="outPoints"/> asks for the totals only; <paramref name="outClosed"/> holds C bools.</summary>
        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_naked_boundaries(
            WeftMeshHandle mesh, [Out] double[] outPoints, UIntPtr pointsCapacity,
            [Out] UIntPtr[] outPointCounts, [Out] byte[] outClosed, UIntPtr polylinesCapacity,
            out UIntPtr outPointTotal, out UIntPtr outPolylineCount);

        // ---- the mesh ----

        /// <summary>Static, never freed.</summary>
        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern IntPtr weft_version();

        /// <summary>Thread-local; copy it.</summary>
        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern IntPtr weft_last_error_message();

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_mesh_new(
            double[] positions, UIntPtr vertexCount,
            uint[] faceSizes, UIntPtr faceCount,
            uint[] faceIndices, UIntPtr indexCount,
            out WeftMeshHandle outMesh);

        /// <summary>Only <see cref="WeftMeshHandle"/> calls it.</summary>
        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern void weft_mesh_free(IntPtr mesh);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern UIntPtr weft_mesh_vertex_count(WeftMeshHandle mesh);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern UIntPtr weft_mesh_face_count(WeftMeshHandle mesh);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern UIntPtr weft_mesh_index_count(WeftMeshHandle mesh);

        /// <summary>Borrowed from the mesh.</summary>
        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern IntPtr weft_mesh_positions(WeftMeshHandle mesh);

        /// <summary>Borrowed from the mesh.</summary>
        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern IntPtr weft_mesh_face_sizes(WeftMeshHandle mesh);

        /// <summary>Borrowed from the mesh.</summary>
        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern IntPtr weft_mesh_face_indices(WeftMeshHandle mesh);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_mesh_copy_positions(
            WeftMeshHandle mesh, [Out] double[] outPositions, UIntPtr capacity);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_mesh_copy_faces(
            WeftMeshHandle mesh,
            [Out] uint[] outFaceSizes, UIntPtr sizesCapacity,
            [Out] uint[] outFaceIndices, UIntPtr indicesCapacity);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_mesh_info(WeftMeshHandle mesh, out NativeMeshInfo outInfo);

        // ---- subdivision ----

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_refiner_new(
            WeftMeshHandle cage, uint scheme, uint levels, uint nakedEdges, out WeftRefinerHandle outRefiner);

        /// <summary>Blittable arrays are pinned, not copied: no allocation per call.</summary>
        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_refiner_evaluate(
            WeftRefinerHandle refiner, double[] cagePositions, UIntPtr vertexCount,
            [Out] double[] outPositions, UIntPtr outLen);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_refiner_mesh(WeftRefinerHandle refiner, out WeftMeshHandle outMesh);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern UIntPtr weft_refiner_vertex_count(WeftRefinerHandle refiner);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern UIntPtr weft_refiner_face_count(WeftRefinerHandle refiner);

        /// <summary>Only <see cref="WeftRefinerHandle"/> calls it.</summary>
        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern void weft_refiner_free(IntPtr refiner);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_catmull_clark(WeftMeshHandle mesh, uint levels, uint nakedEdges, out WeftMeshHandle outMesh);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_loop(WeftMeshHandle mesh, uint levels, uint nakedEdges, out WeftMeshHandle outMesh);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_subdivision_face_count(WeftMeshHandle cage, uint scheme, uint levels, out UIntPtr outFaceCount);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_subdivision_parent_faces(
            WeftMeshHandle cage, uint scheme, uint levels, [Out] uint[] outParents, UIntPtr capacity);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_triangulate(WeftMeshHandle mesh, out WeftMeshHandle outMesh);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_triangulate_ex(WeftMeshHandle mesh, out WeftMeshHandle outMesh, [Out] uint[] outParentFaces);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_as_triangles(WeftMeshHandle mesh, out WeftMeshHandle outMesh, out UIntPtr outSplitFaces);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_match_points_to_vertices(
            WeftMeshHandle mesh, UIntPtr pointCount, double[] points, double tolerance, [Out] uint[] outVertices);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_match_lines_to_edges(
            WeftMeshHandle mesh, UIntPtr lineCount, double[] lines, double tolerance, [Out] uint[] outVertexPairs);

        // ---- the toolbar ----

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_split_polygons(WeftMeshHandle mesh, uint levels, out WeftMeshHandle outMesh);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_split_triangles(WeftMeshHandle mesh, uint levels, out WeftMeshHandle outMesh);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_constant_quads_split(WeftMeshHandle mesh, uint levels, out WeftMeshHandle outMesh);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_midedge(WeftMeshHandle mesh, uint levels, out WeftMeshHandle outMesh);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_inner_polygons(WeftMeshHandle mesh, uint levels, double pull, out WeftMeshHandle outMesh);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_sierpinski_triangles(WeftMeshHandle mesh, uint levels, out WeftMeshHandle outMesh);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_laplacian_smooth(
            WeftMeshHandle mesh, uint iterations, double blend, uint nakedEdges, out WeftMeshHandle outMesh);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_laplacian_hc_smooth(
            WeftMeshHandle mesh, uint iterations, double alpha, double beta, uint nakedEdges, out WeftMeshHandle outMesh);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_laplacian_hc_smooth_ex(
            WeftMeshHandle mesh, uint iterations, double alpha, double beta, uint nakedEdges, uint direction,
            double[] activation, UIntPtr activationCount, out WeftMeshHandle outMesh);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_tile(WeftMeshHandle mesh, uint fill, uint faces, out WeftMeshHandle outMesh);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_blur_values(
            WeftMeshHandle mesh, double[] values, UIntPtr valueCount, UIntPtr components,
            uint iterations, double blend, uint nakedEdges, [Out] double[] outValues, UIntPtr outLen);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_offset_mesh(WeftMeshHandle mesh, double distance, uint offsetType, out WeftMeshHandle outMesh);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_thicken_mesh(WeftMeshHandle mesh, double distance, uint offsetType, out WeftMeshHandle outMesh);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_mesh_window(
            WeftMeshHandle mesh, double[] distances, UIntPtr distanceCount, uint insetMode, out WeftMeshHandle outMesh);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_picture_frame(
            WeftMeshHandle mesh, double[] distances, UIntPtr distanceCount, uint insetMode, out WeftMeshHandle outMesh);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_sierpinski_carpet(WeftMeshHandle mesh, uint levels, out WeftMeshHandle outMesh);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_bevel_edges(WeftMeshHandle mesh, double fraction, out WeftMeshHandle outMesh);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_bevel_vertices(WeftMeshHandle mesh, double fraction, out WeftMeshHandle outMesh);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_dual(WeftMeshHandle mesh, uint dualMode, out WeftMeshHandle outMesh);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_mesh_edge_count(WeftMeshHandle mesh, out UIntPtr outCount);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_mesh_copy_edges(WeftMeshHandle mesh, [Out] uint[] outPairs, UIntPtr outLen);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_mesh_copy_edge_segments(WeftMeshHandle mesh, [Out] double[] outSegments, UIntPtr outLen);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_reroute_faces(WeftMeshHandle mesh, long shift, out WeftMeshHandle outMesh);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint weft_mesh_from_lines(
            double[] segments, UIntPtr segmentCount, double tolerance, uint maxValence, out WeftMeshHandle outMesh);
    }
}
