//! The `slider-crank` program run as a user runs it (feature `cli`): its
//! commands, files and errors, the gallery, handouts and animations, PDF
//! output, the robustness table, other processes, and the teaching pages in
//! a browser. One test binary, one module per suite; a suite that needs
//! more than `cli` is compiled only with those features (the gates below),
//! so `--no-default-features --features cli` still runs the rest.

// Each crate uses a part of the shared helpers.
#[allow(dead_code)]
#[path = "../command/mod.rs"]
mod command;
#[allow(dead_code)]
#[path = "../common/mod.rs"]
mod common;
#[allow(dead_code)]
#[path = "../common/hostile.rs"]
mod hostile;
#[allow(dead_code)]
#[cfg(feature = "png")]
#[path = "../common/plate.rs"]
mod plate;
#[path = "../common/worked_engine.rs"]
mod worked_engine;

mod handout;
mod handout_dynamics;
mod options_table;

// PNG output (`--out x.png`, the gallery's PNGs) or resvg in the test
#[cfg(feature = "png")]
mod animate;
#[cfg(feature = "png")]
mod browser;
#[cfg(feature = "png")]
mod cli;
#[cfg(feature = "png")]
mod cli_figures;
// the explorer's server (and, ignored, its page in Chromium)
#[cfg(all(feature = "explore", feature = "png"))]
mod devtools;
#[cfg(feature = "explore")]
mod explore;
#[cfg(feature = "png")]
mod fonts;
#[cfg(feature = "png")]
mod odd_text;
#[cfg(feature = "png")]
mod robustness;

// PDF output
#[cfg(all(feature = "png", feature = "pdf"))]
mod gallery;
#[cfg(feature = "pdf")]
mod pdf;
// TikZ compiled by LaTeX, compared with the PDF
#[cfg(feature = "pdf")]
mod tikz;
// two galleries at once and a gallery interrupted by SIGINT
#[cfg(all(feature = "png", feature = "pdf"))]
mod processes;
