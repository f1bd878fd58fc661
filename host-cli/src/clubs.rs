//! `carry clubs`: the presets and their parameters.

use carry_core::PRESETS;
use serde_json::json;
use std::fmt::Write as _;

fn radius(r: f64) -> String {
    if r.is_finite() {
        format!("{r:.3}")
    } else {
        "flat".into()
    }
}

/// The presets as a table.
#[must_use]
pub fn table() -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "{:<8}{:>9}{:>10}{:>10}{:>10}{:>10}{:>8}{:>9}{:>11}{:>6}",
        "club",
        "mass kg",
        "loft deg",
        "Ixx kgm2",
        "Iyy kgm2",
        "Izz kgm2",
        "roll m",
        "bulge m",
        "cg-face m",
        "COR"
    );
    for p in PRESETS {
        let [ixx, iyy, izz] = p.inertia_kgm2;
        let _ = writeln!(
            out,
            "{:<8}{:>9.3}{:>10.1}{:>10.2e}{:>10.2e}{:>10.2e}{:>8}{:>9}{:>11.3}{:>6.2}",
            p.name,
            p.mass_kg,
            p.loft_deg,
            ixx,
            iyy,
            izz,
            radius(p.roll_radius_m),
            radius(p.bulge_radius_m),
            p.cg_to_face_m,
            p.restitution
        );
    }
    out.push('\n');
    for p in PRESETS {
        let _ = writeln!(out, "{:<8}{}", p.name, p.source);
    }
    out
}

/// The presets as JSON (an array; flat radii are `null`).
#[must_use]
pub fn json() -> String {
    let finite = |x: f64| {
        if x.is_finite() {
            json!(x)
        } else {
            serde_json::Value::Null
        }
    };
    let list: Vec<_> = PRESETS
        .iter()
        .map(|p| {
            json!({
                "name": p.name,
                "source": p.source,
                "mass_kg": p.mass_kg,
                "inertia_kgm2": p.inertia_kgm2,
                "loft_deg": p.loft_deg,
                "roll_radius_m": finite(p.roll_radius_m),
                "bulge_radius_m": finite(p.bulge_radius_m),
                "cg_to_face_m": [p.cg_to_face_m, 0.0, 0.0],
                "restitution": p.restitution,
            })
        })
        .collect();
    let mut s = serde_json::to_string_pretty(&list).unwrap_or_default();
    s.push('\n');
    s
}
