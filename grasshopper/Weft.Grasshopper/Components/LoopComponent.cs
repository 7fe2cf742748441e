using System;
using System.Runtime.InteropServices;

namespace Weft.Grasshopper
{
    /// <summary>Loop subdivision (Weaverbird's wbLoop); quads and n-gons are triangulated first.</summary>
    [Guid("57a9011b-8439-44ee-bf53-c3ea93793bc6")]
    public sealed class LoopComponent : PlainSubdivisionComponent
    {
        public LoopComponent()
            : base(Scheme.Loop, "Loop Subdivision", "wbLoop",
                   "Subdivides a triangle mesh with the Loop scheme; quads and n-gons are triangulated first.",
                   "loop")
        {
        }
    }
}
