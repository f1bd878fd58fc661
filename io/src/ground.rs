//! The ground after the landing: `--ground NAME|FILE.toml` and its options → a core
//! [`Ground`].
//!
//! Surfaces: `fairway` (firm), `fairway-trackman` (TrackMan's single drives),
//! `fairway-joint` (TrackMan's single drives and 2010 chart at once), `fairway-soft`,
//! `rough`, `green` (with `--stimp`, feet — the stimpmeter's own unit — default 10). Any
//! of `--ground-restitution`, `--ground-friction`, `--rolling-resistance`, `--crater-scale`,
//! `--grass-height` (m) overrides the surface's value (a custom turf). `--ground-slope DEG` tilts the ground plane through the landing
//! point, rising towards `--ground-slope-direction DEG` (from downrange towards the right,
//! like the wind: 0 = uphill to the target, 180 = downhill, 90 = rising to the right).
//!
//! A ground file (TOML), and a `[ground]` table or `ground = "green"` in a scene file, take
//! the keys `surface`, `stimp`, `restitution`, `friction`, `rolling_resistance`,
//! `crater_scale`, `grass_height`, `slope`, `slope_direction`.

use crate::error::InputError;
use carry_core::real::lit;
use carry_core::units::deg;
use carry_core::{Ground, Real, Surface, Turf};
use std::path::Path;

/// A named surface.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum GroundPreset {
    /// Firm fairway.
    Fairway,
    /// The launch monitor's fairway (fitted to TrackMan's single drives).
    FairwayTrackman,
    /// The fairway of both TrackMan data sets (fitted to its single drives and its 2010
    /// chart at once).
    FairwayJoint,
    /// Soft fairway.
    FairwaySoft,
    /// Rough.
    Rough,
    /// Green (stimp from `--stimp`).
    Green,
}

/// The surface names, for messages.
pub const GROUND_NAMES: &str =
    "fairway, fairway-trackman, fairway-joint, fairway-soft, rough, green, or a FILE.toml";

impl GroundPreset {
    /// Looks a surface up by name.
    #[must_use]
    pub fn find(name: &str) -> Option<Self> {
        match name.trim().to_ascii_lowercase().replace('_', "-").as_str() {
            "fairway" | "fairway-firm" => Some(Self::Fairway),
            "fairway-trackman" | "trackman" => Some(Self::FairwayTrackman),
            "fairway-joint" => Some(Self::FairwayJoint),
            "fairway-soft" => Some(Self::FairwaySoft),
            "rough" => Some(Self::Rough),
            "green" => Some(Self::Green),
            _ => None,
        }
    }
}

/// Everything about the ground the options, a scene file or a ground file say (SI except
/// stimp in feet; angles in degrees).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct GroundSpec {
    /// The surface.
    pub preset: Option<GroundPreset>,
    /// Stimp (ft), greens only.
    pub stimp_ft: Option<f64>,
    /// Restitution at vanishing normal speed.
    pub restitution: Option<f64>,
    /// Ball–turf friction.
    pub friction: Option<f64>,
    /// Rolling resistance.
    pub rolling_resistance: Option<f64>,
    /// Crater scale.
    pub crater_scale: Option<f64>,
    /// Grass height (m): a rebound that does not rise clear of it ends the bouncing.
    pub grass_height_m: Option<f64>,
    /// Slope (deg).
    pub slope_deg: Option<f64>,
    /// Direction the ground rises towards (deg).
    pub slope_direction_deg: Option<f64>,
}

impl GroundSpec {
    /// Whether nothing about the ground was given.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        *self == Self::default()
    }

    /// Takes every value `other` gives.
    pub fn merge(&mut self, other: &Self) {
        macro_rules! take {
            ($($f:ident),*) => { $( if other.$f.is_some() { self.$f = other.$f; } )* };
        }
        take!(
            preset,
            stimp_ft,
            restitution,
            friction,
            rolling_resistance,
            crater_scale,
            grass_height_m,
            slope_deg,
            slope_direction_deg
        );
    }
}

/// `--ground` text: a surface name or a ground file.
///
/// # Errors
/// The reason, for a message.
pub fn parse(text: &str) -> Result<GroundSpec, String> {
    if let Some(preset) = GroundPreset::find(text) {
        return Ok(GroundSpec {
            preset: Some(preset),
            ..GroundSpec::default()
        });
    }
    let path = Path::new(text.trim());
    let is_file = path
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("toml"));
    if !is_file {
        return Err(format!(
            "unknown surface '{}' ({GROUND_NAMES})",
            text.trim()
        ));
    }
    let body = std::fs::read_to_string(path)
        .map_err(|e| format!("cannot read {}: {e}", path.display()))?;
    let table: toml::Table = body.parse().map_err(|e: toml::de::Error| {
        let msg = e.message().replace('\n', " ");
        format!("{}: not valid TOML: {}", path.display(), msg.trim())
    })?;
    from_table(&table).map_err(|e| format!("in {}: {e}", path.display()))
}

/// The keys of a ground table.
const TABLE_KEYS: &str = "surface, stimp, restitution, friction, rolling_resistance, crater_scale, grass_height, slope, slope_direction";

/// A ground table (a ground file, or `[ground]` in a scene file).
///
/// # Errors
/// The reason, for a message.
pub fn from_table(table: &toml::Table) -> Result<GroundSpec, String> {
    let mut g = GroundSpec::default();
    for (name, value) in table {
        let number = || -> Result<f64, String> {
            let x = match value {
                toml::Value::Float(x) => *x,
                #[allow(clippy::cast_precision_loss)]
                toml::Value::Integer(i) => *i as f64,
                _ => return Err(format!("{name} must be a number")),
            };
            if x.is_finite() {
                Ok(x)
            } else {
                Err(format!("{name} is not a finite number"))
            }
        };
        match name.as_str() {
            "surface" => {
                let toml::Value::String(s) = value else {
                    return Err(format!("surface must be a name ({GROUND_NAMES})"));
                };
                g.preset =
                    Some(GroundPreset::find(s).ok_or_else(|| format!("unknown surface '{s}'"))?);
            }
            "stimp" => g.stimp_ft = Some(number()?),
            "restitution" => g.restitution = Some(number()?),
            "friction" => g.friction = Some(number()?),
            "rolling_resistance" => g.rolling_resistance = Some(number()?),
            "crater_scale" => g.crater_scale = Some(number()?),
            "grass_height" => g.grass_height_m = Some(number()?),
            "slope" => g.slope_deg = Some(number()?),
            "slope_direction" => g.slope_direction_deg = Some(number()?),
            other => return Err(format!("unknown key '{other}' (keys: {TABLE_KEYS})")),
        }
    }
    Ok(g)
}

/// The core ground `spec` describes, `None` when none was asked for.
///
/// # Errors
/// Ground options without `--ground`, `--stimp` off a green, a bad stimp.
pub fn build<T: Real>(spec: &GroundSpec) -> Result<Option<Ground<T>>, InputError> {
    if spec.is_empty() {
        return Ok(None);
    }
    let Some(preset) = spec.preset else {
        return Err(InputError::new(
            "ground",
            format!("the ground options need a surface: --ground {GROUND_NAMES}"),
        ));
    };
    let surface = match (preset, spec.stimp_ft) {
        (GroundPreset::Green, stimp) => Surface::Green {
            stimp_m: lit(stimp.unwrap_or(10.0) * carry_core::ground::surface::FOOT_M),
        },
        (_, Some(_)) => {
            return Err(InputError::new("stimp", "applies to --ground green only"));
        }
        (GroundPreset::Fairway, None) => Surface::FairwayFirm,
        (GroundPreset::FairwayTrackman, None) => Surface::FairwayTrackman,
        (GroundPreset::FairwayJoint, None) => Surface::FairwayJoint,
        (GroundPreset::FairwaySoft, None) => Surface::FairwaySoft,
        (GroundPreset::Rough, None) => Surface::Rough,
    };
    let overrides = [
        spec.restitution,
        spec.friction,
        spec.rolling_resistance,
        spec.crater_scale,
        spec.grass_height_m,
    ];
    let surface = if overrides.iter().any(Option::is_some) {
        let base = surface.turf().map_err(InputError::from)?;
        let pick = |x: Option<f64>, d: T| x.map_or(d, lit);
        Surface::Custom(Turf {
            restitution: pick(spec.restitution, base.restitution),
            friction: pick(spec.friction, base.friction),
            rolling_resistance: pick(spec.rolling_resistance, base.rolling_resistance),
            crater_scale: pick(spec.crater_scale, base.crater_scale),
            grass_height_m: pick(spec.grass_height_m, base.grass_height_m),
            ..base
        })
    } else {
        surface
    };
    let slope = spec.slope_deg.unwrap_or(0.0);
    Ok(Some(
        if slope == 0.0 && spec.slope_direction_deg.is_none() {
            Ground::level(surface)
        } else {
            Ground::sloped(
                surface,
                deg(lit::<T>(slope)),
                deg(lit::<T>(spec.slope_direction_deg.unwrap_or(0.0))),
            )
        },
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_and_errors() {
        assert_eq!(
            parse("Fairway-Soft").map(|g| g.preset),
            Ok(Some(GroundPreset::FairwaySoft))
        );
        assert_eq!(
            parse("fairway_joint").map(|g| g.preset),
            Ok(Some(GroundPreset::FairwayJoint))
        );
        assert_eq!(
            build::<f64>(&parse("fairway-joint").unwrap()).map(|g| g.map(|g| g.surface)),
            Ok(Some(Surface::FairwayJoint))
        );
        assert!(parse("sand").is_err_and(|e| e.contains("unknown surface 'sand'")));
        assert!(GROUND_NAMES.contains("fairway-joint"));
        let spec = GroundSpec {
            slope_deg: Some(2.0),
            ..GroundSpec::default()
        };
        assert_eq!(build::<f64>(&spec).map_err(|e| e.key), Err("ground"));
        let spec = GroundSpec {
            preset: Some(GroundPreset::Rough),
            stimp_ft: Some(10.0),
            ..GroundSpec::default()
        };
        assert_eq!(build::<f64>(&spec).map_err(|e| e.key), Err("stimp"));
        assert_eq!(build::<f64>(&GroundSpec::default()), Ok(None));
    }
}
