//! Paths of straight and cubic Bézier segments, in a panel's world
//! coordinates.

use crate::geom::Point;

/// One step of a [`Path`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum PathSegment {
    /// Start a new subpath at the point.
    MoveTo(Point),
    /// A straight line to the point.
    LineTo(Point),
    /// A cubic Bézier curve with two control points to the end point.
    CubicTo(Point, Point, Point),
    /// Close the current subpath with a straight line to its start.
    Close,
}

/// A path a figure draws, in its panel's world coordinates: subpaths of
/// lines and cubic Béziers, each starting with [`PathSegment::MoveTo`].
/// (A curve traced by the curve engine is a [`crate::diagram::TracedPath`], in
/// page coordinates, until [`crate::diagram::TracedPath::to_figure_path`] turns
/// it into one of these.)
///
/// Built through [`Path::new`] and the `move_to`, `line_to`, `cubic_to`,
/// `close` methods; a segment with a non-finite coordinate, or a drawing
/// segment before the first `move_to`, is refused at [`PathBuilder::build`], which
/// returns `None` then (never a path with NaN in it).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Path {
    segments: Vec<PathSegment>,
}

/// Collects the segments of a [`Path`].
#[derive(Debug, Clone, Default)]
pub struct PathBuilder {
    segments: Vec<PathSegment>,
    bad: bool,
}

fn finite(p: &Point) -> bool {
    p.x.is_finite() && p.y.is_finite()
}

impl Path {
    /// An empty builder.
    #[allow(clippy::new_ret_no_self)]
    pub fn new() -> PathBuilder {
        PathBuilder::default()
    }

    /// A polyline as a path (`None` for fewer than two points or a
    /// non-finite point).
    pub fn polyline(points: &[Point]) -> Option<Self> {
        let (first, rest) = points.split_first()?;
        if rest.is_empty() {
            return None;
        }
        let mut b = Path::new().move_to(*first);
        for p in rest {
            b = b.line_to(*p);
        }
        b.build()
    }

    /// The segments.
    pub fn segments(&self) -> &[PathSegment] {
        &self.segments
    }

    /// Every point the path names (ends and control points), in order.
    pub fn points(&self) -> impl Iterator<Item = Point> + '_ {
        self.segments.iter().flat_map(|s| {
            let v: Vec<Point> = match *s {
                PathSegment::MoveTo(p) | PathSegment::LineTo(p) => vec![p],
                PathSegment::CubicTo(c1, c2, p) => vec![c1, c2, p],
                PathSegment::Close => vec![],
            };
            v
        })
    }

    /// The number of cubic segments.
    pub fn cubic_count(&self) -> usize {
        self.segments
            .iter()
            .filter(|s| matches!(s, PathSegment::CubicTo(..)))
            .count()
    }
}

impl PathBuilder {
    /// Starts a subpath at `p`.
    pub fn move_to(mut self, p: Point) -> Self {
        self.bad |= !finite(&p);
        self.segments.push(PathSegment::MoveTo(p));
        self
    }

    fn started(&self) -> bool {
        !self.segments.is_empty()
    }

    /// A straight line to `p`.
    pub fn line_to(mut self, p: Point) -> Self {
        self.bad |= !finite(&p) || !self.started();
        self.segments.push(PathSegment::LineTo(p));
        self
    }

    /// A cubic Bézier through control points `c1`, `c2` to `p`.
    pub fn cubic_to(mut self, c1: Point, c2: Point, p: Point) -> Self {
        self.bad |= !(finite(&c1) && finite(&c2) && finite(&p) && self.started());
        self.segments.push(PathSegment::CubicTo(c1, c2, p));
        self
    }

    /// Closes the current subpath.
    pub fn close(mut self) -> Self {
        self.bad |= !self.started();
        self.segments.push(PathSegment::Close);
        self
    }

    /// The path; `None` if it is empty, has a non-finite point or draws
    /// before its first `move_to`.
    pub fn build(self) -> Option<Path> {
        (!self.bad && self.started()).then_some(Path {
            segments: self.segments,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn builder_refuses_nan_and_missing_start() {
        let p = Point::new(0.0, 0.0);
        assert!(Path::new().line_to(p).build().is_none());
        assert!(
            Path::new()
                .move_to(p)
                .line_to(Point::new(f64::NAN, 1.0))
                .build()
                .is_none()
        );
        assert!(Path::new().build().is_none());
        let ok = Path::new()
            .move_to(p)
            .cubic_to(p, Point::new(1.0, 1.0), Point::new(2.0, 0.0))
            .close()
            .build()
            .unwrap();
        assert_eq!(ok.cubic_count(), 1);
        assert_eq!(ok.points().count(), 4);
    }

    #[test]
    fn polyline_needs_two_points() {
        assert!(Path::polyline(&[Point::new(0.0, 0.0)]).is_none());
        let p = Path::polyline(&[Point::new(0.0, 0.0), Point::new(1.0, 0.0)]).unwrap();
        assert_eq!(p.segments().len(), 2);
    }
}
