//! Decoding fuzzer bytes into physical parameters.
//!
//! Each parameter reads one tag byte: most tags give a value spread over the parameter's
//! physical range (so the fuzzer reaches deep into the solvers), the rest give the hard
//! values of issue 7 — NaN, ±∞, ±0, negative, subnormal, the extremes of the precision —
//! or raw bits. Running out of bytes gives the range's low end, so every input decodes.

/// A cursor over the fuzzer's bytes.
pub struct Bytes<'a> {
    data: &'a [u8],
}

/// The hard values every field is tried with.
const SPECIAL: [f64; 16] = [
    f64::NAN,
    f64::INFINITY,
    f64::NEG_INFINITY,
    0.0,
    -0.0,
    -1.0,
    1.0,
    5e-324,  // smallest f64 subnormal
    1.0e-40, // an f32 subnormal
    f64::MIN_POSITIVE,
    f64::MAX,
    -f64::MAX,
    1.0e-300,
    1.0e300,
    3.4e38, // near f32::MAX
    -1.0e-12,
];

impl<'a> Bytes<'a> {
    /// A cursor at the start of `data`.
    #[must_use]
    pub fn new(data: &'a [u8]) -> Self {
        Self { data }
    }

    /// The next byte (0 when exhausted).
    pub fn byte(&mut self) -> u8 {
        match self.data.split_first() {
            Some((b, rest)) => {
                self.data = rest;
                *b
            }
            None => 0,
        }
    }

    fn u16(&mut self) -> u16 {
        u16::from_le_bytes([self.byte(), self.byte()])
    }

    fn u64(&mut self) -> u64 {
        let mut b = [0_u8; 8];
        for x in &mut b {
            *x = self.byte();
        }
        u64::from_le_bytes(b)
    }

    /// A boolean.
    pub fn flag(&mut self) -> bool {
        self.byte() & 1 == 1
    }

    /// A value for a parameter whose physical range is `lo..=hi`: tags 0–191 spread over
    /// the range, 192–239 a hard value, 240–255 raw `f64` bits.
    pub fn param(&mut self, lo: f64, hi: f64) -> f64 {
        let tag = self.byte();
        match tag {
            0..=191 => lo + (hi - lo) * f64::from(self.u16()) / 65535.0,
            192..=239 => SPECIAL[usize::from(tag - 192) % SPECIAL.len()],
            _ => f64::from_bits(self.u64()),
        }
    }

    /// Three parameters.
    pub fn vec3(&mut self, lo: f64, hi: f64) -> [f64; 3] {
        [self.param(lo, hi), self.param(lo, hi), self.param(lo, hi)]
    }
}
