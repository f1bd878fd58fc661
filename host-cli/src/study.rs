//! `carry bench accuracy`: the accuracy study (issue 6). A stub until it is built.

use std::path::PathBuf;

/// Options of the accuracy study.
#[derive(Debug, Clone, Default)]
pub struct StudyOptions {
    /// Print JSON instead of a table.
    pub json: bool,
    /// Also write an SVG chart here.
    pub svg: Option<PathBuf>,
    /// A quick, smaller study.
    pub quick: bool,
}

/// Runs the accuracy study.
///
/// # Errors
/// Always, for now: the study is not built yet.
pub fn run(options: &StudyOptions) -> Result<(), String> {
    let _ = (options.json, &options.svg, options.quick);
    Err("the accuracy study is not built yet".into())
}
