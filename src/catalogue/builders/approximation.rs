//! The error of the textbook's approximations against θ for n = 4, 5, 6:
//! the error due to obliquity (§35), the piston velocity of eq. (2), the
//! acceleration of eq. (3) and the rod's angular acceleration of eq. (2a).
//!
//! Each error is approximation − exact, made dimensionless (by r, V_c,
//! rω² and ω²), so it holds for any crank radius and speed; the signs are
//! the textbook's (velocity and acceleration towards the crank positive),
//! for an in-line engine.

use super::{Ctx, Sheet, against_angle};
use crate::diagram::{Axis, Curve, Plot};
use crate::error::Result;
use crate::figure::{Dash, Figure};
use crate::geom::{Frame, Point};
use crate::{angle::Angle, mechanism::Pose, mechanism::SliderCrank};

/// The ratios n = l/r drawn, with their dashes.
const RATIOS: [(f64, Dash); 3] = [
    (4.0, Dash::Solid),
    (5.0, Dash::Dashed),
    (6.0, Dash::DashDot),
];

/// An error as a function of the pose of an engine with r = 1: value and
/// derivative per radian.
type ErrorOf = fn(&Pose) -> (f64, f64);

fn q(p: &Pose) -> f64 {
    let n = p.mechanism().ratio();
    let s = p.angle().sin();
    ((n - s) * (n + s)).sqrt()
}

fn obliquity(p: &Pose) -> (f64, f64) {
    let (s, c) = (p.angle().sin(), p.angle().cos());
    (p.obliquity_error(), -s * c / q(p))
}

fn velocity(p: &Pose) -> (f64, f64) {
    let n = p.mechanism().ratio();
    let (s, c) = (p.angle().sin(), p.angle().cos());
    let cos2 = (c - s) * (c + s);
    (
        s + s * c / n + p.position_rate(),
        c + cos2 / n + p.position_acceleration(),
    )
}

fn acceleration(p: &Pose) -> (f64, f64) {
    let n = p.mechanism().ratio();
    let (s, c) = (p.angle().sin(), p.angle().cos());
    let cos2 = (c - s) * (c + s);
    (
        c + cos2 / n + p.position_acceleration(),
        -s - 4.0 * s * c / n + p.position_jerk(),
    )
}

fn rod(p: &Pose) -> (f64, f64) {
    let n = p.mechanism().ratio();
    let (s, c) = (p.angle().sin(), p.angle().cos());
    let q = q(p);
    (
        -s / q - p.obliquity_acceleration(),
        -n * n * c / (q * q * q) - p.obliquity_jerk(),
    )
}

pub(in crate::catalogue) fn build(ctx: &Ctx) -> Result<Figure> {
    let page = ctx.page();
    let mut sheet = Sheet::new(ctx);
    sheet.mechanism(ctx, false, false);
    sheet.meta("ratios", serde_json::json!(RATIOS.map(|(n, _)| n)));
    let panels: [(&str, &str, &str, ErrorOf); 4] = [
        (
            "obliquity",
            "error ÷ *r*",
            "(a) Error due to obliquity, √(*n*²\u{a0}−\u{a0}sin²θ)\u{a0}−\u{a0}*n*",
            obliquity,
        ),
        (
            "velocity",
            "error ÷ *V*_c",
            "(b) Piston velocity: eq.\u{a0}(2)\u{a0}−\u{a0}exact",
            velocity,
        ),
        (
            "acceleration",
            "error ÷ *r*ω²",
            "(c) Piston acceleration: eq.\u{a0}(3)\u{a0}−\u{a0}exact",
            acceleration,
        ),
        (
            "rod",
            "error ÷ ω²",
            "(d) Rod angular acceleration: eq.\u{a0}(2a)\u{a0}−\u{a0}exact",
            rod,
        ),
    ];
    let width = 0.5 * (page.width() - 48.0);
    let height = 0.5 * (page.height() - 32.0 - 40.0);
    for (k, (name, title, caption, f)) in panels.into_iter().enumerate() {
        let engines: Vec<SliderCrank> = RATIOS
            .iter()
            .map(|(n, _)| SliderCrank::in_line(1.0, *n))
            .collect::<Result<_>>()?;
        let (lo, hi) = engines
            .iter()
            .flat_map(|m| {
                (0..=720).filter_map(move |j| {
                    let a = Angle::from_degrees(j as f64 * 0.5).ok()?;
                    Some(f(&m.pose(a)).0)
                })
            })
            .fold((0.0f64, 0.0f64), |(lo, hi), v| (lo.min(v), hi.max(v)));
        let x = Axis::linear("crank angle θ (°)", 0.0, 360.0)?.with_step(60.0)?;
        let y = Axis::nice(title, lo, hi)?;
        let rect = Frame::from_origin_size(
            16.0 + (k % 2) as f64 * (width + 16.0),
            16.0 + (k / 2) as f64 * (height + 8.0),
            width,
            height,
        );
        let mut plot = Plot::new(name, rect, x, y, ctx.tolerance, ctx.font)?.with_caption(caption);
        // One legend, in (a): the rods are drawn alike in every panel (at
        // 500 units wide the same legend stood under each of the four).
        for (m, (n, dash)) in engines.iter().zip(RATIOS) {
            let curve = against_angle(*m, f);
            let pieces: [(&dyn Curve, _); 1] = [(&curve, 0.0..=360.0)];
            let key = format!("*n* = {}", n as u32);
            plot.curve(
                &format!("curve-{name}-n{}", n as u32),
                &pieces,
                dash,
                (k == 0).then_some(key.as_str()),
            )?;
        }
        sheet.plot(plot);
    }
    sheet.notes(
        Point::new(20.0, page.height() - 44.0),
        &[
            "Approximation − exact, divided by *r*, *V*_c = *r*ω, *r*ω² or ω², so the same for any crank and speed; in-line engine; each rod drawn alike in every panel, as (a)’s legend gives.".into(),
            "Signs as the textbook’s: velocity and acceleration towards the crank positive; the rod’s d²φ/d*t*² as in §37.".into(),
        ],
    );
    Ok(sheet.finish())
}
