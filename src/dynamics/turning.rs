//! The turning-moment diagram over one cycle (a turn, or two for a
//! four-stroke indicator diagram): the mean torque, the areas above and
//! below it and the fluctuation of energy.

use super::engine::Engine;
use super::gas::GasForce;
use super::quadrature::{bisect, integrate};
use crate::angle::Angle;
use crate::error::{Error, Field, Result, finite};
use std::f64::consts::TAU;

/// Samples per turn that bracket the crossings of the mean line.
const BRACKETS: usize = 720;

/// Relative tolerance of the integrals: each is within this fraction of
/// max |T| × the cycle (2π a turn).
pub const RELATIVE_TOLERANCE: f64 = 1e-12;

/// Most cylinders of one engine.
pub const MAX_CYLINDERS: usize = 64;

/// One area between the turning-moment curve and its mean line, between
/// two crossings (or the ends of the cycle).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Lobe {
    /// Where it starts, crank angle in degrees.
    pub from_deg: f64,
    /// Where it ends.
    pub to_deg: f64,
    /// ∫ (T − T_mean) dθ over it: positive above the mean (energy stored
    /// in the flywheel), negative below.
    pub area: f64,
    /// The energy stored since θ = 0 at its end, the sum of the areas so
    /// far.
    pub energy: f64,
}

/// The turning-moment diagram of an engine of one or more cylinders: each
/// is the same engine on a crank `phase` degrees ahead of the first
/// (cylinder i's crank at θ + δ_i), and T(θ) is the sum of their torques.
/// Over a four-stroke cycle θ and the phases run over 720°: cylinder i is
/// in the second turn of its cycle where θ + δ_i is (modulo 720°) past
/// 360°.
///
/// Integrals are by adaptive Simpson quadrature, split at every kink (dead
/// centres and the indicator diagram's rows) and at the exact crossings of
/// the mean line (found by bisection), to an absolute tolerance of
/// [`RELATIVE_TOLERANCE`] × max |T| × the cycle. A crossing where the curve only
/// touches the mean line is not a crossing and is not needed: the energy's
/// extremes are at true crossings.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct TurningMoment {
    /// The cylinders' phase angles δ_i in degrees (the first 0).
    pub phases_deg: Vec<f64>,
    /// The crank angle of one cycle in degrees: 360, or 720 for a
    /// four-stroke indicator diagram.
    pub cycle_deg: f64,
    /// The work of one cycle, ∫ T dθ over it.
    pub work: f64,
    /// The mean torque, work / the cycle in radians.
    pub mean: f64,
    /// The largest |T| seen (the scale of the tolerance).
    pub peak: f64,
    /// The absolute tolerance of the integrals.
    pub tolerance: f64,
    /// The areas between the curve and its mean line, in order from θ = 0.
    pub lobes: Vec<Lobe>,
    /// The fluctuation of energy ΔE = E_max − E_min.
    pub fluctuation: f64,
    /// The crank angle (degrees) of the most energy stored (the greatest
    /// speed).
    pub max_energy_deg: f64,
    /// The crank angle of the least (the least speed).
    pub min_energy_deg: f64,
    /// The angles in degrees where T has a kink (dead centres, the
    /// indicator diagram's rows), with 0 and the cycle's end: T is smooth
    /// between.
    pub kinks_deg: Vec<f64>,
}

impl TurningMoment {
    /// The diagram of `engine` with cylinders at `phases_deg` (one 0 for a
    /// single cylinder; an empty list is one cylinder).
    ///
    /// Errors: a phase not finite, more than [`MAX_CYLINDERS`].
    pub fn new(engine: &Engine, phases_deg: &[f64]) -> Result<Self> {
        let phases = check_phases(phases_deg)?;
        let radians: Vec<f64> = phases.iter().map(|d| d.to_radians()).collect();
        let turns = engine.gas().turns();
        let cycle = TAU * turns as f64;
        let torque = |t: f64| total_torque(engine, &radians, t);
        let breaks = breakpoints(engine, &radians);
        let samples = BRACKETS * turns;
        let peak = (0..samples)
            .map(|i| torque(cycle * i as f64 / samples as f64).abs())
            .fold(0.0, f64::max);
        let tolerance = RELATIVE_TOLERANCE * peak * cycle;
        let over = |f: &dyn Fn(f64) -> f64, a: f64, b: f64| -> f64 {
            pieces(&breaks, a, b)
                .map(|(x, y)| integrate(f, x, y, tolerance * (y - x) / cycle))
                .sum()
        };
        let work = over(&torque, 0.0, cycle);
        let mean = work / cycle;
        let excess = |t: f64| torque(t) - mean;
        let crossings = crossings(&excess, &breaks, cycle, samples);
        let mut lobes = Vec::with_capacity(crossings.len() + 1);
        let (mut energy, mut start) = (0.0, 0.0);
        let (mut max, mut min) = ((0.0, 0.0), (0.0, 0.0));
        for end in crossings.into_iter().chain([cycle]) {
            let area = over(&excess, start, end);
            energy += area;
            lobes.push(Lobe {
                from_deg: start.to_degrees(),
                to_deg: end.to_degrees(),
                area,
                energy,
            });
            if energy > max.0 {
                max = (energy, end);
            }
            if energy < min.0 {
                min = (energy, end);
            }
            start = end;
        }
        let cycle_deg = 360.0 * turns as f64;
        Ok(Self {
            phases_deg: phases,
            cycle_deg,
            work,
            mean,
            peak,
            tolerance,
            lobes,
            fluctuation: max.0 - min.0,
            max_energy_deg: max.1.to_degrees() % cycle_deg,
            min_energy_deg: min.1.to_degrees() % cycle_deg,
            kinks_deg: breaks.iter().map(|t| t.to_degrees()).collect(),
        })
    }
}

fn check_phases(phases: &[f64]) -> Result<Vec<f64>> {
    if phases.len() > MAX_CYLINDERS {
        return Err(Error::OutOfRange {
            name: Field::Cylinders,
            value: phases.len() as f64,
            reason: format!("an engine has at most {MAX_CYLINDERS} cylinders"),
        });
    }
    if phases.is_empty() {
        return Ok(vec![0.0]);
    }
    phases.iter().map(|&d| finite(Field::Phase, d)).collect()
}

/// T(θ) = Σ T_i(θ + δ_i), θ and δ_i in radians; each cylinder in the turn
/// of its cycle that θ + δ_i falls in.
pub(crate) fn total_torque(engine: &Engine, phases: &[f64], theta: f64) -> f64 {
    let turns = engine.gas().turns();
    phases
        .iter()
        .map(|d| {
            let at = theta + d;
            // The turn, 0 ≤ turn < turns (a float's turn count is exact
            // for any finite angle here: |θ + δ| is far below 2⁵³ turns).
            let turn = (at.div_euclid(TAU) as i64).rem_euclid(turns as i64) as usize;
            match Angle::from_radians(at) {
                Ok(a) => engine.torque_in_turn(&engine.mechanism().pose(a), turn),
                Err(_) => 0.0,
            }
        })
        .sum()
}

/// The angles in [0, cycle) where some cylinder's torque has a kink: its
/// dead centres and, with an indicator diagram, the poses of its rows on
/// both strokes, in every turn of the cycle; sorted, with 0 and the
/// cycle's end.
fn breakpoints(engine: &Engine, phases: &[f64]) -> Vec<f64> {
    let m = engine.mechanism();
    let (outer, inner) = (
        m.outer_dead_centre().radians(),
        m.inner_dead_centre().radians(),
    );
    let inner = if inner < outer { inner + TAU } else { inner };
    let mut own = vec![outer, inner];
    if let GasForce::Indicator(d) = engine.gas() {
        let x_outer = m.pose(m.outer_dead_centre()).position();
        let fractions = d.fractions();
        let middle = fractions.get(1..fractions.len().saturating_sub(1));
        for &f in middle.unwrap_or_default() {
            let target = x_outer - f * m.stroke();
            let gap =
                |t: f64| Angle::from_radians(t).map_or(0.0, |a| m.pose(a).position() - target);
            own.push(bisect(&gap, outer, inner));
            own.push(bisect(&gap, inner, outer + TAU));
        }
    }
    let turns = engine.gas().turns();
    let cycle = TAU * turns as f64;
    let own: Vec<f64> = (0..turns)
        .flat_map(|k| own.iter().map(move |t| t + TAU * k as f64))
        .collect();
    let mut all: Vec<f64> = phases
        .iter()
        .flat_map(|d| own.iter().map(move |t| (t - d).rem_euclid(cycle)))
        .filter(|t| *t > 0.0 && *t < cycle)
        .collect();
    all.extend([0.0, cycle]);
    all.sort_by(f64::total_cmp);
    all.dedup();
    all
}

/// The pieces of [a, b] between the breakpoints.
fn pieces(breaks: &[f64], a: f64, b: f64) -> impl Iterator<Item = (f64, f64)> + '_ {
    let inner = breaks.iter().copied().filter(move |&t| t > a && t < b);
    let mut previous = a;
    inner
        .chain([b])
        .map(move |t| (std::mem::replace(&mut previous, t), t))
        .filter(|(x, y)| y > x)
}

/// The angles in (0, cycle) where `f` changes sign, bracketed by
/// `count` samples over the cycle ([`BRACKETS`] per turn) and one at every
/// breakpoint, and found by bisection.
fn crossings(f: &dyn Fn(f64) -> f64, breaks: &[f64], cycle: f64, count: usize) -> Vec<f64> {
    let mut samples: Vec<f64> = (0..=count)
        .map(|i| cycle * i as f64 / count as f64)
        .collect();
    samples.extend_from_slice(breaks);
    samples.sort_by(f64::total_cmp);
    samples.dedup();
    let values: Vec<(f64, f64)> = samples.iter().map(|&t| (t, f(t))).collect();
    let mut roots = Vec::new();
    // The value at the sample before the pair, when there is one.
    let mut before: Option<f64> = None;
    for (&(s0, a), &(s1, b)) in values.iter().zip(values.iter().skip(1)) {
        match before {
            // A sample exactly on the line: a crossing where the sign
            // changes across it.
            Some(c) if a == 0.0 && s0 < cycle && (c < 0.0) != (b < 0.0) && c != 0.0 && b != 0.0 => {
                roots.push(s0);
            }
            _ if a != 0.0 && b != 0.0 && (a < 0.0) != (b < 0.0) => {
                roots.push(bisect(f, s0, s1));
            }
            _ => {}
        }
        before = Some(a);
    }
    roots
}

impl Engine {
    /// T(θ) of cylinders at `phases_deg` (degrees ahead of the first),
    /// the sum of their torques ([`Engine::torque_in_turn`]), θ in the
    /// first turn of the cycle (a cylinder whose θ + δ is past 360° is in
    /// the second turn of a four-stroke cycle).
    ///
    /// Errors: a phase that is not finite.
    pub fn torque_of_cylinders(&self, phases_deg: &[f64], angle: Angle) -> Result<f64> {
        let phases = check_phases(phases_deg)?;
        let turns = self.gas().turns() as i64;
        let mut sum = 0.0;
        for d in phases {
            let at = angle.degrees() + d;
            let turn = (at.div_euclid(360.0) as i64).rem_euclid(turns) as usize;
            let a = Angle::from_degrees(at)?;
            sum += self.torque_in_turn(&self.mechanism().pose(a), turn);
        }
        Ok(sum)
    }
}
