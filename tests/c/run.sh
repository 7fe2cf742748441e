#!/usr/bin/env bash
# Builds and runs the C tests against the cdylib: every tests/c/test_*.c as
# C99 and the header checks as C99 and C++17, all with warnings as errors;
# then everything once more under AddressSanitizer and UndefinedBehaviorSanitizer.
# Prints "N passed, N failed" and exits non-zero on any failure.
set -uo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
cd "$root"
build=tests/c/build
mkdir -p "$build"
cargo build --quiet --lib || exit 1
lib=target/debug
export LD_LIBRARY_PATH="$root/$lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
warn=(-Wall -Wextra -Werror -pedantic)
passed=0 failed=0
run() { # name, command...
  local name=$1; shift
  if "$@" >"$build/$name.log" 2>&1; then
    passed=$((passed + 1))
  else
    failed=$((failed + 1)); echo "FAILED: $name"; tail -n 30 "$build/$name.log"
  fi
}
compile_and_run() { # name, sanitizer flags
  local name=$1 flags=$2 source=tests/c/$1.c exe
  exe=$build/$name${flags:+-san}
  if cc -std=c99 "${warn[@]}" $flags -g -Iinclude "$source" tests/c/check.c -o "$exe" -L"$lib" -lweft -lpthread -lm \
      >"$build/$name-compile.log" 2>&1; then
    run "$name${flags:+ (sanitized)}" "$exe"
  else
    failed=$((failed + 1)); echo "FAILED to compile: $source"; cat "$build/$name-compile.log"
  fi
}
# The header alone, as strict C99 and as C++17.
run "header as C99" cc -std=c99 "${warn[@]}" -Iinclude -c tests/c/header_c99.c -o "$build/header_c99.o"
run "header as C++17" c++ -std=c++17 "${warn[@]}" -Iinclude -c tests/c/header_cpp17.cpp -o "$build/header_cpp17.o"
sanitize="-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all"
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1
for source in tests/c/test_*.c; do
  name=$(basename "$source" .c)
  compile_and_run "$name" ""
  compile_and_run "$name" "$sanitize"
done
# The examples of the README, built as a user would and run.
for source in examples/*.c; do
  name=$(basename "$source" .c)
  run "example $name" sh -c "cc -std=c99 ${warn[*]} -Iinclude '$source' -o '$build/$name' -L'$lib' -lweft && '$build/$name'"
done
echo "C tests: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
