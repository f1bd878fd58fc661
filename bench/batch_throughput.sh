#!/usr/bin/env bash
# `carry batch shot` throughput (issue 6): full shots (delivery → impact → flight, default
# f64 fidelity) per second, including CSV parsing and CSV output, against batch size and
# thread count. Cost per shot should be flat in batch size.
#
#   bench/batch_throughput.sh [ROWS...]      (default: 1000 10000 100000 1000000)
#
# Inputs are random deliveries (fixed seed): club speed 35–50 m/s, attack −3..4°, path and
# face ±4°/±3°, impact ±8 mm up, ±15 mm toe, driver preset, standard scene. Output goes to
# /dev/null. Each size is run REPEATS times (default 3); the median wall time is reported,
# and the CPU time (user + sys) of that run: on a shared machine the CPU time per shot is
# the stabler figure (shots/CPU-s × cores = what an idle machine sustains).
set -euo pipefail
cd "$(dirname "$0")/.."
sizes=("${@:-1000 10000 100000 1000000}")
read -r -a sizes <<< "${sizes[*]}"
repeats=${REPEATS:-3}
cargo build --quiet --release -p carry-cli
carry=target/release/carry
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

largest=0
for n in "${sizes[@]}"; do (( n > largest )) && largest=$n; done
python3 - "$largest" > "$tmp/all.csv" <<'EOF'
import random, sys
random.seed(6)
n = int(sys.argv[1])
out = ["club_speed,attack_angle,club_path,face_angle,impact_height,impact_toe"]
for _ in range(n):
    out.append("%.2f,%.2f,%.2f,%.2f,%.4f,%.4f" % (
        random.uniform(35, 50), random.uniform(-3, 4), random.uniform(-4, 4),
        random.uniform(-3, 3), random.uniform(-0.008, 0.008), random.uniform(-0.015, 0.015)))
print("\n".join(out))
EOF

echo "# carry batch shot throughput ($(nproc) cores, load $(cut -d' ' -f1 /proc/loadavg) at start)"
printf "| %9s | %7s | %10s | %10s | %10s | %14s |\n" rows threads "wall (s)" "shots/s" "CPU (s)" "CPU µs/shot"
printf "|%s|%s|%s|%s|%s|%s|\n" ----------: --------: -----------: -----------: -----------: ---------------:
for n in "${sizes[@]}"; do
    head -n $((n + 1)) "$tmp/all.csv" > "$tmp/in.csv"
    for threads in 1 "$(nproc)"; do
        runs=()
        for _ in $(seq "$repeats"); do
            # "wall cpu" per run (GNU time: elapsed, user + sys).
            /usr/bin/time -f "%e %U %S" -o "$tmp/time" \
                "$carry" batch shot --no-progress --threads "$threads" -i "$tmp/in.csv" > /dev/null
            runs+=("$(awk '{ printf "%s %.3f", $1, $2 + $3 }' "$tmp/time")")
        done
        median=$(printf "%s\n" "${runs[@]}" | sort -g | sed -n "$(( (repeats + 1) / 2 ))p")
        awk -v n="$n" -v c="$threads" -v run="$median" 'BEGIN {
            split(run, r, " "); t = r[1] < 0.01 ? 0.01 : r[1]
            printf "| %9d | %7d | %10.2f | %10.0f | %10.2f | %14.3f |\n", n, c, r[1], n / t, r[2], r[2] / n * 1e6 }'
    done
done
