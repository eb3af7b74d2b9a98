//! Balancing of the reciprocating masses of an in-line engine of several
//! cylinders: the primary and secondary forces and couples, their
//! polygons and what is left unbalanced.

use crate::angle::Angle;
use crate::error::{Error, Field, Result, finite, positive};
use crate::mechanism::SliderCrank;

/// The crank angles of `table balance` and Python's `balance()` when
/// none are given: the four-cylinder flat crank.
pub const DEFAULT_CRANKS: [f64; 4] = [0.0, 180.0, 180.0, 0.0];

/// The planes of `cylinders` cylinders when none are given: a pitch of 1
/// about the middle of the engine, where the textbooks take the reference
/// plane (a couple depends on the plane where its force is unbalanced).
pub fn default_planes(cylinders: usize) -> Vec<f64> {
    let middle = (cylinders as f64 - 1.0) / 2.0;
    (0..cylinders).map(|i| i as f64 - middle).collect()
}

/// Most cylinders of one in-line engine.
pub const MAX_INLINE_CYLINDERS: usize = 64;

/// A part of the unbalance left by the cylinders together: the closing
/// side of its polygon.
///
/// Each cylinder's primary force is the projection on the line of stroke
/// of a vector m r ω² turning with its crank, at the crank's angle α_i
/// (secondary: m r ω²/n at 2α_i); the couple about the reference plane
/// multiplies each by the cylinder's distance a_i. The polygon of these
/// vectors at θ = 0 closes when the part is balanced; otherwise its
/// closing side, turning with the crank (twice as fast for the secondary),
/// is the resultant, whose projection on the line of stroke is the
/// unbalanced force or couple at each θ.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Resultant {
    /// The resultant's components at θ = 0 (x along the line of stroke),
    /// per unit m r ω² (and, for a couple, in the unit of the distances).
    pub vector: [f64; 2],
    /// Its length: the largest unbalanced force (or couple) over a turn.
    pub amplitude: f64,
    /// Whether the polygon closes: the amplitude within `tolerance` ×
    /// the sum of the sides' lengths.
    pub balanced: bool,
}

/// One of the four polygons of an in-line engine's balance.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Polygon {
    /// The primary forces: unit sides along the cranks.
    PrimaryForce,
    /// The primary couples about the reference plane.
    PrimaryCouple,
    /// The secondary forces: sides 1/n at twice the cranks' angles.
    SecondaryForce,
    /// The secondary couples.
    SecondaryCouple,
}

impl Polygon {
    /// The four, primary then secondary, force then couple.
    pub const ALL: [Polygon; 4] = [
        Polygon::PrimaryForce,
        Polygon::PrimaryCouple,
        Polygon::SecondaryForce,
        Polygon::SecondaryCouple,
    ];
}

/// The balance of an in-line engine: its cylinders' crank angles and
/// distances from the reference plane, checked, and the four resultants.
///
/// All values are per unit m r ω² (m the reciprocating mass of one
/// cylinder, the same for all): the secondary ones carry 1/n. The series
/// is that of an in-line cylinder, cos θ + cos 2θ / n, to within
/// O(1/n³); the exact force of each cylinder stands beside it in
/// [`InlineEngine::exact_force`].
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct InlineEngine {
    cranks_deg: Vec<f64>,
    planes: Vec<f64>,
    ratio: f64,
    /// The primary force's resultant.
    pub primary_force: Resultant,
    /// The primary couple's about the reference plane.
    pub primary_couple: Resultant,
    /// The secondary force's.
    pub secondary_force: Resultant,
    /// The secondary couple's.
    pub secondary_couple: Resultant,
}

/// The relative size below which a polygon counts as closed: the
/// rounding of a few dozen sines and cosines.
pub const BALANCE_TOLERANCE: f64 = 1e-12;

impl InlineEngine {
    /// The engine with cylinder i's crank at `cranks_deg[i]` degrees ahead
    /// of the first's, its line of stroke at `planes[i]` from the
    /// reference plane along the shaft, and the ratio n = l / r of every
    /// cylinder; closed polygons judged to [`BALANCE_TOLERANCE`].
    ///
    /// Errors: no cylinder, more than [`MAX_INLINE_CYLINDERS`], lists of
    /// different lengths, a value not finite, n not above 1.
    pub fn new(cranks_deg: &[f64], planes: &[f64], ratio: f64) -> Result<Self> {
        check(cranks_deg, planes)?;
        let ratio = rod_ratio(ratio)?;
        let angles: Vec<Angle> = cranks_deg
            .iter()
            .map(|&d| Angle::from_degrees(d))
            .collect::<Result<_>>()?;
        let once = |a: &Angle| (a.cos(), a.sin());
        // cos 2α, sin 2α from α's, exact where α's are (multiples of 90°).
        let twice = |a: &Angle| {
            let (c, s) = (a.cos(), a.sin());
            (c * c - s * s, 2.0 * s * c)
        };
        let ones = vec![1.0; angles.len()];
        let resultant = |f: &dyn Fn(&Angle) -> (f64, f64), w: &[f64], scale: f64| {
            polygon(angles.iter().map(f).zip(w.iter().copied()), scale)
        };
        let n = ratio;
        Ok(Self {
            primary_force: resultant(&once, &ones, 1.0),
            primary_couple: resultant(&once, planes, 1.0),
            secondary_force: resultant(&twice, &ones, 1.0 / n),
            secondary_couple: resultant(&twice, planes, 1.0 / n),
            cranks_deg: cranks_deg.to_vec(),
            planes: planes.to_vec(),
            ratio,
        })
    }

    /// The cylinders' crank angles in degrees.
    pub fn cranks_deg(&self) -> &[f64] {
        &self.cranks_deg
    }

    /// The cylinders' distances from the reference plane.
    pub fn planes(&self) -> &[f64] {
        &self.planes
    }

    /// Whether the primary and secondary forces and couples are all
    /// balanced.
    pub fn is_balanced(&self) -> bool {
        [
            self.primary_force,
            self.primary_couple,
            self.secondary_force,
            self.secondary_couple,
        ]
        .iter()
        .all(|r| r.balanced)
    }

    /// The polygon `part`'s sides, cylinder by cylinder, per unit m r ω²
    /// as [`Resultant::vector`] is: cylinder i's unit vector along its
    /// crank at α_i (at 2α_i for the secondary), times a_i for a couple,
    /// ÷ n for the secondary. Drawn head to tail from the origin they end
    /// at the resultant; a cylinder in the reference plane has a couple's
    /// side of length 0.
    pub fn sides(&self, part: Polygon) -> Vec<[f64; 2]> {
        let (twice, couple) = match part {
            Polygon::PrimaryForce => (false, false),
            Polygon::PrimaryCouple => (false, true),
            Polygon::SecondaryForce => (true, false),
            Polygon::SecondaryCouple => (true, true),
        };
        let scale = if twice { 1.0 / self.ratio } else { 1.0 };
        self.cranks_deg
            .iter()
            .zip(&self.planes)
            .map(|(&d, &a)| {
                // The cranks were checked finite in `new`.
                let (c, s) = Angle::from_degrees(d).map_or((1.0, 0.0), |a| (a.cos(), a.sin()));
                let (c, s) = if twice {
                    (c * c - s * s, 2.0 * s * c)
                } else {
                    (c, s)
                };
                let w = scale * if couple { a } else { 1.0 };
                [w * c, w * s]
            })
            .collect()
    }

    /// The resultant of the polygon `part`: one of the four fields.
    pub fn resultant(&self, part: Polygon) -> Resultant {
        match part {
            Polygon::PrimaryForce => self.primary_force,
            Polygon::PrimaryCouple => self.primary_couple,
            Polygon::SecondaryForce => self.secondary_force,
            Polygon::SecondaryCouple => self.secondary_couple,
        }
    }

    /// The ratio n = l/r of every cylinder.
    pub fn ratio(&self) -> f64 {
        self.ratio
    }

    /// The unbalanced (primary, secondary) force along the line of stroke
    /// at crank angle `angle` of the first cylinder, per unit m r ω²:
    /// the resultants' projections, x cos θ − y sin θ (at 2θ for the
    /// secondary).
    pub fn forces_at(&self, angle: Angle) -> (f64, f64) {
        (
            project(self.primary_force.vector, angle, 1),
            project(self.secondary_force.vector, angle, 2),
        )
    }

    /// The unbalanced (primary, secondary) couple about the reference
    /// plane at crank angle `angle`, per unit m r ω².
    pub fn couples_at(&self, angle: Angle) -> (f64, f64) {
        (
            project(self.primary_couple.vector, angle, 1),
            project(self.secondary_couple.vector, angle, 2),
        )
    }

    /// The exact unbalanced force of all cylinders along the line of
    /// stroke at `angle`, per unit m r ω² (each cylinder's −s″/r, the
    /// harmonics of every order; the offset is 0).
    pub fn exact_force(&self, angle: Angle) -> Result<f64> {
        let mut sum = 0.0;
        for d in &self.cranks_deg {
            sum += exact_along(Angle::from_degrees(angle.degrees() + d)?, self.ratio);
        }
        Ok(sum)
    }
}

/// Samples of a turn for [`offset_harmonic`].
const HARMONIC_SAMPLES: usize = 4096;

/// The harmonic of order `k` (k ≥ 1) of one cylinder's inertia force in
/// the engine `mechanism` (its offset included), per unit m r ω²: the
/// complex coefficient [re, im] = c_k with −s″/r = Σ_k Re(c_k e^{ikθ}),
/// from the exact acceleration at 4096 and at 8192 samples of a turn (a
/// sum that is exact for every harmonic below half the samples); `None`
/// where the two differ by more than 1e-9 (an engine so near its limit of
/// assembly that its harmonics fall too slowly).
///
/// For e = 0, c₁ = 1 and c₂ = A₂ ≈ 1/n, both real. An offset, the same in
/// every cylinder, makes each cylinder's harmonic k the in-line one's
/// direction turned by arg c_k and its size times |c_k|: every side of a
/// polygon of harmonic k is multiplied by the same c_k, so which polygons
/// close does not depend on the offset (`docs/dynamics.md` §6).
pub fn offset_harmonic(mechanism: &SliderCrank, k: usize) -> Option<[f64; 2]> {
    let sum = |samples: usize| {
        let (mut re, mut im) = (0.0, 0.0);
        for j in 0..samples {
            let turn = j as f64 / samples as f64;
            let angle = Angle::from_degrees(360.0 * turn).ok()?;
            let f = -mechanism.pose(angle).position_acceleration() / mechanism.crank();
            let (s, c) = (std::f64::consts::TAU * k as f64 * turn).sin_cos();
            re += f * c;
            im -= f * s;
        }
        let scale = 2.0 / samples as f64;
        Some([scale * re, scale * im])
    };
    let (a, b) = (sum(HARMONIC_SAMPLES)?, sum(2 * HARMONIC_SAMPLES)?);
    let close = (a[0] - b[0]).hypot(a[1] - b[1]) <= 1e-9 * b[0].hypot(b[1]).max(1.0);
    (close && b.iter().all(|v| v.is_finite())).then_some(b)
}

/// One in-line cylinder's exact inertia force −s″/r ω² along its line of
/// stroke at crank angle `a` for n = `ratio` (per unit m r ω², no offset):
/// cos θ + (n² cos 2θ + sin⁴θ)/(n² − sin²θ)^{3/2}, written with λ = 1/n
/// as cos θ + λ (cos 2θ + λ² sin⁴θ)/(1 − λ² sin²θ)^{3/2} so that no n
/// up to the largest f64 overflows.
pub(super) fn exact_along(a: Angle, ratio: f64) -> f64 {
    let (s, c) = (a.sin(), a.cos());
    let lambda = 1.0 / ratio;
    let l2 = lambda * lambda;
    let cos2 = c * c - s * s;
    let w = 1.0 - l2 * s * s;
    c + lambda * (cos2 + l2 * s.powi(4)) / (w * w.sqrt())
}

/// The closing side of the polygon of `sides` (each a unit vector and its
/// weight), scaled by `scale`.
pub(super) fn polygon(sides: impl Iterator<Item = ((f64, f64), f64)>, scale: f64) -> Resultant {
    let (mut x, mut y, mut length) = (0.0, 0.0, 0.0);
    for ((c, s), w) in sides {
        x += w * c;
        y += w * s;
        length += w.abs();
    }
    let amplitude = x.hypot(y);
    Resultant {
        vector: [scale * x, scale * y],
        amplitude: scale * amplitude,
        balanced: amplitude <= BALANCE_TOLERANCE * length.max(f64::MIN_POSITIVE),
    }
}

/// The projection on the line of stroke of `v` turned by `times` × the
/// crank angle.
fn project(v: [f64; 2], angle: Angle, times: i32) -> f64 {
    let (c, s) = (angle.cos(), angle.sin());
    let (c, s) = if times == 2 {
        (c * c - s * s, 2.0 * s * c)
    } else {
        (c, s)
    };
    v[0] * c - v[1] * s
}

/// Refuses lists of no cylinder, too many, of different lengths, or with
/// a value not finite.
fn check(cranks: &[f64], planes: &[f64]) -> Result<()> {
    if cranks.is_empty() || cranks.len() > MAX_INLINE_CYLINDERS {
        return Err(Error::OutOfRange {
            name: Field::Cylinders,
            value: cranks.len() as f64,
            reason: format!("an in-line engine has 1 to {MAX_INLINE_CYLINDERS} cylinders"),
        });
    }
    if planes.len() != cranks.len() {
        return Err(Error::OutOfRange {
            name: Field::Cylinders,
            value: planes.len() as f64,
            reason: format!(
                "each of the {} cylinders has one crank angle and one plane",
                cranks.len()
            ),
        });
    }
    for &d in cranks {
        finite(Field::Phase, d)?;
    }
    for &a in planes {
        finite(Field::Plane, a)?;
    }
    Ok(())
}

/// The ratio n = l/r of an engine's rod to its crank, checked: positive,
/// finite and above 1 (a rod no longer than its crank does not assemble
/// over a turn). Shared by the in-line and the radial engines.
pub(super) fn rod_ratio(ratio: f64) -> Result<f64> {
    let ratio = positive(Field::Ratio, ratio)?;
    if ratio <= 1.0 {
        return Err(Error::OutOfRange {
            name: Field::Ratio,
            value: ratio,
            reason: "the rod is longer than the crank, n = l/r > 1".into(),
        });
    }
    Ok(ratio)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Cylinders at a pitch of 1, the reference plane in the middle (as
    /// the textbooks take it: where a force is not balanced its couple
    /// depends on the plane).
    fn engine(cranks: &[f64], n: f64) -> InlineEngine {
        let middle = (cranks.len() - 1) as f64 / 2.0;
        let planes: Vec<f64> = (0..cranks.len()).map(|i| i as f64 - middle).collect();
        InlineEngine::new(cranks, &planes, n).unwrap()
    }

    /// The textbooks' standard arrangements.
    #[test]
    fn the_standard_arrangements_balance_as_the_books_say() {
        // Four cylinders, flat crank 0-180-180-0, equal pitch: primary
        // forces and couples balanced, secondary couples about the middle
        // too, secondary forces four times one cylinder's, 4/n.
        let four = engine(&[0.0, 180.0, 180.0, 0.0], 4.0);
        assert!(four.primary_force.balanced && four.primary_couple.balanced);
        assert!(four.secondary_couple.balanced);
        assert!(!four.secondary_force.balanced);
        assert_eq!(four.secondary_force.amplitude, 1.0);
        assert_eq!(four.secondary_force.vector, [1.0, 0.0]);
        // About the first cylinder's plane the unbalanced secondary force
        // has a moment: Σ a_i = 0 + 1 + 2 + 3 = 6, ÷ n.
        let first =
            InlineEngine::new(&[0.0, 180.0, 180.0, 0.0], &[0.0, 1.0, 2.0, 3.0], 4.0).unwrap();
        assert_eq!(first.secondary_couple.amplitude, 1.5);
        // Three cylinders at 120°: forces balanced, couples not; the
        // primary couple of pitch 1 is √3 (planes −1, 0, 1).
        let three = engine(&[0.0, 120.0, 240.0], 5.0);
        assert!(three.primary_force.balanced && three.secondary_force.balanced);
        assert!(!three.primary_couple.balanced && !three.secondary_couple.balanced);
        assert!((three.primary_couple.amplitude - 3f64.sqrt()).abs() < 1e-15);
        // Six cylinders 0-120-240-240-120-0: everything balanced.
        let six = engine(&[0.0, 120.0, 240.0, 240.0, 120.0, 0.0], 3.5);
        assert!(six.is_balanced(), "{six:?}");
        // Two cylinders at 180°: primary force balanced, its couple not,
        // secondary forces add.
        let two = engine(&[0.0, 180.0], 4.0);
        assert!(two.primary_force.balanced && !two.primary_couple.balanced);
        assert_eq!(two.secondary_force.amplitude, 0.5);
        // Eight in line, 0-180-90-270-270-90-180-0: all balanced.
        let eight = engine(&[0.0, 180.0, 90.0, 270.0, 270.0, 90.0, 180.0, 0.0], 4.0);
        assert!(eight.is_balanced(), "{eight:?}");
    }

    /// The resultants' projections against a brute sum of the cylinders'
    /// primary and secondary forces and couples, at random arrangements.
    #[test]
    fn the_resultants_are_the_sum_of_the_cylinders() {
        let mut next = crate::dynamics::uniform_draws(0x2545_f491_4f6c_dd1du64);
        for _ in 0..200 {
            let count = 1 + (next() * 8.0) as usize;
            let cranks: Vec<f64> = (0..count).map(|_| 360.0 * next()).collect();
            let planes: Vec<f64> = (0..count).map(|_| 10.0 * next() - 3.0).collect();
            let n = 1.05 + 20.0 * next();
            let e = InlineEngine::new(&cranks, &planes, n).unwrap();
            let theta = 360.0 * next();
            let at = Angle::deg(theta);
            let (mut fp, mut fs, mut cp, mut cs) = (0.0, 0.0, 0.0, 0.0);
            for (d, a) in cranks.iter().zip(&planes) {
                let t = (theta + d).to_radians();
                fp += t.cos();
                fs += (2.0 * t).cos() / n;
                cp += a * t.cos();
                cs += a * (2.0 * t).cos() / n;
            }
            let (p, s) = e.forces_at(at);
            let (pc, sc) = e.couples_at(at);
            let scale = 10.0 * count as f64;
            for (got, want) in [(p, fp), (s, fs), (pc, cp), (sc, cs)] {
                assert!((got - want).abs() <= 1e-12 * scale, "{got} vs {want}");
            }
            // Each polygon's sides, head to tail, end at its resultant;
            // side i is cylinder i's term at θ = 0 (the brute sum's).
            for part in Polygon::ALL {
                let sides = e.sides(part);
                let end = sides
                    .iter()
                    .fold([0.0, 0.0], |a, s| [a[0] + s[0], a[1] + s[1]]);
                let r = e.resultant(part).vector;
                assert!((end[0] - r[0]).abs() <= 1e-12 * scale, "{part:?}");
                assert!((end[1] - r[1]).abs() <= 1e-12 * scale, "{part:?}");
                let (twice, weighted) = match part {
                    Polygon::PrimaryForce => (1.0, false),
                    Polygon::PrimaryCouple => (1.0, true),
                    Polygon::SecondaryForce => (2.0, false),
                    Polygon::SecondaryCouple => (2.0, true),
                };
                for ((side, d), a) in sides.iter().zip(&cranks).zip(&planes) {
                    let t = (twice * d).to_radians();
                    let w = if weighted { *a } else { 1.0 } / if twice > 1.0 { n } else { 1.0 };
                    assert!((side[0] - w * t.cos()).abs() <= 1e-13 * scale);
                    assert!((side[1] - w * t.sin()).abs() <= 1e-13 * scale);
                }
            }
            // The exact force's harmonics beyond the second are within
            // ½ (n² − 1)^(−3/2) for each cylinder (→ 1/(2n³) for a long
            // rod; the bound is met at θ = 90°).
            let exact = e.exact_force(at).unwrap();
            assert!(
                (exact - fp - fs).abs() <= count as f64 * 0.5 / (n * n - 1.0).powf(1.5),
                "{exact} vs {}",
                fp + fs
            );
        }
    }

    /// The harmonics of an offset engine against a sum written here from
    /// x_A = r cos θ + √(l² − (r sin θ − e)²) differentiated by hand; for
    /// e = 0 the first is 1 and the second A₂.
    #[test]
    fn the_offset_harmonics_are_the_fourier_sums_of_the_exact_force() {
        let x2 = |r: f64, l: f64, e: f64, t: f64| {
            let (u, u1, u2) = (r * t.sin() - e, r * t.cos(), -r * t.sin());
            let s = (l * l - u * u).sqrt();
            -r * t.cos() - (u1 * u1 + u * u2) / s - (u * u1).powi(2) / s.powi(3)
        };
        for (r, l, e) in [(1.0, 2.59, 1.29), (0.5, 3.0, 0.0), (1.0, 4.0, -2.0)] {
            let m = SliderCrank::new(r, l, e).unwrap();
            for k in [1usize, 2] {
                let n = 1000;
                let (mut re, mut im) = (0.0, 0.0);
                for j in 0..n {
                    let t = std::f64::consts::TAU * j as f64 / n as f64;
                    let f = -x2(r, l, e, t) / r;
                    re += 2.0 * f * (k as f64 * t).cos() / n as f64;
                    im -= 2.0 * f * (k as f64 * t).sin() / n as f64;
                }
                let c = offset_harmonic(&m, k).unwrap();
                assert!(
                    (c[0] - re).abs() < 1e-10 && (c[1] - im).abs() < 1e-10,
                    "{c:?}"
                );
            }
        }
        let centred = SliderCrank::new(1.0, 4.0, 0.0).unwrap();
        let c1 = offset_harmonic(&centred, 1).unwrap();
        assert!((c1[0] - 1.0).abs() < 1e-14 && c1[1].abs() < 1e-14);
        let a2 = crate::analytic::harmonics::Harmonics::new(4.0, 1)
            .unwrap()
            .even[0];
        let c2 = offset_harmonic(&centred, 2).unwrap();
        assert!((c2[0] - a2).abs() < 1e-13 && c2[1].abs() < 1e-14);
    }

    #[test]
    fn bad_engines_are_refused() {
        assert!(InlineEngine::new(&[], &[], 4.0).is_err());
        assert!(InlineEngine::new(&[0.0, 180.0], &[0.0], 4.0).is_err());
        assert!(InlineEngine::new(&[0.0, f64::NAN], &[0.0, 1.0], 4.0).is_err());
        assert!(InlineEngine::new(&[0.0], &[f64::INFINITY], 4.0).is_err());
        assert!(InlineEngine::new(&[0.0], &[0.0], 1.0).is_err());
        assert!(InlineEngine::new(&vec![0.0; 65], &vec![0.0; 65], 4.0).is_err());
    }
}
