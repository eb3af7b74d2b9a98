//! How the command line writes the fields the library's messages name:
//! as its flags (`--gas-force`, `--bore D`).

use slider_crank::{Error, Field, Spelling};

/// The command line's spelling: a field's key with hyphens for its
/// underscores, after two hyphens (`--max-cells`); set to a value, the
/// value after a space (`--max-cells 50000000`).
pub struct Flags;

impl Spelling for Flags {
    fn option(&self, field: Field) -> String {
        format!("--{}", field.key().replace('_', "-"))
    }

    fn set(&self, field: Field, value: &str) -> String {
        format!("{} {value}", self.option(field))
    }
}

/// `e` as the command line prints it: its fields spelled as flags, one
/// line.
pub fn said(e: Error) -> Error {
    e.spelled(&Flags).one_line()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fields_are_written_as_flags() {
        assert_eq!(Flags.option(Field::GasForce), "--gas-force");
        assert_eq!(Flags.option(Field::Data), "--data");
        assert_eq!(Flags.set(Field::MaxCells, "5"), "--max-cells 5");
        assert_eq!(Flags.option(Field::Ratio), "--n");
    }
}
