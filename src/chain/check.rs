//! Cross-checks of the curved slot and the quadric chain: each exact value
//! beside one from an independent formulation, in scaled units.

use super::centres::{ChainCentres, SlotConstruction};
use super::cylindric::CylindricChain;
use super::quadric::{Assembly, QuadricChain};
use crate::angle::Angle;
use crate::construct::Link;
use crate::geom::{Circle, CircleIntersection, Intersection, Point, cross};
use std::f64::consts::{FRAC_PI_2, PI};

/// The worst scaled difference of one quantity over a sweep, measured
/// against the quantity's condition number κ at each pose (as the engine's
/// check does): its name, the difference and κ where the difference
/// divided by κ was largest, the crank angle in degrees there, and the
/// number of poses where both values existed. A sweep passes a tolerance
/// T when `worst ≤ T · condition` (see [`ChainCheckRow::passes`]).
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct ChainCheckRow {
    /// What is compared, and with what.
    pub name: &'static str,
    /// The scaled difference where difference / κ is worst (infinite if a
    /// NaN appeared).
    pub worst: f64,
    /// κ there: 1 far from a toggle or the slot's limit, growing as the
    /// answer itself grows ill-conditioned there.
    pub condition: f64,
    /// Where, in degrees.
    pub at_degrees: f64,
    /// Poses compared.
    pub poses: usize,
}

impl ChainCheckRow {
    /// Whether the worst difference is within `tolerance` × κ.
    pub fn passes(&self, tolerance: f64) -> bool {
        self.worst <= tolerance * self.condition
    }
}

/// The least |sin| of the angle a condition number divides by: √ε, where
/// a square root of rounding is all an answer at a toggle has. κ is
/// bounded by it (an unbounded κ would pass any difference).
const LEAST_SINE: f64 = 1.4901161193847656e-8;

/// κ of a quantity that divides by a sine s of the chain's angles `power`
/// times: 1 + k / s^(2 power), k = 2 for positions and rates, 6 for
/// accelerations (docs/design.md §6, as [`crate::construct::condition`]
/// with s = w / l).
fn kappa(sine: f64, k: f64) -> f64 {
    let s = sine.abs().max(LEAST_SINE);
    1.0 + k / (s * s)
}

struct Worst(Vec<ChainCheckRow>);

impl Worst {
    fn new(names: &[&'static str]) -> Self {
        Self(
            names
                .iter()
                .map(|&name| ChainCheckRow {
                    name,
                    worst: 0.0,
                    condition: 1.0,
                    at_degrees: 0.0,
                    poses: 0,
                })
                .collect(),
        )
    }

    /// Records the difference of quantity `i` at `degrees`, where its
    /// condition number is `condition` (≥ 1).
    fn add(&mut self, i: usize, degrees: f64, difference: Option<f64>, condition: f64) {
        let Some(err) = difference else { return };
        let err = if err.is_nan() { f64::INFINITY } else { err };
        // `i` is one of the indices of the names this was made with.
        let Some(row) = self.0.get_mut(i) else { return };
        row.poses += 1;
        if err / condition > row.worst / row.condition || row.poses == 1 {
            row.worst = err;
            row.condition = condition;
            row.at_degrees = degrees;
        }
    }
}

/// The block's arc position found by Newton's method on the slot's arc
/// parameter, A(σ) = (sin κσ / κ, e + (1 − cos κσ)/κ) written with sinc so
/// that κ = 0 is the line: a closure independent of the quadratic the core
/// solves. The root is bracketed (g(σ) = |A − B|² − l² rises from its
/// least, at the foot of B on the slot, to the point of the slot half a
/// turn on or (π/2)(l + |B − foot|) along, whichever is nearer), and a
/// Newton step that leaves the bracket is a bisection: near the limit of
/// assembly, where the rod meets the slot almost square, plain Newton
/// jumped turns of the slot away. The result is reduced to the core's
/// range, |σ| ≤ π/|κ|.
pub fn arc_position_by_iteration(chain: &CylindricChain, angle: Angle) -> f64 {
    let m = chain.mechanism();
    let (r, l, e) = (m.crank(), m.rod(), m.offset());
    let k = -chain.curvature();
    let b = Point::new(r * angle.cos(), r * angle.sin());
    let sinc = |t: f64| if t == 0.0 { 1.0 } else { t.sin() / t };
    let at = |s: f64| {
        let t = k * s;
        let a = Point::new(s * sinc(t), e + 0.5 * k * s * s * sinc(0.5 * t).powi(2));
        (a, crate::geom::Vector::new(t.cos(), t.sin()))
    };
    // The foot of B: on the line, its x; on the circle about (0, e + 1/k),
    // the arc parameter of the direction from the centre to B.
    let foot = if k == 0.0 {
        b.x
    } else {
        let (vx, vy) = (b.x, b.y - (e + 1.0 / k));
        (k * vx).atan2(-k * vy) / k
    };
    let half_turn = if k == 0.0 {
        f64::INFINITY
    } else {
        PI / k.abs()
    };
    let g = |s: f64| (at(s).0 - b).norm_squared() - l * l;
    let (mut lo, mut hi) = (
        foot,
        foot + half_turn.min(FRAC_PI_2 * (l + (at(foot).0 - b).norm())),
    );
    let mut s = m.pose(angle).position().clamp(lo, hi);
    for _ in 0..200 {
        let (a, tangent) = at(s);
        let value = g(s);
        if value < 0.0 {
            lo = s;
        } else {
            hi = s;
        }
        let newton = s - value / (2.0 * (a - b).dot(&tangent));
        let next = if newton > lo && newton < hi {
            newton
        } else {
            0.5 * (lo + hi)
        };
        let done = (next - s).abs() <= 1e-17 * (s.abs() + r) || next == lo || next == hi;
        s = next;
        if done {
            break;
        }
    }
    if k == 0.0 {
        s
    } else {
        let turn = 2.0 * half_turn;
        s - (s / turn).round() * turn
    }
}

/// The curved slot over `samples` crank angles (and 0°, 90°, 180°, 270°):
/// arc position against [`arc_position_by_iteration`] (scaled by l + r), the
/// block's velocity from E and from D, its acceleration from Klein (scaled
/// by r), and the rod's angular velocity from D (unscaled).
pub fn slot_sweep(chain: &CylindricChain, samples: usize) -> Vec<ChainCheckRow> {
    let r = chain.mechanism().crank();
    let mut worst = Worst::new(&[
        "arc position (Newton on the arc; /(l+r))",
        "velocity (E, O_ac)",
        "velocity (D, O_bd)",
        "acceleration (Klein)",
        "rod angular velocity (D, O_bd)",
    ]);
    for angle in angles(samples) {
        let p = chain.pose(angle);
        let s = SlotConstruction::construct(&p);
        let deg = angle.degrees();
        // The block is ill-conditioned where the rod meets the slot square
        // on: s = rod · tangent / l, the w / l of the straight slot.
        let sine = p.rod_vector().dot(&p.tangent()) / chain.mechanism().rod();
        let (first, second) = (kappa(sine, 2.0), kappa(sine, 6.0));
        let diff = |x: Option<f64>, y: f64, scale: f64| x.map(|x| (x - y).abs() / scale);
        let by_newton = arc_position_by_iteration(chain, angle);
        // Positions are of size l + r, and rounded at that size.
        let size = r + chain.mechanism().rod();
        worst.add(0, deg, diff(Some(by_newton), p.arc_position(), size), first);
        worst.add(1, deg, diff(s.arc_rate_from_e(), p.arc_rate(), r), first);
        worst.add(2, deg, diff(s.arc_rate_from_d(), p.arc_rate(), r), first);
        worst.add(
            3,
            deg,
            diff(s.arc_acceleration_from_klein(), p.arc_acceleration(), r),
            second,
        );
        worst.add(
            4,
            deg,
            diff(s.obliquity_rate_from_d(), p.obliquity_rate(), 1.0),
            first,
        );
    }
    worst.0
}

/// The quadric chain in both modes over `samples` crank angles it reaches
/// (and its limits): the pin A against the intersection of the circles
/// about B and O_cd (scaled by the longest link), the coupler's angular
/// velocity from O_bd and the lever's from O_ac (scaled by 1 + |value|:
/// near a toggle they grow without bound).
pub fn quadric_sweep(chain: &QuadricChain, samples: usize) -> Vec<ChainCheckRow> {
    let size = chain
        .crank()
        .max(chain.coupler())
        .max(chain.lever())
        .max(chain.frame());
    let mut worst = Worst::new(&[
        "pin A (circle intersection)",
        "coupler angular velocity (O_bd)",
        "lever angular velocity (O_ac)",
    ]);
    let mut list = angles(samples);
    // The limits are angles in [0, 2π] from atan2: finite, so `ok()` drops
    // none.
    list.extend(
        chain
            .reach()
            .limits()
            .into_iter()
            .filter_map(|t| Angle::from_radians(t).ok()),
    );
    for angle in list {
        for mode in [Assembly::Open, Assembly::Crossed] {
            let Ok(p) = chain.pose(angle, mode) else {
                continue;
            };
            let deg = angle.degrees();
            // Ill-conditioned at a toggle: s = sin of the angle between
            // coupler and lever.
            let sine =
                cross(&p.coupler_vector(), &p.lever_vector()) / (chain.coupler() * chain.lever());
            let (pin, rate) = (kappa(sine, 2.0), kappa(sine, 2.0));
            let circles = Circle::new(p.b(), chain.coupler())
                .zip(Circle::new(chain.lever_pivot(), chain.lever()))
                .map(|(one, two)| one.intersect_circle(&two, 0.0));
            let by_circles = match circles {
                Some(CircleIntersection::Two(x, y)) => {
                    let left = cross(&(chain.lever_pivot() - p.b()), &(x - p.b())) > 0.0;
                    Some(if left == (mode == Assembly::Open) {
                        x
                    } else {
                        y
                    })
                }
                Some(CircleIntersection::Tangent(x)) => Some(x),
                _ => None,
            };
            worst.add(0, deg, by_circles.map(|x| (x - p.a()).norm() / size), pin);
            let Some(rates) = p.rates() else { continue };
            let centres = ChainCentres::of_quadric(&p);
            let rel = |x: Option<f64>, y: f64| x.map(|x| (x - y).abs() / (1.0 + y.abs()));
            worst.add(
                1,
                deg,
                rel(coupler_rate(&centres, p.b()), rates.coupler_velocity),
                rate,
            );
            worst.add(
                2,
                deg,
                rel(lever_rate(&centres, chain.frame()), rates.lever_velocity),
                rate,
            );
        }
    }
    worst.0
}

/// The coupler turns about O_bd: ω_b (B − O_bd) = B, so ω_b = B·(B − O_bd)/|B − O_bd|².
fn coupler_rate(centres: &ChainCentres, b: Point) -> Option<f64> {
    match centres.centre(Link::B, Link::D)? {
        Intersection::Point(d) => {
            let bd = b - d;
            Some(b.coords.dot(&bd) / bd.norm_squared())
        }
        Intersection::AtInfinity(_) => Some(0.0),
        Intersection::Coincident => None,
    }
}

/// Crank and lever share O_ac's velocity: ω_c = x / (x − d) for O_ac on the
/// frame line at x; 1 when it is at infinity.
fn lever_rate(centres: &ChainCentres, d: f64) -> Option<f64> {
    match centres.centre(Link::A, Link::C)? {
        Intersection::Point(e) => Some(e.x / (e.x - d)),
        Intersection::AtInfinity(_) => Some(1.0),
        Intersection::Coincident => None,
    }
}

/// The polygons of inversion 2 or 3 with the Coriolis component
/// ([`super::CoriolisPolygon`], what the figures `coriolis-inversion-2`
/// and `-3` draw and read) over `samples` angles (and 0°, 90°, 180°,
/// 270°), the driver at 1 rad/s, against the chain's exact link motion
/// ([`super::InversionPose::motion`], the engine's derivatives of φ and
/// x_A): d's angular velocity and acceleration, the block's sliding
/// velocity and acceleration along d (scaled by r), and the size of the
/// Coriolis component against 2 |ω_d v| of the exact values. κ divides by
/// s = x_A / (l + r + |e|), the share of the chain's size the meets of
/// the polygons divide by (CA · u = x_A); empty for inversions 1 and 4.
pub fn coriolis_sweep(chain: &super::InvertedChain, samples: usize) -> Vec<ChainCheckRow> {
    let m = chain.mechanism();
    let (r, size) = (m.crank(), m.crank() + m.rod() + m.offset().abs());
    let mut worst = Worst::new(&[
        "ω_d (velocity polygon)",
        "α_d (acceleration polygon)",
        "sliding velocity (/r)",
        "sliding acceleration (Coriolis; /r)",
        "Coriolis 2ω_d v (/r)",
    ]);
    for angle in angles(samples) {
        let p = chain.pose(angle);
        let (Some(exact), Some(c)) = (p.motion(1.0), super::CoriolisPolygon::construct(&p, 1.0))
        else {
            continue;
        };
        let deg = angle.degrees();
        let sine = p.engine_pose().position() / size;
        let (first, second) = (kappa(sine, 2.0), kappa(sine, 6.0));
        let diff = |x: f64, y: f64, scale: f64| Some((x - y).abs() / scale);
        let w = exact.velocity[3];
        worst.add(0, deg, diff(c.omega_d(), w, 1.0), first);
        worst.add(
            1,
            deg,
            diff(c.alpha_d(), exact.acceleration[3], 1.0),
            second,
        );
        worst.add(
            2,
            deg,
            diff(c.sliding_velocity(), exact.sliding_velocity, r),
            first,
        );
        worst.add(
            3,
            deg,
            diff(c.sliding_acceleration(), exact.sliding_acceleration, r),
            second,
        );
        let coriolis = 2.0 * (w * exact.sliding_velocity).abs();
        worst.add(4, deg, diff(c.coriolis().norm(), coriolis, r), second);
    }
    worst.0
}

fn angles(samples: usize) -> Vec<Angle> {
    let n = samples.max(1);
    let mut out: Vec<Angle> = (0..n)
        .filter_map(|k| Angle::from_degrees(360.0 * k as f64 / n as f64).ok())
        .collect();
    out.extend([0.0, 90.0, 180.0, 270.0].map(Angle::deg));
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mechanism::SliderCrank;

    #[test]
    fn sweeps_pass_at_1e_12() {
        let m = SliderCrank::new(1.0, 2.0, -0.3).unwrap();
        for rho in [1.01 * 3.0, -1.01 * 3.0, 1e3, 1e15] {
            for row in slot_sweep(&CylindricChain::new(m, rho).unwrap(), 720) {
                assert!(row.passes(1e-12), "{rho}: {row:?}");
                assert!(row.poses > 0);
            }
        }
        // At the limit of assembly (l = r + 1 ulp) the rod meets the slot
        // almost square near θ = 280.73°, where plain Newton jumped turns
        // of the slot away (a difference of 4.6e3 × (l + r)).
        let m = SliderCrank::new(1.0, 1.0000000000000002, 0.0).unwrap();
        let chain = CylindricChain::new(m, 2.0).unwrap();
        for row in slot_sweep(&chain, 3600) {
            assert!(row.passes(1e-12), "limit: {row:?}");
        }
        for deg in [280.7316, 90.0, 270.0, 179.5] {
            let angle = Angle::from_degrees(deg).unwrap();
            let s = arc_position_by_iteration(&chain, angle);
            // The circle of radius 2 about (0, −2), tangent to y = 0 at the
            // origin: A at arc σ is (2 sin(σ/2), 2 cos(σ/2) − 2).
            let (a, b) = (
                Point::new(2.0 * (s / 2.0).sin(), 2.0 * (s / 2.0).cos() - 2.0),
                Point::new(angle.cos(), angle.sin()),
            );
            assert!(s.abs() <= 2.0 * std::f64::consts::PI, "{deg}: σ = {s}");
            assert!(
                ((a - b).norm() - m.rod()).abs() < 1e-12,
                "{deg}: |A − B| = {}",
                (a - b).norm()
            );
        }
        for links in [
            [1.0, 3.0, 2.5, 3.2],
            [3.0, 2.0, 3.0, 4.5],
            [1.0, 3.0, 1.0, 3.0],
        ] {
            let q = QuadricChain::new(links[0], links[1], links[2], links[3]).unwrap();
            for row in quadric_sweep(&q, 720) {
                assert!(row.passes(1e-12), "{links:?}: {row:?}");
            }
        }
    }
}
