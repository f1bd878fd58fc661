#!/usr/bin/env bash
# Flash and static RAM of the firmware images, f32 and f64.
#
#   ./size.sh [an386|an500|microbit]      (default an386)
#
# flash = .vector_table + .text + .rodata + .data (its load image);
# static RAM = .data + .bss + .uninit. The stack comes on top (see the `shot` binary's
# painted-stack report). `size-baseline` is the same runtime (defmt, semihosting, exit,
# handlers) with no physics, so `image − baseline` is what the core costs.
set -euo pipefail
cd "$(dirname "$0")"
. ./board.sh "${1:-an386}"
SIZE=${SIZE:-arm-none-eabi-size}
command -v "$SIZE" >/dev/null || { echo "size.sh: $SIZE not found (apt-get install binutils-arm-none-eabi)" >&2; exit 127; }

bins=(size-baseline size-impact size-flight size-shot shot)
echo "# flash / static RAM on $BOARD ($TARGET), bytes"
printf '| %-14s | %-4s | %8s | %10s | %16s |\n' image real flash "static RAM" "flash − baseline"
printf '|%s|%s|%s|%s|%s|\n' ---------------- ------ ---------: -----------: -----------------:
for real in f32 f64; do
    features=()
    [ "$real" = f64 ] && features=(--features f64)
    args=(--release --target "$TARGET" "${features[@]}")
    cargo build --quiet "${args[@]}" $(printf -- '--bin %s ' "${bins[@]}")
    base=
    for b in "${bins[@]}"; do
        elf=$CARGO_TARGET_DIR/$TARGET/release/$b
        read -r flash ram < <("$SIZE" -A "$elf" | awk '
            $1 == ".vector_table" || $1 == ".text" || $1 == ".rodata" { f += $2 }
            $1 == ".data" { f += $2; r += $2 }
            $1 == ".bss" || $1 == ".uninit" { r += $2 }
            END { print f + 0, r + 0 }')
        [ -z "$base" ] && base=$flash
        printf '| %-14s | %-4s | %8d | %10d | %16d |\n' "$b" "$real" "$flash" "$ram" $((flash - base))
    done
done
