//! Fuzz the command line's parsing: arbitrary argument vectors through clap, option
//! validation and the computation they ask for (`impact`, `flight`, `shot`), and arbitrary
//! CSV through `carry batch`'s reader, column mapping, per-row validation and formatting.
//! A bad input must come back as an error (status 2 / an error row), never a panic.
//!
//! Byte 0 picks the harness: even → arguments (NUL-separated, lossy UTF-8), 7 mod 8 → a
//! swing file for `carry sweep` (the lab's CSV reader and contact search), other odd → CSV
//! (byte 1 picks impact/flight/shot and CSV or JSON lines). The lab commands (`optimize`,
//! `sweep`, `dispersion`, `normalize`) run too, with their work capped (shots, starts,
//! chart and sweep sizes) so an input stays fast. Arguments that read files
//! (`--scene`, `--input`) or write them (`plot`, `bench`) are skipped: they are I/O, not
//! parsing.
#![no_main]

use carry_cli::cli::{Cli, Command};
use carry_io::batch::{self, Job};
use carry_io::compute::{self, Mode};
use carry_io::units::Units;
use clap::Parser as _;
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Some((&selector, rest)) = data.split_first() else {
        return;
    };
    if selector % 2 == 0 {
        arguments(rest);
    } else if selector % 8 == 7 {
        swing_file(rest);
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
    if args.iter().any(|a| {
        [
            "--scene",
            "--input",
            "--output",
            "--svg",
            "--swing",
            "--generate",
        ]
        .iter()
        .any(|f| a.contains(f))
    }) {
        return;
    }
    let Ok(cli) = Cli::try_parse_from(&args) else {
        return; // a usage error: the CLI prints one line and exits 2
    };
    let resolved = match &cli.command {
        Command::Impact(c) => c.resolve().map(|r| (Mode::Impact, r)),
        Command::Flight(c) => c.resolve().map(|r| (Mode::Flight, r)),
        Command::Shot(c) => c.resolve().map(|r| (Mode::Shot, r)),
        Command::Optimize(c) => {
            let s = &c.search;
            // A chart only on a small grid given in full (at most 4 cells; the grid's own
            // validation sees the rest: a bad triple is an error before any cell runs).
            let cells = |t: Option<[f64; 3]>| {
                t.map(|[a, b, step]| ((b - a) / step).abs())
                    .filter(|n| *n <= 1.0)
            };
            let small_chart = cells(s.club_speeds).is_some() && cells(s.attack_angles).is_some();
            if s.starts <= 3 && c.monte_carlo.shots.unwrap_or(0) <= 64 && (!s.chart || small_chart)
            {
                let _ = c.run();
            }
            return;
        }
        Command::Dispersion(c) => {
            if c.monte_carlo.shots.is_some_and(|n| n <= 256) {
                let _ = c.run();
            }
            return;
        }
        Command::Normalize(c) => {
            let _ = c.run();
            return;
        }
        Command::Sweep(c) => {
            if c.ball_positions
                .is_some_and(|[a, b, step]| (b - a) / step <= 50.0)
            {
                let _ = c.run();
            }
            return;
        }
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

/// A swing file: the lab's reader, then a short sweep on the default setup.
fn swing_file(bytes: &[u8]) {
    let Ok(setup) = carry_lab::Setup::<f64>::standard(&carry_core::PRESETS[0], 45.0) else {
        return;
    };
    if let Ok(motion) = carry_lab::sweep::Motion::from_csv(bytes, setup.club.loft_rad()) {
        let _ = carry_lab::sweep::sweep(&setup, &motion, &[-0.05, 0.0, 0.05]);
    }
}
