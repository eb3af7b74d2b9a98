//! The catalogue of the seeds' named figures, with their own parameters,
//! and the scene files that start from them: mechanism figures drawn by a
//! [`Scene`](crate::scene::Scene), and diagrams (plots against θ, time or
//! position, polar diagrams, centrodes, Ng's graphs, the chain's figures).
//!
//! It sits above the scenes and the diagrams it builds from, and below the
//! gallery and the command line that name its figures.

pub(crate) mod builders;
mod name;
mod options;
mod parse;
mod request;
mod scene_file;
mod scene_toml;
mod source;
mod specs;

pub(crate) use options::Setting;
pub use options::{FigureOptions, Fit};
#[cfg(feature = "html")]
pub(crate) use parse::{located, toml_error};
pub use request::{FigureRequest, crank_speed};
pub use scene_file::SceneFile;
pub use specs::{FigureName, Group};
