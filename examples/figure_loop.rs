//! Builds one seed figure and writes its SVG `N` times: a fixed amount of
//! work whose instruction count (under `valgrind --tool=cachegrind`) does
//! not depend on what else the machine runs, unlike wall-clock medians.
//!
//! ```sh
//! cargo build --release --example figure_loop
//! valgrind --tool=cachegrind --cache-sim=no target/release/examples/figure_loop fig-67-example 11
//! ```
//!
//! The difference between 11 and 1 repetitions, divided by 10, is the
//! count of one figure without the start-up (font parsing).

use slider_crank::FigureName;
use slider_crank::render::to_svg;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let (Some(name), Some(n)) = (
        args.get(1),
        args.get(2).and_then(|n| n.parse::<usize>().ok()),
    ) else {
        eprintln!("usage: figure_loop NAME REPETITIONS");
        std::process::exit(2);
    };
    let Some(figure) = FigureName::SCENES.iter().find(|f| f.name() == name) else {
        eprintln!("figure_loop: not a mechanism figure: {name}");
        std::process::exit(2);
    };
    let scene = figure.scene().expect("a seed figure builds");
    let mut bytes = 0;
    for _ in 0..n {
        bytes += to_svg(
            &std::hint::black_box(&scene)
                .figure()
                .expect("a seed figure builds"),
        )
        .len();
    }
    println!("{bytes} bytes written");
}
