//! How a caller spells an option in a message: the command line's flag
//! (`--gas-force`) or the Python package's keyword (`gas_force=`), so that
//! a refusal made once in the library names what its user typed.

/// How the user names an option, for the message that refuses a request.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[non_exhaustive]
pub enum Spelling {
    /// The command line's flags: `--max-cells 50000000`, `--gas-force`.
    #[default]
    Flag,
    /// The Python package's keywords: `max_cells=50000000`, `gas_force=`.
    Keyword,
}

impl Spelling {
    /// The option named `name` in the command line's words (`gas-force`),
    /// as the user writes it: `--gas-force` or `gas_force=`.
    pub fn option(self, name: &str) -> String {
        match self {
            Spelling::Flag => format!("--{name}"),
            Spelling::Keyword => format!("{}=", name.replace('-', "_")),
        }
    }

    /// The option `name` set to `value`: `--bore D` or `bore=D`.
    pub fn set(self, name: &str, value: impl std::fmt::Display) -> String {
        match self {
            Spelling::Flag => format!("--{name} {value}"),
            Spelling::Keyword => format!("{}{value}", self.option(name)),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn flags_and_keywords() {
        assert_eq!(Spelling::Flag.option("gas-force"), "--gas-force");
        assert_eq!(Spelling::Keyword.option("gas-force"), "gas_force=");
        assert_eq!(Spelling::Flag.set("max-cells", 5), "--max-cells 5");
        assert_eq!(Spelling::Keyword.set("max-cells", 5), "max_cells=5");
    }
}
