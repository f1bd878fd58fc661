//! The club–ball impact of Petersen and McPhee: rigid bodies, instantaneous impulse,
//! normal restitution and rolling without slipping on the face (gear effect).
//!
//! Unknowns: club `V_c, Ω_c`, ball `V_b, Ω_b` after impact and the impulse `P` on the
//! ball (the club receives `−P`). Lower case = before impact.
//!
//! ```text
//! m_c (V_c − v_c) = −P                 I_c (Ω_c − ω_c) = r_imp  × (−P)
//! m_b (V_b − v_b) =  P                 I_b (Ω_b − ω_b) = r_ball ×   P
//! n · u = −e (n · u⁰)                  t_i · u = 0   (i = 1, 2)
//! ```
//! with `u = (V_b + Ω_b × r_ball) − (V_c + Ω_c × r_imp)` the relative velocity of the
//! contact points. Two solvers give the same solution: [`Solver::Full`] assembles and
//! eliminates the 15×15 system ([`full`]); [`Solver::Reduced`] solves the 3×3
//! collision-matrix form `K P = −u⁰ − e (n·u⁰) n` ([`reduced`]).
//!
//! The contact conditions above are the seed's law, [`ContactLaw::Rolling`]. The club may
//! hold [`ContactLaw::Compliant`] instead ([`contact_law`]: Coulomb friction cone,
//! tangential restitution, speed-dependent COR, energy never increases), which the reduced
//! solver computes from the same `K`; the full solver supports only the seed's law.
//!
//! Source: N. Petersen & J. McPhee, "Shape optimization of golf clubface using finite
//! element impact models", Sports Engineering 12 (2009); the impulse–momentum model of
//! their three-dimensional club–ball impact.

pub use crate::contact_law;
pub mod axis_share;
pub mod full;
pub mod reduced;

pub use contact_law::{CompliantContact, ContactLaw, Regime};

use crate::ball::{Ball, BallMotion};
use crate::club::ClubHead;
use crate::contact::Contact;
use crate::delivery::{ClubMotion, Strike};
use crate::error::{Error, Field, Reason, Result};
use crate::launch::LaunchMetrics;
use crate::linalg::Pivoting;
use crate::real::Real;
use nalgebra::Vector3;

/// Which formulation solves the impact.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum Solver {
    /// The exact 3×3 collision-matrix form (fast; the default).
    #[default]
    Reduced,
    /// The full 15×15 system by Gaussian elimination with the given pivoting.
    Full(Pivoting),
}

impl Solver {
    /// The full solver with its default (row-equilibrated partial) pivoting.
    pub const FULL: Self = Self::Full(Pivoting::Equilibrated);
}

/// Everything an impact solve needs, validated and expressed in G.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Problem<T: Real> {
    /// Club mass (kg).
    pub club_mass_kg: T,
    /// Ball mass (kg).
    pub ball_mass_kg: T,
    /// Ball moment of inertia (kg·m²).
    pub ball_inertia_kgm2: T,
    /// Coefficient of restitution (the club's rating; the compliant law varies it with
    /// the normal speed).
    pub restitution: T,
    /// Contact geometry.
    pub contact: Contact<T>,
    /// Club motion before impact.
    pub club: ClubMotion<T>,
    /// Ball motion before impact.
    pub ball: BallMotion<T>,
    /// Relative contact-point velocity before impact, u⁰ = u_b⁰ − u_c⁰ (m/s).
    pub approach_mps: Vector3<T>,
}

/// Post-impact velocities of both bodies (the solvers' common output).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PostImpact<T: Real> {
    /// Club CoM velocity V_c (m/s).
    pub club_velocity_mps: Vector3<T>,
    /// Club angular velocity Ω_c (rad/s).
    pub club_spin_radps: Vector3<T>,
    /// Ball velocity V_b (m/s).
    pub ball_velocity_mps: Vector3<T>,
    /// Ball angular velocity Ω_b (rad/s).
    pub ball_spin_radps: Vector3<T>,
    /// Impulse on the ball P (N·s).
    pub impulse_ns: Vector3<T>,
}

/// The result of an impact.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct ImpactOutcome<T: Real> {
    /// Ball velocity and spin after impact (G).
    pub ball: BallMotion<T>,
    /// Club velocity and spin after impact (G); orientation unchanged (instantaneous impact).
    pub club: ClubMotion<T>,
    /// Impulse on the ball P (N·s, G); the club receives −P.
    pub impulse_ns: Vector3<T>,
    /// Contact geometry (normal, lever arms).
    pub contact: Contact<T>,
    /// Launch metrics of the ball.
    pub launch: LaunchMetrics<T>,
}

impl<T: Real> Problem<T> {
    /// Assembles the problem; checks that the club approaches the ball.
    ///
    /// # Errors
    /// [`Error::OffFace`] for an impact point off the face, [`Error::NoApproach`] when
    /// `n·u⁰ ≥ 0`.
    pub fn new(club: &ClubHead<T>, ball: &Ball<T>, strike: &Strike<T>) -> Result<Self> {
        let contact = Contact::new(club, ball, strike)?;
        let c = strike.club();
        let b = strike.ball();
        let u_ball = b.velocity_mps + b.spin_radps.cross(&contact.ball_lever_m);
        let u_club = c.velocity_mps + c.spin_radps.cross(&contact.club_lever_m);
        let approach = u_ball - u_club;
        let closing = contact.normal.dot(&approach);
        if !(closing < T::zero()) {
            return Err(Error::NoApproach);
        }
        Ok(Self {
            club_mass_kg: club.mass_kg(),
            ball_mass_kg: ball.mass_kg(),
            ball_inertia_kgm2: ball.inertia_kgm2(),
            restitution: club.restitution(),
            contact,
            club: *c,
            ball: *b,
            approach_mps: approach,
        })
    }

    /// The seed's (rolling) target relative contact velocity after impact, `−e (n·u⁰) n`.
    #[must_use]
    pub fn target_velocity_mps(&self) -> Vector3<T> {
        let n = &self.contact.normal;
        n * (-self.restitution * n.dot(&self.approach_mps))
    }

    /// Post-impact motion from the impulse `p` on the ball (momentum balances).
    #[must_use]
    #[inline(always)]
    pub fn apply_impulse(&self, p: &Vector3<T>) -> PostImpact<T> {
        let k = &self.contact;
        PostImpact {
            club_velocity_mps: self.club.velocity_mps - p / self.club_mass_kg,
            club_spin_radps: self.club.spin_radps
                - k.club_inverse_inertia * k.club_lever_m.cross(p),
            ball_velocity_mps: self.ball.velocity_mps + p / self.ball_mass_kg,
            ball_spin_radps: self.ball.spin_radps
                + k.ball_lever_m.cross(p) / self.ball_inertia_kgm2,
            impulse_ns: *p,
        }
    }
}

/// Solves the impact of `strike` between `club` and `ball` with `solver`; with a club's
/// empirical spin-axis share other than 1 the ball's spin axis is then scaled
/// ([`axis_share`]).
///
/// # Errors
/// [`Error::OffFace`], [`Error::NoApproach`], or [`Error::Singular`] when the system is too
/// ill-conditioned for the precision; [`Error::InvalidInput`] (`ContactLaw`,
/// `UnsupportedBySolver`) for the full solver with a contact law other than the seed's.
pub fn solve<T: Real>(
    club: &ClubHead<T>,
    ball: &Ball<T>,
    strike: &Strike<T>,
    solver: Solver,
) -> Result<ImpactOutcome<T>> {
    // The share's path is its own (cold, out of line): the physics' path is the code it
    // was, with one comparison before it (docs/firmware.md: M4F cost; the micro:bit's f64
    // estimate stacks this frame deep).
    #[allow(clippy::float_cmp)]
    if club.spin_axis_share() != T::one() {
        return solve_with_axis_share(club, ball, strike, solver);
    }
    let problem = Problem::new(club, ball, strike)?;
    // the seed's path is the seed's code: a law it does not use costs it nothing
    let post = match (solver, club.contact_law()) {
        (Solver::Reduced, ContactLaw::Rolling) => reduced::solve(&problem)?,
        (Solver::Reduced, ContactLaw::Compliant(law)) => reduced::solve_compliant(&problem, law)?,
        (Solver::Full(pivoting), ContactLaw::Rolling) => full::solve(&problem, pivoting)?,
        (Solver::Full(_), ContactLaw::Compliant(_)) => {
            return Err(Error::invalid(
                Field::ContactLaw,
                Reason::UnsupportedBySolver,
            ));
        }
    };
    let ball_after = BallMotion {
        velocity_mps: post.ball_velocity_mps,
        spin_radps: post.ball_spin_radps,
    };
    let finite = |v: &Vector3<T>| v.iter().all(|x| x.is_finite());
    if !(finite(&post.club_velocity_mps)
        && finite(&post.club_spin_radps)
        && finite(&post.ball_velocity_mps)
        && finite(&post.ball_spin_radps)
        && finite(&post.impulse_ns))
    {
        return Err(Error::Singular);
    }
    let launch = LaunchMetrics::from_motion(&ball_after, strike.club_speed_mps());
    // Finite components can still overflow a norm (inputs near the precision's largest
    // value; found by fuzzing, issue 7): out of range for the precision, never ±∞ out.
    if !(launch.ball_speed_mps.is_finite()
        && launch.spin_radps.is_finite()
        && launch.smash_factor.is_finite())
    {
        return Err(Error::Singular);
    }
    Ok(ImpactOutcome {
        ball: ball_after,
        club: ClubMotion {
            velocity_mps: post.club_velocity_mps,
            spin_radps: post.club_spin_radps,
            orientation: strike.club().orientation,
        },
        impulse_ns: post.impulse_ns,
        contact: problem.contact,
        launch,
    })
}

/// [`solve`] for a club with an empirical spin-axis share: the physics' impact (the same
/// club with the share 1), then the ball's spin axis scaled ([`axis_share::apply`]) and its
/// launch metrics recomputed.
#[cold]
#[inline(never)]
fn solve_with_axis_share<T: Real>(
    club: &ClubHead<T>,
    ball: &Ball<T>,
    strike: &Strike<T>,
    solver: Solver,
) -> Result<ImpactOutcome<T>> {
    let mut out = solve(&club.with_physics_axis(), ball, strike, solver)?;
    axis_share::apply(
        club.spin_axis_share(),
        &out.ball.velocity_mps,
        &mut out.ball.spin_radps,
    );
    out.launch = LaunchMetrics::from_motion(&out.ball, strike.club_speed_mps());
    if !out.launch.spin_radps.is_finite() {
        return Err(Error::Singular);
    }
    Ok(out)
}
