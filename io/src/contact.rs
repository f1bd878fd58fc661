//! `--contact NAME|FILE.toml`: the face–ball contact law.
//!
//! Names: `rolling` (the seed's rigid contact: rolling without slipping, constant COR),
//! `compliant` or `fitted` (the calibrated friction-limited compliant contact every preset
//! carries, `carry_core::presets::FITTED_CONTACT`). A TOML file gives a compliant law's
//! parameters by name (the ones `carry fit` writes); missing ones take the fitted values:
//!
//! ```toml
//! law = "compliant"                  # or "rolling"
//! friction = 0.4                     # μ ≥ 0, or "inf"
//! tangential_restitution = 0.02      # e_t0 in [−1, 1]
//! tangential_restitution_slope = 0.25
//! tangential_restitution_max = 0.25  # e_t,max in [0, 1]
//! restitution_speed_slope_spm = 0.003
//! ```

use carry_core::impact::ContactLaw;
use carry_core::presets::{FITTED_COMPLIANT, FITTED_CONTACT};
use std::path::Path;

/// The contact-law names, for messages and `--help`.
pub const NAMES: &str = "rolling, compliant (= fitted)";

/// A contact law by name, or from a TOML file (a name ending in `.toml`).
///
/// # Errors
/// One line: an unknown name, an unreadable file, bad TOML, an unknown key, a bad value.
pub fn parse(text: &str) -> Result<ContactLaw<f64>, String> {
    let t = text.trim();
    match t.to_ascii_lowercase().as_str() {
        "rolling" | "seed" => return Ok(ContactLaw::Rolling),
        "compliant" | "fitted" => return Ok(FITTED_CONTACT),
        _ => {}
    }
    if !t.to_ascii_lowercase().ends_with(".toml") {
        return Err(format!(
            "unknown contact '{t}' (names: {NAMES}; or a FILE.toml)"
        ));
    }
    let path = Path::new(t);
    let body = std::fs::read_to_string(path)
        .map_err(|e| format!("cannot read {}: {e}", path.display()))?;
    from_toml(&body).map_err(|e| format!("{}: {e}", path.display()))
}

/// A contact law from TOML text.
///
/// # Errors
/// The reason, one line.
pub fn from_toml(body: &str) -> Result<ContactLaw<f64>, String> {
    let table: toml::Table = body.parse().map_err(|e: toml::de::Error| {
        format!("not valid TOML: {}", e.message().replace('\n', " ").trim())
    })?;
    let mut law = FITTED_COMPLIANT;
    let mut rolling = false;
    for (name, value) in &table {
        let number = || -> Result<f64, String> {
            match value {
                toml::Value::Float(x) if !x.is_nan() => Ok(*x),
                #[allow(clippy::cast_precision_loss)]
                toml::Value::Integer(i) => Ok(*i as f64),
                toml::Value::String(s) if s.eq_ignore_ascii_case("inf") => Ok(f64::INFINITY),
                _ => Err(format!("{name} must be a number")),
            }
        };
        match name.as_str() {
            "law" => match value.as_str() {
                Some("rolling") => rolling = true,
                Some("compliant") => rolling = false,
                _ => return Err("law must be \"rolling\" or \"compliant\"".into()),
            },
            "friction" => law.friction = number()?,
            "tangential_restitution" => law.tangential_restitution = number()?,
            "tangential_restitution_slope" => law.tangential_restitution_slope = number()?,
            "tangential_restitution_max" => law.tangential_restitution_max = number()?,
            "restitution_speed_slope_spm" => law.restitution_speed_slope_spm = number()?,
            other => {
                return Err(format!(
                    "unknown key '{other}' (keys: law, friction, tangential_restitution, \
                     tangential_restitution_slope, tangential_restitution_max, \
                     restitution_speed_slope_spm)"
                ));
            }
        }
    }
    if rolling {
        return Ok(ContactLaw::Rolling);
    }
    ContactLaw::Compliant(law)
        .validate()
        .map_err(|e| e.to_string())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_and_files() {
        assert_eq!(parse("rolling"), Ok(ContactLaw::Rolling));
        assert_eq!(parse("fitted"), Ok(FITTED_CONTACT));
        assert!(parse("sticky").is_err_and(|e| e.contains("unknown contact")));
        let Ok(ContactLaw::Compliant(c)) = from_toml("friction = 0.3\n") else {
            panic!("toml")
        };
        assert_eq!(c.friction, 0.3);
        assert_eq!(
            c.tangential_restitution,
            FITTED_COMPLIANT.tangential_restitution
        );
        assert_eq!(from_toml("law = \"rolling\""), Ok(ContactLaw::Rolling));
        assert!(from_toml("friction = -1").is_err_and(|e| e.contains("friction")));
        assert!(from_toml("mu = 1").is_err_and(|e| e.contains("unknown key")));
        assert_eq!(
            from_toml("tangential_restitution_max = 0.3").map(
                |l| matches!(l, ContactLaw::Compliant(c) if c.tangential_restitution_max == 0.3)
            ),
            Ok(true)
        );
        assert!(
            from_toml("tangential_restitution_max = 1.2").is_err_and(|e| e.contains("ceiling"))
        );
        assert!(from_toml("friction = ").is_err_and(|e| e.contains("TOML")));
        assert_eq!(
            from_toml("friction = \"inf\"")
                .map(|l| matches!(l, ContactLaw::Compliant(c) if c.friction.is_infinite())),
            Ok(true)
        );
    }
}
