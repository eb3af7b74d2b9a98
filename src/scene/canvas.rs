//! Collects a panel's primitives while the layers draw: clips lines to the
//! panel's world frame, keeps ids unique, and shows points that fall off
//! the page by arrows at its edge. The scene's layers and the catalogue's
//! linkage sketches draw with it alike (the frame's bearings, hatching and
//! guides are in [`super::ground`]).

use crate::figure::{
    DOT_RADIUS, Hue, Item, PIN_PEN, PIN_RADIUS, PageFromWorld, Part, RichText, Role, Shape,
    TextSize,
};
use crate::geom::{Direction, Frame, Intersection, MeetJson, Point, Vector};
use serde_json::{Map, Value, json};
use std::collections::BTreeSet;

/// Shortest line drawn, in page units: shorter ones are degenerate.
const MIN_PAGE_LENGTH: f64 = 0.5;
/// The word before the letter of an arrow towards a point off the page
/// that is not at infinity (which is lettered "at ∞"), so that a reader
/// tells the two apart: "to *D*", as Kennedy's diagrams point to a
/// centre beyond the drawing.
const OFF_PAGE: &str = "to ";
/// Length of an arrow that points at something off the page.
const EDGE_ARROW: f64 = 34.0;
/// How far inside the frame such an arrow ends.
const EDGE_GAP: f64 = 3.0;

/// Page distance within which two lettered images of a polygon stand
/// close enough for their letters to meet side by side ("*n* *c*′" read
/// as one word in inversion 3's default, the points 14 units apart): each
/// letter is tried first on the side away from the other point.
const PAIRED: f64 = 24.0;

/// How a named point is marked.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Marker {
    /// A pin joint.
    Pin,
    /// A small dot.
    Dot,
    /// A small dot drawn with the links, over them: a point of the
    /// construction lying in a link drawn as a body, whose tone and the
    /// paper round the links over it would hide a dot drawn under them.
    DotOver,
}

/// A panel's items being drawn in one world frame with one map to the
/// page.
pub(crate) struct Canvas {
    transform: PageFromWorld,
    frame: Frame,
    items: Vec<Item>,
    ids: BTreeSet<String>,
    points: Map<String, Value>,
    /// Put before every id (a detail panel's `detail-`).
    prefix: &'static str,
    /// Put after every id (a sketch's panel, `-a` in panel (a) of
    /// Fig. 60, so that several sketches share one plot).
    suffix: &'static str,
    /// Whether points off the frame are shown by arrows at its edge (not
    /// in a detail, which shows only its region).
    edge_arrows: bool,
    /// Where constructed points get neither dot nor letter (the region a
    /// detail shows lettered).
    quiet: Option<Frame>,
    /// Where the marks about the crank (angles, the torque arrow) are left
    /// to a detail of the crank.
    bare: Option<Frame>,
    /// What the lines drawn now stand for (set per layer).
    hue: Option<Hue>,
    /// What the items drawn now are ([`Canvas::with_part`]).
    part: Part,
    /// The named points marked on the page, in the order drawn (name,
    /// place, marker): those that coincide are lettered together when
    /// the panel is finished ([`Canvas::letter_together`]).
    marked: Vec<(String, Point, Marker)>,
}

impl Canvas {
    pub(crate) fn new(transform: PageFromWorld, frame: Frame) -> Self {
        Self {
            transform,
            frame,
            items: Vec::new(),
            ids: BTreeSet::new(),
            points: Map::new(),
            prefix: "",
            suffix: "",
            edge_arrows: true,
            quiet: None,
            bare: None,
            hue: None,
            part: Part::Plain,
            marked: Vec::new(),
        }
    }

    /// Sets what the lines drawn from now on stand for; returns the
    /// previous setting.
    pub(crate) fn set_hue(&mut self, hue: Option<Hue>) -> Option<Hue> {
        std::mem::replace(&mut self.hue, hue)
    }

    /// Adds an item standing for `hue` (see [`Canvas::push`]).
    pub(crate) fn push_hued(
        &mut self,
        id: impl Into<String>,
        role: Role,
        hue: Hue,
        shape: Shape,
    ) -> bool {
        let old = self.set_hue(Some(hue));
        let added = self.push(id, role, shape);
        self.hue = old;
        added
    }

    /// Draws what `draw` adds as `part` (the writer, the handout and the
    /// catalogue tell such items apart by it, never by their ids).
    pub(crate) fn with_part(&mut self, part: Part, draw: impl FnOnce(&mut Self)) {
        let old = std::mem::replace(&mut self.part, part);
        draw(self);
        self.part = old;
    }

    /// A centre line (the line of stroke) from `a` to `b`, clipped as
    /// [`Canvas::segment`]: auxiliary, written long dash and dot.
    pub(crate) fn centre_line(&mut self, id: impl Into<String>, a: Point, b: Point) {
        self.with_part(Part::CentreLine, |c| c.segment(id, Role::Auxiliary, a, b));
    }

    /// Leaves the dots and letters of constructed points inside `region`,
    /// and the right-angle marks there, to a detail (pins and lines are
    /// still drawn): the detail shows them where they stand apart.
    pub(crate) fn quiet(mut self, region: Frame) -> Self {
        self.quiet = Some(region);
        self
    }

    /// Leaves the marks about the crank inside `region` (angle marks, the
    /// torque arrow, the names on the crank) to a detail of the crank: the
    /// layers ask [`Canvas::is_bare`] before drawing them.
    pub(crate) fn bare(mut self, region: Frame) -> Self {
        self.bare = Some(region);
        self
    }

    /// The region whose marks about the crank are left to a detail
    /// ([`Canvas::bare`]), if any.
    pub(crate) fn bare_region(&self) -> Option<&Frame> {
        self.bare.as_ref()
    }

    /// Whether marks about `p` are left to a detail ([`Canvas::bare`]).
    pub(crate) fn is_bare(&self, p: Point) -> bool {
        self.bare.is_some_and(|f| f.contains(p))
    }

    /// The canvas of a detail: every id gets `prefix`, and points off the
    /// frame are left out rather than shown by arrows.
    pub(crate) fn detail(mut self, prefix: &'static str) -> Self {
        self.prefix = prefix;
        self.edge_arrows = false;
        self
    }

    /// The canvas of one of several sketches in a plot: every id gets
    /// `suffix`.
    pub(crate) fn suffixed(mut self, suffix: &'static str) -> Self {
        self.suffix = suffix;
        self
    }

    pub(crate) fn transform(&self) -> &PageFromWorld {
        &self.transform
    }

    pub(crate) fn frame(&self) -> &Frame {
        &self.frame
    }

    /// World length of `px` page units.
    pub(crate) fn world(&self, px: f64) -> f64 {
        px / self.transform.scale()
    }

    /// Page length of a world length.
    pub(crate) fn page(&self, length: f64) -> f64 {
        length * self.transform.scale()
    }

    pub(crate) fn has(&self, id: &str) -> bool {
        self.ids.contains(id)
    }

    /// Adds an item unless one with its id is already there (layers that
    /// share a line draw it once). Returns whether it was added.
    pub(crate) fn push(&mut self, id: impl Into<String>, role: Role, shape: Shape) -> bool {
        let id = id.into();
        if self.ids.contains(&id) {
            return false;
        }
        if let Shape::RightAngle { vertex, .. } = &shape
            && self.quiet.is_some_and(|f| f.contains(*vertex))
        {
            return false;
        }
        self.ids.insert(id.clone());
        let mut item = Item::new(format!("{}{id}{}", self.prefix, self.suffix), role, shape)
            .as_part(self.part);
        if let Some(h) = self.hue
            && !matches!(role, Role::Link | Role::Frame | Role::Label)
        {
            item = item.hued(h);
        }
        self.items.push(item);
        true
    }

    /// Adds a ready-made item as [`Canvas::push`] does (its dash, hue and
    /// part are the canvas's); a label only when its anchor is on the
    /// frame, as [`Canvas::label`].
    pub(crate) fn push_item(&mut self, item: Item) {
        if let Shape::Label { anchor, .. } = &item.shape
            && !self.contains(*anchor)
        {
            return;
        }
        self.push(item.id, item.role, item.shape);
    }

    pub(crate) fn contains(&self, p: Point) -> bool {
        self.frame.contains(p)
    }

    /// The segment `a b`, clipped to the frame; nothing if it misses the
    /// frame or is shorter than half a page unit.
    pub(crate) fn segment(&mut self, id: impl Into<String>, role: Role, a: Point, b: Point) {
        let clipped = self.frame.clip_segment(a, b);
        self.push_clipped(id, role, clipped);
    }

    /// The ray from `origin` along `direction`, clipped to the frame.
    pub(crate) fn ray(
        &mut self,
        id: impl Into<String>,
        role: Role,
        origin: Point,
        direction: Vector,
    ) {
        if direction.norm() == 0.0 {
            return;
        }
        let clipped = self.frame.clip_ray(origin, direction);
        self.push_clipped(id, role, clipped);
    }

    /// A clipped piece of line, if any of it is on the page and it is at
    /// least [`MIN_PAGE_LENGTH`] long there.
    fn push_clipped(&mut self, id: impl Into<String>, role: Role, clipped: Option<(Point, Point)>) {
        if let Some((p, q)) = clipped
            && self.page((q - p).norm()) >= MIN_PAGE_LENGTH
        {
            self.push(
                id,
                role,
                Shape::Polyline {
                    points: vec![p, q],
                    closed: false,
                },
            );
        }
    }

    /// A label near `anchor` (placed clear of lines by the renderer).
    pub(crate) fn label(
        &mut self,
        id: impl Into<String>,
        anchor: Point,
        text: RichText,
        size: TextSize,
    ) {
        self.label_naming(id, anchor, (None, None), text, size);
    }

    /// A label near `anchor`, tried first `toward` (a world direction:
    /// a block's letter set off its side, out of the slotted bar it rides
    /// in); nothing where the anchor is off the page.
    pub(crate) fn label_toward(
        &mut self,
        id: impl Into<String>,
        anchor: Point,
        toward: Vector,
        text: RichText,
        size: TextSize,
    ) {
        self.label_naming(id, anchor, (Some(toward), None), text, size);
    }

    /// A text naming the line from `a` to `b` (a link's length), set by
    /// its middle and kept nearer it than any other link (placed by the
    /// renderer); nothing where the middle is off the page.
    pub(crate) fn line_label(
        &mut self,
        id: impl Into<String>,
        (a, b): (Point, Point),
        text: RichText,
        size: TextSize,
    ) {
        let anchor = nalgebra::center(&a, &b);
        self.label_naming(id, anchor, (None, Some([a, b])), text, size);
    }

    /// [`Canvas::line_label`], tried first `toward` (a world direction:
    /// one side of a link lying along another, whose letter takes the
    /// other side).
    pub(crate) fn line_label_toward(
        &mut self,
        id: impl Into<String>,
        (a, b): (Point, Point),
        toward: Vector,
        text: RichText,
        size: TextSize,
    ) {
        let anchor = nalgebra::center(&a, &b);
        self.label_naming(id, anchor, (Some(toward), Some([a, b])), text, size);
    }

    /// A label at `anchor`, tried first `toward` and naming `line` if
    /// any; nothing where the anchor is off the page.
    fn label_naming(
        &mut self,
        id: impl Into<String>,
        anchor: Point,
        (toward, line): (Option<Vector>, Option<[Point; 2]>),
        text: RichText,
        size: TextSize,
    ) {
        if self.contains(anchor) {
            let shape = Shape::Label {
                anchor,
                text,
                size,
                toward,
                line,
            };
            self.push(id, Role::Label, shape);
        }
    }

    /// Records a named point in the metadata and draws it: its marker and
    /// letter when on the page, an arrow at the frame edge pointing to it
    /// (from `from`, a point on the page) when off it, lettered "to" and
    /// its letter ([`OFF_PAGE`]).
    pub(crate) fn point(&mut self, name: &str, p: Point, marker: Marker, from: Point) {
        self.point_lettered(name, RichText::italic(name), p, marker, from);
    }

    /// [`Canvas::point`] lettered `letter` where the letter is not the
    /// name (a primed image, `a′`, whose id and metadata name is `a2`).
    pub(crate) fn point_lettered(
        &mut self,
        name: &str,
        letter: RichText,
        p: Point,
        marker: Marker,
        from: Point,
    ) {
        self.point_lettered_toward(name, letter, p, marker, from, None);
    }

    /// [`Canvas::point_lettered`], its letter tried first `toward` (a
    /// world direction): away from a point that stands near it.
    fn point_lettered_toward(
        &mut self,
        name: &str,
        letter: RichText,
        p: Point,
        marker: Marker,
        from: Point,
        toward: Option<Vector>,
    ) {
        let key = format!("point-{name}");
        if self.has(&key) || self.has(&format!("offpage-{name}")) {
            return;
        }
        self.points
            .insert(name.to_string(), json!([round(p.x), round(p.y)]));
        let quiet = marker == Marker::Dot && self.quiet.is_some_and(|f| f.contains(p));
        if quiet {
            // Left to the detail, the point is still where the lines
            // drawn meet: a pin's letter in the detail's frame that
            // stands nearer it than its own pin is left to the detail.
            // It is kept undrawn, as a detail's mark ([`Part::DetailMark`]).
            self.with_part(Part::DetailMark, |canvas| {
                canvas.push(key, Role::Construction, Shape::Dot { centre: p });
            });
        } else if self.contains(p) {
            self.mark(name, p, marker, letter, toward);
            self.marked.push((name.to_string(), p, marker));
        } else if !self.edge_arrows {
        } else if let Some((_, edge)) = self.frame.clip_segment(from, p) {
            let dir = p - from;
            if dir.norm() > 0.0 {
                let tail =
                    self.edge_arrow(format!("offpage-{name}"), edge, dir.normalize(), EDGE_ARROW);
                let letter = RichText::parse(OFF_PAGE).then(letter);
                self.label(format!("label-{name}"), tail, letter, TextSize::Letter);
            }
        }
    }

    /// Records a named point in the metadata without drawing it: a point
    /// that another's joint letter names where the two coincide on the
    /// page (a folded polygon's b′ and x at θ = 90°).
    pub(crate) fn record(&mut self, name: &str, p: Point) {
        self.points
            .insert(name.to_string(), json!([round(p.x), round(p.y)]));
    }

    /// Letters a polygon's points (name, markup, place; the pole `pole`)
    /// with dots: those on the frame and outside `held` (a region a detail
    /// letters) that stand within `crowd` page units of each other, as a
    /// book letters coinciding images, by one letter at the first naming
    /// them all ("*b*′, *x*"), the others recorded undrawn
    /// ([`Canvas::record`]); every other point by its own letter.
    pub(crate) fn letter_crowded(
        &mut self,
        points: &[(&str, &str, Point)],
        crowd: f64,
        pole: Point,
        held: Option<Frame>,
    ) {
        let shown = |c: &Self, p: Point| c.contains(p) && !held.is_some_and(|f| f.contains(p));
        let groups = crowds(
            points,
            |p| shown(self, p.2),
            |p, q| self.page((p.2 - q.2).norm()) < crowd,
        );
        let lettered: Vec<Point> = (groups.iter())
            .filter_map(|g| g.first().map(|p| p.2))
            .filter(|p| shown(self, *p))
            .collect();
        for group in &groups {
            let Some(&first) = group.first() else {
                continue;
            };
            let joint: Vec<&str> = group.iter().map(|g| g.1).collect();
            let text = RichText::parse(&joint.join(", "));
            let toward = self.away(first.2, &lettered);
            self.point_lettered_toward(first.0, text, first.2, Marker::Dot, pole, toward);
            for g in group.iter().skip(1) {
                self.record(g.0, g.2);
            }
        }
    }

    /// Letters the named points marked on the page that coincide there
    /// (within [`COINCIDE`] page units of each other, their dots run into
    /// one) by one letter, as a book does: "*A*, *D*" at a dead centre,
    /// where D is A, "*B*, *E*, *F*, *K*" where Ritterhaus's points meet
    /// at the crank pin near θ = 90°. Grouped as
    /// [`Canvas::letter_crowded`] groups a polygon's images; the letter
    /// is a pin's where one is among them (its own letter first, the
    /// others' after it in the order of their names), and the others'
    /// markers and letters are taken out, their places kept in the
    /// metadata. Two pins are not joined to each other: each is a part
    /// drawn.
    fn letter_together(&mut self) {
        let marked = std::mem::take(&mut self.marked);
        let within = self.together_within();
        let pin = |m: &(String, Point, Marker)| m.2 == Marker::Pin;
        let groups = crowds(
            &marked,
            |_| true,
            |p, q| !(pin(p) && pin(q)) && self.page((p.1 - q.1).norm()) < within,
        );
        for mut group in groups.into_iter().filter(|g| g.len() > 1) {
            // Pins first in the order drawn, then the others by name.
            group.sort_by_key(|m| (!pin(m), (!pin(m)).then_some(m.0.as_str())));
            let Some((head, rest)) = group.split_first() else {
                continue;
            };
            let id =
                |kind: &str, name: &str| format!("{}{kind}-{name}{}", self.prefix, self.suffix);
            let text_of = |items: &[Item], name: &str| {
                let label = id("label", name);
                (items.iter().find(|it| it.id == label)).and_then(|it| match &it.shape {
                    Shape::Label { text, .. } => Some(text.clone()),
                    _ => None,
                })
            };
            let gone: Vec<String> = (rest.iter())
                .flat_map(|m| [id("label", &m.0), id("point", &m.0)])
                .collect();
            let Some(mut joint) = text_of(&self.items, &head.0) else {
                // A pin lettered in the crank's detail: the points at it
                // are lettered with it there.
                if pin(head) && self.is_bare(head.1) {
                    self.items.retain(|it| !gone.contains(&it.id));
                }
                continue;
            };
            for m in rest {
                if let Some(text) = text_of(&self.items, &m.0) {
                    joint = joint.then(RichText::parse(", ")).then(text);
                }
            }
            self.items.retain(|it| !gone.contains(&it.id));
            let label = id("label", &head.0);
            if let Some(Shape::Label { text, .. }) = (self.items.iter_mut())
                .find(|it| it.id == label)
                .map(|it| &mut it.shape)
            {
                *text = joint;
            }
        }
    }

    /// The page distance under which points are lettered together
    /// ([`Canvas::letter_together`]): [`COINCIDE`] on a main view; in a
    /// detail, whose enlargement sets apart points merely near, only
    /// those that coincide there exactly ([`EXACTLY`]: E at C at a dead
    /// centre), which the main view leaves to it.
    fn together_within(&self) -> f64 {
        if self.edge_arrows { COINCIDE } else { EXACTLY }
    }

    /// The world direction from the nearest of `others` (other than `p`)
    /// within [`PAIRED`] page units to `p`, if any: where a letter of `p`
    /// stands apart from the nearest one's.
    fn away(&self, p: Point, others: &[Point]) -> Option<Vector> {
        let nearest = (others.iter())
            .map(|q| p - q)
            .filter(|d| d.norm() > 0.0 && self.page(d.norm()) < PAIRED)
            .min_by(|a, b| a.norm().total_cmp(&b.norm()))?;
        Some(nearest.normalize())
    }

    /// A point's marker (`point-{name}`) and its letter (`label-{name}`).
    fn mark(
        &mut self,
        name: &str,
        p: Point,
        marker: Marker,
        letter: RichText,
        toward: Option<Vector>,
    ) {
        let key = format!("point-{name}");
        match marker {
            Marker::Pin => self.push(key, Role::Link, Shape::Pin { centre: p }),
            Marker::Dot => self.push(key, Role::Construction, Shape::Dot { centre: p }),
            Marker::DotOver => self.push(key, Role::Link, Shape::Dot { centre: p }),
        };
        // A pin inside a crank's detail is lettered there: on the main
        // view its letter stood against its neighbour's (A and C touching
        // at a short rod's inner dead centre, the block in the circle).
        if !(marker == Marker::Pin && self.is_bare(p)) {
            let id = format!("label-{name}");
            self.label_naming(id, p, (toward, None), letter, TextSize::Letter);
        }
    }

    /// A point lettered `markup` (a sketch's, which records no metadata):
    /// its marker and letter when on the frame, else an arrow at the
    /// frame's edge on the line from `from` (a point on the frame) towards
    /// it, lettered "to" and `markup` at its tail ([`OFF_PAGE`]), where
    /// the arrow fits between `from` and the edge (nothing where it does
    /// not).
    pub(crate) fn lettered(
        &mut self,
        name: &str,
        p: Point,
        markup: &str,
        marker: Marker,
        from: Point,
    ) {
        if self.contains(p) {
            self.mark(name, p, marker, RichText::parse(markup), None);
        } else if !self.edge_arrows {
            // A detail's edge is not the drawing's: its links run on
            // beyond it, and an arrow there would lie on one.
        } else if let Some((_, edge)) = self.frame.clip_segment(from, p)
            && (p - from).norm() > 0.0
        {
            let u = (p - from).normalize();
            if let Some(tail) = self.edge_arrow_after(format!("offpage-{name}"), from, edge, u) {
                self.label(
                    format!("label-{name}"),
                    tail,
                    RichText::parse(OFF_PAGE).then(RichText::parse(markup)),
                    TextSize::Letter,
                );
            }
        }
    }

    /// A point at infinity in the direction `u` (a sketch's, which records
    /// no metadata): an arrow at the frame's edge on the ray from `from`,
    /// lettered `markup` "at ∞", where it fits between `from` and the edge;
    /// nothing for a zero `u` or in a detail. The letter stands by the arrow's tail, or,
    /// `beside` it, by its middle as a line's name (where a point lettered
    /// already stands at the tail: inversion 2's O_bd, whose letter and
    /// O_cd's were stacked over one dot). Returns the arrow's tail, where
    /// a line towards it from `from` would end (`None`: no arrow drawn).
    pub(crate) fn lettered_at_infinity(
        &mut self,
        name: &str,
        (from, u): (Point, Vector),
        markup: &str,
        beside: bool,
    ) -> Option<Point> {
        // A detail shows its region only: the arrow is the main view's.
        if u.norm() == 0.0 || !self.edge_arrows {
            return None;
        }
        let u = u.normalize();
        let (_, edge) = self.frame.clip_ray(from, u)?;
        let tail = self.edge_arrow_after(format!("infinity-{name}"), from, edge, u)?;
        let letter = RichText::parse(&format!("{markup} at ∞"));
        if beside {
            let head = edge - u * self.world(EDGE_GAP);
            self.line_label(
                format!("label-{name}"),
                (tail, head),
                letter,
                TextSize::Letter,
            );
        } else {
            self.label(format!("label-{name}"), tail, letter, TextSize::Letter);
        }
        Some(tail)
    }

    /// The head and tail of an arrow of `length` page units along the unit
    /// `u` that ends just inside the frame at `edge`.
    fn edge_ends(&self, edge: Point, u: Vector, length: f64) -> (Point, Point) {
        let head = edge - u * self.world(EDGE_GAP);
        (head, head - u * self.world(length))
    }

    /// An [`EDGE_ARROW`] long arrow along the unit `u` that ends just
    /// inside the frame at `edge`, if its tail is not behind `from`;
    /// returns its tail.
    fn edge_arrow_after(
        &mut self,
        id: String,
        from: Point,
        edge: Point,
        u: Vector,
    ) -> Option<Point> {
        let (_, tail) = self.edge_ends(edge, u, EDGE_ARROW);
        if (tail - from).dot(&u) < 0.0 {
            return None;
        }
        Some(self.edge_arrow(id, edge, u, EDGE_ARROW))
    }

    /// An arrow of `length` page units along the unit `u` that ends just
    /// inside the frame at `edge` (where a line to an off-page point leaves
    /// it); returns its tail, where the label goes.
    pub(crate) fn edge_arrow(
        &mut self,
        id: impl Into<String>,
        edge: Point,
        u: Vector,
        length: f64,
    ) -> Point {
        let (head, tail) = self.edge_ends(edge, u, length);
        self.push(
            id,
            Role::Construction,
            Shape::Arrow {
                from: tail,
                to: head,
            },
        );
        tail
    }

    /// Records a point at infinity in the metadata and shows it by a
    /// labelled direction arrow at the frame edge, on the ray from `through`
    /// along `direction`.
    pub(crate) fn point_at_infinity(&mut self, name: &str, direction: Direction, through: Point) {
        let id = format!("infinity-{name}");
        if self.has(&id) {
            return;
        }
        self.points.insert(
            name.to_string(),
            MeetJson(&Intersection::AtInfinity(direction), round).value(),
        );
        let u = direction.into_inner();
        if !self.edge_arrows {
            return;
        }
        if let Some((_, edge)) = self.frame.clip_ray(through, u) {
            let (head, _) = self.edge_ends(edge, u, EDGE_ARROW);
            if (head - through).dot(&u) > 0.0 {
                let tail = self.edge_arrow(id, edge, u, EDGE_ARROW);
                self.label(
                    format!("label-{name}"),
                    tail,
                    RichText::parse(&format!("*{name}* at ∞")),
                    TextSize::Letter,
                );
            }
        }
    }

    /// A point that may be at infinity (D): at infinity it is shown by a
    /// direction arrow on the ray from `from` along `towards` (the caller
    /// knows which way the construction runs).
    pub(crate) fn intersection(
        &mut self,
        name: &str,
        p: &Intersection,
        marker: Marker,
        from: Point,
        towards: Vector,
    ) {
        match p {
            Intersection::Point(p) => self.point(name, *p, marker, from),
            Intersection::AtInfinity(_) => {
                if let Some(d) = Direction::try_new(towards, 0.0) {
                    self.point_at_infinity(name, d, from)
                }
            }
            Intersection::Coincident => {}
        }
    }

    /// The items drawn, the letters of edge arrows running side by side
    /// set apart ([`super::edge_letters::part`]), and the points recorded.
    pub(crate) fn finish(mut self) -> (Vec<Item>, Map<String, Value>) {
        self.letter_together();
        let near = self.world(super::edge_letters::SIDE_BY_SIDE);
        let shift = self.world(super::edge_letters::SHIFT);
        super::edge_letters::part(&mut self.items, near, shift);
        (self.items, self.points)
    }
}

/// Page distance under which two named points coincide for the eye:
/// their dots (2.1 units in radius, a pin's 4.2) run into one, and one
/// letter names them all ([`Canvas::letter_together`]), as the polygons'
/// images are ([`super::draw::polygons::COINCIDE`]).
pub(crate) const COINCIDE: f64 = super::draw::polygons::COINCIDE;

/// Page distance, centre to centre, under which a constructed point's
/// dot is one point with a pin's in a detail: the dot under the pin's
/// circle or its edge within two of the circle's pen widths of it
/// ([`crate::scene::letter_near_together`]). Kisch's E, F and H at 4.2
/// units from B at l = 43.8 r, 90.84°, Bennett's E at 6.8 from B and G
/// at 7.8 from C at l = 29 r, 89.08°, hidden by the pin or read as a
/// burr on it, each stood lettered apart with no dot to tell it by.
/// Parting the dots just beside a pin from it (6.3 units, the dot clear of
/// the pin line's middle) gave Kisch's foot F, G at 6.7 units from B at
/// l = 43.1 r, 180° its own letter, but set Bennett's E, 7.1 units from B
/// at l = 30 r, 91°, lettered alone 3.5 units from B's letter: the dots'
/// own letters must first be placed apart from the pin's.
pub(crate) const UNDER_PIN: f64 = PIN_RADIUS + DOT_RADIUS + 2.0 * PIN_PEN;

/// Page distance, centre to centre, within which a result's dot in a
/// detail (E, G: [`crate::scene::letter_near_together`]) is one point
/// with a pin's: its disc reaching the pin's circle, read as on the pin.
/// A result's dot further off is seen beside the pin and lettered apart:
/// Bennett's G, 0.026 r beyond B at l = 39 r, 0°, 8.3 units from B at
/// ×20, was lettered "B, F, G, K, L", and the figure read as CG = CB
/// against notes giving CG = 1.026 r.
pub(crate) const ON_PIN: f64 = PIN_RADIUS + DOT_RADIUS;

/// Page distance, centre to centre, within which a constructed point's
/// dot stands by a pin in a detail: under it ([`UNDER_PIN`]) or its edge
/// within two of the circle's pen widths of it. The letters of such
/// points, joined or each its own, are set beside the pin, and the
/// detail keeps room for them there.
pub(crate) const BESIDE_PIN: f64 = PIN_RADIUS + DOT_RADIUS + 2.0 * PIN_PEN;

/// Page distance under which two named points are one point in a
/// detail: a dot inside the other's marker, lettered with it there
/// ([`Canvas::letter_together`]).
const EXACTLY: f64 = 1.0;

/// The groups of `things` that crowd, in order: the first thing left
/// that is `shown`, with every shown thing `near` one of the group
/// already (one not shown stands alone); a group's first member is the
/// first of it in order.
fn crowds<T>(
    things: &[T],
    shown: impl Fn(&T) -> bool,
    near: impl Fn(&T, &T) -> bool,
) -> Vec<Vec<&T>> {
    let mut left: Vec<&T> = things.iter().collect();
    let mut groups = Vec::new();
    while !left.is_empty() {
        let first = left.remove(0);
        let mut group = vec![first];
        if shown(first) {
            while let Some(j) =
                (left.iter()).position(|p| shown(p) && group.iter().any(|g| near(g, p)))
            {
                group.push(left.remove(j));
            }
        }
        groups.push(group);
    }
    groups
}

/// A number for the metadata, to 12 significant digits (stable text).
pub(crate) fn round(x: f64) -> f64 {
    if x == 0.0 || !x.is_finite() {
        return 0.0;
    }
    let digits = 11 - x.abs().log10().floor() as i32;
    let digits = digits.clamp(-300, 300);
    let p = 10f64.powi(digits);
    let r = (x * p).round() / p;
    if r.is_finite() { r + 0.0 } else { x }
}
