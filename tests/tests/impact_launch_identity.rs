//! The launch identity (docs/impact.md §0.7). The contact impulse `P` acts on the ball at its
//! contact point, `R` from its centre against the face normal, so it gives the ball its
//! tangential velocity `P_t/m` and its spin `R·P_t/I` in a fixed ratio: `v_t = (I/(mR))·ω`.
//! A ball struck square (face angle and path 0, no toe offset, no club spin, lie 0) therefore
//! leaves at the face normal's elevation less `asin(I·ω/(m·R·V))`, whatever the contact law
//! (rolling or compliant, gripping or sliding), the club, its speed, attack angle and strike
//! height. In TrackMan's convention the normal's elevation at the contact point is the dynamic
//! loft given, so no contact law can move the launch away from what a row's own loft, spin
//! and ball speed imply. Property test over every preset and any contact law, f64 and f32.

use carry_core::impact::{self, Solver};
use carry_core::real::{Real, lit, to_f64};
use carry_core::units::deg;
use carry_core::{Ball, ClubSpec, ContactLaw, Delivery, DeliveryConvention, FaceLocation, PRESETS};
use carry_tests::scenario::compliant_law;
use nalgebra::Vector3;
use proptest::prelude::*;

/// `|launch − (loft − asin(Iω/(mRV)))|` (rad) of `preset` struck square with `contact`.
fn identity_gap<T: Real>(
    index: usize,
    contact: ContactLaw<f64>,
    speed_mps: f64,
    attack_deg: f64,
    loft_deg: f64,
    height_m: f64,
) -> f64 {
    let preset = &PRESETS[index % PRESETS.len()];
    let Ok(club) = ClubSpec::<T> {
        contact: contact.cast(),
        ..preset.spec::<T>()
    }
    .validate() else {
        panic!("{}", preset.name)
    };
    let ball = Ball::<T>::standard();
    let delivery = Delivery {
        club_speed_mps: lit::<T>(speed_mps),
        attack_angle_rad: deg(lit::<T>(attack_deg)),
        club_path_rad: T::zero(),
        face_angle_rad: T::zero(),
        dynamic_loft_rad: deg(lit::<T>(loft_deg)),
        lie_rad: T::zero(),
        club_spin_radps: Vector3::zeros(),
        location: FaceLocation {
            height_m: lit::<T>(height_m),
            toe_m: T::zero(),
        },
    };
    let out = delivery
        .strike_in(&club, DeliveryConvention::TrackMan)
        .and_then(|s| impact::solve(&club, &ball, &s, Solver::Reduced));
    let Ok(out) = out else {
        panic!("{}: {out:?}", preset.name)
    };
    let l = out.launch;
    let ratio = to_f64(ball.inertia_kgm2() * l.backspin_radps)
        / to_f64(ball.mass_kg() * ball.radius_m() * l.ball_speed_mps);
    (to_f64(l.launch_angle_rad) - (to_f64(deg(lit::<T>(loft_deg))) - ratio.asin())).abs()
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 1024, ..ProptestConfig::default() })]

    #[test]
    fn a_square_strike_leaves_at_the_normal_less_the_spins_share(
        index in 0_usize..64,
        contact in prop_oneof![
            Just(ContactLaw::Rolling),
            Just(carry_core::presets::FITTED_CONTACT),
            compliant_law().prop_map(ContactLaw::Compliant),
        ],
        speed in 5.0_f64..60.0,
        attack in -8.0_f64..8.0,
        loft in 2.0_f64..55.0,
        height in -0.010_f64..0.010,
    ) {
        let f64_gap = identity_gap::<f64>(index, contact, speed, attack, loft, height);
        prop_assert!(f64_gap < 1e-9, "f64: {f64_gap}");
        let f32_gap = identity_gap::<f32>(index, contact, speed, attack, loft, height);
        prop_assert!(f32_gap < 2e-5, "f32: {f32_gap}");
    }
}
