//! Options that take one of a few names (`--units si|imperial`, `--precision f32|f64`, …),
//! parsed without a command-line library: the Python package and the scene files read them
//! by the names the CLI shows.

use crate::compute::{IntegratorChoice, PosteriorChoice, Precision, SolverChoice};
use crate::units::Units;

/// An option value that is one of a few names.
pub trait Choice: Copy + 'static {
    /// The names and their values, as the CLI spells them.
    const CHOICES: &'static [(&'static str, Self)];

    /// The value named `text` (case-insensitive, surrounding blanks ignored).
    ///
    /// # Errors
    /// `invalid value 'x' (one of: a, b)`.
    fn parse(text: &str) -> Result<Self, String> {
        let t = text.trim();
        Self::CHOICES
            .iter()
            .find(|(n, _)| n.eq_ignore_ascii_case(t))
            .map(|(_, v)| *v)
            .ok_or_else(|| {
                let names: Vec<&str> = Self::CHOICES.iter().map(|(n, _)| *n).collect();
                format!("invalid value '{text}' (one of: {})", names.join(", "))
            })
    }
}

impl Choice for Units {
    const CHOICES: &'static [(&'static str, Self)] =
        &[("si", Self::Si), ("imperial", Self::Imperial)];
}

impl Choice for Precision {
    const CHOICES: &'static [(&'static str, Self)] = &[("f32", Self::F32), ("f64", Self::F64)];
}

impl Choice for SolverChoice {
    const CHOICES: &'static [(&'static str, Self)] =
        &[("reduced", Self::Reduced), ("full", Self::Full)];
}

impl Choice for PosteriorChoice {
    const CHOICES: &'static [(&'static str, Self)] =
        &[("profile", Self::Profile), ("laplace", Self::Laplace)];
}

impl Choice for IntegratorChoice {
    const CHOICES: &'static [(&'static str, Self)] = &[
        ("euler", Self::Euler),
        ("rk4", Self::Rk4),
        ("dp45", Self::Dp45),
    ];
}

#[cfg(all(test, feature = "clap"))]
mod tests {
    use super::*;
    use clap::ValueEnum;

    fn same<T: Choice + ValueEnum + PartialEq + std::fmt::Debug>() {
        let clap: Vec<String> = T::value_variants()
            .iter()
            .filter_map(|v| v.to_possible_value().map(|p| p.get_name().to_owned()))
            .collect();
        let ours: Vec<&str> = T::CHOICES.iter().map(|(n, _)| *n).collect();
        assert_eq!(clap, ours);
        for (n, v) in T::CHOICES {
            assert_eq!(T::from_str(n, true).ok(), Some(*v));
        }
    }

    /// The names are the CLI's, value for value.
    #[test]
    fn the_names_are_the_clis() {
        same::<Units>();
        same::<Precision>();
        same::<SolverChoice>();
        same::<IntegratorChoice>();
        same::<PosteriorChoice>();
    }
}
