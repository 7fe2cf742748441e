// Must NOT compile against the stubs: check.sh expects each marked line to
// fail, proving the stubs reject what the real SDK rejects. Each case is
// compiled on its own (CASE_1 ... CASE_4).
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
#if CASE_2
            DA.GetData(1, levels); // ref missing
#endif
#if CASE_3
            Mesh mesh = new Mesh();
            mesh.Vertices.UseDoublePrecisionVertice = true; // misspelled member
#endif
#if CASE_4
            unsafe
            {
                Mesh m = new Mesh();
                MeshUnsafeLock data = m.GetUnsafeLock(false);
                int length;
                Point3f* p = data.VertexPoint3dArray(out length); // double array as float
            }
#endif
            DA.GetData(1, ref levels);
        }
    }
}
