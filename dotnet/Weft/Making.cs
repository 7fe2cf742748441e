using System;
using System.Runtime.InteropServices;

namespace Weft
{
    /// <summary>
    /// Meshes made from points, grids and parameters: Delaunay, Voronoi,
    /// mesh from grid, stellate and the primitives (Weaverbird's Define panel).
    /// Each returns a new object the caller disposes; failures raise a
    /// <see cref="WeftException"/>.
    /// </summary>
    public static class Making
    {
        static Making()
        {
            NativeLibraryLoader.EnsureLoaded();
        }

        /// <summary>
        /// Delaunay triangulation of points (x, y, z each) projected onto
        /// <paramref name="plane"/> (null: world XY); the vertices are the
        /// distinct original points, the triangles face the plane's normal.
        /// <paramref name="merged"/> counts points merged into an earlier one.
        /// </summary>
        public static WeftMesh Delaunay(double[] points, WeftPlane? plane, out int merged)
        {
            UIntPtr count = Arguments.Triples(points, "points");
            WeftMeshHandle result;
            UIntPtr mergedCount;
            uint status = NativeMethods.weft_delaunay(points, count, Arguments.Plane(plane), out result, out mergedCount);
            WeftMesh mesh = WeftMesh.FromCall(status, result);
            merged = Arguments.ToInt(mergedCount);
            return mesh;
        }

        /// <summary>Delaunay triangulation on the world XY plane.</summary>
        public static WeftMesh Delaunay(double[] points)
        {
            int merged;
            return Delaunay(points, null, out merged);
        }

        /// <summary>
        /// The Voronoi cell of each point on <paramref name="plane"/> (null:
        /// world XY), clipped to <paramref name="boundary"/> (corners of a simple
        /// polygon, x, y, z each; null or empty: the points' bounding rectangle
        /// grown by 10 %) and, when <paramref name="radius"/> is positive, to a
        /// circle of that radius around the point.
        /// </summary>
        public static VoronoiCells Voronoi(double[] points, WeftPlane? plane, double[] boundary, double radius)
        {
            UIntPtr count = Arguments.Triples(points, "points");
            UIntPtr boundaryCount = boundary == null ? UIntPtr.Zero : Arguments.Triples(boundary, "boundary");
            WeftCellsHandle cells;
            uint status = NativeMethods.weft_voronoi(points, count, Arguments.Plane(plane), boundary, boundaryCount, radius, out cells);
            if (status != (uint)WeftStatus.Ok)
            {
                string message = WeftException.LastErrorMessage();
                if (cells != null) cells.Dispose();
                throw new WeftException((WeftStatus)status, message);
            }
            return new VoronoiCells(cells);
        }

        /// <summary>
        /// Connects a <paramref name="uCount"/> × <paramref name="vCount"/> grid
        /// of points (u runs fastest) into quads, or triangles along the
        /// shorter diagonal; a closed direction wraps around.
        /// </summary>
        public static WeftMesh MeshFromGrid(double[] points, int uCount, int vCount, bool closedU, bool closedV, bool triangulate)
        {
            UIntPtr count = Arguments.Triples(points, "points");
            WeftMeshHandle result;
            uint status = NativeMethods.weft_mesh_from_grid(
                points, count, Arguments.Size(uCount, "uCount"), Arguments.Size(vCount, "vCount"),
                closedU, closedV, triangulate, out result);
            return WeftMesh.FromCall(status, result);
        }

        /// <summary>
        /// Raises a pyramid on every face (Stellate/Cumulation): the apex of
        /// face f is vertex <c>VertexCount + f</c>, at the centroid moved along
        /// the normal by one height for all faces or one per face.
        /// </summary>
        public static WeftMesh Stellate(WeftMesh mesh, params double[] heights)
        {
            WeftMeshHandle h = Arguments.Mesh(mesh, "mesh");
            Arguments.NotNull(heights, "heights");
            WeftMeshHandle result;
            uint status = NativeMethods.weft_stellate(h, heights, (UIntPtr)heights.Length, out result);
            return WeftMesh.FromCall(status, result);
        }

        /// <summary>A flat <paramref name="sizeX"/> × <paramref name="sizeY"/> rectangle of quads on XY, centred on the origin, facing +z.</summary>
        public static WeftMesh PlaneGrid(double sizeX, double sizeY, int uCount, int vCount)
        {
            WeftMeshHandle result;
            uint status = NativeMethods.weft_plane_grid(sizeX, sizeY, Arguments.Size(uCount, "uCount"), Arguments.Size(vCount, "vCount"), out result);
            return WeftMesh.FromCall(status, result);
        }

        /// <summary>A closed, welded box centred on the origin, its sides divided into quads.</summary>
        public static WeftMesh Box(double sizeX, double sizeY, double sizeZ, int uCount, int vCount, int wCount)
        {
            WeftMeshHandle result;
            uint status = NativeMethods.weft_box(
                sizeX, sizeY, sizeZ, Arguments.Size(uCount, "uCount"), Arguments.Size(vCount, "vCount"), Arguments.Size(wCount, "wCount"), out result);
            return WeftMesh.FromCall(status, result);
        }

        /// <summary>A sphere centred on the origin: <paramref name="uCount"/> segments around z (at least 3), <paramref name="vCount"/> pole to pole (at least 2).</summary>
        public static WeftMesh UvSphere(double radius, int uCount, int vCount)
        {
            WeftMeshHandle result;
            uint status = NativeMethods.weft_uv_sphere(radius, Arguments.Size(uCount, "uCount"), Arguments.Size(vCount, "vCount"), out result);
            return WeftMesh.FromCall(status, result);
        }

        /// <summary>A platonic solid centred on the origin, its vertices on the sphere of <paramref name="radius"/>.</summary>
        public static WeftMesh Platonic(PlatonicSolid kind, double radius)
        {
            WeftMeshHandle result;
            uint status = NativeMethods.weft_platonic((uint)kind, radius, out result);
            return WeftMesh.FromCall(status, result);
        }

        /// <summary>A prism, antiprism, pyramid or dipyramid on a regular n-gon about z, centred on the origin.</summary>
        public static WeftMesh Sided(SidedSolid kind, int sides, double radius, double height)
        {
            WeftMeshHandle result;
            uint status = NativeMethods.weft_sided_solid((uint)kind, Arguments.Size(sides, "sides"), radius, height, out result);
            return WeftMesh.FromCall(status, result);
        }
    }

    /// <summary>
    /// Voronoi cells, one polygon per input point (empty for a point outside
    /// the boundary or repeating an earlier one), owned by the native library.
    /// </summary>
    public sealed class VoronoiCells : NativeObject<WeftCellsHandle>
    {
        internal VoronoiCells(WeftCellsHandle handle)
            : base(handle, "The cells were disposed and their native memory freed.")
        {
        }

        /// <summary>Number of cells (the number of input points).</summary>
        public int Count
        {
            get { return Arguments.ToInt(NativeMethods.weft_cells_count(Handle)); }
        }

        /// <summary>Number of corners of all cells together.</summary>
        public int CornerCount
        {
            get { return Arguments.ToInt(NativeMethods.weft_cells_corner_count(Handle)); }
        }

        /// <summary>The corner count of each cell (0 for an empty one), read from the native buffer.</summary>
        public uint[] GetSizes()
        {
            WeftCellsHandle h = Handle;
            var sizes = new uint[Count];
            if (sizes.Length == 0) return sizes;
            var raw = new int[sizes.Length];
            Marshal.Copy(NativeMethods.weft_cells_sizes(h), raw, 0, raw.Length);
            Buffer.BlockCopy(raw, 0, sizes, 0, 4 * raw.Length);
            GC.KeepAlive(this);
            return sizes;
        }

        /// <summary>The corners of all cells, x, y, z each, cell after cell, read from the native buffer.</summary>
        public double[] GetCorners()
        {
            WeftCellsHandle h = Handle;
            var corners = new double[checked(3 * CornerCount)];
            if (corners.Length == 0) return corners;
            Marshal.Copy(NativeMethods.weft_cells_corners(h), corners, 0, corners.Length);
            GC.KeepAlive(this);
            return corners;
        }

        /// <summary>
        /// Copies the cells into caller buffers (<see cref="Count"/> sizes,
        /// 3 × <see cref="CornerCount"/> doubles); too small a buffer fails
        /// with <see cref="WeftStatus.BufferTooSmall"/> and nothing is written.
        /// </summary>
        public void CopyTo(uint[] sizes, double[] corners)
        {
            Arguments.NotNull(sizes, "sizes");
            Arguments.NotNull(corners, "corners");
            WeftException.Check(NativeMethods.weft_cells_copy(Handle, sizes, (UIntPtr)sizes.Length, corners, (UIntPtr)corners.Length));
        }

        /// <summary>A mesh with one n-gon face per non-empty cell; the cells share no vertices (weld to join them).</summary>
        public WeftMesh ToMesh()
        {
            WeftMeshHandle result;
            uint status = NativeMethods.weft_cells_to_mesh(Handle, out result);
            return WeftMesh.FromCall(status, result);
        }
    }
}
