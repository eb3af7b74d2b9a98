//! The layout: a figure's items placed on the page. Each panel's items are
//! mapped to the page by the panel's one transform and made into marks
//! (paths, circles, texts) in drawing order, each symbol telling the label
//! placement what it covers; then the labels are placed clear of
//! everything drawn, with leaders where a letter stands off, and the lines
//! that open for letters (the line of stroke, angle marks, hatching, a
//! detail's frame) are made with their gaps. What comes out,
//! [`PlacedFigure`], has every place decided: the writers (SVG, and PNG
//! and PDF through it) only write it.
//!
//! Each item is made by the function of its symbol, one family to a file:
//! lines (`lines.rs`: paths, polylines, regions, circles, arcs), points
//! (`points.rs`: pins, dots, markers), the frame (`frame.rs`: bearing,
//! hatching, slider block), marks (`marks.rs`: arrows, right-angle and
//! angle marks, dimensions) and text (`notes.rs`: labels, fixed texts,
//! notes).

mod angle_leader;
mod centre;
mod cull;
mod frame;
mod hatching;
mod labels;
mod line_leader;
mod lines;
mod mark;
mod marks;
mod markup;
mod notes;
mod placed;
mod points;
mod symbol_sizes;
mod text;

use crate::figure::{Figure, Font, Item, PageFromWorld, Panel, Part, RichText, Role, Shape};
use crate::figure::{Pen, SMALL_DETAIL_EMS, Style};
use crate::geom::{Frame, Point, Vector};
use labels::{
    NEARER, Obstacles, ROOM, STRUCK, Steer, TOO_NEAR, Wedge, box_nearer_another, over_the_other,
    place_toward,
};
pub use mark::{
    Mark, Paint, PathCommand, PathData, Shape as MarkShape, Stroke, TextAnchor, TextMark,
};
use markup::{finite, path, polyline_d, unit};
pub use placed::{PlacedFigure, PlacedPanel};
use std::cell::Cell;
use std::f64::consts::FRAC_PI_2;
use text::{ink_box, starts_italic, text_node};

/// Two joints nearer than this many ems inside one small detail's frame
/// (its sides under [`SMALL_DETAIL_EMS`]) are lettered in the detail only:
/// on the main view their letters would pile on each other and on the
/// frame's magnification (the crank of a long rod, a few units across).
const CROWDED_EMS: f64 = 2.0;
/// The farthest a label's glyphs may be put from its anchor, in font
/// sizes: 1.5 em, less the side bearing (up to about 0.15 em) by which an
/// italic letter's ink sits inside its advance, less a margin.
const REACH: f64 = 1.3;

/// The farthest a point's letter stands from its point on the rings, in
/// font sizes, glyphs to point: a reader takes a letter within an em and
/// a half for its point's. The box, measured on the ink with [`ROOM`]
/// about it, keeps a unit inside that more, for the glyphs' side
/// bearings.
const LETTER_FARTHEST: f64 = 1.5;

/// How far, in font sizes, a name or a value (not a point's letter) looks
/// for a clear place when none within [`REACH`] is: first within 2.5 em,
/// then within 4 (a value names what it gives, "l = 1.05 r", and reads
/// from farther off than a letter, but not from anywhere).
const WIDE_REACH: [f64; 2] = [2.5, 4.0];

/// How far, in font sizes, a text naming a line looks last for a place
/// beside that line and nearer it than any other link (a short rod's
/// "l = 1.05 r" by a crank and the letters about it): it names the line
/// it stands beside, so it may stand farther off than a value by a point.
const LINE_REACH: f64 = 6.0;

/// Where along its line (from its first end) a text naming a line is
/// tried, in turn: its middle, then towards either end, until a place is
/// clear.
const ALONG_LINE: [f64; 5] = [0.5, 0.35, 0.65, 0.2, 0.8];

/// What each page unit an angle's letter stands out from the point of
/// its arc it was tried at costs ([`ALONG_ARC`]): 20 units out cost 2,
/// more than a clear place beside another point of the arc, less than
/// a crowded one.
const ARC_STRAY: f64 = 0.1;

/// The room (page units) an angle's letter keeps from each leg of its
/// angle: a link's half width and a letter's clearance. A sector whose
/// chord a letter's height beyond its arc is narrower than the letter and
/// this either side cannot hold it, and its letter stands beside it.
const LEG_ROOM: f64 = 3.0;

/// What a place outside its angle costs an angle's letter more: more
/// than a clear place 10 units out from its arc (Ng's φ above its dashed
/// reference read as the angle above it).
const OUTSIDE_ANGLE: f64 = 1.0;

/// How far (page units, past its gap) an angle's letter may stand out
/// from the point of its arc it was tried at and still end the search.
const ARC_CLOSE: f64 = 4.0;

/// Where along its arc (from its start) an angle's letter is tried, in
/// turn: beyond its middle, then towards either arm, until a place is
/// clear. θ at 180° with the rod across the top of its half-circle stood
/// 50 units above the circle, its arc's middle crowded (Fig. 62, offset).
pub(super) const ALONG_ARC: [f64; 5] = [0.5, 0.35, 0.65, 0.22, 0.78];

/// The room, in font sizes, kept on either side of a name or a value
/// placed within [`WIDE_REACH`] (about a word space).
const WIDE_ROOM: f64 = 0.3;

/// A label waiting to be placed once every line is known.
#[derive(Clone)]
struct Pending {
    id: String,
    anchor: Point,
    text: RichText,
    size: f64,
    gap: f64,
    /// Whether it is a point's letter, placed before the values and
    /// names, which are freer to move.
    letter: bool,
    /// The page direction tried first, out to the last ring (an angle's
    /// bisector), if any.
    toward: Option<Vector>,
    /// Whether it is a joint's letter (a pin of the mechanism), which a
    /// detail whose frame holds the pin letters too.
    joint: bool,
    /// The page line the text names, if any (a link's length).
    line: Option<(Point, Point)>,
    /// The places an angle's letter is tried at in turn, each a point of
    /// its arc and the page direction out from the arc's centre there
    /// ([`ALONG_ARC`]): beyond its middle where that is clear, else beyond
    /// another point of it, before it looks farther off. Empty for any
    /// other label.
    along: Vec<(Point, Vector)>,
    /// An angle's vertex, the page direction of its middle and half its
    /// size (radians): a place for its letter outside the angle costs
    /// [`OUTSIDE_ANGLE`] more. None for any other label.
    wedge: Option<(Point, Vector, f64)>,
}

impl Pending {
    /// Whether the label says what it marks, and so may stand farther
    /// from it than a letter ([`WIDE_REACH`]): a name or a value, or a
    /// letter with words ("D at ∞" at an arrow towards a point off the
    /// page); not a letter alone, read with what is nearest, nor the
    /// joint letter of points that coincide ("*O*, *M*"), whose names
    /// are letters alone parted by commas: crossed within reach, it goes
    /// farther out with a leader to its point, as a letter does.
    fn names_itself(&self) -> bool {
        !self.letter || (self.text.plain().split(", ")).any(|name| name.contains(' '))
    }
}

/// What an item's symbol is written with: its id, its role (the class)
/// and its pen.
struct Ink<'a> {
    id: &'a str,
    role: Role,
    pen: Pen,
    /// What the item is, where code tells it apart.
    part: Part,
}

impl Ink<'_> {
    /// `mark` with the item's id and class.
    fn tag(&self, mark: Mark) -> Mark {
        mark.tagged(self.id, self.role.name())
    }
}

/// The layout of one panel: its map, and what labels must keep clear of.
struct PanelLayout<'a> {
    t: &'a PageFromWorld,
    page_width: f64,
    style: Style,
    font: Font,
    obstacles: Obstacles,
    pending: Vec<Pending>,
    /// Lines that open for letters, to write again once the labels are
    /// placed.
    open_lines: Vec<centre::OpenLine>,
    /// Hatchings to write again once the labels are placed.
    hatchings: Vec<hatching::Hatching>,
    /// The angle marks' radii: (page vertex, size of the sweep, radius).
    angle_radii: Vec<(Point, f64, f64)>,
    /// Whether the panel is a detail (clipped to its rectangle), where
    /// the slider's block is enlarged.
    detail: bool,
    /// The page boxes of the detail marks drawn (a detail's frame on the
    /// main view, its border).
    detail_marks: Vec<Frame>,
    /// The straight pieces of the construction, result and auxiliary lines drawn
    /// (page points), which the hatching is broken for.
    crossing: Vec<(Point, Point)>,
    /// The page centres of the pins and constructed points drawn, which
    /// a point's letter keeps nearer its own than.
    points: Vec<Point>,
    /// The page centres of the constructed points left to a detail
    /// (undrawn here, where lines drawn meet): a joint's letter whose pin
    /// lies in the detail's frame that stands nearer one of these than
    /// its own pin is left to the detail (Kisch's A under the foot F, G).
    quiet: Vec<Point>,
    /// The links and forces drawn (page segments), which a text naming a
    /// line keeps nearer its own than.
    links: Vec<(Point, Point)>,
    /// The dimension lines drawn (page segments), which a text naming a
    /// line keeps nearer its own than where it can.
    dimensions: Vec<(Point, Point)>,
    /// The outlines of the bodies drawn (page points), over which a link
    /// is drawn with a rim of paper.
    bodies: Vec<Vec<Point>>,
    /// The sides of the blocks and bars drawn (page segments, each one's
    /// closed outline): a letter set on a block's side names the block,
    /// and keeps nearer it than any link.
    blocks: Vec<Vec<(Point, Point)>>,
    /// The bearings drawn (page segments: each one's triangle, foot and
    /// the far edge of its hatching), which a block's letter keeps
    /// farther from than from its block.
    grounds: Vec<(Point, Point)>,
}

impl PanelLayout<'_> {
    /// The page point of a world point.
    fn p(&self, w: Point) -> Point {
        self.t.apply(w)
    }

    /// 1 where the map keeps the world's sense of turning, −1 where it
    /// mirrors it.
    fn orientation(&self) -> f64 {
        let [a, b, c, d, _, _] = self.t.coefficients();
        if a * d - b * c < 0.0 { -1.0 } else { 1.0 }
    }

    /// The pen of an item: its role's, with its own dash and hue.
    fn pen(&self, item: &Item) -> Pen {
        let mut pen = self.style.pen(item.role);
        if let Some(dash) = item.dash {
            pen.dash = Style::dash(dash);
            if let Some(colour) = self.style.series(dash) {
                pen.colour = colour;
            }
        }
        if let Some(colour) = item.hue.and_then(|h| self.style.hue(h)) {
            pen.colour = colour;
        }
        pen
    }

    /// The item drawn by its symbol's function; `None` where nothing is
    /// written now (labels, placed later) or the item is off the map.
    fn item(&mut self, item: &Item) -> Option<Mark> {
        let ink = Ink {
            id: &item.id,
            role: item.role,
            pen: self.pen(item),
            part: item.part,
        };
        self.obstacles.set_weight(match item.role {
            // A letter may sit on a centre line, which opens for it.
            _ if centre::is_centre_line(item.part) => centre::WEIGHT,
            // An angle mark's arc opens for a letter too.
            _ if matches!(item.shape, Shape::AngleMark { .. }) => centre::WEIGHT,
            // Hatching is as bad to letter over as a link.
            Role::Link | Role::Force | Role::Frame => 3.0,
            Role::Construction | Role::Result => 1.5,
            _ => 1.0,
        });
        // Hatching and a detail's frame are written again with a gap
        // where a letter sits: a letter with no clean place goes there.
        let opens = matches!(item.shape, Shape::Hatch { .. }) || item.part == Part::DetailMark;
        self.obstacles.set_opens(opens);
        match &item.shape {
            Shape::Path(p) => self.fitted_path(&ink, p),
            Shape::Polyline { points, closed } => self.polyline(&ink, points, *closed, item.part),
            Shape::Region { points } => self.region(&ink, points),
            Shape::Circle { centre, radius } => self.circle(&ink, *centre, *radius),
            Shape::Arc {
                centre,
                radius,
                start,
                sweep,
                arrow,
            } => self.arc(&ink, *centre, *radius, (*start, *sweep), *arrow),
            Shape::Pin { centre } => self.pin(&ink, *centre),
            // A constructed point left to a detail: undrawn here, but a
            // point a joint's letter in the detail's frame that stands
            // nearer it than its own pin is left to the detail for.
            Shape::Dot { centre } if item.part == Part::DetailMark => {
                let c = self.p(*centre);
                if finite(&c) {
                    self.quiet.push(c);
                }
                None
            }
            Shape::Dot { centre } => self.dot(&ink, *centre),
            Shape::Marker { centre, symbol } => self.marker(&ink, *centre, *symbol),
            Shape::Bearing { centre, foot } => self.bearing(&ink, *centre, *foot),
            Shape::Hatch { from, to, side } => self.hatch(&ink, *from, *to, *side),
            Shape::Block { points } => self.block(&ink, points),
            Shape::Body { points } => self.body(&ink, points),
            Shape::Arrow { from, to } => self.arrow(&ink, *from, *to),
            Shape::RightAngle { vertex, u, v } => self.right_angle(&ink, *vertex, *u, *v),
            Shape::AngleMark {
                vertex,
                start,
                sweep,
                text,
            } => self.angle_mark(&ink, *vertex, (*start, *sweep), text.as_ref()),
            Shape::Dimension {
                from,
                to,
                side,
                offset,
                text,
            } => self.dimension(&ink, (*from, *to), *side, *offset, text),
            Shape::Label {
                anchor,
                text,
                size,
                toward,
                line,
            } => self.label(&ink, *anchor, text, *size, (*toward, *line)),
            Shape::Text {
                at,
                offset,
                text,
                align,
                size,
            } => self.text(&ink, (*at, *offset), text, *align, *size),
            Shape::Note { corner, lines } => self.note(&ink, *corner, lines),
        }
    }
}

/// Where an item is drawn in its panel: by role (later on top), tinted
/// regions under the role's lines and pins over them.
fn draw_order(role: Role, shape: &Shape) -> (usize, usize) {
    let r = Role::ALL.iter().position(|x| *x == role).unwrap_or(0);
    let s = match shape {
        Shape::Region { .. } => 0,
        Shape::Pin { .. } => 2,
        _ => 1,
    };
    (r, s)
}

/// A panel placed: its items made into marks in drawing order (those a
/// detail's rectangle cannot show left out), then its labels placed in
/// `room` clear of everything drawn, the lines that open for letters made
/// with their gaps.
fn place_panel(panel: &Panel, style: Style, font: Font, room: &Frame) -> PlacedPanel {
    let t = panel.transform();
    let mut w = PanelLayout {
        t,
        page_width: room.max().x,
        style,
        font,
        obstacles: Obstacles::default(),
        pending: Vec::new(),
        open_lines: Vec::new(),
        hatchings: Vec::new(),
        angle_radii: Vec::new(),
        detail: panel.is_clipped(),
        detail_marks: Vec::new(),
        crossing: Vec::new(),
        points: Vec::new(),
        quiet: Vec::new(),
        links: Vec::new(),
        dimensions: Vec::new(),
        bodies: Vec::new(),
        blocks: Vec::new(),
        grounds: Vec::new(),
    };
    let clip = panel.is_clipped().then(|| *panel.rect());
    let mut order: Vec<(usize, &Item)> = panel
        .items()
        .iter()
        .enumerate()
        .filter(|(_, item)| clip.is_none_or(|r| cull::may_show(t, &r, &item.shape)))
        .collect();
    order.sort_by_key(|(i, item)| (draw_order(item.role, &item.shape), *i));
    let shown: Vec<&Item> = order.iter().map(|(_, item)| *item).collect();
    w.angle_radii = marks::angle_radii(t, &shown);
    let mut marks: Vec<Mark> = Vec::new();
    for (_, item) in &order {
        let (lines, hatchings) = (w.open_lines.len(), w.hatchings.len());
        if let Some(mark) = w.item(item) {
            if let Some(line) = w.open_lines.get_mut(lines) {
                line.node = marks.len();
            }
            if let Some(hatching) = w.hatchings.get_mut(hatchings) {
                hatching.node = marks.len();
            }
            marks.push(mark);
        }
    }
    let (texts, boxes) = w.place_labels(room);
    for line in &w.open_lines {
        if let Some(mark) = marks.get_mut(line.node) {
            // A line the letters leave nothing of is left empty.
            *mark = line.written(&boxes).unwrap_or_else(Mark::group);
        }
    }
    // A hatching every stroke of which lies under letters is left empty.
    for hatching in &w.hatchings {
        if let Some(mark) = marks.get_mut(hatching.node) {
            *mark = hatching
                .written(&boxes, &w.crossing)
                .unwrap_or_else(Mark::group);
        }
    }
    marks.extend(texts);
    PlacedPanel::new(panel, marks)
}

/// The figure laid out: every panel's items and labels placed on the
/// page ([`PlacedFigure`]), which a writer only writes. Labels stay a
/// little inside the page, and in their panel or just beside it (a
/// detail's inside its frame).
pub fn place(figure: &Figure) -> PlacedFigure<'_> {
    let (w, h) = (figure.width(), figure.height());
    let page = Frame::from_origin_size(2.0, 2.0, w - 4.0, h - 4.0);
    let panels = (figure.panels().iter())
        .map(|panel| {
            let room = label_room(panel, &page);
            place_panel(panel, figure.style(), figure.font(), &room)
        })
        .collect();
    PlacedFigure::new(figure, panels)
}

impl PanelLayout<'_> {
    /// The pending labels placed in `room` one by one, the points'
    /// letters first, each clear of what is drawn and of the labels
    /// before it: their text elements and their boxes. Where some label
    /// could not keep its glyphs clear, the labels are placed once more
    /// with those first (an earlier label may have taken the one place
    /// they had), and the better of the two placings is kept: fewer
    /// labels crossed by what stays once written (a letter on hatching or
    /// on a detail's frame is not: both open for it), then fewer struck
    /// labels, then less cost.
    fn place_labels(&mut self, room: &Frame) -> (Vec<Mark>, Vec<Frame>) {
        let mut pending = std::mem::take(&mut self.pending);
        let halves: Vec<Vector> = (pending.iter())
            .map(|p| ink_box(&p.text, p.size, self.font).0)
            .collect();
        self.obstacles.build(room, &halves);
        pending.sort_by_key(|p| !p.letter);
        let start = self.obstacles.mark();
        let (order, placed) = self.arranged(&pending, room, start);
        // A detail's joint letter of points that coincide there ("B, E,
        // F, H" under Kisch's crank pin) stays one letter by its pin even
        // where it finds no clear place: parted, each name stood at a
        // corner of the pin with no dot of its own to read it by, and
        // the reader could not tell which point was which.
        let joints: Vec<Point> = (order.iter())
            .filter(|p| p.joint)
            .map(|p| p.anchor)
            .collect();
        let mut nodes = Vec::new();
        let mut boxes = Vec::new();
        for (p, at) in order.into_iter().zip(placed) {
            let others = self.others(p, p.size);
            if !self.left_to_detail(p, &at, &joints, (joints.iter()).chain(&others)) {
                nodes.extend(self.label_nodes(p, &at));
                boxes.push(at.bounds);
            }
        }
        (nodes, boxes)
    }

    /// The `pending` labels placed (in their order, or, where some could
    /// not keep clear, in a better one), the obstacles rolled back to
    /// `start` between tries: the order kept and the places.
    fn arranged<'p>(
        &mut self,
        pending: &'p [Pending],
        room: &Frame,
        start: labels::Mark,
    ) -> (Vec<&'p Pending>, Vec<Placed>) {
        let first: Vec<&Pending> = pending.iter().collect();
        let placed = self.placing(&first, room);
        // Labels crossed once written (a hatching and a detail's frame
        // open for theirs), then struck, then the cost.
        let struck = |placed: &[Placed]| {
            let lasting = placed.iter().filter(|p| p.lasting).count();
            let n = placed.iter().filter(|p| p.cost >= STRUCK).count();
            (lasting, n, placed.iter().map(|p| p.cost).sum::<f64>())
        };
        let (lasting, n, cost) = struck(&placed);
        let (order, placed) = if n == 0 {
            (first, placed)
        } else {
            self.obstacles.rollback(start);
            let (lost, kept): (Vec<_>, Vec<_>) = first
                .iter()
                .zip(&placed)
                .partition(|(_, p)| p.cost >= STRUCK);
            let again: Vec<&Pending> = lost.into_iter().chain(kept).map(|(p, _)| *p).collect();
            let second = self.placing(&again, room);
            let mut best = if struck(&second) < (lasting, n, cost) {
                (again, second)
            } else {
                (first.clone(), placed)
            };
            if best.1.iter().any(|p| p.lasting) {
                // Some letter is crossed anyway: once more with hatching
                // and frames taken for what they are, lines that open.
                self.obstacles.rollback(start);
                self.obstacles.set_openings_strike(false);
                let third = self.placing(&first, room);
                self.obstacles.set_openings_strike(true);
                if struck(&third) < struck(&best.1) {
                    best = (first, third);
                }
            }
            best
        };
        (order, placed)
    }

    /// A placed label's text, then its leader if it has one.
    fn label_nodes(&self, p: &Pending, at: &Placed) -> impl Iterator<Item = Mark> {
        let pen = self.style.pen(Role::Label);
        let text = text_node(
            &p.id,
            at.at,
            &p.text,
            p.size,
            pen.colour,
            TextAnchor::Middle,
            starts_italic(&p.text),
        );
        let leader = at.leader.map(|(a, b)| {
            // `label-B` → `leader-B`, a detail's `detail-label-B` →
            // `detail-leader-B`; any other id `leader-` before it.
            let id = match p.id.split_once("label-") {
                Some((prefix, rest)) => format!("{prefix}leader-{rest}"),
                None => format!("leader-{}", p.id),
            };
            path(polyline_d(&[a, b], false), pen).tagged(id, "leader")
        });
        std::iter::once(text).chain(leader)
    }

    /// Whether a label is left out here and to the detail: a joint's
    /// letter on the main view, where the pin lies inside a detail's
    /// frame (the detail enlarges everything in its frame and letters the
    /// pin there, clear), that is crossed by a line that stays, shares
    /// a small frame with another of the `joints` within [`CROWDED_EMS`]
    /// (the crank of a long rod, a few units across: its letters piled on
    /// the frame's magnification), or stands nearer another of the `near`
    /// points (the other joints, the points drawn over an em away) than
    /// its own by more than [`NEARER`] (two pins a few units apart, A's
    /// letter beyond C).
    fn left_to_detail<'p>(
        &self,
        p: &Pending,
        at: &Placed,
        joints: &[Point],
        mut near: impl Iterator<Item = &'p Point>,
    ) -> bool {
        if !self.in_detail_frame(p) {
            return false;
        }
        let own = at.bounds.distance_to(p.anchor);
        let crowded = || {
            joints.iter().any(|&q| {
                q != p.anchor
                    && (q - p.anchor).norm() < CROWDED_EMS * p.size
                    && (self.detail_marks.iter()).any(|m| {
                        let side = (m.max() - m.min()).max();
                        m.contains(p.anchor) && m.contains(q) && side < SMALL_DETAIL_EMS * p.size
                    })
            })
        };
        let mut nearer = || near.any(|&q| q != p.anchor && at.bounds.distance_to(q) + NEARER < own);
        at.lasting || crowded() || nearer()
    }

    /// [`others`], and for a joint's letter whose pin lies in a detail's
    /// frame the points left to the detail too ([`PanelLayout::quiet`]):
    /// those it may not stand nearer than its own pin, else it is left
    /// to the detail.
    fn others(&self, p: &Pending, beyond: f64) -> Vec<Point> {
        let mut near = others(p, &self.points, beyond);
        if self.in_detail_frame(p) && !near.is_empty() {
            near.extend((self.quiet.iter()).filter(|q| (**q - p.anchor).norm() > beyond));
        }
        near
    }

    /// Whether a label is a joint's letter on the main view whose pin
    /// lies inside a detail's frame, the detail lettering it too.
    fn in_detail_frame(&self, p: &Pending) -> bool {
        p.joint && !self.detail && self.detail_marks.iter().any(|m| m.contains(p.anchor))
    }

    /// The labels placed in the `order` given, each box added to the
    /// obstacles as it is placed.
    fn placing(&mut self, order: &[&Pending], room: &Frame) -> Vec<Placed> {
        order
            .iter()
            .map(|p| {
                let others = others(p, &self.points, 0.0);
                let rivals = rivals(p, &self.links);
                let block = block_of(p, &self.points, &self.blocks);
                // A bar's sides are links too: its own are not its rivals.
                let unlike_block: Vec<(Point, Point)> = match block {
                    Some(own) => (self.links.iter().chain(&self.grounds))
                        .filter(|l| !own.contains(l))
                        .copied()
                        .collect(),
                    None => Vec::new(),
                };
                let (half, shift) = ink_box(&p.text, p.size, self.font);
                // The box keeps [`ROOM`] about the glyphs: its reach is that less.
                let reach = REACH * p.size - ROOM;
                // An angle's letter keeps within its sector where that is
                // wide enough to hold it just beyond its arc.
                let sector = Cell::new(p.wedge.and_then(|(vertex, middle, half_angle)| {
                    let out = (p.anchor - vertex).norm() + 2.0 * half.y;
                    let chord = 2.0 * out * half_angle.min(FRAC_PI_2).sin();
                    (chord >= 2.0 * (half.x + LEG_ROOM)).then_some(Wedge {
                        vertex,
                        middle,
                        half: half_angle,
                    })
                }));
                let place_from =
                    |anchor: Point, toward: Option<Vector>, reach: f64, half: Vector| {
                        place_toward(
                            anchor,
                            half,
                            p.gap,
                            reach,
                            Steer {
                                toward,
                                others: &others,
                                pair: p.size,
                                line: p.line.map(|own| (own, rivals.as_slice())),
                                dimensions: &self.dimensions,
                                block: block.map(|own| (own, unlike_block.as_slice())),
                                led: None,
                                near_first: p.letter && p.along.is_empty() && p.line.is_none(),
                                farthest: (p.letter && p.along.is_empty() && p.line.is_none())
                                    .then_some(LETTER_FARTHEST * p.size - 2.0 * ROOM),
                                apart: APART_EMS * p.size,
                                back: p.letter
                                    && p.along.is_empty()
                                    && p.line.is_none()
                                    && self.points.contains(&p.anchor),
                                head_first: p.joint && p.text.plain().contains(", "),
                                wedge: sector.get(),
                            },
                            &self.obstacles,
                            room,
                        )
                    };
                let place_at = |anchor: Point, reach: f64, half: Vector| {
                    place_from(anchor, p.toward, reach, half)
                };
                // A text naming a line is set by its middle where a place
                // there is clear, else by another point along it; an
                // angle's letter likewise along its arc.
                let place = |reach: f64, half: Vector| {
                    let tries: Vec<(Point, Option<Vector>)> = match p.line {
                        Some((a, b)) => (ALONG_LINE.iter())
                            .map(|t| (a + (b - a) * *t, p.toward))
                            .collect(),
                        None if !p.along.is_empty() => {
                            p.along.iter().map(|&(at, u)| (at, Some(u))).collect()
                        }
                        None => return place_at(p.anchor, reach, half),
                    };
                    let arc = p.line.is_none();
                    let (mut best, mut score) = ((p.anchor, f64::INFINITY), f64::INFINITY);
                    for (anchor, toward) in tries {
                        let at = place_from(anchor, toward, reach, half);
                        // An angle's letter clear but far out from this
                        // point of its arc scores less than one clear
                        // beside another point of it.
                        let stray = match arc {
                            true => {
                                (Frame::around(at.0, half).distance_to(anchor) - p.gap).max(0.0)
                            }
                            false => 0.0,
                        };
                        let outside = p.wedge.is_some_and(|(c, mid, half)| {
                            unit(at.0 - c).is_some_and(|u| u.dot(&mid) < half.cos())
                        });
                        let here =
                            at.1 + ARC_STRAY * stray + f64::from(u8::from(outside)) * OUTSIDE_ANGLE;
                        if here < score {
                            (best, score) = (at, here);
                        }
                        if best.1 < 1.0 && stray <= ARC_CLOSE {
                            break;
                        }
                    }
                    best
                };
                let lasting = |(centre, cost): (Point, f64)| {
                    cost >= STRUCK
                        && (self.obstacles).lasting(&Frame::around(centre, half), p.anchor)
                };
                let mut best = place(reach, half);
                // An angle's letter crowded in its sector stands beyond its
                // arc with a leader; where that finds no room either and
                // every place in the sector is struck, the best outside it,
                // with a leader to its arc.
                let mut angle_led = self.angle_leader(p, half, best.1, room);
                if let Some((led, _)) = angle_led {
                    best = led;
                } else if best.1 >= STRUCK && sector.take().is_some() {
                    best = Some(place(reach, half))
                        .filter(|free| free.1 < best.1)
                        .unwrap_or(best);
                    angle_led = (self.outside_leader(p, best.0, half)).map(|line| (best, line));
                }
                // A text naming a line whose nearest place names another
                // link looks further out too.
                let misnames = |(_, cost): (Point, f64)| p.line.is_some() && cost >= STRUCK;
                // Within half an em of another text, its glyphs clear.
                let crowds = |(centre, cost): (Point, f64)| {
                    let grown = Frame::around(centre, half).inflate(APART_EMS * p.size);
                    (TOO_NEAR..STRUCK).contains(&cost) && self.obstacles.meets_a_text(&grown)
                };
                // A link's name keeps its place by its link (farther
                // out it reads as another's): only a value or a scale
                // looks farther for room from the texts.
                let crowded = p.line.is_none() && crowds(best);
                if p.names_itself() && (lasting(best) || misnames(best) || crowded) {
                    // A name or a value crossed within a letter's reach by
                    // a line that stays (a detail's magnification beside a
                    // frame among crowding pins) looks further out, no
                    // point holding it near, with a space's room on each
                    // side so that it does not read as one word with a
                    // letter beside it; one within half an em of another
                    // text ("E″×20"), for a place clear of the texts.
                    let room = Vector::new(WIDE_ROOM * p.size, 0.0);
                    let farther = p.line.map(|_| LINE_REACH);
                    for far in WIDE_REACH.into_iter().chain(farther) {
                        let wide = place(far * p.size - ROOM, half + room);
                        if !lasting(wide) && !misnames(wide) && (!crowded || wide.1 < TOO_NEAR) {
                            best = wide;
                            break;
                        }
                    }
                }
                let mut leader = angle_led.map(|(_, line)| line);
                if let Some((led, line)) = self.line_leader(p, half, best.1, room) {
                    best = led;
                    leader = Some(line);
                }
                let framed = self.in_detail_frame(p);
                // Whether a place stands nearer another point than its
                // own, measured from its middle.
                let over = |(centre, _): (Point, f64)| {
                    over_the_other(&Frame::around(centre, half), p.anchor, &others)
                };
                // Whether its box stands nearer another point than its
                // own, however little: read as the other's.
                let nearer = |(centre, _): (Point, f64)| {
                    box_nearer_another(&Frame::around(centre, half), p.anchor, &others)
                };
                let crossed = lasting(best);
                if !p.names_itself()
                    && self.points.contains(&p.anchor)
                    && !framed
                    && (crossed || over(best) || crowds(best) || nearer(best))
                {
                    // A point's letter crossed within reach by a line
                    // that stays goes to a clear place farther out, a
                    // leader drawn from it to the point, as a draughtsman
                    // letters a point with no room beside it (a pin in a
                    // detail's frame is left to the detail instead), the
                    // leader through no label, part or marker.
                    // A place whose leader runs along a line drawn (the
                    // crank beside its centre, the leader lost in it) or
                    // through a box is shut, and the next best looked for.
                    // So too a letter with no clear place whose nearest
                    // point is its own: it stands where it must, nearer
                    // another point, with a leader to its own however
                    // near it stands.
                    let far_reach = LEADER_REACH * p.size - ROOM;
                    let mark = self.obstacles.mark();
                    let mut found = None;
                    for _ in 0..LEADER_TRIES {
                        let far = place_toward(
                            p.anchor,
                            half,
                            p.gap,
                            far_reach,
                            Steer {
                                toward: p.toward,
                                others: &others,
                                pair: p.size,
                                line: None,
                                dimensions: &self.dimensions,
                                block: None,
                                led: None,
                                near_first: p.letter && p.along.is_empty(),
                                farthest: None,
                                apart: APART_EMS * p.size,
                                back: false,
                                head_first: false,
                                wedge: None,
                            },
                            &self.obstacles,
                            room,
                        );
                        let b = Frame::around(far.0, half);
                        if far.1 >= STRUCK && self.obstacles.lasting(&b, p.anchor) {
                            break;
                        }
                        let within = match over(far) {
                            true => LEADER_LEAST,
                            false => reach,
                        };
                        let line = leader_line(&b, p.anchor, within);
                        let clear = line.is_none_or(|(a, b)| {
                            !self.obstacles.crosses_a_box(a, b, p.anchor)
                                && !self.obstacles.runs_along(a, b)
                        });
                        // A far place whose box stands nearer another
                        // point than its own reads as the other's, its
                        // leader notwithstanding: shut, as one whose
                        // leader is not clear; so is one beyond a
                        // letter's reach with no leader.
                        let held = line.is_some() || b.distance_to(p.anchor) <= reach;
                        if clear && held && !box_nearer_another(&b, p.anchor, &others) {
                            found = Some((far, line));
                            break;
                        }
                        self.obstacles.boxed(b);
                    }
                    self.obstacles.rollback(mark);
                    // A letter that looked farther only for standing over
                    // another point or nearer it, or within half an em of
                    // another text, takes a place there that reads as its
                    // own and is clear (of the other texts too, where it
                    // stood too near one), else keeps its own, with a
                    // leader where it stands over another point far
                    // enough out for one.
                    let better = |far: (Point, f64)| {
                        far.1 < STRUCK && !over(far) && (over(best) || far.1 < TOO_NEAR)
                    };
                    match found {
                        Some((far, line)) if crossed || better(far) => {
                            best = far;
                            leader = line;
                        }
                        _ if over(best) => {
                            let b = Frame::around(best.0, half);
                            leader = leader_line(&b, p.anchor, LEADER_LEAST).filter(|&(a, b)| {
                                !self.obstacles.crosses_a_box(a, b, p.anchor)
                                    && !self.obstacles.runs_along(a, b)
                            });
                        }
                        _ => {}
                    }
                }
                let (centre, cost) = best;
                let bounds = Frame::around(centre, half);
                let lasting = cost >= STRUCK && self.obstacles.lasting(&bounds, p.anchor);
                self.obstacles.text(bounds);
                if let Some((a, b)) = leader {
                    self.obstacles.set_weight(1.0);
                    self.obstacles.segment(a, b);
                }
                Placed {
                    at: centre + shift,
                    bounds,
                    cost,
                    lasting,
                    leader,
                }
            })
            .collect()
    }
}

/// The points a label's place keeps farther from than from its own:
/// for a point's letter, every other point drawn more than `beyond`
/// from it (a pair nearer than an em is read as one place, their letters
/// as a pair, [`Steer::pair`]); for any other label, none.
fn others(p: &Pending, points: &[Point], beyond: f64) -> Vec<Point> {
    if !p.letter || !points.contains(&p.anchor) {
        return Vec::new();
    }
    (points.iter())
        .filter(|q| (**q - p.anchor).norm() > beyond)
        .copied()
        .collect()
}

/// The links a text naming a line keeps nearer its own line than: every
/// link drawn but the pieces of its own; none for a text that names no
/// line.
fn rivals(p: &Pending, links: &[(Point, Point)]) -> Vec<(Point, Point)> {
    let Some((a, b)) = p.line else {
        return Vec::new();
    };
    let on_own = |q: Point| crate::geom::point_segment_distance(q, a, b) < 0.5;
    (links.iter())
        .filter(|(p, q)| !(on_own(*p) && on_own(*q)))
        .copied()
        .collect()
}

/// The sides of the block a point's letter is set on (its anchor on the
/// block's outline, not a point drawn): the block's own letter ("c", the
/// block in Fig. 60's slot), which keeps nearer the block than any link
/// or bearing ([`labels::Steer::block`]). Set by the rod it entered the slot by, it
/// hugged the rod and named it (Fig. 60 (b) at l = 1.06 r, 269.09°); by
/// the crank, under C's bearing (main (c) at 90.03°).
fn block_of<'b>(
    p: &Pending,
    points: &[Point],
    blocks: &'b [Vec<(Point, Point)>],
) -> Option<&'b [(Point, Point)]> {
    if !p.letter || p.line.is_some() || !p.along.is_empty() || points.contains(&p.anchor) {
        return None;
    }
    let on = |sides: &&Vec<(Point, Point)>| {
        (sides.iter()).any(|&(x, y)| crate::geom::point_segment_distance(p.anchor, x, y) < 0.5)
    };
    blocks.iter().find(on).map(Vec::as_slice)
}

/// Where a label was placed: the point its text is written at, its box,
/// and what the place cost.
struct Placed {
    at: Point,
    bounds: Frame,
    cost: f64,
    /// Whether its glyphs meet what stays once written
    /// ([`Obstacles::lasting`]).
    lasting: bool,
    /// The leader from the box towards its point, where a letter stands
    /// beyond a letter's reach ([`leader_line`]).
    leader: Option<(Point, Point)>,
}

/// How far, in font sizes, a point's letter crossed within [`REACH`]
/// looks for a clear place with a leader to its point.
const LEADER_REACH: f64 = 2.5;

/// How many places farther out a letter tries ([`LEADER_REACH`]) for
/// one whose leader runs along no line drawn, each tried place shut
/// before the next.
const LEADER_TRIES: usize = 8;

/// How far (page units) a leader stops short of its point: clear of a
/// pin's circle (4.2) and a dot.
const LEADER_SHORT: f64 = 6.0;

/// The least distance (page units) from a letter's box to its point at
/// which a leader is drawn to a letter standing nearer another point
/// ([`over_the_other`]): [`LEADER_SHORT`] and two units of line.
const LEADER_LEAST: f64 = LEADER_SHORT + 2.0;

/// The room, in font sizes, a label keeps from any other text
/// ([`Steer::apart`]): half an em.
const APART_EMS: f64 = 0.5;

/// The leader from the box `b` to `anchor`: from the box's nearest point
/// to [`LEADER_SHORT`] short of the anchor; none where the box stands
/// within `reach`, the letter there read with its point without one.
fn leader_line(b: &Frame, anchor: Point, reach: f64) -> Option<(Point, Point)> {
    let from = Point::new(
        anchor.x.clamp(b.min().x, b.max().x),
        anchor.y.clamp(b.min().y, b.max().y),
    );
    let d = anchor - from;
    (d.norm() > reach).then(|| (from, anchor - d * (LEADER_SHORT / d.norm())))
}

/// Where a panel's labels may go: in the panel, or just outside it (into
/// the margin) for points near its edge, and always on the `page`. A
/// clipped panel (a detail) keeps its labels inside.
fn label_room(panel: &Panel, page: &Frame) -> Frame {
    let r = panel.rect();
    let out = if panel.is_clipped() { -3.0 } else { 8.0 };
    let x0 = (r.min().x - out).max(page.min().x);
    let y0 = (r.min().y - out).max(page.min().y);
    let x1 = (r.max().x + out).min(page.max().x);
    let y1 = (r.max().y + out).min(page.max().y);
    Frame::from_origin_size(x0, y0, x1 - x0, y1 - y0)
}
