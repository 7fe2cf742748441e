// Generated from include/weft.h by dotnet/generate.py; do not edit (dotnet/test.sh checks it is current).
namespace Weft
{
    /// <summary>
    /// The outcome of every Weft call, <c>WeftStatus</c> in <c>include/weft.h</c> value for
    /// value. New values are only ever added at the end.
    /// </summary>
    public enum WeftStatus : uint
    {
        /// <summary>Success.</summary>
        Ok = 0,
        /// <summary>A required pointer argument was NULL.</summary>
        NullPointer = 1,
        /// <summary>An argument other than a mesh is out of its domain (an unknown enum value, a negative tolerance, a level count above the cap).</summary>
        InvalidArgument = 2,
        /// <summary>A face names a vertex index at or past the vertex count.</summary>
        IndexOutOfRange = 3,
        /// <summary>A face has fewer than three vertices.</summary>
        FaceTooSmall = 4,
        /// <summary>A face names the same vertex twice.</summary>
        RepeatedIndex = 5,
        /// <summary>A coordinate is NaN or infinite.</summary>
        NonFiniteCoordinate = 6,
        /// <summary>The face sizes do not add up to the index count, or a buffer length disagrees with a count.</summary>
        CountMismatch = 7,
        /// <summary>The input has more vertices or indices than 32-bit indices address.</summary>
        InputTooLarge = 8,
        /// <summary>An operation that needs triangles was given another polygon.</summary>
        NotTriangles = 9,
        /// <summary>The result would pass the size cap or overflow 32-bit indices.</summary>
        ResultTooLarge = 10,
        /// <summary>Memory for the result could not be allocated.</summary>
        OutOfMemory = 11,
        /// <summary>A caller buffer is too small for what is to be copied into it.</summary>
        BufferTooSmall = 12,
        /// <summary>The input is geometrically degenerate for the operation (collinear points, fewer points than needed, a zero-length axis).</summary>
        DegenerateInput = 13,
        /// <summary>A bug inside Weft was caught at the boundary; the host keeps running.</summary>
        InternalPanic = 14,
    }
}
