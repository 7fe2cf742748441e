using System;
using System.Runtime.InteropServices;

namespace Weft
{
    /// <summary>
    /// A plane for <c>Making.Delaunay</c> and <see cref="Making.Voronoi"/>,
    /// laid out as <c>WeftPlane</c>: an origin and two axes, three doubles
    /// each. The axes need not be unit length or orthogonal; the normal (the
    /// front side) is x × y.
    /// </summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct WeftPlane
    {
        /// <summary>Origin x.</summary>
        public double OriginX;
        /// <summary>Origin y.</summary>
        public double OriginY;
        /// <summary>Origin z.</summary>
        public double OriginZ;
        /// <summary>The x axis (not zero), x.</summary>
        public double XAxisX;
        /// <summary>The x axis (not zero), y.</summary>
        public double XAxisY;
        /// <summary>The x axis (not zero), z.</summary>
        public double XAxisZ;
        /// <summary>The y axis (not zero or parallel to x), x.</summary>
        public double YAxisX;
        /// <summary>The y axis (not zero or parallel to x), y.</summary>
        public double YAxisY;
        /// <summary>The y axis (not zero or parallel to x), z.</summary>
        public double YAxisZ;

        /// <summary>A plane through <paramref name="origin"/> spanned by two axes (three doubles each).</summary>
        public WeftPlane(double[] origin, double[] xAxis, double[] yAxis)
        {
            if (origin == null || origin.Length != 3) throw new ArgumentException("origin must hold 3 doubles", "origin");
            if (xAxis == null || xAxis.Length != 3) throw new ArgumentException("xAxis must hold 3 doubles", "xAxis");
            if (yAxis == null || yAxis.Length != 3) throw new ArgumentException("yAxis must hold 3 doubles", "yAxis");
            OriginX = origin[0]; OriginY = origin[1]; OriginZ = origin[2];
            XAxisX = xAxis[0]; XAxisY = xAxis[1]; XAxisZ = xAxis[2];
            YAxisX = yAxis[0]; YAxisY = yAxis[1]; YAxisZ = yAxis[2];
        }

        /// <summary>The world XY plane: origin 0, x (1, 0, 0), y (0, 1, 0).</summary>
        public static WeftPlane WorldXY
        {
            get { return new WeftPlane(new double[] { 0, 0, 0 }, new double[] { 1, 0, 0 }, new double[] { 0, 1, 0 }); }
        }
    }

    /// <summary>What <see cref="Mending.Weld(WeftMesh, double, out WeftWeldReport)"/> changed, laid out as <c>WeftWeldReport</c>.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct WeftWeldReport
    {
        private UIntPtr mergedVertexCount;
        private UIntPtr removedFaceCount;
        private UIntPtr unusedVertexCount;

        /// <summary>Vertices merged into another one.</summary>
        public long MergedVertexCount { get { return (long)mergedVertexCount.ToUInt64(); } }
        /// <summary>Faces removed for having fewer than 3 distinct vertices left.</summary>
        public long RemovedFaceCount { get { return (long)removedFaceCount.ToUInt64(); } }
        /// <summary>Vertices left out because no face used them.</summary>
        public long UnusedVertexCount { get { return (long)unusedVertexCount.ToUInt64(); } }
    }

    /// <summary>What <see cref="Mending.OrientOutward"/> found and changed, laid out as <c>WeftOrientReport</c>.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct WeftOrientReport
    {
        private UIntPtr flippedFaces;
        private UIntPtr pieces;
        private UIntPtr turnedOutward;
        private UIntPtr openPieces;
        private UIntPtr nonOrientablePieces;

        /// <summary>Faces reversed.</summary>
        public long FlippedFaces { get { return (long)flippedFaces.ToUInt64(); } }
        /// <summary>Connected pieces (faces joined through shared edges).</summary>
        public long Pieces { get { return (long)pieces.ToUInt64(); } }
        /// <summary>Closed pieces that were inside out and were turned outward.</summary>
        public long TurnedOutward { get { return (long)turnedOutward.ToUInt64(); } }
        /// <summary>Pieces with a naked or non-manifold edge: unified, with no inside to face away from.</summary>
        public long OpenPieces { get { return (long)openPieces.ToUInt64(); } }
        /// <summary>Pieces no winding makes consistent (a Möbius strip).</summary>
        public long NonOrientablePieces { get { return (long)nonOrientablePieces.ToUInt64(); } }
    }

    /// <summary>
    /// A vertex lying inside another face's naked edge (see
    /// <see cref="Mending.FindTNodes"/>), laid out as <c>WeftTNode</c>.
    /// </summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct WeftTNode
    {
        /// <summary>The vertex on the edge.</summary>
        public uint Vertex;
        /// <summary>The edge's first vertex, as the face runs it.</summary>
        public uint EdgeStart;
        /// <summary>The edge's second vertex.</summary>
        public uint EdgeEnd;
        /// <summary>The face the edge belongs to.</summary>
        public uint Face;
        /// <summary>Where along the edge the vertex lies, 0 at its start, 1 at its end.</summary>
        public double Parameter;
    }

    /// <summary>Polylines as flat arrays: the points of each after one another.</summary>
    public sealed class PolylineSet
    {
        /// <summary>x, y, z per point, polyline after polyline.</summary>
        public double[] Points { get; internal set; }
        /// <summary>Number of points of each polyline.</summary>
        public int[] PointCounts { get; internal set; }
        /// <summary>Whether each polyline is closed (its first point is not repeated at the end).</summary>
        public bool[] Closed { get; internal set; }

        /// <summary>Number of polylines.</summary>
        public int Count { get { return PointCounts.Length; } }
    }
}
