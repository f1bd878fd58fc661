//! f32 against f64 on the carry and total of topped and low shots that skip in low hops
//! (docs/ground.md, Cost): the worst differences over a grid.
//!
//! `cargo run --release -p carry-core --example ground_precision`
use carry_core::ground::{Ground, Surface};
use carry_core::units::{deg, rpm};
use carry_core::{Ball, Integrator, Launch, Real, Scene, fly};

struct Out {
    carry: f64,
    total: f64,
    bounces: u32,
    angle: f64,
}

fn shot<T: Real>(v: f64, l: f64, w: f64, s: Surface<T>) -> Option<Out> {
    let c = |x: f64| carry_core::real::lit::<T>(x);
    let m = Launch {
        ball_speed_mps: c(v * 0.44704),
        launch_angle_rad: deg(c(l)),
        launch_direction_rad: T::zero(),
        backspin_radps: rpm(c(w)),
        sidespin_radps: T::zero(),
    }
    .ball_motion()
    .ok()?;
    let scene = Scene {
        ground: Some(Ground::level(s)),
        ..Scene::default()
    };
    let integrator = if let Some(t) = std::env::var("TOL")
        .ok()
        .and_then(|t| t.parse::<f64>().ok())
    {
        Integrator::dormand_prince(c(t))
    } else if std::env::var_os("SEED").is_some() {
        Integrator::seed()
    } else {
        Integrator::default()
    };
    let o = fly(&Ball::<T>::standard(), &m, &scene, &integrator, None).ok()?;
    let g = o.ground?;
    let f = carry_core::real::to_f64::<T>;
    Some(Out {
        carry: f(o.carry_m),
        total: f(g.total_m),
        bounces: g.bounces,
        angle: f(o.landing_angle_rad).to_degrees(),
    })
}

fn main() {
    let mut worst: Vec<(f64, String)> = Vec::new();
    let mut n = 0;
    for (name, s64, s32) in [
        ("fairway", Surface::FairwayFirm, Surface::FairwayFirm),
        ("fairway-soft", Surface::FairwaySoft, Surface::FairwaySoft),
        ("rough", Surface::Rough, Surface::Rough),
        ("green", Surface::green(), Surface::green()),
    ] {
        for v in [
            60.0, 70.0, 80.0, 90.0, 100.0, 110.0, 120.0, 130.0, 140.0, 160.0,
        ] {
            for l in [-4.0, -3.0, -2.0, -1.0, 0.0, 0.5, 1.0, 2.0, 3.0, 5.0, 8.0] {
                for w in [-500.0, 0.0, 300.0, 1000.0, 1500.0, 2000.0, 3000.0, 4000.0] {
                    let (Some(a), Some(b)) = (shot::<f64>(v, l, w, s64), shot::<f32>(v, l, w, s32))
                    else {
                        continue;
                    };
                    n += 1;
                    let d = (a.total - b.total).abs().max((a.carry - b.carry).abs());
                    worst.push((
                        d,
                        format!(
                            "{name:12} {v:5} mph {l:4}° {w:6} rpm: total {:.3} m (f64) {:+.4} m (f32-f64), carry {:+.4}, bounces {} / {}, landing {:.1}°",
                            a.total,
                            b.total - a.total,
                            b.carry - a.carry,
                            a.bounces,
                            b.bounces,
                            a.angle
                        ),
                    ));
                }
            }
        }
    }
    worst.sort_by(|a, b| b.0.total_cmp(&a.0));
    let over = worst.iter().filter(|w| w.0 > 0.01).count();
    println!("{n} shots; {over} over 1 cm; worst:");
    let show = std::env::var("SHOW")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(25);
    for (_, line) in worst.iter().take(show) {
        println!("  {line}");
    }
}
