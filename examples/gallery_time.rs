//! Times the whole gallery built by one process, split by artefact, and
//! the frames of an animation: `cargo run --release --example gallery_time
//! [ROUNDS]` (default 5) prints the median over the rounds of each part
//! and its share of the whole (docs/benchmarks.md).
//!
//! Each file the gallery hands over is charged with the time since the
//! previous one: a figure's SVG carries the building of its model and its
//! SVG text, its PNG and PDF the conversion of that SVG, each table its
//! computation and text, `index.html` its page.

use slider_crank::gallery::Gallery;
use slider_crank::{Angle, FigureName, Layer};
use std::collections::BTreeMap;
use std::time::{Duration, Instant};

/// The kind of a gallery file, by its name.
fn kind(name: &str) -> &'static str {
    match name.rsplit('.').next() {
        Some("svg") => "SVG (model and text)",
        Some("png") => "PNG",
        Some("pdf") => "PDF",
        Some("html") => "HTML (index)",
        _ => "tables",
    }
}

/// One build of the whole gallery: the time charged to each kind.
fn gallery_round() -> BTreeMap<&'static str, Duration> {
    let mut spent = BTreeMap::new();
    let mut last = Instant::now();
    Gallery::new()
        .build(|file| {
            let now = Instant::now();
            *spent.entry(kind(&file.name)).or_default() += now - last;
            std::hint::black_box(&file.bytes);
            last = Instant::now();
            Ok(())
        })
        .expect("the gallery builds");
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
    let mut totals = Vec::new();
    for _ in 0..rounds {
        let spent = gallery_round();
        totals.push(spent.values().sum());
        for (k, d) in spent {
            by_kind.entry(k).or_default().push(d);
        }
    }
    let total = median(totals);
    println!("whole gallery, median of {rounds}: {total:.2?}");
    for (k, v) in by_kind {
        let m = median(v);
        println!(
            "  {k:<22} {m:>10.2?}  {:>5.1} %",
            100.0 * m.as_secs_f64() / total.as_secs_f64()
        );
    }
    let frame = median((0..rounds).map(|_| animation_round()).collect());
    println!(
        "animation frame (Fig. 67, every layer, 72 frames in one held view): {frame:.2?}, {:.1} % of the gallery",
        100.0 * frame.as_secs_f64() / total.as_secs_f64()
    );
}
