//! The checks of a scene's settings, made once when the figure is built
//! ([`Scene::build`]) and by the scene file's reader at each value, so
//! that its message points at the key.

use super::Scene;
use crate::angle::Angle;
use crate::error::{Error, Field, Input, Result, finite, positive};

/// The most poses one figure draws (the first and its ghosts).
pub(crate) const MAX_POSES: usize = 64;

/// The most poses a view is held over ([`Scene::with_held_view`]): every
/// tenth of a degree and every degree, the most an animation holds (its
/// 3600 frames with the revolution).
pub(crate) const MAX_HELD: usize = 3960;

/// Every setting of `scene` that can be out of range.
pub(crate) fn scene(scene: &Scene) -> Result<()> {
    omega(scene.omega)?;
    torque(scene.torque)?;
    tolerance(scene.tolerance)?;
    angles(&scene.angles)?;
    if let Some(held) = &scene.held_view {
        held_view(held)?;
    }
    Ok(())
}

/// A crank speed for the scale notes: non-zero, within
/// [`crate::analytic::kinematics::MAX_OMEGA`].
pub(crate) fn omega(omega: f64) -> Result<f64> {
    let omega = crate::analytic::kinematics::check_omega(omega)?;
    if omega == 0.0 {
        return Err(Error::NotPositive {
            name: Field::Omega,
            value: omega,
        });
    }
    Ok(omega)
}

/// A crank torque: finite.
pub(crate) fn torque(torque: f64) -> Result<f64> {
    finite(Field::Torque, torque)
}

/// A curve tolerance in page units, in [1e-6, 10].
pub(crate) fn tolerance(tolerance: f64) -> Result<f64> {
    let t = positive(Field::Tolerance, tolerance)?;
    if !(1e-6..=10.0).contains(&t) {
        return Err(Error::OutOfRange {
            name: Field::Tolerance,
            value: t,
            reason: "give a page tolerance between 1e-6 and 10".into(),
        });
    }
    Ok(t)
}

/// The poses of one figure: 1 to [`MAX_POSES`].
pub(crate) fn angles(angles: &[Angle]) -> Result<()> {
    if angles.is_empty() {
        return Err(Error::invalid(
            Input::Angles,
            "a scene needs at least one angle".into(),
        ));
    }
    if angles.len() > MAX_POSES {
        return Err(Error::OutOfRange {
            name: Field::Angles,
            value: angles.len() as f64,
            reason: format!("at most {MAX_POSES} poses in one figure"),
        });
    }
    Ok(())
}

/// The poses a view is held over: 1 to [`MAX_HELD`].
pub(crate) fn held_view(angles: &[Angle]) -> Result<()> {
    if angles.is_empty() {
        return Err(Error::invalid(
            Input::Angles,
            "a view is held over at least one angle".into(),
        ));
    }
    if angles.len() > MAX_HELD {
        return Err(Error::OutOfRange {
            name: Field::HeldAngles,
            value: angles.len() as f64,
            reason: format!("a view is held over at most {MAX_HELD} poses"),
        });
    }
    Ok(())
}
