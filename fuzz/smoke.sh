#!/usr/bin/env bash
# A short, reproducible run of every fuzz target, starting from the committed
# corpus: a fixed number of inputs (FUZZ_RUNS each, default 20000) from a fixed
# random seed per target, so two runs of one commit try (nearly) the same
# inputs; see fuzz/README.md for what still varies.
# New inputs go to a scratch folder, so the repository's corpus stays small.
# Needs cargo-fuzz (installed when missing) and builds with AddressSanitizer.
#
# A longer run, for minutes per target and from another seed:
#   FUZZ_SECONDS=600 fuzz/smoke.sh
#   FUZZ_SECONDS=600 FUZZ_SEED=7 fuzz/smoke.sh
# Keep what a long run found worth keeping, then shrink the corpus again:
#   cargo fuzz cmin operations   (named regression inputs are kept; see README)
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${FUZZ_RUNS:-20000}
seconds=${FUZZ_SECONDS:-}
command -v cargo-fuzz >/dev/null 2>&1 || cargo install cargo-fuzz --locked --quiet
# cargo-fuzz passes the sanitizer flags that are unstable in rustc.
export RUSTC_BOOTSTRAP=1
# One thread: the coverage a run sees does not depend on how work is split.
export RAYON_NUM_THREADS=${RAYON_NUM_THREADS:-1}
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
# One fixed seed per target (libFuzzer's -seed; 0 would mean "from the clock").
seed_of() {
  case "$1" in
    mesh_new) echo 1101 ;;
    operations) echo 1102 ;;
    readers) echo 1103 ;;
    *) echo 1199 ;;
  esac
}
passed=0 failed=0
for target in $(cargo fuzz list); do
  mkdir -p "$scratch/$target" "fuzz/corpus/$target"
  seed=${FUZZ_SEED:-$(seed_of "$target")}
  if [ -n "$seconds" ]; then
    budget=(-max_total_time="$seconds")
  else
    # The time limit only guards against a hang; the run count ends the run.
    budget=(-runs="$runs" -max_total_time=300)
  fi
  start=$SECONDS
  if cargo fuzz run "$target" "$scratch/$target" "fuzz/corpus/$target" -- \
      -seed="$seed" "${budget[@]}" -print_final_stats=1 >"$scratch/$target.log" 2>&1; then
    execs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$scratch/$target.log" | grep -o '[0-9]*$' || echo "?")
    echo "fuzz $target: $execs runs in $((SECONDS - start))s (seed $seed), no crash"
    passed=$((passed + 1))
  else
    echo "fuzz $target: FAILED (seed $seed)"
    # From libFuzzer's report on (for running out of memory, the stacks of
    # the allocations live then), else the run's last lines; the whole log
    # is kept. One command each: no pipe for `pipefail` to end the script on.
    log="$scratch/$target.log"
    report=$(grep -n -m1 -E '^==[0-9]+== ?ERROR' "$log" || true)
    report=${report%%:*}
    if [ -n "$report" ]; then sed -n "${report},$((report + 199))p" "$log"; else tail -n 40 "$log"; fi
    mkdir -p "fuzz/artifacts/$target"
    cp "$log" "fuzz/artifacts/$target/smoke-seed-$seed.log"
    echo "whole log: fuzz/artifacts/$target/smoke-seed-$seed.log"
    if grep -q 'libFuzzer: out-of-memory' "$log"; then
      # The sanitizer's allocator keeps what an input freed, so the input
      # named above is seldom the one that took the memory: replay the
      # inputs this run added, each in a process of its own.
      echo "the largest peaks of the inputs this run added, replayed one by one:"
      host=$(rustc -vV | sed -n 's/^host: //p')
      python3 - "fuzz/target/$host/release/$target" "$scratch/$target" <<'PY' || true
import os, subprocess, sys
binary, folder = sys.argv[1], sys.argv[2]
peaks = []
for name in os.listdir(folder):
    child = subprocess.Popen([binary, os.path.join(folder, name)],
                             stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    _, _, usage = os.wait4(child.pid, 0)
    peaks.append((usage.ru_maxrss // 1024, name))
for megabytes, name in sorted(peaks, reverse=True)[:3]:
    print(f"  {megabytes} MB  {name}")
PY
      mkdir -p "fuzz/artifacts/$target/added"
      cp "$scratch/$target"/* "fuzz/artifacts/$target/added/" 2>/dev/null || true
      echo "those inputs: fuzz/artifacts/$target/added/"
    fi
    failed=$((failed + 1))
  fi
done
echo "fuzz targets: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
