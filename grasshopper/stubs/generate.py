#!/usr/bin/env python3
"""Generates C# reference stubs (signatures only, bodies `throw null;`) for the
RhinoCommon and Grasshopper types the Weft components use, from the typed
Python stubs `rhino-stubs-typed` and `grasshopper-stubs-typed` (.pyi files).

Those stubs are lossy (Python `float` is both float and double, `uint` is
`int`, arrays and IEnumerable are `Iterable`, `out`/`ref` become tuple
returns), so a fix-up table below restores the C# signatures the components
rely on. Members that mention a type outside WANTED are left out: using one
fails the compile, which is the point: a misspelled member, a wrong overload
or a missing `ref`/`out` must not compile against these stubs.

Out and ref parameters are never guessed: the .pyi turns them into tuple
returns and loses their position (GH_Convert.ToDouble is
`(object data, out double destination, GH_Conversion conversion_level)`,
out in the middle). OUT_REF below is the hand-checked list, from the API
documentation, of every out/ref member the plug-in uses; every other member
whose .pyi shows an out or ref parameter is refused (left out of the stubs),
so code calling it does not compile until its signature is checked and added.

With --rhino7 <folder of rhino-stubs and grasshopper-stubs 7.x>, every member
(and enum value) that McNeel's Rhino 7 stubs do not list for the class or its
bases is dropped too: the plug-in compiling against that output uses only
members Rhino 7 has.

usage: generate.py <folder with Rhino/ and Grasshopper/> <output .cs> [--rhino7 <folder>]
"""
import ast
import re
import sys
from pathlib import Path

# Types the components use, by namespace (module path of the .pyi).
WANTED = {
    "Rhino.Geometry": ["GeometryBase", "Mesh", "MeshFace", "MeshNgon", "MeshUnsafeLock",
                       "Point3d", "Point3f", "Vector3d", "Vector3f", "Curve", "PolylineCurve", "Polyline",
                       "Line", "Plane", "Surface", "NurbsSurface"],
    "Rhino.Geometry.Collections": ["MeshVertexList", "MeshFaceList", "MeshNgonList", "MeshVertexNormalList",
                                   "MeshVertexColorList", "NurbsSurfacePointList", "NurbsSurfaceKnotList"],
    "Grasshopper.Kernel": ["GH_Component", "IGH_DataAccess", "IGH_Param", "GH_RuntimeMessageLevel",
                           "GH_ParamAccess", "GH_Exposure", "GH_Convert", "GH_Conversion",
                           "GH_AssemblyInfo", "GH_AssemblyPriority", "GH_LoadingInstruction",
                           "GH_LoadingDemand", "GH_Document", "GH_DocumentContext", "GH_ComponentServer"],
    "Grasshopper": ["Instances"],
    "Rhino": ["RhinoDoc"],
}
STRUCTS = {"MeshFace", "Point3d", "Point3f", "Vector3d", "Vector3f", "Line", "Plane"}
INTERFACES = {"IGH_DataAccess", "IGH_Param"}
FLOAT_TYPES = {"Point3f", "Vector3f"}  # `float` means System.Single in these
BUILTIN = {"int": "int", "bool": "bool", "str": "string", "object": "object", "Any": "object",
           "type": "global::System.Type", "Guid": "global::System.Guid", "TimeSpan": "global::System.TimeSpan",
           "Bitmap": "global::System.Drawing.Bitmap", "Color": "global::System.Drawing.Color",
           "Int32": "int", "T": "T"}
SKIP_NAMES = {"Equals", "GetHashCode", "GetType", "ToString", "Item", "MemberwiseClone", "Finalize"}
# Members the overlay declares (protected, virtual or abstract in the real API).
OVERLAY_MEMBERS = {
    "GH_Component": {"__init__", "ComponentGuid", "Exposure", "Icon", "RemovedFromDocument", "DocumentContextChanged"},
    "GH_AssemblyInfo": {"__init__", "Name", "Icon", "Description", "Id", "AuthorName", "AuthorContact", "Version"},
    "GH_AssemblyPriority": {"__init__", "PriorityLoad"},
}
# Overlay members that are protected, so McNeel's stubs cannot list them.
PROTECTED_OVERLAY = {"__init__", "Icon"}
# Every out/ref member the plug-in uses, each declaration copied from the
# API documentation page named beside it (Grasshopper:
# developer.rhino3d.com/api/grasshopper/html/, RhinoCommon:
# developer.rhino3d.com/api/rhinocommon/). They replace every overload.
OUT_REF = {
    # M_Grasshopper_Kernel_IGH_DataAccess_GetData__1.htm and ..._GetData__1_1.htm
    "IGH_DataAccess.GetData": ["bool GetData<T>(int index, ref T destination)", "bool GetData<T>(string name, ref T destination)"],
    # M_Grasshopper_Kernel_GH_Convert_ToDouble.htm: the out parameter is second
    "GH_Convert.ToDouble": ["public static bool ToDouble(object data, out double destination, global::Grasshopper.Kernel.GH_Conversion conversion_level)"],
    # M_Grasshopper_Kernel_GH_Convert_ToCurve.htm, _ToMesh.htm, _ToLine.htm
    "GH_Convert.ToCurve": ["public static bool ToCurve(object data, ref global::Rhino.Geometry.Curve rc, global::Grasshopper.Kernel.GH_Conversion conversion_level)"],
    "GH_Convert.ToMesh": ["public static bool ToMesh(object data, ref global::Rhino.Geometry.Mesh rc, global::Grasshopper.Kernel.GH_Conversion conversion_level)"],
    "GH_Convert.ToLine": ["public static bool ToLine(object data, ref global::Rhino.Geometry.Line rc, global::Grasshopper.Kernel.GH_Conversion conversion_level)"],
    # rhino.geometry.curve/trygetpolyline: both overloads
    "Curve.TryGetPolyline": ["public bool TryGetPolyline(out global::Rhino.Geometry.Polyline polyline)",
                             "public bool TryGetPolyline(out global::Rhino.Geometry.Polyline polyline, out double[] parameters)"],
    # rhino.geometry.meshunsafelock: VertexPoint3fArray, VertexPoint3dArray, FacesArray (since 6.20)
    "MeshUnsafeLock.VertexPoint3fArray": ["public unsafe global::Rhino.Geometry.Point3f* VertexPoint3fArray(out int length)"],
    "MeshUnsafeLock.VertexPoint3dArray": ["public unsafe global::Rhino.Geometry.Point3d* VertexPoint3dArray(out int length)"],
    "MeshUnsafeLock.FacesArray": ["public unsafe global::Rhino.Geometry.MeshFace* FacesArray(out int length)"],
    # ... and VertexColorsArray (Rhino 8 only: tests/WrongOverload.cs uses it to prove the Rhino 7 check)
    "MeshUnsafeLock.VertexColorsArray": ["public unsafe int* VertexColorsArray(out int length)"],
}
# Exact C# declarations where the .pyi loses a type (float/double, uint,
# arrays), from the same documentation; never an out or ref parameter.
FIXUPS = {
    "MeshNgon.Create": ["public static global::Rhino.Geometry.MeshNgon Create(global::System.Collections.Generic.IList<int> meshVertexIndexList, global::System.Collections.Generic.IList<int> meshFaceIndexList)"],
    "MeshNgon.Set": ["public void Set(global::System.Collections.Generic.IList<int> meshVertexIndexList, global::System.Collections.Generic.IList<int> meshFaceIndexList)"],
    "MeshNgon.BoundaryVertexIndexList": ["public uint[] BoundaryVertexIndexList()"],
    "MeshNgon.FaceIndexList": ["public uint[] FaceIndexList()"],
    "MeshNgonList.GetNgonBoundary": ["public int[] GetNgonBoundary(global::System.Collections.Generic.IEnumerable<int> ngonFaceIndexList)"],
    "MeshVertexList.ToFloatArray": ["public float[] ToFloatArray()"],
    "MeshVertexColorList.ToARGBArray": ["public int[] ToARGBArray()"],
    "MeshVertexColorList.SetColors": ["public bool SetColors(global::System.Drawing.Color[] colors)"],
    "IGH_DataAccess.GetDataList": ["bool GetDataList<T>(int index, global::System.Collections.Generic.List<T> list)",
                                   "bool GetDataList<T>(string name, global::System.Collections.Generic.List<T> list)"],
    "IGH_DataAccess.SetDataList": ["bool SetDataList(int paramIndex, global::System.Collections.IEnumerable data)",
                                   "bool SetDataList(string paramName, global::System.Collections.IEnumerable data)"],
}
CHECKED = dict(FIXUPS, **OUT_REF)
# Members of the .pyi with an out or ref parameter that are not in OUT_REF.
REFUSED = []
# OUT_REF and FIXUPS entries met in the .pyi (an entry never met is stale).
USED = set()

KEYWORDS = {"object", "string", "params", "base", "checked", "event", "ref", "out", "in", "fixed", "default",
            "operator", "lock", "namespace", "class", "struct", "delegate", "this", "new", "internal"}


def qualified():
    return {name: f"global::{ns}.{name}" for ns, names in WANTED.items() for name in names}


QUALIFIED = qualified()


def cs_type(node, single, position):
    """The C# type of an annotation, or None when it names a type not stubbed.
    single: Python's float means System.Single here. position: 'param',
    'return' or 'out' (collections differ between them)."""
    if node is None:
        return "void"
    if isinstance(node, ast.Constant) and node.value is None:
        return "void"
    if isinstance(node, ast.Name):
        if node.id == "float":
            return "float" if single else "double"
        if node.id == "None":
            return "void"
        return BUILTIN.get(node.id) or QUALIFIED.get(node.id)
    if isinstance(node, ast.Subscript) and isinstance(node.value, ast.Name):
        container = node.value.id
        if container in ("Iterable", "Sequence", "MutableSequence", "Iterator"):
            if isinstance(node.slice, ast.Name) and node.slice.id == "Any":
                return "global::System.Collections.IEnumerable"
            item = cs_type(node.slice, single, "param")
            if item is None or item == "void":
                return None
            if position == "out":
                return item + "[]"
            if container == "MutableSequence":
                return f"global::System.Collections.Generic.IList<{item}>"
            return f"global::System.Collections.Generic.IEnumerable<{item}>"
    return None


def param_name(name):
    return "@" + name if name in KEYWORDS else name


class Member:
    def __init__(self, name, decl, key):
        self.name, self.decl, self.key = name, decl, key


def method(owner, fn, is_static, interface, single=False):
    """The declaration of one overload, or None when a type is not stubbed or
    the overload has an out or ref parameter (a tuple return in the .pyi)."""
    args = [a for a in fn.args.args if a.arg not in ("self", "cls")]
    params, types = [], []
    for a in args:
        t = cs_type(a.annotation, single, "param")
        if t is None:
            return None
        params.append([t, param_name(a.arg)])
        types.append(ast.dump(a.annotation))
    ret = fn.returns
    if isinstance(ret, ast.Subscript) and isinstance(ret.value, ast.Name) and ret.value.id == "tuple":
        # An out or ref parameter whose position the .pyi lost: never guessed.
        REFUSED.append(f"{owner}.{fn.name}")
        return None
    ret_type = cs_type(ret, single, "return")
    if ret_type is None:
        return None
    generic = "<T>" if re.search(r"\bT\b", " ".join(t for t, _ in params) + " " + ret_type) else ""
    plist = ", ".join(f"{t} {n}" for t, n in params)
    # C# cannot overload on ref/out alone; the first overload wins.
    key = fn.name + "(" + ",".join(t for t, _ in params) + ")"
    if fn.name == "__init__":
        return Member(fn.name, f"public {owner}({plist}) {{ throw null; }}", key)
    if interface:
        return Member(fn.name, f"{ret_type} {fn.name}{generic}({plist});", key)
    static = "static " if is_static else ""
    return Member(fn.name, f"public {static}{ret_type} {fn.name}{generic}({plist}) {{ throw null; }}", key)


def decorators(fn):
    names = set()
    for d in fn.decorator_list:
        if isinstance(d, ast.Name):
            names.add(d.id)
        elif isinstance(d, ast.Attribute):
            names.add(d.attr)  # X.setter
    return names


def class_body(cls, owner, interface, is_struct):
    members, props, seen = [], {}, set()
    single = owner in FLOAT_TYPES
    for fn in cls.body:
        if not isinstance(fn, ast.FunctionDef):
            continue
        deco = decorators(fn)
        name = fn.name
        if name in SKIP_NAMES or name in OVERLAY_MEMBERS.get(owner, ()) or name.startswith(("add_", "remove_", "op_")):
            continue
        if f"{owner}.{name}" in CHECKED:
            USED.add(f"{owner}.{name}")
            if name not in seen:
                seen.add(name)
                for decl in CHECKED[f"{owner}.{name}"]:
                    members.append(Member(name, decl + ";" if interface else decl + " { throw null; }", name))
            continue
        if name in ("__getitem__", "__setitem__"):
            t = cs_type(fn.returns if name == "__getitem__" else fn.args.args[2].annotation, single, "return")
            if t is not None:
                props.setdefault("this[int index]", [t, False, False])[2 if name == "__setitem__" else 1] = True
            continue
        if name.startswith("__") and name != "__init__":
            continue
        if "property" in deco or "setter" in deco:
            t = cs_type(fn.returns if "property" in deco else fn.args.args[1].annotation, single, "return")
            if t is None:
                continue
            entry = props.setdefault(name, [t, "classmethod" in deco or "staticmethod" in deco, False])
            if "setter" in deco:
                entry[2] = True
            continue
        if name == "__init__" and (interface or (is_struct and not fn.args.args[1:])):
            continue
        m = method(owner, fn, "staticmethod" in deco, interface, single)
        if m is not None and m.key not in seen:
            seen.add(m.key)
            members.append(m)
        elif m is not None and "double" in m.key:
            # Python's float hid a float/double overload pair: emit the float one too.
            m2 = method(owner, fn, "staticmethod" in deco, interface, single=True)
            if m2 is not None and m2.key not in seen:
                seen.add(m2.key)
                members.append(m2)
    for name, (t, static, settable) in props.items():
        if name == "this[int index]":
            get, sett = static, settable  # reused slots: has getter, has setter
            acc = ("get; " if get else "") + ("set; " if sett else "") if interface else \
                ("get { throw null; } " if get else "") + ("set { throw null; } " if sett else "")
            decl = f"{t} this[int index] {{ {acc}}}" if interface else f"public {t} this[int index] {{ {acc}}}"
        elif interface:
            decl = f"{t} {name} {{ get; {'set; ' if settable else ''}}}"
        else:
            decl = (f"public {'static ' if static else ''}{t} {name} "
                    f"{{ get {{ throw null; }} {'set { throw null; } ' if settable else ''}}}")
        members.append(Member(name, decl, name))
    return [m for m in members if in_rhino7(owner, "Item" if m.name == "this[int index]" else m.name)]


def emit_class(ns, cls, out):
    name = cls.name
    bases = [b.id for b in cls.bases if isinstance(b, ast.Name)]
    if "Enum" in bases:
        values = [(s.targets[0].id, s.value.value) for s in cls.body
                  if isinstance(s, ast.Assign) and isinstance(s.value, ast.Constant) and in_rhino7(name, s.targets[0].id)]
        wide = any(not -2**31 <= v < 2**31 for _, v in values)
        out.append(f"    public enum {name}{' : long' if wide else ''}\n    {{")
        out.extend(f"        {n} = {v}," for n, v in values)
        out.append("    }")
        return
    interface, is_struct = name in INTERFACES, name in STRUCTS
    base = next((QUALIFIED[b] for b in bases if b in QUALIFIED), None)
    members = class_body(cls, name, interface, is_struct)
    kind = "interface" if interface else "struct" if is_struct else "class"
    out.append(f"    public partial {kind} {name}" + (f" : {base}" if base else "") + "\n    {")
    has_ctor = any(m.name == "__init__" for m in members)
    if not interface and not is_struct and not has_ctor and name not in OVERLAY_MEMBERS:
        out.append(f"        internal {name}() {{ }}")  # not constructible from outside, as in the real API
    for m in members:
        out.append("        " + m.decl)
    out.append("    }")


# Class name -> (base names, member names) of McNeel's Rhino 7 stubs, or
# None when no --rhino7 folder was given.
RHINO7 = None
# Members the 7.x stubs leave out with the generic base they live on:
# RhinoCommon 7 declares `Polyline : Point3dList : RhinoList<Point3d>`, and
# RhinoList<T> has had Count and the indexer since Rhino 5 (API
# documentation, T_Rhino_Collections_RhinoList_1.htm). Only members the
# plug-in uses are listed.
RHINO7_DOCUMENTED = {"Polyline": {"Count", "Item"}}
# "Class.Member" of the Rhino 8 stubs that Rhino 7 lacks (dropped).
MISSING_IN_RHINO7 = []


def read_rhino7(folder):
    """The classes of rhino-stubs / grasshopper-stubs 7.x. Those files are not
    all valid Python (`Set(Byte)`, `#None = -1`), so read them line by line:
    `class Name(Base):`, then `def Member(` and `Value = n` inside it."""
    classes = {}
    for path in sorted(Path(folder).rglob("*.pyi")):
        current = None
        for line in path.read_text(encoding="utf-8").splitlines():
            head = re.match(r"class (\w+)(?:\(([^)]*)\))?:", line)
            if head:
                bases = [b.strip().split(".")[-1] for b in (head.group(2) or "").split(",") if b.strip()]
                entry = classes.setdefault(head.group(1), (set(), set()))
                entry[0].update(bases)
                current = entry[1]
                continue
            if current is None:
                continue
            member = re.match(r"    (?:def (\w+)\(|(\w+) = )", line)
            if member:
                current.add(member.group(1) or member.group(2))
    for name, members in RHINO7_DOCUMENTED.items():
        classes.setdefault(name, (set(), set()))[1].update(members)
    return classes


def in_rhino7(owner, name):
    """True when Rhino 7 has the member on the class or one of its bases (or when not checking)."""
    if RHINO7 is None:
        return True
    todo, seen = [owner], set()
    while todo:
        cls = todo.pop()
        if cls in seen or cls not in RHINO7:
            continue
        seen.add(cls)
        bases, members = RHINO7[cls]
        if name in members:
            return True
        todo.extend(bases)
    MISSING_IN_RHINO7.append(f"{owner}.{name}")
    return False


def main():
    global RHINO7
    args = sys.argv[1:]
    if len(args) not in (2, 4) or (len(args) == 4 and args[2] != "--rhino7"):
        sys.exit("usage: generate.py <folder with Rhino/ and Grasshopper/> <output .cs> [--rhino7 <folder>]")
    root, target = Path(args[0]), Path(args[1])
    for key, decls in FIXUPS.items():
        if any(re.search(r"\b(out|ref) ", d) for d in decls):
            sys.exit(f"generate.py: FIXUPS[{key}] has an out or ref parameter; such members belong in OUT_REF, checked against the API documentation")
    if len(args) == 4:
        RHINO7 = read_rhino7(args[3])
        for ns, names in WANTED.items():
            for name in names:
                if name not in RHINO7:
                    sys.exit(f"generate.py: {ns}.{name} is not in the Rhino 7 stubs under {args[3]}")
        # The overlay's public members are in the Rhino 7 stubs too (the protected ones are not listed there).
        for owner, members in OVERLAY_MEMBERS.items():
            for member in sorted(members - PROTECTED_OVERLAY):
                if not in_rhino7(owner, member):
                    sys.exit(f"generate.py: the overlay declares {owner}.{member}, which Rhino 7 lacks")
    source = "rhino-stubs-typed and grasshopper-stubs-typed 8.20.25157"
    if RHINO7 is not None:
        source += ",\n// keeping only the members rhino-stubs / grasshopper-stubs 7.x list"
    out = [f"// Generated by grasshopper/stubs/generate.py from {source}.",
           "// Signatures only; do not edit.",
           "#pragma warning disable 108, 109, 114, 660, 661, 3021"]
    for ns, names in WANTED.items():
        path = root.joinpath(*ns.split("."), "__init__.pyi")
        tree = ast.parse(path.read_text(encoding="utf-8"))
        classes = {c.name: c for c in tree.body if isinstance(c, ast.ClassDef)}
        out.append(f"namespace {ns}\n{{")
        for name in names:
            if name not in classes:
                sys.exit(f"generate.py: {name} not found in {path}")
            emit_class(ns, classes[name], out)
        out.append("}")
    stale = sorted(set(CHECKED) - USED)
    if stale:
        sys.exit("generate.py: checked declarations for members the stubs do not have: " + ", ".join(stale))
    target.write_text("\n".join(out) + "\n", encoding="utf-8")
    refused = sorted(set(REFUSED))
    print(f"generate.py: {len(OUT_REF)} checked out/ref members; {len(refused)} other out/ref overloads refused"
          + (f"; {len(set(MISSING_IN_RHINO7))} members absent from Rhino 7 dropped" if RHINO7 is not None else ""))


if __name__ == "__main__":
    main()
