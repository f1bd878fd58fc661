//! Club heads and balls: presets by name or index, custom clubs as a plain struct.

use crate::error::{CARRY_ERR_UNKNOWN_NAME, CARRY_ERR_UNKNOWN_OPTION, Result};
use carry_core::impact::{CompliantContact, ContactLaw};
use carry_core::presets::{PRESETS, Preset};
use carry_core::real::{Real, lit};
use carry_core::{Ball, ClubSpec};
use core::ffi::{CStr, c_char};
use nalgebra::{Matrix3, Vector3};

/// `CarryClub::contact`: the seed's rigid contact (rolling without slipping; what
/// PHYSICS.md's reference numbers and the golden files use).
pub const CARRY_CONTACT_ROLLING: u32 = 0;
/// `CarryClub::contact`: the calibrated friction-limited compliant contact (the presets'
/// and the CLI's default), with the `friction`… parameters of the struct.
pub const CARRY_CONTACT_COMPLIANT: u32 = 1;

/// A club head (SI units, angles in radians; frames of PHYSICS.md). Start from
/// `carry_club_default_*` or a preset (`carry_club_preset_*`), then change fields.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CarryClub<T> {
    /// Head mass (kg).
    pub mass_kg: T,
    /// Inertia tensor about the CoM in the club frame, row-major (kg·m²): symmetric
    /// positive definite.
    pub inertia_kgm2: [T; 9],
    /// Static loft (rad).
    pub loft_rad: T,
    /// Roll radius, curvature up the face (m); `INFINITY` for a flat face.
    pub roll_radius_m: T,
    /// Bulge radius, curvature across the face (m); `INFINITY` for a flat face.
    pub bulge_radius_m: T,
    /// Face depth radius (m); 0 for the core's default (the bulge radius when finite,
    /// else the roll radius, else flat).
    pub face_depth_radius_m: T,
    /// CoM → face centre in the face frame (m): depth, height, toe.
    pub cg_to_face_m: [T; 3],
    /// Coefficient of restitution, in [0, 1].
    pub restitution: T,
    /// `CARRY_CONTACT_ROLLING` or `CARRY_CONTACT_COMPLIANT`.
    pub contact: u32,
    /// Compliant contact: Coulomb friction coefficient (≥ 0; `INFINITY` never slides).
    pub friction: T,
    /// Compliant contact: tangential restitution at normal incidence, in [−1, 1].
    pub tangential_restitution: T,
    /// Compliant contact: change of the tangential restitution per unit tan(obliquity).
    pub tangential_restitution_slope: T,
    /// Compliant contact: fall of the normal restitution per m/s of normal speed (s/m).
    pub restitution_speed_slope_spm: T,
    /// Compliant contact: ceiling of the tangential restitution, in [0, 1] (1: none).
    pub tangential_restitution_max: T,
    /// The empirical D-plane share of the spin axis, in (0, 1]: `tan a' = k tan a`
    /// (docs/impact.md §0.8); 1 (the presets' and defaults') is the impact's own axis.
    pub spin_axis_share: T,
}

/// A ball (SI units).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CarryBall<T> {
    /// Mass (kg).
    pub mass_kg: T,
    /// Radius (m).
    pub radius_m: T,
}

/// The presets' names as C strings, in `carry_core::PRESETS` order.
pub const PRESET_NAMES: [&CStr; 13] = [
    c"driver", c"3wood", c"hybrid", c"4iron", c"5iron", c"6iron", c"7iron", c"8iron", c"9iron",
    c"pw", c"gw", c"sw", c"lw",
];

impl<T: Real> CarryClub<T> {
    /// The C form of a core club.
    #[must_use]
    pub fn from_spec(s: &ClubSpec<T>) -> Self {
        let i = &s.inertia_kgm2;
        let (contact, c) = match s.contact {
            ContactLaw::Rolling => (CARRY_CONTACT_ROLLING, compliant_off()),
            ContactLaw::Compliant(c) => (CARRY_CONTACT_COMPLIANT, c),
        };
        Self {
            mass_kg: s.mass_kg,
            inertia_kgm2: [
                i.m11, i.m12, i.m13, i.m21, i.m22, i.m23, i.m31, i.m32, i.m33,
            ],
            loft_rad: s.loft_rad,
            roll_radius_m: s.roll_radius_m,
            bulge_radius_m: s.bulge_radius_m,
            face_depth_radius_m: s.face_depth_radius_m.unwrap_or_else(T::zero),
            cg_to_face_m: s.cg_to_face_m.into(),
            restitution: s.restitution,
            contact,
            friction: c.friction,
            tangential_restitution: c.tangential_restitution,
            tangential_restitution_slope: c.tangential_restitution_slope,
            restitution_speed_slope_spm: c.restitution_speed_slope_spm,
            tangential_restitution_max: c.tangential_restitution_max,
            spin_axis_share: s.spin_axis_share,
        }
    }

    /// The core club (not yet validated: the core does that).
    ///
    /// # Errors
    /// `CARRY_ERR_UNKNOWN_OPTION` for an unknown `contact`.
    pub fn spec(&self) -> Result<ClubSpec<T>> {
        let [a, b, c, d, e, f, g, h, k] = self.inertia_kgm2;
        let contact = match self.contact {
            CARRY_CONTACT_ROLLING => ContactLaw::Rolling,
            CARRY_CONTACT_COMPLIANT => ContactLaw::Compliant(CompliantContact {
                friction: self.friction,
                tangential_restitution: self.tangential_restitution,
                tangential_restitution_slope: self.tangential_restitution_slope,
                tangential_restitution_max: self.tangential_restitution_max,
                restitution_speed_slope_spm: self.restitution_speed_slope_spm,
            }),
            _ => return Err(CARRY_ERR_UNKNOWN_OPTION),
        };
        Ok(ClubSpec {
            mass_kg: self.mass_kg,
            inertia_kgm2: Matrix3::new(a, b, c, d, e, f, g, h, k),
            loft_rad: self.loft_rad,
            roll_radius_m: self.roll_radius_m,
            bulge_radius_m: self.bulge_radius_m,
            face_depth_radius_m: (self.face_depth_radius_m != T::zero())
                .then_some(self.face_depth_radius_m),
            cg_to_face_m: Vector3::from(self.cg_to_face_m),
            restitution: self.restitution,
            contact,
            spin_axis_share: self.spin_axis_share,
        })
    }
}

/// The calibrated compliant parameters, stored even in a rolling club so that switching
/// `contact` to compliant gives the presets' law.
fn compliant_off<T: Real>() -> CompliantContact<T> {
    carry_core::presets::FITTED_COMPLIANT.cast()
}

impl<T: Real> CarryBall<T> {
    /// The standard ball (PHYSICS.md).
    #[must_use]
    pub fn standard() -> Self {
        Self {
            mass_kg: lit(Ball::<T>::STANDARD_MASS_KG),
            radius_m: lit(Ball::<T>::STANDARD_RADIUS_M),
        }
    }

    /// The validated core ball.
    ///
    /// # Errors
    /// The core's `InvalidInput`.
    pub fn ball(&self) -> Result<Ball<T>> {
        Ok(Ball::new(self.mass_kg, self.radius_m)?)
    }
}

/// The preset at `index`.
///
/// # Errors
/// `CARRY_ERR_UNKNOWN_NAME` past the last preset.
pub fn preset_at(index: u32) -> Result<&'static Preset> {
    PRESETS
        .get(usize::try_from(index).map_err(|_| CARRY_ERR_UNKNOWN_NAME)?)
        .ok_or(CARRY_ERR_UNKNOWN_NAME)
}

/// The preset named `name` (a NUL-terminated string; names and aliases as the CLI's
/// `--club`).
///
/// # Safety
/// `name` is NULL or a NUL-terminated string.
///
/// # Errors
/// `CARRY_ERR_NULL_POINTER`, `CARRY_ERR_UNKNOWN_NAME`.
pub unsafe fn preset_named(name: *const c_char) -> Result<&'static Preset> {
    if name.is_null() {
        return Err(crate::error::CARRY_ERR_NULL_POINTER);
    }
    // SAFETY: not NULL and NUL-terminated by the caller's contract.
    let name = unsafe { CStr::from_ptr(name) };
    let name = name.to_str().map_err(|_| CARRY_ERR_UNKNOWN_NAME)?;
    Preset::find(name).ok_or(CARRY_ERR_UNKNOWN_NAME)
}

/// The club of the CLI's default (PHYSICS.md's reference driver head, calibrated compliant
/// contact: `carry_core::presets::REFERENCE_DRIVER`).
#[must_use]
pub fn default_club<T: Real>() -> CarryClub<T> {
    CarryClub::from_spec(&carry_core::presets::REFERENCE_DRIVER.spec())
}
