//! Helpers shared by the integration tests: run the `carry` binary and read what it wrote.
//!
//! Each test file declares `mod common;` and compiles its own copy of this module.

// Every test binary compiles this module on its own, and not every one uses every helper.
#![allow(dead_code)]

use assert_cmd::Command;
use serde_json::Value;
use std::path::PathBuf;

/// A command for the `carry` binary under test.
pub fn carry() -> Command {
    Command::cargo_bin("carry").expect("the carry binary is built")
}

/// What one run of `carry` returned: exit status (-1 if killed) and both streams.
pub struct Run {
    pub code: i32,
    pub stdout: String,
    pub stderr: String,
}

/// Runs `carry` with `args` and collects its status and output.
pub fn run(args: &[&str]) -> Run {
    let out = carry().args(args).output().expect("carry runs");
    Run {
        code: out.status.code().unwrap_or(-1),
        stdout: String::from_utf8_lossy(&out.stdout).into_owned(),
        stderr: String::from_utf8_lossy(&out.stderr).into_owned(),
    }
}

/// Runs `carry` with `args`, asserts it succeeded, and parses its stdout as JSON.
#[track_caller]
pub fn json(args: &[&str]) -> Value {
    let r = run(args);
    assert_eq!(r.code, 0, "carry {args:?} failed: {}", r.stderr);
    serde_json::from_str(&r.stdout).expect("stdout is JSON")
}

/// Writes `contents` to a file `name` in a temp directory of this test binary's own
/// (named after the binary and the process id, so parallel test binaries don't clash).
pub fn temp_file(name: &str, contents: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!(
        "carry-{}-tests-{}",
        env!("CARGO_CRATE_NAME"),
        std::process::id()
    ));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let path = dir.join(name);
    std::fs::write(&path, contents).expect("temp file");
    path
}
