//! The named-club rule (`Preset::completed`, docs/impact.md §0.6) on any preset and any
//! given loft, in both precisions: a flat face given a dynamic loft (and no strike height)
//! strikes where a ball on firm turf meets it at that loft; a curved face keeps its typical
//! strike; a height given is the height struck; what is not given is the typical delivery's;
//! every value finite.
use carry_core::presets::{GivenDelivery, PRESETS, turf_impact_height_m};
use carry_core::real::{Real, lit};
use proptest::prelude::*;

fn check<T: Real + core::fmt::Debug>(index: usize, loft: f64, height: Option<f64>) {
    let preset = &PRESETS[index % PRESETS.len()];
    let radius = lit::<T>(0.021_336);
    let given = GivenDelivery {
        club_speed_mps: None,
        attack_angle_rad: None,
        dynamic_loft_rad: Some(lit::<T>(loft)),
        impact_height_m: height.map(lit::<T>),
    };
    let d = preset.completed(&given, radius);
    let typical = preset.typical.delivery::<T>();
    assert_eq!(d.dynamic_loft_rad, lit::<T>(loft));
    assert_eq!(d.club_speed_mps, typical.club_speed_mps);
    assert_eq!(d.attack_angle_rad, typical.attack_angle_rad);
    assert_eq!(d.location.toe_m, typical.location.toe_m);
    let expected = match height {
        Some(h) => lit::<T>(h),
        None if preset.roll_radius_m.is_finite() => typical.location.height_m,
        None => turf_impact_height_m(lit::<T>(loft), radius),
    };
    assert_eq!(d.location.height_m, expected, "{}", preset.name);
    assert!(d.location.height_m.is_finite());
    // on the turf the strike is below the face centre and above the ball's lowest point
    if height.is_none() && !preset.roll_radius_m.is_finite() {
        let h = d.location.height_m;
        assert!(
            h <= lit::<T>(0.0016) && h >= lit::<T>(-0.0201),
            "{}: {h:?}",
            preset.name
        );
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 512, ..ProptestConfig::default() })]

    #[test]
    fn a_given_loft_places_the_strike(
        index in 0_usize..64,
        loft in 0.0_f64..1.5,
        height in prop_oneof![Just(None), (-0.03_f64..0.03).prop_map(Some)],
    ) {
        check::<f64>(index, loft, height);
        check::<f32>(index, loft, height);
    }
}
