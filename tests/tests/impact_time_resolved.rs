//! A time-resolved check of the gear effect's two directions (docs/impact.md §0.5): the ball
//! against a driver head through the contact, not as one impulse — a linear normal
//! spring–dashpot (contact time τ, restitution e), a linear tangential spring capped by
//! Coulomb friction (Cross, Am. J. Phys. 70 (2002) 1093; frequency ratio r = ω_t/ω_n), both
//! bodies rigid otherwise, explicit time steps of 10 ns, flat face, face frame (x out of the
//! face, y up it, z toward the toe). It answers one question: does the contact itself pass the
//! vertical gear effect (along the slip the lofted face already gives the ball) differently
//! from the horizontal one (across it)? And does the face's turn during the contact matter
//! (the face held as at first touch, or turning with the head)? Prints the spin per mm of
//! strike height, the sidespin per mm toward the toe and their ratio, to compare with the
//! inertia ratio Iyy/Izz, and the launch and start-line responses. A third face ("at max
//! compression") is held as the turning face stands at maximum compression: TrackMan's
//! dynamic loft and face angle are the face's "at the time of maximum compression"
//! (TrackMan's parameter definitions), so a model fed them holds that face.
//!
//! `cargo test -p carry-tests --test impact_time_resolved -- --ignored --nocapture`

use nalgebra::Vector3;

const BALL_KG: f64 = 0.045_93;
const BALL_M: f64 = 0.021_335;
const HEAD_KG: f64 = 0.2;
/// The `driver` preset's principal inertias (kg·m²), taken in the face frame.
const HEAD_KGM2: [f64; 3] = [3.4e-4, 4.8e-4, 3.2e-4];
const CLUB_MPS: f64 = 45.0;
const LOFT_DEG: f64 = 12.8;
const CG_DEPTH_M: f64 = 0.04;

struct Out {
    spin: Vector3<f64>,
    velocity: Vector3<f64>,
    slip_s: f64,
    /// The head's rotation since first touch at maximum compression (rad, small angles).
    turn_at_max_compression: Vector3<f64>,
}

/// How the face moves during the contact.
#[derive(Clone, Copy)]
enum Face {
    /// Held as at first touch.
    Held,
    /// Turning with the head.
    Turns,
    /// Held, turned by this small rotation from first touch (rad).
    HeldTurned(Vector3<f64>),
}

/// One strike `h` up and `z` toward the toe; `r` the tangential/normal frequency ratio, `mu`
/// the friction coefficient; `face`: held, or turning with the head during the contact (its
/// normal and the contact point's lever rotate by the head's small rotation angle), or held
/// at a given turn.
fn strike(h: f64, z: f64, r: f64, mu: f64, face: Face) -> Out {
    let (tau, e, dt): (f64, f64, f64) = (0.45e-3, 0.8, 1e-8);
    let ib = 0.4 * BALL_KG * BALL_M * BALL_M;
    let n0 = Vector3::x();
    let loft = LOFT_DEG.to_radians();
    let (mut vb, mut wb) = (Vector3::zeros(), Vector3::<f64>::zeros());
    let mut vc = Vector3::new(CLUB_MPS * loft.cos(), -CLUB_MPS * loft.sin(), 0.0);
    let mut wc = Vector3::<f64>::zeros();
    let rc0 = Vector3::new(CG_DEPTH_M, h, z);
    // the head's rotation since first touch (small angles)
    let mut turn = Vector3::<f64>::zeros();
    let mut turn_at_max_compression = Vector3::<f64>::zeros();
    let mn = 1.0 / (1.0 / BALL_KG + 1.0 / HEAD_KG);
    let kn = mn * (std::f64::consts::PI / tau).powi(2);
    let zeta = -e.ln() / (std::f64::consts::PI.powi(2) + e.ln().powi(2)).sqrt();
    let cn = 2.0 * zeta * (kn * mn).sqrt();
    let mt = 1.0 / (1.0 / BALL_KG + BALL_M * BALL_M / ib + 1.0 / HEAD_KG);
    let kt = mt * (r * std::f64::consts::PI / tau).powi(2);
    let (mut dn, mut xi, mut t, mut slip_s, mut started) =
        (0.0, Vector3::<f64>::zeros(), 0.0, 0.0, false);
    while t < 5.0 * tau {
        let rotated =
            |turn: &Vector3<f64>| ((n0 + turn.cross(&n0)).normalize(), rc0 + turn.cross(&rc0));
        let (n, rc) = match face {
            Face::Held => (n0, rc0),
            Face::Turns => rotated(&turn),
            Face::HeldTurned(fixed) => rotated(&fixed),
        };
        let rb = -n * BALL_M;
        let u = (vb + wb.cross(&rb)) - (vc + wc.cross(&rc));
        let dnd = -u.dot(&n);
        if started && dnd <= 0.0 && turn_at_max_compression == Vector3::zeros() {
            turn_at_max_compression = turn;
        }
        dn += dnd * dt;
        xi += (u - n * u.dot(&n)) * dt;
        // the tangential spring stays in the (turning) contact plane
        xi -= n * xi.dot(&n);
        if dn <= 0.0 && started {
            break;
        }
        started |= dn > 0.0;
        let fnorm = if dn > 0.0 {
            (kn * dn + cn * dnd).max(0.0)
        } else {
            0.0
        };
        let mut ft = -xi * kt;
        let m = ft.norm();
        if m > mu * fnorm && m > 0.0 {
            ft *= mu * fnorm / m;
            xi = -ft / kt;
            slip_s += dt;
        }
        let f = n * fnorm + ft;
        vb += f * (dt / BALL_KG);
        wb += rb.cross(&f) * (dt / ib);
        vc -= f * (dt / HEAD_KG);
        let tq = rc.cross(&-f);
        wc += Vector3::new(
            tq.x / HEAD_KGM2[0],
            tq.y / HEAD_KGM2[1],
            tq.z / HEAD_KGM2[2],
        ) * dt;
        turn += wc * dt;
        t += dt;
    }
    Out {
        spin: wb,
        velocity: vb,
        slip_s,
        turn_at_max_compression,
    }
}

#[test]
#[ignore = "slow (10 ns steps); prints the table docs/impact.md §0.5 quotes"]
fn vertical_and_horizontal_gear_effect_through_the_contact() {
    let rpm = 60.0 / std::f64::consts::TAU;
    println!(
        "| r | μ | face | centre spin rpm | slip ms | vertical rpm/mm (%/mm) | sidespin rpm/mm | vertical/horizontal | launch °/mm up | start °/mm toe | turn at max compression, 10 mm up (°) |"
    );
    println!("|---|---|---|---|---|---|---|---|---|---|---|");
    for (r, mu) in [
        (0.506, 0.4),
        (0.506, 0.2),
        (0.506, 0.1),
        (1.4, 0.4),
        (1.4, 0.15),
    ] {
        // The face at maximum compression of each strike, from the turning face's run.
        let at_max = |h: f64, z: f64| {
            Face::HeldTurned(strike(h, z, r, mu, Face::Turns).turn_at_max_compression)
        };
        let faces: [(&str, [Face; 5]); 3] = [
            ("held", [Face::Held; 5]),
            ("turns", [Face::Turns; 5]),
            (
                "at max compression",
                [
                    at_max(0.0, 0.0),
                    at_max(0.01, 0.0),
                    at_max(-0.01, 0.0),
                    at_max(0.0, 0.01),
                    at_max(0.0, -0.01),
                ],
            ),
        ];
        for (name, [fc, fu, fd, ft, fh]) in faces {
            let c = strike(0.0, 0.0, r, mu, fc);
            let (up, down) = (strike(0.01, 0.0, r, mu, fu), strike(-0.01, 0.0, r, mu, fd));
            let (toe, heel) = (strike(0.0, 0.01, r, mu, ft), strike(0.0, -0.01, r, mu, fh));
            let centre = c.spin.norm() * rpm;
            let vertical = (up.spin.norm() - down.spin.norm()) * rpm / 20.0;
            let side = (toe.spin.y - heel.spin.y) * rpm / 20.0;
            let ratio = (vertical / side).abs();
            let elevation = |o: &Out| o.velocity.y.atan2(o.velocity.x).to_degrees();
            let azimuth = |o: &Out| o.velocity.z.atan2(o.velocity.x).to_degrees();
            println!(
                "| {r} | {mu} | {name} | {centre:.0} | {:.3} | {vertical:+.1} ({:+.2}) | {side:+.1} | {ratio:.2} | {:+.3} | {:+.3} | {:.3} |",
                c.slip_s * 1e3,
                vertical / centre * 100.0,
                (elevation(&up) - elevation(&down)) / 20.0,
                (azimuth(&toe) - azimuth(&heel)) / 20.0,
                up.turn_at_max_compression.norm().to_degrees(),
            );
            assert!(centre.is_finite() && ratio.is_finite());
        }
    }
    println!("Iyy/Izz = {:.2}", HEAD_KGM2[1] / HEAD_KGM2[2]);
}
