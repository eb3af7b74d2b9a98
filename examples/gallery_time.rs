//! Times the whole gallery built by one process, split by artefact, and
//! the frames of an animation: `cargo run --release --example gallery_time
//! [ROUNDS]` (default 5) prints the median over the rounds of each part
//! and its share of the whole (docs/benchmarks.md).
//!
//! The gallery makes its files on every core, so the time between two
//! files it hands over says nothing of what either cost. The split is
//! therefore taken on one thread, piece by piece, as the gallery makes
//! them: each figure's model and SVG text, then each of its other formats
//! from that SVG, each table, the index. The whole gallery (every core)
//! is timed as [`Gallery::build`] runs it.

use slider_crank::catalogue::FigureOptions;
use slider_crank::gallery::Gallery;
use slider_crank::render::{FileFormat, TikzOptions, to_svg, to_tikz};
use slider_crank::table::TableName;
use slider_crank::{Angle, FigureName, Layer};
use std::collections::BTreeMap;
use std::time::{Duration, Instant};

/// One build of the whole gallery, on every core: its wall time.
fn gallery_round() -> Duration {
    let start = Instant::now();
    Gallery::new()
        .build(|file| {
            std::hint::black_box(&file.bytes);
            Ok(())
        })
        .expect("the gallery builds");
    start.elapsed()
}

/// The gallery's pieces made one after the other on this thread: the
/// time spent on each kind.
fn split_round() -> BTreeMap<&'static str, Duration> {
    let mut spent: BTreeMap<&'static str, Duration> = BTreeMap::new();
    let gallery = Gallery::new();
    for &figure in gallery.figures() {
        let start = Instant::now();
        let drawn = figure.figure(&FigureOptions::default()).expect("a figure");
        *spent.entry("figure model").or_default() += start.elapsed();
        let start = Instant::now();
        let svg = to_svg(&drawn);
        *spent.entry("SVG (layout and text)").or_default() += start.elapsed();
        let start = Instant::now();
        std::hint::black_box(to_tikz(&drawn, &TikzOptions::default()));
        *spent.entry("TikZ (layout and text)").or_default() += start.elapsed();
        for &format in gallery.formats() {
            let name = match format {
                FileFormat::Svg | FileFormat::Tikz => continue,
                FileFormat::Png => "PNG",
                FileFormat::Pdf => "PDF",
            };
            let start = Instant::now();
            std::hint::black_box(format.encode(&drawn, &svg).expect("encodes"));
            *spent.entry(name).or_default() += start.elapsed();
        }
    }
    for table in TableName::ALL {
        let start = Instant::now();
        std::hint::black_box(table.table().expect("a table"));
        *spent.entry("tables").or_default() += start.elapsed();
    }
    spent
}

/// One revolution of Fig. 67 in 72 frames held in one view: the time per
/// frame, the fit over the revolution included.
fn animation_round() -> Duration {
    let scene = FigureName::Fig67Example
        .scene()
        .expect("a mechanism figure")
        .with_layers(Layer::ALL);
    let angles: Vec<Angle> = (0..72).map(|k| Angle::deg(5.0 * f64::from(k))).collect();
    let start = Instant::now();
    let frames = scene.frames(&angles).expect("the frames build");
    let svg: usize = frames
        .iter()
        .map(|f| slider_crank::render::to_svg(f).len())
        .sum();
    std::hint::black_box(svg);
    start.elapsed() / 72
}

fn median(mut v: Vec<Duration>) -> Duration {
    v.sort();
    v[v.len() / 2]
}

fn main() {
    let rounds: usize = std::env::args()
        .nth(1)
        .map(|a| a.parse().expect("ROUNDS is a count"))
        .unwrap_or(5)
        .max(1);
    let mut by_kind: BTreeMap<&'static str, Vec<Duration>> = BTreeMap::new();
    let mut wholes = Vec::new();
    let mut ones = Vec::new();
    for _ in 0..rounds {
        wholes.push(gallery_round());
        let spent = split_round();
        ones.push(spent.values().sum());
        for (k, d) in spent {
            by_kind.entry(k).or_default().push(d);
        }
    }
    let total = median(wholes);
    let one = median(ones);
    println!("whole gallery on every core, median of {rounds}: {total:.2?}");
    println!("its pieces one after the other on one thread: {one:.2?}");
    for (k, v) in by_kind {
        let m = median(v);
        println!(
            "  {k:<22} {m:>10.2?}  {:>5.1} %",
            100.0 * m.as_secs_f64() / one.as_secs_f64()
        );
    }
    let frame = median((0..rounds).map(|_| animation_round()).collect());
    println!(
        "animation frame (Fig. 67, every layer, 72 frames in one held view): {frame:.2?}, {:.1} % of the gallery",
        100.0 * frame.as_secs_f64() / total.as_secs_f64()
    );
}
