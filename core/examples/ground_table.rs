//! Prints the rollout of a few shots on each surface (docs/ground.md).
use carry_core::ground::{Ground, Surface};
use carry_core::units::{deg, rpm};
use carry_core::{Ball, Integrator, Launch, Scene, fly};
fn main() {
    let shots = [
        ("driver", 171.0, 10.4, 2545.0),
        ("7iron", 123.0, 16.1, 7124.0),
        ("pw", 104.0, 23.7, 9316.0),
        ("driver45", 147.4, 8.7, 2258.0),
    ];
    for (name, s) in [
        ("fairway", Surface::FairwayFirm),
        ("fairway-soft", Surface::FairwaySoft),
        ("rough", Surface::Rough),
        ("green", Surface::green()),
    ] {
        for (club, v, l, w) in shots {
            let Ok(m) = (Launch {
                ball_speed_mps: v * 0.44704,
                launch_angle_rad: deg(l),
                launch_direction_rad: 0.0,
                backspin_radps: rpm(w),
                sidespin_radps: 0.0,
            })
            .ball_motion() else {
                return;
            };
            let scene = Scene {
                ground: Some(Ground::level(s)),
                ..Scene::default()
            };
            let Ok(o) = fly(
                &Ball::<f64>::standard(),
                &m,
                &scene,
                &Integrator::default(),
                None,
            ) else {
                return;
            };
            let Some(g) = o.ground else { return };
            println!(
                "{name:13} {club:8} carry {:6.1} yd land {:4.1}° {:4.1} m/s {:5.0} rpm | roll {:+9.5} yd bounces {} t {:5.2} s evals {:3} (flight {})",
                o.carry_m / 0.9144,
                o.landing_angle_rad.to_degrees(),
                o.landing_speed_mps,
                o.landing_spin_radps * 60.0 / std::f64::consts::TAU,
                g.roll_m / 0.9144,
                g.bounces,
                g.time_to_rest_s,
                g.stats.force_evaluations,
                o.stats.force_evaluations
            );
        }
    }
}
