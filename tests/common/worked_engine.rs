//! One in-line engine worked from the formulas, for the tests that check
//! the dynamics figures and the handout's dynamics against something the
//! code under test did not compute: crank r, rod l, speed ω, reciprocating
//! mass m and the gas force of an indicator diagram (examples/indicator.csv
//! on a 10 in bore, or the rows and bore given).
#![allow(dead_code)] // each test uses what it needs

use std::f64::consts::PI;

/// The rows of examples/indicator.csv: fraction, expansion, compression.
pub fn indicator() -> Vec<[f64; 3]> {
    include_str!("../../examples/indicator.csv")
        .lines()
        .filter(|l| !l.starts_with('#') && !l.starts_with("fraction"))
        .map(|l| {
            let v: Vec<f64> = l.split(',').map(|x| x.trim().parse().unwrap()).collect();
            [v[0], v[1], v[2]]
        })
        .collect()
}

/// An in-line engine of crank r and rod l at ω (rad/s) with the
/// reciprocating mass m and the gas force of examples/indicator.csv on a
/// 10 in bore, worked from the formulas.
pub struct Engine {
    pub r: f64,
    pub l: f64,
    pub omega: f64,
    pub m: f64,
    pub rows: Vec<[f64; 3]>,
    /// The bore, in the length unit (10/12 ft for examples/indicator.csv).
    pub bore: f64,
}

impl Engine {
    pub fn area(&self) -> f64 {
        PI * self.bore.powi(2) / 4.0
    }

    /// x = r cos θ + √(l² − r² sin² θ) and its second derivative in θ.
    pub fn x(&self, t: f64) -> (f64, f64) {
        let (r, l) = (self.r, self.l);
        let w = (l * l - (r * t.sin()).powi(2)).sqrt();
        let x2 = -r * t.cos()
            - r * r * (2.0 * t).cos() / w
            - r.powi(4) * (t.sin() * t.cos()).powi(2) / w.powi(3);
        (r * t.cos() + w, x2)
    }

    /// m a towards the crank's positive sign: the inertia force.
    pub fn inertia(&self, t: f64) -> f64 {
        self.m * self.omega * self.omega * self.x(t).1
    }

    /// p A, on the expansion stroke while 0 < θ < π (piston towards the
    /// crank).
    pub fn gas(&self, t: f64) -> f64 {
        let fraction = ((self.r + self.l - self.x(t).0) / (2.0 * self.r)).clamp(0.0, 1.0);
        let column = if t.sin() > 0.0 { 1 } else { 2 };
        let w = self.rows.windows(2).find(|w| fraction <= w[1][0]).unwrap();
        let s = (fraction - w[0][0]) / (w[1][0] - w[0][0]);
        self.area() * (w[0][column] + (w[1][column] - w[0][column]) * s)
    }

    /// T = F (r sin θ + r cos θ tan φ), sin φ = r sin θ / l.
    pub fn torque(&self, t: f64) -> f64 {
        let phi = (self.r * t.sin() / self.l).asin();
        (self.gas(t) + self.inertia(t)) * self.r * (t.sin() + t.cos() * phi.tan())
    }

    /// The indicator diagram's work by hand: A × stroke × the trapezoids
    /// of expansion less compression over the fraction.
    pub fn indicated(&self) -> f64 {
        let area: f64 = self
            .rows
            .windows(2)
            .map(|w| 0.5 * (w[1][0] - w[0][0]) * (w[0][1] + w[1][1] - w[0][2] - w[1][2]))
            .sum();
        self.area() * 2.0 * self.r * area
    }

    /// The mean torque and ΔE by composite Simpson over `n` intervals.
    pub fn turn(&self, n: usize) -> (f64, f64) {
        let h = 2.0 * PI / n as f64;
        let t: Vec<f64> = (0..=n).map(|k| self.torque(k as f64 * h)).collect();
        let simpson = |v: &[f64], k: usize| h / 3.0 * (v[k] + 4.0 * v[k + 1] + v[k + 2]);
        let mean = (0..n).step_by(2).map(|k| simpson(&t, k)).sum::<f64>() / (2.0 * PI);
        let excess: Vec<f64> = t.iter().map(|x| x - mean).collect();
        let (mut e, mut lo, mut hi) = (0.0, 0.0f64, 0.0f64);
        for k in (0..n).step_by(2) {
            e += simpson(&excess, k);
            lo = lo.min(e);
            hi = hi.max(e);
        }
        (mean, hi - lo)
    }
}
