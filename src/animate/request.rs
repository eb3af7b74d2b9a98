//! The request of an animation as a front end gives it: the figure's
//! options, the frames, the period and the projector's view, the same for
//! the command line (its flags) and the Python package (its keywords),
//! checked here once. Where the document goes and in which format is the
//! front end's.

use super::{Animation, AnimationFormat, DEFAULT_FRAMES, DEFAULT_PERIOD, write};
use crate::catalogue::{FigureName, FigureRequest};
use crate::error::{Error, Field, Input, Result, Wording};
use crate::scene::Scene;

/// What a user asks of an animation of a mechanism figure; `None` leaves
/// the animation's own value ([`DEFAULT_FRAMES`] frames, one revolution
/// in [`DEFAULT_PERIOD`] seconds, the figure's own detail). Each field is
/// the option of its name on every front end ([`Field::key`]).
///
/// Fields may be added in later versions: start from
/// [`AnimateRequest::default`] and set the fields wanted.
#[derive(Debug, Clone, PartialEq, Default)]
#[non_exhaustive]
pub struct AnimateRequest {
    /// The changes to the figure, as `figure` takes them (the angle is
    /// the first frame's); its `data` and `fit` are refused, the
    /// mechanism figures drawing no measured data.
    pub figure: FigureRequest,
    /// Frames per revolution.
    pub frames: Option<usize>,
    /// Seconds per revolution.
    pub period: Option<f64>,
    /// The frames without the enlarged detail about the crank
    /// ([`Scene::without_detail`]); `false` when not given.
    pub projector: Option<bool>,
}

impl AnimateRequest {
    /// Frames per revolution: as given, else [`DEFAULT_FRAMES`].
    pub fn frames(&self) -> usize {
        self.frames.unwrap_or(DEFAULT_FRAMES)
    }

    /// Seconds per revolution: as given, else [`DEFAULT_PERIOD`].
    pub fn period(&self) -> f64 {
        self.period.unwrap_or(DEFAULT_PERIOD)
    }

    /// The scene of the mechanism figure `name` this request animates,
    /// its options applied (without its detail for the projector).
    ///
    /// Errors: `data` or `fit` given; an option the figure refuses
    /// ([`FigureRequest::options`], [`FigureName::scene_with`]); `name` a
    /// diagram, which has no scene to turn. The frames, the period and
    /// frames × layers are checked by [`AnimateRequest::write`] and
    /// [`AnimateRequest::animation`] before any frame is drawn.
    pub fn scene(&self, name: FigureName) -> Result<Scene> {
        let measured = [
            (self.figure.data.is_some(), Field::Data),
            (self.figure.fit.is_some(), Field::Fit),
        ];
        if let Some(&(_, field)) = measured.iter().find(|(given, _)| *given) {
            return Err(Error::refused(
                Input::Options,
                Wording::from("animate takes no ")
                    .option(field)
                    .then(": the mechanism figures draw no measured data"),
            ));
        }
        let options = self.figure.options(name)?;
        let scene = name
            .scene_with(&options)?
            .ok_or_else(|| not_animated(name))?;
        Ok(match self.projector {
            Some(true) => scene.without_detail(),
            _ => scene,
        })
    }

    /// Writes the animation of `name` in `format` a frame at a time to
    /// `sink` ([`super::write()`]), calling `progress(done, count)` after
    /// each frame. Errors: as [`AnimateRequest::scene`], then the frames,
    /// the period and frames × layers refused before anything is drawn,
    /// then any error of `sink`.
    pub fn write(
        &self,
        name: FigureName,
        format: AnimationFormat,
        sink: &mut dyn FnMut(&str) -> Result<()>,
        progress: impl FnMut(usize, usize),
    ) -> Result<()> {
        let scene = self.scene(name)?;
        write(
            &scene,
            (self.frames(), self.period()),
            format,
            sink,
            progress,
        )
    }

    /// The animation of `name`, held whole ([`Animation::new`]). Errors
    /// as [`AnimateRequest::write`].
    pub fn animation(&self, name: FigureName) -> Result<Animation> {
        Animation::new(&self.scene(name)?, self.frames(), self.period())
    }
}

/// The refusal of a diagram, naming the figures that are animated.
fn not_animated(name: FigureName) -> Error {
    let names: Vec<&str> = FigureName::SCENES.iter().map(FigureName::name).collect();
    Error::invalid(
        Input::FigureName,
        format!(
            "{} is a diagram: animate draws the mechanism figures, {}",
            name.name(),
            names.join(", ")
        ),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    fn velocity() -> FigureName {
        FigureName::Fig63Velocity
    }

    #[test]
    fn a_request_of_no_option_is_72_frames_in_4_seconds() {
        let r = AnimateRequest::default();
        assert_eq!((r.frames(), r.period()), (72, 4.0));
        let scene = r.scene(velocity()).unwrap();
        let own = velocity().scene_with(&Default::default()).unwrap().unwrap();
        assert_eq!(scene, own);
    }

    #[test]
    fn measured_data_and_diagrams_are_refused_by_their_keys() {
        let mut r = AnimateRequest::default();
        r.figure.fit = Some(crate::catalogue::Fit::Both);
        let e = r.scene(velocity()).unwrap_err().to_string();
        assert_eq!(
            e,
            "animate takes no `fit`: the mechanism figures draw no measured data"
        );
        let e = AnimateRequest::default()
            .scene(FigureName::TurningMoment)
            .unwrap_err()
            .to_string();
        assert!(
            e.starts_with("turning-moment is a diagram: animate draws"),
            "{e}"
        );
        assert!(e.contains("fig-66-kisch"), "{e}");
    }

    #[test]
    fn the_guards_refuse_before_a_frame_is_drawn() {
        let r = AnimateRequest {
            frames: Some(1),
            ..Default::default()
        };
        let mut drawn = 0;
        let mut sink = |_: &str| Ok(());
        let e = r.write(velocity(), AnimationFormat::Svg, &mut sink, |_, _| {
            drawn += 1
        });
        assert!(e.unwrap_err().to_string().contains("2 to 3600 frames"));
        assert_eq!(drawn, 0);
        let r = AnimateRequest {
            frames: Some(2),
            period: Some(0.0),
            ..Default::default()
        };
        let e = r.animation(velocity()).unwrap_err().to_string();
        assert!(e.contains("from 0.001 to 3600 seconds"), "{e}");
    }

    #[test]
    fn the_projector_drops_the_detail_only() {
        let r = AnimateRequest {
            projector: Some(true),
            ..Default::default()
        };
        let plain = AnimateRequest::default().scene(FigureName::Fig66Kisch);
        let plain = plain.unwrap();
        let scene = r.scene(FigureName::Fig66Kisch).unwrap();
        assert_ne!(scene, plain);
        assert_eq!(scene, plain.without_detail());
    }
}
