//! Display and input units: SI by default, launch-monitor imperial on request.
//!
//! `--units imperial` changes what the user types and reads, never the JSON (always SI):
//!
//! | quantity | SI | imperial |
//! |---|---|---|
//! | speeds (club, ball, wind, landing) | m/s | mph |
//! | long distances (carry, side, landing X/Z) | m | yd |
//! | heights (apex, landing height, altitude, wind reference height) | m | ft |
//! | impact location on the face | m (table: mm) | in |
//! | temperature | °C | °F |
//!
//! Angles stay in degrees, launch spins in rpm, club spin in rad/s, club and ball
//! parameters in kg, kg·m² and m, pressure in Pa and air density in kg/m³ in both systems.

use carry_core::units::{M_PER_FOOT, M_PER_YARD, MPS_PER_MPH};

/// Metres per inch (exact).
pub const M_PER_INCH: f64 = 0.0254;

/// The unit system of input and display.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
pub enum Units {
    /// m/s, m, °C.
    #[default]
    Si,
    /// mph, yards (carry, side), feet (heights), inches (impact location), °F.
    Imperial,
}

/// What kind of quantity a value is, for unit conversion.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Quantity {
    /// Not converted (angles, spins, masses, …).
    Plain,
    /// m/s ↔ mph.
    Speed,
    /// m ↔ yd.
    Long,
    /// m ↔ ft.
    Height,
    /// m ↔ in (impact offsets).
    Offset,
    /// °C ↔ °F.
    Temperature,
}

impl Units {
    /// A value typed in these units → SI.
    #[must_use]
    pub fn to_si(self, q: Quantity, x: f64) -> f64 {
        match (self, q) {
            (Self::Si, _) | (_, Quantity::Plain) => x,
            (Self::Imperial, Quantity::Speed) => x * MPS_PER_MPH,
            (Self::Imperial, Quantity::Long) => x * M_PER_YARD,
            (Self::Imperial, Quantity::Height) => x * M_PER_FOOT,
            (Self::Imperial, Quantity::Offset) => x * M_PER_INCH,
            (Self::Imperial, Quantity::Temperature) => (x - 32.0) * (5.0 / 9.0),
        }
    }

    /// An SI value → these units, for display.
    #[must_use]
    pub fn to_display(self, q: Quantity, x: f64) -> f64 {
        match (self, q) {
            (Self::Si, _) | (_, Quantity::Plain) => x,
            (Self::Imperial, Quantity::Speed) => x / MPS_PER_MPH,
            (Self::Imperial, Quantity::Long) => x / M_PER_YARD,
            (Self::Imperial, Quantity::Height) => x / M_PER_FOOT,
            (Self::Imperial, Quantity::Offset) => x / M_PER_INCH,
            (Self::Imperial, Quantity::Temperature) => x * (9.0 / 5.0) + 32.0,
        }
    }

    /// The unit symbol of a quantity as the user types it.
    #[must_use]
    pub fn input_symbol(self, q: Quantity) -> &'static str {
        match (self, q) {
            (_, Quantity::Plain) => "",
            (Self::Si, Quantity::Speed) => "m/s",
            (Self::Si, Quantity::Long | Quantity::Height | Quantity::Offset) => "m",
            (Self::Si, Quantity::Temperature) => "°C",
            (Self::Imperial, Quantity::Speed) => "mph",
            (Self::Imperial, Quantity::Long) => "yd",
            (Self::Imperial, Quantity::Height) => "ft",
            (Self::Imperial, Quantity::Offset) => "in",
            (Self::Imperial, Quantity::Temperature) => "°F",
        }
    }

    /// A length (m) for display in the unit of `q`, as (value, symbol). Impact offsets
    /// are shown in millimetres in SI (launch-monitor style), inches in imperial.
    #[must_use]
    pub fn display(self, q: Quantity, x: f64) -> (f64, &'static str) {
        match (self, q) {
            (Self::Si, Quantity::Offset) => (x * 1000.0, "mm"),
            _ => (self.to_display(q, x), self.input_symbol(q)),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn round_trips() {
        for q in [
            Quantity::Speed,
            Quantity::Long,
            Quantity::Height,
            Quantity::Offset,
            Quantity::Temperature,
        ] {
            let x = 12.345;
            assert!((Units::Imperial.to_si(q, Units::Imperial.to_display(q, x)) - x).abs() < 1e-12);
        }
        assert!((Units::Imperial.to_si(Quantity::Speed, 100.0) - 44.704).abs() < 1e-12);
        assert!((Units::Imperial.to_si(Quantity::Temperature, 212.0) - 100.0).abs() < 1e-12);
    }
}
