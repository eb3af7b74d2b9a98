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
    /// single cylinder; an empty list is refused, not taken for one).
    ///
    /// Each phase is reduced exactly modulo the cycle before use (and
    /// `phases_deg` holds it so): 1e17° is 280° on a one-turn cycle, as it
    /// is in exact arithmetic.
    ///
    /// Errors: no phase, a phase not finite, more than [`MAX_CYLINDERS`]; an engine
    /// whose torque the quadrature cannot integrate to the tolerance
    /// within its budget ([`Error::Limit`]: near the limit of assembly the
    /// torque spikes at the dead centres), refused rather than answered
    /// with a fluctuation of energy that may be far from the truth.
    pub fn new(engine: &Engine, phases_deg: &[f64]) -> Result<Self> {
        let turns = engine.gas().turns();
        let phases = check_phases(phases_deg, turns)?;
        let radians: Vec<f64> = phases.iter().map(|d| d.to_radians()).collect();
        let cycle = TAU * turns as f64;
        let torque = |t: f64| total_torque(engine, &radians, t);
        let breaks = breakpoints(engine, &radians);
        let samples = BRACKETS * turns;
        let peak = (0..samples)
            .map(|i| torque(cycle * i as f64 / samples as f64).abs())
            .fold(0.0, f64::max);
        let tolerance = RELATIVE_TOLERANCE * peak * cycle;
        let over = |f: &dyn Fn(f64) -> f64, a: f64, b: f64| -> Result<f64> {
            pieces(&breaks, a, b)
                .map(|(x, y)| {
                    let piece = integrate(f, x, y, tolerance * (y - x) / cycle);
                    if piece.met {
                        Ok(piece.value)
                    } else {
                        Err(out_of_reach(x, y))
                    }
                })
                .sum()
        };
        let work = over(&torque, 0.0, cycle)?;
        let mean = work / cycle;
        let excess = |t: f64| torque(t) - mean;
        let crossings = crossings(&excess, &breaks, cycle, samples);
        let mut lobes = Vec::with_capacity(crossings.len() + 1);
        let (mut energy, mut start) = (0.0, 0.0);
        let (mut max, mut min) = ((0.0, 0.0), (0.0, 0.0));
        for end in crossings.into_iter().chain([cycle]) {
            let area = over(&excess, start, end)?;
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

/// The phases, each finite and reduced exactly into [0, the cycle) (360°
/// a turn): a phase and the same plus any whole number of cycles give one
/// engine, however large.
impl TurningMoment {
    /// `x`, an amount of work or energy of this diagram, or 0 where it is
    /// within the integrals' tolerance of zero: below it a value's digits
    /// are rounding, not the engine's (the inertia forces alone do no work
    /// over a turn, and print 0, not −1.1e−13).
    pub fn settled(&self, x: f64) -> f64 {
        if x.abs() <= self.tolerance { 0.0 } else { x }
    }
}

/// The refusal of an engine whose torque between `a` and `b` (radians)
/// the quadrature cannot integrate to its tolerance within its budget.
fn out_of_reach(a: f64, b: f64) -> Error {
    Error::Limit(format!(
        "the turning moment of this engine cannot be integrated to its tolerance between θ = {}° and {}°: the torque there spikes too sharply (the rod at the limit of assembly, l close to r + |e|); a longer rod or a smaller offset can be done",
        crate::number::significant(a.to_degrees(), 6),
        crate::number::significant(b.to_degrees(), 6)
    ))
}

fn check_phases(phases: &[f64], turns: usize) -> Result<Vec<f64>> {
    if phases.len() > MAX_CYLINDERS {
        return Err(Error::OutOfRange {
            name: Field::Cylinders,
            value: phases.len() as f64,
            reason: format!("an engine has at most {MAX_CYLINDERS} cylinders"),
        });
    }
    if phases.is_empty() {
        return Err(Error::OutOfRange {
            name: Field::Cylinders,
            value: 0.0,
            reason: "an engine has at least one cylinder: give its phase, 0 for one cylinder"
                .into(),
        });
    }
    let cycle = 360.0 * turns as f64;
    phases
        .iter()
        .map(|&d| finite(Field::Phase, d).map(|d| reduce(d, cycle)))
        .collect()
}

/// `d` modulo `cycle` in [0, cycle), exactly: the remainder of two floats
/// is exact, and a negative one is raised by a cycle (where that rounds up
/// to the cycle itself, the angle is 0).
fn reduce(d: f64, cycle: f64) -> f64 {
    let r = d % cycle;
    let r = if r < 0.0 { r + cycle } else { r };
    if r >= cycle { 0.0 } else { r + 0.0 }
}

/// T(θ) = Σ T_i(θ + δ_i), θ and δ_i in radians; each cylinder in the turn
/// of its cycle that θ + δ_i falls in.
pub(crate) fn total_torque(engine: &Engine, phases: &[f64], theta: f64) -> f64 {
    phases
        .iter()
        .map(|d| {
            let at = theta + d;
            let turn = engine.turn_at_radians(at);
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
        let phases = check_phases(phases_deg, self.gas().turns())?;
        let mut sum = 0.0;
        for d in phases {
            let at = angle.degrees() + d;
            let turn = self.turn_at_degrees(at);
            let a = Angle::from_degrees(at)?;
            sum += self.torque_in_turn(&self.mechanism().pose(a), turn);
        }
        Ok(sum)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::SliderCrank;
    use crate::dynamics::IndicatorDiagram;

    fn engine() -> Engine {
        Engine::new(SliderCrank::new(1.0, 3.0, 0.2).unwrap(), 1.0, 10.0).unwrap()
    }

    fn four_stroke() -> Engine {
        let d = IndicatorDiagram::new(
            vec![0.0, 0.5, 1.0],
            vec![40.0, 10.0, 3.0],
            vec![9.0, 4.0, 1.0],
            1.0,
        )
        .unwrap()
        .with_pumping(vec![1.5, 1.2, 1.1], vec![-0.2, -0.3, -0.1])
        .unwrap();
        engine().with_gas(GasForce::Indicator(d)).unwrap()
    }

    #[test]
    fn phases_are_reduced_exactly_modulo_the_cycle() {
        assert!(TurningMoment::new(&engine(), &[]).is_err());
        assert_eq!(reduce(1e17, 360.0), 280.0);
        assert_eq!(reduce(1e17, 720.0), 640.0);
        assert_eq!(reduce(-90.0, 360.0), 270.0);
        assert_eq!(reduce(-1e-300, 360.0), 0.0);
        assert_eq!(reduce(-0.0, 360.0).to_bits(), 0.0f64.to_bits());
        let e = engine();
        let far = TurningMoment::new(&e, &[0.0, 1e17]).unwrap();
        let near = TurningMoment::new(&e, &[0.0, 280.0]).unwrap();
        assert_eq!(far, near);
        let e = four_stroke();
        let far = TurningMoment::new(&e, &[0.0, 1e17, -1e17]).unwrap();
        let near = TurningMoment::new(&e, &[0.0, 640.0, 80.0]).unwrap();
        assert_eq!(far, near);
        let at = Angle::deg(33.0);
        assert_eq!(
            e.torque_of_cylinders(&[1e17], at).unwrap(),
            e.torque_of_cylinders(&[640.0], at).unwrap()
        );
    }

    #[test]
    fn each_dead_centre_takes_the_line_of_the_stroke_that_starts_there() {
        let e = four_stroke();
        let m = *e.mechanism();
        let GasForce::Indicator(d) = e.gas() else {
            unreachable!()
        };
        let (odc, idc) = (m.pose(m.outer_dead_centre()), m.pose(m.inner_dead_centre()));
        let area = d.area();
        for omega in [10.0, -10.0] {
            // Firing top dead centre: compression ends, expansion starts.
            assert_eq!(d.force_in_turn(&odc, omega, 0), 40.0 * area);
            // The end of expansion is the start of exhaust.
            assert_eq!(d.force_in_turn(&idc, omega, 0), 1.1 * area);
            // The end of exhaust is the start of intake.
            assert_eq!(d.force_in_turn(&odc, omega, 1), -0.2 * area);
            // The end of intake is the start of compression.
            assert_eq!(d.force_in_turn(&idc, omega, 1), 1.0 * area);
        }
    }
}
