//! The C API from Rust: results equal the core's bit for bit (golden cases, every solver
//! and integrator, f32 and f64; random deliveries), trajectories equal the core
//! recorder's, every error code has a message, bad input gives the right code.
#![allow(unsafe_code, clippy::undocumented_unsafe_blocks)]

#[path = "../../firmware/src/cases.rs"]
mod cases;
#[path = "support/golden.rs"]
mod golden;
#[path = "../../firmware/src/golden_input.rs"]
mod golden_input;

use carry_core::aero::AeroModel;
use carry_core::flight::{Recorder, Sample};
use carry_core::presets::PRESETS;
use carry_core::real::Real;
use carry_core::shot::{self, Fidelity};
use carry_core::{Ball, Integrator};
use carry_ffi::error::{ALL, CarryError, CarryError::*};
use carry_ffi::scene::{CARRY_AERO_DRIVES2026, CARRY_AERO_QUINTAVALLA, CARRY_AERO_TOUR2023};
use carry_ffi::*;
use core::ptr::{null, null_mut};
use std::ffi::CStr;

/// The C API's precision-specific entry points, for generic tests.
trait Api: Real {
    fn bits(self) -> u64;
    fn impact(i: &CarryImpactInput<Self>, o: &mut CarryImpactResult<Self>) -> CarryError;
    fn flight(
        i: &CarryFlightInput<Self>,
        s: &mut [CarrySample<Self>],
        n: &mut usize,
        o: &mut CarryFlightResult<Self>,
    ) -> CarryError;
    fn shot(
        i: &CarryShotInput<Self>,
        s: &mut [CarrySample<Self>],
        n: &mut usize,
        o: &mut CarryShotResult<Self>,
    ) -> CarryError;
    fn shot_default(i: &mut CarryShotInput<Self>) -> CarryError;
}

macro_rules! api {
    ($t:ty, $bits:expr, $impact:ident, $flight:ident, $shot:ident, $default:ident) => {
        impl Api for $t {
            fn bits(self) -> u64 {
                $bits(self)
            }
            fn impact(i: &CarryImpactInput<Self>, o: &mut CarryImpactResult<Self>) -> CarryError {
                // SAFETY: valid references.
                unsafe { $impact(i, o) }
            }
            fn flight(
                i: &CarryFlightInput<Self>,
                s: &mut [CarrySample<Self>],
                n: &mut usize,
                o: &mut CarryFlightResult<Self>,
            ) -> CarryError {
                let p = if s.is_empty() {
                    null_mut()
                } else {
                    s.as_mut_ptr()
                };
                // SAFETY: valid references; `p` holds `s.len()` samples.
                unsafe { $flight(i, p, s.len(), n, o) }
            }
            fn shot(
                i: &CarryShotInput<Self>,
                s: &mut [CarrySample<Self>],
                n: &mut usize,
                o: &mut CarryShotResult<Self>,
            ) -> CarryError {
                let p = if s.is_empty() {
                    null_mut()
                } else {
                    s.as_mut_ptr()
                };
                // SAFETY: valid references; `p` holds `s.len()` samples.
                unsafe { $shot(i, p, s.len(), n, o) }
            }
            fn shot_default(i: &mut CarryShotInput<Self>) -> CarryError {
                // SAFETY: a valid reference.
                unsafe { $default(i) }
            }
        }
    };
}
api!(
    f32,
    |x: f32| u64::from(x.to_bits()),
    carry_impact_f32,
    carry_flight_f32,
    carry_shot_f32,
    carry_shot_input_default_f32
);
api!(
    f64,
    f64::to_bits,
    carry_impact_f64,
    carry_flight_f64,
    carry_shot_f64,
    carry_shot_input_default_f64
);

/// An all-zero struct (every field of the C API's structs is a float or an integer).
fn zeroed<S>() -> S {
    // SAFETY: all-zero bits are a valid value of every C API struct.
    unsafe { core::mem::zeroed() }
}

fn same_bits<T: Api>(what: &str, a: &[T], b: &[T]) {
    let a: Vec<u64> = a.iter().map(|x| x.bits()).collect();
    let b: Vec<u64> = b.iter().map(|x| x.bits()).collect();
    assert_eq!(a, b, "{what}: C API differs from the core");
}

fn impact_golden<T: Api>() {
    let mut n = 0;
    for case in golden::impact_cases() {
        for (variant, solver, compliant, share) in golden::variants() {
            let core_solver = cases::VARIANTS.iter().find(|v| v.0 == variant).map(|v| v.1);
            let core =
                case.input
                    .outputs_with::<T>(core_solver.unwrap_or_default(), compliant, share);
            let input = golden::impact_input::<T>(&case.input, solver, compliant, share);
            let mut out = zeroed::<CarryImpactResult<T>>();
            let code = T::impact(&input, &mut out);
            let what = format!("{} {variant}", case.name);
            match core {
                Ok(v) => {
                    assert_eq!(code, CARRY_OK, "{what}");
                    same_bits(&what, &golden::impact_outputs(&out), &v);
                }
                Err(e) => assert_eq!(code, CarryError::from(e), "{what}"),
            }
            n += 1;
        }
    }
    assert!(n >= 60, "{n} impact cases");
}

fn flight_golden<T: Api>() {
    let mut n = 0;
    for case in golden::flight_cases() {
        let mut runs: Vec<(String, Integrator<T>, u32, AeroModel<T>)> = cases::integrators::<T>()
            .iter()
            .map(|(name, i)| {
                (
                    (*name).to_owned(),
                    *i,
                    CARRY_AERO_QUINTAVALLA,
                    AeroModel::quintavalla(),
                )
            })
            .collect();
        runs.push((
            "tour2023".into(),
            Integrator::default(),
            CARRY_AERO_TOUR2023,
            AeroModel::tour_2023(),
        ));
        runs.push((
            "drives2026".into(),
            Integrator::default(),
            CARRY_AERO_DRIVES2026,
            AeroModel::drives_2026(),
        ));
        for (name, integrator, aero, model) in runs {
            let core = case.input.outputs_with::<T>(&integrator, model);
            let input =
                golden::flight_input::<T>(&case.input, aero, golden::c_settings(&integrator));
            let mut out = zeroed::<CarryFlightResult<T>>();
            let mut count = 0;
            let code = T::flight(&input, &mut [], &mut count, &mut out);
            let what = format!("{} {name}", case.name);
            match core {
                Ok(v) => {
                    assert_eq!(code, CARRY_OK, "{what}");
                    same_bits(&what, &golden::flight_outputs(&out), &v);
                }
                Err(e) => assert_eq!(code, CarryError::from(e), "{what}"),
            }
            n += 1;
        }
    }
    assert!(n >= 80, "{n} flight runs");
}

#[test]
fn impact_golden_cases_bit_identical_to_core() {
    impact_golden::<f32>();
    impact_golden::<f64>();
}

#[test]
fn flight_golden_cases_bit_identical_to_core() {
    flight_golden::<f32>();
    flight_golden::<f64>();
}

/// The default shot with a ground and a trajectory: result and samples equal the core's.
fn shot_with_trajectory<T: Api>() {
    let mut input = zeroed::<CarryShotInput<T>>();
    assert_eq!(T::shot_default(&mut input), CARRY_OK);
    input.scene.ground = carry_ffi::scene::CARRY_GROUND_GREEN;
    let club = input.club.spec().and_then(|s| Ok(s.validate()?));
    let ball = Ball::<T>::standard();
    let scene = input.scene.scene().and_then(|s| Ok(s.prepare(&ball)?));
    let (Ok(club), Ok(scene)) = (club, scene) else {
        panic!("default inputs")
    };
    let mut buf: heapless::Vec<Sample<T>, 256> = heapless::Vec::new();
    let Ok(mut rec) = Recorder::new(input.record_interval_s, &mut buf) else {
        panic!()
    };
    let core = shot::play(
        &club,
        &ball,
        &input.delivery.delivery(),
        &scene,
        &Fidelity::default(),
        Some(&mut rec),
    );
    let Ok(core) = core else { panic!("core shot") };
    let mut samples = vec![zeroed::<CarrySample<T>>(); 256];
    let mut count = 0;
    let mut out = zeroed::<CarryShotResult<T>>();
    assert_eq!(
        T::shot(&input, &mut samples, &mut count, &mut out),
        CARRY_OK
    );
    assert_eq!(out.impact, CarryImpactResult::from_outcome(&core.impact));
    assert_eq!(out.flight, CarryFlightResult::from_outcome(&core.flight));
    assert_eq!(out.flight.has_ground, 1);
    assert_eq!(count, buf.len());
    for (c, s) in samples.iter().zip(&buf) {
        let flat = |x: &CarrySample<T>| {
            let mut v = vec![x.time_s];
            v.extend(
                x.position_m
                    .iter()
                    .chain(&x.velocity_mps)
                    .chain(&x.spin_radps),
            );
            v
        };
        let core_sample = CarrySample {
            time_s: s.time_s,
            position_m: s.position_m.into(),
            velocity_mps: s.velocity_mps.into(),
            spin_radps: s.spin_radps.into(),
        };
        same_bits("sample", &flat(c), &flat(&core_sample));
    }
    // A buffer of 3: the same result, 3 samples, and the code says the buffer was small.
    let mut small = vec![zeroed::<CarrySample<T>>(); 3];
    let mut out_small = zeroed::<CarryShotResult<T>>();
    assert_eq!(
        T::shot(&input, &mut small, &mut count, &mut out_small),
        CARRY_ERR_BUFFER_TOO_SMALL
    );
    assert_eq!(count, 3);
    assert_eq!(out_small.flight.recording_full, 1);
    assert_eq!(out_small.flight.carry_m, out.flight.carry_m);
    assert_eq!(&small[..], &samples[..3]);
}

/// Every named turf of `CarryScene::ground` is the core's surface of that name, and the
/// default shot run out on it through the C API is the core's, bit for bit (the joint
/// fairway of issue 35 included); an unknown code is refused.
fn named_turfs<T: Api>() {
    use carry_core::ground::{Ground, Surface};
    use carry_ffi::scene::{
        CARRY_GROUND_FAIRWAY, CARRY_GROUND_FAIRWAY_JOINT, CARRY_GROUND_FAIRWAY_SOFT,
        CARRY_GROUND_FAIRWAY_TRACKMAN, CARRY_GROUND_ROUGH,
    };
    let mut totals = Vec::new();
    for (code, surface) in [
        (CARRY_GROUND_FAIRWAY, Surface::<T>::FairwayFirm),
        (CARRY_GROUND_FAIRWAY_SOFT, Surface::FairwaySoft),
        (CARRY_GROUND_ROUGH, Surface::Rough),
        (CARRY_GROUND_FAIRWAY_TRACKMAN, Surface::FairwayTrackman),
        (CARRY_GROUND_FAIRWAY_JOINT, Surface::FairwayJoint),
    ] {
        let mut input = zeroed::<CarryShotInput<T>>();
        assert_eq!(T::shot_default(&mut input), CARRY_OK);
        input.scene.ground = code;
        let Ok(scene) = input.scene.scene() else {
            panic!("scene {code}")
        };
        assert_eq!(scene.ground, Some(Ground::level(surface)), "code {code}");
        let ball = Ball::<T>::standard();
        let (Ok(club), Ok(prepared)) = (
            input.club.spec().and_then(|s| Ok(s.validate()?)),
            scene.prepare(&ball),
        ) else {
            panic!("default inputs")
        };
        let delivery = input.delivery.delivery();
        let Ok(core) = shot::play(
            &club,
            &ball,
            &delivery,
            &prepared,
            &Fidelity::default(),
            None,
        ) else {
            panic!("core shot {code}")
        };
        let mut out = zeroed::<CarryShotResult<T>>();
        let mut count = 0;
        assert_eq!(T::shot(&input, &mut [], &mut count, &mut out), CARRY_OK);
        assert_eq!(
            out.flight,
            CarryFlightResult::from_outcome(&core.flight),
            "code {code}"
        );
        assert_eq!(out.flight.has_ground, 1);
        totals.push(out.flight.total_m);
    }
    // The joint fairway is a turf of its own: its total is neither fairway's.
    assert!(
        totals[4] != totals[0] && totals[4] != totals[3],
        "{totals:?}"
    );
    let mut input = zeroed::<CarryShotInput<T>>();
    assert_eq!(T::shot_default(&mut input), CARRY_OK);
    input.scene.ground = CARRY_GROUND_FAIRWAY_JOINT + 1;
    let mut out = zeroed::<CarryShotResult<T>>();
    let mut count = 0;
    assert_eq!(
        T::shot(&input, &mut [], &mut count, &mut out),
        CARRY_ERR_UNKNOWN_OPTION
    );
}

#[test]
fn named_turfs_equal_the_core() {
    named_turfs::<f32>();
    named_turfs::<f64>();
}

#[test]
fn shot_and_trajectory_equal_the_core() {
    shot_with_trajectory::<f32>();
    shot_with_trajectory::<f64>();
}

/// A flight that fails after recording samples (it never comes down to a 1 km landing
/// height) reports no samples: they are not results.
#[test]
fn failed_flight_reports_no_samples() {
    let mut i = CarryFlightInputF64::default();
    i.scene.landing_height_m = 1000.0;
    let mut samples = vec![zeroed::<CarrySampleF64>(); 64];
    let mut count = usize::MAX;
    let mut out = zeroed::<CarryFlightResultF64>();
    assert_eq!(
        f64::flight(&i, &mut samples, &mut count, &mut out),
        CARRY_ERR_NO_LANDING
    );
    assert_eq!(count, 0);
    assert!(
        samples[0].time_s == 0.0 && samples[1].time_s > 0.0,
        "it did record"
    );
}

#[test]
fn every_error_code_has_a_distinct_message() {
    let mut seen = std::collections::HashSet::new();
    for (k, code) in ALL.iter().enumerate() {
        assert_eq!(*code as u32, k as u32, "codes are dense from CARRY_OK = 0");
        let p = carry_error_message(*code as u32);
        assert!(!p.is_null());
        // SAFETY: a static NUL-terminated string.
        let m = unsafe { CStr::from_ptr(p) }.to_str().unwrap_or("");
        assert!(!m.is_empty() && seen.insert(m.to_owned()), "{code:?}: {m}");
    }
    // SAFETY: as above.
    let unknown = unsafe { CStr::from_ptr(carry_error_message(9999)) };
    assert_eq!(unknown.to_str().ok(), Some("unknown error code"));
}

#[test]
fn null_pointers_are_reported() {
    let mut r = zeroed::<CarryImpactResultF32>();
    let mut i = zeroed::<CarryImpactInputF32>();
    // SAFETY: NULL or valid pointers only.
    unsafe {
        assert_eq!(carry_impact_f32(null(), &mut r), CARRY_ERR_NULL_POINTER);
        assert_eq!(carry_impact_f32(&i, null_mut()), CARRY_ERR_NULL_POINTER);
        assert_eq!(
            carry_impact_input_default_f32(null_mut()),
            CARRY_ERR_NULL_POINTER
        );
        assert_eq!(carry_impact_input_default_f32(&mut i), CARRY_OK);
        assert_eq!(carry_impact_f32(&i, &mut r), CARRY_OK);
        let f = CarryFlightInputF64::default();
        let mut fr = zeroed::<CarryFlightResultF64>();
        let mut s = [zeroed::<CarrySampleF64>(); 4];
        assert_eq!(
            carry_flight_f64(null(), null_mut(), 0, null_mut(), &mut fr),
            CARRY_ERR_NULL_POINTER
        );
        assert_eq!(
            carry_flight_f64(&f, null_mut(), 0, null_mut(), null_mut()),
            CARRY_ERR_NULL_POINTER
        );
        // A buffer needs a count.
        assert_eq!(
            carry_flight_f64(&f, s.as_mut_ptr(), 4, null_mut(), &mut fr),
            CARRY_ERR_NULL_POINTER
        );
        assert_eq!(
            carry_flight_f64(&f, null_mut(), 0, null_mut(), &mut fr),
            CARRY_OK
        );
        let mut c = zeroed::<CarryClubF32>();
        assert_eq!(
            carry_club_preset_f32(null(), &mut c),
            CARRY_ERR_NULL_POINTER
        );
        assert_eq!(
            carry_club_preset_f32(c"driver".as_ptr(), null_mut()),
            CARRY_ERR_NULL_POINTER
        );
        assert_eq!(
            carry_shot_f32(null(), null_mut(), 0, null_mut(), null_mut()),
            CARRY_ERR_NULL_POINTER
        );
    }
}

#[test]
fn bad_input_gives_the_right_code() {
    let mut i = CarryShotInputF32::default();
    let mut r = zeroed::<CarryShotResultF32>();
    let mut n = 0;
    let mut run = |i: &CarryShotInputF32| f32::shot(i, &mut [], &mut n, &mut r);
    assert_eq!(run(&i), CARRY_OK);
    i.delivery.club_speed_mps = f32::NAN;
    assert_eq!(run(&i), CARRY_ERR_INVALID_INPUT);
    i = CarryShotInputF32::default();
    i.delivery.club_speed_mps = 0.0;
    assert_eq!(run(&i), CARRY_ERR_NO_APPROACH);
    i = CarryShotInputF32::default();
    i.delivery.impact_toe_m = 0.5;
    assert_eq!(run(&i), CARRY_ERR_OFF_FACE);
    for bad in [
        |i: &mut CarryShotInputF32| i.club.contact = 7,
        |i: &mut CarryShotInputF32| i.scene.aero = 3,
        |i: &mut CarryShotInputF32| i.scene.air = 3,
        |i: &mut CarryShotInputF32| i.scene.wind = 3,
        |i: &mut CarryShotInputF32| i.scene.ground = 8,
        |i: &mut CarryShotInputF32| i.settings.solver = 2,
        |i: &mut CarryShotInputF32| i.settings.integrator = u32::MAX,
    ] {
        let mut i = CarryShotInputF32::default();
        bad(&mut i);
        assert_eq!(run(&i), CARRY_ERR_UNKNOWN_OPTION);
    }
    i = CarryShotInputF32::default();
    i.scene.landing_height_m = 1000.0;
    assert_eq!(run(&i), CARRY_ERR_NO_LANDING);
    i = CarryShotInputF32::default();
    i.scene.time_limit_s = 0.5;
    assert_eq!(run(&i), CARRY_ERR_TIME_LIMIT);
    i = CarryShotInputF32::default();
    i.settings.solver = carry_ffi::settings::CARRY_SOLVER_FULL; // compliant contact
    assert_eq!(run(&i), CARRY_ERR_INVALID_INPUT);
    let mut c = zeroed::<CarryClubF64>();
    // SAFETY: valid pointers.
    unsafe {
        assert_eq!(
            carry_club_preset_f64(c"putter".as_ptr(), &mut c),
            CARRY_ERR_UNKNOWN_NAME
        );
        assert_eq!(
            carry_club_preset_index_f64(carry_club_preset_count(), &mut c),
            CARRY_ERR_UNKNOWN_NAME
        );
        assert!(carry_club_preset_name(carry_club_preset_count()).is_null());
    }
}

#[test]
fn presets_by_name_and_index_are_the_cores() {
    assert_eq!(carry_club_preset_count() as usize, PRESETS.len());
    for (k, p) in PRESETS.iter().enumerate() {
        let name = carry_club_preset_name(k as u32);
        // SAFETY: a static NUL-terminated string.
        assert_eq!(unsafe { CStr::from_ptr(name) }.to_str().ok(), Some(p.name));
        let (mut a, mut b) = (zeroed::<CarryClubF64>(), zeroed::<CarryClubF64>());
        // SAFETY: valid pointers.
        unsafe {
            assert_eq!(carry_club_preset_f64(name, &mut a), CARRY_OK);
            assert_eq!(carry_club_preset_index_f64(k as u32, &mut b), CARRY_OK);
        }
        assert_eq!(a, b);
        assert_eq!(a.spec().ok(), Some(p.spec::<f64>()));
    }
}

/// The named-club rule's strike height: the core's `Preset::completed` for every preset, both
/// precisions; typed errors for a bad name, loft, radius or pointer.
#[test]
fn strike_height_is_the_named_club_rule() {
    use carry_core::presets::GivenDelivery;
    for (k, p) in PRESETS.iter().enumerate() {
        let name = carry_club_preset_name(k as u32);
        for loft in [0.0_f64, 0.25, 0.35, 0.8, 1.4] {
            let (mut h64, mut h32) = (f64::NAN, f32::NAN);
            // SAFETY: a static NUL-terminated name and writable floats.
            unsafe {
                assert_eq!(
                    carry_strike_height_f64(name, loft, 0.021_336, &mut h64),
                    CARRY_OK
                );
                assert_eq!(
                    carry_strike_height_f32(name, loft as f32, 0.021_336, &mut h32),
                    CARRY_OK
                );
            }
            let given = GivenDelivery {
                dynamic_loft_rad: Some(loft),
                ..GivenDelivery::default()
            };
            assert_eq!(
                h64,
                p.completed(&given, 0.021_336).location.height_m,
                "{}",
                p.name
            );
            let given32 = GivenDelivery {
                dynamic_loft_rad: Some(loft as f32),
                ..GivenDelivery::default()
            };
            assert_eq!(h32, p.completed(&given32, 0.021_336_f32).location.height_m);
        }
    }
    let mut h = 0.0_f64;
    // SAFETY: NUL-terminated names; the NULL cases are the point.
    unsafe {
        assert_eq!(
            carry_strike_height_f64(c"putter".as_ptr(), 0.3, 0.021, &mut h),
            CARRY_ERR_UNKNOWN_NAME
        );
        assert_eq!(
            carry_strike_height_f64(null(), 0.3, 0.021, &mut h),
            CARRY_ERR_NULL_POINTER
        );
        assert_eq!(
            carry_strike_height_f64(c"7iron".as_ptr(), 0.3, 0.021, null_mut()),
            CARRY_ERR_NULL_POINTER
        );
        for (loft, radius) in [
            (f64::NAN, 0.021),
            (f64::INFINITY, 0.021),
            (0.3, 0.0),
            (0.3, f64::NAN),
            (0.3, -1.0),
            (-1.5, f64::MAX),
        ] {
            assert_eq!(
                carry_strike_height_f64(c"7iron".as_ptr(), loft, radius, &mut h),
                CARRY_ERR_INVALID_INPUT,
                "{loft} {radius}"
            );
        }
    }
}

proptest::proptest! {
    /// Any finite loft and positive radius: a finite strike height, the core's; anything
    /// else a typed error, never a NaN written.
    #[test]
    fn strike_height_is_finite_or_an_error(
        k in 0_u32..13, loft in proptest::num::f64::ANY, radius in proptest::num::f64::ANY,
    ) {
        let mut h = 0.5_f64;
        // SAFETY: a static NUL-terminated name and a writable float.
        let code = unsafe { carry_strike_height_f64(carry_club_preset_name(k), loft, radius, &mut h) };
        if code == CARRY_OK {
            proptest::prop_assert!(h.is_finite());
        } else {
            proptest::prop_assert_eq!(code, CARRY_ERR_INVALID_INPUT);
            proptest::prop_assert_eq!(h, 0.5);
        }
    }

    /// Any delivery: the C API's impact is the core's, bit for bit (or the same error).
    #[test]
    fn random_deliveries_bit_identical(
        speed in 0.0f64..80.0, attack in -0.2f64..0.2, path in -0.2f64..0.2,
        face in -0.2f64..0.2, loft in 0.0f64..1.0, toe in -0.04f64..0.04,
        height in -0.03f64..0.03, compliant in proptest::bool::ANY,
    ) {
        let mut i = CarryImpactInputF64::default();
        if !compliant {
            i.club.contact = carry_ffi::club::CARRY_CONTACT_ROLLING;
        }
        i.delivery = CarryDeliveryF64 {
            club_speed_mps: speed, attack_angle_rad: attack, club_path_rad: path,
            face_angle_rad: face, dynamic_loft_rad: loft, impact_toe_m: toe,
            impact_height_m: height, ..i.delivery
        };
        let core = i.club.spec().and_then(|s| Ok(s.validate()?)).and_then(|club| {
            let strike = i.delivery.delivery().strike_in(&club, carry_core::DeliveryConvention::TrackMan)?;
            Ok(carry_core::impact::solve(&club, &Ball::standard(), &strike, carry_core::Solver::Reduced)?)
        });
        let mut out = zeroed::<CarryImpactResultF64>();
        let code = f64::impact(&i, &mut out);
        match core {
            Ok(o) => {
                proptest::prop_assert_eq!(code, CARRY_OK);
                same_bits("impact", &golden::impact_outputs(&out), &golden::impact_outputs(&CarryImpactResult::from_outcome(&o)));
            }
            Err(e) => proptest::prop_assert_eq!(code, e),
        }
    }
}

/// `CarryDelivery::convention`: the defaults read TrackMan's angles at the contact point, the
/// seed's reading is the core's `Delivery::strike`, and an unknown value is a typed error.
#[test]
fn delivery_convention_is_selectable() {
    let mut i = CarryImpactInputF64::default();
    assert_eq!(
        i.delivery.convention,
        carry_ffi::impact::CARRY_CONVENTION_TRACKMAN
    );
    i.delivery.impact_toe_m = 0.02;
    i.delivery.impact_height_m = 0.01;
    let mut tm = zeroed::<CarryImpactResultF64>();
    assert_eq!(f64::impact(&i, &mut tm), CARRY_OK);
    i.delivery.convention = carry_ffi::impact::CARRY_CONVENTION_SEED_CENTRE;
    let mut seed = zeroed::<CarryImpactResultF64>();
    assert_eq!(f64::impact(&i, &mut seed), CARRY_OK);
    let Ok(club) = i.club.spec().and_then(|s| Ok(s.validate()?)) else {
        panic!("club")
    };
    let Ok(core) = i.delivery.delivery().strike(&club).and_then(|s| {
        carry_core::impact::solve(&club, &Ball::standard(), &s, carry_core::Solver::Reduced)
    }) else {
        panic!("core")
    };
    same_bits(
        "seed",
        &golden::impact_outputs(&seed),
        &golden::impact_outputs(&CarryImpactResult::from_outcome(&core)),
    );
    // the toe's bulge no longer starts the ball right when the face is square there
    assert!(tm.launch_direction_rad.abs() < seed.launch_direction_rad.abs());
    i.delivery.convention = 7;
    assert_eq!(
        f64::impact(&i, &mut seed),
        carry_ffi::error::CarryError::CARRY_ERR_UNKNOWN_OPTION
    );
}

/// Issue 34: the club's empirical spin-axis share crosses the C API (`CarryClub::
/// spin_axis_share`): the defaults and presets hold 1; 0.5 gives the core's impact with the
/// same share (bit for bit) and halves the axis tangent; 0 or NaN is an invalid input.
#[test]
fn spin_axis_share_crosses_the_c_api() {
    fn check<T: Api>() {
        let mut input = zeroed::<CarryShotInput<T>>();
        assert_eq!(T::shot_default(&mut input), CARRY_OK);
        assert_eq!(input.club.spin_axis_share, T::one());
        input.delivery.face_angle_rad = carry_core::real::lit(0.05);
        let mut physics = zeroed::<CarryShotResult<T>>();
        let mut n = 0;
        assert_eq!(T::shot(&input, &mut [], &mut n, &mut physics), CARRY_OK);
        input.club.spin_axis_share = carry_core::real::lit(0.5);
        let mut shared = zeroed::<CarryShotResult<T>>();
        assert_eq!(T::shot(&input, &mut [], &mut n, &mut shared), CARRY_OK);
        let Ok(club) = input.club.spec().and_then(|s| Ok(s.validate()?)) else {
            panic!("club")
        };
        let Ok(strike) = input.delivery.delivery().strike(&club) else {
            panic!("strike")
        };
        let Ok(core) = carry_core::impact::solve(
            &club,
            &Ball::standard(),
            &strike,
            carry_core::impact::Solver::Reduced,
        ) else {
            panic!("impact")
        };
        assert_eq!(shared.impact, CarryImpactResult::from_outcome(&core));
        let tan = |r: &CarryShotResult<T>| carry_core::real::to_f64(r.impact.spin_axis_rad).tan();
        assert!(tan(&physics).abs() > 0.05);
        assert!((tan(&shared) - 0.5 * tan(&physics)).abs() < 1e-5);
        assert_eq!(shared.impact.ball_speed_mps, physics.impact.ball_speed_mps);
        for bad in [0.0, f64::NAN, 1.5] {
            input.club.spin_axis_share = carry_core::real::lit(bad);
            assert_eq!(
                T::shot(&input, &mut [], &mut n, &mut shared),
                CARRY_ERR_INVALID_INPUT,
                "{bad}"
            );
        }
    }
    check::<f32>();
    check::<f64>();
    let mut c = zeroed::<CarryClubF64>();
    for k in 0..carry_club_preset_count() {
        // SAFETY: valid pointers.
        assert_eq!(unsafe { carry_club_preset_index_f64(k, &mut c) }, CARRY_OK);
        assert_eq!(c.spin_axis_share, 1.0);
    }
}
