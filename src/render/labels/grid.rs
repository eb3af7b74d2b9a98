//! A uniform grid of buckets over a region of the page: each bucket holds,
//! in their order, the shapes that pass through its cell, so that a box
//! looks only at the buckets it covers.

use super::Bounds;
use crate::figure::PageRect;
use crate::geom::Point;

/// A shape put in the grid: a segment (by its ends) or a box.
#[derive(Debug, Clone, Copy)]
pub(super) enum Shape {
    Segment(Point, Point),
    Box(Bounds),
}

/// The shapes given to [`Grid::new`], by their number, in a bucket per
/// cell. The cells on the edge reach on without end, so that a shape or
/// box beyond the region falls in them: every shape meeting a box is in a
/// bucket the box covers, wherever either lies.
#[derive(Debug)]
pub(super) struct Grid {
    origin: Point,
    cell: f64,
    columns: usize,
    rows: usize,
    /// Where each cell's bucket starts in `items` (one more than the
    /// cells: the last is where the last bucket ends).
    starts: Vec<u32>,
    /// The buckets one after another, each in the order of the shapes.
    items: Vec<u32>,
}

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
            columns: 1,
            rows: 1,
            starts: vec![0, 0],
            items: Vec::new(),
        }
    }
}

impl Grid {
    /// The grid over `region` holding `shapes`, about one shape a cell
    /// (cells no smaller than [`LEAST_CELL`]). A region that is empty or
    /// not finite makes one cell holding every shape.
    pub fn new(region: &PageRect, shapes: &[Shape]) -> Self {
        let (width, height) = (region.width, region.height);
        let sized = [region.x, region.y, width, height]
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
            origin: Point::new(region.x, region.y),
            cell,
            columns: count(width),
            rows: count(height),
            starts: Vec::new(),
            items: Vec::new(),
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
        // [`Grid::row`] clamp), so the indexing below stays in bounds.
        let cells = self.columns * self.rows;
        let mut starts = vec![0u32; cells + 1];
        for &(cell, _) in &pairs {
            starts[cell as usize + 1] += 1;
        }
        for i in 0..cells {
            starts[i + 1] += starts[i];
        }
        let mut next = starts.clone();
        let mut items = vec![0u32; pairs.len()];
        for (cell, n) in pairs {
            let at = &mut next[cell as usize];
            items[*at as usize] = n;
            *at += 1;
        }
        self.starts = starts;
        self.items = items;
    }

    /// The column of `x`, the edge columns reaching on without end.
    fn column(&self, x: f64) -> usize {
        let c = ((x - self.origin.x) / self.cell).floor();
        c.clamp(0.0, (self.columns - 1) as f64) as usize
    }

    /// The row of `y`, as [`Grid::column`].
    fn row(&self, y: f64) -> usize {
        let r = ((y - self.origin.y) / self.cell).floor();
        r.clamp(0.0, (self.rows - 1) as f64) as usize
    }

    /// Calls `put` with each cell `shape` passes through: a box's every
    /// cell; a segment's, row by row, the columns its part in the row's
    /// band spans, each band and span widened by a little
    /// ([`Grid::slack`]) so that rounding never leaves out a cell it
    /// touches.
    fn cells_of(&self, shape: &Shape, mut put: impl FnMut(u32)) {
        let mut span = |row: usize, x0: f64, x1: f64| {
            for column in self.column(x0)..=self.column(x1) {
                put(u32::try_from(row * self.columns + column).unwrap_or(u32::MAX));
            }
        };
        match *shape {
            Shape::Box(b) => {
                for row in self.row(b.min.y)..=self.row(b.max.y) {
                    span(row, b.min.x, b.max.x);
                }
            }
            Shape::Segment(p, q) => {
                let slack = self.slack(p, q);
                let (d, top, bottom) = (q - p, p.y.min(q.y), p.y.max(q.y));
                for row in self.row(top - slack)..=self.row(bottom + slack) {
                    let (t0, t1) = if d.y == 0.0 {
                        (0.0, 1.0)
                    } else {
                        let (y0, y1) = self.band(row);
                        let (a, b) = ((y0 - slack - p.y) / d.y, (y1 + slack - p.y) / d.y);
                        (a.min(b).max(0.0), a.max(b).min(1.0))
                    };
                    let (xa, xb) = (p.x + t0 * d.x, p.x + t1 * d.x);
                    span(row, xa.min(xb) - slack, xa.max(xb) + slack);
                }
            }
        }
    }

    /// How far a segment's cells reach beyond it: a thousandth of a cell,
    /// and more than the rounding of coordinates as large as its ends'.
    fn slack(&self, p: Point, q: Point) -> f64 {
        1e-3 * self.cell + 1e-9 * (p.x.abs() + p.y.abs() + q.x.abs() + q.y.abs())
    }

    /// The band of page a row holds, the first and last reaching on
    /// without end.
    fn band(&self, row: usize) -> (f64, f64) {
        let top = self.origin.y + row as f64 * self.cell;
        (
            if row == 0 { f64::NEG_INFINITY } else { top },
            if row + 1 == self.rows {
                f64::INFINITY
            } else {
                top + self.cell
            },
        )
    }

    /// The numbers of the shapes in the buckets that `b` covers, each
    /// once, in the order of the shapes, into `into` (emptied first): a
    /// superset of those that meet `b` (a box whose corners are the
    /// wrong way round covers the box between them).
    pub fn gather(&self, b: &Bounds, into: &mut Vec<u32>) {
        into.clear();
        let (x0, x1) = (b.min.x.min(b.max.x), b.min.x.max(b.max.x));
        let (y0, y1) = (b.min.y.min(b.max.y), b.min.y.max(b.max.y));
        let (c0, c1) = (self.column(x0), self.column(x1));
        let (r0, r1) = (self.row(y0), self.row(y1));
        for row in r0..=r1 {
            // The cells are in bounds ([`Grid::column`], [`Grid::row`]),
            // and so are the buckets' starts.
            let (first, last) = (row * self.columns + c0, row * self.columns + c1);
            let (from, to) = (self.starts[first], self.starts[last + 1]);
            into.extend_from_slice(&self.items[from as usize..to as usize]);
        }
        if c0 != c1 || r0 != r1 {
            into.sort_unstable();
            into.dedup();
        }
    }
}
