//! The batch report's numeric rows against its CSV rows.

use carry_io::compute::{Numerics, run};
use carry_io::mode::Mode;
use carry_io::params::{Key, Params};
use carry_io::report::{csv_columns, csv_values, single_csv};
use carry_io::units::Units;

/// The numeric row matches the CSV row, column for column, in every mode.
#[test]
fn csv_values_follow_the_csv_columns() {
    let mut p = Params::default();
    Key::Ground.set(
        &mut p,
        Units::Si,
        Key::Ground.parse("fairway").expect("a surface"),
    );
    for mode in [Mode::Impact, Mode::Flight, Mode::Shot] {
        let r = run(mode, &p, &Numerics::default()).expect("the defaults fly");
        let ground = mode != Mode::Impact;
        let mut values = Vec::new();
        csv_values(&mut values, mode, ground, &r);
        let text = String::from_utf8(single_csv(mode, &r)).expect("UTF-8");
        let row: Vec<&str> = text.lines().nth(1).unwrap_or_default().split(',').collect();
        assert_eq!(values.len(), csv_columns(mode, ground).len());
        assert_eq!(values.len(), row.len());
        for (v, t) in values.iter().zip(row) {
            let t = match t {
                "true" => 1.0,
                "false" => 0.0,
                t => t.parse().expect("a number"),
            };
            assert_eq!(*v, t);
        }
    }
}
