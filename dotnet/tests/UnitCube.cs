namespace Weft.Tests
{
    /// <summary>The unit cube's arrays, faces wound outwards (face 0 is the bottom, facing -z), for the wrapper and the Grasshopper conversion tests.</summary>
    internal static class UnitCube
    {
        internal static readonly double[] Positions =
        {
            0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0,
            0, 0, 1, 1, 0, 1, 0, 1, 1, 1, 1, 1,
        };
        internal static readonly uint[] Sizes = { 4, 4, 4, 4, 4, 4 };
        internal static readonly uint[] Indices =
        {
            0, 2, 3, 1, 4, 5, 7, 6, 0, 1, 5, 4,
            2, 6, 7, 3, 0, 4, 6, 2, 1, 3, 7, 5,
        };
    }
}
