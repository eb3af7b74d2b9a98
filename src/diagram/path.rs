//! Paths: subpaths of line and cubic Bézier segments, in page or world
//! coordinates.

use crate::figure::PageFromWorld;
use crate::geom::{Point, Vector};

/// One piece of a subpath, drawn from the end of the previous piece (or
/// the subpath's start).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Segment {
    /// A straight line to the point.
    Line(Point),
    /// A cubic Bézier with two control points and an end point.
    Cubic(Point, Point, Point),
}

impl Segment {
    /// The end point.
    pub fn end(&self) -> Point {
        match self {
            Segment::Line(p) | Segment::Cubic(_, _, p) => *p,
        }
    }

    /// The point at parameter `u` in [0, 1] of the piece that starts at
    /// `start` (Bernstein form; `u` outside [0, 1] extrapolates).
    pub fn eval(&self, start: Point, u: f64) -> Point {
        match self {
            Segment::Line(p) => start + (p - start) * u,
            Segment::Cubic(c1, c2, p) => {
                let v = 1.0 - u;
                let (b0, b1, b2, b3) = (v * v * v, 3.0 * v * v * u, 3.0 * v * u * u, u * u * u);
                Point::from(start.coords * b0 + c1.coords * b1 + c2.coords * b2 + p.coords * b3)
            }
        }
    }

    /// The derivative with respect to `u` at `u` of the piece that starts
    /// at `start`.
    pub fn derivative(&self, start: Point, u: f64) -> Vector {
        match self {
            Segment::Line(p) => p - start,
            Segment::Cubic(c1, c2, p) => {
                let v = 1.0 - u;
                ((c1 - start) * (v * v) + (c2 - c1) * (2.0 * u * v) + (p - c2) * (u * u)) * 3.0
            }
        }
    }

    /// The points that define it, after `start`.
    fn points(&self) -> impl Iterator<Item = Point> {
        let (list, n) = match *self {
            Segment::Line(p) => ([p, p, p], 1),
            Segment::Cubic(a, b, p) => ([a, b, p], 3),
        };
        list.into_iter().take(n)
    }

    fn map(&self, m: &PageFromWorld) -> Self {
        match self {
            Segment::Line(p) => Segment::Line(m.apply(*p)),
            Segment::Cubic(a, b, p) => Segment::Cubic(m.apply(*a), m.apply(*b), m.apply(*p)),
        }
    }
}

fn finite(p: &Point) -> bool {
    p.x.is_finite() && p.y.is_finite()
}

/// A connected run of segments from a start point.
#[derive(Debug, Clone, PartialEq)]
pub struct Subpath {
    start: Point,
    segments: Vec<Segment>,
}

impl Subpath {
    /// The subpath from `start` through `segments`; `None` when any point is
    /// not finite. An empty list of segments is allowed (a lone point).
    pub fn new(start: Point, segments: Vec<Segment>) -> Option<Self> {
        let ok = finite(&start)
            && segments
                .iter()
                .flat_map(Segment::points)
                .all(|p| finite(&p));
        ok.then_some(Self { start, segments })
    }

    /// Where it starts.
    pub fn start(&self) -> Point {
        self.start
    }

    /// Its segments in order.
    pub fn segments(&self) -> &[Segment] {
        &self.segments
    }

    /// Where it ends (the start when it has no segment).
    pub fn end(&self) -> Point {
        self.segments.last().map_or(self.start, Segment::end)
    }

    /// Each segment with the point it starts from.
    pub fn pieces(&self) -> impl Iterator<Item = (Point, Segment)> + '_ {
        let starts = std::iter::once(self.start).chain(self.segments.iter().map(Segment::end));
        starts.zip(self.segments.iter().copied())
    }

    pub(crate) fn push(&mut self, segment: Segment) {
        self.segments.push(segment);
    }

    pub(crate) fn starting_at(start: Point) -> Self {
        Self {
            start,
            segments: Vec::new(),
        }
    }
}

/// A list of subpaths: what a curve becomes once traced and clipped, in
/// page coordinates (or in world coordinates through
/// [`TracedPath::transform`]), each subpath a start and its segments. Not the
/// path a figure draws: that is [`crate::figure::Path`], in a panel's world
/// coordinates, which [`TracedPath::to_figure_path`] makes of this one.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct TracedPath {
    subpaths: Vec<Subpath>,
}

impl TracedPath {
    /// The path made of `subpaths`.
    pub fn new(subpaths: Vec<Subpath>) -> Self {
        Self { subpaths }
    }

    /// Its subpaths in order.
    pub fn subpaths(&self) -> &[Subpath] {
        &self.subpaths
    }

    /// The number of segments over all subpaths.
    pub fn segment_count(&self) -> usize {
        self.subpaths.iter().map(|s| s.segments.len()).sum()
    }

    /// Whether it has no segment at all (nothing would be drawn).
    pub fn is_empty(&self) -> bool {
        self.segment_count() == 0
    }

    /// The path mapped through `map`: every point and control point mapped,
    /// which maps lines and Béziers exactly (affine maps keep them). Use the
    /// inverse of a panel's page-from-world map to store a page path in world
    /// coordinates, and the map itself to bring it back. `None` when a mapped
    /// point overflows to infinity.
    pub fn transform(&self, map: &PageFromWorld) -> Option<Self> {
        let subpaths = self
            .subpaths
            .iter()
            .map(|s| {
                let segments = s.segments.iter().map(|g| g.map(map)).collect();
                Subpath::new(map.apply(s.start), segments)
            })
            .collect::<Option<Vec<_>>>()?;
        Some(Self { subpaths })
    }

    /// The figure path of this page-space path in world coordinates: each
    /// subpath a move and its segments, mapped back through `map`'s
    /// inverse; a subpath that ends where it starts (within `1e-9` page
    /// units) is closed. `None` if the path is empty or a point maps to a
    /// non-finite one.
    pub fn to_figure_path(&self, map: &PageFromWorld) -> Option<crate::figure::Path> {
        let world = self.transform(&map.inverse())?;
        let mut builder = crate::figure::Path::new();
        for (page, sub) in self.subpaths.iter().zip(world.subpaths()) {
            builder = builder.move_to(sub.start());
            for seg in sub.segments() {
                builder = match *seg {
                    Segment::Line(p) => builder.line_to(p),
                    Segment::Cubic(a, b, p) => builder.cubic_to(a, b, p),
                };
            }
            if (page.end() - page.start()).norm() <= 1e-9 && !page.segments().is_empty() {
                builder = builder.close();
            }
        }
        builder.build()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cubic_eval_hits_its_ends_and_midpoint() {
        let s = Segment::Cubic(
            Point::new(0.0, 1.0),
            Point::new(1.0, 1.0),
            Point::new(1.0, 0.0),
        );
        let start = Point::new(0.0, 0.0);
        assert_eq!(s.eval(start, 0.0), start);
        assert_eq!(s.eval(start, 1.0), Point::new(1.0, 0.0));
        // (0 + 3·0 + 3·1 + 1)/8, (0 + 3 + 3 + 0)/8
        assert_eq!(s.eval(start, 0.5), Point::new(0.5, 0.75));
    }

    #[test]
    fn cubic_derivative_at_the_ends_is_three_times_the_handles() {
        let s = Segment::Cubic(
            Point::new(1.0, 2.0),
            Point::new(3.0, 2.0),
            Point::new(4.0, 0.0),
        );
        let start = Point::new(0.0, 0.0);
        assert_eq!(s.derivative(start, 0.0), Vector::new(3.0, 6.0));
        assert_eq!(s.derivative(start, 1.0), Vector::new(3.0, -6.0));
        let line = Segment::Line(Point::new(2.0, -1.0));
        assert_eq!(line.derivative(start, 0.3), Vector::new(2.0, -1.0));
    }

    #[test]
    fn non_finite_points_are_refused() {
        assert!(Subpath::new(Point::new(f64::NAN, 0.0), vec![]).is_none());
        let bad = Segment::Line(Point::new(0.0, f64::INFINITY));
        assert!(Subpath::new(Point::origin(), vec![bad]).is_none());
    }

    #[test]
    fn transform_maps_every_point() {
        let sub = Subpath::new(
            Point::new(1.0, 2.0),
            vec![
                Segment::Line(Point::new(3.0, 4.0)),
                Segment::Cubic(
                    Point::new(5.0, 6.0),
                    Point::new(7.0, 8.0),
                    Point::new(9.0, 10.0),
                ),
            ],
        )
        .unwrap();
        let path = TracedPath::new(vec![sub]);
        let m = PageFromWorld::scale_translate(2.0, -1.0, 10.0, 0.0).unwrap();
        let mapped = path.transform(&m).unwrap();
        let s = &mapped.subpaths()[0];
        assert_eq!(s.start(), Point::new(12.0, -2.0));
        assert_eq!(s.segments()[0], Segment::Line(Point::new(16.0, -4.0)));
        assert_eq!(s.end(), Point::new(28.0, -10.0));
        assert_eq!(mapped.segment_count(), 2);
        let huge = PageFromWorld::scale_translate(1e150, 1e150, 0.0, 0.0).unwrap();
        let far = TracedPath::new(vec![Subpath::new(Point::new(1e200, 0.0), vec![]).unwrap()]);
        assert!(far.transform(&huge).is_none());
    }
}
