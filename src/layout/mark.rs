//! What the layout hands the writers: marks in page space, each a path,
//! a circle, a text or a group of marks, with its paint decided. A writer
//! turns each into its own format's element and decides nothing.

use crate::figure::{Pen, RichText};
use crate::geom::Point;

/// One command of a page path.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum PathCommand {
    /// Start a piece at the point.
    Move(Point),
    /// A straight line to the point.
    Line(Point),
    /// A cubic Bézier to the last point, the first two its control
    /// points.
    Cubic(Point, Point, Point),
    /// Close the piece back to its start.
    Close,
}

/// A page path: its commands in order (a path of no command draws
/// nothing).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct PathData {
    commands: Vec<PathCommand>,
}

impl PathData {
    /// A path of no command.
    pub fn new() -> Self {
        Self::default()
    }

    /// The path with `command` added at its end.
    pub fn push(&mut self, command: PathCommand) {
        self.commands.push(command);
    }

    /// The commands, in order.
    pub fn commands(&self) -> &[PathCommand] {
        &self.commands
    }

    /// Whether it has no command.
    pub fn is_empty(&self) -> bool {
        self.commands.is_empty()
    }

    /// The path with every command of `other` after its own.
    pub fn extend(&mut self, other: PathData) {
        self.commands.extend(other.commands);
    }

    /// A polyline through `points`, closed back to the first if `closed`.
    pub fn polyline(points: &[Point], closed: bool) -> Self {
        let mut d = Self::new();
        for (i, p) in points.iter().enumerate() {
            d.push(if i == 0 {
                PathCommand::Move(*p)
            } else {
                PathCommand::Line(*p)
            });
        }
        if closed {
            d.push(PathCommand::Close);
        }
        d
    }

    /// Cubic Bézier pieces joined end to end, from the first's start.
    pub fn beziers(pieces: &[[Point; 4]]) -> Self {
        let mut d = Self::new();
        if let Some(first) = pieces.first() {
            d.push(PathCommand::Move(first[0]));
        }
        for [_, c1, c2, p] in pieces {
            d.push(PathCommand::Cubic(*c1, *c2, *p));
        }
        d
    }
}

/// How a mark's outline is stroked.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Stroke {
    /// Its colour (a CSS colour).
    pub colour: &'static str,
    /// Its width, page units.
    pub width: f64,
    /// Its dash pattern (dash and gap lengths, page units), if dashed.
    pub dash: Option<&'static str>,
    /// Whether its ends and corners are round (lines), or the writer's
    /// default (circles and filled shapes).
    pub round: bool,
}

/// How a mark is painted: its stroke, if any, and its fill.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Paint {
    /// The outline's stroke; `None` for no outline.
    pub stroke: Option<Stroke>,
    /// The fill colour, `"none"` for none.
    pub fill: &'static str,
    /// The fill's opacity where it is not opaque.
    pub fill_opacity: Option<f64>,
}

impl Paint {
    /// An outline in `pen`, unfilled; round ends where `round`.
    pub(crate) fn stroked(pen: Pen, round: bool) -> Self {
        Paint {
            stroke: Some(Stroke {
                colour: pen.colour,
                width: pen.width,
                dash: pen.dash,
                round,
            }),
            fill: "none",
            fill_opacity: None,
        }
    }

    /// A fill of `colour` without outline.
    pub fn filled(colour: &'static str) -> Self {
        Paint {
            stroke: None,
            fill: colour,
            fill_opacity: None,
        }
    }
}

/// Where a text's anchor point is along its line.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TextAnchor {
    /// At its start.
    Start,
    /// At its middle.
    Middle,
    /// At its end.
    End,
}

/// A text set on the page: where its baseline's anchor is, its size and
/// colour, and whether its base style is italic (its runs differ from it
/// where they say).
#[derive(Debug, Clone, PartialEq)]
pub struct TextMark {
    /// The anchor point on the baseline, page units.
    pub at: Point,
    /// The text, as runs.
    pub text: RichText,
    /// The font size, page units.
    pub size: f64,
    /// The colour.
    pub colour: &'static str,
    /// Where `at` is along the text.
    pub anchor: TextAnchor,
    /// Whether the base style is italic.
    pub italic: bool,
}

/// What a mark draws.
#[derive(Debug, Clone, PartialEq)]
pub enum Shape {
    /// A path.
    Path(PathData, Paint),
    /// A circle about a page point.
    Circle {
        /// Its centre.
        centre: Point,
        /// Its radius, page units.
        radius: f64,
        /// Its paint.
        paint: Paint,
    },
    /// A text.
    Text(TextMark),
    /// Marks drawn one over the other, in order (none draws nothing).
    Group(Vec<Mark>),
}

/// A mark on the page: what it draws, and the id and class of the figure
/// item it draws (none for a piece of an item's group).
#[derive(Debug, Clone, PartialEq)]
pub struct Mark {
    /// The id of the item it draws, unique in the figure.
    pub id: Option<String>,
    /// The item's class (its role's name, or `leader`).
    pub class: Option<&'static str>,
    /// What it draws.
    pub shape: Shape,
}

impl Mark {
    /// A mark of `shape` with no id or class.
    pub fn new(shape: Shape) -> Self {
        Mark {
            id: None,
            class: None,
            shape,
        }
    }

    /// An empty group.
    pub fn group() -> Self {
        Mark::new(Shape::Group(Vec::new()))
    }

    /// The mark with `child` added at the end of its group (a mark that
    /// is not a group is left as it is).
    pub fn with(mut self, child: Mark) -> Self {
        if let Shape::Group(children) = &mut self.shape {
            children.push(child);
        }
        self
    }

    /// The mark with its id and class set.
    pub fn tagged(mut self, id: impl Into<String>, class: &'static str) -> Self {
        self.id = Some(id.into());
        self.class = Some(class);
        self
    }

    /// The mark's paint, if it is a path or a circle.
    fn paint_mut(&mut self) -> Option<&mut Paint> {
        match &mut self.shape {
            Shape::Path(_, paint) | Shape::Circle { paint, .. } => Some(paint),
            _ => None,
        }
    }

    /// The mark filled with `colour` (a path or a circle).
    pub fn fill(mut self, colour: &'static str) -> Self {
        if let Some(p) = self.paint_mut() {
            p.fill = colour;
        }
        self
    }

    /// The mark's fill at `opacity` (a filled path or circle).
    pub fn fill_opacity(mut self, opacity: f64) -> Self {
        if let Some(p) = self.paint_mut() {
            p.fill_opacity = Some(opacity);
        }
        self
    }

    /// The mark's outline dashed with `dash` (a stroked path or circle).
    pub fn dashed(mut self, dash: &'static str) -> Self {
        if let Some(s) = self.paint_mut().and_then(|p| p.stroke.as_mut()) {
            s.dash = Some(dash);
        }
        self
    }
}
