//! Static forces after Ng: the OM torque line, slider force, side thrust,
//! friction, transmission angle.
//!
//! Ng's M is the textbook's E: the rod AB produced meets the perpendicular
//! to the stroke through the crank centre there, and OM = CE = −ds/dθ
//! (signed). Virtual work, T ω + F v_p = 0, gives the slider force F = T/OM
//! along +x that holds the crank torque T (counter-clockwise positive).

use crate::angle::Angle;
use crate::error::{Error, Field, Result, finite, non_negative};
use crate::mechanism::Pose;
use crate::number::plain;

/// The signed length OM (= CE = E_y = −ds/dθ): the moment arm that turns a
/// crank torque into a slider force (Ng eq. 2, 5). Zero at the dead centres.
pub fn om(pose: &Pose) -> f64 {
    -pose.position_rate()
}

/// Slider force from crank torque, F_p = T / OM (Ng eq. 6), positive along
/// +x. `Ok(None)` only at a dead centre, where OM = 0 and no finite slider
/// force balances a torque.
///
/// Errors: a torque that is not finite, or a force beyond the largest f64
/// (a huge torque on a tiny mechanism: OM is small but not zero). The
/// torque line of the construction ([`crate::construct::TorqueLine`])
/// divides through the same function, so the two agree on which is which.
pub fn slider_force(pose: &Pose, torque: f64) -> Result<Option<f64>> {
    let tan_phi = pose.tan_obliquity();
    let arm = Arm {
        om: om(pose),
        crank: pose.mechanism().crank(),
        per_crank: om_per_crank(pose.angle(), tan_phi),
    };
    force_over_arm(torque, arm, pose.angle())
}

/// The moment arm OM of a pose, in world units and per unit crank.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Arm {
    /// Signed OM (= CE), world units: zero at a dead centre, and also when
    /// r · OM/r is below the smallest f64 (a tiny crank a hair from a dead
    /// centre).
    pub om: f64,
    /// The crank radius r.
    pub crank: f64,
    /// OM / r = sin θ + cos θ tan φ, which is zero only at a dead centre.
    pub per_crank: f64,
}

/// OM / r = sin θ + cos θ tan φ (E_y = r sin θ + r cos θ tan φ): the arm
/// per unit crank, which does not underflow where OM does.
pub(crate) fn om_per_crank(angle: Angle, tan_phi: f64) -> f64 {
    angle.sin() + angle.cos() * tan_phi
}

/// F_p = T / OM for the moment arm `arm` at the crank angle `angle`:
/// `Ok(None)` at a dead centre (OM / r = 0), an error when T is not finite
/// or the quotient is beyond the largest f64. The one division behind
/// [`slider_force`] and [`crate::construct::TorqueLine::slider_force`].
pub(crate) fn force_over_arm(torque: f64, arm: Arm, angle: Angle) -> Result<Option<f64>> {
    let torque = finite(Field::Torque, torque)?;
    let f = if arm.om != 0.0 {
        torque / arm.om
    } else if arm.per_crank == 0.0 {
        return Ok(None);
    } else {
        // OM = r · (OM/r) is below the smallest f64, so r < 1 and
        // |OM/r| < 1: neither quotient shrinks, and the first overflows
        // only when the force does.
        torque / arm.crank / arm.per_crank
    };
    if f.is_finite() {
        return Ok(Some(f));
    }
    let om = if arm.om != 0.0 {
        format!("OM = {:e}", arm.om)
    } else {
        format!("OM = {:e} r, below the smallest number", arm.per_crank)
    };
    Err(Error::OutOfRange {
        name: Field::Torque,
        value: torque,
        reason: format!(
            "the slider force T/OM at θ = {}° ({om}) exceeds the largest number (about 1.8e308): {UNIT_ADVICE}",
            plain(angle.degrees())
        ),
    })
}

/// What to do when a force exceeds the largest f64: forces scale with the
/// unit of force the torque is given in (lengths cancel: T/OM is force).
const UNIT_ADVICE: &str = "give the torque in a larger unit of force (kN·m rather than N·m)";

/// Crank torque balanced by a slider force F along +x, T = F · OM (Ng eq. 2);
/// zero at the dead centres, where the slider force passes through C.
pub fn torque_from_slider_force(pose: &Pose, force: f64) -> f64 {
    force * om(pose)
}

/// Side thrust of the guides on the slider, F_s = F_p tan φ (Ng eq. 7),
/// signed along +y.
///
/// Errors: a slider force that is not finite, or a thrust beyond the
/// largest f64 (a huge force near the limit of assembly, where tan φ
/// grows without bound as the rod lines up with the crank).
pub fn side_thrust(pose: &Pose, slider_force: f64) -> Result<f64> {
    thrust(slider_force, pose.tan_obliquity(), pose.angle())
}

/// F_s = F_p tan φ at the crank angle `angle`, an error when F_p is not
/// finite or the product is beyond the largest f64. The one product
/// behind [`side_thrust`] and [`crate::construct::TorqueLine::side_thrust`].
pub(crate) fn thrust(slider_force: f64, tan_phi: f64, angle: Angle) -> Result<f64> {
    let slider_force = finite(Field::SliderForce, slider_force)?;
    let fs = slider_force * tan_phi;
    if fs.is_finite() {
        Ok(fs)
    } else {
        Err(Error::OutOfRange {
            name: Field::SliderForce,
            value: slider_force,
            reason: format!(
                "the side thrust F_p tan φ at θ = {}° (tan φ = {tan_phi:e}) exceeds the largest number (about 1.8e308): {UNIT_ADVICE}",
                plain(angle.degrees())
            ),
        })
    }
}

/// The slider force needed with friction in the guides.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Friction {
    /// F_p' = F_p (1 − μ |tan φ|) (Ng eq. 8, where tan φ > 0): friction helps
    /// hold the slider, so less force is needed.
    Force(f64),
    /// μ |tan φ| ≥ 1: friction alone holds the slider and eq. (8) would
    /// give zero or a negative force. Carries μ |tan φ|.
    SelfLocking(f64),
}

/// Slider force with friction coefficient μ ≥ 0 (Ng eq. 8). The normal force
/// on the guides is the side thrust, which the torque alone fixes, so
/// eq. (8) is exact; |tan φ| is used so that the result also holds below
/// the line of stroke (θ in 180°…360°), where friction again opposes the
/// impending motion.
pub fn with_friction(pose: &Pose, slider_force: f64, mu: f64) -> Result<Friction> {
    let mu = non_negative(Field::Friction, mu)?;
    let slider_force = finite(Field::SliderForce, slider_force)?;
    let k = mu * pose.tan_obliquity().abs();
    Ok(if k >= 1.0 {
        Friction::SelfLocking(k)
    } else {
        Friction::Force(slider_force * (1.0 - k))
    })
}

/// Coefficient of friction from the tilt at which a block first slides,
/// μ = tan(tilt) (Ng eq. 10). The tilt must be in [0°, 90°).
pub fn mu_from_tilt_degrees(tilt: f64) -> Result<f64> {
    let tilt = non_negative(Field::Tilt, tilt)?;
    if tilt >= 90.0 {
        return Err(Error::OutOfRange {
            name: Field::Tilt,
            value: tilt,
            reason: "a block slides before the plane is vertical; give a tilt below 90°".into(),
        });
    }
    if tilt == 45.0 {
        return Ok(1.0);
    }
    Ok(tilt.to_radians().tan())
}

/// Ng's transmission angle β = 180° − φ − θ (eq. 11), in degrees, valid for
/// an in-line mechanism with 0 < θ < 180°. Use
/// [`Pose::transmission_angle`] for the general interior angle at the pin.
pub fn transmission_angle_ng_degrees(pose: &Pose) -> f64 {
    180.0 - pose.obliquity().to_degrees() - pose.angle().degrees()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{angle::Angle, mechanism::SliderCrank};

    fn pose(d: f64) -> Pose {
        SliderCrank::in_line(0.025, 0.072)
            .unwrap()
            .pose(Angle::deg(d))
    }

    #[test]
    fn dead_centre_has_no_finite_force() {
        assert_eq!(slider_force(&pose(0.0), 1.0), Ok(None));
        assert_eq!(slider_force(&pose(180.0), 1.0), Ok(None));
        assert_eq!(torque_from_slider_force(&pose(0.0), 5.0), 0.0);
    }

    #[test]
    fn force_and_torque_are_inverse() {
        let p = pose(37.0);
        let f = slider_force(&p, 0.3).unwrap().unwrap();
        assert!((torque_from_slider_force(&p, f) - 0.3).abs() < 1e-16);
    }

    #[test]
    fn ng_eq_6_form_agrees_in_line() {
        // F = T / (tan φ (r cos θ + l cos φ)).
        for d in [10.0, 60.0, 90.0, 160.0] {
            let p = pose(d);
            let phi = p.obliquity();
            let eq6 = 0.2 / (phi.tan() * (0.025 * p.angle().cos() + 0.072 * phi.cos()));
            let f = slider_force(&p, 0.2).unwrap().unwrap();
            assert!((f - eq6).abs() < 1e-12 * f, "{d}");
        }
    }

    #[test]
    fn overflow_is_an_error_not_a_dead_centre() {
        // Issue 9 (6): T = 1e308 on r = 1e-100, l = 3e-100 at 45°:
        // OM ≈ 8.8e-101, not zero.
        let m = SliderCrank::in_line(1e-100, 3e-100).unwrap();
        let p = m.pose(Angle::deg(45.0));
        assert!(om(&p) > 8e-101);
        let err = slider_force(&p, 1e308).unwrap_err();
        assert!(
            err.to_string().contains("exceeds the largest number"),
            "{err}"
        );
        assert!(slider_force(&p, f64::NAN).is_err());
    }

    #[test]
    fn an_arm_below_the_smallest_number_is_not_a_dead_centre() {
        // θ = 1e-230° on r = 1e-100: OM = r (sin θ + cos θ tan φ) ≈ 2.3e-332
        // is below the smallest f64 and computes as 0, but OM / r does not.
        let m = SliderCrank::in_line(1e-100, 3e-100).unwrap();
        let p = m.pose(Angle::deg(1e-230));
        assert_eq!(om(&p), 0.0);
        let err = slider_force(&p, 1.0).unwrap_err().to_string();
        assert!(err.contains("θ = 1e-230°"), "{err}");
        assert!(err.contains("below the smallest number"), "{err}");
        // A torque small enough gives the finite force T / (r · OM/r).
        let f = slider_force(&p, 1e-30).unwrap().unwrap();
        let expected = 1e-30 / 1e-100 / (1e-230f64.to_radians() * (1.0 + 1.0 / 3.0));
        assert!((f / expected - 1.0).abs() < 1e-12, "{f} {expected}");
        // At the dead centre itself OM / r is zero too.
        let p = m.pose(Angle::deg(180.0));
        assert_eq!(slider_force(&p, 1e-30), Ok(None));
    }

    #[test]
    fn self_locking_is_reported() {
        let p = pose(90.0);
        assert!(
            matches!(with_friction(&p, 10.0, 5.0).unwrap(), Friction::SelfLocking(k) if k > 1.0)
        );
        match with_friction(&p, 10.0, 1.0).unwrap() {
            Friction::Force(f) => assert!(f > 0.0 && f < 10.0),
            other => panic!("{other:?}"),
        }
        assert!(with_friction(&p, 10.0, -0.1).is_err());
    }

    #[test]
    fn tilt_to_mu() {
        assert_eq!(mu_from_tilt_degrees(45.0).unwrap(), 1.0);
        assert_eq!(mu_from_tilt_degrees(0.0).unwrap(), 0.0);
        assert!(mu_from_tilt_degrees(90.0).is_err());
        assert!(mu_from_tilt_degrees(-1.0).is_err());
    }
}
