/* The C firmware's cost probe: one full f32 shot through the C API (validate the club,
   prepare the scene, strike, impact, flight) between the instruction-count markers of
   firmware/icount-plugin, after an empty region that calibrates the marker overhead —
   the C twin of the Rust firmware's "full shot + ClubSpec::validate + Scene::prepare"
   (firmware/src/bin/cost.rs). Prints the carry's bits. */
#include <stdint.h>
#include <string.h>

#include "carry.h"
#include "carry_golden.h"
#include "semihost.h"

/* Region markers: the plugin counts the instructions between their entries. */
__attribute__((noinline, used)) void carry_icount_start(void) { __asm__ volatile("nop"); }
__attribute__((noinline, used)) void carry_icount_stop(void) { __asm__ volatile("nop\n nop"); }

static void hex(char *p, uint32_t v) {
    for (int i = 7; i >= 0; --i) *p++ = "0123456789abcdef"[(v >> (4 * i)) & 15u];
}

int main(void) {
    /* volatile: the input is opaque to the compiler, as black_box in the Rust probe. */
    static volatile CarryShotInputF32 input;
    CarryShotInputF32 in;
    CarryShotResultF32 out;
    memcpy((void *)&input, &CARRY_COST_SHOT_F32, sizeof in);
    memcpy(&in, (const void *)&input, sizeof in);
    carry_icount_start(); /* region 0: empty (calibration) */
    carry_icount_stop();
    carry_icount_start(); /* region 1: the shot */
    carry_error_t code = carry_shot_f32(&in, 0, 0, 0, &out);
    carry_icount_stop();
    uint32_t bits;
    memcpy(&bits, &out.flight.carry_m, sizeof bits);
    char line[] = "shot f32 carry_bits 00000000 evals 00000000\n";
    hex(line + 20, bits);
    hex(line + 35, out.flight.force_evaluations);
    semihost_write0(code == CARRY_OK ? line : "shot f32 failed\n");
    return code == CARRY_OK ? 0 : 1;
}
