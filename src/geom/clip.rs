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

    /// Lower-left corner.
    pub fn min(&self) -> Point {
        self.min
    }

    /// Upper-right corner.
    pub fn max(&self) -> Point {
        self.max
    }

    /// Whether `p` lies in the frame (boundary included).
    pub fn contains(&self, p: Point) -> bool {
        p.x >= self.min.x && p.x <= self.max.x && p.y >= self.min.y && p.y <= self.max.y
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
        for i in 0..2 {
            let (o, d) = (origin[i], direction[i]);
            if d == 0.0 {
                if o < self.min[i] || o > self.max[i] {
                    return None;
                }
                continue;
            }
            let inverse = 1.0 / d;
            let a = (self.min[i] - o) * inverse;
            let b = (self.max[i] - o) * inverse;
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

/// The clips against parry2d-f64's `Aabb`, which computed them before:
/// the same points, bit for bit, on random and degenerate inputs, save
/// where parry2d was wrong (a line whose point lies past the frame, a
/// segment that ends before it, a NaN point taken for one inside).
#[cfg(test)]
mod against_parry2d {
    use super::*;
    use parry2d_f64::bounding_volume::Aabb;
    use parry2d_f64::query::Ray;

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
                4 => 1e300 * (u - 0.5),
                5 => 5e-324,
                6 => f64::NAN,
                7 => f64::INFINITY,
                _ => 80.0 * u - 40.0,
            }
        }
    }

    fn bits(s: Option<(Point, Point)>) -> Option<[u64; 4]> {
        s.map(|(p, q)| [p.x, p.y, q.x, q.y].map(f64::to_bits))
    }

    fn old(s: Option<parry2d_f64::shape::Segment>) -> Option<(Point, Point)> {
        s.map(|s| (s.a, s.b))
    }

    #[test]
    fn rays_and_segments_are_clipped_as_parry2d_clipped_them() {
        let mut next = numbers();
        let mut point = || Point::new(next(), next());
        let (mut met, mut segments_ending_short) = (0, 0);
        for _ in 0..200_000 {
            let (c0, c1) = (point(), point());
            // Frames are finite (Frame::try_new refuses others).
            let Some(frame) = Frame::try_new(c0, c1) else {
                continue;
            };
            let aabb = Aabb::new(c0.inf(&c1), c0.sup(&c1));
            let (a, b) = (point(), point());
            let d = b - a;
            let ray = frame.clip_ray(a, d);
            // parry2d took a NaN point for one inside the frame and gave
            // NaN points back.
            if a.x.is_nan() || a.y.is_nan() {
                assert!(ray.is_none() && frame.clip_segment(a, b).is_none());
                continue;
            }
            assert_eq!(
                bits(ray),
                bits(old(aabb.clip_ray(&Ray::new(a, d)))),
                "{a:?} {d:?} in {c0:?} {c1:?}"
            );
            met += usize::from(ray.is_some());
            let old_segment = old(aabb.clip_segment(&a, &b));
            let segment = frame.clip_segment(a, b);
            // parry2d gave a segment ending before the frame as the piece
            // from its far end back to b.
            let short = (frame.slab(a, d)).is_some_and(|(t0, t1)| t1 >= 0.0 && t0 > 1.0);
            if short {
                segments_ending_short += 1;
                assert!(segment.is_none() && old_segment.is_some(), "{a} {b}");
            } else {
                assert_eq!(bits(segment), bits(old_segment), "{a} {b} in {c0} {c1}");
            }
        }
        assert!(
            met > 20_000 && segments_ending_short > 1_000,
            "{met} {segments_ending_short}"
        );
    }

    #[test]
    fn lines_are_clipped_as_parry2d_clipped_those_whose_point_comes_first() {
        let mut next = numbers();
        let mut point = || Point::new(next(), next());
        let (mut same, mut behind) = (0, 0);
        for _ in 0..200_000 {
            let (c0, c1) = (point(), point());
            let Some(frame) = Frame::try_new(c0, c1) else {
                continue;
            };
            let aabb = Aabb::new(c0.inf(&c1), c0.sup(&c1));
            let (p, d) = (point(), point() - Point::origin());
            let Some(line) = Line::new(p, d) else {
                continue;
            };
            let new = frame.clip_line(&line);
            let old = old(aabb.clip_line(&line.point(), &line.direction()));
            // parry2d refused a line whose frame lies behind its point.
            if let (Some(_), None) = (new, old) {
                behind += 1;
                let exit = frame.slab(p, d).map(|(_, t1)| t1);
                assert!(exit.is_some_and(|t1| t1 < 0.0), "{p} {d}");
            } else {
                same += 1;
                assert_eq!(bits(new), bits(old));
            }
        }
        assert!(same > 50_000 && behind > 1_000, "{same} {behind}");
    }
}
