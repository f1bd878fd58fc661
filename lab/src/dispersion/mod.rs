//! `carry dispersion`: Monte-Carlo over delivery noise.
//!
//! Shot `i` perturbs the base delivery by `sd_k · z_k` with seven independent standard
//! normal draws `z_k` (face angle, club path, attack angle, dynamic loft, club speed,
//! impact height, impact toe, always drawn in that order). The draws come from ChaCha8
//! (`rand_chacha`; Bernstein 2008, 8 rounds) keyed by the user's seed with the stream set
//! to the shot index, so every shot's noise depends only on `(seed, i)`: the result does
//! not depend on the thread count or the order the shots run in. Normal variates are
//! `rand_distr::StandardNormal` (the Ziggurat method). With every SD zero each shot is the
//! base delivery, bit for bit.
//!
//! Statistics (shots whose delivery fails, e.g. off the face, are counted and left out):
//! means, sample SDs and the 2×2 sample covariance (n − 1) of the landing point (X down
//! the target line, Z right); the 95 % ellipse of a bivariate normal with that covariance,
//! semi-axes `√(χ²₂(0.95)·λᵢ)` with `χ²₂(0.95) = −2 ln 0.05 = 5.991` and the major axis at
//! the angle of the first eigenvector; percentiles of carry and side (linear interpolation
//! between order statistics).

mod stats;
mod svg;

pub use stats::Percentiles;
pub use svg::draw;

use crate::error::{Error, Input, Result};
use crate::setup::Setup;
use carry_core::real::{lit, to_f64};
use carry_core::units::deg;
use carry_core::{Delivery, Real};
use rand::SeedableRng as _;
use rand_chacha::ChaCha8Rng;
use rand_distr::{Distribution as _, StandardNormal};
use rayon::prelude::*;
use serde::Serialize;

/// Standard deviations of the delivery noise. Angles in degrees, speed m/s, location m.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize)]
pub struct Noise {
    /// Face angle SD (deg).
    pub face_angle_deg: f64,
    /// Club path SD (deg).
    pub club_path_deg: f64,
    /// Attack angle SD (deg).
    pub attack_angle_deg: f64,
    /// Dynamic loft SD (deg).
    pub dynamic_loft_deg: f64,
    /// Club speed SD (m/s).
    pub club_speed_mps: f64,
    /// Impact height SD (m).
    pub impact_height_m: f64,
    /// Impact toe SD (m).
    pub impact_toe_m: f64,
}

impl Noise {
    /// The fields' names, in draw order (the CLI adds `-sd`).
    pub const FIELDS: [&'static str; 7] = [
        "face_angle",
        "club_path",
        "attack_angle",
        "dynamic_loft",
        "club_speed",
        "impact_height",
        "impact_toe",
    ];

    fn sds(&self) -> [f64; 7] {
        [
            self.face_angle_deg,
            self.club_path_deg,
            self.attack_angle_deg,
            self.dynamic_loft_deg,
            self.club_speed_mps,
            self.impact_height_m,
            self.impact_toe_m,
        ]
    }

    /// Checks every SD is finite and not negative.
    ///
    /// # Errors
    /// [`Error::Invalid`] naming the first bad SD.
    pub fn validate(&self) -> Result<()> {
        for (i, sd) in self.sds().iter().enumerate() {
            if !(sd.is_finite() && *sd >= 0.0) {
                return Err(Error::invalid(
                    Input::NoiseSd(i),
                    "must be a finite number, not negative",
                ));
            }
        }
        Ok(())
    }

    /// The delivery of shot `index` under this noise.
    #[must_use]
    pub fn perturb<T: Real>(&self, base: &Delivery<T>, seed: u64, index: u64) -> Delivery<T> {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        rng.set_stream(index);
        let sd = self.sds();
        let mut z = [0.0_f64; 7];
        for zk in &mut z {
            *zk = StandardNormal.sample(&mut rng);
        }
        let step = |k: usize| sd[k] * z[k];
        let mut d = *base;
        // Adding an exact zero keeps every field bit for bit when the SD is zero.
        d.face_angle_rad += deg(lit::<T>(step(0)));
        d.club_path_rad += deg(lit::<T>(step(1)));
        d.attack_angle_rad += deg(lit::<T>(step(2)));
        d.dynamic_loft_rad += deg(lit::<T>(step(3)));
        d.club_speed_mps += lit::<T>(step(4));
        d.location.height_m += lit::<T>(step(5));
        d.location.toe_m += lit::<T>(step(6));
        d
    }
}

/// The 95 % confidence ellipse of the landing point.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Ellipse {
    /// Centre (m): X down the target line, Z right.
    pub centre_m: [f64; 2],
    /// Semi-major axis (m).
    pub semi_major_m: f64,
    /// Semi-minor axis (m).
    pub semi_minor_m: f64,
    /// Angle of the major axis from +X towards +Z (deg).
    pub angle_deg: f64,
}

/// The Monte-Carlo's result.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Dispersion {
    /// Shots asked for.
    pub shots: usize,
    /// Shots whose delivery failed (left out of the statistics).
    pub failed_shots: usize,
    /// The seed.
    pub seed: u64,
    /// The noise.
    pub noise: Noise,
    /// Mean carry (m).
    pub carry_mean_m: f64,
    /// Carry SD (m).
    pub carry_sd_m: f64,
    /// Mean side (m, + right).
    pub side_mean_m: f64,
    /// Side SD (m).
    pub side_sd_m: f64,
    /// Mean landing point (m): X, Z.
    pub landing_mean_m: [f64; 2],
    /// Sample covariance of the landing point (m²): [[XX, XZ], [ZX, ZZ]].
    pub covariance_m2: [[f64; 2]; 2],
    /// The 95 % ellipse.
    pub ellipse_95: Ellipse,
    /// Carry percentiles (m).
    pub carry_percentiles_m: Percentiles,
    /// Side percentiles (m).
    pub side_percentiles_m: Percentiles,
    /// Landing points (m, X and Z) of the successful shots, in shot order (not in JSON).
    #[serde(skip)]
    pub landings_m: Vec<[f64; 2]>,
}

/// One shot: carry, landing X, landing Z.
type Landing = Option<[f64; 3]>;

fn shot<T: Real>(setup: &Setup<T>, noise: &Noise, seed: u64, i: u64) -> Landing {
    let d = noise.perturb(&setup.delivery, seed, i);
    setup.play(&d).ok().map(|out| {
        let f = &out.flight;
        [
            to_f64(f.carry_m),
            to_f64(f.landing_position_m.x),
            to_f64(f.landing_position_m.z),
        ]
    })
}

/// Shots per progress report.
const PROGRESS_BLOCK: usize = 1024;

/// Runs `shots` noisy shots around the setup's delivery, in parallel (rayon's pool);
/// `progress` (if any) is called with the number of shots just finished.
///
/// # Errors
/// [`Error::Invalid`] for a bad SD or fewer than 2 shots; [`Error::Core`] when fewer than
/// 2 shots succeed and the base delivery fails; [`Error::Invalid`] when fewer than 2
/// succeed otherwise.
pub fn simulate<T: Real>(
    setup: &Setup<T>,
    noise: &Noise,
    shots: usize,
    seed: u64,
    progress: Option<&(dyn Fn(usize) + Sync)>,
) -> Result<Dispersion> {
    noise.validate()?;
    if shots < 2 {
        return Err(Error::invalid(Input::Count, "need at least 2 shots"));
    }
    let blocks = shots.div_ceil(PROGRESS_BLOCK);
    let results: Vec<Landing> = (0..blocks)
        .into_par_iter()
        .flat_map_iter(|b| {
            let start = b * PROGRESS_BLOCK;
            let end = (start + PROGRESS_BLOCK).min(shots);
            let block: Vec<Landing> = (start..end)
                .map(|i| shot(setup, noise, seed, i as u64))
                .collect();
            if let Some(p) = progress {
                p(end - start);
            }
            block
        })
        .collect();
    let ok: Vec<[f64; 3]> = results.iter().flatten().copied().collect();
    if ok.len() < 2 {
        // The base delivery's own error says most; else the noise is too wide.
        setup.play_base()?;
        return Err(Error::invalid(
            Input::Count,
            format!("fewer than 2 of the {shots} noisy shots are valid: reduce the noise"),
        ));
    }
    Ok(stats::summarise(shots, seed, *noise, &ok))
}
