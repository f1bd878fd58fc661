//! `compute::run_rows` (the lanes kernel for batches, issue 37) against `compute::run` row
//! by row: flight and shot modes, f64 and f32, winds per row, a ground and the seed's model
//! (scalar fallbacks), and bad rows among them.
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
                        assert_eq!(serde_json::to_string(a).ok(), serde_json::to_string(b).ok())
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
