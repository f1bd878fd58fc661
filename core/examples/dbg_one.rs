use carry_core::ground::{Ground, Surface};
use carry_core::units::{deg, rpm};
use carry_core::{Ball, Integrator, Launch, Real, Scene, fly};
fn one<T: Real>(v: f64, l: f64, w: f64) {
    let c = |x: f64| carry_core::real::lit::<T>(x);
    let m = Launch {
        ball_speed_mps: c(v * 0.44704),
        launch_angle_rad: deg(c(l)),
        launch_direction_rad: T::zero(),
        backspin_radps: rpm(c(w)),
        sidespin_radps: T::zero(),
    }
    .ball_motion()
    .unwrap();
    let scene = Scene {
        ground: Some(Ground::level(Surface::FairwayFirm)),
        ..Scene::default()
    };
    let o = fly(
        &Ball::<T>::standard(),
        &m,
        &scene,
        &Integrator::default(),
        None,
    )
    .unwrap();
    let g = o.ground.unwrap();
    eprintln!(
        "total {:?} carry {:?} t {:?} v {:?} steps {} rej {} land {:?}",
        g.total_m,
        o.carry_m,
        o.flight_time_s,
        o.landing_velocity_mps.as_slice(),
        o.stats.steps,
        o.stats.rejected_steps,
        o.landing_angle_rad
    );
}
fn main() {
    let a: Vec<f64> = std::env::args()
        .skip(1)
        .map(|x| x.parse().unwrap())
        .collect();
    one::<f64>(a[0], a[1], a[2]);
    one::<f32>(a[0], a[1], a[2]);
}
