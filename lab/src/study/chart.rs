//! The study's SVG: worst carry error against cost (host time, force evaluations), log–log,
//! one marker per setting and the Pareto front of each precision (plotters, the style of
//! `carry plot`).

use super::measure::Method;
use plotters::prelude::*;
use std::path::Path;

/// One setting on the chart.
#[derive(Debug, Clone, Copy)]
pub struct Point {
    pub f32: bool,
    pub method: Method,
    pub full_solver: bool,
    pub is_default: bool,
    pub us: f64,
    pub evals: f64,
    pub error_m: f64,
    pub pareto_time: bool,
    pub pareto_evals: bool,
}

/// Errors below this are drawn at it (the f64 reference agrees to ~1e-10 m).
const FLOOR_M: f64 = 1e-9;

const F64_COLOUR: RGBColor = RGBColor(31, 119, 180);
const F32_COLOUR: RGBColor = RGBColor(255, 127, 14);

fn colour(f32: bool) -> RGBColor {
    if f32 { F32_COLOUR } else { F64_COLOUR }
}

fn span(values: impl Iterator<Item = f64>) -> (f64, f64) {
    let (lo, hi) = values
        .filter(|v| v.is_finite() && *v > 0.0)
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
            (a.min(v), b.max(v))
        });
    if lo.is_finite() {
        (lo / 1.6, hi * 1.6)
    } else {
        (0.1, 10.0)
    }
}

type Chart<'a, 'b> = ChartContext<'a, SVGBackend<'b>, Cartesian2d<LogCoord<f64>, LogCoord<f64>>>;

fn panel<'a, 'b: 'a>(
    chart: &mut Chart<'a, 'b>,
    points: &[Point],
    cost: fn(&Point) -> f64,
    front: fn(&Point) -> bool,
    x_desc: &str,
) -> Result<(), Box<dyn std::error::Error>> {
    chart
        .configure_mesh()
        .x_desc(x_desc)
        .y_desc("worst carry error over the set (m)")
        .y_label_formatter(&|v| format!("{v:.0e}"))
        .x_label_formatter(&|v| {
            if *v >= 1.0 {
                format!("{v:.0}")
            } else {
                format!("{v}")
            }
        })
        .label_style(("sans-serif", 14))
        .axis_desc_style(("sans-serif", 16))
        .draw()?;
    // The 1 cm default-fidelity target.
    let (x0, x1) = (chart.x_range().start, chart.x_range().end);
    chart
        .draw_series(LineSeries::new(
            [(x0, 0.01), (x1, 0.01)],
            RGBColor(150, 150, 150).stroke_width(1),
        ))?
        .label("1 cm target")
        .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], RGBColor(150, 150, 150)));
    for f32 in [false, true] {
        let colour = colour(f32);
        let mut pts: Vec<(f64, f64)> = points
            .iter()
            .filter(|p| p.f32 == f32 && front(p))
            .map(|p| (cost(p), p.error_m.max(FLOOR_M)))
            .collect();
        pts.sort_by(|a, b| a.0.total_cmp(&b.0));
        chart
            .draw_series(LineSeries::new(pts, colour.stroke_width(2)))?
            .label(if f32 {
                "f32 Pareto front"
            } else {
                "f64 Pareto front"
            })
            .legend(move |(x, y)| {
                PathElement::new(vec![(x, y), (x + 20, y)], colour.stroke_width(2))
            });
    }
    for method in [Method::Euler, Method::Rk4, Method::Dp45] {
        for f32 in [false, true] {
            for full in [false, true] {
                let colour = colour(f32);
                let style = if full {
                    colour.stroke_width(1)
                } else {
                    colour.filled()
                };
                let xy: Vec<(f64, f64)> = points
                    .iter()
                    .filter(|p| p.method == method && p.f32 == f32 && p.full_solver == full)
                    .map(|p| (cost(p), p.error_m.max(FLOOR_M)))
                    .collect();
                // Circle (Euler), triangle (RK4), square (DP45).
                let drawn = match method {
                    Method::Euler => {
                        chart.draw_series(xy.into_iter().map(|c| Circle::new(c, 4, style)))?
                    }
                    Method::Rk4 => chart
                        .draw_series(xy.into_iter().map(|c| TriangleMarker::new(c, 5, style)))?,
                    Method::Dp45 => chart.draw_series(xy.into_iter().map(|c| {
                        EmptyElement::at(c) + Rectangle::new([(-4, -4), (4, 4)], style)
                    }))?,
                };
                if !full {
                    let name = format!("{} {}", if f32 { "f32" } else { "f64" }, method.name());
                    let drawn = drawn.label(name);
                    match method {
                        Method::Euler => {
                            drawn.legend(move |(x, y)| Circle::new((x + 10, y), 4, style));
                        }
                        Method::Rk4 => {
                            drawn.legend(move |(x, y)| TriangleMarker::new((x + 10, y), 5, style));
                        }
                        Method::Dp45 => {
                            drawn.legend(move |(x, y)| {
                                EmptyElement::at((x + 10, y))
                                    + Rectangle::new([(-4, -4), (4, 4)], style)
                            });
                        }
                    }
                }
            }
        }
    }
    // Ring the defaults.
    chart.draw_series(
        points
            .iter()
            .filter(|p| p.is_default)
            .map(|p| Circle::new((cost(p), p.error_m.max(FLOOR_M)), 9, BLACK.stroke_width(1))),
    )?;
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::LowerRight)
        .label_font(("sans-serif", 13))
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .draw()?;
    Ok(())
}

/// One panel: drawing area, caption, x-axis description, cost, Pareto membership.
type Panel<'a, 'b> = (
    &'a DrawingArea<SVGBackend<'b>, plotters::coord::Shift>,
    &'static str,
    &'static str,
    fn(&Point) -> f64,
    fn(&Point) -> bool,
);

/// Draws the chart to `path`.
///
/// # Errors
/// Failing to write the file.
pub fn draw(path: &Path, points: &[Point]) -> Result<(), Box<dyn std::error::Error>> {
    let root = SVGBackend::new(path, (1400, 680)).into_drawing_area();
    root.fill(&WHITE)?;
    let root = root.titled(
        "carry: accuracy vs cost (filled: reduced impact solver, hollow: full; ringed: default)",
        ("sans-serif", 22),
    )?;
    let (left, right) = root.split_horizontally(700);
    let (y0, y1) = span(points.iter().map(|p| p.error_m.max(FLOOR_M)));
    let (y0, y1) = (y0.min(5e-3), y1.max(2e-2));
    let panels: [Panel<'_, '_>; 2] = [
        (
            &left,
            "Error vs host time per shot (noisy)",
            "host time per shot (µs, median, one core)",
            |p| p.us,
            |p| p.pareto_time,
        ),
        (
            &right,
            "Error vs force evaluations per shot (exact)",
            "force evaluations per shot (mean over the set)",
            |p| p.evals,
            |p| p.pareto_evals,
        ),
    ];
    for (area, caption, x_desc, cost, front) in panels {
        let (x0, x1) = span(points.iter().map(cost));
        let mut chart = ChartBuilder::on(area)
            .caption(caption, ("sans-serif", 18))
            .margin(15)
            .x_label_area_size(45)
            .y_label_area_size(70)
            .build_cartesian_2d((x0..x1).log_scale(), (y0..y1).log_scale())?;
        panel(&mut chart, points, cost, front, x_desc)?;
    }
    root.present()?;
    Ok(())
}
