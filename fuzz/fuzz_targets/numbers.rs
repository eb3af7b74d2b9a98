//! Mechanism and angle numbers to `analyze` and to every named figure.
#![no_main]

#[allow(dead_code)]
#[path = "../../tests/common/hostile.rs"]
mod hostile;

#[derive(Debug, arbitrary::Arbitrary)]
struct Input {
    crank: f64,
    rod: f64,
    offset: f64,
    degrees: f64,
    omega: f64,
    torque: f64,
    figure: u8,
}

libfuzzer_sys::fuzz_target!(|i: Input| {
    hostile::numbers(
        i.crank, i.rod, i.offset, i.degrees, i.omega, i.torque, i.figure,
    );
});
