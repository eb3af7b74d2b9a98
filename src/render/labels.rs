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
/// the obstacles where possible and inside `page`: first on rings of
/// sixteen directions, `gap` and more from the anchor, then, if each of
/// those is crowded, anywhere on a fine grid no farther than `reach`.
/// Deterministic: ties go to the earlier candidate.
pub(crate) fn place(
    anchor: Point,
    half: Vector,
    gap: f64,
    reach: f64,
    obstacles: &Obstacles,
    page: &PageRect,
) -> Point {
    // The best so far: its score (cost and distance), its cost, its centre.
    let mut best = (f64::INFINITY, f64::INFINITY, anchor);
    let consider = |best: &mut (f64, f64, Point), centre: Point, penalty: f64| {
        let b = Bounds::around(centre, half);
        let mut cost = obstacles.cost(&b.inflate(CLEARANCE));
        if !b.inside(page) {
            cost += 1e6;
        }
        if cost + penalty < best.0 {
            *best = (cost + penalty, cost, centre);
        }
    };
    for extra in RINGS {
        for (k, deg) in DIRECTIONS.iter().enumerate() {
            let (dy, dx) = deg.to_radians().sin_cos();
            let u = Vector::new(dx, dy);
            let reach = gap + extra + dx.abs() * half.x + dy.abs() * half.y;
            consider(&mut best, anchor + u * reach, 1.5 * extra + 0.05 * k as f64);
        }
        if best.1 < 1.0 {
            return best.2;
        }
    }
    // Every ring is crowded: look at every position of a fine grid within
    // `reach`, for a nook the sixteen directions miss.
    for (penalty, centre) in nooks(anchor, half, gap, reach.max(gap)) {
        consider(&mut best, centre, penalty);
    }
    best.2
}

/// Room a label keeps from what it avoids, page units.
const CLEARANCE: f64 = 1.0;

/// Spacing of the fine grid of [`nooks`], page units.
const NOOK_STEP: f64 = 1.5;

/// Centres of a fine grid around `anchor` whose box (half-size `half`)
/// keeps at least `gap` / 2 and at most `reach` from the anchor, each with
/// the penalty its distance beyond `gap` earns (as in the rings).
fn nooks(anchor: Point, half: Vector, gap: f64, reach: f64) -> impl Iterator<Item = (f64, Point)> {
    let (nx, ny) = (
        ((half.x + reach) / NOOK_STEP).ceil() as i32,
        ((half.y + reach) / NOOK_STEP).ceil() as i32,
    );
    (-ny..=ny).flat_map(move |j| {
        (-nx..=nx).filter_map(move |i| {
            let d = Vector::new(i as f64 * NOOK_STEP, j as f64 * NOOK_STEP);
            // Distance from the anchor to the box about anchor + d.
            let out = Vector::new((d.x.abs() - half.x).max(0.0), (d.y.abs() - half.y).max(0.0));
            let dist = out.norm();
            (dist >= 0.5 * gap && dist <= reach).then(|| (1.5 * (dist - gap).max(0.0), anchor + d))
        })
    })
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
            24.0,
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
        let a = place(Point::new(95.0, 5.0), half, 4.0, 24.0, &o, &page);
        assert!(Bounds::around(a, half).inside(&page));
        o.boxed(Bounds::around(a, half));
        let b = place(Point::new(95.0, 5.0), half, 4.0, 24.0, &o, &page);
        assert_eq!(
            Bounds::around(a, half).overlap(&Bounds::around(b, half)),
            0.0
        );
    }
}
