//! The firm fairway's rolling resistance calibrated to TrackMan's 2010 driver chart, and
//! the chart's rows at the preset (docs/ground.md):
//! `cargo run --release -p carry-lab --example ground_calibration [--no-fit | --crater-scan]`.
use carry_core::ground::Surface;
use carry_lab::ground_fit::{
    RollRow, calibrate_fairway, chart_scene, crater_scan, mean_abs, parse_chart, roll_rows,
};

fn print(rows: &[RollRow]) {
    println!(
        "{:16} {:>7} {:>7} {:>6} {:>6} {:>7} {:>7} {:>7} {:>7} {:>6}",
        "row", "carry", "model", "land°", "m/s", "roll", "model", "total", "model", "err"
    );
    for r in rows {
        println!(
            "{:16} {:7.1} {:7.1} {:6.1} {:6.1} {:7.1} {:7.1} {:7.1} {:7.1} {:+6.1}",
            r.label,
            r.carry_yd.0,
            r.carry_yd.1,
            r.landing.0,
            r.landing.1,
            r.roll_yd.0,
            r.roll_yd.1,
            r.total_yd.0,
            r.total_yd.1,
            r.total_error_yd()
        );
    }
    println!(
        "mean |err|: roll {:.2} yd, total {:.2} yd, carry {:.2} yd",
        mean_abs(rows.iter().map(RollRow::roll_error_yd)),
        mean_abs(rows.iter().map(RollRow::total_error_yd)),
        mean_abs(rows.iter().map(|r| r.carry_yd.1 - r.carry_yd.0))
    );
}

fn main() -> Result<(), String> {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../tests/data/trackman_driver_optimizer_2010.csv"
    );
    let text = std::fs::read_to_string(path).map_err(|e| e.to_string())?;
    let rows = parse_chart(&text)?;
    println!("preset fairway:");
    print(&roll_rows(&rows, &chart_scene(Surface::FairwayFirm))?);
    if std::env::args().any(|a| a == "--no-fit") {
        return Ok(());
    }
    if std::env::args().any(|a| a == "--crater-scan") {
        println!("\ncrater scale held, rho0 fitted: roll and total mean |err| (yd)");
        let kappas = [0.0, 0.2, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0, 1.2];
        for r in crater_scan(&rows, &chart_scene(Surface::FairwayFirm), &kappas)? {
            println!(
                "kappa {:.2}  rho0 {:.4}  roll {:.2}  total {:.2}",
                r.crater_scale, r.rolling_resistance, r.roll_yd, r.total_yd
            );
        }
        return Ok(());
    }
    let fit = calibrate_fairway(&rows, &chart_scene(Surface::FairwayFirm))?;
    println!("\nfitted rho0 = {:.4}", fit.rolling_resistance);
    print(&fit.rows);
    println!(
        "leave-one-out roll mean |err| {:.2} yd, worst {:.2} yd",
        mean_abs(fit.leave_one_out_yd.iter().copied()),
        fit.leave_one_out_yd
            .iter()
            .fold(0.0_f64, |m, e| m.max(e.abs()))
    );
    Ok(())
}
