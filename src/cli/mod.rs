//! The subcommands of the `slider-crank` program.

pub mod analyze;
pub mod animate;
pub mod args;
pub mod chain;
pub mod check;
pub mod dynamics;
#[cfg(feature = "explore")]
pub mod explore;
pub mod figure;
pub mod flags;
pub mod gallery;
pub mod handout;
pub mod output;
pub mod scene;
pub mod stream;
pub mod table;
