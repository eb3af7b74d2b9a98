//! Culling a clipped panel (a detail): what lies wholly outside its
//! rectangle is not written, since the clip would hide it anyway.

use super::symbol_sizes::ANGLE_RADIUS;
use crate::figure::{PageFromWorld, Shape};
use crate::geom::{Frame, Point, Vector};

/// Page room around the points of a symbol drawn to page sizes: pins,
/// dots and markers; arrows' heads; a right-angle mark.
const MARK: f64 = 20.0;
/// Room around a bearing's centre (its triangle, foot and hatching).
const BEARING: f64 = 30.0;
/// Room around a letter's anchor: its search reach and the letter itself.
const LETTER: f64 = 60.0;

/// Whether `shape`, mapped by `t`, may show in `rect`: its world points
/// mapped to the page, grown by what its symbol adds in page units, meet
/// the rectangle. Conservative: texts set at fixed places and notes
/// always show; a shape with a non-finite point is left to its writer.
pub(super) fn may_show(t: &PageFromWorld, rect: &Frame, shape: &Shape) -> bool {
    let square = |c: Point, r: f64| {
        [
            c + Vector::new(-r, -r),
            c + Vector::new(r, r),
            c + Vector::new(-r, r),
            c + Vector::new(r, -r),
        ]
    };
    let (points, room): (Vec<Point>, f64) = match shape {
        Shape::Path(p) => (p.points().collect(), 2.0),
        Shape::Polyline { points, .. }
        | Shape::Region { points }
        | Shape::Block { points }
        | Shape::Body { points } => (points.clone(), 2.0),
        Shape::Circle { centre, radius } | Shape::Arc { centre, radius, .. } => {
            (square(*centre, *radius).to_vec(), MARK)
        }
        Shape::Pin { centre } | Shape::Dot { centre } | Shape::Marker { centre, .. } => {
            (vec![*centre], MARK)
        }
        Shape::Bearing { centre, .. } => (vec![*centre], BEARING),
        Shape::Arrow { from, to } | Shape::Hatch { from, to, .. } => (vec![*from, *to], MARK),
        Shape::RightAngle { vertex, .. } => (vec![*vertex], MARK),
        Shape::AngleMark { vertex, .. } => (vec![*vertex], ANGLE_RADIUS + LETTER),
        Shape::Dimension {
            from, to, offset, ..
        } => (vec![*from, *to], offset.abs() + LETTER),
        Shape::Label { anchor, .. } => (vec![*anchor], LETTER),
        Shape::Text { .. } | Shape::Note { .. } => return true,
    };
    let page: Vec<Point> = points.iter().map(|p| t.apply(*p)).collect();
    let Some(&first) = page.first() else {
        return true;
    };
    if !page.iter().all(|p| p.x.is_finite() && p.y.is_finite()) {
        return true;
    }
    let (mut lo, mut hi) = (first, first);
    for p in &page {
        lo = lo.inf(p);
        hi = hi.sup(p);
    }
    lo.x - room <= rect.max().x
        && hi.x + room >= rect.min().x
        && lo.y - room <= rect.max().y
        && hi.y + room >= rect.min().y
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn what_lies_wholly_outside_is_culled_and_what_reaches_in_is_kept() {
        let t = PageFromWorld::uniform(1.0, false, Point::origin(), Point::origin()).unwrap();
        // The page rectangle about the origin, so that the map's flip of
        // y does not matter.
        let rect = Frame::from_origin_size(-50.0, -50.0, 100.0, 100.0);
        let far = Shape::Pin {
            centre: Point::new(500.0, 500.0),
        };
        assert!(!may_show(&t, &rect, &far));
        // A segment crossing the rectangle with both ends outside.
        let across = Shape::Polyline {
            points: vec![Point::new(-150.0, 0.0), Point::new(150.0, 0.0)],
            closed: false,
        };
        assert!(may_show(&t, &rect, &across));
        // A circle whose centre is outside but whose rim reaches in.
        let circle = Shape::Circle {
            centre: Point::new(-150.0, 0.0),
            radius: 120.0,
        };
        assert!(may_show(&t, &rect, &circle));
        // A pin just outside still shows its disc.
        let near = Shape::Pin {
            centre: Point::new(55.0, 0.0),
        };
        assert!(may_show(&t, &rect, &near));
    }
}
