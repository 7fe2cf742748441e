using System;
using System.Runtime.InteropServices;

namespace Weft
{
    /// <summary>
    /// Counts and flags of a mesh's topology (see <see cref="WeftMesh.Info"/>).
    /// </summary>
    public sealed class WeftMeshInfo
    {
        /// <summary>Number of vertices.</summary>
        public long VertexCount { get; internal set; }
        /// <summary>Number of unique edges.</summary>
        public long EdgeCount { get; internal set; }
        /// <summary>Number of faces.</summary>
        public long FaceCount { get; internal set; }
        /// <summary>Edges with exactly one face.</summary>
        public long NakedEdgeCount { get; internal set; }
        /// <summary>Edges with three or more faces.</summary>
        public long NonManifoldEdgeCount { get; internal set; }
        /// <summary>Vertices whose faces do not form one fan, or on a non-manifold edge.</summary>
        public long NonManifoldVertexCount { get; internal set; }
        /// <summary>Pieces of faces connected through shared edges.</summary>
        public long ComponentCount { get; internal set; }
        /// <summary>No naked and no non-manifold edges (false for a mesh without faces).</summary>
        public bool IsClosed { get; internal set; }
        /// <summary>Every component can be given one consistent winding.</summary>
        public bool IsOrientable { get; internal set; }
        /// <summary>Every manifold edge already runs in opposite directions in its two faces.</summary>
        public bool IsOriented { get; internal set; }
    }

    /// <summary>
    /// An immutable polygon mesh owned by the native library: positions as
    /// x, y, z doubles per vertex, faces as sizes plus their concatenated
    /// vertex indices (triangles, quads and n-gons mixed). Dispose it to free
    /// the native memory at once; the finalizer frees it otherwise.
    /// </summary>
    public sealed class WeftMesh : IDisposable
    {
        private readonly WeftMeshHandle handle;

        static WeftMesh()
        {
            NativeLibraryLoader.EnsureLoaded();
        }

        internal WeftMesh(WeftMeshHandle handle)
        {
            this.handle = handle;
        }

        /// <summary>
        /// Creates a mesh by copying the buffers: <paramref name="positions"/>
        /// holds 3 doubles per vertex, <paramref name="faceSizes"/> one corner
        /// count (at least 3) per face, <paramref name="faceIndices"/> the faces'
        /// vertex indices one face after another.
        /// </summary>
        /// <exception cref="ArgumentNullException">A buffer is null.</exception>
        /// <exception cref="WeftException">
        /// The library refused the mesh: <see cref="WeftStatus.IndexOutOfRange"/>,
        /// <see cref="WeftStatus.FaceTooSmall"/>, <see cref="WeftStatus.RepeatedIndex"/>,
        /// <see cref="WeftStatus.NonFiniteCoordinate"/>, <see cref="WeftStatus.CountMismatch"/>
        /// (also when the position count is not a multiple of 3) or
        /// <see cref="WeftStatus.InputTooLarge"/>, with a message naming the face or vertex.
        /// </exception>
        public static WeftMesh Create(double[] positions, uint[] faceSizes, uint[] faceIndices)
        {
            return Create(positions, faceSizes, faceIndices, false);
        }

        /// <summary>
        /// As <see cref="Create(double[], uint[], uint[])"/>; with
        /// <paramref name="allowRepeatedVertices"/>, faces that name a vertex more
        /// than once (0 1 1 2) are accepted, and subdivision treats them as
        /// OpenSubdiv does, as non-manifold topology.
        /// </summary>
        public static WeftMesh Create(double[] positions, uint[] faceSizes, uint[] faceIndices, bool allowRepeatedVertices)
        {
            if (positions == null) throw new ArgumentNullException("positions");
            if (faceSizes == null) throw new ArgumentNullException("faceSizes");
            if (faceIndices == null) throw new ArgumentNullException("faceIndices");
            if (positions.Length % 3 != 0)
            {
                throw new WeftException(
                    WeftStatus.CountMismatch,
                    "positions holds " + positions.Length + " doubles, which is not 3 per vertex");
            }
            WeftMeshHandle created;
            uint status = NativeMethods.weft_mesh_new_ex(
                positions, (UIntPtr)(positions.Length / 3),
                faceSizes, (UIntPtr)faceSizes.Length,
                faceIndices, (UIntPtr)faceIndices.Length,
                allowRepeatedVertices ? NativeConstants.MeshAllowRepeatedVertices : 0u,
                out created);
            return FromCall(status, created);
        }

        /// <summary>An export that makes a mesh from a mesh and counts something it did.</summary>
        internal delegate uint CountingCall(WeftMeshHandle mesh, out WeftMeshHandle result, out UIntPtr count);

        /// <summary>Runs a <see cref="CountingCall"/>: the new mesh, and the count in <paramref name="count"/>.</summary>
        internal static WeftMesh FromCountingCall(CountingCall call, WeftMesh mesh, out int count)
        {
            WeftMeshHandle result;
            UIntPtr counted;
            uint status = call(Arguments.Mesh(mesh, "mesh"), out result, out counted);
            WeftMesh made = FromCall(status, result);
            count = Arguments.ToInt(counted);
            return made;
        }

        /// <summary>
        /// Wraps the handle an operation produced, or disposes it and throws
        /// when the call failed.
        /// </summary>
        internal static WeftMesh FromCall(uint status, WeftMeshHandle created)
        {
            if (status != (uint)WeftStatus.Ok)
            {
                string message = WeftException.LastErrorMessage();
                if (created != null)
                {
                    created.Dispose();
                }
                throw new WeftException((WeftStatus)status, message);
            }
            return new WeftMesh(created);
        }

        /// <summary>The library's version, such as "0.1.0".</summary>
        public static string LibraryVersion
        {
            get
            {
                NativeLibraryLoader.EnsureLoaded();
                return Utf8.FromNative(NativeMethods.weft_version());
            }
        }

        /// <summary>The native handle, for wrapper methods; refused after Dispose.</summary>
        internal WeftMeshHandle Handle
        {
            get
            {
                if (handle.IsClosed || handle.IsInvalid)
                {
                    throw new ObjectDisposedException("WeftMesh", "The mesh was disposed and its native memory freed.");
                }
                return handle;
            }
        }

        /// <summary>True once <see cref="Dispose"/> has run.</summary>
        public bool IsDisposed
        {
            get { return handle.IsClosed || handle.IsInvalid; }
        }

        /// <summary>Number of vertices.</summary>
        public int VertexCount
        {
            get { return ToInt(NativeMethods.weft_mesh_vertex_count(Handle)); }
        }

        /// <summary>Number of faces.</summary>
        public int FaceCount
        {
            get { return ToInt(NativeMethods.weft_mesh_face_count(Handle)); }
        }

        /// <summary>Number of face corners (the sum of the face sizes).</summary>
        public int IndexCount
        {
            get { return ToInt(NativeMethods.weft_mesh_index_count(Handle)); }
        }

        /// <summary>A copy of the positions, 3 doubles per vertex.</summary>
        public double[] GetPositions()
        {
            var positions = new double[checked(3 * VertexCount)];
            WeftException.Check(NativeMethods.weft_mesh_copy_positions(Handle, positions, (UIntPtr)positions.Length));
            return positions;
        }

        /// <summary>A copy of the face sizes, one per face.</summary>
        public uint[] GetFaceSizes()
        {
            uint[] sizes;
            uint[] indices;
            GetFaces(out sizes, out indices);
            return sizes;
        }

        /// <summary>A copy of the face indices, the faces one after another.</summary>
        public uint[] GetFaceIndices()
        {
            uint[] sizes;
            uint[] indices;
            GetFaces(out sizes, out indices);
            return indices;
        }

        /// <summary>Copies the face sizes and indices in one call.</summary>
        public void GetFaces(out uint[] faceSizes, out uint[] faceIndices)
        {
            WeftMeshHandle h = Handle;
            var sizes = new uint[ToInt(NativeMethods.weft_mesh_face_count(h))];
            var indices = new uint[ToInt(NativeMethods.weft_mesh_index_count(h))];
            WeftException.Check(NativeMethods.weft_mesh_copy_faces(
                h, sizes, (UIntPtr)sizes.Length, indices, (UIntPtr)indices.Length));
            faceSizes = sizes;
            faceIndices = indices;
        }

        /// <summary>Counts and flags of the mesh's topology.</summary>
        public WeftMeshInfo Info()
        {
            NativeMeshInfo raw;
            WeftException.Check(NativeMethods.weft_mesh_info(Handle, out raw));
            return new WeftMeshInfo
            {
                VertexCount = (long)raw.VertexCount.ToUInt64(),
                EdgeCount = (long)raw.EdgeCount.ToUInt64(),
                FaceCount = (long)raw.FaceCount.ToUInt64(),
                NakedEdgeCount = (long)raw.NakedEdgeCount.ToUInt64(),
                NonManifoldEdgeCount = (long)raw.NonManifoldEdgeCount.ToUInt64(),
                NonManifoldVertexCount = (long)raw.NonManifoldVertexCount.ToUInt64(),
                ComponentCount = (long)raw.ComponentCount.ToUInt64(),
                IsClosed = raw.IsClosed,
                IsOrientable = raw.IsOrientable,
                IsOriented = raw.IsOriented,
            };
        }

        /// <summary>Frees the native mesh now; later calls are ignored.</summary>
        public void Dispose()
        {
            handle.Dispose();
        }

        private static int ToInt(UIntPtr count)
        {
            return checked((int)count.ToUInt64());
        }
    }
}
