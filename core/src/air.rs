//! Air density: a fixed value, or weather through the moist-air formula (PHYSICS.md).
//!
//! ```text
//! p   = given, or 101325 · (1 − 2.25577e-5 · altitude_m)^5.25588          Pa (standard atmosphere)
//! e_s = 611.21 · exp((18.678 − T/234.5) · T / (257.14 + T))               Pa (Buck 1981)
//! p_v = RH · e_s
//! ρ   = (p − p_v) / (287.058 · (T + 273.15)) + p_v / (461.495 · (T + 273.15))
//! ```
//!
//! Buck, A. L. (1981), "New equations for computing vapor pressure and enhancement
//! factor", J. Appl. Meteorol. 20, 1527–1532 (the 1996 revision of its coefficients).

use crate::error::{Error, Field, Reason, Result};
use crate::real::{Real, lit};
/// Accepted temperature (°C) and altitude (m) ranges.
pub use crate::units::{ALTITUDE_RANGE_M, TEMPERATURE_RANGE_C};
use crate::validate::{finite, in_range, positive};

/// Sea-level standard air density (kg/m³), the default of PHYSICS.md.
pub const STANDARD_DENSITY_KGM3: f64 = 1.225;
/// Sea-level standard pressure (Pa).
pub const STANDARD_PRESSURE_PA: f64 = 101_325.0;
/// Dynamic viscosity of air at 15 °C by Sutherland's law (Pa·s): the viscosity of an
/// [`Air::Density`] whose temperature is not given (ISA sea level).
pub const STANDARD_VISCOSITY_PAS: f64 = 1.789_4e-5;
/// Specific gas constant of dry air (J/(kg·K)).
pub const R_DRY: f64 = 287.058;
/// Specific gas constant of water vapour (J/(kg·K)).
pub const R_VAPOUR: f64 = 461.495;

/// Where the air pressure of a [`Weather`] comes from.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum Pressure<T> {
    /// Station pressure as measured (Pa).
    Pa(T),
    /// Altitude above sea level (m); pressure from the standard atmosphere,
    /// `p = 101325 · (1 − 2.25577e-5 · h)^5.25588`.
    Altitude(T),
}

/// Weather from which the air density is computed.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Weather<T> {
    /// Air temperature (°C), in −100..=100.
    pub temperature_c: T,
    /// Relative humidity, 0..=1.
    pub relative_humidity: T,
    /// Pressure, given or from the altitude.
    pub pressure: Pressure<T>,
}

/// The air a scene flies through.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum Air<T> {
    /// A fixed density (kg/m³), finite and not negative (0 is a vacuum).
    Density(T),
    /// Density from the weather (moist-air formula).
    Weather(Weather<T>),
}

impl<T: Real> Default for Air<T> {
    /// Standard sea-level air, ρ = 1.225 kg/m³.
    fn default() -> Self {
        Self::Density(lit(STANDARD_DENSITY_KGM3))
    }
}

impl<T: Real> Weather<T> {
    /// Station pressure (Pa): given, or from the altitude by the standard atmosphere.
    ///
    /// # Errors
    /// [`Field::Pressure`] not finite and positive; [`Field::Altitude`] not finite or
    /// beyond the standard atmosphere's range (−5 km..=11 km).
    pub fn pressure_pa(&self) -> Result<T> {
        match self.pressure {
            Pressure::Pa(p) => positive(p, Field::Pressure),
            Pressure::Altitude(h) => {
                let (low, high) = ALTITUDE_RANGE_M;
                let h = in_range(h, lit(low), lit(high), Field::Altitude)?;
                let base = T::one() - lit::<T>(2.25577e-5) * h;
                Ok(lit::<T>(STANDARD_PRESSURE_PA) * base.powf(lit(5.25588)))
            }
        }
    }

    /// Saturation vapour pressure over water, Buck (1981/1996):
    /// `e_s = 611.21 · exp((18.678 − T/234.5) · T / (257.14 + T))` (Pa).
    #[must_use]
    pub fn saturation_vapour_pressure_pa(temperature_c: T) -> T {
        let t = temperature_c;
        lit::<T>(611.21) * ((lit::<T>(18.678) - t / lit(234.5)) * t / (lit::<T>(257.14) + t)).exp()
    }

    /// Moist-air density (kg/m³): dry air and water vapour as ideal gases at their
    /// partial pressures, `ρ = (p − p_v)/(R_d·T_K) + p_v/(R_v·T_K)`, `p_v = RH · e_s(T)`.
    ///
    /// # Errors
    /// [`Field::Temperature`] outside −100..=100 °C, [`Field::Humidity`] outside 0..=1,
    /// and the errors of [`Weather::pressure_pa`]; [`Field::Pressure`] with
    /// [`Reason::OutOfRange`] when the vapour pressure exceeds the total pressure.
    pub fn density_kgm3(&self) -> Result<T> {
        let (low, high) = TEMPERATURE_RANGE_C;
        let t = in_range(self.temperature_c, lit(low), lit(high), Field::Temperature)?;
        let rh = in_range(self.relative_humidity, T::zero(), T::one(), Field::Humidity)?;
        let p = self.pressure_pa()?;
        let pv = rh * Self::saturation_vapour_pressure_pa(t);
        if pv > p {
            return Err(Error::invalid(Field::Pressure, Reason::OutOfRange));
        }
        let tk = t + lit(273.15);
        finite(
            (p - pv) / (lit::<T>(R_DRY) * tk) + pv / (lit::<T>(R_VAPOUR) * tk),
            Field::AirDensity,
        )
    }
}

impl<T: Real> Air<T> {
    /// Dynamic viscosity μ (Pa·s), for the Reynolds number `Re = ρVD/μ`: Sutherland's law
    /// `μ = 1.458·10⁻⁶·T_K^1.5/(T_K + 110.4)` at the weather's temperature, or
    /// [`STANDARD_VISCOSITY_PAS`] (15 °C) for a fixed density. Humidity changes μ by under
    /// 1 % and is neglected.
    ///
    /// # Errors
    /// [`Field::Temperature`] outside −100..=100 °C.
    pub fn dynamic_viscosity_pas(&self) -> Result<T> {
        match self {
            Self::Density(_) => Ok(lit(STANDARD_VISCOSITY_PAS)),
            Self::Weather(w) => {
                let (low, high) = TEMPERATURE_RANGE_C;
                let t = in_range(w.temperature_c, lit(low), lit(high), Field::Temperature)?;
                let tk = t + lit(273.15);
                Ok(lit::<T>(1.458e-6) * tk * tk.root() / (tk + lit(110.4)))
            }
        }
    }

    /// The density this air has (kg/m³).
    ///
    /// # Errors
    /// [`Field::AirDensity`] for a NaN, infinite or negative fixed density; the errors of
    /// [`Weather::density_kgm3`].
    pub fn density_kgm3(&self) -> Result<T> {
        match self {
            Self::Density(rho) => crate::validate::non_negative(*rho, Field::AirDensity),
            Self::Weather(w) => w.density_kgm3(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn standard_atmosphere_dry_air() {
        // 15 °C, dry, sea level: the ISA density 1.2250 kg/m³.
        let w = Weather {
            temperature_c: 15.0_f64,
            relative_humidity: 0.0,
            pressure: Pressure::Altitude(0.0),
        };
        assert!((w.density_kgm3().unwrap_or(0.0) - 1.2250).abs() < 2e-4);
    }

    #[test]
    fn humid_air_is_lighter() {
        let dry = Weather {
            temperature_c: 30.0_f64,
            relative_humidity: 0.0,
            pressure: Pressure::Pa(101_325.0),
        };
        let wet = Weather {
            relative_humidity: 1.0,
            ..dry
        };
        assert!(wet.density_kgm3().unwrap_or(9.0) < dry.density_kgm3().unwrap_or(0.0));
        // Buck at 30 °C: 4246 Pa.
        assert!((Weather::saturation_vapour_pressure_pa(30.0_f64) - 4246.0).abs() < 5.0);
    }

    #[test]
    fn rejects_bad_weather() {
        let w = Weather {
            temperature_c: 20.0_f32,
            relative_humidity: 1.5,
            pressure: Pressure::Pa(1e5),
        };
        assert_eq!(
            w.density_kgm3(),
            Err(Error::invalid(Field::Humidity, Reason::OutOfRange))
        );
        assert_eq!(
            Air::Density(-1.0_f64).density_kgm3(),
            Err(Error::invalid(Field::AirDensity, Reason::Negative))
        );
        let w = Weather {
            temperature_c: 20.0_f64,
            relative_humidity: 0.5,
            pressure: Pressure::Pa(f64::NAN),
        };
        assert_eq!(
            w.density_kgm3(),
            Err(Error::invalid(Field::Pressure, Reason::NotFinite))
        );
    }
}
