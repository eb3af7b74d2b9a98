//! Short rich texts: letters, subscripts and italic runs for labels and
//! notes.

use super::{Font, FontStyle, TextBox};
use crate::error::Input;

/// A subscript's size, as a fraction of its line's.
pub const SUBSCRIPT_SIZE: f64 = 0.7;
/// How far a subscript's baseline sits below its line's, as a fraction of
/// the line's size.
pub const SUBSCRIPT_DROP: f64 = 0.3;
/// How far a superscript's baseline sits above its line's, as a fraction
/// of the line's size (superscripts are set at [`SUBSCRIPT_SIZE`] too).
pub const SUPERSCRIPT_RISE: f64 = 0.38;

/// The Unicode superscripts and what they are set as.
const SUPERSCRIPTS: [(char, char); 12] = [
    ('⁰', '0'),
    ('¹', '1'),
    ('²', '2'),
    ('³', '3'),
    ('⁴', '4'),
    ('⁵', '5'),
    ('⁶', '6'),
    ('⁷', '7'),
    ('⁸', '8'),
    ('⁹', '9'),
    ('⁻', '−'),
    ('⁺', '+'),
];

/// One run of a [`RichText`].
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Run {
    /// The characters.
    pub text: String,
    /// Set as a subscript.
    pub subscript: bool,
    /// Set as a superscript (exponents written with the Unicode
    /// superscript characters, kept here as plain digits and signs so that
    /// every face has their glyphs).
    pub superscript: bool,
    /// Set in italic.
    pub italic: bool,
}

/// A line of text made of runs.
///
/// [`RichText::parse`] reads a small markup: `_x` or `_{xy}` is a subscript,
/// `*...*` is italic (for point letters inside a roman note); the Unicode
/// superscripts `⁰`–`⁹`, `⁻`, `⁺` become superscript runs of `0`–`9`,
/// `−`, `+` (most text faces have no glyphs of their own for `⁴` or `⁻`). A
/// label made with [`RichText::italic`] is italic throughout, but for its
/// subscripts and superscripts.
///
/// One typographic convention holds in every text, drawing and note
/// alike (ISO 80000-2, as a book sets it; docs/design.md): a quantity's
/// symbol is italic, Latin or Greek (a small Greek letter is italic
/// wherever it is written, but π, a number, and α, whose italic in the
/// text faces is drawn as an italic a); subscripts, which here are
/// descriptive (links, points, `c` for crank, digits), and exponents are
/// upright; a prime (′, ″) is set in the style of the letter it marks.
/// Numbers, units and words are upright.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct RichText {
    runs: Vec<Run>,
}

impl RichText {
    /// Parses the markup; unbalanced `*` runs to the end, a trailing `_` is
    /// kept as a character.
    pub fn parse(markup: &str) -> Self {
        let mut out = RichText::default();
        let mut italic = false;
        let mut chars = markup.chars().peekable();
        let run = |text: String, subscript: bool, italic: bool| Run {
            text,
            subscript,
            superscript: false,
            italic,
        };
        while let Some(ch) = chars.next() {
            match ch {
                '*' => italic = !italic,
                '_' => match chars.next() {
                    Some('{') => {
                        let mut sub = String::new();
                        for c in chars.by_ref() {
                            if c == '}' {
                                break;
                            }
                            sub.push(c);
                        }
                        out.push(run(sub, true, false));
                    }
                    Some(c) => out.push(run(c.to_string(), true, false)),
                    None => out.push(run("_".into(), false, italic)),
                },
                c => match SUPERSCRIPTS.iter().find(|(sup, _)| *sup == c) {
                    Some((_, plain)) => out.push(Run {
                        superscript: true,
                        ..run(plain.to_string(), false, false)
                    }),
                    None => {
                        let style = italic || is_quantity_greek(c) || primes_italic(&out.runs, c);
                        out.push(run(text_prime(c).to_string(), false, style))
                    }
                },
            }
        }
        out
    }

    /// The markup parsed and set in italic throughout (point letters),
    /// but for its subscripts and superscripts, which stay upright.
    pub fn italic(markup: &str) -> Self {
        let mut t = Self::parse(markup);
        for r in &mut t.runs {
            r.italic |= !(r.subscript || r.superscript);
        }
        t
    }

    /// This text followed by `other` (words and a letter, "to *D*");
    /// an empty `other` adds nothing.
    pub fn then(mut self, other: RichText) -> Self {
        self.runs.extend(other.runs);
        self
    }

    /// The runs.
    pub fn runs(&self) -> &[Run] {
        &self.runs
    }

    /// The characters without markup (superscripts as the Unicode
    /// superscript characters).
    pub fn plain(&self) -> String {
        let sup = |c: char| {
            SUPERSCRIPTS
                .iter()
                .find(|(_, plain)| *plain == c)
                .map_or(c, |(s, _)| *s)
        };
        self.runs
            .iter()
            .flat_map(|r| {
                r.text
                    .chars()
                    .map(move |c| if r.superscript { sup(c) } else { c })
            })
            .collect()
    }

    /// The extent of the text set in `font` at `size`, run by run: each
    /// run in its own style, subscripts at 70 % of `size` and
    /// [`SUBSCRIPT_DROP`] × `size` below the baseline, superscripts at 70 %
    /// and [`SUPERSCRIPT_RISE`] × `size` above it.
    pub fn measure(&self, font: Font, size: f64) -> TextBox {
        self.runs.iter().fold(TextBox::default(), |b, r| {
            let style = FontStyle::from_italic(r.italic);
            let shifted = |drop: f64| {
                let t = font.measure(&r.text, SUBSCRIPT_SIZE * size, style);
                TextBox {
                    above: t.above - drop * size,
                    below: t.below + drop * size,
                    ..t
                }
            };
            let run = if r.subscript {
                shifted(SUBSCRIPT_DROP)
            } else if r.superscript {
                shifted(-SUPERSCRIPT_RISE)
            } else {
                font.measure(&r.text, size, style)
            };
            b.then(run)
        })
    }

    /// The width of the text set in `font` at `size` (page units).
    pub fn width(&self, font: Font, size: f64) -> f64 {
        self.measure(font, size).width
    }

    /// The text broken at its spaces into lines no wider than `width` set
    /// in `font` at `size`, as many words on each as fit, so that a note
    /// keeps its size on a narrow page. A word wider than `width` has a
    /// line of its own (it is never cut); a text that fits is one line;
    /// an empty text stays one empty line. Only plain spaces break, and
    /// not those that hold a number to its unit (after a digit) or an
    /// equation's sign to its sides (about `=`); a no-break space, or a
    /// space in a subscript, holds its words together.
    pub fn wrap(&self, font: Font, size: f64, width: f64) -> Vec<RichText> {
        if self.width(font, size) <= width {
            return vec![self.clone()];
        }
        let mut lines = Vec::new();
        let mut line = RichText::default();
        for word in self.words() {
            if line.runs.is_empty() {
                line = word;
                continue;
            }
            let longer = line.joined(&word);
            if longer.width(font, size) <= width {
                line = longer;
            } else {
                lines.push(std::mem::replace(&mut line, word));
            }
        }
        lines.push(line);
        lines
    }

    /// The words of the text: its runs cut at the plain spaces of
    /// ordinary (not sub- or superscript) runs, the spaces dropped.
    fn words(&self) -> Vec<RichText> {
        let mut words = Vec::new();
        let mut word = RichText::default();
        for run in &self.runs {
            if run.subscript || run.superscript {
                word.push(run.clone());
                continue;
            }
            for (i, piece) in run.text.split(' ').enumerate() {
                if i > 0 && !word.runs.is_empty() {
                    words.push(std::mem::take(&mut word));
                }
                if !piece.is_empty() {
                    word.push(Run {
                        text: piece.to_string(),
                        ..run.clone()
                    });
                }
            }
        }
        if !word.runs.is_empty() {
            words.push(word);
        }
        // A number stays with its unit, `=` with both its sides.
        let mut held: Vec<RichText> = Vec::new();
        for word in words {
            let text = word.plain();
            match held.last_mut() {
                Some(last)
                    if last.plain().ends_with(|c: char| c.is_ascii_digit())
                        || text == "="
                        || last.plain().ends_with(" =")
                        || last.plain() == "=" =>
                {
                    *last = last.joined(&word);
                }
                _ => held.push(word),
            }
        }
        held
    }

    /// This text, a plain space, then `other`.
    fn joined(&self, other: &RichText) -> RichText {
        let mut out = self.clone();
        out.push(Run {
            text: " ".into(),
            subscript: false,
            superscript: false,
            italic: false,
        });
        for r in other.runs.iter().cloned() {
            out.push(r);
        }
        out
    }

    /// Appends `run`, joined to the last run when their styles agree; an
    /// empty run adds nothing.
    fn push(&mut self, run: Run) {
        if run.text.is_empty() {
            return;
        }
        match self.runs.last_mut() {
            Some(last)
                if last.subscript == run.subscript
                    && last.superscript == run.superscript
                    && last.italic == run.italic =>
            {
                last.text.push_str(&run.text)
            }
            _ => self.runs.push(run),
        }
    }
}

/// Whether `c` is a small Greek letter, set italic as a quantity's
/// symbol wherever it is written (θ, φ, ω, μ, …); not π, a number, nor
/// α: New Computer Modern's italic α is the text face's, an italic a
/// with a flick, which a reader takes for the point *a* (the angular
/// acceleration α_d read as the image a_d); upright it is the α of the
/// maths face, not to be mistaken.
fn is_quantity_greek(c: char) -> bool {
    matches!(c, 'β'..='ω' | 'ϑ' | 'ϕ' | 'ϵ') && c != 'π' && c != 'ς'
}

/// The prime `c` as the text faces set it: ′ and ″ as the modifier
/// primes ʹ and ʺ, which every bundled text face has in both styles (New
/// Computer Modern's text faces have no ′: a renderer finding it only in
/// the maths face would set the whole line in that upright face); any
/// other character as it is.
fn text_prime(c: char) -> char {
    match c {
        '′' => 'ʹ',
        '″' => 'ʺ',
        c => c,
    }
}

/// Whether `c` is a prime that follows an italic letter, and so is set in
/// italic with it (the prime belongs to the symbol it marks: *E*′).
fn primes_italic(runs: &[Run], c: char) -> bool {
    matches!(c, '′' | '″' | '‴' | 'ʹ' | 'ʺ')
        && runs
            .last()
            .is_some_and(|r| r.italic && !r.subscript && !r.superscript)
}

/// Longest title, in characters.
pub const MAX_TITLE_CHARS: usize = 200;

/// A figure's title: set as a caption centred below the figure and written
/// as the SVG's `<title>`. It may use the notes' markup ([`RichText::parse`]:
/// `*A*` in italic, `V_p` or `O_{bd}` with a subscript). Made by
/// [`Title::new`] or [`str::parse`]: 1 to [`MAX_TITLE_CHARS`] characters, not
/// all spaces, no control characters and no non-characters.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct Title(String);

impl Title {
    /// The title `text`; an error (one line) when it is empty or blank,
    /// longer than [`MAX_TITLE_CHARS`], or unfit as every user's text is
    /// (the one check of a user's text: a control character such as a line
    /// break, a non-character such as U+FFFE, a bidirectional control, an
    /// invisible character).
    pub fn new(text: &str) -> crate::error::Result<Self> {
        let bad = |why: &str| {
            Err(crate::error::Error::invalid(
                Input::Title,
                format!("invalid title: {why}"),
            ))
        };
        if text.trim().is_empty() {
            return bad("it is empty");
        }
        if text.chars().count() > MAX_TITLE_CHARS {
            return bad(&format!("it is longer than {MAX_TITLE_CHARS} characters"));
        }
        if let Some(why) = crate::error::text_fault(text) {
            return bad(&why);
        }
        Ok(Title(text.to_string()))
    }

    /// The text as given, with its markup.
    pub fn as_str(&self) -> &str {
        &self.0
    }

    /// The text as set: the markup parsed.
    pub fn rich(&self) -> RichText {
        RichText::parse(&self.0)
    }
}

impl std::str::FromStr for Title {
    type Err = crate::error::Error;

    fn from_str(s: &str) -> crate::error::Result<Self> {
        Title::new(s)
    }
}

impl<'de> serde::Deserialize<'de> for Title {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> std::result::Result<Self, D::Error> {
        let text = String::deserialize(d)?;
        Title::new(&text).map_err(serde::de::Error::custom)
    }
}

impl std::fmt::Display for Title {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn titles_are_one_line_of_text() {
        let t: Title = "Velocity of *A*, V_p".parse().unwrap();
        assert_eq!(t.rich().plain(), "Velocity of A, Vp");
        for bad in ["", "   ", "two\nlines", &"x".repeat(201)] {
            let e = bad.parse::<Title>().unwrap_err().to_string();
            assert!(e.starts_with("invalid title"), "{e}");
        }
    }

    #[test]
    fn non_characters_are_refused_as_control_characters_are() {
        for bad in [
            "a\u{FFFE}b",
            "\u{FFFF}",
            "x\u{FDD0}",
            "\u{10FFFF}",
            "\u{1FFFE}",
        ] {
            let e = bad.parse::<Title>().unwrap_err().to_string();
            assert!(
                e.starts_with("invalid title: it holds the non-character U+"),
                "{e}"
            );
        }
        // Their neighbours are text.
        for good in ["\u{FFFD}", "\u{FDCF}", "\u{FDF0}", "\u{10FFFD}"] {
            assert!(good.parse::<Title>().is_ok(), "{good:?}");
        }
        // Text that reorders or hides what follows it is refused too.
        for (bad, why) in [
            ("\u{202E}x", "the bidirectional control U+202E"),
            ("a\u{2066}b", "the bidirectional control U+2066"),
            ("a\u{200B}b", "the invisible character U+200B"),
            ("\u{FEFF}a", "the invisible character U+FEFF"),
        ] {
            let e = bad.parse::<Title>().unwrap_err().to_string();
            assert!(
                e.starts_with(&format!("invalid title: it holds {why}")),
                "{e}"
            );
        }
        assert!(
            crate::error::is_noncharacter('\u{FFFE}') && !crate::error::is_noncharacter('\u{FFFD}')
        );
    }

    #[test]
    fn subscripts_and_italics() {
        let t = RichText::parse("*CB* represents V_c = 13.08 ft/s, O_{bd}");
        let runs: Vec<(&str, bool, bool)> = t
            .runs()
            .iter()
            .map(|r| (r.text.as_str(), r.subscript, r.italic))
            .collect();
        assert_eq!(
            runs,
            vec![
                ("CB", false, true),
                (" represents V", false, false),
                ("c", true, false),
                (" = 13.08 ft/s, O", false, false),
                ("bd", true, false),
            ]
        );
        assert_eq!(t.plain(), "CB represents Vc = 13.08 ft/s, Obd");
    }

    #[test]
    fn unicode_superscripts_become_superscript_runs() {
        let t = RichText::parse("10⁻⁶ ft/s²");
        let runs: Vec<(&str, bool)> = t
            .runs()
            .iter()
            .map(|r| (r.text.as_str(), r.superscript))
            .collect();
        assert_eq!(
            runs,
            vec![("10", false), ("−6", true), (" ft/s", false), ("2", true)]
        );
        assert_eq!(t.plain(), "10⁻⁶ ft/s²");
        let f = Font::NewComputerModern;
        let b = t.measure(f, 10.0);
        // The exponent's ink reaches above the digits' cap height.
        assert!(b.above > f.measure("10", 10.0, FontStyle::Regular).above + 1.0);
    }

    #[test]
    fn italic_label_and_trailing_underscore() {
        // The symbol italic, its descriptive subscript upright.
        let t = RichText::italic("F_p′");
        let runs: Vec<(&str, bool)> = t
            .runs()
            .iter()
            .map(|r| (r.text.as_str(), r.italic))
            .collect();
        assert_eq!(runs, vec![("F", true), ("p", false), ("ʹ", true)]);
        assert_eq!(RichText::parse("a_").plain(), "a_");
    }

    #[test]
    fn one_convention_greek_italic_primes_with_their_letter() {
        // Issue 20: θ upright in notes beside italic θ in the drawing, a
        // roman prime after an italic E, italic subscript digits. Primes
        // are set as the modifier primes the text faces have.
        let t = RichText::parse("at θ = 30°, *E*′ and *CG*″, 2π rad, ω², *P*_1, E′");
        let runs: Vec<(&str, bool)> = t
            .runs()
            .iter()
            .map(|r| (r.text.as_str(), r.italic))
            .collect();
        assert_eq!(
            runs,
            vec![
                ("at ", false),
                ("θ", true),
                (" = 30°, ", false),
                ("Eʹ", true),
                (" and ", false),
                ("CGʺ", true),
                (", 2π rad, ", false),
                ("ω", true),
                ("2", false),
                (", ", false),
                ("P", true),
                ("1", false),
                (", Eʹ", false),
            ]
        );
        for c in ['β', 'θ', 'φ', 'ϕ', 'ω', 'μ'] {
            assert!(is_quantity_greek(c), "{c}");
        }
        for c in ['π', 'α', 'Δ', 'Ω', 'a', '′'] {
            assert!(!is_quantity_greek(c), "{c}");
        }
    }

    #[test]
    fn notes_wrap_at_spaces_and_keep_their_runs() {
        let f = Font::NewComputerModern;
        let t = RichText::parse("The pins *O*_{ad} and *O*_{ab} are *C* and *B* of Figs. 62–67.");
        let whole = t.width(f, 13.0);
        // Wide enough: one line, the same text.
        assert_eq!(t.wrap(f, 13.0, whole), vec![t.clone()]);
        // A third of the width: several lines, each within it (but for a
        // word wider than it), together the same words in the same styles.
        let lines = t.wrap(f, 13.0, whole / 3.0);
        assert!(lines.len() >= 3, "{lines:?}");
        for l in &lines {
            assert!(l.width(f, 13.0) <= whole / 3.0 + 1e-9, "{l:?}");
        }
        let joined: Vec<String> = lines.iter().map(RichText::plain).collect();
        assert_eq!(joined.join(" "), t.plain());
        let styled = |ts: &[RichText]| -> Vec<(String, bool, bool)> {
            ts.iter()
                .flat_map(|l| {
                    l.runs()
                        .iter()
                        .map(|r| (r.text.replace(' ', ""), r.subscript, r.italic))
                })
                .filter(|(s, _, _)| !s.is_empty())
                .collect()
        };
        let (a, b) = (styled(&lines), styled(std::slice::from_ref(&t)));
        let concat = |v: &[(String, bool, bool)]| -> Vec<(String, bool, bool)> {
            let mut out: Vec<(String, bool, bool)> = Vec::new();
            for (s, sub, it) in v {
                match out.last_mut() {
                    Some(l) if l.1 == *sub && l.2 == *it => l.0.push_str(s),
                    _ => out.push((s.clone(), *sub, *it)),
                }
            }
            out
        };
        assert_eq!(concat(&a), concat(&b));
        // A number keeps its unit, an equation its sides.
        let t = RichText::parse("where the torque *T* = 264.87 N·mm is kept as it is");
        for w in [40.0, 60.0, 90.0] {
            let lines: Vec<String> = t.wrap(f, 13.0, w).iter().map(RichText::plain).collect();
            assert!(
                lines.iter().any(|l| l.contains("T = 264.87 N·mm")),
                "{w}: {lines:?}"
            );
        }
        // A word longer than the width is never cut.
        let long = RichText::parse("Supercalifragilistic word");
        let lines = long.wrap(f, 13.0, 10.0);
        assert_eq!(
            lines.iter().map(RichText::plain).collect::<Vec<_>>(),
            ["Supercalifragilistic", "word"]
        );
    }

    #[test]
    fn measured_run_by_run() {
        let f = Font::NewComputerModern;
        let (it, up) = (FontStyle::Italic, FontStyle::Regular);
        // "V_c = 2": V italic, c an upright subscript at 70 %, the rest
        // roman.
        let t = RichText::parse("*V_c* = 2");
        let expected = f.width("V", 20.0, it) + f.width("c", 14.0, up) + f.width(" = 2", 20.0, up);
        assert!((t.width(f, 20.0) - expected).abs() < 1e-9);
        // Subscripts reach below the baseline by the drop.
        let b = t.measure(f, 20.0);
        assert!(b.below >= 0.3 * 20.0 - 1e-9, "{b:?}");
        assert!(RichText::parse("M").width(f, 10.0) > RichText::parse("i").width(f, 10.0));
    }
}
