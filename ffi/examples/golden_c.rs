//! Generates the data of the C programs (`ffi/tests/c/test_carry.c`, the C firmware in
//! `ffi/examples/firmware/`) from the golden files, and the results they must print:
//!
//! ```sh
//! cargo run -p carry-ffi --example golden_c -- OUT_DIR
//! ```
//!
//! writes `OUT_DIR/carry_golden.h` (every golden case as the C API's input structs, in
//! exact hexadecimal floating point, f32 and f64; the f64 reference values of the golden
//! files; the firmware cost shot) and `OUT_DIR/expected.txt` (one line per run: the result
//! bits this host computes through the C API — which `tests/api.rs` proves equal to the
//! core's — in the format the C programs print).

#[path = "../../firmware/src/cases.rs"]
mod cases;
#[path = "../tests/support/golden.rs"]
mod golden;
#[path = "../../firmware/src/golden_input.rs"]
mod golden_input;

use carry_core::Integrator;
use carry_core::real::{Real, lit, to_f64};
use carry_core::units::deg;
use carry_ffi::error::CarryError;
use carry_ffi::scene::{CARRY_AERO_QUINTAVALLA, CARRY_AERO_TOUR2023};
use carry_ffi::*;
use std::fmt::Write as _;

/// A C literal of exactly `x` (hexadecimal floating point; `f` suffix for f32).
fn lit_c(x: f64, single: bool) -> String {
    if x.is_nan() {
        return "NAN".into();
    }
    if x.is_infinite() {
        return if x > 0.0 { "INFINITY" } else { "-INFINITY" }.into();
    }
    let b = x.to_bits();
    let sign = if b >> 63 == 1 { "-" } else { "" };
    let e = ((b >> 52) & 0x7ff) as i64;
    let m = b & ((1 << 52) - 1);
    let body = match (e, m) {
        (0, 0) => "0x0p+0".to_owned(),
        (0, _) => format!("0x0.{m:013x}p-1022"),
        _ => format!("0x1.{m:013x}p{:+}", e - 1023),
    };
    format!("{sign}{body}{}", if single { "f" } else { "" })
}

/// Writes designated initializers of the C API's structs.
struct Init<'a> {
    out: String,
    single: bool,
    _p: std::marker::PhantomData<&'a ()>,
}

impl Init<'_> {
    fn new(single: bool) -> Self {
        Self {
            out: "{".into(),
            single,
            _p: std::marker::PhantomData,
        }
    }
    fn f<T: Real>(mut self, name: &str, x: T) -> Self {
        let _ = write!(self.out, ".{name} = {}, ", lit_c(to_f64(x), self.single));
        self
    }
    fn a<T: Real>(mut self, name: &str, xs: &[T]) -> Self {
        let items: Vec<String> = xs.iter().map(|&x| lit_c(to_f64(x), self.single)).collect();
        let _ = write!(self.out, ".{name} = {{{}}}, ", items.join(", "));
        self
    }
    fn u(mut self, name: &str, x: u32) -> Self {
        let _ = write!(self.out, ".{name} = {x}u, ");
        self
    }
    fn s(mut self, name: &str, init: String) -> Self {
        let _ = write!(self.out, ".{name} = {init}, ");
        self
    }
    fn end(mut self) -> String {
        self.out.push('}');
        self.out
    }
}

fn single<T: Real>() -> bool {
    T::default_epsilon() > lit(1e-10)
}

fn club<T: Real>(c: &CarryClub<T>) -> String {
    Init::new(single::<T>())
        .f("mass_kg", c.mass_kg)
        .a("inertia_kgm2", &c.inertia_kgm2)
        .f("loft_rad", c.loft_rad)
        .f("roll_radius_m", c.roll_radius_m)
        .f("bulge_radius_m", c.bulge_radius_m)
        .f("face_depth_radius_m", c.face_depth_radius_m)
        .a("cg_to_face_m", &c.cg_to_face_m)
        .f("restitution", c.restitution)
        .u("contact", c.contact)
        .f("friction", c.friction)
        .f("tangential_restitution", c.tangential_restitution)
        .f(
            "tangential_restitution_slope",
            c.tangential_restitution_slope,
        )
        .f("restitution_speed_slope_spm", c.restitution_speed_slope_spm)
        .f("tangential_restitution_max", c.tangential_restitution_max)
        .f("spin_axis_share", c.spin_axis_share)
        .end()
}

fn ball<T: Real>(b: &CarryBall<T>) -> String {
    Init::new(single::<T>())
        .f("mass_kg", b.mass_kg)
        .f("radius_m", b.radius_m)
        .end()
}

fn delivery<T: Real>(d: &CarryDelivery<T>) -> String {
    Init::new(single::<T>())
        .f("club_speed_mps", d.club_speed_mps)
        .f("attack_angle_rad", d.attack_angle_rad)
        .f("club_path_rad", d.club_path_rad)
        .f("face_angle_rad", d.face_angle_rad)
        .f("dynamic_loft_rad", d.dynamic_loft_rad)
        .f("lie_rad", d.lie_rad)
        .a("club_spin_radps", &d.club_spin_radps)
        .f("impact_height_m", d.impact_height_m)
        .f("impact_toe_m", d.impact_toe_m)
        .end()
}

fn settings<T: Real>(s: &CarrySettings<T>) -> String {
    Init::new(single::<T>())
        .u("solver", s.solver)
        .u("integrator", s.integrator)
        .f("step_s", s.step_s)
        .f("rtol", s.rtol)
        .f("atol", s.atol)
        .f("initial_step_s", s.initial_step_s)
        .f("max_step_s", s.max_step_s)
        .end()
}

fn launch<T: Real>(l: &CarryLaunch<T>) -> String {
    Init::new(single::<T>())
        .f("ball_speed_mps", l.ball_speed_mps)
        .f("launch_angle_rad", l.launch_angle_rad)
        .f("launch_direction_rad", l.launch_direction_rad)
        .f("backspin_radps", l.backspin_radps)
        .f("sidespin_radps", l.sidespin_radps)
        .end()
}

fn scene<T: Real>(s: &CarryScene<T>) -> String {
    Init::new(single::<T>())
        .u("drag", s.drag)
        .u("lift", s.lift)
        .u("spin_decay", s.spin_decay)
        .u("aero", s.aero)
        .u("air", s.air)
        .f("air_density_kgm3", s.air_density_kgm3)
        .f("temperature_c", s.temperature_c)
        .f("relative_humidity", s.relative_humidity)
        .f("pressure_pa", s.pressure_pa)
        .f("altitude_m", s.altitude_m)
        .u("wind", s.wind)
        .a("wind_mps", &s.wind_mps)
        .f("wind_reference_height_m", s.wind_reference_height_m)
        .f("wind_exponent", s.wind_exponent)
        .f("landing_height_m", s.landing_height_m)
        .f("time_limit_s", s.time_limit_s)
        .f("gravity_mps2", s.gravity_mps2)
        .a("launch_position_m", &s.launch_position_m)
        .u("ground", s.ground)
        .f("stimp_m", s.stimp_m)
        .f("ground_restitution", s.ground_restitution)
        .f("ground_friction", s.ground_friction)
        .f("rolling_resistance", s.rolling_resistance)
        .f("crater_scale", s.crater_scale)
        .a("ground_normal", &s.ground_normal)
        .end()
}

fn impact_input<T: Real>(i: &CarryImpactInput<T>) -> String {
    Init::new(single::<T>())
        .s("club", club(&i.club))
        .s("ball", ball(&i.ball))
        .s("delivery", delivery(&i.delivery))
        .s("settings", settings(&i.settings))
        .end()
}

fn flight_input<T: Real>(i: &CarryFlightInput<T>) -> String {
    Init::new(single::<T>())
        .s("ball", ball(&i.ball))
        .s("launch", launch(&i.launch))
        .s("scene", scene(&i.scene))
        .s("settings", settings(&i.settings))
        .f("record_interval_s", i.record_interval_s)
        .end()
}

fn shot_input<T: Real>(i: &CarryShotInput<T>) -> String {
    Init::new(single::<T>())
        .s("club", club(&i.club))
        .s("ball", ball(&i.ball))
        .s("delivery", delivery(&i.delivery))
        .s("scene", scene(&i.scene))
        .s("settings", settings(&i.settings))
        .f("record_interval_s", i.record_interval_s)
        .end()
}

/// The C programs' line for one run: `KIND PREC NAME ok HEX…` or `KIND PREC NAME err CODE`.
fn line<T: Real>(kind: &str, name: &str, r: Result<Vec<T>, CarryError>) -> String {
    let prec = if single::<T>() { "f32" } else { "f64" };
    match r {
        Ok(v) => {
            let hex: Vec<String> = v
                .iter()
                .map(|&x| {
                    if single::<T>() {
                        format!("{:08x}", (to_f64(x) as f32).to_bits())
                    } else {
                        format!("{:016x}", to_f64(x).to_bits())
                    }
                })
                .collect();
            format!("{kind} {prec} {name} ok {}\n", hex.join(" "))
        }
        Err(e) => format!("{kind} {prec} {name} err {}\n", e as u32),
    }
}

/// The firmware cost shot (`firmware/src/shot.rs`): the golden driver with the seed's
/// rolling contact, 45 m/s square and centred, the default scene and settings.
fn cost_shot<T: Real>() -> CarryShotInput<T> {
    let mut spec = carry_core::ClubSpec::<T>::driver();
    spec.face_depth_radius_m = Some(lit(0.3));
    spec.loft_rad = deg(lit(10.5));
    let club = CarryClub::from_spec(&spec);
    CarryShotInput {
        club,
        delivery: CarryDelivery::square(&club),
        ..CarryShotInput::default()
    }
}

struct Tables {
    header: String,
    expected: String,
}

fn precision<T: Real>(
    t: &mut Tables,
    suffix: &str,
    run_impact: fn(&CarryImpactInput<T>) -> Result<CarryImpactResult<T>, CarryError>,
    run_flight: fn(&CarryFlightInput<T>) -> Result<CarryFlightResult<T>, CarryError>,
) {
    let s = suffix.to_uppercase();
    let mut names = Vec::new();
    let mut inits = Vec::new();
    for case in golden::impact_cases() {
        for (variant, solver, compliant, share) in golden::variants() {
            let input = golden::impact_input::<T>(&case.input, solver, compliant, share);
            let name = format!("{}/{variant}", case.name);
            let r = run_impact(&input).map(|o| golden::impact_outputs(&o).to_vec());
            t.expected.push_str(&line::<T>("impact", &name, r));
            names.push(format!("\"{name}\""));
            inits.push(impact_input(&input));
        }
    }
    let _ = writeln!(
        t.header,
        "#define CARRY_GOLDEN_IMPACT_N_{s} {}",
        inits.len()
    );
    let _ = writeln!(
        t.header,
        "static const char *const CARRY_GOLDEN_IMPACT_NAMES_{s}[] = {{\n  {}\n}};",
        names.join(",\n  ")
    );
    let _ = writeln!(
        t.header,
        "static const CarryImpactInput{s} CARRY_GOLDEN_IMPACT_{s}[] = {{\n  {}\n}};\n",
        inits.join(",\n  ")
    );
    names.clear();
    inits.clear();
    for case in golden::flight_cases() {
        let mut runs: Vec<(String, u32, carry_ffi::CarrySettings<T>)> = golden::settings::<T>()
            .into_iter()
            .map(|(n, st)| (n.to_owned(), CARRY_AERO_QUINTAVALLA, st))
            .collect();
        runs.push((
            "tour2023".into(),
            CARRY_AERO_TOUR2023,
            golden::c_settings(&Integrator::default()),
        ));
        for (run, aero, st) in runs {
            let input = golden::flight_input::<T>(&case.input, aero, st);
            let name = format!("{}/{run}", case.name);
            let r = run_flight(&input).map(|o| golden::flight_outputs(&o).to_vec());
            t.expected.push_str(&line::<T>("flight", &name, r));
            names.push(format!("\"{name}\""));
            inits.push(flight_input(&input));
        }
    }
    let _ = writeln!(
        t.header,
        "#define CARRY_GOLDEN_FLIGHT_N_{s} {}",
        inits.len()
    );
    let _ = writeln!(
        t.header,
        "static const char *const CARRY_GOLDEN_FLIGHT_NAMES_{s}[] = {{\n  {}\n}};",
        names.join(",\n  ")
    );
    let _ = writeln!(
        t.header,
        "static const CarryFlightInput{s} CARRY_GOLDEN_FLIGHT_{s}[] = {{\n  {}\n}};\n",
        inits.join(",\n  ")
    );
    let _ = writeln!(
        t.header,
        "static const CarryShotInput{s} CARRY_COST_SHOT_{s} = {};\n",
        shot_input(&cost_shot::<T>())
    );
}

fn impact32(i: &CarryImpactInputF32) -> Result<CarryImpactResultF32, CarryError> {
    carry_ffi::impact::run(i)
}
fn impact64(i: &CarryImpactInputF64) -> Result<CarryImpactResultF64, CarryError> {
    carry_ffi::impact::run(i)
}
fn flight32(i: &CarryFlightInputF32) -> Result<CarryFlightResultF32, CarryError> {
    carry_ffi::flight::run(i, None)
}
fn flight64(i: &CarryFlightInputF64) -> Result<CarryFlightResultF64, CarryError> {
    carry_ffi::flight::run(i, None)
}

fn main() {
    let out = std::path::PathBuf::from(std::env::args().nth(1).unwrap_or_else(|| ".".into()));
    let mut t = Tables {
        header: String::from(
            "/* @generated by `cargo run -p carry-ffi --example golden_c`: the golden cases of\n   tests/golden/{impact,flight}.json as C API inputs (exact hexadecimal floats). */\n#ifndef CARRY_GOLDEN_H\n#define CARRY_GOLDEN_H\n#include <math.h>\n#include \"carry.h\"\n\n",
        ),
        expected: String::new(),
    };
    precision::<f32>(&mut t, "f32", impact32, flight32);
    precision::<f64>(&mut t, "f64", impact64, flight64);
    // The f64 reference of the golden files, for the C test's accuracy check.
    let refs: Vec<String> = golden::flight_reference()
        .iter()
        .map(|(name, carry)| format!("  {{\"{name}\", {}}}", lit_c(*carry, false)))
        .collect();
    let _ = writeln!(
        t.header,
        "typedef struct {{ const char *name; double carry_m; }} CarryGoldenCarry;"
    );
    let _ = writeln!(t.header, "#define CARRY_GOLDEN_CARRY_N {}", refs.len());
    let _ = writeln!(
        t.header,
        "static const CarryGoldenCarry CARRY_GOLDEN_CARRY[] = {{\n{}\n}};\n#endif",
        refs.join(",\n")
    );
    std::fs::create_dir_all(&out).unwrap_or_else(|e| panic!("{}: {e}", out.display()));
    for (file, text) in [("carry_golden.h", &t.header), ("expected.txt", &t.expected)] {
        let path = out.join(file);
        std::fs::write(&path, text).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    }
}
