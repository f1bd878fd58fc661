//! `carry.estimate`: club data from ball data over numpy columns — lab's typed
//! [`carry_lab::request::estimate`] per row (the CLI's `carry estimate` and `carry batch
//! estimate` call the same), rows in parallel, into the columns of
//! [`EstimateRecord::COLUMNS`].

use crate::args::{MEASURED, Request, check_value};
use crate::rows::Output;
use carry_io::error::{Failure, InputError};
use carry_io::params::Params;
use carry_lab::request::{EstimateRecord, MeasuredClub};

/// Which of the measured club data ([`MEASURED`]) the call gives, as options or columns.
fn given(req: &Request, options: &[(String, String)]) -> [bool; 5] {
    MEASURED
        .map(|k| req.keys.contains(&k) || options.iter().any(|(name, _)| name.as_str() == k.name()))
}

/// The measured club data of one row: what is given, read from the row's options (the
/// option table has converted them to SI and degrees).
fn measured(p: &Params, given: [bool; 5]) -> MeasuredClub {
    let d = &p.delivery;
    MeasuredClub {
        club_speed_mps: given[0].then_some(d.club_speed_mps),
        attack_angle_deg: d.attack_angle_deg.filter(|_| given[1]),
        club_path_deg: given[2].then_some(d.club_path_deg),
        face_angle_deg: given[3].then_some(d.face_angle_deg),
        dynamic_loft_deg: d.dynamic_loft_deg.filter(|_| given[4]),
    }
}

/// One row's options and measured club data.
fn row(
    req: &Request,
    given: [bool; 5],
    columns: &[&[f64]],
    i: usize,
) -> Result<(Params, MeasuredClub), InputError> {
    let mut p = req.base;
    for (key, column) in req.keys.iter().zip(columns) {
        let value = check_value(*key, column[i])?;
        key.set(&mut p, req.units, value);
    }
    Ok((p, measured(&p, given)))
}

/// Estimates every row of `columns` (`columns[j]` holds the values of `req.keys[j]`) on
/// all cores.
///
/// # Errors
/// The thread pool cannot start.
pub fn run(
    req: &Request,
    options: &[(String, String)],
    columns: &[&[f64]],
    rows: usize,
) -> Result<Output, Failure> {
    let given = given(req, options);
    let inputs: Vec<_> = (0..rows).map(|i| row(req, given, columns, i)).collect();
    let results = carry_lab::request::estimate_rows(&inputs, &req.numerics, None)?;
    let width = EstimateRecord::COLUMNS.len();
    let mut data = vec![f64::NAN; rows * width];
    let mut failed = Vec::new();
    for (i, (r, slot)) in results.iter().zip(data.chunks_exact_mut(width)).enumerate() {
        match r {
            Ok(r) => slot.copy_from_slice(&r.values()),
            Err(e) => failed.push((i, e.as_column())),
        }
    }
    Ok(Output {
        names: EstimateRecord::COLUMNS.to_vec(),
        data,
        failed,
    })
}
