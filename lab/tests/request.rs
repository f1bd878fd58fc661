//! The typed analysis requests (`carry_lab::request`) the CLI and Python share: options given
//! with the shot are held or noted, in f32 and f64, and the fit request's exclusive options.

use carry_io::compute::{Numerics, Precision};
use carry_io::params::{Key, Params, Value};
use carry_io::units::Units;
use carry_lab::fit::request::FitRequest;
use carry_lab::request::{OptimizeOutcome, OptimizeRequest, SweepRequest};

fn seven_iron() -> Params {
    let mut p = Params::default();
    Key::Club.set(
        &mut p,
        Units::Si,
        Key::Club.parse("7iron").expect("a preset"),
    );
    Key::ClubSpeed.set(&mut p, Units::Si, Value::Number(40.0));
    p
}

fn numerics(precision: Precision) -> Numerics {
    Numerics {
        precision,
        ..Numerics::default()
    }
}

#[test]
fn a_given_angle_is_held_and_a_range_frees_it_with_a_note() {
    for precision in [Precision::F32, Precision::F64] {
        let n = numerics(precision);
        let mut p = seven_iron();
        Key::AttackAngle.set(&mut p, Units::Si, Value::Number(-2.0));
        let request = OptimizeRequest {
            starts: 1,
            dynamic_loft_range: Some([18.0, 32.0]),
            ..OptimizeRequest::default()
        };
        let mut notes = Vec::new();
        let Ok(OptimizeOutcome::Optimum(held)) = request.run(&p, &n, &mut notes) else {
            panic!("{precision:?}: the search runs")
        };
        assert!(notes.is_empty(), "{notes:?}");
        assert_eq!(held.point.attack_angle_deg, -2.0, "{precision:?}");
        assert_eq!(held.flatness.len(), 1, "{precision:?}");

        let ranged = OptimizeRequest {
            attack_angle_range: Some([-5.0, 1.0]),
            ..request
        };
        let Ok(OptimizeOutcome::Optimum(free)) = ranged.run(&p, &n, &mut notes) else {
            panic!("{precision:?}: the search runs")
        };
        assert_eq!(notes.len(), 1, "{notes:?}");
        assert!(notes[0].contains("--attack-angle is ignored"), "{notes:?}");
        assert_eq!(free.flatness.len(), 2);
        // Freed, the optimizer finds at least the carry of the held angle.
        assert!(free.objective_value >= held.objective_value - 1e-3);
    }
}

#[test]
fn the_swing_notes_the_delivery_it_replaces() {
    let mut p = seven_iron();
    Key::FaceAngle.set(&mut p, Units::Si, Value::Number(1.0));
    let request = SweepRequest {
        ball_positions: Some([0.0, 0.01, 0.01]),
        ..SweepRequest::default()
    };
    let mut notes = Vec::new();
    let sweep = request.run(&p, &numerics(Precision::F64), &mut notes);
    assert!(sweep.is_ok());
    // The club speed and the face angle were given.
    assert_eq!(notes.len(), 2, "{notes:?}");
    assert!(
        notes.iter().any(|n| n.contains("--face-angle")),
        "{notes:?}"
    );
}

#[test]
fn the_fit_request_rejects_options_that_exclude_each_other() {
    let base = FitRequest {
        family: "modern".into(),
        ..FitRequest::default()
    };
    assert!(base.check().is_ok());
    for (bad, key) in [
        (
            FitRequest {
                air_density: Some(1.2),
                temperature: Some(20.0),
                ..base.clone()
            },
            "air_density",
        ),
        (
            FitRequest {
                pressure: Some(101_325.0),
                altitude: Some(100.0),
                ..base.clone()
            },
            "pressure",
        ),
        (
            FitRequest {
                output: Some("m.toml".into()),
                evaluate: Some("tour2023".into()),
                ..base.clone()
            },
            "output",
        ),
    ] {
        assert_eq!(bad.check().map_err(|e| e.key), Err(key));
    }
}

#[test]
fn the_estimate_columns_are_the_record_s_fields_in_order() {
    let mut p = Params::default();
    for (key, value) in [
        (Key::BallSpeed, 68.0),
        (Key::LaunchAngle, 12.5),
        (Key::Spin, 2700.0),
        (Key::SpinAxis, -3.0),
    ] {
        key.set(&mut p, Units::Si, Value::Number(value));
    }
    let club = carry_lab::request::MeasuredClub {
        club_speed_mps: Some(46.0),
        ..Default::default()
    };
    let r = carry_lab::request::estimate(&p, &numerics(Precision::F64), &club).expect("estimate");
    let doc = serde_json::to_value(r).expect("serialisable");
    let fields = doc.as_object().expect("an object");
    let values = r.values();
    for (k, name) in carry_lab::request::EstimateRecord::COLUMNS
        .iter()
        .enumerate()
    {
        let v = &fields[*name];
        let number = v
            .as_f64()
            .or_else(|| v.as_bool().map(|b| f64::from(u8::from(b))));
        assert_eq!(number, Some(values[k]), "{name}");
    }
    assert_eq!(
        fields.len(),
        carry_lab::request::EstimateRecord::COLUMNS.len()
    );
    assert!(!r.club_speed_estimated);
}

/// A single-drive export (synthetic rows in the shared file's format) is recognised by its
/// header: its premium indoor row is a fit row with its session; the outdoor and range-ball
/// rows are left out and noted.
#[test]
fn a_single_drive_export_is_read_by_its_header() {
    use carry_lab::fit::request::{Conditions, read_input};
    let header = "Ball,Club Speed,Attack Angle,Club Path,Dyn. Loft,Face Angle,Face To Path,Ball Speed,Smash Factor,Launch Angle,Launch Direction,Spin Rate,Spin Axis,Max Height - Height,Last data Point - Length,Last data Point - Side,Last data Point - Height,Last data Point - Time,Carry Flat - Length,Carry Flat - Side,Carry Flat - Land. Angle,Carry Flat - Ball Speed,Carry Flat - Time,Total,Side Total,Impact Offset,Impact Height
,[mph],[deg],[deg],[deg],[deg],[deg],[mph],[],[deg],[deg],[rpm],[deg],[ft],[yds],[yds],[yds],[s],[yds],[yds],[deg],[mph],[s],[yds],[yds],[mm],[mm]
";
    // Synthetic: a 145 mph, 12°, 2,500 rpm drive indoors; the same tracked outdoors; a
    // range ball indoors.
    let rows = "Premium,100,1,2,12,0.5,-1.5,145,1.45,12,0.4,2500,-3,90,6,0.1,1,0.1,235,-5,38,60,6.2,255,-6,,
Premium,100,1,2,12,0.5,-1.5,145,1.45,12,0.4,2500,-3,90,150,0.1,20,3,235,-5,38,60,6.2,255,-6,,
Limited Distance Soft,100,1,2,12,0.5,-1.5,145,1.45,12,0.4,2500,-3,90,6,0.1,1,0.1,220,-5,38,60,6.2,240,-6,,
";
    let path = std::env::temp_dir().join(format!("carry-drives-{}.csv", std::process::id()));
    std::fs::write(&path, format!("{header}{rows}")).expect("temp file");
    let read = read_input(&path, Units::Si, &Conditions::default());
    let _ = std::fs::remove_file(&path);
    let (rows, notes) = read.expect("a drives file");
    assert_eq!(rows.len(), 1);
    assert_eq!(rows[0].session, Some(0));
    assert!((rows[0].carry_m - 235.0 * 0.9144).abs() < 1e-9);
    assert!((rows[0].apex_m.unwrap_or(0.0) - 90.0 * 0.3048).abs() < 1e-9);
    assert!(
        notes[0].contains("1 outdoors") && notes[0].contains("1 other balls"),
        "{notes:?}"
    );
}
