//! The figures rendered (feature `png`): the seeds' figures and the
//! diagrams against their reviewed snapshots and the exact curves, the
//! plate check over a sweep of poses, and single layouts read back through
//! usvg. One test binary, one module per suite; the shared helpers are
//! modules of it.

// Each crate uses a part of the shared helpers.
#[allow(dead_code)]
#[path = "../common/mod.rs"]
mod common;
#[allow(dead_code)]
#[path = "../common/plate.rs"]
mod plate;
#[path = "../common/worked_engine.rs"]
mod worked_engine;

mod angle_letters;
mod chain_figures;
mod detail_review;
mod diagrams;
mod dynamics_marks;
mod figure_layout;
mod figure_texts;
mod figures;
mod inversion_figures;
mod mechanism_review;
mod plates;
mod polygon_figures;
mod quick_return_figures;
