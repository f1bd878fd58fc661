#!/usr/bin/env bash
# Random fuzz exploration (issue 20): every cargo-fuzz target with a fresh seed for
# SECONDS each (default 600), starting from a copy of the committed corpus. CI does not
# call this (its fuzz step, .ci/robustness.sh, is a fixed-seed regression run). Run it
# before resolving any change to the core, the C API or the club-data estimator; fix what
# it finds, then commit the input to fuzz/corpus/<target>/ (docs/robustness.md).
#
#   bash .ci/fuzz-explore.sh [SECONDS] [TARGET...]
#
# Prints, per target: the seed, executions and the coverage reached; on a find, the input
# (base64 and file) and the command that reproduces it. Exits 1 if anything was found.
set -uo pipefail
cd "$(dirname "$0")/../fuzz"
SECONDS_PER_TARGET=${1:-600}
shift || true
export RUSTC_BOOTSTRAP=1
if ! cargo fuzz --version >/dev/null 2>&1; then
  cargo install cargo-fuzz --locked --version 0.13.2 || exit 1
fi
cargo fuzz build -O || exit 1
targets=("$@")
if [ ${#targets[@]} -eq 0 ]; then
  mapfile -t targets < <(cargo fuzz list)
fi
out=${FUZZ_EXPLORE_DIR:-$(mktemp -d /tmp/carry-fuzz-explore.XXXXXX)}
found=0
summary=()
for target in "${targets[@]}"; do
  seed=$(od -An -N4 -tu4 /dev/urandom | tr -d ' ')
  mkdir -p "$out/corpus/$target" "$out/finds/$target"
  cp -r "corpus/$target/." "$out/corpus/$target/" 2>/dev/null || true
  log="$out/$target.log"
  echo "--- $target: seed $seed, ${SECONDS_PER_TARGET}s (log $log)"
  cargo fuzz run -O "$target" "$out/corpus/$target" -- \
    -seed="$seed" -max_total_time="$SECONDS_PER_TARGET" -timeout=10 -rss_limit_mb=2048 \
    -artifact_prefix="$out/finds/$target/" -print_final_stats=1 >"$log" 2>&1
  rc=$?
  execs=$(grep -Eo 'stat::number_of_executed_units: [0-9]+' "$log" | awk '{print $2}' | tail -1)
  cov=$(grep -Eo 'cov: [0-9]+' "$log" | tail -1 | awk '{print $2}')
  finds=$(find "$out/finds/$target" -type f | wc -l)
  summary+=("$target seed=$seed executions=${execs:-?} cov=${cov:-?} finds=$finds exit=$rc")
  if [ "$rc" != 0 ] || [ "$finds" != 0 ]; then
    found=1
    grep -E 'panicked|SUMMARY|==[0-9]+== ERROR' "$log" | head -5
    for f in "$out/finds/$target"/*; do
      [ -f "$f" ] || continue
      echo "FIND $target: $f"
      echo "  input (base64): $(base64 -w0 "$f")"
      echo "  reproduce: cd fuzz && RUSTC_BOOTSTRAP=1 cargo fuzz run -O $target $f"
      echo "  then fix it and commit it: cp $f fuzz/corpus/$target/<name>"
    done
  fi
done
echo "=== fuzz exploration summary (${SECONDS_PER_TARGET}s per target; work in $out)"
printf '%s\n' "${summary[@]}"
exit "$found"
