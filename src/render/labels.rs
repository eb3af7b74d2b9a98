//! Placing letters clear of lines and of each other: a search over
//! positions around the anchor, scored against nearby segments and boxes.

use crate::figure::PageRect;
use crate::geom::{Point, Vector};
use rstar::primitives::{GeomWithData, Rectangle};
use rstar::{AABB, RTree, RTreeObject};

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

    /// The box grown by `by` on every side.
    pub(crate) fn inflate(&self, by: f64) -> Self {
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

    /// Whether the two boxes meet, touching included (as the index's
    /// envelope query counts them).
    pub(crate) fn meets(&self, o: &Bounds) -> bool {
        self.min.x <= o.max.x
            && o.min.x <= self.max.x
            && self.min.y <= o.max.y
            && o.min.y <= self.max.y
    }

    /// Whether the point `p` lies in the box, edges included.
    pub(crate) fn holds(&self, p: Point) -> bool {
        self.min.x <= p.x && p.x <= self.max.x && self.min.y <= p.y && p.y <= self.max.y
    }

    /// The least box holding both.
    fn union(&self, o: &Bounds) -> Bounds {
        Bounds {
            min: Point::new(self.min.x.min(o.min.x), self.min.y.min(o.min.y)),
            max: Point::new(self.max.x.max(o.max.x), self.max.y.max(o.max.y)),
        }
    }

    fn contains(&self, o: &Bounds) -> bool {
        self.min.x <= o.min.x
            && self.min.y <= o.min.y
            && o.max.x <= self.max.x
            && o.max.y <= self.max.y
    }

    /// The glyphs of a label's box: the box less its [`ROOM`] (the box
    /// is measured on the ink, an italic letter's overhang included).
    fn glyphs(&self) -> Self {
        self.inflate(-ROOM)
    }

    fn inside(&self, r: &PageRect) -> bool {
        self.min.x >= r.x
            && self.min.y >= r.y
            && self.max.x <= r.x + r.width
            && self.max.y <= r.y + r.height
    }
}

/// The obstacles' counts at a moment ([`Obstacles::mark`]).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Mark {
    segments: usize,
    boxes: usize,
    pending: usize,
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
    /// Each box, and whether it is hollow ([`Obstacles::hollow`]).
    boxes: Vec<(Bounds, bool)>,
    index: RTree<Entry>,
    /// Obstacles added since the index was last built, looked at one by
    /// one.
    pending: Vec<Entry>,
    /// Weight of the segments added next (thick links cost more to cover).
    weight: f64,
}

impl Default for Obstacles {
    fn default() -> Self {
        Self {
            segments: Vec::new(),
            boxes: Vec::new(),
            index: RTree::new(),
            pending: Vec::new(),
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
            self.pending
                .push(GeomWithData::new(rectangle(a, b), Obstacle::Segment(i)));
        }
    }

    /// Puts what was added so far into the spatial index (in one bulk
    /// load when the index is empty, which builds a better tree faster
    /// than inserting one by one).
    pub fn build(&mut self) {
        let pending = std::mem::take(&mut self.pending);
        if self.index.size() == 0 {
            self.index = RTree::bulk_load(pending);
        } else {
            for entry in pending {
                self.index.insert(entry);
            }
        }
    }

    /// How many obstacles there are now, to [`Obstacles::rollback`] to.
    pub fn mark(&self) -> Mark {
        Mark {
            segments: self.segments.len(),
            boxes: self.boxes.len(),
            pending: self.pending.len(),
        }
    }

    /// Forgets what was added since `mark` was taken, if the index was not
    /// built in between.
    pub fn rollback(&mut self, mark: Mark) {
        self.segments.truncate(mark.segments);
        self.boxes.truncate(mark.boxes);
        self.pending.truncate(mark.pending);
    }

    pub fn polyline(&mut self, points: &[Point]) {
        for (&a, &b) in points.iter().zip(points.iter().skip(1)) {
            self.segment(a, b);
        }
    }

    pub fn boxed(&mut self, b: Bounds) {
        self.add_box(b, false);
    }

    /// A box no label enters save the letter of a point inside it, which
    /// keeps off its outline only (a slider block large enough to hold
    /// its pin's letter beside the pin).
    pub fn hollow(&mut self, b: Bounds) {
        let (p, q) = (b.min, b.max);
        let corners = [p, Point::new(q.x, p.y), q, Point::new(p.x, q.y), p];
        self.polyline(&corners);
        self.add_box(b, true);
    }

    fn add_box(&mut self, b: Bounds, hollow: bool) {
        if [b.min.x, b.min.y, b.max.x, b.max.y]
            .iter()
            .all(|v| v.is_finite())
        {
            let i = self.boxes.len();
            self.boxes.push((b, hollow));
            self.pending
                .push(GeomWithData::new(rectangle(b.min, b.max), Obstacle::Box(i)));
        }
    }

    /// The obstacles whose boxes meet `within`, taken out of the index
    /// once for a whole search, in the index's own order (so that the sums
    /// of [`Near::cost`] add in the order a query per candidate would);
    /// not the hollow boxes that hold `anchor`, the point of the letter
    /// looked for.
    fn near(&self, within: &Bounds, anchor: Option<Point>) -> Near<'_> {
        let env = AABB::from_corners([within.min.x, within.min.y], [within.max.x, within.max.y]);
        let bounds = |entry: &Entry| {
            let e = entry.geom().envelope();
            let (lo, hi) = (e.lower(), e.upper());
            let bounds = Bounds {
                min: Point::new(lo[0], lo[1]),
                max: Point::new(hi[0], hi[1]),
            };
            (bounds, entry.data)
        };
        let found = self
            .index
            .locate_in_envelope_intersecting(env)
            .map(bounds)
            .chain(
                self.pending
                    .iter()
                    .map(bounds)
                    .filter(|(b, _)| b.meets(within)),
            )
            .filter(|(_, o)| anchor.is_none_or(|a| !self.holds(*o, a)))
            .collect();
        Near::new(self, *within, found)
    }

    /// Whether `o` is a hollow box holding `p`.
    fn holds(&self, o: Obstacle, p: Point) -> bool {
        let Obstacle::Box(i) = o else {
            return false;
        };
        let Some(&(b, hollow)) = self.boxes.get(i) else {
            return false;
        };
        hollow && b.contains(&Bounds { min: p, max: p })
    }

    /// Length of line inside `b` plus a large weight for boxes it overlaps.
    pub fn cost(&self, b: &Bounds) -> f64 {
        self.near(b, None).cost(b)
    }
}

/// The obstacles near one label's search, with their boxes.
struct Near<'a> {
    obstacles: &'a Obstacles,
    within: Bounds,
    found: Vec<(Bounds, Obstacle)>,
    /// The box of each run of [`RUN`] obstacles of `found` (the last run
    /// perhaps shorter). The index hands out its obstacles leaf by leaf,
    /// neighbours together, so a run's box is small, and a candidate
    /// that misses it skips the run whole.
    runs: Vec<Bounds>,
    /// The box of each [`RUN`] runs, a group of `RUN`² obstacles.
    groups: Vec<Bounds>,
}

/// How many obstacles, one after another in [`Near::found`], share one
/// box of [`Near::runs`], and how many runs one of [`Near::groups`].
const RUN: usize = 8;

#[cfg(test)]
thread_local! {
    /// How many boxes the searches of this thread have compared with a
    /// candidate's: an obstacle's, a run's or a group's ([`Near::runs`],
    /// [`Near::groups`]).
    static EXAMINED: std::cell::Cell<u64> = const { std::cell::Cell::new(0) };
}

impl<'a> Near<'a> {
    fn new(obstacles: &'a Obstacles, within: Bounds, found: Vec<(Bounds, Obstacle)>) -> Self {
        let runs: Vec<Bounds> = found
            .chunks(RUN)
            .filter_map(|run| run.iter().map(|(b, _)| *b).reduce(|a, b| a.union(&b)))
            .collect();
        let groups = runs
            .chunks(RUN)
            .filter_map(|group| group.iter().copied().reduce(|a, b| a.union(&b)))
            .collect();
        Near {
            obstacles,
            within,
            found,
            runs,
            groups,
        }
    }

    /// The part that meets the horizontal band from `top` to `bottom`.
    fn band(&self, top: f64, bottom: f64) -> Near<'a> {
        let mut within = self.within;
        within.min.y = within.min.y.max(top);
        within.max.y = within.max.y.min(bottom);
        let found = self
            .found
            .iter()
            .filter(|(b, _)| b.min.y <= bottom && top <= b.max.y)
            .copied()
            .collect();
        Near::new(self.obstacles, within, found)
    }

    /// Length of line inside `b` plus a large weight for boxes it
    /// overlaps; `b` must lie within the search's bounds.
    fn cost(&self, b: &Bounds) -> f64 {
        self.cost_of(b, 0.0, f64::INFINITY)
    }

    /// Whether `b` meets a box or a line a letter may not sit on (one of
    /// weight [`OPEN`] or more: not a centre line, which opens for it).
    fn struck(&self, b: &Bounds) -> bool {
        self.cost_of(b, OPEN, f64::MIN_POSITIVE) > 0.0
    }

    /// [`Near::cost`] of the boxes and of the segments weighing at least
    /// `least`, or some sum not below `limit` once it reaches it (the
    /// terms are never negative: a caller that only asks whether the cost
    /// stays under `limit` learns it sooner).
    ///
    /// The obstacles are looked at in the order of `found`, a group and
    /// a run at a time: a group or run whose box misses `b` holds none
    /// that meets it, so the sum is the same, term by term, as one over
    /// every obstacle.
    fn cost_of(&self, b: &Bounds, least: f64, limit: f64) -> f64 {
        debug_assert!(self.within.contains(b), "{b:?} outside {:?}", self.within);
        let mut cost = 0.0;
        let groups = (self.found.chunks(RUN * RUN))
            .zip(self.runs.chunks(RUN))
            .zip(&self.groups);
        let runs = groups
            .filter(|(_, extent)| {
                #[cfg(test)]
                EXAMINED.set(EXAMINED.get() + 1);
                extent.meets(b)
            })
            .flat_map(|((found, runs), _)| found.chunks(RUN).zip(runs));
        for (run, extent) in runs {
            #[cfg(test)]
            EXAMINED.set(EXAMINED.get() + 1);
            if !extent.meets(b) {
                continue;
            }
            for (bounds, obstacle) in run {
                #[cfg(test)]
                EXAMINED.set(EXAMINED.get() + 1);
                if !bounds.meets(b) {
                    continue;
                }
                match *obstacle {
                    Obstacle::Segment(i) => {
                        let Some(&(p, q, w)) = self.obstacles.segments.get(i) else {
                            continue;
                        };
                        if w < least {
                            continue;
                        }
                        if let Some(length) = length_inside(p, q, b) {
                            cost += w * (4.0 + length);
                            if cost >= limit {
                                return cost;
                            }
                        }
                    }
                    Obstacle::Box(i) => {
                        let a = self.obstacles.boxes.get(i).map_or(0.0, |o| b.overlap(&o.0));
                        if a > 0.0 {
                            cost += 200.0 + a;
                            if cost >= limit {
                                return cost;
                            }
                        }
                    }
                }
            }
        }
        cost
    }
}

/// The length of the segment `pq` inside `b`, or `None` if it misses the
/// box; a segment that only touches the box, or a point inside it, has
/// length 0.
fn length_inside(p: Point, q: Point, b: &Bounds) -> Option<f64> {
    let d = q - p;
    span(p, d, b).map(|(t0, t1)| (t1 - t0) * d.norm())
}

/// The parameters `t0 ≤ t1` within 0..1 between which `from + t d` lies
/// in the box `b` (Liang and Barsky's clipping), if it meets it.
pub(crate) fn span(from: Point, d: Vector, b: &Bounds) -> Option<(f64, f64)> {
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for (towards, room) in [
        (-d.x, from.x - b.min.x),
        (d.x, b.max.x - from.x),
        (-d.y, from.y - b.min.y),
        (d.y, b.max.y - from.y),
    ] {
        if towards == 0.0 {
            if room < 0.0 {
                return None;
            }
        } else {
            let t = room / towards;
            if towards < 0.0 {
                t0 = t0.max(t);
            } else {
                t1 = t1.min(t);
            }
        }
    }
    (t0 <= t1).then_some((t0, t1))
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

/// The unit vectors of [`DIRECTIONS`], (cos, sin), computed once.
fn directions() -> &'static [(f64, f64); 16] {
    static UNITS: std::sync::OnceLock<[(f64, f64); 16]> = std::sync::OnceLock::new();
    UNITS.get_or_init(|| {
        DIRECTIONS.map(|deg| {
            let (sin, cos) = deg.to_radians().sin_cos();
            (cos, sin)
        })
    })
}

/// The centre of a box of half-size `half` placed near `anchor`, clear of
/// the obstacles where possible and inside `page`: first on rings of
/// sixteen directions, `gap` and more from the anchor, then, if each of
/// those is crowded, anywhere on a fine grid no farther than `reach`.
/// Where every place is crowded, one where only the room about the glyphs
/// meets something beats any where the glyphs do ([`STRUCK`]).
/// Deterministic: ties go to the earlier candidate. Returns the centre
/// and its cost: 0 where nothing is near, [`STRUCK`] or more where the
/// glyphs themselves meet something.
pub(crate) fn place(
    anchor: Point,
    half: Vector,
    gap: f64,
    reach: f64,
    obstacles: &Obstacles,
    page: &PageRect,
) -> (Point, f64) {
    // Every candidate box lies within this one (a ring's centre is at
    // most gap + 17 + half.x + half.y out, a nook's box edge at most
    // `reach`): its obstacles are looked up once.
    let [.., last_ring] = RINGS;
    let out = gap.max(reach) + last_ring + NOOK_STEP + 2.0 * (half.x + half.y);
    let within = Bounds::around(anchor, Vector::new(out, out)).inflate(CLEARANCE);
    let near = obstacles.near(&within, Some(anchor));
    // The best so far: its score (cost and distance), its cost, its centre.
    let mut best = (f64::INFINITY, f64::INFINITY, anchor);
    let consider = |near: &Near, best: &mut (f64, f64, Point), centre: Point, penalty: f64| {
        // The cost is never negative: a candidate whose penalty alone
        // reaches the best score cannot beat it.
        if penalty >= best.0 {
            return;
        }
        let b = Bounds::around(centre, half);
        // A candidate whose cost reaches this cannot beat the best.
        let limit = best.0 - penalty;
        let mut cost = near.cost_of(&b.inflate(CLEARANCE), 0.0, limit);
        if cost >= limit {
            return;
        }
        if cost > 0.0 && near.struck(&b.glyphs()) {
            // Not only the room about the glyphs is crowded: the glyphs.
            cost += STRUCK;
        }
        if !b.inside(page) {
            cost += 1e6;
        }
        if cost + penalty < best.0 {
            *best = (cost + penalty, cost, centre);
        }
    };
    let units = directions();
    for extra in RINGS {
        for (k, &(dx, dy)) in units.iter().enumerate() {
            let u = Vector::new(dx, dy);
            let reach = gap + extra + dx.abs() * half.x + dy.abs() * half.y;
            consider(
                &near,
                &mut best,
                anchor + u * reach,
                1.5 * extra + 0.05 * k as f64,
            );
        }
        if best.1 < 1.0 {
            return (best.2, best.1);
        }
    }
    // Every ring is crowded: look at every position of a fine grid within
    // `reach`, for a nook the sixteen directions miss; row by row, each
    // looking only at what crosses its band.
    for row in nooks(anchor, half, gap, reach.max(gap)) {
        let Some((_, first)) = row.first() else {
            continue;
        };
        let y = first.y;
        let band = near.band(y - half.y - CLEARANCE, y + half.y + CLEARANCE);
        for (penalty, centre) in row {
            consider(&band, &mut best, centre, penalty);
        }
    }
    (best.2, best.1)
}

/// Room a label keeps from what it avoids, page units.
const CLEARANCE: f64 = 1.0;

/// Room a label's box keeps about its glyphs on every side, page units:
/// the box less this is the ink.
pub(crate) const ROOM: f64 = 1.0;

/// The least weight of a line no letter may sit on (lighter ones open
/// for letters).
const OPEN: f64 = 1.0;

/// What a place costs more whose glyphs themselves (not only the room
/// about them) meet something: any place where only the room is crowded
/// is better.
pub(crate) const STRUCK: f64 = 1000.0;

/// Spacing of the fine grid of [`nooks`], page units.
const NOOK_STEP: f64 = 1.5;

/// Rows (top to bottom) of the centres of a fine grid around `anchor`
/// whose box (half-size `half`) keeps at least `gap` / 2 and at most
/// `reach` from the anchor, each with the penalty its distance beyond
/// `gap` earns (as in the rings).
fn nooks(
    anchor: Point,
    half: Vector,
    gap: f64,
    reach: f64,
) -> impl Iterator<Item = Vec<(f64, Point)>> {
    let (nx, ny) = (
        ((half.x + reach) / NOOK_STEP).ceil() as i32,
        ((half.y + reach) / NOOK_STEP).ceil() as i32,
    );
    (-ny..=ny).map(move |j| {
        (-nx..=nx)
            .filter_map(move |i| {
                let d = Vector::new(i as f64 * NOOK_STEP, j as f64 * NOOK_STEP);
                // Distance from the anchor to the box about anchor + d.
                let out = Vector::new((d.x.abs() - half.x).max(0.0), (d.y.abs() - half.y).max(0.0));
                let dist = out.norm();
                (dist >= 0.5 * gap && dist <= reach)
                    .then(|| (1.5 * (dist - gap).max(0.0), anchor + d))
            })
            .collect()
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
        let (c, cost) = place(
            Point::new(100.0, 100.0),
            Vector::new(5.0, 6.0),
            4.0,
            24.0,
            &o,
            &page,
        );
        let b = Bounds::around(c, Vector::new(5.0, 6.0));
        assert_eq!(o.cost(&b), 0.0, "{c:?}");
        assert_eq!(cost, 0.0);
        assert!((c - Point::new(100.0, 100.0)).norm() < 20.0);
    }

    #[test]
    fn length_inside_a_box_is_the_clipped_length() {
        let b = Bounds::around(Point::new(0.0, 0.0), Vector::new(2.0, 1.0));
        let at = |x, y| Point::new(x, y);
        let close = |got: Option<f64>, want: f64| {
            let got = got.expect("the segment meets the box");
            assert!((got - want).abs() < 1e-12, "{got} ≠ {want}");
        };
        // Across, diagonal, partly in, along an edge, missing, a point.
        close(length_inside(at(-5.0, 0.0), at(5.0, 0.0), &b), 4.0);
        close(length_inside(at(-1.0, -1.0), at(1.0, 1.0), &b), 8f64.sqrt());
        close(length_inside(at(1.0, 0.5), at(5.0, 0.5), &b), 1.0);
        close(length_inside(at(-5.0, 1.0), at(5.0, 1.0), &b), 4.0);
        close(length_inside(at(0.5, 0.5), at(0.5, 0.5), &b), 0.0);
        assert_eq!(length_inside(at(-5.0, 1.5), at(5.0, 1.5), &b), None);
        assert_eq!(length_inside(at(3.0, -3.0), at(5.0, 3.0), &b), None);
        assert_eq!(length_inside(at(-3.0, 0.0), at(-2.5, 0.0), &b), None);
    }

    #[test]
    fn a_hollow_box_takes_the_letter_of_its_own_point_only() {
        let page = PageRect::new(0.0, 0.0, 400.0, 400.0);
        let half = Vector::new(6.0, 7.0);
        let block = Bounds::around(Point::new(200.0, 200.0), Vector::new(60.0, 60.0));
        let mut o = Obstacles::default();
        o.hollow(block);
        // The point inside: its letter stays beside it, inside the block.
        let (inside, _) = place(Point::new(200.0, 200.0), half, 4.0, 22.0, &o, &page);
        assert!(block.contains(&Bounds::around(inside, half)), "{inside:?}");
        // A point outside keeps its letter out of the block.
        let (outside, _) = place(Point::new(265.0, 200.0), half, 4.0, 22.0, &o, &page);
        assert_eq!(block.overlap(&Bounds::around(outside, half)), 0.0);
    }

    #[test]
    fn labels_avoid_each_other_and_the_page_edge() {
        let mut o = Obstacles::default();
        let page = PageRect::new(0.0, 0.0, 100.0, 100.0);
        let half = Vector::new(5.0, 6.0);
        let (a, _) = place(Point::new(95.0, 5.0), half, 4.0, 24.0, &o, &page);
        assert!(Bounds::around(a, half).inside(&page));
        let mark = o.mark();
        o.boxed(Bounds::around(a, half));
        let (b, _) = place(Point::new(95.0, 5.0), half, 4.0, 24.0, &o, &page);
        assert_eq!(
            Bounds::around(a, half).overlap(&Bounds::around(b, half)),
            0.0
        );
        // Rolled back, the first label's place is free again.
        o.rollback(mark);
        assert_eq!(
            place(Point::new(95.0, 5.0), half, 4.0, 24.0, &o, &page).0,
            a
        );
    }

    #[test]
    fn a_place_whose_glyphs_meet_a_line_costs_struck() {
        // Links every 8 units across the page: no letter 16 units tall
        // fits between two.
        let mut o = Obstacles::default();
        o.set_weight(3.0);
        let p = Point::new(50.0, 50.0);
        for k in 0..=12 {
            let y = 8.0 * k as f64 + 2.0;
            o.segment(Point::new(0.0, y), Point::new(100.0, y));
        }
        o.build();
        let page = PageRect::new(0.0, 0.0, 100.0, 100.0);
        let (_, cost) = place(p, Vector::new(6.0, 8.0), 4.0, 20.0, &o, &page);
        assert!(cost >= STRUCK, "{cost}");
    }

    /// Horizontal lines every 8 units across a 100-unit page, weight 3:
    /// no letter 16 units tall fits between two, so every ring is crowded
    /// and the search goes on to the fine grid.
    fn ruled() -> Obstacles {
        let mut o = Obstacles::default();
        o.set_weight(3.0);
        for k in 0..=12 {
            let y = 8.0 * k as f64 + 2.0;
            o.segment(Point::new(0.0, y), Point::new(100.0, y));
        }
        o
    }

    /// The boxes looked at while placing one letter at (50, 50) on `o`,
    /// and where it went.
    fn examined(mut o: Obstacles) -> (u64, Point, f64) {
        o.build();
        let page = PageRect::new(0.0, 0.0, 100.0, 100.0);
        EXAMINED.set(0);
        let (at, cost) = place(
            Point::new(50.0, 50.0),
            Vector::new(6.0, 8.0),
            4.0,
            20.0,
            &o,
            &page,
        );
        (EXAMINED.get(), at, cost)
    }

    #[test]
    fn a_crowded_search_looks_at_a_far_curve_a_group_at_a_time() {
        // Two dense curves (1 200 short segments) beside the crowd, 45
        // units either side of the letter's point: inside the search's
        // square and across every row of its grid, but beside none of its
        // candidates (the grid and the rings reach 34 units).
        let (before, at, cost) = examined(ruled());
        let mut o = ruled();
        for x in [5.0, 95.0] {
            let points: Vec<Point> = (0..=600)
                .map(|k| Point::new(x + 0.01 * (k % 2) as f64, 20.0 + 0.1 * k as f64))
                .collect();
            o.polyline(&points);
        }
        let (after, at_too, cost_too) = examined(o);
        assert_eq!(
            (at, cost),
            (at_too, cost_too),
            "the curves moved the letter"
        );
        assert!(cost >= STRUCK, "the grid was not searched: {cost}");
        // Each of the search's ~1 000 costs once compared its box with
        // every segment of the curves it had (all 1 200 for a ring's
        // candidate, the 360 crossing its row for the grid's): 760 000
        // more in all. Now it compares a group's or a run's box first and
        // looks into one only where that box meets its own; the runs and
        // groups that also hold one of the crowd's long lines still meet
        // every candidate (110 000 more, measured).
        let added = after - before;
        assert!(added <= 160_000, "{added} more boxes looked at");
    }

    #[test]
    fn a_run_holds_its_obstacles_and_the_costs_are_the_sums_over_all() {
        // Segments and boxes scattered by a fixed recurrence, some huge,
        // some a point.
        let mut o = Obstacles::default();
        let mut seed = 12345u64;
        let mut next = || {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (seed >> 11) as f64 / (1u64 << 53) as f64
        };
        for k in 0..400 {
            let (x, y) = (200.0 * next() - 50.0, 200.0 * next() - 50.0);
            let size = if k % 50 == 0 { 300.0 } else { 12.0 * next() };
            if k % 3 == 0 {
                o.boxed(Bounds::around(
                    Point::new(x, y),
                    Vector::new(size, 0.5 * size),
                ));
            } else {
                o.segment(
                    Point::new(x, y),
                    Point::new(x + size * next(), y - size * next()),
                );
            }
        }
        o.build();
        let anchor = Point::new(47.3, 52.1);
        let within = Bounds::around(anchor, Vector::new(80.0, 80.0));
        let near = o.near(&within, None);
        assert_eq!(near.runs.len(), near.found.len().div_ceil(RUN));
        assert_eq!(near.groups.len(), near.runs.len().div_ceil(RUN));
        for (run, extent) in near.found.chunks(RUN).zip(&near.runs) {
            assert!(run.iter().all(|(b, _)| extent.contains(b)), "{extent:?}");
        }
        for (group, extent) in near.found.chunks(RUN * RUN).zip(&near.groups) {
            assert!(group.iter().all(|(b, _)| extent.contains(b)), "{extent:?}");
        }
        // Every cost is the sum over every obstacle, in their order.
        let mut compared = 0;
        for j in -40..=40 {
            for i in -40..=40 {
                let centre = anchor + Vector::new(1.7 * i as f64, 1.3 * j as f64);
                let b = Bounds::around(centre, Vector::new(8.0, 6.0));
                let mut sum = 0.0;
                for (bounds, obstacle) in &near.found {
                    if !bounds.meets(&b) {
                        continue;
                    }
                    sum += match *obstacle {
                        Obstacle::Segment(k) => {
                            let (p, q, w) = o.segments[k];
                            length_inside(p, q, &b).map_or(0.0, |l| w * (4.0 + l))
                        }
                        Obstacle::Box(k) => {
                            let a = b.overlap(&o.boxes[k].0);
                            if a > 0.0 { 200.0 + a } else { 0.0 }
                        }
                    };
                }
                assert_eq!(
                    near.cost_of(&b, 0.0, f64::INFINITY).to_bits(),
                    sum.to_bits()
                );
                compared += usize::from(sum > 0.0);
            }
        }
        assert!(compared > 3000, "{compared}");
    }
}
