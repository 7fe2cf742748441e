// Generated from include/weft.h by dotnet/generate.py; do not edit (dotnet/test.sh checks it is current).
using System;
using System.Runtime.InteropServices;

namespace Weft
{
    /// <summary>
    /// Laid out as <c>WeftSubdivisionOptions</c> in <c>include/weft.h</c>.
    /// </summary>
    [StructLayout(LayoutKind.Sequential)]
    internal struct NativeSubdivisionOptions
    {
        /// <summary>A WEFT_SCHEME_* value.</summary>
        public uint Scheme;
        /// <summary>A WEFT_NAKED_EDGES_* value.</summary>
        public uint NakedEdges;
        /// <summary>A WEFT_CREASING_* value.</summary>
        public uint Creasing;
        /// <summary>Number of creased edges.</summary>
        public UIntPtr CreaseCount;
        /// <summary><c>2 * crease_count</c> vertex indices: the ends of each creased edge, which must be an edge of the mesh; NULL when <c>crease_count</c> is 0.</summary>
        public IntPtr CreaseVertexPairs;
        /// <summary><c>crease_count</c> sharpness values: 0 or more, WEFT_SHARPNESS_INFINITE or more (or INFINITY) for a hard crease.</summary>
        public IntPtr CreaseSharpness;
        /// <summary>Number of sharp vertices.</summary>
        public UIntPtr CornerCount;
        /// <summary><c>corner_count</c> vertex indices; NULL when <c>corner_count</c> is 0.</summary>
        public IntPtr CornerVertices;
        /// <summary><c>corner_count</c> sharpness values, as for creases.</summary>
        public IntPtr CornerSharpness;
        /// <summary>Number of hole faces.</summary>
        public UIntPtr HoleCount;
        /// <summary><c>hole_count</c> face indices: faces left out of the result (OpenSubdiv's hole tags), whose vertices and edges still shape their neighbours; NULL when <c>hole_count</c> is 0.</summary>
        public IntPtr HoleFaces;
        /// <summary>A WEFT_TRIANGLES_* value: Catmull-Clark's weights at triangles (Loop ignores it).</summary>
        public uint Triangles;
        /// <summary>Must be 0 (see above).</summary>
        public uint ReservedFlags;
        /// <summary>Must be 0 (see above). (element 0)</summary>
        public UIntPtr Reserved0;
        /// <summary>Must be 0 (see above). (element 1)</summary>
        public UIntPtr Reserved1;
        /// <summary>Must be 0 (see above). (element 2)</summary>
        public UIntPtr Reserved2;
        /// <summary>Must be 0 (see above). (element 3)</summary>
        public UIntPtr Reserved3;
        /// <summary>Must be 0 (see above). (element 4)</summary>
        public UIntPtr Reserved4;
        /// <summary>Must be 0 (see above). (element 5)</summary>
        public UIntPtr Reserved5;
        /// <summary>Must be 0 (see above). (element 6)</summary>
        public UIntPtr Reserved6;
        /// <summary>Must be 0 (see above). (element 7)</summary>
        public UIntPtr Reserved7;
    }

    /// <summary>
    /// Laid out as <c>WeftMeshInfo</c> in <c>include/weft.h</c>.
    /// </summary>
    [StructLayout(LayoutKind.Sequential)]
    internal struct NativeMeshInfo
    {
        /// <summary>Number of vertices.</summary>
        public UIntPtr VertexCount;
        /// <summary>Number of unique edges.</summary>
        public UIntPtr EdgeCount;
        /// <summary>Number of faces.</summary>
        public UIntPtr FaceCount;
        /// <summary>Edges with exactly one face.</summary>
        public UIntPtr NakedEdgeCount;
        /// <summary>Edges with three or more faces.</summary>
        public UIntPtr NonManifoldEdgeCount;
        /// <summary>Vertices whose faces do not form one fan, or on a non-manifold edge.</summary>
        public UIntPtr NonManifoldVertexCount;
        /// <summary>Pieces of faces connected through shared edges.</summary>
        public UIntPtr ComponentCount;
        /// <summary>No naked and no non-manifold edges (false for a mesh without faces).</summary>
        [MarshalAs(UnmanagedType.U1)] public bool IsClosed;
        /// <summary>Every component can be given one consistent winding.</summary>
        [MarshalAs(UnmanagedType.U1)] public bool IsOrientable;
        /// <summary>Every manifold edge already runs in opposite directions in its two faces.</summary>
        [MarshalAs(UnmanagedType.U1)] public bool IsOriented;
    }

    /// <summary>
    /// The exports of <c>include/weft.h</c>, one for one, in the header's order.
    /// Call these only through the wrapper classes, which load the native library first.
    /// </summary>
    internal static class NativeMethods
    {
        /// <summary>The library's file name without prefix or extension.</summary>
        internal const string Library = "weft";

        /// <summary>The outcome of every Weft function. The values are stable: new ones are only ever added at the end. /</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern IntPtr weft_version();

        /// <summary>Returns the UTF-8 sentence that explains the last failure on the calling thread, or an empty string when no call on this thread has failed.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern IntPtr weft_last_error_message();

        /// <summary>Creates a mesh by copying caller buffers; the buffers may be freed after the call.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_mesh_new(double[] positions, UIntPtr vertexCount, uint[] faceSizes, UIntPtr faceCount, uint[] faceIndices, UIntPtr indexCount, out WeftMeshHandle outMesh);

        /// <summary>As <c>weft_mesh_new</c>, with <c>flags</c> (0, or WEFT_MESH_ALLOW_REPEATED_VERTICES) saying what else to accept. An unknown flag fails with WEFT_STATUS_INVALID_ARGUMENT.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_mesh_new_ex(double[] positions, UIntPtr vertexCount, uint[] faceSizes, UIntPtr faceCount, uint[] faceIndices, UIntPtr indexCount, uint flags, out WeftMeshHandle outMesh);

        /// <summary>As <c>weft_mesh_new_ex</c>, but the mesh reads <c>positions</c> and <c>face_indices</c> where they are instead of copying them: a million vertices and faces cross in the time it takes to check them. The arrays are checked as <c>weft_mesh_new_ex</c> checks them, with the same errors. <c>face_sizes</c> may be freed after the call (Weft keeps a copy only when the faces differ in size).</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_mesh_new_borrowed(IntPtr positions, UIntPtr vertexCount, uint[] faceSizes, UIntPtr faceCount, IntPtr faceIndices, UIntPtr indexCount, uint flags, out WeftMeshHandle outMesh);

        /// <summary>Frees a mesh made by Weft. NULL is ignored.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern void weft_mesh_free(IntPtr mesh);

        /// <summary>Returns the number of vertices, or 0 when <c>mesh</c> is NULL.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern UIntPtr weft_mesh_vertex_count(WeftMeshHandle mesh);

        /// <summary>Returns whether the mesh reads arrays a caller lent it (<c>weft_mesh_new_borrowed</c>); false when <c>mesh</c> is NULL, and for every mesh an operation returns.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        [return: MarshalAs(UnmanagedType.U1)]
        internal static extern bool weft_mesh_is_borrowed(WeftMeshHandle mesh);

        /// <summary>Returns the number of faces, or 0 when <c>mesh</c> is NULL.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern UIntPtr weft_mesh_face_count(WeftMeshHandle mesh);

        /// <summary>Returns the number of face corners (the sum of the face sizes), or 0 when <c>mesh</c> is NULL.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern UIntPtr weft_mesh_index_count(WeftMeshHandle mesh);

        /// <summary>Returns the positions, <c>3 * vertex_count</c> doubles, or NULL when <c>mesh</c> is NULL or has no vertices.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern IntPtr weft_mesh_positions(WeftMeshHandle mesh);

        /// <summary>Returns the face sizes, <c>face_count</c> values, or NULL when <c>mesh</c> is NULL or has no faces.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern IntPtr weft_mesh_face_sizes(WeftMeshHandle mesh);

        /// <summary>Returns the face indices, <c>index_count</c> values, or NULL when <c>mesh</c> is NULL or has no faces.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern IntPtr weft_mesh_face_indices(WeftMeshHandle mesh);

        /// <summary>Copies the positions into a caller buffer.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_mesh_copy_positions(WeftMeshHandle mesh, [Out] double[] outPositions, UIntPtr capacity);

        /// <summary>Copies the faces into caller buffers.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_mesh_copy_faces(WeftMeshHandle mesh, [Out] uint[] outFaceSizes, UIntPtr sizesCapacity, [Out] uint[] outFaceIndices, UIntPtr indicesCapacity);

        /// <summary>Computes the counts and flags of a mesh's topology.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_mesh_info(WeftMeshHandle mesh, out NativeMeshInfo outInfo);

        /// <summary>Reads a mesh file, choosing the format by the extension of <c>path</c> (<c>.obj</c>, <c>.ply</c>, <c>.stl</c> or <c>.off</c>, any case), as <c>weft</c> does. STL corners come unwelded, one vertex per triangle corner (<c>weft_weld</c> with tolerance 0 joins them); vertex colours, UVs and creases are not read.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_read_mesh_file(byte[] path, out WeftMeshHandle outMesh);

        /// <summary>Writes a mesh file, choosing the format by the extension of <c>path</c> (<c>.obj</c>, <c>.ply</c>, <c>.stl</c> or <c>.off</c>, any case), as <c>weft</c> does: PLY as binary little endian, STL as binary with polygons written as triangle fans. The file is written beside its destination under a temporary name and renamed into place, so a failed write leaves no partial file and an existing file as it was.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_write_mesh_file(WeftMeshHandle mesh, byte[] path);

        /// <summary>Finds, for each point, the nearest vertex of the mesh within a tolerance (the lower index when two are equally near), through the spatial hash that <c>weft_weld</c> uses.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_match_points_to_vertices(WeftMeshHandle mesh, UIntPtr pointCount, double[] points, double tolerance, [Out] uint[] outVertices);

        /// <summary>Finds, for each line, the edge of the mesh whose end points lie within a tolerance of the line's, in either direction. When several vertices are within reach of an end, the pair that is an edge wins, the nearest (the smallest sum of the two distances) first.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_match_lines_to_edges(WeftMeshHandle mesh, UIntPtr lineCount, double[] lines, double tolerance, [Out] uint[] outVertexPairs);

        /// <summary>Subdivides a mesh with Catmull-Clark, <c>levels</c> times, as OpenSubdiv's Catmark scheme does; triangles, quads and n-gons may be mixed, and every face of the result is a quad.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_catmull_clark(WeftMeshHandle mesh, uint levels, uint nakedEdges, out WeftMeshHandle outMesh);

        /// <summary>Subdivides a triangle mesh with Loop, <c>levels</c> times, as OpenSubdiv's Loop scheme does; each triangle becomes 4.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_loop(WeftMeshHandle mesh, uint levels, uint nakedEdges, out WeftMeshHandle outMesh);

        /// <summary>Subdivides into the caller's buffers: the result of <c>weft_catmull_clark</c> or <c>weft_loop</c> (by <c>scheme</c>, a WEFT_SCHEME_* value), bit for bit, written into memory the caller keeps instead of a new mesh. A host that subdivides again and again allocates once, from the counts of <c>weft_subdivision_counts</c> (<c>weft_subdivision_counts_ex</c> for WEFT_NAKED_EDGES_NONE, whose holes leave faces out), so no fresh memory is faulted in for the output on each call, and the last level's points are written where they belong, each once.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_subdivide_into(WeftMeshHandle mesh, uint scheme, uint levels, uint nakedEdges, [Out] double[] outPositions, UIntPtr positionCapacity, [Out] uint[] outFaceIndices, UIntPtr indexCapacity);

        /// <summary>Gives the number of faces <c>levels</c> steps of <c>scheme</c> make from <c>cage</c>, without subdividing: the length <c>weft_subdivision_parent_faces</c> needs.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_subdivision_face_count(WeftMeshHandle cage, uint scheme, uint levels, out UIntPtr outFaceCount);

        /// <summary>Writes, for every face of the mesh that <c>levels</c> steps of <c>scheme</c> make from <c>cage</c>, the index of the cage face it comes from (the naked-edge mode does not change it, except WEFT_NAKED_EDGES_NONE, whose holes <c>weft_subdivision_parent_faces_ex</c> leaves out). Only the cage's face sizes are used.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_subdivision_parent_faces(WeftMeshHandle cage, uint scheme, uint levels, [Out] uint[] outParents, UIntPtr capacity);

        /// <summary>Triangulates every face: triangles stay, a quad is split along its shorter diagonal, an n-gon is ear-clipped in its best-fit plane (concave n-gons included). Vertices keep their indices and positions; the triangles of face f are consecutive, in face order (a face of n corners makes n − 2).</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_triangulate(WeftMeshHandle mesh, out WeftMeshHandle outMesh);

        /// <summary>Triangulates every face as <c>weft_triangulate</c> does, and gives the face of the input that each triangle was cut from.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_triangulate_ex(WeftMeshHandle mesh, out WeftMeshHandle outMesh, [Out] uint[] outParentFaces);

        /// <summary>Gives the mesh as triangles, for the operations that need them (Loop, <c>weft_split_triangles</c>): a copy when every face is a triangle, else the triangulation of <c>weft_triangulate</c>.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_as_triangles(WeftMeshHandle mesh, out WeftMeshHandle outMesh, out UIntPtr outSplitFaces);

        /// <summary>Plans <c>levels</c> steps of <c>scheme</c> on the faces of <c>cage</c>: everything that depends only on its topology (the faces of each level and what each new vertex is made of) is computed here, once.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_refiner_new(WeftMeshHandle cage, uint scheme, uint levels, uint nakedEdges, out WeftRefinerHandle outRefiner);

        /// <summary>Plans a subdivision with the scheme, naked-edge mode, creases and corners of <c>options</c> once, for re-evaluation with <c>weft_refiner_evaluate</c> (the other <c>weft_refiner_*</c> functions work on it as on one from <c>weft_refiner_new</c>).</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_refiner_new_ex(WeftMeshHandle cage, ref NativeSubdivisionOptions options, uint levels, out WeftRefinerHandle outRefiner);

        /// <summary>Computes the refined positions for new cage positions, without allocating: the cage's faces must be those the refiner was built from.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_refiner_evaluate(WeftRefinerHandle refiner, double[] cagePositions, UIntPtr vertexCount, [Out] double[] outPositions, UIntPtr outLen);

        /// <summary>Makes the refined mesh at the cage positions the refiner was built from.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_refiner_mesh(WeftRefinerHandle refiner, out WeftMeshHandle outMesh);

        /// <summary>Returns the number of refined vertices (the output of <c>weft_refiner_evaluate</c> holds three doubles each), or 0 when <c>refiner</c> is NULL.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern UIntPtr weft_refiner_vertex_count(WeftRefinerHandle refiner);

        /// <summary>Returns the number of refined faces, or 0 when <c>refiner</c> is NULL.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern UIntPtr weft_refiner_face_count(WeftRefinerHandle refiner);

        /// <summary>Frees a refiner. NULL is ignored.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern void weft_refiner_free(IntPtr refiner);

        /// <summary>Subdivides a mesh <c>levels</c> times with the scheme, naked-edge mode, creases and corners of <c>options</c>, as OpenSubdiv does with the same <c>Sdc::Options</c> and <c>TopologyDescriptor</c> arrays. Output order as <c>weft_catmull_clark</c> and <c>weft_loop</c>.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_subdivide_ex(WeftMeshHandle mesh, ref NativeSubdivisionOptions options, uint levels, out WeftMeshHandle outMesh);

        /// <summary>Gives the vertex, face and face-index counts of the mesh <c>levels</c> steps of <c>scheme</c> make from <c>mesh</c> (creases do not change them; holes do: see <c>weft_subdivision_counts_ex</c>), without subdividing: the sizes the buffers of <c>weft_subdivide_vertex_data</c>, <c>weft_subdivide_face_varying</c> and <c>weft_subdivide_limit</c> need.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_subdivision_counts(WeftMeshHandle mesh, uint scheme, uint levels, out UIntPtr outVertexCount, out UIntPtr outFaceCount, out UIntPtr outIndexCount);

        /// <summary>As <c>weft_subdivision_counts</c>, for the subdivision <c>options</c> describe: holes (and with WEFT_NAKED_EDGES_NONE the faces at the boundary) leave their vertices but no faces, so these are the sizes of <c>weft_subdivide_ex</c>'s result and of the buffers of <c>weft_subdivide_face_varying</c> with the same options.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_subdivision_counts_ex(WeftMeshHandle mesh, ref NativeSubdivisionOptions options, uint levels, out UIntPtr outVertexCount, out UIntPtr outFaceCount, out UIntPtr outIndexCount);

        /// <summary>As <c>weft_subdivision_parent_faces</c>, for the subdivision <c>options</c> describe: the faces of <c>weft_subdivide_ex</c>'s result, without the children of holes. <c>out_parents</c> needs room for the face count <c>weft_subdivision_counts_ex</c> gives, else the call fails with WEFT_STATUS_BUFFER_TOO_SMALL and writes nothing.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_subdivision_parent_faces_ex(WeftMeshHandle mesh, ref NativeSubdivisionOptions options, uint levels, [Out] uint[] outParents, UIntPtr capacity);

        /// <summary>Carries per-vertex data of any width (colours, weights) through the subdivision of <c>weft_subdivide_ex</c>: every refined vertex gets the same weighted sum of cage values as its position (OpenSubdiv's <c>PrimvarRefiner::Interpolate</c>).</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_subdivide_vertex_data(WeftMeshHandle mesh, ref NativeSubdivisionOptions options, uint levels, double[] data, UIntPtr dataLen, UIntPtr width, [Out] double[] outData, UIntPtr capacity);

        /// <summary>Carries per-face-corner values (UVs) through the subdivision of <c>weft_subdivide_ex</c>, face-varying as OpenSubdiv's <c>PrimvarRefiner::InterpolateFaceVarying</c>: corners of one vertex that use different values are a seam, and <c>face_varying_linear</c> says where values are interpolated linearly.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_subdivide_face_varying(WeftMeshHandle mesh, ref NativeSubdivisionOptions options, uint levels, uint faceVaryingLinear, double[] values, UIntPtr valueCount, UIntPtr width, uint[] valueIndices, UIntPtr indexCount, [Out] double[] outValues, UIntPtr capacity);

        /// <summary>Projects the vertices of the subdivision of <c>weft_subdivide_ex</c> onto the limit surface, and gives the surface's unit normals there (OpenSubdiv's <c>PrimvarRefiner::Limit</c>; normal = du × dv normalised, outward for counter-clockwise faces, zero where undefined).</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_subdivide_limit(WeftMeshHandle mesh, ref NativeSubdivisionOptions options, uint levels, [Out] double[] outPositions, [Out] double[] outNormals, UIntPtr capacity);

        /// <summary>Prepares the limit surface of <c>cage</c> subdivided as <c>options</c> say (scheme, naked-edge mode, creases, corners, holes, creasing, triangle weights), for evaluation anywhere with <c>weft_limit_surface_evaluate</c>.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_limit_surface_new(WeftMeshHandle cage, ref NativeSubdivisionOptions options, out WeftLimitSurfaceHandle outSurface);

        /// <summary>Evaluates the limit surface at <c>count</c> samples: sample i lies on cage face <c>faces[i]</c> at <c>(uvs[2 i], uvs[2 i + 1])</c>. Parallel; nothing is allocated per sample.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_limit_surface_evaluate(WeftLimitSurfaceHandle surface, UIntPtr count, uint[] faces, double[] uvs, [Out] double[] outPositions, [Out] double[] outDu, [Out] double[] outDv);

        /// <summary>Finds the nearest point of the limit surface to each of <c>count</c> query points: its face, its (u, v) on that face (parameters as <c>weft_limit_surface_evaluate</c>) and its position, which is the surface evaluated there.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_limit_surface_closest_point(WeftLimitSurfaceHandle surface, UIntPtr count, double[] points, [Out] uint[] outFaces, [Out] double[] outUvs, [Out] double[] outPositions);

        /// <summary>Frees a limit surface. NULL is ignored.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern void weft_limit_surface_free(IntPtr surface);

        /// <summary>Prepares a mesh whose creases are unwelded seams or sharp folds for creased subdivision, as Rhino's ToSubD does: welds vertices at exactly the same position, and lists as creases every edge that was naked before welding and has two faces after, and every edge whose faces' normals differ by more than <c>angle_degrees</c> (180 or more: no fold test). Pass the pairs as <c>crease_vertex_pairs</c> with <c>WEFT_SHARPNESS_INFINITE</c> sharpness. <c>weft_crease_edges_from_mesh_ex</c> also gives which welded vertex each input vertex became.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_crease_edges_from_mesh(WeftMeshHandle mesh, double angleDegrees, out WeftMeshHandle outWelded, [Out] uint[] outPairs, UIntPtr capacity, out UIntPtr outCreaseCount);

        /// <summary>As <c>weft_crease_edges_from_mesh</c>, and gives the vertex map of the weld: for each vertex of <c>mesh</c>, the index of the vertex of the welded mesh it became (the first of the vertices at its position). With it a host carries per-vertex data given on the input (colours, weights, its own creases and corners) onto the welded mesh: welded vertex <c>out_vertex_map[v]</c> takes vertex <c>v</c>'s value.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_crease_edges_from_mesh_ex(WeftMeshHandle mesh, double angleDegrees, out WeftMeshHandle outWelded, [Out] uint[] outPairs, UIntPtr capacity, out UIntPtr outCreaseCount, [Out] uint[] outVertexMap, UIntPtr vertexMapCapacity);

        /// <summary>The limit surface of the Catmull-Clark subdivision <c>options</c> describes (its scheme must be WEFT_SCHEME_CATMULL_CLARK) as one bicubic Bézier patch per face of <c>cage</c> refined <c>isolation</c> levels (1 to 8), in the refined faces' order, <c>weft_subdivision_counts_ex(cage, options, isolation, ...)</c> of them.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_limit_patches(WeftMeshHandle cage, ref NativeSubdivisionOptions options, uint isolation, [Out] double[] outControlPoints, [Out] uint[] outCageFaces, [Out] double[] outErrors, UIntPtr capacity, out UIntPtr outPatchCount, [Out] double[] outMaxError, out UIntPtr outExactCount);

        /// <summary>The limit surface's patches, as <c>weft_limit_patches</c> gives them for the cage and options <c>surface</c> was made from (its scheme must be WEFT_SCHEME_CATMULL_CLARK): the same buffers, the same rules, the same errors, and WEFT_STATUS_NULL_POINTER for a NULL <c>surface</c>.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_limit_surface_patches(WeftLimitSurfaceHandle surface, uint isolation, [Out] double[] outControlPoints, [Out] uint[] outCageFaces, [Out] double[] outErrors, UIntPtr capacity, out UIntPtr outPatchCount, [Out] double[] outMaxError, out UIntPtr outExactCount);

        /// <summary>Joins meshes into one: the vertices of each follow those of the meshes before it and its face indices are offset to match; faces keep their order.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_join(IntPtr[] meshes, UIntPtr count, out WeftMeshHandle outMesh);

        /// <summary>The tolerance to weld <c>mesh</c> with when the host has none of its own: a millionth of the mesh's bounding-box diagonal (0 for an empty mesh or a single point). Unlike the absolute WEFT_DEFAULT_WELD_TOLERANCE, it never collapses the faces of a small part or a dense scan, whatever the units. The command line's <c>weld</c> and <c>t-nodes</c> use it when no tolerance is given.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_weld_relative_tolerance(WeftMeshHandle mesh, [Out] double[] outTolerance);

        /// <summary>Returns how many vertices no face uses, or 0 when <c>mesh</c> is NULL. Subdivision keeps such bare vertices in place (OpenSubdiv cages carry them on purpose); <c>weft_remove_unused_vertices</c> leaves them out.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern UIntPtr weft_mesh_unused_vertex_count(WeftMeshHandle mesh);

        /// <summary>Leaves out the vertices no face uses; the others keep their order (the face indices are renumbered to match).</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_remove_unused_vertices(WeftMeshHandle mesh, out WeftMeshHandle outMesh, out UIntPtr outRemoved);

        /// <summary>Welds vertices: every two vertices at most <c>tolerance</c> apart become one, transitively. The merged vertex keeps the position of its cluster's lowest-index vertex (seams stay where the surface put them, and welding twice changes nothing). Faces drop repeated corners (a quad with two merged corners becomes a triangle); faces left with fewer than 3 vertices are removed; vertices no face uses are left out.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_weld(WeftMeshHandle mesh, double tolerance, out WeftMeshHandle outMesh, out WeftWeldReport outReport);

        /// <summary>Finds the T-nodes: vertices on the naked boundary that lie within <c>tolerance</c> of the inside of another face's naked edge (and further than <c>tolerance</c> from its ends). They are sorted by face, then by the edge's place in the face, then by parameter.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_find_t_nodes(WeftMeshHandle mesh, double tolerance, [Out] WeftTNode[] outNodes, UIntPtr capacity, out UIntPtr outCount);

        /// <summary>Repairs the T-nodes that <c>weft_find_t_nodes</c> reports: each vertex is inserted into the edge it lies on (several on one edge in order), so the face becomes an n-gon and both sides share the seam. Positions do not change.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_repair_t_nodes(WeftMeshHandle mesh, double tolerance, out WeftMeshHandle outMesh, out UIntPtr outInserted);

        /// <summary>Removes every face that has a twin with the same vertices (in either orientation, from any corner): all copies go. These are the walls inside an aggregation of joined and welded boxes. Vertices are kept as they are.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_cull_adjacent(WeftMeshHandle mesh, out WeftMeshHandle outMesh, out UIntPtr outRemoved);

        /// <summary>Computes the unit normal of each face by Newell's method (robust on non-planar polygons); a face of zero area gets (0, 0, 0).</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_face_normals(WeftMeshHandle mesh, [Out] double[] outNormals, UIntPtr capacity);

        /// <summary>Computes the unit normal of each vertex: the face normals weighted by the face's angle at the vertex (unchanged when faces are split into triangles). A vertex no face uses gets (0, 0, 0).</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_vertex_normals(WeftMeshHandle mesh, [Out] double[] outNormals, UIntPtr capacity);

        /// <summary>Computes, per face, the largest distance of its corners from its best-fit (least-squares) plane; 0 for triangles. A face is planar within a tolerance when its value is at most the tolerance (the planar-quad mesh check).</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_planarity(WeftMeshHandle mesh, [Out] double[] outDeviations, UIntPtr capacity);

        /// <summary>Chains the naked edges (edges with one face) into polylines. On a manifold mesh each border is one closed polyline running the way its faces run their edges; at a vertex with one or three or more naked edges polylines stop, and one that returns to its start is closed. A closed polyline does not repeat its first point at the end.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_naked_boundaries(WeftMeshHandle mesh, [Out] double[] outPoints, UIntPtr pointsCapacity, [Out] UIntPtr[] outPointCounts, [Out] byte[] outClosed, UIntPtr polylinesCapacity, out UIntPtr outPointTotal, out UIntPtr outPolylineCount);

        /// <summary>Gives every connected piece one consistent winding, flipping the fewest of its faces, then turns each closed orientable piece to face outward. A piece that cannot be oriented (a Möbius strip) is wound as consistently as it can be; <c>weft_mesh_info</c> tells whether the mesh is orientable.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_unify_orientation(WeftMeshHandle mesh, out WeftMeshHandle outMesh, out UIntPtr outFlipped);

        /// <summary>As <c>weft_unify_orientation</c> (one consistent winding per piece, closed pieces turned to enclose a positive volume), reporting the pieces. The triangles of an STL file share no vertices: weld them first (<c>weft_weld</c>), or every triangle is an open piece of its own.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_orient_outward(WeftMeshHandle mesh, out WeftMeshHandle outMesh, out WeftOrientReport outReport);

        /// <summary>Reverses every face, keeping its first corner first ({a, b, c, d} becomes {a, d, c, b}), so that flipping twice gives the input back.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_flip(WeftMeshHandle mesh, out WeftMeshHandle outMesh);

        /// <summary>Triangulates points by the Delaunay criterion of their projections onto a plane; the mesh's vertices are the original 3-D points, its triangles front-facing along the plane's normal.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_delaunay(double[] points, UIntPtr pointCount, WeftPlane[] plane, out WeftMeshHandle outMesh, out UIntPtr outMerged);

        /// <summary>Computes the Voronoi cell of each point on a plane, clipped to a boundary polygon and, when <c>radius</c> is positive, to the 64-gon inscribed in the circle of that radius around the point.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_voronoi(double[] points, UIntPtr pointCount, WeftPlane[] plane, double[] boundary, UIntPtr boundaryCount, double radius, out WeftCellsHandle outCells);

        /// <summary>Returns the number of cells (the number of input points), or 0 when <c>cells</c> is NULL.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern UIntPtr weft_cells_count(WeftCellsHandle cells);

        /// <summary>Returns the number of corners of all cells together, or 0 when <c>cells</c> is NULL.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern UIntPtr weft_cells_corner_count(WeftCellsHandle cells);

        /// <summary>Returns the number of corners of each cell (<c>weft_cells_count</c> values, 0 for an empty cell), or NULL when <c>cells</c> is NULL or holds no cells.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern IntPtr weft_cells_sizes(WeftCellsHandle cells);

        /// <summary>Returns the corners of all cells, one cell after another, <c>3 * weft_cells_corner_count</c> doubles, or NULL when <c>cells</c> is NULL or every cell is empty.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern IntPtr weft_cells_corners(WeftCellsHandle cells);

        /// <summary>Copies the cells into caller buffers.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_cells_copy(WeftCellsHandle cells, [Out] uint[] outSizes, UIntPtr sizesCapacity, [Out] double[] outCorners, UIntPtr cornersCapacity);

        /// <summary>Makes a mesh with one n-gon face per non-empty cell, in cell order; the cells share no vertices (weld the mesh to join them).</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_cells_to_mesh(WeftCellsHandle cells, out WeftMeshHandle outMesh);

        /// <summary>Frees cells made by <c>weft_voronoi</c>. NULL is ignored.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern void weft_cells_free(IntPtr cells);

        /// <summary>Connects a <c>u_count × v_count</c> grid of points (a sampled surface) into a quad mesh, or triangles.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_mesh_from_grid(double[] points, UIntPtr pointCount, UIntPtr uCount, UIntPtr vCount, [MarshalAs(UnmanagedType.U1)] bool closedU, [MarshalAs(UnmanagedType.U1)] bool closedV, [MarshalAs(UnmanagedType.U1)] bool triangulate, out WeftMeshHandle outMesh);

        /// <summary>Raises a pyramid on every face: a new vertex at the face's centroid moved along its normal by the face's height, and a fan of triangles.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_stellate(WeftMeshHandle mesh, double[] heights, UIntPtr heightCount, out WeftMeshHandle outMesh);

        /// <summary>Makes a flat rectangle of <c>size_x × size_y</c> on the XY plane, centred on the origin and facing +z, of <c>u_count × v_count</c> quads.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_plane_grid(double sizeX, double sizeY, UIntPtr uCount, UIntPtr vCount, out WeftMeshHandle outMesh);

        /// <summary>Makes a closed, welded box centred on the origin whose sides are divided into quads: <c>u_count</c> along x, <c>v_count</c> along y, <c>w_count</c> along z.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_box(double sizeX, double sizeY, double sizeZ, UIntPtr uCount, UIntPtr vCount, UIntPtr wCount, out WeftMeshHandle outMesh);

        /// <summary>Makes a sphere of <c>radius</c> centred on the origin with <c>u_count</c> segments around the z axis (at least 3) and <c>v_count</c> from pole to pole (at least 2); each pole is one vertex with a fan of triangles, the rest are quads. Counts whose result would pass 2^31 − 1 face corners (any count near SIZE_MAX included) fail with WEFT_STATUS_RESULT_TOO_LARGE before anything is allocated.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_uv_sphere(double radius, UIntPtr uCount, UIntPtr vCount, out WeftMeshHandle outMesh);

        /// <summary>Makes a platonic solid centred on the origin with its vertices on the sphere of <c>radius</c>.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_platonic(uint kind, double radius, out WeftMeshHandle outMesh);

        /// <summary>Makes a prism, antiprism, pyramid or dipyramid on a regular n-gon of circumradius <c>radius</c> about the z axis, <c>height</c> tall and centred on the origin.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_sided_solid(uint kind, UIntPtr sides, double radius, double height, out WeftMeshHandle outMesh);

        /// <summary>Splits each n-gon into n quads through its edge midpoints and centroid, <c>levels</c> times, without smoothing (Weaverbird's Split Polygons: the topology of Catmull-Clark, the surface unchanged, the result welded).</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_split_polygons(WeftMeshHandle mesh, uint levels, out WeftMeshHandle outMesh);

        /// <summary>Splits each triangle into four through its edge midpoints, <c>levels</c> times, without smoothing (Weaverbird's Split Triangles).</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_split_triangles(WeftMeshHandle mesh, uint levels, out WeftMeshHandle outMesh);

        /// <summary>Splits each quad into four quads, each triangle into four triangles and each larger polygon into quads around its centroid, <c>levels</c> times, without smoothing (Weaverbird's Constant Quads Split).</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_constant_quads_split(WeftMeshHandle mesh, uint levels, out WeftMeshHandle outMesh);

        /// <summary>The mid-edge subdivision (Peters and Reif), <c>levels</c> times: a face of edge midpoints per face and per vertex; boundary vertices are kept so an open mesh keeps its outline.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_midedge(WeftMeshHandle mesh, uint levels, out WeftMeshHandle outMesh);

        /// <summary>Gives each face an inner face, its corners pulled towards its centroid, joined to it by one quad per edge, <c>levels</c> times (Weaverbird's Inner Polygons).</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_inner_polygons(WeftMeshHandle mesh, uint levels, double pull, out WeftMeshHandle outMesh);

        /// <summary>Places a triangle in each corner of each face and leaves the middle open, <c>levels</c> times (Weaverbird's Sierpinski Triangles): one new hole per face and level.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_sierpinski_triangles(WeftMeshHandle mesh, uint levels, out WeftMeshHandle outMesh);

        /// <summary>Laplacian smoothing: each iteration moves every vertex <c>blend</c> of the way towards the average of its neighbours (Weaverbird's Laplacian Smoothing). The faces do not change.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_laplacian_smooth(WeftMeshHandle mesh, uint iterations, double blend, uint nakedEdges, out WeftMeshHandle outMesh);

        /// <summary>Volume-preserving Laplacian smoothing, the HC algorithm of Vollmer, Mann and Müller (1999): each iteration averages, then pushes every vertex back by <c>beta</c> of its own displacement and <c>1 - beta</c> of its neighbours' (Weaverbird's LaplacianHC).</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_laplacian_hc_smooth(WeftMeshHandle mesh, uint iterations, double alpha, double beta, uint nakedEdges, out WeftMeshHandle outMesh);

        /// <summary><c>weft_laplacian_hc_smooth</c> with Weaverbird's remaining LaplacianHC inputs: a direction (its orientation input) and per-vertex activation weights. Each weight scales the steps its vertex takes (0 keeps it where it is and it anchors its neighbours, 1 is the full step); the direction then restricts each vertex to its original normal line or tangent plane.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_laplacian_hc_smooth_ex(WeftMeshHandle mesh, uint iterations, double alpha, double beta, uint nakedEdges, uint direction, double[] activation, UIntPtr activationCount, out WeftMeshHandle outMesh);

        /// <summary>Blurs a per-vertex value (a colour, a weight) over the mesh: each iteration moves every vertex's value <c>blend</c> of the way towards the average of its neighbours' (Weaverbird's Blur). The mesh is unchanged.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_blur_values(WeftMeshHandle mesh, double[] values, UIntPtr valueCount, UIntPtr components, uint iterations, double blend, uint nakedEdges, [Out] double[] outValues, UIntPtr outLen);

        /// <summary>Moves every vertex by <c>distance</c> along the surface normal (positive: towards the front); the faces are kept (Weaverbird's Offset Mesh).</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_offset_mesh(WeftMeshHandle mesh, double distance, uint offsetType, out WeftMeshHandle outMesh);

        /// <summary>Makes a solid of a surface: the input, its offset by <c>distance</c>, and a quad along every naked edge joining them, wound to face outwards (Weaverbird's Mesh Thicken). Vertex <c>v</c>'s offset is vertex <c>vertex_count + v</c>.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_thicken_mesh(WeftMeshHandle mesh, double distance, uint offsetType, out WeftMeshHandle outMesh);

        /// <summary>Insets each face and keeps both the frame of quads and the inner face (Weaverbird's Mesh Window).</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_mesh_window(WeftMeshHandle mesh, double[] distances, UIntPtr distanceCount, uint insetMode, out WeftMeshHandle outMesh);

        /// <summary>Insets each face and keeps only the frame of quads: each face becomes a ring around a new hole (Weaverbird's Picture Frame).</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_picture_frame(WeftMeshHandle mesh, double[] distances, UIntPtr distanceCount, uint insetMode, out WeftMeshHandle outMesh);

        /// <summary>Cuts each quad into 3 × 3 quads and removes the middle one, <c>levels</c> times (Weaverbird's Sierpinski Carpet).</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_sierpinski_carpet(WeftMeshHandle mesh, uint levels, out WeftMeshHandle outMesh);

        /// <summary>Bevels every edge: faces shrink towards their centroids by <c>fraction</c>, each edge between two faces becomes a quad and each interior vertex a face (Conway's expansion: a cube gives a rhombicuboctahedron).</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_bevel_edges(WeftMeshHandle mesh, double fraction, out WeftMeshHandle outMesh);

        /// <summary>Cuts every vertex off at <c>fraction</c> of each edge's length, adding a face per vertex (Conway's truncation: a cube gives 6 octagons and 8 triangles); boundary vertices are kept so the outline stays.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_bevel_vertices(WeftMeshHandle mesh, double fraction, out WeftMeshHandle outMesh);

        /// <summary>Re-fills the chosen faces of a mesh by a pattern of triangles or quads (Weaverbird's Tile, with its numbers for both choices). Every pattern keeps each face's outline and winding and the input's vertices (their indices too), so seams stay welded and a closed mesh stays closed; the fans' centroids follow the input's vertices, one per filled face.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_tile(WeftMeshHandle mesh, uint fill, uint faces, out WeftMeshHandle outMesh);

        /// <summary>The dual mesh: a vertex per face, a face per interior vertex joining the faces around it (Weaverbird's Dual). Vertices on naked or non-manifold edges get no face.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_dual(WeftMeshHandle mesh, uint dualMode, out WeftMeshHandle outMesh);

        /// <summary>Counts the unique edges of a mesh, to size the buffers of <c>weft_mesh_copy_edges</c> and <c>weft_mesh_copy_edge_segments</c>.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_mesh_edge_count(WeftMeshHandle mesh, out UIntPtr outCount);

        /// <summary>Copies the unique edges as vertex index pairs <c>(low, high)</c>, sorted (Weaverbird's Mesh Edges, as indices).</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_mesh_copy_edges(WeftMeshHandle mesh, [Out] uint[] outPairs, UIntPtr outLen);

        /// <summary>Copies the unique edges as line segments, six doubles each (start x, y, z, end x, y, z), in the order of <c>weft_mesh_copy_edges</c> (Weaverbird's Mesh Edges).</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_mesh_copy_edge_segments(WeftMeshHandle mesh, [Out] double[] outSegments, UIntPtr outLen);

        /// <summary>Rotates every face's corner list so it starts <c>shift</c> corners later (<c>[a, b, c, d]</c> by 1 is <c>[b, c, d, a]</c>; negative goes back); the winding and vertices are unchanged (Weaverbird's Reroute Faces).</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_reroute_faces(WeftMeshHandle mesh, long shift, out WeftMeshHandle outMesh);

        /// <summary>Builds the faces a set of line segments encloses (Weaverbird's Mesh From Lines): endpoints within <c>tolerance</c> are welded, dangling segments ignored, and the smallest cycles of the segments, seen in their best-fit plane, become faces wound about its normal.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint weft_mesh_from_lines(double[] segments, UIntPtr segmentCount, double tolerance, uint maxValence, out WeftMeshHandle outMesh);
    }
}
