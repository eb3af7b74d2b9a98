//! Cross-checks: each value read off a construction beside the analytic
//! core's, in the scaled units of docs/design.md §6.

use super::{
    AccelerationPolygon, Bennett, CouplerPoint, InstantCentre, Kisch, Klein, Ritterhaus,
    VelocityLine, VelocityPolygon,
};
use crate::angle::Angle;
use crate::mechanism::{Pose, SliderCrank};

/// A quantity that a construction gives and the analytic core computes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
#[non_exhaustive]
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
    /// Slider velocity from oa of the velocity polygon, scaled by rω.
    VelocityPolygon,
    /// Rod angular velocity from ab / AB of the velocity polygon, scaled
    /// by ω.
    RodAngularVelocityPolygon,
    /// The speed of the rod's mid-point from oq, its velocity image,
    /// scaled by rω.
    CouplerVelocityPolygon,
    /// Slider acceleration from o′a′ of the acceleration polygon, scaled
    /// by rω².
    AccelerationPolygon,
    /// Rod angular acceleration from the tangential component xa′ / AB of
    /// the acceleration polygon, scaled by ω².
    RodAngularAccelerationPolygon,
    /// The acceleration's magnitude of the rod's mid-point from o′q′, its
    /// acceleration image, scaled by rω².
    CouplerAccelerationPolygon,
    /// Slider acceleration from CG by Ritterhaus's construction, scaled
    /// by rω².
    AccelerationRitterhaus,
    /// Slider acceleration from CG by Bennett's construction (in-line
    /// engines only), scaled by rω².
    AccelerationBennett,
    /// The speed of a point of the rod's plane off its line from oq, its
    /// velocity image (the triangle abq similar to ABQ), scaled by rω.
    OffRodVelocityPolygon,
    /// The acceleration's magnitude of a point of the rod's plane off
    /// its line from o′q′, its acceleration image, scaled by rω².
    OffRodAccelerationPolygon,
}

/// The point of the rod whose images the cross-check reads: its middle.
const CHECKED_COUPLER: f64 = 0.5;

/// The point of the rod's plane off its line whose images the
/// cross-check reads: over the rod's middle, a quarter of the rod's
/// length to the left of A → B (t, across of [`CouplerPoint::off_rod`]).
const CHECKED_OFF_ROD: (f64, f64) = (0.5, 0.25);

impl Quantity {
    /// Every quantity, in report order.
    pub const ALL: [Quantity; 16] = [
        Quantity::Velocity,
        Quantity::RodAngularVelocity,
        Quantity::AccelerationKisch,
        Quantity::AccelerationKlein,
        Quantity::RodAngularAccelerationKisch,
        Quantity::RodAngularAccelerationKlein,
        Quantity::VelocityPolygon,
        Quantity::RodAngularVelocityPolygon,
        Quantity::CouplerVelocityPolygon,
        Quantity::AccelerationPolygon,
        Quantity::RodAngularAccelerationPolygon,
        Quantity::CouplerAccelerationPolygon,
        Quantity::AccelerationRitterhaus,
        Quantity::AccelerationBennett,
        Quantity::OffRodVelocityPolygon,
        Quantity::OffRodAccelerationPolygon,
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
            Quantity::VelocityPolygon => "velocity (oa, polygon)",
            Quantity::RodAngularVelocityPolygon => "rod angular velocity (ab, polygon)",
            Quantity::CouplerVelocityPolygon => "mid-rod speed (oq, polygon)",
            Quantity::AccelerationPolygon => "acceleration (o′a′, polygon)",
            Quantity::RodAngularAccelerationPolygon => "rod angular acceleration (xa′, polygon)",
            Quantity::CouplerAccelerationPolygon => "mid-rod acceleration (o′q′, polygon)",
            Quantity::AccelerationRitterhaus => "acceleration (CG, Ritterhaus)",
            Quantity::AccelerationBennett => "acceleration (CG, Bennett)",
            Quantity::OffRodVelocityPolygon => "off-rod point's speed (oq, polygon)",
            Quantity::OffRodAccelerationPolygon => "off-rod point's acceleration (o′q′, polygon)",
        }
    }
}

/// One quantity at one pose, as θ-rates (ds/dθ, d²s/dθ², dφ/dθ, d²φ/dθ²).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct CheckRow {
    /// What is compared.
    pub quantity: Quantity,
    /// Read off the construction.
    pub graphical: f64,
    /// From the analytic core.
    pub analytic: f64,
    /// The scale of docs/design.md §6: r for the slider, 1 for the rod.
    pub scale: f64,
    /// The condition number κ of the quantity at this pose (≥ 1, see
    /// [`condition`]): moving any input (r, l, e, θ) by one part in
    /// 2⁻⁵² moves the exact scaled value by about κ · 2⁻⁵².
    pub condition: f64,
}

impl CheckRow {
    /// |graphical − analytic| / scale.
    pub fn scaled_error(&self) -> f64 {
        (self.graphical - self.analytic).abs() / self.scale
    }

    /// The scaled error in units of the rounding the problem itself allows,
    /// |graphical − analytic| / (scale · ε · κ), ε = 2⁻⁵²: a few for every
    /// pose, however near the limit of assembly.
    pub fn ulps(&self) -> f64 {
        self.scaled_error() / (f64::EPSILON * self.condition)
    }
}

/// The condition number κ of `quantity` at `pose`, in the scaled units of
/// docs/design.md §6: κ = 1 + T (1 + k (l/w)²), where T is the sum of the
/// magnitudes of the terms of its formula (scaled), w = l cos φ, and k = 2
/// for the rates (one w in a denominator), 6 for the accelerations (w³).
/// A point of the rod's plane `across` rod lengths off its line adds
/// `across` times the images' difference b − a to its image, so its terms
/// are the rod point's times 1 + |across|.
///
/// Every quantity is a sum of terms that divide by powers of
/// w = √(l² − h²), h = r sin θ − e. A relative change δ of the inputs
/// changes w by about δ (l² + h²)/w ≤ 2δ l²/w, so each power of 1/w
/// multiplies a term's relative sensitivity by 2 (l/w)²; terms that nearly
/// cancel (the acceleration near 90° when l → r) keep their own
/// sensitivity, which is why T sums magnitudes. Near the limit of assembly
/// (l → r + |e|, w → 0 where the rod lines up with the crank) κ grows
/// without bound: there the answer itself is ill-conditioned, and so is any
/// construction of it.
pub fn condition(pose: &Pose, quantity: Quantity) -> f64 {
    let m = pose.mechanism();
    let (l, h, w) = (m.rod(), pose.rise(), pose.run());
    let (s, c) = (pose.angle().sin().abs(), pose.angle().cos().abs());
    let r = m.crank();
    let (rc_w, h) = (r * c / w, h.abs());
    let off = 1.0 + CHECKED_OFF_ROD.1.abs();
    // Terms over r (slider) or 1 (rod), as in Pose's formulas.
    let (terms, k) = match quantity {
        Quantity::Velocity | Quantity::VelocityPolygon => (s + c * h / w, 2.0),
        // The crank pin's velocity, r, is a term of the coupler's.
        Quantity::CouplerVelocityPolygon => (1.0 + s + c * h / w, 2.0),
        Quantity::RodAngularVelocity | Quantity::RodAngularVelocityPolygon => (rc_w, 2.0),
        Quantity::AccelerationKisch
        | Quantity::AccelerationKlein
        | Quantity::AccelerationPolygon
        | Quantity::AccelerationRitterhaus
        | Quantity::AccelerationBennett => (c + c * rc_w * (l / w) * (l / w) + s * h / w, 6.0),
        Quantity::CouplerAccelerationPolygon => {
            (1.0 + c + c * rc_w * (l / w) * (l / w) + s * h / w, 6.0)
        }
        Quantity::OffRodVelocityPolygon => (off * (1.0 + s + c * h / w), 2.0),
        Quantity::OffRodAccelerationPolygon => (
            off * (1.0 + c + c * rc_w * (l / w) * (l / w) + s * h / w),
            6.0,
        ),
        Quantity::RodAngularAccelerationKisch
        | Quantity::RodAngularAccelerationKlein
        | Quantity::RodAngularAccelerationPolygon => (r * s / w + rc_w * rc_w * h / w, 6.0),
    };
    let lw = l / w;
    1.0 + terms * (1.0 + k * lw * lw)
}

/// Every construction of `pose` against the analytic core. Klein's rows are
/// missing where D is at infinity, Bennett's for an offset engine. The
/// polygons' coupler rows read the images of the rod's mid-point, their
/// off-rod rows those of the point halfway along AB and a quarter of AB
/// to its left (`CouplerPoint::off_rod(0.5, 0.25)`).
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
        condition: condition(pose, quantity),
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
    rows.extend(polygon_rows(pose, &row));
    let ritterhaus = Ritterhaus::construct(pose, &e);
    rows.push(row(
        Quantity::AccelerationRitterhaus,
        ritterhaus.points().acceleration_ratio(),
        pose.position_acceleration(),
        r,
    ));
    if let Some(bennett) = Bennett::construct(pose) {
        rows.push(row(
            Quantity::AccelerationBennett,
            bennett.points().acceleration_ratio(),
            pose.position_acceleration(),
            r,
        ));
    }
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

/// The rows of the velocity and acceleration polygons of `pose`, made by
/// `row` (quantity, graphical, analytic, scale).
fn polygon_rows(pose: &Pose, row: &impl Fn(Quantity, f64, f64, f64) -> CheckRow) -> [CheckRow; 8] {
    let r = pose.mechanism().crank();
    // cannot fail: CHECKED_COUPLER and CHECKED_OFF_ROD are within range.
    let coupler = CouplerPoint::new(CHECKED_COUPLER).ok();
    let off_rod = CouplerPoint::off_rod(CHECKED_OFF_ROD.0, CHECKED_OFF_ROD.1).ok();
    let v = VelocityPolygon::construct(pose, coupler);
    let acc = AccelerationPolygon::construct(pose, &v, coupler);
    let v_off = VelocityPolygon::construct(pose, off_rod);
    let acc_off = AccelerationPolygon::construct(pose, &v_off, off_rod);
    let norm = |x: Option<crate::geom::Vector>| x.map_or(f64::NAN, |x| x.norm());
    let exact = |point: Option<CouplerPoint>,
                 f: fn(&CouplerPoint, &Pose) -> crate::geom::Vector| {
        point.map_or(f64::NAN, |p| f(&p, pose).norm())
    };
    [
        row(
            Quantity::VelocityPolygon,
            v.slider_velocity_ratio(),
            pose.position_rate(),
            r,
        ),
        row(
            Quantity::RodAngularVelocityPolygon,
            v.rod_angular_velocity_ratio(),
            pose.obliquity_rate(),
            1.0,
        ),
        row(
            Quantity::CouplerVelocityPolygon,
            norm(v.q()),
            exact(coupler, CouplerPoint::derivative),
            r,
        ),
        row(
            Quantity::AccelerationPolygon,
            acc.slider_acceleration_ratio(),
            pose.position_acceleration(),
            r,
        ),
        row(
            Quantity::RodAngularAccelerationPolygon,
            acc.rod_angular_acceleration_ratio(),
            pose.obliquity_acceleration(),
            1.0,
        ),
        row(
            Quantity::CouplerAccelerationPolygon,
            norm(acc.q()),
            exact(coupler, CouplerPoint::second_derivative),
            r,
        ),
        row(
            Quantity::OffRodVelocityPolygon,
            norm(v_off.q()),
            exact(off_rod, CouplerPoint::derivative),
            r,
        ),
        row(
            Quantity::OffRodAccelerationPolygon,
            norm(acc_off.q()),
            exact(off_rod, CouplerPoint::second_derivative),
            r,
        ),
    ]
}

/// The worst scaled error of each quantity over a sweep.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct SweepReport {
    /// Poses checked.
    pub poses: usize,
    /// Per quantity: the largest scaled error, the crank angle (degrees)
    /// where it occurred, and the number of poses where it was available.
    pub worst: Vec<(Quantity, f64, f64, usize)>,
    /// Per quantity: the largest [`CheckRow::ulps`], the condition number
    /// κ there and the crank angle (degrees).
    pub worst_ulps: Vec<(Quantity, f64, f64, f64)>,
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
    let dead = [mechanism.outer_dead_centre(), mechanism.inner_dead_centre()].map(Ok);
    let angles = even.chain(quarters).chain(dead).filter_map(|a| a.ok());
    let mut poses = 0;
    let mut worst_ulps: Vec<(Quantity, f64, f64, f64)> =
        Quantity::ALL.iter().map(|q| (*q, 0.0, 1.0, 0.0)).collect();
    let mut worst: Vec<(Quantity, f64, f64, usize)> =
        Quantity::ALL.iter().map(|q| (*q, 0.0, 0.0, 0)).collect();
    for angle in angles {
        poses += 1;
        let pose = mechanism.pose(angle);
        for row in cross_check(&pose) {
            // Every quantity is listed (from Quantity::ALL).
            let Some(slot) = worst.iter_mut().find(|w| w.0 == row.quantity) else {
                continue;
            };
            let err = row.scaled_error();
            slot.3 += 1;
            // NaN must not hide: count it as infinite.
            let err = if err.is_nan() { f64::INFINITY } else { err };
            if err > slot.1 || slot.3 == 1 {
                slot.1 = err;
                slot.2 = angle.degrees();
            }
            let Some(u) = worst_ulps.iter_mut().find(|w| w.0 == row.quantity) else {
                continue;
            };
            let ulps = row.ulps();
            let ulps = if ulps.is_nan() { f64::INFINITY } else { ulps };
            if ulps > u.1 {
                *u = (row.quantity, ulps, row.condition, angle.degrees());
            }
        }
    }
    SweepReport {
        poses,
        worst,
        worst_ulps,
    }
}
