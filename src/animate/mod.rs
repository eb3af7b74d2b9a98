//! Animations: one revolution of a mechanism figure, its constructions
//! moving with the crank.
//!
//! An [`Animation`] is a series of still figures of one [`Scene`], the
//! crank turned by equal steps through a whole revolution from the scene's
//! own pose, all drawn in one view held over the revolution
//! ([`Scene::frames`]), so that nothing moves but the mechanism and its
//! constructions: E slides on its line, D runs off to infinity and back as
//! an arrow at the frame's edge, Kisch's H, F and G follow the pin. Each
//! frame is exactly the figure [`Scene::frames`] draws at its angle, with
//! the same plate standards as a still figure.
//!
//! It is written as a self-playing SVG ([`Animation::to_svg`]: the frames
//! shown in turn by SMIL, as Chromium and Firefox play it) or as an HTML
//! page with a slider for the crank angle and a play button
//! ([`Animation::to_html`]); both are self-contained, and
//! [`AnimationFormat`] tells them by a file's extension. Every front end
//! asks for one by an [`AnimateRequest`], checked there.

mod format;
mod frames;
#[cfg(feature = "html")]
mod page;
mod request;
mod svg;

pub use format::AnimationFormat;
pub use frames::{Frame, MAX_EVALUATIONS};
pub use request::AnimateRequest;

use crate::error::{Error, Field, Input, Result};
use crate::figure::PageUnit;
use crate::{angle::Angle, scene::Scene};

/// Frames per revolution unless asked otherwise: one every 5°.
pub const DEFAULT_FRAMES: usize = 72;

/// The fewest frames of an animation: two poses half a turn apart.
pub const MIN_FRAMES: usize = 2;

/// The most frames of an animation: one every tenth of a degree. The
/// frames are written as they are drawn ([`write()`]), so memory does not
/// grow with their number; their curves are bounded in all
/// ([`MAX_EVALUATIONS`]).
pub const MAX_FRAMES: usize = 3600;

/// The most frames × layers of an animation, checked before any frame is
/// drawn: each layer of each frame is drawn and its labels placed (720
/// frames of all 13 layers of a mechanism figure, 9360, took 35 to 50 s;
/// 3600 frames of them, 209 s): 3600 frames of four layers (every
/// figure's own layers are at most four), 1107 frames of all thirteen.
pub const MAX_FRAME_LAYERS: usize = 14_400;

/// Seconds per revolution unless asked otherwise.
pub const DEFAULT_PERIOD: f64 = 4.0;

/// The longest period, in seconds: an hour per revolution.
pub const MAX_PERIOD: f64 = 3600.0;

/// The shortest period, in seconds: a millisecond per revolution (below
/// it no screen shows a frame), so that a period is written as given, in
/// a few digits.
pub const MIN_PERIOD: f64 = 1e-3;

/// One revolution of a mechanism figure: the still frames and the time
/// the revolution takes.
#[derive(Debug, Clone, PartialEq)]
pub struct Animation {
    name: String,
    period: f64,
    frames: Vec<Frame>,
    sheet: frames::Sheet,
}

impl Animation {
    /// `count` frames of `scene`, its first pose turned by 360°/`count`
    /// from one frame to the next, starting at the scene's own pose, all
    /// in one view held over the revolution, played once every `period`
    /// seconds.
    ///
    /// The view is held over every degree of the turn and the frames' own
    /// angles (over the scene's [`Scene::held_view`] poses and the frames'
    /// angles when it holds some), so a pose of the animation never
    /// reaches past the page and a different `count` keeps the same view.
    /// Errors when `count` is outside [`MIN_FRAMES`]..=[`MAX_FRAMES`],
    /// when `count` × the scene's layers pass [`MAX_FRAME_LAYERS`] (before
    /// any frame is drawn), or
    /// `period` is not a finite number of seconds in [[`MIN_PERIOD`],
    /// [`MAX_PERIOD`]].
    pub fn new(scene: &Scene, count: usize, period: f64) -> Result<Self> {
        Self::with_progress(scene, count, period, |_, _| {})
    }

    /// [`Animation::new`], calling `progress(done, count)` after each
    /// frame is drawn (`done` from 1 to `count`), for a long series.
    pub fn with_progress(
        scene: &Scene,
        count: usize,
        period: f64,
        progress: impl FnMut(usize, usize),
    ) -> Result<Self> {
        let period = check_period(period)?;
        let angles = angles(first_angle(scene)?, count)?;
        check_cost(count, scene.layers().len())?;
        let (frames, sheet) = frames::draw(scene, &angles, progress)?;
        Ok(Self {
            name: scene.name().to_string(),
            period,
            frames,
            sheet,
        })
    }

    /// The figure's name (`fig-66-kisch`).
    pub fn name(&self) -> &str {
        &self.name
    }

    /// Seconds per revolution.
    pub fn period(&self) -> f64 {
        self.period
    }

    /// The frames, in the order they are played (at least two).
    pub fn frames(&self) -> &[Frame] {
        &self.frames
    }

    /// The page's width in page units, the same for every frame.
    pub fn width(&self) -> f64 {
        self.sheet.width
    }

    /// The page's height in page units: the tallest frame's (a frame
    /// needing more room for its notes than the others is not cut).
    pub fn height(&self) -> f64 {
        self.frames.iter().map(Frame::height).fold(0.0, f64::max)
    }

    /// The unit the page's size is written in ([`crate::scene::Page::unit`]).
    pub fn size_unit(&self) -> PageUnit {
        self.sheet.unit
    }

    /// The CSS font family the frames are set in.
    pub fn font_family(&self) -> &str {
        self.sheet.font_family
    }

    /// The figure's title in plain text, if it has one.
    pub fn title(&self) -> Option<&str> {
        self.sheet.title.as_deref()
    }

    /// The self-playing SVG: every frame a group (`id="f000"`, its ids
    /// prefixed `f000-`) shown in turn for 1/N of the period by an SMIL
    /// `<animate>` of its visibility, the revolution repeated without end;
    /// a viewer that does not animate shows the first frame. The root's
    /// metadata is the first frame's without the keys of its pose, with an
    /// `animation` object (`frames`, `period`, `angles_deg`).
    pub fn to_svg(&self) -> String {
        self.collected(svg::write)
    }

    /// The HTML page: the frames inline, a slider to scrub the crank
    /// angle and a play/pause button (a small inline script; nothing
    /// fetched). Feature `html`.
    #[cfg(feature = "html")]
    pub fn to_html(&self) -> String {
        self.collected(page::write)
    }

    /// What `write` writes of this animation, as one string (writing to a
    /// string cannot fail).
    fn collected(&self, write: DocumentWriter) -> String {
        let mut out = String::new();
        let mut frames = self.frames.iter().cloned();
        let _: Result<()> = write(&self.reel(), &mut frames, &mut |s| {
            out.push_str(s);
            Ok(())
        });
        out
    }

    /// The animation in `format`.
    pub fn encode(&self, format: AnimationFormat) -> String {
        match format {
            AnimationFormat::Svg => self.to_svg(),
            #[cfg(feature = "html")]
            AnimationFormat::Html => self.to_html(),
        }
    }

    /// What the documents need besides the frames' markup.
    // cannot fail: an animation is made only by `with_progress`, with a
    // frame for each of its `count` ≥ MIN_FRAMES angles (`angles` refuses
    // fewer).
    #[allow(clippy::indexing_slicing)]
    fn reel(&self) -> Reel<'_> {
        Reel {
            name: &self.name,
            period: self.period,
            sheet: &self.sheet,
            height: self.height(),
            angles: self.frames.iter().map(Frame::angle).collect(),
            first: &self.frames[0],
        }
    }
}

/// Draws [`Animation::new`]'s animation of `scene` and writes it in
/// `format` a frame at a time to `sink`, calling `progress(done, count)`
/// after each frame is written: memory does not grow with `count`. The
/// bytes are [`Animation::encode`]'s. The frames' models are built twice
/// (a first pass finds the tallest page, which the document states before
/// any frame), the SVG of each once.
///
/// Errors: as [`Animation::new`] (frames × layers beyond
/// [`MAX_FRAME_LAYERS`] before anything is drawn), the animation's curves beyond
/// [`MAX_EVALUATIONS`] (before anything is written), and any error of
/// `sink`, which ends the writing.
pub fn write(
    scene: &Scene,
    (count, period): (usize, f64),
    format: AnimationFormat,
    sink: &mut dyn FnMut(&str) -> Result<()>,
    mut progress: impl FnMut(usize, usize),
) -> Result<()> {
    let period = check_period(period)?;
    let angles = angles(first_angle(scene)?, count)?;
    check_cost(count, scene.layers().len())?;
    let series = frames::Series::new(scene, angles);
    let survey = series.survey()?;
    let reel = Reel {
        name: scene.name(),
        period,
        sheet: &survey.sheet,
        height: survey.height,
        angles: series.angles().to_vec(),
        first: &survey.first,
    };
    let mut done = 0;
    let mut frames = series.frames()?.inspect(|_| {
        done += 1;
        progress(done, count);
    });
    let write: DocumentWriter = match format {
        AnimationFormat::Svg => svg::write,
        #[cfg(feature = "html")]
        AnimationFormat::Html => page::write,
    };
    write(&reel, &mut frames, sink)
}

/// A document's writer ([`svg::write`], [`page::write`]): the reel, its
/// frames as they are drawn, and the sink the text goes to.
type DocumentWriter =
    fn(&Reel, &mut dyn Iterator<Item = Frame>, &mut dyn FnMut(&str) -> Result<()>) -> Result<()>;

/// What a document of an animation needs besides the frames' markup:
/// the page, the period, the frames' angles and the first frame (whose
/// metadata the SVG's root carries).
pub(super) struct Reel<'a> {
    // read by the HTML page's heading only
    #[cfg_attr(not(feature = "html"), allow(dead_code))]
    name: &'a str,
    period: f64,
    sheet: &'a frames::Sheet,
    height: f64,
    angles: Vec<Angle>,
    first: &'a Frame,
}

impl Reel<'_> {
    /// The figure's name.
    #[cfg(feature = "html")]
    fn name(&self) -> &str {
        self.name
    }

    /// Seconds per revolution.
    fn period(&self) -> f64 {
        self.period
    }

    /// The page's width in page units.
    fn width(&self) -> f64 {
        self.sheet.width
    }

    /// The tallest frame's height in page units.
    fn height(&self) -> f64 {
        self.height
    }

    /// The unit the page's size is written in.
    fn size_unit(&self) -> PageUnit {
        self.sheet.unit
    }

    /// The CSS font family the frames are set in.
    fn font_family(&self) -> &str {
        self.sheet.font_family
    }

    /// The figure's title in plain text, if it has one.
    fn title(&self) -> Option<&str> {
        self.sheet.title.as_deref()
    }

    /// The frames' angles, in the order they are played.
    fn angles(&self) -> &[Angle] {
        &self.angles
    }

    /// The first frame.
    fn first(&self) -> &Frame {
        self.first
    }
}

/// Where the frames go in a document's skeleton ([`split`]); no markup the
/// renderer writes holds a NUL.
const FRAMES_HERE: &str = "\u{0}frames\u{0}";

/// A document written with [`FRAMES_HERE`] in place of its frames, cut
/// there: what comes before the frames and what after.
fn split(skeleton: &str) -> (&str, &str) {
    skeleton.split_once(FRAMES_HERE).unwrap_or((skeleton, ""))
}

/// `period` checked: finite, positive, at most [`MAX_PERIOD`].
fn check_period(period: f64) -> Result<f64> {
    if !period.is_finite() {
        return Err(Error::NotFinite {
            name: Field::Period,
            value: period,
        });
    }
    if !(MIN_PERIOD..=MAX_PERIOD).contains(&period) {
        return Err(Error::OutOfRange {
            name: Field::Period,
            value: period,
            reason: format!("a revolution takes from {MIN_PERIOD} to {MAX_PERIOD} seconds"),
        });
    }
    Ok(period)
}

/// The `count` angles of a revolution from `start`, in equal steps.
/// The scene's first pose, where an animation starts; an error for a
/// scene with none.
fn first_angle(scene: &Scene) -> Result<Angle> {
    scene
        .angles()
        .first()
        .copied()
        .ok_or_else(|| Error::invalid(Input::Angles, "a scene needs at least one angle".into()))
}

/// Refuses `count` frames of `layers` layers beyond [`MAX_FRAME_LAYERS`],
/// naming the product and the ways to bring it within.
fn check_cost(count: usize, layers: usize) -> Result<()> {
    let cost = count.saturating_mul(layers.max(1));
    if cost <= MAX_FRAME_LAYERS {
        return Ok(());
    }
    Err(Error::OutOfRange {
        name: Field::Frames,
        value: count as f64,
        reason: format!(
            "{count} frames of {layers} layers are {cost} frame layers to draw, more than {MAX_FRAME_LAYERS}: give at most {} frames or fewer layers",
            MAX_FRAME_LAYERS / layers.max(1)
        ),
    })
}

/// The refusal of `count` frames, a count outside
/// [`MIN_FRAMES`]..=[`MAX_FRAMES`]: the one line every front end gives for
/// it. `count` is the number as given, so that a front end whose integers
/// no `usize` holds (a negative count from Python) refuses it with the same
/// line rather than one of its own; nothing checks that `count` is in fact
/// out of range.
pub fn frames_refused(count: f64) -> Error {
    Error::OutOfRange {
        name: Field::Frames,
        value: count,
        reason: format!("an animation has {MIN_FRAMES} to {MAX_FRAMES} frames"),
    }
}

fn angles(start: Angle, count: usize) -> Result<Vec<Angle>> {
    if !(MIN_FRAMES..=MAX_FRAMES).contains(&count) {
        return Err(frames_refused(count as f64));
    }
    (0..count)
        .map(|k| Angle::from_degrees(start.degrees() + 360.0 * k as f64 / count as f64))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mechanism::SliderCrank;

    fn engine() -> Scene {
        Scene::new(SliderCrank::in_line(0.5, 3.0).unwrap(), Angle::deg(30.0))
    }

    #[test]
    fn a_period_is_refused_below_a_millisecond_and_kept_as_given_above() {
        for bad in [1e-5, 5e-324, 0.000_999, 3600.5] {
            let e = check_period(bad).unwrap_err().to_string();
            assert!(
                e.contains("a revolution takes from 0.001 to 3600 seconds"),
                "{e}"
            );
        }
        assert_eq!(check_period(0.001).unwrap(), 0.001);
        assert_eq!(check_period(0.0015).unwrap(), 0.0015);
    }

    #[test]
    fn the_frames_turn_once_from_the_scene_pose() {
        let a = angles(Angle::deg(30.0), 4).unwrap();
        let d: Vec<f64> = a.iter().map(Angle::degrees).collect();
        assert_eq!(d, [30.0, 120.0, 210.0, 300.0]);
        // 90° and 270° land exactly: D is at infinity there.
        let a = angles(Angle::deg(0.0), 4).unwrap();
        assert_eq!(a[1].cos(), 0.0);
    }

    #[test]
    fn a_count_no_usize_holds_is_refused_by_the_same_line() {
        assert_eq!(
            frames_refused(-1.0).to_string(),
            "frames = -1 is out of range: an animation has 2 to 3600 frames"
        );
    }

    #[test]
    fn counts_and_periods_out_of_range_are_refused() {
        for n in [0, 1, MAX_FRAMES + 1, 100_000] {
            let e = Animation::new(&engine(), n, 4.0).unwrap_err();
            assert!(e.to_string().contains("2 to 3600 frames"), "{n}: {e}");
        }
        for p in [0.0, -1.0, f64::NAN, f64::INFINITY, MAX_PERIOD * 2.0] {
            assert!(Animation::new(&engine(), 4, p).is_err(), "{p}");
        }
    }

    #[test]
    fn a_scene_without_an_angle_is_refused_not_a_panic() {
        let scene = engine().with_angles(Vec::new());
        let e = Animation::new(&scene, 4, 1.0).unwrap_err();
        assert!(e.to_string().contains("at least one angle"), "{e}");
        let mut sink = |_: &str| Ok(());
        let e = write(&scene, (4, 1.0), AnimationFormat::Svg, &mut sink, |_, _| {}).unwrap_err();
        assert!(e.to_string().contains("at least one angle"), "{e}");
    }

    #[test]
    fn progress_counts_every_frame() {
        let mut seen = Vec::new();
        let a = Animation::with_progress(&engine(), 3, 1.0, |d, n| seen.push((d, n))).unwrap();
        assert_eq!(seen, [(1, 3), (2, 3), (3, 3)]);
        assert_eq!(a.frames().len(), 3);
        assert_eq!(a.frames()[2].angle().degrees(), 270.0);
    }

    #[test]
    fn written_a_frame_at_a_time_is_the_document_held_whole() {
        let scene = engine();
        let whole = Animation::new(&scene, 5, 2.0).unwrap();
        let formats: &[AnimationFormat] = &[
            AnimationFormat::Svg,
            #[cfg(feature = "html")]
            AnimationFormat::Html,
        ];
        for &format in formats {
            let (mut out, mut pieces, mut seen) = (String::new(), 0, Vec::new());
            let mut sink = |s: &str| {
                out.push_str(s);
                pieces += 1;
                Ok(())
            };
            write(&scene, (5, 2.0), format, &mut sink, |d, n| {
                seen.push((d, n))
            })
            .unwrap();
            assert_eq!(out, whole.encode(format), "{format:?}");
            // The head, five frames (and the newlines between them in
            // SVG), the tail: never the document in one piece.
            assert!(pieces >= 7, "{pieces}");
            assert_eq!(seen, [(1, 5), (2, 5), (3, 5), (4, 5), (5, 5)]);
        }
        // A failing sink ends the writing with its error.
        let mut calls = 0;
        let mut failing = |_: &str| {
            calls += 1;
            Err(Error::invalid(Input::Angles, "full".into()))
        };
        let e = write(
            &engine(),
            (5, 2.0),
            AnimationFormat::Svg,
            &mut failing,
            |_, _| {},
        );
        assert_eq!(e.unwrap_err().to_string(), "full");
        assert_eq!(calls, 1);
    }

    #[test]
    fn frames_times_layers_are_bounded_before_drawing() {
        assert!(check_cost(MAX_FRAMES, 4).is_ok());
        assert!(check_cost(1107, 13).is_ok());
        assert!(check_cost(1108, 13).is_err());
        let e = check_cost(3600, 13).unwrap_err().to_string();
        assert!(
            e.contains("3600 frames of 13 layers are 46800 frame layers"),
            "{e}"
        );
        assert!(e.contains("give at most 1107 frames"), "{e}");
        assert!(check_cost(usize::MAX, 13).is_err());
    }

    #[test]
    fn frames_whose_curves_take_the_engines_budget_are_refused_first() {
        let e = frames::check_evaluations_for_test(950_000, 1, 720).unwrap_err();
        let e = e.to_string();
        assert!(
            e.contains("720 frames × 950000 = 684000000, more than the 20000000"),
            "{e}"
        );
        assert!(e.contains("give at most 21 frames"), "{e}");
        assert!(frames::check_evaluations_for_test(20_000, 4, 3600).is_ok());
    }
}
