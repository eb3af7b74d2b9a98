//! The frames of an animation: each a still figure, written as its own
//! SVG or with its ids made its own, to sit beside the others in one
//! document.

use crate::error::{Error, Input, Result};
use crate::figure::{EngineRecord, Figure, PageUnit};
use crate::render::{SvgOptions, metadata_of, svg_body, to_svg};
use crate::{angle::Angle, scene::Scene};
use serde_json::{Map, Value};

/// One frame: the crank angle and the still figure drawn there.
#[derive(Debug, Clone, PartialEq)]
pub struct Frame {
    angle: Angle,
    figure: Figure,
}

impl Frame {
    /// The crank angle of the frame's pose.
    pub fn angle(&self) -> Angle {
        self.angle
    }

    /// The still figure as its own SVG document: what
    /// [`render::to_svg`](crate::render::to_svg) writes for the figure of
    /// [`Scene::frames`] at this angle, byte for byte.
    pub fn svg(&self) -> String {
        to_svg(&self.figure)
    }

    /// The JSON object of the still figure's `<metadata>`
    /// ([`render::metadata_of`](crate::render::metadata_of)).
    pub fn metadata(&self) -> Map<String, Value> {
        metadata_of(&self.figure)
    }

    /// The engine the still figure draws, as its metadata records it.
    pub fn engine(&self) -> Option<&EngineRecord> {
        self.figure.metadata().engine()
    }

    /// The figure's page height in page units.
    pub fn height(&self) -> f64 {
        self.figure.height()
    }

    /// The ids' prefix of frame `index` in an animation: `f000-`, `f001-`,
    /// … (at least three digits, more past 999).
    pub fn prefix(index: usize) -> String {
        format!("f{index:03}-")
    }

    /// What the still figure draws, without its root element, every id and
    /// reference to one prefixed with `prefix`
    /// ([`SvgOptions::with_id_prefix`]), to be set in a group or an inline
    /// `<svg>` beside other frames.
    pub fn body(&self, prefix: &str) -> String {
        svg_body(&self.figure, &SvgOptions::default().with_id_prefix(prefix))
    }
}

/// What every frame shares, read off the first: the page's width and the
/// unit of its size, the font family and the title.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Sheet {
    pub width: f64,
    pub unit: PageUnit,
    pub font_family: &'static str,
    pub title: Option<String>,
}

impl Sheet {
    fn of(figure: &Figure) -> Self {
        Self {
            width: figure.width(),
            unit: figure.size_unit(),
            font_family: figure.font().css_family(),
            title: figure.title().map(|t| t.rich().plain()),
        }
    }
}

/// The most curve evaluations the frames of one animation may make in all
/// (about twenty curves traced to the curve engine's own limit, a few
/// seconds): an engine whose curves each take the engine's whole budget
/// (a rod one ulp longer than the crank) is refused after its first
/// frame rather than drawn for minutes.
pub const MAX_EVALUATIONS: u64 = 20_000_000;

/// The frames of a scene at its angles, in a view held over the whole
/// revolution and the frames' angles ([`super::Animation::new`]), each
/// drawn when asked for: a document is written a frame at a time.
pub(super) struct Series {
    scene: Scene,
    angles: Vec<Angle>,
}

/// What a pass over the frames' models finds before any is written: what
/// they share, the tallest frame's height and the first frame's SVG.
pub(super) struct Survey {
    pub sheet: Sheet,
    pub height: f64,
    pub first: Frame,
}

impl Series {
    /// The frames of `scene` at `angles` (at least one).
    pub fn new(scene: &Scene, angles: Vec<Angle>) -> Self {
        let mut held: Vec<Angle> = match scene.held_view() {
            Some(poses) => poses.to_vec(),
            None => (0..360).map(|d| Angle::deg(f64::from(d))).collect(),
        };
        held.extend_from_slice(&angles);
        Self {
            scene: scene.clone().with_held_view(held),
            angles,
        }
    }

    /// The frames' angles.
    pub fn angles(&self) -> &[Angle] {
        &self.angles
    }

    /// The figures in order, each built when asked for.
    fn figures(&self) -> Result<impl Iterator<Item = (Angle, Figure)> + '_> {
        Ok(self
            .angles
            .iter()
            .copied()
            .zip(self.scene.frame_series(&self.angles)?))
    }

    /// A pass over the frames' models (no SVG but the first frame's),
    /// refused once their curves would take more than
    /// [`MAX_EVALUATIONS`] in all.
    pub fn survey(&self) -> Result<Survey> {
        let start = crate::diagram::evaluations_on_this_thread();
        let count = self.angles.len() as u64;
        let (mut survey, mut done) = (None::<Survey>, 0u64);
        for (angle, figure) in self.figures()? {
            done += 1;
            let spent = crate::diagram::evaluations_on_this_thread() - start;
            check_evaluations(&self.scene, spent, done, count)?;
            match &mut survey {
                Some(s) => s.height = s.height.max(figure.height()),
                None => {
                    survey = Some(Survey {
                        sheet: Sheet::of(&figure),
                        height: figure.height(),
                        first: Frame::of(angle, figure),
                    })
                }
            }
        }
        survey.ok_or_else(|| {
            Error::invalid(Input::Angles, "an animation has at least one frame".into())
        })
    }

    /// The frames in order, each drawn and written when asked for.
    pub fn frames(&self) -> Result<impl Iterator<Item = Frame> + '_> {
        Ok(self
            .figures()?
            .map(|(angle, figure)| Frame::of(angle, figure)))
    }
}

impl Frame {
    fn of(angle: Angle, figure: Figure) -> Self {
        Frame { angle, figure }
    }
}

/// An error when frames whose curves took `spent` evaluations over the
/// first `done` of `count` would take more than [`MAX_EVALUATIONS`] in
/// all, naming the product and the frames that would fit.
fn check_evaluations(scene: &Scene, spent: u64, done: u64, count: u64) -> Result<()> {
    let per_frame = spent.div_ceil(done.max(1));
    let total = u128::from(per_frame) * u128::from(count);
    if total <= u128::from(MAX_EVALUATIONS) {
        return Ok(());
    }
    let fit = (MAX_EVALUATIONS / per_frame.max(1)).max(1);
    Err(Error::Limit(format!(
        "an animation of {} takes {per_frame} curve evaluations a frame: {count} frames × {per_frame} = {total}, more than the {MAX_EVALUATIONS} an animation may take; give at most {fit} frames, fewer layers or a longer rod",
        scene.name()
    )))
}

/// [`check_evaluations`] for an animation of Fig. 66.
#[cfg(test)]
// cannot fail: Fig. 66 is a mechanism figure, whose scene always builds.
#[allow(clippy::expect_used)]
pub(super) fn check_evaluations_for_test(spent: u64, done: u64, count: u64) -> Result<()> {
    let scene = crate::catalogue::FigureName::Fig66Kisch
        .scene()
        .expect("a seed figure");
    check_evaluations(&scene, spent, done, count)
}

/// The frames of `scene` at `angles` (at least one), in a view held over
/// the whole revolution and the frames' angles
/// ([`super::Animation::new`]), calling `progress` after each, and what
/// they share.
pub(super) fn draw(
    scene: &Scene,
    angles: &[Angle],
    mut progress: impl FnMut(usize, usize),
) -> Result<(Vec<Frame>, Sheet)> {
    let series = Series::new(scene, angles.to_vec());
    let start = crate::diagram::evaluations_on_this_thread();
    let mut frames = Vec::with_capacity(angles.len());
    let mut sheet = None;
    for (angle, figure) in series.figures()? {
        let spent = crate::diagram::evaluations_on_this_thread() - start;
        check_evaluations(scene, spent, frames.len() as u64 + 1, angles.len() as u64)?;
        sheet.get_or_insert_with(|| Sheet::of(&figure));
        frames.push(Frame::of(angle, figure));
        progress(frames.len(), angles.len());
    }
    let sheet = sheet.ok_or_else(|| {
        Error::invalid(Input::Angles, "an animation has at least one frame".into())
    })?;
    Ok((frames, sheet))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn prefixes_keep_their_order() {
        assert_eq!(Frame::prefix(0), "f000-");
        assert_eq!(Frame::prefix(719), "f719-");
        assert_eq!(Frame::prefix(1234), "f1234-");
    }
}
