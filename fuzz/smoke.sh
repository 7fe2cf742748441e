#!/usr/bin/env bash
# A short bounded run of every fuzz target (FUZZ_SECONDS each, default 5),
# starting from the committed corpus; new inputs go to a scratch folder so
# the repository's corpus stays small. Needs cargo-fuzz (installed when
# missing) and builds with AddressSanitizer.
# A longer run: FUZZ_SECONDS=600 fuzz/smoke.sh
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${FUZZ_SECONDS:-5}
command -v cargo-fuzz >/dev/null 2>&1 || cargo install cargo-fuzz --locked --quiet
# cargo-fuzz passes the sanitizer flags that are unstable in rustc.
export RUSTC_BOOTSTRAP=1
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
passed=0 failed=0
for target in $(cargo fuzz list); do
  mkdir -p "$scratch/$target" "fuzz/corpus/$target"
  if cargo fuzz run "$target" "$scratch/$target" "fuzz/corpus/$target" -- \
      -max_total_time="$seconds" -print_final_stats=1 >"$scratch/$target.log" 2>&1; then
    runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$scratch/$target.log" | grep -o '[0-9]*$' || echo "?")
    echo "fuzz $target: $runs runs in ${seconds}s, no crash"
    passed=$((passed + 1))
  else
    echo "fuzz $target: FAILED"; tail -n 40 "$scratch/$target.log"
    failed=$((failed + 1))
  fi
done
echo "fuzz targets: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
