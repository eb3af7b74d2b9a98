//! The curves of the curve benchmark and the search for the uniform
//! polyline's step count; shared by `benches/curves.rs` and
//! `examples/curve_table.rs`.

#![allow(dead_code)]

use slider_crank::SliderCrank;
use slider_crank::construct::CentrodeKind;
use slider_crank::diagram::{Locus, LocusKind, Method, TraceOptions, TracedPath, measure, trace};
use slider_crank::figure::PageFromWorld;
use slider_crank::geom::{Frame, Point};
use std::ops::RangeInclusive;

/// The tolerances of the benchmark, page units (px).
pub const TOLERANCES: [f64; 5] = [1e-1, 1e-2, 1e-3, 1e-4, 1e-5];

/// One curve on one panel.
pub struct Case {
    /// Short name, used in benchmark ids.
    pub name: &'static str,
    /// What it is, for the table.
    pub description: &'static str,
    pub curve: Locus,
    pub range: RangeInclusive<f64>,
    pub map: PageFromWorld,
    pub frame: Frame,
}

/// The textbook's engine of §35 (r = 0.5 ft, l = 3 ft, n = 6) on two
/// panels: its polar velocity curve at 300 px/ft on a 400 × 400 px panel,
/// and its fixed centrode at 150 px/ft on an 800 × 500 px panel showing
/// the mechanism (C at (120, 250), the cylinder on the right), θ = 0…360°.
pub fn cases() -> Vec<Case> {
    let engine = SliderCrank::in_line(0.5, 3.0).expect("valid engine");
    vec![
        Case {
            name: "polar",
            description: "polar velocity curve, n = 6, 300 px/ft, 400 × 400 px",
            curve: Locus::new(engine, LocusKind::PolarVelocity),
            range: 0.0..=360.0,
            map: PageFromWorld::scale_translate(300.0, -300.0, 200.0, 200.0).expect("invertible"),
            frame: Frame::new(Point::new(0.0, 0.0), Point::new(400.0, 400.0)),
        },
        Case {
            name: "centrode",
            description: "fixed centrode, n = 6, 150 px/ft, 800 × 500 px",
            curve: Locus::new(engine, LocusKind::Centrode(CentrodeKind::Fixed)),
            range: 0.0..=360.0,
            map: PageFromWorld::scale_translate(150.0, -150.0, 120.0, 250.0).expect("invertible"),
            frame: Frame::new(Point::new(0.0, 0.0), Point::new(800.0, 500.0)),
        },
    ]
}

impl Case {
    /// Traces with `method` at `tolerance`.
    pub fn trace(&self, method: Method, tolerance: f64) -> TracedPath {
        let options = TraceOptions::with_tolerance(tolerance);
        trace(
            &self.curve,
            self.range.clone(),
            &self.map,
            &self.frame,
            method,
            &options,
        )
        .expect("the benchmark curves trace")
    }

    /// The measured deviation of `path` (the larger of both ways).
    pub fn error(&self, path: &TracedPath) -> f64 {
        measure(
            path,
            &self.curve,
            self.range.clone(),
            &self.map,
            &self.frame,
        )
        .max()
    }

    /// The smallest step count N whose uniform polyline's measured error is
    /// within `tolerance`: doubling, then bisection. (The measured error is
    /// not exactly monotonic in N; this is the smallest N the bisection
    /// meets between the last failing and first passing power of two.)
    pub fn uniform_steps(&self, tolerance: f64) -> usize {
        let passes = |n: usize| self.error(&self.trace(Method::Uniform(n), tolerance)) <= tolerance;
        let mut hi = 8;
        while !passes(hi) {
            hi *= 2;
        }
        let mut lo = hi / 2;
        while hi - lo > 1 {
            let mid = lo + (hi - lo) / 2;
            if passes(mid) {
                hi = mid;
            } else {
                lo = mid;
            }
        }
        hi
    }
}
