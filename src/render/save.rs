//! A figure saved to a file in the format its name asks for.

use super::{FileFormat, to_svg, write_atomic};
use crate::error::Result;
use crate::figure::Figure;
use std::path::Path;

/// Writes `figure` to `path` in the format its extension names (`.svg`,
/// `.png` at 2 pixels per page unit, `.pdf`; SVG for a name without an
/// extension), whole or not at all: what `Figure::save` would be, kept
/// here because the figure model knows nothing of its writers.
///
/// Errors: an unknown extension ([`Error::Invalid`](crate::error::Error::Invalid),
/// before anything is written), a format whose feature this build leaves
/// out ([`Error::Unsupported`](crate::error::Error::Unsupported)), or the write
/// itself ([`Error::Io`](crate::error::Error::Io), the existing file untouched).
///
/// ```no_run
/// use slider_crank::FigureName;
/// use slider_crank::catalogue::FigureOptions;
/// use slider_crank::render::save;
///
/// let figure = FigureName::Fig67Example.figure(&FigureOptions::default())?;
/// save(&figure, "fig-67.pdf")?;
/// # Ok::<(), slider_crank::Error>(())
/// ```
pub fn save(figure: &Figure, path: impl AsRef<Path>) -> Result<()> {
    let path = path.as_ref();
    let format = FileFormat::from_path(path)?;
    write_atomic(path, &format.encode(figure, &to_svg(figure))?)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::catalogue::FigureName;

    #[test]
    fn the_extension_chooses_the_format_and_an_unknown_one_writes_nothing() {
        let dir = tempfile::tempdir().unwrap();
        let figure = FigureName::Fig63Velocity.scene().unwrap().figure().unwrap();
        let svg = dir.path().join("f.svg");
        save(&figure, &svg).unwrap();
        assert_eq!(std::fs::read_to_string(&svg).unwrap(), to_svg(&figure));
        let bad = dir.path().join("f.jpg");
        let err = save(&figure, &bad).unwrap_err();
        assert!(
            err.to_string().contains(".svg, .png, .pdf or .tex"),
            "{err}"
        );
        assert!(!bad.exists());
        #[cfg(feature = "png")]
        {
            let png = dir.path().join("f.PNG");
            save(&figure, &png).unwrap();
            assert!(std::fs::read(&png).unwrap().starts_with(b"\x89PNG"));
        }
        #[cfg(feature = "pdf")]
        {
            let pdf = dir.path().join("f.pdf");
            save(&figure, &pdf).unwrap();
            assert!(std::fs::read(&pdf).unwrap().starts_with(b"%PDF"));
        }
    }
}
