//! Target against host, bit for bit: the comparison the on-target test images share
//! (`tests/golden.rs`, `tests/estimate.rs`).

use crate::cases;
use crate::golden::Host;
use carry_core::Real;

/// A precision the suite runs in.
pub trait Precision: Real + defmt::Format {
    /// `f32` or `f64`, for the log.
    const NAME: &'static str;
    /// The bits' type (`u32`, `u64`).
    type Bits: Copy + PartialEq + Into<u64>;
    /// The value's bits.
    fn bits(self) -> Self::Bits;
}

impl Precision for f32 {
    const NAME: &'static str = "f32";
    type Bits = u32;
    fn bits(self) -> u32 {
        self.to_bits()
    }
}

impl Precision for f64 {
    const NAME: &'static str = "f64";
    type Bits = u64;
    fn bits(self) -> u64 {
        self.to_bits()
    }
}

/// Compares one target result with the host's; logs every difference. Returns whether
/// they are identical.
pub fn identical<T: Precision, const N: usize>(
    case: &str,
    variant: &str,
    names: &[&str; N],
    target: &Result<[T; N], carry_core::Error>,
    host: &Host<T::Bits, N>,
) -> bool {
    match (target, host) {
        (Ok(t), Host::Ok(h)) => {
            let mut same = true;
            for i in 0..N {
                if t[i].bits() != h[i] {
                    same = false;
                    defmt::error!(
                        "{=str} {=str} {=str}: {=str} target {=u64:#x} ({}) != host {=u64:#x}",
                        T::NAME,
                        case,
                        variant,
                        names[i],
                        t[i].bits().into(),
                        t[i],
                        h[i].into()
                    );
                }
            }
            same
        }
        (Err(e), Host::Err(code)) if cases::error_code(e) == *code => true,
        (t, _) => {
            defmt::error!(
                "{=str} {=str} {=str}: outcome differs: target {}",
                T::NAME,
                case,
                variant,
                t.is_ok()
            );
            false
        }
    }
}
