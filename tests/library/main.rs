//! The suites that need the library alone (`cargo test
//! --no-default-features` builds and runs them): the numbers, the
//! constructions and curves against the exact formulas, the figures read
//! back from their SVG, scene files, tables, and the repository's own text
//! (layering, no panic on input, references). One test binary, one module
//! per suite; the shared helpers are modules of it.

// Each crate uses a part of the shared helpers.
#[allow(dead_code)]
#[path = "../common/mod.rs"]
mod common;
#[path = "../common/hostile.rs"]
mod hostile;

mod analytic;
mod chain;
mod constructions;
mod coriolis;
mod curves;
mod dynamics;
mod dynamics_figures;
mod dynamics_guide;
mod flag_free;
mod fuzz_twins;
mod ignored;
mod layering;
mod panic_free;
mod polygon_letters;
mod polygons;
mod python_build;
mod quick_return;
mod reading_json;
mod references;
mod ritterhaus_bennett;
mod scene_format;
mod scenes;
mod seeds;
mod table_snapshots;
mod worked_examples;
// reads the bundled faces' glyphs (skrifa)
#[cfg(feature = "fonts")]
mod typography;
