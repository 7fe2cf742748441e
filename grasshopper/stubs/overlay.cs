// What the typed Python stubs cannot show: protected, virtual and abstract
// members and nested types, written by hand from the Grasshopper SDK
// documentation. Completes the generated partial types; signatures only.
using System;
using System.Collections.Generic;
using System.Drawing;

namespace Grasshopper.Kernel
{
    public abstract partial class GH_Component
    {
        protected GH_Component() { throw null; }
        protected GH_Component(string name, string nickname, string description, string category, string subCategory) { throw null; }

        protected abstract void RegisterInputParams(GH_InputParamManager pManager);
        protected abstract void RegisterOutputParams(GH_OutputParamManager pManager);
        protected abstract void SolveInstance(IGH_DataAccess DA);
        protected virtual void BeforeSolveInstance() { throw null; }
        protected virtual void AfterSolveInstance() { throw null; }

        public abstract Guid ComponentGuid { get; }
        public virtual GH_Exposure Exposure { get { throw null; } }
        protected virtual Bitmap Icon { get { throw null; } }

        public virtual void RemovedFromDocument(GH_Document document) { throw null; }
        public virtual void DocumentContextChanged(GH_Document document, GH_DocumentContext context) { throw null; }

        protected static double DocumentTolerance() { throw null; }
        protected static double DocumentAngleTolerance() { throw null; }

        public class GH_InputParamManager
        {
            internal GH_InputParamManager() { }
            public IGH_Param this[int index] { get { throw null; } }
            public int ParamCount { get { throw null; } }
            public void HideParameter(int index) { throw null; }
            public int AddGenericParameter(string name, string nickname, string description, GH_ParamAccess access) { throw null; }
            public int AddMeshParameter(string name, string nickname, string description, GH_ParamAccess access) { throw null; }
            public int AddCurveParameter(string name, string nickname, string description, GH_ParamAccess access) { throw null; }
            public int AddPointParameter(string name, string nickname, string description, GH_ParamAccess access) { throw null; }
            public int AddPointParameter(string name, string nickname, string description, GH_ParamAccess access, Rhino.Geometry.Point3d @default) { throw null; }
            public int AddPlaneParameter(string name, string nickname, string description, GH_ParamAccess access) { throw null; }
            public int AddLineParameter(string name, string nickname, string description, GH_ParamAccess access) { throw null; }
            public int AddIntegerParameter(string name, string nickname, string description, GH_ParamAccess access) { throw null; }
            public int AddIntegerParameter(string name, string nickname, string description, GH_ParamAccess access, int @default) { throw null; }
            public int AddIntegerParameter(string name, string nickname, string description, GH_ParamAccess access, IEnumerable<int> @default) { throw null; }
            public int AddNumberParameter(string name, string nickname, string description, GH_ParamAccess access) { throw null; }
            public int AddNumberParameter(string name, string nickname, string description, GH_ParamAccess access, double @default) { throw null; }
            public int AddNumberParameter(string name, string nickname, string description, GH_ParamAccess access, IEnumerable<double> @default) { throw null; }
            public int AddBooleanParameter(string name, string nickname, string description, GH_ParamAccess access) { throw null; }
            public int AddBooleanParameter(string name, string nickname, string description, GH_ParamAccess access, bool @default) { throw null; }
            public int AddBooleanParameter(string name, string nickname, string description, GH_ParamAccess access, IEnumerable<bool> @default) { throw null; }
            public int AddTextParameter(string name, string nickname, string description, GH_ParamAccess access) { throw null; }
            public int AddTextParameter(string name, string nickname, string description, GH_ParamAccess access, string @default) { throw null; }
            public int AddParameter(IGH_Param param, string name, string nickname, string description, GH_ParamAccess access) { throw null; }
        }

        public class GH_OutputParamManager
        {
            internal GH_OutputParamManager() { }
            public IGH_Param this[int index] { get { throw null; } }
            public int ParamCount { get { throw null; } }
            public void HideParameter(int index) { throw null; }
            public int AddGenericParameter(string name, string nickname, string description, GH_ParamAccess access) { throw null; }
            public int AddMeshParameter(string name, string nickname, string description, GH_ParamAccess access) { throw null; }
            public int AddCurveParameter(string name, string nickname, string description, GH_ParamAccess access) { throw null; }
            public int AddSurfaceParameter(string name, string nickname, string description, GH_ParamAccess access) { throw null; }
            public int AddPointParameter(string name, string nickname, string description, GH_ParamAccess access) { throw null; }
            public int AddLineParameter(string name, string nickname, string description, GH_ParamAccess access) { throw null; }
            public int AddVectorParameter(string name, string nickname, string description, GH_ParamAccess access) { throw null; }
            public int AddIntegerParameter(string name, string nickname, string description, GH_ParamAccess access) { throw null; }
            public int AddNumberParameter(string name, string nickname, string description, GH_ParamAccess access) { throw null; }
            public int AddBooleanParameter(string name, string nickname, string description, GH_ParamAccess access) { throw null; }
            public int AddTextParameter(string name, string nickname, string description, GH_ParamAccess access) { throw null; }
            public int AddParameter(IGH_Param param, string name, string nickname, string description, GH_ParamAccess access) { throw null; }
        }
    }

    public abstract partial class GH_AssemblyInfo
    {
        protected GH_AssemblyInfo() { throw null; }
        public virtual string Name { get { throw null; } }
        public virtual Bitmap Icon { get { throw null; } }
        public virtual string Description { get { throw null; } }
        public virtual Guid Id { get { throw null; } }
        public virtual string AuthorName { get { throw null; } }
        public virtual string AuthorContact { get { throw null; } }
        public virtual string Version { get { throw null; } }
    }

    /// <summary>How Grasshopper loads the assembly (an attribute, so written here; Grasshopper 1.0 and later).</summary>
    [AttributeUsage(AttributeTargets.Assembly)]
    public sealed class GH_LoadingAttribute : Attribute
    {
        public GH_LoadingAttribute(GH_LoadingDemand demand) { throw null; }
    }

    public abstract partial class GH_AssemblyPriority
    {
        protected GH_AssemblyPriority() { throw null; }
        public abstract GH_LoadingInstruction PriorityLoad();
    }
}
