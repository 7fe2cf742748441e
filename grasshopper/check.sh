#!/usr/bin/env bash
# Checks of the Grasshopper plug-in without Rhino or NuGet:
#  1. generates C# reference stubs of RhinoCommon and Grasshopper from the
#     typed Python stub packages (downloaded once into stubs/build/) plus the
#     hand-written overlay, and compiles the components against them; then
#     again keeping only the members McNeel's Rhino 7 stubs (rhino-stubs /
#     grasshopper-stubs 7.7.21140) list, so every member used exists in Rhino 7;
#  2. compiles each case of tests/WrongOverload.cs and expects it to FAIL,
#     proving the stubs reject a wrong overload, a missing or misplaced
#     out/ref, a misspelled member, a wrong pointer type and (against the
#     Rhino 7 stubs) a Rhino 8-only member;
#  3. runs the Rhino-free conversion tests on Mono;
#  4. replays RhinoMeshes' and RhinoSurfaces' calls on openNURBS (rhino3dm
#     8.35.0 from PyPI, installed into build/py);
#  5. assembles the three Yak layouts with package.sh (the Linux library
#     standing in for the Windows and Mac ones) and checks every file and
#     manifest, and that the project references RhinoCommon 7.x for net48
#     and 8.x for net7.0.
# Closing line: "grasshopper compile check: N passed, N failed".
set -uo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(dirname "$here")
build="$here/build"
stubs="$here/stubs/build"
version=8.20.25157
rhino7=7.7.21140
rhino3dm_version=8.35.0
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

# McNeel's Rhino 7 stubs (source archives), fetched once.
if [ ! -d "$stubs/pyi7/Rhino" ] || [ ! -d "$stubs/pyi7/Grasshopper" ]; then
  if ! ls "$stubs"/Rhino-stubs-$rhino7.tar.gz "$stubs"/Grasshopper-stubs-$rhino7.tar.gz >/dev/null 2>&1; then
    python3 -m pip download --quiet --no-deps --dest "$stubs" \
      "rhino-stubs==$rhino7" "grasshopper-stubs==$rhino7" || { fail "download of the Rhino 7 stub packages"; finish; }
  fi
  rm -rf "$stubs/pyi7" && mkdir -p "$stubs/pyi7"
  python3 - "$stubs" "$rhino7" <<'PY' || { fail "unpacking the Rhino 7 stubs"; finish; }
import sys, tarfile, pathlib, shutil
stubs, version = pathlib.Path(sys.argv[1]), sys.argv[2]
for name in ("Rhino", "Grasshopper"):
    with tarfile.open(stubs / f"{name}-stubs-{version}.tar.gz") as archive:
        archive.extractall(stubs / "unpacked7")
    shutil.copytree(stubs / "unpacked7" / f"{name}-stubs-{version}" / f"{name}-stubs", stubs / "pyi7" / name)
PY
fi

python3 "$here/stubs/generate.py" "$stubs/pyi" "$build/RhinoStubs.cs" || { fail "stub generation"; finish; }
python3 "$here/stubs/generate.py" "$stubs/pyi" "$build/RhinoStubs7.cs" --rhino7 "$stubs/pyi7" || { fail "Rhino 7 stub generation"; finish; }
for flavour in "" 7; do
  mcs -sdk:4.8-api -langversion:7.2 -unsafe -nologo -target:library -r:System.Drawing.dll \
    -out:"$build/RhinoStubs$flavour.dll" "$build/RhinoStubs$flavour.cs" "$here/stubs/overlay.cs" || { fail "stub compilation $flavour"; finish; }
done

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
if mcs "${mcs_flags[@]}" -unsafe -target:library -out:"$build/Weft.Grasshopper.rhino7.gha" \
    -r:System.Drawing.dll -r:"$build/RhinoStubs7.dll" -r:"$build/Weft.Interop.dll" \
    $(find "$here/Weft.Grasshopper" -name '*.cs' | sort); then
  pass "every RhinoCommon and Grasshopper member the components use is in Rhino 7 (stubs $rhino7)"
else
  fail "every RhinoCommon and Grasshopper member the components use is in Rhino 7 (stubs $rhino7)"
fi

# Component GUIDs are fixed forever; every component class has one and two never share one.
duplicates=$(grep -rhoE '\[Guid\("[0-9a-f-]+"\)\]' "$here/Weft.Grasshopper" | sort | uniq -d)
classes=$(grep -rhcE '^    public sealed class \w+ : \w+Component$' "$here/Weft.Grasshopper" | awk '{ s += $1 } END { print s + 0 }')
guids=$(grep -rhB1 -E '^    public sealed class \w+ : \w+Component$' "$here/Weft.Grasshopper" | grep -cE '^    \[Guid\("[0-9a-f-]{36}"\)\]$')
if [ -z "$duplicates" ] && [ "$classes" -gt 0 ] && [ "$classes" -eq "$guids" ]; then
  pass "each of the $classes components has its own [Guid]"
else
  fail "component GUIDs: $guids of $classes classes have one${duplicates:+; shared: $duplicates}"
fi

# Every component's name and nickname are the README's, row for row (users compare them with Weaverbird's there).
unlisted=$(python3 - "$here" <<'PY'
import re, sys, pathlib
here = pathlib.Path(sys.argv[1])
source = "\n".join(p.read_text(encoding="utf-8") for p in (here / "Weft.Grasshopper" / "Components").glob("*.cs"))
pairs = re.findall(r':\s*base\((?:Scheme\.\w+,\s*)?"([^"]+)",\s*"([^"]+)"', source)
rows = set(re.findall(r"^\| [A-Z][a-z]+ \| ([^|]+?) \| ([^|]+?) \|", (here / "README.md").read_text(encoding="utf-8"), re.M))
print(len(pairs) if pairs else "none found", *[f"{n} ({k})" for n, k in pairs if (n, k) not in rows], sep="; ")
PY
)
case "$unlisted" in
  [0-9]*) if [ "${unlisted#*;}" = "$unlisted" ]; then pass "the README lists all $unlisted components by name and nickname"; else fail "components missing from the README table: ${unlisted#*; }"; fi ;;
  *) fail "no component names found: $unlisted" ;;
esac

# Every icon a component names is embedded, 24 x 24.
missing=""
for name in $(grep -rhoE '"[a-z_]+"(, "[^"]*", "[^"]*")?\)$' "$here/Weft.Grasshopper/Components" | grep -oE '^"[a-z_]+"' | tr -d '"' | sort -u); do
  png="$here/Weft.Grasshopper/Icons/$name.png"
  if [ ! -f "$png" ] || [ "$(python3 -c 'import struct,sys; d=open(sys.argv[1],"rb").read(24); print(struct.unpack(">II", d[16:24]))' "$png")" != "(24, 24)" ]; then
    missing="$missing $name"
  fi
done
if [ -z "$missing" ]; then pass "every component icon is a 24 x 24 PNG"; else fail "icons missing or not 24 x 24:$missing"; fi

# 2. Deliberately wrong code must be refused (without -warnaserror, so a case fails for its own error).
wrong_flags=(-sdk:4.8-api -langversion:7.2 -nologo -unsafe -target:library -r:System.Drawing.dll)
for case in 1 2 3 4 5 6 7 8; do
  if mcs "${wrong_flags[@]}" -define:CASE_$case -out:"$build/Wrong$case.dll" \
      -r:"$build/RhinoStubs.dll" "$here/tests/WrongOverload.cs" >"$build/wrong$case.log" 2>&1; then
    fail "wrong snippet CASE_$case was accepted by the stubs"
  else
    pass "wrong snippet CASE_$case refused: $(grep -o 'error CS[0-9]*' "$build/wrong$case.log" | head -1)"
  fi
done
# ... while the same file without a case compiles, so the refusals are the cases' own.
for flavour in "" 7; do
  if mcs "${mcs_flags[@]}" -unsafe -target:library -out:"$build/Wrong0$flavour.dll" \
      -r:System.Drawing.dll -r:"$build/RhinoStubs$flavour.dll" "$here/tests/WrongOverload.cs"; then
    pass "the snippet without a wrong case compiles${flavour:+ against the Rhino 7 stubs}"
  else
    fail "the snippet without a wrong case compiles${flavour:+ against the Rhino 7 stubs}"
  fi
done
# A Rhino 8-only member compiles against the Rhino 8 stubs and is refused by the Rhino 7 ones.
if mcs "${wrong_flags[@]}" -define:RHINO8_ONLY -out:"$build/Rhino8Only.dll" -r:"$build/RhinoStubs.dll" "$here/tests/WrongOverload.cs" \
    && ! mcs "${wrong_flags[@]}" -define:RHINO8_ONLY -out:"$build/Rhino8Only7.dll" -r:"$build/RhinoStubs7.dll" "$here/tests/WrongOverload.cs" >"$build/rhino8only.log" 2>&1; then
  pass "a Rhino 8-only member is refused by the Rhino 7 stubs: $(grep -o 'error CS[0-9]*' "$build/rhino8only.log" | head -1)"
else
  fail "a Rhino 8-only member is refused by the Rhino 7 stubs"
fi

# 3. The Rhino-free conversions, run against the native library.
(cd "$root" && cargo build --lib --quiet) || { fail "cargo build --lib"; finish; }
cp "$root/target/debug/libweft.so" "$build/"
if mcs "${mcs_flags[@]}" -target:exe -out:"$build/Conversion.Tests.exe" -r:"$build/Weft.Interop.dll" \
    "$here/tests/ConversionTests.cs" "$here/tests/CreaseInputTests.cs" "$root/dotnet/tests/Runner.cs" "$root/dotnet/tests/UnitCube.cs" \
    "$here/Weft.Grasshopper/MeshArrays.cs" "$here/Weft.Grasshopper/FlatGeometry.cs" "$here/Weft.Grasshopper/RefinerCache.cs" \
    "$here/Weft.Grasshopper/CreaseInputs.cs" "$here/Weft.Grasshopper/FaceBudget.cs" "$here/Weft.Grasshopper/LimitSamples.cs" \
  && LD_LIBRARY_PATH="$root/target/debug${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" mono --debug "$build/Conversion.Tests.exe"; then
  pass "mesh conversion tests"
else
  fail "mesh conversion tests"
fi

# 4. RhinoMeshes' calls replayed on openNURBS.
if ! PYTHONPATH="$build/py" python3 -c "import rhino3dm; assert rhino3dm.__version__ == '$rhino3dm_version'" 2>/dev/null; then
  PIP_ROOT_USER_ACTION=ignore python3 -m pip install --quiet --disable-pip-version-check --no-deps --upgrade --target "$build/py" "rhino3dm==$rhino3dm_version" \
    || { fail "install of rhino3dm $rhino3dm_version"; finish; }
fi
if PYTHONPATH="$build/py" python3 "$here/tests/replay_rhino_meshes.py" "$here/Weft.Grasshopper/RhinoMeshes.cs"; then
  pass "RhinoMeshes replayed on openNURBS (rhino3dm $rhino3dm_version)"
else
  fail "RhinoMeshes replayed on openNURBS (rhino3dm $rhino3dm_version)"
fi
if PYTHONPATH="$build/py" python3 "$here/tests/replay_rhino_surfaces.py" "$here/Weft.Grasshopper/RhinoSurfaces.cs"; then
  pass "RhinoSurfaces replayed on openNURBS (rhino3dm $rhino3dm_version)"
else
  fail "RhinoSurfaces replayed on openNURBS (rhino3dm $rhino3dm_version)"
fi

# 5. The Yak layouts, with the Linux library standing in for weft.dll and libweft.dylib.
if python3 "$here/tests/check_packages.py" "$here" "$build/Weft.Grasshopper.gha" "$build/Weft.Interop.dll" "$build/libweft.so" "$build/packages"; then
  pass "package.sh lays out the Rhino 7 Windows, Rhino 7 Mac and Rhino 8 packages"
else
  fail "package.sh lays out the Rhino 7 Windows, Rhino 7 Mac and Rhino 8 packages"
fi
# Rhino 7 for Mac runs Mono, and its package puts the native library beside Weft.Interop.dll:
# load the wrapper from a package-like folder, with no library path, the host program elsewhere.
probe="$build/probe" host="$build/probe-host"
rm -rf "$probe" "$host" && mkdir -p "$probe" "$host"
cp "$build/Weft.Interop.dll" "$build/libweft.so" "$probe/"
if mcs "${mcs_flags[@]}" -target:exe -out:"$host/LoadProbe.exe" -r:"$probe/Weft.Interop.dll" "$here/tests/LoadProbe.cs" \
    && loaded=$(cd / && env -u LD_LIBRARY_PATH MONO_PATH="$probe" mono "$host/LoadProbe.exe") && echo "$loaded" | grep -q "$probe/libweft.so"; then
  pass "loaded from a package folder on Mono, the wrapper finds the native library beside it with no library path ($loaded)"
else
  fail "loaded from a package folder on Mono, the wrapper finds the native library beside it with no library path"
fi
finish
