//! Fuzz the command line's parsing: arbitrary argument vectors through clap, option
//! validation and the computation they ask for (`impact`, `flight`, `shot`), and arbitrary
//! CSV through `carry batch`'s reader, column mapping, per-row validation and formatting.
//! A bad input must come back as an error (status 2 / an error row), never a panic.
//!
//! Byte 0 picks the harness: even → arguments (NUL-separated, lossy UTF-8), odd → CSV
//! (byte 1 picks impact/flight/shot and CSV or JSON lines). Arguments that read files
//! (`--scene`, `--input`) or write them (`plot`, `bench`) are skipped: they are I/O, not
//! parsing.
#![no_main]

use carry_cli::batch::{self, Job};
use carry_cli::cli::{Cli, Command};
use carry_cli::compute::{self, Mode};
use carry_cli::units::Units;
use clap::Parser as _;
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Some((&selector, rest)) = data.split_first() else {
        return;
    };
    if selector % 2 == 0 {
        arguments(rest);
    } else {
        csv_rows(rest);
    }
});

fn arguments(bytes: &[u8]) {
    let mut args = vec!["carry".to_owned()];
    args.extend(
        bytes
            .split(|&b| b == 0)
            .map(|a| String::from_utf8_lossy(a).into_owned()),
    );
    if args
        .iter()
        .any(|a| a.contains("--scene") || a.contains("--input") || a.contains("--output"))
    {
        return;
    }
    let Ok(cli) = Cli::try_parse_from(&args) else {
        return; // a usage error: the CLI prints one line and exits 2
    };
    let resolved = match &cli.command {
        Command::Impact(c) => c.resolve().map(|r| (Mode::Impact, r)),
        Command::Flight(c) => c.resolve().map(|r| (Mode::Flight, r)),
        Command::Shot(c) => c.resolve().map(|r| (Mode::Shot, r)),
        _ => return,
    };
    if let Ok((mode, (params, numerics))) = resolved {
        let _ = compute::run(mode, &params, &numerics);
    }
}

fn csv_rows(bytes: &[u8]) {
    let Some((&flags, csv)) = bytes.split_first() else {
        return;
    };
    let (mode, command) = match flags % 3 {
        0 => (Mode::Impact, "impact"),
        1 => (Mode::Flight, "flight"),
        _ => (Mode::Shot, "shot"),
    };
    // The defaults the columns override, resolved as `carry batch <mode>` resolves them.
    let Ok(cli) = Cli::try_parse_from(["carry", command]) else {
        return;
    };
    let base = match &cli.command {
        Command::Impact(c) => c.resolve(),
        Command::Flight(c) => c.resolve(),
        Command::Shot(c) => c.resolve(),
        _ => return,
    };
    let Ok((base, numerics)) = base else {
        return;
    };
    let job = Job {
        mode,
        base,
        numerics,
        units: if flags & 4 == 0 {
            Units::Si
        } else {
            Units::Imperial
        },
        json: flags & 8 != 0,
        input: "-".into(),
        threads: Some(1),
        progress: false,
    };
    let mut out = Vec::new();
    if let Ok((rows, errors)) = batch::run_bytes(&job, csv, &mut out) {
        assert!(errors <= rows, "{errors} error rows of {rows}");
    }
}
