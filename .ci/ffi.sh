#!/usr/bin/env bash
# The C API in CI (issue 13; called by .ci/run): installs what a fresh machine lacks, then
#  1. regenerates ffi/include/carry.h with cbindgen and fails on drift;
#  2. builds libcarry_ffi (host), generates the golden data (ffi/examples/golden_c.rs) and
#     builds + runs the host C test (ffi/tests/c/test_carry.c) against the staticlib and
#     the cdylib;
#  3. builds libcarry_ffi.a for thumbv7em-none-eabihf (profile `firmware`) and the C
#     example firmware (ffi/examples/firmware, arm-none-eabi-gcc), runs its golden suite on
#     QEMU mps2-an386 and checks it bit for bit against the host's expected results;
#  4. counts the instructions of a full f32 shot through the C API (firmware/icount-plugin)
#     and prints them and the flash size beside the Rust firmware's (firmware/cost.sh,
#     firmware/size.sh). Fails if the C shot costs more than FFI_MAX_RATIO (default 1.05)
#     times the Rust one.
# Budget: ~1.5 minutes on the 2-core CI machine after .ci/firmware.sh (warm caches); a
# fresh machine adds `cargo install cbindgen` (~3.5 min) and the firmware build.
set -euo pipefail
cd "$(dirname "$0")/.."
start=$SECONDS
t() { printf '\n--- ffi: %s (t=%ss)\n' "$*" "$((SECONDS - start))"; }
CBINDGEN_VERSION=0.29.4
TARGET=thumbv7em-none-eabihf
TD=${CARGO_TARGET_DIR:-target}
GEN=$TD/ffi-gen
OUT=$TD/ffi-firmware

t "install"
need_apt=()
command -v arm-none-eabi-gcc >/dev/null || need_apt+=(gcc-arm-none-eabi)
[ -e /usr/lib/arm-none-eabi/newlib/libc.a ] || [ -e /usr/lib/arm-none-eabi/lib/libc.a ] || need_apt+=(libnewlib-arm-none-eabi)
command -v qemu-system-arm >/dev/null || need_apt+=(qemu-system-arm)
command -v arm-none-eabi-size >/dev/null || need_apt+=(binutils-arm-none-eabi)
command -v cc >/dev/null || need_apt+=(gcc)
if [ ${#need_apt[@]} -gt 0 ]; then
    sudo_=; [ "$(id -u)" = 0 ] || sudo_=sudo
    $sudo_ apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $sudo_ apt-get install -y -qq --no-install-recommends "${need_apt[@]}" >/dev/null
fi
rustup target list --installed | grep -qx "$TARGET" || rustup target add "$TARGET"
if [ "$(cbindgen --version 2>/dev/null)" != "cbindgen $CBINDGEN_VERSION" ]; then
    cargo install --locked "cbindgen@$CBINDGEN_VERSION"
fi
# The Rust firmware's cost.sh (step 4) links with flip-link and decodes with defmt-print;
# .ci/firmware.sh installs them first in .ci/run, this covers a run of ffi.sh alone.
need_cargo=()
command -v flip-link >/dev/null || need_cargo+=(flip-link)
command -v defmt-print >/dev/null || need_cargo+=(defmt-print)
[ ${#need_cargo[@]} -eq 0 ] || cargo install --locked "${need_cargo[@]}"
arm-none-eabi-gcc --version | head -1
cbindgen --version

t "header drift: ffi/include/carry.h is cbindgen's output"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cbindgen --quiet --config ffi/cbindgen.toml --crate carry-ffi --output "$tmp/carry.h"
if ! cmp -s "$tmp/carry.h" ffi/include/carry.h; then
    diff -u ffi/include/carry.h "$tmp/carry.h" | head -40 >&2 || true
    echo "ffi/include/carry.h is stale: run (cd ffi && cbindgen --config cbindgen.toml --crate carry-ffi --output include/carry.h)" >&2
    exit 1
fi
echo "carry.h up to date"

t "host: libcarry_ffi, golden data, C test (staticlib and cdylib)"
cargo build --quiet --release -p carry-ffi
cargo run --quiet --release -p carry-ffi --example golden_c -- "$GEN"
ccflags=(-std=c11 -Wall -Wextra -Werror -pedantic -O2 -I ffi/include -I "$GEN" -I ffi/tests/c)
csrc=(ffi/tests/c/test_carry.c ffi/tests/c/golden_run.c)
native=$(cargo rustc --quiet --release -p carry-ffi --crate-type staticlib -- --print native-static-libs 2>&1 \
    | sed -n 's/.*native-static-libs: //p' | tail -1)
# shellcheck disable=SC2086
cc "${ccflags[@]}" "${csrc[@]}" "$TD/release/libcarry_ffi.a" $native -o "$tmp/test_carry_static"
cc "${ccflags[@]}" "${csrc[@]}" -L "$TD/release" -lcarry_ffi -Wl,-rpath,"$(cd "$TD/release" && pwd)" -lm -o "$tmp/test_carry_shared"
"$tmp/test_carry_static" "$GEN/expected.txt"
"$tmp/test_carry_shared" "$GEN/expected.txt"

t "Cortex-M: libcarry_ffi.a ($TARGET, profile firmware) and the C firmware"
cargo rustc --quiet -p carry-ffi --target "$TARGET" --profile firmware --crate-type staticlib
mkdir -p "$GEN" "$OUT"
lib=$(cd "$TD/$TARGET/firmware" && pwd)/libcarry_ffi.a
make -s -C ffi/examples/firmware GEN="$(cd "$GEN" && pwd)" LIB="$lib" OUT="$(cd "$OUT" && pwd)"
qemu() { # ELF [extra args]: runs on mps2-an386, semihosting console on stdout
    local elf=$1; shift
    timeout -k 5 300 qemu-system-arm -machine mps2-an386 -cpu cortex-m4 -nographic \
        -serial none -monitor none -chardev stdio,id=semi \
        -semihosting-config enable=on,target=native,chardev=semi "$@" -kernel "$elf"
}

t "C firmware golden suite on QEMU mps2-an386, bit for bit against the host"
qemu "$OUT/golden.elf" > "$tmp/target.txt"
grep -v '^#' "$tmp/target.txt" > "$tmp/target-lines.txt"
if ! cmp -s "$tmp/target-lines.txt" "$GEN/expected.txt"; then
    diff "$GEN/expected.txt" "$tmp/target-lines.txt" | head -20 >&2 || true
    echo "the C firmware's results differ from the host's" >&2
    exit 1
fi
runs=$(wc -l < "$GEN/expected.txt")
echo "C firmware: $runs golden runs (impact and flight, f32 and f64) bit-identical to the host"

t "instruction count of a full f32 shot, C API vs Rust firmware (QEMU plugin)"
host=$(rustc -vV | sed -n 's/^host: //p')
(cd firmware/icount-plugin && CARGO_TARGET_DIR=target cargo build --quiet --release --target "$host")
plugin=$PWD/firmware/icount-plugin/target/$host/release/libcarry_icount_plugin.so
qemu "$OUT/shot.elf" -icount shift=0 -plugin "$plugin,out=$tmp/icount.txt" > "$tmp/shot.txt"
cat "$tmp/shot.txt"
c_empty=$(awk '$1 == "icount" && $2 == "region" && $3 == 0 { print $4 }' "$tmp/icount.txt")
c_shot=$(awk '$1 == "icount" && $2 == "region" && $3 == 1 { print $4 }' "$tmp/icount.txt")
c_insns=$((c_shot - c_empty))
(cd firmware && ./cost.sh an386) > "$tmp/rust-cost.txt"
rust_insns=$(awk -F'|' '/full shot \+ ClubSpec::validate \+ Scene::prepare \[f32\]/ { gsub(/ /, "", $3); print $3 }' "$tmp/rust-cost.txt")
(cd firmware && ./size.sh an386) > "$tmp/rust-size.txt"
flash() { arm-none-eabi-size -A "$1" | awk '
    $1 == ".vector_table" || $1 == ".text" || $1 == ".rodata" || $1 == ".ARM.exidx" { f += $2 }
    $1 == ".data" { f += $2 } END { print f + 0 }'; }
rust_flash() { awk -F'|' -v b="$1" '{ gsub(/ /, "", $2); gsub(/ /, "", $3); gsub(/ /, "", $4) } $2 == b && $3 == "f32" { print $4 }' "$tmp/rust-size.txt"; }
ratio=$(awk -v c="$c_insns" -v r="$rust_insns" 'BEGIN { printf "%.3f", c / r }')
echo
echo "# full f32 shot on mps2-an386 (Cortex-M4F): validate club, prepare scene, strike, impact, flight"
printf '| %-44s | %12s | %10s |\n' image "instructions" "flash (B)"
printf '|%s|%s|%s|\n' ---------------------------------------------- -------------: -----------:
printf '| %-44s | %12d | %10d |\n' "Rust firmware (cost.sh row / size-shot)" "$rust_insns" "$(rust_flash size-shot)"
printf '| %-44s | %12s | %10d |\n' "Rust firmware example (bin shot)" "" "$(rust_flash shot)"
printf '| %-44s | %12d | %10d |\n' "C firmware through the C API (shot.elf)" "$c_insns" "$(flash "$OUT/shot.elf")"
printf '| %-44s | %12s | %10d |\n' "C firmware golden suite (golden.elf)" "" "$(flash "$OUT/golden.elf")"
echo "C / Rust instructions: $ratio (limit ${FFI_MAX_RATIO:-1.05})"
awk -v x="$ratio" -v m="${FFI_MAX_RATIO:-1.05}" 'BEGIN { exit !(x <= m) }' \
    || { echo "the C API's full shot costs more than ${FFI_MAX_RATIO:-1.05}x the Rust firmware's" >&2; exit 1; }

t "done"
