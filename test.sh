#!/usr/bin/env bash
# Runs every test of Weft, start to end: formatting, lints, the API
# documentation's links, the Rust tests
# (with the OpenSubdiv and OpenMesh comparisons and the header check), the C
# tests (also under AddressSanitizer and UndefinedBehaviorSanitizer), the C#
# wrapper's tests on Mono, the Grasshopper compile check and replay, the
# Python package's tests in a fresh virtual environment, the C and C++
# install (pkg-config, CMake, weft.hpp) and a short run of every fuzz target.
# On a fresh Debian machine, run as root, it first installs what is missing.
set -uo pipefail
cd "$(dirname "$0")"
scripts/install-test-deps.sh || exit 1

passed=0 failed=0 failures=()
suite() { # name, command...
  local name=$1; shift
  echo "=== $name"
  if "$@"; then
    passed=$((passed + 1))
  else
    failed=$((failed + 1)); failures+=("$name")
  fi
}

suite "cargo fmt --check" cargo fmt --all --check
suite "cargo clippy" cargo clippy --workspace --all-targets --quiet -- -D warnings
suite "cargo doc" env RUSTDOCFLAGS="-D warnings" cargo doc --no-deps --lib --quiet
suite "cargo test" cargo test --workspace
suite "C tests" tests/c/run.sh
for script in dotnet/test.sh grasshopper/check.sh python/test.sh tests/install/run.sh tests/step/run.sh fuzz/smoke.sh; do
  [ -x "$script" ] && suite "$script" "$script"
done

echo "=== summary"
[ ${#failures[@]} -gt 0 ] && printf 'failed suite: %s\n' "${failures[@]}"
echo "test suites: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
