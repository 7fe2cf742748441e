using System;

namespace Weft.Grasshopper
{
    /// <summary>A refined mesh as arrays: positions and the faces in both layouts.</summary>
    public sealed class RefinedArrays
    {
        /// <summary>x, y, z per refined vertex.</summary>
        public double[] Positions;
        /// <summary>Corner count of each refined face.</summary>
        public uint[] FaceSizes;
        /// <summary>The refined faces' vertex indices.</summary>
        public uint[] FaceIndices;
        /// <summary>The refined faces as Rhino stores them, converted once per topology.</summary>
        public RhinoArrays Rhino;
    }

    /// <summary>
    /// Keeps one <see cref="Refiner"/> while the cage's faces, the scheme, the
    /// levels, the naked-edge mode and any creases and corners stay the same, so that a slider moving
    /// the cage costs only <c>weft_refiner_evaluate</c>: no planning, no face
    /// conversion, and the output positions buffer is reused. A component owns
    /// one; dispose it with the component's document.
    /// </summary>
    public sealed class RefinerCache : IDisposable
    {
        private Refiner refiner;
        private uint[] cageSizes;
        private uint[] cageIndices;
        private Scheme scheme;
        private int levels;
        private NakedEdges nakedEdges;
        private SubdivisionOptions options;
        private RefinedArrays refined;

        /// <summary>True when the last <see cref="Subdivide"/> reused the refiner (only positions were evaluated).</summary>
        public bool LastReused { get; private set; }

        /// <summary>How many times a refiner was planned.</summary>
        public int PlanCount { get; private set; }

        /// <summary>
        /// Subdivides a cage given as arrays. The returned object is owned by
        /// the cache and overwritten by the next call; copy what must outlive it.
        /// </summary>
        public RefinedArrays Subdivide(double[] positions, uint[] faceSizes, uint[] faceIndices, Scheme scheme, int levels, NakedEdges nakedEdges)
        {
            return Subdivide(positions, faceSizes, faceIndices, scheme, levels, nakedEdges, null);
        }

        /// <summary>
        /// As <see cref="Subdivide(double[], uint[], uint[], Scheme, int, NakedEdges)"/>, with the
        /// naked-edge mode, creases and corners of <paramref name="options"/>: the refiner is reused
        /// while they stay the same too (compared by value).
        /// </summary>
        public RefinedArrays Subdivide(double[] positions, uint[] faceSizes, uint[] faceIndices, Scheme scheme, int levels, SubdivisionOptions options)
        {
            if (options == null) throw new ArgumentNullException("options");
            return Subdivide(positions, faceSizes, faceIndices, scheme, levels, options.NakedEdges, options);
        }

        private RefinedArrays Subdivide(double[] positions, uint[] faceSizes, uint[] faceIndices, Scheme scheme, int levels,
                                        NakedEdges nakedEdges, SubdivisionOptions options)
        {
            if (positions == null) throw new ArgumentNullException("positions");
            bool sameOptions = options == null ? this.options == null : options.SameAs(this.options);
            if (refiner != null && scheme == this.scheme && levels == this.levels && nakedEdges == this.nakedEdges && sameOptions
                && refiner.CageVertexCount * 3 == positions.Length
                && SameValues(faceSizes, cageSizes) && SameValues(faceIndices, cageIndices))
            {
                refiner.Evaluate(positions, refined.Positions);
                LastReused = true;
                return refined;
            }
            Reset();
            using (WeftMesh cage = WeftMesh.Create(positions, faceSizes, faceIndices))
            {
                Refiner planned = options == null
                    ? new Refiner(cage, scheme, levels, nakedEdges)
                    : new Refiner(cage, scheme, levels, options);
                try
                {
                    var result = new RefinedArrays();
                    using (WeftMesh mesh = planned.Mesh())
                    {
                        result.Positions = mesh.GetPositions();
                        mesh.GetFaces(out result.FaceSizes, out result.FaceIndices);
                    }
                    result.Rhino = MeshArrays.ToRhino(result.Positions, result.FaceSizes, result.FaceIndices);
                    refiner = planned;
                    refined = result;
                }
                catch
                {
                    planned.Dispose();
                    throw;
                }
            }
            cageSizes = (uint[])faceSizes.Clone();
            cageIndices = (uint[])faceIndices.Clone();
            this.scheme = scheme;
            this.levels = levels;
            this.nakedEdges = nakedEdges;
            this.options = options == null ? null : options.Clone();
            LastReused = false;
            PlanCount++;
            return refined;
        }

        /// <summary>Forgets the refiner (the next call plans again).</summary>
        public void Reset()
        {
            if (refiner != null) refiner.Dispose();
            refiner = null;
            refined = null;
            cageSizes = null;
            cageIndices = null;
            options = null;
        }

        /// <summary>Frees the native refiner.</summary>
        public void Dispose()
        {
            Reset();
        }

        private static bool SameValues(uint[] a, uint[] b)
        {
            if (a == null || b == null || a.Length != b.Length) return false;
            for (int i = 0; i < a.Length; i++)
            {
                if (a[i] != b[i]) return false;
            }
            return true;
        }
    }
}

namespace Weft.Grasshopper
{
    /// <summary>
    /// One <see cref="RefinerCache"/> per branch of a data tree (per solve
    /// iteration), so a tree of cages with different topologies does not
    /// re-plan every branch on every solution. Caches of branches the last
    /// solution no longer had are freed when it ends.
    /// </summary>
    public sealed class RefinerPool : IDisposable
    {
        private readonly System.Collections.Generic.List<RefinerCache> caches = new System.Collections.Generic.List<RefinerCache>();
        private int used;

        /// <summary>How many branch caches are alive.</summary>
        public int Count
        {
            get { return caches.Count; }
        }

        /// <summary>The cache of branch (iteration) <paramref name="branch"/>, created on first use.</summary>
        public RefinerCache For(int branch)
        {
            if (branch < 0) throw new ArgumentOutOfRangeException("branch", branch, "a branch index is 0 or more");
            while (caches.Count <= branch) caches.Add(new RefinerCache());
            used = Math.Max(used, branch + 1);
            return caches[branch];
        }

        /// <summary>Call before a solution's first branch.</summary>
        public void BeginSolution()
        {
            used = 0;
        }

        /// <summary>Call after a solution's last branch: frees the caches of branches it did not use.</summary>
        public void EndSolution()
        {
            for (int i = caches.Count - 1; i >= used; i--)
            {
                caches[i].Dispose();
                caches.RemoveAt(i);
            }
        }

        /// <summary>Frees every native refiner (the component left its document, or the document closed).</summary>
        public void Dispose()
        {
            foreach (RefinerCache cache in caches) cache.Dispose();
            caches.Clear();
            used = 0;
        }
    }
}
