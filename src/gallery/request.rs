//! The request of a gallery as a front end gives it: the manifest that
//! chooses its contents, or the figures it is limited to, the same for
//! the command line (its flags) and the Python package (its keywords),
//! made into the [`Gallery`] once here. Where the gallery is written, and
//! whether it is written or compared ([`Gallery::write_into`],
//! [`Gallery::compare_with`]), is the front end's.

use super::Gallery;
use crate::catalogue::FigureName;
use crate::error::{Error, Field, Input, Result, Wording};
use crate::files::{MAX_SCENE_BYTES, read_text};
use std::path::{Path, PathBuf};

/// What a user asks of a gallery; `None` leaves the gallery's own
/// ([`Gallery::new`]: every named figure in SVG, PNG and PDF, each in its
/// own style). Each field is the option of its name on every front end
/// ([`Field::key`]).
///
/// Fields may be added in later versions: start from
/// [`GalleryRequest::default`] and set the fields wanted.
#[derive(Debug, Clone, PartialEq, Default)]
#[non_exhaustive]
pub struct GalleryRequest {
    /// A TOML manifest of what the gallery holds
    /// ([`Gallery::from_manifest`]); its scene files are read from the
    /// manifest's directory.
    pub manifest: Option<PathBuf>,
    /// Only these figures, by name, in this order (the tables and the
    /// index are always made); not with `manifest`, which names its own.
    /// An entry may itself list several names separated by commas, as the
    /// command line and a Python string give them.
    pub only: Option<Vec<String>>,
}

impl GalleryRequest {
    /// The gallery this request asks for: the manifest read, or the
    /// figures of `only` named, and checked that it can be built
    /// ([`Gallery::can_build`]).
    ///
    /// Errors: `manifest` with `only`; a manifest unreadable, larger than
    /// [`MAX_SCENE_BYTES`] or refused (the message names the file and the
    /// line); a name of `only` no figure has (an empty list names none).
    pub fn gallery(&self) -> Result<Gallery> {
        let gallery = match (&self.manifest, &self.only) {
            (Some(_), Some(_)) => {
                return Err(Error::refused(
                    Input::Options,
                    Wording::default()
                        .option(Field::Only)
                        .then(" chooses the figures a manifest chooses: give ")
                        .option(Field::Manifest)
                        .then(" or ")
                        .option(Field::Only)
                        .then(", not both"),
                ));
            }
            (Some(path), None) => read_manifest(path)?,
            (None, Some(names)) => Gallery::new().with_figures(figures_named(names)?),
            (None, None) => Gallery::new(),
        };
        gallery.can_build()?;
        Ok(gallery)
    }
}

/// The gallery of the manifest at `path`, an error naming the file.
fn read_manifest(path: &Path) -> Result<Gallery> {
    let text = read_text(path, MAX_SCENE_BYTES, Input::Manifest)?;
    let base = path.parent().unwrap_or(Path::new(""));
    Gallery::from_manifest(&text, base).map_err(|e| {
        Error::invalid(
            Input::Manifest,
            format!("{}: {}", path.display(), e.one_line()),
        )
    })
}

/// The figures of `names` (each entry split at its commas, each name
/// trimmed), the first unknown name an error (an empty one too).
fn figures_named(names: &[String]) -> Result<Vec<FigureName>> {
    names
        .iter()
        .flat_map(|n| n.split(','))
        .map(|n| FigureName::from_name(n.trim()))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_request_of_no_option_is_the_whole_catalogue() {
        let g = GalleryRequest::default().gallery().unwrap();
        assert_eq!(g, Gallery::new());
        assert_eq!(g.figures().len(), FigureName::ALL.len());
    }

    #[test]
    fn only_keeps_the_figures_named_in_their_order() {
        let r = GalleryRequest {
            only: Some(vec![" fig-66-kisch".into(), "fig-63-velocity".into()]),
            ..Default::default()
        };
        let g = r.gallery().unwrap();
        assert_eq!(
            g.figures(),
            [FigureName::Fig66Kisch, FigureName::Fig63Velocity]
        );
        // One entry listing several, as the command line gives them.
        let r = GalleryRequest {
            only: Some(vec!["fig-67-example, fig-66-kisch".into()]),
            ..Default::default()
        };
        let g = r.gallery().unwrap();
        assert_eq!(
            g.figures(),
            [FigureName::Fig67Example, FigureName::Fig66Kisch]
        );
        let r = GalleryRequest {
            only: Some(vec!["fig-66-kisch,".into()]),
            ..Default::default()
        };
        assert!(r.gallery().is_err(), "an empty name is no figure");
    }

    #[test]
    fn fields_are_refused_by_their_keys() {
        let r = GalleryRequest {
            manifest: Some("m.toml".into()),
            only: Some(vec!["fig-66-kisch".into()]),
        };
        let e = r.gallery().unwrap_err().to_string();
        assert_eq!(
            e,
            "`only` chooses the figures a manifest chooses: give `manifest` or `only`, not both"
        );
        let r = GalleryRequest {
            only: Some(vec!["fig-99".into()]),
            ..Default::default()
        };
        let e = r.gallery().unwrap_err().to_string();
        assert!(e.contains("fig-99"), "{e}");
    }

    #[test]
    fn a_manifest_that_cannot_be_read_is_named() {
        let r = GalleryRequest {
            manifest: Some("/nonexistent/gallery.toml".into()),
            ..Default::default()
        };
        let e = r.gallery().unwrap_err().to_string();
        assert!(e.contains("/nonexistent/gallery.toml"), "{e}");
    }
}
