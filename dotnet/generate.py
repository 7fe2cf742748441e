#!/usr/bin/env python3
"""Generates the C# mirror of Weft's C ABI from include/weft.h:

  dotnet/Weft/NativeMethods.cs  a [DllImport] per function, in the header's
                                order, and the structs passed by reference
  dotnet/Weft/Enums.cs          an enum per family of WEFT_* constants, and
                                the other constants
  dotnet/Weft/WeftStatus.cs     the WeftStatus enum

Each C type maps to one C# type: uint32_t -> uint, int64_t -> long, size_t
-> UIntPtr, double -> double, bool -> a one-byte bool (byte in arrays),
WeftStatus -> uint, const T * -> T[] (pinned for the call), T * -> [Out]
T[] (size_t * -> out UIntPtr, a count), struct WeftX ** -> out handle,
const struct WeftX * -> the handle, const struct S * -> ref S, struct S *
-> out S, returned pointers -> IntPtr. The few parameters the header's
types alone do not settle are named in the tables below.

dotnet/test.sh regenerates into a temporary folder and fails on any
difference, as tests/header.rs does for the header. Python 3 standard
library only.

usage: generate.py [--header include/weft.h] [--out dotnet/Weft]
"""
import argparse
import re
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent

# Opaque handles and the SafeHandle that owns each.
HANDLES = {"WeftMesh": "WeftMeshHandle", "WeftRefiner": "WeftRefinerHandle", "WeftLimitSurface": "WeftLimitSurfaceHandle", "WeftCells": "WeftCellsHandle"}
# Structs generated here (internal, passed by reference) under their C# names.
NATIVE_STRUCTS = {"WeftSubdivisionOptions": "NativeSubdivisionOptions", "WeftMeshInfo": "NativeMeshInfo"}
# Structs whose public C# declaration is hand-written in Structs.cs (same layout, documented API).
PUBLIC_STRUCTS = {"WeftPlane", "WeftWeldReport", "WeftOrientReport", "WeftTNode"}
# A const pointer to one of these may be NULL: passed as an array of one element or null.
OPTIONAL_STRUCTS = {"WeftPlane"}
# A non-const pointer to one of these is a caller buffer of many elements, not one result.
ELEMENT_STRUCTS = {"WeftTNode"}
# Const pointers the library keeps after the call (a lent array): IntPtr, for
# memory the caller pins or allocates natively, never an array pinned only
# for the call.
LENT_POINTERS = {("weft_mesh_new_borrowed", "positions"), ("weft_mesh_new_borrowed", "face_indices")}
# size_t * parameters that are caller buffers rather than one count.
SIZE_ARRAYS = {("weft_naked_boundaries", "out_point_counts")}
SCALARS = {"uint32_t": "uint", "int32_t": "int", "int64_t": "long", "uint64_t": "ulong", "size_t": "UIntPtr",
           "double": "double", "float": "float", "bool": "bool", "WeftStatus": "uint",
           # const char * is a NUL-terminated UTF-8 path: byte[] from Encoding.UTF8 plus a 0.
           "char": "byte"}
BOOL = "[MarshalAs(UnmanagedType.U1)] bool"

# Families of WEFT_* constants and the enum each becomes.
ENUMS = [
    ("NakedEdges", "WEFT_NAKED_EDGES_", "How subdivision treats naked (boundary) edges (WEFT_NAKED_EDGES_*)."),
    ("Scheme", "WEFT_SCHEME_", "A subdivision scheme (WEFT_SCHEME_*)."),
    ("Creasing", "WEFT_CREASING_", "How semi-sharp creases soften from level to level (WEFT_CREASING_*; OpenSubdiv's crease method)."),
    ("TriangleRule", "WEFT_TRIANGLES_", "Catmull-Clark's weights at triangles (WEFT_TRIANGLES_*; OpenSubdiv's TriangleSubdivision)."),
    ("FaceVaryingLinear", "WEFT_FACE_VARYING_", "Where face-varying values (UVs) are interpolated linearly (WEFT_FACE_VARYING_*; OpenSubdiv's FVarLinearInterpolation)."),
    ("SmoothDirection", "WEFT_SMOOTH_DIRECTION_", "Which way LaplacianHC lets a vertex move (WEFT_SMOOTH_DIRECTION_*; Weaverbird's orientation input)."),
    ("TileFill", "WEFT_TILE_FILL_", "The pattern Tile fills a face with (WEFT_TILE_FILL_*; Weaverbird's numbers)."),
    ("TileFaces", "WEFT_TILE_FACES_", "Which faces Tile fills (WEFT_TILE_FACES_*; Weaverbird's numbers)."),
    ("OffsetType", "WEFT_OFFSET_", "How Mesh Offset and Mesh Thicken place the offset vertices (WEFT_OFFSET_*)."),
    ("InsetMode", "WEFT_INSET_", "How Mesh Window and Picture Frame measure the inset (WEFT_INSET_*)."),
    ("DualMode", "WEFT_DUAL_", "Where the dual mesh puts its vertices (WEFT_DUAL_*)."),
    ("PlatonicSolid", "WEFT_PLATONIC_", "A Platonic solid (WEFT_PLATONIC_*)."),
    ("SidedSolid", "WEFT_SIDED_", "A solid built on a regular polygon (WEFT_SIDED_*)."),
]
# The other constants, in NativeConstants.
CONSTANTS = {"WEFT_SHARPNESS_INFINITE": "SharpnessInfinite", "WEFT_DEFAULT_WELD_TOLERANCE": "DefaultWeldTolerance",
             "WEFT_SUBDIVISION_OPTIONS_RESERVED": "SubdivisionOptionsReserved",
             "WEFT_MESH_ALLOW_REPEATED_VERTICES": "MeshAllowRepeatedVertices", "WEFT_PATCH_DOUBLES": "PatchDoubles",
             "WEFT_VERSION_MAJOR": "VersionMajor", "WEFT_VERSION_MINOR": "VersionMinor", "WEFT_VERSION_PATCH": "VersionPatch"}


class HeaderError(Exception):
    pass


def pascal(snake):
    return "".join(part[:1].upper() + part[1:].lower() for part in snake.split("_") if part)


def camel(snake):
    p = pascal(snake)
    return p[:1].lower() + p[1:]


def summary(doc):
    """The first paragraph of a /** */ comment as XML doc text."""
    lines = [re.sub(r"^\s*\* ?", "", line) for line in doc.strip().splitlines()]
    paragraph = []
    for line in lines:
        if not line.strip():
            if paragraph:
                break
            continue
        paragraph.append(line.strip())
    text = " ".join(paragraph)
    text = text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")
    return re.sub(r"`([^`]+)`", r"<c>\1</c>", text)


def parse(header):
    """The header's constants, status values, structs and functions, in order."""
    text = header
    status = []
    m = re.search(r"enum WeftStatus\b[^{]*\{(.*?)\};", text, re.S)
    if not m:
        raise HeaderError("enum WeftStatus not found")
    for doc, name, value in re.findall(r"/\*\*(.*?)\*/\s*(WEFT_STATUS_\w+) = (\d+),", m.group(1), re.S):
        status.append((name, int(value), summary(doc)))
    text = text[:m.start()] + text[m.end():]

    structs = []
    for m in re.finditer(r"typedef struct (\w+) \{(.*?)\} \1;", text, re.S):
        fields = []
        for doc, ctype, name, length in re.findall(r"/\*\*(.*?)\*/\s*([^;/]*?)\s*\b(\w+)(?:\[(\w+)\])?;", m.group(2), re.S):
            fields.append((" ".join(ctype.split()), name, summary(doc), length))
        structs.append((m.group(1), fields))
    text = re.sub(r"typedef struct (\w+) \{(.*?)\} \1;", "", text, flags=re.S)

    defines, functions = [], []
    for m in re.finditer(r"/\*\*(.*?)\*/\s*(#define (WEFT_\w+) (\S+)|([^;{}]*?)\b(weft_\w+)\(([^()]*)\);)", text, re.S):
        doc = m.group(1)
        if m.group(3):
            defines.append((m.group(3), m.group(4), summary(doc)))
        else:
            params = [] if m.group(7).strip() in ("", "void") else [" ".join(p.split()) for p in m.group(7).split(",")]
            functions.append((" ".join(m.group(5).split()), m.group(6), params, summary(doc)))
    declared = set(re.findall(r"\b(weft_\w+)\(", re.sub(r"/\*.*?\*/", "", header, flags=re.S)))
    missed = declared - {f[1] for f in functions}
    if missed:
        raise HeaderError("functions without a doc comment, which this parser needs: " + ", ".join(sorted(missed)))
    return defines, status, structs, functions


def split_param(param):
    m = re.match(r"(.*?)\s*\b(\w+)$", param)
    if not m:
        raise HeaderError(f"cannot read the parameter {param!r}")
    return m.group(1).replace(" *", "*").replace("* ", "*").strip(), m.group(2)


def cs_param(function, ctype, name):
    """The C# declaration of one parameter (type and name)."""
    cs_name = camel(name)
    if cs_name in ("params", "base", "out", "ref", "object", "string", "fixed", "checked", "lock"):
        cs_name = "@" + cs_name
    m = re.fullmatch(r"(const )?struct (\w+)(\*const\*|\*\*|\*)", ctype)
    if m:
        const, struct, stars = bool(m.group(1)), m.group(2), m.group(3)
        if struct in HANDLES:
            if stars == "*const*":
                return f"IntPtr[] {cs_name}"
            if stars == "**":
                return f"out {HANDLES[struct]} {cs_name}"
            if function.endswith("_free"):
                return f"IntPtr {cs_name}"
            return f"{HANDLES[struct]} {cs_name}"
        cs_struct = NATIVE_STRUCTS.get(struct, struct)
        if struct not in NATIVE_STRUCTS and struct not in PUBLIC_STRUCTS:
            raise HeaderError(f"{function}: struct {struct} has no C# mirror; add it to NATIVE_STRUCTS or PUBLIC_STRUCTS")
        if stars != "*":
            raise HeaderError(f"{function}: {ctype} {name} is not a supported struct pointer")
        if const:
            return f"{cs_struct}[] {cs_name}" if struct in OPTIONAL_STRUCTS else f"ref {cs_struct} {cs_name}"
        return f"[Out] {cs_struct}[] {cs_name}" if struct in ELEMENT_STRUCTS else f"out {cs_struct} {cs_name}"
    m = re.fullmatch(r"(const )?(\w+)(\*?)", ctype)
    if not m or m.group(2) not in SCALARS:
        raise HeaderError(f"{function}: no C# type for {ctype!r} ({name})")
    const, base, pointer = bool(m.group(1)), m.group(2), bool(m.group(3))
    cs = SCALARS[base]
    if pointer and (function, name) in LENT_POINTERS:
        return f"IntPtr {cs_name}"
    if not pointer:
        return f"{BOOL} {cs_name}" if base == "bool" else f"{cs} {cs_name}"
    element = "byte" if base == "bool" else cs
    if const:
        return f"{element}[] {cs_name}"
    if base == "size_t" and (function, name) not in SIZE_ARRAYS:
        return f"out UIntPtr {cs_name}"
    return f"[Out] {element}[] {cs_name}"


def cs_return(function, ctype):
    ctype = ctype.replace(" *", "*").strip()
    if ctype.endswith("*"):
        return "IntPtr"
    if ctype == "void":
        return "void"
    if ctype not in SCALARS:
        raise HeaderError(f"{function}: no C# type for the return type {ctype!r}")
    return "[return: MarshalAs(UnmanagedType.U1)] bool" if ctype == "bool" else SCALARS[ctype]


def cs_field(struct, ctype, name):
    ctype = ctype.replace(" *", "*").strip()
    field = pascal(name)
    if ctype.endswith("*"):
        return f"public IntPtr {field};"
    base = ctype.replace("const ", "")
    if base not in SCALARS:
        raise HeaderError(f"{struct}.{name}: no C# type for {ctype!r}")
    return f"[MarshalAs(UnmanagedType.U1)] public bool {field};" if base == "bool" else f"public {SCALARS[base]} {field};"


def generated_line():
    return "// Generated from include/weft.h by dotnet/generate.py; do not edit (dotnet/test.sh checks it is current)."


def native_methods(structs, functions, constants):
    out = [generated_line(), "using System;", "using System.Runtime.InteropServices;", "", "namespace Weft", "{"]
    by_name = dict(structs)
    for c_name, cs_name in NATIVE_STRUCTS.items():
        if c_name not in by_name:
            raise HeaderError(f"struct {c_name} not found in the header")
        out += ["    /// <summary>", f"    /// Laid out as <c>{c_name}</c> in <c>include/weft.h</c>.", "    /// </summary>",
                "    [StructLayout(LayoutKind.Sequential)]", f"    internal struct {cs_name}", "    {"]
        for ctype, name, doc, length in by_name[c_name]:
            if not length:
                out += [f"        /// <summary>{doc}</summary>", "        " + cs_field(c_name, ctype, name)]
                continue
            # A fixed array of scalars: one field per element keeps the struct blittable.
            count = int(length) if length.isdigit() else int(constants.get(length, "0"))
            if count == 0:
                raise HeaderError(f"{c_name}.{name}: array length {length!r} is not a number or a #define")
            for i in range(count):
                out += [f"        /// <summary>{doc} (element {i})</summary>", "        " + cs_field(c_name, ctype, f"{name}{i}")]
        out += ["    }", ""]
    out += ["    /// <summary>",
            "    /// The exports of <c>include/weft.h</c>, one for one, in the header's order.",
            "    /// Call these only through the wrapper classes, which load the native library first.",
            "    /// </summary>",
            "    internal static class NativeMethods",
            "    {",
            "        /// <summary>The library's file name without prefix or extension.</summary>",
            "        internal const string Library = \"weft\";",
            ""]
    for ret, name, params, doc in functions:
        decls = [cs_param(name, *split_param(p)) for p in params]
        out += [f"        /// <summary>{doc}</summary>",
                "        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]"]
        returns = cs_return(name, ret)
        attribute = ""
        if returns.startswith("[return:"):
            attribute, returns = returns[:returns.index("]") + 1], "bool"
            out.append("        " + attribute)
        out.append(f"        internal static extern {returns} {name}({', '.join(decls)});")
        out.append("")
    out[-1:] = ["    }", "}"]
    return "\n".join(out) + "\n"


def enums(defines):
    families = {cs: [] for cs, _, _ in ENUMS}
    constants = []
    for name, value, doc in defines:
        if name in CONSTANTS:
            constants.append((CONSTANTS[name], value, doc))
            continue
        family = max((e for e in ENUMS if name.startswith(e[1])), key=lambda e: len(e[1]), default=None)
        if family is None:
            raise HeaderError(f"{name} belongs to no family: add its prefix to ENUMS or the name to CONSTANTS in dotnet/generate.py")
        if not re.fullmatch(r"\d+", value):
            raise HeaderError(f"{name} = {value} is not a whole number")
        families[family[0]].append((pascal(name[len(family[1]):]), int(value), doc))
    out = [generated_line(), "namespace Weft", "{"]
    for cs, prefix, doc in ENUMS:
        if not families[cs]:
            raise HeaderError(f"no {prefix}* constant in the header for enum {cs}")
        out += [f"    /// <summary>{doc}</summary>", f"    public enum {cs} : uint", "    {"]
        for value_name, value, value_doc in families[cs]:
            out += [f"        /// <summary>{value_doc}</summary>", f"        {value_name} = {value},"]
        out += ["    }", ""]
    out += ["    /// <summary>The header's other constants.</summary>", "    internal static class NativeConstants", "    {"]
    for cs, value, doc in constants:
        kind = "double" if "." in value else "uint"
        out += [f"        /// <summary>{doc}</summary>", f"        internal const {kind} {cs} = {value};"]
    out += ["    }", "}"]
    return "\n".join(out) + "\n"


def weft_status(status):
    out = [generated_line(), "namespace Weft", "{", "    /// <summary>",
           "    /// The outcome of every Weft call, <c>WeftStatus</c> in <c>include/weft.h</c> value for",
           "    /// value. New values are only ever added at the end.", "    /// </summary>",
           "    public enum WeftStatus : uint", "    {"]
    for name, value, doc in status:
        out += [f"        /// <summary>{doc}</summary>", f"        {pascal(name[len('WEFT_STATUS_'):])} = {value},"]
    out += ["    }", "}"]
    return "\n".join(out) + "\n"


def generate(header_text):
    defines, status, structs, functions = parse(header_text)
    constants = {name: value for name, value, _ in defines}
    return {"NativeMethods.cs": native_methods(structs, functions, constants), "Enums.cs": enums(defines), "WeftStatus.cs": weft_status(status)}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--header", default=str(ROOT / "include" / "weft.h"))
    parser.add_argument("--out", default=str(ROOT / "dotnet" / "Weft"))
    args = parser.parse_args()
    try:
        files = generate(Path(args.header).read_text(encoding="utf-8"))
    except (HeaderError, OSError) as e:
        sys.exit(f"dotnet/generate.py: {e}")
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    for name, text in files.items():
        (out / name).write_text(text, encoding="utf-8")
    print(f"dotnet/generate.py: wrote {', '.join(files)} to {out}")


if __name__ == "__main__":
    main()
