//! The affine map from a panel's world coordinates to page coordinates.

use crate::geom::{Frame, Point, Vector};

/// `page = (a x + c y + e, b x + d y + f)`: the six numbers of an SVG
/// `matrix(a b c d e f)`, invertible by construction.
///
/// The one world-to-page map of the crate: figure panels and the curve
/// engine ([`crate::diagram::trace`]) both use it. Mechanism panels use a
/// uniform scale with y flipped (world y up, page y down) and, for a
/// mirrored figure, x flipped too; plot panels may scale x and y
/// differently. Text is never transformed by it: the renderer maps only a
/// label's anchor. The inverse is computed once, when the map is built, so
/// `m.inverse().inverse() == m`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PageFromWorld {
    m: [f64; 6],
    inv: [f64; 6],
}

fn inverse_of(m: &[f64; 6]) -> Option<[f64; 6]> {
    let [a, b, c, d, e, f] = *m;
    let det = a * d - b * c;
    let inv = [
        d / det,
        -b / det,
        -c / det,
        a / det,
        (c * f - d * e) / det,
        (b * e - a * f) / det,
    ];
    (det != 0.0 && inv.iter().all(|v| v.is_finite())).then_some(inv)
}

fn apply(m: &[f64; 6], p: Point) -> Point {
    Point::new(
        m[0] * p.x + m[2] * p.y + m[4],
        m[1] * p.x + m[3] * p.y + m[5],
    )
}

impl PageFromWorld {
    /// The map `[a, b, c, d, e, f]`; `None` unless all six are finite and
    /// the map is invertible with a finite inverse.
    pub fn new(coefficients: [f64; 6]) -> Option<Self> {
        if !coefficients.iter().all(|v| v.is_finite()) {
            return None;
        }
        let inv = inverse_of(&coefficients)?;
        Some(Self {
            m: coefficients,
            inv,
        })
    }

    /// The identity map.
    pub fn identity() -> Self {
        let m = [1.0, 0.0, 0.0, 1.0, 0.0, 0.0];
        Self { m, inv: m }
    }

    /// `page = (sx x + tx, sy y + ty)`; `None` for a zero or non-finite
    /// scale or translation.
    pub fn scale_translate(sx: f64, sy: f64, tx: f64, ty: f64) -> Option<Self> {
        Self::new([sx, 0.0, 0.0, sy, tx, ty])
    }

    /// The map of uniform `scale` (page units per world unit, > 0) taking
    /// `world` to `page`, with world y up; `mirror` flips x (the textbook's
    /// cylinder on the left). `None` unless everything is finite and the
    /// scale positive.
    pub fn uniform(scale: f64, mirror: bool, world: Point, page: Point) -> Option<Self> {
        if scale.is_nan() || scale <= 0.0 {
            return None;
        }
        let sx = if mirror { -scale } else { scale };
        Self::axes(sx, -scale, world, page)
    }

    /// The map scaling x by `sx` and y by `sy` (either sign, non-zero), taking
    /// `world` to `page`: for plot panels with axes. `None` for a zero or
    /// non-finite scale or a non-finite point.
    pub fn axes(sx: f64, sy: f64, world: Point, page: Point) -> Option<Self> {
        Self::new([
            sx,
            0.0,
            0.0,
            sy,
            page.x - sx * world.x,
            page.y - sy * world.y,
        ])
    }

    /// The largest uniform map that shows the world rectangle `world` whole
    /// inside `page`, centred; `None` if either is empty or not finite.
    pub fn fit(world: &Frame, page: &Frame, mirror: bool) -> Option<Self> {
        let size = world.max() - world.min();
        if !(size.x > 0.0 && size.y > 0.0 && page.width() > 0.0 && page.height() > 0.0) {
            return None;
        }
        let scale = (page.width() / size.x).min(page.height() / size.y);
        let centre = nalgebra::center(&world.min(), &world.max());
        Self::uniform(scale, mirror, centre, page.centre())
    }

    /// `[a, b, c, d, e, f]`.
    pub fn coefficients(&self) -> [f64; 6] {
        self.m
    }

    /// The page point of a world point.
    pub fn apply(&self, p: Point) -> Point {
        apply(&self.m, p)
    }

    /// The page vector of a world vector (the linear part only).
    pub fn apply_vector(&self, v: Vector) -> Vector {
        let m = &self.m;
        Vector::new(m[0] * v.x + m[2] * v.y, m[1] * v.x + m[3] * v.y)
    }

    /// The world point of a page point, solved directly (one rounding
    /// fewer than applying [`PageFromWorld::inverse`]).
    pub fn invert(&self, p: Point) -> Point {
        let [a, b, c, d, e, f] = self.m;
        let det = a * d - b * c;
        let (x, y) = (p.x - e, p.y - f);
        Point::new((d * x - c * y) / det, (a * y - b * x) / det)
    }

    /// The inverse map, world from page.
    pub fn inverse(&self) -> Self {
        Self {
            m: self.inv,
            inv: self.m,
        }
    }

    /// Page units per world unit along x (absolute value); for a uniform map
    /// the scale of every length.
    pub fn scale(&self) -> f64 {
        self.m[0].hypot(self.m[1])
    }

    /// The least stretch of the linear part (its smaller singular value):
    /// a world length ℓ is at least `min_stretch() · ℓ` on the page.
    pub fn min_stretch(&self) -> f64 {
        let [a, b, c, d, ..] = self.m;
        nalgebra::Matrix2::new(a, c, b, d).singular_values().min()
    }

    /// Whether x is flipped relative to y (a mirrored page).
    pub fn is_mirrored(&self) -> bool {
        self.m[0] * self.m[3] - self.m[1] * self.m[2] > 0.0
    }

    /// The world rectangle that the page rectangle shows (exact for an
    /// axis-aligned map; the bounding box of the corners' images otherwise).
    pub fn world_frame(&self, page: &Frame) -> Frame {
        let p = self.invert(Point::new(page.min().x, page.min().y));
        let q = self.invert(Point::new(page.max().x, page.max().y));
        Frame::new(p, q)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn uniform_map_flips_y_and_mirrors_x() {
        let t = PageFromWorld::uniform(100.0, false, Point::new(0.0, 0.0), Point::new(50.0, 60.0))
            .unwrap();
        assert_eq!(t.apply(Point::new(1.0, 1.0)), Point::new(150.0, -40.0));
        let m = PageFromWorld::uniform(100.0, true, Point::new(0.0, 0.0), Point::new(50.0, 60.0))
            .unwrap();
        assert_eq!(m.apply(Point::new(1.0, 1.0)), Point::new(-50.0, -40.0));
        assert!(m.is_mirrored() && !t.is_mirrored());
        assert_eq!(m.invert(Point::new(-50.0, -40.0)), Point::new(1.0, 1.0));
        assert_eq!(m.inverse().inverse(), m);
        assert_eq!(
            m.inverse().apply(Point::new(-50.0, -40.0)),
            Point::new(1.0, 1.0)
        );
        assert_eq!(m.coefficients(), [-100.0, 0.0, 0.0, -100.0, 50.0, 60.0]);
    }

    #[test]
    fn fit_centres_and_keeps_aspect() {
        let world = Frame::new(Point::new(0.0, 0.0), Point::new(4.0, 1.0));
        let page = Frame::from_origin_size(10.0, 10.0, 400.0, 400.0);
        let t = PageFromWorld::fit(&world, &page, false).unwrap();
        assert_eq!(t.scale(), 100.0);
        assert_eq!(t.apply(Point::new(2.0, 0.5)), Point::new(210.0, 210.0));
        let shown = t.world_frame(&page);
        assert_eq!(shown.min(), Point::new(0.0, -1.5));
        assert_eq!(shown.max(), Point::new(4.0, 2.5));
    }

    #[test]
    fn degenerate_maps_are_refused() {
        let empty = Frame::new(Point::new(1.0, 1.0), Point::new(1.0, 3.0));
        let page = Frame::from_origin_size(0.0, 0.0, 10.0, 10.0);
        assert!(PageFromWorld::fit(&empty, &page, false).is_none());
        assert!(PageFromWorld::axes(0.0, 1.0, Point::origin(), Point::origin()).is_none());
        assert!(
            PageFromWorld::uniform(f64::NAN, false, Point::origin(), Point::origin()).is_none()
        );
        assert!(PageFromWorld::new([1.0, 2.0, 2.0, 4.0, 0.0, 0.0]).is_none());
        assert!(PageFromWorld::new([1e-300, 0.0, 0.0, 1e-300, 0.0, 0.0]).is_none());
    }
}
