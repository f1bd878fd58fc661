//! `compute::run_rows` (the lanes kernel for batches, issue 37) against `compute::run` row
//! by row: flight and shot modes, f64 and f32, winds per row, a ground and the seed's model
//! (scalar fallbacks), and bad rows among them. Bit for bit on the exact packs; within
//! 1e-9 relative where the CPU has FMA (the fused `f64` kernel, docs/performance.md).
use carry_io::compute::{self, Mode, Numerics, Precision};
use carry_io::params::Params;

fn rows() -> Vec<Params> {
    let mut out = Vec::new();
    for i in 0..97u32 {
        let x = f64::from(i);
        let mut p = Params::default();
        p.launch.ball_speed_mps = 35.0 + (x * 7.3) % 45.0;
        p.launch.launch_angle_deg = 6.0 + (x * 3.1) % 30.0;
        p.launch.launch_direction_deg = (x * 1.7) % 6.0 - 3.0;
        p.launch.backspin_rpm = Some(1800.0 + (x * 613.0) % 8000.0);
        p.launch.sidespin_rpm = Some((x * 211.0) % 1600.0 - 800.0);
        p.delivery.club_speed_mps = 30.0 + (x * 2.9) % 22.0;
        if i % 3 == 0 {
            p.scene.wind_speed_mps = Some((x * 0.7) % 9.0);
            p.scene.wind_direction_deg = Some((x * 37.0) % 360.0);
        }
        if i % 11 == 0 {
            p.launch.ball_speed_mps = f64::NAN;
            p.delivery.club_speed_mps = -1.0;
        }
        if i % 13 == 0 {
            p.scene.aero = Some(carry_core::aero::AeroModel::quintavalla());
        }
        if i % 17 == 0 {
            p.scene.wind_exponent = Some(1.0 / 7.0);
        }
        out.push(p);
    }
    out
}

#[test]
fn rows_together_equal_rows_one_by_one() {
    let rows = rows();
    let fused = carry_io::lanes::cpu().is_some_and(|c| c.fma());
    for precision in [Precision::F64, Precision::F32] {
        let n = Numerics {
            precision,
            ..Numerics::default()
        };
        for mode in [Mode::Flight, Mode::Shot] {
            let together = compute::run_rows(mode, &rows, &n);
            assert_eq!(together.len(), rows.len());
            let mut failed = 0;
            for (p, got) in rows.iter().zip(&together) {
                let want = compute::run(mode, p, &n);
                match (got, &want) {
                    (Ok(a), Ok(b)) => {
                        let (a, b) = (serde_json::to_value(a), serde_json::to_value(b));
                        let (Ok(a), Ok(b)) = (a, b) else {
                            panic!("reports to JSON")
                        };
                        if fused && precision == Precision::F64 {
                            close(&a, &b);
                        } else {
                            assert_eq!(a, b);
                        }
                    }
                    (Err(a), Err(b)) => {
                        failed += 1;
                        assert_eq!(a.as_column(), b.as_column());
                    }
                    _ => panic!("{mode:?}: {got:?} against {want:?}"),
                }
            }
            assert!(failed >= 9, "the bad rows fail ({failed})");
        }
    }
}

/// The same JSON, numbers within 1e-9 relative (at least 1 of scale: 1 m, 1 s, 1 rad...).
fn close(a: &serde_json::Value, b: &serde_json::Value) {
    use serde_json::Value;
    match (a, b) {
        (Value::Number(x), Value::Number(y)) => {
            let (x, y) = (
                x.as_f64().unwrap_or(f64::NAN),
                y.as_f64().unwrap_or(f64::NAN),
            );
            assert!((x - y).abs() <= 1e-9 * y.abs().max(1.0), "{x} against {y}");
        }
        (Value::Array(x), Value::Array(y)) => {
            assert_eq!(x.len(), y.len());
            x.iter().zip(y).for_each(|(x, y)| close(x, y));
        }
        (Value::Object(x), Value::Object(y)) => {
            assert_eq!(x.len(), y.len());
            for (k, v) in x {
                close(v, y.get(k).unwrap_or_else(|| panic!("{k} missing")));
            }
        }
        _ => assert_eq!(a, b),
    }
}
