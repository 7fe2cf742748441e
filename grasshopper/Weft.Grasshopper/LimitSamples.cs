namespace Weft.Grasshopper
{
    /// <summary>
    /// Evaluate Limit Surface's inputs F, U, V as the library's samples, and its
    /// derivatives as unit normals; plain arrays, so they run in tests without Rhino.
    /// </summary>
    public static class LimitSamples
    {
        /// <summary>
        /// One sample per U and V: the face of F (one for all, or one per sample) and
        /// the (u, v) pair. Unequal lengths and negative faces are refused, naming them.
        /// </summary>
        public static void Build(int[] faces, double[] u, double[] v, out uint[] sampleFaces, out double[] uvs)
        {
            if (u.Length != v.Length)
            {
                throw new WeftException(WeftStatus.CountMismatch, "U has " + u.Length + " values and V " + v.Length + "; give one V per U");
            }
            if (faces.Length != 1 && faces.Length != u.Length)
            {
                throw new WeftException(WeftStatus.CountMismatch,
                    "F has " + faces.Length + " faces for " + u.Length + " samples; give one face for all or one per sample");
            }
            int count = u.Length;
            sampleFaces = new uint[count];
            uvs = new double[2 * count];
            for (int i = 0; i < count; i++)
            {
                int face = faces[faces.Length == 1 ? 0 : i];
                if (face < 0) throw new WeftException(WeftStatus.IndexOutOfRange, "F[" + (faces.Length == 1 ? 0 : i) + "] is " + face + "; faces are numbered from 0");
                sampleFaces[i] = (uint)face;
                uvs[2 * i] = u[i];
                uvs[2 * i + 1] = v[i];
            }
        }
    }
}
