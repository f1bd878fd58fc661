#!/usr/bin/env bash
# Issue 7 in CI (called by .ci/run): the no-panic link check of the core and of the C API
# (carry-ffi, issue 13) for thumbv7em-none-eabihf, its negative control, and a deterministic
# fuzz run of each cargo-fuzz target, the C API's (`ffi`) included: the committed corpus
# under fuzz/corpus/, a fixed seed and a fixed number of executions (issue 20).
# See docs/robustness.md.
set -euo pipefail
cd "$(dirname "$0")/.."
start=$SECONDS
say() { printf -- '--- %s (t=%ss)\n' "$*" "$((SECONDS - start))"; }

say "no-panic link: release images of the impact and flight paths and of the C API, undefined panic handler"
(cd nopanic && cargo build --release --target thumbv7em-none-eabihf)
echo "nopanic: linked — no panic path reachable from the core's impact, flight, estimate and launch-fit entry points"
echo "nopanic: linked — no panic path reachable from the C API's entry points (carry-ffi, bin ffi)"

say "negative control: one deliberate panic must fail the link"
if (cd nopanic && cargo build --release --target thumbv7em-none-eabihf --features canary) >/tmp/nopanic-canary.log 2>&1; then
  echo "nopanic canary linked: the check would not catch a panic" >&2
  exit 1
fi
grep -q "undefined symbol: carry_core_reached_a_panic_path" /tmp/nopanic-canary.log
echo "nopanic canary: link failed on carry_core_reached_a_panic_path, as it must"
if (cd nopanic && cargo build --release --target thumbv7em-none-eabihf --features canary --bin ffi) >/tmp/nopanic-canary-ffi.log 2>&1; then
  echo "nopanic canary (C API image) linked: the check would not catch a panic" >&2
  exit 1
fi
grep -q "undefined symbol: carry_core_reached_a_panic_path" /tmp/nopanic-canary-ffi.log
echo "nopanic canary (C API image): link failed as it must"

say "cargo-fuzz"
if ! cargo fuzz --version >/dev/null 2>&1; then
  cargo install cargo-fuzz --locked --version 0.13.2
fi
# libFuzzer and the sanitizer need -Z flags: the machine has one stable toolchain, so
# RUSTC_BOOTSTRAP=1 unlocks them (docs/robustness.md).
export RUSTC_BOOTSTRAP=1
cd fuzz
cargo fuzz build -O
# Deterministic regression run (issue 20): every target starts from the committed corpus
# (copied, so the run never writes into the tree) with a fixed seed and a fixed number of
# executions, so the same commit always gets the same verdict. Random exploration with
# fresh seeds is .ci/fuzz-explore.sh, which CI does not call. The counts give about
# 30-60 s per target on a 2-core machine; FUZZ_RUNS_SCALE scales them all (e.g. 0.1 for a
# quick local check). -reload=0: libFuzzer otherwise re-reads the corpus directory on a
# timer, which makes two runs with the same seed differ (measured: 1107 vs 1110 inputs after
# 5000 flight runs; identical with -reload=0). The time cap only guards against a
# pathologically slow machine.
FUZZ_SEED=${FUZZ_SEED:-20261125}
FUZZ_RUNS_SCALE=${FUZZ_RUNS_SCALE:-1}
runs_for() {
  local base
  case "$1" in
    cli) base=12000 ;;
    ffi) base=120000 ;;
    estimate) base=20000 ;;
    launch_fit) base=8000 ;;
    flight) base=80000 ;;
    ground) base=150000 ;;
    impact) base=5000000 ;;
    *) base=50000 ;;
  esac
  awk -v b="$base" -v s="$FUZZ_RUNS_SCALE" 'BEGIN { printf "%d", b * s }'
}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# Each libFuzzer run is one process on one core, so two targets run at once on CI's two cores
# (the verdicts do not change: each run has its own corpus copy, seed and execution count).
fuzz_one() {
  local target=$1 runs
  runs=$(runs_for "$target")
  mkdir -p "$work/$target" "artifacts/$target"
  cp -r "corpus/$target/." "$work/$target/" 2>/dev/null || true
  local rc=0
  cargo fuzz run -O "$target" "$work/$target" -- \
    -seed="$FUZZ_SEED" -runs="$runs" -reload=0 -max_total_time=900 -timeout=10 -rss_limit_mb=2048 \
    -print_final_stats=1 >"artifacts/$target.log" 2>&1 || rc=$?
  echo "$rc" >"$work/$target.rc"
}
FUZZ_JOBS=${FUZZ_JOBS:-2}
targets=$(cargo fuzz list)
say "fuzz ${targets//$'\n'/ }: seed $FUZZ_SEED over the committed corpus, $FUZZ_JOBS at a time"
for target in $targets; do
  while [ "$(jobs -rp | wc -l)" -ge "$FUZZ_JOBS" ]; do wait -n || true; done
  fuzz_one "$target" &
done
wait
failed=0
for target in $targets; do
  log="artifacts/$target.log"
  rc=$(cat "$work/$target.rc" 2>/dev/null || echo missing)
  say "fuzz $target: $(runs_for "$target") executions, exit $rc"
  grep -E '^(#[0-9]+ +DONE|Done|stat::number_of_executed_units|stat::peak_rss_mb|SUMMARY|==[0-9]+== ERROR)|panicked' "$log" || true
  # libFuzzer exits non-zero on a crash, timeout or OOM and leaves the input in artifacts/.
  if [ "$rc" != 0 ] || [ -n "$(find "artifacts/$target" -type f \( -name 'crash-*' -o -name 'timeout-*' -o -name 'oom-*' \) 2>/dev/null)" ]; then
    echo "fuzz $target failed (exit $rc); last lines and the failing input:" >&2
    tail -n 40 "$log" >&2
    for f in $(find "artifacts/$target" -type f \( -name 'crash-*' -o -name 'timeout-*' -o -name 'oom-*' \)); do
      echo "input $f (base64): $(base64 -w0 "$f")" >&2
      echo "reproduce: cd fuzz && RUSTC_BOOTSTRAP=1 cargo fuzz run -O $target $f" >&2
    done
    failed=1
  fi
done
[ "$failed" = 0 ] || exit 1
say "robustness done"
