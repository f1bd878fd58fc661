# Sourced by the firmware scripts: maps a board name to its cargo target, target dir and
# code-generation flags. Usage: . ./board.sh BOARD   (an386 | an500 | microbit)
# Sets: BOARD TARGET TARGET_DIR and exports CARRY_BOARD (read by qemu-run) and, for the
# M7, the rustflags that enable its double-precision FPU; for the M0, opt-level "s".
BOARD=${1:-an386}
case "$BOARD" in
    an386) TARGET=thumbv7em-none-eabihf; TARGET_DIR=target ;;
    an500) TARGET=thumbv7em-none-eabihf; TARGET_DIR=target/m7
           # Replaces the (empty) [target.thumbv7em-none-eabihf] rustflags of
           # .cargo/config.toml; the link arguments live in the cfg() table and stay.
           export CARGO_TARGET_THUMBV7EM_NONE_EABIHF_RUSTFLAGS="-C target-cpu=cortex-m7" ;;
    microbit) TARGET=thumbv6m-none-eabi; TARGET_DIR=target/m0
              # 256 KiB of flash: optimise for size. At opt-level 3 the golden-test image
              # (f32 and f64 in software, every case's host results) outgrew it by 2.6 KiB
              # with the aimed hop (issue 12); at "s" it is 220 KiB. Same bits either way.
              export CARGO_PROFILE_RELEASE_OPT_LEVEL=s ;;
    *) echo "unknown board $BOARD (an386 | an500 | microbit)" >&2; return 2 2>/dev/null || exit 2 ;;
esac
export CARRY_BOARD=$BOARD CARGO_TARGET_DIR=$TARGET_DIR
