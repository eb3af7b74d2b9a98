//! Scenes: what one figure shows, and the lazy evaluation that computes
//! only what its layers draw.
//!
//! A [`Scene`] is a mechanism, one pose (or several for an overlay), the
//! [`Layer`]s to draw, the page, the style and whether to mirror. Building
//! it ([`Scene::build`]) asks each layer, in a fixed order, for the
//! constructions it needs through a cache that computes each at most once
//! and counts it ([`Evaluations`]); the result is an immutable
//! [`Figure`] in world coordinates. The page is fitted to the scene's own
//! pose, or held over a range of poses ([`Scene::with_held_view`],
//! [`Scene::frames`]) so that a series of figures shares one map.

mod cache;
mod canvas;
mod draw;
mod edge_letters;
mod layer;
mod letter_ways;
mod linkage;
mod notation;
pub(crate) mod valid;

pub use cache::Evaluations;
pub(crate) use canvas::{Canvas, Marker, round};
pub(crate) use draw::{
    COINCIDE, LINK_BESIDE, LINK_JOG, letter_near_together, offset_note, path_beside, torque_arrow,
};
pub use layer::Layer;
pub(crate) use letter_ways::{LINK_LETTER_NEAR, letter_ways};
pub(crate) use linkage::{BEARING_REACH, PIN_CLEAR, Seg, Slot};
pub use notation::Notation;

use crate::construct::CouplerPoint;
use crate::error::{Error, Field, Result, finite, positive};
use crate::figure::Figure;
use crate::figure::Font;
use crate::figure::Style;
use crate::figure::{PageLength, PageUnit, Title};
use crate::number::plain;
use crate::{angle::Angle, mechanism::SliderCrank, units::Unit, units::Units};

use crate::diagram::DEFAULT_TOLERANCE;

/// The bounds of a page's size, as a refusal gives them.
/// How far, page units, a figure may end past a fixed page height (the
/// rounding of its parts' sizes) before it is refused.
const HEIGHT_SLACK: f64 = 0.5;
/// The narrowest page a figure's own page is narrowed to
/// ([`Page::with_width_fitted`]), page units: room for a line of notes.
pub const LEAST_FITTED_WIDTH: f64 = 420.0;
/// A page is narrowed where its drawing takes less than this share of
/// its width.
const FIT_WIDTH_BELOW: f64 = 0.85;

const PAGE_RANGE: &str =
    "a page is between 50 and 20000 units (px, 96 to the inch: 13.3 mm to 5.29 m)";

/// Page units in a message: two decimals at most (`9.6`), exponent form
/// far from the page's range (`1.8e-322`, not 0), words for an overflow
/// (`1e308mm is more than the largest number of page units`).
fn units_text(units: f64) -> String {
    if (0.01..1e15).contains(&units) {
        let text = format!("{units:.2}");
        text.trim_end_matches('0').trim_end_matches('.').to_string()
    } else if units.is_finite() {
        plain(units)
    } else {
        "more than the largest number of".into()
    }
}

/// A page: its size and the margin kept clear on every side, in page units
/// (SVG user units, 1/96 in), and the unit the SVG gives its size in.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Page {
    width: f64,
    height: f64,
    margin: f64,
    unit: PageUnit,
    /// Whether the height is fixed ([`Page::with_fixed_height`]).
    fixed_height: bool,
    fitted: bool,
}

impl Page {
    /// A page of `width` × `height` with `margin`; each finite, the size
    /// between 50 and 20000, the margin ≥ 0 and leaving at least 50 units
    /// of drawing each way (a margin above 9975, which leaves none on any
    /// page, is refused as the margin).
    pub fn new(width: f64, height: f64, margin: f64) -> Result<Self> {
        let width = positive(Field::PageWidth, width)?;
        let height = positive(Field::PageHeight, height)?;
        let margin = finite(Field::PageMargin, margin)?;
        for (name, v) in [(Field::PageWidth, width), (Field::PageHeight, height)] {
            if !(50.0..=20000.0).contains(&v) {
                return Err(Error::OutOfRange {
                    name,
                    value: v,
                    reason: PAGE_RANGE.into(),
                });
            }
        }
        // A margin that no page could hold (none is wider than 20000) is
        // the margin's fault, whatever the page.
        if margin < 0.0 || 2.0 * margin + 50.0 > 20000.0 {
            return Err(Error::OutOfRange {
                name: Field::PageMargin,
                value: margin,
                reason: "the margin must be ≥ 0 and leave at least 50 units each way on a page of at most 20000: at most 9975".into(),
            });
        }
        // A page too small for the margin names the side given, not the
        // margin (which a figure sets itself: a width of 60 asked for has no
        // margin).
        for (name, v) in [(Field::PageWidth, width), (Field::PageHeight, height)] {
            if v - 2.0 * margin < 50.0 {
                return Err(Error::OutOfRange {
                    name,
                    value: v,
                    reason: format!(
                        "a margin of {} on each side leaves less than 50 units of drawing: give at least {}",
                        plain(margin),
                        plain(50.0 + 2.0 * margin)
                    ),
                });
            }
        }
        Ok(Self {
            width,
            height,
            margin,
            unit: PageUnit::Px,
            fixed_height: false,
            fitted: false,
        })
    }

    /// A page of `width` × `height` given with their units ([`PageLength`]:
    /// `800`, `120mm`, `4.5in`), laid out in page units (96 to the inch),
    /// with `margin` in page units. The SVG gives its size in the unit of
    /// `width` if that is physical (mm, cm, in or pt), else in that of `height`
    /// ([`Page::unit`]). The bounds are those of [`Page::new`].
    pub fn sized(width: PageLength, height: PageLength, margin: f64) -> Result<Self> {
        let unit = if width.unit().is_physical() {
            width.unit()
        } else {
            height.unit()
        };
        let page = Self::new(width.page_units(), height.page_units(), margin);
        // A size out of bounds is named as it was given (`0.1in`), also
        // when its page units overflow (`1e308mm`, not "got inf").
        let page = page.map_err(|e| {
            let (name, reason) = match e {
                Error::OutOfRange {
                    name: name @ (Field::PageWidth | Field::PageHeight),
                    reason,
                    ..
                } => (name, reason),
                Error::NotFinite {
                    name: name @ (Field::PageWidth | Field::PageHeight),
                    ..
                } => (name, PAGE_RANGE.to_string()),
                e => return e,
            };
            let given = if name == Field::PageWidth {
                width
            } else {
                height
            };
            Error::OutOfRange {
                name,
                value: given.value(),
                reason: if given.unit().is_physical() {
                    format!(
                        "{given} is {} page units; {reason}",
                        units_text(given.page_units())
                    )
                } else {
                    reason
                },
            }
        })?;
        Ok(page.with_unit(unit))
    }

    /// The same page with its size written in `unit` in the SVG
    /// (`width="120mm"`); the layout is unchanged.
    pub fn with_unit(mut self, unit: PageUnit) -> Self {
        self.unit = unit;
        self
    }

    /// The same page with its height fixed (the height an author asks
    /// for): a mechanism figure fits its drawing within it, and one whose
    /// detail or notes would grow the page past it is refused by
    /// [`Scene::build`], naming the height it needs, instead of coming out
    /// taller than asked.
    pub fn with_fixed_height(mut self) -> Self {
        self.fixed_height = true;
        self
    }

    /// The same page with its width the most the drawing takes: a
    /// mechanism figure whose drawing is fitted to the height (a short
    /// rod, whose crank circle is as tall as the engine is long) comes on
    /// a page narrowed to what it draws, at least [`LEAST_FITTED_WIDTH`]
    /// units, and its notes are set to that width. The figures' own pages;
    /// a width asked for is kept.
    pub fn with_width_fitted(mut self) -> Self {
        self.fitted = true;
        self
    }

    /// The same page with its width kept whatever the drawing takes
    /// (the default for a page made with [`Page::new`]): a page that sets
    /// its figures to a column's width, where a narrower figure would
    /// print taller.
    pub fn with_width_kept(mut self) -> Self {
        self.fitted = false;
        self
    }

    /// Whether the width may be narrowed to the drawing
    /// ([`Page::with_width_fitted`]).
    pub fn fits_width(&self) -> bool {
        self.fitted
    }

    /// The same page `width` units wide (the other settings kept); errors
    /// as [`Page::new`] for a width out of range.
    pub(crate) fn with_width(self, width: f64) -> Result<Self> {
        let page = Self::new(width, self.height, self.margin)?;
        Ok(Self {
            unit: self.unit,
            fixed_height: self.fixed_height,
            fitted: self.fitted,
            ..page
        })
    }

    /// The same page with its height the most the main drawing takes
    /// (the default): the page grows for a detail and for notes.
    pub(crate) fn with_height_free(mut self) -> Self {
        self.fixed_height = false;
        self
    }

    /// Whether the height is fixed ([`Page::with_fixed_height`]);
    /// otherwise it is the most the main drawing takes, and the page grows
    /// for a detail and for notes. (A view is *held* over several poses,
    /// [`Scene::with_held_view`]; a page's height is *fixed*.)
    pub fn has_fixed_height(&self) -> bool {
        self.fixed_height
    }

    /// The unit the SVG gives the page's size in (page units unless a
    /// physical size was asked).
    pub fn unit(&self) -> PageUnit {
        self.unit
    }

    /// Width.
    pub fn width(&self) -> f64 {
        self.width
    }

    /// Height.
    pub fn height(&self) -> f64 {
        self.height
    }

    /// Margin.
    pub fn margin(&self) -> f64 {
        self.margin
    }
}

impl Default for Page {
    /// 760 × 460 with a margin of 16.
    fn default() -> Self {
        Self {
            width: 760.0,
            height: 460.0,
            margin: 16.0,
            unit: PageUnit::Px,
            fixed_height: false,
            fitted: false,
        }
    }
}

/// What one figure shows. Built with [`Scene::new`] and the `with_*`
/// methods, which cannot fail: the settings that can be out of range (the
/// speed, the torque, the tolerance, the number of poses) are checked
/// once, together, when the figure is built ([`Scene::build`],
/// [`Scene::figure`], [`Scene::frames`]), with one `Result`. Read from
/// TOML with [`SceneFile::from_toml`](crate::catalogue::SceneFile::from_toml), which
/// checks each value where the file gives it.
///
/// ```
/// use slider_crank::{Angle, Layer, Scene, SliderCrank};
/// let figure = Scene::new(SliderCrank::in_line(0.5, 3.0)?, Angle::deg(30.0))
///     .with_layers([Layer::Mechanism, Layer::Velocity, Layer::Torque])
///     .with_omega(26.18)
///     .with_torque(12.0)
///     .with_mirror(true)
///     .figure()?;
/// # Ok::<(), slider_crank::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct Scene {
    name: String,
    mechanism: SliderCrank,
    angles: Vec<Angle>,
    layers: Vec<Layer>,
    style: Style,
    font: Font,
    notation: Notation,
    mirror: bool,
    page: Page,
    omega: f64,
    units: Units,
    title: Option<Title>,
    torque: f64,
    coupler: CouplerPoint,
    tolerance: f64,
    /// The poses the page map is held over ([`Scene::with_held_view`]).
    held_view: Option<Vec<Angle>>,
    /// A world frame the view holds besides what the layers draw
    /// ([`Scene::with_view_holding`]).
    holding: Option<crate::geom::Frame>,
    /// A subject drawn on the mechanism that a detail holds where the
    /// main view draws it small ([`Scene::with_detail_subject`]).
    subject: Option<crate::geom::Frame>,
    /// Where curves drawn on the mechanism turn, reaching their highest
    /// or lowest (world x, and height above the line of stroke, negative
    /// below), which the guides keep clear of
    /// ([`Scene::with_guides_clear_of`]).
    extremes: Vec<(f64, f64)>,
    /// Whether the figure is drawn without an enlarged detail
    /// ([`Scene::without_detail`]).
    no_detail: bool,
}

/// The poses a series is held over by default: the whole revolution,
/// every degree.
// cannot fail: whole degrees 0 to 359 are finite.
#[allow(clippy::expect_used)]
fn revolution() -> Vec<Angle> {
    (0..360)
        .map(|d| Angle::from_degrees(f64::from(d)).expect("finite"))
        .collect()
}

impl Scene {
    /// The mechanism at `angle`, drawn with the mechanism layer only, in the
    /// textbook style, not mirrored, on the default page, untitled; 250
    /// rpm, lengths in feet and forces in pounds-force
    /// ([`Units::FOOT_POUND`]), torque 1.
    // cannot fail: the coupler point's fraction is the constant 0.5.
    #[allow(clippy::expect_used)]
    pub fn new(mechanism: SliderCrank, angle: Angle) -> Self {
        Self {
            name: "scene".into(),
            mechanism,
            angles: vec![angle],
            layers: vec![Layer::Mechanism],
            style: Style::Textbook,
            font: Font::default(),
            notation: Notation::Textbook,
            mirror: false,
            page: Page::default(),
            omega: crate::analytic::kinematics::rpm_to_omega(crate::sources::RPM),
            units: Units::FOOT_POUND,
            title: None,
            torque: 1.0,
            coupler: CouplerPoint::new(0.5).expect("0.5 is in [0, 1]"),
            tolerance: DEFAULT_TOLERANCE,
            held_view: None,
            holding: None,
            subject: None,
            extremes: Vec::new(),
            no_detail: false,
        }
    }

    /// The same scene for another mechanism (poses, layers and page are
    /// kept; constructions are made anew when the figure is built).
    pub fn with_mechanism(mut self, mechanism: SliderCrank) -> Self {
        self.mechanism = mechanism;
        self
    }

    /// Names the figure (the `figure` of its metadata).
    pub fn with_name(mut self, name: impl Into<String>) -> Self {
        self.name = name.into();
        self
    }

    /// The poses: the first carries the constructions, the others are
    /// drawn as ghosts by the mechanism layer. Building the figure fails
    /// when there is none or more than 64.
    pub fn with_angles(mut self, angles: Vec<Angle>) -> Self {
        self.angles = angles;
        self
    }

    /// The layers to draw (order and repeats do not matter).
    pub fn with_layers(mut self, layers: impl IntoIterator<Item = Layer>) -> Self {
        let mut l: Vec<Layer> = layers.into_iter().collect();
        l.sort();
        l.dedup();
        self.layers = l;
        self
    }

    /// The style.
    pub fn with_style(mut self, style: Style) -> Self {
        self.style = style;
        self
    }

    /// The face of the text.
    pub fn with_font(mut self, font: Font) -> Self {
        self.font = font;
        self
    }

    /// The letters.
    pub fn with_notation(mut self, notation: Notation) -> Self {
        self.notation = notation;
        self
    }

    /// Draws the cylinder on the left (a page transform; the world frame is
    /// unchanged).
    pub fn with_mirror(mut self, mirror: bool) -> Self {
        self.mirror = mirror;
        self
    }

    /// The page.
    pub fn with_page(mut self, page: Page) -> Self {
        self.page = page;
        self
    }

    /// The crank speed ω in rad/s, for scale notes. Building the figure
    /// fails unless it is non-zero and within [`crate::analytic::kinematics::MAX_OMEGA`].
    pub fn with_omega(mut self, omega: f64) -> Self {
        self.omega = omega;
        self
    }

    /// The units written in notes and metadata: names only, the numbers
    /// are not converted (give the mechanism in the length unit).
    pub fn with_units(mut self, units: Units) -> Self {
        self.units = units;
        self
    }

    /// The same units with another length unit (`mm`).
    pub fn with_length_unit(mut self, unit: Unit) -> Self {
        self.units = self.units.with_length(unit);
        self
    }

    /// The same units with another force unit (`N`).
    pub fn with_force_unit(mut self, unit: Unit) -> Self {
        self.units = self.units.with_force(unit);
        self
    }

    /// A title, set centred below the figure and written as the SVG's
    /// `<title>` ([`crate::figure::Figure::with_title`]).
    pub fn with_title(mut self, title: Title) -> Self {
        self.title = Some(title);
        self
    }

    /// The crank torque of the torque layer, in force × length. Building
    /// the figure fails unless it is finite.
    pub fn with_torque(mut self, torque: f64) -> Self {
        self.torque = torque;
        self
    }

    /// The point of the rod whose path the coupler layer draws.
    pub fn with_coupler(mut self, point: CouplerPoint) -> Self {
        self.coupler = point;
        self
    }

    /// The drawing tolerance of curves in page units. Building the figure
    /// fails unless it is in [1e-6, 10].
    pub fn with_tolerance(mut self, tolerance: f64) -> Self {
        self.tolerance = tolerance;
        self
    }

    /// Holds the page map over the poses at `angles`: the figure is laid
    /// out once for what the scene draws at all of them (the drawing, the
    /// room for the notes, the detail) instead of for its own pose, so that
    /// figures drawn at any of those angles share one page-from-world map
    /// per panel and one page size, as the frames of an animation or a
    /// series of plates must. [`Scene::frames`] draws such a series, held
    /// over the whole revolution unless the scene holds other poses.
    ///
    /// - D is fitted into the page wherever it comes within 0.8 (l + r) of
    ///   the line of stroke at one of the poses; farther, and at infinity
    ///   (θ = 90° and 270°, CB perpendicular to the stroke), it is shown by
    ///   an arrow at the frame's edge, as in a single figure. Near those
    ///   angles D climbs far from the stroke: the held view is fitted to
    ///   what the poses draw without D, and D is drawn where it falls on
    ///   the page, else shown by its arrow at the frame's edge, so that a
    ///   view held over the whole turn draws the mechanism as large as
    ///   its other constructions allow.
    /// - The detail (the acceleration constructions of Figs. 65–67, and a
    ///   velocity triangle too small to letter) is held too: when any pose
    ///   needs one, every figure has one, showing the union of the regions
    ///   the poses' details would show at the least of their
    ///   magnifications, lowered until it fits the page's width (none when
    ///   not even ×2 fits). The constructions of a pose outside that
    ///   region are clipped at its border.
    /// - A pose outside the range is drawn in the same map: whatever it
    ///   draws beyond what the range draws may leave the page (lines are
    ///   clipped to it, far points shown by arrows at its edge), and if it
    ///   has more notes than any pose of the range, the page grows below
    ///   for them (the maps stay).
    ///
    /// The constructions computed for the fit are not counted in the
    /// figure's [`Evaluations`], which count what it draws. Building the
    /// figure fails when `angles` is empty or holds more than 3960 angles.
    pub fn with_held_view(mut self, angles: Vec<Angle>) -> Self {
        self.held_view = Some(angles);
        self
    }

    /// The same scene drawn without the enlarged detail of its
    /// constructions about the crank: for a page shown large (a
    /// projector's screen, where the whole page is the enlargement), not
    /// for print, where a construction the main view draws small is
    /// lettered only in its detail. The main view is unchanged.
    pub fn without_detail(mut self) -> Self {
        self.no_detail = true;
        self
    }

    /// Whether the figure is drawn without its detail
    /// ([`Scene::without_detail`]).
    pub(crate) fn has_no_detail(&self) -> bool {
        self.no_detail
    }

    /// The same scene with a view fitted to hold the world `frame` too,
    /// besides what its layers draw: the room for what a diagram draws
    /// on the mechanism in its own world coordinates (Fig. 64's polar
    /// diagram and distance base, whose heights CE exceed the crank at
    /// short rods). A frame that is not finite is left out.
    pub(crate) fn with_view_holding(mut self, frame: crate::geom::Frame) -> Self {
        let finite = |p: crate::geom::Point| p.x.is_finite() && p.y.is_finite();
        self.holding = (finite(frame.min()) && finite(frame.max())).then_some(frame);
        self
    }

    /// The same scene with `frame` (world) named as a subject that a
    /// diagram draws on the mechanism in its own world coordinates (Fig.
    /// 64's polar diagram about the crank): where the main view draws it
    /// smaller than a reader can read (a long rod's crank), the scene's
    /// detail holds it whole, enlarged, for the diagram to draw there too.
    /// A frame that is not finite is left out.
    pub(crate) fn with_detail_subject(mut self, frame: crate::geom::Frame) -> Self {
        let finite = |p: crate::geom::Point| p.x.is_finite() && p.y.is_finite();
        self.subject = (finite(frame.min()) && finite(frame.max())).then_some(frame);
        self
    }

    /// The subject a diagram draws on the mechanism
    /// ([`Scene::with_detail_subject`]), if any.
    pub(crate) fn subject(&self) -> Option<&crate::geom::Frame> {
        self.subject.as_ref()
    }

    /// The same scene with its guides set clear of curves drawn on the
    /// mechanism that turn (reach their highest or lowest) at `extremes`,
    /// world x and height above the line of stroke: the coupler curves'
    /// ovals, whose tops ran along a guide. The channel between the
    /// guides keeps its height where the turns over the guides' stretch
    /// are clear of them (or none is finite), else takes the height
    /// within bounds that stands farthest from every such turn
    /// ([`draw`]'s `channel_clear_of`).
    pub(crate) fn with_guides_clear_of(mut self, extremes: Vec<(f64, f64)>) -> Self {
        self.extremes = (extremes.into_iter())
            .filter(|(x, y)| x.is_finite() && y.is_finite())
            .collect();
        self
    }

    /// Where curves drawn on the mechanism turn, their highest and lowest
    /// points ([`Scene::with_guides_clear_of`]).
    pub(crate) fn extremes(&self) -> &[(f64, f64)] {
        &self.extremes
    }

    /// The world frame the view holds besides what the layers draw
    /// ([`Scene::with_view_holding`]), if any.
    pub(crate) fn holding(&self) -> Option<&crate::geom::Frame> {
        self.holding.as_ref()
    }

    /// The poses the page map is held over ([`Scene::with_held_view`]); `None`
    /// when the figure is fitted to its own pose.
    pub fn held_view(&self) -> Option<&[Angle]> {
        self.held_view.as_deref()
    }

    /// The figures of the scene at each of `angles`, in order: its first
    /// pose moved to each angle (the ghosts of an overlay stay where they
    /// are), all laid out once in a view held over the scene's
    /// [`Scene::held_view`] poses, or over the whole revolution (every degree)
    /// when it holds none. Every frame then has the same page-from-world
    /// map in each panel and the same page size (see
    /// [`Scene::with_held_view`] for D at infinity, the detail and poses
    /// outside the range). Each frame is the figure of
    /// `self.with_held_view(range).with_angles(..)`, byte for byte. Errors
    /// when `angles` is empty or holds more than 3960 angles.
    ///
    /// ```
    /// use slider_crank::{Angle, Layer, Scene, SliderCrank};
    /// let scene = Scene::new(SliderCrank::in_line(0.5, 3.0)?, Angle::from_degrees(0.0)?)
    ///     .with_layers([Layer::Mechanism, Layer::Velocity]);
    /// let angles: Vec<Angle> = (0..36)
    ///     .map(|k| Angle::from_degrees(10.0 * f64::from(k)))
    ///     .collect::<Result<_, _>>()?;
    /// let frames = scene.frames(&angles)?;
    /// assert_eq!(frames.len(), 36);
    /// assert!(frames.iter().all(|f| f.panels()[0].transform() == frames[0].panels()[0].transform()));
    /// # Ok::<(), slider_crank::Error>(())
    /// ```
    pub fn frames(&self, angles: &[Angle]) -> Result<Vec<Figure>> {
        Ok(self.frame_series(angles)?.collect())
    }

    /// The figures [`Scene::frames`] draws, one at a time: the view is
    /// laid out at once, each frame when the iterator reaches it (for a
    /// long series shown with its progress, or written as it is drawn).
    /// Errors as [`Scene::frames`].
    pub fn frame_series<'a>(
        &self,
        angles: &'a [Angle],
    ) -> Result<impl Iterator<Item = Figure> + use<'a>> {
        valid::scene(self)?;
        if angles.is_empty() || angles.len() > valid::MAX_HELD {
            return Err(Error::OutOfRange {
                name: Field::Frames,
                value: angles.len() as f64,
                reason: format!("a series has 1 to {} frames", valid::MAX_HELD),
            });
        }
        let range = match &self.held_view {
            Some(held) => held.clone(),
            None => revolution(),
        };
        let held = self.clone().with_held_view(range);
        valid::scene(&held)?;
        let layout = draw::held_view(&held, held.held_view().unwrap_or_default());
        Ok(angles.iter().map(move |a| {
            let mut frame = held.clone();
            // The first pose moved; the number of poses is unchanged, so
            // the frame stays as valid as the held scene.
            if let Some(first) = frame.angles.first_mut() {
                *first = *a;
            }
            draw::build(&frame, &layout).0
        }))
    }

    /// The figure's name.
    pub fn name(&self) -> &str {
        &self.name
    }

    /// The mechanism.
    pub fn mechanism(&self) -> &SliderCrank {
        &self.mechanism
    }

    /// The poses (at least one).
    pub fn angles(&self) -> &[Angle] {
        &self.angles
    }

    /// The layers, in drawing order.
    pub fn layers(&self) -> &[Layer] {
        &self.layers
    }

    /// Whether `layer` is drawn.
    pub fn has(&self, layer: Layer) -> bool {
        self.layers.contains(&layer)
    }

    /// The style.
    pub fn style(&self) -> Style {
        self.style
    }

    /// The face of the text.
    pub fn font(&self) -> Font {
        self.font
    }

    /// The letters.
    pub fn notation(&self) -> Notation {
        self.notation
    }

    /// Whether the page is mirrored.
    pub fn is_mirrored(&self) -> bool {
        self.mirror
    }

    /// The page.
    pub fn page(&self) -> &Page {
        &self.page
    }

    /// Crank speed ω in rad/s.
    pub fn omega(&self) -> f64 {
        self.omega
    }

    /// The units.
    pub fn units(&self) -> &Units {
        &self.units
    }

    /// The title, if any.
    pub fn title(&self) -> Option<&Title> {
        self.title.as_ref()
    }

    /// Crank torque.
    pub fn torque(&self) -> f64 {
        self.torque
    }

    /// The coupler point.
    pub fn coupler(&self) -> CouplerPoint {
        self.coupler
    }

    /// The curve tolerance in page units.
    pub fn tolerance(&self) -> f64 {
        self.tolerance
    }

    /// Builds the figure, computing only what the layers draw. Errors
    /// name the first setting out of range (see [`Scene::build`]).
    pub fn figure(&self) -> Result<Figure> {
        Ok(self.build()?.0)
    }

    /// Builds the figure and says what was computed for it: fitted to
    /// its own pose, or in the view held over [`Scene::held_view`]. The one
    /// check of the settings: the speed non-zero and within
    /// [`crate::analytic::kinematics::MAX_OMEGA`], the torque finite, the tolerance in
    /// [1e-6, 10], 1 to 64 poses, 1 to 3960 held poses.
    pub fn build(&self) -> Result<(Figure, Evaluations)> {
        valid::scene(self)?;
        let layout = match self.held_view.as_deref() {
            Some(a) => draw::held_view(self, a),
            None => draw::own(self),
        };
        if self.held_view.is_none() && self.page.fits_width() {
            let used = draw::used_width(self, &layout).max(LEAST_FITTED_WIDTH);
            if used < FIT_WIDTH_BELOW * self.page.width() {
                let mut narrow = self.clone();
                narrow.page = self.page.with_width(used.ceil())?;
                narrow.page.fitted = false;
                return narrow.build();
            }
        }
        let (figure, evaluations) = draw::build(self, &layout);
        let page = self.page;
        if page.has_fixed_height() && figure.height() > page.height() + HEIGHT_SLACK {
            return Err(Error::OutOfRange {
                name: Field::PageHeight,
                value: page.height(),
                reason: format!(
                    "this figure needs {} page units at this width (its drawing, detail and notes); \
                     give at least that, or leave the height to the figure",
                    figure.height().ceil()
                ),
            });
        }
        Ok((figure, evaluations))
    }
}
