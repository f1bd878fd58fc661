//! The sweep as an SVG: carry and side against ball position (plotters).

use super::Sweep;
use plotters::prelude::*;
use std::path::Path;

/// (ball position, carry, side).
type Point = (f64, f64, f64);
/// A panel: its axis label, the value it draws, its colour.
type Panel = (&'static str, fn(&Point) -> f64, RGBColor);

/// Writes carry (top) and side (bottom) against ball position to `path`.
///
/// # Errors
/// Failing to draw or write the file.
pub fn draw(path: &Path, sweep: &Sweep) -> Result<(), Box<dyn std::error::Error>> {
    let points: Vec<Point> = sweep
        .rows
        .iter()
        .filter_map(|r| r.shot.map(|s| (r.ball_position_m, s.carry_m, s.side_m)))
        .collect();
    let span = |f: fn(&Point) -> f64| {
        let (lo, hi) = points
            .iter()
            .map(f)
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
                (a.min(v), b.max(v))
            });
        if lo.is_finite() {
            let pad = ((hi - lo) * 0.08).max(0.1);
            (lo - pad, hi + pad)
        } else {
            (0.0, 1.0)
        }
    };
    let (x0, x1) = span(|p| p.0);
    let root = SVGBackend::new(path, (800, 700)).into_drawing_area();
    root.fill(&WHITE)?;
    let panels = root.split_evenly((2, 1));
    let series: [Panel; 2] = [
        ("carry (m)", |p| p.1, RGBColor(31, 119, 180)),
        ("side (m, + right)", |p| p.2, RGBColor(214, 39, 40)),
    ];
    for (area, (label, f, colour)) in panels.iter().zip(series) {
        let (y0, y1) = span(f);
        let mut chart = ChartBuilder::on(area)
            .margin(15)
            .x_label_area_size(40)
            .y_label_area_size(60)
            .build_cartesian_2d(x0..x1, y0..y1)?;
        chart
            .configure_mesh()
            .x_desc("ball position along the target line (m, + towards the target)")
            .y_desc(label)
            .label_style(("sans-serif", 13))
            .draw()?;
        chart.draw_series(LineSeries::new(
            points.iter().map(|p| (p.0, f(p))),
            colour.stroke_width(2),
        ))?;
        if let Some(best) = sweep.best_row()
            && let Some(s) = best.shot
        {
            let y = f(&(best.ball_position_m, s.carry_m, s.side_m));
            chart.draw_series(std::iter::once(Circle::new(
                (best.ball_position_m, y),
                5,
                BLACK.filled(),
            )))?;
        }
    }
    root.present()?;
    Ok(())
}
