//! Aerodynamic model files (TOML): what `carry fit --output` writes and `--aero FILE.toml`
//! reads.
//!
//! ```toml
//! family = "modern"            # or "quintavalla" (the seed's linear family)
//! cd_supercritical = 0.2       # coefficients by name; a missing one takes the value of
//! cd_lift = 0.5                # the family's built-in model (tour2023 / quintavalla)
//! ```
//!
//! One exception keeps the files of issue 10 meaning what they meant: a modern file that
//! names all seven coefficients of issue 10's form and neither `cl_low` nor
//! `cl_low_saturation_spin` has no low-spin lift (`cl_low = 0`).

use carry_core::aero::{AeroModel, BUILT_IN_MODELS, LINEAR_NAMES, LinearAero, MODERN_NAMES};
use std::fmt::Write as _;
use std::path::Path;

/// The coefficient names and values of `model`.
#[must_use]
pub fn coefficients(model: &AeroModel<f64>) -> Vec<(&'static str, f64)> {
    match model {
        AeroModel::Linear(c) => LINEAR_NAMES.into_iter().zip(c.to_array()).collect(),
        AeroModel::Modern(c) => MODERN_NAMES.into_iter().zip(c.to_array()).collect(),
    }
}

/// The model as a TOML document, after `comment` lines (each prefixed with `# `).
#[must_use]
pub fn to_toml(model: &AeroModel<f64>, comment: &str) -> String {
    let mut s = String::new();
    for line in comment.lines() {
        let _ = writeln!(s, "# {line}");
    }
    let _ = writeln!(s, "family = \"{}\"", model.family());
    for (name, value) in coefficients(model) {
        // `{:?}` prints the shortest representation that reads back exactly.
        let _ = writeln!(s, "{name} = {value:?}");
    }
    s
}

/// Parses a model file's text.
///
/// # Errors
/// A one-line message: not TOML, no or unknown `family`, an unknown key, a value that is
/// not a number, or coefficients the core rejects.
pub fn from_toml(text: &str) -> Result<AeroModel<f64>, String> {
    let table: toml::Table = text
        .parse()
        .map_err(|e: toml::de::Error| format!("not valid TOML: {}", e.message().trim()))?;
    let family = match table.get("family") {
        Some(toml::Value::String(f)) => f.as_str(),
        Some(_) => return Err("family: must be a string".into()),
        None => return Err("missing key 'family' (\"modern\" or \"quintavalla\")".into()),
    };
    let (names, mut values): (&[&str], Vec<f64>) = match family {
        "quintavalla" => (
            &LINEAR_NAMES,
            LinearAero::<f64>::quintavalla().to_array().to_vec(),
        ),
        "modern" => match AeroModel::<f64>::tour_2023() {
            AeroModel::Modern(m) => (&MODERN_NAMES, m.to_array().to_vec()),
            AeroModel::Linear(_) => return Err("internal: tour2023 is not modern".into()),
        },
        other => {
            return Err(format!(
                "family: unknown family '{other}' (modern, quintavalla)"
            ));
        }
    };
    for (key, value) in &table {
        if key == "family" {
            continue;
        }
        let i = names.iter().position(|n| n == key).ok_or_else(|| {
            format!(
                "unknown key '{key}' for family {family} (keys: family, {})",
                names.join(", ")
            )
        })?;
        #[allow(clippy::cast_precision_loss)]
        let x = match value {
            toml::Value::Float(x) => *x,
            toml::Value::Integer(n) => *n as f64,
            _ => return Err(format!("{key}: must be a number")),
        };
        values[i] = x;
    }
    if family == "modern"
        && names[..7].iter().all(|n| table.contains_key(*n))
        && !names[7..].iter().any(|n| table.contains_key(*n))
    {
        values[7] = 0.0; // an issue 10 file: no low-spin lift
    }
    let model = match family {
        "quintavalla" => AeroModel::Linear(LinearAero::from_array(to_array(&values)?)),
        _ => AeroModel::Modern(carry_core::aero::ModernAero::from_array(to_array(&values)?)),
    };
    model.validate().map_err(|e| match e {
        carry_core::Error::InvalidInput { field, reason } => format!("{field} {reason}"),
        other => other.to_string(),
    })
}

fn to_array<const N: usize>(v: &[f64]) -> Result<[f64; N], String> {
    v.try_into()
        .map_err(|_| "internal: wrong coefficient count".to_string())
}

/// A built-in model by name, or a model file by path.
///
/// # Errors
/// A one-line message: neither a built-in name nor a readable, valid file (naming it).
pub fn resolve(name_or_path: &str) -> Result<AeroModel<f64>, String> {
    if let Some(m) = AeroModel::named(name_or_path) {
        return Ok(m);
    }
    let path = Path::new(name_or_path);
    if !path.exists() {
        return Err(format!(
            "'{name_or_path}' is neither a built-in model ({}) nor a file",
            BUILT_IN_MODELS.join(", ")
        ));
    }
    let text = std::fs::read_to_string(path)
        .map_err(|e| format!("cannot read {}: {e}", path.display()))?;
    from_toml(&text).map_err(|e| format!("{}: {e}", path.display()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn round_trips_every_built_in_model_exactly() {
        for name in BUILT_IN_MODELS {
            let Some(m) = AeroModel::<f64>::named(name) else {
                panic!("{name}")
            };
            assert_eq!(from_toml(&to_toml(&m, "a comment\nover two lines")), Ok(m));
        }
    }

    #[test]
    fn names_what_is_wrong() {
        let err = |t: &str| from_toml(t).err().unwrap_or_default();
        assert!(err("family = \"modern\"\ncd_spn = 0.2").contains("unknown key 'cd_spn'"));
        assert!(err("cd0 = 0.2").contains("missing key 'family'"));
        assert!(err("family = \"smooth\"").contains("unknown family 'smooth'"));
        assert!(err("family = \"quintavalla\"\ncd0 = -1.0").contains("drag coefficient"));
        assert!(err("family = \"quintavalla\"\ncd0 = \"x\"").contains("cd0: must be a number"));
        assert!(err("family = ").contains("not valid TOML"));
        assert!(resolve("no-such-model").is_err());
        // A partial file takes the family's built-in values for the rest.
        let m = from_toml("family = \"quintavalla\"\ncd0 = 0.2");
        let q = LinearAero::<f64>::quintavalla();
        assert_eq!(m, Ok(AeroModel::Linear(LinearAero { cd0: 0.2, ..q })));
    }

    #[test]
    fn an_issue_10_file_keeps_its_model() {
        let old = "family = \"modern\"\ncd_supercritical = 0.1478\ncd_subcritical = 0.46\n\
                   reynolds_critical = 65810.0\ncl_max = 0.3232\ncl_saturation_spin = 0.5881\n\
                   cd_lift = 0.4745\ncm_spin = 0.0119\n";
        let Ok(AeroModel::Modern(m)) = from_toml(old) else {
            panic!("reads")
        };
        assert_eq!((m.cl_max, m.cl_low), (0.3232, 0.0));
        // Naming a low-spin key, or leaving an old key out, takes the built-in values.
        let Ok(AeroModel::Modern(n)) = from_toml(&format!("{old}cl_low_saturation_spin = 0.05\n"))
        else {
            panic!("reads")
        };
        assert!(n.cl_low > 0.0 && n.cl_low_saturation_spin == 0.05);
        let Ok(AeroModel::Modern(p)) = from_toml("family = \"modern\"\ncl_max = 0.3\n") else {
            panic!("reads")
        };
        assert!(p.cl_low > 0.0);
    }
}
