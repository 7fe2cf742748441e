#!/usr/bin/env bash
# Installs Weft with scripts/install.sh into a temporary prefix (and once
# more staged under DESTDIR) and builds against it as a C or C++ host would:
# pkg-config with the shared and the static library, by hand with an rpath,
# CMake's weft::weft and weft::weft_static in a C++ and a C-only project,
# the C++ example and the tests of weft.hpp under AddressSanitizer. Checks
# the soname, the exported symbols, the size, and that removing what the
# manifest lists removes all.
# Prints "install tests: N passed, N failed" and exits non-zero on a failure.
set -uo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
cd "$root" || exit 1
work=$(mktemp -d "${TMPDIR:-/tmp}/weft-install-test.XXXXXX")
trap 'rm -rf "$work"' EXIT
prefix=$work/prefix
version=$(awk -F'"' '/^\[/ { s = $0 } s == "[package]" && /^version *=/ { print $2; exit }' Cargo.toml)
major=${version%%.*}
lib=$prefix/lib
unset LD_LIBRARY_PATH
export PKG_CONFIG_PATH=$lib/pkgconfig
warn=(-Wall -Wextra -Werror -pedantic)

passed=0 failed=0
check() { # name, command... (output kept in a log, shown on failure)
  local name=$1 log=$work/log.$((passed + failed)); shift
  if "$@" >"$log" 2>&1; then
    passed=$((passed + 1)); echo "ok: $name"
  else
    failed=$((failed + 1)); echo "FAILED: $name"; tail -n 30 "$log"
  fi
}
# The cube example prints its counts; the programs must say them.
runs_cube() { # executable, env assignments...
  local exe=$1 out; shift
  out=$(env "$@" "$exe") || { echo "$exe exited with $?: $out"; return 1; }
  echo "$out"
  grep -q "98 vertices, 96 faces, closed: 1" <<<"$out"
}
needs_libweft() { readelf -d "$1" | grep -q "NEEDED.*\[libweft\.so\.$major\]"; }
no_libweft() { ! readelf -d "$1" | grep -q "NEEDED.*libweft"; }

missing=()
for tool in cargo cc c++ cmake pkg-config readelf nm; do command -v "$tool" >/dev/null || missing+=("$tool"); done
if [ ${#missing[@]} -gt 0 ]; then
  echo "The install tests need ${missing[*]} (scripts/install-test-deps.sh installs them)."
  echo "install tests: 0 passed, 1 failed"
  exit 1
fi

if ! scripts/install.sh --prefix "$prefix" >"$work/install.log" 2>&1; then
  tail -n 40 "$work/install.log"
  echo "install tests: 0 passed, 1 failed"
  exit 1
fi

check "install.sh --help names --prefix and DESTDIR" sh -c 'scripts/install.sh --help | grep -q -- --prefix && scripts/install.sh --help | grep -q DESTDIR'
check "install.sh rejects an unknown argument" sh -c '! scripts/install.sh --prefx /tmp 2>/dev/null'
expected_files=(include/weft.h include/weft.hpp "lib/libweft.so.$version" "lib/libweft.so.$major" lib/libweft.so
  lib/libweft.a lib/pkgconfig/weft.pc lib/cmake/weft/weftConfig.cmake lib/cmake/weft/weftConfigVersion.cmake
  share/weft/install_manifest.txt)
all_installed() { local f; for f in "${expected_files[@]}"; do [ -e "$prefix/$f" ] || { echo "missing $f"; return 1; }; done; }
check "every file is installed" all_installed
check "the installed weft.h is the committed one" cmp include/weft.h "$prefix/include/weft.h"
check "libweft.so.$major and libweft.so point to libweft.so.$version" sh -c \
  "[ \"\$(readlink '$lib/libweft.so.$major')\" = libweft.so.$version ] && [ \"\$(readlink '$lib/libweft.so')\" = libweft.so.$version ]"
check "the soname is libweft.so.$major" sh -c "readelf -d '$lib/libweft.so.$version' | grep -q 'SONAME.*\[libweft\.so\.$major\]'"

only_weft_exported() {
  local symbols others
  symbols=$(nm -D --defined-only "$lib/libweft.so.$version" | awk '{ print $3 }')
  others=$(grep -v '^weft_' <<<"$symbols" || true)
  echo "$(wc -l <<<"$symbols") exported symbols"
  [ -z "$others" ] || { echo "exported besides weft_*: $others"; return 1; }
  grep -qx weft_mesh_new <<<"$symbols" && grep -qx weft_catmull_clark <<<"$symbols"
}
check "the shared library exports weft_* and nothing else" only_weft_exported
lean() {
  local shared static
  shared=$(stat -c %s "$lib/libweft.so.$version") static=$(stat -c %s "$lib/libweft.a")
  echo "libweft.so: $shared bytes, libweft.a: $static bytes"
  ! readelf -S "$lib/libweft.so.$version" | grep -q '\.debug_' || { echo "libweft.so has debug sections"; return 1; }
  [ "$shared" -lt $((8 * 1024 * 1024)) ] && [ "$static" -lt $((40 * 1024 * 1024)) ]
}
check "the libraries carry no debug info (libweft.so under 8 MB)" lean

check "pkg-config gives Cargo.toml's version" sh -c "[ \"\$(pkg-config --modversion weft)\" = '$version' ]"
static_link_line() {
  local libs
  libs=$(pkg-config --static --libs-only-l weft | xargs) # xargs trims the spacing
  echo "pkg-config --static --libs-only-l weft: $libs"
  [ "$libs" = "-lweft -lm -lpthread -ldl" ]
}
check "Libs.private is -lm -lpthread -ldl" static_link_line

# pkg-config, shared: needs the library path at run time, runs with it.
bin=$work/bin
mkdir -p "$bin"
check "pkg-config shared build" sh -c \
  "cc -std=c99 ${warn[*]} examples/subdivide_cube.c \$(pkg-config --cflags --libs weft) -o '$bin/cube_shared'"
check "the shared build needs libweft.so.$major" needs_libweft "$bin/cube_shared"
check "the shared build does not run without the library path" sh -c "! '$bin/cube_shared'"
check "the shared build runs with LD_LIBRARY_PATH" runs_cube "$bin/cube_shared" "LD_LIBRARY_PATH=$lib"

# pkg-config, static: the archive and the system libraries pkg-config lists.
static_libs() { pkg-config --static --libs-only-l weft | sed 's/-lweft\( \|$\)//'; }
check "pkg-config static build" sh -c \
  "cc -std=c99 ${warn[*]} examples/subdivide_cube.c \$(pkg-config --cflags weft) '$lib/libweft.a' $(static_libs) -o '$bin/cube_static'"
check "the static build does not need libweft" no_libweft "$bin/cube_static"
check "the static build runs with no library path" runs_cube "$bin/cube_static"

# By hand, as the README shows: -rpath, then the static archive with -lm -lpthread -ldl.
check "by-hand build with -rpath" sh -c \
  "cc -std=c99 ${warn[*]} examples/subdivide_cube.c -I'$prefix/include' -L'$lib' -Wl,-rpath,'$lib' -lweft -o '$bin/cube_rpath'"
check "the -rpath build runs with no library path" runs_cube "$bin/cube_rpath"
check "by-hand static build" sh -c \
  "cc -std=c99 ${warn[*]} examples/subdivide_cube.c -I'$prefix/include' '$lib/libweft.a' -lm -lpthread -ldl -o '$bin/cube_hand_static'"
check "the by-hand static build runs" runs_cube "$bin/cube_hand_static"

# weft.hpp: strict C++17 with every compiler present; the example under ASan.
for cxx in g++ clang++; do
  command -v "$cxx" >/dev/null || continue
  check "weft.hpp compiles with $cxx -std=c++17 ${warn[*]}" \
    "$cxx" -std=c++17 "${warn[@]}" -I"$prefix/include" -c examples/subdivide_cube.cpp -o "$bin/cube_cpp_$cxx.o"
  check "weft.hpp tests compile with $cxx" \
    "$cxx" -std=c++17 "${warn[@]}" -I"$prefix/include" -c tests/install/wrapper_test.cpp -o "$bin/wrapper_$cxx.o"
done
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
check "C++ example with AddressSanitizer builds" sh -c \
  "c++ -std=c++17 ${warn[*]} -g -fsanitize=address,undefined -fno-omit-frame-pointer examples/subdivide_cube.cpp \$(pkg-config --cflags --libs weft) -o '$bin/cube_cpp_asan'"
check "C++ example runs clean under AddressSanitizer" runs_cube "$bin/cube_cpp_asan" "LD_LIBRARY_PATH=$lib"
check "weft.hpp tests build with AddressSanitizer" sh -c \
  "c++ -std=c++17 ${warn[*]} -g -fsanitize=address,undefined -fno-omit-frame-pointer tests/install/wrapper_test.cpp \$(pkg-config --cflags --libs weft) -Wl,-rpath,'$lib' -o '$bin/wrapper_test'"
check "weft.hpp tests pass under AddressSanitizer" "$bin/wrapper_test"
unset ASAN_OPTIONS UBSAN_OPTIONS

# CMake: both targets, in a C++ project and in a C-only one; they run with
# no library path (CMake sets the rpath of the shared one).
cmake_build() { # source dir, build dir, prefix
  cmake -S "$1" -B "$2" -DCMAKE_PREFIX_PATH="$3" -DCMAKE_BUILD_TYPE=Release &&
    cmake --build "$2" -- -j2
}
check "CMake C++ project configures and builds" cmake_build examples/cmake "$work/cmake-cxx" "$prefix"
check "CMake weft::weft (C++) runs" runs_cube "$work/cmake-cxx/subdivide_cube_cpp"
check "CMake weft::weft (C in the C++ project) runs" runs_cube "$work/cmake-cxx/subdivide_cube_c"
check "CMake weft::weft_static (C++) does not need libweft" no_libweft "$work/cmake-cxx/subdivide_cube_cpp_static"
check "CMake weft::weft_static (C++) runs" runs_cube "$work/cmake-cxx/subdivide_cube_cpp_static"
check "CMake C-only project configures and builds" cmake_build examples/cmake/c-only "$work/cmake-c" "$prefix"
check "CMake weft::weft (C-only) runs" runs_cube "$work/cmake-c/subdivide_cube"
check "CMake weft::weft_static (C-only) runs" runs_cube "$work/cmake-c/subdivide_cube_static"
mkdir -p "$work/too-new"
cat >"$work/too-new/CMakeLists.txt" <<EOF
cmake_minimum_required(VERSION 3.14)
project(too_new LANGUAGES C)
find_package(weft $((major + 1)).0 CONFIG)
if(weft_FOUND)
  message(FATAL_ERROR "weft $((major + 1)).0 was accepted from an installed $version")
endif()
EOF
check "CMake refuses a request for the next major version" \
  cmake -S "$work/too-new" -B "$work/too-new/build" -DCMAKE_PREFIX_PATH="$prefix"

# Uninstall: remove what the manifest names; nothing may be left.
uninstall() { # manifest, DESTDIR
  local file
  while read -r file; do rm -f "$2$file"; done <"$1"
}
left_over() { [ -z "$(find "$1" \( -type f -o -type l \) -print)" ] || { find "$1" \( -type f -o -type l \); return 1; }; }
check "uninstall by the manifest" uninstall "$prefix/share/weft/install_manifest.txt" ""
check "nothing is left in the prefix" left_over "$prefix"

# DESTDIR: files land under it, while what they say names the real prefix.
stage=$work/stage target_prefix=/opt/weft-install-test-$$
check "install with DESTDIR" env DESTDIR="$stage" scripts/install.sh --prefix "$target_prefix"
check "nothing is written outside DESTDIR" sh -c "[ ! -e '$target_prefix' ]"
check "the staged weft.pc names the real prefix" grep -qx "prefix=$target_prefix" "$stage$target_prefix/lib/pkgconfig/weft.pc"
check "the staged manifest names the real prefix" sh -c \
  "[ -s '$stage$target_prefix/share/weft/install_manifest.txt' ] && ! grep -v '^$target_prefix/' '$stage$target_prefix/share/weft/install_manifest.txt'"
check "the staged CMake package works where it lies" cmake_build examples/cmake/c-only "$work/cmake-staged" "$stage$target_prefix"
check "the staged CMake build runs" runs_cube "$work/cmake-staged/subdivide_cube"
check "uninstall the staged copy by its manifest" uninstall "$stage$target_prefix/share/weft/install_manifest.txt" "$stage"
check "nothing is left in the staged prefix" left_over "$stage"

echo "install tests: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
