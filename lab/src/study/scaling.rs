//! Cost against flight time (per integrator, with log–log slopes) and against batch size.

use super::measure::{self, Budget};
use super::report::{BatchRow, FlightTimeRow, Scaling, Slope};
use super::shots;

/// Least-squares slope of log y against log x.
fn loglog_slope(points: &[(f64, f64)]) -> f64 {
    let pts: Vec<(f64, f64)> = points
        .iter()
        .filter(|(x, y)| *x > 0.0 && *y > 0.0)
        .map(|(x, y)| (x.ln(), y.ln()))
        .collect();
    #[allow(clippy::cast_precision_loss)]
    let n = pts.len() as f64;
    let (mx, my) = (
        pts.iter().map(|p| p.0).sum::<f64>() / n,
        pts.iter().map(|p| p.1).sum::<f64>() / n,
    );
    let sxy: f64 = pts.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
    let sxx: f64 = pts.iter().map(|p| (p.0 - mx).powi(2)).sum();
    sxy / sxx
}

/// Measures the scaling of cost with flight time and batch size.
///
/// # Errors
/// A scaling launch that cannot be flown.
pub fn measure(
    quick: bool,
    p64: &[shots::Prepared<f64>],
    budget: Budget,
    aero: &carry_core::aero::AeroModel<f64>,
) -> Result<Scaling, String> {
    use carry_core::flight::Integrator;
    let methods: [(&str, Integrator<f64>); 3] = [
        ("euler h=1e-3", Integrator::Euler { step_s: 1e-3 }),
        ("rk4 h=0.02", Integrator::Rk4 { step_s: 0.02 }),
        ("dp45 default", Integrator::default()),
    ];
    let ball = carry_core::Ball::<f64>::standard();
    let scene = carry_core::Scene::<f64> {
        aero: *aero,
        ..carry_core::Scene::default()
    };
    let mut flight_time = Vec::new();
    for launch in shots::scaling_launches(quick) {
        let motion = launch.ball_motion().map_err(|e| e.to_string())?;
        let mut evals = Vec::new();
        let mut us = Vec::new();
        let mut t = 0.0;
        for (_, integrator) in &methods {
            let out = carry_core::fly(&ball, &motion, &scene, integrator, None)
                .map_err(|e| format!("scaling flight: {e}"))?;
            t = out.flight_time_s;
            evals.push(out.stats.force_evaluations);
            us.push(measure::time_us(
                || {
                    let _ = std::hint::black_box(carry_core::fly(
                        &ball,
                        std::hint::black_box(&motion),
                        &scene,
                        integrator,
                        None,
                    ));
                },
                1,
                budget,
            ));
        }
        flight_time.push(FlightTimeRow {
            ball_speed_mps: launch.ball_speed_mps,
            flight_time_s: t,
            evals,
            us,
        });
    }
    let slopes = methods
        .iter()
        .enumerate()
        .map(|(i, (name, _))| Slope {
            integrator: (*name).to_owned(),
            evals_slope: loglog_slope(
                &flight_time
                    .iter()
                    .map(|r| (r.flight_time_s, f64::from(r.evals[i])))
                    .collect::<Vec<_>>(),
            ),
            time_slope: loglog_slope(
                &flight_time
                    .iter()
                    .map(|r| (r.flight_time_s, r.us[i]))
                    .collect::<Vec<_>>(),
            ),
        })
        .collect();

    // Batch size: the default f64 full shot over the delivery shots, n at a time.
    let deliveries: Vec<&shots::Prepared<f64>> = p64
        .iter()
        .filter(|p| matches!(p.start, shots::PreparedStart::Delivery { .. }))
        .collect();
    let integrator = Integrator::<f64>::default();
    let sizes: &[usize] = if quick {
        &[1, 100]
    } else {
        &[1, 10, 100, 1000, 10_000]
    };
    // Every batch size cycles through the same mix of deliveries (the cursor persists
    // across batches), so only the batch size differs.
    let mut cursor = 0_usize;
    let batch = sizes
        .iter()
        .map(|&n| BatchRow {
            batch_size: n,
            us_per_shot: measure::time_us(
                || {
                    for _ in 0..n {
                        let p = deliveries[cursor % deliveries.len()];
                        cursor = cursor.wrapping_add(1);
                        let _ = std::hint::black_box(measure::run_shot(
                            std::hint::black_box(p),
                            carry_core::Solver::Reduced,
                            &integrator,
                        ));
                    }
                },
                n,
                budget,
            ),
        })
        .collect();
    Ok(Scaling {
        methods: methods.iter().map(|(n, _)| (*n).to_owned()).collect(),
        flight_time,
        slopes,
        batch,
    })
}
