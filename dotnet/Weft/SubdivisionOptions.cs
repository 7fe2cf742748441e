using System;
using System.Collections.Generic;
using System.Runtime.InteropServices;

namespace Weft
{
    /// <summary>
    /// What besides the mesh and the scheme shapes a subdivision: the
    /// naked-edge mode, the creasing rule, OpenSubdiv-style creases (a
    /// sharpness per edge, named by its two vertices) and corners (a
    /// sharpness per vertex), holes (faces left out of the result) and the
    /// triangle weights. A new instance is Weft's default: fixed naked
    /// edges, uniform creasing, nothing creased, no hole.
    /// </summary>
    /// <remarks>
    /// Sharpness is 0 or more: 0 is smooth, a value s below
    /// <see cref="SharpnessInfinite"/> keeps the edge or vertex sharp for s
    /// levels before it softens, and <see cref="SharpnessInfinite"/> or more
    /// (or <see cref="double.PositiveInfinity"/>) never softens: a hard crease
    /// follows the cage's polyline refined as a B-spline, a hard corner stays
    /// where it is. The library checks the values and the edges when the
    /// options are used.
    /// </remarks>
    public sealed class SubdivisionOptions
    {
        /// <summary>The sharpness at and above which a crease or corner never softens (WEFT_SHARPNESS_INFINITE).</summary>
        public const double SharpnessInfinite = NativeConstants.SharpnessInfinite;

        private readonly List<uint> creasePairs = new List<uint>();
        private readonly List<double> creaseSharpness = new List<double>();
        private readonly List<uint> cornerVertices = new List<uint>();
        private readonly List<double> cornerSharpness = new List<double>();
        private readonly List<uint> holes = new List<uint>();

        /// <summary>Options with the given naked-edge mode, uniform creasing and nothing creased.</summary>
        public SubdivisionOptions(NakedEdges nakedEdges)
        {
            NakedEdges = nakedEdges;
        }

        /// <summary>Options with fixed naked edges, uniform creasing and nothing creased.</summary>
        public SubdivisionOptions()
            : this(NakedEdges.Fixed)
        {
        }

        /// <summary>How naked (boundary) edges are treated.</summary>
        public NakedEdges NakedEdges { get; set; }

        /// <summary>How semi-sharp creases soften.</summary>
        public Creasing Creasing { get; set; }

        /// <summary>Catmull-Clark's weights at triangles (Loop ignores it).</summary>
        public TriangleRule Triangles { get; set; }

        /// <summary>Number of hole faces.</summary>
        public int HoleCount
        {
            get { return holes.Count; }
        }

        /// <summary>
        /// Leaves face <paramref name="face"/> of the cage out of the result
        /// (OpenSubdiv's hole tag): it leaves no faces, but its vertices and
        /// edges still shape its neighbours; returns this for chaining.
        /// </summary>
        public SubdivisionOptions AddHole(int face)
        {
            holes.Add(Arguments.Unsigned(face, "face"));
            return this;
        }

        /// <summary>The hole faces (a copy).</summary>
        public uint[] GetHoles()
        {
            return holes.ToArray();
        }

        /// <summary>Number of creased edges.</summary>
        public int CreaseCount
        {
            get { return creaseSharpness.Count; }
        }

        /// <summary>Number of sharp vertices.</summary>
        public int CornerCount
        {
            get { return cornerSharpness.Count; }
        }

        /// <summary>Creases the edge between vertices <paramref name="a"/> and <paramref name="b"/> (either order); returns this for chaining.</summary>
        public SubdivisionOptions AddCrease(int a, int b, double sharpness)
        {
            creasePairs.Add(Arguments.Unsigned(a, "a"));
            creasePairs.Add(Arguments.Unsigned(b, "b"));
            creaseSharpness.Add(sharpness);
            return this;
        }

        /// <summary>
        /// Creases every edge of <paramref name="vertexPairs"/> (two vertex
        /// indices per edge, as <see cref="Subdivision.CreaseEdgesFromMesh(WeftMesh, double, out uint[])"/>
        /// gives them) with one sharpness; returns this for chaining.
        /// </summary>
        /// <exception cref="WeftException"><see cref="WeftStatus.CountMismatch"/> when the length is odd.</exception>
        public SubdivisionOptions AddCreases(uint[] vertexPairs, double sharpness)
        {
            Arguments.NotNull(vertexPairs, "vertexPairs");
            if (vertexPairs.Length % 2 != 0)
            {
                throw new WeftException(WeftStatus.CountMismatch,
                    "vertexPairs holds " + vertexPairs.Length + " indices, which is not 2 per crease");
            }
            for (int i = 0; i < vertexPairs.Length; i += 2)
            {
                creasePairs.Add(vertexPairs[i]);
                creasePairs.Add(vertexPairs[i + 1]);
                creaseSharpness.Add(sharpness);
            }
            return this;
        }

        /// <summary>Makes vertex <paramref name="vertex"/> a corner of the given sharpness; returns this for chaining.</summary>
        public SubdivisionOptions AddCorner(int vertex, double sharpness)
        {
            cornerVertices.Add(Arguments.Unsigned(vertex, "vertex"));
            cornerSharpness.Add(sharpness);
            return this;
        }

        /// <summary>The creased edges' vertices, two per crease (a copy).</summary>
        public uint[] GetCreaseVertexPairs()
        {
            return creasePairs.ToArray();
        }

        /// <summary>The creases' sharpness values (a copy).</summary>
        public double[] GetCreaseSharpness()
        {
            return creaseSharpness.ToArray();
        }

        /// <summary>The corner vertices (a copy).</summary>
        public uint[] GetCornerVertices()
        {
            return cornerVertices.ToArray();
        }

        /// <summary>The corners' sharpness values (a copy).</summary>
        public double[] GetCornerSharpness()
        {
            return cornerSharpness.ToArray();
        }

        /// <summary>Removes every crease, corner and hole.</summary>
        public void Clear()
        {
            creasePairs.Clear();
            creaseSharpness.Clear();
            cornerVertices.Clear();
            cornerSharpness.Clear();
            holes.Clear();
        }

        /// <summary>A copy that later changes to this one do not affect.</summary>
        public SubdivisionOptions Clone()
        {
            var copy = new SubdivisionOptions(NakedEdges) { Creasing = Creasing, Triangles = Triangles };
            copy.holes.AddRange(holes);
            copy.creasePairs.AddRange(creasePairs);
            copy.creaseSharpness.AddRange(creaseSharpness);
            copy.cornerVertices.AddRange(cornerVertices);
            copy.cornerSharpness.AddRange(cornerSharpness);
            return copy;
        }

        /// <summary>True when <paramref name="other"/> has the same mode, rules, creases, corners and holes in the same order (sharpness compared bit for bit).</summary>
        public bool SameAs(SubdivisionOptions other)
        {
            if (other == null) return false;
            return NakedEdges == other.NakedEdges && Creasing == other.Creasing && Triangles == other.Triangles
                && Same(holes, other.holes) && Same(creasePairs, other.creasePairs) && Same(creaseSharpness, other.creaseSharpness)
                && Same(cornerVertices, other.cornerVertices) && Same(cornerSharpness, other.cornerSharpness);
        }

        private static bool Same<T>(List<T> a, List<T> b)
        {
            if (a.Count != b.Count) return false;
            EqualityComparer<T> equal = EqualityComparer<T>.Default;
            for (int i = 0; i < a.Count; i++)
            {
                if (!equal.Equals(a[i], b[i])) return false;
            }
            return true;
        }

        /// <summary>
        /// Pins the arrays of <paramref name="options"/> (null: the defaults)
        /// and fills the native struct for <paramref name="scheme"/>; dispose
        /// the result right after the native call.
        /// </summary>
        internal static Pinned Pin(SubdivisionOptions options, Scheme scheme)
        {
            return new Pinned(options ?? new SubdivisionOptions(), scheme);
        }

        /// <summary>An export that takes a mesh, the options and a level count and makes one native object.</summary>
        internal delegate uint OptionsCall<TResult>(WeftMeshHandle mesh, ref NativeSubdivisionOptions options, uint levels, out TResult result);

        /// <summary>
        /// Checks <paramref name="mesh"/> (named <paramref name="meshName"/> in errors) and
        /// <paramref name="levels"/>, then makes <paramref name="call"/> with the options pinned for it.
        /// </summary>
        internal static uint Call<TResult>(OptionsCall<TResult> call, WeftMesh mesh, string meshName, SubdivisionOptions options,
                                           Scheme scheme, int levels, out TResult result)
        {
            WeftMeshHandle handle = Arguments.Mesh(mesh, meshName);
            uint steps = Arguments.Unsigned(levels, "levels");
            using (Pinned pinned = Pin(options, scheme))
            {
                NativeSubdivisionOptions native = pinned.Native;
                return call(handle, ref native, steps, out result);
            }
        }

        /// <summary>The native struct over pinned copies of the arrays, valid until disposed.</summary>
        internal sealed class Pinned : IDisposable
        {
            private readonly GCHandle[] handles = new GCHandle[5];

            /// <summary>The struct to pass by reference.</summary>
            internal NativeSubdivisionOptions Native;

            internal Pinned(SubdivisionOptions options, Scheme scheme)
            {
                Native.Scheme = (uint)scheme;
                Native.NakedEdges = (uint)options.NakedEdges;
                Native.Creasing = (uint)options.Creasing;
                Native.Triangles = (uint)options.Triangles;
                Native.CreaseCount = (UIntPtr)options.creaseSharpness.Count;
                Native.CornerCount = (UIntPtr)options.cornerSharpness.Count;
                Native.HoleCount = (UIntPtr)options.holes.Count;
                try
                {
                    Native.CreaseVertexPairs = PinArray(0, options.creasePairs.ToArray());
                    Native.CreaseSharpness = PinArray(1, options.creaseSharpness.ToArray());
                    Native.CornerVertices = PinArray(2, options.cornerVertices.ToArray());
                    Native.CornerSharpness = PinArray(3, options.cornerSharpness.ToArray());
                    Native.HoleFaces = PinArray(4, options.holes.ToArray());
                }
                catch
                {
                    Dispose();
                    throw;
                }
            }

            // An empty array is passed as NULL, which the library accepts for a count of 0.
            private IntPtr PinArray(int slot, Array values)
            {
                if (values.Length == 0) return IntPtr.Zero;
                handles[slot] = GCHandle.Alloc(values, GCHandleType.Pinned);
                return handles[slot].AddrOfPinnedObject();
            }

            /// <summary>Unpins the arrays.</summary>
            public void Dispose()
            {
                for (int i = 0; i < handles.Length; i++)
                {
                    if (handles[i].IsAllocated) handles[i].Free();
                }
            }
        }
    }

    /// <summary>The sizes of a subdivided mesh (see <see cref="Subdivision.Counts(WeftMesh, Scheme, int, SubdivisionOptions)"/>).</summary>
    public struct SubdivisionCounts
    {
        /// <summary>Refined vertices.</summary>
        public int VertexCount;
        /// <summary>Refined faces.</summary>
        public int FaceCount;
        /// <summary>Refined face corners (the sum of the face sizes).</summary>
        public int IndexCount;
    }

    /// <summary>Points on the limit surface and its unit normals there (see <see cref="Subdivision.SubdivideLimit(WeftMesh, Scheme, int, SubdivisionOptions)"/>).</summary>
    public sealed class LimitSurface
    {
        /// <summary>x, y, z per refined vertex, projected onto the limit surface.</summary>
        public double[] Positions { get; internal set; }
        /// <summary>x, y, z of the unit normal per refined vertex (outward for counter-clockwise faces; zero where undefined).</summary>
        public double[] Normals { get; internal set; }
    }
}
