#!/usr/bin/env bash
# Builds the release library and installs Weft for C and C++ hosts: the
# headers, the shared and static libraries, a pkg-config file and a CMake
# package. Run scripts/install.sh --help for the options.
set -euo pipefail

usage() {
  cat <<'EOF'
Usage: scripts/install.sh [--prefix DIR]

Builds Weft's release library (cargo build --release --lib) and installs:
  DIR/include/weft.h, DIR/include/weft.hpp    the C header and the C++17 wrapper
  DIR/lib/libweft.so.X.Y.Z (soname libweft.so.X) and the symlinks
      libweft.so.X, libweft.so                (macOS: libweft.X.Y.Z.dylib, ...)
  DIR/lib/libweft.a                           the static library
  DIR/lib/pkgconfig/weft.pc                   for pkg-config
  DIR/lib/cmake/weft/weftConfig.cmake         for find_package(weft CONFIG):
      weftConfigVersion.cmake                   targets weft::weft, weft::weft_static
  DIR/share/weft/install_manifest.txt         every path above, one a line

Options:
  --prefix DIR   where to install (default /usr/local)
  -h, --help     show this help

The DESTDIR environment variable, when set, is prepended to every path
written (for staging a package); the installed files still name DIR.
To uninstall, remove the files the manifest lists:
  while read -r f; do rm -f "$f"; done < DIR/share/weft/install_manifest.txt
EOF
}

prefix=/usr/local
while [ $# -gt 0 ]; do
  case $1 in
    --prefix) [ $# -ge 2 ] || { echo "install.sh: --prefix needs a directory" >&2; exit 2; }
              prefix=$2; shift 2 ;;
    --prefix=*) prefix=${1#--prefix=}; shift ;;
    -h|--help) usage; exit 0 ;;
    *) echo "install.sh: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
done
case $prefix in
  /*) ;;
  "") echo "install.sh: --prefix is empty" >&2; exit 2 ;;
  *) prefix=$(cd "$(dirname "$prefix")" 2>/dev/null && pwd)/$(basename "$prefix") ||
       { echo "install.sh: the parent of --prefix '$prefix' does not exist" >&2; exit 2; } ;;
esac
prefix=${prefix%/}
destdir=${DESTDIR:-}
destdir=${destdir%/}

root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"

# The version is Cargo.toml's, the only place it is written.
version=$(awk -F'"' '/^\[/ { section = $0 } section == "[package]" && /^version *=/ { print $2; exit }' Cargo.toml)
case $version in
  [0-9]*.[0-9]*.[0-9]*) ;;
  *) echo "install.sh: no version found in the [package] section of Cargo.toml" >&2; exit 1 ;;
esac
major=${version%%.*}

# The command line tool sits behind a `cli` feature when Cargo.toml has one;
# the library is built without it, so it never carries the CLI's dependencies.
build_flags=(--release --lib)
if awk '/^\[/ { section = $0 } section == "[features]" && /^cli *=/ { found = 1 } END { exit !found }' Cargo.toml; then
  build_flags+=(--no-default-features)
fi
echo "Building: cargo build ${build_flags[*]}"
cargo build "${build_flags[@]}"
target_dir=${CARGO_TARGET_DIR:-$root/target}
built=$target_dir/release

case $(uname -s) in
  Darwin)
    shared=libweft.$version.dylib
    shared_links=("libweft.$major.dylib" libweft.dylib)
    built_shared=libweft.dylib static=libweft.a import_lib= ;;
  MINGW*|MSYS*|CYGWIN*)
    # The DLL goes to bin/ (found next to the executable or on PATH); the
    # import library and the static library go to lib/.
    shared=weft.dll shared_links=() built_shared=weft.dll
    if [ -f "$built/weft.dll.lib" ]; then import_lib=weft.dll.lib static=weft.lib
    else import_lib=libweft.dll.a static=libweft.a; fi ;;
  *)
    shared=libweft.so.$version
    shared_links=("libweft.so.$major" libweft.so)
    built_shared=libweft.so static=libweft.a import_lib= ;;
esac
for file in "$built_shared" "$static" $import_lib; do
  [ -f "$built/$file" ] || { echo "install.sh: the build did not produce $built/$file" >&2; exit 1; }
done

manifest_dir=$prefix/share/weft
manifest=$manifest_dir/install_manifest.txt
installed=()
put() { # mode, source, destination (without DESTDIR)
  install -d "$destdir$(dirname "$3")"
  install -m "$1" "$2" "$destdir$3"
  installed+=("$3")
}
link() { # target, link name (without DESTDIR)
  ln -sfn "$1" "$destdir$2"
  installed+=("$2")
}
# A file written from standard input.
write() { # destination (without DESTDIR)
  install -d "$destdir$(dirname "$1")"
  cat >"$destdir$1"
  chmod 644 "$destdir$1"
  installed+=("$1")
}

put 644 include/weft.h "$prefix/include/weft.h"
put 644 include/weft.hpp "$prefix/include/weft.hpp"

if [ -n "$import_lib" ]; then
  put 755 "$built/$shared" "$prefix/bin/$shared"
  put 644 "$built/$import_lib" "$prefix/lib/$import_lib"
  shared_location=$prefix/bin/$shared
else
  put 755 "$built/$built_shared" "$prefix/lib/$shared"
  for name in "${shared_links[@]}"; do link "$shared" "$prefix/lib/$name"; done
  shared_location=$prefix/lib/$shared
fi
if [ "$(uname -s)" = Darwin ] && command -v install_name_tool >/dev/null; then
  # Hosts record this path, so they find the library without an rpath.
  install_name_tool -id "$prefix/lib/libweft.$major.dylib" "$destdir$prefix/lib/$shared"
fi
put 644 "$built/$static" "$prefix/lib/$static"
# The static archive holds the debug info of Rust's standard library;
# hosts link faster and smaller without it.
if command -v strip >/dev/null && [ "$(uname -s)" = Linux ]; then
  strip --strip-debug "$destdir$prefix/lib/$static"
fi

# What rustc --print native-static-libs names beside the C library.
case $(uname -s) in
  Darwin) system_libs=() ;;
  MINGW*|MSYS*|CYGWIN*) system_libs=(kernel32 advapi32 ntdll userenv ws2_32 dbghelp) ;;
  *) system_libs=(m pthread dl) ;;
esac
libs_private=""
for lib in "${system_libs[@]}"; do libs_private+=" -l$lib"; done

write "$prefix/lib/pkgconfig/weft.pc" <<EOF
prefix=$prefix
exec_prefix=\${prefix}
libdir=\${exec_prefix}/lib
includedir=\${prefix}/include

Name: weft
Description: Subdivision surfaces (Loop, Catmull-Clark) and mesh making and mending tools, with a flat C ABI
Version: $version
Libs: -L\${libdir} -lweft
Libs.private:$libs_private
Cflags: -I\${includedir}
EOF

# The CMake package finds its files relative to itself, so a staged or
# moved installation still works.
if [ -n "$import_lib" ]; then
  shared_properties="IMPORTED_LOCATION \"\${_weft_prefix}/bin/$shared\"
    IMPORTED_IMPLIB \"\${_weft_prefix}/lib/$import_lib\""
elif [ "$(uname -s)" = Darwin ]; then
  shared_properties="IMPORTED_LOCATION \"\${_weft_prefix}/lib/$shared\"
    IMPORTED_SONAME \"$prefix/lib/libweft.$major.dylib\""
else
  shared_properties="IMPORTED_LOCATION \"\${_weft_prefix}/lib/$shared\"
    IMPORTED_SONAME \"libweft.so.$major\""
fi
write "$prefix/lib/cmake/weft/weftConfig.cmake" <<EOF
# The CMake package of Weft $version, written by scripts/install.sh.
#   find_package(weft CONFIG REQUIRED)
#   target_link_libraries(app PRIVATE weft::weft)         # the shared library
#   target_link_libraries(app PRIVATE weft::weft_static)  # the static library
# Both targets carry the include directory of weft.h and weft.hpp; the static
# one also the system libraries it needs. Works in C and C++ projects.
get_filename_component(_weft_prefix "\${CMAKE_CURRENT_LIST_DIR}/../../.." ABSOLUTE)

if(NOT TARGET weft::weft)
  add_library(weft::weft SHARED IMPORTED)
  set_target_properties(weft::weft PROPERTIES
    $shared_properties
    INTERFACE_INCLUDE_DIRECTORIES "\${_weft_prefix}/include")
endif()

if(NOT TARGET weft::weft_static)
  add_library(weft::weft_static STATIC IMPORTED)
  set_target_properties(weft::weft_static PROPERTIES
    IMPORTED_LOCATION "\${_weft_prefix}/lib/$static"
    IMPORTED_LINK_INTERFACE_LANGUAGES "C"
    INTERFACE_INCLUDE_DIRECTORIES "\${_weft_prefix}/include"
    INTERFACE_LINK_LIBRARIES "$(IFS=';'; echo "${system_libs[*]}")")
endif()

unset(_weft_prefix)
set(weft_VERSION "$version")
EOF

write "$prefix/lib/cmake/weft/weftConfigVersion.cmake" <<EOF
# Weft $version: compatible with requests for the same major version that are
# not newer (the ABI only grows within a major version).
set(PACKAGE_VERSION "$version")
if(PACKAGE_FIND_VERSION VERSION_GREATER PACKAGE_VERSION)
  set(PACKAGE_VERSION_COMPATIBLE FALSE)
elseif(PACKAGE_FIND_VERSION_MAJOR STREQUAL "$major")
  set(PACKAGE_VERSION_COMPATIBLE TRUE)
  if(PACKAGE_FIND_VERSION VERSION_EQUAL PACKAGE_VERSION)
    set(PACKAGE_VERSION_EXACT TRUE)
  endif()
else()
  set(PACKAGE_VERSION_COMPATIBLE FALSE)
endif()
# Built for 64-bit targets only.
if(CMAKE_SIZEOF_VOID_P AND NOT CMAKE_SIZEOF_VOID_P STREQUAL "8")
  set(PACKAGE_VERSION "\${PACKAGE_VERSION} (64-bit)")
  set(PACKAGE_VERSION_UNSUITABLE TRUE)
endif()
EOF

installed+=("$manifest")
install -d "$destdir$manifest_dir"
printf '%s\n' "${installed[@]}" >"$destdir$manifest"
echo "Installed Weft $version into $destdir$prefix (shared library: $shared_location)"
echo "The list of installed files: $destdir$manifest"
