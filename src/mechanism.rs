//! The validated slider-crank mechanism and its pose at a crank angle.

use crate::angle::Angle;
use crate::error::{Error, Field, Result, finite, positive};
use crate::geom::Point;

/// Smallest crank radius and rod length accepted, in any unit.
///
/// Lengths are squared and multiplied in the constructions (BE², the
/// distance to a far instantaneous centre); within [`MIN_LENGTH`,
/// [`MAX_LENGTH`]] every such product stays a normal f64.
pub const MIN_LENGTH: f64 = 1e-100;

/// Largest crank radius, rod length or offset accepted, in any unit.
pub const MAX_LENGTH: f64 = 1e100;

/// An in-line or offset slider-crank chain, validated once.
///
/// World frame (docs/design.md §1): the crank centre C at the origin, the line of
/// stroke `y = offset`, the slider on the `+x` side; crank angle θ
/// counter-clockwise from `+x`.
///
/// The rod must be longer than `crank + |offset|`, so that the crank turns a
/// full revolution and every angle is reachable; a shorter rod is an error
/// that names the bound.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SliderCrank {
    crank: f64,
    rod: f64,
    offset: f64,
}

pub(crate) fn in_range(name: Field, value: f64) -> Result<f64> {
    if (MIN_LENGTH..=MAX_LENGTH).contains(&value) {
        Ok(value)
    } else {
        Err(Error::OutOfRange {
            name,
            value,
            reason: format!(
                "lengths must lie between {MIN_LENGTH:e} and {MAX_LENGTH:e} (any unit: choose one that brings them in range)"
            ),
        })
    }
}

impl SliderCrank {
    /// Validates crank radius `r > 0`, rod length `l > r + |e|` and offset
    /// `e` (all finite, any consistent unit; r and l between [`MIN_LENGTH`]
    /// and [`MAX_LENGTH`], so that no product of lengths overflows or
    /// underflows).
    pub fn new(crank: f64, rod: f64, offset: f64) -> Result<Self> {
        let crank = in_range(Field::Crank, positive(Field::Crank, crank)?)?;
        let rod = in_range(Field::Rod, positive(Field::Rod, rod)?)?;
        let offset = finite(Field::Offset, offset)?;
        let needed = crank + offset.abs();
        if rod <= needed || !needed.is_finite() {
            return Err(Error::RodTooShort {
                crank,
                rod,
                offset,
                needed,
            });
        }
        Ok(Self { crank, rod, offset })
    }

    /// An in-line mechanism (offset 0).
    pub fn in_line(crank: f64, rod: f64) -> Result<Self> {
        Self::new(crank, rod, 0.0)
    }

    /// Crank radius r.
    #[inline]
    pub fn crank(&self) -> f64 {
        self.crank
    }

    /// Connecting-rod length l.
    #[inline]
    pub fn rod(&self) -> f64 {
        self.rod
    }

    /// Offset e of the line of stroke from the crank centre.
    #[inline]
    pub fn offset(&self) -> f64 {
        self.offset
    }

    /// The ratio n = l / r.
    pub fn ratio(&self) -> f64 {
        self.rod / self.crank
    }

    /// The mechanism at crank angle `angle`.
    #[inline]
    pub fn pose(&self, angle: Angle) -> Pose {
        Pose::new(*self, angle)
    }

    /// The outer dead centre: crank and rod in one line, slider farthest out;
    /// θ = asin(e / (l + r)), 0° in line. As every [`Angle`] it is reduced
    /// to [0°, 360°): with a negative offset it lies just below 360°.
    // cannot fail: asin of e / (l + r), |e| < l + r, is finite: Angle::from_radians takes it.
    #[allow(clippy::expect_used)]
    pub fn outer_dead_centre(&self) -> Angle {
        Angle::from_radians(self.dead_centres().0).expect("asin of a ratio below 1 is finite")
    }

    /// The inner dead centre: rod folded over the crank, slider nearest;
    /// θ = π + asin(e / (l − r)), 180° in line. With an offset the two dead
    /// centres are not 180° apart.
    // cannot fail: π + asin of e / (l − r), |e| < l − r, is finite: Angle::from_radians takes it.
    #[allow(clippy::expect_used)]
    pub fn inner_dead_centre(&self) -> Angle {
        Angle::from_radians(self.dead_centres().1).expect("asin of a ratio below 1 is finite")
    }

    /// The outer and inner dead centres in radians, unreduced: the outer in
    /// (−π/2, π/2), the inner in (π/2, 3π/2).
    pub(crate) fn dead_centres(&self) -> (f64, f64) {
        (
            (self.offset / (self.rod + self.crank)).asin(),
            std::f64::consts::PI + (self.offset / (self.rod - self.crank)).asin(),
        )
    }

    /// The stroke: the distance between the slider's two dead-centre
    /// positions, √((l + r)² − e²) − √((l − r)² − e²); 2r when e = 0.
    pub fn stroke(&self) -> f64 {
        let (r, l, e) = (self.crank, self.rod, self.offset);
        let far = ((l + r - e) * (l + r + e)).sqrt();
        let near = ((l - r - e) * (l - r + e)).sqrt();
        // far − near without cancellation: (far² − near²) / (far + near).
        4.0 * l * r / (far + near)
    }

    /// Crank angle turned while the slider goes from the outer to the inner
    /// dead centre (ω > 0), in radians; π when e = 0.
    pub fn inward_stroke_angle(&self) -> f64 {
        let (outer, inner) = self.dead_centres();
        inner - outer
    }

    /// Quick-return time ratio at constant ω: the longer stroke's time over
    /// the shorter's, ≥ 1, exactly 1 for an in-line mechanism.
    pub fn quick_return_ratio(&self) -> f64 {
        let inward = self.inward_stroke_angle();
        let outward = 2.0 * std::f64::consts::PI - inward;
        inward.max(outward) / inward.min(outward)
    }
}

/// The mechanism at one crank angle: the points A, B, C and the exact
/// derivatives of the slider position and rod obliquity with respect to θ.
///
/// Derivatives here are with respect to θ; multiply by ω (first) and ω²
/// (second) for time derivatives at constant angular speed, as
/// [`crate::analytic::kinematics::Kinematics`] does.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pose {
    mechanism: SliderCrank,
    angle: Angle,
    /// r sin θ − e: height of the crank pin above the line of stroke.
    h: f64,
    /// √(l² − h²) = l cos φ, horizontal extent of the rod (> 0 always).
    w: f64,
}

impl Pose {
    #[inline]
    fn new(mechanism: SliderCrank, angle: Angle) -> Self {
        let (r, l, e) = (mechanism.crank, mechanism.rod, mechanism.offset);
        let h = r * angle.sin() - e;
        // Factored to keep precision when the rod is nearly vertical (n → 1).
        let w = ((l - h) * (l + h)).sqrt();
        Self {
            mechanism,
            angle,
            h,
            w,
        }
    }

    /// The mechanism this pose belongs to.
    #[inline]
    pub fn mechanism(&self) -> &SliderCrank {
        &self.mechanism
    }

    /// The crank angle.
    #[inline]
    pub fn angle(&self) -> Angle {
        self.angle
    }

    /// Crank centre C (the origin; Ng's O).
    #[inline]
    pub fn c(&self) -> Point {
        Point::origin()
    }

    /// Crank pin B = r(cos θ, sin θ) (Ng's C).
    #[inline]
    pub fn b(&self) -> Point {
        let r = self.mechanism.crank;
        Point::new(r * self.angle.cos(), r * self.angle.sin())
    }

    /// Cross-head A on the line of stroke (Ng's P).
    #[inline]
    pub fn a(&self) -> Point {
        Point::new(self.position(), self.mechanism.offset)
    }

    /// Height of the crank pin above the line of stroke, r sin θ − e = l sin φ.
    #[inline]
    pub fn rise(&self) -> f64 {
        self.h
    }

    /// Horizontal extent of the rod, l cos φ (always > 0).
    #[inline]
    pub fn run(&self) -> f64 {
        self.w
    }

    /// tan φ = (r sin θ − e) / (l cos φ). Per unit crank,
    /// (sin θ − e/r) / (w/r), where r sin θ − e is below the normal range
    /// of f64 (a tiny crank a hair from the line of stroke): the quotient
    /// of two underflowed lengths would be 0 where tan φ is not.
    #[inline]
    pub fn tan_obliquity(&self) -> f64 {
        if self.h.abs() >= f64::MIN_POSITIVE {
            self.h / self.w
        } else {
            let (r, e) = (self.mechanism.crank, self.mechanism.offset);
            (self.angle.sin() - e / r) / (self.w / r)
        }
    }

    /// Slider position s = x_A = r cos θ + √(l² − (r sin θ − e)²).
    #[inline]
    pub fn position(&self) -> f64 {
        self.mechanism.crank * self.angle.cos() + self.w
    }

    /// ds/dθ = −r sin θ − r cos θ (r sin θ − e)/√(l² − (r sin θ − e)²).
    #[inline]
    pub fn position_rate(&self) -> f64 {
        let r = self.mechanism.crank;
        let (s, c) = (self.angle.sin(), self.angle.cos());
        -r * s - r * c * self.h / self.w
    }

    /// d²s/dθ² = −r cos θ − r² cos²θ l² / w³ + r sin θ h / w.
    #[inline]
    pub fn position_acceleration(&self) -> f64 {
        let (r, l) = (self.mechanism.crank, self.mechanism.rod);
        let (s, c) = (self.angle.sin(), self.angle.cos());
        let w = self.w;
        let rc_over_w = r * c / w;
        -r * c - rc_over_w * rc_over_w * (l / w) * l + r * s * self.h / w
    }

    /// Obliquity φ of the rod: sin φ = (r sin θ − e)/l, in (−π/2, π/2).
    #[inline]
    pub fn obliquity(&self) -> f64 {
        self.h.atan2(self.w)
    }

    /// dφ/dθ = r cos θ / (l cos φ).
    #[inline]
    pub fn obliquity_rate(&self) -> f64 {
        self.mechanism.crank * self.angle.cos() / self.w
    }

    /// d²φ/dθ² = −r sin θ / w + r² cos²θ h / w³.
    #[inline]
    pub fn obliquity_acceleration(&self) -> f64 {
        let r = self.mechanism.crank;
        let (s, c) = (self.angle.sin(), self.angle.cos());
        let w = self.w;
        let rc_over_w = r * c / w;
        -r * s / w + rc_over_w * rc_over_w * self.h / w
    }

    /// d³s/dθ³ = r sin θ + r sin θ φ′ − 2 r cos θ φ″ − h φ‴ (h = r sin θ − e,
    /// φ′, φ″, φ‴ the obliquity's derivatives): the rate of change of
    /// [`Pose::position_acceleration`], which acceleration diagrams need for
    /// their exact tangents.
    pub fn position_jerk(&self) -> f64 {
        let r = self.mechanism.crank;
        let (s, c) = (self.angle.sin(), self.angle.cos());
        r * s + r * s * self.obliquity_rate()
            - 2.0 * r * c * self.obliquity_acceleration()
            - self.h * self.obliquity_jerk()
    }

    /// d³φ/dθ³ = h‴/w + (3 h h′ h″ + h′³)/w³ + 3 h² h′³/w⁵ with h = r sin θ − e,
    /// h′ = r cos θ, h″ = −r sin θ, h‴ = −r cos θ, w = l cos φ: the rate of
    /// change of [`Pose::obliquity_acceleration`].
    pub fn obliquity_jerk(&self) -> f64 {
        let r = self.mechanism.crank;
        let (s, c) = (self.angle.sin(), self.angle.cos());
        let (h, w) = (self.h, self.w);
        let (h1, h2, h3) = (r * c, -r * s, -r * c);
        let q3 = h1 * h1 * h1 / (w * w * w);
        h3 / w + 3.0 * h * h1 * h2 / (w * w * w) + q3 + 3.0 * h * h * q3 / (w * w)
    }

    /// The textbook's error due to obliquity, x_A − (r cos θ + l) = w − l,
    /// computed as −h²/(w + l) without cancellation; r(√(n² − sin²θ) − n)
    /// when e = 0. Never positive.
    pub fn obliquity_error(&self) -> f64 {
        -self.h * self.h / (self.w + self.mechanism.rod)
    }

    /// The interior angle of the triangle C B A at the crank pin, in radians
    /// in [0, π]: the general transmission angle. For e = 0 and
    /// 0 < θ < 180° it equals π − φ − θ (Ng eq. 11); it is 0 or π at the
    /// dead centres.
    pub fn transmission_angle(&self) -> f64 {
        let b = self.b();
        let to_c = self.c() - b;
        let to_a = self.a() - b;
        let cross = to_c.x * to_a.y - to_c.y * to_a.x;
        cross.abs().atan2(to_c.dot(&to_a))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tan_obliquity_survives_an_underflowed_rise() {
        // r sin θ = 1e-100 · 1.7e-232 is below the smallest f64; tan φ is
        // sin θ / √(n² − sin²θ) ≈ 5.8e-233, not 0.
        let m = SliderCrank::in_line(1e-100, 3e-100).unwrap();
        let p = m.pose(Angle::deg(1e-230));
        assert_eq!(p.rise(), 0.0);
        let expected = 1e-230f64.to_radians() / 3.0;
        assert!((p.tan_obliquity() / expected - 1.0).abs() < 1e-15);
        // Elsewhere it is the quotient of the two lengths.
        let p = SliderCrank::new(0.5, 3.0, 0.1)
            .unwrap()
            .pose(Angle::deg(33.0));
        assert_eq!(p.tan_obliquity(), p.rise() / p.run());
        assert_eq!(m.pose(Angle::deg(180.0)).tan_obliquity(), 0.0);
    }

    #[test]
    fn validation_names_the_bound() {
        let err = SliderCrank::new(0.5, 0.4, 0.0).unwrap_err();
        assert!(matches!(err, Error::RodTooShort { needed, .. } if needed == 0.5));
        assert!(err.to_string().contains("rod > crank + |offset| = 0.5"));
        assert!(SliderCrank::new(1.0, 3.0, 2.0).is_err());
        assert!(SliderCrank::new(1.0, 3.0, -2.0).is_err());
        assert!(SliderCrank::new(1.0, 3.0, 1.9).is_ok());
        assert!(SliderCrank::new(-1.0, 3.0, 0.0).is_err());
        assert!(SliderCrank::new(0.0, 3.0, 0.0).is_err());
        assert!(SliderCrank::new(f64::NAN, 3.0, 0.0).is_err());
        assert!(SliderCrank::new(1.0, f64::INFINITY, 0.0).is_err());
        assert!(SliderCrank::new(1.0, 3.0, f64::NAN).is_err());
        assert!(SliderCrank::new(f64::MAX, f64::MAX, f64::MAX).is_err());
        assert!(matches!(
            SliderCrank::new(1e300, 3e300, 0.0),
            Err(Error::OutOfRange {
                name: Field::Crank,
                ..
            })
        ));
        assert!(matches!(
            SliderCrank::new(1e-300, 3e-300, 0.0),
            Err(Error::OutOfRange {
                name: Field::Crank,
                ..
            })
        ));
        assert!(SliderCrank::new(1e-100, 3e-100, 0.0).is_ok());
        assert!(SliderCrank::new(1e99, 1e100, 0.0).is_ok());
    }

    #[test]
    fn dead_centres_in_line() {
        let m = SliderCrank::in_line(0.5, 3.0).unwrap();
        assert_eq!(m.outer_dead_centre(), Angle::deg(0.0));
        assert_eq!(m.inner_dead_centre().degrees(), 180.0);
        let below = SliderCrank::new(1.0, 3.0, -0.5).unwrap();
        assert!((below.outer_dead_centre().degrees() - (360.0 - 7.180755781)).abs() < 1e-8);
        assert!((m.stroke() - 1.0).abs() < 1e-15);
        assert_eq!(m.quick_return_ratio(), 1.0);
        let outer = m.pose(Angle::deg(0.0));
        assert_eq!(outer.position(), 3.5);
        assert_eq!(m.pose(Angle::deg(180.0)).position(), 2.5);
        assert_eq!(outer.position_rate(), 0.0);
    }

    #[test]
    fn offset_dead_centres_are_stationary_and_collinear() {
        let m = SliderCrank::new(1.0, 3.0, 0.7).unwrap();
        for theta in [m.outer_dead_centre(), m.inner_dead_centre()] {
            let p = m.pose(theta);
            assert!(p.position_rate().abs() < 1e-14, "{}", p.position_rate());
            assert!(
                p.transmission_angle()
                    .min(std::f64::consts::PI - p.transmission_angle())
                    < 1e-7
            );
        }
        let far = m.pose(m.outer_dead_centre()).position();
        let near = m.pose(m.inner_dead_centre()).position();
        assert!((far - near - m.stroke()).abs() < 1e-14);
        assert!(m.quick_return_ratio() > 1.0);
    }

    #[test]
    fn rod_has_its_length_at_every_pose() {
        let m = SliderCrank::new(1.0, 1.05, 0.04).unwrap();
        for k in 0..360 {
            let p = m.pose(Angle::deg(k as f64));
            assert!(((p.a() - p.b()).norm() - 1.05).abs() < 1e-15);
        }
    }

    #[test]
    fn transmission_angle_matches_ng_eq_11_in_line() {
        let m = SliderCrank::in_line(25.0, 72.0).unwrap();
        for d in [10.0, 45.0, 90.0, 135.0, 170.0] {
            let p = m.pose(Angle::deg(d));
            let ng = std::f64::consts::PI - p.obliquity() - p.angle().radians();
            assert!((p.transmission_angle() - ng).abs() < 1e-14, "{d}");
        }
    }

    #[test]
    fn third_derivatives_match_differences_of_the_second() {
        // Central differences of the exact second derivatives, against the
        // exact third, with an offset and a short rod.
        for m in [
            SliderCrank::in_line(0.5, 3.0).unwrap(),
            SliderCrank::new(1.0, 1.6, -0.5).unwrap(),
        ] {
            for d in [0.0f64, 10.0, 45.0, 90.0, 150.0, 200.0, 300.0] {
                let h = 1e-5;
                let at = |x: f64| m.pose(Angle::from_radians(d.to_radians() + x).unwrap());
                let (p, q, here) = (at(h), at(-h), at(0.0));
                let ds3 = (p.position_acceleration() - q.position_acceleration()) / (2.0 * h);
                let dp3 = (p.obliquity_acceleration() - q.obliquity_acceleration()) / (2.0 * h);
                let scale = m.crank() * (1.0 + here.position_jerk().abs());
                assert!(
                    (here.position_jerk() - ds3).abs() < 1e-7 * scale,
                    "{m:?} {d}: {} vs {ds3}",
                    here.position_jerk()
                );
                assert!(
                    (here.obliquity_jerk() - dp3).abs() < 1e-7 * (1.0 + dp3.abs()),
                    "{m:?} {d}: {} vs {dp3}",
                    here.obliquity_jerk()
                );
            }
        }
        // In line at θ = 0: s is even in θ, so s‴(0) = 0; and
        // φ‴(0) = −(r/l)(1 − r²/l²) from sin φ = (r/l) sin θ.
        let m = SliderCrank::in_line(0.5, 3.0).unwrap();
        let outer = m.pose(Angle::deg(0.0));
        assert_eq!(outer.position_jerk(), 0.0);
        let k: f64 = 1.0 / 6.0;
        assert!((outer.obliquity_jerk() + k * (1.0 - k * k)).abs() < 1e-16);
    }

    #[test]
    fn obliquity_error_matches_textbook_form() {
        let m = SliderCrank::in_line(1.0, 4.0).unwrap();
        let p = m.pose(Angle::deg(90.0));
        assert!((p.obliquity_error() - (15f64.sqrt() - 4.0)).abs() < 1e-15);
    }
}
