/* See golden_run.h. */
#include <stdint.h>
#include <string.h>

#include "carry.h"
#include "carry_golden.h"
#include "golden_run.h"

static char *put(char *p, const char *s) {
    while (*s) *p++ = *s++;
    return p;
}

static char *hex(char *p, uint64_t v, int digits) {
    for (int i = digits - 1; i >= 0; --i) *p++ = "0123456789abcdef"[(v >> (4 * i)) & 15u];
    return p;
}

static char *dec(char *p, unsigned v) {
    char tmp[12];
    int n = 0;
    do {
        tmp[n++] = (char)('0' + v % 10u);
        v /= 10u;
    } while (v);
    while (n) *p++ = tmp[--n];
    return p;
}

static uint64_t bits32(float x) {
    uint32_t u;
    memcpy(&u, &x, sizeof u);
    return u;
}

static uint64_t bits64(double x) {
    uint64_t u;
    memcpy(&u, &x, sizeof u);
    return u;
}

/* Emits one line; `bits` holds `n` values (digits hex digits each) when code is CARRY_OK. */
static void line(carry_golden_emit emit, const char *kind, const char *prec, const char *name,
                 carry_error_t code, const uint64_t *bits, int n, int digits) {
    static char buf[1024];
    char *p = put(put(put(put(put(buf, kind), " "), prec), " "), name);
    if (code == CARRY_OK) {
        p = put(p, " ok");
        for (int i = 0; i < n; ++i) p = hex(put(p, " "), bits[i], digits);
    } else {
        p = dec(put(p, " err "), (unsigned)code);
    }
    p = put(p, "\n");
    *p = 0;
    emit(buf);
}

/* The results in the order of firmware/src/cases.rs (IMPACT_OUTPUTS, FLIGHT_OUTPUTS). */
#define DEFINE_PRECISION(S, SUF, T, BITS, DIGITS, PREC)                                              \
    static int run_##S(carry_golden_emit emit) {                                               \
        uint64_t b[23];                                                                         \
        int runs = 0;                                                                           \
        for (int k = 0; k < CARRY_GOLDEN_IMPACT_N_##S; ++k, ++runs) {                          \
            CarryImpactResult##S r;                                                             \
            carry_error_t code = carry_impact_##SUF(&CARRY_GOLDEN_IMPACT_##S[k], &r);             \
            const T *vs[5] = {r.ball_velocity_mps, r.ball_spin_radps, r.club_velocity_mps,      \
                              r.club_spin_radps, r.impulse_ns};                                 \
            for (int v = 0; v < 5; ++v)                                                         \
                for (int c = 0; c < 3; ++c) b[3 * v + c] = BITS(vs[v][c]);                      \
            const T m[8] = {r.ball_speed_mps, r.launch_angle_rad, r.launch_direction_rad,      \
                            r.spin_radps,     r.backspin_radps,   r.sidespin_radps,            \
                            r.spin_axis_rad,  r.smash_factor};                                  \
            for (int i = 0; i < 8; ++i) b[15 + i] = BITS(m[i]);                                 \
            line(emit, "impact", PREC, CARRY_GOLDEN_IMPACT_NAMES_##S[k], code, b, 23, DIGITS); \
        }                                                                                       \
        for (int k = 0; k < CARRY_GOLDEN_FLIGHT_N_##S; ++k, ++runs) {                          \
            CarryFlightResult##S r;                                                             \
            carry_error_t code = carry_flight_##SUF(&CARRY_GOLDEN_FLIGHT_##S[k], NULL, 0, NULL, &r); \
            const T f[13] = {r.carry_m,           r.carry_x_m,          r.side_m,              \
                             r.flight_time_s,     r.apex_m,             r.apex_time_s,         \
                             r.landing_angle_rad, r.landing_speed_mps,  r.landing_spin_radps,  \
                             r.air_density_kgm3,  (T)r.force_evaluations, (T)r.steps,          \
                             (T)r.rejected_steps};                                              \
            for (int i = 0; i < 13; ++i) b[i] = BITS(f[i]);                                     \
            line(emit, "flight", PREC, CARRY_GOLDEN_FLIGHT_NAMES_##S[k], code, b, 13, DIGITS); \
        }                                                                                       \
        return runs;                                                                            \
    }

DEFINE_PRECISION(F32, f32, float, bits32, 8, "f32")
DEFINE_PRECISION(F64, f64, double, bits64, 16, "f64")

int carry_golden_run(const char *precision, carry_golden_emit emit) {
    int runs = 0;
    int only32 = precision && strcmp(precision, "f32") == 0;
    int only64 = precision && strcmp(precision, "f64") == 0;
    if (!only64) runs += run_F32(emit);
    if (!only32) runs += run_F64(emit);
    return runs;
}
