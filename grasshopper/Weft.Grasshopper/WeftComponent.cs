using System;
using System.Collections.Generic;
using System.Drawing;
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
            var items = new List<object>();
            if (!DA.GetDataList(index, items) || items.Count == 0)
            {
                return null;
            }
            var parts = new List<PolygonArrays>();
            var polylines = new List<double[]>();
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
                parts.Add(MeshArrays.FromPolylines(polylines, DocumentTolerance()));
            }
            if (parts.Count == 0)
            {
                AddRuntimeMessage(GH_RuntimeMessageLevel.Warning, "No mesh or closed polyline to work on.");
                return null;
            }
            PolygonArrays all = parts.Count == 1 ? parts[0] : MeshArrays.Concatenate(parts);
            return WeftMesh.Create(all.Positions, all.FaceSizes, all.FaceIndices);
        }

        /// <summary>Reads a naked-edge mode input (0 Fixed, 1 Smooth, 2 Corner Fixed).</summary>
        protected static NakedEdges ToNakedEdges(int mode)
        {
            if (mode < 0 || mode > 2)
            {
                throw new WeftException(WeftStatus.InvalidArgument, "S is " + mode + "; use 0 (fixed), 1 (smooth) or 2 (corner fixed)");
            }
            return (NakedEdges)mode;
        }

        /// <summary>Sets a Weft mesh as a Rhino mesh on an output.</summary>
        protected static void SetMesh(IGH_DataAccess DA, int index, WeftMesh mesh)
        {
            DA.SetData(index, RhinoMeshes.FromWeft(mesh));
        }
    }
}
