//! The file formats a figure is written in, told by the file's extension.

use super::tikz::{TikzOptions, to_tikz};
use crate::error::{Error, Input, Result};
use crate::figure::Figure;
use std::path::Path;

/// A file format of figures.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum FileFormat {
    /// SVG text ([`to_svg`](super::to_svg)), the reference.
    Svg,
    /// PNG at 2 pixels per page unit ([`to_png`](super::to_png), feature
    /// `png`).
    Png,
    /// Vector PDF with the faces embedded ([`to_pdf`](super::to_pdf),
    /// feature `pdf`).
    Pdf,
    /// A TikZ picture for a LaTeX book ([`to_tikz`](super::to_tikz)),
    /// its letters set by LaTeX in the book's fonts; named `tikz`, its
    /// files end in `.tex`.
    Tikz,
}

impl FileFormat {
    /// Every format, in the order a gallery lists them.
    pub const ALL: [FileFormat; 4] = [
        FileFormat::Svg,
        FileFormat::Png,
        FileFormat::Pdf,
        FileFormat::Tikz,
    ];

    /// The formats a gallery writes when it is not told which: the
    /// pictures (SVG, PNG, PDF), not the TikZ a book asks for.
    pub const PICTURES: [FileFormat; 3] = [FileFormat::Svg, FileFormat::Png, FileFormat::Pdf];

    /// The extension, without the dot (`svg`, `png`, `pdf`, `tex`).
    pub fn extension(&self) -> &'static str {
        match self {
            FileFormat::Svg => "svg",
            FileFormat::Png => "png",
            FileFormat::Pdf => "pdf",
            FileFormat::Tikz => "tex",
        }
    }

    /// The format as a reader names it (`SVG`, `PNG`, `PDF`, `TikZ`).
    pub fn label(&self) -> &'static str {
        match self {
            FileFormat::Svg => "SVG",
            FileFormat::Png => "PNG",
            FileFormat::Pdf => "PDF",
            FileFormat::Tikz => "TikZ",
        }
    }

    /// The format's name (`svg`, `png`, `pdf`, `tikz`).
    pub fn name(&self) -> &'static str {
        match self {
            FileFormat::Tikz => "tikz",
            other => other.extension(),
        }
    }

    /// Whether this build writes the format: SVG always, PNG with the
    /// `png` feature, PDF with the `pdf` feature.
    pub fn is_supported(&self) -> bool {
        match self {
            FileFormat::Svg => true,
            FileFormat::Png => cfg!(feature = "png"),
            FileFormat::Pdf => cfg!(feature = "pdf"),
            FileFormat::Tikz => true,
        }
    }

    /// The format of that name or extension (`svg`, `png`, `pdf`, in any
    /// case); the error names the formats.
    pub fn from_name(name: &str) -> Result<Self> {
        Self::ALL
            .into_iter()
            .find(|f| {
                f.extension().eq_ignore_ascii_case(name) || f.name().eq_ignore_ascii_case(name)
            })
            .ok_or_else(|| {
                Error::invalid(
                    Input::FileFormat,
                    format!("unknown format '{name}': the formats are svg, png, pdf and tikz"),
                )
            })
    }

    /// The format a file is written in, by its extension: `.svg`, `.png`,
    /// `.pdf`, `.tex` (TikZ; in any case); SVG for a name without one (`-`, a device such
    /// as `/dev/stdout`, a FIFO). Any other extension is an error that
    /// names the formats.
    pub fn from_path(path: &Path) -> Result<Self> {
        match path.extension() {
            None => Ok(FileFormat::Svg),
            Some(ext) => ext
                .to_str()
                .and_then(|e| Self::from_name(e).ok())
                .ok_or_else(|| {
                    Error::invalid(Input::OutputFile, format!(
                        "cannot write {}: .{} is not an output format: give a file ending in .svg, .png, .pdf or .tex",
                        path.display(),
                        ext.to_string_lossy()
                    ))
                }),
        }
    }

    /// The bytes of `figure`, whose SVG is `svg`, in this format (PNG at 2
    /// pixels per page unit, TikZ the picture alone). Errors when this
    /// build leaves the format's feature out ([`Error::Unsupported`]) and
    /// as the converters do.
    pub fn encode(&self, figure: &Figure, svg: &str) -> Result<Vec<u8>> {
        match self {
            FileFormat::Svg => Ok(svg.as_bytes().to_vec()),
            FileFormat::Png => super::to_png(svg, PNG_SCALE),
            FileFormat::Pdf => super::to_pdf(svg),
            FileFormat::Tikz => Ok(to_tikz(figure, &TikzOptions::default()).into_bytes()),
        }
    }

    /// The bytes of the figure whose SVG is `svg` in each of `formats`, in
    /// their order: [`FileFormat::encode`] of each, the SVG read (parsed,
    /// its letters laid out) once for PNG and PDF together. Errors as the
    /// first format that fails.
    pub fn encode_all(figure: &Figure, svg: &str, formats: &[FileFormat]) -> Result<Vec<Vec<u8>>> {
        #[cfg(any(feature = "png", feature = "pdf"))]
        {
            let mut read = None;
            formats
                .iter()
                .map(|f| f.encode_reading(figure, svg, &mut read))
                .collect()
        }
        #[cfg(not(any(feature = "png", feature = "pdf")))]
        formats.iter().map(|f| f.encode(figure, svg)).collect()
    }

    /// [`FileFormat::encode`], from `read` (the SVG's tree) where this
    /// format draws from one, reading it into `read` first if it is empty.
    #[cfg(any(feature = "png", feature = "pdf"))]
    fn encode_reading(
        &self,
        figure: &Figure,
        svg: &str,
        read: &mut Option<usvg::Tree>,
    ) -> Result<Vec<u8>> {
        let tree = match (self, read.take()) {
            (FileFormat::Svg | FileFormat::Tikz, _) => return self.encode(figure, svg),
            (_, Some(tree)) => tree,
            (_, None) => super::svg_tree::read(svg)?,
        };
        let bytes = match self {
            #[cfg(feature = "png")]
            FileFormat::Png => super::png::tree_to_png(&tree, PNG_SCALE),
            #[cfg(feature = "pdf")]
            FileFormat::Pdf => super::pdf::tree_to_pdf(&tree),
            _ => self.encode(figure, svg),
        };
        *read = Some(tree);
        bytes
    }
}

/// Pixels per page unit of a PNG written by [`FileFormat::encode`].
const PNG_SCALE: f32 = 2.0;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn formats_encoded_together_are_the_bytes_of_each_alone() {
        let figure = crate::catalogue::FigureName::Fig63Velocity
            .figure(&crate::catalogue::FigureOptions::default())
            .unwrap();
        let svg = crate::render::to_svg(&figure);
        for formats in [
            &FileFormat::ALL[..],
            &[FileFormat::Pdf, FileFormat::Png][..],
            &[FileFormat::Png][..],
        ] {
            let together = FileFormat::encode_all(&figure, &svg, formats).unwrap();
            assert_eq!(together.len(), formats.len());
            for (bytes, format) in together.iter().zip(formats) {
                assert!(
                    *bytes == format.encode(&figure, &svg).unwrap(),
                    "{format:?}"
                );
            }
        }
        assert!(FileFormat::encode_all(&figure, "<svg", &FileFormat::PICTURES).is_err());
    }

    #[test]
    fn the_extension_tells_the_format() {
        for (path, format) in [
            ("a.svg", FileFormat::Svg),
            ("a.PNG", FileFormat::Png),
            ("dir.x/fig.pdf", FileFormat::Pdf),
            ("fig.tex", FileFormat::Tikz),
            ("-", FileFormat::Svg),
            ("/dev/stdout", FileFormat::Svg),
            ("figure", FileFormat::Svg),
        ] {
            assert_eq!(FileFormat::from_path(Path::new(path)).unwrap(), format);
        }
        for path in ["x.jpg", "x.eps", "x.svg.bak", ".pdf.tmp"] {
            let err = FileFormat::from_path(Path::new(path))
                .unwrap_err()
                .to_string();
            assert!(
                err.starts_with(&format!("cannot write {path}: ."))
                    && err.ends_with("give a file ending in .svg, .png, .pdf or .tex"),
                "{err}"
            );
        }
    }
}
