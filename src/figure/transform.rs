//! The affine map from a panel's world coordinates to page coordinates.

use crate::geom::{Frame, Point, Vector};

/// A rectangle of the page, in page units (SVG user units, y down).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PageRect {
    /// Left edge.
    pub x: f64,
    /// Top edge.
    pub y: f64,
    /// Width (≥ 0).
    pub width: f64,
    /// Height (≥ 0).
    pub height: f64,
}

impl PageRect {
    /// The rectangle with top-left corner `(x, y)` and the given size.
    pub fn new(x: f64, y: f64, width: f64, height: f64) -> Self {
        Self {
            x,
            y,
            width,
            height,
        }
    }

    /// The rectangle as a [`Frame`] of page points.
    pub fn frame(&self) -> Frame {
        Frame::new(
            Point::new(self.x, self.y),
            Point::new(self.x + self.width, self.y + self.height),
        )
    }

    /// Whether `p` lies inside (boundary included).
    pub fn contains(&self, p: Point) -> bool {
        self.frame().contains(p)
    }

    /// The centre.
    pub fn centre(&self) -> Point {
        Point::new(self.x + 0.5 * self.width, self.y + 0.5 * self.height)
    }
}

/// `page = (a x + c y + e, b x + d y + f)`: the six numbers of an SVG
/// `matrix(a b c d e f)`.
///
/// Mechanism panels use a uniform scale with y flipped (world y up, page y
/// down) and, for a mirrored figure, x flipped too; plot panels may scale x
/// and y differently. Text is never transformed by it: the renderer maps
/// only a label's anchor.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PageFromWorld {
    a: f64,
    b: f64,
    c: f64,
    d: f64,
    e: f64,
    f: f64,
}

impl PageFromWorld {
    /// The map of uniform `scale` (page units per world unit, > 0) taking
    /// `world` to `page`, with world y up; `mirror` flips x (the textbook's
    /// cylinder on the left). `None` unless everything is finite and the
    /// scale positive.
    pub fn uniform(scale: f64, mirror: bool, world: Point, page: Point) -> Option<Self> {
        let sx = if mirror { -scale } else { scale };
        Self::axes(sx, -scale, world, page)
    }

    /// The map scaling x by `sx` and y by `sy` (either sign, non-zero), taking
    /// `world` to `page`: for plot panels with axes. `None` for a zero or
    /// non-finite scale or a non-finite point.
    pub fn axes(sx: f64, sy: f64, world: Point, page: Point) -> Option<Self> {
        let t = Self {
            a: sx,
            b: 0.0,
            c: 0.0,
            d: sy,
            e: page.x - sx * world.x,
            f: page.y - sy * world.y,
        };
        (sx != 0.0 && sy != 0.0 && t.coefficients().iter().all(|v| v.is_finite())).then_some(t)
    }

    /// The largest uniform map that shows the world rectangle `world` whole
    /// inside `page`, centred; `None` if either is empty or not finite.
    pub fn fit(world: &Frame, page: &PageRect, mirror: bool) -> Option<Self> {
        let size = world.max() - world.min();
        if !(size.x > 0.0 && size.y > 0.0 && page.width > 0.0 && page.height > 0.0) {
            return None;
        }
        let scale = (page.width / size.x).min(page.height / size.y);
        let centre = nalgebra::center(&world.min(), &world.max());
        Self::uniform(scale, mirror, centre, page.centre())
    }

    /// `[a, b, c, d, e, f]`.
    pub fn coefficients(&self) -> [f64; 6] {
        [self.a, self.b, self.c, self.d, self.e, self.f]
    }

    /// The page point of a world point.
    pub fn apply(&self, p: Point) -> Point {
        Point::new(
            self.a * p.x + self.c * p.y + self.e,
            self.b * p.x + self.d * p.y + self.f,
        )
    }

    /// The page vector of a world vector.
    pub fn apply_vector(&self, v: Vector) -> Vector {
        Vector::new(self.a * v.x + self.c * v.y, self.b * v.x + self.d * v.y)
    }

    /// The world point of a page point; `None` if the map is singular.
    pub fn invert(&self, p: Point) -> Option<Point> {
        let det = self.a * self.d - self.b * self.c;
        if det == 0.0 || !det.is_finite() {
            return None;
        }
        let (x, y) = (p.x - self.e, p.y - self.f);
        Some(Point::new(
            (self.d * x - self.c * y) / det,
            (-self.b * x + self.a * y) / det,
        ))
    }

    /// Page units per world unit along x (absolute value); for a uniform map
    /// the scale of every length.
    pub fn scale(&self) -> f64 {
        (self.a * self.a + self.b * self.b).sqrt()
    }

    /// Whether x is flipped relative to y (a mirrored page).
    pub fn is_mirrored(&self) -> bool {
        self.a * self.d - self.b * self.c > 0.0
    }

    /// The world rectangle that the page rectangle shows (for an
    /// axis-aligned map); `None` if the map is singular.
    pub fn world_frame(&self, page: &PageRect) -> Option<Frame> {
        let p = self.invert(Point::new(page.x, page.y))?;
        let q = self.invert(Point::new(page.x + page.width, page.y + page.height))?;
        Some(Frame::new(p, q))
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
        assert_eq!(
            m.invert(Point::new(-50.0, -40.0)),
            Some(Point::new(1.0, 1.0))
        );
        assert_eq!(m.coefficients(), [-100.0, 0.0, 0.0, -100.0, 50.0, 60.0]);
    }

    #[test]
    fn fit_centres_and_keeps_aspect() {
        let world = Frame::new(Point::new(0.0, 0.0), Point::new(4.0, 1.0));
        let page = PageRect::new(10.0, 10.0, 400.0, 400.0);
        let t = PageFromWorld::fit(&world, &page, false).unwrap();
        assert_eq!(t.scale(), 100.0);
        assert_eq!(t.apply(Point::new(2.0, 0.5)), Point::new(210.0, 210.0));
        let shown = t.world_frame(&page).unwrap();
        assert_eq!(shown.min(), Point::new(0.0, -1.5));
        assert_eq!(shown.max(), Point::new(4.0, 2.5));
    }

    #[test]
    fn degenerate_maps_are_refused() {
        let empty = Frame::new(Point::new(1.0, 1.0), Point::new(1.0, 3.0));
        let page = PageRect::new(0.0, 0.0, 10.0, 10.0);
        assert!(PageFromWorld::fit(&empty, &page, false).is_none());
        assert!(PageFromWorld::axes(0.0, 1.0, Point::origin(), Point::origin()).is_none());
        assert!(
            PageFromWorld::uniform(f64::NAN, false, Point::origin(), Point::origin()).is_none()
        );
    }
}
