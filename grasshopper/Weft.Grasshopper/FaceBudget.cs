using System;

namespace Weft.Grasshopper
{
    /// <summary>
    /// Refuses a subdivision whose output would pass <see cref="MaxFaces"/>
    /// faces before any work is done: Grasshopper solves on Rhino's UI thread,
    /// and .NET Framework arrays stop at 2 GB, so a level too many would freeze
    /// Rhino or fail late. The counts come from <c>weft_subdivision_counts</c>.
    /// </summary>
    public static class FaceBudget
    {
        /// <summary>The most output faces a subdivision component makes: 4 million (about 64 MB of Rhino faces).</summary>
        public const long MaxFaces = 4000000;

        /// <summary>
        /// Throws a <see cref="WeftException"/> naming the highest level that fits when
        /// <paramref name="levels"/> steps of <paramref name="scheme"/> on the cage would make
        /// more than <paramref name="maxFaces"/> faces.
        /// </summary>
        public static void Check(WeftMesh cage, Scheme scheme, int levels, long maxFaces)
        {
            Check(level => FacesAt(cage, scheme, level), levels, maxFaces);
        }

        /// <summary>As <see cref="Check(WeftMesh, Scheme, int, long)"/> with the face count of each level given.</summary>
        public static void Check(Func<int, long> facesAt, int levels, long maxFaces)
        {
            long faces = facesAt(levels);
            if (faces <= maxFaces) return;
            int fits = levels - 1;
            while (fits > 0 && facesAt(fits) > maxFaces) fits--;
            throw new WeftException(WeftStatus.ResultTooLarge,
                "L = " + levels + " would make " + (faces == long.MaxValue ? "more than 2^63" : faces.ToString("N0")) + " faces, above the budget of "
                + maxFaces.ToString("N0") + "; L = " + fits + " is the highest level that fits");
        }

        /// <summary>The face count after <paramref name="level"/> steps, or long.MaxValue when it overflows.</summary>
        public static long FacesAt(WeftMesh cage, Scheme scheme, int level)
        {
            try
            {
                return Subdivision.Counts(cage, scheme, level).FaceCount;
            }
            catch (OverflowException)
            {
                return long.MaxValue;
            }
            catch (WeftException e)
            {
                if (e.Status == WeftStatus.ResultTooLarge) return long.MaxValue;
                throw;
            }
        }
    }

    /// <summary>The tolerance a component uses when no Rhino document gives one.</summary>
    public static class Tolerances
    {
        /// <summary>Used without an active document (Rhino.Compute, headless Rhino): 0.001 model units.</summary>
        public const double Default = 0.001;

        /// <summary>The document's tolerance when it is a positive number, else <see cref="Default"/> (<paramref name="fellBack"/> says which).</summary>
        public static double Choose(double documentTolerance, out bool fellBack)
        {
            fellBack = !(documentTolerance > 0) || double.IsInfinity(documentTolerance);
            return fellBack ? Default : documentTolerance;
        }
    }
}
