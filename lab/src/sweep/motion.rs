//! A club-head motion through impact, sampled in time: validation, the CSV form, the
//! derived rates and interpolation.
//!
//! **CSV** (a header, then one row per sample; `#` lines are comments): `t_s, x_m, y_m,
//! z_m` (the club head's centre of mass in G, origin at the ball's centre for ball
//! position 0), the orientation R_club (C → G) as a unit quaternion `qw, qx, qy, qz` or as
//! launch-monitor angles `face_angle_deg, dynamic_loft_deg, lie_deg` (R = Ry(−face) ·
//! Rz(loft − static loft) · Rx(lie), PHYSICS.md), optionally the velocity `vx_mps, vy_mps,
//! vz_mps` and the angular velocity `wx_radps, wy_radps, wz_radps` (G).
//!
//! **Derived rates** when the file has none: central differences on the samples
//! (one-sided at the ends), `vᵢ = (pᵢ₊₁ − pᵢ₋₁)/(tᵢ₊₁ − tᵢ₋₁)` and, on the rotation group,
//! `ωᵢ = log(qᵢ₊₁ qᵢ₋₁⁻¹)/(tᵢ₊₁ − tᵢ₋₁)` (the rotation vector of the relative rotation,
//! world frame). Second order in the sample spacing for uniform sampling.
//!
//! **Interpolation** at a time between samples: position and rates linear, orientation by
//! spherical linear interpolation (slerp).

use crate::error::{Error, Input, Result};
use nalgebra::{Quaternion, Rotation3, UnitQuaternion, Vector3};
use std::io::Read;

/// A quaternion is accepted as a rotation when `| |q| − 1 |` is at most this; it is then
/// normalised.
pub const UNIT_TOLERANCE: f64 = 1.0e-3;

/// One sample of the club-head motion.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sample {
    /// Time (s).
    pub time_s: f64,
    /// Club head CoM (m, G).
    pub position_m: Vector3<f64>,
    /// Orientation R_club (C → G).
    pub orientation: UnitQuaternion<f64>,
    /// CoM velocity (m/s, G).
    pub velocity_mps: Vector3<f64>,
    /// Angular velocity (rad/s, G).
    pub spin_radps: Vector3<f64>,
}

/// A validated motion: at least 3 samples, strictly increasing times, rates filled in.
#[derive(Debug, Clone, PartialEq)]
pub struct Motion {
    samples: Vec<Sample>,
}

fn bad(why: impl Into<String>) -> Error {
    Error::invalid(Input::Swing, why)
}

impl Motion {
    /// A motion from samples. With `derive_velocity` / `derive_spin` the rates are
    /// replaced by central differences.
    ///
    /// # Errors
    /// [`Error::Invalid`] ([`Input::Swing`]): fewer than 3 samples, a non-finite value,
    /// times not strictly increasing.
    pub fn new(mut samples: Vec<Sample>, derive_velocity: bool, derive_spin: bool) -> Result<Self> {
        if samples.len() < 3 {
            return Err(bad("needs at least 3 samples"));
        }
        for (i, pair) in samples.windows(2).enumerate() {
            if let [a, b] = pair
                && !(b.time_s > a.time_s)
            {
                return Err(bad(format!(
                    "sample {}: time {} s does not increase (previous {} s)",
                    i + 2,
                    b.time_s,
                    a.time_s
                )));
            }
        }
        for (i, s) in samples.iter().enumerate() {
            let finite = s.time_s.is_finite()
                && s.position_m.iter().all(|x| x.is_finite())
                && s.orientation.coords.iter().all(|x| x.is_finite())
                && s.velocity_mps.iter().all(|x| x.is_finite())
                && s.spin_radps.iter().all(|x| x.is_finite());
            if !finite {
                return Err(bad(format!("sample {}: not a finite number", i + 1)));
            }
        }
        let n = samples.len();
        let rates: Vec<(Vector3<f64>, Vector3<f64>)> = (0..n)
            .map(|i| {
                let (a, b) = (i.saturating_sub(1), (i + 1).min(n - 1));
                let (sa, sb) = (&samples[a], &samples[b]);
                let dt = sb.time_s - sa.time_s;
                let v = (sb.position_m - sa.position_m) / dt;
                let w = (sb.orientation * sa.orientation.inverse()).scaled_axis() / dt;
                (v, w)
            })
            .collect();
        for (s, (v, w)) in samples.iter_mut().zip(rates) {
            if derive_velocity {
                s.velocity_mps = v;
            }
            if derive_spin {
                s.spin_radps = w;
            }
        }
        Ok(Self { samples })
    }

    /// The samples.
    #[must_use]
    pub fn samples(&self) -> &[Sample] {
        &self.samples
    }

    /// The state at `i + s` (`s` in 0..1 between samples `i` and `i + 1`).
    #[must_use]
    pub fn interpolate(&self, i: usize, s: f64) -> Sample {
        let a = self.samples.get(i).or(self.samples.last());
        let b = self.samples.get(i + 1).or(a);
        match (a, b) {
            (Some(a), Some(b)) => Sample {
                time_s: a.time_s + s * (b.time_s - a.time_s),
                position_m: a.position_m.lerp(&b.position_m, s),
                orientation: a.orientation.slerp(&b.orientation, s),
                velocity_mps: a.velocity_mps.lerp(&b.velocity_mps, s),
                spin_radps: a.spin_radps.lerp(&b.spin_radps, s),
            },
            // `new` guarantees samples; this arm is unreachable in practice.
            _ => Sample {
                time_s: 0.0,
                position_m: Vector3::zeros(),
                orientation: UnitQuaternion::identity(),
                velocity_mps: Vector3::zeros(),
                spin_radps: Vector3::zeros(),
            },
        }
    }

    /// Reads the CSV form (see the module docs); `static_loft_rad` turns launch-monitor
    /// angles into an orientation.
    ///
    /// # Errors
    /// [`Error::Invalid`] ([`Input::Swing`]) naming the line and column: unreadable CSV,
    /// missing columns, a value that is not a number, a quaternion that is not a unit
    /// quaternion, and the errors of [`Motion::new`].
    pub fn from_csv(reader: impl Read, static_loft_rad: f64) -> Result<Self> {
        let mut csv = csv::ReaderBuilder::new()
            .comment(Some(b'#'))
            .trim(csv::Trim::All)
            .from_reader(reader);
        let header = csv
            .headers()
            .map_err(|e| bad(format!("not CSV: {e}")))?
            .clone();
        let col = |name: &str| header.iter().position(|h| h == name);
        let need = |name: &str| col(name).ok_or_else(|| bad(format!("missing column {name}")));
        let position = [need("t_s")?, need("x_m")?, need("y_m")?, need("z_m")?];
        let quaternion = [col("qw"), col("qx"), col("qy"), col("qz")];
        let angles = [
            col("face_angle_deg"),
            col("dynamic_loft_deg"),
            col("lie_deg"),
        ];
        let velocity = [col("vx_mps"), col("vy_mps"), col("vz_mps")];
        let spin = [col("wx_radps"), col("wy_radps"), col("wz_radps")];
        let all = |c: &[Option<usize>]| c.iter().all(Option::is_some);
        let use_quaternion = all(&quaternion);
        if !use_quaternion && !all(&angles) {
            return Err(bad(
                "needs the orientation: columns qw,qx,qy,qz or face_angle_deg,dynamic_loft_deg,lie_deg",
            ));
        }
        let (has_velocity, has_spin) = (all(&velocity), all(&spin));
        let mut samples = Vec::new();
        for (row, record) in csv.records().enumerate() {
            let line = record
                .as_ref()
                .ok()
                .and_then(|r| r.position())
                .map_or(row + 2, |p| usize::try_from(p.line()).unwrap_or(row + 2));
            let record = record.map_err(|e| bad(format!("line {line}: {e}")))?;
            let get = |c: Option<usize>| -> Result<f64> {
                let i = c.unwrap_or(usize::MAX);
                let text = record.get(i).unwrap_or("");
                let name = header.get(i).unwrap_or("?");
                text.parse::<f64>()
                    .ok()
                    .filter(|x| x.is_finite())
                    .ok_or_else(|| bad(format!("line {line}: {name}: '{text}' is not a number")))
            };
            let v3 = |c: [Option<usize>; 3]| -> Result<Vector3<f64>> {
                Ok(Vector3::new(get(c[0])?, get(c[1])?, get(c[2])?))
            };
            let orientation = if use_quaternion {
                let q = Quaternion::new(
                    get(quaternion[0])?,
                    get(quaternion[1])?,
                    get(quaternion[2])?,
                    get(quaternion[3])?,
                );
                let norm = q.norm();
                if !((norm - 1.0).abs() <= UNIT_TOLERANCE) {
                    return Err(bad(format!(
                        "line {line}: the quaternion is not a unit quaternion (|q| = {norm:.6}, tolerance {UNIT_TOLERANCE})"
                    )));
                }
                UnitQuaternion::new_normalize(q)
            } else {
                let [face, loft, lie] = [
                    get(angles[0])?.to_radians(),
                    get(angles[1])?.to_radians(),
                    get(angles[2])?.to_radians(),
                ];
                let r = Rotation3::from_axis_angle(&Vector3::y_axis(), -face)
                    * Rotation3::from_axis_angle(&Vector3::z_axis(), loft - static_loft_rad)
                    * Rotation3::from_axis_angle(&Vector3::x_axis(), lie);
                UnitQuaternion::from_rotation_matrix(&r)
            };
            samples.push(Sample {
                time_s: get(Some(position[0]))?,
                position_m: v3([Some(position[1]), Some(position[2]), Some(position[3])])?,
                orientation,
                velocity_mps: if has_velocity {
                    v3(velocity)?
                } else {
                    Vector3::zeros()
                },
                spin_radps: if has_spin {
                    v3(spin)?
                } else {
                    Vector3::zeros()
                },
            });
        }
        Self::new(samples, !has_velocity, !has_spin)
    }

    /// The CSV form: position and quaternion, with the rates when `rates`.
    #[must_use]
    pub fn to_csv(&self, rates: bool, comment: &str) -> String {
        use std::fmt::Write as _;
        let mut s = String::new();
        for line in comment.lines() {
            let _ = writeln!(s, "# {line}");
        }
        s.push_str("t_s,x_m,y_m,z_m,qw,qx,qy,qz");
        if rates {
            s.push_str(",vx_mps,vy_mps,vz_mps,wx_radps,wy_radps,wz_radps");
        }
        s.push('\n');
        for p in &self.samples {
            let q = p.orientation.quaternion();
            let _ = write!(
                s,
                "{:.6},{:.7},{:.7},{:.7},{:.9},{:.9},{:.9},{:.9}",
                p.time_s, p.position_m.x, p.position_m.y, p.position_m.z, q.w, q.i, q.j, q.k
            );
            if rates {
                let (v, w) = (p.velocity_mps, p.spin_radps);
                let _ = write!(
                    s,
                    ",{:.6},{:.6},{:.6},{:.6},{:.6},{:.6}",
                    v.x, v.y, v.z, w.x, w.y, w.z
                );
            }
            s.push('\n');
        }
        s
    }
}
