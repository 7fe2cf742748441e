using System;
using System.Collections.Generic;
using System.Drawing;
using System.Runtime.InteropServices;
using Grasshopper.Kernel;
using Rhino.Geometry;

namespace Weft.Grasshopper
{
    /// <summary>
    /// What every Weft component shares: the "Weft" tab, its icon, mesh input
    /// that accepts Rhino meshes or closed polylines, and failures shown as
    /// runtime messages (red balloons) instead of exceptions.
    /// </summary>
    public abstract class WeftComponent : GH_Component
    {
        /// <summary>The ribbon tab of every Weft component.</summary>
        public const string Tab = "Weft";

        private readonly string iconName;

        protected WeftComponent(string name, string nickname, string description, string subcategory, string iconName)
            : base(name, nickname, description, Tab, subcategory)
        {
            this.iconName = iconName;
        }

        protected override Bitmap Icon
        {
            get { return Icons.Load(iconName); }
        }

        /// <summary>The component class's <c>[Guid]</c>: fixed forever and never shared (check.sh checks both).</summary>
        public sealed override Guid ComponentGuid
        {
            get
            {
                var id = (GuidAttribute)Attribute.GetCustomAttribute(GetType(), typeof(GuidAttribute));
                if (id == null) throw new InvalidOperationException(GetType().Name + " has no [Guid]; every component needs a fixed one");
                return new Guid(id.Value);
            }
        }

        /// <summary>Runs <see cref="Solve"/>, turning every failure into an error message on the component.</summary>
        protected sealed override void SolveInstance(IGH_DataAccess DA)
        {
            try
            {
                Solve(DA);
            }
            catch (WeftException e)
            {
                AddRuntimeMessage(GH_RuntimeMessageLevel.Error, e.Message);
            }
            catch (DllNotFoundException e)
            {
                AddRuntimeMessage(GH_RuntimeMessageLevel.Error, "The Weft native library could not be loaded: " + e.Message);
            }
            catch (EntryPointNotFoundException e)
            {
                AddRuntimeMessage(GH_RuntimeMessageLevel.Error, "The Weft native library is older than this plug-in: " + e.Message);
            }
            catch (Exception e)
            {
                AddRuntimeMessage(GH_RuntimeMessageLevel.Error, e.GetType().Name + ": " + e.Message);
            }
        }

        /// <summary>The component's work; may throw, never needs to catch.</summary>
        protected abstract void Solve(IGH_DataAccess DA);

        /// <summary>Registers the usual mesh input: meshes or closed polylines, as a list.</summary>
        protected static void AddMeshInput(GH_InputParamManager pManager, string nickname, string description)
        {
            pManager.AddGenericParameter("Mesh", nickname, description + " A mesh, or a list of closed polylines (one n-gon face each).", GH_ParamAccess.list);
        }

        /// <summary>
        /// Reads the items of a mesh input as one Weft mesh: each Rhino mesh
        /// as it is, all closed polylines as polygons whose corners are merged
        /// within the document tolerance. Returns null (with a message) when
        /// nothing usable was given.
        /// </summary>
        protected WeftMesh GetMesh(IGH_DataAccess DA, int index)
        {
            PolygonArrays all = GetPolygons(DA, index);
            return all == null ? null : WeftMesh.Create(all.Positions, all.FaceSizes, all.FaceIndices);
        }

        /// <summary>Reads the items of a mesh input as one polygon mesh's arrays (see <see cref="GetMesh"/>), or null.</summary>
        protected PolygonArrays GetPolygons(IGH_DataAccess DA, int index)
        {
            int[] colours;
            return GetPolygons(DA, index, out colours);
        }

        /// <summary>
        /// As <see cref="GetPolygons(IGH_DataAccess, int)"/>, with the vertex colours (packed
        /// ARGB, one per vertex of the result) when every item is a Rhino mesh with a colour
        /// per vertex; otherwise <paramref name="colours"/> is null.
        /// </summary>
        protected PolygonArrays GetPolygons(IGH_DataAccess DA, int index, out int[] colours)
        {
            colours = null;
            var items = new List<object>();
            if (!DA.GetDataList(index, items) || items.Count == 0)
            {
                return null;
            }
            var parts = new List<PolygonArrays>();
            var polylines = new List<double[]>();
            var partColours = new List<int>();
            bool allColoured = true;
            int skipped = 0;
            foreach (object item in items)
            {
                Curve curve = null;
                Mesh mesh = null;
                if (GH_Convert.ToCurve(item, ref curve, GH_Conversion.Primary))
                {
                    double[] corners = RhinoMeshes.ClosedPolylineCorners(curve);
                    if (corners != null) polylines.Add(corners);
                    else skipped++;
                }
                else if (GH_Convert.ToMesh(item, ref mesh, GH_Conversion.Both) && mesh != null)
                {
                    parts.Add(RhinoMeshes.ToArrays(mesh));
                    int[] own = RhinoMeshes.VertexColours(mesh);
                    if (own == null) allColoured = false;
                    else partColours.AddRange(own);
                }
                else
                {
                    skipped++;
                }
            }
            if (skipped > 0)
            {
                AddRuntimeMessage(GH_RuntimeMessageLevel.Warning, skipped + " input item(s) are neither a mesh nor a closed polyline and were ignored.");
            }
            if (polylines.Count > 0)
            {
                parts.Add(MeshArrays.FromPolylines(polylines, Tolerance()));
            }
            if (parts.Count == 0)
            {
                AddRuntimeMessage(GH_RuntimeMessageLevel.Warning, "No mesh or closed polyline to work on.");
                return null;
            }
            PolygonArrays all = parts.Count == 1 ? parts[0] : MeshArrays.Join(parts);
            if (allColoured && polylines.Count == 0 && partColours.Count * 3 == all.Positions.Length)
            {
                colours = partColours.ToArray();
            }
            return all;
        }

        /// <summary>
        /// The active Rhino document's absolute tolerance; without a document (Rhino.Compute,
        /// headless Rhino) <see cref="Tolerances.Default"/>, with a remark saying so.
        /// </summary>
        protected double Tolerance()
        {
            bool fellBack;
            double tolerance = Tolerances.Choose(Rhino.RhinoDoc.ActiveDoc == null ? double.NaN : DocumentTolerance(), out fellBack);
            if (fellBack)
            {
                Remark("No Rhino document gives a tolerance: " + Tolerances.Default + " is used where one is needed and T is empty.");
            }
            return tolerance;
        }

        /// <summary>Registers an optional tolerance input T; <paramref name="what"/> says what it measures.</summary>
        protected static void AddToleranceInput(GH_InputParamManager pManager, string what)
        {
            int index = pManager.AddNumberParameter("Tolerance", "T", what + "; the document's absolute tolerance when empty.", GH_ParamAccess.item);
            pManager[index].Optional = true;
        }

        /// <summary>
        /// The tolerance input at <paramref name="index"/>, or <see cref="Tolerance"/> when it is
        /// empty; a negative or NaN value is refused, naming T.
        /// </summary>
        protected double GetTolerance(IGH_DataAccess DA, int index)
        {
            double tolerance = 0;
            if (!DA.GetData(index, ref tolerance)) return Tolerance();
            if (double.IsNaN(tolerance) || tolerance < 0)
            {
                throw new WeftException(WeftStatus.InvalidArgument, "T is " + tolerance + "; the tolerance must be 0 or more");
            }
            return tolerance;
        }

        /// <summary>The value of an item input, or <paramref name="fallback"/> when it is empty.</summary>
        protected static T Get<T>(IGH_DataAccess DA, int index, T fallback)
        {
            T value = fallback;
            DA.GetData(index, ref value);
            return value;
        }

        /// <summary>The values of a list input as an array (empty when nothing is connected).</summary>
        protected static T[] GetList<T>(IGH_DataAccess DA, int index)
        {
            var values = new List<T>();
            DA.GetDataList(index, values);
            return values.ToArray();
        }

        /// <summary>Reads a mode input of <paramref name="count"/> values (0 to count - 1), naming them in the error.</summary>
        protected static uint ToMode(int mode, int count, string nickname, string meanings)
        {
            if (mode < 0 || mode >= count)
            {
                throw new WeftException(WeftStatus.InvalidArgument, nickname + " is " + mode + "; use " + meanings);
            }
            return (uint)mode;
        }

        /// <summary>Registers the usual levels input L (default 1).</summary>
        protected static void AddLevelsInput(GH_InputParamManager pManager)
        {
            pManager.AddIntegerParameter("Level", "L", "Number of steps (0 returns the input).", GH_ParamAccess.item, 1);
        }

        /// <summary>Registers the smoothing iterations input L (default 1).</summary>
        protected static void AddIterationsInput(GH_InputParamManager pManager)
        {
            pManager.AddIntegerParameter("Level", "L", "Iterations.", GH_ParamAccess.item, 1);
        }

        /// <summary>Registers the smoothing naked-edge input S (0 fixed, 1 smooth, 2 corner fixed; default 0).</summary>
        protected static void AddSmoothNakedInput(GH_InputParamManager pManager)
        {
            pManager.AddIntegerParameter("Smooth Naked Edges", "S", "0: naked vertices stay, 1: they slide along the boundary, 2: as 1 but corners stay.", GH_ParamAccess.item, 0);
        }

        /// <summary>Reads a smoothing naked-edge input.</summary>
        protected static SmoothNakedEdges ToSmoothNaked(int mode)
        {
            return (SmoothNakedEdges)ToMode(mode, 3, "S", "0 (fixed), 1 (smooth) or 2 (corner fixed)");
        }

        /// <summary>Reads an offset type input (0 diagonal, 1 hypotenuse average, 2 planes intersection).</summary>
        protected static OffsetType ToOffsetType(int type)
        {
            return (OffsetType)ToMode(type, 3, "T", "0 (distance on diagonals), 1 (hypotenuse average) or 2 (planes intersection)");
        }

        /// <summary>The subdivision components' S input: Weaverbird's three modes, and OpenSubdiv's "none" beyond them.</summary>
        protected const string NakedEdgesDescription =
            "0: fixed, 1: smooth, 2: corner fixed (Weaverbird's three); 3: none, OpenSubdiv's: every face at a naked edge is left out as a hole, the rest refined as smooth.";

        /// <summary>Reads a subdivision naked-edge mode input (0 Fixed, 1 Smooth, 2 Corner Fixed, 3 None).</summary>
        protected static NakedEdges ToNakedEdges(int mode)
        {
            return (NakedEdges)ToMode(mode, 4, "S", "0 (fixed), 1 (smooth), 2 (corner fixed) or 3 (none: boundary faces left out)");
        }

        /// <summary>Shows a warning balloon.</summary>
        protected void Warn(string text)
        {
            AddRuntimeMessage(GH_RuntimeMessageLevel.Warning, text);
        }

        /// <summary>Shows a remark balloon.</summary>
        protected void Remark(string text)
        {
            AddRuntimeMessage(GH_RuntimeMessageLevel.Remark, text);
        }

        /// <summary>Registers the mesh output M.</summary>
        protected static void AddMeshOutput(GH_OutputParamManager pManager, string description)
        {
            pManager.AddMeshParameter("Mesh", "M", description, GH_ParamAccess.item);
        }

        /// <summary>Sets a Weft mesh as a Rhino mesh on an output.</summary>
        protected static void SetMesh(IGH_DataAccess DA, int index, WeftMesh mesh)
        {
            DA.SetData(index, RhinoMeshes.FromWeft(mesh));
        }

        /// <summary>A warning balloon when welding at <paramref name="tolerance"/> collapsed faces.</summary>
        protected void WarnOfCollapse(WeftWeldReport report, int faceCount, double tolerance)
        {
            if (report.RemovedFaceCount == 0) return;
            AddRuntimeMessage(GH_RuntimeMessageLevel.Warning, "Welding at " + tolerance + " collapsed "
                + report.RemovedFaceCount + " of " + faceCount + " faces (their corners merged); a smaller T keeps them.");
        }
    }

    /// <summary>
    /// A component that reads one mesh (input 0, M), then its options, and
    /// answers from it: subclasses register their options and outputs and
    /// implement <see cref="Query"/>.
    /// </summary>
    public abstract class MeshQueryComponent : WeftComponent
    {
        private readonly string inputDescription;

        protected MeshQueryComponent(string name, string nickname, string description, string subcategory, string iconName,
                                     string inputDescription)
            : base(name, nickname, description, subcategory, iconName)
        {
            this.inputDescription = inputDescription;
        }

        protected sealed override void RegisterInputParams(GH_InputParamManager pManager)
        {
            AddMeshInput(pManager, "M", inputDescription);
            RegisterOptions(pManager);
        }

        /// <summary>Registers the inputs after M (index 1 on); none by default.</summary>
        protected virtual void RegisterOptions(GH_InputParamManager pManager)
        {
        }

        protected sealed override void Solve(IGH_DataAccess DA)
        {
            using (WeftMesh mesh = GetMesh(DA, 0))
            {
                if (mesh == null) return;
                Query(mesh, DA);
            }
        }

        /// <summary>Reads the options from DA and sets the outputs; the mesh is disposed afterwards.</summary>
        protected abstract void Query(WeftMesh mesh, IGH_DataAccess DA);
    }

    /// <summary>
    /// A component that reads one mesh (input 0, M), applies one operation and
    /// outputs one mesh (output 0, M): subclasses only register their options
    /// and call the wrapper.
    /// </summary>
    public abstract class MeshOperationComponent : MeshQueryComponent
    {
        private readonly string outputDescription;

        protected MeshOperationComponent(string name, string nickname, string description, string subcategory, string iconName,
                                         string inputDescription, string outputDescription)
            : base(name, nickname, description, subcategory, iconName, inputDescription)
        {
            this.outputDescription = outputDescription;
        }

        protected override void RegisterOutputParams(GH_OutputParamManager pManager)
        {
            AddMeshOutput(pManager, outputDescription);
        }

        protected sealed override void Query(WeftMesh mesh, IGH_DataAccess DA)
        {
            using (WeftMesh result = Apply(mesh, DA))
            {
                SetMesh(DA, 0, result);
            }
        }

        /// <summary>The operation: reads its options from DA and returns the new mesh.</summary>
        protected abstract WeftMesh Apply(WeftMesh mesh, IGH_DataAccess DA);
    }
}

namespace Weft.Grasshopper
{
    /// <summary>A mesh operation whose only option is the levels input L (default 1).</summary>
    public abstract class LevelsOperationComponent : MeshOperationComponent
    {
        private readonly Func<WeftMesh, int, WeftMesh> operation;

        protected LevelsOperationComponent(string name, string nickname, string description, string subcategory, string iconName,
                                           Func<WeftMesh, int, WeftMesh> operation)
            : base(name, nickname, description, subcategory, iconName, "The mesh to split.", "The split mesh.")
        {
            this.operation = operation;
        }

        protected sealed override void RegisterOptions(GH_InputParamManager pManager)
        {
            AddLevelsInput(pManager);
        }

        protected sealed override WeftMesh Apply(WeftMesh mesh, IGH_DataAccess DA)
        {
            return operation(mesh, Get(DA, 1, 1));
        }
    }

    /// <summary>A mesh operation whose only option is one item input, declared as data.</summary>
    public abstract class OptionOperationComponent<T> : MeshOperationComponent
    {
        private readonly ItemOption<T> option;
        private readonly Func<WeftMesh, T, WeftMesh> operation;

        protected OptionOperationComponent(string name, string nickname, string description,
                                           ItemOption<T> option, Func<WeftMesh, T, WeftMesh> operation,
                                           string subcategory, string iconName, string inputDescription, string outputDescription)
            : base(name, nickname, description, subcategory, iconName, inputDescription, outputDescription)
        {
            this.option = option;
            this.operation = operation;
        }

        protected sealed override void RegisterOptions(GH_InputParamManager pManager)
        {
            option.Register(pManager);
        }

        protected sealed override WeftMesh Apply(WeftMesh mesh, IGH_DataAccess DA)
        {
            return operation(mesh, option.Read(DA, 1));
        }
    }

    /// <summary>A splitting operation with the levels input L (default 1) and one more item input after it, declared as data.</summary>
    public abstract class LevelsOptionOperationComponent<T> : MeshOperationComponent
    {
        private readonly ItemOption<T> option;
        private readonly Func<WeftMesh, int, T, WeftMesh> operation;

        protected LevelsOptionOperationComponent(string name, string nickname, string description,
                                                 ItemOption<T> option, Func<WeftMesh, int, T, WeftMesh> operation,
                                                 string subcategory, string iconName)
            : base(name, nickname, description, subcategory, iconName, "The mesh to split.", "The split mesh.")
        {
            this.option = option;
            this.operation = operation;
        }

        protected sealed override void RegisterOptions(GH_InputParamManager pManager)
        {
            AddLevelsInput(pManager);
            option.Register(pManager);
        }

        protected sealed override WeftMesh Apply(WeftMesh mesh, IGH_DataAccess DA)
        {
            return operation(mesh, Get(DA, 1, 1), option.Read(DA, 2));
        }
    }

    /// <summary>A mesh operation whose only option is the fraction input F (default 0.25).</summary>
    public abstract class FractionOperationComponent : MeshOperationComponent
    {
        private readonly string fractionDescription;
        private readonly Func<WeftMesh, double, WeftMesh> operation;

        protected FractionOperationComponent(string name, string nickname, string description, string iconName, string fractionDescription,
                                             Func<WeftMesh, double, WeftMesh> operation)
            : base(name, nickname, description, "Transform", iconName, "The mesh to bevel.", "The bevelled mesh.")
        {
            this.fractionDescription = fractionDescription;
            this.operation = operation;
        }

        protected sealed override void RegisterOptions(GH_InputParamManager pManager)
        {
            pManager.AddNumberParameter("Fraction", "F", fractionDescription, GH_ParamAccess.item, 0.25);
        }

        protected sealed override WeftMesh Apply(WeftMesh mesh, IGH_DataAccess DA)
        {
            return operation(mesh, Get(DA, 1, 0.25));
        }
    }
}
