using System;

namespace Weft
{
    /// <summary>
    /// Joining, welding, T-nodes, culling, orientation, normals, planarity and
    /// naked boundaries. Meshes passed in stay owned by the caller; new ones
    /// are the caller's to dispose; failures raise a <see cref="WeftException"/>.
    /// </summary>
    public static class Mending
    {
        /// <summary>The weld tolerance that suits most models (WEFT_DEFAULT_WELD_TOLERANCE).</summary>
        public const double DefaultWeldTolerance = NativeConstants.DefaultWeldTolerance;

        static Mending()
        {
            NativeLibraryLoader.EnsureLoaded();
        }

        /// <summary>
        /// For each point (x, y, z per point), the nearest vertex of <paramref name="mesh"/>
        /// within <paramref name="tolerance"/> (the lower index on a tie).
        /// </summary>
        /// <exception cref="WeftException">A point with no vertex in reach (the message names its index and coordinates), or a bad tolerance.</exception>
        public static uint[] MatchPointsToVertices(WeftMesh mesh, double[] points, double tolerance)
        {
            WeftMeshHandle handle = Arguments.Mesh(mesh, "mesh");
            Arguments.NotNull(points, "points");
            if (points.Length % 3 != 0) throw new WeftException(WeftStatus.CountMismatch, "points holds " + points.Length + " doubles, not 3 per point");
            var vertices = new uint[points.Length / 3];
            WeftException.Check(NativeMethods.weft_match_points_to_vertices(handle, (UIntPtr)vertices.Length, points, tolerance, vertices));
            return vertices;
        }

        /// <summary>
        /// For each line (start x, y, z, end x, y, z), the two vertices of the edge of
        /// <paramref name="mesh"/> whose ends lie within <paramref name="tolerance"/> of the
        /// line's, the one at its start first.
        /// </summary>
        /// <exception cref="WeftException">A line that matches no edge (the message names its index, its ends and which end found no vertex), or a bad tolerance.</exception>
        public static uint[] MatchLinesToEdges(WeftMesh mesh, double[] lines, double tolerance)
        {
            WeftMeshHandle handle = Arguments.Mesh(mesh, "mesh");
            Arguments.NotNull(lines, "lines");
            if (lines.Length % 6 != 0) throw new WeftException(WeftStatus.CountMismatch, "lines holds " + lines.Length + " doubles, not 6 per line");
            var pairs = new uint[lines.Length / 3];
            WeftException.Check(NativeMethods.weft_match_lines_to_edges(handle, (UIntPtr)(lines.Length / 6), lines, tolerance, pairs));
            return pairs;
        }

        /// <summary>Concatenates meshes in order, offsetting each one's indices; no mesh gives the empty mesh.</summary>
        public static WeftMesh Join(params WeftMesh[] meshes)
        {
            Arguments.NotNull(meshes, "meshes");
            var handles = new WeftMeshHandle[meshes.Length];
            var raw = new IntPtr[meshes.Length];
            var added = new bool[meshes.Length];
            try
            {
                for (int i = 0; i < meshes.Length; i++)
                {
                    if (meshes[i] == null) throw new ArgumentNullException("meshes", "mesh " + i + " is null");
                    handles[i] = meshes[i].Handle;
                    // Keeps each native mesh alive while C holds the raw pointer.
                    handles[i].DangerousAddRef(ref added[i]);
                    raw[i] = handles[i].DangerousGetHandle();
                }
                WeftMeshHandle result;
                uint status = NativeMethods.weft_join(raw, (UIntPtr)raw.Length, out result);
                return WeftMesh.FromCall(status, result);
            }
            finally
            {
                for (int i = 0; i < meshes.Length; i++)
                {
                    if (added[i]) handles[i].DangerousRelease();
                }
            }
        }

        /// <summary>
        /// Merges vertices at most <paramref name="tolerance"/> apart (transitively);
        /// faces drop repeated corners, faces with fewer than 3 are removed,
        /// unused vertices are left out. <paramref name="report"/> says what changed.
        /// </summary>
        public static WeftMesh Weld(WeftMesh mesh, double tolerance, out WeftWeldReport report)
        {
            WeftMeshHandle result;
            uint status = NativeMethods.weft_weld(Arguments.Mesh(mesh, "mesh"), tolerance, out result, out report);
            return WeftMesh.FromCall(status, result);
        }

        /// <summary>Welds as <see cref="Weld(WeftMesh, double, out WeftWeldReport)"/> without the report.</summary>
        public static WeftMesh Weld(WeftMesh mesh, double tolerance)
        {
            WeftWeldReport report;
            return Weld(mesh, tolerance, out report);
        }

        /// <summary>The vertices lying within <paramref name="tolerance"/> of the inside of another face's naked edge, sorted by face, edge and parameter.</summary>
        public static WeftTNode[] FindTNodes(WeftMesh mesh, double tolerance)
        {
            WeftMeshHandle h = Arguments.Mesh(mesh, "mesh");
            UIntPtr count;
            WeftException.Check(NativeMethods.weft_find_t_nodes(h, tolerance, null, UIntPtr.Zero, out count));
            var nodes = new WeftTNode[Arguments.ToInt(count)];
            if (nodes.Length == 0) return nodes;
            WeftException.Check(NativeMethods.weft_find_t_nodes(h, tolerance, nodes, (UIntPtr)nodes.Length, out count));
            return nodes;
        }

        /// <summary>Inserts each T-node into the edge it lies on; <paramref name="inserted"/> counts the insertions.</summary>
        public static WeftMesh RepairTNodes(WeftMesh mesh, double tolerance, out int inserted)
        {
            WeftMeshHandle result;
            UIntPtr count;
            uint status = NativeMethods.weft_repair_t_nodes(Arguments.Mesh(mesh, "mesh"), tolerance, out result, out count);
            WeftMesh repaired = WeftMesh.FromCall(status, result);
            inserted = Arguments.ToInt(count);
            return repaired;
        }

        /// <summary>Removes every face that has a twin over the same vertices (all copies go); <paramref name="removed"/> counts them.</summary>
        public static WeftMesh CullAdjacent(WeftMesh mesh, out int removed)
        {
            return WeftMesh.FromCountingCall(NativeMethods.weft_cull_adjacent, mesh, out removed);
        }

        /// <summary>Gives each piece one winding, flipping the fewest faces, closed pieces facing out; <paramref name="flipped"/> counts the reversed faces.</summary>
        public static WeftMesh UnifyOrientation(WeftMesh mesh, out int flipped)
        {
            return WeftMesh.FromCountingCall(NativeMethods.weft_unify_orientation, mesh, out flipped);
        }

        /// <summary>
        /// Unifies every piece and turns each closed one to enclose a positive
        /// volume; <paramref name="report"/> counts the pieces found, turned,
        /// left open and not orientable. Weld STL triangles first.
        /// </summary>
        public static WeftMesh OrientOutward(WeftMesh mesh, out WeftOrientReport report)
        {
            WeftMeshHandle result;
            uint status = NativeMethods.weft_orient_outward(Arguments.Mesh(mesh, "mesh"), out result, out report);
            return WeftMesh.FromCall(status, result);
        }

        /// <summary>A weld tolerance suited to the mesh's size: a millionth of its bounding-box diagonal.</summary>
        public static double RelativeWeldTolerance(WeftMesh mesh)
        {
            var tolerance = new double[1];
            WeftException.Check(NativeMethods.weft_weld_relative_tolerance(Arguments.Mesh(mesh, "mesh"), tolerance));
            return tolerance[0];
        }

        /// <summary>How many vertices no face uses.</summary>
        public static long UnusedVertexCount(WeftMesh mesh)
        {
            return (long)NativeMethods.weft_mesh_unused_vertex_count(Arguments.Mesh(mesh, "mesh")).ToUInt64();
        }

        /// <summary>Leaves out the vertices no face uses; <paramref name="removed"/> counts them.</summary>
        public static WeftMesh RemoveUnusedVertices(WeftMesh mesh, out int removed)
        {
            return WeftMesh.FromCountingCall(NativeMethods.weft_remove_unused_vertices, mesh, out removed);
        }

        /// <summary>Reverses every face, keeping its first corner first ({a, b, c, d} becomes {a, d, c, b}).</summary>
        public static WeftMesh Flip(WeftMesh mesh)
        {
            WeftMeshHandle result;
            uint status = NativeMethods.weft_flip(Arguments.Mesh(mesh, "mesh"), out result);
            return WeftMesh.FromCall(status, result);
        }

        /// <summary>The unit normal of each face (Newell's method), x, y, z per face; (0, 0, 0) for a face without area.</summary>
        public static double[] FaceNormals(WeftMesh mesh)
        {
            WeftMeshHandle h = Arguments.Mesh(mesh, "mesh");
            var normals = new double[checked(3 * mesh.FaceCount)];
            WeftException.Check(NativeMethods.weft_face_normals(h, normals, (UIntPtr)normals.Length));
            return normals;
        }

        /// <summary>The unit normal of each vertex (face normals weighted by angle), x, y, z per vertex.</summary>
        public static double[] VertexNormals(WeftMesh mesh)
        {
            WeftMeshHandle h = Arguments.Mesh(mesh, "mesh");
            var normals = new double[checked(3 * mesh.VertexCount)];
            WeftException.Check(NativeMethods.weft_vertex_normals(h, normals, (UIntPtr)normals.Length));
            return normals;
        }

        /// <summary>Per face, the largest distance of a corner from the face's best-fit plane (0 for triangles).</summary>
        public static double[] Planarity(WeftMesh mesh)
        {
            WeftMeshHandle h = Arguments.Mesh(mesh, "mesh");
            var deviations = new double[mesh.FaceCount];
            WeftException.Check(NativeMethods.weft_planarity(h, deviations, (UIntPtr)deviations.Length));
            return deviations;
        }

        /// <summary>The naked edges chained into polylines; a closed one does not repeat its first point.</summary>
        public static PolylineSet NakedBoundaries(WeftMesh mesh)
        {
            WeftMeshHandle h = Arguments.Mesh(mesh, "mesh");
            UIntPtr pointTotal, polylineCount;
            WeftException.Check(NativeMethods.weft_naked_boundaries(
                h, null, UIntPtr.Zero, null, null, UIntPtr.Zero, out pointTotal, out polylineCount));
            var points = new double[checked(3 * Arguments.ToInt(pointTotal))];
            var counts = new UIntPtr[Arguments.ToInt(polylineCount)];
            var closed = new byte[counts.Length];
            WeftException.Check(NativeMethods.weft_naked_boundaries(
                h, points, (UIntPtr)points.Length, counts, closed, (UIntPtr)counts.Length, out pointTotal, out polylineCount));
            var set = new PolylineSet { Points = points, PointCounts = new int[counts.Length], Closed = new bool[counts.Length] };
            for (int i = 0; i < counts.Length; i++)
            {
                set.PointCounts[i] = Arguments.ToInt(counts[i]);
                set.Closed[i] = closed[i] != 0;
            }
            return set;
        }
    }
}
