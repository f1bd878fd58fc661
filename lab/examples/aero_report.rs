//! Produces the figures of docs/aero.md: the families compared on TrackMan's 2023 tour
//! averages (fit and leave-one-out errors per club) and the SVG of C_D(S), C_L(S).
//!
//! ```sh
//! cargo run --release -p carry-lab --example aero_report -- docs/aero-coefficients.svg
//! ```

#[path = "../tests/common/mod.rs"]
mod common;

use carry_core::aero::AeroModel;
use carry_lab::fit::flight::{AeroFamily, AeroProblem};
use carry_lab::fit::{self, Fit, FitOptions};
use plotters::prelude::*;

fn errors(f: &Fit, row: usize, loo: bool) -> [f64; 3] {
    let r = &f.rows[row];
    let p = if loo {
        r.loo_predicted.as_ref().unwrap_or(&r.predicted)
    } else {
        &r.predicted
    };
    let o = |i: usize| r.observed[i].unwrap_or(f64::NAN);
    [
        100.0 * (p[0] - o(0)) / o(0),
        (p[1] - o(1)) / common::YD,
        p[2] - o(2),
    ]
}

fn main() {
    let svg = std::env::args()
        .nth(1)
        .unwrap_or_else(|| "aero-coefficients.svg".into());
    let rows = common::tour_2023().expect("../shared/data/trackman_tour_2023.csv");
    let seed = fit::evaluate(
        &AeroProblem::new(AeroFamily::Quintavalla),
        &rows,
        &AeroFamily::Quintavalla
            .parameters(&AeroModel::quintavalla())
            .expect("linear"),
    )
    .expect("seed");
    let t = std::time::Instant::now();
    let refit = fit::fit(
        &AeroProblem::new(AeroFamily::Quintavalla),
        &rows,
        FitOptions::default(),
        &|| {},
    )
    .expect("refit");
    let t_refit = t.elapsed();
    let t = std::time::Instant::now();
    let modern = fit::fit(
        &AeroProblem::new(AeroFamily::Modern),
        &rows,
        FitOptions::default(),
        &|| {},
    )
    .expect("modern");
    let t_modern = t.elapsed();
    println!("fit + leave-one-out wall time: refit {t_refit:.2?}, modern {t_modern:.2?}\n");
    println!(
        "| club | seed carry % | refit carry % (LOO) | tour2023 carry % (LOO) | seed / refit / tour2023 apex yd | seed / refit / tour2023 land ° |"
    );
    println!("|---|---:|---:|---:|---:|---:|");
    for (i, r) in rows.iter().enumerate() {
        let (s, q, ql, m, ml) = (
            errors(&seed, i, false),
            errors(&refit, i, false),
            errors(&refit, i, true),
            errors(&modern, i, false),
            errors(&modern, i, true),
        );
        println!(
            "| {} | {:+.1} | {:+.1} ({:+.1}) | {:+.1} ({:+.1}) | {:+.1} / {:+.1} / {:+.1} | {:+.1} / {:+.1} / {:+.1} |",
            r.label, s[0], q[0], ql[0], m[0], ml[0], s[1], q[1], m[1], s[2], q[2], m[2]
        );
    }
    println!(
        "\n| model | carry mean % | carry max % | LOO carry mean % | LOO carry max % | apex mean yd | LOO apex yd | land mean ° | LOO land ° |"
    );
    println!("|---|---:|---:|---:|---:|---:|---:|---:|---:|");
    for (name, f) in [
        ("seed (quintavalla)", &seed),
        ("quintavalla family refitted", &refit),
        ("tour2023 (modern family)", &modern),
    ] {
        let s = |q: &str| *f.summary_of(q).expect("q");
        let l = |q: &str| f.loo_summary_of(q).copied();
        let lc = l("carry");
        println!(
            "| {name} | {:.2} | {:.2} | {} | {} | {:.2} | {} | {:.2} | {} |",
            s("carry").mean_abs_pct,
            s("carry").max_abs_pct,
            lc.map_or("—".into(), |x| format!("{:.2}", x.mean_abs_pct)),
            lc.map_or("—".into(), |x| format!("{:.2}", x.max_abs_pct)),
            s("apex").mean_abs / common::YD,
            l("apex").map_or("—".into(), |x| format!("{:.2}", x.mean_abs / common::YD)),
            s("land_angle").mean_abs,
            l("land_angle").map_or("—".into(), |x| format!("{:.2}", x.mean_abs)),
        );
    }
    println!("\nrefitted quintavalla family: {:?}", refit.values());
    println!("modern family: {:?}", modern.values());
    draw(&svg, &AeroFamily::Quintavalla.model(&refit.values())).expect("svg");
    println!("\nwrote {svg}");
}

/// C_D(S) and C_L(S) of each model at Re = 1.5·10⁵ (a mid-flight iron) and, for the modern
/// model, at 7·10⁴ (a wedge near its apex), with Nathan's published fits.
fn draw(path: &str, refit: &AeroModel<f64>) -> Result<(), Box<dyn std::error::Error>> {
    let root = SVGBackend::new(path, (1000, 420)).into_drawing_area();
    root.fill(&WHITE)?;
    let (left, right) = root.split_horizontally(500);
    let s_grid: Vec<f64> = (0..=60).map(|i| f64::from(i) * 0.01).collect();
    let models: [(&str, AeroModel<f64>, f64, RGBColor); 4] = [
        (
            "seed (Quintavalla), Re 1.5e5",
            AeroModel::quintavalla(),
            1.5e5,
            RGBColor(200, 60, 40),
        ),
        (
            "Quintavalla family refitted",
            *refit,
            1.5e5,
            RGBColor(230, 150, 30),
        ),
        (
            "tour2023, Re 1.5e5",
            AeroModel::tour_2023(),
            1.5e5,
            RGBColor(30, 90, 200),
        ),
        (
            "tour2023, Re 7e4",
            AeroModel::tour_2023(),
            7.0e4,
            RGBColor(120, 170, 240),
        ),
    ];
    for (area, title, pick, top) in [
        (&left, "drag coefficient C_D(S)", 0usize, 0.7),
        (&right, "lift coefficient C_L(S)", 1usize, 0.7),
    ] {
        let mut chart = ChartBuilder::on(area)
            .caption(title, ("sans-serif", 18))
            .margin(10)
            .x_label_area_size(35)
            .y_label_area_size(45)
            .build_cartesian_2d(0.0..0.6, 0.0..top)?;
        chart
            .configure_mesh()
            .x_desc("spin parameter S = Rω/V")
            .draw()?;
        for (name, m, re, color) in &models {
            chart
                .draw_series(LineSeries::new(
                    s_grid.iter().map(|&s| {
                        let (cd, cl, _) = m.coefficients(s, *re);
                        (s, if pick == 0 { cd } else { cl })
                    }),
                    color.stroke_width(2),
                ))?
                .label(*name)
                .legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 18, y)], color.stroke_width(2))
                });
        }
        // Nathan's calculator (REFERENCES.md): C_L = 0.2294·S^0.4, C_D = C_D0 + 0.2087·S
        // above the drag crisis (C_D0 ≈ 0.18 assumed for the curve).
        let black = RGBColor(40, 40, 40);
        chart
            .draw_series(DashedLineSeries::new(
                s_grid.iter().map(|&s| {
                    (
                        s,
                        if pick == 0 {
                            0.18 + 0.2087 * s
                        } else {
                            0.2294 * s.powf(0.4)
                        },
                    )
                }),
                6,
                4,
                black.stroke_width(1),
            ))?
            .label("Nathan's published fit")
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 18, y)], black));
        chart
            .configure_series_labels()
            .border_style(BLACK)
            .background_style(WHITE.mix(0.8))
            .position(SeriesLabelPosition::UpperLeft)
            .label_font(("sans-serif", 11))
            .draw()?;
    }
    root.present()?;
    Ok(())
}
