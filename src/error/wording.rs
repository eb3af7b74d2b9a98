//! A message that names a request's fields, each front end writing them
//! its own way: the command line as its flags, the Python package as its
//! keywords, a scene file as its keys. The library never writes a flag.

use super::Field;

/// How a front end writes the fields a [`Wording`] names. The library's
/// own is [`Keys`]; the command line and the Python package each have
/// theirs, so that a refusal made once in the library names what its
/// user typed.
pub trait Spelling {
    /// The field as an option the user gives (the field [`Field::Data`]:
    /// `data` in a scene file, `data=` in Python).
    fn option(&self, field: Field) -> String;
    /// The field given the value `value` (`bore = D` in a scene file,
    /// `bore=D` in Python).
    fn set(&self, field: Field, value: &str) -> String;
}

/// The library's spelling: a field by its key ([`Field::key`]) in
/// backquotes, as a scene file's messages write it (`` `gas_force` ``,
/// `` `bore = D` ``). It is how a [`Wording`] displays unspelled.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Keys;

impl Spelling for Keys {
    fn option(&self, field: Field) -> String {
        format!("`{}`", field.key())
    }

    fn set(&self, field: Field, value: &str) -> String {
        format!("`{} = {value}`", field.key())
    }
}

/// One piece of a [`Wording`].
#[derive(Debug, Clone, PartialEq)]
enum Piece {
    /// Text written as it is.
    Text(String),
    /// A field named as an option.
    Option(Field),
    /// A field named with a value (`D`, `50000000`).
    Set(Field, String),
}

/// The text of a message with the request's fields in it, written by a
/// [`Spelling`] ([`Wording::spelled`]); its `Display` is the library's
/// own, [`Keys`]. A wording of text alone (every message that names no
/// field, the empty one among them) reads the same in every spelling.
///
/// ```
/// use slider_crank::{Field, Keys, Wording};
/// let w = Wording::from("give ").set(Field::Bore, "D").then(" with ").option(Field::Data);
/// assert_eq!(w.to_string(), "give `bore = D` with `data`");
/// assert_eq!(w.spelled(&Keys), w.to_string());
/// ```
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Wording(Vec<Piece>);

impl Wording {
    /// The wording with `text` after it.
    pub fn then(mut self, text: impl Into<String>) -> Self {
        self.0.push(Piece::Text(text.into()));
        self
    }

    /// The wording with the option `field` after it (`data=` in Python).
    pub fn option(mut self, field: Field) -> Self {
        self.0.push(Piece::Option(field));
        self
    }

    /// The wording with `field` set to `value` after it (`bore=D` in
    /// Python).
    pub fn set(mut self, field: Field, value: impl std::fmt::Display) -> Self {
        self.0.push(Piece::Set(field, value.to_string()));
        self
    }

    /// The wording with `other`'s pieces after its own.
    pub fn and(mut self, other: Wording) -> Self {
        self.0.extend(other.0);
        self
    }

    /// The fields the wording names, in order (none for plain text).
    pub fn fields(&self) -> impl Iterator<Item = Field> + '_ {
        self.0.iter().filter_map(|p| match p {
            Piece::Text(_) => None,
            Piece::Option(f) | Piece::Set(f, _) => Some(*f),
        })
    }

    /// The text as `spelling` writes its fields.
    pub fn spelled(&self, spelling: &dyn Spelling) -> String {
        self.0
            .iter()
            .map(|p| match p {
                Piece::Text(t) => t.clone(),
                Piece::Option(f) => spelling.option(*f),
                Piece::Set(f, v) => spelling.set(*f, v),
            })
            .collect()
    }

    /// The wording with each text and value passed through `f` (the
    /// fields' names are the library's own and need nothing).
    pub(crate) fn map_text(self, f: impl Fn(&str) -> String) -> Self {
        Wording(
            self.0
                .into_iter()
                .map(|p| match p {
                    Piece::Text(t) => Piece::Text(f(&t)),
                    Piece::Set(field, v) => Piece::Set(field, f(&v)),
                    option => option,
                })
                .collect(),
        )
    }
}

impl From<String> for Wording {
    fn from(text: String) -> Self {
        Wording(vec![Piece::Text(text)])
    }
}

impl From<&str> for Wording {
    fn from(text: &str) -> Self {
        Wording::from(text.to_string())
    }
}

impl std::fmt::Display for Wording {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.spelled(&Keys))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A spelling made up here: each field in brackets, a value after a
    /// colon.
    struct Brackets;

    impl Spelling for Brackets {
        fn option(&self, field: Field) -> String {
            format!("[{}]", field.key())
        }
        fn set(&self, field: Field, value: &str) -> String {
            format!("[{}:{value}]", field.key())
        }
    }

    #[test]
    fn each_spelling_writes_the_fields_its_way() {
        let w = Wording::from("give ")
            .set(Field::MaxCells, 5)
            .then(" or ")
            .option(Field::GasForce);
        assert_eq!(w.to_string(), "give `max_cells = 5` or `gas_force`");
        assert_eq!(w.spelled(&Brackets), "give [max_cells:5] or [gas_force]");
        assert_eq!(
            w.fields().collect::<Vec<_>>(),
            [Field::MaxCells, Field::GasForce]
        );
        let plain = Wording::from("no field");
        assert_eq!(plain.spelled(&Brackets), "no field");
        assert_eq!(plain.fields().count(), 0);
        assert_eq!(Wording::default().to_string(), "");
    }
}
