// Must NOT compile against the stubs: check.sh compiles each case on its own
// (CASE_1 ... CASE_8) and expects it to fail, proving the stubs reject what
// the real SDK rejects. RHINO8_ONLY must compile against the Rhino 8 stubs
// and fail against the Rhino 7 ones. Without a case the file compiles.
using Grasshopper.Kernel;
using Rhino.Geometry;

namespace Weft.Grasshopper.StrictnessCheck
{
    public sealed class Wrong : GH_Component
    {
        public Wrong() : base("Wrong", "W", "d", "Weft", "Test") { }
        public override System.Guid ComponentGuid { get { return System.Guid.Empty; } }
        protected override void RegisterInputParams(GH_InputParamManager pManager)
        {
#if CASE_1
            pManager.AddMeshParameter("Mesh", "M", "a misspelled member", GH_ParamAccess.item, 3.0); // no such overload
#endif
        }
        protected override void RegisterOutputParams(GH_OutputParamManager pManager) { }
        protected override void SolveInstance(IGH_DataAccess DA)
        {
            int levels = 1;
            object item = null;
            double number;
            Mesh mesh = null;
            Curve curve = null;
            Polyline polyline;
#if CASE_2
            DA.GetData(1, levels); // ref missing
#endif
#if CASE_3
            mesh.Vertices.UseDoublePrecisionVertice = true; // misspelled member
#endif
#if CASE_4
            unsafe
            {
                MeshUnsafeLock data = mesh.GetUnsafeLock(false);
                int length;
                Point3f* p = data.VertexPoint3dArray(out length); // double array as float
            }
#endif
#if CASE_5
            GH_Convert.ToDouble(item, GH_Conversion.Primary, out number); // the out parameter is second, not last
#endif
#if CASE_6
            GH_Convert.ToMesh(item, out mesh, GH_Conversion.Both); // ref, not out
#endif
#if CASE_7
            curve.TryGetPolyline(ref polyline); // out, not ref
#endif
#if CASE_8
            Point3d p8 = Point3d.Origin;
            Vector3d normal;
            mesh.ClosestPoint(ref p8, 1.0, out normal); // an out/ref signature guessed from the .pyi: refused
#endif
#if RHINO8_ONLY
            unsafe
            {
                MeshUnsafeLock colours = mesh.GetUnsafeLock(false);
                int count;
                int* argb = colours.VertexColorsArray(out count); // since Rhino 8
                levels += count > 0 ? argb[0] : 0;
            }
#endif
            DA.GetData(1, ref levels);
            GH_Convert.ToDouble(item, out number, GH_Conversion.Primary);
            GH_Convert.ToMesh(item, ref mesh, GH_Conversion.Both);
            curve.TryGetPolyline(out polyline);
        }
    }
}
