//! The landing points as an SVG scatter with the 95 % ellipse (plotters).

use super::Dispersion;
use plotters::prelude::*;
use std::path::Path;

/// Most points drawn (a larger sample is thinned evenly; the statistics use every shot).
const MAX_POINTS: usize = 5000;

/// Writes the scatter of `d`'s landing points and its ellipse to `path`.
///
/// # Errors
/// Failing to draw or write the file.
pub fn draw(path: &Path, d: &Dispersion) -> Result<(), Box<dyn std::error::Error>> {
    let e = &d.ellipse_95;
    let (sin, cos) = e.angle_deg.to_radians().sin_cos();
    let outline: Vec<(f64, f64)> = (0..=120)
        .map(|k| {
            let t = f64::from(k) / 120.0 * std::f64::consts::TAU;
            let (a, b) = (e.semi_major_m * t.cos(), e.semi_minor_m * t.sin());
            // (X, Z) on the ground; drawn as side (Z) across, downrange (X) up.
            let x = e.centre_m[0] + a * cos - b * sin;
            let z = e.centre_m[1] + a * sin + b * cos;
            (z, x)
        })
        .collect();
    let stride = d.landings_m.len().div_ceil(MAX_POINTS).max(1);
    let points: Vec<(f64, f64)> = d
        .landings_m
        .iter()
        .step_by(stride)
        .map(|p| (p[1], p[0]))
        .collect();
    let (mut z0, mut z1, mut x0, mut x1) = (
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
    );
    for &(z, x) in points.iter().chain(&outline) {
        (z0, z1, x0, x1) = (z0.min(z), z1.max(z), x0.min(x), x1.max(x));
    }
    // Equal-ish scales: the side axis at least as wide as the downrange spread.
    let half = (0.5 * (z1 - z0)).max(0.5 * (x1 - x0)).max(0.5) * 1.1;
    let (zc, xc) = (0.5 * (z0 + z1), 0.5 * (x0 + x1));
    let root = SVGBackend::new(path, (700, 700)).into_drawing_area();
    root.fill(&WHITE)?;
    let mut chart = ChartBuilder::on(&root)
        .caption(
            format!(
                "Landing points ({} shots) and the 95 % ellipse",
                d.shots - d.failed_shots
            ),
            ("sans-serif", 18),
        )
        .margin(15)
        .x_label_area_size(45)
        .y_label_area_size(60)
        .build_cartesian_2d(zc - half..zc + half, xc - half..xc + half)?;
    chart
        .configure_mesh()
        .x_desc("side (m, + right)")
        .y_desc("downrange (m)")
        .label_style(("sans-serif", 13))
        .draw()?;
    chart.draw_series(
        points
            .iter()
            .map(|&p| Circle::new(p, 2, RGBColor(31, 119, 180).mix(0.4).filled())),
    )?;
    chart.draw_series(LineSeries::new(outline, RED.stroke_width(2)))?;
    root.present()?;
    Ok(())
}
