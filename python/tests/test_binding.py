"""Every function of include/weft.h is declared for ctypes and reached by a
Python function; the Python option names match the header's constants."""

import re
from pathlib import Path

import weft
from weft import _lib, _ops

PACKAGE = Path(weft.__file__).parent

# Declared and callable through weft.lib, but with no wrapper of their own,
# because the package does the same through another function:
NO_WRAPPER = {
    # The message is read by every failing call and lands in WeftError.message.
    "weft_last_error_message",
}


def header_functions(header):
    return set(re.findall(r"^[A-Za-z_][\w\s\*]*?\b(weft_\w+)\(", header, re.M))


def test_the_header_is_parsed(header):
    names = header_functions(header)
    assert {"weft_mesh_new", "weft_catmull_clark", "weft_tile", "weft_read_mesh_file"} <= names
    assert len(names) > 80


def test_every_header_function_is_declared(header):
    missing = header_functions(header) - set(_lib._SIGNATURES)
    assert not missing, f"functions of weft.h with no ctypes declaration in weft/_lib.py: {sorted(missing)}"
    stale = set(_lib._SIGNATURES) - header_functions(header)
    assert not stale, f"declarations of functions weft.h no longer has: {sorted(stale)}"


def test_every_declaration_has_the_header_argument_count(header):
    for name, (_, argtypes) in _lib._SIGNATURES.items():
        match = re.search(rf"\b{name}\(([^)]*)\);", header)
        arguments = match.group(1).strip()
        count = 0 if arguments in ("", "void") else arguments.count(",") + 1
        assert len(argtypes) == count, f"{name}: {len(argtypes)} ctypes arguments, {count} in weft.h"


def test_every_declared_function_is_called_by_a_wrapper():
    source = "".join(p.read_text(encoding="utf-8") for p in PACKAGE.glob("*.py") if p.name != "_lib.py")
    used = set(re.findall(r"lib\.(weft_\w+)", source))
    unreached = set(_lib._SIGNATURES) - used - NO_WRAPPER
    assert not unreached, f"declared but called by no Python function: {sorted(unreached)}"
    assert "weft_last_error_message" in (PACKAGE / "_lib.py").read_text(encoding="utf-8")


def header_defines(header, prefix):
    return {name: float(value) for name, value in re.findall(rf"#define ({prefix}\w*) ([\d.]+)", header)}


def test_option_names_match_the_header_constants(header):
    tables = {
        "WEFT_NAKED_EDGES_": _ops.NAKED_EDGES,
        "WEFT_SCHEME_": _ops.SCHEMES,
        "WEFT_CREASING_": _ops.CREASING,
        "WEFT_TRIANGLES_": _ops.TRIANGLES,
        "WEFT_FACE_VARYING_": _ops.FACE_VARYING,
        "WEFT_PLATONIC_": _ops.PLATONIC,
        "WEFT_SIDED_": _ops.SIDED,
        "WEFT_OFFSET_": _ops.OFFSET,
        "WEFT_INSET_": _ops.INSET,
        "WEFT_SMOOTH_DIRECTION_": _ops.SMOOTH_DIRECTION,
        "WEFT_TILE_FILL_": _ops.TILE_FILL,
        "WEFT_TILE_FACES_": _ops.TILE_FACES,
        "WEFT_DUAL_": _ops.DUAL,
    }
    for prefix, table in tables.items():
        defines = header_defines(header, prefix)
        expected = {name[len(prefix):].lower().replace("_", "-"): int(value) for name, value in defines.items()}
        assert table == expected, f"{prefix}*: Python has {table}, weft.h {expected}"
    assert header_defines(header, "WEFT_DEFAULT_WELD_TOLERANCE")["WEFT_DEFAULT_WELD_TOLERANCE"] == weft.DEFAULT_WELD_TOLERANCE
    assert header_defines(header, "WEFT_SHARPNESS_INFINITE")["WEFT_SHARPNESS_INFINITE"] == weft.SHARPNESS_INFINITE


def test_status_values_match_the_header(header):
    for name, value in re.findall(r"^\s+WEFT_STATUS_(\w+) = (\d+),", header, re.M):
        assert getattr(weft.Status, name) == int(value), name


def test_version_matches_the_header(header):
    parts = [re.search(rf"#define WEFT_VERSION_{p} (\d+)", header).group(1) for p in ("MAJOR", "MINOR", "PATCH")]
    assert weft.version() == ".".join(parts) == weft.__version__


def test_every_public_function_has_a_docstring():
    for name in dir(weft):
        value = getattr(weft, name)
        if callable(value) and not name.startswith("_"):
            assert value.__doc__ and value.__doc__.strip(), f"weft.{name} has no docstring"
