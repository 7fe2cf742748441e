using System;

namespace Weft
{
    /// <summary>
    /// Subdivision with creases and corners, data carried through it, the
    /// limit surface, and creases found on a mesh (OpenSubdiv's rules; see
    /// <see cref="SubdivisionOptions"/>). A null options argument means the
    /// defaults: fixed naked edges, nothing creased.
    /// </summary>
    public static partial class Subdivision
    {
        /// <summary>
        /// Subdivides <paramref name="mesh"/> <paramref name="levels"/> times (0 copies) with
        /// the naked-edge mode, creases and corners of <paramref name="options"/>.
        /// Output order as <see cref="CatmullClark"/> and <see cref="Loop"/>.
        /// </summary>
        /// <exception cref="WeftException">
        /// <see cref="WeftStatus.InvalidArgument"/> for an unknown mode or rule, a crease
        /// whose vertices are not an edge of the mesh, a corner past the vertex count or a
        /// negative or NaN sharpness (the message names which crease or corner);
        /// <see cref="WeftStatus.NotTriangles"/> for Loop on other faces; a result too large.
        /// </exception>
        public static WeftMesh Subdivide(WeftMesh mesh, Scheme scheme, int levels, SubdivisionOptions options)
        {
            WeftMeshHandle result;
            uint status = SubdivisionOptions.Call(NativeMethods.weft_subdivide_ex, mesh, "mesh", options, scheme, levels, out result);
            return WeftMesh.FromCall(status, result);
        }

        /// <summary>
        /// The vertex, face and face-index counts of <see cref="Subdivide"/>'s result with
        /// <paramref name="options"/>: holes (and <see cref="NakedEdges.None"/>) leave their
        /// vertices but no faces. These are the sizes the outputs with the same options need.
        /// </summary>
        public static SubdivisionCounts Counts(WeftMesh mesh, Scheme scheme, int levels, SubdivisionOptions options)
        {
            UIntPtr[] sizes;
            WeftException.Check(SubdivisionOptions.Call(
                (WeftMeshHandle handle, ref NativeSubdivisionOptions native, uint steps, out UIntPtr[] result) =>
                {
                    UIntPtr vertices, faces, indices;
                    uint status = NativeMethods.weft_subdivision_counts_ex(handle, ref native, steps, out vertices, out faces, out indices);
                    result = new[] { vertices, faces, indices };
                    return status;
                },
                mesh, "mesh", options, scheme, levels, out sizes));
            return new SubdivisionCounts
            {
                VertexCount = Arguments.ToInt(sizes[0]),
                FaceCount = Arguments.ToInt(sizes[1]),
                IndexCount = Arguments.ToInt(sizes[2]),
            };
        }

        /// <summary>
        /// For each face of <see cref="Subdivide"/>'s result with <paramref name="options"/>, the
        /// index of the cage face it comes from; holes have none.
        /// </summary>
        public static uint[] ParentFaces(WeftMesh mesh, Scheme scheme, int levels, SubdivisionOptions options)
        {
            var parents = new uint[Counts(mesh, scheme, levels, options).FaceCount];
            int unused;
            WeftException.Check(SubdivisionOptions.Call(
                (WeftMeshHandle handle, ref NativeSubdivisionOptions native, uint steps, out int result) =>
                {
                    result = 0;
                    return NativeMethods.weft_subdivision_parent_faces_ex(handle, ref native, steps, parents, (UIntPtr)parents.Length);
                },
                mesh, "mesh", options, scheme, levels, out unused));
            return parents;
        }

        /// <summary>
        /// The vertex, face and face-corner counts of <paramref name="levels"/> steps of
        /// <paramref name="scheme"/> on <paramref name="mesh"/>, without subdividing
        /// (creases do not change them): the sizes the other methods' buffers need.
        /// </summary>
        public static SubdivisionCounts Counts(WeftMesh mesh, Scheme scheme, int levels)
        {
            UIntPtr vertices, faces, indices;
            WeftException.Check(NativeMethods.weft_subdivision_counts(
                Arguments.Mesh(mesh, "mesh"), (uint)scheme, Arguments.Unsigned(levels, "levels"),
                out vertices, out faces, out indices));
            return new SubdivisionCounts
            {
                VertexCount = Arguments.ToInt(vertices),
                FaceCount = Arguments.ToInt(faces),
                IndexCount = Arguments.ToInt(indices),
            };
        }

        /// <summary>
        /// Carries per-vertex values (<paramref name="width"/> doubles per cage vertex:
        /// colours, weights) through the subdivision of <see cref="Subdivide"/>: each refined
        /// vertex gets the same weighted sum of cage values as its position. Returns
        /// <paramref name="width"/> doubles per refined vertex.
        /// </summary>
        /// <exception cref="WeftException">
        /// As <see cref="Subdivide"/>; <see cref="WeftStatus.CountMismatch"/> when
        /// <paramref name="data"/> does not hold <paramref name="width"/> values per vertex;
        /// <see cref="WeftStatus.InvalidArgument"/> when <paramref name="width"/> is 0 or less.
        /// </exception>
        public static double[] SubdivideVertexData(WeftMesh mesh, Scheme scheme, int levels, SubdivisionOptions options, double[] data, int width)
        {
            Arguments.NotNull(data, "data");
            Arguments.Unsigned(width, "width");
            SubdivisionCounts counts = Counts(mesh, scheme, levels, options);
            var output = new double[checked(counts.VertexCount * width)];
            SubdivideVertexData(mesh, scheme, levels, options, data, width, output);
            return output;
        }

        /// <summary>
        /// As <see cref="SubdivideVertexData(WeftMesh, Scheme, int, SubdivisionOptions, double[], int)"/>,
        /// into <paramref name="output"/>, which needs <paramref name="width"/> doubles per
        /// refined vertex (<see cref="Counts(WeftMesh, Scheme, int, SubdivisionOptions)"/>); <see cref="WeftStatus.BufferTooSmall"/> otherwise.
        /// </summary>
        public static void SubdivideVertexData(WeftMesh mesh, Scheme scheme, int levels, SubdivisionOptions options, double[] data, int width, double[] output)
        {
            WeftMeshHandle handle = Arguments.Mesh(mesh, "mesh");
            uint steps = Arguments.Unsigned(levels, "levels");
            Arguments.NotNull(data, "data");
            Arguments.NotNull(output, "output");
            UIntPtr size = Arguments.Size(width, "width");
            uint status;
            using (SubdivisionOptions.Pinned pinned = SubdivisionOptions.Pin(options, scheme))
            {
                NativeSubdivisionOptions native = pinned.Native;
                status = NativeMethods.weft_subdivide_vertex_data(
                    handle, ref native, steps, data, (UIntPtr)data.Length, size, output, (UIntPtr)output.Length);
            }
            WeftException.Check(status);
        }

        /// <summary>
        /// Carries per-face-corner values (UVs) through the subdivision of
        /// <see cref="Subdivide"/>, face-varying: <paramref name="values"/> holds
        /// <paramref name="width"/> doubles per value, <paramref name="valueIndices"/> the value
        /// of every face corner of <paramref name="mesh"/>, face after face (corners of one
        /// vertex with different values are a seam). Returns <paramref name="width"/> doubles
        /// per face corner of the refined mesh, face after face.
        /// </summary>
        /// <exception cref="WeftException">
        /// As <see cref="Subdivide"/>; <see cref="WeftStatus.CountMismatch"/> (lengths),
        /// <see cref="WeftStatus.IndexOutOfRange"/> (a value index past the values),
        /// <see cref="WeftStatus.InvalidArgument"/> (an unknown <paramref name="linear"/>, a width of 0).
        /// </exception>
        public static double[] SubdivideFaceVarying(WeftMesh mesh, Scheme scheme, int levels, SubdivisionOptions options,
                                                    FaceVaryingLinear linear, double[] values, int width, uint[] valueIndices)
        {
            Arguments.Unsigned(width, "width");
            SubdivisionCounts counts = Counts(mesh, scheme, levels, options);
            var output = new double[checked(counts.IndexCount * width)];
            SubdivideFaceVarying(mesh, scheme, levels, options, linear, values, width, valueIndices, output);
            return output;
        }

        /// <summary>
        /// As <see cref="SubdivideFaceVarying(WeftMesh, Scheme, int, SubdivisionOptions, FaceVaryingLinear, double[], int, uint[])"/>,
        /// into <paramref name="output"/>, which needs <paramref name="width"/> doubles per refined
        /// face corner (<see cref="Counts(WeftMesh, Scheme, int, SubdivisionOptions)"/>); <see cref="WeftStatus.BufferTooSmall"/> otherwise.
        /// </summary>
        public static void SubdivideFaceVarying(WeftMesh mesh, Scheme scheme, int levels, SubdivisionOptions options,
                                                FaceVaryingLinear linear, double[] values, int width, uint[] valueIndices, double[] output)
        {
            WeftMeshHandle handle = Arguments.Mesh(mesh, "mesh");
            uint steps = Arguments.Unsigned(levels, "levels");
            Arguments.NotNull(values, "values");
            Arguments.NotNull(valueIndices, "valueIndices");
            Arguments.NotNull(output, "output");
            UIntPtr size = Arguments.Size(width, "width");
            // Width 0 is left to the library, which names it.
            if (width > 0 && values.Length % width != 0)
            {
                throw new WeftException(WeftStatus.CountMismatch,
                    "values holds " + values.Length + " doubles, which is not " + width + " per value");
            }
            UIntPtr valueCount = (UIntPtr)(width > 0 ? values.Length / width : 0);
            uint status;
            using (SubdivisionOptions.Pinned pinned = SubdivisionOptions.Pin(options, scheme))
            {
                NativeSubdivisionOptions native = pinned.Native;
                status = NativeMethods.weft_subdivide_face_varying(
                    handle, ref native, steps, (uint)linear, values, valueCount, size,
                    valueIndices, (UIntPtr)valueIndices.Length, output, (UIntPtr)output.Length);
            }
            WeftException.Check(status);
        }

        /// <summary>
        /// The vertices of the subdivision of <see cref="Subdivide"/> projected onto the
        /// limit surface, with the surface's unit normals there (OpenSubdiv's
        /// <c>PrimvarRefiner::Limit</c>); in the refined mesh's vertex order.
        /// </summary>
        /// <exception cref="WeftException">
        /// As <see cref="Subdivide"/>, and <see cref="WeftStatus.InvalidArgument"/> for
        /// Catmull-Clark at level 0 on a mesh whose faces are not all quads.
        /// </exception>
        public static LimitSurface SubdivideLimit(WeftMesh mesh, Scheme scheme, int levels, SubdivisionOptions options)
        {
            SubdivisionCounts counts = Counts(mesh, scheme, levels, options);
            var positions = new double[checked(3 * counts.VertexCount)];
            var normals = new double[positions.Length];
            SubdivideLimit(mesh, scheme, levels, options, positions, normals);
            return new LimitSurface { Positions = positions, Normals = normals };
        }

        /// <summary>
        /// As <see cref="SubdivideLimit(WeftMesh, Scheme, int, SubdivisionOptions)"/>, into caller
        /// buffers of 3 doubles per refined vertex each (<see cref="Counts(WeftMesh, Scheme, int, SubdivisionOptions)"/>;
        /// <see cref="WeftStatus.BufferTooSmall"/> otherwise). <paramref name="normals"/> may be
        /// null when they are not wanted; when given it must be as long as <paramref name="positions"/>.
        /// </summary>
        public static void SubdivideLimit(WeftMesh mesh, Scheme scheme, int levels, SubdivisionOptions options, double[] positions, double[] normals)
        {
            WeftMeshHandle handle = Arguments.Mesh(mesh, "mesh");
            uint steps = Arguments.Unsigned(levels, "levels");
            Arguments.NotNull(positions, "positions");
            if (normals != null && normals.Length != positions.Length)
            {
                throw new WeftException(WeftStatus.CountMismatch,
                    "normals holds " + normals.Length + " doubles but positions holds " + positions.Length + "; give them the same length");
            }
            uint status;
            using (SubdivisionOptions.Pinned pinned = SubdivisionOptions.Pin(options, scheme))
            {
                NativeSubdivisionOptions native = pinned.Native;
                status = NativeMethods.weft_subdivide_limit(handle, ref native, steps, positions, normals, (UIntPtr)positions.Length);
            }
            WeftException.Check(status);
        }

        /// <summary>
        /// Prepares a mesh whose creases are unwelded seams or sharp folds, as Rhino's
        /// ToSubD does: returns the mesh with vertices at exactly the same position welded,
        /// and in <paramref name="creaseVertexPairs"/> two vertex indices (of the welded mesh)
        /// per crease: every edge that was naked before welding and has two faces after, and
        /// every edge whose faces' normals differ by more than <paramref name="angleDegrees"/>
        /// (180 or more: no fold test). Pass them to
        /// <see cref="SubdivisionOptions.AddCreases"/> with <see cref="SubdivisionOptions.SharpnessInfinite"/>.
        /// </summary>
        /// <exception cref="WeftException"><see cref="WeftStatus.InvalidArgument"/> for a NaN or negative angle.</exception>
        public static WeftMesh CreaseEdgesFromMesh(WeftMesh mesh, double angleDegrees, out uint[] creaseVertexPairs)
        {
            return CreaseEdges(mesh, angleDegrees, out creaseVertexPairs, null);
        }

        /// <summary>
        /// As <see cref="CreaseEdgesFromMesh(WeftMesh, double, out uint[])"/>, and gives the
        /// weld's vertex map: <paramref name="vertexMap"/> holds, for each vertex of
        /// <paramref name="mesh"/>, the vertex of the welded mesh it became (the first of
        /// the vertices at its position). Per-vertex data given on the input (colours,
        /// weights) follows the weld through it: welded vertex <c>vertexMap[v]</c> takes
        /// vertex <c>v</c>'s value.
        /// </summary>
        /// <exception cref="WeftException"><see cref="WeftStatus.InvalidArgument"/> for a NaN or negative angle.</exception>
        public static WeftMesh CreaseEdgesFromMesh(WeftMesh mesh, double angleDegrees, out uint[] creaseVertexPairs, out uint[] vertexMap)
        {
            Arguments.Mesh(mesh, "mesh");
            var map = new uint[mesh.VertexCount];
            WeftMesh result = CreaseEdges(mesh, angleDegrees, out creaseVertexPairs, map);
            vertexMap = map;
            return result;
        }

        /// <summary>Both overloads: <paramref name="map"/> null leaves the vertex map out.</summary>
        private static WeftMesh CreaseEdges(WeftMesh mesh, double angleDegrees, out uint[] creaseVertexPairs, uint[] map)
        {
            WeftMeshHandle handle = Arguments.Mesh(mesh, "mesh");
            // Two per face corner always suffices: no mesh has more edges than corners.
            var pairs = new uint[checked(2 * mesh.IndexCount)];
            WeftMeshHandle welded;
            UIntPtr count;
            uint status = map == null
                ? NativeMethods.weft_crease_edges_from_mesh(handle, angleDegrees, out welded, pairs, (UIntPtr)pairs.Length, out count)
                : NativeMethods.weft_crease_edges_from_mesh_ex(handle, angleDegrees, out welded, pairs, (UIntPtr)pairs.Length, out count,
                    map, (UIntPtr)map.Length);
            WeftMesh result = WeftMesh.FromCall(status, welded);
            var trimmed = new uint[checked(2 * Arguments.ToInt(count))];
            Array.Copy(pairs, trimmed, trimmed.Length);
            creaseVertexPairs = trimmed;
            return result;
        }
    }
}
