//! Plot panels: axes with round ticks, titles with units, curves traced by
//! [`trace`] to a tolerance in page units, data markers and lines, and a
//! legend set where nothing is drawn.

use super::{Axis, Curve, Method, Scale, TraceOptions, trace};
use crate::error::{Error, Field, Result};
use crate::figure::{
    Align, AxisRecord, AxisScale, Dash, Font, Item, PageFromWorld, Panel, PathBuilder, PlotRecord,
    RichText, Role, Shape, Symbol, TextSize,
};
use crate::geom::{Frame, Point, Vector};
use std::ops::RangeInclusive;

/// Length of a labelled tick, page units.
const TICK: f64 = 5.0;
/// Size of tick labels and legend text.
const TICK_TEXT: f64 = 12.0;
/// Room above the plot area for the ordinate's title.
const TOP: f64 = 30.0;
/// Room below the plot area for tick labels and the abscissa's title.
const BOTTOM: f64 = 42.0;
/// Room below that for a caption.
pub(crate) const CAPTION: f64 = 22.0;
/// Size of a caption's text (the style's small text, which every style
/// sets at this size).
const CAPTION_TEXT: f64 = 13.0;
/// Line height of a caption broken over several lines.
const CAPTION_LINE: f64 = 16.0;
/// Line height of legends and notes.
const LEGEND_LINE: f64 = 16.0;
/// Length of a legend's line sample.
const KEY: f64 = 28.0;
/// Room between the plot area and a legend set beside it, page units.
pub(crate) const LEGEND_GAP: f64 = 16.0;

/// Spacing (page units) of the points a straight line leaves for the
/// legend to keep clear of.
const LINE_SAMPLE: f64 = 6.0;
/// Space between neighbouring labels of a horizontal axis, page units.
const LABEL_GAP: f64 = 8.0;
/// Least distance between labels of a vertical axis, in label sizes.
const LABEL_PITCH: f64 = 1.4;
/// Strides tried, in order, for keeping every k-th tick label.
const STRIDES: [usize; 8] = [1, 2, 5, 10, 20, 50, 100, 200];
/// The shortest decade of a log axis (page units) that keeps its minor
/// ticks.
const LEAST_DECADE: f64 = 24.0;

/// Which way an axis runs on the page: its labels are measured across
/// (their widths) or up (their height).
#[derive(Debug, Clone, Copy)]
enum Direction {
    Across,
    Up,
}

/// A tick as drawn: its value, its label if it keeps one, and whether it
/// is a major (once labelled) tick.
#[derive(Debug, Clone)]
struct Shown {
    value: f64,
    label: Option<String>,
    major: bool,
}

/// What a legend entry shows beside its text.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Key {
    Line(Dash),
    Marker(Symbol),
}

/// A block of text lines (a legend or a note) set in a free corner.
#[derive(Debug, Clone)]
struct Block {
    id: String,
    lines: Vec<(RichText, Option<Key>)>,
}

/// A plot panel being built: with axes ([`Plot::new`]), or without, at a
/// uniform scale for diagrams in a mechanism's own world coordinates
/// ([`Plot::world`]).
///
/// Item ids are the caller's for what it adds (`curve-...`); the plot's
/// own (axes, ticks, legend) start with its name. With a log axis the
/// world coordinate is log₁₀ of the value: [`Plot::curve`],
/// [`Plot::points`] and [`Plot::line`] take values and convert them.
#[derive(Debug, Clone)]
pub struct Plot {
    name: String,
    rect: Frame,
    area: Frame,
    axes: Option<(Axis, Axis)>,
    map: PageFromWorld,
    tolerance: f64,
    font: Font,
    grid: bool,
    items: Vec<Item>,
    blocks: Vec<Block>,
    legend: Vec<(RichText, Option<Key>)>,
    drawn: Vec<Point>,
    caption: Vec<RichText>,
    /// How the map follows a change of the area: the world rectangle and
    /// its mirroring for a world plot; `None` for a plot with axes (the
    /// axes' ranges map onto the area) or a map taken over.
    world: Option<(Frame, bool)>,
    /// Blocks try the bottom corners first (the band [`Plot::band`] keeps
    /// free for them).
    below: bool,
    /// Blocks try the left corners before the right (under notes set at
    /// the left, as theirs).
    left_first: bool,
    /// Where the legend's top left corner goes when it is set below or
    /// beside the plot area rather than in a corner of it
    /// ([`Plot::legend_clear_of_the_curves`]).
    legend_at: Option<Point>,
}

/// What a user can change when a curve reaches the curve engine's limits.
/// How near (page units) a piece of a curve must start to where the one
/// before it ended for a dashed curve to run on through it in one subpath:
/// a dash pattern starts again at each subpath, so pieces shorter than a
/// dash, one after another (a load curve's 10° pieces where it moves
/// slowly), would each draw a whole dash and read as a solid line. A
/// thousandth of a unit, below what the SVG writes (two decimals): pieces
/// that meet at a kink end and start a little inside it.
const PIECES_MEET: f64 = 1e-3;

const LIMIT_ADVICE: &str = "a mechanism this close to its limit of assembly (rod = crank + |offset|) changes too fast to draw: give a longer rod or a smaller offset, or data that vary less";

fn too_small(rect: &Frame) -> Error {
    Error::OutOfRange {
        name: Field::PanelWidth,
        value: rect.width(),
        reason: format!(
            "a plot panel of {} × {} leaves no room for its plot",
            rect.width(),
            rect.height()
        ),
    }
}

impl Plot {
    /// A plot named `name` (its panel is `panel-{name}`) filling `rect`,
    /// with abscissa `x` and ordinate `y`; curves are drawn to `tolerance`
    /// page units in the written file. The plot area is `rect` less room
    /// for tick labels (measured in `font`, the face the figure is set
    /// in), titles and a caption. Errors when that leaves less than
    /// 40 × 40 units or the tolerance is not positive.
    pub fn new(
        name: &str,
        rect: Frame,
        x: Axis,
        y: Axis,
        tolerance: f64,
        font: Font,
    ) -> Result<Self> {
        let tolerance = crate::error::positive(Field::Tolerance, tolerance)?;
        let widest = y
            .ticks()
            .iter()
            .filter_map(|t| t.label.as_ref())
            .map(|l| RichText::parse(l).width(font, TICK_TEXT))
            .fold(0.0, f64::max);
        // At least the room of "−0000", so that plots stacked in a column
        // line up.
        let left = widest.max(3.0 * TICK_TEXT) + TICK + 10.0;
        let last_x = x
            .ticks()
            .iter()
            .rev()
            .find_map(|t| t.label.clone())
            .unwrap_or_default();
        let right = 0.5 * RichText::parse(&last_x).width(font, TICK_TEXT) + 8.0;
        let area = Frame::from_origin_size(
            rect.min().x + left,
            rect.min().y + TOP,
            rect.width() - left - right,
            rect.height() - TOP - BOTTOM - CAPTION,
        );
        if area.width() < 40.0 || area.height() < 40.0 {
            return Err(too_small(&rect));
        }
        let (x0, x1) = x.world_range();
        let (y0, y1) = y.world_range();
        let map = PageFromWorld::axes(
            area.width() / (x1 - x0),
            -area.height() / (y1 - y0),
            Point::new(x0, y0),
            Point::new(area.min().x, area.max().y),
        )
        .ok_or_else(|| Error::OutOfRange {
            name: Field::AxisRange,
            value: (x1 - x0).max(y1 - y0),
            reason: "an axis range too large or too small to map onto the page".into(),
        })?;
        Ok(Self {
            name: name.to_string(),
            rect,
            area,
            axes: Some((x, y)),
            map,
            tolerance,
            font,
            grid: false,
            items: Vec::new(),
            blocks: Vec::new(),
            legend: Vec::new(),
            drawn: Vec::new(),
            caption: Vec::new(),
            world: None,
            below: false,
            left_first: false,
            legend_at: None,
        })
    }

    /// A plot without axes showing the world rectangle `world` whole at
    /// one scale in `rect` (less room for a caption), mirrored in x when
    /// `mirror`: polar diagrams and curves drawn on the mechanism; legends
    /// are measured in `font`. Errors for an empty rectangle or a
    /// non-positive tolerance.
    pub fn world(
        name: &str,
        rect: Frame,
        world: &Frame,
        mirror: bool,
        tolerance: f64,
        font: Font,
    ) -> Result<Self> {
        let tolerance = crate::error::positive(Field::Tolerance, tolerance)?;
        let area = Frame::from_origin_size(
            rect.min().x,
            rect.min().y,
            rect.width(),
            rect.height() - CAPTION,
        );
        if area.width() < 40.0 || area.height() < 40.0 {
            return Err(too_small(&rect));
        }
        let map = PageFromWorld::fit(world, &area, mirror).ok_or_else(|| Error::OutOfRange {
            name: Field::WorldFrame,
            value: (world.max() - world.min()).norm(),
            reason: "a world panel needs a rectangle of positive size".into(),
        })?;
        let mut plot = Self::with_map(name, rect, area, map, tolerance, font);
        plot.world = Some((*world, mirror));
        Ok(plot)
    }

    /// A plot without axes with the given map and plot area (a mechanism
    /// panel taken over from a [`crate::scene::Scene`]), legends measured in
    /// `font`.
    pub(crate) fn with_map(
        name: &str,
        rect: Frame,
        area: Frame,
        map: PageFromWorld,
        tolerance: f64,
        font: Font,
    ) -> Self {
        Self {
            name: name.to_string(),
            rect,
            area,
            axes: None,
            map,
            tolerance,
            font,
            grid: false,
            items: Vec::new(),
            blocks: Vec::new(),
            legend: Vec::new(),
            drawn: Vec::new(),
            caption: Vec::new(),
            world: None,
            below: false,
            left_first: false,
            legend_at: None,
        }
    }

    /// Sets the legend and notes in the bottom band of the area when it is
    /// free there (see [`Plot::band`]), before the other corners.
    pub(crate) fn blocks_below(mut self) -> Self {
        self.below = true;
        self
    }

    /// As [`Plot::blocks_below`], the bottom left corner first: a legend in
    /// a band of its own under notes set at the left reads with them, not
    /// with what is drawn below it.
    pub(crate) fn blocks_below_at_left(mut self) -> Self {
        self.below = true;
        self.left_first = true;
        self
    }

    /// The width and height of the legend as it stands, page units (zero
    /// without entries): the room [`Plot::with_legend_set_beside`] takes.
    pub(crate) fn legend_size(&self) -> (f64, f64) {
        match self.legend.is_empty() {
            true => (0.0, 0.0),
            false => block_size(&self.legend, self.font),
        }
    }

    /// The same plot with no legend (its series drawn, their entries
    /// dropped): for a plot whose legend another beside it carries.
    pub(crate) fn without_legend(mut self) -> Self {
        self.legend.clear();
        self
    }

    /// The legend beside the plot area, on its right at its top, whatever
    /// the corners hold: the area narrows by the legend's width
    /// ([`Plot::legend_size`]) and [`LEGEND_GAP`] (a plot too short for
    /// any corner to hold its legend clear of the data, given that much
    /// more width). Call after the legend's last entry; where the area
    /// would be left under 40 units wide, the legend stays in a corner.
    pub(crate) fn with_legend_set_beside(self) -> Self {
        let (width, _) = self.legend_size();
        match width > 0.0 {
            true => self.with_legend_beside(width),
            false => self,
        }
    }

    /// The legend beside the plot area, on its right at its top, instead
    /// of in a corner of it: the area narrows by the legend's `width` and
    /// a gap, and the map follows (the items, kept in world coordinates,
    /// with it). Where that would leave the area under 40 units wide, the
    /// legend stays in a corner.
    fn with_legend_beside(mut self, width: f64) -> Self {
        let narrower = self.area.width() - width - LEGEND_GAP;
        if narrower >= 40.0 {
            self.area = Frame::from_origin_size(
                self.area.min().x,
                self.area.min().y,
                narrower,
                self.area.height(),
            );
            self.remap();
            self.legend_at = Some(Point::new(
                self.area.min().x + narrower + LEGEND_GAP,
                self.area.min().y,
            ));
        }
        self
    }

    /// The legend below the plot area, centred under it between the
    /// abscissa's title and the caption, instead of in a corner of it: the
    /// area loses the legend's `height` and a gap, and the map follows.
    /// Where that would leave the area under 40 units tall, the legend
    /// stays in a corner.
    fn with_legend_below(mut self, (width, height): (f64, f64)) -> Self {
        let lower = self.area.height() - height - LEGEND_GAP;
        if lower >= 40.0 {
            self.area = Frame::from_origin_size(
                self.area.min().x,
                self.area.min().y,
                self.area.width(),
                lower,
            );
            self.remap();
            self.legend_at = Some(Point::new(
                self.area.min().x + 0.5 * (self.area.width() - width),
                self.area.min().y + lower + BOTTOM + 0.5 * LEGEND_GAP,
            ));
        }
        self
    }

    /// Draws dotted grid lines at the labelled ticks.
    pub fn with_grid(mut self) -> Self {
        self.grid = true;
        self
    }

    /// A caption below the plot (markup, `(a) Velocity on a time base`),
    /// broken at its spaces to the panel's width; each line past the
    /// first takes its height from the plot area, whose map follows. Call
    /// it before drawing. A single word wider than the panel stays whole
    /// (the writer fits it); a plot whose map was taken over keeps its
    /// area, so there the caption stays on one line.
    pub fn with_caption(mut self, caption: &str) -> Self {
        let text = RichText::parse(caption);
        let lines = match (&self.axes, &self.world) {
            (None, None) => vec![text],
            _ => text.wrap(self.font, CAPTION_TEXT, self.caption_room()),
        };
        let extra = CAPTION_LINE * (lines.len() - 1) as f64;
        if extra > 0.0 && self.area.height() - extra >= 40.0 {
            self.area = Frame::from_origin_size(
                self.area.min().x,
                self.area.min().y,
                self.area.width(),
                self.area.height() - extra,
            );
            self.remap();
            self.caption = lines;
        } else {
            self.caption = vec![RichText::parse(caption)];
        }
        self
    }

    /// The widest caption line centred under the plot area that stays
    /// 4 units inside the panel.
    fn caption_room(&self) -> f64 {
        let centre = self.area.min().x + 0.5 * self.area.width();
        let left = centre - self.rect.min().x;
        let right = self.rect.max().x - centre;
        2.0 * left.min(right) - 8.0
    }

    /// The map again after the area changed: the axes' ranges onto the
    /// area, or the world rectangle fitted into it.
    fn remap(&mut self) {
        let map = match (&self.axes, &self.world) {
            (Some((x, y)), _) => {
                let (x0, x1) = x.world_range();
                let (y0, y1) = y.world_range();
                PageFromWorld::axes(
                    self.area.width() / (x1 - x0),
                    -self.area.height() / (y1 - y0),
                    Point::new(x0, y0),
                    Point::new(self.area.min().x, self.area.max().y),
                )
            }
            (None, Some((world, mirror))) => PageFromWorld::fit(world, &self.area, *mirror),
            (None, None) => None,
        };
        // The ranges mapped onto a larger area before, so they map now.
        if let Some(map) = map {
            self.map = map;
        }
    }

    /// The world-to-page map of the panel.
    pub fn map(&self) -> &PageFromWorld {
        &self.map
    }

    /// The panel's rectangle (page units): the area with its axes'
    /// labels, titles and caption.
    pub fn rect(&self) -> Frame {
        self.rect
    }

    /// The plot area (page units): curves are clipped to it.
    pub fn area(&self) -> Frame {
        self.area
    }

    /// The panel's id, `panel-{name}`.
    pub fn panel_id(&self) -> String {
        format!("panel-{}", self.name)
    }

    /// The world point of a pair of values (log₁₀ on a log axis); `None`
    /// for a value a log axis cannot show.
    pub fn world_point(&self, x: f64, y: f64) -> Option<Point> {
        match &self.axes {
            Some((ax, ay)) => Some(Point::new(ax.world(x)?, ay.world(y)?)),
            None => (x.is_finite() && y.is_finite()).then(|| Point::new(x, y)),
        }
    }

    fn scales(&self) -> (Scale, Scale) {
        match &self.axes {
            Some((x, y)) => (x.scale(), y.scale()),
            None => (Scale::Linear, Scale::Linear),
        }
    }

    fn remember(&mut self, page: Point) {
        if page.x.is_finite() && page.y.is_finite() {
            self.drawn.push(page);
        }
    }

    /// Traces a curve given in pieces, each a function of values with
    /// exact derivatives over its own parameter range (pieces meet at
    /// corners or have different formulas), to the plot's tolerance, clipped
    /// to the plot area, as one item `id` stroked with `dash`, with a legend
    /// entry when `legend` is given. A curve wholly outside the area draws
    /// nothing. Errors are the curve engine's ([`trace`]).
    pub fn curve(
        &mut self,
        id: &str,
        pieces: &[(&dyn Curve, RangeInclusive<f64>)],
        dash: Dash,
        legend: Option<&str>,
    ) -> Result<()> {
        let (sx, sy) = self.scales();
        let ln10 = std::f64::consts::LN_10;
        let world = |curve: &dyn Curve, t: f64| -> Option<(Point, Vector)> {
            let (p, d) = curve.eval(t)?;
            let (x, dx) = match sx {
                Scale::Linear => (p.x, d.x),
                Scale::Log if p.x > 0.0 => (p.x.log10(), d.x / (p.x * ln10)),
                Scale::Log => return None,
            };
            let (y, dy) = match sy {
                Scale::Linear => (p.y, d.y),
                Scale::Log if p.y > 0.0 => (p.y.log10(), d.y / (p.y * ln10)),
                Scale::Log => return None,
            };
            Some((Point::new(x, y), Vector::new(dx, dy)))
        };
        let options = TraceOptions::written(self.tolerance);
        let mut subpaths = Vec::new();
        for (curve, range) in pieces {
            let traced = trace(
                &|t: f64| world(*curve, t),
                range.clone(),
                &self.map,
                &self.area,
                Method::Cubic,
                &options,
            )
            .map_err(|e| match e {
                Error::Limit(why) => {
                    Error::Limit(format!("cannot draw {id}: {why}; {LIMIT_ADVICE}"))
                }
                e => e,
            })?;
            for sub in traced.subpaths() {
                match subpaths.last_mut() {
                    Some(last) if dash != Dash::Solid && runs_on(last, sub) => {
                        sub.segments().iter().for_each(|s| last.push(*s));
                    }
                    _ => subpaths.push(sub.clone()),
                }
            }
        }
        let page = super::TracedPath::new(subpaths);
        for sub in page.subpaths() {
            for (start, seg) in sub.pieces() {
                let n = ((seg.end() - start).norm() / 6.0).ceil().clamp(4.0, 400.0) as usize;
                for k in 0..n {
                    let p = seg.eval(start, k as f64 / n as f64);
                    self.remember(p);
                }
            }
        }
        if let Some(path) = page.to_figure_path(&self.map) {
            self.items
                .push(Item::new(id, Role::Curve, Shape::Path(path)).dashed(dash));
        }
        if let Some(text) = legend {
            self.legend
                .push((RichText::parse(text), Some(Key::Line(dash))));
        }
        Ok(())
    }

    /// Data points as markers `{id}-1`, `{id}-2`, … (numbered in the order
    /// given, skipping none: a point outside the plot area or one a log
    /// axis cannot show keeps its number and is not drawn).
    pub fn points(
        &mut self,
        id: &str,
        values: &[(f64, f64)],
        symbol: Symbol,
        legend: Option<&str>,
    ) {
        let frame = self.area;
        for (k, &(x, y)) in values.iter().enumerate() {
            let Some(w) = self.world_point(x, y) else {
                continue;
            };
            let page = self.map.apply(w);
            if !frame.contains(page) {
                continue;
            }
            self.remember(page);
            self.items.push(Item::new(
                format!("{id}-{}", k + 1),
                Role::Curve,
                Shape::Marker { centre: w, symbol },
            ));
        }
        if let Some(text) = legend {
            self.legend
                .push((RichText::parse(text), Some(Key::Marker(symbol))));
        }
    }

    /// A polyline through data values (not a traced curve: straight
    /// between the values), as the item `id`; points a log axis cannot
    /// show are left out. Nothing is drawn for fewer than two points.
    pub fn line(&mut self, id: &str, values: &[(f64, f64)], dash: Dash, legend: Option<&str>) {
        let points: Vec<Point> = values
            .iter()
            .filter_map(|&(x, y)| self.world_point(x, y))
            .collect();
        if points.len() >= 2 {
            // Every few units along each piece, so that a legend counts
            // how much of the line it would cover.
            for (a, b) in points.iter().zip(points.iter().skip(1)) {
                let (pa, pb) = (self.map.apply(*a), self.map.apply(*b));
                let steps = ((pb - pa).norm() / LINE_SAMPLE).ceil().clamp(1.0, 1e4) as usize;
                for k in 0..=steps {
                    self.remember(pa + (pb - pa) * (k as f64 / steps as f64));
                }
            }
            self.items.push(
                Item::new(
                    id,
                    Role::Curve,
                    Shape::Polyline {
                        points,
                        closed: false,
                    },
                )
                .dashed(dash),
            );
        }
        if let Some(text) = legend {
            self.legend
                .push((RichText::parse(text), Some(Key::Line(dash))));
        }
    }

    /// Adds an item in world coordinates as it is (the legend keeps clear
    /// of its points and control points).
    pub fn push(&mut self, item: Item) {
        self.avoid(&item);
        self.items.push(item);
    }

    /// Keeps the legend and notes clear of an item drawn by someone else
    /// in the same panel.
    pub fn avoid(&mut self, item: &Item) {
        let chain: Vec<Point> = match &item.shape {
            Shape::Path(p) => p.points().collect(),
            Shape::Polyline { points, closed } => {
                let mut v = points.clone();
                if *closed && let Some(first) = points.first() {
                    v.push(*first);
                }
                v
            }
            Shape::Region { points } | Shape::Block { points } | Shape::Body { points } => {
                points.clone()
            }
            Shape::Marker { centre, .. }
            | Shape::Dot { centre }
            | Shape::Pin { centre }
            | Shape::Bearing { centre, .. } => vec![*centre],
            Shape::Arrow { from, to } | Shape::Hatch { from, to, .. } => vec![*from, *to],
            Shape::Label { anchor, .. } => vec![*anchor],
            Shape::Circle { centre, radius } | Shape::Arc { centre, radius, .. } => (0..=48)
                .map(|k| {
                    let t = std::f64::consts::TAU * k as f64 / 48.0;
                    centre + Vector::new(t.cos(), t.sin()) * *radius
                })
                .collect(),
            _ => Vec::new(),
        };
        let page: Vec<Point> = chain.iter().map(|p| self.map.apply(*p)).collect();
        if let [only] = page.as_slice() {
            self.remember(*only);
        }
        for (&a, &b) in page.iter().zip(page.iter().skip(1)) {
            let n = ((b - a).norm() / 8.0).ceil().clamp(1.0, 500.0) as usize;
            for k in 0..=n {
                self.remember(a + (b - a) * (k as f64 / n as f64));
            }
        }
    }

    /// The room a legend or note of `lines` lines takes below a plot area
    /// when it is set in the area's bottom band: its height and the inset
    /// from the area's edge, page units.
    pub fn band(lines: usize) -> f64 {
        LEGEND_LINE * lines as f64 + 8.0 + 8.0
    }

    /// A legend entry without a drawn item (for a series drawn by
    /// [`Plot::push`]).
    pub fn legend_line(&mut self, text: &str, dash: Dash) {
        self.legend
            .push((RichText::parse(text), Some(Key::Line(dash))));
    }

    /// A legend entry for markers drawn by [`Plot::points`] without one.
    pub fn legend_marker(&mut self, text: &str, symbol: Symbol) {
        self.legend
            .push((RichText::parse(text), Some(Key::Marker(symbol))));
    }

    /// A note: lines of markup set in a free corner of the plot area, after
    /// the legend, as the items `{name}-{id}-1`, …
    pub fn note(&mut self, id: &str, lines: &[String]) {
        self.blocks.push(Block {
            id: format!("{}-{id}", self.name),
            lines: lines.iter().map(|l| (RichText::parse(l), None)).collect(),
        });
    }

    /// The plot's description for the figure's metadata: panel id, plot
    /// area and, with axes, each axis's title, range and scale.
    pub fn record(&self) -> PlotRecord {
        let r = self.area;
        let axis = |a: &Axis| {
            let (min, max) = a.range();
            AxisRecord {
                title: a.title().plain(),
                min,
                max,
                scale: match a.scale() {
                    Scale::Linear => AxisScale::Linear,
                    Scale::Log => AxisScale::Log,
                },
            }
        };
        PlotRecord {
            panel: self.panel_id(),
            area: [r.min().x, r.min().y, r.width(), r.height()],
            x: self.axes.as_ref().map(|(x, _)| axis(x)),
            y: self.axes.as_ref().map(|(_, y)| axis(y)),
        }
    }

    fn unmap(&self, page: Point) -> Point {
        self.map.invert(page)
    }

    fn text(&self, id: String, page: Point, text: RichText, align: Align, size: TextSize) -> Item {
        Item::new(
            id,
            Role::Label,
            Shape::Text {
                at: self.unmap(page),
                offset: Vector::zeros(),
                text,
                align,
                size,
            },
        )
    }

    fn segment(&self, id: String, role: Role, a: Point, b: Point) -> Item {
        Item::new(
            id,
            role,
            Shape::Polyline {
                points: vec![self.unmap(a), self.unmap(b)],
                closed: false,
            },
        )
    }

    /// The axes' lines, ticks, labels and titles, the zero lines and the
    /// grid.
    /// The ticks of an axis as drawn along `lo..=hi` (page units, `page`
    /// taking a value to its page coordinate): where labels would crowd,
    /// only every second, fifth, tenth … keeps its label (the others stay
    /// long ticks); where a log axis's decades are too short for minor
    /// ticks to read, those go.
    fn thinned(
        &self,
        axis: &Axis,
        page: &dyn Fn(f64) -> Option<f64>,
        lo: f64,
        hi: f64,
        direction: Direction,
    ) -> Vec<Shown> {
        let ticks = axis.ticks();
        let at: Vec<(usize, f64, f64)> = ticks
            .iter()
            .enumerate()
            .filter_map(|(i, t)| {
                let label = t.label.as_ref()?;
                let p = page(t.value).filter(|p| *p >= lo - 0.01 && *p <= hi + 0.01)?;
                let need = match direction {
                    Direction::Across => {
                        RichText::parse(label).width(self.font, TICK_TEXT) + LABEL_GAP
                    }
                    Direction::Up => LABEL_PITCH * TICK_TEXT,
                };
                Some((i, p, need))
            })
            .collect();
        let room = |stride: usize| {
            at.iter()
                .step_by(stride)
                .zip(at.iter().step_by(stride).skip(1))
                .all(|(a, b)| (b.1 - a.1).abs() >= 0.5 * (a.2 + b.2))
        };
        let stride = STRIDES
            .iter()
            .copied()
            .find(|s| room(*s))
            .unwrap_or(at.len().max(1));
        // A decade shorter than this leaves no room between minor ticks.
        let decade = at
            .iter()
            .zip(at.iter().skip(1))
            .map(|(a, b)| (b.1 - a.1).abs())
            .fold(f64::INFINITY, f64::min);
        let minors = axis.scale() == Scale::Linear || decade >= LEAST_DECADE;
        // Kept labels fall on round multiples (10⁰, 10⁵, … or 0, 100, …)
        // where that keeps two of them.
        let round = |i: &usize| {
            let w = ticks.get(*i).and_then(|t| axis.world(t.value));
            w.is_some_and(|w| ((w / axis.step()).round() as i64).rem_euclid(stride as i64) == 0)
        };
        let mut kept: Vec<usize> = at.iter().map(|a| a.0).filter(round).collect();
        if stride == 1 || kept.len() < 2 {
            kept = at.iter().step_by(stride).map(|a| a.0).collect();
        }
        ticks
            .into_iter()
            .enumerate()
            .filter_map(|(i, t)| {
                let major = t.label.is_some();
                if !major && !minors {
                    return None;
                }
                let label = t.label.filter(|_| kept.contains(&i));
                Some(Shown {
                    value: t.value,
                    label,
                    major,
                })
            })
            .collect()
    }

    fn axis_items(&self, x: &Axis, y: &Axis) -> Vec<Item> {
        let n = &self.name;
        let a = self.area;
        let (left, right, top, bottom) = (a.min().x, a.max().x, a.min().y, a.max().y);
        let mut items = vec![
            self.segment(
                format!("{n}-axis-x"),
                Role::Frame,
                Point::new(left, bottom),
                Point::new(right, bottom),
            ),
            self.segment(
                format!("{n}-axis-y"),
                Role::Frame,
                Point::new(left, bottom),
                Point::new(left, top),
            ),
        ];
        let mut marks = Marks::default();
        self.x_ticks(x, &mut items, &mut marks);
        self.y_ticks(y, &mut items, &mut marks);
        if marks.has_ticks
            && let Some(path) = marks.ticks.build()
        {
            items.push(Item::new(
                format!("{n}-ticks"),
                Role::Frame,
                Shape::Path(path),
            ));
        }
        if marks.has_grid
            && let Some(path) = marks.grid.build()
        {
            items.push(
                Item::new(format!("{n}-grid"), Role::Dimension, Shape::Path(path))
                    .dashed(Dash::Dotted),
            );
        }
        self.zero_lines(x, y, &mut items);
        items.push(self.text(
            format!("{n}-title-x"),
            Point::new(0.5 * (left + right), bottom + TICK + 27.0),
            x.title(),
            Align::Middle,
            TextSize::Small,
        ));
        items.push(self.text(
            format!("{n}-title-y"),
            Point::new(self.rect.min().x + 2.0, top - 19.0),
            y.title(),
            Align::Start,
            TextSize::Small,
        ));
        items
    }

    /// The abscissa's ticks and grid lines into `marks`, its tick labels
    /// into `items`.
    fn x_ticks(&self, x: &Axis, items: &mut Vec<Item>, marks: &mut Marks) {
        let n = &self.name;
        let a = self.area;
        let (left, right, top, bottom) = (a.min().x, a.max().x, a.min().y, a.max().y);
        let px = |v: f64| x.world(v).map(|w| self.map.apply(Point::new(w, 0.0)).x);
        let x_ticks = self.thinned(x, &px, left, right, Direction::Across);
        for (k, t) in x_ticks.iter().enumerate() {
            let Some(p) = px(t.value).filter(|p| inside(*p, left, right)) else {
                continue;
            };
            let len = if t.label.is_some() || t.major {
                TICK
            } else {
                0.6 * TICK
            };
            marks.ticks = std::mem::take(&mut marks.ticks)
                .move_to(self.unmap(Point::new(p, bottom)))
                .line_to(self.unmap(Point::new(p, bottom + len)));
            marks.has_ticks = true;
            if let Some(label) = &t.label {
                items.push(self.text(
                    format!("{n}-tick-x-{}", k + 1),
                    Point::new(p, bottom + TICK + 9.0),
                    RichText::parse(label),
                    Align::Middle,
                    TextSize::Tick,
                ));
                if self.grid && (p - left).abs() > 0.5 && (p - right).abs() > 0.5 {
                    marks.grid = std::mem::take(&mut marks.grid)
                        .move_to(self.unmap(Point::new(p, bottom)))
                        .line_to(self.unmap(Point::new(p, top)));
                    marks.has_grid = true;
                }
            }
        }
    }

    /// The ordinate's ticks and grid lines into `marks`, its tick labels
    /// into `items`.
    fn y_ticks(&self, y: &Axis, items: &mut Vec<Item>, marks: &mut Marks) {
        let n = &self.name;
        let a = self.area;
        let (left, right, top, bottom) = (a.min().x, a.max().x, a.min().y, a.max().y);
        let py = |v: f64| y.world(v).map(|w| self.map.apply(Point::new(0.0, w)).y);
        let y_ticks = self.thinned(y, &py, top, bottom, Direction::Up);
        for (k, t) in y_ticks.iter().enumerate() {
            let Some(p) = py(t.value).filter(|p| inside(*p, top, bottom)) else {
                continue;
            };
            let len = if t.label.is_some() || t.major {
                TICK
            } else {
                0.6 * TICK
            };
            marks.ticks = std::mem::take(&mut marks.ticks)
                .move_to(self.unmap(Point::new(left, p)))
                .line_to(self.unmap(Point::new(left - len, p)));
            marks.has_ticks = true;
            if let Some(label) = &t.label {
                items.push(self.text(
                    format!("{n}-tick-y-{}", k + 1),
                    Point::new(left - TICK - 3.0, p),
                    RichText::parse(label),
                    Align::End,
                    TextSize::Tick,
                ));
                if self.grid && (p - bottom).abs() > 0.5 && (p - top).abs() > 0.5 {
                    marks.grid = std::mem::take(&mut marks.grid)
                        .move_to(self.unmap(Point::new(left, p)))
                        .line_to(self.unmap(Point::new(right, p)));
                    marks.has_grid = true;
                }
            }
        }
    }

    /// Zero lines where zero is strictly inside a linear range.
    fn zero_lines(&self, x: &Axis, y: &Axis, items: &mut Vec<Item>) {
        let n = &self.name;
        let a = self.area;
        let (left, right, top, bottom) = (a.min().x, a.max().x, a.min().y, a.max().y);
        let px = |v: f64| x.world(v).map(|w| self.map.apply(Point::new(w, 0.0)).x);
        let py = |v: f64| y.world(v).map(|w| self.map.apply(Point::new(0.0, w)).y);
        if let Some(p) = py(0.0).filter(|p| *p > top + 0.5 && *p < bottom - 0.5)
            && y.scale() == Scale::Linear
        {
            items.push(self.segment(
                format!("{n}-zero-y"),
                Role::Dimension,
                Point::new(left, p),
                Point::new(right, p),
            ));
        }
        if let Some(p) = px(0.0).filter(|p| *p > left + 0.5 && *p < right - 0.5)
            && x.scale() == Scale::Linear
        {
            items.push(self.segment(
                format!("{n}-zero-x"),
                Role::Dimension,
                Point::new(p, bottom),
                Point::new(p, top),
            ));
        }
    }

    /// Sets a block of lines in the corner of the plot area where it
    /// covers the fewest drawn points (and no other block).
    fn place(&mut self, block: &Block, taken: &mut Vec<(Point, Point)>) -> Vec<Item> {
        let (width, height) = block_size(&block.lines, self.font);
        let beside = self
            .legend_at
            .filter(|_| block.id == format!("{}-legend", self.name));
        let lo = match beside {
            Some(lo) => lo,
            None => self.corner(width, height, taken).0,
        };
        taken.push((lo, lo + Vector::new(width, height)));
        self.block_items(block, lo, width, height)
    }

    /// The corner of the plot area where a block `width` × `height`
    /// covers the fewest drawn points (and no block in `taken`), and how
    /// many it covers there.
    fn corner(&self, width: f64, height: f64, taken: &[(Point, Point)]) -> (Point, usize) {
        let a = self.area;
        let inset = 8.0;
        let xs = [
            a.max().x - inset - width,
            a.min().x + inset,
            a.min().x + 0.5 * (a.width() - width),
        ];
        let ys = [
            a.min().y + inset,
            a.max().y - inset - height,
            a.min().y + 0.5 * (a.height() - height),
        ];
        let mut best: Option<(f64, Point, usize)> = None;
        for (j, y) in ys.iter().enumerate() {
            for (i, x) in xs.iter().enumerate() {
                let lo = Point::new(*x, *y);
                let hi = Point::new(x + width, y + height);
                let hit = |p: &Point| {
                    p.x >= lo.x - 3.0 && p.x <= hi.x + 3.0 && p.y >= lo.y - 3.0 && p.y <= hi.y + 3.0
                };
                let count = self.drawn.iter().filter(|p| hit(p)).count();
                let covered = count as f64;
                let clash = taken.iter().any(|(l, h)| {
                    l.x < hi.x + 4.0 && h.x > lo.x - 4.0 && l.y < hi.y + 4.0 && h.y > lo.y - 4.0
                });
                // Corners first, then edges' middles, then the centre;
                // with `below`, the bottom row before the top.
                let row = match (self.below, j) {
                    (true, 0) => 1,
                    (true, 1) => 0,
                    _ => j,
                };
                let column = match (self.left_first, i) {
                    (true, 0) => 1,
                    (true, 1) => 0,
                    _ => i,
                };
                let order = (column.min(2) + row) as f64 * 0.01;
                let score = covered + if clash { 1e6 } else { 0.0 } + order;
                if best.is_none_or(|(s, _, _)| score < s) {
                    best = Some((score, lo, count));
                }
            }
        }
        best.map_or((Point::new(a.min().x, a.min().y), 0), |(_, lo, count)| {
            (lo, count)
        })
    }

    /// The items of `block` set with its top left corner at `lo` in a box
    /// `width` × `height`.
    fn block_items(&self, block: &Block, lo: Point, width: f64, height: f64) -> Vec<Item> {
        let mut items = Vec::new();
        if block.lines.iter().any(|(_, k)| k.is_some()) {
            let hi = lo + Vector::new(width, height);
            items.push(Item::new(
                format!("{}-box", block.id),
                Role::Dimension,
                Shape::Polyline {
                    points: vec![
                        self.unmap(lo),
                        self.unmap(Point::new(hi.x, lo.y)),
                        self.unmap(hi),
                        self.unmap(Point::new(lo.x, hi.y)),
                    ],
                    closed: true,
                },
            ));
        }
        for (k, (text, key)) in block.lines.iter().enumerate() {
            let y = lo.y + 4.0 + LEGEND_LINE * (k as f64 + 0.5);
            let mut x = lo.x + 7.0;
            match key {
                Some(Key::Line(dash)) => {
                    items.push(
                        self.segment(
                            format!("{}-key-{}", block.id, k + 1),
                            Role::Curve,
                            Point::new(x, y),
                            Point::new(x + KEY, y),
                        )
                        .dashed(*dash),
                    );
                    x += KEY + 8.0;
                }
                Some(Key::Marker(symbol)) => {
                    items.push(Item::new(
                        format!("{}-key-{}", block.id, k + 1),
                        Role::Curve,
                        Shape::Marker {
                            centre: self.unmap(Point::new(x + 0.5 * KEY, y)),
                            symbol: *symbol,
                        },
                    ));
                    x += KEY + 8.0;
                }
                None => {}
            }
            items.push(self.text(
                format!("{}-{}", block.id, k + 1),
                Point::new(x, y),
                text.clone(),
                Align::Start,
                TextSize::Tick,
            ));
        }
        items
    }

    /// A plot with axes whose legend no corner holds clear of what is
    /// drawn (a narrow or short page) with the legend set below the plot
    /// when it is wider than half the area, else beside it where that
    /// leaves the plot at least half its width
    /// ([`Plot::with_legend_below`], [`Plot::with_legend_beside`]); the
    /// curves, kept in world coordinates, follow the smaller area. A
    /// legend neither takes stays in its least covered corner.
    fn legend_clear_of_the_curves(self) -> Self {
        if self.axes.is_none() || self.legend_at.is_some() || self.legend.is_empty() {
            return self;
        }
        let (width, height) = block_size(&self.legend, self.font);
        if self.corner(width, height, &[]).1 == 0 {
            return self;
        }
        let wide = 2.0 * width > self.area.width();
        let plot = match wide {
            true => self.with_legend_below((width, height)),
            false => self,
        };
        // Below takes a wide legend; beside, a legend that leaves the
        // plot at least half its width.
        match plot.legend_at.is_none() && 2.0 * width <= plot.area.width() - LEGEND_GAP {
            true => plot.with_legend_beside(width),
            false => plot,
        }
    }

    /// The panel of a detail: [`Plot::finish`]'s, clipped to the plot
    /// area, and its caption lines in a panel of their own, not clipped
    /// (`None` without a caption), so that the links and circles running
    /// on beyond the region it enlarges end at the area's edge instead of
    /// crossing the caption below it.
    pub fn finish_detail(self) -> (Panel, Option<Panel>) {
        let (id, area, rect) = (self.panel_id(), self.area, self.rect);
        let caption = format!("{}-caption", self.name);
        let panel = self.finish();
        let transform = *panel.transform();
        let (captions, drawn): (Vec<Item>, Vec<Item>) =
            (panel.items().iter().cloned()).partition(|item| item.id.starts_with(&caption));
        let captions = (!captions.is_empty())
            .then(|| Panel::new(format!("{id}-caption"), rect, transform, captions));
        (Panel::new(id, area, transform, drawn).clipped(), captions)
    }

    /// The panel: axes, then what was added, then the legend and notes.
    pub fn finish(mut self) -> Panel {
        self = self.legend_clear_of_the_curves();
        let mut items = match &self.axes {
            Some((x, y)) => self.axis_items(x, y),
            None => Vec::new(),
        };
        items.append(&mut self.items);
        let mut blocks = Vec::new();
        if !self.legend.is_empty() {
            blocks.push(Block {
                id: format!("{}-legend", self.name),
                lines: std::mem::take(&mut self.legend),
            });
        }
        blocks.append(&mut self.blocks);
        let mut taken = Vec::new();
        for block in &blocks {
            let placed = self.place(block, &mut taken);
            items.extend(placed);
        }
        let lines = std::mem::take(&mut self.caption);
        let last = lines.len().saturating_sub(1);
        for (i, line) in lines.into_iter().enumerate() {
            let up = CAPTION_LINE * (last - i) as f64;
            let y = self.rect.max().y - 0.5 * CAPTION - up;
            let x = self.area.min().x + 0.5 * self.area.width();
            let id = match i {
                0 => format!("{}-caption", self.name),
                _ => format!("{}-caption-{}", self.name, i + 1),
            };
            items.push(self.text(id, Point::new(x, y), line, Align::Middle, TextSize::Small));
        }
        Panel::new(self.panel_id(), self.rect, self.map, items)
    }
}

/// The axes' tick marks and grid lines, gathered into two paths as the
/// ticks are drawn.
#[derive(Default)]
struct Marks {
    ticks: PathBuilder,
    grid: PathBuilder,
    has_ticks: bool,
    has_grid: bool,
}

/// Whether the page coordinate `p` lies within `lo..=hi` (to 0.01).
fn inside(p: f64, lo: f64, hi: f64) -> bool {
    p >= lo - 0.01 && p <= hi + 0.01
}

/// The width and height (page units) of a block of `lines`.
fn block_size(lines: &[(RichText, Option<Key>)], font: Font) -> (f64, f64) {
    let width = lines
        .iter()
        .map(|(t, key)| t.width(font, TICK_TEXT) + if key.is_some() { KEY + 8.0 } else { 0.0 })
        .fold(0.0, f64::max)
        + 14.0;
    (width, LEGEND_LINE * lines.len() as f64 + 8.0)
}

/// Whether `next` starts where `last` ends (within [`PIECES_MEET`]), so
/// that a dashed curve runs on from one into the other.
fn runs_on(last: &super::Subpath, next: &super::Subpath) -> bool {
    (next.start() - last.end()).norm() <= PIECES_MEET
}

#[cfg(test)]
mod tests {
    use super::*;

    fn plot() -> Plot {
        let x = Axis::linear("θ (°)", 0.0, 360.0)
            .unwrap()
            .with_step(90.0)
            .unwrap();
        let y = Axis::nice("y", -1.0, 1.0).unwrap();
        Plot::new(
            "p",
            Frame::from_origin_size(0.0, 0.0, 400.0, 300.0),
            x,
            y,
            0.01,
            Font::default(),
        )
        .unwrap()
    }

    #[test]
    fn the_map_takes_the_axis_ends_to_the_area_corners() {
        let p = plot();
        let a = p.area();
        let lo = p.map().apply(Point::new(0.0, -1.0));
        let hi = p.map().apply(Point::new(360.0, 1.0));
        assert!((lo - Point::new(a.min().x, a.max().y)).norm() < 1e-9);
        assert!((hi - Point::new(a.max().x, a.min().y)).norm() < 1e-9);
    }

    #[test]
    fn a_sine_is_traced_within_the_area_with_its_legend() {
        let mut p = plot();
        let sine = |t: f64| {
            let r = t.to_radians();
            Some((
                Point::new(t, r.sin()),
                Vector::new(1.0, r.cos() * std::f64::consts::PI / 180.0),
            ))
        };
        p.curve(
            "curve-sine",
            &[(&sine, 0.0..=360.0)],
            Dash::Solid,
            Some("sin θ"),
        )
        .unwrap();
        let panel = p.finish();
        assert!(panel.item("curve-sine").is_some());
        assert!(panel.item("p-legend-1").is_some());
        assert!(panel.item("p-tick-x-5").is_some());
        assert!(panel.item("p-zero-y").is_some());
        assert_eq!(panel.id(), "panel-p");
    }

    #[test]
    fn points_outside_the_area_keep_their_numbers() {
        let mut p = plot();
        p.points(
            "data",
            &[(10.0, 0.5), (20.0, 5.0), (30.0, -0.5)],
            Symbol::Disc,
            None,
        );
        let panel = p.finish();
        assert!(panel.item("data-1").is_some());
        assert!(panel.item("data-2").is_none());
        assert!(panel.item("data-3").is_some());
    }

    #[test]
    fn a_panel_too_small_for_its_axes_is_an_error() {
        let x = Axis::linear("x", 0.0, 1.0).unwrap();
        let y = Axis::linear("y", 0.0, 1.0).unwrap();
        assert!(
            Plot::new(
                "p",
                Frame::from_origin_size(0.0, 0.0, 60.0, 60.0),
                x,
                y,
                0.01,
                Font::default()
            )
            .is_err()
        );
    }

    #[test]
    fn log_axes_take_values() {
        let x = Axis::log("e", 1e-5, 1e-1).unwrap();
        let y = Axis::log("n", 1.0, 1e4).unwrap();
        let mut p = Plot::new(
            "b",
            Frame::from_origin_size(0.0, 0.0, 400.0, 300.0),
            x,
            y,
            0.01,
            Font::default(),
        )
        .unwrap();
        assert_eq!(p.world_point(1e-3, 100.0), Some(Point::new(-3.0, 2.0)));
        assert_eq!(p.world_point(0.0, 100.0), None);
        p.line(
            "series",
            &[(1e-4, 10.0), (1e-3, 100.0)],
            Dash::Dashed,
            Some("a"),
        );
        let panel = p.finish();
        let Some(Shape::Polyline { points, .. }) = panel.item("series").map(|i| &i.shape) else {
            panic!("a polyline")
        };
        assert_eq!(points[0], Point::new(-4.0, 1.0));
    }
}
