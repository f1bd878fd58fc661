//! Random impact scenarios for property tests, held in f64 and built in any precision.

use carry_core::real::lit;
use carry_core::units::deg;
use carry_core::{
    Ball, ClubHead, ClubSpec, ContactLaw, Delivery, FaceLocation, PRESETS, Real, Strike,
};
use nalgebra::{Matrix3, Vector3};
use proptest::prelude::*;

/// One impact scenario in launch-monitor terms (degrees, SI otherwise).
#[allow(missing_docs)]
#[derive(Debug, Clone, Copy)]
pub struct Scenario {
    pub club_mass_kg: f64,
    pub inertia_diag: [f64; 3],
    /// Products of inertia as fractions of the smallest principal moment.
    pub products_frac: [f64; 3],
    pub loft_deg: f64,
    pub roll_radius_m: f64,
    pub bulge_radius_m: f64,
    pub cg_to_face_m: [f64; 3],
    pub restitution: f64,
    pub club_speed_mps: f64,
    pub attack_deg: f64,
    pub path_deg: f64,
    pub face_deg: f64,
    pub dynamic_loft_offset_deg: f64,
    pub lie_deg: f64,
    pub club_spin_radps: [f64; 3],
    pub height_m: f64,
    pub toe_m: f64,
    /// The contact law (the seed's rolling one unless a test asks otherwise).
    pub contact: ContactLaw<f64>,
}

impl Scenario {
    /// Club parameters in precision `T`.
    #[must_use]
    pub fn club_spec<T: Real>(&self) -> ClubSpec<T> {
        let [a, b, c] = self.inertia_diag;
        let s = a.min(b).min(c);
        let [pxy, pxz, pyz] = self.products_frac.map(|f| f * s);
        let i = Matrix3::new(a, pxy, pxz, pxy, b, pyz, pxz, pyz, c);
        let cg = self.cg_to_face_m;
        ClubSpec {
            mass_kg: lit(self.club_mass_kg),
            inertia_kgm2: i.map(lit),
            loft_rad: deg(lit(self.loft_deg)),
            roll_radius_m: lit(self.roll_radius_m),
            bulge_radius_m: lit(self.bulge_radius_m),
            face_depth_radius_m: None,
            cg_to_face_m: Vector3::new(lit(cg[0]), lit(cg[1]), lit(cg[2])),
            restitution: lit(self.restitution),
            contact: self.contact.cast(),
            spin_axis_share: T::one(),
        }
    }

    /// Delivery in precision `T`.
    #[must_use]
    pub fn delivery<T: Real>(&self) -> Delivery<T> {
        let w = self.club_spin_radps;
        Delivery {
            club_speed_mps: lit(self.club_speed_mps),
            attack_angle_rad: deg(lit(self.attack_deg)),
            club_path_rad: deg(lit(self.path_deg)),
            face_angle_rad: deg(lit(self.face_deg)),
            dynamic_loft_rad: deg(lit(self.loft_deg + self.dynamic_loft_offset_deg)),
            lie_rad: deg(lit(self.lie_deg)),
            club_spin_radps: Vector3::new(lit(w[0]), lit(w[1]), lit(w[2])),
            location: FaceLocation {
                height_m: lit(self.height_m),
                toe_m: lit(self.toe_m),
            },
        }
    }

    /// Validated club, standard ball and strike.
    ///
    /// # Errors
    /// When the scenario is invalid for the precision.
    pub fn build<T: Real>(&self) -> carry_core::Result<(ClubHead<T>, Ball<T>, Strike<T>)> {
        let club = self.club_spec::<T>().validate()?;
        let strike = self.delivery::<T>().strike(&club)?;
        Ok((club, Ball::standard(), strike))
    }

    /// The mirror image through the vertical plane of the target line (Z → −Z).
    #[must_use]
    pub fn mirrored(&self) -> Self {
        let mut m = *self;
        // Ixy keeps its sign; Ixz and Iyz flip.
        m.products_frac = [
            self.products_frac[0],
            -self.products_frac[1],
            -self.products_frac[2],
        ];
        m.cg_to_face_m[2] = -self.cg_to_face_m[2];
        m.path_deg = -self.path_deg;
        m.face_deg = -self.face_deg;
        m.lie_deg = -self.lie_deg;
        m.club_spin_radps = [
            -self.club_spin_radps[0],
            -self.club_spin_radps[1],
            self.club_spin_radps[2],
        ];
        m.toe_m = -self.toe_m;
        m
    }
}

/// Any valid scenario: every club from wedge to driver, any delivery a golfer produces.
pub fn scenario() -> impl Strategy<Value = Scenario> {
    let club = (
        0.15..0.35_f64,
        [5e-5..6e-4_f64, 5e-5..6e-4_f64, 5e-5..6e-4_f64],
        [-0.2..0.2_f64, -0.2..0.2_f64, -0.2..0.2_f64],
        0.0..60.0_f64,
        prop_oneof![0.2..0.5_f64, Just(f64::INFINITY)],
        prop_oneof![0.2..0.5_f64, Just(f64::INFINITY)],
        [0.0..0.045_f64, -0.005..0.005_f64, -0.005..0.005_f64],
        0.0..=1.0_f64,
    );
    let delivery = (
        2.0..60.0_f64,
        -8.0..8.0_f64,
        -10.0..10.0_f64,
        -10.0..10.0_f64,
        -6.0..6.0_f64,
        -8.0..8.0_f64,
        [-30.0..30.0_f64, -30.0..30.0_f64, -30.0..30.0_f64],
        -0.02..0.02_f64,
        -0.03..0.03_f64,
    );
    (club, delivery).prop_map(|(c, d)| Scenario {
        club_mass_kg: c.0,
        inertia_diag: c.1,
        products_frac: c.2,
        loft_deg: c.3,
        roll_radius_m: c.4,
        bulge_radius_m: c.5,
        cg_to_face_m: c.6,
        restitution: c.7,
        club_speed_mps: d.0,
        attack_deg: d.1,
        path_deg: d.2,
        face_deg: d.3,
        dynamic_loft_offset_deg: d.4,
        lie_deg: d.5,
        club_spin_radps: d.6,
        height_m: d.7,
        toe_m: d.8,
        contact: ContactLaw::Rolling,
    })
}

/// A scenario with one of the built-in preset clubs (restitution up to the preset's) and any
/// delivery a golfer produces: the realistic part of the domain.
pub fn preset_scenario() -> impl Strategy<Value = Scenario> {
    (0..PRESETS.len(), 0.0..=1.0_f64, scenario()).prop_map(|(i, e_frac, s)| {
        let p = &PRESETS[i];
        Scenario {
            club_mass_kg: p.mass_kg,
            inertia_diag: p.inertia_kgm2,
            products_frac: [0.0; 3],
            loft_deg: p.loft_deg,
            roll_radius_m: p.roll_radius_m,
            bulge_radius_m: p.bulge_radius_m,
            cg_to_face_m: p.cg_to_face_m,
            restitution: p.restitution * e_frac,
            ..s
        }
    })
}

/// Any valid compliant contact law, with the limits weighted in: μ = 0, μ = ∞, e_t at its
/// clamps, steep obliquity slopes, steep restitution speed slopes.
pub fn compliant_law() -> impl Strategy<Value = carry_core::impact::CompliantContact<f64>> {
    (
        prop_oneof![Just(0.0), Just(f64::INFINITY), 0.0..2.0_f64],
        prop_oneof![Just(-1.0), Just(0.0), Just(1.0), -1.0..=1.0_f64],
        prop_oneof![Just(0.0), -3.0..3.0_f64],
        prop_oneof![Just(0.0), 0.0..0.03_f64],
        prop_oneof![Just(1.0), Just(0.0), 0.0..=1.0_f64],
    )
        .prop_map(|(mu, e0, s, k, cap)| carry_core::impact::CompliantContact {
            friction: mu,
            tangential_restitution: e0,
            tangential_restitution_slope: s,
            tangential_restitution_max: cap,
            restitution_speed_slope_spm: k,
        })
}

/// [`scenario`] with a [`compliant_law`].
pub fn compliant_scenario() -> impl Strategy<Value = Scenario> {
    (scenario(), compliant_law()).prop_map(|(s, law)| Scenario {
        contact: ContactLaw::Compliant(law),
        ..s
    })
}
