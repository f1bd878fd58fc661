//! The `carry` command line: a shell over carry-io (options, runs, records, batch) and
//! carry-lab (analyses, fits). [`run`] parses (clap), dispatches and maps errors to one
//! line on stderr and an exit status (0 ok, 1 I/O, 2 invalid input; never a panic); the
//! binary (`src/main.rs`) is a thin shell over it. What is here: the grammar ([`cli`], the
//! option groups its commands and the analyses share ([`args`]) and
//! the commands' clap structs), the human table ([`table`]), plots ([`plot`]) and exit
//! codes. The modules are public for the fuzz target that fuzzes the grammar
//! (`fuzz/fuzz_targets/cli.rs`); no other crate depends on this one.
// Internal modules of an application, documented where it matters to their readers.
#![allow(missing_docs)]

pub mod analyses;
pub mod args;
use carry_io::{batch, compute, error, params, report};
pub mod cli;
pub mod clubs;
pub mod fit;
pub mod plot;
pub mod table;

use clap::Parser as _;
use cli::{BatchCmd, BenchCmd, Cli, Command, OutputArgs, PlotCmd};
use compute::Mode;
use error::Failure;
use params::Params;
use std::io::Write as _;
use std::process::ExitCode;

/// Exit status for invalid input (also clap's usage-error status).
pub const EXIT_INPUT: u8 = 2;
/// Exit status for an I/O failure (writing output, reading a file that exists).
pub const EXIT_IO: u8 = 1;

/// Runs the command line `args` (the first is the program name), writing to stdout and
/// stderr; returns the exit status.
pub fn run<I, T>(args: I) -> ExitCode
where
    I: IntoIterator<Item = T>,
    T: Into<std::ffi::OsString> + Clone,
{
    let cli = match Cli::try_parse_from(args) {
        Ok(cli) => cli,
        Err(e) => return usage_error(&e),
    };
    match dispatch(cli) {
        Ok(()) => ExitCode::SUCCESS,
        Err(Failure::Input(e)) => {
            let _ = writeln!(std::io::stderr(), "carry: {e}");
            ExitCode::from(EXIT_INPUT)
        }
        Err(Failure::Io(e)) if e.kind() == std::io::ErrorKind::BrokenPipe => ExitCode::SUCCESS,
        Err(Failure::Io(e)) => {
            let _ = writeln!(std::io::stderr(), "carry: {e}");
            ExitCode::from(EXIT_IO)
        }
        Err(Failure::Other(msg)) => {
            let _ = writeln!(std::io::stderr(), "carry: {msg}");
            ExitCode::from(EXIT_IO)
        }
    }
}

/// Help and version print as clap renders them; a usage error prints its first line only.
fn usage_error(e: &clap::Error) -> ExitCode {
    use clap::error::ErrorKind;
    if matches!(
        e.kind(),
        ErrorKind::DisplayHelp
            | ErrorKind::DisplayVersion
            | ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand
    ) {
        let _ = e.print();
        return ExitCode::from(u8::try_from(e.exit_code()).unwrap_or(EXIT_INPUT));
    }
    let _ = writeln!(std::io::stderr(), "carry: {}", usage_line(e));
    ExitCode::from(EXIT_INPUT)
}

/// One line for a clap usage error: `--option: reason` where clap says which option.
fn usage_line(e: &clap::Error) -> String {
    use clap::error::{ContextKind, ContextValue, ErrorKind};
    let option = |kind| match e.get(kind) {
        Some(ContextValue::String(s)) => s.split_whitespace().next().map(str::to_owned),
        Some(ContextValue::Strings(v)) => v
            .first()
            .and_then(|s| s.split_whitespace().next())
            .map(str::to_owned),
        _ => None,
    };
    let arg = option(ContextKind::InvalidArg);
    match (e.kind(), arg) {
        (ErrorKind::ValueValidation, Some(arg)) => {
            if let Some(reason) = std::error::Error::source(e) {
                return format!("{arg}: {reason}");
            }
        }
        (ErrorKind::MissingRequiredArgument, Some(arg)) => return format!("{arg}: is required"),
        (ErrorKind::InvalidValue, Some(arg)) => {
            let value = match e.get(ContextKind::InvalidValue) {
                Some(ContextValue::String(v)) => v.clone(),
                _ => String::new(),
            };
            let valid = match e.get(ContextKind::ValidValue) {
                Some(ContextValue::Strings(v)) if !v.is_empty() => {
                    format!(" (one of: {})", v.join(", "))
                }
                _ => String::new(),
            };
            return if value.is_empty() {
                format!("{arg}: a value is required{valid}")
            } else {
                format!("{arg}: invalid value '{value}'{valid}")
            };
        }
        (ErrorKind::ArgumentConflict, Some(arg)) => {
            if let Some(prior) = option(ContextKind::PriorArg) {
                return format!("{arg}: cannot be used with {prior}");
            }
        }
        _ => {}
    }
    let text = e.render().to_string();
    let line = text
        .lines()
        .map(str::trim)
        .find(|l| !l.is_empty())
        .unwrap_or("invalid command line");
    line.strip_prefix("error: ").unwrap_or(line).to_owned()
}

pub(crate) fn write_stdout(bytes: &[u8]) -> Result<(), Failure> {
    let mut out = std::io::stdout().lock();
    out.write_all(bytes)?;
    out.flush()?;
    Ok(())
}

fn single(
    mode: Mode,
    p: &Params,
    n: &compute::Numerics,
    output: &OutputArgs,
) -> Result<(), Failure> {
    let r = compute::run(mode, p, n)?;
    let bytes = if output.json {
        let mut s = serde_json::to_string_pretty(&r).map_err(|e| Failure::Other(e.to_string()))?;
        s.push('\n');
        s.into_bytes()
    } else if output.csv {
        report::single_csv(mode, &r)
    } else {
        let ctx = table::TableContext {
            club: p.club.preset.name,
            club_speed_mps: (mode != Mode::Flight).then_some(compute::club_speed_mps(p)),
            impact_location_m: (mode != Mode::Flight)
                .then_some((compute::impact_height_m(p), p.delivery.impact_toe_m)),
        };
        table::table(mode, &r, output.units, &ctx).into_bytes()
    };
    write_stdout(&bytes)
}

fn dispatch(cli: Cli) -> Result<(), Failure> {
    match cli.command {
        Command::Impact(c) => {
            let (p, n) = c.resolve()?;
            single(Mode::Impact, &p, &n, &c.output)
        }
        Command::Flight(c) => {
            let (p, n) = c.resolve()?;
            single(Mode::Flight, &p, &n, &c.output)
        }
        Command::Shot(c) => {
            let (p, n) = c.resolve()?;
            single(Mode::Shot, &p, &n, &c.output)
        }
        Command::Batch(b) => {
            let (mode, batch, (p, n), output) = match &b {
                BatchCmd::Impact { batch, cmd } => {
                    (Mode::Impact, batch, cmd.resolve()?, &cmd.output)
                }
                BatchCmd::Flight { batch, cmd } => {
                    (Mode::Flight, batch, cmd.resolve()?, &cmd.output)
                }
                BatchCmd::Shot { batch, cmd } => (Mode::Shot, batch, cmd.resolve()?, &cmd.output),
                BatchCmd::Estimate { batch, cmd } => {
                    return crate::analyses::estimate::batch(batch, cmd);
                }
            };
            batch::run(&batch::Job {
                mode,
                base: p,
                numerics: n,
                units: output.units,
                json: output.json,
                input: batch.input.clone(),
                threads: batch.threads,
                progress: !batch.no_progress,
            })
        }
        Command::Plot(c) => {
            let (mode, plot, (p, n), units) = match &c {
                PlotCmd::Flight { plot, cmd } => {
                    (Mode::Flight, plot, cmd.resolve()?, cmd.output.units)
                }
                PlotCmd::Shot { plot, cmd } => (Mode::Shot, plot, cmd.resolve()?, cmd.output.units),
            };
            plot::run(mode, &p, &n, units, plot)
        }
        Command::Fit(c) => fit::run(&c),
        Command::Clubs(c) => write_stdout(
            if c.json {
                clubs::json()
            } else {
                clubs::table()
            }
            .as_bytes(),
        ),
        Command::Optimize(c) => write_stdout(c.run()?.as_bytes()),
        Command::Sweep(c) => write_stdout(c.run()?.as_bytes()),
        Command::Dispersion(c) => write_stdout(c.run()?.as_bytes()),
        Command::Normalize(c) => write_stdout(c.run()?.as_bytes()),
        Command::Estimate(c) => write_stdout(c.run()?.as_bytes()),
        Command::Bench(BenchCmd::Accuracy {
            json,
            svg,
            quick,
            aero,
        }) => {
            let aero = match aero {
                Some(a) => carry_io::aero_file::resolve(&a)
                    .map_err(|e| Failure::Input(error::InputError::new("aero", e)))?,
                None => carry_core::aero::AeroModel::default(),
            };
            let options = carry_lab::study::StudyOptions {
                json,
                svg,
                quick,
                aero,
            };
            let text = carry_lab::study::run(&options).map_err(Failure::Other)?;
            write_stdout(text.as_bytes())
        }
    }
}
