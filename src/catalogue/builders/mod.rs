//! The builders of the catalogue's diagram figures: each file builds one, from plot
//! panels ([`crate::diagram::Plot`]) and, where the textbook draws on the
//! mechanism, a [`crate::scene::Scene`]'s panel with curves added.

pub(super) mod acceleration;
pub(super) mod approximation;
pub(super) mod balance;
pub(super) mod benchmark;
pub(super) mod calibration;
pub(super) mod centrodes;
pub(super) mod chains;
pub(super) mod convergence;
pub(super) mod coriolis;
pub(super) mod coupler;
pub(super) mod crank_detail;
pub(super) mod cranks;
pub(super) mod flywheel;
pub(super) mod forces;
pub(super) mod incline;
pub(super) mod inertia;
pub(super) mod inversions;
pub(super) mod load_letters;
pub(super) mod loads;
pub(super) mod quick_return;
pub(super) mod rod;
pub(super) mod turning;
pub(super) mod unbalanced;
pub(super) mod velocity;

use super::{FigureName, FigureOptions};
use crate::diagram::DEFAULT_TOLERANCE;
use crate::diagram::Plot;
use crate::error::{Error, Field, Input, Result};
use crate::figure::Style;
use crate::figure::{EngineRecord, Figure, Font, Metadata, Panel, RichText};
use crate::figure::{Item, PageFromWorld, Role, Shape};
use crate::figure::{NOTE_LINE, NOTE_SIZE};
use crate::geom::{Frame, Point, Vector};
use crate::number::format_number;
pub(crate) use crate::number::{short, sig};
use crate::scene::{Page, Scene};
use crate::{angle::Angle, mechanism::Pose, mechanism::SliderCrank, units::Unit, units::Units};
use serde_json::Value;

pub(crate) use crate::csv::Table;

/// Radians per degree: the curves' parameter is θ in degrees.
pub(crate) const PER_DEGREE: f64 = std::f64::consts::PI / 180.0;

/// Page margin.
const MARGIN: f64 = 16.0;

/// What a diagram is drawn with: the options resolved against the
/// figure's own values.
pub(crate) struct Ctx<'a> {
    pub name: FigureName,
    pub options: &'a FigureOptions,
    pub mechanism: SliderCrank,
    pub omega: f64,
    pub angle: Angle,
    pub style: Style,
    pub font: Font,
    pub tolerance: f64,
    /// The units named in notes and axis titles.
    pub units: Units,
    /// The page, the catalogue's or the one asked for.
    pub page: Page,
    /// Whether the mechanism is drawn mirrored (the cylinder on the left).
    pub mirror: bool,
}

impl Ctx<'_> {
    /// The length unit of the figure.
    pub fn unit(&self) -> &Unit {
        self.units.length()
    }

    /// The offset as a note's engine line gives it after r and l, signed
    /// and its side said, ", *e* = −0.25 ft (the line of stroke below the
    /// crank centre)": a bare "−0.25 ft" left the reader to know which
    /// way the sign points; empty for an in-line engine.
    pub fn offset_clause(&self) -> String {
        match self.mechanism.offset() {
            0.0 => String::new(),
            e => format!(
                ", *e* = {} {} (the line of stroke {} the crank centre)",
                crate::number::short(e),
                self.unit(),
                if e > 0.0 { "above" } else { "below" }
            ),
        }
    }

    /// The page.
    pub fn page(&self) -> Page {
        self.page
    }

    /// The pose whose construction is drawn.
    pub fn pose(&self) -> Pose {
        self.mechanism.pose(self.angle)
    }

    /// V_c = rω.
    pub fn crank_speed(&self) -> f64 {
        self.mechanism.crank() * self.omega
    }

    /// The crank speed in rpm, for notes.
    pub fn rpm(&self) -> f64 {
        self.omega * 60.0 / std::f64::consts::TAU
    }

    /// The page rectangle inside the margin, from `top` down `height` units.
    pub fn band(&self, top: f64, height: f64) -> Frame {
        let page = self.page();
        Frame::from_origin_size(MARGIN, top, page.width() - 2.0 * MARGIN, height)
    }

    /// A mechanism scene of this figure's engine at its pose, drawn in the
    /// textbook manner (mirrored, the cylinder on the left, unless the
    /// options say otherwise) on a page of `width` × `height`.
    pub fn scene(&self, width: f64, height: f64) -> Result<Scene> {
        Ok(Scene::new(self.mechanism, self.angle)
            .with_name(self.name.name())
            .with_page(Page::new(width, height, MARGIN)?)
            .with_style(self.style)
            .with_font(self.font)
            .with_units(self.units.clone())
            .with_omega(self.omega)
            .with_mirror(self.mirror))
    }
}

/// The reciprocating mass of a figure that draws the inertia force of
/// the reciprocating parts: the one asked for ([`FigureOptions::mass`]), else the
/// example engine's ([`crate::dynamics::EXAMPLE_MASS`]). Errors for a
/// mass that is not positive and finite: with none there is no force to
/// draw, and its scale m ω² would be zero; and for one whose force scale
/// m r ω² lies outside [`MIN_DRAWN_FORCE`] to [`MAX_DRAWN_FORCE`].
pub(crate) fn positive_mass(ctx: &Ctx) -> Result<f64> {
    let m = ctx.options.mass.unwrap_or(crate::dynamics::EXAMPLE_MASS);
    let refuse = |reason: String| Error::OutOfRange {
        name: Field::Mass,
        value: m,
        reason,
    };
    if !(m > 0.0 && m.is_finite()) {
        return Err(refuse(format!(
            "{} draws the inertia force of the reciprocating parts: give a positive, finite mass",
            ctx.name.name()
        )));
    }
    // The forces are drawn at a scale of their own (arrows, a polar
    // diagram, an axis): m r ω² within 1e-280 to 1e140, so that the
    // panel's size, its square and its steps are numbers; named here, as
    // the mass the user gave, not as the panel it would break.
    let force = m * ctx.mechanism.crank() * ctx.omega * ctx.omega;
    if !(MIN_DRAWN_FORCE..=MAX_DRAWN_FORCE).contains(&force) {
        let f = ctx.units.force();
        return Err(refuse(format!(
            "{} draws the inertia force m r ω² = {} {f}, which must lie between {} and {} {f} to be drawn: give the mass, lengths or speed in other units",
            ctx.name.name(),
            crate::number::plain(force),
            crate::number::plain(MIN_DRAWN_FORCE),
            crate::number::plain(MAX_DRAWN_FORCE),
        )));
    }
    Ok(m)
}

/// The smallest inertia force scale m r ω² a dynamics figure draws.
pub(crate) const MIN_DRAWN_FORCE: f64 = 1e-280;

/// The largest inertia force scale m r ω² a dynamics figure draws.
pub(crate) const MAX_DRAWN_FORCE: f64 = 1e140;

/// The italic letter `name` labelling the point `anchor`, id `label-{id}`
/// (placed clear of lines by the renderer).
pub(super) fn letter(id: &str, anchor: Point, name: &str) -> Item {
    Item::new(
        format!("label-{id}"),
        Role::Label,
        Shape::Label {
            anchor,
            text: RichText::italic(name),
            size: crate::figure::TextSize::Letter,
            toward: None,
            line: None,
        },
    )
}

/// The arc about `centre` of `radius` from the angle `start` to the angle
/// `end` (radians) the short way round, as a plain (arrowless) arc.
pub(super) fn short_arc(centre: Point, radius: f64, start: f64, end: f64) -> Shape {
    let tau = std::f64::consts::TAU;
    let sweep = (end - start + std::f64::consts::PI).rem_euclid(tau) - std::f64::consts::PI;
    Shape::Arc {
        centre,
        radius,
        start,
        sweep,
        arrow: false,
    }
}

/// The largest of 1, 2, 2.5 and 5 times a power of ten not above `x`
/// (positive and finite): a scale bar's length.
pub(super) fn round_below(x: f64) -> f64 {
    let decade = 10f64.powf(x.log10().floor());
    [1.0, 2.0, 2.5, 5.0]
        .iter()
        .map(|s| s * decade)
        .filter(|s| *s <= x * (1.0 + 1e-12))
        .fold(decade, f64::max)
}

/// A scale bar `id`, `length` long to the right of `from` (world), its
/// text `text` above it.
pub(super) fn scale_bar(id: &str, from: Point, length: f64, text: &str) -> Item {
    Item::new(
        id,
        Role::Dimension,
        Shape::Dimension {
            from,
            to: Point::new(from.x + length, from.y),
            side: Vector::new(0.0, 1.0),
            offset: 0.0,
            text: RichText::parse(text),
        },
    )
}

/// A diagram's builder: the figure from the options resolved.
pub(crate) type Builder = fn(&Ctx) -> Result<Figure>;

/// Builds the diagram `name` with `options` by its builder `build` (its
/// entry in the table of figures): the options resolved against the
/// figure's own values first, an option it does not take refused.
pub(crate) fn build(name: FigureName, build: Builder, options: &FigureOptions) -> Result<Figure> {
    name.refuse_unused(options)?;
    let omega = options
        .omega
        .unwrap_or_else(|| crate::analytic::kinematics::rpm_to_omega(crate::sources::RPM));
    if !(omega > 0.0 && omega.is_finite()) {
        return Err(Error::OutOfRange {
            name: Field::Omega,
            value: omega,
            reason: "the diagrams are drawn for a crank turning counter-clockwise: give a positive speed"
                .into(),
        });
    }
    let omega = crate::analytic::kinematics::check_omega(omega)?;
    let ctx = Ctx {
        name,
        options,
        mechanism: options.mechanism.unwrap_or_else(|| name.mechanism()),
        omega,
        angle: match options.angle {
            Some(a) => a,
            None => Angle::from_degrees(name.angle_degrees())?,
        },
        style: options.style.unwrap_or(Style::Textbook),
        font: options.font.unwrap_or_default(),
        tolerance: DEFAULT_TOLERANCE,
        units: name
            .units()
            .asked(options.length_unit.as_ref(), options.force_unit.as_ref()),
        page: options.page(&name.page())?,
        mirror: options.mirror.unwrap_or(!name.is_ng()),
    };
    let page = ctx.page;
    let built = build(&ctx);
    // A page asked for that the diagram's bands do not fit: say so in its
    // terms rather than a plot's.
    let asked = options.width.is_some() || options.height.is_some();
    built.map_err(|e| match e {
        Error::OutOfRange {
            name: Field::PanelWidth,
            ..
        } if asked => Error::invalid(Input::PageLength, format!(
            "a page of {} × {} units leaves no room for the plots of {}: give it a larger width or height",
            format_number(page.width(), 1),
            format_number(page.height(), 1),
            name.name()
        )),
        e => e,
    })
}

/// A figure being assembled from panels.
pub(crate) struct Sheet {
    name: FigureName,
    page: Page,
    title: Option<crate::figure::Title>,
    style: Style,
    font: Font,
    tolerance: f64,
    panels: Vec<Panel>,
    meta: Metadata,
    /// The page's height when not the catalogue's (fitted to a drawing).
    height: Option<f64>,
    /// The height the notes' wrapped lines add to what the sheet laid
    /// out for them (a line each), page units: the page grows by it.
    notes_extra: f64,
}

impl Sheet {
    pub fn new(ctx: &Ctx) -> Self {
        Self {
            name: ctx.name,
            page: ctx.page,
            title: ctx.options.title.clone(),
            style: ctx.style,
            font: ctx.font,
            tolerance: ctx.tolerance,
            panels: Vec::new(),
            meta: Metadata::new(),
            height: None,
            notes_extra: 0.0,
        }
    }

    /// Ends the page at `bottom` plus the margin (no higher than the
    /// figure's page): for sheets whose mechanism panel is fitted to the
    /// pose, so that no empty band is left below.
    pub fn fit(&mut self, bottom: f64) {
        self.height((bottom + MARGIN).min(self.page.height()));
    }

    /// Narrows the page to `width` where its drawing came out narrower
    /// (a scene narrowed to what it draws, [`Page::with_width_fitted`]);
    /// a wider `width` leaves it as it is.
    pub fn narrow(&mut self, width: f64) -> Result<()> {
        if width < self.page.width() {
            self.page = self.page.with_width(width)?;
        }
        Ok(())
    }

    /// Sets the page's height (a page fitted to its drawing).
    pub fn height(&mut self, height: f64) {
        self.height = Some(height);
    }

    /// Records the mechanism, speed and pose in the metadata.
    pub fn mechanism(&mut self, ctx: &Ctx, with_speed: bool, with_angle: bool) {
        let m = &ctx.mechanism;
        self.meta.set_engine(EngineRecord {
            crank: m.crank(),
            rod: m.rod(),
            offset: m.offset(),
            unit: ctx.unit().to_string(),
        });
        if with_speed {
            self.meta.set_omega(ctx.omega);
        }
        if with_angle {
            self.meta.set_angle_deg(ctx.angle.degrees());
        }
    }

    /// Adds a metadata key.
    pub fn meta(&mut self, key: &str, value: Value) {
        self.meta.insert(key, value);
    }

    /// Adds a plot's panel and its description.
    pub fn plot(&mut self, plot: Plot) {
        self.meta.push_plot(plot.record());
        self.panels.push(plot.finish());
    }

    /// Adds a plot as a detail: nothing drawn outside its plot area (its
    /// links and circles run on beyond the region it enlarges), its
    /// caption below it ([`Plot::finish_detail`]).
    pub fn detail(&mut self, plot: Plot) {
        self.meta.push_plot(plot.record());
        let (drawn, caption) = plot.finish_detail();
        self.panels.push(drawn);
        self.panels.extend(caption);
    }

    /// Adds a panel as it is.
    pub fn panel(&mut self, panel: Panel) {
        self.panels.push(panel);
    }

    /// Lines of notes from `corner` (page units) down, in a panel of their
    /// own (`panel-notes`).
    /// Each line is broken to fit the page at the notes' size (as the
    /// writer sets them from `corner`, with 8 units to spare), so that a
    /// narrow page adds lines, and grows to hold them, instead of
    /// shrinking the type.
    pub fn notes(&mut self, corner: Point, lines: &[String]) {
        let room = self.page.width() - MARGIN - corner.x - 8.0;
        let given = lines.len();
        let lines: Vec<RichText> = lines
            .iter()
            .flat_map(|l| RichText::parse(l).wrap(self.font, NOTE_SIZE, room))
            .collect();
        self.notes_extra = NOTE_LINE * lines.len().saturating_sub(given) as f64;
        let item = Item::new("note-diagram", Role::Label, Shape::Note { corner, lines });
        let page = self.page;
        let rect = Frame::from_origin_size(
            corner.x,
            corner.y,
            (page.width() - MARGIN - corner.x).max(1.0),
            (self.height.unwrap_or(page.height()) + self.notes_extra - MARGIN - corner.y).max(1.0),
        );
        self.panels.push(Panel::new(
            "panel-notes",
            rect,
            PageFromWorld::identity(),
            vec![item],
        ));
    }

    /// The figure, with every number of its metadata rounded to 12
    /// significant digits (stable text).
    pub fn finish(self) -> Figure {
        let page = self.page;
        let height = self.height.unwrap_or(page.height()) + self.notes_extra;
        let figure = Figure::new(
            self.name.name(),
            page.width(),
            height,
            self.style,
            self.tolerance,
            self.panels,
            self.meta.rounded(crate::scene::round),
        )
        .with_font(self.font)
        .with_size_unit(page.unit());
        match self.title {
            Some(t) => figure.with_title(t),
            None => figure,
        }
    }
}

/// The rectangle, from the top margin down, of a world panel showing
/// `world` whole across the page's width (less the margins) with a caption
/// below, no taller than the catalogue's page leaves above notes
/// `notes_height` tall.
pub(crate) fn fitted_rect(page: &Page, world: &crate::geom::Frame, notes_height: f64) -> Frame {
    let width = page.width() - 2.0 * MARGIN;
    let most = page.height() - 2.0 * MARGIN - notes_height - crate::diagram::CAPTION;
    let size = world.max() - world.min();
    let tall = if size.x > 0.0 && size.y.is_finite() {
        (width * size.y / size.x).clamp(60.0, most.max(60.0))
    } else {
        most
    };
    Frame::from_origin_size(MARGIN, MARGIN, width, tall + crate::diagram::CAPTION)
}

/// A value of the pose against the crank angle: the point (θ in degrees,
/// f) and its derivative per degree, from `f` giving the value and its
/// derivative per radian.
pub(crate) fn against_angle<'a>(
    m: SliderCrank,
    f: impl Fn(&Pose) -> (f64, f64) + 'a,
) -> impl Fn(f64) -> Option<(Point, Vector)> + 'a {
    move |deg| {
        let pose = m.pose(Angle::from_degrees(deg).ok()?);
        let (v, dv) = f(&pose);
        Some((Point::new(deg, v), Vector::new(1.0, dv * PER_DEGREE)))
    }
}

/// The same against time t = θ/ω (θ in radians), parameter θ in degrees.
pub(crate) fn against_time<'a>(
    m: SliderCrank,
    omega: f64,
    f: impl Fn(&Pose) -> (f64, f64) + 'a,
) -> impl Fn(f64) -> Option<(Point, Vector)> + 'a {
    move |deg| {
        let pose = m.pose(Angle::from_degrees(deg).ok()?);
        let (v, dv) = f(&pose);
        Some((
            Point::new(deg * PER_DEGREE / omega, v),
            Vector::new(PER_DEGREE / omega, dv * PER_DEGREE),
        ))
    }
}

/// The same against the displacement of A from the outer dead centre,
/// x₀ − x_A, parameter θ in degrees.
pub(crate) fn against_travel<'a>(
    m: SliderCrank,
    f: impl Fn(&Pose) -> (f64, f64) + 'a,
) -> impl Fn(f64) -> Option<(Point, Vector)> + 'a {
    let (r, l, e) = (m.crank(), m.rod(), m.offset());
    let far = ((l + r - e) * (l + r + e)).sqrt();
    move |deg| {
        let pose = m.pose(Angle::from_degrees(deg).ok()?);
        let (v, dv) = f(&pose);
        Some((
            Point::new(far - pose.position(), v),
            Vector::new(-pose.position_rate() * PER_DEGREE, dv * PER_DEGREE),
        ))
    }
}

/// The dead centres in degrees, outer then inner (0° and 180° in line).
pub(crate) fn dead_centres(m: &SliderCrank) -> (f64, f64) {
    let (outer, inner) = m.dead_centres();
    (outer.to_degrees(), inner.to_degrees())
}

/// Largest |value| of `f` over a turn (721 samples), for axis ranges.
pub(crate) fn extent(m: &SliderCrank, f: impl Fn(&Pose) -> f64) -> (f64, f64) {
    (0..=720)
        .filter_map(|k| Angle::from_degrees(k as f64 * 0.5).ok())
        .map(|a| f(&m.pose(a)))
        .filter(|v| v.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
            (lo.min(v), hi.max(v))
        })
}
