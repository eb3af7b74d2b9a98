//! The slider in its guides: the friction μ |N| against its motion, N the
//! guides' reaction, which itself depends on the friction, and the weights
//! along and across the line of stroke. The slider's two balances are
//! solved exactly (no iteration), and a coefficient for which they have
//! no unique solution somewhere in the turn is refused.

use crate::error::{Error, Field, Result, non_negative};
use crate::mechanism::{Pose, SliderCrank};

/// |ds/dθ| below this times r counts as the slider at rest: a dead centre
/// reached by its angle (where s′ is the rounding of 0, about 1e-17 r).
/// There the friction is taken as 0, between its two one-sided values
/// (the torque is F · OM with OM = 0 there, so it is not affected).
pub const AT_REST: f64 = 1e-12;

/// The direction of the slider's velocity along +x at `pose`, the crank
/// turning at `omega`: 1, −1, or 0 at rest ([`AT_REST`]; ω = 0).
pub(crate) fn motion(pose: &Pose, omega: f64) -> f64 {
    let rate = pose.position_rate();
    if rate.abs() <= AT_REST * pose.mechanism().crank() || omega == 0.0 {
        0.0
    } else {
        (rate * omega).signum()
    }
}

/// The largest |tan φ| of `mechanism` over a turn: at θ = 90° or 270°,
/// where |r sin θ − e| reaches r + |e|.
pub fn largest_tan_obliquity(mechanism: &SliderCrank) -> f64 {
    let rise = mechanism.crank() + mechanism.offset().abs();
    let l = mechanism.rod();
    rise / ((l - rise) * (l + rise)).sqrt()
}

/// Checks the coefficient of friction μ of the slider in the guides of
/// `mechanism` for the running engine: finite, ≥ 0, and below 1 / |tan φ|
/// at every pose of the turn.
///
/// Where μ |tan φ| ≥ 1 with the slider moving, the slider's balances
/// (F = F₀ + μ s |N|, N = P + F tan φ) have two solutions or none: the
/// slider self-locks, the friction able to take all the force the rod
/// gives it. The running engine passes through the largest obliquity
/// every turn, so such a μ is refused for the engine, not at a pose.
///
/// Errors: μ negative or not finite; μ ≥ 1 / max |tan φ|.
pub fn check_friction(mechanism: &SliderCrank, mu: f64) -> Result<f64> {
    let mu = non_negative(Field::Friction, mu)?;
    let tan = largest_tan_obliquity(mechanism);
    if mu * tan < 1.0 {
        return Ok(mu);
    }
    let at = if mechanism.offset() > 0.0 { 270 } else { 90 };
    Err(Error::OutOfRange {
        name: Field::Friction,
        value: mu,
        reason: format!(
            "the slider self-locks in its guides where μ |tan φ| ≥ 1 (the friction can then take all the rod's force, and the forces have no unique value); this engine reaches |tan φ| = {} at θ = {at}°, so μ must be below 1/|tan φ| = {}",
            crate::number::significant(tan, 6),
            crate::number::significant(1.0 / tan, 6)
        ),
    })
}

/// The slider's balances with friction, solved exactly: the piston effort
/// F and the guides' reaction N on the slider (along +y) from
///
///   F = F₀ + μ s |N|,  N = N(F) = P + t F,
///
/// F₀ the effort without friction (towards the crank), s the direction of
/// the slider's motion along +x ([`motion`]), t = tan φ and `reaction`
/// the affine N(F). With μ |t| < 1 ([`check_friction`]) the solution is
/// unique: N has the sign σ of N₀ = N(F₀), and N = N₀ / (1 − μ s t σ).
/// With s = 0 or μ = 0, N = N₀ and F = F₀.
pub(crate) fn slide(f0: f64, reaction: impl Fn(f64) -> f64, t: f64, mu: f64, s: f64) -> (f64, f64) {
    let n0 = reaction(f0);
    if mu == 0.0 || s == 0.0 {
        return (f0, n0);
    }
    let sigma = if n0 < 0.0 { -1.0 } else { 1.0 };
    let n = n0 / (1.0 - mu * s * t * sigma);
    (f0 + mu * s * n.abs(), n)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The solution satisfies both balances, and no other N of either
    /// sign does (the two cases of |N| written out).
    #[test]
    fn the_slider_balance_has_its_one_solution() {
        let mut next = crate::dynamics::uniform_draws(0x005e_ed0f_f1c7);
        for _ in 0..2000 {
            let (f0, p) = (200.0 * next() - 100.0, 200.0 * next() - 100.0);
            let t = 4.0 * next() - 2.0;
            let mu = 0.999 * next() / t.abs().max(1e-9);
            let s = [-1.0, 0.0, 1.0][(3.0 * next()) as usize % 3];
            let (f, n) = slide(f0, |f| p + t * f, t, mu, s);
            let scale = 1.0 + f0.abs() + p.abs() + f.abs();
            assert!((f - f0 - mu * s * n.abs()).abs() <= 1e-12 * scale * (1.0 + mu));
            assert!((n - p - t * f).abs() <= 1e-12 * scale * (1.0 + t.abs()));
            // Each sign of N solved as a linear equation: exactly one
            // agrees with its sign, and it is the solution.
            let n0 = p + t * f0;
            let agree: Vec<f64> = [1.0f64, -1.0]
                .into_iter()
                .map(|sign| (sign, n0 / (1.0 - mu * s * t * sign)))
                .filter(|(sign, n)| n * sign > 0.0)
                .map(|(_, n)| n)
                .collect();
            if n0 != 0.0 {
                assert_eq!(agree.len(), 1, "{f0} {p} {t} {mu} {s}");
                assert!((agree[0] - n).abs() <= 1e-12 * scale);
            }
        }
    }

    #[test]
    fn a_self_locking_coefficient_is_refused_naming_the_bound() {
        let m = SliderCrank::in_line(1.0, 2.0).unwrap();
        // tan φ_max = 1/√3: μ below √3.
        assert!((largest_tan_obliquity(&m) - 1.0 / 3f64.sqrt()).abs() < 1e-15);
        assert_eq!(check_friction(&m, 1.7).unwrap(), 1.7);
        let e = check_friction(&m, 1.74).unwrap_err().to_string();
        assert!(
            e.contains("self-locks") && e.contains("below 1/|tan φ| = 1.73205"),
            "{e}"
        );
        // r + |e| = 1.5, l = 4: tan φ = 1.5/√13.75, μ below 2.472.
        let offset = SliderCrank::new(1.0, 4.0, 0.5).unwrap();
        assert!(check_friction(&offset, 2.47).is_ok());
        let e = check_friction(&offset, 2.48).unwrap_err().to_string();
        assert!(
            e.contains("θ = 270°") && e.contains("below 1/|tan φ| = 2.47207"),
            "{e}"
        );
        assert!(check_friction(&m, -0.1).is_err());
        assert!(check_friction(&m, f64::NAN).is_err());
        assert!(check_friction(&m, f64::INFINITY).is_err());
    }
}
