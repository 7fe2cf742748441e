using System;

namespace Weft.Tests
{
    /// <summary>Named shapes built in code, and checks shared by the test classes.</summary>
    internal static class Shapes
    {
        internal static Runner T;

        /// <summary>The unit cube of <see cref="UnitCube"/>, faces wound outwards (face 0 is the bottom, facing -z).</summary>
        internal static WeftMesh Cube()
        {
            return WeftMesh.Create(UnitCube.Positions, UnitCube.Sizes, UnitCube.Indices);
        }

        /// <summary>The cube moved by (dx, 0, 0).</summary>
        internal static WeftMesh CubeAt(double dx)
        {
            var positions = (double[])UnitCube.Positions.Clone();
            for (int i = 0; i < positions.Length; i += 3) positions[i] += dx;
            return WeftMesh.Create(positions, UnitCube.Sizes, UnitCube.Indices);
        }

        /// <summary>The octahedron with vertices on the unit axes, 8 triangles wound outwards.</summary>
        internal static WeftMesh Octahedron()
        {
            double[] positions = { 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1 };
            uint[] indices =
            {
                0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4,
                2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5,
            };
            return WeftMesh.Create(positions, Repeat(3, 8), indices);
        }

        /// <summary>A 2 × 2 grid of unit quads on XY facing +z; vertex 4 is the centre, the others are on the boundary.</summary>
        internal static WeftMesh Grid(double centreZ)
        {
            double[] positions =
            {
                0, 0, 0, 1, 0, 0, 2, 0, 0,
                0, 1, 0, 1, 1, centreZ, 2, 1, 0,
                0, 2, 0, 1, 2, 0, 2, 2, 0,
            };
            uint[] indices = { 0, 1, 4, 3, 1, 2, 5, 4, 3, 4, 7, 6, 4, 5, 8, 7 };
            return WeftMesh.Create(positions, Repeat(4, 4), indices);
        }

        internal static uint[] Repeat(uint value, int count)
        {
            var values = new uint[count];
            for (int i = 0; i < count; i++) values[i] = value;
            return values;
        }

        /// <summary>Expects a <see cref="WeftException"/> of <paramref name="status"/> whose message contains <paramref name="message"/>.</summary>
        internal static void Fails(Action action, WeftStatus status, string message)
        {
            WeftException e = T.Throws<WeftException>(action, status.ToString());
            if (e == null) return;
            T.Equal(status, e.Status, "status");
            T.True(e.Message.Contains(message), "message containing \"" + message + "\", got \"" + e.Message + "\"");
        }

        /// <summary>Checks that two coordinate arrays agree within <paramref name="tolerance"/>.</summary>
        internal static void Near(double[] expected, double[] actual, double tolerance, string what)
        {
            if (actual == null || expected.Length != actual.Length)
            {
                T.Fail(what + ": expected " + expected.Length + " values, got " + (actual == null ? "null" : actual.Length.ToString()));
                return;
            }
            for (int i = 0; i < expected.Length; i++)
            {
                if (Math.Abs(expected[i] - actual[i]) > tolerance)
                {
                    T.Fail(what + "[" + i + "]: expected " + expected[i] + ", got " + actual[i]);
                    return;
                }
            }
        }

        /// <summary>Position of vertex <paramref name="v"/>.</summary>
        internal static double[] Vertex(WeftMesh mesh, int v)
        {
            double[] p = mesh.GetPositions();
            return new[] { p[3 * v], p[3 * v + 1], p[3 * v + 2] };
        }

        /// <summary>The vertex indices of face <paramref name="f"/>.</summary>
        internal static uint[] Face(WeftMesh mesh, int f)
        {
            uint[] sizes, indices;
            mesh.GetFaces(out sizes, out indices);
            int start = 0;
            for (int i = 0; i < f; i++) start += (int)sizes[i];
            var face = new uint[sizes[f]];
            Array.Copy(indices, start, face, 0, face.Length);
            return face;
        }
    }
}
