//! Balance in two planes: the masses in two chosen planes (a locomotive's
//! two driving wheels) that balance revolving masses in other planes (the
//! cranks and the balanced share of the reciprocating parts in the
//! cylinders' planes), from the two-plane moment equations.

use crate::angle::Angle;
use crate::error::{Error, Field, Result, finite};

/// A revolving mass's moment m r, its angle and its plane along the shaft.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Revolving {
    /// m r, the mass times its radius (a balance mass's: what it must
    /// carry at whatever radius it is set).
    pub moment: f64,
    /// Its angle, degrees, from the first crank, in the sense of rotation.
    pub angle_deg: f64,
    /// Its plane's distance along the shaft from any one origin.
    pub plane: f64,
}

/// The two balance masses, in the planes `planes` (the wheels'), that
/// balance the revolving `masses` (each m r at its angle and plane): the
/// sum of the m r vectors and of their moments about any plane vanish
/// with them. Taking moments about the second plane gives the first,
/// B₁ (x₁ − x₂) = −Σ m_i r_i (x_i − x₂) along each mass's angle, and
/// about the first the second; each returned with its angle in [0°, 360°)
/// (0 for a zero balance) and its plane.
///
/// Errors: no mass, a value not finite, the two planes the same (one
/// plane cannot balance a couple).
pub fn two_plane_balance(masses: &[Revolving], planes: (f64, f64)) -> Result<[Revolving; 2]> {
    if masses.is_empty() {
        return Err(Error::OutOfRange {
            name: Field::Cylinders,
            value: 0.0,
            reason: "give at least one revolving mass to balance".into(),
        });
    }
    let (x1, x2) = (
        finite(Field::Plane, planes.0)?,
        finite(Field::Plane, planes.1)?,
    );
    if x1 == x2 {
        return Err(Error::OutOfRange {
            name: Field::Plane,
            value: x1,
            reason: "the two balance planes are distinct: one plane cannot balance a couple".into(),
        });
    }
    let mut sums = [[0.0; 2]; 2];
    for m in masses {
        let angle = Angle::from_degrees(finite(Field::Phase, m.angle_deg)?)?;
        let (c, s) = (angle.cos(), angle.sin());
        let mr = finite(Field::Mass, m.moment)?;
        let plane = finite(Field::Plane, m.plane)?;
        // About the second plane for the first mass, about the first for
        // the second.
        for (sum, (about, other)) in sums.iter_mut().zip([(x2, x1), (x1, x2)]) {
            let w = -mr * (plane - about) / (other - about);
            sum[0] += w * c;
            sum[1] += w * s;
        }
    }
    let [b1, b2] = sums;
    Ok([polar(b1, x1), polar(b2, x2)])
}

/// The vector `v` as a [`Revolving`] in `plane`.
fn polar(v: [f64; 2], plane: f64) -> Revolving {
    let moment = v[0].hypot(v[1]);
    let angle_deg = if moment == 0.0 {
        0.0
    } else {
        v[1].atan2(v[0]).to_degrees().rem_euclid(360.0)
    };
    Revolving {
        moment,
        angle_deg,
        plane,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn vector(m: &Revolving) -> [f64; 2] {
        let t = m.angle_deg.to_radians();
        [m.moment * t.cos(), m.moment * t.sin()]
    }

    /// A locomotive's two cylinders inside the frames, cranks at 90°,
    /// each with m r = 1 to balance, in planes ±c from the middle, the
    /// wheels at ±w: moments about the right wheel give the left wheel's
    /// B_L (−2w) = −[(−c − w) (1, 0) + (c − w) (0, 1)], so
    /// B_L = −((c + w), (w − c)) / 2w, worked here for c = 0.3, w = 0.75:
    /// (−0.7, −0.3), |B_L| = √0.58; the right wheel's by symmetry
    /// (−0.3, −0.7).
    #[test]
    fn a_locomotives_two_cylinders_are_balanced_in_its_wheels() {
        let (c, w) = (0.3, 0.75);
        let cylinders = [
            Revolving {
                moment: 1.0,
                angle_deg: 0.0,
                plane: -c,
            },
            Revolving {
                moment: 1.0,
                angle_deg: 90.0,
                plane: c,
            },
        ];
        let [left, right] = two_plane_balance(&cylinders, (-w, w)).unwrap();
        let (l, r) = (vector(&left), vector(&right));
        for (got, want) in [(l, [-0.7, -0.3]), (r, [-0.3, -0.7])] {
            assert!(
                (got[0] - want[0]).abs() < 1e-12 && (got[1] - want[1]).abs() < 1e-12,
                "{got:?}"
            );
        }
        assert!((left.moment - 0.58f64.sqrt()).abs() < 1e-12);
        // The left balance lies 180° + atan(0.3/0.7) from the first crank.
        assert!((left.angle_deg - (180.0 + (0.3f64 / 0.7).atan().to_degrees())).abs() < 1e-9);
    }

    /// Random masses: with the two balance masses, the m r vectors sum to
    /// zero and so do their moments about any plane (the two-plane
    /// equations, written here as the sums).
    #[test]
    fn the_balance_masses_close_the_force_and_couple_polygons() {
        let mut next = crate::dynamics::uniform_draws(0x9e37_79b9_7f4a_7c15u64);
        for _ in 0..200 {
            let count = 1 + (next() * 6.0) as usize;
            let masses: Vec<Revolving> = (0..count)
                .map(|_| Revolving {
                    moment: 5.0 * next(),
                    angle_deg: 360.0 * next(),
                    plane: 4.0 * next() - 2.0,
                })
                .collect();
            let planes = (3.0 * next() - 3.0, 3.0 * next() + 0.1);
            let balance = two_plane_balance(&masses, planes).unwrap();
            let about = 10.0 * next() - 5.0;
            let (mut force, mut couple) = ([0.0; 2], [0.0; 2]);
            for m in masses.iter().chain(&balance) {
                let v = vector(m);
                for i in 0..2 {
                    force[i] += v[i];
                    couple[i] += v[i] * (m.plane - about);
                }
            }
            let scale: f64 = masses
                .iter()
                .map(|m| m.moment * (1.0 + m.plane.abs()))
                .sum::<f64>()
                * 10.0;
            for v in [force, couple] {
                assert!(
                    v[0].abs() < 1e-12 * scale && v[1].abs() < 1e-12 * scale,
                    "{v:?}"
                );
            }
        }
    }

    #[test]
    fn one_plane_or_no_mass_is_refused() {
        let m = [Revolving {
            moment: 1.0,
            angle_deg: 0.0,
            plane: 0.5,
        }];
        assert!(two_plane_balance(&m, (1.0, 1.0)).is_err());
        assert!(two_plane_balance(&[], (0.0, 1.0)).is_err());
        assert!(two_plane_balance(&m, (f64::NAN, 1.0)).is_err());
        let bad = [Revolving {
            moment: f64::INFINITY,
            angle_deg: 0.0,
            plane: 0.5,
        }];
        assert!(two_plane_balance(&bad, (0.0, 1.0)).is_err());
    }
}
