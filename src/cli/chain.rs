//! The chain of Fig. 60 on the command line: the flags `--slot-radius`,
//! `--links`, `--inversion` of `analyze` and `check` (each checked and
//! run by the library's request of its command).

use clap::{Args, ValueEnum};
use serde_json::Value;
use slider_crank::{Assembly, Error, Input, Result};

/// The chain flags shared by `analyze` and `check`.
#[derive(Debug, Clone, Args)]
pub struct ChainArgs {
    /// Put the block in a circular slot of radius ρ (Fig. 60 b), in the
    /// length unit: its centre O_cd is at (0, e − ρ), below the stroke for
    /// ρ > 0, above it for ρ < 0; |ρ| must exceed (l + r + e)/2 for ρ > 0,
    /// (l + r − e)/2 for ρ < 0
    #[arg(
        long,
        allow_hyphen_values = true,
        value_name = "RHO",
        conflicts_with_all = ["links", "inversion"]
    )]
    pub slot_radius: Option<f64>,
    /// A quadric crank chain instead of the engine (Fig. 60 a): the lengths
    /// of crank a, coupler b, lever c and frame d, comma-separated (in place
    /// of --crank, --rod and --offset)
    #[arg(
        long,
        allow_hyphen_values = true,
        value_name = "A,B,C,D",
        conflicts_with_all = ["inversion", "crank", "rod", "offset"]
    )]
    pub links: Option<String>,
    /// Assembly mode of the quadric chain (with --links)
    #[arg(long, value_enum, default_value_t = AssemblyArg::Open, requires = "links")]
    pub assembly: AssemblyArg,
    /// Fix another link of the slider-crank chain: 1 frame d (the engine),
    /// 2 crank a, 3 rod b, 4 slider c; --angle is then the crank's angle
    /// against the frame and --rpm or --omega the speed of the driving link
    #[arg(long, value_name = "N")]
    pub inversion: Option<u32>,
}

/// A request's chain fields: slot radius, links, assembly, inversion.
pub type ChainFields = (Option<f64>, Option<[f64; 4]>, Option<Assembly>, Option<u32>);

/// The assembly mode flag.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum AssemblyArg {
    /// A to the left of the diagonal from B to O_cd
    Open,
    /// A to the right of the diagonal from B to O_cd
    Crossed,
}

impl ChainArgs {
    /// The four lengths `--links` gives, `None` without it.
    fn links(&self) -> Result<Option<[f64; 4]>> {
        let Some(spec) = &self.links else {
            return Ok(None);
        };
        let v = super::args::parse_list(spec, "link length", false)?;
        match v[..] {
            [a, b, c, d] => Ok(Some([a, b, c, d])),
            _ => Err(Error::invalid(
                Input::Links,
                format!(
                    "invalid --links '{spec}': expected four lengths a,b,c,d (crank, coupler, lever, frame)"
                ),
            )),
        }
    }

    /// The chain fields of a request (`analyze`'s, `check`'s): the slot
    /// radius, the four links, their assembly (with `--links` only) and
    /// the inversion, each `None` where not given.
    pub fn fields(&self) -> Result<ChainFields> {
        let assembly = self.links.as_ref().map(|_| self.assembly());
        Ok((self.slot_radius, self.links()?, assembly, self.inversion))
    }

    /// The assembly mode `--assembly` names.
    fn assembly(&self) -> Assembly {
        match self.assembly {
            AssemblyArg::Open => Assembly::Open,
            AssemblyArg::Crossed => Assembly::Crossed,
        }
    }
}

/// One `key.sub = value` line per number, for the text output.
pub fn flatten(prefix: &str, v: &Value, out: &mut String) {
    match v {
        Value::Object(map) => {
            for (k, x) in map {
                let key = if prefix.is_empty() {
                    k.clone()
                } else {
                    format!("{prefix}.{k}")
                };
                flatten(&key, x, out);
            }
        }
        other => out.push_str(&format!("{prefix:<44} {other}\n")),
    }
}
