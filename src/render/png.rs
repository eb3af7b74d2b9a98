//! SVG to PNG through resvg, with the bundled faces only: no system font
//! is ever loaded, so the same SVG gives the same bytes on every machine.

use super::font_database::font_database;
use super::svg_tree::read_with;
use crate::error::{Error, Field, Result};
use resvg::tiny_skia;
use std::sync::Arc;
use usvg::fontdb::Database;

/// Most pixels of a PNG (24 megapixels, 96 MB of canvas: a 2400 × 2400
/// page at scale 2). A larger picture is refused with a message, never
/// allocated.
pub const MAX_PNG_PIXELS: u64 = 24_000_000;

/// Renders SVG text to PNG bytes at `scale` pixels per page unit (1 for
/// the page size, 2 for a sharper picture). Letters are set in the
/// bundled faces ([`Font`](crate::figure::Font)) whatever fonts the machine has.
pub fn to_png(svg: &str, scale: f32) -> Result<Vec<u8>> {
    render(svg, scale, font_database())
}

fn render(svg: &str, scale: f32, fontdb: Arc<Database>) -> Result<Vec<u8>> {
    check_scale(scale)?;
    draw(&read_with(svg, fontdb)?, scale)
}

/// The PNG of an SVG already read ([`super::svg_tree::read`]), at `scale`
/// pixels per page unit: the same bytes as [`to_png`] of its text.
pub(crate) fn tree_to_png(tree: &usvg::Tree, scale: f32) -> Result<Vec<u8>> {
    check_scale(scale)?;
    draw(tree, scale)
}

fn check_scale(scale: f32) -> Result<()> {
    if scale.is_finite() && scale > 0.0 && scale <= 16.0 {
        Ok(())
    } else {
        Err(Error::OutOfRange {
            name: Field::Scale,
            value: scale as f64,
            reason: "a PNG scale is between 0 and 16".into(),
        })
    }
}

/// Rasterises `tree` at `scale` (checked) onto its paper and encodes it.
fn draw(tree: &usvg::Tree, scale: f32) -> Result<Vec<u8>> {
    let size = tree
        .size()
        .to_int_size()
        .scale_by(scale)
        .ok_or_else(|| Error::OutOfRange {
            name: Field::Scale,
            value: scale as f64,
            reason: "the picture would be empty".into(),
        })?;
    let pixels = u64::from(size.width()) * u64::from(size.height());
    if pixels > MAX_PNG_PIXELS {
        return Err(Error::OutOfRange {
            name: Field::PngSize,
            value: pixels as f64,
            reason: format!(
                "a PNG of {} × {} pixels is more than the {} megapixels this program draws: make the page smaller, or write SVG",
                size.width(),
                size.height(),
                MAX_PNG_PIXELS / 1_000_000
            ),
        });
    }
    let paper = paper(tree);
    let mut pixmap = canvas(size, paper).ok_or_else(|| Error::OutOfRange {
        name: Field::Scale,
        value: scale as f64,
        reason: "the picture would be too large".into(),
    })?;
    resvg::render(
        tree,
        tiny_skia::Transform::from_scale(scale, scale),
        &mut pixmap.as_mut(),
    );
    let encoded = match paper {
        Some(_) => encode_opaque(&pixmap),
        None => pixmap.encode_png(),
    };
    keep(pixmap);
    encoded.map_err(|e| Error::Io {
        message: format!("cannot encode PNG: {e}"),
        path: None,
        source: None,
    })
}

/// The canvas of `size` pixels, filled with `paper` (in one pass: a blank
/// canvas then filled would be written twice) or transparent, made in this
/// thread's spare canvas where it has one ([`SPARE`]). `None` for a canvas
/// too large to allocate.
fn canvas(size: tiny_skia::IntSize, paper: Option<tiny_skia::Color>) -> Option<tiny_skia::Pixmap> {
    let bytes = usize::try_from(u64::from(size.width()) * u64::from(size.height()) * 4).ok()?;
    let mut data = SPARE.with_borrow_mut(std::mem::take);
    data.clear();
    match paper {
        Some(colour) => {
            let c = colour.premultiply().to_color_u8();
            data.try_reserve_exact(bytes).ok()?;
            data.extend_from_slice(&[c.red(), c.green(), c.blue(), c.alpha()]);
            // Doubled copies of what is there: memory speed, as `repeat`.
            while data.len() < bytes {
                data.extend_from_within(..data.len().min(bytes - data.len()));
            }
        }
        None => {
            data.try_reserve_exact(bytes).ok()?;
            data.resize(bytes, 0);
        }
    }
    tiny_skia::Pixmap::from_vec(data, size)
}

/// The largest canvas a thread keeps for its next PNG, bytes (a page of
/// 1 000 × 1 400 units at scale 2 is 11.2 MB).
const SPARE_LARGEST: usize = 16 << 20;

thread_local! {
    /// The canvas this thread last drew on, kept for its next PNG: a fresh
    /// one of several megabytes is memory the kernel finds and zeroes page
    /// by page on its first touch (a tenth of the gallery's time), a kept
    /// one is only painted over. Pictures larger than [`SPARE_LARGEST`]
    /// are not kept.
    static SPARE: std::cell::RefCell<Vec<u8>> = const { std::cell::RefCell::new(Vec::new()) };
}

/// Gives `pixmap`'s memory back to this thread's spare canvas.
fn keep(pixmap: tiny_skia::Pixmap) {
    let data = pixmap.take();
    if data.capacity() <= SPARE_LARGEST {
        SPARE.set(data);
    }
}

/// The colour of a figure's paper (its `<rect id="paper">`, opaque), to
/// lay under the whole picture: the paper then reaches the last row and
/// column of pixels even where the page ends within them (a page of
/// 453.54 units is 908 pixels at scale 2, the last one 9 % paper).
/// `None` for an SVG without one (drawn on transparency).
fn paper(tree: &usvg::Tree) -> Option<tiny_skia::Color> {
    let Some(usvg::Node::Path(rect)) = tree.node_by_id("paper") else {
        return None;
    };
    let fill = rect.fill()?;
    match fill.paint() {
        usvg::Paint::Color(c) if fill.opacity().get() == 1.0 => {
            Some(tiny_skia::Color::from_rgba8(c.red, c.green, c.blue, 255))
        }
        _ => None,
    }
}

/// A picture every pixel of which is opaque, as an 8-bit RGB PNG written
/// straight from the canvas (opaque pixels are the same premultiplied or
/// not, so there is no demultiplied copy). No filter and zlib level
/// [`LEVEL`]: of the settings measured on the gallery's PNGs
/// (docs/benchmarks.md) the fastest that is also among the smallest; the
/// adaptive filter, `png`'s default, made them larger and slower. The pixels are deflated here,
/// [`ROWS_BYTES`] at a time, into the one IDAT chunk `png` itself would
/// write: `png` hands the compressor each row in two writes, and each
/// write cost a clearing of the compressor's 32 KiB output buffer.
fn encode_opaque(pixmap: &tiny_skia::Pixmap) -> std::result::Result<Vec<u8>, png::EncodingError> {
    let mut out = Vec::new();
    let mut encoder = png::Encoder::new(&mut out, pixmap.width(), pixmap.height());
    encoder.set_color(png::ColorType::Rgb);
    encoder.set_depth(png::BitDepth::Eight);
    let mut writer = encoder.write_header()?;
    writer.write_chunk(png::chunk::IDAT, &deflate_rows(pixmap)?)?;
    writer.finish()?;
    Ok(out)
}

/// Bytes of scanlines handed to the compressor at a time.
const ROWS_BYTES: usize = 256 * 1024;

/// The zlib compression level of a PNG: level 5 deflates the gallery's
/// pictures in three quarters of level 6's time for 1.4 % more bytes
/// (levels 1, 3, 4, 5, 6 and 9 measured, docs/benchmarks.md).
const LEVEL: u32 = 5;

/// The zlib stream (level [`LEVEL`]) of the canvas's scanlines as a PNG without
/// filter holds them: each row its filter byte 0 and its pixels' red,
/// green and blue.
fn deflate_rows(pixmap: &tiny_skia::Pixmap) -> std::io::Result<Vec<u8>> {
    use std::io::Write;
    let width = pixmap.width() as usize;
    let row_bytes = 1 + 3 * width;
    let rows_at_a_time = (ROWS_BYTES / row_bytes).max(1);
    let mut block = Vec::with_capacity(rows_at_a_time * row_bytes);
    let mut zlib = flate2::write::ZlibEncoder::new(Vec::new(), flate2::Compression::new(LEVEL));
    for rows in pixmap.data().chunks(4 * width * rows_at_a_time) {
        block.clear();
        for pixels in rows.chunks_exact(4 * width) {
            block.push(0);
            for rgba in pixels.chunks_exact(4) {
                block.extend_from_slice(rgba.get(..3).unwrap_or_default());
            }
        }
        zlib.write_all(&block)?;
    }
    zlib.finish()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::catalogue::FigureOptions;
    use crate::figure::{Font, FontStyle};
    use crate::render::font_database::load_bundled;
    use crate::render::to_svg;
    use crate::{catalogue::FigureName, figure::Style};
    use usvg::fontdb::Source;
    use usvg::fontdb::{Family, Query};

    #[test]
    fn a_kept_canvas_paints_as_a_fresh_one() {
        let svg = |name: FigureName| to_svg(&name.figure(&FigureOptions::default()).unwrap());
        let (big, small) = (
            svg(FigureName::Fig67Example),
            svg(FigureName::Fig63Velocity),
        );
        let clear = r#"<svg xmlns="http://www.w3.org/2000/svg" width="40" height="30"><path d="M5 5 L35 25" stroke="black"/></svg>"#;
        let first =
            [to_png(&small, 1.0), to_png(clear, 1.0), to_png(&big, 1.0)].map(Result::unwrap);
        // Each drawn again on the canvas the one before left behind.
        for (k, svg) in [small.as_str(), clear, big.as_str()]
            .into_iter()
            .enumerate()
            .rev()
        {
            assert!(
                to_png(svg, 1.0).unwrap() == first[k],
                "picture {k} changed on a kept canvas"
            );
        }
        let fresh = std::thread::spawn(move || to_png(&small, 1.0).unwrap())
            .join()
            .unwrap();
        assert!(fresh == first[0]);
    }

    #[test]
    fn huge_pages_are_refused_before_drawing() {
        // Issue 9 (8): a 20000 × 20000 page took 12 GB.
        let svg = r#"<svg xmlns="http://www.w3.org/2000/svg" width="20000" height="20000"/>"#;
        let err = to_png(svg, 2.0).unwrap_err().to_string();
        assert!(
            err.contains("a PNG of 40000 × 40000 pixels is more than the 24 megapixels"),
            "{err}"
        );
        let small = r#"<svg xmlns="http://www.w3.org/2000/svg" width="100" height="50"/>"#;
        assert!(to_png(small, 2.0).unwrap().starts_with(b"\x89PNG"));
    }

    #[test]
    fn the_paper_reaches_the_last_row_and_column() {
        // Issue 20: a page of 120 mm (453.54 units) is 908 pixels at
        // scale 2, its last column 9 % paper; and 800 × 300 asked of Fig.
        // 67 (since refused: 700). Every pixel is opaque, the edges the
        // paper's colour.
        for (name, width, height, style) in [
            (FigureName::Fig60Chains, "120mm", None, Style::Textbook),
            (FigureName::Fig67Example, "800", Some("700"), Style::Handout),
        ] {
            let options = FigureOptions {
                width: Some(width.parse().unwrap()),
                height: height.map(|h| h.parse().unwrap()),
                style: Some(style),
                ..FigureOptions::default()
            };
            let svg = to_svg(&name.figure(&options).unwrap());
            let png = to_png(&svg, 2.0).unwrap();
            let pixmap = tiny_skia::Pixmap::decode_png(&png).unwrap();
            let (w, h) = (pixmap.width(), pixmap.height());
            let paper = match style {
                Style::Textbook => [255, 255, 255],
                _ => [255, 253, 247],
            };
            for y in 0..h {
                for x in 0..w {
                    let p = pixmap.pixel(x, y).unwrap();
                    assert_eq!(p.alpha(), 255, "{} ({x}, {y})", name.name());
                    if x + 1 == w || y + 1 == h {
                        assert_eq!(
                            [p.red(), p.green(), p.blue()],
                            paper,
                            "{} ({x}, {y})",
                            name.name()
                        );
                    }
                }
            }
        }
        // An SVG without a paper keeps its transparency.
        let bare = r#"<svg xmlns="http://www.w3.org/2000/svg" width="10.5" height="10"/>"#;
        let pixmap = tiny_skia::Pixmap::decode_png(&to_png(bare, 1.0).unwrap()).unwrap();
        assert_eq!(pixmap.pixel(0, 0).unwrap().alpha(), 0);
    }

    /// Every font file under `dir` (the machine's fonts), read with std
    /// alone: the font database is built without file-system support.
    fn load_dir(db: &mut Database, dir: &std::path::Path) {
        let Ok(entries) = std::fs::read_dir(dir) else {
            return;
        };
        for e in entries.flatten() {
            let p = e.path();
            if p.is_dir() {
                load_dir(db, &p);
            } else if p
                .extension()
                .and_then(|x| x.to_str())
                .is_some_and(|x| ["ttf", "otf", "ttc", "otc"].contains(&x.to_lowercase().as_str()))
                && let Ok(bytes) = std::fs::read(&p)
            {
                db.load_font_data(bytes);
            }
        }
    }

    #[test]
    fn the_svg_family_is_found_among_the_bundled_faces() {
        let db = font_database();
        for font in Font::ALL {
            let id = db
                .query(&Query {
                    families: &[Family::Name(font.family())],
                    style: usvg::fontdb::Style::Italic,
                    ..Query::default()
                })
                .expect("family found");
            let name = db.face(id).map(|f| f.post_script_name.clone());
            assert_eq!(
                name.as_deref(),
                Some(font.postscript_name(FontStyle::Italic))
            );
        }
    }

    #[test]
    fn png_bytes_do_not_depend_on_the_machines_fonts() {
        // Other fonts a machine may have: its own, and the faces
        // typst-assets ships that the figures do not use (DejaVu Sans
        // Mono, Libertinus bold, the maths faces), loaded after the
        // bundled ones.
        let mut crowded = Database::new();
        load_bundled(&mut crowded);
        let bundled_faces = crowded.len();
        load_dir(&mut crowded, std::path::Path::new("/usr/share/fonts"));
        for data in typst_assets::fonts() {
            crowded.load_font_source(Source::Binary(Arc::new(data)));
        }
        assert!(crowded.len() > bundled_faces + 10, "{}", crowded.len());
        let crowded = Arc::new(crowded);
        for (name, font) in [
            (FigureName::Fig67Example, Font::NewComputerModern),
            (FigureName::NgFig1Torque, Font::LibertinusSerif),
            (FigureName::Fig64VelocityDiagrams, Font::NewComputerModern),
        ] {
            let options = FigureOptions {
                font: Some(font),
                style: Some(Style::Handout),
                ..FigureOptions::default()
            };
            let svg = to_svg(&name.figure(&options).unwrap());
            let alone = render(&svg, 1.0, font_database()).unwrap();
            let with_machine = render(&svg, 1.0, crowded.clone()).unwrap();
            assert!(alone == with_machine, "{}", name.name());
            // The text is drawn at all: without fonts the bytes differ.
            let bare = render(&svg, 1.0, Arc::new(Database::new())).unwrap();
            assert!(alone != bare, "{}", name.name());
            // The SVG's family is the face drawn: a database of that face
            // alone gives the same bytes (no fallback to the generic serif).
            let mut only = Database::new();
            for data in font.files() {
                only.load_font_source(Source::Binary(Arc::new(data)));
            }
            let only = render(&svg, 1.0, Arc::new(only)).unwrap();
            assert!(alone == only, "{}", name.name());
        }
    }
}
