//! On-target golden tests (defmt-test), run on QEMU by `cargo test --release`.
//!
//! Every golden case of `tests/golden/` is solved on the target, in f32 and f64, with
//! every impact solver and three flight integrators, and compared
//!
//! * **bit for bit** with the host's result for the same case (computed by `build.rs` on
//!   the build machine from the same source): with nalgebra's `libm-force` and the `libm`
//!   crate, every transcendental function is the same Rust code on both sides, and
//!   `+ − × ÷ √` are correctly rounded IEEE operations on both (hardware VFP for f32 on the
//!   M4F, compiler-builtins' soft float for f64 and on the M0), so the results must be
//!   identical; and
//! * with the independent f64 reference, to the core's documented accuracy (a sanity
//!   check: bit-identity with the host already implies the host suite's checks).
#![no_std]
#![no_main]

use carry_firmware as _;

use carry_firmware::cases::{self, FLIGHT_NAMES, IMPACT_NAMES, SOLVERS, VARIANTS};
use carry_firmware::compare::{Precision, identical};
use carry_firmware::golden::{Expected, FLIGHT, GROUND, Host, IMPACT};
use carry_firmware::ground_cases::{GROUND_CASES, GROUND_NAMES};

fn impact_bit_identity<T: Precision>(
    host: impl Fn(&carry_firmware::golden::ImpactCase) -> &[Host<T::Bits, 23>; VARIANTS.len()],
) {
    let mut compared = 0u32;
    let mut differ = 0u32;
    for case in IMPACT {
        for (k, (sname, solver, compliant, share)) in VARIANTS.iter().enumerate() {
            let target = case.input.outputs_with::<T>(*solver, *compliant, *share);
            compared += 1;
            if !identical(case.name, sname, &IMPACT_NAMES, &target, &host(case)[k]) {
                differ += 1;
            }
        }
    }
    defmt::info!(
        "impact {=str}: {=u32} solves, {=u32} differ from the host",
        T::NAME,
        compared,
        differ
    );
    defmt::assert_eq!(differ, 0);
}

fn flight_bit_identity<T: Precision>(
    host: impl Fn(&carry_firmware::golden::FlightCase) -> &[Host<T::Bits, 13>; 3],
) {
    let mut compared = 0u32;
    let mut differ = 0u32;
    for case in FLIGHT {
        for (k, (iname, integrator)) in cases::integrators::<T>().iter().enumerate() {
            let target = case.input.outputs::<T>(integrator);
            compared += 1;
            if !identical(case.name, iname, &FLIGHT_NAMES, &target, &host(case)[k]) {
                differ += 1;
            }
        }
    }
    defmt::info!(
        "flight {=str}: {=u32} flights, {=u32} differ from the host",
        T::NAME,
        compared,
        differ
    );
    defmt::assert_eq!(differ, 0);
}

fn calibrated_bit_identity<T: Precision>(
    host: impl Fn(&carry_firmware::golden::FlightCase) -> &Host<T::Bits, 13>,
) {
    let mut differ = 0u32;
    for case in FLIGHT {
        let target = case.input.outputs_with::<T>(
            &carry_core::Integrator::default(),
            carry_core::aero::AeroModel::tour_2023(),
        );
        if !identical(case.name, "tour2023", &FLIGHT_NAMES, &target, host(case)) {
            differ += 1;
        }
    }
    defmt::info!(
        "flight {=str} tour2023: {=u32} flights, {=u32} differ from the host",
        T::NAME,
        FLIGHT.len() as u32,
        differ
    );
    defmt::assert_eq!(differ, 0);
}

/// Full shots with a ground (bounces, hops with the scene's aerodynamics, roll to rest or
/// the time cap), bit for bit against the host.
fn ground_bit_identity<T: Precision>(
    host: impl Fn(&carry_firmware::golden::GroundHost) -> &Host<T::Bits, 10>,
) {
    let mut differ = 0u32;
    for (case, h) in GROUND_CASES.iter().zip(GROUND) {
        defmt::assert_eq!(case.name, h.name);
        let target = case.outputs::<T>();
        if !identical(case.name, "default", &GROUND_NAMES, &target, host(h)) {
            differ += 1;
        }
    }
    defmt::info!(
        "ground {=str}: {=usize} shots, {=u32} differ from the host",
        T::NAME,
        GROUND_CASES.len(),
        differ
    );
    defmt::assert_eq!(differ, 0);
}

/// Relative difference of `a` from `b`, scaled by `scale`.
fn rel(a: f64, b: f64, scale: f64) -> f64 {
    let d = a - b;
    let d = if d < 0.0 { -d } else { d };
    d / if scale > 1e-12 { scale } else { 1e-12 }
}

fn norm(v: &[f64]) -> f64 {
    libm_sqrt(v.iter().map(|x| x * x).sum())
}

fn libm_sqrt(x: f64) -> f64 {
    use carry_core::real::to_f64;
    to_f64(nalgebra::ComplexField::sqrt(x))
}

/// Ball velocity and spin against the reference, relative to each vector's magnitude.
fn impact_reference<T: Precision>(tol: f64) {
    let mut worst = 0.0f64;
    for case in IMPACT {
        for (sname, solver) in SOLVERS {
            let target = case.input.outputs::<T>(solver);
            match (&case.expected, target) {
                (Expected::Values(e), Ok(t)) => {
                    let t: [f64; 6] = core::array::from_fn(|i| carry_core::real::to_f64(t[i]));
                    for (range, what) in [(0..3, "velocity"), (3..6, "spin")] {
                        let scale = norm(&e[range.clone()]);
                        for i in range {
                            let r = rel(t[i], e[i], scale);
                            worst = worst.max(r);
                            if r > tol {
                                defmt::error!(
                                    "{=str} {=str} {=str}: ball {=str}[{=usize}] {=f64} vs reference {=f64}",
                                    T::NAME,
                                    case.name,
                                    sname,
                                    what,
                                    i % 3,
                                    t[i],
                                    e[i]
                                );
                                defmt::panic!("impact off the reference");
                            }
                        }
                    }
                }
                (Expected::Error(name), Err(err)) => {
                    defmt::assert_eq!(
                        cases::error_name(cases::error_code(&err)),
                        *name,
                        "{=str}",
                        case.name
                    );
                }
                (_, t) => defmt::panic!(
                    "{=str} {=str}: unexpected outcome (ok = {})",
                    case.name,
                    sname,
                    t.is_ok()
                ),
            }
        }
    }
    defmt::info!(
        "impact {=str}: worst relative deviation from the reference {=f64}",
        T::NAME,
        worst
    );
}

/// Carry at the default fidelity against the reference.
fn flight_reference<T: Precision>(carry_tol_m: f64) {
    let mut worst = 0.0f64;
    for case in FLIGHT {
        let out = case.input.outputs::<T>(&carry_core::Integrator::default());
        let Ok(out) = out else {
            defmt::panic!("{=str}: flight failed", case.name)
        };
        let carry = carry_core::real::to_f64(out[0]);
        let d = carry - case.expected[0];
        let d = if d < 0.0 { -d } else { d };
        worst = worst.max(d);
        if d > carry_tol_m {
            defmt::panic!(
                "{=str} {=str}: carry {=f64} m vs reference {=f64} m",
                T::NAME,
                case.name,
                carry,
                case.expected[0]
            );
        }
    }
    defmt::info!(
        "flight {=str}: worst carry deviation from the reference {=f64} m",
        T::NAME,
        worst
    );
}

#[defmt_test::tests]
mod tests {
    use super::*;

    #[test]
    fn impact_f32_bit_identical_to_host() {
        impact_bit_identity::<f32>(|c| &c.host_f32);
    }

    #[test]
    fn impact_f64_bit_identical_to_host() {
        impact_bit_identity::<f64>(|c| &c.host_f64);
    }

    #[test]
    fn flight_f32_bit_identical_to_host() {
        flight_bit_identity::<f32>(|c| &c.host_f32);
    }

    #[test]
    fn flight_f64_bit_identical_to_host() {
        flight_bit_identity::<f64>(|c| &c.host_f64);
    }

    /// The calibrated default model (`tour2023`), every golden launch and scene.
    #[test]
    fn flight_calibrated_model_bit_identical_to_host() {
        calibrated_bit_identity::<f32>(|c| &c.tour2023_f32);
        calibrated_bit_identity::<f64>(|c| &c.tour2023_f64);
    }

    #[test]
    fn ground_f32_bit_identical_to_host() {
        ground_bit_identity::<f32>(|c| &c.host_f32);
    }

    #[test]
    fn ground_f64_bit_identical_to_host() {
        ground_bit_identity::<f64>(|c| &c.host_f64);
    }

    /// The core's square root (the FPU's `VSQRT.F32` on the M4F and M7, libm's software
    /// `sqrtf` on the M0) is libm's, bit for bit, on 65,536 values spread over both signs
    /// and every exponent, and on zeros, infinities and NaN.
    #[test]
    fn square_root_is_libms_bit_for_bit() {
        use carry_core::real::Root;
        let same = |x: f32| {
            let (a, b) = (x.root(), nalgebra::ComplexField::sqrt(x));
            a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan())
        };
        let mut differ = 0u32;
        let mut checked = 0u32;
        let mut bits = 0u32;
        loop {
            checked += 1;
            if !same(f32::from_bits(bits)) {
                differ += 1;
            }
            match bits.checked_add(65_537) {
                Some(next) => bits = next,
                None => break,
            }
        }
        for x in [
            0.0,
            -0.0,
            f32::INFINITY,
            f32::NEG_INFINITY,
            f32::NAN,
            f32::MIN_POSITIVE,
        ] {
            checked += 1;
            if !same(x) {
                differ += 1;
            }
        }
        defmt::info!(
            "sqrt f32: {=u32} values, {=u32} differ from libm",
            checked,
            differ
        );
        defmt::assert_eq!(differ, 0);
    }

    /// The host suite's tolerances: 1e-9 relative in f64, 4e-6 in f32.
    #[test]
    fn impact_matches_reference() {
        impact_reference::<f64>(1e-9);
        impact_reference::<f32>(4e-6);
    }

    /// The documented default fidelity: carry within 1 mm (f64) and 1 cm (f32).
    #[test]
    fn flight_matches_reference() {
        flight_reference::<f64>(1e-3);
        flight_reference::<f32>(1e-2);
    }
}
