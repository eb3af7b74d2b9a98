//! Cylinders about one crank: V engines (two banks) and radial engines,
//! balanced by the direct and reverse crank method.

use super::inline::{Resultant, exact_along, polygon};
use crate::angle::Angle;
use crate::error::{Error, Field, Result, finite};

/// The cylinder axes of `table radial` and Python's `radial()` when none
/// are given: the 90° V-twin, its banks at ±45° from the V's middle line.
pub const DEFAULT_AXES: [f64; 2] = [-45.0, 45.0];

/// Most cylinders about one crank.
pub const MAX_RADIAL_CYLINDERS: usize = 64;

/// An engine whose cylinders all work on one crank pin, their axes at
/// the angles β_i (degrees, counter-clockwise from the reference line x),
/// every one with the same reciprocating mass m, crank r and rod ratio
/// n = l/r: a V engine of two banks at ±α (included angle 2α) or a radial
/// engine of k cylinders at 360°/k. The crank angle θ is measured from
/// the reference line; cylinder i's crank angle is θ − β_i. (A radial
/// engine's articulated rods are taken as k equal rods on the pin.)
///
/// Cylinder i's force along its own axis (away from the crank) is
/// m r ω² (cos(θ − β_i) + cos 2(θ − β_i)/n) to within O(1/n³). Summed as
/// vectors, writing e^{iφ} for the unit vector at φ, the primary force is
///
///   (m r ω²/2) [k e^{iθ} + Σ e^{i(2β_i − θ)}]
///
/// and the secondary
///
///   (m r ω²/2n) [Σ e^{−iβ_i} e^{2iθ} + Σ e^{3iβ_i} e^{−2iθ}]:
///
/// each is a **direct crank** turning with the crank (the secondary at
/// 2ω) and a **reverse crank** turning against it, each of constant size
/// (the closing sides of the polygons [`Resultant`] here, drawn at θ = 0).
/// All values are per unit m r ω².
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct RadialEngine {
    axes_deg: Vec<f64>,
    ratio: f64,
    /// The primary direct crank: k/2 along the crank at θ = 0, never
    /// balanced by the cylinders (a counterweight of k m/2 at r opposite
    /// the crank balances it).
    pub primary_direct: Resultant,
    /// The primary reverse crank, ½ Σ e^{2iβ_i}, at −θ.
    pub primary_reverse: Resultant,
    /// The secondary direct crank, (1/2n) Σ e^{−iβ_i}, at 2θ.
    pub secondary_direct: Resultant,
    /// The secondary reverse crank, (1/2n) Σ e^{3iβ_i}, at −2θ.
    pub secondary_reverse: Resultant,
}

impl RadialEngine {
    /// The engine of cylinders with axes at `axes_deg` degrees and rod
    /// ratio n = `ratio`.
    ///
    /// Errors: no cylinder or more than [`MAX_RADIAL_CYLINDERS`], an axis
    /// not finite, n not above 1.
    pub fn new(axes_deg: &[f64], ratio: f64) -> Result<Self> {
        if axes_deg.is_empty() || axes_deg.len() > MAX_RADIAL_CYLINDERS {
            return Err(Error::OutOfRange {
                name: Field::Cylinders,
                value: axes_deg.len() as f64,
                reason: format!("one crank drives 1 to {MAX_RADIAL_CYLINDERS} cylinders"),
            });
        }
        let ratio = super::inline::rod_ratio(ratio)?;
        let mut angles = Vec::with_capacity(axes_deg.len());
        for &b in axes_deg {
            finite(Field::Axis, b)?;
            angles.push(Angle::from_degrees(b)?);
        }
        let half = vec![0.5; angles.len()];
        // e^{ijβ}, exact where β's sine and cosine are.
        let times = |j: i32| -> Vec<(f64, f64)> {
            angles
                .iter()
                .map(|a| {
                    let (c, s) = (a.cos(), a.sin());
                    let (mut x, mut y) = (1.0, 0.0);
                    for _ in 0..j.abs() {
                        (x, y) = (x * c - y * s, x * s + y * c);
                    }
                    (x, if j < 0 { -y } else { y })
                })
                .collect()
        };
        let side =
            |j: i32, scale: f64| polygon(times(j).into_iter().zip(half.iter().copied()), scale);
        let n = ratio;
        Ok(Self {
            primary_direct: side(0, 1.0),
            primary_reverse: side(2, 1.0),
            secondary_direct: side(-1, 1.0 / n),
            secondary_reverse: side(3, 1.0 / n),
            axes_deg: axes_deg.to_vec(),
            ratio,
        })
    }

    /// The cylinders' axes in degrees.
    pub fn axes_deg(&self) -> &[f64] {
        &self.axes_deg
    }

    /// The rod ratio n.
    pub fn ratio(&self) -> f64 {
        self.ratio
    }

    /// The primary force (x, y) at crank angle `angle`, per unit m r ω²:
    /// the direct crank turned by θ plus the reverse turned by −θ.
    pub fn primary_at(&self, angle: Angle) -> [f64; 2] {
        let (c, s) = (angle.cos(), angle.sin());
        add(
            turn(self.primary_direct.vector, c, s),
            turn(self.primary_reverse.vector, c, -s),
        )
    }

    /// The secondary force (x, y) at `angle`, per unit m r ω²: the direct
    /// crank turned by 2θ plus the reverse turned by −2θ.
    pub fn secondary_at(&self, angle: Angle) -> [f64; 2] {
        let (c, s) = (angle.cos(), angle.sin());
        let (c2, s2) = (c * c - s * s, 2.0 * s * c);
        add(
            turn(self.secondary_direct.vector, c2, s2),
            turn(self.secondary_reverse.vector, c2, -s2),
        )
    }

    /// The exact inertia force (x, y) of all the cylinders at `angle`,
    /// per unit m r ω²: each cylinder's −s″/r at its own crank angle
    /// θ − β_i along its axis (every harmonic; no offset).
    ///
    /// Errors: an angle θ − β_i too large to reduce.
    pub fn exact_at(&self, angle: Angle) -> Result<[f64; 2]> {
        let mut sum = [0.0, 0.0];
        for &b in &self.axes_deg {
            let axis = Angle::from_degrees(b)?;
            let along = exact_along(Angle::from_degrees(angle.degrees() - b)?, self.ratio);
            sum = add(sum, [along * axis.cos(), along * axis.sin()]);
        }
        Ok(sum)
    }
}

/// `v` turned by the angle of cosine `c` and sine `s`.
fn turn(v: [f64; 2], c: f64, s: f64) -> [f64; 2] {
    [v[0] * c - v[1] * s, v[0] * s + v[1] * c]
}

fn add(a: [f64; 2], b: [f64; 2]) -> [f64; 2] {
    [a[0] + b[0] + 0.0, a[1] + b[1] + 0.0]
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A small xorshift generator in [0, 1).
    fn random(seed: &mut u64) -> f64 {
        *seed ^= *seed << 13;
        *seed ^= *seed >> 7;
        *seed ^= *seed << 17;
        (*seed >> 11) as f64 / (1u64 << 53) as f64
    }

    /// Each cylinder's primary and secondary force along its own axis,
    /// summed as vectors: the brute sum the direct and reverse cranks
    /// must equal.
    fn brute(axes: &[f64], n: f64, theta: f64) -> ([f64; 2], [f64; 2]) {
        let (mut p, mut q) = ([0.0, 0.0], [0.0, 0.0]);
        for b in axes {
            let (t, u) = ((theta - b).to_radians(), b.to_radians());
            let (f1, f2) = (t.cos(), (2.0 * t).cos() / n);
            p[0] += f1 * u.cos();
            p[1] += f1 * u.sin();
            q[0] += f2 * u.cos();
            q[1] += f2 * u.sin();
        }
        (p, q)
    }

    fn close(a: [f64; 2], b: [f64; 2], tol: f64) -> bool {
        (a[0] - b[0]).abs() <= tol && (a[1] - b[1]).abs() <= tol
    }

    #[test]
    fn random_engines_against_the_brute_sum() {
        let mut seed = 0x9e37_79b9_7f4a_7c15u64;
        for _ in 0..300 {
            let k = 1 + (random(&mut seed) * 9.0) as usize;
            let axes: Vec<f64> = (0..k).map(|_| 360.0 * random(&mut seed) - 180.0).collect();
            let n = 1.05 + 30.0 * random(&mut seed);
            let e = RadialEngine::new(&axes, n).unwrap();
            let theta = 720.0 * random(&mut seed) - 360.0;
            let (p, q) = brute(&axes, n, theta);
            let at = Angle::deg(theta);
            let tol = 1e-13 * k as f64;
            assert!(close(e.primary_at(at), p, tol), "{axes:?} {theta}");
            assert!(close(e.secondary_at(at), q, tol), "{axes:?} {theta}");
            // The exact force's higher harmonics: ½ (n² − 1)^(−3/2) a
            // cylinder at most.
            let x = e.exact_at(at).unwrap();
            let bound = k as f64 * 0.5 / (n * n - 1.0).powf(1.5);
            let series = add(p, q);
            assert!(close(x, series, bound + tol), "{x:?} {series:?}");
        }
    }

    /// V engines of banks at ±α against the textbooks' closed forms:
    /// primary (2 cos²α cos θ, 2 sin²α sin θ), secondary
    /// (2/n)(cos α cos 2α cos 2θ, sin α sin 2α sin 2θ).
    #[test]
    fn v_engines_as_the_books_give_them() {
        let mut seed = 0x1234_5678_9abc_def1u64;
        for _ in 0..200 {
            let alpha = 89.0 * random(&mut seed) + 0.5;
            let n = 1.1 + 10.0 * random(&mut seed);
            let e = RadialEngine::new(&[-alpha, alpha], n).unwrap();
            let theta = 360.0 * random(&mut seed);
            let (a, t) = (alpha.to_radians(), theta.to_radians());
            let p = [
                2.0 * a.cos().powi(2) * t.cos(),
                2.0 * a.sin().powi(2) * t.sin(),
            ];
            let q = [
                2.0 / n * a.cos() * (2.0 * a).cos() * (2.0 * t).cos(),
                2.0 / n * a.sin() * (2.0 * a).sin() * (2.0 * t).sin(),
            ];
            let at = Angle::deg(theta);
            assert!(close(e.primary_at(at), p, 1e-14));
            assert!(close(e.secondary_at(at), q, 1e-14));
        }
    }

    /// The 90° V-twin: the primary force is m r ω² along the crank at every
    /// angle (all direct crank: a counterweight of m at r balances it);
    /// the secondary √2 m r ω² sin 2θ / n across the V's middle line.
    #[test]
    fn the_ninety_degree_v_twin() {
        let n = 4.0;
        let e = RadialEngine::new(&DEFAULT_AXES, n).unwrap();
        assert!(e.primary_reverse.balanced);
        assert_eq!(e.primary_direct.vector, [1.0, 0.0]);
        assert!(!e.secondary_direct.balanced && !e.secondary_reverse.balanced);
        for k in 0..36 {
            let d = 10.0 * k as f64;
            let t = d.to_radians();
            let p = e.primary_at(Angle::deg(d));
            assert!(close(p, [t.cos(), t.sin()], 1e-15), "{d}: {p:?}");
            let q = e.secondary_at(Angle::deg(d));
            assert!(close(q, [0.0, 2f64.sqrt() * (2.0 * t).sin() / n], 1e-15));
        }
    }

    /// Radial engines of 3, 5 and 7 equally spaced cylinders: the primary
    /// force is k/2 m r ω² along the crank (the reverse cranks cancel);
    /// the secondary forces cancel for 5 and 7, and for 3 leave a reverse
    /// crank of 3/(2n) m r ω² turning at −2ω.
    #[test]
    fn radial_engines_of_three_five_and_seven() {
        let n = 3.5;
        for k in [3usize, 5, 7] {
            let axes: Vec<f64> = (0..k).map(|i| 360.0 * i as f64 / k as f64).collect();
            let e = RadialEngine::new(&axes, n).unwrap();
            assert!(
                e.primary_reverse.balanced && e.secondary_direct.balanced,
                "{k}"
            );
            assert_eq!(e.primary_direct.amplitude, k as f64 / 2.0);
            assert_eq!(e.secondary_reverse.balanced, k != 3, "{k}");
            for j in 0..24 {
                let d = 15.0 * j as f64 + 7.0;
                let t = d.to_radians();
                let (p, q) = brute(&axes, n, d);
                let half = k as f64 / 2.0;
                assert!(close(p, [half * t.cos(), half * t.sin()], 1e-14), "{k} {d}");
                let want = if k == 3 {
                    [1.5 / n * (2.0 * t).cos(), -1.5 / n * (2.0 * t).sin()]
                } else {
                    [0.0, 0.0]
                };
                assert!(close(q, want, 1e-14), "{k} {d}: {q:?}");
                let at = Angle::deg(d);
                assert!(close(e.primary_at(at), p, 1e-14));
                assert!(close(e.secondary_at(at), q, 1e-14));
            }
        }
    }

    #[test]
    fn bad_engines_are_refused() {
        assert!(RadialEngine::new(&[], 4.0).is_err());
        assert!(RadialEngine::new(&[0.0, f64::NAN], 4.0).is_err());
        assert!(RadialEngine::new(&[0.0], 1.0).is_err());
        assert!(RadialEngine::new(&[0.0], f64::INFINITY).is_err());
        assert!(RadialEngine::new(&[0.0; 65], 4.0).is_err());
        assert!(RadialEngine::new(&[0.0, 90.0], 1.5).is_ok());
        // The longest rods: every value finite, the exact force the
        // primary (the secondary and beyond vanish as 1/n).
        let e = RadialEngine::new(&[0.0, 120.0, 240.0], f64::MAX).unwrap();
        for d in [0.0, 30.0, 90.0, 200.0] {
            let x = e.exact_at(Angle::deg(d)).unwrap();
            let p = e.primary_at(Angle::deg(d));
            assert!(close(x, p, 1e-15), "{d}: {x:?} {p:?}");
        }
    }
}
