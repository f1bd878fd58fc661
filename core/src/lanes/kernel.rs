//! The lanes kernel's arithmetic: [`LANES`](super::LANES) shots' states as a structure of
//! SIMD packs (component `i` of every lane in `y[i]`), the modern family's force evaluation
//! across the lanes, and one Dormand–Prince 5(4) step of every lane, each with its own step
//! size.
//!
//! Every lane runs the very operations of the scalar path ([`crate::aero::Dynamics`],
//! `integrator::integrate::dormand_prince`) in the same order, on `wide`'s packs
//! (`f64x4`, `f32x4`: `mulpd`, `divpd`, `sqrtpd`, compares and blends on x86-64; plain
//! arrays and a correctly rounded software square root where a target has no SIMD unit).
//! The spin laws' piece is a blend, not a branch. IEEE 754 arithmetic is the same packed or
//! scalar (and Rust never fuses a multiply and an add on its own), so a lane's numbers are
//! the scalar path's bit for bit. Negation flips the sign bit (`wide`'s `-x` is `0 − x`,
//! which loses the sign of a zero). The multiply–adds are written [`Pack::mul_add`] and
//! its kin: a product and a sum on every pack but the AVX one with FMA ([`Pack::FUSED`]),
//! which fuses them and, where `FUSED` says so, takes shorter paths of its own (results
//! within 1e-9 of the scalar path's rather than equal).

use crate::real::{Real, lit};
use core::ops::{Add, BitAnd, BitOr, BitXor, Div, Mul, Not, Sub};

/// A pack of lanes of one scalar: what the kernel needs of a SIMD type.
pub trait Pack:
    Copy
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + BitAnd<Output = Self>
    + BitOr<Output = Self>
    + BitXor<Output = Self>
    + Not<Output = Self>
{
    /// The scalar of a lane.
    type Scalar: Real;
    /// Lanes in a pack.
    const LANES: usize;
    /// Whether the apex and landing are located on packs (`Run::locate`), else by the
    /// scalar tracker lane by lane.
    const PACKED_EVENTS: bool = true;
    /// Every lane `x`.
    fn splat(x: Self::Scalar) -> Self;
    /// Lane `l % LANES`.
    fn get(&self, l: usize) -> Self::Scalar;
    /// Sets lane `l % LANES`.
    fn set(&mut self, l: usize, x: Self::Scalar);
    /// The correctly rounded square root of each lane.
    #[must_use]
    fn sqrt(self) -> Self;
    /// `|x|` of each lane.
    #[must_use]
    fn abs(self) -> Self;
    /// Lane masks of `self < o`, `self <= o`, `self != o`.
    #[must_use]
    fn lt(self, o: Self) -> Self;
    /// See [`Pack::lt`].
    #[must_use]
    fn le(self, o: Self) -> Self;
    /// See [`Pack::lt`].
    #[must_use]
    fn ne(self, o: Self) -> Self;
    /// `t` where the mask `self` is set, else `f`.
    #[must_use]
    fn blend(self, t: Self, f: Self) -> Self;
    /// The mask's lanes as bits (lane `l` in bit `l`).
    #[must_use]
    fn bits(self) -> u32;
    /// The mask of the lanes whose bit is set in `bits`.
    #[must_use]
    fn mask(bits: u32) -> Self;
    /// Whether [`Pack::mul_add`], [`Pack::mul_sub`] and [`Pack::neg_mul_add`] fuse (one
    /// rounding: the AVX pack with FMA); else each is the product rounded, then the sum,
    /// the very operations the scalar path writes as `a·b + c`, `a·b − c`, `c − a·b`.
    const FUSED: bool = false;
    /// `self·b + c` (`c + self·b` unfused: IEEE addition commutes bit for bit).
    #[inline(always)]
    #[must_use]
    fn mul_add(self, b: Self, c: Self) -> Self {
        self * b + c
    }
    /// `self·b − c`.
    #[inline(always)]
    #[must_use]
    fn mul_sub(self, b: Self, c: Self) -> Self {
        self * b - c
    }
    /// `c − self·b`.
    #[inline(always)]
    #[must_use]
    fn neg_mul_add(self, b: Self, c: Self) -> Self {
        c - self * b
    }
}

macro_rules! pack {
    ($pack:ty, $scalar:ty, $n:literal) => {
        impl Pack for $pack {
            type Scalar = $scalar;
            const LANES: usize = $n;
            const PACKED_EVENTS: bool = false;
            #[inline(always)]
            fn splat(x: $scalar) -> Self {
                <$pack>::splat(x)
            }
            #[inline(always)]
            fn get(&self, l: usize) -> $scalar {
                self.as_array_ref()[l % $n]
            }
            #[inline(always)]
            fn set(&mut self, l: usize, x: $scalar) {
                self.as_array_mut()[l % $n] = x;
            }
            #[inline(always)]
            fn sqrt(self) -> Self {
                <$pack>::sqrt(self)
            }
            #[inline(always)]
            fn abs(self) -> Self {
                <$pack>::abs(self)
            }
            #[inline(always)]
            fn lt(self, o: Self) -> Self {
                wide::CmpLt::cmp_lt(self, o)
            }
            #[inline(always)]
            fn le(self, o: Self) -> Self {
                wide::CmpLe::cmp_le(self, o)
            }
            #[inline(always)]
            fn ne(self, o: Self) -> Self {
                wide::CmpNe::cmp_ne(self, o)
            }
            #[inline(always)]
            fn blend(self, t: Self, f: Self) -> Self {
                <$pack>::blend(self, t, f)
            }
            #[inline(always)]
            fn bits(self) -> u32 {
                self.move_mask().cast_unsigned()
            }
            #[inline(always)]
            fn mask(bits: u32) -> Self {
                let set = <$scalar>::from_bits(!0);
                <$pack>::new(core::array::from_fn(|l| {
                    if bits & (1 << l) != 0 { set } else { 0.0 }
                }))
            }
        }
    };
}
pack!(wide::f64x4, f64, 4);
pack!(wide::f32x4, f32, 4);

/// `-x` of each lane: the sign bit flipped.
#[inline(always)]
fn neg<P: Pack>(x: P) -> P {
    x ^ P::splat(lit(-0.0))
}

/// The 7-component state (position, velocity, spin magnitude) of every lane.
pub(crate) type States<P> = [P; 7];

/// Lane `l` of `x` as one state.
#[inline(always)]
pub(crate) fn lane<P: Pack>(x: &States<P>, l: usize) -> [P::Scalar; 7] {
    core::array::from_fn(|i| x[i].get(l))
}

/// Writes the state `v` into lane `l` of `x`.
#[inline(always)]
pub(crate) fn set_lane<P: Pack>(x: &mut States<P>, l: usize, v: &[P::Scalar; 7]) {
    for (xi, vi) in x.iter_mut().zip(v.iter()) {
        xi.set(l, *vi);
    }
}

/// Every lane's force field, in the modern family's per-unit-mass form
/// (`aero::model::Forces::Modern`).
#[derive(Clone, Copy)]
pub(crate) struct Field<P> {
    /// `−g` (m/s²).
    pub(crate) minus_gravity: P,
    /// Uniform wind (m/s, G; zero in still air).
    pub(crate) wind: [P; 3],
    /// Spin axis ω̂ (zero without spin).
    pub(crate) axis: [P; 3],
    /// Spin decay `λ` (1/m).
    pub(crate) decay: P,
    /// `A·c_d,super` (1/m).
    pub(crate) drag_v: P,
    /// The crisis `Δ` and `k⁶`.
    pub(crate) crisis_below: P,
    pub(crate) crisis_k6: P,
    /// The spin laws: `R/S_first`, `ρ_second`, `ρ_second²`.
    pub(crate) per_spin: P,
    pub(crate) second: P,
    pub(crate) second_sq: P,
    /// Polynomial coefficients `[α₀..α₄]` of the lift and the spin drag on the rising piece
    /// and on the second piece, and `α₀` past both saturations.
    pub(crate) rising_lift: [P; 5],
    pub(crate) rising_drag: [P; 5],
    pub(crate) second_lift: [P; 5],
    pub(crate) second_drag: [P; 5],
    pub(crate) saturated_lift: P,
    pub(crate) saturated_drag: P,
}

impl<P: Pack> Field<P> {
    /// A field whose every lane is zero (filled lane by lane).
    pub(crate) fn zero() -> Self {
        let z = P::splat(lit(0.0));
        Self {
            minus_gravity: z,
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
pub(crate) fn eval<P: Pack>(f: &Field<P>, y: &States<P>) -> States<P> {
    let zero = P::splat(lit(0.0));
    let one = P::splat(lit(1.0));
    let (vx, vy, vz, s) = (y[3], y[4], y[5], y[6]);
    let rx = vx - f.wind[0];
    let ry = vy - f.wind[1];
    let rz = vz - f.wind[2];
    let speed_sq = rz.mul_add(rz, rx.mul_add(rx, ry * ry));
    let speed = speed_sq.sqrt();
    // The spin laws' piece (`SpinLaws::piece`), blended rather than branched on: past both
    // saturations the laws are (0, α₀).
    let kappa = f.per_spin * s;
    let y_sq = (kappa * kappa) / speed_sq;
    let x_sq = f.second_sq * y_sq;
    let rising = y_sq.lt(one);
    let second = !rising & x_sq.lt(one);
    // Both pieces' laws, then the lane's piece's results blended in (4 blends a piece).
    let k2 = f.second * kappa;
    let (rl, rd) = (
        law(&f.rising_lift, kappa, y_sq),
        law(&f.rising_drag, kappa, y_sq),
    );
    let (ql, qd) = (law(&f.second_lift, k2, x_sq), law(&f.second_drag, k2, x_sq));
    let (lift_0, lift_1) = (
        pick(rising, second, rl.0, ql.0, zero),
        pick(rising, second, rl.1, ql.1, f.saturated_lift),
    );
    let (drag_0, drag_1) = (
        pick(rising, second, rd.0, qd.0, zero),
        pick(rising, second, rd.1, qd.1, f.saturated_drag),
    );
    let crisis = f.crisis_below / (speed_sq * speed_sq).mul_add(speed_sq * f.crisis_k6, one);
    let kd = f.drag_v.mul_add(speed, drag_0) + drag_1.mul_add(speed, crisis * speed);
    let kl = lift_1.mul_add(speed, lift_0);
    let [ax, ay, az] = f.axis;
    let (cx, cy, cz) = (
        ay.mul_sub(rz, az * ry),
        az.mul_sub(rx, ax * rz),
        ax.mul_sub(ry, ay * rx),
    );
    if P::FUSED {
        // Fused: `c·k_l − r·k_d` (and `(−g + c_y·k_l) − r_y·k_d`) with `k_d`, the last to be
        // ready (it waits for the crisis's division and `V`), in the last instruction: one
        // fused operation after it rather than two.
        return [
            vx,
            vy,
            vz,
            rx.neg_mul_add(kd, cx * kl),
            ry.neg_mul_add(kd, cy.mul_add(kl, f.minus_gravity)),
            rz.neg_mul_add(kd, cz * kl),
            neg(f.decay * speed) * s,
        ];
    }
    [
        vx,
        vy,
        vz,
        cx.mul_add(kl, rx.neg_mul_add(kd, zero)),
        cy.mul_add(kl, ry.neg_mul_add(kd, f.minus_gravity)),
        cz.mul_add(kl, rz.neg_mul_add(kd, zero)),
        neg(f.decay * speed) * s,
    ]
}

/// A spin law's two parts on a piece: `κ'·(α₁ + α₃u²)` and `α₀ + u²·(α₂ + α₄u²)`.
/// (Functions, not closures, here and in [`pick`]: a closure the compiler outlines would not
/// get its caller's target features, and its packed intrinsics would become calls.)
#[inline(always)]
fn law<P: Pack>(a: &[P; 5], k: P, u: P) -> (P, P) {
    (
        k * a[3].mul_add(u, a[1]),
        u.mul_add(a[4].mul_add(u, a[2]), a[0]),
    )
}

/// The rising piece's `r` where `rising`, else the second piece's `q` where `second`, else
/// `past`.
#[inline(always)]
fn pick<P: Pack>(rising: P, second: P, r: P, q: P, past: P) -> P {
    rising.blend(r, second.blend(q, past))
}

/// `y + h Σ cⱼ kⱼ` in every lane, each with its own `h` (the scalar `combine`'s order).
#[inline(always)]
fn combine<P: Pack, const K: usize>(
    y: &States<P>,
    h: P,
    c: [f64; K],
    k: [&States<P>; K],
) -> States<P> {
    let mut out = *y;
    for (cj, kj) in c.iter().zip(k.iter()) {
        let w = h * P::splat(lit(*cj));
        for (o, x) in out.iter_mut().zip(kj.iter()) {
            *o = w.mul_add(*x, *o);
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
pub(crate) struct Stages<P> {
    pub(crate) k3: States<P>,
    pub(crate) k4: States<P>,
    pub(crate) k5: States<P>,
    pub(crate) k6: States<P>,
    pub(crate) k7: States<P>,
    pub(crate) y1: States<P>,
    /// `max_i |eᵢ|·wᵢ` (≤ 1 passes; NaN propagates as a rejection).
    pub(crate) err: P,
}

/// `larger(a, b)` of `crate::real` (C's `fmax`) as one blend: `b` when `a < b` or `a` is
/// NaN, else `a`.
#[inline(always)]
fn larger<P: Pack>(a: P, b: P) -> P {
    (a.lt(b) | a.ne(a)).blend(b, a)
}

/// `b` where `a < b`, else `a` (the larger of two numbers neither of which is NaN).
#[inline(always)]
fn larger_of<P: Pack>(a: P, b: P) -> P {
    a.lt(b).blend(b, a)
}

/// One step of size `h[l]` from `y` (with `k₁ = f(y)`) in every lane: 6 evaluations.
#[inline(always)]
pub(crate) fn step<P: Pack>(
    f: &Field<P>,
    y: &States<P>,
    k1: &States<P>,
    h: P,
    rtol: P,
    atol: P,
) -> Stages<P> {
    // Each evaluation reads the field through an opaque copy of its reference: else the
    // compiler merges the seven evaluations' loads of each coefficient into one and keeps
    // it live across the step, in a spill slot it first copies it to (≈ 65 copies a step);
    // read afresh, each load folds into its arithmetic instruction.
    let fresh = core::hint::black_box::<&Field<P>>;
    let k2 = eval(fresh(f), &combine(y, h, A2, [k1]));
    let k3 = eval(fresh(f), &combine(y, h, A3, [k1, &k2]));
    let k4 = eval(fresh(f), &combine(y, h, A4, [k1, &k2, &k3]));
    let k5 = eval(fresh(f), &combine(y, h, A5, [k1, &k2, &k3, &k4]));
    let k6 = eval(fresh(f), &combine(y, h, A6, [k1, &k2, &k3, &k4, &k5]));
    let y1 = combine(y, h, B, [k1, &k3, &k4, &k5, &k6]);
    let one = P::splat(lit(1.0));
    let zero = P::splat(lit(0.0));
    let mut weight: States<P> = [zero; 7];
    for ((w, a), b) in weight.iter_mut().zip(y.iter()).zip(y1.iter()) {
        *w = one / rtol.mul_add(larger(a.abs(), b.abs()), atol);
    }
    let k7 = eval(fresh(f), &y1);
    let e = combine(&[zero; 7], h, E, [k1, &k3, &k4, &k5, &k6, &k7]);
    let mut r = [zero; 7];
    for ((ri, ei), wi) in r.iter_mut().zip(e.iter()).zip(weight.iter()) {
        *ri = ei.abs() * *wi;
    }
    // The fused packs: the largest `rᵢ ≥ 0` by a tree (3 compares and blends deep rather
    // than 7), the scalar fold's value where no `rᵢ` is NaN (a NaN sum says one is; the
    // fold below then gives the scalar rule's result).
    let no_nan = || {
        let sum = ((r[0] + r[1]) + (r[2] + r[3])) + ((r[4] + r[5]) + r[6]);
        sum.ne(sum).bits() == 0
    };
    let err = if P::FUSED && no_nan() {
        larger_of(
            larger_of(larger_of(r[0], r[1]), larger_of(r[2], r[3])),
            larger_of(larger_of(r[4], r[5]), r[6]),
        )
    } else {
        let mut err = zero;
        for ri in r {
            // `!(r <= err)` also propagates NaN into a rejection (the scalar rule).
            err = (!ri.le(err)).blend(ri, err);
        }
        err
    };
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

/// The dense-output coefficients `r₁..r₅` of one component in every lane
/// (`integrator::events::Step::poly_of`'s operations, in its order):
/// `r₂ = y₁ − y₀`, `r₃ = h f₀ − r₂`, `r₄ = (r₂ − h f₁) − r₃`, `r₅ = h Σ dᵢ kᵢ`.
#[inline(always)]
pub(crate) fn poly<P: Pack>(h: P, y0: P, y1: P, f0: P, f1: P, mid: [P; 4]) -> [P; 5] {
    let [d1, d3, d4, d5, d6, d7] = crate::integrator::events::DP_DENSE;
    let [k3, k4, k5, k6] = mid;
    let r2 = y1 - y0;
    let r3 = h.mul_sub(f0, r2);
    let r4 = h.neg_mul_add(f1, r2) - r3;
    let mut sum = P::splat(lit(d1)).mul_add(f0, P::splat(lit(d3)) * k3);
    sum = P::splat(lit(d4)).mul_add(k4, sum);
    sum = P::splat(lit(d5)).mul_add(k5, sum);
    sum = P::splat(lit(d6)).mul_add(k6, sum);
    let r5 = h * P::splat(lit(d7)).mul_add(f1, sum);
    [y0, r2, r3, r4, r5]
}

/// The interpolant `r₁ + θ (r₂ + (1−θ) (r₃ + θ (r₄ + (1−θ) r₅)))` at `θ` in every lane
/// (`Poly::at`).
#[inline(always)]
pub(crate) fn at<P: Pack>(r: &[P; 5], th: P) -> P {
    let [r1, r2, r3, r4, r5] = *r;
    let th1 = P::splat(lit(1.0)) - th;
    th.mul_add(th1.mul_add(th.mul_add(th1.mul_add(r5, r4), r3), r2), r1)
}

/// The interpolant's value and slope in `θ` in every lane (`Poly::with_slope`).
#[inline(always)]
fn with_slope<P: Pack>(r: &[P; 5], th: P) -> (P, P) {
    let [r1, r2, r3, r4, r5] = *r;
    let th1 = P::splat(lit(1.0)) - th;
    let c = th1.mul_add(r5, r4);
    let b = th.mul_add(c, r3);
    let db = th.neg_mul_add(r5, c);
    let (q, dq) = (th1.mul_add(b, r2), th1.mul_sub(db, b));
    (th.mul_add(q, r1), th.mul_add(dq, q))
}

/// `integrator::events::find_root` in the lanes of the mask `live`, each on its own
/// interpolant `r` less `c` (`c = 0` for the apex's `v_y`: `x − 0 = x` bit for bit), bracket
/// `[a, b]` and end values: the scalar iteration's operations and tests, a lane leaving
/// the loop (its result kept) where the scalar one returns. Runs until every lane is done
/// (at most 64 iterations, as the scalar one).
#[inline(always)]
pub(crate) fn find_root<T: Real, P: Pack<Scalar = T>>(
    live: P,
    r: &[P; 5],
    c: P,
    a: P,
    b: P,
    fa: P,
    fb: P,
) -> P {
    let zero = P::splat(lit(0.0));
    let half = P::splat(lit(0.5));
    let tiny = P::splat(T::default_epsilon() * lit(4.0));
    // The Newton step small enough to stop at: the scalar `4ε`, or on the fused packs
    // (results within 1e-9, not bit for bit) `√ε`, one iteration sooner: the step taken
    // then leaves an error of the order of its square (Newton's quadratic convergence),
    // ≈ ε again, so the root moves by a few ulps rather than not at all.
    let tiny_step = if P::FUSED {
        P::splat(lit(1.0 / 67_108_864.0)) // 2⁻²⁶ = √ε of `f64` (the fused packs')
    } else {
        tiny
    };
    let (mut a, mut b, mut fa) = (a, b, fa);
    // `fb == 0` returns `b` (`!(x ≠ 0)` is the ordered `x == 0`).
    let mut out = b;
    let mut live = live & fb.ne(zero);
    let denom = fb - fa;
    let mut x = denom
        .ne(zero)
        .blend(a.mul_sub(fb, b * fa) / denom, (a + b) * half);
    for _ in 0..64 {
        if live.bits() == 0 {
            return out;
        }
        let lt = a.lt(b);
        let (lo, hi) = (lt.blend(a, b), lt.blend(b, a));
        x = (lo.lt(x) & x.lt(hi)).blend(x, (a + b) * half);
        let (v, slope) = with_slope(r, x);
        let fx = v - c;
        let hit = live & !fx.ne(zero);
        out = hit.blend(x, out);
        live = live & !hit;
        let same = !(zero.lt(fx) ^ zero.lt(fa));
        let (move_a, move_b) = (live & same, live & !same);
        a = move_a.blend(x, a);
        fa = move_a.blend(fx, fa);
        b = move_b.blend(x, b);
        let step = fx / slope;
        let next = x - step;
        let stop = live & (step.abs().le(tiny_step) | (b - a).abs().le(tiny));
        let lt = a.lt(b);
        let (lo, hi) = (lt.blend(a, b), lt.blend(b, a));
        out = stop.blend((lo.lt(next) & next.lt(hi)).blend(next, x), out);
        live = live & !stop;
        x = next;
    }
    live.blend(x, out)
}
