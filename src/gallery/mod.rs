//! The gallery: every named figure at the seed's own parameters in each
//! file format, every table `slider-crank table` prints, and an
//! `index.html` that shows them with a caption naming the seed, section and
//! figure each reproduces.
//!
//! [`Gallery::build`] makes the files one at a time, in the order of
//! [`Gallery::file_names`], and hands each to the caller (which writes it,
//! or compares it with a file on disk); nothing is written here.
//!
//! ```
//! use slider_crank::gallery::Gallery;
//! use slider_crank::render::FileFormat;
//! use slider_crank::FigureName;
//!
//! let gallery = Gallery::new()
//!     .with_figures([FigureName::Fig63Velocity])
//!     .with_formats([FileFormat::Svg]);
//! let mut names = Vec::new();
//! gallery.build(|file| {
//!     names.push(file.name);
//!     Ok(())
//! })?;
//! assert_eq!(names, gallery.file_names());
//! assert_eq!(names.first().map(String::as_str), Some("fig-63-velocity.svg"));
//! assert_eq!(names.last().map(String::as_str), Some("index.html"));
//! # Ok::<(), slider_crank::Error>(())
//! ```

mod index;

use crate::error::{Error, Result};
use crate::figure::{FigureOptions, Font};
use crate::render::{FileFormat, to_svg};
use crate::table::{Format, TableName};
use crate::{FigureName, Style};

/// The name of the gallery's index page.
pub const INDEX: &str = "index.html";

/// What a gallery holds: which figures, in which formats, drawn in which
/// style and face. [`Gallery::new`] is the whole catalogue in SVG, PNG and
/// PDF, each figure in its own style.
#[derive(Debug, Clone, PartialEq)]
pub struct Gallery {
    figures: Vec<FigureName>,
    formats: Vec<FileFormat>,
    style: Option<Style>,
    font: Option<Font>,
}

/// One file of a gallery: its name in the gallery's directory and its
/// bytes.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct GalleryFile {
    /// The file name (`fig-67-example.pdf`, `table-forces.txt`,
    /// `index.html`).
    pub name: String,
    /// The file's contents.
    pub bytes: Vec<u8>,
}

impl Default for Gallery {
    fn default() -> Self {
        Self::new()
    }
}

impl Gallery {
    /// Every named figure ([`FigureName::ALL`]) as SVG, PNG and PDF, every
    /// table, and the index.
    pub fn new() -> Self {
        Gallery {
            figures: FigureName::ALL.to_vec(),
            formats: FileFormat::ALL.to_vec(),
            style: None,
            font: None,
        }
    }

    /// Only these figures, in this order (each once).
    pub fn with_figures(mut self, figures: impl IntoIterator<Item = FigureName>) -> Self {
        self.figures.clear();
        for f in figures {
            if !self.figures.contains(&f) {
                self.figures.push(f);
            }
        }
        self
    }

    /// Only these formats, in this order (each once).
    pub fn with_formats(mut self, formats: impl IntoIterator<Item = FileFormat>) -> Self {
        self.formats.clear();
        for f in formats {
            if !self.formats.contains(&f) {
                self.formats.push(f);
            }
        }
        self
    }

    /// Every figure drawn in `style` instead of its own.
    pub fn with_style(mut self, style: Style) -> Self {
        self.style = Some(style);
        self
    }

    /// Every figure's text set in `font` instead of the default face.
    pub fn with_font(mut self, font: Font) -> Self {
        self.font = Some(font);
        self
    }

    /// The figures, in the order they are made.
    pub fn figures(&self) -> &[FigureName] {
        &self.figures
    }

    /// The formats each figure is written in.
    pub fn formats(&self) -> &[FileFormat] {
        &self.formats
    }

    /// The name of a figure's file in `format` (`fig-65-klein.pdf`).
    pub fn figure_file(figure: FigureName, format: FileFormat) -> String {
        format!("{}.{}", figure.name(), format.extension())
    }

    /// The name of a table's text file (`table-forces.txt`).
    pub fn table_file(table: TableName) -> String {
        format!("table-{}.txt", table.name())
    }

    /// Every file [`Gallery::build`] makes, in that order: each figure in
    /// each format, the tables, then [`INDEX`].
    pub fn file_names(&self) -> Vec<String> {
        let figures = self.figures.iter().flat_map(|&f| {
            self.formats
                .iter()
                .map(move |&format| Self::figure_file(f, format))
        });
        figures
            .chain(TableName::ALL.into_iter().map(Self::table_file))
            .chain([INDEX.to_string()])
            .collect()
    }

    /// Makes every file of [`Gallery::file_names`], in order, and hands
    /// each to `each` as soon as it is made; stops at the first error
    /// (of a figure, of a format this build leaves out, or of `each`).
    pub fn build(&self, mut each: impl FnMut(GalleryFile) -> Result<()>) -> Result<()> {
        if self.formats.is_empty() {
            return Err(Error::Parse("a gallery needs at least one format".into()));
        }
        let options = FigureOptions {
            style: self.style,
            font: self.font,
            ..FigureOptions::default()
        };
        for &figure in &self.figures {
            let svg = to_svg(&figure.figure(&options)?);
            for &format in &self.formats {
                let name = Self::figure_file(figure, format);
                let bytes = format.encode(&svg)?;
                each(GalleryFile { name, bytes })?;
            }
        }
        let mut tables = Vec::new();
        for table in TableName::ALL {
            let t = table.table()?;
            each(GalleryFile {
                name: Self::table_file(table),
                bytes: t.render(Format::Text).into_bytes(),
            })?;
            tables.push((table, t));
        }
        each(GalleryFile {
            name: INDEX.into(),
            bytes: index::page(self, &tables).into_bytes(),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_whole_catalogue_in_three_formats() {
        let names = Gallery::new().file_names();
        assert_eq!(
            names.len(),
            FigureName::ALL.len() * 3 + TableName::ALL.len() + 1
        );
        for f in FigureName::ALL {
            for ext in ["svg", "png", "pdf"] {
                assert!(names.contains(&format!("{}.{ext}", f.name())));
            }
        }
        assert_eq!(names.last().unwrap(), INDEX);
    }

    #[test]
    fn an_error_names_the_file() {
        let err = Gallery::new()
            .with_formats([])
            .build(|_| Ok(()))
            .unwrap_err();
        assert!(err.to_string().contains("at least one format"), "{err}");
    }
}
