//! Partial balance of a single cylinder: a counterweight on the crank
//! balancing the rotating mass and a fraction c of the reciprocating
//! mass, what it leaves unbalanced, and the hammer blow it puts on the
//! rails when the crank is a locomotive's coupled wheel.

use crate::angle::Angle;
use crate::error::{Error, Field, Result, finite, non_negative, positive};

/// The fractions of `table partial-balance` and Python's
/// `partial_balance()` when none are given: none balanced, a half (the
/// unbalanced force constant in size), two thirds (the textbooks' usual
/// locomotive practice) and all (the whole primary force moved across
/// the line of stroke).
pub const DEFAULT_FRACTIONS: [f64; 4] = [0.0, 0.5, 2.0 / 3.0, 1.0];

/// The unbalanced primary force of one cylinder with the fraction c of
/// its reciprocating mass m (and all its rotating mass) balanced by a
/// counterweight opposite the crank, per unit m r ω², at one crank angle.
///
/// The reciprocating parts' primary force is m r ω² cos θ along the line
/// of stroke; the rotating mass m_R at the crank pin exerts m_R r ω²
/// along the crank; the counterweight B at radius b, with
/// B b = (m_R + c m) r, exerts (m_R + c m) r ω² opposite the crank. What
/// is left is (1 − c) m r ω² cos θ along the line of stroke and
/// −c m r ω² sin θ across it: the rotating mass cancels, so the
/// counterweight's share for it changes nothing here.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Unbalanced {
    /// Along the line of stroke, away from the crank (horizontal in a
    /// horizontal engine): (1 − c) cos θ.
    pub horizontal: f64,
    /// Across it, in the sense θ turns (vertical in a horizontal engine):
    /// −c sin θ.
    pub vertical: f64,
    /// The size, √((1 − c)² cos²θ + c² sin²θ).
    pub magnitude: f64,
}

/// The fraction c of the reciprocating mass a counterweight balances.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct PartialBalance {
    fraction: f64,
}

impl PartialBalance {
    /// The balance of the fraction `fraction` (0 ≤ c ≤ 1: 0 balances the
    /// rotating mass alone, 1 moves the whole primary force across the
    /// line of stroke).
    ///
    /// Errors: c not finite or outside 0 to 1.
    pub fn new(fraction: f64) -> Result<Self> {
        let c = non_negative(Field::BalancedFraction, fraction)?;
        if c > 1.0 {
            return Err(Error::OutOfRange {
                name: Field::BalancedFraction,
                value: c,
                reason: "a counterweight balances a fraction 0 to 1 of the reciprocating mass"
                    .into(),
            });
        }
        Ok(Self { fraction: c })
    }

    /// The fraction c.
    pub fn fraction(&self) -> f64 {
        self.fraction
    }

    /// The unbalanced force at `angle`, per unit m r ω².
    pub fn at(&self, angle: Angle) -> Unbalanced {
        let c = self.fraction;
        let horizontal = (1.0 - c) * angle.cos();
        let vertical = -c * angle.sin();
        Unbalanced {
            horizontal: horizontal + 0.0,
            vertical: vertical + 0.0,
            magnitude: horizontal.hypot(vertical),
        }
    }

    /// The largest size of the unbalanced force over a turn, per unit
    /// m r ω²: max(1 − c, c), along the line of stroke at the dead
    /// centres when c ≤ ½, across it at 90° and 270° when c ≥ ½ (at
    /// c = ½ the size is ½ at every angle).
    pub fn largest(&self) -> f64 {
        self.fraction.max(1.0 - self.fraction)
    }

    /// The least size over a turn: min(1 − c, c).
    pub fn least(&self) -> f64 {
        self.fraction.min(1.0 - self.fraction)
    }

    /// The counterweight's moment B b = (m_R + c m) r (mass × length):
    /// the counterweight B at radius b opposite the crank for the rotating
    /// mass `rotating` at the crank pin, the reciprocating mass
    /// `reciprocating` and the crank radius `crank`.
    pub fn counterweight(&self, rotating: f64, reciprocating: f64, crank: f64) -> f64 {
        (rotating + self.fraction * reciprocating) * crank
    }
}

/// A locomotive's coupled wheel carrying the crank: the hammer blow of
/// the counterweight's share for the reciprocating parts.
///
/// The counterweight's share for the rotating mass is cancelled by the
/// rotating mass at every angle; its share for the reciprocating parts,
/// B_r b = c m r, is not cancelled across the line of stroke: its
/// centrifugal force c m r ω² has the vertical component −c m r ω² sin θ
/// that presses the wheel on the rail and lifts it once a turn. Its
/// largest value, **c m r ω²**, is the hammer blow; with the wheel of
/// diameter D rolling at the speed v, ω = 2v/D.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct HammerBlow {
    /// c m r, the reciprocating parts' share of the counterweight's
    /// moment (mass × length).
    pub moment: f64,
    /// The wheel's diameter D.
    pub wheel: f64,
}

impl HammerBlow {
    /// The wheel of diameter `wheel` with the fraction `balance` of the
    /// reciprocating mass `mass` balanced on a crank of radius `crank`.
    ///
    /// Errors: a mass or a crank negative or not finite, a wheel not
    /// positive, a moment c m r beyond the largest f64. A mass or a
    /// fraction of 0 gives no hammer blow.
    pub fn new(balance: &PartialBalance, mass: f64, crank: f64, wheel: f64) -> Result<Self> {
        let mass = non_negative(Field::Mass, mass)?;
        let crank = non_negative(Field::Crank, crank)?;
        let wheel = positive(Field::Wheel, wheel)?;
        let moment = balance.fraction() * mass * crank;
        if !moment.is_finite() {
            return Err(Error::OutOfRange {
                name: Field::Mass,
                value: mass,
                reason: "the counterweight's moment c m r is beyond the largest number".into(),
            });
        }
        Ok(Self { moment, wheel })
    }

    /// The wheel's angular speed 2v/D at the speed `speed` along the
    /// rails (length unit per second).
    pub fn omega(&self, speed: f64) -> f64 {
        2.0 * speed / self.wheel
    }

    /// The hammer blow c m r ω² at the speed `speed`, in the force unit.
    ///
    /// Errors: a speed not finite, or so fast that the blow is beyond the
    /// largest number.
    pub fn at_speed(&self, speed: f64) -> Result<f64> {
        let w = self.omega(finite(Field::Speed, speed)?);
        let blow = self.moment * w * w;
        if blow.is_finite() {
            Ok(blow)
        } else {
            Err(Error::OutOfRange {
                name: Field::Speed,
                value: speed,
                reason: "the hammer blow c m r ω² is beyond the largest number".into(),
            })
        }
    }

    /// The speed at which the hammer blow equals the wheel's static load
    /// `load` on the rail, so that the wheel lifts off once a turn:
    /// v = (D/2) √(P / (c m r)); `None` when nothing is balanced (no
    /// hammer blow at any speed).
    ///
    /// Errors: a load not positive, or one so far above the blow's
    /// moment that the speed is beyond the largest number.
    pub fn lifting_speed(&self, load: f64) -> Result<Option<f64>> {
        let load = positive(Field::Load, load)?;
        if self.moment == 0.0 {
            return Ok(None);
        }
        let v = 0.5 * self.wheel * (load / self.moment).sqrt();
        if v.is_finite() {
            Ok(Some(v))
        } else {
            Err(Error::OutOfRange {
                name: Field::Load,
                value: load,
                reason: "the wheel would lift only beyond the largest speed".into(),
            })
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The closed forms at c = 0, ½, ⅔, 1 against the forces summed
    /// vector by vector in the test: the reciprocating mass's primary
    /// force, the rotating mass's and the counterweight's.
    #[test]
    fn the_unbalanced_force_is_the_sum_of_the_three() {
        let (m, m_rot) = (3.0, 1.7);
        for c in [0.0, 0.5, 2.0 / 3.0, 1.0] {
            let b = PartialBalance::new(c).unwrap();
            for k in 0..72 {
                let t = (5.0 * k as f64).to_radians();
                // Per unit r ω²: m cos θ along x; m_R (cos θ, sin θ); the
                // counterweight −(m_R + c m)(cos θ, sin θ).
                let x = m * t.cos() + m_rot * t.cos() - (m_rot + c * m) * t.cos();
                let y = m_rot * t.sin() - (m_rot + c * m) * t.sin();
                let u = b.at(Angle::deg(5.0 * k as f64));
                assert!((u.horizontal - x / m).abs() < 1e-15, "{c} {k}");
                assert!((u.vertical - y / m).abs() < 1e-15, "{c} {k}");
                assert!((u.magnitude - x.hypot(y) / m).abs() < 1e-15);
            }
        }
    }

    /// c = 0: the whole primary force along the stroke, none across;
    /// c = 1: none along, all across; c = ½: the size ½ at every angle,
    /// the largest over the turn the formula's max(1 − c, c).
    #[test]
    fn the_textbook_cases() {
        let none = PartialBalance::new(0.0).unwrap();
        let all = PartialBalance::new(1.0).unwrap();
        let half = PartialBalance::new(0.5).unwrap();
        for d in [0.0, 30.0, 90.0, 135.0, 270.0] {
            let a = Angle::deg(d);
            assert_eq!(none.at(a).vertical, 0.0);
            assert_eq!(none.at(a).horizontal, a.cos() + 0.0);
            assert_eq!(all.at(a).horizontal, 0.0);
            assert_eq!(all.at(a).vertical, -a.sin() + 0.0);
            assert!((half.at(a).magnitude - 0.5).abs() < 1e-16);
        }
        // The largest over a fine turn against max(1 − c, c), ⅔ → ⅔ at 90°.
        for c in [0.0, 0.25, 0.5, 2.0 / 3.0, 0.9, 1.0] {
            let b = PartialBalance::new(c).unwrap();
            let brute = (0..=3600)
                .map(|k| b.at(Angle::deg(k as f64 / 10.0)).magnitude)
                .fold(0.0, f64::max);
            assert!((brute - f64::max(c, 1.0 - c)).abs() < 1e-15, "{c}");
            assert_eq!(b.largest(), f64::max(c, 1.0 - c));
            assert_eq!(b.least(), f64::min(c, 1.0 - c));
        }
    }

    #[test]
    fn the_counterweight_and_the_hammer_blow() {
        let b = PartialBalance::new(2.0 / 3.0).unwrap();
        // B b = (m_R + c m) r.
        assert!((b.counterweight(150.0, 180.0, 0.3) - (150.0 + 120.0) * 0.3).abs() < 1e-12);
        // A wheel of 1.8 m at 90 km/h = 25 m/s: ω = 2 × 25 / 1.8 rad/s;
        // the blow (2/3)(180)(0.3) ω².
        let h = HammerBlow::new(&b, 180.0, 0.3, 1.8).unwrap();
        let w = 50.0 / 1.8;
        assert!((h.at_speed(25.0).unwrap() - 36.0 * w * w).abs() < 1e-9);
        // The wheel lifts where the blow equals the load.
        let v = h.lifting_speed(60_000.0).unwrap().unwrap();
        assert!((h.at_speed(v).unwrap() - 60_000.0).abs() < 1e-8);
        let none = HammerBlow::new(&PartialBalance::new(0.0).unwrap(), 180.0, 0.3, 1.8).unwrap();
        assert_eq!(none.at_speed(25.0).unwrap(), 0.0);
        assert_eq!(none.lifting_speed(60_000.0).unwrap(), None);
    }

    #[test]
    fn bad_values_are_refused() {
        for c in [-0.1, 1.01, f64::NAN, f64::INFINITY] {
            assert!(PartialBalance::new(c).is_err(), "{c}");
        }
        let b = PartialBalance::new(0.5).unwrap();
        assert!(HammerBlow::new(&b, 1.0, 1.0, 0.0).is_err());
        assert!(HammerBlow::new(&b, -1.0, 1.0, 1.0).is_err());
        assert!(HammerBlow::new(&b, 1.0, f64::NAN, 1.0).is_err());
        // Beyond the largest number: refused, never inf.
        assert!(HammerBlow::new(&b, 1e300, 1e300, 1.0).is_err());
        let h = HammerBlow::new(&b, 1.0, 1.0, 1.0).unwrap();
        assert!(h.at_speed(1e200).is_err());
        assert!(h.at_speed(f64::NAN).is_err());
        assert!(h.lifting_speed(-1.0).is_err());
        let tiny = HammerBlow::new(&b, 1e-300, 1e-5, 1.0).unwrap();
        assert!(tiny.lifting_speed(1e300).is_err());
    }
}
