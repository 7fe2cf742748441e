using System;

namespace Weft
{
    /// <summary>Checks shared by the wrapper methods before a native call.</summary>
    internal static class Arguments
    {
        internal static WeftMeshHandle Mesh(WeftMesh mesh, string name)
        {
            if (mesh == null) throw new ArgumentNullException(name);
            return mesh.Handle;
        }

        internal static T NotNull<T>(T value, string name) where T : class
        {
            if (value == null) throw new ArgumentNullException(name);
            return value;
        }

        /// <summary>A count or level that C takes unsigned; a negative one is refused as the library would refuse a bad argument.</summary>
        internal static uint Unsigned(int value, string name)
        {
            if (value < 0)
            {
                throw new WeftException(WeftStatus.InvalidArgument, name + " is " + value + "; it must be 0 or more");
            }
            return (uint)value;
        }

        internal static UIntPtr Size(int value, string name)
        {
            return (UIntPtr)Unsigned(value, name);
        }

        /// <summary>The number of points in a buffer of x, y, z triples.</summary>
        internal static UIntPtr Triples(double[] values, string name)
        {
            NotNull(values, name);
            if (values.Length % 3 != 0)
            {
                throw new WeftException(WeftStatus.CountMismatch, name + " holds " + values.Length + " doubles, which is not 3 per point");
            }
            return (UIntPtr)(values.Length / 3);
        }

        internal static int ToInt(UIntPtr count)
        {
            return checked((int)count.ToUInt64());
        }

        internal static WeftPlane[] Plane(WeftPlane? plane)
        {
            return plane.HasValue ? new[] { plane.Value } : null;
        }
    }
}
