#!/usr/bin/env bash
# Issue 7 in CI (called by .ci/run): the no-panic link check of the core and of the C API
# (carry-ffi, issue 13) for thumbv7em-none-eabihf, its negative control, and a bounded fuzz
# run of each cargo-fuzz target, the C API's (`ffi`) included (FUZZ_SECONDS each, default
# 60; the corpus under fuzz/corpus/ is committed).
# See docs/robustness.md.
set -euo pipefail
cd "$(dirname "$0")/.."
FUZZ_SECONDS=${FUZZ_SECONDS:-60}
start=$SECONDS
say() { printf -- '--- %s (t=%ss)\n' "$*" "$((SECONDS - start))"; }

say "no-panic link: release images of the impact and flight paths and of the C API, undefined panic handler"
(cd nopanic && cargo build --release --target thumbv7em-none-eabihf)
echo "nopanic: linked — no panic path reachable from the core's impact and flight entry points"
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
for target in $(cargo fuzz list); do
  say "fuzz $target for ${FUZZ_SECONDS}s"
  mkdir -p "corpus/$target"
  log="artifacts/$target.log"
  mkdir -p artifacts
  set +e
  cargo fuzz run -O "$target" "corpus/$target" -- \
    -max_total_time="$FUZZ_SECONDS" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 >"$log" 2>&1
  rc=$?
  set -e
  grep -E '^(#[0-9]+ +DONE|Done|stat::number_of_executed_units|stat::peak_rss_mb|SUMMARY|==[0-9]+== ERROR)|panicked' "$log" || true
  # libFuzzer exits non-zero on a crash, timeout or OOM and leaves the input in artifacts/.
  if [ "$rc" != 0 ] || [ -n "$(find "artifacts/$target" -type f \( -name 'crash-*' -o -name 'timeout-*' -o -name 'oom-*' \) 2>/dev/null)" ]; then
    echo "fuzz $target failed (exit $rc); last lines and the failing input:" >&2
    tail -n 40 "$log" >&2
    find "artifacts/$target" -type f >&2 2>/dev/null || true
    exit 1
  fi
done
say "robustness done"
