#!/usr/bin/env bash
# Builds the Rust cdylib, compiles the C# wrapper and its tests with Mono's
# mcs against the .NET Framework 4.8 API, and runs them. The last line is the
# runner's "N passed, N failed"; the exit code is non-zero on any failure.
set -uo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(dirname "$here")
build="$here/build"
mkdir -p "$build"

for tool in mcs mono cargo; do
  command -v "$tool" >/dev/null || { echo "dotnet/test.sh: $tool not found (install mono-devel)"; echo "0 passed, 1 failed"; exit 1; }
done

(cd "$root" && cargo build --lib --quiet) || { echo "0 passed, 1 failed"; exit 1; }
native="$root/target/debug/libweft.so"

mcs_flags=(-sdk:4.8-api -langversion:7.2 -warnaserror -nologo -debug)
mcs "${mcs_flags[@]}" -target:library -out:"$build/Weft.Interop.dll" -doc:"$build/Weft.Interop.xml" \
  "$here"/Weft/*.cs 2>&1 || { echo "0 passed, 1 failed"; exit 1; }
mcs "${mcs_flags[@]}" -target:exe -out:"$build/Weft.Tests.exe" \
  -r:"$build/Weft.Interop.dll" "$here"/tests/*.cs 2>&1 || { echo "0 passed, 1 failed"; exit 1; }

# Beside the assembly, as in the plug-in folder; LD_LIBRARY_PATH as a fallback.
cp "$native" "$build/"
WEFT_HEADER="$root/include/weft.h" LD_LIBRARY_PATH="$root/target/debug${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" mono --debug "$build/Weft.Tests.exe"
