//! The impact golden cases (`tests/golden/impact.json`, read by `carry-golden`, the one
//! golden-file reader, which also turns them into the core's types).

pub use carry_golden::{ImpactCase, ImpactExpected};

/// All impact cases.
///
/// # Panics
/// When the golden file does not match its schema (a broken checkout).
#[must_use]
pub fn impact_cases() -> Vec<ImpactCase> {
    carry_golden::impact_cases().unwrap_or_else(|e| panic!("{e}"))
}

/// Maps a core error to the golden file's error names.
#[must_use]
pub fn error_name(e: &carry_core::Error) -> &'static str {
    match e {
        carry_core::Error::InvalidInput { .. } => "invalid_input",
        carry_core::Error::OffFace => "off_face",
        carry_core::Error::NoApproach => "no_approach",
        carry_core::Error::Singular => "singular",
        _ => "other",
    }
}
