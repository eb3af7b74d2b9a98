//! Cross-checks: each value read off a construction beside the analytic
//! core's, in the scaled units of DESIGN.md §6.

use super::{InstantCentre, Kisch, Klein, VelocityLine};
use crate::angle::Angle;
use crate::mechanism::{Pose, SliderCrank};

/// A quantity that a construction gives and the analytic core computes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Quantity {
    /// Slider velocity from CE (E, Fig. 63), scaled by rω.
    Velocity,
    /// Rod angular velocity from CB/BD (D, §37), scaled by ω.
    RodAngularVelocity,
    /// Slider acceleration from CG by Kisch (Fig. 66), scaled by rω².
    AccelerationKisch,
    /// Slider acceleration from CG by Klein (Fig. 65), scaled by rω².
    AccelerationKlein,
    /// Rod angular acceleration from FG by Kisch, scaled by ω².
    RodAngularAccelerationKisch,
    /// Rod angular acceleration from FG by Klein, scaled by ω².
    RodAngularAccelerationKlein,
}

impl Quantity {
    /// Every quantity, in report order.
    pub const ALL: [Quantity; 6] = [
        Quantity::Velocity,
        Quantity::RodAngularVelocity,
        Quantity::AccelerationKisch,
        Quantity::AccelerationKlein,
        Quantity::RodAngularAccelerationKisch,
        Quantity::RodAngularAccelerationKlein,
    ];

    /// A short name for reports.
    pub fn name(&self) -> &'static str {
        match self {
            Quantity::Velocity => "velocity (CE)",
            Quantity::RodAngularVelocity => "rod angular velocity (BD)",
            Quantity::AccelerationKisch => "acceleration (CG, Kisch)",
            Quantity::AccelerationKlein => "acceleration (CG, Klein)",
            Quantity::RodAngularAccelerationKisch => "rod angular acceleration (FG, Kisch)",
            Quantity::RodAngularAccelerationKlein => "rod angular acceleration (FG, Klein)",
        }
    }
}

/// One quantity at one pose, as θ-rates (ds/dθ, d²s/dθ², dφ/dθ, d²φ/dθ²).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CheckRow {
    /// What is compared.
    pub quantity: Quantity,
    /// Read off the construction.
    pub graphical: f64,
    /// From the analytic core.
    pub analytic: f64,
    /// The scale of DESIGN.md §6: r for the slider, 1 for the rod.
    pub scale: f64,
}

impl CheckRow {
    /// |graphical − analytic| / scale.
    pub fn scaled_error(&self) -> f64 {
        (self.graphical - self.analytic).abs() / self.scale
    }
}

/// Every construction of `pose` against the analytic core. Klein's rows are
/// missing where D is at infinity.
pub fn cross_check(pose: &Pose) -> Vec<CheckRow> {
    let r = pose.mechanism().crank();
    let d = InstantCentre::construct(pose);
    let e = VelocityLine::construct(pose);
    let kisch = Kisch::construct(pose, &e);
    let row = |quantity, graphical, analytic, scale| CheckRow {
        quantity,
        graphical,
        analytic,
        scale,
    };
    let mut rows = vec![
        row(
            Quantity::Velocity,
            e.velocity_ratio(),
            pose.position_rate(),
            r,
        ),
        row(
            Quantity::RodAngularVelocity,
            d.rod_angular_velocity_ratio(),
            pose.obliquity_rate(),
            1.0,
        ),
        row(
            Quantity::AccelerationKisch,
            kisch.points().acceleration_ratio(),
            pose.position_acceleration(),
            r,
        ),
        row(
            Quantity::RodAngularAccelerationKisch,
            kisch.points().rod_angular_acceleration_ratio(),
            pose.obliquity_acceleration(),
            1.0,
        ),
    ];
    if let Some(klein) = Klein::construct(pose, &d, &e) {
        rows.push(row(
            Quantity::AccelerationKlein,
            klein.points().acceleration_ratio(),
            pose.position_acceleration(),
            r,
        ));
        rows.push(row(
            Quantity::RodAngularAccelerationKlein,
            klein.points().rod_angular_acceleration_ratio(),
            pose.obliquity_acceleration(),
            1.0,
        ));
    }
    rows
}

/// The worst scaled error of each quantity over a sweep.
#[derive(Debug, Clone, PartialEq)]
pub struct SweepReport {
    /// Poses checked.
    pub poses: usize,
    /// Per quantity: the largest scaled error, the crank angle (degrees)
    /// where it occurred, and the number of poses where it was available.
    pub worst: Vec<(Quantity, f64, f64, usize)>,
}

impl SweepReport {
    /// The largest error over all quantities.
    pub fn max_error(&self) -> f64 {
        self.worst.iter().map(|w| w.1).fold(0.0, f64::max)
    }
}

/// Checks `samples` equally spaced crank angles over the whole turn plus the
/// exact dead centres, 90° and 270°.
pub fn sweep(mechanism: &SliderCrank, samples: usize) -> SweepReport {
    // Generated as they are checked: memory does not grow with `samples`.
    let even = (0..samples).map(|k| Angle::from_degrees(360.0 * k as f64 / samples as f64));
    let quarters = [0.0, 90.0, 180.0, 270.0].map(Angle::from_degrees);
    let dead =
        [mechanism.outer_dead_centre(), mechanism.inner_dead_centre()].map(Angle::from_radians);
    let angles = even.chain(quarters).chain(dead).filter_map(|a| a.ok());
    let mut poses = 0;
    let mut worst: Vec<(Quantity, f64, f64, usize)> =
        Quantity::ALL.iter().map(|q| (*q, 0.0, 0.0, 0)).collect();
    for angle in angles {
        poses += 1;
        let pose = mechanism.pose(angle);
        for row in cross_check(&pose) {
            let slot = worst
                .iter_mut()
                .find(|w| w.0 == row.quantity)
                .expect("all listed");
            let err = row.scaled_error();
            slot.3 += 1;
            // NaN must not hide: count it as infinite.
            let err = if err.is_nan() { f64::INFINITY } else { err };
            if err > slot.1 || slot.3 == 1 {
                slot.1 = err;
                slot.2 = angle.degrees();
            }
        }
    }
    SweepReport { poses, worst }
}
