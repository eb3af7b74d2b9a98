//! The PNG settings measured on the gallery's figures: every named figure
//! at its defaults drawn as `render::to_png` draws it (twice the page
//! size, on its paper), then encoded with each colour type, row filter and
//! compression; the total size and the median encoding time of each
//! setting over the rounds (docs/benchmarks.md).
//!
//! ```sh
//! cargo run --release --example png_encoding [ROUNDS]
//! ```

use resvg::tiny_skia::{self, Pixmap};
use slider_crank::catalogue::FigureOptions;
use slider_crank::render::to_svg;
use slider_crank::{FigureName, Font};
use std::sync::Arc;
use std::time::{Duration, Instant};

/// Every named figure's canvas, drawn at scale 2 on white.
fn canvases() -> Vec<Pixmap> {
    let mut db = usvg::fontdb::Database::new();
    for font in Font::ALL {
        for data in font.files() {
            db.load_font_data(data.to_vec());
        }
    }
    let options = usvg::Options {
        fontdb: Arc::new(db),
        ..usvg::Options::default()
    };
    FigureName::ALL
        .iter()
        .map(|name| {
            let figure = name
                .figure(&FigureOptions::default())
                .expect("a named figure builds");
            let tree = usvg::Tree::from_str(&to_svg(&figure), &options).expect("its SVG reads");
            let size = tree.size().to_int_size().scale_by(2.0).expect("a size");
            let mut pixmap = Pixmap::new(size.width(), size.height()).expect("a canvas");
            pixmap.fill(tiny_skia::Color::WHITE);
            resvg::render(
                &tree,
                tiny_skia::Transform::from_scale(2.0, 2.0),
                &mut pixmap.as_mut(),
            );
            pixmap
        })
        .collect()
}

/// One canvas encoded with the given settings: its length.
fn encode(
    pixmap: &Pixmap,
    rgb: bool,
    filter: png::Filter,
    compression: png::DeflateCompression,
) -> usize {
    let (w, h) = (pixmap.width(), pixmap.height());
    let mut out = Vec::new();
    let mut encoder = png::Encoder::new(&mut out, w, h);
    encoder.set_color(if rgb {
        png::ColorType::Rgb
    } else {
        png::ColorType::Rgba
    });
    encoder.set_depth(png::BitDepth::Eight);
    encoder.set_filter(filter);
    encoder.set_deflate_compression(compression);
    let mut writer = encoder.write_header().expect("a header");
    if rgb {
        let mut stream = writer.stream_writer().expect("a stream");
        let mut row = Vec::with_capacity(3 * w as usize);
        for pixels in pixmap.data().chunks_exact(4 * w as usize) {
            row.clear();
            for px in pixels.chunks_exact(4) {
                row.extend_from_slice(&px[..3]);
            }
            std::io::Write::write_all(&mut stream, &row).expect("written");
        }
        stream.finish().expect("finished");
    } else {
        writer.write_image_data(pixmap.data()).expect("written");
    }
    writer.finish().expect("finished");
    out.len()
}

fn main() {
    let rounds: usize = std::env::args()
        .nth(1)
        .map(|a| a.parse().expect("ROUNDS is a count"))
        .unwrap_or(3)
        .max(1);
    let canvases = canvases();
    // resvg's own encoder (tiny-skia: a demultiplied copy, RGBA, the
    // adaptive filter, level 6) for comparison.
    let mut times = Vec::new();
    let mut bytes = 0;
    for _ in 0..rounds {
        let start = Instant::now();
        bytes = canvases
            .iter()
            .map(|p| p.encode_png().expect("encoded").len())
            .sum();
        times.push(start.elapsed());
    }
    times.sort();
    println!(
        "{:<42} {:>10} {:>10.1?}",
        "tiny-skia encode_png (RGBA, adaptive, 6)",
        bytes,
        times[times.len() / 2]
    );
    use png::DeflateCompression::{FdeflateUltraFast, Level};
    for rgb in [true, false] {
        for (fname, filter) in [
            ("none", png::Filter::NoFilter),
            ("sub", png::Filter::Sub),
            ("up", png::Filter::Up),
            ("paeth", png::Filter::Paeth),
            ("adaptive", png::Filter::Adaptive),
        ] {
            for (cname, compression) in [
                ("fdeflate", FdeflateUltraFast),
                ("1", Level(1)),
                ("3", Level(3)),
                ("4", Level(4)),
                ("5", Level(5)),
                ("6", Level(6)),
                ("9", Level(9)),
            ] {
                let mut times: Vec<Duration> = Vec::new();
                let mut bytes = 0;
                for _ in 0..rounds {
                    let start = Instant::now();
                    bytes = canvases
                        .iter()
                        .map(|p| encode(p, rgb, filter, compression))
                        .sum();
                    times.push(start.elapsed());
                }
                times.sort();
                let label = format!(
                    "{} filter {fname}, deflate {cname}",
                    if rgb { "RGB " } else { "RGBA" }
                );
                println!("{label:<42} {bytes:>10} {:>10.1?}", times[times.len() / 2]);
            }
        }
    }
}
