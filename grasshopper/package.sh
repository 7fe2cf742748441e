#!/usr/bin/env bash
# Lays out the three Yak package folders of the Weft plug-in from built
# binaries; run `yak build` in each (the release workflow does).
#
#   rh7-win/  Rhino 7 for Windows: the net48 build (against RhinoCommon 7.x)
#             at the top, weft.dll (x64) beside it.
#   rh7-mac/  Rhino 7 for Mac (Mono): the same net48 build, the universal
#             libweft.dylib (x86_64 + arm64) beside Weft.Interop.dll, where
#             Mono's DllImport finds it.
#   rh8/      Rhino 8, any platform: net48/ (Rhino 8 switched to .NET
#             Framework on Windows) and net7.0/ (the net7.0 build against
#             RhinoCommon 8.x), each with weft.dll for win-x64 and win-arm64
#             under runtimes/<rid>/native/; net7.0/ has the universal
#             libweft.dylib beside Weft.Interop.dll for Rhino 8 for Mac.
#
# usage: package.sh --net48 DIR --net7 DIR --win-x64 FILE --win-arm64 FILE
#                   --osx FILE --out DIR [--version X.Y.Z]
# DIR holds Weft.Grasshopper.gha and Weft.Interop.dll; FILE is a native
# library (copied under the platform's name). Prints each folder with the
# yak command and the distribution it makes.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
version=$(sed -n 's/^version: *//p' "$here/manifest.yml")
net48="" net7="" win_x64="" win_arm64="" osx="" out=""
while [ $# -gt 0 ]; do
  case "$1" in
    --net48) net48=$2 ;;
    --net7) net7=$2 ;;
    --win-x64) win_x64=$2 ;;
    --win-arm64) win_arm64=$2 ;;
    --osx) osx=$2 ;;
    --out) out=$2 ;;
    --version) version=$2 ;;
    *) echo "package.sh: unknown argument $1" >&2; exit 2 ;;
  esac
  shift 2
done
for pair in "--net48:$net48" "--net7:$net7" "--win-x64:$win_x64" "--win-arm64:$win_arm64" "--osx:$osx" "--out:$out"; do
  [ -n "${pair#*:}" ] || { echo "package.sh: ${pair%%:*} is missing" >&2; exit 2; }
done
for dir in "$net48" "$net7"; do
  for file in Weft.Grasshopper.gha Weft.Interop.dll; do
    [ -f "$dir/$file" ] || { echo "package.sh: $dir/$file not found" >&2; exit 1; }
  done
done
for file in "$win_x64" "$win_arm64" "$osx"; do
  [ -f "$file" ] || { echo "package.sh: native library $file not found" >&2; exit 1; }
done

# manifest.yml with the package's version; the icon beside it.
manifest() {
  mkdir -p "$1"
  sed "s/^version: .*/version: $version/" "$here/manifest.yml" >"$1/manifest.yml"
  cp "$here/icon.png" "$1/icon.png"
}
# The plug-in and its wrapper from a build folder.
plugin() {
  mkdir -p "$2"
  cp "$1/Weft.Grasshopper.gha" "$1/Weft.Interop.dll" "$2/"
}
native() {
  mkdir -p "$(dirname "$2")"
  cp "$1" "$2"
}

rm -rf "$out/rh7-win" "$out/rh7-mac" "$out/rh8"

manifest "$out/rh7-win"
plugin "$net48" "$out/rh7-win"
native "$win_x64" "$out/rh7-win/weft.dll"

manifest "$out/rh7-mac"
plugin "$net48" "$out/rh7-mac"
native "$osx" "$out/rh7-mac/libweft.dylib"

manifest "$out/rh8"
plugin "$net48" "$out/rh8/net48"
native "$win_x64" "$out/rh8/net48/weft.dll"
native "$win_x64" "$out/rh8/net48/runtimes/win-x64/native/weft.dll"
native "$win_arm64" "$out/rh8/net48/runtimes/win-arm64/native/weft.dll"
plugin "$net7" "$out/rh8/net7.0"
native "$win_x64" "$out/rh8/net7.0/runtimes/win-x64/native/weft.dll"
native "$win_arm64" "$out/rh8/net7.0/runtimes/win-arm64/native/weft.dll"
native "$osx" "$out/rh8/net7.0/libweft.dylib"

echo "rh7-win: $out/rh7-win  (yak build --platform win -> weft-$version-rh7_0-win.yak)"
echo "rh7-mac: $out/rh7-mac  (yak build --platform mac -> weft-$version-rh7_0-mac.yak)"
echo "rh8:     $out/rh8  (yak build --platform any -> weft-$version-rh8_0-any.yak)"
