#!/usr/bin/env bash
# Instruction counts per operation on an emulated board, exact and deterministic.
#
#   ./cost.sh [an386|an500|microbit]      (default an386, the Cortex-M4F)
#
# Builds the host-side QEMU plugin (icount-plugin/) and the `cost` firmware, runs it under
# `-icount shift=0` with the plugin loaded, and prints one row per operation:
#   exact   — instructions per call from the plugin, minus the empty loop's overhead
#   SysTick — the same from SysTick virtual time under -icount (±1 tick = 40 insns/region)
#   evals   — force evaluations of a flight; carry — its carry (m)
#
# PROFILE=N ./cost.sh   also lists, per operation, the N functions that executed the most
#                       instructions (the plugin's per-symbol counters).
# ADDRS=K ./cost.sh     also counts every instruction address of operation K (the table's
#                       K-th row counted from 1, plus 1: region 0 and 1 are the calibration
#                       loops) and lists its top ${LINES:-40} source lines, each as the
#                       innermost core frame and the one inlining it (llvm-addr2line -i):
#                       inside the few big inlined functions, where PROFILE cannot see.
set -euo pipefail
cd "$(dirname "$0")"
. ./board.sh "${1:-an386}"

host=$(rustc -vV | sed -n 's/^host: //p')
(cd icount-plugin && CARGO_TARGET_DIR=target cargo build --quiet --release --target "$host")
plugin=$PWD/icount-plugin/target/$host/release/libcarry_icount_plugin.so

cargo build --quiet --release --target "$TARGET" --bin cost
elf=$CARGO_TARGET_DIR/$TARGET/release/cost

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
addrs=${ADDRS:+,addrs=$ADDRS}
CARRY_QEMU_ARGS="-icount shift=0 -plugin $plugin,out=$tmp/icount.txt,profile=${PROFILE:-0}$addrs" \
    ./qemu-run "$elf" > "$tmp/log.txt"

echo "# instruction counts on $BOARD ($TARGET) — $(git -C .. rev-parse --short HEAD 2>/dev/null || echo uncommitted)"
awk '
    FNR == NR { if ($1 == "icount" && $2 == "region" && $4 != "fn") exact[$3] = $4; next }
    /^note: region/ { sub(/^note: /, ""); notes = notes "\n- " $0; next }
    /^cost region=/ {
        for (i = 2; i <= 7; i++) { split($i, kv, "="); v[kv[1]] = kv[2] }
        k = v["region"]; n = v["n"]
        op = $0; sub(/.* op=/, "", op)
        if (op ~ /^empty/) { base[n] = exact[k]; abase[n] = v["approx"]; next }
        if (!header++) {
            printf "| %-58s | %11s | %11s | %6s | %-10s |\n", "operation", "exact", "SysTick", "evals", "carry (m)"
            printf "|%s|%s|%s|%s|%s|\n", "------------------------------------------------------------", "------------:", "------------:", "-------:", "------------"
        }
        evals = v["evals"] == 0 ? "" : (v["evals"] == 4294967295 ? "error" : v["evals"])
        carry = v["carry"] ~ /NaN|nan/ ? "" : sprintf("%.4f", v["carry"])
        printf "| %-58s | %11d | %11d | %6s | %-10s |\n", op, (exact[k] - base[n]) / n, v["approx"] - abase[n], evals, carry
    }
    /^reference carry/ { ref = $3 }
    END { if (ref) printf "\nf64 reference carry of this shot: %s m\n", ref; if (notes) printf "%s\n", notes }
' "$tmp/icount.txt" "$tmp/log.txt"

if [ "${PROFILE:-0}" != 0 ]; then
    echo
    echo "## where the instructions go (top ${PROFILE} functions per operation; whole loop of n calls)"
    awk '
        FNR == NR { if ($1 == "icount" && $3 ~ /^[0-9]+$/ && $4 == "fn") { k = $3; line = $0; sub(/^icount region [0-9]+ fn /, "", line); fns[k] = fns[k] "    " line "\n" } next }
        /^cost region=[0-9]+ n=/ { split($2, kv, "="); op = $0; sub(/.* op=/, "", op); if (op !~ /^empty/) printf "%s\n%s", op, fns[kv[2]] }
    ' "$tmp/icount.txt" "$tmp/log.txt"
fi

if [ -n "${ADDRS:-}" ]; then
    echo
    echo "## where operation $ADDRS's instructions go, by source line (innermost core frame <- its caller)"
    awk '$1 == "icount" && $2 == "addr" { print "0x" $3 }' "$tmp/icount.txt" |
        llvm-addr2line -e "$elf" -i -f -C -a > "$tmp/lines.txt"
    awk -v src="$(cd .. && pwd)/core/src/" '
        FNR == NR { if ($1 == "icount" && $2 == "addr") n["0x" $3] = $4; next }
        function flush() { if (addr != "") { k = (inner == "" ? "?" : inner (outer == "" ? "" : " <- " outer)); sum[k] += n[addr] } }
        /^0x[0-9a-f]+$/ { flush(); addr = $0; inner = ""; outer = ""; next }
        /^\// || /^\?/ {
            if (index($0, src) == 1) {
                loc = substr($0, length(src) + 1); sub(/ .*/, "", loc)
                if (inner == "") inner = loc; else if (outer == "") outer = loc
            }
            next
        }
        END { flush(); for (k in sum) printf "%8d  %s\n", sum[k], k }
    ' "$tmp/icount.txt" "$tmp/lines.txt" | sort -rn | head -n "${LINES:-40}"
fi
