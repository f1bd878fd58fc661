#!/usr/bin/env bash
# Firmware CI (called by .ci/run): installs what a fresh machine lacks, then runs the
# on-target golden suite on the emulated Cortex-M4F (mps2-an386) and, within the time
# budget, on the Cortex-M7 (mps2-an500) and Cortex-M0 (micro:bit) boards.
#
# Environment: CARRY_FIRMWARE_BOARDS (default "an386 an500 microbit") picks the boards.
# Budget: under 10 minutes on the 2-core CI machine (see docs/firmware.md for timings).
set -euo pipefail
cd "$(dirname "$0")/.."
start=$SECONDS
t() { printf '\n--- firmware: %s (t=%ss)\n' "$*" "$((SECONDS - start))"; }

t "install"
need_apt=()
command -v qemu-system-arm >/dev/null || need_apt+=(qemu-system-arm)
command -v arm-none-eabi-size >/dev/null || need_apt+=(binutils-arm-none-eabi)
if [ ${#need_apt[@]} -gt 0 ]; then
    sudo_=; [ "$(id -u)" = 0 ] || sudo_=sudo
    $sudo_ apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $sudo_ apt-get install -y -qq --no-install-recommends "${need_apt[@]}" >/dev/null
fi
qemu-system-arm --version | head -1
for m in mps2-an386 mps2-an500 microbit; do
    qemu-system-arm -machine help | grep -q "^$m " || { echo "qemu-system-arm lacks machine $m" >&2; exit 1; }
done
installed_targets=$(rustup target list --installed)
for tgt in thumbv7em-none-eabihf thumbv6m-none-eabi; do
    grep -qx "$tgt" <<<"$installed_targets" || rustup target add "$tgt"
done
need_cargo=()
command -v flip-link >/dev/null || need_cargo+=(flip-link)
command -v defmt-print >/dev/null || need_cargo+=(defmt-print)
if [ ${#need_cargo[@]} -gt 0 ]; then
    cargo install --locked "${need_cargo[@]}"
fi
defmt-print --version

cd firmware
t "rustfmt"
cargo fmt -p carry-firmware --check   # not --all: that would reach ../core (path dependency)
(cd icount-plugin && cargo fmt --check)

passed=0
run_suite() { # board
    local board=$1 log
    log=$(mktemp)
    t "on-target tests on $board"
    ( . ./board.sh "$board" && cargo test --release --target "$TARGET" ) 2>&1 | tee "$log"
    local rc=${PIPESTATUS[0]}
    [ "$rc" = 0 ] || { echo "firmware tests failed on $board (exit $rc)" >&2; exit "$rc"; }
    grep -q 'all tests passed!' "$log" || { echo "no defmt-test summary on $board" >&2; exit 1; }
    local n
    n=$(grep -cE '^\([0-9]+/[0-9]+\) running' "$log" || true)
    passed=$((passed + n))
    rm -f "$log"
}

for board in ${CARRY_FIRMWARE_BOARDS:-an386 an500 microbit}; do
    run_suite "$board"
done

t "example: a full shot on the M4F"
cargo run --release --bin shot

t "instruction counts (exact, QEMU plugin) on the M4F"
./cost.sh an386

t "flash / static RAM on the M4F"
./size.sh an386

t "done"
echo "firmware: $passed passed, 0 failed"
