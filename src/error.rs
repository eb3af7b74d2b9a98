//! The crate's one error type.

use std::path::PathBuf;
use std::sync::Arc;
use thiserror::Error;

mod field;
mod input;
mod wording;

pub use field::Field;
pub use input::Input;
pub use wording::{Keys, Spelling, Wording};

/// Everything that can go wrong at the boundary of the crate: bad numbers,
/// a mechanism that cannot be assembled, a malformed request.
///
/// Each message names the offending value and what would be needed instead,
/// so that the command line can print it as one line on standard error.
///
/// Two errors are equal when their variants and fields are; the operating
/// system's errors of two [`Error::Io`] are compared by their kind.
#[derive(Debug, Clone, Error)]
#[non_exhaustive]
pub enum Error {
    /// A parameter is NaN or infinite.
    #[error("{name} must be a finite number, got {}", Num(*.value))]
    NotFinite {
        /// Which parameter (for example [`Field::Crank`]).
        name: Field,
        /// The value given.
        value: f64,
    },
    /// A length or other parameter that must be positive is zero or negative.
    #[error("{name} must be greater than zero, got {}", Num(*.value))]
    NotPositive {
        /// Which parameter.
        name: Field,
        /// The value given.
        value: f64,
    },
    /// A parameter that must not be negative is negative.
    #[error("{name} must not be negative, got {}", Num(*.value))]
    Negative {
        /// Which parameter.
        name: Field,
        /// The value given.
        value: f64,
    },
    /// The connecting rod is too short for the crank to turn a full revolution.
    #[error(
        "rod {} is too short for crank {} and offset {}: the crank turns fully only when rod > crank + |offset| = {}",
        Num(*.rod), Num(*.crank), Num(*.offset), Num(*.needed)
    )]
    RodTooShort {
        /// Crank radius given.
        crank: f64,
        /// Rod length given.
        rod: f64,
        /// Offset of the line of stroke given.
        offset: f64,
        /// The bound the rod must exceed, crank + |offset|.
        needed: f64,
    },
    /// A value that is outside the range a computation accepts.
    #[error("{name} = {} is out of range: {reason}", Num(*.value))]
    OutOfRange {
        /// Which parameter.
        name: Field,
        /// The value given.
        value: f64,
        /// What the range is.
        reason: String,
    },
    /// Input that could not be understood (an angle range, a unit's name,
    /// a scene file, the data file, options that do not go together).
    #[error("{message}")]
    Invalid {
        /// What kind of input it was (the data file, a scene file).
        input: Input,
        /// What was wrong, as printed (`unknown layer 'x': expected one
        /// of …`); it names the input where the user needs to be told,
        /// and the request's fields as [`Field`]s, which each front end
        /// writes its own way ([`Error::spelled`]).
        message: Wording,
    },
    /// Reading or writing failed (a file, standard output, the PNG
    /// encoder). The message is the whole of what is shown: it names the
    /// file and quotes the cause; the cause itself is kept as the error's
    /// [`source`](std::error::Error::source) when the operating system
    /// gave one.
    #[error("{message}")]
    Io {
        /// What failed, as printed (`cannot write out.svg: Permission
        /// denied (os error 13)`).
        message: String,
        /// The file read or written, when there is one.
        path: Option<PathBuf>,
        /// The operating system's error, when one caused the failure
        /// (shared, so that the error stays `Clone`).
        #[source]
        source: Option<Arc<std::io::Error>>,
    },
    /// A computation reached one of its limits (the evaluations, halvings
    /// or segments of a curve); the message says what can be changed.
    #[error("{0}")]
    Limit(String),
    /// Something this build of the crate leaves out (PNG output without
    /// the `png` feature); the message names the feature.
    #[error("{0}")]
    Unsupported(String),
}

impl Error {
    /// An [`Error::Invalid`] about `input`; `message` is what is printed.
    pub fn invalid(input: Input, message: String) -> Self {
        Error::refused(input, Wording::from(message))
    }

    /// An [`Error::Invalid`] about `input` whose `message` names the
    /// request's fields, each front end writing them its own way.
    pub fn refused(input: Input, message: Wording) -> Self {
        Error::Invalid { input, message }
    }

    /// The same error with the fields its message names written by
    /// `spelling` (the command line's flags, the Python package's
    /// keywords), so that it prints as its user typed them; an error
    /// that names no field is unchanged. Its `Display` without this is
    /// the library's own spelling, [`Keys`].
    pub fn spelled(self, spelling: &dyn Spelling) -> Self {
        match self {
            Error::Invalid { input, message } => Error::invalid(input, message.spelled(spelling)),
            e => e,
        }
    }

    /// The same error said to be about `input` when it is an
    /// [`Error::Invalid`] (an indicator diagram read as a figure's data
    /// file is the data file); any other error unchanged.
    pub(crate) fn about(self, input: Input) -> Self {
        match self {
            Error::Invalid { message, .. } => Error::Invalid { input, message },
            e => e,
        }
    }

    /// The same error with `path` before its message when it is an
    /// [`Error::Invalid`] about `input`, so that a message about the data
    /// file names the file (`runs.csv: data line 3: …`); any other error
    /// unchanged (one about the angle, or the line fit through the data).
    pub fn in_file(self, input: Input, path: &std::path::Path) -> Self {
        match self {
            Error::Invalid { input: i, message } if i == input => Error::refused(
                input,
                Wording::from(format!("{}: ", path.display())).and(message),
            ),
            e => e,
        }
    }

    /// An [`Error::Io`] about `path` with the operating system's `source`;
    /// `message` is what is printed.
    pub fn io_at(message: String, path: &std::path::Path, source: std::io::Error) -> Self {
        Error::Io {
            message,
            path: Some(path.to_path_buf()),
            source: Some(Arc::new(source)),
        }
    }

    /// An [`Error::Io`] about `path` without an operating-system cause
    /// (a path that exists but is the wrong kind of file).
    pub fn io_about(message: String, path: &std::path::Path) -> Self {
        Error::Io {
            message,
            path: Some(path.to_path_buf()),
            source: None,
        }
    }

    /// Most characters of a user's value quoted by [`Error::show`].
    pub const MAX_SHOWN_CHARS: usize = 60;

    /// Most characters of a message's text after [`Error::one_line`].
    pub const MAX_MESSAGE_CHARS: usize = 1000;

    /// A value given by a user as a message quotes it: its control
    /// characters, bidirectional controls (U+202E, which would reverse the
    /// rest of the line on a terminal) and non-characters written as
    /// escapes (`\r`, `\u{202e}`), and cut to [`Error::MAX_SHOWN_CHARS`]
    /// characters with `…` after (a 100 KB title is not echoed whole). The
    /// empty value stays empty.
    pub fn show(value: &str) -> String {
        let mut shown = escape_controls(value);
        if shown.chars().count() > Error::MAX_SHOWN_CHARS {
            shown = shown.chars().take(Error::MAX_SHOWN_CHARS).collect();
            shown.push('…');
        }
        shown
    }

    /// `text` (a path, a file's or a scene's name) as the program prints it
    /// on a terminal or writes it into a page: every control character
    /// (an escape sequence's ESC, a carriage return), bidirectional
    /// control, non-character and invisible character written as a Rust
    /// escape (`\u{1b}`, `\r`, `\u{202e}`), the rest as it is; a text
    /// of printable characters (the empty text among them) is unchanged.
    /// The one function through which every path and name a user gave
    /// reaches standard error, standard output or the gallery's page.
    pub fn printable(text: &str) -> String {
        let mut out = String::with_capacity(text.len());
        for c in text.chars() {
            if is_unprintable(c) {
                out.extend(c.escape_default());
            } else {
                out.push(c);
            }
        }
        out
    }

    /// The same error with every control character of its texts (a
    /// newline or carriage return quoted from a user's file), and every
    /// bidirectional control and non-character, written as an escape
    /// (`\n`, `\u{202e}`), so that the message is one line and reads as
    /// printed; a text longer than [`Error::MAX_MESSAGE_CHARS`] characters is
    /// cut there, with `…` (a message that names fields, each of its
    /// texts: spell it first, [`Error::spelled`], to cut the whole).
    pub fn one_line(self) -> Self {
        match self {
            Error::OutOfRange {
                name,
                value,
                reason,
            } => Error::OutOfRange {
                name,
                value,
                reason: escape_controls(&reason),
            },
            Error::Invalid { input, message } => Error::Invalid {
                input,
                message: message.map_text(escape_controls),
            },
            Error::Io {
                message,
                path,
                source,
            } => Error::Io {
                message: escape_controls(&message),
                path,
                source,
            },
            Error::Limit(m) => Error::Limit(escape_controls(&m)),
            e => e,
        }
    }
}

impl PartialEq for Error {
    fn eq(&self, other: &Self) -> bool {
        use Error::*;
        match (self, other) {
            (NotFinite { name: a, value: x }, NotFinite { name: b, value: y })
            | (NotPositive { name: a, value: x }, NotPositive { name: b, value: y })
            | (Negative { name: a, value: x }, Negative { name: b, value: y }) => a == b && x == y,
            (
                RodTooShort {
                    crank,
                    rod,
                    offset,
                    needed,
                },
                RodTooShort {
                    crank: c,
                    rod: r,
                    offset: o,
                    needed: n,
                },
            ) => crank == c && rod == r && offset == o && needed == n,
            (
                OutOfRange {
                    name,
                    value,
                    reason,
                },
                OutOfRange {
                    name: n,
                    value: v,
                    reason: r,
                },
            ) => name == n && value == v && reason == r,
            (
                Invalid { input, message },
                Invalid {
                    input: i,
                    message: m,
                },
            ) => input == i && message == m,
            (Limit(a), Limit(b)) | (Unsupported(a), Unsupported(b)) => a == b,
            (
                Io {
                    message,
                    path,
                    source,
                },
                Io {
                    message: m,
                    path: p,
                    source: s,
                },
            ) => {
                message == m
                    && path == p
                    && source.as_ref().map(|e| e.kind()) == s.as_ref().map(|e| e.kind())
            }
            _ => false,
        }
    }
}

/// `text` with control characters (`\n`, `\r`, `\u{1b}`), bidirectional
/// controls and non-characters escaped, cut to [`Error::MAX_MESSAGE_CHARS`].
fn escape_controls(text: &str) -> String {
    match text.char_indices().nth(Error::MAX_MESSAGE_CHARS) {
        Some((cut, _)) => Error::printable(text.get(..cut).unwrap_or(text)) + "…",
        None => Error::printable(text),
    }
}

/// Whether `c` is printed as an escape by [`Error::printable`].
fn is_unprintable(c: char) -> bool {
    c.is_control() || is_bidi_control(c) || is_noncharacter(c) || is_invisible(c)
}

/// The characters that reorder the text after them on a terminal: the
/// embeddings, overrides and isolates of Unicode's bidirectional
/// algorithm, and its marks.
fn is_bidi_control(c: char) -> bool {
    matches!(c, '\u{061C}' | '\u{200E}' | '\u{200F}' | '\u{202A}'..='\u{202E}' | '\u{2066}'..='\u{2069}')
}

/// The characters that print nothing and hide where text begins or
/// breaks: the zero-width space, non-joiner and joiner, the word joiner
/// and the byte-order mark (a zero-width no-break space inside text).
fn is_invisible(c: char) -> bool {
    matches!(c, '\u{200B}'..='\u{200D}' | '\u{2060}' | '\u{FEFF}')
}

/// What makes `text`, a text a user gives (a unit, a title, a name, a
/// field of a data file), unfit to be written into a figure, a page or a
/// table, or `None` when it is fit: a control character (line breaks
/// included: such a text is one line), a non-character
/// ([`is_noncharacter`]: not text, and U+FFFE and U+FFFF are not even
/// allowed in XML), a bidirectional control (U+202E and its kin reorder
/// what follows them) or an invisible character (U+200B, U+FEFF: a text
/// that looks like another). The one rule every front end's text passes;
/// each caller words the error its own way around the reason returned,
/// such as "it holds the bidirectional control U+202E".
pub fn text_fault(text: &str) -> Option<String> {
    let c = text.chars().find(|&c| is_unprintable(c))?;
    let code = u32::from(c);
    Some(if c.is_control() {
        "it holds a control character (such a text is one line of printable characters)".into()
    } else if is_noncharacter(c) {
        format!("it holds the non-character U+{code:04X} (not text, and not allowed in SVG)")
    } else if is_bidi_control(c) {
        format!("it holds the bidirectional control U+{code:04X}, which reorders the text after it")
    } else {
        format!("it holds the invisible character U+{code:04X}")
    })
}

/// A number as a message shows it: plainly in the usual range, in
/// exponent form when very large or very small (no 100-digit integers).
struct Num(f64);

impl std::fmt::Display for Num {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&crate::number::plain(self.0))
    }
}

/// The crate's result type.
pub type Result<T> = std::result::Result<T, Error>;

/// Checks that `value` is finite, naming it in the error otherwise.
pub(crate) fn finite(name: Field, value: f64) -> Result<f64> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(Error::NotFinite { name, value })
    }
}

/// Checks that `value` is finite and strictly positive.
pub(crate) fn positive(name: Field, value: f64) -> Result<f64> {
    let value = finite(name, value)?;
    if value > 0.0 {
        Ok(value)
    } else {
        Err(Error::NotPositive { name, value })
    }
}

/// Checks that `value` is finite and not negative.
pub(crate) fn non_negative(name: Field, value: f64) -> Result<f64> {
    let value = finite(name, value)?;
    if value >= 0.0 {
        Ok(value)
    } else {
        Err(Error::Negative { name, value })
    }
}

/// Whether `c` is one of Unicode's 66 non-characters (U+FDD0 to U+FDEF,
/// and the last two code points of each plane, U+FFFE and U+FFFF among
/// them): never text, and U+FFFE and U+FFFF are not allowed in XML at all,
/// so a figure refuses them in any text it writes, as it refuses control
/// characters.
pub fn is_noncharacter(c: char) -> bool {
    let u = u32::from(c);
    (0xFDD0..=0xFDEF).contains(&u) || u & 0xFFFE == 0xFFFE
}

/// `FromStr` through `from_name` and `Display` through `name` for a value
/// enum named on the command line and in scene files, so that
/// `x.to_string().parse() == Ok(x)`; the parse error lists the names.
macro_rules! parse_by_name {
    ($($t:ty),+ $(,)?) => {$(
        impl ::std::str::FromStr for $t {
            type Err = $crate::error::Error;

            fn from_str(s: &str) -> $crate::error::Result<Self> {
                <$t>::from_name(s)
            }
        }

        impl ::std::fmt::Display for $t {
            fn fmt(&self, f: &mut ::std::fmt::Formatter<'_>) -> ::std::fmt::Result {
                f.write_str(self.name())
            }
        }
    )+};
}
pub(crate) use parse_by_name;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn values_are_shown_escaped_and_cut() {
        assert_eq!(Error::show("a\rb"), "a\\rb");
        assert_eq!(Error::show("x\u{202E}y\u{FFFE}"), "x\\u{202e}y\\u{fffe}");
        assert_eq!(Error::show("é ok"), "é ok");
        let long = Error::show(&"t".repeat(100_000));
        assert_eq!(long, format!("{}…", "t".repeat(60)));
        let e = Error::invalid(
            Input::FigureName,
            format!("unknown figure '{}\u{2066}'", "f".repeat(5000)),
        )
        .one_line();
        let text = e.to_string();
        assert_eq!(text.chars().count(), 1001);
        assert!(text.ends_with("ff…"), "{text}");
        let e = Error::invalid(Input::Title, "a\u{202E}b".into()).one_line();
        assert_eq!(e.to_string(), "a\\u{202e}b");
    }

    #[test]
    fn paths_and_names_are_printable_whole() {
        // ESC of a colour sequence, an OSC title sequence's BEL, a carriage
        // return, a bidi isolate, a zero-width space, a C1 CSI: escaped;
        // printable text (accents, spaces, a backslash) kept, and not cut.
        assert_eq!(Error::printable("g\u{1b}[31m/x.svg"), r"g\u{1b}[31m/x.svg");
        assert_eq!(Error::printable("a\u{7}b\rc"), r"a\u{7}b\rc");
        assert_eq!(
            Error::printable("\u{2066}\u{200B}\u{9b}"),
            r"\u{2066}\u{200b}\u{9b}"
        );
        assert_eq!(Error::printable(r"é d\x"), r"é d\x");
        assert_eq!(Error::printable(&"p".repeat(5000)), "p".repeat(5000));
        assert_eq!(Error::printable(""), "");
    }

    #[test]
    fn messages_show_extreme_numbers_compactly() {
        let e = Error::NotPositive {
            name: Field::Crank,
            value: -1e100,
        };
        assert_eq!(e.to_string(), "crank must be greater than zero, got -1e100");
        let e = Error::NotFinite {
            name: Field::Crank,
            value: f64::NAN,
        };
        assert_eq!(e.to_string(), "crank must be a finite number, got NaN");
        let e = Error::Negative {
            name: Field::Friction,
            value: -0.5,
        };
        assert_eq!(e.to_string(), "friction must not be negative, got -0.5");
    }

    #[test]
    fn invalid_input_reads_as_its_message() {
        let e = Error::invalid(Input::Layers, "unknown layer 'gears'".into());
        assert_eq!(e.to_string(), "unknown layer 'gears'");
        assert_eq!(Input::Data.to_string(), "data file");
        assert_eq!(Input::Scene.to_string(), "scene file");
        assert_eq!(Input::Indicator.to_string(), "indicator diagram");
        assert_eq!(Input::Unit.to_string(), "unit name");
    }

    #[test]
    fn only_errors_of_the_file_s_kind_name_the_file() {
        let path = std::path::Path::new("runs.csv");
        let data = Error::invalid(
            Input::Data,
            "data line 3: 'x' is not a finite number".into(),
        );
        assert_eq!(
            data.in_file(Input::Data, path).to_string(),
            "runs.csv: data line 3: 'x' is not a finite number"
        );
        // The kind decides, not the text: a message that happens to start
        // with "data" about another input is left alone.
        let other = Error::invalid(
            Input::Calibration,
            "data points: a line fit needs two".into(),
        );
        assert_eq!(
            other.clone().in_file(Input::Data, path),
            other,
            "only the data file's errors"
        );
        let field = Error::NotPositive {
            name: Field::Crank,
            value: 0.0,
        };
        assert_eq!(field.clone().in_file(Input::Data, path), field);
        // An indicator diagram read as a figure's data is the data file.
        let indicator = Error::invalid(Input::Indicator, "data: no rows".into()).about(Input::Data);
        assert_eq!(
            indicator.in_file(Input::Data, path).to_string(),
            "runs.csv: data: no rows"
        );
    }

    #[test]
    fn quoted_newlines_are_escaped() {
        // Found by fuzzing: a layer name "a\nb" in a scene file.
        let e = Error::invalid(Input::Scene, "unknown variant `a\nb\r`".into()).one_line();
        assert_eq!(e.to_string(), "unknown variant `a\\nb\\r`");
    }
}
