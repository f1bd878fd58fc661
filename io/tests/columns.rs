//! `columns::run_block` (the Python package's rows, issue 37's cheap wrapper) against
//! `compute::run` row by row: every value bit for bit (within 1e-9 relative on the fused f64 kernel) and every message, for launch-only
//! flights (the fast path), rows that vary the scene, shots, f64 and f32, SI and imperial,
//! bad numbers among the rows, and bases whose ball, scene or spins fail.
use carry_io::columns::{Columns, run_block};
use carry_io::compute::{self, Mode, Numerics, Precision};
use carry_io::params::{Key, Kind, Params, Value};
use carry_io::report::{csv_columns, csv_values};
use carry_io::units::Units;

/// `n` numbers for `key` that wander over a plausible range, with a NaN, an infinity and
/// (for the spin) a negative value at fixed rows.
fn column(key: Key, n: usize) -> Vec<f64> {
    (0..n)
        .map(|i| {
            let x = i as f64;
            match (key, i % 29) {
                (_, 5) if key == Key::BallSpeed => f64::NAN,
                (_, 9) if key == Key::LaunchAngle => f64::INFINITY,
                (_, 13) if key == Key::Spin => -100.0,
                _ => match key {
                    Key::BallSpeed => 30.0 + (x * 7.3) % 50.0,
                    Key::LaunchAngle => 4.0 + (x * 3.1) % 30.0,
                    Key::LaunchDirection => (x * 1.7) % 10.0 - 5.0,
                    Key::Spin => 1500.0 + (x * 613.0) % 8000.0,
                    Key::SpinAxis => (x * 2.3) % 40.0 - 20.0,
                    Key::Backspin => 1500.0 + (x * 577.0) % 8000.0,
                    Key::Sidespin => (x * 211.0) % 1600.0 - 800.0,
                    Key::ClubSpeed => 25.0 + (x * 2.9) % 30.0,
                    Key::AttackAngle => (x * 0.37) % 8.0 - 5.0,
                    Key::FaceAngle => (x * 0.53) % 6.0 - 3.0,
                    Key::WindSpeed => (x * 0.7) % 9.0,
                    Key::WindDirection => (x * 37.0) % 360.0,
                    Key::Temperature => 5.0 + (x * 1.3) % 30.0,
                    _ => 1.0,
                },
            }
        })
        .collect()
}

/// What the run gives for row `i`, row by row: its values, or its message.
fn expected(
    mode: Mode,
    cols: &Columns<'_>,
    n: &Numerics,
    ground: bool,
    i: usize,
) -> Result<Vec<f64>, String> {
    let mut p = *cols.base;
    for (key, column) in cols.keys.iter().zip(cols.values) {
        let x = column[i];
        let ok = match key.kind() {
            Kind::Radius => !x.is_nan() && x != f64::NEG_INFINITY,
            _ => x.is_finite(),
        };
        if !ok {
            return Err(format!("{}: '{x}' is not a finite number", key.name()));
        }
        key.set(&mut p, cols.units, Value::Number(x));
    }
    let r = compute::run(mode, &p, n).map_err(|e| e.as_column())?;
    let mut out = Vec::new();
    csv_values(&mut out, mode, ground, &r);
    Ok(out)
}

/// Runs the rows in blocks of 37 and compares each with [`expected`]; returns how many
/// rows failed.
fn check(mode: Mode, base: &Params, units: Units, keys: &[Key], n: &Numerics) -> usize {
    let rows = 150;
    let ground = !base.scene.ground.is_empty() && mode != Mode::Impact;
    let data: Vec<Vec<f64>> = keys.iter().map(|k| column(*k, rows)).collect();
    let values: Vec<&[f64]> = data.iter().map(Vec::as_slice).collect();
    let cols = Columns {
        base,
        units,
        keys,
        values: &values,
    };
    let width = csv_columns(mode, ground).len();
    let mut out = vec![0.0; rows * width];
    let mut failed = Vec::new();
    for (b, chunk) in out.chunks_mut(37 * width).enumerate() {
        failed.extend(match n.precision {
            Precision::F64 => run_block::<f64>(mode, &cols, n, ground, b * 37, chunk, width),
            Precision::F32 => run_block::<f32>(mode, &cols, n, ground, b * 37, chunk, width),
        });
    }
    let fused = n.precision == Precision::F64 && carry_io::lanes::cpu().is_some_and(|c| c.fma());
    let mut failures = failed.iter();
    let mut count = 0;
    for i in 0..rows {
        let got = &out[i * width..(i + 1) * width];
        match expected(mode, &cols, n, ground, i) {
            Ok(want) => {
                // Bit for bit, except on the fused `f64` kernel (a CPU with FMA: within
                // 1e-9 relative, at least 1 of scale; docs/performance.md, "Lanes kernel").
                let same = want.iter().zip(got).all(|(a, b)| {
                    a.to_bits() == b.to_bits()
                        || (fused && (a - b).abs() <= 1e-9 * a.abs().max(1.0))
                });
                assert!(same, "{mode:?} {keys:?} row {i}: {got:?} against {want:?}");
            }
            Err(message) => {
                count += 1;
                assert!(got.iter().all(|x| x.is_nan()), "row {i}: NaN when failed");
                let f = failures.next();
                assert_eq!(
                    f.map(|(j, e)| (*j, e.as_column())),
                    Some((i, message)),
                    "{mode:?} {keys:?}"
                );
            }
        }
    }
    assert!(failures.next().is_none(), "no other failures");
    count
}

const LAUNCH: [Key; 5] = [
    Key::BallSpeed,
    Key::LaunchAngle,
    Key::LaunchDirection,
    Key::Spin,
    Key::SpinAxis,
];

#[test]
fn launch_only_flights_equal_the_run() {
    for precision in [Precision::F64, Precision::F32] {
        let n = Numerics {
            precision,
            ..Numerics::default()
        };
        let still = Params::default();
        let mut windy = Params::default();
        windy.scene.wind_speed_mps = Some(4.0);
        windy.scene.wind_direction_deg = Some(30.0);
        let mut seed = Params::default();
        seed.scene.aero = Some(carry_core::aero::AeroModel::quintavalla());
        let mut fairway = Params::default();
        Key::Ground.set(
            &mut fairway,
            Units::Si,
            Key::Ground.parse("fairway").expect("a surface"),
        );
        for base in [&still, &windy, &seed, &fairway] {
            for units in [Units::Si, Units::Imperial] {
                let failed = check(Mode::Flight, base, units, &LAUNCH, &n);
                // NaN speeds, infinite angles, negative spins.
                assert!(failed >= 15, "{failed}");
            }
        }
        let two = [Key::BallSpeed, Key::Backspin, Key::Sidespin];
        check(Mode::Flight, &still, Units::Si, &two, &n);
    }
}

#[test]
fn bad_bases_fail_every_row_as_the_run_does() {
    let n = Numerics::default();
    // The spins given twice: every good row fails on the launch.
    let mut both = Params::default();
    both.launch.backspin_rpm = Some(3000.0);
    let failed = check(Mode::Flight, &both, Units::Si, &LAUNCH, &n);
    assert_eq!(failed, 150);
    // An invalid ball and an invalid scene: the rows' own errors first, then the base's.
    let ball = Params {
        ball_mass_kg: -1.0,
        ..Params::default()
    };
    assert_eq!(check(Mode::Flight, &ball, Units::Si, &LAUNCH, &n), 150);
    let mut air = Params::default();
    air.scene.humidity_pct = Some(250.0);
    assert_eq!(check(Mode::Flight, &air, Units::Si, &LAUNCH, &n), 150);
}

#[test]
fn rows_that_vary_the_scene_or_the_delivery_equal_the_run() {
    for precision in [Precision::F64, Precision::F32] {
        let n = Numerics {
            precision,
            ..Numerics::default()
        };
        let base = Params::default();
        let windy = [
            Key::BallSpeed,
            Key::LaunchAngle,
            Key::WindSpeed,
            Key::WindDirection,
        ];
        check(Mode::Flight, &base, Units::Imperial, &windy, &n);
        check(
            Mode::Flight,
            &base,
            Units::Si,
            &[Key::Temperature, Key::Spin],
            &n,
        );
        let delivery = [Key::ClubSpeed, Key::AttackAngle, Key::FaceAngle];
        for mode in [Mode::Shot, Mode::Impact] {
            check(mode, &base, Units::Si, &delivery, &n);
            let mut keys = delivery.to_vec();
            keys.extend([Key::WindSpeed, Key::WindDirection]);
            check(mode, &base, Units::Imperial, &keys, &n);
        }
    }
}

/// A value of each kind that [`Key::parse`] takes.
fn text(kind: Kind) -> &'static str {
    match kind {
        Kind::Number | Kind::Radius => "1.25",
        Kind::Vector | Kind::Tensor => "1,2,3",
        Kind::Preset => "7iron",
        Kind::Contact => "rolling",
        Kind::Aero => "quintavalla",
        Kind::Bool => "true",
        Kind::Ground => "green",
        Kind::Convention => "seed",
    }
}

#[test]
fn scene_and_launch_keys_are_the_ones_that_set_them() {
    for key in Key::ALL {
        let before = Params::default();
        let mut p = before;
        let value = key.parse(text(key.kind())).expect("a valid value");
        key.set(&mut p, Units::Si, value);
        assert_ne!(p, before, "{key:?} sets something");
        let scene = p.scene != before.scene
            || p.ball_mass_kg != before.ball_mass_kg
            || p.ball_radius_m != before.ball_radius_m;
        assert_eq!(key.is_scene(), scene, "{key:?}: scene or ball");
        let launch_only = p.launch != before.launch && {
            let mut q = p;
            q.launch = before.launch;
            q == before
        };
        assert_eq!(key.is_launch(), launch_only, "{key:?}: launch only");
    }
}
