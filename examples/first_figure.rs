//! The first figure of a process against the steady state: builds one
//! figure and writes its SVG `N` times in a fresh process, and prints the
//! time of the first and the median of the others (docs/benchmarks.md).
//! Whatever the first figure pays once (fonts, tables) shows as the
//! difference.
//!
//! ```sh
//! cargo run --release --example first_figure [NAME] [N]
//! ```

use slider_crank::FigureName;
use slider_crank::catalogue::FigureOptions;
use slider_crank::render::to_svg;
use std::time::{Duration, Instant};

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let name = args.get(1).map_or("fig-67-example", String::as_str);
    let n: usize = args
        .get(2)
        .map(|n| n.parse().expect("N is a count"))
        .unwrap_or(200)
        .max(2);
    let Some(figure) = FigureName::ALL.iter().find(|f| f.name() == name) else {
        eprintln!("first_figure: no figure named {name}");
        std::process::exit(2);
    };
    let mut times: Vec<Duration> = Vec::with_capacity(n);
    let mut bytes = 0;
    for _ in 0..n {
        let start = Instant::now();
        let f = figure
            .figure(std::hint::black_box(&FigureOptions::default()))
            .expect("a named figure builds");
        bytes += to_svg(&f).len();
        times.push(start.elapsed());
    }
    let first = times[0];
    let mut rest = times[1..].to_vec();
    rest.sort();
    println!(
        "{name}: first figure {first:.2?}, then median {:.2?} over {} ({bytes} bytes)",
        rest[rest.len() / 2],
        n - 1
    );
}
