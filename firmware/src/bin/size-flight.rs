//! Size probe: flight only — launch conditions in, landing out (every integrator linked:
//! the integrator is a run-time choice). See size.sh.
#![no_std]
#![no_main]

use carry_core::flight::{self, Integrator};
use carry_core::real::lit;
use carry_core::scene::Scene;
use carry_core::units::{deg, rpm};
use carry_core::{Ball, Launch};
use carry_firmware::shot::R;
use core::hint::black_box;
use cortex_m_rt::entry;

#[entry]
fn main() -> ! {
    let launch = black_box(Launch::<R> {
        ball_speed_mps: lit(65.88),
        launch_angle_rad: deg(lit(8.74)),
        launch_direction_rad: lit(0.0),
        backspin_radps: rpm(lit(2258.0)),
        sidespin_radps: lit(0.0),
    });
    let scene = black_box(Scene::<R>::default());
    let integrator = black_box(Integrator::<R>::default());
    let out = launch
        .ball_motion()
        .and_then(|m| flight::fly(&Ball::standard(), &m, &scene, &integrator, None));
    match out {
        Ok(f) => defmt::println!("carry {} m", f.carry_m),
        Err(e) => defmt::println!("{}", e),
    }
    carry_firmware::exit_ok()
}
