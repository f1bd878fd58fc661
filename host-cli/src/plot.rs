//! `carry plot`: side and top views of one or more trajectories, drawn with plotters
//! (SVG backend). Each trajectory is the base options plus one `--vary` value or one row
//! of `--input`.

use crate::cli::PlotArgs;
use carry_io::batch::{applies, reader};
use carry_io::compute::{self, Mode, Numerics};
use carry_io::error::{Failure, InputError};
use carry_io::params::{Key, Kind, Params};
use carry_io::units::{Quantity, Units};
use csv::ByteRecord;
use plotters::prelude::*;
use std::fmt::Write as _;
use std::io::Write as _;

/// One trajectory to draw.
struct Curve {
    label: String,
    /// (downrange, height, side) in display units.
    points: Vec<(f64, f64, f64)>,
}

/// The trajectories `plot` asks for: (label, parameters).
fn variants(
    mode: Mode,
    base: &Params,
    units: Units,
    plot: &PlotArgs,
) -> Result<Vec<(String, Params)>, InputError> {
    if let Some(spec) = &plot.vary {
        let (name, values) = spec
            .split_once('=')
            .ok_or_else(|| InputError::new("vary", format!("'{spec}' must be NAME=V1,V2,…")))?;
        let key = Key::find(name)
            .filter(|k| applies(mode, *k))
            .ok_or_else(|| {
                InputError::new(
                    "vary",
                    format!("'{}' is not an option of this plot", name.trim()),
                )
            })?;
        // Vector values are separated by ';' (their components by ',').
        let sep = if matches!(key.kind(), Kind::Vector | Kind::Tensor) {
            ';'
        } else {
            ','
        };
        let mut out = Vec::new();
        for text in values.split(sep).map(str::trim).filter(|t| !t.is_empty()) {
            let value = key
                .parse(text)
                .map_err(|e| InputError::new("vary", format!("{}: {}", e.key, e.reason)))?;
            let mut p = *base;
            key.set(&mut p, units, value);
            let unit = units.input_symbol(key.quantity());
            let label = if unit.is_empty() {
                format!("{} = {text}", key.name())
            } else {
                format!("{} = {text} {unit}", key.name())
            };
            out.push((label, p));
        }
        if out.is_empty() {
            return Err(InputError::new("vary", "no values given"));
        }
        return Ok(out);
    }
    if let Some(path) = &plot.input {
        let (mut rdr, cols, _) = reader(path, mode)?;
        let mut rec = ByteRecord::new();
        let mut out = Vec::new();
        loop {
            match rdr.read_byte_record(&mut rec) {
                Ok(true) => {}
                Ok(false) => break,
                Err(e) => return Err(InputError::new("input", e.to_string())),
            }
            let line = rec.position().map_or(0, csv::Position::line);
            let p = cols
                .apply(&rec, base, units)
                .map_err(|e| InputError::new("input", format!("line {line}: {}", e.as_column())))?;
            let label = cols.label.and_then(|i| rec.get(i)).map_or_else(
                || format!("line {line}"),
                |l| String::from_utf8_lossy(l).into_owned(),
            );
            out.push((label, p));
        }
        if out.is_empty() {
            return Err(InputError::new("input", "no rows"));
        }
        return Ok(out);
    }
    Ok(vec![(
        if mode == Mode::Shot { "shot" } else { "flight" }.to_owned(),
        *base,
    )])
}

/// Computes and draws the trajectories.
///
/// # Errors
/// Invalid input (naming the option and the curve) or failing to write the file.
pub fn run(
    mode: Mode,
    base: &Params,
    n: &Numerics,
    units: Units,
    plot: &PlotArgs,
) -> Result<(), Failure> {
    let mut curves = Vec::new();
    let mut trace = Vec::new();
    let mut summary = String::new();
    for (label, p) in variants(mode, base, units, plot)? {
        let report = compute::run_traced(mode, &p, n, &mut trace).map_err(|e| InputError {
            key: e.key,
            reason: format!("{} (curve '{label}')", e.reason),
        })?;
        if let Some(f) = &report.flight {
            let (carry, long) = units.display(Quantity::Long, f.carry_m);
            let (side, _) = units.display(Quantity::Long, f.side_m);
            let side = if side.abs() < 0.05 { 0.0 } else { side };
            let (apex, high) = units.display(Quantity::Height, f.apex_m);
            let _ = write!(
                summary,
                "{label:<28} carry {carry:>6.1} {long}  side {side:>+6.1} {long}  apex {apex:>5.1} {high}"
            );
            if let Some(g) = &f.ground {
                let (total, _) = units.display(Quantity::Long, g.total_m);
                let (roll, _) = units.display(Quantity::Long, g.roll_m);
                let _ = write!(
                    summary,
                    "  total {total:>6.1} {long}  roll {roll:>+5.1} {long}"
                );
            }
            summary.push('\n');
        }
        let points = trace
            .iter()
            .map(|[x, y, z]| {
                (
                    units.to_display(Quantity::Long, *x),
                    units.to_display(Quantity::Height, *y),
                    units.to_display(Quantity::Long, *z),
                )
            })
            .collect();
        curves.push(Curve { label, points });
    }
    draw(&curves, units, plot)
        .map_err(|e| Failure::Other(format!("cannot write {}: {e}", plot.output.display())))?;
    let _ = writeln!(summary, "wrote {}", plot.output.display());
    let mut out = std::io::stdout().lock();
    out.write_all(summary.as_bytes())?;
    out.flush()?;
    Ok(())
}

/// Distinct, readable line colours (the "tab10" palette).
const COLOURS: [(u8, u8, u8); 10] = [
    (31, 119, 180),
    (255, 127, 14),
    (44, 160, 44),
    (214, 39, 40),
    (148, 103, 189),
    (140, 86, 75),
    (227, 119, 194),
    (127, 127, 127),
    (188, 189, 34),
    (23, 190, 207),
];

fn colour(i: usize) -> RGBColor {
    let (r, g, b) = COLOURS[i % COLOURS.len()];
    RGBColor(r, g, b)
}

fn range(values: impl Iterator<Item = f64>, floor_zero: bool) -> (f64, f64) {
    let (mut lo, mut hi) = values.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
        (a.min(v), b.max(v))
    });
    if !lo.is_finite() || !hi.is_finite() {
        return (0.0, 1.0);
    }
    if floor_zero {
        lo = lo.min(0.0);
    }
    let pad = ((hi - lo) * 0.05).max(1.0);
    hi += pad;
    if !floor_zero || lo < 0.0 {
        lo -= pad;
    }
    (lo, hi)
}

fn draw(curves: &[Curve], units: Units, plot: &PlotArgs) -> Result<(), Box<dyn std::error::Error>> {
    let long = units.input_symbol(Quantity::Long);
    let height = units.input_symbol(Quantity::Height);
    let all = || curves.iter().flat_map(|c| c.points.iter());
    let (x0, x1) = range(all().map(|p| p.0), true);
    let (y0, y1) = range(all().map(|p| p.1), true);
    let (z0, z1) = range(all().map(|p| p.2).chain([0.0]), false);
    // A symmetric side axis, so the target line is in the middle.
    let zmax = z0.abs().max(z1.abs());

    let root = SVGBackend::new(&plot.output, (1000, 900)).into_drawing_area();
    root.fill(&WHITE)?;
    let title = plot
        .title
        .clone()
        .unwrap_or_else(|| "carry: trajectories".to_owned());
    let root = root.titled(&title, ("sans-serif", 26))?;
    let (upper, lower) = root.split_vertically(430);

    let mut side = ChartBuilder::on(&upper)
        .caption("Side view", ("sans-serif", 20))
        .margin(15)
        .x_label_area_size(45)
        .y_label_area_size(65)
        .build_cartesian_2d(x0..x1, y0..y1)?;
    side.configure_mesh()
        .x_desc(format!("downrange ({long})"))
        .y_desc(format!("height ({height})"))
        .label_style(("sans-serif", 15))
        .axis_desc_style(("sans-serif", 17))
        .draw()?;
    for (i, c) in curves.iter().enumerate() {
        let color = colour(i);
        side.draw_series(LineSeries::new(
            c.points.iter().map(|p| (p.0, p.1)),
            color.stroke_width(2),
        ))?
        .label(c.label.as_str())
        .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(2)));
    }
    side.configure_series_labels()
        .position(SeriesLabelPosition::UpperLeft)
        .label_font(("sans-serif", 15))
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .draw()?;

    let mut top = ChartBuilder::on(&lower)
        .caption("Top view (+ right of the target line)", ("sans-serif", 20))
        .margin(15)
        .x_label_area_size(45)
        .y_label_area_size(65)
        .build_cartesian_2d(x0..x1, -zmax..zmax)?;
    top.configure_mesh()
        .x_desc(format!("downrange ({long})"))
        .y_desc(format!("side ({long})"))
        .label_style(("sans-serif", 15))
        .axis_desc_style(("sans-serif", 17))
        .draw()?;
    for (i, c) in curves.iter().enumerate() {
        let color = colour(i);
        top.draw_series(LineSeries::new(
            c.points.iter().map(|p| (p.0, p.2)),
            color.stroke_width(2),
        ))?;
    }
    root.present()?;
    Ok(())
}
