//! Profiling aid: the default shot with and without a ground, many times:
//! `ground_cost {n|g|trackman|green|rough} N` (no ground, firm fairway, the launch
//! monitor's fairway, green, rough).
use carry_core::ground::{Ground, Surface};
use carry_core::real::lit;
use carry_core::shot::{Fidelity, play};
use carry_core::{Ball, ClubSpec, Delivery, FaceLocation, Scene};
use std::hint::black_box;
fn main() {
    let surface = match std::env::args().nth(1).as_deref() {
        Some("g") => Some(Surface::FairwayFirm),
        Some("trackman") => Some(Surface::FairwayTrackman),
        Some("green") => Some(Surface::green()),
        Some("rough") => Some(Surface::Rough),
        _ => None,
    };
    let Ok(club) = ClubSpec::<f64>::driver().validate() else {
        return;
    };
    let mut d = Delivery::square(lit(45.0), &club);
    d.location = FaceLocation {
        height_m: 0.005,
        toe_m: 0.01,
    };
    let ball = Ball::standard();
    let scene = Scene {
        ground: surface.map(Ground::level),
        ..Scene::default()
    };
    let Ok(scene) = scene.prepare(&ball) else {
        return;
    };
    let mut n = 0.0;
    let iters: u32 = std::env::args()
        .nth(2)
        .and_then(|s| s.parse().ok())
        .unwrap_or(200_000);
    for _ in 0..iters {
        if let Ok(o) = play(
            black_box(&club),
            &ball,
            black_box(&d),
            &scene,
            &Fidelity::default(),
            None,
        ) {
            n += o.flight.ground.map_or(o.flight.carry_m, |g| g.total_m);
        }
    }
    println!("{n}");
}
