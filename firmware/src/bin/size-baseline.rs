//! Size probe: the firmware runtime (defmt over semihosting, exit, fault and panic
//! handlers) with no physics: what every other image has too. See size.sh.
#![no_std]
#![no_main]

use cortex_m_rt::entry;

#[entry]
fn main() -> ! {
    carry_firmware::exit_ok()
}
