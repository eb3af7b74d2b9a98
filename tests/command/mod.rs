//! Running the program from the tests.

use std::process::{Command, Output};

/// The program run with `args`, its output captured.
pub fn run(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_slider-crank"))
        .args(args)
        .output()
        .expect("the binary runs")
}

/// Asserts a zero exit, showing standard error otherwise.
pub fn succeeded(out: &Output) {
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}
