//! One analysis over many rows in parallel: each row's parameters and request (or the error
//! its input had) through a per-shot function on a pool of worker threads, results in row
//! order. `carry batch estimate` (club data from ball data, or the launch from the flight)
//! and Python's array calls run their rows through it.

use carry_io::error::{Failure, InputError};
use carry_io::params::Params;

/// `run` over `rows` in parallel on `threads` workers (`None`: all cores), the results in
/// row order. A row's input error stays its result; a failure other than an input error is
/// reported as an input error of `option` (the one row fails, the others run).
///
/// # Errors
/// The thread pool cannot start.
pub fn par_rows<R, Out, F>(
    rows: &[Result<(Params, R), InputError>],
    threads: Option<usize>,
    option: &'static str,
    run: F,
) -> Result<Vec<Result<Out, InputError>>, Failure>
where
    R: Sync,
    Out: Send,
    F: Fn(&Params, &R) -> Result<Out, Failure> + Sync,
{
    use rayon::prelude::*;
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads.unwrap_or(0))
        .build()
        .map_err(|e| Failure::Other(e.to_string()))?;
    Ok(pool.install(|| {
        rows.par_iter()
            .map(|row| {
                let (p, r) = row.as_ref().map_err(Clone::clone)?;
                run(p, r).map_err(|e| match e {
                    Failure::Input(e) => e,
                    other => InputError::new(option, format!("{other:?}")),
                })
            })
            .collect()
    }))
}
