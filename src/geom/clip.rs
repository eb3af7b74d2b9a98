//! Clipping lines, rays and segments to an axis-aligned frame: the slab
//! method (Kay and Kajiya), a line's entry and exit parameters on each
//! axis, the latest entry and the earliest exit kept.

use super::{Line, Point, Vector};

/// An axis-aligned rectangle: a drawing frame or a plot area.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Frame {
    min: Point,
    max: Point,
}

impl Frame {
    /// The rectangle spanned by two corners (in any order); `None` when a
    /// coordinate is NaN or infinite. Use this for corners from outside.
    pub fn try_new(a: Point, b: Point) -> Option<Self> {
        let ok = [a.x, a.y, b.x, b.y].iter().all(|v| v.is_finite());
        ok.then(|| Self::new(a, b))
    }

    /// The rectangle spanned by two corners (in any order), known to be
    /// finite (the program's own frames; [`Frame::try_new`] checks). A NaN
    /// coordinate gives a frame that contains no point, never a panic.
    pub fn new(a: Point, b: Point) -> Self {
        Self {
            min: a.inf(&b),
            max: a.sup(&b),
        }
    }

    /// The frame from its least and greatest corner as given, not
    /// reordered: a `min` past `max` on an axis (a box clipped to a region
    /// it misses, or shrunk past its middle) gives a frame that contains
    /// no point, holds no frame with its corners in order, overlaps
    /// nothing and meets only a frame reaching across its crossed corners.
    pub fn from_corners(min: Point, max: Point) -> Self {
        Self { min, max }
    }

    /// The rectangle with its least corner at `(x, y)` (on a page, whose y
    /// runs down, the top left) and the given size: the figure's panels and
    /// page regions. The corners are not reordered: a negative size gives a
    /// frame with its corners crossed (see [`Frame::from_corners`]).
    pub fn from_origin_size(x: f64, y: f64, width: f64, height: f64) -> Self {
        Self {
            min: Point::new(x, y),
            max: Point::new(x + width, y + height),
        }
    }

    /// The extent along x (negative for corners crossed on x).
    pub fn width(&self) -> f64 {
        self.max.x - self.min.x
    }

    /// The extent along y (negative for corners crossed on y).
    pub fn height(&self) -> f64 {
        self.max.y - self.min.y
    }

    /// The centre, halfway between the corners.
    pub fn centre(&self) -> Point {
        Point::new(
            self.min.x + 0.5 * self.width(),
            self.min.y + 0.5 * self.height(),
        )
    }

    /// Lower-left corner.
    pub fn min(&self) -> Point {
        self.min
    }

    /// Upper-right corner.
    pub fn max(&self) -> Point {
        self.max
    }

    /// Grows the frame to hold `p`; a point with a coordinate that is not
    /// finite is left out (the frame unchanged).
    pub fn include(&mut self, p: Point) {
        if p.x.is_finite() && p.y.is_finite() {
            self.min = self.min.inf(&p);
            self.max = self.max.sup(&p);
        }
    }

    /// Whether `p` lies in the frame (boundary included).
    pub fn contains(&self, p: Point) -> bool {
        p.x >= self.min.x && p.x <= self.max.x && p.y >= self.min.y && p.y <= self.max.y
    }

    /// The frame reaching `half` from `centre` on each axis; a negative
    /// component gives a frame with its corners crossed, which contains no
    /// point (see [`Frame::from_corners`]).
    pub fn around(centre: Point, half: Vector) -> Self {
        Self {
            min: centre - half,
            max: centre + half,
        }
    }

    /// The least frame holding every one of `points` (`None` for none).
    pub fn enclosing(points: &[Point]) -> Option<Self> {
        let (first, rest) = points.split_first()?;
        Some(
            rest.iter()
                .fold(Self::around(*first, Vector::zeros()), |f, p| Self {
                    min: f.min.inf(p),
                    max: f.max.sup(p),
                }),
        )
    }

    /// The frame grown by `by` on every side (shrunk for a negative `by`;
    /// shrunk past its middle, a frame with its corners crossed, see
    /// [`Frame::from_corners`]).
    pub fn inflate(&self, by: f64) -> Self {
        let d = Vector::new(by, by);
        Self {
            min: self.min - d,
            max: self.max + d,
        }
    }

    /// The area the two frames share (0 where they do not overlap).
    pub fn overlap_area(&self, o: &Frame) -> f64 {
        let w = (self.max.x.min(o.max.x) - self.min.x.max(o.min.x)).max(0.0);
        let h = (self.max.y.min(o.max.y) - self.min.y.max(o.min.y)).max(0.0);
        w * h
    }

    /// Whether the two frames meet, touching included.
    pub fn meets(&self, o: &Frame) -> bool {
        self.min.x <= o.max.x
            && o.min.x <= self.max.x
            && self.min.y <= o.max.y
            && o.min.y <= self.max.y
    }

    /// Whether `o` lies wholly in the frame (edges included).
    pub fn holds(&self, o: &Frame) -> bool {
        self.min.x <= o.min.x
            && self.min.y <= o.min.y
            && o.max.x <= self.max.x
            && o.max.y <= self.max.y
    }

    /// The distance from the frame to the point `p` (0 inside).
    pub fn distance_to(&self, p: Point) -> f64 {
        let dx = (self.min.x - p.x).max(p.x - self.max.x).max(0.0);
        let dy = (self.min.y - p.y).max(p.y - self.max.y).max(0.0);
        dx.hypot(dy)
    }

    /// The part of an infinite line inside the frame (in the order of its
    /// direction), or `None`; a line touching a corner gives that point
    /// twice.
    pub fn clip_line(&self, line: &Line) -> Option<(Point, Point)> {
        let (p, d) = (line.point(), line.direction());
        let (t0, t1) = self.slab(p, d)?;
        Some((p + d * t0, p + d * t1))
    }

    /// The part of the ray from `origin` along `direction` inside the
    /// frame, from its first point there; `None` if it misses the frame
    /// or points away from it. A zero or NaN direction gives `origin`
    /// twice if the frame holds it.
    pub fn clip_ray(&self, origin: Point, direction: Vector) -> Option<(Point, Point)> {
        let (t0, t1) = self.slab(origin, direction).filter(|&(_, t1)| t1 >= 0.0)?;
        let t0 = t0.max(0.0);
        Some((origin + direction * t0, origin + direction * t1))
    }

    /// The part of the segment `a b` inside the frame, from the end
    /// nearer `a`; `None` if it misses the frame. A segment of no length
    /// gives `a` twice if the frame holds it.
    pub fn clip_segment(&self, a: Point, b: Point) -> Option<(Point, Point)> {
        let ab = b - a;
        let (t0, t1) = (self.slab(a, ab)).filter(|&(t0, t1)| t1 >= 0.0 && t0 <= 1.0)?;
        Some((a + ab * t0.max(0.0), a + ab * t1.min(1.0)))
    }

    /// The parameters `t0 <= t1` at which the line `origin + t direction`
    /// enters and leaves the frame, or `None` if it misses it. On an axis
    /// where the direction is zero the line must lie between the frame's
    /// sides; where no axis gives a parameter (a zero or NaN direction, or
    /// one so small that its inverse is infinite) the answer is `(0, 0)`
    /// if the frame holds `origin`. A NaN `origin` meets nothing.
    fn slab(&self, origin: Point, direction: Vector) -> Option<(f64, f64)> {
        if origin.iter().any(|v| v.is_nan()) {
            return None;
        }
        let (mut t0, mut t1) = (-f64::MAX, f64::MAX);
        let (mut entered, mut left) = (false, false);
        let (lo, hi) = (self.min, self.max);
        for (o, d, lo, hi) in [
            (origin.x, direction.x, lo.x, hi.x),
            (origin.y, direction.y, lo.y, hi.y),
        ] {
            if d == 0.0 {
                if o < lo || o > hi {
                    return None;
                }
                continue;
            }
            let inverse = 1.0 / d;
            let a = (lo - o) * inverse;
            let b = (hi - o) * inverse;
            let (near, far) = if a > b { (b, a) } else { (a, b) };
            if near > t0 {
                t0 = near;
            }
            if far < t1 {
                t1 = far;
            }
            entered |= near >= t0;
            left |= far <= t1;
        }
        if t0 > t1 {
            None
        } else if entered && left {
            Some((t0, t1))
        } else {
            self.contains(origin).then_some((0.0, 0.0))
        }
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn nan_corners_are_refused_or_contain_nothing() {
        // Issue 9 (10): Frame::new accepted NaN.
        let nan = Point::new(f64::NAN, 0.0);
        let one = Point::new(1.0, 1.0);
        assert!(Frame::try_new(nan, one).is_none());
        assert!(Frame::try_new(Point::new(f64::INFINITY, 0.0), one).is_none());
        assert!(Frame::try_new(Point::origin(), one).is_some());
        let f = Frame::new(nan, one);
        assert!(!f.contains(Point::new(0.5, 0.5)));
    }

    use super::*;

    #[test]
    fn boxes_meet_hold_and_overlap_by_their_edges() {
        let p = Point::new;
        let a = Frame::around(p(0.0, 0.0), Vector::new(2.0, 1.0));
        assert_eq!((a.min(), a.max()), (p(-2.0, -1.0), p(2.0, 1.0)));
        let touching = Frame::new(p(2.0, 0.0), p(3.0, 5.0));
        assert!(a.meets(&touching) && touching.meets(&a));
        assert_eq!(a.overlap_area(&touching), 0.0);
        let across = Frame::new(p(1.0, 0.5), p(3.0, 5.0));
        assert_eq!(a.overlap_area(&across), 0.5);
        assert!(a.holds(&a.inflate(-0.5)) && !a.holds(&across));
        assert_eq!(a.distance_to(p(5.0, 5.0)), 5.0);
        assert_eq!(a.distance_to(p(1.0, 0.0)), 0.0);
        let e = Frame::enclosing(&[p(1.0, -3.0), p(-1.0, 4.0), p(0.0, 0.0)]).unwrap();
        assert_eq!((e.min(), e.max()), (p(-1.0, -3.0), p(1.0, 4.0)));
        assert!(Frame::enclosing(&[]).is_none());
    }

    #[test]
    fn a_box_shrunk_past_its_middle_is_empty() {
        let a = Frame::around(Point::new(0.0, 0.0), Vector::new(1.0, 1.0));
        let gone = a.inflate(-1.5);
        assert!(!gone.contains(Point::new(0.0, 0.0)));
        assert_eq!(gone.overlap_area(&a), 0.0);
        let beside = Frame::around(Point::new(0.4, 0.0), Vector::new(0.05, 2.0));
        assert!(!gone.meets(&beside));
        let missed = Frame::from_corners(Point::new(3.0, 0.0), Point::new(2.0, 1.0));
        assert!(!missed.contains(Point::new(2.5, 0.5)) && !missed.meets(&a));
    }

    #[test]
    fn a_frame_grows_to_hold_finite_points_only() {
        let mut f = Frame::new(Point::new(-1.0, -1.0), Point::new(1.0, 1.0));
        f.include(Point::new(3.0, -2.0));
        f.include(Point::new(f64::NAN, 50.0));
        f.include(Point::new(-f64::INFINITY, 0.0));
        f.include(Point::new(0.0, 0.5));
        assert_eq!(f.min(), Point::new(-1.0, -2.0));
        assert_eq!(f.max(), Point::new(3.0, 1.0));
    }

    #[test]
    fn line_is_clipped_to_frame_edges() {
        let f = Frame::new(Point::new(0.0, 0.0), Point::new(10.0, 5.0));
        let l = Line::new(Point::new(-100.0, 2.0), Vector::new(1.0, 0.0)).unwrap();
        let (a, b) = f.clip_line(&l).unwrap();
        assert_eq!((a, b), (Point::new(0.0, 2.0), Point::new(10.0, 2.0)));
        let outside = Line::new(Point::new(0.0, 7.0), Vector::new(1.0, 0.0)).unwrap();
        assert!(f.clip_line(&outside).is_none());
    }

    #[test]
    fn ray_starts_at_its_origin() {
        let f = Frame::new(Point::new(0.0, 0.0), Point::new(10.0, 10.0));
        let (a, b) = f
            .clip_ray(Point::new(5.0, 5.0), Vector::new(0.0, 1.0))
            .unwrap();
        assert_eq!((a, b), (Point::new(5.0, 5.0), Point::new(5.0, 10.0)));
        assert!(f.contains(a) && !f.contains(Point::new(11.0, 0.0)));
    }
}

/// The clips on random and degenerate inputs against what they must be:
/// the ends on the frame's sides or the segment's own, in the frame, in
/// the order of the direction. (Bit for bit against parry2d-f64's `Aabb`,
/// which clipped before, in the commit that wrote these clips.)
#[cfg(test)]
mod random {
    use super::*;

    /// A fixed recurrence of coordinates: mostly spread over ±40 about a
    /// frame of ±10, some exactly on its sides, zeros, tiny and huge.
    fn numbers() -> impl FnMut() -> f64 {
        let mut seed = 0x2545_f491_4f6c_dd1du64;
        move || {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            let u = (seed >> 11) as f64 / (1u64 << 53) as f64;
            match seed % 23 {
                0 => 0.0,
                1 => 10.0,
                2 => -10.0,
                3 => 1e-300 * (u - 0.5),
                _ => 80.0 * u - 40.0,
            }
        }
    }

    /// Whether `p` is in `f` grown by `by` times the rounding of the
    /// frame's size (shrunk where `by` is negative).
    fn inside(f: &Frame, p: Point, by: f64) -> bool {
        let slack = by * 1e-12 * (f.max() - f.min()).norm().max(1.0);
        let (min, max) = (f.min().map(|v| v - slack), f.max().map(|v| v + slack));
        (min.x <= max.x && min.y <= max.y) && Frame::new(min, max).contains(p)
    }

    #[test]
    fn segments_and_rays_keep_their_part_in_the_frame() {
        let mut next = numbers();
        let mut point = || Point::new(next(), next());
        let (mut met, mut missed) = (0, 0);
        for _ in 0..100_000 {
            let frame = Frame::new(point(), point());
            let (a, b) = (point(), point());
            let Some((p, q)) = frame.clip_segment(a, b) else {
                // No point of the segment (sampled) lies inside, beyond
                // rounding.
                missed += 1;
                let samples = (0..=64).map(|k| a + (b - a) * (k as f64 / 64.0));
                let inside = samples.filter(|&s| inside(&frame, s, -1.0)).count();
                assert_eq!(inside, 0, "{a} {b}");
                continue;
            };
            met += 1;
            assert!(inside(&frame, p, 1.0) && inside(&frame, q, 1.0), "{a} {b}");
            // Both ends on a b, in its order.
            let ab = b - a;
            let along = |s: Point| (s - a).dot(&ab) / ab.norm_squared().max(f64::MIN_POSITIVE);
            let (tp, tq) = (along(p), along(q));
            assert!(
                (0.0..=1.0).contains(&tp) && tp <= tq && tq <= 1.0,
                "{a} {b}"
            );
            // The ray from a along a b holds the segment's part.
            let (r0, r1) = frame.clip_ray(a, ab).expect("the ray meets the frame");
            assert!(
                along(r0) <= tp + 1e-12 && along(r1) >= tq - 1e-12,
                "{a} {b}"
            );
        }
        assert!(met > 10_000 && missed > 10_000, "{met} {missed}");
    }
}
