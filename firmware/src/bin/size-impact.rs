//! Size probe: impact only — a delivery in, launch conditions out (both solvers linked:
//! the solver is a run-time choice). See size.sh.
#![no_std]
#![no_main]

use carry_core::impact::Solver;
use carry_firmware::shot::{self, R};
use core::hint::black_box;
use cortex_m_rt::entry;

#[entry]
fn main() -> ! {
    let club = black_box(shot::driver::<R>());
    let delivery = black_box(shot::delivery::<R>());
    match shot::impact(&club, &delivery, black_box(Solver::Reduced)) {
        Ok(hit) => defmt::println!("{}", hit.launch),
        Err(e) => defmt::println!("{}", e),
    }
    carry_firmware::exit_ok()
}
