#!/usr/bin/env bash
# The CLI audit of issue 20 (not run by CI; docs/robustness.md, "Audit"): `carry flight`
# over extreme but plausible inputs — ball speeds 0.1–3000 m/s, spins to 10⁶ rpm, landing
# heights ±50 m, slopes up to and past the 45° maximum, f32/f64, dp45/RK4. Every run must
# either print finite figures (none above 10²⁰) or fail with one line and exit status 2.
#
#   bash .ci/audit-extremes.sh        # builds the release CLI first
set -uo pipefail
cd "$(dirname "$0")/.."
cargo build --release -q -p carry-cli || exit 1
C=target/release/carry
err=$(mktemp)
msgs=$(mktemp)
trap 'rm -f "$err" "$msgs"' EXIT
n=0 ok=0 e2=0 bad=0
for v in 0.1 1 5 30 70 100 149.9 150 151 500 3000; do
  for spin in 0 100 3000 20000 28000 28700 100000 1000000; do
    for lh in -50 -10 0 10 50; do
      for slope in none 0 20 44.9 45 46; do
        for prec in f64 f32; do
          for integ in dp45 rk4; do
            args=(flight --ball-speed "$v" --spin "$spin" --launch-angle 12 --landing-height "$lh"
              --precision "$prec" --integrator "$integ" --json)
            [ "$slope" != none ] && args+=(--ground fairway --ground-slope "$slope" --ground-slope-direction 180)
            out=$("$C" "${args[@]}" 2>"$err")
            rc=$?
            n=$((n + 1))
            if [ $rc = 0 ]; then
              if grep -qiE 'nan|inf|e\+?[2-9][0-9]' <<<"$out"; then
                bad=$((bad + 1))
                echo "BAD (figures) ${args[*]}: ${out:0:300}"
              else
                ok=$((ok + 1))
              fi
            elif [ $rc = 2 ] && [ "$(wc -l <"$err")" = 1 ]; then
              e2=$((e2 + 1))
              cat "$err" >>"$msgs"
            else
              bad=$((bad + 1))
              echo "BAD (exit $rc) ${args[*]}: $(cat "$err")"
            fi
          done
        done
      done
    done
  done
done
echo "runs=$n finite=$ok one-line-exit-2=$e2 bad=$bad"
sort "$msgs" | uniq -c | sort -rn
[ "$bad" = 0 ]
