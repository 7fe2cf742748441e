namespace Weft
{
    /// <summary>
    /// How the smoothing operations treat naked edges. The header passes these
    /// as WEFT_NAKED_EDGES_* values (the same numbers); this enum names what
    /// each means for smoothing rather than subdivision.
    /// </summary>
    public enum SmoothNakedEdges : uint
    {
        /// <summary>Boundary vertices stay.</summary>
        Fixed = 0,
        /// <summary>Boundary vertices move along the boundary, averaged with their boundary neighbours only.</summary>
        Smooth = 1,
        /// <summary>As Smooth, but a boundary vertex with a single face (a corner) stays.</summary>
        CornerFixed = 2,
    }
}
