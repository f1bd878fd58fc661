//! A full shot as a launch monitor runs it: delivery → impact → flight → carry, in the
//! firmware's precision (f32; `--features f64` for f64), printed with defmt. Also reports
//! the shot's peak stack use (painted stack).
#![no_std]
#![no_main]

use carry_core::flight::Integrator;
use carry_core::impact::Solver;
use carry_core::real::to_f64;
use carry_core::scene::Scene;
use carry_core::units::{to_deg, to_rpm};
use carry_core::{ClubSpec, Delivery};
use carry_firmware::shot::{self, CALIBRATED_CARRY_M, R};
use core::hint::black_box;
use cortex_m_rt::entry;

type Shot = carry_core::Result<(carry_core::ImpactOutcome<R>, carry_core::FlightOutcome<R>)>;

/// The launch monitor's shot: the reduced solver (the default).
#[inline(never)]
fn shot_reduced(
    club: &ClubSpec<R>,
    delivery: &Delivery<R>,
    scene: &Scene<R>,
    integrator: &Integrator<R>,
) -> Shot {
    shot::full(club, delivery, Solver::Reduced, scene, integrator)
}

/// The same shot through the full 15×15 solver (its matrix lives on the stack).
#[inline(never)]
fn shot_full(
    club: &ClubSpec<R>,
    delivery: &Delivery<R>,
    scene: &Scene<R>,
    integrator: &Integrator<R>,
) -> Shot {
    shot::full(club, delivery, Solver::FULL, scene, integrator)
}

#[entry]
fn main() -> ! {
    // What the launch monitor measured (opaque to the optimiser, as a sensor reading is).
    let club = black_box(shot::driver::<R>());
    let delivery = black_box(shot::delivery::<R>());
    let scene = black_box(Scene::<R>::default());
    let integrator = black_box(Integrator::<R>::default());

    let (result, stack) =
        carry_firmware::stack::measure(|| shot_reduced(&club, &delivery, &scene, &integrator));
    let (hit, flight) = match result {
        Ok(r) => r,
        Err(e) => {
            defmt::error!("shot failed: {}", e);
            carry_firmware::exit(1)
        }
    };
    let l = &hit.launch;
    defmt::println!(
        "launch: ball {=f64} m/s, smash {=f64}, launch {=f64}°, direction {=f64}°, backspin {=f64} rpm, sidespin {=f64} rpm",
        to_f64(l.ball_speed_mps),
        to_f64(l.smash_factor),
        to_f64(to_deg(l.launch_angle_rad)),
        to_f64(to_deg(l.launch_direction_rad)),
        to_f64(to_rpm(l.backspin_radps)),
        to_f64(to_rpm(l.sidespin_radps))
    );
    let carry = to_f64(flight.carry_m);
    defmt::println!(
        "flight: carry {=f64} m, side {=f64} m, apex {=f64} m, {=f64} s in the air, lands at {=f64}° ({=u32} force evaluations)",
        carry,
        to_f64(flight.side_m),
        to_f64(flight.apex_m),
        to_f64(flight.flight_time_s),
        to_f64(to_deg(flight.landing_angle_rad)),
        flight.stats.force_evaluations
    );
    // The worst case over both solvers: the full 15×15 solve keeps its matrix on the stack.
    let (full, stack_full) =
        carry_firmware::stack::measure(|| shot_full(&club, &delivery, &scene, &integrator));
    if full.is_err() {
        defmt::error!("shot with the full solver failed");
        carry_firmware::exit(1)
    }
    defmt::println!(
        "peak stack of the shot: {=usize} bytes (reduced solver), {=usize} bytes (full solver)",
        stack,
        stack_full
    );
    // Scene::default() flies the calibrated model (drives2026), as a launch monitor would.
    let off = carry - CALIBRATED_CARRY_M;
    defmt::println!("carry − f64 reference = {=f64} m", off);
    if off.abs() > 0.01 {
        defmt::error!("carry more than 1 cm off the reference");
        carry_firmware::exit(1)
    }
    carry_firmware::exit_ok()
}
