//! The optimizer chart as an SVG heat map: club speed (rows) × attack angle (columns),
//! coloured by carry, each cell labelled with its best dynamic loft and carry.

use super::Chart;
use plotters::prelude::*;
use std::path::Path;

/// Carry → colour: light yellow (short) to dark blue (long).
fn colour(t: f64) -> RGBColor {
    let t = t.clamp(0.0, 1.0);
    let lerp = |a: f64, b: f64| (a + (b - a) * t).round().clamp(0.0, 255.0) as u8;
    RGBColor(lerp(255.0, 8.0), lerp(247.0, 48.0), lerp(188.0, 107.0))
}

/// Writes the heat map of `chart` to `path`.
///
/// # Errors
/// Failing to draw or write the file.
pub fn draw(path: &Path, chart: &Chart) -> Result<(), Box<dyn std::error::Error>> {
    let (rows, cols) = (chart.club_speeds_mps.len(), chart.attack_angles_deg.len());
    let width = 140 + 110 * u32::try_from(cols.max(1))?;
    let height = 120 + 60 * u32::try_from(rows.max(1))?;
    let root = SVGBackend::new(path, (width, height)).into_drawing_area();
    root.fill(&WHITE)?;
    let (lo, hi) = chart
        .cells
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), c| {
            (a.min(c.shot.carry_m), b.max(c.shot.carry_m))
        });
    let span = if hi > lo { hi - lo } else { 1.0 };
    #[allow(clippy::cast_precision_loss)]
    let (nx, ny) = (cols as f64, rows as f64);
    let mut plot = ChartBuilder::on(&root)
        .caption(
            "Optimizer chart: best dynamic loft (deg) and carry (m)",
            ("sans-serif", 18),
        )
        .margin(15)
        .x_label_area_size(45)
        .y_label_area_size(70)
        .build_cartesian_2d(0.0..nx, 0.0..ny)?;
    let attacks = chart.attack_angles_deg.clone();
    let speeds = chart.club_speeds_mps.clone();
    plot.configure_mesh()
        .disable_mesh()
        .x_labels(cols)
        .y_labels(rows)
        .x_label_formatter(&|x| {
            let i = x.floor() as usize;
            attacks.get(i).map_or(String::new(), |a| format!("{a:+.1}"))
        })
        .y_label_formatter(&|y| {
            let i = y.floor() as usize;
            speeds.get(i).map_or(String::new(), |v| format!("{v:.1}"))
        })
        .x_desc("attack angle (deg)")
        .y_desc("club speed (m/s)")
        .label_style(("sans-serif", 13))
        .draw()?;
    for (k, c) in chart.cells.iter().enumerate() {
        #[allow(clippy::cast_precision_loss)]
        let (x, y) = ((k % cols.max(1)) as f64, (k / cols.max(1)) as f64);
        let fill = colour((c.shot.carry_m - lo) / span);
        plot.draw_series(std::iter::once(Rectangle::new(
            [(x, y), (x + 1.0, y + 1.0)],
            fill.filled(),
        )))?;
        let ink = if (c.shot.carry_m - lo) / span > 0.55 {
            WHITE
        } else {
            BLACK
        };
        let style = ("sans-serif", 13).into_font().color(&ink);
        plot.draw_series(std::iter::once(Text::new(
            format!("{:.1}°", c.dynamic_loft_deg),
            (x + 0.3, y + 0.75),
            style.clone(),
        )))?;
        plot.draw_series(std::iter::once(Text::new(
            format!("{:.0} m", c.shot.carry_m),
            (x + 0.3, y + 0.4),
            style,
        )))?;
    }
    root.present()?;
    Ok(())
}
