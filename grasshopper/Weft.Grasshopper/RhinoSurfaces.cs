using Rhino.Geometry;

namespace Weft.Grasshopper
{
    /// <summary>Weft's bicubic patches as Rhino NURBS surfaces.</summary>
    public static class RhinoSurfaces
    {
        /// <summary>
        /// Patch <paramref name="patch"/> of <paramref name="controlPoints"/> (48 doubles a
        /// patch, control point i along u and j along v at 12 i + 3 j) as a NurbsSurface of
        /// degree 3 × 3 with 4 × 4 control points and clamped uniform knots (0, 0, 0, 1, 1, 1):
        /// the patch's Bézier form, so the surface is the patch over [0, 1]².
        /// </summary>
        public static NurbsSurface FromPatch(double[] controlPoints, int patch)
        {
            NurbsSurface surface = NurbsSurface.Create(3, false, 4, 4, 4, 4);
            surface.KnotsU.CreateUniformKnots(1.0);
            surface.KnotsV.CreateUniformKnots(1.0);
            int start = 48 * patch;
            for (int i = 0; i < 4; i++)
            {
                for (int j = 0; j < 4; j++)
                {
                    int k = start + 12 * i + 3 * j;
                    surface.Points.SetPoint(i, j, new Point3d(controlPoints[k], controlPoints[k + 1], controlPoints[k + 2]));
                }
            }
            return surface;
        }
    }
}
