/* Host test of the C API: the header compiles as C11, every golden case through the
   C API reproduces the results a host Rust program computed through the same API
   (expected.txt, bit for bit), carries are within the documented accuracy of the golden
   files' reference, and bad input gives the right error code.

     test_carry EXPECTED_TXT            (see .ci/ffi.sh and docs/ffi.md) */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "carry.h"
#include "carry_golden.h"
#include "golden_run.h"

static int failures = 0;
static FILE *expected = NULL;
static int lines = 0;

#define CHECK(cond)                                                         \
    do {                                                                    \
        if (!(cond)) {                                                      \
            fprintf(stderr, "%s:%d: check failed: %s\n", __FILE__, __LINE__, #cond); \
            ++failures;                                                     \
        }                                                                   \
    } while (0)

#define CHECK_CODE(call, want)                                                         \
    do {                                                                               \
        carry_error_t got_ = (call);                                                   \
        if (got_ != (want)) {                                                          \
            fprintf(stderr, "%s:%d: %s gave %d (%s), want %s\n", __FILE__, __LINE__, #call, \
                    (int)got_, carry_error_message(got_), #want);                      \
            ++failures;                                                                \
        }                                                                              \
    } while (0)

/* Compares each emitted line with the next line of expected.txt. */
static void compare(const char *got) {
    static char want[4096];
    ++lines;
    if (!fgets(want, sizeof want, expected)) {
        fprintf(stderr, "expected.txt ends before: %s", got);
        ++failures;
    } else if (strcmp(want, got) != 0) {
        if (failures < 5) fprintf(stderr, "differs from the host:\n  got  %s  want %s", got, want);
        ++failures;
    }
}

/* Golden reference carry (f64, tests/golden/flight.json) of case `name`. */
static double reference_carry(const char *name) {
    for (int k = 0; k < CARRY_GOLDEN_CARRY_N; ++k)
        if (strncmp(name, CARRY_GOLDEN_CARRY[k].name, strlen(CARRY_GOLDEN_CARRY[k].name)) == 0 &&
            name[strlen(CARRY_GOLDEN_CARRY[k].name)] == '/')
            return CARRY_GOLDEN_CARRY[k].carry_m;
    return NAN;
}

/* The documented accuracy of the default fidelity (docs/flight.md): 1 mm in f64, 1 cm in
   f32, against the golden files' independent reference, seed aerodynamics. */
static void accuracy(void) {
    int n = 0;
    for (int k = 0; k < CARRY_GOLDEN_FLIGHT_N_F64; ++k) {
        const char *name = CARRY_GOLDEN_FLIGHT_NAMES_F64[k];
        if (!strstr(name, "/default")) continue;
        CarryFlightResultF64 r64;
        CarryFlightResultF32 r32;
        CHECK_CODE(carry_flight_f64(&CARRY_GOLDEN_FLIGHT_F64[k], NULL, 0, NULL, &r64), CARRY_OK);
        CHECK_CODE(carry_flight_f32(&CARRY_GOLDEN_FLIGHT_F32[k], NULL, 0, NULL, &r32), CARRY_OK);
        double ref = reference_carry(name);
        CHECK(fabs(r64.carry_m - ref) <= 1e-3);
        CHECK(fabs((double)r32.carry_m - ref) <= 1e-2);
        ++n;
    }
    CHECK(n == CARRY_GOLDEN_CARRY_N);
}

static void defaults_and_trajectory(void) {
    CarryShotInputF32 in;
    CarryShotResultF32 full, small;
    CarrySampleF32 samples[512], few[2];
    size_t count = 99;
    CHECK_CODE(carry_shot_input_default_f32(&in), CARRY_OK);
    CHECK_CODE(carry_shot_f32(&in, samples, 512, &count, &full), CARRY_OK);
    CHECK(count > 2 && count < 512);
    CHECK(full.flight.carry_m > 0.0f && isfinite(full.flight.carry_m));
    /* The last sample is the landing. */
    CHECK(samples[count - 1].time_s == full.flight.flight_time_s);
    CHECK(samples[count - 1].position_m[0] == full.flight.landing_position_m[0]);
    /* A too-small buffer: complete results, two samples, and the code says so. */
    CHECK_CODE(carry_shot_f32(&in, few, 2, &count, &small), CARRY_ERR_BUFFER_TOO_SMALL);
    CHECK(count == 2 && small.flight.recording_full == 1);
    CHECK(small.flight.carry_m == full.flight.carry_m);
    CHECK(memcmp(few, samples, sizeof few) == 0);
    /* A buffer needs a count. */
    CHECK_CODE(carry_shot_f32(&in, few, 2, NULL, &small), CARRY_ERR_NULL_POINTER);

    CarryShotInputF64 in64;
    CarryShotResultF64 out64;
    CHECK_CODE(carry_shot_input_default_f64(&in64), CARRY_OK);
    CHECK_CODE(carry_shot_f64(&in64, NULL, 0, NULL, &out64), CARRY_OK);
    /* f32 and f64 agree to the f32 default fidelity (1 cm). */
    CHECK(fabs(out64.flight.carry_m - (double)full.flight.carry_m) < 1e-2);
}

static void presets(void) {
    uint32_t n = carry_club_preset_count();
    CHECK(n > 0);
    for (uint32_t k = 0; k < n; ++k) {
        const char *name = carry_club_preset_name(k);
        CarryClubF64 a, b;
        CarryShotInputF64 in;
        CarryShotResultF64 out;
        CHECK(name != NULL);
        CHECK_CODE(carry_club_preset_f64(name, &a), CARRY_OK);
        CHECK_CODE(carry_club_preset_index_f64(k, &b), CARRY_OK);
        CHECK(a.mass_kg == b.mass_kg && a.loft_rad == b.loft_rad && a.contact == b.contact);
        CHECK(memcmp(a.inertia_kgm2, b.inertia_kgm2, sizeof a.inertia_kgm2) == 0);
        CHECK_CODE(carry_shot_input_default_f64(&in), CARRY_OK);
        in.club = a;
        CHECK_CODE(carry_delivery_typical_f64(name, &in.delivery), CARRY_OK);
        /* the named-club rule at the typical loft: the typical strike (to the table's 0.1 mm) */
        double h = 1.0;
        CHECK_CODE(carry_strike_height_f64(name, in.delivery.dynamic_loft_rad, 0.021336, &h),
                   CARRY_OK);
        CHECK(fabs(h - in.delivery.impact_height_m) < 6e-5);
        CHECK_CODE(carry_shot_f64(&in, NULL, 0, NULL, &out), CARRY_OK);
        CHECK(out.flight.carry_m > 0.0);
    }
    CHECK(carry_club_preset_name(n) == NULL);
    CarryClubF32 c;
    CHECK_CODE(carry_club_preset_f32("putter", &c), CARRY_ERR_UNKNOWN_NAME);
    CHECK_CODE(carry_club_preset_index_f32(n, &c), CARRY_ERR_UNKNOWN_NAME);
    CHECK_CODE(carry_club_preset_f32(NULL, &c), CARRY_ERR_NULL_POINTER);
    float h32 = 0.0f;
    CHECK_CODE(carry_strike_height_f32("7iron", NAN, 0.021336f, &h32), CARRY_ERR_INVALID_INPUT);
    CHECK_CODE(carry_strike_height_f32("putter", 0.3f, 0.021336f, &h32), CARRY_ERR_UNKNOWN_NAME);
    CHECK_CODE(carry_strike_height_f32("7iron", 0.3f, 0.021336f, NULL), CARRY_ERR_NULL_POINTER);
}

/* Issue 36: a known launch flown forward, its spin and axis fitted back from the flight's
 * summaries within 1σ, with the measured ball speed and angles; the error codes. */
static CarryLaunchFromFlightWorkspaceF64 launch_fit_scratch; /* caller-owned, 43 KiB */

static void launch_from_flight(void) {
    CarryFlightInputF64 fin;
    CarryFlightResultF64 fout;
    const double spin = carry_rpm_to_radps_f64(2800.0), axis = carry_deg_to_rad_f64(5.0);
    CHECK_CODE(carry_flight_input_default_f64(&fin), CARRY_OK);
    fin.launch.ball_speed_mps = 70.0;
    fin.launch.launch_angle_rad = carry_deg_to_rad_f64(12.0);
    fin.launch.launch_direction_rad = 0.0;
    fin.launch.backspin_radps = spin * cos(axis);
    fin.launch.sidespin_radps = spin * sin(axis);
    CHECK_CODE(carry_flight_f64(&fin, NULL, 0, NULL, &fout), CARRY_OK);

    CarryLaunchFromFlightInputF64 in;
    CarryLaunchFromFlightResultF64 out;
    CHECK_CODE(carry_launch_from_flight_input_default_f64(&in), CARRY_OK);
    in.measured = CARRY_MEASURED_BALL_SPEED | CARRY_MEASURED_LAUNCH_ANGLE |
                  CARRY_MEASURED_LAUNCH_DIRECTION;
    in.measured_launch.ball_speed_mps = 70.0;
    in.measured_launch.launch_angle_rad = carry_deg_to_rad_f64(12.0);
    in.measured_launch.launch_direction_rad = 0.0;
    in.observed = CARRY_OBSERVED_APEX_HEIGHT | CARRY_OBSERVED_CARRY | CARRY_OBSERVED_SIDE |
                  CARRY_OBSERVED_FLIGHT_TIME | CARRY_OBSERVED_LAND_ANGLE;
    in.summaries.apex_height_m = fout.apex_m;
    in.summaries.carry_m = fout.carry_m;
    in.summaries.side_m = fout.side_m;
    in.summaries.flight_time_s = fout.flight_time_s;
    in.summaries.land_angle_rad = fout.landing_angle_rad;
    CHECK_CODE(carry_launch_from_flight_f64(&in, &launch_fit_scratch, &out), CARRY_OK);
    CHECK(fabs(out.value.spin_radps - spin) < out.sd.spin_radps);
    CHECK(fabs(out.value.spin_axis_rad - axis) < out.sd.spin_axis_rad);
    CHECK(out.source.spin == CARRY_SOURCE_FITTED && out.source.spin_axis == CARRY_SOURCE_FITTED);
    CHECK(out.source.ball_speed == CARRY_SOURCE_MEASURED);
    CHECK(out.observations == 5 && out.flights > 0 && isfinite(out.chi2));
    CHECK(fabs(out.flight.carry_m - fout.carry_m) < 1.0);
    /* a track array of three points past its capacity, a NULL array, too few data */
    CarryTrackPointF64 track[CARRY_LAUNCH_FIT_MAX_TRACK_POINTS + 1];
    memset(track, 0, sizeof track);
    CarryLaunchFromFlightInputF64 bad = in;
    bad.track = track;
    bad.track_len = CARRY_LAUNCH_FIT_MAX_TRACK_POINTS + 1;
    CHECK_CODE(carry_launch_from_flight_f64(&bad, &launch_fit_scratch, &out),
               CARRY_ERR_TOO_MANY_OBSERVATIONS);
    bad.track = NULL;
    bad.track_len = 3;
    CHECK_CODE(carry_launch_from_flight_f64(&bad, &launch_fit_scratch, &out),
               CARRY_ERR_NULL_POINTER);
    bad = in;
    bad.observed = CARRY_OBSERVED_CARRY;
    CHECK_CODE(carry_launch_from_flight_f64(&bad, &launch_fit_scratch, &out),
               CARRY_ERR_TOO_FEW_OBSERVATIONS);
    bad = in;
    bad.observed = CARRY_OBSERVED_APEX_HEIGHT | CARRY_OBSERVED_CARRY | CARRY_OBSERVED_FLIGHT_TIME;
    bad.summaries.apex_height_m = 31.9;
    bad.summaries.carry_m = 222.4;
    bad.summaries.flight_time_s = 6.7;
    CHECK_CODE(carry_launch_from_flight_f64(&bad, &launch_fit_scratch, &out),
               CARRY_ERR_UNIDENTIFIABLE);
    CHECK(out.unidentified == CARRY_DATUM_SPIN_AXIS);
    CHECK_CODE(carry_launch_from_flight_f64(&in, NULL, &out), CARRY_ERR_NULL_POINTER);
}

static void bad_input(void) {
    CarryShotInputF32 in;
    CarryShotResultF32 out;
    CarryImpactInputF64 imp;
    CarryImpactResultF64 imp_out;
    CHECK_CODE(carry_shot_input_default_f32(&in), CARRY_OK);
    in.delivery.club_speed_mps = NAN;
    CHECK_CODE(carry_shot_f32(&in, NULL, 0, NULL, &out), CARRY_ERR_INVALID_INPUT);
    CHECK_CODE(carry_shot_input_default_f32(&in), CARRY_OK);
    in.club.mass_kg = -1.0f;
    CHECK_CODE(carry_shot_f32(&in, NULL, 0, NULL, &out), CARRY_ERR_INVALID_INPUT);
    CHECK_CODE(carry_shot_input_default_f32(&in), CARRY_OK);
    in.delivery.impact_toe_m = 0.5f;
    CHECK_CODE(carry_shot_f32(&in, NULL, 0, NULL, &out), CARRY_ERR_OFF_FACE);
    CHECK_CODE(carry_shot_input_default_f32(&in), CARRY_OK);
    in.scene.landing_height_m = 1000.0f;
    CHECK_CODE(carry_shot_f32(&in, NULL, 0, NULL, &out), CARRY_ERR_NO_LANDING);
    CHECK_CODE(carry_shot_input_default_f32(&in), CARRY_OK);
    in.scene.aero = 42u;
    CHECK_CODE(carry_shot_f32(&in, NULL, 0, NULL, &out), CARRY_ERR_UNKNOWN_OPTION);
    CHECK_CODE(carry_impact_input_default_f64(&imp), CARRY_OK);
    imp.delivery.club_speed_mps = 0.0;
    CHECK_CODE(carry_impact_f64(&imp, &imp_out), CARRY_ERR_NO_APPROACH);
    CHECK_CODE(carry_impact_f64(NULL, &imp_out), CARRY_ERR_NULL_POINTER);
    CHECK_CODE(carry_impact_f64(&imp, NULL), CARRY_ERR_NULL_POINTER);
    CHECK_CODE(carry_scene_default_f64(NULL), CARRY_ERR_NULL_POINTER);
    /* Every code has a message; unknown codes too. */
    for (int code = CARRY_OK; code <= CARRY_ERR_TOO_MANY_OBSERVATIONS; ++code) {
        const char *m = carry_error_message((uint32_t)code);
        CHECK(m != NULL && m[0] != 0);
    }
    CHECK(strcmp(carry_error_message(1000u), "unknown error code") == 0);
}

int main(int argc, char **argv) {
    if (argc != 2 || !(expected = fopen(argv[1], "r"))) {
        fprintf(stderr, "usage: test_carry EXPECTED_TXT (from the golden_c example)\n");
        return 2;
    }
    int runs = carry_golden_run(NULL, compare);
    char rest[8];
    if (fgets(rest, sizeof rest, expected)) {
        fprintf(stderr, "expected.txt has more lines than the %d runs\n", runs);
        ++failures;
    }
    fclose(expected);
    int golden_failures = failures;
    accuracy();
    defaults_and_trajectory();
    presets();
    bad_input();
    launch_from_flight();
    printf("test_carry: %d golden runs bit-identical to the host Rust results (%d differ); "
           "%d failures in all\n", runs, golden_failures, failures);
    return failures == 0 ? 0 : 1;
}
