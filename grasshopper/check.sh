#!/usr/bin/env bash
# Compile check of the Grasshopper components without Rhino or NuGet:
#  1. generates C# reference stubs of RhinoCommon and Grasshopper from the
#     typed Python stub packages (downloaded once into stubs/build/) plus the
#     hand-written overlay, and compiles the components against them;
#  2. compiles each case of tests/WrongOverload.cs and expects it to FAIL,
#     proving the stubs reject a wrong overload, a missing ref, a misspelled
#     member and a wrong pointer type;
#  3. runs the Rhino-free mesh conversion tests on Mono.
# Closing line: "grasshopper compile check: N passed, N failed".
set -uo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(dirname "$here")
build="$here/build"
stubs="$here/stubs/build"
version=8.20.25157
mkdir -p "$build" "$stubs"
passed=0 failed=0
pass() { echo "ok   $1"; passed=$((passed + 1)); }
fail() { echo "FAIL $1"; failed=$((failed + 1)); }
finish() { echo "grasshopper compile check: $passed passed, $failed failed"; [ "$failed" -eq 0 ]; exit $?; }

for tool in mcs mono python3 cargo; do
  command -v "$tool" >/dev/null || { fail "$tool not found (install mono-devel, python3)"; finish; }
done

# The typed stub packages, fetched once.
if [ ! -f "$stubs/pyi/Rhino/Geometry/__init__.pyi" ] || [ ! -f "$stubs/pyi/Grasshopper/Kernel/__init__.pyi" ]; then
  if ! ls "$stubs"/grasshopper_stubs_typed-$version-*.whl "$stubs"/rhino_stubs_typed-$version-*.whl >/dev/null 2>&1; then
    python3 -m pip download --quiet --no-deps --dest "$stubs" \
      "grasshopper-stubs-typed==$version" "rhino-stubs-typed==$version" || { fail "download of the stub packages"; finish; }
  fi
  rm -rf "$stubs/pyi" && mkdir -p "$stubs/pyi"
  for wheel in "$stubs"/*-$version-*.whl; do
    python3 -m zipfile -e "$wheel" "$stubs/pyi" || { fail "unpacking $wheel"; finish; }
  done
fi

python3 "$here/stubs/generate.py" "$stubs/pyi" "$build/RhinoStubs.cs" || { fail "stub generation"; finish; }
mcs -sdk:4.8-api -langversion:7.2 -unsafe -nologo -target:library -r:System.Drawing.dll \
  -out:"$build/RhinoStubs.dll" "$build/RhinoStubs.cs" "$here/stubs/overlay.cs" || { fail "stub compilation"; finish; }

mcs_flags=(-sdk:4.8-api -langversion:7.2 -nologo -warnaserror)
mcs "${mcs_flags[@]}" -target:library -out:"$build/Weft.Interop.dll" "$root"/dotnet/Weft/*.cs \
  || { fail "wrapper compilation"; finish; }

# 1. The components against the stubs, with their icons embedded.
resources=()
for png in "$here"/Weft.Grasshopper/Icons/*.png; do
  [ -f "$png" ] && resources+=("-resource:$png,Weft.Grasshopper.Icons.$(basename "$png")")
done
if mcs "${mcs_flags[@]}" -unsafe -target:library -out:"$build/Weft.Grasshopper.gha" \
    -r:System.Drawing.dll -r:"$build/RhinoStubs.dll" -r:"$build/Weft.Interop.dll" "${resources[@]}" \
    $(find "$here/Weft.Grasshopper" -name '*.cs' | sort); then
  pass "components compile against the RhinoCommon and Grasshopper stubs"
else
  fail "components compile against the RhinoCommon and Grasshopper stubs"
fi

# Component GUIDs are fixed forever; two components must never share one.
duplicates=$(grep -rhoE 'new Guid\("[0-9a-f-]+"\)' "$here/Weft.Grasshopper" | sort | uniq -d)
if [ -z "$duplicates" ]; then pass "component GUIDs are distinct"; else fail "duplicate GUIDs: $duplicates"; fi

# Every icon a component names is embedded, 24 x 24.
missing=""
for name in $(grep -rhoE '"[a-z_]+"(, "[^"]*", "[^"]*")?\)$' "$here/Weft.Grasshopper/Components" | grep -oE '^"[a-z_]+"' | tr -d '"' | sort -u); do
  png="$here/Weft.Grasshopper/Icons/$name.png"
  if [ ! -f "$png" ] || [ "$(python3 -c 'import struct,sys; d=open(sys.argv[1],"rb").read(24); print(struct.unpack(">II", d[16:24]))' "$png")" != "(24, 24)" ]; then
    missing="$missing $name"
  fi
done
if [ -z "$missing" ]; then pass "every component icon is a 24 x 24 PNG"; else fail "icons missing or not 24 x 24:$missing"; fi

# 2. Deliberately wrong code must be refused.
for case in 1 2 3 4; do
  if mcs "${mcs_flags[@]}" -unsafe -target:library -define:CASE_$case -out:"$build/Wrong$case.dll" \
      -r:System.Drawing.dll -r:"$build/RhinoStubs.dll" "$here/tests/WrongOverload.cs" >"$build/wrong$case.log" 2>&1; then
    fail "wrong snippet CASE_$case was accepted by the stubs"
  else
    pass "wrong snippet CASE_$case refused: $(grep -o 'error CS[0-9]*' "$build/wrong$case.log" | head -1)"
  fi
done
# ... while the same file without a case compiles, so the refusals are the cases' own.
if mcs "${mcs_flags[@]}" -unsafe -target:library -out:"$build/Wrong0.dll" \
    -r:System.Drawing.dll -r:"$build/RhinoStubs.dll" "$here/tests/WrongOverload.cs"; then
  pass "the snippet without a wrong case compiles"
else
  fail "the snippet without a wrong case compiles"
fi

# 3. The Rhino-free conversions, run against the native library.
(cd "$root" && cargo build --lib --quiet) || { fail "cargo build --lib"; finish; }
cp "$root/target/debug/libweft.so" "$build/"
if mcs "${mcs_flags[@]}" -target:exe -out:"$build/Conversion.Tests.exe" -r:"$build/Weft.Interop.dll" \
    "$here/tests/ConversionTests.cs" "$here/tests/CreaseInputTests.cs" "$root/dotnet/tests/Runner.cs" \
    "$here/Weft.Grasshopper/MeshArrays.cs" "$here/Weft.Grasshopper/FlatGeometry.cs" "$here/Weft.Grasshopper/RefinerCache.cs" \
    "$here/Weft.Grasshopper/CreaseInputs.cs" \
  && LD_LIBRARY_PATH="$root/target/debug${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" mono --debug "$build/Conversion.Tests.exe"; then
  pass "mesh conversion tests"
else
  fail "mesh conversion tests"
fi
finish
