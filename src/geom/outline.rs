//! Whether a point lies inside a closed outline: a body drawn as a
//! polygon (the inversions' slotted bar) and the marks that must stand
//! out of it.

use super::Point;

/// Whether `p` lies inside the closed outline `outline` (its corners in
/// order, the last joined to the first) by the even-odd rule, so that a
/// concave outline (a bar bent square at its leg's foot) is read as
/// drawn. Degenerate: an outline of fewer than three corners holds no
/// point; a point on a side may be counted either way.
pub(crate) fn inside_outline(outline: &[Point], p: Point) -> bool {
    let mut inside = false;
    // Each side from its corner to the one before (the last's before the first).
    let before = outline.iter().cycle().skip(outline.len().saturating_sub(1));
    for (a, b) in outline.iter().zip(before) {
        if (a.y > p.y) != (b.y > p.y) && p.x < a.x + (b.x - a.x) * (p.y - a.y) / (b.y - a.y) {
            inside = !inside;
        }
    }
    inside && outline.len() >= 3
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pts(c: &[(f64, f64)]) -> Vec<Point> {
        c.iter().map(|&(x, y)| Point::new(x, y)).collect()
    }

    #[test]
    fn a_concave_outline_holds_its_arms_not_its_notch() {
        // An L: a bar 0..4 × 0..1 with a leg 0..1 × 1..3.
        let l = pts(&[
            (0.0, 0.0),
            (4.0, 0.0),
            (4.0, 1.0),
            (1.0, 1.0),
            (1.0, 3.0),
            (0.0, 3.0),
        ]);
        assert!(inside_outline(&l, Point::new(3.0, 0.5)));
        assert!(inside_outline(&l, Point::new(0.5, 2.5)));
        assert!(!inside_outline(&l, Point::new(3.0, 2.0)), "the notch");
        assert!(!inside_outline(&l, Point::new(5.0, 0.5)));
        assert!(!inside_outline(&l, Point::new(-1.0, 2.0)));
    }

    #[test]
    fn fewer_than_three_corners_hold_nothing() {
        assert!(!inside_outline(&[], Point::origin()));
        let two = pts(&[(0.0, 0.0), (2.0, 2.0)]);
        assert!(!inside_outline(&two, Point::new(1.0, 1.0)));
    }
}
