#!/usr/bin/env bash
# Builds the Rust cdylib, compiles the C# wrapper and its tests with Mono's
# mcs against the .NET Framework 4.8 API, checks that the generated C# mirror
# of include/weft.h is current, and runs the tests. The last line is
# "dotnet tests: N passed, N failed"; the exit code is non-zero on any failure.
set -uo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(dirname "$here")
build="$here/build"
mkdir -p "$build"

for tool in mcs mono cargo python3; do
  command -v "$tool" >/dev/null || { echo "dotnet/test.sh: $tool not found (install mono-devel)"; echo "0 passed, 1 failed"; exit 1; }
done

(cd "$root" && cargo build --lib --quiet) || { echo "0 passed, 1 failed"; exit 1; }
native="$root/target/debug/libweft.so"

mcs_flags=(-sdk:4.8-api -langversion:7.2 -warnaserror -nologo -debug)
mcs "${mcs_flags[@]}" -target:library -out:"$build/Weft.Interop.dll" -doc:"$build/Weft.Interop.xml" \
  "$here"/Weft/*.cs 2>&1 || { echo "0 passed, 1 failed"; exit 1; }
mcs "${mcs_flags[@]}" -target:exe -out:"$build/Weft.Tests.exe" \
  -r:"$build/Weft.Interop.dll" "$here"/tests/*.cs 2>&1 || { echo "0 passed, 1 failed"; exit 1; }

# The C# mirror of the header is generated: regenerate it and compare, file by
# file, as tests/header.rs does for the header itself.
gen_passed=0 gen_failed=0
generated="$build/generated"
rm -rf "$generated"
if python3 "$here/generate.py" --header "$root/include/weft.h" --out "$generated" >/dev/null; then
  for file in NativeMethods.cs Enums.cs WeftStatus.cs; do
    if diff -u "$here/Weft/$file" "$generated/$file" >"$build/$file.diff"; then
      echo "ok   dotnet/Weft/$file is what dotnet/generate.py makes of include/weft.h"; gen_passed=$((gen_passed + 1))
    else
      echo "FAIL dotnet/Weft/$file differs from include/weft.h; run python3 dotnet/generate.py"; head -20 "$build/$file.diff"
      gen_failed=$((gen_failed + 1))
    fi
  done
  # The comparison notices a size_t declared as uint (the kind of drift a name-and-count check misses).
  sed '0,/UIntPtr outVertexCount/s//uint outVertexCount/' "$here/Weft/NativeMethods.cs" >"$build/Drifted.cs"
  if ! diff -q "$build/Drifted.cs" "$generated/NativeMethods.cs" >/dev/null && grep -q "uint outVertexCount" "$build/Drifted.cs"; then
    echo "ok   a uint where the header has size_t is a difference"; gen_passed=$((gen_passed + 1))
  else
    echo "FAIL a uint where the header has size_t went unnoticed"; gen_failed=$((gen_failed + 1))
  fi
else
  echo "FAIL dotnet/generate.py could not read include/weft.h"; gen_failed=$((gen_failed + 1))
fi

# Beside the assembly, as in the plug-in folder; LD_LIBRARY_PATH as a fallback.
cp "$native" "$build/"
WEFT_HEADER="$root/include/weft.h" LD_LIBRARY_PATH="$root/target/debug${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" mono --debug "$build/Weft.Tests.exe" | tee "$build/tests.log"
status=${PIPESTATUS[0]}
summary=$(tail -1 "$build/tests.log")
passed=$(echo "$summary" | sed -n 's/^\([0-9]*\) passed, \([0-9]*\) failed$/\1/p')
failed=$(echo "$summary" | sed -n 's/^\([0-9]*\) passed, \([0-9]*\) failed$/\2/p')
[ -n "$passed" ] || { passed=0; failed=1; }
[ "$status" -eq 0 ] || [ "$failed" -gt 0 ] || failed=1
echo "dotnet tests: $((passed + gen_passed)) passed, $((failed + gen_failed)) failed"
[ $((failed + gen_failed)) -eq 0 ]
