//! Worked examples of the textbooks with their printed answers: the
//! engine's value against the answer as printed, within the book's own
//! rounding, each difference explained where it is asserted. Every source
//! is named (book, chapter, example, page where given); docs/dynamics.md
//! lists them ("Worked examples").
//!
//! The books measure θ from the inner dead centre (IDC), the pose the
//! program calls θ = 0 (the outer dead centre of its own drawing), so a
//! book's θ is the program's θ.

use slider_crank::dynamics::{Engine, Flywheel, GasForce, PartialBalance};
use slider_crank::{Angle, SliderCrank};
use std::f64::consts::PI;

/// ω in rad/s of a speed in rev/min.
fn rad_per_s(rpm: f64) -> f64 {
    2.0 * PI * rpm / 60.0
}

/// `value` within `tolerance` of the printed `printed`.
fn near(what: &str, value: f64, printed: f64, tolerance: f64) {
    assert!(
        (value - printed).abs() <= tolerance,
        "{what}: the engine gives {value}, the book prints {printed} (± {tolerance})"
    );
}

/// A horizontal steam engine at 240 rev/min, bore 300 mm, stroke 600 mm,
/// rod 1.25 m, reciprocating parts 60 kg; at θ = 60° from the inner dead
/// centre the steam pressure is 1.125 N/mm² on the cover side and
/// 0.125 N/mm² on the crank side. Source: the worked solution at
/// sarthaks.com, question 491480 ("A horizontal steam engine running at
/// 240 r.p.m. has a bore of 300 mm and stroke 600 mm …"), which names no
/// book; the problem and its method are those of the textbooks' chapter
/// on inertia forces in reciprocating parts. Printed: net load on the
/// piston F_L = 70685.83 N, inertia force F_I = 4319.68 N, piston effort
/// F_P = F_L − F_I = 66.366 kN.
#[test]
fn horizontal_steam_engine_piston_effort() {
    let omega = rad_per_s(240.0);
    let gas = (1.125e6 - 0.125e6) * PI / 4.0 * 0.3 * 0.3;
    let engine = Engine::new(SliderCrank::in_line(0.3, 1.25).unwrap(), 60.0, omega)
        .unwrap()
        .with_gas(GasForce::Constant(gas))
        .unwrap();
    let at = engine.at(Angle::deg(60.0)).unwrap();
    // The net load is (p₁ − p₂) π D²/4 and nothing else: the book's
    // 70685.83 N to its last figure.
    near("gas force", at.gas_force, 70685.83, 0.01);
    // The book's F_I uses the two-term series cos θ + cos 2θ / n with
    // ω rounded to 25.13 rad/s: the exact acceleration (the engine's) is
    // 4321.55 N, the series at the unrounded ω 4320.52 N, and ω = 25.13
    // takes 0.94 N off (2 × 0.0027 / 25.13 of it): 4319.58 N, which the
    // book prints as 4319.68. So within 2.5 N: 0.06 %, the series' error
    // (of order 1/n³, n = 4.167) and ω's rounding together. The inertia
    // force resists the piston's acceleration towards the crank, so it
    // takes from the gas force: the engine's inertia force is −F_I.
    near("inertia force", -at.inertia_force, 4319.68, 2.5);
    // F_P = 66.366 kN printed to the newton; the engine's 66364.3 N
    // differs by the same 2 N.
    near("piston effort", at.piston_effort, 66366.0, 2.5);
}

/// R. S. Khurmi and J. K. Gupta, Theory of Machines (14th ed., 2009),
/// chapter 16, "Turning Moment Diagrams and Flywheel", Example 16.1
/// (p. 573): a flywheel of 6.5 t with a radius of gyration of 1.8 m
/// takes up ΔE = 56 kN·m at a mean speed of 120 rev/min; the greatest and
/// least speeds are printed as 121 and 119 rev/min. The data and the
/// answers as the FOSSEE Python Textbook Companion to the book
/// (Theory_Of_Machines/ch16.ipynb) prints them, so for the two examples
/// after it.
#[test]
fn khurmi_example_16_1_speeds_of_a_flywheel() {
    let omega = rad_per_s(120.0);
    let wheel = Flywheel::for_inertia(56e3, omega, 6500.0 * 1.8 * 1.8).unwrap();
    // C_s = (N₁ − N₂)/N with N the mean: N₁,₂ = N (1 ± C_s/2). The book
    // rounds to whole rev/min: 121.01 and 118.99.
    let greatest = 120.0 * (1.0 + wheel.coefficient / 2.0);
    let least = 120.0 * (1.0 - wheel.coefficient / 2.0);
    near("greatest speed", greatest, 121.0, 0.5);
    near("least speed", least, 119.0, 0.5);
}

/// Khurmi and Gupta, chapter 16, Example 16.3 (p. 574): an engine of
/// 300 kW at 90 rev/min, a coefficient of fluctuation of energy of 0.1,
/// the speed held within ±0.5 % (C_s = 0.01), the flywheel's radius of
/// gyration 2 m; the mass printed as 5628 kg (the companion as above).
#[test]
fn khurmi_example_16_3_mass_of_a_flywheel() {
    let omega = rad_per_s(90.0);
    // The work of a turn is P · 60/N = 200 kN·m; ΔE = 0.1 of it.
    let fluctuation = 0.1 * 300e3 * 60.0 / 90.0;
    let wheel = Flywheel::for_coefficient(fluctuation, omega, 0.01).unwrap();
    // m = I / k² = 5628.95 kg: the whole kilograms are printed (5628,
    // not 5629).
    near("flywheel mass", wheel.inertia / 4.0, 5628.0, 1.0);
}

/// Khurmi and Gupta, chapter 16, Example 16.5 (p. 575): the turning
/// moment diagram's greatest excess and deficit are +52 and −120 mm² at
/// 1 mm² = 10π N·m (so ΔE = 172 × 10π = 5403.5 N·m), 600 rev/min,
/// C_s = 0.03, the flywheel's rim of radius 0.5 m; printed 182 kg.
#[test]
fn khurmi_example_16_5_flywheel_rim() {
    let omega = rad_per_s(600.0);
    let fluctuation = (52.0 + 120.0) * 10.0 * PI;
    let wheel = Flywheel::for_coefficient(fluctuation, omega, 0.03).unwrap();
    // m = I / R² = 182.50 kg: the whole kilograms again.
    near("flywheel mass", wheel.inertia / 0.25, 182.0, 1.0);
}

/// B. K. Sarkar, Theory of Machines, chapter 12, "Balancing of
/// Reciprocating Masses", Illustration 1 (p. 310): a single-cylinder
/// engine at 250 rev/min, reciprocating parts 120 kg, crank radius
/// 0.09 m, two thirds of the reciprocating mass balanced; the residual
/// unbalanced force at θ = 30° from the inner dead centre printed as
/// 3263.971 N, as the FOSSEE Python Textbook Companion to the book
/// (Theory_Of_Machines_by__B._K._Sarkar/Chapter12_1.ipynb) prints it.
#[test]
fn sarkar_illustration_12_1_residual_unbalanced_force() {
    let omega = rad_per_s(250.0);
    let left = PartialBalance::new(2.0 / 3.0).unwrap().at(Angle::deg(30.0));
    let force = 120.0 * omega * omega * 0.09 * left.magnitude;
    // The exact value is 3264.065 N; the worked solution turns degrees
    // into radians with 57.3 (not 180/π = 57.2958), which moves cos 30°
    // and sin 30° in their fourth figure: 3263.971 N. Within 0.1 N.
    near("residual unbalanced force", force, 3263.971, 0.1);
    // The same force from its parts, (1 − c) cos θ along the stroke and
    // c sin θ across it: 1/3 · 0.8660 and 2/3 · 0.5.
    near("along the stroke", left.horizontal, 0.866_025 / 3.0, 1e-6);
    near("across the stroke", left.vertical.abs(), 1.0 / 3.0, 1e-12);
}
