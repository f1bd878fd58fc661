//! Number formatting shared by the table and the conclusions.

use super::measure::Stat;

/// A number with 3 significant digits, scientific when very small or large.
pub fn sig(x: f64) -> String {
    if !x.is_finite() {
        return if x.is_nan() {
            "—".into()
        } else {
            "∞".into()
        };
    }
    if x == 0.0 {
        return "0".into();
    }
    let a = x.abs();
    if (0.01..10_000.0).contains(&a) {
        // Digits after the point for 3 significant digits.
        #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
        let d = (2 - a.log10().floor() as i32).max(0) as usize;
        format!("{x:.d$}")
    } else {
        sci(x)
    }
}

/// A number in scientific notation with 2 significant digits (`0` for zero).
pub fn sci(x: f64) -> String {
    if x == 0.0 {
        "0".into()
    } else {
        format!("{x:.1e}")
    }
}

/// Worst (median) of a statistic, scaled.
pub fn pair(s: &Stat, scale: f64) -> String {
    format!("{} ({})", sig(s.worst * scale), sig(s.median * scale))
}
