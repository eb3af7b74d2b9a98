//! Placing letters clear of lines and of each other: a search over
//! positions around the anchor, scored against nearby segments and boxes.

use super::line_leader::leader_to_line;
use crate::geom::{Frame, Point, Vector, crossing, segment_distance};
use std::cell::RefCell;
use std::ops::{ControlFlow, RangeInclusive};

mod grid;

use grid::{CHUNK, Grid, Shape};

/// The glyphs of a label's box: the box less its [`ROOM`] (the box is
/// measured on the ink, an italic letter's overhang included).
fn glyphs(b: &Frame) -> Frame {
    b.inflate(-ROOM)
}

/// The obstacles' counts at a moment ([`Obstacles::mark`]).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Mark {
    segments: usize,
    boxes: usize,
    pending: usize,
}

/// One obstacle: a segment or a box, by its place in
/// [`Obstacles::segments`] or [`Obstacles::boxes`].
#[derive(Debug, Clone, Copy, PartialEq)]
enum Obstacle {
    Segment(usize),
    Box(usize),
}

/// What labels must keep clear of, in a uniform grid of buckets, so that
/// each place a label tries looks only at what lies in its cells.
#[derive(Debug)]
pub(crate) struct Obstacles {
    segments: Vec<(Point, Point, f64)>,
    /// Each box, and whether it is hollow ([`Obstacles::hollow`]).
    boxes: Vec<(Frame, bool)>,
    /// Whether each box of `boxes` is a text's ([`Obstacles::text`]),
    /// which another text keeps half an em from ([`Steer::apart`]).
    texts: Vec<bool>,
    /// The obstacles built, each with its box, in the order they were
    /// added: the order in which a place's costs are added
    /// ([`Near::cost_of`]), so that a figure's placing depends on what
    /// it draws and in which order, not on how an index was loaded.
    ordered: Vec<(Frame, Obstacle)>,
    /// The obstacles of `ordered`, by their place in it, in the buckets of
    /// the cells they come within reach of: two grids, one reaching as far
    /// as three labels in four do, one as far as the largest.
    grids: [Grid; 2],
    /// Obstacles added since the grid was last built, looked at one by
    /// one.
    pending: Vec<(Frame, Obstacle)>,
    /// Weight of the segments added next (thick links cost more to cover).
    weight: f64,
    /// Which segments open for a letter once it is placed (hatching, a
    /// detail's frame), by their place in `segments`: a search weighs
    /// them as any, but a letter on them does not stay struck
    /// ([`Obstacles::lasting`]).
    opening: Vec<bool>,
    /// Whether the segments added next open for letters.
    opens: bool,
    /// Whether a letter's glyphs on a segment that opens are struck in a
    /// search ([`Obstacles::set_openings_strike`]).
    openings_strike: bool,
}

impl Default for Obstacles {
    fn default() -> Self {
        Self {
            segments: Vec::new(),
            boxes: Vec::new(),
            texts: Vec::new(),
            ordered: Vec::new(),
            grids: [Grid::default(), Grid::default()],
            pending: Vec::new(),
            weight: 1.0,
            opening: Vec::new(),
            opens: false,
            openings_strike: true,
        }
    }
}

/// The box of the segment `a b` (or of a box's corners).
fn rectangle(a: Point, b: Point) -> Frame {
    Frame::from_corners(a.inf(&b), a.sup(&b))
}

impl Obstacles {
    /// Sets the weight of the segments added from now on.
    pub fn set_weight(&mut self, weight: f64) {
        self.weight = weight;
    }

    /// Sets whether the segments added from now on open for a letter
    /// placed on them (a hatching's strokes, a detail's frame, written
    /// again with a gap once the labels are placed): a search weighs them
    /// as any, but a letter whose glyphs meet only such lines does not
    /// stay struck ([`Obstacles::lasting`]).
    pub fn set_opens(&mut self, opens: bool) {
        self.opens = opens;
    }

    /// Sets whether the searches from now on take a letter whose glyphs
    /// meet a line that opens ([`Obstacles::set_opens`]) for struck
    /// ([`STRUCK`]), as they do at first: a letter keeps off hatching
    /// where it can. A placing that leaves some letter crossed anyway is
    /// tried once more without, so that such a letter goes onto the
    /// hatching rather than a line that stays.
    pub fn set_openings_strike(&mut self, strike: bool) {
        self.openings_strike = strike;
    }

    /// Whether the glyphs of a label's box `b`, the letter of the point
    /// `anchor`, meet what stays where the label is written: a box (a
    /// part, another label) or a line of weight [`OPEN`] or more that
    /// does not open for letters ([`Obstacles::set_opens`]). A placing
    /// whose struck labels sit only on hatching or a detail's frame
    /// leaves none crossed once written.
    pub fn lasting(&self, b: &Frame, anchor: Point) -> bool {
        let glyphs = glyphs(b);
        let mut near = self.near(&glyphs, Some(anchor));
        near.openings = false;
        near.cost_of(&glyphs, OPEN, f64::MIN_POSITIVE) > 0.0
    }

    /// Whether the segment from `a` to `b` (a leader) runs along a line
    /// drawn that a letter may not sit on (weight [`OPEN`] or more): at
    /// less than [`ALONG_ANGLE`] to it, within [`ALONG_NEAR`] of it over
    /// a part of its length, where a reader would take the two for one.
    pub fn runs_along(&self, a: Point, b: Point) -> bool {
        let Some(u) = (b - a).try_normalize(0.0) else {
            return false;
        };
        (self.segments.iter()).any(|&(p, q, w)| {
            let Some(v) = (q - p).try_normalize(0.0) else {
                return false;
            };
            let sine = (u.x * v.y - u.y * v.x).abs();
            // The leader's points, by quarters, near the line's segment.
            let near = (0..=4)
                .map(|k| a + (b - a) * (f64::from(k) / 4.0))
                .filter(|&m| crate::geom::point_segment_distance(m, p, q) < ALONG_NEAR)
                .count();
            w >= OPEN && sine < ALONG_ANGLE.sin() && near >= 2
        })
    }

    /// The lines a letter's way back to its point `anchor` may not cross
    /// ([`crosses_back`]): those of weight [`LINK`] or more (links, guides,
    /// forces) that meet `within` and do not open for letters, less the
    /// outline of a box that holds the anchor (a slider block about its
    /// pin, which any letter outside it crosses).
    fn thick_near(&self, within: &Frame, anchor: Point) -> Vec<Segment> {
        let on_edge = |f: &Frame, q: Point| {
            let (lo, hi) = (f.min(), f.max());
            f.inflate(0.5).contains(q)
                && [q.x - lo.x, hi.x - q.x, q.y - lo.y, hi.y - q.y]
                    .iter()
                    .any(|d| d.abs() < 0.5)
        };
        let holding: Vec<&Frame> = (self.boxes.iter())
            .map(|(f, _)| f)
            .filter(|f| f.contains(anchor))
            .collect();
        (self.segments.iter().zip(&self.opening))
            .filter(|((p, q, w), opens)| {
                *w >= LINK
                    && !**opens
                    && rectangle(*p, *q).meets(within)
                    && !holding.iter().any(|f| on_edge(f, *p) && on_edge(f, *q))
            })
            .map(|(&(p, q, _), _)| (p, q))
            .collect()
    }

    /// Whether the segment from `a` to `b` (a leader) crosses a line
    /// drawn that a letter may not sit on (weight [`OPEN`] or more).
    pub fn crosses_a_line(&self, a: Point, b: Point) -> bool {
        (self.segments.iter()).any(|&(p, q, w)| w >= OPEN && crossing(a, b, p, q).is_some())
    }

    /// Whether `b` meets the box of a text ([`Obstacles::text`]).
    pub fn meets_a_text(&self, b: &Frame) -> bool {
        (self.boxes.iter().zip(&self.texts)).any(|((t, _), &text)| text && b.overlap_area(t) > 0.0)
    }

    /// Whether the segment from `a` to `b` passes through a box (a label
    /// placed, a part, a point's marker) that does not hold `anchor`.
    pub fn crosses_a_box(&self, a: Point, b: Point, anchor: Point) -> bool {
        let at = Frame::from_corners(anchor, anchor);
        (self.boxes.iter()).any(|(bx, _)| !bx.holds(&at) && span(a, b - a, bx).is_some())
    }

    pub fn segment(&mut self, a: Point, b: Point) {
        if a.x.is_finite() && a.y.is_finite() && b.x.is_finite() && b.y.is_finite() {
            let i = self.segments.len();
            self.segments.push((a, b, self.weight));
            self.opening.push(self.opens);
            self.pending.push((rectangle(a, b), Obstacle::Segment(i)));
        }
    }

    /// Lists what was added so far after what was built before, in the
    /// order added. Beyond [`FEW`]
    /// obstacles (an animation's frame with its curves) it puts them, in
    /// that order, into a grid over `region`, where the labels will go
    /// (what lies beyond it falls in the grid's edge cells), for labels
    /// whose boxes' half-sizes are `halves`: each place a label tries
    /// looks in one bucket of one of two grids (a label larger than
    /// [`MOST_REACH`], in a few). Up to [`FEW`], each label gathers the
    /// obstacles near it once ([`Obstacles::near`]).
    pub fn build(&mut self, region: &Frame, halves: &[Vector]) {
        self.ordered.append(&mut self.pending);
        let reach = |q: usize| {
            let most = Vector::new(quantile(halves, q, 0), quantile(halves, q, 1));
            (most + Vector::new(CLEARANCE, CLEARANCE)).inf(&MOST_REACH)
        };
        // A few obstacles are looked through without a grid ([`FEW`]).
        self.grids = if self.ordered.len() <= FEW {
            [Grid::default(), Grid::default()]
        } else {
            let shapes: Vec<Shape> = (self.ordered.iter())
                .map(|&(b, o)| match o {
                    Obstacle::Segment(i) => self
                        .segments
                        .get(i)
                        .map_or(Shape::Box(b), |&(p, q, _)| Shape::Segment(p, q)),
                    Obstacle::Box(_) => Shape::Box(b),
                })
                .collect();
            [
                Grid::new(region, reach(3), &shapes),
                Grid::new(region, reach(4), &shapes),
            ]
        };
    }

    /// How many obstacles there are now, to [`Obstacles::rollback`] to.
    pub fn mark(&self) -> Mark {
        Mark {
            segments: self.segments.len(),
            boxes: self.boxes.len(),
            pending: self.pending.len(),
        }
    }

    /// Forgets what was added since `mark` was taken, if the grid was not
    /// built in between.
    pub fn rollback(&mut self, mark: Mark) {
        self.segments.truncate(mark.segments);
        self.opening.truncate(mark.segments);
        self.boxes.truncate(mark.boxes);
        self.texts.truncate(mark.boxes);
        self.pending.truncate(mark.pending);
    }

    pub fn polyline(&mut self, points: &[Point]) {
        for (&a, &b) in points.iter().zip(points.iter().skip(1)) {
            self.segment(a, b);
        }
    }

    pub fn boxed(&mut self, b: Frame) {
        self.add_box(b, false, false);
    }

    /// The box of a text written (a label placed, a note's line, a
    /// dimension's value): a box as [`Obstacles::boxed`], which another
    /// text's place also keeps [`Steer::apart`] from, lest the two read
    /// as one run ("LG", "B F").
    pub fn text(&mut self, b: Frame) {
        self.add_box(b, false, true);
    }

    /// A box no label enters save the letter of a point inside it, which
    /// keeps off its outline only (a slider block large enough to hold
    /// its pin's letter beside the pin).
    pub fn hollow(&mut self, b: Frame) {
        let (p, q) = (b.min(), b.max());
        let corners = [p, Point::new(q.x, p.y), q, Point::new(p.x, q.y), p];
        self.polyline(&corners);
        self.add_box(b, true, false);
    }

    fn add_box(&mut self, b: Frame, hollow: bool, text: bool) {
        if [b.min().x, b.min().y, b.max().x, b.max().y]
            .iter()
            .all(|v| v.is_finite())
        {
            let i = self.boxes.len();
            self.boxes.push((b, hollow));
            self.texts.push(text);
            self.pending
                .push((rectangle(b.min(), b.max()), Obstacle::Box(i)));
        }
    }

    /// What a search about `anchor` looks at: the grid, asked about each
    /// candidate's box on its own, and the obstacles added since it was
    /// built (the labels placed so far) that meet `within`; not the
    /// hollow boxes that hold `anchor`, the point of the letter looked
    /// for.
    fn near(&self, within: &Frame, anchor: Option<Point>) -> Near<'_> {
        let pending = (self.pending.iter())
            .copied()
            .filter(|(b, o)| b.meets(within) && anchor.is_none_or(|a| !self.holds(*o, a)))
            .collect();
        // Few obstacles: those near the label, gathered once for all its
        // places, in the grid's order (the same sums, term by term).
        let found = (self.ordered.len() <= FEW).then(|| {
            (self.ordered.iter())
                .filter(|(b, o)| b.meets(within) && anchor.is_none_or(|a| !self.holds(*o, a)))
                .copied()
                .collect()
        });
        Near {
            obstacles: self,
            openings: self.openings_strike,
            within: *within,
            anchor,
            found,
            pending,
            hits: RefCell::new(Vec::new()),
            marks: RefCell::new(vec![0; self.ordered.len().div_ceil(64)]),
        }
    }

    /// The grid of least reach that reaches as far as `b` from its centre
    /// (else the other).
    fn grid(&self, b: &Frame) -> &Grid {
        let [narrow, wide] = &self.grids;
        let half = 0.5 * (b.max() - b.min()).abs();
        let reach = narrow.reach();
        if half.x <= reach.x && half.y <= reach.y {
            narrow
        } else {
            wide
        }
    }

    /// Whether `o` is a hollow box holding `p`.
    fn holds(&self, o: Obstacle, p: Point) -> bool {
        let Obstacle::Box(i) = o else {
            return false;
        };
        let Some(&(b, hollow)) = self.boxes.get(i) else {
            return false;
        };
        hollow && b.contains(p)
    }

    /// Length of line inside `b` plus a large weight for boxes it overlaps.
    pub fn cost(&self, b: &Frame) -> f64 {
        self.near(b, None).cost(b)
    }
}

/// The `q` quarter (0 to 4) of the coordinates `axis` (0 or 1) of
/// `halves`: 4 is the largest, 0 if none.
fn quantile(halves: &[Vector], q: usize, axis: usize) -> f64 {
    let mut v: Vec<f64> = halves.iter().map(|h| h[axis]).collect();
    v.sort_by(f64::total_cmp);
    let at = (v.len() * q / 4).min(v.len().saturating_sub(1));
    v.get(at).copied().unwrap_or(0.0)
}

/// One label's search: the grid, and the few obstacles added since it was
/// built that lie near the label.
struct Near<'a> {
    obstacles: &'a Obstacles,
    /// Whether the lines that open for letters strike a letter's glyphs
    /// as any (a search, at first), or not (a test of what stays under
    /// it, [`Obstacles::lasting`]); their cost counts either way.
    openings: bool,
    /// The box every candidate of the search lies in.
    within: Frame,
    /// The point of the letter looked for, whose hollow box it may enter.
    anchor: Option<Point>,
    /// Where the grid holds no more than [`FEW`] obstacles, those of
    /// them that meet `within`, less the hollow boxes that hold the
    /// anchor, in the grid's order: each place tried looks through these
    /// instead of the grid's buckets.
    found: Option<Vec<(Frame, Obstacle)>>,
    /// The obstacles added since the grid was built that meet `within`,
    /// in the order they were added.
    pending: Vec<(Frame, Obstacle)>,
    /// The obstacles of the grid that meet one candidate, by their place
    /// in [`Obstacles::ordered`], in that order (room kept from one
    /// candidate to the next).
    hits: RefCell<Vec<u32>>,
    /// A bit for each obstacle of the grid, set while the buckets of a
    /// candidate that covers several cells are looked through (an
    /// obstacle may lie in more than one), and cleared as they are read
    /// off in order.
    marks: RefCell<Vec<u64>>,
}

#[cfg(test)]
thread_local! {
    /// How many boxes the searches of this thread have compared with a
    /// candidate's: an obstacle's from the grid's buckets or one added
    /// since.
    static EXAMINED: std::cell::Cell<u64> = const { std::cell::Cell::new(0) };
}

impl Near<'_> {
    /// The search narrowed to `band`, a box within its own: the obstacles
    /// gathered that meet `band`, in the same order, so that the cost of
    /// a box within `band` is the same sum, term by term, over fewer
    /// looked at (a row of [`nooks`]). Unchanged where the obstacles are
    /// looked up in the grid (more than [`FEW`]).
    fn narrowed(&self, band: &Frame) -> Self {
        let meeting = |list: &[(Frame, Obstacle)]| -> Vec<(Frame, Obstacle)> {
            (list.iter())
                .filter(|(b, _)| b.meets(band))
                .copied()
                .collect()
        };
        Near {
            obstacles: self.obstacles,
            openings: self.openings,
            within: match self.found {
                Some(_) => Frame::from_corners(
                    self.within.min().sup(&band.min()),
                    self.within.max().inf(&band.max()),
                ),
                None => self.within,
            },
            anchor: self.anchor,
            found: self.found.as_deref().map(meeting),
            pending: meeting(&self.pending),
            hits: RefCell::new(Vec::new()),
            marks: RefCell::new(self.marks.borrow().clone()),
        }
    }

    /// Length of line inside `b` plus a large weight for boxes it
    /// overlaps; `b` must lie within the search's bounds.
    fn cost(&self, b: &Frame) -> f64 {
        self.cost_of(b, 0.0, f64::INFINITY)
    }

    /// Whether `b` meets a box or a line a letter may not sit on (one of
    /// weight [`OPEN`] or more: not a centre line, which opens for it).
    fn struck(&self, b: &Frame) -> bool {
        self.cost_of(b, OPEN, f64::MIN_POSITIVE) > 0.0
    }

    /// [`Near::cost`] of the boxes and of the segments weighing at least
    /// `least`, or some sum not below `limit` once it reaches it (the
    /// terms are never negative: a caller that only asks whether the cost
    /// stays under `limit` learns it sooner).
    ///
    /// Only the obstacles in the buckets that hold all that meets `b` are
    /// looked at (one bucket of the grid that reaches as far as `b`, else
    /// a few, [`Grid::cover`]), in the order added, then those added
    /// since, in the order added: the sum is the same, term by term, as
    /// one over every obstacle whose box meets `b` in the order added.
    fn cost_of(&self, b: &Frame, least: f64, limit: f64) -> f64 {
        self.sum(b, limit, |o| self.term(o, b, least))
    }

    /// What the texts whose boxes meet `b` (a place's box grown by
    /// [`Steer::apart`]) add to its cost: [`TOO_NEAR`] and the area
    /// shared each, or some sum not below `limit` once it reaches it.
    fn crowding(&self, b: &Frame, limit: f64) -> f64 {
        self.sum(b, limit, |o| match o {
            Obstacle::Box(i) if self.obstacles.texts.get(i) == Some(&true) => {
                let a = (self.obstacles.boxes.get(i)).map_or(0.0, |t| b.overlap_area(&t.0));
                (a > 0.0).then_some(TOO_NEAR + a)
            }
            _ => None,
        })
    }

    /// The sum of `term` over the obstacles whose boxes meet `b`, in the
    /// order of [`Near::cost_of`], or some sum not below `limit` once it
    /// reaches it.
    fn sum(&self, b: &Frame, limit: f64, term: impl Fn(Obstacle) -> Option<f64>) -> f64 {
        debug_assert!(self.within.holds(b), "{b:?} outside {:?}", self.within);
        let mut cost = 0.0;
        // Adds what an obstacle costs; breaks off once the sum reaches
        // the limit.
        let mut add = |&(_, o): &(Frame, Obstacle)| {
            if self.anchor.is_none_or(|a| !self.obstacles.holds(o, a))
                && let Some(term) = term(o)
            {
                cost += term;
                if cost >= limit {
                    return ControlFlow::Break(());
                }
            }
            ControlFlow::Continue(())
        };
        let flow = match &self.found {
            Some(found) => (found.iter())
                .filter(|(bounds, _)| {
                    #[cfg(test)]
                    EXAMINED.set(EXAMINED.get() + 1);
                    bounds.meets(b)
                })
                .try_for_each(&mut add),
            None => self.in_grid(b, &mut add),
        };
        if flow.is_continue() {
            let pending = self.pending.iter().filter(|(bounds, _)| {
                #[cfg(test)]
                EXAMINED.set(EXAMINED.get() + 1);
                bounds.meets(b)
            });
            let _ = pending.into_iter().try_for_each(&mut add);
        }
        cost
    }

    /// Calls `add` with each obstacle of the grid whose box meets `b`, in
    /// the grid's order, until it breaks off: from the one bucket that
    /// holds all that meets `b`, else from the few `b` covers.
    fn in_grid(
        &self,
        b: &Frame,
        add: &mut impl FnMut(&(Frame, Obstacle)) -> ControlFlow<()>,
    ) -> ControlFlow<()> {
        let ordered = &self.obstacles.ordered;
        let grid = self.obstacles.grid(b);
        let (rows, columns) = grid.cover(b);
        if rows.start() == rows.end() && columns.start() == columns.end() {
            self.look(grid, rows, columns, b, |n| {
                ordered
                    .get(n as usize)
                    .map_or(ControlFlow::Continue(()), &mut *add)
            })
        } else {
            let mut hits = self.hits.borrow_mut();
            self.marked(grid, rows, columns, b, &mut hits);
            (hits.iter())
                .filter_map(|&n| ordered.get(n as usize))
                .try_for_each(add)
        }
    }

    /// The obstacles of the grid's buckets in `rows` and `columns` whose
    /// boxes meet `b`, each once, by their place in
    /// [`Obstacles::ordered`], in that order, into `hits` (emptied first),
    /// through [`Near::marks`] (an obstacle may be in more than one).
    fn marked(
        &self,
        grid: &Grid,
        rows: RangeInclusive<usize>,
        columns: RangeInclusive<usize>,
        b: &Frame,
        hits: &mut Vec<u32>,
    ) {
        hits.clear();
        let mut marks = self.marks.borrow_mut();
        let (mut first, mut last) = (usize::MAX, 0);
        let _ = self.look(grid, rows, columns, b, |n| {
            let word = n as usize / 64;
            if let Some(bits) = marks.get_mut(word) {
                *bits |= 1 << (n % 64);
                (first, last) = (first.min(word), last.max(word));
            }
            ControlFlow::Continue(())
        });
        for word in first..=last {
            let Some(bits) = marks.get_mut(word) else {
                break;
            };
            let mut left = std::mem::take(bits);
            while left != 0 {
                let bit = left.trailing_zeros();
                left &= left - 1;
                hits.push(word as u32 * 64 + bit);
            }
        }
    }

    /// Calls `found` with each obstacle of the grid's buckets in `rows`
    /// and `columns` whose box meets `b`, bucket by bucket, each in its
    /// order, skipping whole every run whose box misses `b`, until `found`
    /// breaks off.
    fn look(
        &self,
        grid: &Grid,
        rows: RangeInclusive<usize>,
        columns: RangeInclusive<usize>,
        b: &Frame,
        mut found: impl FnMut(u32) -> ControlFlow<()>,
    ) -> ControlFlow<()> {
        let ordered = &self.obstacles.ordered;
        let meets = |extent: &Frame| {
            #[cfg(test)]
            EXAMINED.set(EXAMINED.get() + 1);
            extent.meets(b)
        };
        for (row, column) in rows.flat_map(|row| columns.clone().map(move |c| (row, c))) {
            let (items, runs, groups) = grid.bucket(row, column);
            let groups = (items.chunks(CHUNK * CHUNK).zip(runs.chunks(CHUNK))).zip(groups);
            for ((items, runs), _) in groups.filter(|(_, extent)| meets(extent)) {
                for (run, _) in items.chunks(CHUNK).zip(runs).filter(|(_, e)| meets(e)) {
                    for &n in run {
                        if ordered.get(n as usize).is_some_and(|(o, _)| meets(o)) {
                            found(n)?;
                        }
                    }
                }
            }
        }
        ControlFlow::Continue(())
    }

    /// What `obstacle`, whose box meets `b`, adds to the cost of `b`: a
    /// segment weighing at least `least` (where that is [`OPEN`] or more,
    /// not one that opens for letters if they strike none, [`Near::openings`]),
    /// its weight times 4 plus its
    /// length inside; a box, 200 plus the area shared. `None` where it
    /// adds nothing.
    fn term(&self, obstacle: Obstacle, b: &Frame, least: f64) -> Option<f64> {
        match obstacle {
            Obstacle::Segment(i) => {
                let &(p, q, w) = self.obstacles.segments.get(i)?;
                let opens = self.obstacles.opening.get(i).copied().unwrap_or(false);
                if w < least || (opens && least >= OPEN && !self.openings) {
                    return None;
                }
                length_inside(p, q, b).map(|length| w * (4.0 + length))
            }
            Obstacle::Box(i) => {
                let a = self
                    .obstacles
                    .boxes
                    .get(i)
                    .map_or(0.0, |o| b.overlap_area(&o.0));
                (a > 0.0).then_some(200.0 + a)
            }
        }
    }
}

/// The length of the segment `pq` inside `b`, or `None` if it misses the
/// box; a segment that only touches the box, or a point inside it, has
/// length 0.
fn length_inside(p: Point, q: Point, b: &Frame) -> Option<f64> {
    let d = q - p;
    span(p, d, b).map(|(t0, t1)| (t1 - t0) * d.norm())
}

/// The parameters `t0 ≤ t1` within 0..1 between which `from + t d` lies
/// in the box `b` (Liang and Barsky's clipping), if it meets it.
pub(crate) fn span(from: Point, d: Vector, b: &Frame) -> Option<(f64, f64)> {
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for (towards, room) in [
        (-d.x, from.x - b.min().x),
        (d.x, b.max().x - from.x),
        (-d.y, from.y - b.min().y),
        (d.y, b.max().y - from.y),
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
#[cfg(test)]
pub(crate) fn place(
    anchor: Point,
    half: Vector,
    gap: f64,
    reach: f64,
    obstacles: &Obstacles,
    page: &Frame,
) -> (Point, f64) {
    place_toward(anchor, half, gap, reach, Steer::default(), obstacles, page)
}

/// A straight piece of a line on the page, from one end to the other.
pub(crate) type Segment = (Point, Point);

/// An angle's sector on the page: the wedge between its two legs, which
/// its letter's middle keeps within ([`Steer::wedge`]), read as the
/// angle between them and no other.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Wedge {
    /// The angle's vertex.
    pub vertex: Point,
    /// The unit page direction of the angle's middle (its bisector).
    pub middle: Vector,
    /// Half the angle's size, radians.
    pub half: f64,
}

impl Wedge {
    /// Whether the page point `p` lies within the wedge, its direction
    /// from the vertex within [`Wedge::half`] of the bisector.
    pub fn holds(&self, p: Point) -> bool {
        (p - self.vertex)
            .try_normalize(0.0)
            .is_some_and(|u| u.dot(&self.middle) >= self.half.min(std::f64::consts::PI).cos())
    }
}

/// What steers a letter's place besides what it keeps clear of.
#[derive(Debug, Default, Clone, Copy)]
pub(crate) struct Steer<'a> {
    /// The unit page direction tried first (an angle's bisector).
    pub toward: Option<Vector>,
    /// The other lettered points a place should not stand nearer to than
    /// to its own ([`AMBIGUOUS`]); empty for a label that names no point
    /// or where no other point is near.
    pub others: &'a [Point],
    /// The distance (page units, the letter's em) within which another
    /// point is read with the anchor as a pair: the nearer it is, the
    /// more nearer it a letter may stand ([`nearer_another`]); 0 for
    /// none.
    pub pair: f64,
    /// The page line a text names and the other links, which a place
    /// should not stand nearer to than to the line ([`AMBIGUOUS`]).
    pub line: Option<(Segment, &'a [Segment])>,
    /// The dimension lines a text naming a line keeps nearer its own
    /// line than, at a lesser cost ([`MISREAD`]) than another link's.
    pub dimensions: &'a [Segment],
    /// The sides of the block a letter names and the links, which a place
    /// should not stand nearer to than to the block ([`AMBIGUOUS`]):
    /// a block's letter nearer a link names the link. `None` for any
    /// other label.
    pub block: Option<(&'a [Segment], &'a [Segment])>,
    /// The line a leader from the place runs to, the other links and the
    /// dimension lines: a place nearer another link than its line, whose
    /// leader ([`leader_to_line`]) would cross a link, a dimension line or
    /// a box, or that stands too near the line to have one, costs
    /// [`STRUCK`] more; `None` where no leader is drawn.
    pub led: Option<(Segment, &'a [Segment], &'a [Segment])>,
    /// Whether `toward` is a preference only (a point's letter set away
    /// from a point near it), not a side to keep to (an angle's
    /// bisector): beyond its first ring a place along it competes with
    /// the places of the same ring in every direction, and a nearer place
    /// on another side wins. At l = 1.54 r, e = −0.464 r, 0° inversion 3's
    /// n, 17 units below a′_d, was lettered 20 units farther down along
    /// the way from a′_d, across the side o′c′, while a place beside it
    /// to its left was clear.
    pub near_first: bool,
    /// The room (page units) a place's box keeps from any text's box
    /// ([`Obstacles::text`]), half the label's em: two labels of
    /// different things nearer than that read as one run ("LG", "O T",
    /// "ω ×40"). A place within it costs [`TOO_NEAR`] more and the area
    /// shared; 0 for none.
    pub apart: f64,
    /// The farthest (page units) a place on the rings may stand from
    /// the anchor, box to anchor, if any: a point's letter, read with its
    /// point within 1.5 em. A wide letter ("*A*, *D*", a joint letter of
    /// points that coincide) tried on a diagonal stands farther out than
    /// a narrow one on the same ring; it is drawn in to this.
    pub farthest: Option<f64>,
    /// Whether the place is a point's letter read with its point along
    /// the straight way back to it, which should cross no link, guide or
    /// other point ([`crosses_back`]).
    pub back: bool,
    /// Whether the text is a joint letter of the points under one pin,
    /// the pin's own name first ("*B*, *F*, *E*, *H*"): it stands by its
    /// pin only where its head is, so a place whose head stands farther
    /// from the anchor than its tail (the letter to the left of the pin,
    /// run along the rod away from it) costs [`HEAD_AWAY`] more.
    pub head_first: bool,
    /// The sector of the angle a letter names, if any: a place whose
    /// middle lies outside it is not taken (there it reads as the
    /// neighbouring angle's), and one whose way back to its point of
    /// the arc crosses a link or a force beyond [`PIN_CLEAR`] costs
    /// [`ACROSS`] more (θ beyond the rod from its arc, read as the
    /// angle between the rod and the force beside it).
    pub wedge: Option<Wedge>,
}

/// What a joint letter's place costs more where its head (the pin's own
/// name) stands farther from the pin than its tail ([`Steer::head_first`]):
/// as much as a place misread, so that a clear place at the pin's other
/// side or over it wins at any ring, and one whose glyphs meet a line
/// does not. Kisch's "B, F, E, H" at l = 43.1 r, 89.44° ran along the rod
/// to the left of B, its B four names away from the pin.
const HEAD_AWAY: f64 = MISREAD;

/// How far (page units) left of its anchor a joint letter's middle may
/// stand before its head counts as farther from it than its tail.
const HEAD_SLACK: f64 = 1.0;

/// The place along the unit page `u` from `anchor`, `out` units out to
/// the centre of a box of half-size `half`, drawn in towards the anchor
/// until the box stands no farther than `farthest` from it.
fn drawn_in(anchor: Point, u: Vector, out: f64, half: Vector, farthest: Option<f64>) -> Point {
    let apart = |t: f64| {
        let (x, y) = ((t * u.x).abs() - half.x, (t * u.y).abs() - half.y);
        x.max(0.0).hypot(y.max(0.0))
    };
    let Some(most) = farthest.filter(|m| apart(out) > *m) else {
        return anchor + u * out;
    };
    // The distance grows with t: halve the span down to a hundredth of
    // a unit.
    let (mut lo, mut hi) = (0.0, out);
    while hi - lo > 0.01 {
        let mid = 0.5 * (lo + hi);
        if apart(mid) > most {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    anchor + u * lo
}

/// The number of `thick` lines and `others` points met by the way back
/// from the middle of the glyphs `b` to their point `anchor`: its part
/// outside the glyphs and beyond the pin about the anchor ([`PIN_CLEAR`]).
/// Across a link, a guide or another point, a reader pairs the letter
/// with what lies on the other side: the "A" below a lower guide, the
/// "C" nearer G's dot than its pin.
fn crosses_back(b: &Frame, anchor: Point, thick: &[Segment], others: &[Point]) -> usize {
    let centre = nalgebra::center(&b.min(), &b.max());
    let d = centre - anchor;
    let length = d.norm();
    if length <= PIN_CLEAR {
        return 0;
    }
    // Where the way enters the glyphs, from the anchor.
    let enter = span(anchor, d, b).map_or(1.0, |(t0, _)| t0);
    let from = anchor + d * (PIN_CLEAR / length);
    let to = anchor + d * enter;
    if (to - anchor).norm() <= PIN_CLEAR {
        return 0;
    }
    let lines = (thick.iter())
        .filter(|&&(p, q)| crossing(from, to, p, q).is_some())
        .count();
    let points = (others.iter())
        .filter(|&&q| crate::geom::point_segment_distance(q, from, to) < DOT_CLEAR)
        .count();
    lines + points
}

/// How far (page units) from its point the way back to it is looked at
/// ([`crosses_back`]): past the pin's circle (4.2) and its line.
const PIN_CLEAR: f64 = 5.0;

/// How near (page units) the way back passes another point to meet it:
/// its dot's radius (2.1) and a little more.
const DOT_CLEAR: f64 = 2.5;

/// The least weight of a line drawn as a link, a guide or a force.
const LINK: f64 = 3.0;

/// What a place costs more whose way back to its point crosses more
/// links, guides and other points than the fewest any first-ring place
/// does ([`crosses_back`]): half a struck letter's, as a text misread
/// ([`MISREAD`]), so that any place whose way back is clear and whose
/// glyphs are clear beats it, and it still beats one whose glyphs are
/// struck (at 1.0 [`STRUCK`] C's letter of inversion 2 at l = 3 r went
/// onto the frame's line, its way back from the one clear place lying
/// across the frame).
const ACROSS: f64 = MISREAD;

/// How much nearer (page units) another point may be to a letter's box
/// (its glyphs and the room about them) than its own before the letter
/// reads as the other's: 2, a unit inside the 3 a reader (and the plate
/// check, on the glyphs alone) allows, for the room and the corners.
pub(crate) const NEARER: f64 = 2.0;

/// What a place costs more whose box stands nearer another lettered
/// point than its own by more than [`NEARER`]: as much as glyphs struck
/// ([`STRUCK`]), a letter read as another point's being as wrong as one
/// crossed out; so such a letter is placed again first, as a struck one
/// is, and any clear place within reach beats it.
const AMBIGUOUS: f64 = STRUCK;

/// What a place costs more whose box, naming a line, stands nearer a
/// dimension line than its own line: half a struck letter's, so that any
/// place nearer another link costs more (that one names the wrong link;
/// this one reads as the dimension's value beside its own).
pub(crate) const MISREAD: f64 = 0.5 * STRUCK;

/// Whether `b` stands nearer one of `others` than `anchor` by more than
/// [`NEARER`], and by more than that and the share of `pair` the two
/// points are closer than it: two points an em apart or more are told
/// apart by the letters' [`NEARER`] alone, two a few units apart read as
/// a pair whose letters may stand on either side, but not with the other
/// point between a letter and its own (A's letter beyond the O dot
/// beside it); two that coincide take their letters anywhere about them.
fn nearer_another(b: &Frame, anchor: Point, others: &[Point], pair: f64) -> bool {
    let own = b.distance_to(anchor);
    others.iter().any(|&q| {
        let slack = NEARER + (pair - (q - anchor).norm()).max(0.0);
        b.distance_to(q) + slack < own
    })
}

/// What a place costs more whose middle stands nearer another point
/// than its own ([`over_the_other`]; where [`nearer_another`] reads it as
/// the other's, on top of [`AMBIGUOUS`]): as much as glyphs struck
/// ([`STRUCK`]), so that any clear place whose nearest point is its own
/// is taken first, farther out if need be; only where none is clear may
/// a letter stand over another point, and then with a leader to its own. Ng's "O, M" between O and
/// P at a short rod's inner dead centre, taken at the first place tried
/// for half a unit more, read as P's letter.
const OTHER_SIDE: f64 = STRUCK;

/// Whether the centre of `b` is nearer one of `others` (not coinciding
/// with `anchor`) than `anchor`.
pub(crate) fn over_the_other(b: &Frame, anchor: Point, others: &[Point]) -> bool {
    let centre = nalgebra::center(&b.min(), &b.max());
    let own = (centre - anchor).norm();
    (others.iter()).any(|&q| (q - anchor).norm() > 1.0 && (centre - q).norm() < own)
}

/// What a place costs more whose box stands nearer another point than
/// its own at all, however little ([`box_nearer_another`]): a ring's
/// step and more, so that a place as clear on the same ring or the next
/// whose nearest point is its own wins, and none is shut for it. At
/// l = 1.08 r, 170° Fig. 64's E′ over the guide stood 0.7 unit nearer E″,
/// 14 units from it, than E′.
const BOX_NEARER: f64 = 10.0;

/// Whether the box `b` stands nearer one of `others` (not coinciding
/// with `anchor`) than `anchor`, box to point, as a reader measures it.
pub(crate) fn box_nearer_another(b: &Frame, anchor: Point, others: &[Point]) -> bool {
    let own = b.distance_to(anchor);
    (others.iter()).any(|&q| (q - anchor).norm() > 1.0 && b.distance_to(q) < own)
}

/// Whether `b` stands less than [`LINE_NEARER`] nearer the line `own`
/// than one of the `rivals` (links), or not beside `own` at all: its centre
/// beyond the line's middle [`BESIDE`] share, by an end that other lines
/// meet at (a text there is read with the joint).
fn nearer_another_line(b: &Frame, own: Segment, rivals: &[Segment]) -> bool {
    let (p, q) = own;
    let centre = nalgebra::center(&b.min(), &b.max());
    let t = (centre - p).dot(&(q - p)) / (q - p).norm_squared();
    if !(BESIDE.0..=BESIDE.1).contains(&t) {
        return true;
    }
    nearer_a_rival(b, own, rivals)
}

/// Whether `b` stands less than [`LINE_NEARER`] nearer the line `own`
/// than one of the `rivals`, wherever along it.
pub(crate) fn nearer_a_rival(b: &Frame, own: Segment, rivals: &[Segment]) -> bool {
    nearer_a_rival_than(b, &[own], rivals)
}

/// Whether `b` stands less than [`LINE_NEARER`] nearer the nearest of
/// the lines `own` (a block's sides) than one of the `rivals`.
fn nearer_a_rival_than(b: &Frame, own: &[Segment], rivals: &[Segment]) -> bool {
    let distance = |&(p, q): &(Point, Point)| {
        if b.contains(p) || b.contains(q) {
            return 0.0;
        }
        let (c0, c1) = (b.min(), b.max());
        let (c2, c3) = (
            Point::new(b.max().x, b.min().y),
            Point::new(b.min().x, b.max().y),
        );
        [(c0, c2), (c2, c1), (c1, c3), (c3, c0)]
            .into_iter()
            .map(|(u, v)| segment_distance(u, v, p, q))
            .fold(f64::INFINITY, f64::min)
    };
    let mine = own.iter().map(distance).fold(f64::INFINITY, f64::min);
    rivals.iter().any(|r| distance(r) < mine + LINE_NEARER)
}

/// How much nearer (page units) a text naming a line stands to it than
/// to any other link: a unit, the box's room, so that the glyphs alone
/// are never nearer another link.
const LINE_NEARER: f64 = 1.0;

/// The share of its line (from its first end) beside which a text
/// naming the line stands.
const BESIDE: (f64, f64) = (0.1, 0.9);

/// [`place`], trying first the unit page direction `toward` (an angle's
/// bisector: its letter beyond its arc, inside the angle) at each ring
/// out to the last, before the sixteen directions: a letter that fits
/// somewhere along it goes there rather than to another side.
pub(crate) fn place_toward(
    anchor: Point,
    half: Vector,
    gap: f64,
    reach: f64,
    steer: Steer<'_>,
    obstacles: &Obstacles,
    page: &Frame,
) -> (Point, f64) {
    let Steer {
        toward,
        others,
        pair,
        line,
        dimensions,
        block,
        led,
        near_first,
        farthest,
        apart,
        back,
        head_first,
        wedge,
    } = steer;
    // Every candidate box lies within this one (a ring's centre is at
    // most gap + 17 + half.x + half.y out, a nook's box edge at most
    // `reach`): the labels placed so far are sorted out once.
    let [.., last_ring] = RINGS;
    let out = gap.max(reach) + last_ring + NOOK_STEP + 2.0 * (half.x + half.y) + apart;
    let within = Frame::around(anchor, Vector::new(out, out)).inflate(CLEARANCE);
    let near = obstacles.near(&within, Some(anchor));
    let others: Vec<Point> = (others.iter())
        .filter(|&&q| within.contains(q) && q != anchor)
        .copied()
        .collect();
    // The lines the way back to the point should not cross, and the
    // fewest any first-ring place crosses (a pin inside a closed outline
    // crosses it every way).
    let thick = match back || wedge.is_some() {
        true => obstacles.thick_near(&within, anchor),
        false => Vec::new(),
    };
    let fewest = match back {
        true => (directions().iter())
            .map(|&(dx, dy)| {
                let u = Vector::new(dx, dy);
                let reach = gap + dx.abs() * half.x + dy.abs() * half.y;
                let at = drawn_in(anchor, u, reach, half, farthest);
                crosses_back(&glyphs(&Frame::around(at, half)), anchor, &thick, &others)
            })
            .min()
            .unwrap_or(0),
        false => 0,
    };
    // The best so far: its score (cost and distance), its cost, its centre.
    let mut best = (f64::INFINITY, f64::INFINITY, anchor);
    let consider = |near: &Near, best: &mut (f64, f64, Point), centre: Point, penalty: f64| {
        if wedge.is_some_and(|w| !w.holds(centre)) {
            return;
        }
        let penalty = match head_first && centre.x < anchor.x - HEAD_SLACK {
            true => penalty + HEAD_AWAY,
            false => penalty,
        };
        // The cost is never negative: a candidate whose penalty alone
        // reaches the best score cannot beat it.
        if penalty >= best.0 {
            return;
        }
        let b = Frame::around(centre, half);
        // A candidate whose cost reaches this cannot beat the best.
        let limit = best.0 - penalty;
        let mut cost = near.cost_of(&b.inflate(CLEARANCE), 0.0, limit);
        if cost >= limit {
            return;
        }
        if cost > 0.0 && near.struck(&glyphs(&b)) {
            // Not only the room about the glyphs is crowded: the glyphs.
            cost += STRUCK;
        }
        if apart > 0.0 {
            cost += near.crowding(&b.inflate(apart), limit - cost);
            if cost >= limit {
                return;
            }
        }
        if !page.holds(&b) {
            cost += 1e6;
        }
        if nearer_another(&b, anchor, &others, pair)
            || line.is_some_and(|(own, rivals)| nearer_another_line(&b, own, rivals))
            || block.is_some_and(|(own, rivals)| nearer_a_rival_than(&b, own, rivals))
        {
            cost += AMBIGUOUS;
        } else if line.is_some_and(|(own, _)| nearer_another_line(&b, own, dimensions)) {
            cost += MISREAD;
        }
        // On top of [`AMBIGUOUS`]: a place read as another's is worse
        // than one merely over another point of a pair.
        if over_the_other(&b, anchor, &others) {
            cost += OTHER_SIDE;
        } else if box_nearer_another(&b, anchor, &others) {
            cost += BOX_NEARER;
        }
        if back && crosses_back(&glyphs(&b), anchor, &thick, &others) > fewest {
            cost += ACROSS;
        }
        if wedge.is_some() && crosses_back(&glyphs(&b), anchor, &thick, &[]) > 0 {
            cost += ACROSS;
        }
        if let Some((own, links, dimensions)) = led {
            // Led, it still stands nearer its own line than another link.
            let crosses = |(from, to): (Point, Point)| {
                (links.iter().chain(dimensions)).any(|&(p, q)| crossing(from, to, p, q).is_some())
                    || obstacles.crosses_a_box(from, to, to)
            };
            let clear = !nearer_a_rival(&b, own, links)
                && leader_to_line(&b, own).is_some_and(|l| !crosses(l));
            if !clear {
                cost += STRUCK;
            }
        }
        if cost + penalty < best.0 {
            *best = (cost + penalty, cost, centre);
        }
    };
    if let Some(u) = toward {
        for (k, extra) in RINGS.into_iter().enumerate() {
            let reach = gap + extra + u.x.abs() * half.x + u.y.abs() * half.y;
            let penalty = match near_first {
                true => 1.5 * extra + 0.05 * k as f64,
                false => 0.05 * k as f64,
            };
            let at = drawn_in(anchor, u, reach, half, farthest);
            consider(&near, &mut best, at, penalty);
            if best.1 < 1.0 && (!near_first || k == 0) {
                return (best.2, best.1);
            }
        }
    }
    let units = directions();
    for (ring, extra) in RINGS.into_iter().enumerate() {
        for (k, &(dx, dy)) in units.iter().enumerate() {
            let u = Vector::new(dx, dy);
            let reach = gap + extra + dx.abs() * half.x + dy.abs() * half.y;
            consider(
                &near,
                &mut best,
                drawn_in(anchor, u, reach, half, farthest),
                1.5 * extra + 0.05 * k as f64,
            );
        }
        // A preferred place farther out (near_first) waits for the rings
        // whose places could still beat it.
        let next = RINGS.get(ring + 1).map_or(f64::INFINITY, |e| 1.5 * e);
        if best.1 < 1.0 && (!near_first || best.0 < next) {
            return (best.2, best.1);
        }
    }
    // Every ring is crowded: look at every position of a fine grid within
    // `reach`, for a nook the sixteen directions miss, row by row, each
    // row looking only at what meets its band of the page.
    let mut row: Option<(f64, Near)> = None;
    for (penalty, centre) in nooks(anchor, half, gap, reach.max(gap)) {
        if penalty >= best.0 {
            continue;
        }
        if row.as_ref().is_none_or(|(y, _)| *y != centre.y) {
            // A unit more than a candidate's room, against rounding.
            let reach = Vector::new(0.0, half.y + 2.0 * CLEARANCE + apart);
            let band = Frame::from_corners(
                Point::new(within.min().x, centre.y) - reach,
                Point::new(within.max().x, centre.y) + reach,
            );
            row = Some((centre.y, near.narrowed(&band)));
        }
        if let Some((_, near)) = &row {
            consider(near, &mut best, centre, penalty);
        }
    }
    (best.2, best.1)
}

/// The most a grid's reach may be ([`Obstacles::build`]), page units:
/// larger labels look in more than one bucket.
const MOST_REACH: Vector = Vector::new(64.0, 64.0);

/// Room a label keeps from what it avoids, page units.
pub(crate) const CLEARANCE: f64 = 1.0;

/// Up to this many obstacles, each label gathers those near it once and
/// its places look through them ([`Obstacles::near`]); beyond, each place
/// looks in the grid's buckets. A mechanism figure has 100 to 320, an
/// animation's frame with its whole-turn curves thousands.
const FEW: usize = 1024;

/// Room a label's box keeps about its glyphs on every side, page units:
/// the box less this is the ink.
pub(crate) const ROOM: f64 = 1.0;

/// The least weight of a line no letter may sit on (lighter ones open
/// for letters).
const OPEN: f64 = 1.0;

/// The angle (radians) under which a leader is taken to run along a
/// line ([`Obstacles::runs_along`]): 10°.
const ALONG_ANGLE: f64 = std::f64::consts::PI / 18.0;

/// How near (page units) a leader's points stand to a line it runs
/// along ([`Obstacles::runs_along`]): a thick link's half-width and the
/// leader's, with a unit between.
const ALONG_NEAR: f64 = 3.0;

/// What a place costs more whose glyphs themselves (not only the room
/// about them) meet something: any place where only the room is crowded
/// is better.
pub(crate) const STRUCK: f64 = 1000.0;

/// What a place costs more whose box, grown by [`Steer::apart`], meets
/// another text's: as much as a box in its room, so that a place half
/// an em clear of the other labels beats one beside a line or a ring
/// farther out, and any whose glyphs are clear beats one struck.
pub(crate) const TOO_NEAR: f64 = 200.0;

/// Spacing of the fine grid of [`nooks`], page units.
const NOOK_STEP: f64 = 1.5;

/// The centres, row by row from the top, of a fine grid around `anchor`
/// whose box (half-size `half`) keeps at least `gap` / 2 and at most
/// `reach` from the anchor, each with the penalty its distance beyond
/// `gap` earns (as in the rings).
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
        let page = Frame::from_origin_size(0.0, 0.0, 200.0, 200.0);
        let (c, cost) = place(
            Point::new(100.0, 100.0),
            Vector::new(5.0, 6.0),
            4.0,
            24.0,
            &o,
            &page,
        );
        let b = Frame::around(c, Vector::new(5.0, 6.0));
        assert_eq!(o.cost(&b), 0.0, "{c:?}");
        assert_eq!(cost, 0.0);
        assert!((c - Point::new(100.0, 100.0)).norm() < 20.0);
    }

    #[test]
    fn length_inside_a_box_is_the_clipped_length() {
        let b = Frame::around(Point::new(0.0, 0.0), Vector::new(2.0, 1.0));
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
        let page = Frame::from_origin_size(0.0, 0.0, 400.0, 400.0);
        let half = Vector::new(6.0, 7.0);
        let block = Frame::around(Point::new(200.0, 200.0), Vector::new(60.0, 60.0));
        let mut o = Obstacles::default();
        o.hollow(block);
        // The point inside: its letter stays beside it, inside the block.
        let (inside, _) = place(Point::new(200.0, 200.0), half, 4.0, 22.0, &o, &page);
        assert!(block.holds(&Frame::around(inside, half)), "{inside:?}");
        // A point outside keeps its letter out of the block.
        let (outside, _) = place(Point::new(265.0, 200.0), half, 4.0, 22.0, &o, &page);
        assert_eq!(block.overlap_area(&Frame::around(outside, half)), 0.0);
    }

    #[test]
    fn a_letter_keeps_nearer_its_own_point_than_another() {
        let page = Frame::from_origin_size(0.0, 0.0, 200.0, 200.0);
        let (half, own) = (Vector::new(6.0, 7.0), Point::new(100.0, 100.0));
        // Another point 18 units above-right, where the first direction
        // tried (above-right) would put the letter.
        let other = Point::new(113.0, 87.0);
        let o = Obstacles::default();
        let free = place(own, half, 4.0, 22.0, &o, &page).0;
        assert!(nearer_another(
            &Frame::around(free, half),
            own,
            &[other],
            0.0
        ));
        let steer = Steer {
            others: &[other],
            ..Steer::default()
        };
        let (at, cost) = place_toward(own, half, 4.0, 22.0, steer, &o, &page);
        let b = Frame::around(at, half);
        assert!(!nearer_another(&b, own, &[other], 0.0), "{at:?}");
        assert_eq!(cost, 0.0);
        assert!(b.distance_to(own) <= 22.0);
    }

    #[test]
    fn a_letter_of_a_pair_never_has_the_other_point_between_it_and_its_own() {
        let (half, own) = (Vector::new(6.0, 7.0), Point::new(100.0, 100.0));
        let em = 17.0;
        // O's dot 13 units left of A's pin: read with it as a pair.
        let other = Point::new(87.0, 100.0);
        let box_at = |x: f64, y: f64| Frame::around(Point::new(x, y), half);
        // Beyond O from A: the reader takes O's dot for A.
        assert!(nearer_another(&box_at(73.0, 100.0), own, &[other], em));
        // Above the pair, or on A's side: the pair's letters.
        assert!(!nearer_another(&box_at(93.0, 84.0), own, &[other], em));
        assert!(!nearer_another(&box_at(114.0, 100.0), own, &[other], em));
        // Two points that coincide take their letters anywhere about them.
        let at_own = Point::new(100.5, 100.0);
        assert!(!nearer_another(&box_at(80.0, 100.0), own, &[at_own], em));
        // Above the pair nearer O: a pair's letter, not a lone point's.
        assert!(!nearer_another(&box_at(85.0, 84.0), own, &[other], em));
        assert!(nearer_another(&box_at(85.0, 84.0), own, &[other], 0.0));
    }

    #[test]
    fn a_text_naming_a_line_keeps_nearer_it_than_a_dimension_line() {
        // The rod along y = 0 and, a letter's height from it, x's
        // dimension line: "l = 1.63 r" set between them is x's value.
        let rod = (Point::new(0.0, 0.0), Point::new(100.0, 0.0));
        let dimension = (Point::new(0.0, -16.0), Point::new(100.0, -16.0));
        let half = Vector::new(10.0, 5.0);
        let (o, page) = (
            Obstacles::default(),
            Frame::from_origin_size(-100.0, -100.0, 300.0, 200.0),
        );
        let at = |dimensions: &[Segment]| {
            let steer = Steer {
                line: Some((rod, &[])),
                dimensions,
                ..Steer::default()
            };
            let (centre, _) =
                place_toward(Point::new(50.0, 0.0), half, 3.0, 20.0, steer, &o, &page);
            Frame::around(centre, half)
        };
        // Blind to the dimension, the first place tried is by it.
        assert!(nearer_another_line(&at(&[]), rod, &[dimension]));
        let b = at(&[dimension]);
        assert!(!nearer_another_line(&b, rod, &[dimension]), "{b:?}");
    }

    #[test]
    fn a_text_naming_a_line_stands_beside_it_and_nearer_it_than_another_link() {
        // The rod from (0, 0) to (100, 0), the crank from there to
        // (100, 30).
        let rod = (Point::new(0.0, 0.0), Point::new(100.0, 0.0));
        let crank = [(Point::new(100.0, 0.0), Point::new(100.0, 30.0))];
        let half = Vector::new(10.0, 5.0);
        let at = |x: f64, y: f64| Frame::around(Point::new(x, y), half);
        assert!(!nearer_another_line(&at(50.0, 10.0), rod, &crank));
        assert!(
            nearer_another_line(&at(85.0, 15.0), rod, &crank),
            "nearer the crank"
        );
        assert!(
            nearer_another_line(&at(104.0, -10.0), rod, &crank),
            "beyond the rod's end, by the joint"
        );
        // Steered by it, a place by the joint goes beside the rod.
        let o = Obstacles::default();
        let page = Frame::from_origin_size(0.0, 0.0, 300.0, 200.0);
        let steer = Steer {
            line: Some((rod, &crank)),
            ..Steer::default()
        };
        let (centre, cost) = place_toward(Point::new(96.0, 0.0), half, 3.0, 20.0, steer, &o, &page);
        assert!(cost < 1.0, "{centre:?} {cost}");
        assert!(!nearer_another_line(
            &Frame::around(centre, half),
            rod,
            &crank
        ));
    }

    #[test]
    fn a_segment_crossing_a_box_is_told_from_one_beside_it() {
        let mut o = Obstacles::default();
        o.boxed(Frame::around(Point::new(50.0, 50.0), Vector::new(5.0, 5.0)));
        let a = Point::new(0.0, 50.0);
        let far = Point::new(200.0, 0.0);
        assert!(o.crosses_a_box(a, Point::new(100.0, 50.0), far));
        assert!(!o.crosses_a_box(a, Point::new(100.0, 70.0), far));
        // A box holding the anchor (its own marker) is not in the way.
        assert!(!o.crosses_a_box(a, Point::new(100.0, 50.0), Point::new(52.0, 50.0)));
    }

    #[test]
    fn labels_avoid_each_other_and_the_page_edge() {
        let mut o = Obstacles::default();
        let page = Frame::from_origin_size(0.0, 0.0, 100.0, 100.0);
        let half = Vector::new(5.0, 6.0);
        let (a, _) = place(Point::new(95.0, 5.0), half, 4.0, 24.0, &o, &page);
        assert!(page.holds(&Frame::around(a, half)));
        let mark = o.mark();
        o.boxed(Frame::around(a, half));
        let (b, _) = place(Point::new(95.0, 5.0), half, 4.0, 24.0, &o, &page);
        assert_eq!(
            Frame::around(a, half).overlap_area(&Frame::around(b, half)),
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
        let page = Frame::from_origin_size(0.0, 0.0, 100.0, 100.0);
        o.build(&page, &[Vector::new(6.0, 8.0)]);
        let (_, cost) = place(p, Vector::new(6.0, 8.0), 4.0, 20.0, &o, &page);
        assert!(cost >= STRUCK, "{cost}");
    }

    #[test]
    fn a_letter_on_a_line_that_opens_does_not_stay_struck() {
        // Hatching (weight 3, opening) across the top, a link across the
        // bottom: a letter on either is struck while placed, but only the
        // link stays under it once written.
        let mut o = Obstacles::default();
        o.set_weight(3.0);
        o.set_opens(true);
        o.segment(Point::new(0.0, 20.0), Point::new(100.0, 20.0));
        o.set_opens(false);
        o.segment(Point::new(0.0, 80.0), Point::new(100.0, 80.0));
        o.build(
            &Frame::from_origin_size(0.0, 0.0, 100.0, 100.0),
            &[Vector::new(6.0, 8.0)],
        );
        let half = Vector::new(6.0, 8.0);
        let (top, bottom) = (Point::new(50.0, 20.0), Point::new(50.0, 80.0));
        let near = o.near(&Frame::around(top, Vector::new(20.0, 20.0)), Some(top));
        assert!(near.struck(&glyphs(&Frame::around(top, half))));
        assert!(!o.lasting(&Frame::around(top, half), top));
        assert!(o.lasting(&Frame::around(bottom, half), bottom));
        // Clear of both, nothing stays.
        let free = Point::new(50.0, 50.0);
        assert!(!o.lasting(&Frame::around(free, half), free));
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
        let page = Frame::from_origin_size(0.0, 0.0, 100.0, 100.0);
        o.build(&page, &[Vector::new(6.0, 8.0)]);
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

    /// Two dense curves (1 200 short segments) 45 units either side of
    /// the letter's point at (50, 50): beside none of the search's
    /// candidates (the grid and the rings reach 34 units).
    fn curves(o: &mut Obstacles, points: usize) {
        for x in [5.0, 95.0] {
            let points: Vec<Point> = (0..=points)
                .map(|k| {
                    Point::new(
                        x + 0.01 * (k % 2) as f64,
                        20.0 + 60.0 * k as f64 / points as f64,
                    )
                })
                .collect();
            o.polyline(&points);
        }
    }

    #[test]
    fn a_crowded_search_never_looks_into_a_far_curve() {
        let (alone, at, cost) = examined(ruled());
        let mut o = ruled();
        curves(&mut o, 600);
        let (beside, at_too, cost_too) = examined(o);
        assert_eq!(
            (at, cost),
            (at_too, cost_too),
            "the curves moved the letter"
        );
        assert!(cost >= STRUCK, "the grid was not searched: {cost}");
        // Each of the search's ~1 000 costs once compared its box with
        // every segment of the curves (760 000 more comparisons in all);
        // then with the boxes of runs of eight and groups of 64 segments
        // in the R-tree's order, the runs and groups that also held one of
        // the crowd's long lines meeting every candidate (119 776 in all,
        // 9 103 without the curves, measured). Now each candidate looks
        // in the one bucket of its centre's cell, which holds the crowd's
        // lines within reach and nothing of the curves (9 057 in all,
        // 13 510 without the curves, whose grid has larger cells).
        assert!(beside <= 12_000, "{beside} boxes looked at ({alone} alone)");
    }

    #[test]
    fn eight_times_the_far_obstacles_cost_a_crowded_search_next_to_nothing() {
        let count = |points| {
            let mut o = ruled();
            curves(&mut o, points);
            examined(o).0
        };
        // 119 776 and 207 913 with runs and groups (1.74 times); 9 057
        // and 9 112 in the grid.
        let (few, many) = (count(600), count(4800));
        assert!(10 * many <= 11 * few, "{few} then {many}");
    }

    #[test]
    fn every_cost_is_the_sum_over_every_obstacle_near_in_the_order_added() {
        // Segments and boxes scattered by a fixed recurrence, some huge,
        // some a point, some hollow; the last fifty added after the grid
        // was built (as labels are).
        let mut o = Obstacles::default();
        let mut seed = 12345u64;
        let mut next = || {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (seed >> 11) as f64 / (1u64 << 53) as f64
        };
        for k in 0..450 {
            if k == 400 {
                // A region smaller than the scatter: what lies beyond
                // falls in the grid's edge cells.
                o.build(
                    &Frame::from_origin_size(0.0, 0.0, 100.0, 100.0),
                    &[
                        Vector::new(3.0, 4.0),
                        Vector::new(1.0, 2.0),
                        Vector::new(2.0, 1.0),
                    ],
                );
            }
            let (x, y) = (200.0 * next() - 50.0, 200.0 * next() - 50.0);
            let size = if k % 50 == 0 { 300.0 } else { 12.0 * next() };
            let b = Frame::around(Point::new(x, y), Vector::new(size, 0.5 * size));
            match k % 7 {
                0 | 3 => o.boxed(b),
                5 => o.hollow(b),
                _ => o.segment(
                    Point::new(x, y),
                    Point::new(x + size * next(), y - size * next()),
                ),
            }
        }
        let anchor = Point::new(47.3, 52.1);
        let within = Frame::around(anchor, Vector::new(80.0, 80.0));
        let near = o.near(&within, Some(anchor));
        // What a search looked at before the grid: every obstacle
        // meeting its bounds, in the order added; not the hollow boxes
        // holding its point.
        let all: Vec<(Frame, Obstacle)> = (o.ordered.iter().chain(o.pending.iter()))
            .copied()
            .filter(|(b, ob)| b.meets(&within) && !o.holds(*ob, anchor))
            .collect();
        assert!(all.len() < o.segments.len() + o.boxes.len(), "none held");
        let (mut compared, mut narrowed) = (0, 0);
        // Boxes reaching farther than the grid's reach and not.
        for half in [Vector::new(8.0, 6.0), Vector::new(2.5, 3.5)] {
            for j in -40..=40 {
                // The search narrowed to the row's band (as the nooks'
                // rows are): the same sums over fewer obstacles.
                let y = anchor.y + 1.3 * j as f64;
                let row = near.narrowed(&Frame::from_corners(
                    Point::new(within.min().x, y - half.y - 2.0),
                    Point::new(within.max().x, y + half.y + 2.0),
                ));
                narrowed +=
                    (row.found.as_ref()).map_or(0, |f| all.len() - f.len() - row.pending.len());
                for i in -40..=40 {
                    let centre = anchor + Vector::new(1.7 * i as f64, 1.3 * j as f64);
                    let b = Frame::around(centre, half);
                    let mut sum = 0.0;
                    let mut terms = 0;
                    for (bounds, obstacle) in &all {
                        if !bounds.meets(&b) {
                            continue;
                        }
                        let term = match *obstacle {
                            Obstacle::Segment(k) => {
                                let (p, q, w) = o.segments[k];
                                length_inside(p, q, &b).map_or(0.0, |l| w * (4.0 + l))
                            }
                            Obstacle::Box(k) => {
                                let a = b.overlap_area(&o.boxes[k].0);
                                if a > 0.0 { 200.0 + a } else { 0.0 }
                            }
                        };
                        sum += term;
                        terms += usize::from(term > 0.0);
                    }
                    assert_eq!(
                        near.cost_of(&b, 0.0, f64::INFINITY).to_bits(),
                        sum.to_bits()
                    );
                    assert_eq!(row.cost_of(&b, 0.0, f64::INFINITY).to_bits(), sum.to_bits());
                    compared += usize::from(terms >= 3);
                }
            }
        }
        // Sums of three terms or more, whose order shows in their bits.
        assert!(compared > 2000, "{compared}");
        // The rows looked through fewer.
        assert!(narrowed > 100 * 81, "{narrowed}");
    }
}
