//! Size probe: the full-shot firmware — delivery in, impact (the reduced solver, the
//! launch monitor's default) and flight (integrator chosen at run time, so all three are
//! linked) to the carry, printed. See size.sh.
#![no_std]
#![no_main]

use carry_core::flight::Integrator;
use carry_core::impact::Solver;
use carry_core::scene::Scene;
use carry_firmware::shot::{self, R};
use core::hint::black_box;
use cortex_m_rt::entry;

#[entry]
fn main() -> ! {
    let club = black_box(shot::driver::<R>());
    let delivery = black_box(shot::delivery::<R>());
    let scene = black_box(Scene::<R>::default());
    let integrator = black_box(Integrator::<R>::default());
    match shot::full(&club, &delivery, Solver::Reduced, &scene, &integrator) {
        Ok((hit, flight)) => defmt::println!("{} carry {} m", hit.launch, flight.carry_m),
        Err(e) => defmt::println!("{}", e),
    }
    carry_firmware::exit_ok()
}
