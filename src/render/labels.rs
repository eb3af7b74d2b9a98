//! Placing letters clear of lines and of each other: a search over
//! positions around the anchor, scored against nearby segments and boxes.

use crate::figure::PageRect;
use crate::geom::{Frame, Point, Vector};
use rstar::primitives::{GeomWithData, Rectangle};
use rstar::{AABB, RTree};

/// An axis-aligned box on the page.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Bounds {
    pub min: Point,
    pub max: Point,
}

impl Bounds {
    pub fn around(centre: Point, half: Vector) -> Self {
        Self {
            min: centre - half,
            max: centre + half,
        }
    }

    fn inflate(&self, by: f64) -> Self {
        let d = Vector::new(by, by);
        Self {
            min: self.min - d,
            max: self.max + d,
        }
    }

    fn overlap(&self, o: &Bounds) -> f64 {
        let w = (self.max.x.min(o.max.x) - self.min.x.max(o.min.x)).max(0.0);
        let h = (self.max.y.min(o.max.y) - self.min.y.max(o.min.y)).max(0.0);
        w * h
    }

    fn inside(&self, r: &PageRect) -> bool {
        self.min.x >= r.x
            && self.min.y >= r.y
            && self.max.x <= r.x + r.width
            && self.max.y <= r.y + r.height
    }
}

/// One obstacle in the spatial index: a segment or a box, by its index.
type Entry = GeomWithData<Rectangle<[f64; 2]>, Obstacle>;

#[derive(Debug, Clone, Copy, PartialEq)]
enum Obstacle {
    Segment(usize),
    Box(usize),
}

/// What labels must keep clear of, in a spatial index (an R-tree), so that
/// placing each label looks only at what lies near it.
#[derive(Debug)]
pub(crate) struct Obstacles {
    segments: Vec<(Point, Point, f64)>,
    boxes: Vec<Bounds>,
    index: RTree<Entry>,
    /// Weight of the segments added next (thick links cost more to cover).
    weight: f64,
}

impl Default for Obstacles {
    fn default() -> Self {
        Self {
            segments: Vec::new(),
            boxes: Vec::new(),
            index: RTree::new(),
            weight: 1.0,
        }
    }
}

fn rectangle(a: Point, b: Point) -> Rectangle<[f64; 2]> {
    Rectangle::from_corners([a.x, a.y], [b.x, b.y])
}

impl Obstacles {
    /// Sets the weight of the segments added from now on.
    pub fn set_weight(&mut self, weight: f64) {
        self.weight = weight;
    }

    pub fn segment(&mut self, a: Point, b: Point) {
        if a.x.is_finite() && a.y.is_finite() && b.x.is_finite() && b.y.is_finite() {
            let i = self.segments.len();
            self.segments.push((a, b, self.weight));
            self.index
                .insert(GeomWithData::new(rectangle(a, b), Obstacle::Segment(i)));
        }
    }

    pub fn polyline(&mut self, points: &[Point]) {
        for w in points.windows(2) {
            self.segment(w[0], w[1]);
        }
    }

    pub fn boxed(&mut self, b: Bounds) {
        if [b.min.x, b.min.y, b.max.x, b.max.y]
            .iter()
            .all(|v| v.is_finite())
        {
            let i = self.boxes.len();
            self.boxes.push(b);
            self.index
                .insert(GeomWithData::new(rectangle(b.min, b.max), Obstacle::Box(i)));
        }
    }

    /// Length of line inside `b` plus a large weight for boxes it overlaps.
    fn cost(&self, b: &Bounds) -> f64 {
        let frame = Frame::new(b.min, b.max);
        let mut cost = 0.0;
        let near = AABB::from_corners([b.min.x, b.min.y], [b.max.x, b.max.y]);
        for entry in self.index.locate_in_envelope_intersecting(near) {
            match entry.data {
                Obstacle::Segment(i) => {
                    let (p, q, w) = self.segments[i];
                    if let Some((s, t)) = frame.clip_segment(p, q) {
                        cost += w * (4.0 + (t - s).norm());
                    }
                }
                Obstacle::Box(i) => {
                    let a = b.overlap(&self.boxes[i]);
                    if a > 0.0 {
                        cost += 200.0 + a;
                    }
                }
            }
        }
        cost
    }
}

/// How much farther than touching each ring of candidates sits, page
/// units: the last keeps a 17-unit letter within 1.5 em of its point
/// (its gap of 4 plus 17, with room for the glyphs' side bearings).
const RINGS: [f64; 5] = [0.0, 4.0, 8.0, 12.0, 17.0];

/// Directions tried, best first, in page degrees (y down): above-right,
/// right, above, above-left, left, below-right, below, below-left, then
/// the eight between.
const DIRECTIONS: [f64; 16] = [
    -45.0, 0.0, -90.0, -135.0, 180.0, 45.0, 90.0, 135.0, -22.5, -67.5, -112.5, -157.5, 157.5,
    112.5, 67.5, 22.5,
];

/// The centre of a box of half-size `half` placed near `anchor`, clear of
/// the obstacles where possible and inside `page`. Deterministic: ties go
/// to the earlier candidate.
pub(crate) fn place(
    anchor: Point,
    half: Vector,
    gap: f64,
    obstacles: &Obstacles,
    page: &PageRect,
) -> Point {
    let mut best: Option<(f64, Point)> = None;
    for (ring, extra) in RINGS.into_iter().enumerate() {
        for (k, deg) in DIRECTIONS.iter().enumerate() {
            let (dy, dx) = deg.to_radians().sin_cos();
            let u = Vector::new(dx, dy);
            let reach = gap + extra + dx.abs() * half.x + dy.abs() * half.y;
            let centre = anchor + u * reach;
            let b = Bounds::around(centre, half);
            let mut score =
                obstacles.cost(&b.inflate(1.5)) + 1.5 * ring as f64 * 4.0 + 0.05 * k as f64;
            if !b.inside(page) {
                score += 1e6;
            }
            if best.is_none_or(|(s, _)| score < s) {
                best = Some((score, centre));
            }
        }
        if best.is_some_and(|(s, _)| s < 1.0 + 6.0 * ring as f64) {
            break;
        }
    }
    best.map_or(anchor, |(_, c)| c)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn label_moves_off_a_line_through_its_anchor() {
        let mut o = Obstacles::default();
        // A horizontal line through the anchor and one going up-right.
        o.segment(Point::new(0.0, 100.0), Point::new(200.0, 100.0));
        o.segment(Point::new(100.0, 100.0), Point::new(200.0, 0.0));
        let page = PageRect::new(0.0, 0.0, 200.0, 200.0);
        let c = place(
            Point::new(100.0, 100.0),
            Vector::new(5.0, 6.0),
            4.0,
            &o,
            &page,
        );
        let b = Bounds::around(c, Vector::new(5.0, 6.0));
        assert_eq!(o.cost(&b), 0.0, "{c:?}");
        assert!((c - Point::new(100.0, 100.0)).norm() < 20.0);
    }

    #[test]
    fn labels_avoid_each_other_and_the_page_edge() {
        let mut o = Obstacles::default();
        let page = PageRect::new(0.0, 0.0, 100.0, 100.0);
        let half = Vector::new(5.0, 6.0);
        let a = place(Point::new(95.0, 5.0), half, 4.0, &o, &page);
        assert!(Bounds::around(a, half).inside(&page));
        o.boxed(Bounds::around(a, half));
        let b = place(Point::new(95.0, 5.0), half, 4.0, &o, &page);
        assert_eq!(
            Bounds::around(a, half).overlap(&Bounds::around(b, half)),
            0.0
        );
    }
}
