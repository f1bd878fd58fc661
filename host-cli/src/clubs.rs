//! `carry clubs`: the presets, their parameters, contact law and typical delivery.

use carry_core::impact::ContactLaw;
use carry_core::units::MPS_PER_MPH;
use carry_core::{PRESETS, Preset};
use serde_json::json;
use std::fmt::Write as _;

fn radius(r: f64) -> String {
    if r.is_finite() {
        format!("{r:.3}")
    } else {
        "flat".into()
    }
}

/// A contact law in one short phrase.
#[must_use]
pub fn contact_summary(law: &ContactLaw<f64>) -> String {
    match law {
        ContactLaw::Rolling => "rolling (seed)".into(),
        ContactLaw::Compliant(c) => format!(
            "compliant μ={} e_t=min({}{:+}·tanψ, {}) k_e={} s/m",
            c.friction,
            c.tangential_restitution,
            c.tangential_restitution_slope,
            c.tangential_restitution_max,
            c.restitution_speed_slope_spm
        ),
    }
}

fn aliases(p: &Preset) -> String {
    if p.aliases.is_empty() {
        String::new()
    } else {
        format!(" (also {})", p.aliases.join(", "))
    }
}

/// The presets as a table.
#[must_use]
pub fn table() -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "{:<8}{:>7}{:>6}{:>9}{:>9}{:>9}{:>7}{:>7}{:>14}{:>6}{:>8}{:>7}{:>6}",
        "club",
        "kg",
        "loft",
        "Ixx",
        "Iyy",
        "Izz",
        "roll",
        "bulge",
        "cg→face mm",
        "COR",
        "mph",
        "attack",
        "dloft"
    );
    for p in PRESETS {
        let [ixx, iyy, izz] = p.inertia_kgm2;
        let [cx, cy, cz] = p.cg_to_face_m.map(|x| x * 1e3);
        let t = &p.typical;
        let _ = writeln!(
            out,
            "{:<8}{:>7.3}{:>6.1}{:>9.2e}{:>9.2e}{:>9.2e}{:>7}{:>7}{:>14}{:>6.2}{:>8.0}{:>7.1}{:>6.1}",
            p.name,
            p.mass_kg,
            p.loft_deg,
            ixx,
            iyy,
            izz,
            radius(p.roll_radius_m),
            radius(p.bulge_radius_m),
            format!("{cx:.0},{cy:.0},{cz:.0}"),
            p.restitution,
            t.club_speed_mps / MPS_PER_MPH,
            t.attack_angle_deg,
            t.dynamic_loft_deg,
        );
    }
    out.push_str(
        "\ninertia kg·m² about the CoM (x downrange, y up, z toe); cg→face: CoM → face centre \
         (depth, height, toe); mph/attack/dloft: the typical tour delivery used when none is given\n\n",
    );
    for p in PRESETS {
        let _ = writeln!(out, "{:<8}{}{}", p.name, p.source, aliases(&p));
        let _ = writeln!(out, "{:<8}contact: {}", "", contact_summary(&p.contact));
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
            let contact = match p.contact {
                ContactLaw::Rolling => json!({"law": "rolling"}),
                ContactLaw::Compliant(c) => json!({
                    "law": "compliant",
                    "friction": finite(c.friction),
                    "tangential_restitution": c.tangential_restitution,
                    "tangential_restitution_slope": c.tangential_restitution_slope,
                    "tangential_restitution_max": c.tangential_restitution_max,
                    "restitution_speed_slope_spm": c.restitution_speed_slope_spm,
                }),
            };
            json!({
                "name": p.name,
                "aliases": p.aliases,
                "source": p.source,
                "mass_kg": p.mass_kg,
                "inertia_kgm2": p.inertia_kgm2,
                "loft_deg": p.loft_deg,
                "roll_radius_m": finite(p.roll_radius_m),
                "bulge_radius_m": finite(p.bulge_radius_m),
                "cg_to_face_m": p.cg_to_face_m,
                "restitution": p.restitution,
                "contact": contact,
                "typical_delivery": {
                    "club_speed_mps": p.typical.club_speed_mps,
                    "attack_angle_deg": p.typical.attack_angle_deg,
                    "dynamic_loft_deg": p.typical.dynamic_loft_deg,
                },
            })
        })
        .collect();
    let mut s = serde_json::to_string_pretty(&list).unwrap_or_default();
    s.push('\n');
    s
}
