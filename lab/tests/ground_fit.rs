//! The firm fairway's rolling resistance against TrackMan's 2010 driver chart
//! (`carry_lab::ground_fit`): the preset is what the calibration fits, so a change to the
//! aerodynamics or the ground that moves the fit fails here until the preset is re-run
//! (`cargo run --release -p carry-lab --example ground_calibration`).

use carry_core::ground::Surface;
use carry_core::ground::surface::FAIRWAY_ROLLING_RESISTANCE;
use carry_lab::ground_fit::{
    RollRow, calibrate_fairway, chart_scene, crater_scan, mean_abs, parse_chart, roll_rows,
};

const CHART: &str = include_str!("../../tests/data/trackman_driver_optimizer_2010.csv");

#[test]
fn the_fairway_preset_is_the_charts_calibration() {
    let rows = parse_chart(CHART).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(rows.len(), 30);
    let fit = calibrate_fairway(&rows, &chart_scene(Surface::FairwayFirm))
        .unwrap_or_else(|e| panic!("{e}"));
    let rho = fit.rolling_resistance;
    assert!(
        (rho / FAIRWAY_ROLLING_RESISTANCE - 1.0).abs() < 0.03,
        "fitted rho0 {rho:.4} against the preset's {FAIRWAY_ROLLING_RESISTANCE}: re-run the calibration"
    );
    let fitted = mean_abs(fit.rows.iter().map(RollRow::roll_error_yd));
    let loo = mean_abs(fit.leave_one_out_yd.iter().copied());
    assert!(
        fitted < 4.0 && loo < 4.0,
        "roll mean |err| {fitted:.2} yd, leave-one-out {loo:.2} yd"
    );
    // The preset itself: every chart roll within the chart's own scatter (its rolls run
    // 16–40 yd at 35–45° landings), and the mean as fitted.
    let preset =
        roll_rows(&rows, &chart_scene(Surface::FairwayFirm)).unwrap_or_else(|e| panic!("{e}"));
    let mean = mean_abs(preset.iter().map(RollRow::roll_error_yd));
    assert!(mean < 4.0, "{mean}");
    for r in &preset {
        assert!(
            (15.0..35.0).contains(&r.roll_yd.1),
            "{}: {:.1} yd",
            r.label,
            r.roll_yd.1
        );
    }
}

#[test]
fn the_crater_scan_refits_rho_at_each_scale() {
    let rows = parse_chart(CHART).unwrap_or_else(|e| panic!("{e}"));
    let scene = chart_scene(Surface::FairwayFirm);
    let scan = crater_scan(&rows, &scene, &[0.8, 1.0]).unwrap_or_else(|e| panic!("{e}"));
    let (shallow, penner) = (scan[0], scan[1]);
    // At the preset's crater the scan is the calibration's fit.
    assert!(
        (penner.rolling_resistance / FAIRWAY_ROLLING_RESISTANCE - 1.0).abs() < 0.03,
        "{penner:?}"
    );
    // A shallower crater stops the ball less at the bounce: the grass must stop it more.
    assert!(
        shallow.rolling_resistance > 1.2 * penner.rolling_resistance,
        "{shallow:?} {penner:?}"
    );
    for r in &scan {
        assert!(
            r.roll_yd.is_finite() && r.roll_yd < 6.0 && r.total_yd < 8.0,
            "{r:?}"
        );
    }
}

/// The joint fairway (`fairway-joint`, issue 35) on the chart alone, flight `drives2026`
/// (the default): its total within the 5 yd, better than the two fairways it was
/// fitted between (`fairway`, whose ρ₀ is fitted to the chart's rolls, 5.20 yd;
/// `fairway-trackman`, the drives' turf, 6.90 yd), and every row's roll within the chart's
/// own scatter.
#[test]
fn the_joint_fairway_meets_the_charts_total() {
    let rows = parse_chart(CHART).unwrap_or_else(|e| panic!("{e}"));
    let total = |s: Surface<f64>| {
        let r = roll_rows(&rows, &chart_scene(s)).unwrap_or_else(|e| panic!("{e}"));
        (mean_abs(r.iter().map(RollRow::total_error_yd)), r)
    };
    let (joint, r) = total(Surface::FairwayJoint);
    let (firm, _) = total(Surface::FairwayFirm);
    let (trackman, _) = total(Surface::FairwayTrackman);
    assert!(
        joint <= 5.0 && joint < firm && joint < trackman,
        "chart total: joint {joint:.2} yd, fairway {firm:.2}, fairway-trackman {trackman:.2}"
    );
    for r in &r {
        assert!(
            (15.0..35.0).contains(&r.roll_yd.1),
            "{}: {:.1} yd",
            r.label,
            r.roll_yd.1
        );
    }
}
