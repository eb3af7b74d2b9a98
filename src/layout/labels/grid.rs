//! A uniform grid of buckets over a region of the page: each bucket holds,
//! in their order, the shapes that pass through its cell, so that a box
//! looks only at the buckets it covers.

use crate::geom::{Frame, Point, Vector};
use std::ops::RangeInclusive;

/// A shape put in the grid: a segment (by its ends) or a box.
#[derive(Debug, Clone, Copy)]
pub(super) enum Shape {
    Segment(Point, Point),
    Box(Frame),
}

/// The shapes given to [`Grid::new`], by their number, in a bucket per
/// cell: each shape in the bucket of every cell that comes within a
/// reach of it, so that the bucket of the cell holding a box's centre
/// holds every shape the box meets, if the box reaches no farther than
/// that from its centre. The cells on the edge reach on without end, so
/// that a shape or box beyond the region falls in them.
#[derive(Debug)]
pub(super) struct Grid {
    origin: Point,
    cell: f64,
    /// How far from a cell its bucket's shapes may lie, across and down.
    reach: Vector,
    columns: usize,
    rows: usize,
    /// Where each cell's bucket starts in `items` (one more than the
    /// cells: the last is where the last bucket ends).
    starts: Vec<u32>,
    /// The buckets one after another, each in the order of the shapes.
    items: Vec<u32>,
    /// Where each cell's boxes start in `chunks` (as `starts`).
    chunk_starts: Vec<u32>,
    /// The box of each run of [`CHUNK`] shapes of a bucket (the last run
    /// perhaps shorter), each shape's box cut to its cell: shapes
    /// together in the order of the shapes lie together (the order they
    /// were drawn in: a curve's segments one after another), so that a box that misses a run's skips it whole, as it
    /// does a hundred short segments piled at one point.
    chunks: Vec<Frame>,
    /// Where each cell's boxes start in `groups` (as `starts`).
    group_starts: Vec<u32>,
    /// The box of each run of [`CHUNK`] boxes of `chunks` of a bucket, a
    /// group of [`CHUNK`]² shapes.
    groups: Vec<Frame>,
}

/// How many shapes of a bucket one box of [`Grid::chunks`] holds.
pub(super) const CHUNK: usize = 8;

/// The least side of a cell, page units: about a small letter's box, so
/// that a long line crosses few buckets.
const LEAST_CELL: f64 = 8.0;

/// The most cells along a side.
const MOST_CELLS: usize = 256;

impl Default for Grid {
    /// One cell, empty.
    fn default() -> Self {
        Grid {
            origin: Point::origin(),
            cell: 1.0,
            reach: Vector::zeros(),
            columns: 1,
            rows: 1,
            starts: vec![0, 0],
            items: Vec::new(),
            chunk_starts: vec![0, 0],
            chunks: Vec::new(),
            group_starts: vec![0, 0],
            groups: Vec::new(),
        }
    }
}

impl Grid {
    /// The grid over `region` holding `shapes`, each in the bucket of
    /// every cell within `reach` of it, about one shape a cell (cells no
    /// smaller than [`LEAST_CELL`]). A region that is empty or not finite
    /// makes one cell holding every shape.
    pub fn new(region: &Frame, reach: Vector, shapes: &[Shape]) -> Self {
        let (width, height) = (region.width(), region.height());
        let sized = [region.min().x, region.min().y, width, height]
            .iter()
            .all(|v| v.is_finite())
            && width > 0.0
            && height > 0.0;
        let cell = if sized {
            let even = (width * height / shapes.len().max(1) as f64).sqrt();
            let most = width.max(height) / MOST_CELLS as f64;
            even.max(LEAST_CELL).max(most)
        } else {
            1.0
        };
        let count = |side: f64| {
            if sized {
                ((side / cell).ceil() as usize).clamp(1, MOST_CELLS)
            } else {
                1
            }
        };
        let mut grid = Grid {
            origin: Point::new(region.min().x, region.min().y),
            cell,
            reach: Vector::new(reach.x.max(0.0), reach.y.max(0.0)),
            columns: count(width),
            rows: count(height),
            starts: Vec::new(),
            items: Vec::new(),
            chunk_starts: Vec::new(),
            chunks: Vec::new(),
            group_starts: Vec::new(),
            groups: Vec::new(),
        };
        grid.fill(shapes);
        grid
    }

    /// The buckets, by a counting sort of (cell, shape) pairs made in the
    /// order of the shapes: each bucket keeps that order.
    fn fill(&mut self, shapes: &[Shape]) {
        let mut pairs: Vec<(u32, u32)> = Vec::with_capacity(shapes.len() * 2);
        for (n, shape) in shapes.iter().enumerate() {
            let n = u32::try_from(n).unwrap_or(u32::MAX);
            self.cells_of(shape, |cell| pairs.push((cell, n)));
        }
        // Every cell number is below `cells` ([`Grid::column`] and
        // [`Grid::row`] clamp), and every bucket's place below the pairs'
        // count: no `get` below fails.
        let cells = self.columns * self.rows;
        let mut starts = vec![0u32; cells + 1];
        for &(cell, _) in &pairs {
            if let Some(count) = starts.get_mut(cell as usize + 1) {
                *count += 1;
            }
        }
        let mut total = 0;
        for start in &mut starts {
            total += *start;
            *start = total;
        }
        let mut next = starts.clone();
        let mut items = vec![0u32; pairs.len()];
        for (cell, n) in pairs {
            if let Some(at) = next.get_mut(cell as usize)
                && let Some(item) = items.get_mut(*at as usize)
            {
                *item = n;
                *at += 1;
            }
        }
        self.starts = starts;
        self.items = items;
        self.cut(shapes);
    }

    /// The boxes of the runs of [`CHUNK`] shapes of each bucket, each
    /// shape's box cut to its cell widened by the reach and by its
    /// [`Grid::slack`]: what of a shape meets a box whose centre is in the
    /// cell (or that covers the cell, [`Grid::cover`]) lies in that, so a
    /// run whose box misses holds nothing the box needs from that cell.
    fn cut(&mut self, shapes: &[Shape]) {
        let mut chunk_starts = Vec::with_capacity(self.starts.len());
        let mut chunks = Vec::new();
        chunk_starts.push(0);
        let (mut group_starts, mut groups) = (chunk_starts.clone(), Vec::new());
        for (cell, w) in self.starts.windows(2).enumerate() {
            let (x0, x1) = self.span(cell % self.columns, self.columns, self.origin.x);
            let (y0, y1) = self.span(cell / self.columns, self.rows, self.origin.y);
            let (x0, x1) = (x0 - self.reach.x, x1 + self.reach.x);
            let (y0, y1) = (y0 - self.reach.y, y1 + self.reach.y);
            let bucket = slice(&self.items, w);
            for run in bucket.chunks(CHUNK) {
                let cut = run
                    .iter()
                    .filter_map(|&n| shapes.get(n as usize))
                    .map(|shape| {
                        let (b, slack) = self.extent(shape);
                        Frame::from_corners(
                            Point::new(b.min().x.max(x0 - slack), b.min().y.max(y0 - slack)),
                            Point::new(b.max().x.min(x1 + slack), b.max().y.min(y1 + slack)),
                        )
                    });
                chunks.extend(cut.reduce(union));
            }
            let first = chunk_starts.last().map_or(0, |&n| n as usize);
            let runs = chunks.get(first..).unwrap_or(&[]);
            groups.extend(
                runs.chunks(CHUNK)
                    .filter_map(|g| g.iter().copied().reduce(union)),
            );
            chunk_starts.push(u32::try_from(chunks.len()).unwrap_or(u32::MAX));
            group_starts.push(u32::try_from(groups.len()).unwrap_or(u32::MAX));
        }
        self.chunk_starts = chunk_starts;
        self.chunks = chunks;
        self.group_starts = group_starts;
        self.groups = groups;
    }

    /// A shape's box and its [`Grid::slack`].
    fn extent(&self, shape: &Shape) -> (Frame, f64) {
        let (p, q) = match *shape {
            Shape::Segment(p, q) => (p, q),
            Shape::Box(b) => (b.min(), b.max()),
        };
        let b = Frame::from_corners(
            Point::new(p.x.min(q.x), p.y.min(q.y)),
            Point::new(p.x.max(q.x), p.y.max(q.y)),
        );
        (b, self.slack(p, q))
    }

    /// Where column or row `k` of `count` starts and ends along an axis
    /// starting at `origin`, the first and last reaching on without end.
    fn span(&self, k: usize, count: usize, origin: f64) -> (f64, f64) {
        let start = origin + k as f64 * self.cell;
        (
            if k == 0 { f64::NEG_INFINITY } else { start },
            if k + 1 == count {
                f64::INFINITY
            } else {
                start + self.cell
            },
        )
    }

    /// The column of `x`, the edge columns reaching on without end.
    fn column(&self, x: f64) -> usize {
        Self::index((x - self.origin.x) / self.cell, self.columns)
    }

    /// The row of `y`, as [`Grid::column`].
    fn row(&self, y: f64) -> usize {
        Self::index((y - self.origin.y) / self.cell, self.rows)
    }

    /// The whole part of `at`, within 0 and `count` less one: cut toward
    /// zero, which below zero gives no more than 0 as `floor` would, with
    /// no call to it (NaN gives 0).
    fn index(at: f64, count: usize) -> usize {
        (at as isize).clamp(0, count as isize - 1) as usize
    }

    /// Calls `put` with each cell that comes within the reach of `shape`:
    /// a box's, every cell of the box widened by the reach; a segment's,
    /// row by row, the columns its part in the row's band (widened by the
    /// reach down) spans, widened by the reach across; each widened by a
    /// little more ([`Grid::slack`]) so that rounding never leaves out a
    /// cell.
    fn cells_of(&self, shape: &Shape, mut put: impl FnMut(u32)) {
        let mut span = |row: usize, x0: f64, x1: f64| {
            for column in self.column(x0)..=self.column(x1) {
                put(u32::try_from(row * self.columns + column).unwrap_or(u32::MAX));
            }
        };
        match *shape {
            Shape::Box(b) => {
                let slack = self.slack(b.min(), b.max());
                let (across, down) = (self.reach.x + slack, self.reach.y + slack);
                for row in self.row(b.min().y - down)..=self.row(b.max().y + down) {
                    span(row, b.min().x - across, b.max().x + across);
                }
            }
            Shape::Segment(p, q) => {
                let slack = self.slack(p, q);
                let (across, down) = (self.reach.x + slack, self.reach.y + slack);
                let (d, top, bottom) = (q - p, p.y.min(q.y), p.y.max(q.y));
                for row in self.row(top - down)..=self.row(bottom + down) {
                    let (t0, t1) = if d.y == 0.0 {
                        (0.0, 1.0)
                    } else {
                        let (y0, y1) = self.span(row, self.rows, self.origin.y);
                        let (a, b) = ((y0 - down - p.y) / d.y, (y1 + down - p.y) / d.y);
                        (a.min(b).max(0.0), a.max(b).min(1.0))
                    };
                    let (xa, xb) = (p.x + t0 * d.x, p.x + t1 * d.x);
                    span(row, xa.min(xb) - across, xa.max(xb) + across);
                }
            }
        }
    }

    /// How far a segment's cells reach beyond it: a thousandth of a cell,
    /// and more than the rounding of coordinates as large as its ends'.
    fn slack(&self, p: Point, q: Point) -> f64 {
        1e-3 * self.cell + 1e-9 * (p.x.abs() + p.y.abs() + q.x.abs() + q.y.abs())
    }

    /// How far from a cell its bucket's shapes may lie, across and down.
    pub fn reach(&self) -> Vector {
        self.reach
    }

    /// The rows and the columns of the cells whose buckets hold every
    /// shape meeting `b`: the cell of its centre, for a box that reaches
    /// no farther than the grid's reach from it; else the cells of its
    /// core, the box less the reach on every side, for whose every point
    /// the box comes within the reach of one (a box whose corners are the
    /// wrong way round stands for the box between them). A shape meeting
    /// `b` is in one of their buckets at least, where it meets `b` within
    /// the reach of that bucket's cell.
    pub fn cover(&self, b: &Frame) -> (RangeInclusive<usize>, RangeInclusive<usize>) {
        let core = |lo: f64, hi: f64, reach: f64| {
            let (lo, hi) = (lo.min(hi), lo.max(hi));
            let middle = 0.5 * (lo + hi);
            (middle.min(lo + reach), middle.max(hi - reach))
        };
        let (x0, x1) = core(b.min().x, b.max().x, self.reach.x);
        let (y0, y1) = core(b.min().y, b.max().y, self.reach.y);
        (
            self.row(y0)..=self.row(y1),
            self.column(x0)..=self.column(x1),
        )
    }

    /// The bucket of a cell that [`Grid::cover`] gave, each shape once, in
    /// the order of the shapes, with the boxes of its runs of [`CHUNK`]
    /// and of its groups of [`CHUNK`] runs.
    pub fn bucket(&self, row: usize, column: usize) -> (&[u32], &[Frame], &[Frame]) {
        let cell = row * self.columns + column;
        (
            slice(&self.items, ends(&self.starts, cell)),
            slice(&self.chunks, ends(&self.chunk_starts, cell)),
            slice(&self.groups, ends(&self.group_starts, cell)),
        )
    }
}

/// The least box holding both.
fn union(a: Frame, b: Frame) -> Frame {
    Frame::from_corners(
        Point::new(a.min().x.min(b.min().x), a.min().y.min(b.min().y)),
        Point::new(a.max().x.max(b.max().x), a.max().y.max(b.max().y)),
    )
}

/// The part of `of` from the first of `bounds` to the second (nothing if
/// either is missing or they are out of `of`).
fn slice<'a, T>(of: &'a [T], bounds: &[u32]) -> &'a [T] {
    match bounds {
        [from, to, ..] => of.get(*from as usize..*to as usize).unwrap_or(&[]),
        _ => &[],
    }
}

/// Where bucket `cell` starts and ends in `starts` (one more than the
/// cells).
fn ends(starts: &[u32], cell: usize) -> &[u32] {
    starts.get(cell..cell + 2).unwrap_or(&[])
}
