//! The lanes kernel's arithmetic: `N` shots' states as a structure of arrays (component
//! `i` of lane `l` at `y[i][l]`), the modern family's force evaluation across the lanes,
//! and one Dormand–Prince 5(4) step of every lane, each with its own step size.
//!
//! Every lane runs the very operations of the scalar path ([`crate::aero::Dynamics`],
//! `integrator::integrate::dormand_prince`) in the same order: each loop over the lanes has
//! a branch-free body (the spin laws' piece is a select, not a branch), which LLVM turns into
//! packed instructions (`mulpd`, `divpd`, `sqrtpd`, `cmppd` + blends) on hosts. IEEE 754
//! arithmetic is the same packed or scalar (Rust never fuses a multiply and an add on its
//! own), so a lane's numbers are the scalar path's bit for bit.

use crate::real::{Real, lit};

/// `N` lanes of one scalar.
pub(crate) type Lanes<T, const N: usize> = [T; N];
/// `N` lanes of the 7-component state (position, velocity, spin magnitude).
pub(crate) type States<T, const N: usize> = [[T; N]; 7];

/// One lane's force field, in the modern family's per-unit-mass form
/// ([`crate::aero::model::Forces::Modern`]), as lanes.
#[derive(Clone, Copy)]
pub(crate) struct Field<T, const N: usize> {
    pub(crate) gravity: Lanes<T, N>,
    /// Uniform wind (m/s, G; zero in still air).
    pub(crate) wind: [Lanes<T, N>; 3],
    /// Spin axis ω̂ (zero without spin).
    pub(crate) axis: [Lanes<T, N>; 3],
    /// Spin decay `λ` (1/m).
    pub(crate) decay: Lanes<T, N>,
    /// `A·c_d,super` (1/m).
    pub(crate) drag_v: Lanes<T, N>,
    /// The crisis `Δ` and `k⁶`.
    pub(crate) crisis_below: Lanes<T, N>,
    pub(crate) crisis_k6: Lanes<T, N>,
    /// The spin laws: `R/S_first`, `ρ_second`, `ρ_second²`.
    pub(crate) per_spin: Lanes<T, N>,
    pub(crate) second: Lanes<T, N>,
    pub(crate) second_sq: Lanes<T, N>,
    /// Polynomial coefficients `[α₀..α₄]` of the lift and the spin drag on the rising piece,
    /// on the second piece, and past both saturations (`[α₀, 0, 0, 0, 0]`).
    pub(crate) rising_lift: [Lanes<T, N>; 5],
    pub(crate) rising_drag: [Lanes<T, N>; 5],
    pub(crate) second_lift: [Lanes<T, N>; 5],
    pub(crate) second_drag: [Lanes<T, N>; 5],
    pub(crate) saturated_lift: Lanes<T, N>,
    pub(crate) saturated_drag: Lanes<T, N>,
}

impl<T: Real, const N: usize> Field<T, N> {
    /// A field whose every lane is zero (filled lane by lane).
    pub(crate) fn zero() -> Self {
        let z = [T::zero(); N];
        Self {
            gravity: z,
            wind: [z; 3],
            axis: [z; 3],
            decay: z,
            drag_v: z,
            crisis_below: z,
            crisis_k6: z,
            per_spin: z,
            second: z,
            second_sq: z,
            rising_lift: [z; 5],
            rising_drag: [z; 5],
            second_lift: [z; 5],
            second_drag: [z; 5],
            saturated_lift: z,
            saturated_drag: z,
        }
    }
}

/// `dy/dt` of every lane: the modern family with drag, lift and spin decay in still air or
/// a uniform wind, as `Dynamics::forces_switched` computes it:
///
/// ```text
/// v_r = v − w,  V² = v_r·v_r,  V = √V²,  κ = (R/S_first)·s,  y² = κ²/V²
/// (P, Q) = piece(y²): κ'·(α₁ + α₃u²), α₀ + u²·(α₂ + α₄u²)
/// k_d = (P_D + A·c_d,super·V) + (Q_D·V + Δ/(1 + V⁴·(V²k⁶))·V),   k_l = P_L + Q_L·V
/// a = (0, −g, 0) − k_d·v_r + k_l·(ω̂ × v_r),   ds/dt = −(λV)·s
/// ```
#[inline(always)]
pub(crate) fn eval<T: Real, const N: usize>(f: &Field<T, N>, y: &States<T, N>) -> States<T, N> {
    let zero = T::zero();
    let one = T::one();
    let mut out = [[zero; N]; 7];
    for l in 0..N {
        let (vx, vy, vz, s) = (y[3][l], y[4][l], y[5][l], y[6][l]);
        let rx = vx - f.wind[0][l];
        let ry = vy - f.wind[1][l];
        let rz = vz - f.wind[2][l];
        let speed_sq = (rx * rx + ry * ry) + rz * rz;
        let speed = speed_sq.root();
        // The spin laws' piece (`SpinLaws::piece`), selected rather than branched on.
        let kappa = f.per_spin[l] * s;
        let y_sq = (kappa * kappa) / speed_sq;
        let x_sq = f.second_sq[l] * y_sq;
        let rising = y_sq < one;
        let second = !rising && x_sq < one;
        let pick = |r: &[Lanes<T, N>; 5], q: &[Lanes<T, N>; 5], sat: T| -> [T; 5] {
            if rising {
                [r[0][l], r[1][l], r[2][l], r[3][l], r[4][l]]
            } else if second {
                [q[0][l], q[1][l], q[2][l], q[3][l], q[4][l]]
            } else {
                [sat, zero, zero, zero, zero]
            }
        };
        let lift = pick(&f.rising_lift, &f.second_lift, f.saturated_lift[l]);
        let drag = pick(&f.rising_drag, &f.second_drag, f.saturated_drag[l]);
        let (k, u) = if rising {
            (kappa, y_sq)
        } else if second {
            (f.second[l] * kappa, x_sq)
        } else {
            (zero, zero)
        };
        let law = |a: [T; 5]| (k * (a[1] + a[3] * u), a[0] + u * (a[2] + a[4] * u));
        let (lift_0, lift_1) = law(lift);
        let (drag_0, drag_1) = law(drag);
        let crisis =
            f.crisis_below[l] / (one + (speed_sq * speed_sq) * (speed_sq * f.crisis_k6[l]));
        let kd = (drag_0 + f.drag_v[l] * speed) + (drag_1 * speed + crisis * speed);
        let kl = lift_0 + lift_1 * speed;
        let (ax, ay, az) = (f.axis[0][l], f.axis[1][l], f.axis[2][l]);
        let (cx, cy, cz) = (ay * rz - az * ry, az * rx - ax * rz, ax * ry - ay * rx);
        out[0][l] = vx;
        out[1][l] = vy;
        out[2][l] = vz;
        out[3][l] = (zero - rx * kd) + cx * kl;
        out[4][l] = (-f.gravity[l] - ry * kd) + cy * kl;
        out[5][l] = (zero - rz * kd) + cz * kl;
        out[6][l] = -(f.decay[l] * speed) * s;
    }
    out
}

/// `y + h Σ cⱼ kⱼ` in every lane, each with its own `h` (the scalar `combine`'s order).
#[inline(always)]
fn combine<T: Real, const N: usize, const K: usize>(
    y: &States<T, N>,
    h: &Lanes<T, N>,
    c: [f64; K],
    k: [&States<T, N>; K],
) -> States<T, N> {
    let mut out = *y;
    for (cj, kj) in c.iter().zip(k.iter()) {
        let cj = lit::<T>(*cj);
        let mut w = [T::zero(); N];
        for (wl, hl) in w.iter_mut().zip(h.iter()) {
            *wl = *hl * cj;
        }
        for (o, x) in out.iter_mut().zip(kj.iter()) {
            for l in 0..N {
                o[l] += w[l] * x[l];
            }
        }
    }
    out
}

// The Dormand–Prince 5(4) tableau (the scalar integrator's, `integrate.rs`).
const A2: [f64; 1] = [1.0 / 5.0];
const A3: [f64; 2] = [3.0 / 40.0, 9.0 / 40.0];
const A4: [f64; 3] = [44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0];
const A5: [f64; 4] = [
    19372.0 / 6561.0,
    -25360.0 / 2187.0,
    64448.0 / 6561.0,
    -212.0 / 729.0,
];
const A6: [f64; 5] = [
    9017.0 / 3168.0,
    -355.0 / 33.0,
    46732.0 / 5247.0,
    49.0 / 176.0,
    -5103.0 / 18656.0,
];
const B: [f64; 5] = [
    35.0 / 384.0,
    500.0 / 1113.0,
    125.0 / 192.0,
    -2187.0 / 6784.0,
    11.0 / 84.0,
];
const E: [f64; 6] = [
    71.0 / 57600.0,
    -71.0 / 16695.0,
    71.0 / 1920.0,
    -17253.0 / 339_200.0,
    22.0 / 525.0,
    -1.0 / 40.0,
];

/// One Dormand–Prince step of every lane: the stages the interpolant needs, the
/// 5th-order result, `k₇ = f(y₁)` and the scaled error norm.
pub(crate) struct Stages<T, const N: usize> {
    pub(crate) k3: States<T, N>,
    pub(crate) k4: States<T, N>,
    pub(crate) k5: States<T, N>,
    pub(crate) k6: States<T, N>,
    pub(crate) k7: States<T, N>,
    pub(crate) y1: States<T, N>,
    /// `max_i |eᵢ|·wᵢ` (≤ 1 passes; NaN propagates as a rejection).
    pub(crate) err: Lanes<T, N>,
}

/// `larger(a, b)` of `crate::real` (C's `fmax`) as one select: `b` when `a < b` or `a` is
/// NaN, else `a`.
#[inline(always)]
fn larger<T: Real>(a: T, b: T) -> T {
    if a < b || a.partial_cmp(&a).is_none() {
        b
    } else {
        a
    }
}

/// One step of size `h[l]` from `y` (with `k₁ = f(y)`) in every lane: 6 evaluations.
#[inline(always)]
pub(crate) fn step<T: Real, const N: usize>(
    f: &Field<T, N>,
    y: &States<T, N>,
    k1: &States<T, N>,
    h: &Lanes<T, N>,
    rtol: T,
    atol: T,
) -> Stages<T, N> {
    let k2 = eval(f, &combine(y, h, A2, [k1]));
    let k3 = eval(f, &combine(y, h, A3, [k1, &k2]));
    let k4 = eval(f, &combine(y, h, A4, [k1, &k2, &k3]));
    let k5 = eval(f, &combine(y, h, A5, [k1, &k2, &k3, &k4]));
    let k6 = eval(f, &combine(y, h, A6, [k1, &k2, &k3, &k4, &k5]));
    let y1 = combine(y, h, B, [k1, &k3, &k4, &k5, &k6]);
    let mut weight = [[T::zero(); N]; 7];
    for ((w, a), b) in weight.iter_mut().zip(y.iter()).zip(y1.iter()) {
        for l in 0..N {
            w[l] = T::one() / (atol + rtol * larger(a[l].abs(), b[l].abs()));
        }
    }
    let k7 = eval(f, &y1);
    let e = combine(&[[T::zero(); N]; 7], h, E, [k1, &k3, &k4, &k5, &k6, &k7]);
    let mut err = [T::zero(); N];
    for (ei, wi) in e.iter().zip(weight.iter()) {
        for l in 0..N {
            let r = ei[l].abs() * wi[l];
            // `!(r <= err)` also propagates NaN into a rejection (the scalar rule).
            if !(r <= err[l]) {
                err[l] = r;
            }
        }
    }
    Stages {
        k3,
        k4,
        k5,
        k6,
        k7,
        y1,
        err,
    }
}

/// Lane `l` of `x` as one state.
#[inline(always)]
pub(crate) fn lane<T: Real, const N: usize>(x: &States<T, N>, l: usize) -> [T; 7] {
    core::array::from_fn(|i| x[i].get(l).copied().unwrap_or_else(T::zero))
}

/// Writes the state `v` into lane `l` of `x` (nothing for a lane out of range).
#[inline(always)]
pub(crate) fn set_lane<T: Copy, const N: usize>(x: &mut States<T, N>, l: usize, v: &[T; 7]) {
    for (xi, vi) in x.iter_mut().zip(v.iter()) {
        if let Some(slot) = xi.get_mut(l) {
            *slot = *vi;
        }
    }
}
