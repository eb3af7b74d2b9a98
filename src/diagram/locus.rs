//! The mechanism's curves as [`Curve`]s of the crank angle in degrees.

use super::Curve;
use crate::construct::{Centrode, CentrodeKind, CouplerPoint};
use crate::geom::{Point, Vector};
use crate::{angle::Angle, mechanism::SliderCrank};

/// Radians per degree: derivatives with respect to θ in radians times this
/// are per degree.
const PER_DEGREE: f64 = std::f64::consts::PI / 180.0;

/// Which curve of the mechanism.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum LocusKind {
    /// The polar velocity curve: the point E′ at the signed distance
    /// CE = −ds/dθ from C along the crank, CE · (cos θ, sin θ) (textbook
    /// §36: the slider's velocity laid off on the crank, to the scale of
    /// V_c as CB). Where CE < 0 (the return stroke of an in-line engine) the
    /// point lies on the crank produced backwards; the curve passes through
    /// C at the dead centres, smoothly.
    PolarVelocity,
    /// A centrode of the rod (the locus of D); undefined at θ = 90° and
    /// 270°, where it runs off to infinity.
    Centrode(CentrodeKind),
    /// The path of a point of the rod (an oval).
    Coupler(CouplerPoint),
}

/// A curve of a mechanism, parameterised by the crank angle θ in degrees,
/// with exact derivatives per degree from the analytic core.
///
/// Degenerate cases: the centrodes give `None` exactly at their poles
/// (90°, 270°, and every angle equal to them modulo 360°); every other
/// finite angle gives a point. A non-finite angle gives `None`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Locus {
    mechanism: SliderCrank,
    kind: LocusKind,
}

impl Locus {
    /// The curve `kind` of `mechanism`.
    pub fn new(mechanism: SliderCrank, kind: LocusKind) -> Self {
        Self { mechanism, kind }
    }

    /// The mechanism.
    pub fn mechanism(&self) -> &SliderCrank {
        &self.mechanism
    }

    /// Which curve.
    pub fn kind(&self) -> LocusKind {
        self.kind
    }
}

impl Curve for Locus {
    /// The point and its derivative per degree at θ = `degrees`.
    fn eval(&self, degrees: f64) -> Option<(Point, Vector)> {
        let pose = self.mechanism.pose(Angle::from_degrees(degrees).ok()?);
        let (point, per_radian) = match self.kind {
            LocusKind::PolarVelocity => {
                let (s, c) = (pose.angle().sin(), pose.angle().cos());
                let ce = -pose.position_rate();
                let ce_rate = -pose.position_acceleration();
                (
                    Point::new(ce * c, ce * s),
                    Vector::new(ce_rate * c - ce * s, ce_rate * s + ce * c),
                )
            }
            LocusKind::Centrode(kind) => {
                let centrode = Centrode::new(kind);
                (centrode.point(&pose).point()?, centrode.derivative(&pose)?)
            }
            LocusKind::Coupler(point) => (point.point(&pose), point.derivative(&pose)),
        };
        Some((point, per_radian * PER_DEGREE))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::construct::VelocityLine;

    #[test]
    fn polar_velocity_point_is_ce_along_the_crank() {
        let m = SliderCrank::in_line(0.5, 3.0).unwrap();
        let curve = Locus::new(m, LocusKind::PolarVelocity);
        for d in [0.0, 30.0, 45.0, 90.0, 200.0] {
            let angle = Angle::deg(d);
            let ce = VelocityLine::construct(&m.pose(angle)).ce();
            let (p, _) = curve.eval(d).unwrap();
            let expected = Point::new(ce * angle.cos(), ce * angle.sin());
            assert!((p - expected).norm() < 1e-15, "{d}");
        }
        // Dead centre: at C. θ = 90°: CE = CB = r, so E' = B.
        assert_eq!(curve.eval(0.0).unwrap().0, Point::origin());
        assert_eq!(curve.eval(90.0).unwrap().0, Point::new(0.0, 0.5));
    }

    #[test]
    fn derivatives_are_per_degree() {
        // Central differences in degrees against the exact derivative.
        let m = SliderCrank::new(1.0, 4.0, 1.5).unwrap();
        let kinds = [
            LocusKind::PolarVelocity,
            LocusKind::Centrode(CentrodeKind::Fixed),
            LocusKind::Centrode(CentrodeKind::Moving),
            LocusKind::Coupler(CouplerPoint::new(0.3).unwrap()),
        ];
        for kind in kinds {
            let curve = Locus::new(m, kind);
            for d in [10.0, 75.0, 160.0, 300.0] {
                let h = 1e-4;
                let (p1, _) = curve.eval(d + h).unwrap();
                let (p0, _) = curve.eval(d - h).unwrap();
                let (_, exact) = curve.eval(d).unwrap();
                let numeric = (p1 - p0) / (2.0 * h);
                assert!(
                    (numeric - exact).norm() <= 1e-6 * (1.0 + exact.norm()),
                    "{kind:?} at {d}: {numeric} vs {exact}"
                );
            }
        }
    }

    #[test]
    fn centrodes_are_undefined_only_at_their_poles() {
        let m = SliderCrank::in_line(0.5, 3.0).unwrap();
        let fixed = Locus::new(m, LocusKind::Centrode(CentrodeKind::Fixed));
        assert!(fixed.eval(90.0).is_none());
        assert!(fixed.eval(-90.0).is_none());
        assert!(fixed.eval(630.0).is_none());
        assert!(fixed.eval(89.999).is_some());
        assert!(fixed.eval(f64::NAN).is_none());
    }
}
