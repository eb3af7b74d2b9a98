//! The immutable figure model: panels of primitives in world coordinates,
//! each with a role and a stable id.

use super::Style;
use super::{Font, Metadata, PageFromWorld, PageUnit, Path, RichText, Title};
use crate::geom::{Frame, Point, Vector};

/// What a primitive is, which fixes how it is drawn (line weight, dash,
/// colour in the handout style) and its stacking order.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
#[non_exhaustive]
pub enum Role {
    /// The fixed link: hatched ground, guides, bearings.
    Frame,
    /// Thin dashed lines that only help (produced lines, circles drawn to
    /// find a point, ghost poses).
    Auxiliary,
    /// A curve traced by the mechanism (centrodes, coupler ovals, diagrams).
    Curve,
    /// Construction lines (CF, FG, BD, ...).
    Construction,
    /// The lengths a construction is made for, read off at a scale (CE,
    /// CG; Ng's OM): drawn heavier than the lines that find them.
    Result,
    /// Dimension lines and angle marks.
    Dimension,
    /// Force and torque arrows.
    Force,
    /// The moving links: crank, rod, slider block, pins.
    Link,
    /// Letters, values and notes.
    Label,
}

impl Role {
    /// Every role, in drawing order (later on top).
    pub const ALL: [Role; 9] = [
        Role::Frame,
        Role::Auxiliary,
        Role::Curve,
        Role::Construction,
        Role::Result,
        Role::Dimension,
        Role::Force,
        Role::Link,
        Role::Label,
    ];

    /// The lower-case name used in SVG classes.
    pub fn name(&self) -> &'static str {
        match self {
            Role::Frame => "frame",
            Role::Auxiliary => "auxiliary",
            Role::Curve => "curve",
            Role::Construction => "construction",
            Role::Result => "result",
            Role::Dimension => "dimension",
            Role::Force => "force",
            Role::Link => "link",
            Role::Label => "label",
        }
    }
}

/// What an item is, where code tells it apart beyond the stroke of its
/// [`Role`]: the SVG writer, the handout and the catalogue read this,
/// never the item's id, which is a name for the SVG's readers.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[non_exhaustive]
pub enum Part {
    /// Nothing more than its role says.
    #[default]
    Plain,
    /// A centre line (the line of stroke): written long dash and dot,
    /// and broken where a letter sits on it (an auxiliary line).
    CentreLine,
    /// The circle the crank pin runs on.
    CrankCircle,
    /// One of the mechanism's joints (crank centre, crank pin,
    /// cross-head): its pin or its letter.
    Joint,
    /// An enlarged detail's marks on the main view: the frame round the
    /// region it enlarges, its border and its caption.
    DetailMark,
    /// The fixed centrode (the instantaneous centre's path in the frame),
    /// a branch of it or its name.
    FixedCentrode,
    /// The moving centrode (the instantaneous centre's path in the rod),
    /// a branch of it or its name.
    MovingCentrode,
    /// A scene's notes below its drawing (scales, offset).
    Notes,
}

/// How large a text is set.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TextSize {
    /// A point letter (A, B, C ...).
    Letter,
    /// A value or a short caption beside a line.
    Small,
    /// Tick labels and legends of a plot.
    Tick,
}

/// How a fixed text ([`Shape::Text`]) sits on its point, along its
/// baseline.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Align {
    /// The text starts at the point.
    Start,
    /// The text is centred on the point.
    Middle,
    /// The text ends at the point.
    End,
}

/// A stroke pattern for one item, in place of its role's (plots tell
/// their series apart by it).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Dash {
    /// A full line.
    Solid,
    /// Long dashes.
    Dashed,
    /// Dots.
    Dotted,
    /// Long dash, dot.
    DashDot,
}

/// What a line stands for, where colour can say it (the handout style):
/// one hue for velocity, one for acceleration, one for forces.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Hue {
    /// Velocity constructions and arrows (E, D, CE, v_c, v_p, ω, Ω).
    Velocity,
    /// Acceleration constructions (Klein, Kisch: F, G, H, CG).
    Acceleration,
    /// Forces and torques (OM, F_p, F_s, F_c, T).
    Force,
}

/// The symbol of a data point ([`Shape::Marker`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum Symbol {
    /// A filled circle.
    Disc,
    /// An open circle.
    Circle,
    /// An open square.
    Square,
    /// An open triangle, point up.
    Triangle,
    /// An open diamond.
    Diamond,
    /// A diagonal cross.
    Cross,
}

/// A bearing's foot as drawn, page units: the pedestal's depth from the
/// pin to its foot, and half the foot's length (the hatching stands 6
/// units beyond the foot). The layout draws it; a builder that keeps
/// other marks off it reads its reach here.
pub const BEARING_FOOT: (f64, f64) = (17.0, 17.0);

/// A primitive. Positions are in the panel's world coordinates; sizes of
/// symbols (pins, arrowheads, hatch strokes, marks, text) are in page units,
/// The side of its centre a bearing's pedestal and hatched base stand on,
/// in page terms.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Foot {
    /// Below the centre: the usual pedestal.
    Below,
    /// Above it, hanging from the frame.
    Above,
    /// To its left, standing out of a wall.
    Left,
    /// To its right.
    Right,
}

impl Foot {
    /// The page directions (y down) towards the base and along it.
    pub fn axes(self) -> (Vector, Vector) {
        let across = Vector::new(1.0, 0.0);
        let up_the_base = Vector::new(0.0, 1.0);
        match self {
            Foot::Below => (Vector::new(0.0, 1.0), across),
            Foot::Above => (Vector::new(0.0, -1.0), across),
            Foot::Left => (Vector::new(-1.0, 0.0), up_the_base),
            Foot::Right => (Vector::new(1.0, 0.0), up_the_base),
        }
    }
}

/// so they look the same at every scale.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum Shape {
    /// A path of lines and cubic Béziers (a fitted curve).
    Path(Path),
    /// A polyline, closed or open (no fill).
    Polyline {
        /// Vertices in order.
        points: Vec<Point>,
        /// Whether the last vertex joins the first.
        closed: bool,
    },
    /// A filled area without outline (tinted in the handout style only).
    Region {
        /// Vertices in order.
        points: Vec<Point>,
    },
    /// A full circle.
    Circle {
        /// Centre.
        centre: Point,
        /// Radius in world units.
        radius: f64,
    },
    /// A circular arc from world angle `start` turning `sweep` radians
    /// (counter-clockwise in the world when positive).
    Arc {
        /// Centre.
        centre: Point,
        /// Radius in world units.
        radius: f64,
        /// Start angle in radians (world, from +x).
        start: f64,
        /// Signed sweep in radians.
        sweep: f64,
        /// An arrowhead at the end (a torque).
        arrow: bool,
    },
    /// A pin joint: a small open circle.
    Pin {
        /// Centre of the pin.
        centre: Point,
    },
    /// A constructed point: a small filled dot.
    Dot {
        /// The point.
        centre: Point,
    },
    /// The fixed bearing of the crank: a pedestal with a hatched base on
    /// the side `foot` of the centre (in page terms).
    Bearing {
        /// Centre of the shaft.
        centre: Point,
        /// The side the pedestal stands on: below the centre, or, where a
        /// crank pointing down the page would run through it, above or to
        /// a side.
        foot: Foot,
    },
    /// A filled body with a link outline (the slider block).
    Block {
        /// Vertices in order.
        points: Vec<Point>,
    },
    /// A link's body drawn as a bar in a light tone under the links lying
    /// over it: the inversions' slotted bar d, inside whose outline a crank
    /// or a rod running along it read as part of d (inversion 2 near 270°
    /// with the offset near r). Drawn as a [`Shape::Block`] that is a bar,
    /// toned; with fewer than three vertices, nothing.
    Body {
        /// Vertices in order.
        points: Vec<Point>,
    },
    /// A straight arrow with its head at `to`.
    Arrow {
        /// Tail.
        from: Point,
        /// Head.
        to: Point,
    },
    /// Ground hatching along the segment `from`–`to`, on the side `side`
    /// points to (a world vector).
    Hatch {
        /// Start of the hatched edge.
        from: Point,
        /// End of the hatched edge.
        to: Point,
        /// Which side carries the strokes.
        side: Vector,
    },
    /// A right-angle mark at `vertex` between the directions `u` and `v`.
    RightAngle {
        /// The corner.
        vertex: Point,
        /// One arm's direction (world).
        u: Vector,
        /// The other arm's direction (world).
        v: Vector,
    },
    /// An angle mark: an arc about `vertex` from world angle `start`
    /// turning `sweep` radians, with an optional text beside it.
    AngleMark {
        /// The vertex.
        vertex: Point,
        /// Start angle in radians (world).
        start: f64,
        /// Signed sweep in radians.
        sweep: f64,
        /// The angle's name.
        text: Option<RichText>,
    },
    /// A dimension: extension lines and a double-headed line between `from`
    /// and `to`, set off by `offset` page units towards the world direction
    /// `side`, with its text at the middle.
    Dimension {
        /// First end.
        from: Point,
        /// Second end.
        to: Point,
        /// Which way the dimension line is set off (world).
        side: Vector,
        /// Offset in page units.
        offset: f64,
        /// The text.
        text: RichText,
    },
    /// A text placed near `anchor`, clear of lines and other labels.
    Label {
        /// The point labelled.
        anchor: Point,
        /// The text.
        text: RichText,
        /// How large.
        size: TextSize,
        /// The world direction from the anchor tried first, if any (a
        /// force's name beyond its arrow's head, a point's letter on the
        /// side away from what crowds it): a place clear along it is
        /// taken before any other side; `None` (or a zero vector) leaves
        /// the side to the placement alone.
        toward: Option<Vector>,
        /// The line the text names, if any (a link's length, "l = 1.05 r",
        /// set by the link's middle): a place nearer another link than
        /// this line would name the other, and is taken only where no
        /// place is clear. `None` for a text that names a point, or a
        /// line of zero length (then the anchor alone counts).
        line: Option<[Point; 2]>,
    },
    /// A text set at a fixed place, not moved clear of lines: `offset`
    /// page units (y down) from the page point of `at`, aligned by `align`
    /// with the middle of its letters on that place (tick labels, axis
    /// titles, legends).
    Text {
        /// The world point it is set by.
        at: Point,
        /// Page offset from that point.
        offset: Vector,
        /// The text.
        text: RichText,
        /// Where the point is along the text.
        align: Align,
        /// How large.
        size: TextSize,
    },
    /// A data point: a symbol of fixed page size centred on a world point.
    Marker {
        /// The point.
        centre: Point,
        /// Its symbol.
        symbol: Symbol,
    },
    /// Lines of text at a fixed page position (top-left corner), for scale
    /// notes.
    Note {
        /// Top-left corner in page units.
        corner: Point,
        /// The lines.
        lines: Vec<RichText>,
    },
}

/// One primitive with its role and stable id.
#[derive(Debug, Clone, PartialEq)]
pub struct Item {
    /// The id written to SVG (`point-E`, `line-CE`, ...), unique in its
    /// figure.
    pub id: String,
    /// The role.
    pub role: Role,
    /// The geometry.
    pub shape: Shape,
    /// A stroke pattern in place of the role's; `None` keeps the role's.
    pub dash: Option<Dash>,
    /// What the line stands for, if colour should say it.
    pub hue: Option<Hue>,
    /// What the item is, where code tells it apart ([`Part::Plain`] for
    /// most).
    pub part: Part,
}

impl Item {
    /// An item drawn in its role's stroke.
    pub fn new(id: impl Into<String>, role: Role, shape: Shape) -> Self {
        Self {
            id: id.into(),
            role,
            shape,
            dash: None,
            hue: None,
            part: Part::Plain,
        }
    }

    /// The same item marked as `part`.
    pub fn as_part(mut self, part: Part) -> Self {
        self.part = part;
        self
    }

    /// The same item marked as standing for `hue`.
    pub fn hued(mut self, hue: Hue) -> Self {
        self.hue = Some(hue);
        self
    }

    /// The same item stroked with `dash` instead of its role's pattern.
    pub fn dashed(mut self, dash: Dash) -> Self {
        self.dash = Some(dash);
        self
    }
}

/// A panel: a page rectangle, its own world-to-page map and its primitives.
#[derive(Debug, Clone, PartialEq)]
pub struct Panel {
    id: String,
    rect: Frame,
    transform: PageFromWorld,
    items: Vec<Item>,
    clipped: bool,
}

impl Panel {
    /// A panel; items are drawn by role, then in the order given.
    pub fn new(
        id: impl Into<String>,
        rect: Frame,
        transform: PageFromWorld,
        items: Vec<Item>,
    ) -> Self {
        Self {
            id: id.into(),
            rect,
            transform,
            items,
            clipped: false,
        }
    }

    /// The same panel with nothing drawn outside its rectangle (a detail,
    /// whose circles and lines run on beyond the region it enlarges).
    pub fn clipped(mut self) -> Self {
        self.clipped = true;
        self
    }

    /// Whether the renderer clips the panel to its rectangle.
    pub fn is_clipped(&self) -> bool {
        self.clipped
    }

    /// The panel's id (`panel-mechanism`).
    pub fn id(&self) -> &str {
        &self.id
    }

    /// Where it sits on the page.
    pub fn rect(&self) -> &Frame {
        &self.rect
    }

    /// Its world-to-page map.
    pub fn transform(&self) -> &PageFromWorld {
        &self.transform
    }

    /// Its primitives.
    pub fn items(&self) -> &[Item] {
        &self.items
    }

    /// The item with `id`, if any.
    pub fn item(&self, id: &str) -> Option<&Item> {
        self.items.iter().find(|i| i.id == id)
    }

    /// The same panel moved by `(dx, dy)` page units: its rectangle, its
    /// map and the page corners of its notes; world coordinates are
    /// unchanged. `None` if the move is not finite.
    pub fn moved(&self, dx: f64, dy: f64) -> Option<Self> {
        let [a, b, c, d, e, f] = self.transform.coefficients();
        let transform = PageFromWorld::new([a, b, c, d, e + dx, f + dy])?;
        let items = self
            .items
            .iter()
            .map(|item| {
                let mut item = item.clone();
                if let Shape::Note { corner, .. } = &mut item.shape {
                    *corner += Vector::new(dx, dy);
                }
                item
            })
            .collect();
        Some(Self {
            id: self.id.clone(),
            rect: Frame::from_origin_size(
                self.rect.min().x + dx,
                self.rect.min().y + dy,
                self.rect.width(),
                self.rect.height(),
            ),
            transform,
            items,
            clipped: self.clipped,
        })
    }

    /// The same panel with `items` added after its own.
    pub fn with_items(mut self, items: impl IntoIterator<Item = Item>) -> Self {
        self.items.extend(items);
        self
    }

    /// The same panel (its place, transform and clip) with its items as
    /// `edit` leaves them; an edit that empties them leaves an empty
    /// panel.
    pub fn with_items_edited(mut self, edit: impl FnOnce(&mut Vec<Item>)) -> Self {
        edit(&mut self.items);
        self
    }
}

/// A whole figure: page size, style, panels and the metadata written to
/// the SVG's `<metadata>` (docs/design.md §4).
#[derive(Debug, Clone, PartialEq)]
pub struct Figure {
    name: String,
    width: f64,
    height: f64,
    style: Style,
    font: Font,
    tolerance: f64,
    panels: Vec<Panel>,
    metadata: Metadata,
    size_unit: PageUnit,
    title: Option<Title>,
}

/// How far below a figure's last line its title's baseline sits, page
/// units.
const TITLE_DROP: f64 = 10.0;
/// How much a title makes the page grow, page units: the drop, the
/// descenders and a margin.
const TITLE_BAND: f64 = 30.0;

impl Figure {
    /// A figure of `width` × `height` page units; `metadata` adds keys to
    /// the SVG metadata beside the ones the renderer writes (`figure`,
    /// `page_from_world`, `tolerance`, `style`, `panels`); `tolerance` is
    /// the one its curves were traced to ([`Figure::tolerance`]). It is set
    /// in the default [`Font`] until [`Figure::with_font`] says otherwise.
    pub fn new(
        name: impl Into<String>,
        width: f64,
        height: f64,
        style: Style,
        tolerance: f64,
        panels: Vec<Panel>,
        metadata: Metadata,
    ) -> Self {
        Self {
            name: name.into(),
            width,
            height,
            style,
            font: Font::default(),
            tolerance,
            panels,
            metadata,
            size_unit: PageUnit::Px,
            title: None,
        }
    }

    /// Its name (`fig-67-example`).
    pub fn name(&self) -> &str {
        &self.name
    }

    /// Page width.
    pub fn width(&self) -> f64 {
        self.width
    }

    /// Page height.
    pub fn height(&self) -> f64 {
        self.height
    }

    /// The drawing style.
    pub fn style(&self) -> Style {
        self.style
    }

    /// The face its text is set in.
    pub fn font(&self) -> Font {
        self.font
    }

    /// The tolerance, in page units, its curves were traced to by the
    /// curve engine ([`crate::diagram::trace`]): a record of what the
    /// engine was asked for and kept (the written paths are within it),
    /// written to the metadata as `tolerance`; the renderer draws nothing
    /// by it.
    pub fn tolerance(&self) -> f64 {
        self.tolerance
    }

    /// The panels, in drawing order.
    pub fn panels(&self) -> &[Panel] {
        &self.panels
    }

    /// What the figure records beside what it draws (the writer adds its
    /// own keys to it).
    pub fn metadata(&self) -> &Metadata {
        &self.metadata
    }

    /// The same geometry in another style.
    pub fn with_style(mut self, style: Style) -> Self {
        self.style = style;
        self
    }

    /// The unit the SVG gives its `width` and `height` in: page units
    /// ([`PageUnit::Px`], the default) or, for a page asked for in
    /// millimetres or inches, that unit (`width="120mm"`); the `viewBox`
    /// stays in page units, 96 to the inch.
    pub fn size_unit(&self) -> PageUnit {
        self.size_unit
    }

    /// The same figure with its size written in `unit` (see
    /// [`Figure::size_unit`]).
    pub fn with_size_unit(mut self, unit: PageUnit) -> Self {
        self.size_unit = unit;
        self
    }

    /// Its title, if it has one.
    pub fn title(&self) -> Option<&Title> {
        self.title.as_ref()
    }

    /// The same figure with `title` set centred in a band added below it
    /// (panel `panel-title`, item `title`; the page grows by 30 units, a
    /// long title is set smaller to fit) and written as the SVG's
    /// `<title>`. A second title replaces the first.
    pub fn with_title(mut self, title: Title) -> Self {
        if self.title.is_some() {
            // The title's band is the last panel: a figure gains panels
            // only when made and by its title.
            self.panels.pop();
            self.height -= TITLE_BAND;
        }
        let text = title.rich();
        let size = self.style.font_size(super::TextSize::Letter);
        let fits = text.width(self.font, size) <= self.width - 40.0;
        let shape = if fits {
            Shape::Text {
                at: Point::new(0.5 * self.width, self.height + TITLE_DROP),
                offset: Vector::zeros(),
                text,
                align: Align::Middle,
                size: super::TextSize::Letter,
            }
        } else {
            // A note is set smaller until it fits the page's width.
            Shape::Note {
                corner: Point::new(20.0, self.height + TITLE_DROP - 12.0),
                lines: vec![text],
            }
        };
        let rect = Frame::from_origin_size(0.0, self.height, self.width, TITLE_BAND);
        self.panels.push(Panel::new(
            "panel-title",
            rect,
            PageFromWorld::identity(),
            vec![Item::new("title", Role::Label, shape)],
        ));
        self.height += TITLE_BAND;
        self.title = Some(title);
        self
    }

    /// The same figure set in another face. Layout already made with
    /// another face's widths (plot margins, legends) is kept: build the
    /// figure with the face instead where that matters
    /// ([`crate::scene::Scene::with_font`], [`crate::catalogue::FigureOptions::font`]).
    pub fn with_font(mut self, font: Font) -> Self {
        self.font = font;
        self
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_second_title_replaces_the_first_and_keeps_the_drawing() {
        let rect = Frame::from_origin_size(0.0, 0.0, 400.0, 300.0);
        let dot = Item::new(
            "point-A",
            Role::Link,
            Shape::Pin {
                centre: Point::origin(),
            },
        );
        let drawing = Panel::new("panel-main", rect, PageFromWorld::identity(), vec![dot]);
        let plain = Figure::new(
            "f",
            400.0,
            300.0,
            Style::Textbook,
            0.1,
            vec![drawing],
            Metadata::new(),
        );
        let title = |t: &str| Title::new(t).unwrap();
        let once = plain.clone().with_title(title("First"));
        let twice = once.clone().with_title(title("Second"));
        assert_eq!(twice.height(), once.height());
        assert_eq!(twice.panels().len(), 2);
        assert_eq!(twice.panels().first(), plain.panels().first());
        let written = twice.panels().last().and_then(|p| p.items().first());
        assert!(
            matches!(written.map(|i| &i.shape), Some(Shape::Text { text, .. }) if text.plain() == "Second"),
            "{written:?}"
        );
    }
}
