//! The analyses from a shot's options: typed requests over carry-io's [`Params`] and
//! [`Numerics`], what the CLI's commands (`carry optimize`, `sweep`, `dispersion`,
//! `normalize`) and the Python package's functions both call. Each takes the options as
//! given (in the user's [`Units`]), applies the defaults, builds the [`Setup`] in the
//! precision asked for, runs the analysis and returns its data; formatting (tables, JSON,
//! CSV, charts) is the caller's.
//!
//! No option is silently ignored: an option the analysis replaces (a delivery option the
//! swing file sets, an angle given together with its search range) leaves a one-line note
//! in the outcome's `notes`, which the shells print (stderr) or warn.

use crate::dispersion::{self, Dispersion, Noise};
use crate::normalize::{self, Direction, Normalized};
use crate::optimize::{
    self, Chart, ChartObjective, ChartOptions, Objective, Optimum, Options, Range,
};
use crate::sweep::generate::{EXAMPLE_COMMENT, SwingModel};
use crate::sweep::{self, Motion, Sweep};
use crate::{Error, Input, Setup};
use carry_core::Real;
use carry_core::real::to_f64;
use carry_core::shot::Fidelity;
use carry_io::compute::{self, IntegratorChoice, Numerics, Precision};
use carry_io::error::{Failure, InputError};
use carry_io::params::Params;
use carry_io::units::{Quantity, Units};
use std::path::PathBuf;

/// The lab setup of `p` in precision `T`.
///
/// # Errors
/// The core's validation, naming the option.
pub fn setup<T: Real>(p: &Params, n: &Numerics) -> Result<Setup<T>, InputError> {
    let club = compute::club::<T>(&p.club)?;
    let ball = compute::ball::<T>(p)?;
    let scene = carry_io::scene::build::<T>(&p.scene)?.prepare(&ball)?;
    Ok(Setup {
        club,
        ball,
        delivery: compute::delivery(p, &club),
        convention: p.delivery.convention,
        scene,
        fidelity: Fidelity {
            solver: n.solver(),
            integrator: n.integrator(),
        },
    })
}

/// Calls `f32` or `f64` with the setup in the precision `n` asks for.
///
/// # Errors
/// Those of [`setup`] and the callee.
pub fn with_setup<R>(
    p: &Params,
    n: &Numerics,
    f32: impl FnOnce(Setup<f32>) -> Result<R, Failure>,
    f64: impl FnOnce(Setup<f64>) -> Result<R, Failure>,
) -> Result<R, Failure> {
    match n.precision {
        Precision::F32 => f32(setup::<f32>(p, n)?),
        Precision::F64 => f64(setup::<f64>(p, n)?),
    }
}

/// The option a noise SD comes from.
const NOISE_KEYS: [&str; 7] = [
    "face_angle_sd",
    "club_path_sd",
    "attack_angle_sd",
    "dynamic_loft_sd",
    "club_speed_sd",
    "impact_height_sd",
    "impact_toe_sd",
];

/// A lab error as the user reads it; `count` names the option of [`Input::Count`].
#[must_use]
pub fn failure(e: Error, count: &'static str) -> Failure {
    let key = |input: Input| match input {
        Input::DynamicLoftRange => "dynamic_loft_range",
        Input::AttackAngleRange => "attack_angle_range",
        Input::ImpactHeightRange => "impact_height_range",
        Input::Objective => "objective",
        Input::Count => count,
        Input::NoiseSd(i) => NOISE_KEYS.get(i).copied().unwrap_or("noise"),
        Input::Swing => "swing",
        Input::BallPositions => "ball_positions",
        Input::ChartSpeeds => "club_speeds",
        Input::ChartAttackAngles => "attack_angles",
    };
    match e {
        Error::Core(e) => Failure::from(e),
        Error::Invalid(input, why) => Failure::Input(InputError::new(key(input), why)),
        Error::Library(why) => Failure::Other(why),
    }
}

/// The note for an option the analysis replaces: `--attack-angle is ignored: …`.
fn ignored(key: &str, why: &str) -> String {
    format!("note: --{} is ignored: {why}", key.replace('_', "-"))
}

// ---------------------------------------------------------------- dispersion

/// Delivery noise: standard deviations in the user's units (speed m/s or mph, impact
/// location m or in), named after the delivery options.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct NoiseSd {
    /// Face angle SD (deg).
    pub face_angle_sd: f64,
    /// Club path SD (deg).
    pub club_path_sd: f64,
    /// Attack angle SD (deg).
    pub attack_angle_sd: f64,
    /// Dynamic loft SD (deg).
    pub dynamic_loft_sd: f64,
    /// Club speed SD (m/s | mph).
    pub club_speed_sd: f64,
    /// Impact height SD (m | in).
    pub impact_height_sd: f64,
    /// Impact toe SD (m | in).
    pub impact_toe_sd: f64,
}

impl NoiseSd {
    /// The option names, in the order of the fields.
    pub const KEYS: [&'static str; 7] = NOISE_KEYS;

    /// The noise in SI (speed m/s, location m), from `u`.
    #[must_use]
    pub fn noise(&self, u: Units) -> Noise {
        Noise {
            face_angle_deg: self.face_angle_sd,
            club_path_deg: self.club_path_sd,
            attack_angle_deg: self.attack_angle_sd,
            dynamic_loft_deg: self.dynamic_loft_sd,
            club_speed_mps: u.to_si(Quantity::Speed, self.club_speed_sd),
            impact_height_m: u.to_si(Quantity::Offset, self.impact_height_sd),
            impact_toe_m: u.to_si(Quantity::Offset, self.impact_toe_sd),
        }
    }

    /// The SD named `key` (one of [`NoiseSd::KEYS`]), for shells that take options by name.
    pub fn get_mut(&mut self, key: &str) -> Option<&mut f64> {
        Some(match key {
            "face_angle_sd" => &mut self.face_angle_sd,
            "club_path_sd" => &mut self.club_path_sd,
            "attack_angle_sd" => &mut self.attack_angle_sd,
            "dynamic_loft_sd" => &mut self.dynamic_loft_sd,
            "club_speed_sd" => &mut self.club_speed_sd,
            "impact_height_sd" => &mut self.impact_height_sd,
            "impact_toe_sd" => &mut self.impact_toe_sd,
            _ => return None,
        })
    }
}

/// Parses a standard deviation: a finite number, not negative.
///
/// # Errors
/// The reason, for a message.
pub fn parse_sd(text: &str) -> Result<f64, String> {
    let x = carry_io::params::parse_finite(text)?;
    if x < 0.0 {
        Err("must not be negative".into())
    } else {
        Ok(x)
    }
}

/// Default number of shots of a dispersion.
pub const DEFAULT_SHOTS: usize = 10_000;

/// `carry dispersion`: Monte-Carlo over delivery noise.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct DispersionRequest {
    /// Units of the noise SDs.
    pub units: Units,
    /// The noise.
    pub noise: NoiseSd,
    /// Number of shots (default [`DEFAULT_SHOTS`]).
    pub shots: Option<usize>,
    /// Seed of the noise.
    pub seed: u64,
    /// Worker threads (default: all cores).
    pub threads: Option<usize>,
}

impl DispersionRequest {
    /// The number of shots this request flies.
    #[must_use]
    pub fn shots(&self) -> usize {
        self.shots.unwrap_or(DEFAULT_SHOTS)
    }

    /// Runs the Monte-Carlo on the shot `p`; `tick(n)` reports `n` more shots done.
    ///
    /// # Errors
    /// Bad options or base shot (input), a thread pool that cannot start.
    pub fn run(
        &self,
        p: &Params,
        n: &Numerics,
        tick: Option<&(dyn Fn(usize) + Sync)>,
    ) -> Result<Dispersion, Failure> {
        with_setup(
            p,
            n,
            |s| self.simulate(&s, tick),
            |s| self.simulate(&s, tick),
        )
    }

    fn simulate<T: Real>(
        &self,
        setup: &Setup<T>,
        tick: Option<&(dyn Fn(usize) + Sync)>,
    ) -> Result<Dispersion, Failure> {
        let noise = self.noise.noise(self.units);
        let run = || {
            dispersion::simulate(setup, &noise, self.shots(), self.seed, tick)
                .map_err(|e| failure(e, "shots"))
        };
        match self.threads {
            Some(k) => rayon::ThreadPoolBuilder::new()
                .num_threads(k)
                .build()
                .map_err(|e| InputError::new("threads", e.to_string()))?
                .install(run),
            None => run(),
        }
    }
}

// ---------------------------------------------------------------- optimize

/// What to optimise.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum ObjectiveChoice {
    /// Maximise carry.
    #[default]
    Carry,
    /// Maximise total distance (carry + bounce and roll; needs a ground).
    Total,
    /// Minimise the side spread under the noise.
    Dispersion,
}

/// Shots per objective evaluation for the dispersion objective unless `shots` says.
pub const DISPERSION_OBJECTIVE_SHOTS: usize = 500;

/// The optimizer chart's grid, in the user's units (`None`: the defaults, 35–55 m/s by 5
/// and −4° to 4° by 2).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ChartGrid {
    /// Club speeds `[from, to, step]` (m/s | mph).
    pub club_speeds: Option<[f64; 3]>,
    /// Attack angles `[from, to, step]` (deg).
    pub attack_angles: Option<[f64; 3]>,
}

/// `carry optimize`: the delivery that maximises carry within bounds, or the chart.
///
/// A dynamic loft, attack angle or impact height given with the shot (`Params`) holds that
/// variable at its value; its `*_range` frees it again (the range wins, with a note).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct OptimizeRequest {
    /// Units of the impact height range and the chart's club speeds.
    pub units: Units,
    /// Dynamic loft bounds (deg); default the static loft −8 (at least 0) to +12.
    pub dynamic_loft_range: Option<[f64; 2]>,
    /// Attack angle bounds (deg); default −5 to 5.
    pub attack_angle_range: Option<[f64; 2]>,
    /// Impact height bounds (m | in); default held at the shot's impact height.
    pub impact_height_range: Option<[f64; 2]>,
    /// The objective.
    pub objective: ObjectiveChoice,
    /// Number of starts.
    pub starts: usize,
    /// The optimizer chart instead of one optimum.
    pub chart: Option<ChartGrid>,
    /// Noise of the dispersion objective.
    pub noise: NoiseSd,
    /// Shots per evaluation of the dispersion objective.
    pub shots: Option<usize>,
    /// Seed of the random starts and of the noise.
    pub seed: u64,
}

/// What `carry optimize` found.
#[derive(Debug, Clone, PartialEq)]
pub enum OptimizeOutcome {
    /// The optimum.
    Optimum(Optimum),
    /// The chart.
    Chart(Chart),
}

fn grid(
    values: [f64; 3],
    key: &'static str,
    si: impl Fn(f64) -> f64,
) -> Result<Vec<f64>, InputError> {
    let [from, to, step] = values;
    sweep::positions(from, to, step)
        .map(|v| v.into_iter().map(si).collect())
        .map_err(|_| InputError::new(key, "give from,to,step with from ≤ to and a positive step"))
}

impl OptimizeRequest {
    /// The bounds of one angle: the range if given (a given value is then ignored, with a
    /// note), else the given value held, else the default.
    fn angle(
        range: Option<[f64; 2]>,
        given: Option<f64>,
        default: [f64; 2],
        (key, input): (&str, Input),
        notes: &mut Vec<String>,
    ) -> Result<Range, Failure> {
        let r = match (range, given) {
            (Some([a, b]), g) => {
                if g.is_some() {
                    notes.push(ignored(
                        key,
                        &format!("--{key}-range wins").replace('_', "-"),
                    ));
                }
                Range::new(a, b, input)
            }
            (None, Some(v)) => Range::fixed(v, input),
            (None, None) => Range::new(default[0], default[1], input),
        };
        r.map_err(|e| failure(e, "starts"))
    }

    fn options<T: Real>(
        &self,
        p: &Params,
        setup: &Setup<T>,
        notes: &mut Vec<String>,
    ) -> Result<Options, Failure> {
        let u = self.units;
        let loft = to_f64(carry_core::units::to_deg(setup.club.loft_rad()));
        let loft_range = Self::angle(
            self.dynamic_loft_range,
            p.delivery.dynamic_loft_deg,
            [(loft - 8.0).max(0.0), loft + 12.0],
            ("dynamic_loft", Input::DynamicLoftRange),
            notes,
        )?;
        let attack_range = Self::angle(
            self.attack_angle_range,
            p.delivery.attack_angle_deg,
            [-5.0, 5.0],
            ("attack_angle", Input::AttackAngleRange),
            notes,
        )?;
        if self.impact_height_range.is_some() && p.delivery.impact_height_m.is_some() {
            notes.push(ignored("impact_height", "--impact-height-range wins"));
        }
        let height = self
            .impact_height_range
            .map(|[a, b]| {
                Range::new(
                    u.to_si(Quantity::Offset, a),
                    u.to_si(Quantity::Offset, b),
                    Input::ImpactHeightRange,
                )
            })
            .transpose()
            .map_err(|e| failure(e, "starts"))?;
        let objective = match self.objective {
            ObjectiveChoice::Carry => Objective::Carry,
            ObjectiveChoice::Total => Objective::Total,
            ObjectiveChoice::Dispersion => Objective::Dispersion {
                noise: self.noise.noise(u),
                shots: self.shots.unwrap_or(DISPERSION_OBJECTIVE_SHOTS),
                seed: self.seed,
            },
        };
        Ok(Options {
            dynamic_loft_deg: loft_range,
            attack_angle_deg: attack_range,
            impact_height_m: height,
            objective,
            starts: self.starts,
            seed: self.seed,
            max_iterations: 400,
        })
    }

    fn run_in<T: Real>(
        &self,
        p: &Params,
        setup: Setup<T>,
        smooth: bool,
        notes: &mut Vec<String>,
    ) -> Result<OptimizeOutcome, Failure> {
        let setup = if smooth { setup.smooth() } else { setup };
        if let Some(g) = &self.chart {
            // The chart searches the dynamic loft at each club speed and attack angle of
            // its grid: the shot's own values of those are not used.
            let mut chart_notes = Vec::new();
            let options = self.options(p, &setup, &mut chart_notes)?;
            if p.delivery.club_speed_given {
                notes.push(ignored("club_speed", "the chart sets the club speeds"));
            }
            if p.delivery.attack_angle_deg.is_some() {
                notes.push(ignored("attack_angle", "the chart sets the attack angles"));
            }
            notes.extend(
                chart_notes
                    .into_iter()
                    .filter(|n| !n.contains("--attack-angle ")),
            );
            let u = self.units;
            let speeds = grid(
                g.club_speeds.unwrap_or([35.0, 55.0, 5.0]),
                "club_speeds",
                |v| {
                    if g.club_speeds.is_some() {
                        u.to_si(Quantity::Speed, v)
                    } else {
                        v
                    }
                },
            )?;
            let attacks = grid(
                g.attack_angles.unwrap_or([-4.0, 4.0, 2.0]),
                "attack_angles",
                |a| a,
            )?;
            let loft = if options.dynamic_loft_deg.is_fixed() {
                // A chart of the best dynamic loft needs its range: a given dynamic loft
                // does not hold it here.
                let l = to_f64(carry_core::units::to_deg(setup.club.loft_rad()));
                Range::new((l - 8.0).max(0.0), l + 12.0, Input::DynamicLoftRange)
                    .map_err(|e| failure(e, "starts"))?
            } else {
                options.dynamic_loft_deg
            };
            if options.dynamic_loft_deg.is_fixed() && self.dynamic_loft_range.is_none() {
                notes.push(ignored(
                    "dynamic_loft",
                    "the chart searches the dynamic loft",
                ));
            }
            let objective = match self.objective {
                ObjectiveChoice::Carry => ChartObjective::Carry,
                ObjectiveChoice::Total => ChartObjective::Total,
                ObjectiveChoice::Dispersion => {
                    return Err(failure(
                        Error::invalid(
                            Input::Objective,
                            "the chart maximises carry or total, not dispersion",
                        ),
                        "starts",
                    ));
                }
            };
            let chart = optimize::chart(
                &setup,
                &ChartOptions {
                    club_speeds_mps: speeds,
                    attack_angles_deg: attacks,
                    dynamic_loft_deg: loft,
                    objective,
                },
            )
            .map_err(|e| failure(e, "starts"))?;
            return Ok(OptimizeOutcome::Chart(chart));
        }
        let options = self.options(p, &setup, notes)?;
        let best = optimize::optimize(&setup, &options).map_err(|e| failure(e, "starts"))?;
        Ok(OptimizeOutcome::Optimum(best))
    }

    /// Runs the search (or the chart) for the shot `p`; notes on options it replaced go
    /// to `notes`.
    ///
    /// # Errors
    /// Bad options (input), an optimizer failure.
    pub fn run(
        &self,
        p: &Params,
        n: &Numerics,
        notes: &mut Vec<String>,
    ) -> Result<OptimizeOutcome, Failure> {
        if self.objective != ObjectiveChoice::Dispersion {
            let sd = &self.noise;
            for (key, x) in NOISE_KEYS.iter().zip([
                sd.face_angle_sd,
                sd.club_path_sd,
                sd.attack_angle_sd,
                sd.dynamic_loft_sd,
                sd.club_speed_sd,
                sd.impact_height_sd,
                sd.impact_toe_sd,
            ]) {
                if x != 0.0 {
                    notes.push(ignored(key, "only --objective dispersion uses the noise"));
                }
            }
            if self.shots.is_some() {
                notes.push(ignored("shots", "only --objective dispersion flies shots"));
            }
        }
        // A smooth objective unless the user chose the numerics.
        let smooth = n.integrator == IntegratorChoice::Dp45 && n.tolerance.is_none();
        let mut notes32 = Vec::new();
        let mut notes64 = Vec::new();
        let out = with_setup(
            p,
            n,
            |s| self.run_in(p, s, smooth, &mut notes32),
            |s| self.run_in(p, s, smooth, &mut notes64),
        );
        notes.extend(notes32);
        notes.extend(notes64);
        out
    }
}

// ---------------------------------------------------------------- sweep

/// The example swing, compiled in so the analysis runs anywhere.
pub const EXAMPLE_SWING: &str = include_str!("../data/swing_driver.csv");

/// `carry sweep`: a swing file against a range of ball positions.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct SweepRequest {
    /// Units of the ball positions.
    pub units: Units,
    /// The club-head motion (CSV); `None`: [`EXAMPLE_SWING`].
    pub swing: Option<PathBuf>,
    /// Ball positions `[from, to, step]` (m | in); default −0.1 to 0.1 m by 0.01.
    pub ball_positions: Option<[f64; 3]>,
}

/// The delivery options a swing replaces: (key, given).
fn swing_replaces(p: &Params) -> [(&'static str, bool); 6] {
    let d = &p.delivery;
    let base = Params::default().delivery;
    [
        ("club_speed", d.club_speed_given),
        ("attack_angle", d.attack_angle_deg.is_some()),
        ("dynamic_loft", d.dynamic_loft_deg.is_some()),
        ("club_path", d.club_path_deg != base.club_path_deg),
        ("face_angle", d.face_angle_deg != base.face_angle_deg),
        ("impact_height", d.impact_height_m.is_some()),
    ]
}

impl SweepRequest {
    fn run_in<T: Real>(&self, setup: &Setup<T>) -> Result<Sweep, Failure> {
        let loft = to_f64(setup.club.loft_rad());
        let motion = match &self.swing {
            Some(path) => {
                let file = std::fs::File::open(path).map_err(|e| {
                    InputError::new("swing", format!("cannot read {}: {e}", path.display()))
                })?;
                Motion::from_csv(std::io::BufReader::new(file), loft)
            }
            None => Motion::from_csv(EXAMPLE_SWING.as_bytes(), loft),
        }
        .map_err(|e| failure(e, "swing"))?;
        let [from, to, step] = match self.ball_positions {
            Some(v) => v.map(|x| self.units.to_si(Quantity::Offset, x)),
            None => [-0.1, 0.1, 0.01],
        };
        let positions =
            sweep::positions(from, to, step).map_err(|e| failure(e, "ball_positions"))?;
        sweep::sweep(setup, &motion, &positions).map_err(|e| failure(e, "ball_positions"))
    }

    /// Sweeps the ball positions for the club, ball and scene of `p` (its delivery is the
    /// swing's: a delivery option given in `p` is noted as ignored).
    ///
    /// # Errors
    /// Bad options or swing file (input).
    pub fn run(&self, p: &Params, n: &Numerics, notes: &mut Vec<String>) -> Result<Sweep, Failure> {
        for (key, given) in swing_replaces(p) {
            if given {
                notes.push(ignored(key, "the swing sets the delivery"));
            }
        }
        with_setup(p, n, |s| self.run_in(&s), |s| self.run_in(&s))
    }

    /// Writes the example swing (the double-pendulum model) for the club and ball of `p`
    /// to `path`.
    ///
    /// # Errors
    /// Bad options (input), a file that cannot be written.
    pub fn generate(p: &Params, n: &Numerics, path: &std::path::Path) -> Result<(), Failure> {
        let write = |motion: Motion| -> Result<(), Failure> {
            std::fs::write(path, motion.to_csv(false, EXAMPLE_COMMENT))?;
            Ok(())
        };
        with_setup(
            p,
            n,
            |s| write(generate_for(&s)?),
            |s| write(generate_for(&s)?),
        )
    }
}

fn generate_for<T: Real>(setup: &Setup<T>) -> Result<Motion, Failure> {
    SwingModel::default()
        .generate(
            &setup.club.face_rotation().map(to_f64),
            &setup.club.cg_to_face_m().map(to_f64),
            to_f64(setup.ball.radius_m()),
        )
        .map_err(|e| failure(e, "generate"))
}

// ---------------------------------------------------------------- normalize

/// `carry normalize`: a launch's carry in standard conditions, and back.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum To {
    /// From the given conditions to standard ones.
    #[default]
    Standard,
    /// From standard conditions to the given ones.
    Conditions,
}

/// Normalises the launch of `p` (its launch, ball and scene) in direction `to`.
///
/// # Errors
/// Bad options (input).
pub fn normalize(p: &Params, n: &Numerics, to: To) -> Result<Normalized, Failure> {
    fn run_in<T: Real>(p: &Params, n: &Numerics, to: To) -> Result<Normalized, Failure> {
        let ball = compute::ball::<T>(p)?;
        let (motion, _) = compute::launch_motion::<T>(p)?;
        let scene = carry_io::scene::build::<T>(&p.scene)?;
        let direction = match to {
            To::Standard => Direction::ToStandard,
            To::Conditions => Direction::ToConditions,
        };
        normalize::normalize(&ball, &motion, &scene, &n.integrator(), direction)
            .map_err(|e| failure(e, "precision"))
    }
    match n.precision {
        Precision::F32 => run_in::<f32>(p, n, to),
        Precision::F64 => run_in::<f64>(p, n, to),
    }
}

// ---------------------------------------------------------------- estimate

/// What the launch monitor measured of the club, for [`estimate`] (`None`: not measured).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct MeasuredClub {
    /// Club speed (m/s).
    pub club_speed_mps: Option<f64>,
    /// Attack angle (deg).
    pub attack_angle_deg: Option<f64>,
    /// Club path (deg).
    pub club_path_deg: Option<f64>,
    /// Face angle at the contact point (deg).
    pub face_angle_deg: Option<f64>,
    /// Dynamic loft at the contact point (deg).
    pub dynamic_loft_deg: Option<f64>,
}

/// The estimated delivery (issue 23; TrackMan's convention), each datum with its 1σ, the
/// residuals (modelled − measured ball data) and the iterations. Degrees for angles, SI
/// otherwise.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct EstimateRecord {
    /// face angle (deg).
    pub face_angle_deg: f64,
    /// 1σ of the face angle (deg).
    pub face_angle_deg_sd: f64,
    /// club path (deg).
    pub club_path_deg: f64,
    /// 1σ of the club path (deg).
    pub club_path_deg_sd: f64,
    /// face to path (deg).
    pub face_to_path_deg: f64,
    /// 1σ of the face to path (deg).
    pub face_to_path_deg_sd: f64,
    /// dynamic loft (deg).
    pub dynamic_loft_deg: f64,
    /// 1σ of the dynamic loft (deg).
    pub dynamic_loft_deg_sd: f64,
    /// attack angle (deg).
    pub attack_angle_deg: f64,
    /// 1σ of the attack angle (deg).
    pub attack_angle_deg_sd: f64,
    /// spin loft (deg).
    pub spin_loft_deg: f64,
    /// 1σ of the spin loft (deg).
    pub spin_loft_deg_sd: f64,
    /// impact toe (m).
    pub impact_toe_m: f64,
    /// 1σ of the impact toe (m).
    pub impact_toe_m_sd: f64,
    /// impact height (m).
    pub impact_height_m: f64,
    /// 1σ of the impact height (m).
    pub impact_height_m_sd: f64,
    /// club speed (m/s).
    pub club_speed_mps: f64,
    /// 1σ of the club speed (m/s).
    pub club_speed_mps_sd: f64,
    /// smash factor.
    pub smash_factor: f64,
    /// 1σ of the smash factor.
    pub smash_factor_sd: f64,
    /// Whether the club speed was estimated (not measured).
    pub club_speed_estimated: bool,
    /// residual ball speed (m/s).
    pub residual_ball_speed_mps: f64,
    /// residual launch angle (deg).
    pub residual_launch_angle_deg: f64,
    /// residual launch direction (deg).
    pub residual_launch_direction_deg: f64,
    /// residual spin (rpm).
    pub residual_spin_rpm: f64,
    /// residual spin axis (deg).
    pub residual_spin_axis_deg: f64,
    /// The consistency check's χ²: the cost at the most probable delivery (issue 34).
    pub chi2: f64,
    /// Its bound (the χ² quantile of the check's tail probability).
    pub chi2_bound: f64,
    /// Levenberg–Marquardt iterations used.
    pub iterations: u8,
}

impl EstimateRecord {
    /// The names of [`Self::values`], in order: the CSV columns of `carry batch estimate`
    /// and the keys of Python's `carry.estimate` (a flag and the iterations as numbers).
    pub const COLUMNS: [&'static str; 29] = [
        "face_angle_deg",
        "face_angle_deg_sd",
        "club_path_deg",
        "club_path_deg_sd",
        "face_to_path_deg",
        "face_to_path_deg_sd",
        "dynamic_loft_deg",
        "dynamic_loft_deg_sd",
        "attack_angle_deg",
        "attack_angle_deg_sd",
        "spin_loft_deg",
        "spin_loft_deg_sd",
        "impact_toe_m",
        "impact_toe_m_sd",
        "impact_height_m",
        "impact_height_m_sd",
        "club_speed_mps",
        "club_speed_mps_sd",
        "smash_factor",
        "smash_factor_sd",
        "club_speed_estimated",
        "residual_ball_speed_mps",
        "residual_launch_angle_deg",
        "residual_launch_direction_deg",
        "residual_spin_rpm",
        "residual_spin_axis_deg",
        "chi2",
        "chi2_bound",
        "iterations",
    ];

    /// The record as numbers in the order of [`Self::COLUMNS`].
    #[must_use]
    pub fn values(&self) -> [f64; 29] {
        [
            self.face_angle_deg,
            self.face_angle_deg_sd,
            self.club_path_deg,
            self.club_path_deg_sd,
            self.face_to_path_deg,
            self.face_to_path_deg_sd,
            self.dynamic_loft_deg,
            self.dynamic_loft_deg_sd,
            self.attack_angle_deg,
            self.attack_angle_deg_sd,
            self.spin_loft_deg,
            self.spin_loft_deg_sd,
            self.impact_toe_m,
            self.impact_toe_m_sd,
            self.impact_height_m,
            self.impact_height_m_sd,
            self.club_speed_mps,
            self.club_speed_mps_sd,
            self.smash_factor,
            self.smash_factor_sd,
            f64::from(u8::from(self.club_speed_estimated)),
            self.residual_ball_speed_mps,
            self.residual_launch_angle_deg,
            self.residual_launch_direction_deg,
            self.residual_spin_rpm,
            self.residual_spin_axis_deg,
            self.chi2,
            self.chi2_bound,
            f64::from(self.iterations),
        ]
    }
}

/// Estimates the club delivery of `p`'s club (preset and overrides) from `p`'s launch (the
/// measured ball data) and the `club` data measured, with the preset's default settings
/// ([`carry_core::estimate::Settings::typical`]), in `n`'s precision and with `n`'s
/// posterior summary.
///
/// # Errors
/// Bad options, measurements out of range, or no estimate (input: exit 2).
pub fn estimate(p: &Params, n: &Numerics, club: &MeasuredClub) -> Result<EstimateRecord, Failure> {
    use carry_core::estimate::{self as est, BallData, ClubData, Settings};
    use carry_core::real::lit;
    fn run_in<T: Real>(
        p: &Params,
        n: &Numerics,
        club: &MeasuredClub,
    ) -> Result<EstimateRecord, Failure> {
        let head = compute::club::<T>(&p.club)?;
        let ball = compute::ball::<T>(p)?;
        let measured = BallData::from_array(ball_data(p)?.to_array().map(lit::<T>));
        let rad = |d: Option<f64>| d.map(|d| lit::<T>(d.to_radians()));
        let data = ClubData {
            club_speed_mps: club.club_speed_mps.map(lit::<T>),
            attack_angle_rad: rad(club.attack_angle_deg),
            club_path_rad: rad(club.club_path_deg),
            face_angle_rad: rad(club.face_angle_deg),
            dynamic_loft_rad: rad(club.dynamic_loft_deg),
        };
        let settings = Settings::<T> {
            posterior: n.posterior.core(),
            ..Settings::for_preset(p.club.preset)
        };
        let e =
            est::estimate(&head, &ball, &measured, &data, &settings).map_err(InputError::from)?;
        let c = e.consistency;
        if !c.consistent {
            return Err(inconsistent(&c, &settings.check).into());
        }
        let (v, s, r) = (e.value, e.sd, e.residual);
        let d = |x: T| to_f64(x).to_degrees();
        let f = to_f64::<T>;
        Ok(EstimateRecord {
            face_angle_deg: d(v.face_angle_rad),
            face_angle_deg_sd: d(s.face_angle_rad),
            club_path_deg: d(v.club_path_rad),
            club_path_deg_sd: d(s.club_path_rad),
            face_to_path_deg: d(v.face_to_path_rad),
            face_to_path_deg_sd: d(s.face_to_path_rad),
            dynamic_loft_deg: d(v.dynamic_loft_rad),
            dynamic_loft_deg_sd: d(s.dynamic_loft_rad),
            attack_angle_deg: d(v.attack_angle_rad),
            attack_angle_deg_sd: d(s.attack_angle_rad),
            spin_loft_deg: d(v.spin_loft_rad),
            spin_loft_deg_sd: d(s.spin_loft_rad),
            impact_toe_m: f(v.impact_toe_m),
            impact_toe_m_sd: f(s.impact_toe_m),
            impact_height_m: f(v.impact_height_m),
            impact_height_m_sd: f(s.impact_height_m),
            club_speed_mps: f(v.club_speed_mps),
            club_speed_mps_sd: f(s.club_speed_mps),
            smash_factor: f(v.smash_factor),
            smash_factor_sd: f(s.smash_factor),
            club_speed_estimated: e.club_speed_estimated,
            residual_ball_speed_mps: f(r.ball_speed_mps),
            residual_launch_angle_deg: d(r.launch_angle_rad),
            residual_launch_direction_deg: d(r.launch_direction_rad),
            residual_spin_rpm: f(r.spin_radps) * 30.0 / core::f64::consts::PI,
            residual_spin_axis_deg: d(r.spin_axis_rad),
            chi2: f(c.chi2),
            chi2_bound: f(c.bound),
            iterations: e.iterations,
        })
    }
    match n.precision {
        Precision::F32 => run_in::<f32>(p, n, club),
        Precision::F64 => run_in::<f64>(p, n, club),
    }
}

/// The measured ball data of `p`'s launch as a launch monitor reports them (SI): ball
/// speed, launch angle and direction, total spin and spin axis (from `--spin`/`--spin-axis`,
/// or from `--backspin`/`--sidespin`). Read from the options themselves, so that a value out
/// of range is named by its own option (a launch angle of 95° is not turned into a launch
/// direction of 180° on the way).
///
/// # Errors
/// Both spin forms given, a negative spin.
pub fn ball_data(p: &Params) -> Result<carry_core::estimate::BallData<f64>, InputError> {
    let l = &p.launch;
    let (spin_rpm, axis_deg) = if l.spin_rpm.is_some() || l.spin_axis_deg.is_some() {
        if l.backspin_rpm.is_some() || l.sidespin_rpm.is_some() {
            return Err(InputError::new(
                "spin, spin_axis",
                "give either backspin and sidespin or spin and spin axis, not both",
            ));
        }
        (
            l.spin_rpm.unwrap_or(carry_io::params::DEFAULT_BACKSPIN_RPM),
            l.spin_axis_deg.unwrap_or(0.0),
        )
    } else {
        let back = l
            .backspin_rpm
            .unwrap_or(carry_io::params::DEFAULT_BACKSPIN_RPM);
        let side = l.sidespin_rpm.unwrap_or(0.0);
        (back.hypot(side), side.atan2(back).to_degrees())
    };
    if spin_rpm < 0.0 {
        return Err(InputError::new("spin", "must not be negative"));
    }
    Ok(carry_core::estimate::BallData {
        ball_speed_mps: l.ball_speed_mps,
        launch_angle_rad: l.launch_angle_deg.to_radians(),
        launch_direction_rad: l.launch_direction_deg.to_radians(),
        spin_radps: spin_rpm * core::f64::consts::PI / 30.0,
        spin_axis_rad: axis_deg.to_radians(),
    })
}

/// The one-line error of an estimate whose data disagree (issue 34): the worst datum's
/// option, by how many σ the most probable delivery misses it, and the χ² against its bound.
#[must_use]
pub fn inconsistent<T: Real>(
    c: &carry_core::estimate::Consistency<T>,
    check: &carry_core::estimate::Check<T>,
) -> InputError {
    use carry_core::estimate::Datum;
    let stats = format!(
        "χ² {:.1} of {} data, bound {:.1} at p = {}; worst {:.1}σ, bound {}σ",
        to_f64(c.chi2),
        c.dof,
        to_f64(c.bound),
        to_f64(check.tail_probability),
        to_f64(c.worst_sd),
        to_f64(check.max_shift_sd)
    );
    let reason = if c.worst == Datum::Club {
        format!(
            "the ball data disagree with this club: they need a delivery far from its typical one ({stats})"
        )
    } else {
        format!("disagrees with the other data ({stats})")
    };
    InputError::new(carry_io::error::datum_key(c.worst), reason)
}

/// [`estimate`] over many rows in parallel on `threads` workers (`None`: all cores), each
/// row the parameters and measured club data of one shot, or the error its input had; the
/// results in row order.
///
/// # Errors
/// The thread pool cannot start.
pub fn estimate_rows(
    rows: &[Result<(Params, MeasuredClub), InputError>],
    n: &Numerics,
    threads: Option<usize>,
) -> Result<Vec<Result<EstimateRecord, InputError>>, Failure> {
    crate::rows::par_rows(rows, threads, "estimate", |p, club| estimate(p, n, club))
}
