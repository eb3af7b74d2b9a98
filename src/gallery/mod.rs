//! The gallery: every named figure at the seed's own parameters in each
//! file format, every table `slider-crank table` prints, and an
//! `index.html` that shows them with a caption naming the seed, section and
//! figure each reproduces. A manifest ([`Gallery::from_manifest`]) can
//! choose the figures, add scene files, and set the formats, style and
//! face.
//!
//! [`Gallery::build`] makes the files on every core and hands each to the
//! caller in the order of [`Gallery::file_names`] (the caller writes it,
//! or compares it with a file on disk); [`Gallery::write_into`] writes
//! them into a directory, all or none.
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

mod compare;
mod index;
mod manifest;
mod parallel;
mod quote;
mod request;
mod write;

use crate::catalogue::FigureOptions;
use crate::error::{Error, Input, Result};
use crate::figure::Font;
use crate::render::{FileFormat, to_svg};
use crate::table::{Format, TableName};
use crate::{catalogue::FigureName, figure::Style, scene::Scene};

pub use compare::Difference;
pub use request::GalleryRequest;
pub use write::{STAGED_PREFIX, leftovers, lock_directory};

/// The name of the gallery's index page.
pub const INDEX: &str = "index.html";

/// What a gallery holds: which figures, in which formats, drawn in which
/// style and face. [`Gallery::new`] is the whole catalogue in SVG, PNG and
/// PDF, each figure in its own style.
#[derive(Debug, Clone, PartialEq)]
pub struct Gallery {
    figures: Vec<FigureName>,
    scenes: Vec<SceneEntry>,
    formats: Vec<FileFormat>,
    style: Option<Style>,
    font: Option<Font>,
}

/// A scene of a gallery: the name of its files, the scene file it was
/// read from (as the manifest gives it), the scene.
#[derive(Debug, Clone, PartialEq)]
struct SceneEntry {
    name: String,
    file: String,
    scene: Scene,
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
            scenes: Vec::new(),
            formats: FileFormat::PICTURES.to_vec(),
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

    /// Adds a scene, drawn after the named figures into files named
    /// `name.svg`, …; `source` says where it comes from in its caption (a
    /// scene file's path). Errors when a figure or another scene already
    /// has that name, or the name is not a plain file name.
    pub fn with_scene(mut self, name: &str, source: &str, scene: Scene) -> Result<Self> {
        self.add_scene(SceneEntry {
            name: name.into(),
            file: source.into(),
            scene,
        })?;
        Ok(self)
    }

    fn add_scene(&mut self, entry: SceneEntry) -> Result<()> {
        let name = &entry.name;
        let plain = !name.is_empty()
            && !name.starts_with('.')
            && !name.contains(['/', '\\'])
            && name != INDEX;
        if !plain {
            return Err(Error::invalid(
                Input::Manifest,
                format!("'{name}' cannot name a gallery's files"),
            ));
        }
        let taken = self.figures.iter().any(|f| f.name() == name)
            || self.scenes.iter().any(|s| &s.name == name)
            || TableName::GALLERY
                .iter()
                .any(|t| Self::table_file(*t).strip_suffix(".txt") == Some(name));
        if taken {
            return Err(Error::invalid(
                Input::Manifest,
                format!("two entries of the gallery are named {name}: rename the scene file"),
            ));
        }
        self.scenes.push(entry);
        Ok(())
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
    /// each format, each scene in each format, the tables, then [`INDEX`].
    pub fn file_names(&self) -> Vec<String> {
        let figures = self.figures.iter().flat_map(|&f| {
            self.formats
                .iter()
                .map(move |&format| Self::figure_file(f, format))
        });
        let scenes = self.scenes.iter().flat_map(|s| {
            self.formats
                .iter()
                .map(move |format| format!("{}.{}", s.name, format.extension()))
        });
        figures
            .chain(scenes)
            .chain(TableName::GALLERY.into_iter().map(Self::table_file))
            .chain([INDEX.to_string()])
            .collect()
    }

    /// Whether this build can make the gallery: an error when it has no
    /// format, or one that this build leaves out (naming the feature).
    pub fn can_build(&self) -> Result<()> {
        if self.formats.is_empty() {
            return Err(Error::invalid(
                Input::Manifest,
                "a gallery needs at least one format".into(),
            ));
        }
        match self.formats.iter().find(|f| !f.is_supported()) {
            Some(f) => Err(Error::Unsupported(format!(
                "the gallery's {} files need the `{}` feature of slider-crank, which this build leaves out",
                f.extension().to_uppercase(),
                f.extension()
            ))),
            None => Ok(()),
        }
    }

    /// Makes every file of [`Gallery::file_names`] and hands each to
    /// `each`, in that order, as soon as it and those before it are made;
    /// stops at the first error (of [`Gallery::can_build`], of a figure,
    /// or of `each`).
    ///
    /// The figures, scenes and tables are made on as many threads as the
    /// machine runs at once ([`std::thread::available_parallelism`]; one
    /// on a single core); `each` runs on the calling thread, in order, so
    /// the files and their order are those of a single thread.
    pub fn build(&self, mut each: impl FnMut(GalleryFile) -> Result<()>) -> Result<()> {
        self.can_build()?;
        let jobs = self.jobs();
        let threads = std::thread::available_parallelism()
            .map_or(1, |n| n.get())
            .min(jobs.len());
        let mut tables = Vec::new();
        parallel::in_order(
            &jobs,
            threads,
            |job| self.make(job),
            |made| {
                for file in made.files {
                    each(file)?;
                }
                tables.extend(made.table);
                Ok(())
            },
        )?;
        each(GalleryFile {
            name: INDEX.into(),
            bytes: index::page(self, &tables).into_bytes(),
        })
    }

    /// What [`Gallery::build`] makes before the index, in order.
    fn jobs(&self) -> Vec<Job> {
        let figures = self.figures.iter().map(|&f| Job::Figure(f));
        let scenes = (0..self.scenes.len()).map(Job::Scene);
        let tables = TableName::GALLERY.into_iter().map(Job::Table);
        figures.chain(scenes).chain(tables).collect()
    }

    /// The files of one job (and the table, for the index).
    fn make(&self, job: &Job) -> Result<Made> {
        let (drawn, name) = match *job {
            Job::Figure(figure) => {
                let options = FigureOptions {
                    style: self.style,
                    font: self.font,
                    ..FigureOptions::default()
                };
                (figure.figure(&options)?, figure.name())
            }
            Job::Scene(i) => {
                // cannot fail: the scene jobs are made from
                // `0..self.scenes.len()`.
                #[allow(clippy::indexing_slicing)]
                let entry = &self.scenes[i];
                (entry.scene.figure()?, entry.name.as_str())
            }
            Job::Table(table) => {
                let t = table.table()?;
                return Ok(Made {
                    files: vec![GalleryFile {
                        name: Self::table_file(table),
                        bytes: t.render(Format::Text).into_bytes(),
                    }],
                    table: Some((table, t)),
                });
            }
        };
        let svg = to_svg(&drawn);
        let files = FileFormat::encode_all(&drawn, &svg, &self.formats)?
            .into_iter()
            .zip(&self.formats)
            .map(|(bytes, format)| GalleryFile {
                name: format!("{name}.{}", format.extension()),
                bytes,
            })
            .collect();
        Ok(Made { files, table: None })
    }
}

/// One piece of a gallery's work: a figure or scene in every format, or a
/// table.
#[derive(Debug, Clone, Copy)]
enum Job {
    Figure(FigureName),
    /// The scene at this index of [`Gallery::scenes`].
    Scene(usize),
    Table(TableName),
}

/// What one [`Job`] made.
struct Made {
    files: Vec<GalleryFile>,
    table: Option<(TableName, crate::table::Table)>,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_whole_catalogue_in_three_formats() {
        let names = Gallery::new().file_names();
        assert_eq!(
            names.len(),
            FigureName::ALL.len() * 3 + TableName::GALLERY.len() + 1
        );
        for f in FigureName::ALL {
            for ext in ["svg", "png", "pdf"] {
                assert!(names.contains(&format!("{}.{ext}", f.name())));
            }
        }
        assert_eq!(names.last().unwrap(), INDEX);
    }

    #[test]
    fn the_index_quotes_a_scene_file_for_the_shell_and_its_files_for_urls() {
        let scene = FigureName::Fig63Velocity.scene().unwrap();
        let gallery = Gallery::new()
            .with_figures([])
            .with_formats([FileFormat::Svg])
            .with_scene("x;touch PWNED;#", "x;touch PWNED;#.toml", scene.clone())
            .unwrap()
            .with_scene("a?b%c", "a?b%c.toml", scene)
            .unwrap();
        let page = index::page(&gallery, &[]);
        assert!(
            page.contains("<code>slider-crank scene 'x;touch PWNED;#.toml'</code>"),
            "{page}"
        );
        assert!(
            page.contains("href=\"x%3Btouch%20PWNED%3B%23.svg\""),
            "{page}"
        );
        assert!(page.contains("src=\"a%3Fb%25c.svg\""), "{page}");
        assert!(!page.contains("href=\"x;"), "{page}");
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
