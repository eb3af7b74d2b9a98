//! An invertible affine map of the plane: a panel's page-from-world
//! transform.
//!
//! nalgebra's `Affine2` maps points and vectors too, but it does not check
//! invertibility when built and does not speak SVG's `a b c d e f` order;
//! this type is those two things around a `Matrix2` and a translation, with
//! the inverse computed once, when it is built.

use crate::geom::{Point, Vector};
use nalgebra::Matrix2;

/// The affine map `x' = a x + c y + e`, `y' = b x + d y + f`: the six numbers
/// of SVG's `matrix(a b c d e f)`. Non-uniform scales, mirrors and shears are
/// allowed; the map is always invertible (checked when built).
///
/// Points map with the whole map, vectors (derivatives, directions) with its
/// linear part only.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Affine {
    linear: Matrix2<f64>,
    translation: Vector,
    inverse_linear: Matrix2<f64>,
    inverse_translation: Vector,
}

fn all_finite<'a>(values: impl IntoIterator<Item = &'a f64>) -> bool {
    values.into_iter().all(|v| v.is_finite())
}

impl Affine {
    /// The map with SVG coefficients `[a, b, c, d, e, f]`.
    ///
    /// `None` when a coefficient is not finite, or when the linear part is
    /// singular or so nearly singular that its inverse is not finite.
    pub fn new(coefficients: [f64; 6]) -> Option<Self> {
        let [a, b, c, d, e, f] = coefficients;
        if !all_finite(&coefficients) {
            return None;
        }
        // Matrix2::new takes rows: [[a, c], [b, d]].
        let linear = Matrix2::new(a, c, b, d);
        let translation = Vector::new(e, f);
        let inverse_linear = linear.try_inverse()?;
        let inverse_translation = -(inverse_linear * translation);
        let ok = all_finite(inverse_linear.iter())
            && all_finite(inverse_translation.iter())
            && inverse_linear.determinant() != 0.0;
        ok.then_some(Self {
            linear,
            translation,
            inverse_linear,
            inverse_translation,
        })
    }

    /// The identity map.
    pub fn identity() -> Self {
        Self {
            linear: Matrix2::identity(),
            translation: Vector::zeros(),
            inverse_linear: Matrix2::identity(),
            inverse_translation: Vector::zeros(),
        }
    }

    /// Scale by `sx`, `sy` (negative to mirror), then translate by `tx`,
    /// `ty`: `[sx, 0, 0, sy, tx, ty]`. `None` when a scale is zero or a
    /// number is not finite.
    pub fn scale_translate(sx: f64, sy: f64, tx: f64, ty: f64) -> Option<Self> {
        Self::new([sx, 0.0, 0.0, sy, tx, ty])
    }

    /// The six SVG coefficients `[a, b, c, d, e, f]`.
    pub fn coefficients(&self) -> [f64; 6] {
        let m = &self.linear;
        [
            m[(0, 0)],
            m[(1, 0)],
            m[(0, 1)],
            m[(1, 1)],
            self.translation.x,
            self.translation.y,
        ]
    }

    /// The image of a point. It may overflow to infinity for points near
    /// `f64::MAX`; callers that emit geometry check finiteness.
    pub fn point(&self, p: Point) -> Point {
        Point::from(self.linear * p.coords + self.translation)
    }

    /// The image of a vector (a derivative or a direction): the linear part
    /// only.
    pub fn vector(&self, v: Vector) -> Vector {
        self.linear * v
    }

    /// The inverse map (world-from-page for a page-from-world map), exact
    /// in the sense that `m.inverse().inverse() == m`.
    pub fn inverse(&self) -> Self {
        Self {
            linear: self.inverse_linear,
            translation: self.inverse_translation,
            inverse_linear: self.linear,
            inverse_translation: self.translation,
        }
    }

    /// The smallest factor by which the map stretches a length (the least
    /// singular value of the linear part), > 0. A page distance `d` is at
    /// most `d / min_stretch()` in world units.
    pub fn min_stretch(&self) -> f64 {
        self.linear.singular_values().min()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn coefficients_follow_svg_order() {
        // matrix(1 2 3 4 5 6): x' = 1x + 3y + 5, y' = 2x + 4y + 6.
        let m = Affine::new([1.0, 2.0, 3.0, 4.0, 5.0, 6.0]).unwrap();
        assert_eq!(m.point(Point::new(1.0, 0.0)), Point::new(6.0, 8.0));
        assert_eq!(m.point(Point::new(0.0, 1.0)), Point::new(8.0, 10.0));
        assert_eq!(m.vector(Vector::new(0.0, 1.0)), Vector::new(3.0, 4.0));
        assert_eq!(m.coefficients(), [1.0, 2.0, 3.0, 4.0, 5.0, 6.0]);
    }

    #[test]
    fn mirrored_page_map_and_its_inverse() {
        // 200 px per unit, x mirrored, y down, origin at (300, 150).
        let m = Affine::scale_translate(-200.0, -200.0, 300.0, 150.0).unwrap();
        assert_eq!(m.point(Point::new(0.5, 0.25)), Point::new(200.0, 100.0));
        let back = m.inverse();
        assert_eq!(back.point(Point::new(200.0, 100.0)), Point::new(0.5, 0.25));
        assert_eq!(back.coefficients(), [-0.005, 0.0, 0.0, -0.005, 1.5, 0.75]);
        assert_eq!(back.inverse(), m);
        assert_eq!(m.min_stretch(), 200.0);
    }

    #[test]
    fn shear_round_trips() {
        let m = Affine::new([2.0, 1.0, -1.0, 3.0, 7.0, -4.0]).unwrap();
        let p = Point::new(0.3, -1.7);
        let q = m.inverse().point(m.point(p));
        assert!((q - p).norm() < 1e-15);
    }

    #[test]
    fn singular_and_non_finite_maps_are_refused() {
        assert!(Affine::new([1.0, 2.0, 2.0, 4.0, 0.0, 0.0]).is_none());
        assert!(Affine::new([0.0; 6]).is_none());
        assert!(Affine::new([1.0, 0.0, 0.0, 1.0, f64::NAN, 0.0]).is_none());
        assert!(Affine::new([f64::INFINITY, 0.0, 0.0, 1.0, 0.0, 0.0]).is_none());
        assert!(Affine::scale_translate(1e-200, 1e-200, 0.0, 0.0).is_none());
        assert!(Affine::scale_translate(0.0, 1.0, 0.0, 0.0).is_none());
    }
}
