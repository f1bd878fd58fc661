//! The physics runs: options ([`Params`]) → core types in precision `T` → core → a
//! [`Report`] in `f64`. The same generic code serves `--precision f32` and `f64`.

use crate::error::InputError;
use crate::params::{ClubParams, DEFAULT_BACKSPIN_RPM, LaunchParams, Params};
use crate::report::{
    ClubAfter, FlightReport, GroundReport, LaunchFigures, LaunchReport, Report, f3,
};
use carry_core::flight::{Integrator, Recorder, Sample};
use carry_core::impact::{self, Solver};
use carry_core::lanes::{LaneReal, Shot};
use carry_core::real::{lit, to_f64};
use carry_core::units::{deg, rpm, to_deg, to_rpm};
use carry_core::{
    Ball, BallMotion, ClubHead, ClubSpec, Delivery, FlightOutcome, Launch, LaunchMetrics,
    PreparedScene, Real,
};

use nalgebra::{Matrix3, Vector3};

/// Floating-point precision of the computation.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
pub enum Precision {
    /// Single precision (what a launch-monitor MCU runs).
    F32,
    /// Double precision.
    #[default]
    F64,
}

/// Impact solver.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
pub enum SolverChoice {
    /// The exact 3×3 collision-matrix form.
    #[default]
    Reduced,
    /// The full 15×15 system (Gaussian elimination, equilibrated partial pivoting).
    Full,
}

/// Flight integrator.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
pub enum IntegratorChoice {
    /// Explicit Euler, fixed step.
    Euler,
    /// Classical Runge–Kutta 4, fixed step.
    Rk4,
    /// Adaptive Dormand–Prince 5(4).
    #[default]
    Dp45,
}

/// How an estimate of club data from ball data summarises its posterior
/// ([`carry_core::estimate::Posterior`]; docs/estimate.md §1, §6).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
pub enum PosteriorChoice {
    /// Posterior mean and calibrated 1σ (the strike height's profile posterior).
    #[default]
    Profile,
    /// The most probable delivery and the Gauss–Newton 1σ: about half the cost, the 1σ of
    /// attack, spin loft and strike height too narrow.
    Laplace,
}

impl PosteriorChoice {
    /// The core's summary.
    #[must_use]
    pub fn core(self) -> carry_core::estimate::Posterior {
        match self {
            Self::Profile => carry_core::estimate::Posterior::Profile,
            Self::Laplace => carry_core::estimate::Posterior::Laplace,
        }
    }
}

/// Default fixed step for Euler and RK4 (s).
pub const DEFAULT_FIXED_STEP_S: f64 = 1.0e-3;

/// Numerical settings, global to a run.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Numerics {
    /// f32 or f64.
    pub precision: Precision,
    /// Impact solver.
    pub solver: SolverChoice,
    /// Flight integrator.
    pub integrator: IntegratorChoice,
    /// Fixed step (Euler, RK4) or first trial step (DP45), s.
    pub step_s: Option<f64>,
    /// DP45 tolerance (relative and absolute).
    pub tolerance: Option<f64>,
    /// The estimator's posterior summary (club data from ball data).
    pub posterior: PosteriorChoice,
}

pub use crate::mode::Mode;

impl Numerics {
    /// Checks option combinations that do not depend on a shot.
    ///
    /// # Errors
    /// `--tolerance` with a fixed-step integrator.
    pub fn check(&self) -> Result<(), InputError> {
        if self.tolerance.is_some() && self.integrator != IntegratorChoice::Dp45 {
            return Err(InputError::new(
                "tolerance",
                "applies only to --integrator dp45",
            ));
        }
        Ok(())
    }

    /// The core impact solver.
    #[must_use]
    pub fn solver(&self) -> Solver {
        match self.solver {
            SolverChoice::Reduced => Solver::Reduced,
            SolverChoice::Full => Solver::FULL,
        }
    }

    /// The core flight integrator in precision `T`.
    #[must_use]
    pub fn integrator<T: Real>(&self) -> Integrator<T> {
        match self.integrator {
            IntegratorChoice::Euler => Integrator::Euler {
                step_s: lit(self.step_s.unwrap_or(DEFAULT_FIXED_STEP_S)),
            },
            IntegratorChoice::Rk4 => Integrator::Rk4 {
                step_s: lit(self.step_s.unwrap_or(DEFAULT_FIXED_STEP_S)),
            },
            IntegratorChoice::Dp45 => {
                let mut i = match self.tolerance {
                    Some(tol) => Integrator::dormand_prince(lit(tol)),
                    None => Integrator::default(),
                };
                if let (Some(h), Integrator::DormandPrince { initial_step_s, .. }) =
                    (self.step_s, &mut i)
                {
                    *initial_step_s = lit(h);
                }
                i
            }
        }
    }
}

fn v3<T: Real>(v: [f64; 3]) -> Vector3<T> {
    Vector3::new(lit(v[0]), lit(v[1]), lit(v[2]))
}

/// The club head of `c` in precision `T`, validated.
///
/// # Errors
/// The core's validation, naming the club option.
pub fn club<T: Real>(c: &ClubParams) -> Result<ClubHead<T>, InputError> {
    club_spec(c).validate().map_err(InputError::from)
}

/// The club parameters of `c` (preset plus overrides) in precision `T`, unvalidated.
#[must_use]
pub fn club_spec<T: Real>(c: &ClubParams) -> ClubSpec<T> {
    let mut spec = c.preset.spec::<T>();
    if let Some(m) = c.mass_kg {
        spec.mass_kg = lit(m);
    }
    if let Some(i) = c.inertia_kgm2 {
        spec.inertia_kgm2 = Matrix3::from_row_slice(&i.map(lit::<T>));
    }
    if let Some(a) = c.loft_deg {
        spec.loft_rad = deg(lit(a));
    }
    if let Some(b) = c.bulge_m {
        spec.bulge_radius_m = lit(b);
    }
    if let Some(r) = c.roll_m {
        spec.roll_radius_m = lit(r);
    }
    if let Some(a) = c.face_depth_radius_m {
        spec.face_depth_radius_m = Some(lit(a));
    }
    if let Some(cg) = c.cg_to_face_m {
        spec.cg_to_face_m = v3(cg);
    }
    if let Some(e) = c.cor {
        spec.restitution = lit(e);
    }
    if let Some(k) = c.spin_axis_share {
        spec.spin_axis_share = lit(k);
    }
    if let Some(law) = c.contact {
        spec.contact = law.cast();
    }
    spec
}

/// The typical delivery of the named club, if the user named one.
fn typical(p: &Params) -> Option<&'static carry_core::presets::TypicalDelivery> {
    p.club.named.then_some(&p.club.preset.typical)
}

/// Club speed (m/s): given, else the named club's typical (tour) speed, else the default.
#[must_use]
pub fn club_speed_mps(p: &Params) -> f64 {
    match typical(p) {
        Some(t) if !p.delivery.club_speed_given => t.club_speed_mps,
        _ => p.delivery.club_speed_mps,
    }
}

/// Impact height up the face (m): given, else the named club's strike (the core's rule,
/// [`carry_core::Preset::completed`]: a flat face given a dynamic loft strikes where the
/// turf puts the ball at that loft), else 0.
#[must_use]
pub fn impact_height_m(p: &Params) -> f64 {
    p.delivery.impact_height_m.unwrap_or_else(|| {
        if p.club.named {
            p.club
                .preset
                .completed(&given::<f64>(p), p.ball_radius_m)
                .location
                .height_m
        } else {
            0.0
        }
    })
}

/// What the user gave of a delivery the named-club rule completes.
fn given<T: Real>(p: &Params) -> carry_core::presets::GivenDelivery<T> {
    let d = &p.delivery;
    carry_core::presets::GivenDelivery {
        club_speed_mps: d.club_speed_given.then(|| lit(d.club_speed_mps)),
        attack_angle_rad: d.attack_angle_deg.map(|a| deg(lit(a))),
        dynamic_loft_rad: d.dynamic_loft_deg.map(|a| deg(lit(a))),
        impact_height_m: d.impact_height_m.map(lit),
    }
}

/// The ball of `p`, validated.
///
/// # Errors
/// The core's validation, naming the ball option.
pub fn ball<T: Real>(p: &Params) -> Result<Ball<T>, InputError> {
    Ball::new(lit(p.ball_mass_kg), lit(p.ball_radius_m)).map_err(InputError::from)
}

/// The core delivery of `p` for `head`, as the user gave it (degrees → radians; what is not
/// given comes from the named club's typical delivery, else the reference delivery), in
/// `p`'s convention: turn it into the seed's reading with
/// [`Delivery::in_seed_convention`] (as [`strike_delivery`] does).
#[must_use]
pub fn delivery<T: Real>(p: &Params, head: &ClubHead<T>) -> Delivery<T> {
    let d = &p.delivery;
    // What the user did not give: the named club's (the core's rule, `Preset::completed`),
    // else the reference: square and centred at the default club speed and the static loft.
    let given = given::<T>(p);
    let mut out = if p.club.named {
        p.club.preset.completed(&given, lit(p.ball_radius_m))
    } else {
        given.over(Delivery::square(lit(d.club_speed_mps), head))
    };
    out.club_path_rad = deg(lit(d.club_path_deg));
    out.face_angle_rad = deg(lit(d.face_angle_deg));
    out.lie_rad = deg(lit(d.lie_deg));
    out.club_spin_radps = v3(d.club_spin_radps);
    out.location.toe_m = lit(d.impact_toe_m);
    out
}

/// The delivery of `p` in the seed's reading (the club's centre orientation derived from
/// the angles at the contact point under `--convention trackman`).
///
/// # Errors
/// The core's conversion errors (an off-face location, an unreachable loft).
pub fn strike_delivery<T: Real>(p: &Params, head: &ClubHead<T>) -> Result<Delivery<T>, InputError> {
    Ok(delivery(p, head).in_seed_convention(head, p.delivery.convention)?)
}

/// The impact of `p` in precision `T`.
fn solve_impact<T: Real>(
    p: &Params,
    n: &Numerics,
    ball: &Ball<T>,
) -> Result<carry_core::ImpactOutcome<T>, InputError> {
    let head = club::<T>(&p.club)?;
    let d = &p.delivery;
    let strike = strike_delivery::<T>(p, &head)?.strike(&head)?;
    impact::solve(&head, ball, &strike, n.solver()).map_err(|e| {
        if e == carry_core::Error::NoApproach
            && club_speed_mps(p) == 0.0
            && d.club_spin_radps == [0.0; 3]
        {
            InputError::new(
                "club_speed",
                "must be positive: a club at rest does not strike the ball",
            )
        } else {
            e.into()
        }
    })
}

fn launch_report<T: Real>(
    m: &LaunchMetrics<T>,
    motion: &BallMotion<T>,
    smash: bool,
) -> LaunchReport {
    LaunchReport {
        figures: LaunchFigures::of(m),
        smash_factor: smash.then(|| to_f64(m.smash_factor)),
        ball_velocity_mps: f3(&motion.velocity_mps),
        ball_spin_radps: f3(&motion.spin_radps),
    }
}

/// The launch a flight starts from (launch-monitor terms → ball motion).
///
/// # Errors
/// Conflicting spin options or an invalid launch.
pub fn launch_motion<T: Real>(p: &Params) -> Result<(BallMotion<T>, LaunchReport), InputError> {
    launch_motion_of::<T>(&p.launch)
}

/// As [`launch_motion`], from the launch alone (what it reads of the options).
///
/// # Errors
/// Conflicting spin options or an invalid launch.
pub fn launch_motion_of<T: Real>(
    l: &LaunchParams,
) -> Result<(BallMotion<T>, LaunchReport), InputError> {
    let axis_form = l.spin_rpm.is_some() || l.spin_axis_deg.is_some();
    let launch = if axis_form {
        if l.backspin_rpm.is_some() || l.sidespin_rpm.is_some() {
            return Err(InputError::new(
                "spin, spin_axis",
                "give either backspin and sidespin or spin and spin axis, not both",
            ));
        }
        let spin = l.spin_rpm.unwrap_or(DEFAULT_BACKSPIN_RPM);
        if spin < 0.0 {
            return Err(InputError::new("spin", "must not be negative"));
        }
        Launch::from_spin_axis(
            lit(l.ball_speed_mps),
            deg(lit(l.launch_angle_deg)),
            deg(lit(l.launch_direction_deg)),
            rpm(lit(spin)),
            deg(lit(l.spin_axis_deg.unwrap_or(0.0))),
        )
    } else {
        Launch {
            ball_speed_mps: lit(l.ball_speed_mps),
            launch_angle_rad: deg(lit(l.launch_angle_deg)),
            launch_direction_rad: deg(lit(l.launch_direction_deg)),
            backspin_radps: rpm(lit(l.backspin_rpm.unwrap_or(DEFAULT_BACKSPIN_RPM))),
            sidespin_radps: rpm(lit(l.sidespin_rpm.unwrap_or(0.0))),
        }
    };
    let motion = launch.ball_motion()?;
    let back = to_f64(to_rpm(launch.backspin_radps));
    let side = to_f64(to_rpm(launch.sidespin_radps));
    let report = LaunchReport {
        figures: LaunchFigures {
            ball_speed_mps: to_f64(launch.ball_speed_mps),
            launch_angle_deg: to_f64(to_deg(launch.launch_angle_rad)),
            launch_direction_deg: to_f64(to_deg(launch.launch_direction_rad)),
            spin_rpm: to_f64(to_rpm(motion.spin_radps.norm())),
            backspin_rpm: back,
            sidespin_rpm: side,
            spin_axis_deg: side.atan2(back).to_degrees(),
        },
        smash_factor: None,
        ball_velocity_mps: f3(&motion.velocity_mps),
        ball_spin_radps: f3(&motion.spin_radps),
    };
    Ok((motion, report))
}

pub(crate) fn flight_report<T: Real>(f: &FlightOutcome<T>) -> FlightReport {
    FlightReport {
        carry_m: to_f64(f.carry_m),
        side_m: to_f64(f.side_m),
        carry_x_m: to_f64(f.carry_x_m),
        apex_m: to_f64(f.apex_m),
        apex_time_s: to_f64(f.apex_time_s),
        flight_time_s: to_f64(f.flight_time_s),
        land_angle_deg: to_f64(to_deg(f.landing_angle_rad)),
        land_speed_mps: to_f64(f.landing_speed_mps),
        land_spin_rpm: to_f64(to_rpm(f.landing_spin_radps)),
        landing_position_m: f3(&f.landing_position_m),
        force_evaluations: f.stats.force_evaluations,
        landing_velocity_mps: f3(&f.landing_velocity_mps),
        air_density_kgm3: to_f64(f.air_density_kgm3),
        steps: f.stats.steps,
        rejected_steps: f.stats.rejected_steps,
        ground: f.ground.as_ref().map(GroundReport::of),
    }
}

/// Trajectory samples are recorded every this many seconds for plots.
pub const TRACE_INTERVAL_S: f64 = 0.02;
/// Most samples a trace keeps (80 s at the interval above).
pub const TRACE_CAPACITY: usize = 4000;

/// Runs `mode` on `p` in precision `T`; with `trace`, records the trajectory (m, G).
///
/// # Errors
/// An [`InputError`] naming the option at fault.
pub fn run_in<T: Real>(
    mode: Mode,
    p: &Params,
    n: &Numerics,
    trace: Option<&mut Vec<[f64; 3]>>,
) -> Result<Report, InputError> {
    run_in_scene::<T>(mode, p, n, None, trace)
}

/// The scene of `p` prepared for its ball, in precision `T`: what [`run_in`] flies
/// through. Many shots that share a scene and a ball may prepare it once and pass it to
/// [`run_in_scene`].
///
/// # Errors
/// An invalid ball or scene, naming the option.
pub fn prepared_scene<T: Real>(p: &Params) -> Result<PreparedScene<T>, InputError> {
    let ball = ball::<T>(p)?;
    Ok(crate::scene::build::<T>(&p.scene)?.prepare(&ball)?)
}

/// As [`run_in`], flying through `scene` when given: it must be [`prepared_scene`] of
/// a `Params` with the same scene and ball as `p`.
///
/// # Errors
/// An [`InputError`] naming the option at fault.
pub fn run_in_scene<T: Real>(
    mode: Mode,
    p: &Params,
    n: &Numerics,
    scene: Option<&PreparedScene<T>>,
    trace: Option<&mut Vec<[f64; 3]>>,
) -> Result<Report, InputError> {
    let ball = ball::<T>(p)?;
    let (motion, launch, club_after, impulse) = match mode {
        Mode::Impact | Mode::Shot => {
            let out = solve_impact::<T>(p, n, &ball)?;
            let launch = launch_report(&out.launch, &out.ball, true);
            let club_after = ClubAfter {
                velocity_mps: f3(&out.club.velocity_mps),
                spin_radps: f3(&out.club.spin_radps),
            };
            (
                out.ball,
                launch,
                Some(club_after),
                Some(f3(&out.impulse_ns)),
            )
        }
        Mode::Flight => {
            let (motion, launch) = launch_motion::<T>(p)?;
            (motion, launch, None, None)
        }
    };
    let flight = if mode == Mode::Impact {
        None
    } else {
        let owned;
        let scene = match scene {
            Some(s) => s,
            None => {
                owned = crate::scene::build::<T>(&p.scene)?.prepare(&ball)?;
                &owned
            }
        };
        let integrator = n.integrator::<T>();
        let into_ground = |e: carry_core::Error| into_the_ground(e, &motion, scene);
        let outcome = match trace {
            None => scene.fly(&motion, &integrator, None).map_err(into_ground)?,
            Some(points) => {
                let mut buffer = Box::new(heapless::Vec::<Sample<T>, TRACE_CAPACITY>::new());
                let mut recorder = Recorder::new(lit(TRACE_INTERVAL_S), &mut *buffer)?;
                let outcome = scene
                    .fly(&motion, &integrator, Some(&mut recorder))
                    .map_err(into_ground)?;
                points.clear();
                points.extend(recorder.samples().iter().map(|s| f3(&s.position_m)));
                outcome
            }
        };
        Some(flight_report(&outcome))
    };
    Ok(Report {
        launch,
        club_after,
        impulse_ns: impulse,
        flight,
    })
}

/// Runs `mode` on every row of `rows` in precision `T`: as [`run_in`] row by row, with the
/// flights flown by the core's lanes kernel ([`carry_core::lanes`], issue 37; on this CPU's
/// fastest packs, [`crate::lanes::fly_each`]) where it
/// covers the row's scene and the integrator (the modern aerodynamic family with every
/// effect, still air or a uniform wind, no ground, `dp45`), and by the scalar path
/// otherwise. The results are the row-by-row ones (bit for bit; `io/tests` checks it).
/// A row's scene is prepared once for a run of rows with the same scene and ball.
#[must_use]
pub fn run_rows_in<T: LaneReal>(
    mode: Mode,
    rows: &[Params],
    n: &Numerics,
) -> Vec<Result<Report, InputError>> {
    run_rows_sharing::<T>(mode, rows, n, false)
}

/// As [`run_rows_in`]; with `one_scene` the caller vouches that every row has the same
/// scene and ball (e.g. rows that differ only in keys that are not
/// [`crate::params::Key::is_scene`]), so no row's scene is compared with the last: the
/// first row that reaches its flight prepares the scene for all (the same results: a
/// comparison would have found them equal).
#[must_use]
pub fn run_rows_sharing<T: LaneReal>(
    mode: Mode,
    rows: &[Params],
    n: &Numerics,
    one_scene: bool,
) -> Vec<Result<Report, InputError>> {
    if mode == Mode::Impact {
        return rows.iter().map(|p| run_in::<T>(mode, p, n, None)).collect();
    }
    // The scenes (one per run of rows sharing scene and ball), and each row's launch.
    let mut scenes: Vec<PreparedScene<T>> = Vec::new();
    let mut starts: Vec<Result<Start<T>, InputError>> = Vec::with_capacity(rows.len());
    let mut last: Option<&Params> = None;
    for p in rows {
        let same = !scenes.is_empty()
            && (one_scene
                || last.is_some_and(|q| {
                    q.scene == p.scene
                        && q.ball_mass_kg == p.ball_mass_kg
                        && q.ball_radius_m == p.ball_radius_m
                }));
        let start = (|| {
            let ball = ball::<T>(p)?;
            let (motion, launch, club_after, impulse) = launch_of::<T>(mode, p, n, &ball)?;
            if !same {
                scenes.push(crate::scene::build::<T>(&p.scene)?.prepare(&ball)?);
                last = Some(p);
            }
            Ok(Start {
                scene: scenes.len() - 1,
                motion,
                report: Report {
                    launch,
                    club_after,
                    impulse_ns: impulse,
                    flight: None,
                },
            })
        })();
        starts.push(start);
    }
    let mut index = Vec::with_capacity(rows.len());
    let mut shots = Vec::with_capacity(rows.len());
    for (i, s) in starts.iter().enumerate() {
        if let Ok(s) = s {
            index.push(i);
            shots.push(Shot {
                scene: &scenes[s.scene],
                launch: s.motion,
            });
        }
    }
    let integrator = n.integrator::<T>();
    let mut flights: Vec<Option<Result<FlightReport, InputError>>> = vec![None; shots.len()];
    crate::lanes::fly_each(&shots, &integrator, |k, out| {
        let shot = &shots[k];
        flights[k] = Some(
            out.map(|o| flight_report(&o))
                .map_err(|e| into_the_ground(e, &shot.launch, shot.scene)),
        );
    });
    let mut flights = index.into_iter().zip(flights);
    let mut next = flights.next();
    starts
        .into_iter()
        .enumerate()
        .map(|(i, s)| {
            let mut s = s?;
            let flight = match next.take() {
                Some((j, f)) if j == i => {
                    next = flights.next();
                    f
                }
                other => {
                    next = other;
                    None
                }
            };
            s.report.flight =
                Some(flight.unwrap_or_else(|| Err(InputError::new("flight", "not flown")))?);
            Ok(s.report)
        })
        .collect()
}

/// As [`run_rows_in`], in the precision `n` asks for.
#[must_use]
pub fn run_rows(mode: Mode, rows: &[Params], n: &Numerics) -> Vec<Result<Report, InputError>> {
    match n.precision {
        Precision::F32 => run_rows_in::<f32>(mode, rows, n),
        Precision::F64 => run_rows_in::<f64>(mode, rows, n),
    }
}

/// A row of [`run_rows_in`] ready to fly: its scene (an index), launch and report so far.
struct Start<T: Real> {
    scene: usize,
    motion: BallMotion<T>,
    report: Report,
}

/// The launch of `p` (flight mode) or its impact's (shot mode), with the launch report,
/// the club after impact and the impulse.
#[allow(clippy::type_complexity)]
fn launch_of<T: Real>(
    mode: Mode,
    p: &Params,
    n: &Numerics,
    ball: &Ball<T>,
) -> Result<
    (
        BallMotion<T>,
        LaunchReport,
        Option<ClubAfter>,
        Option<[f64; 3]>,
    ),
    InputError,
> {
    Ok(match mode {
        Mode::Impact | Mode::Shot => {
            let out = solve_impact::<T>(p, n, ball)?;
            let launch = launch_report(&out.launch, &out.ball, true);
            let club_after = ClubAfter {
                velocity_mps: f3(&out.club.velocity_mps),
                spin_radps: f3(&out.club.spin_radps),
            };
            (
                out.ball,
                launch,
                Some(club_after),
                Some(f3(&out.impulse_ns)),
            )
        }
        Mode::Flight => {
            let (motion, launch) = launch_motion::<T>(p)?;
            (motion, launch, None, None)
        }
    })
}

/// A clear message for a launch at or below the horizon from the landing height without
/// a ground (the core's [`carry_core::Error::NoLanding`]); other errors as they are.
pub(crate) fn into_the_ground<T: Real>(
    e: carry_core::Error,
    motion: &BallMotion<T>,
    scene: &PreparedScene<T>,
) -> InputError {
    if e == carry_core::Error::NoLanding
        && motion.velocity_mps.y <= T::zero()
        && scene.ground().is_none()
    {
        return InputError::new(
            "launch_angle",
            "launched at or below the horizon, the ball meets the ground at once and never flies: give it a ground to bounce and roll on (e.g. --ground fairway), or a tee (--tee-height)",
        );
    }
    e.into()
}

/// Runs `mode` on `p` in the precision `n` asks for.
///
/// # Errors
/// An [`InputError`] naming the option at fault.
pub fn run(mode: Mode, p: &Params, n: &Numerics) -> Result<Report, InputError> {
    match n.precision {
        Precision::F32 => run_in::<f32>(mode, p, n, None),
        Precision::F64 => run_in::<f64>(mode, p, n, None),
    }
}

/// As [`run`], recording the trajectory for a plot.
///
/// # Errors
/// An [`InputError`] naming the option at fault.
pub fn run_traced(
    mode: Mode,
    p: &Params,
    n: &Numerics,
    trace: &mut Vec<[f64; 3]>,
) -> Result<Report, InputError> {
    match n.precision {
        Precision::F32 => run_in::<f32>(mode, p, n, Some(trace)),
        Precision::F64 => run_in::<f64>(mode, p, n, Some(trace)),
    }
}
