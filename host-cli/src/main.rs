//! `carry`: the command line over carry-core. A thin shell over [`carry_cli::run`]: it
//! installs a panic hook (one line, no backtrace: a panic would be a bug) and passes the
//! process arguments on.

use std::io::Write as _;
use std::process::ExitCode;

fn main() -> ExitCode {
    std::panic::set_hook(Box::new(|info| {
        let msg = info
            .payload()
            .downcast_ref::<&str>()
            .map(ToString::to_string)
            .or_else(|| info.payload().downcast_ref::<String>().cloned())
            .unwrap_or_default();
        let _ = writeln!(
            std::io::stderr(),
            "carry: internal error (a bug, please report it): {msg}"
        );
    }));
    carry_cli::run(std::env::args_os())
}
