//! Short rich texts: letters, subscripts and italic runs for labels and
//! notes.

/// One run of a [`RichText`].
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Run {
    /// The characters.
    pub text: String,
    /// Set as a subscript.
    pub subscript: bool,
    /// Set in italic.
    pub italic: bool,
}

/// A line of text made of runs.
///
/// [`RichText::parse`] reads a small markup: `_x` or `_{xy}` is a subscript,
/// `*...*` is italic (for point letters inside a roman note). A label made
/// with [`RichText::italic`] is italic throughout.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct RichText {
    runs: Vec<Run>,
}

impl RichText {
    /// Parses the markup; unbalanced `*` runs to the end, a trailing `_` is
    /// kept as a character.
    pub fn parse(markup: &str) -> Self {
        let mut runs: Vec<Run> = Vec::new();
        let mut italic = false;
        let mut chars = markup.chars().peekable();
        let push = |runs: &mut Vec<Run>, text: String, subscript: bool, italic: bool| {
            if text.is_empty() {
                return;
            }
            match runs.last_mut() {
                Some(last) if last.subscript == subscript && last.italic == italic => {
                    last.text.push_str(&text)
                }
                _ => runs.push(Run {
                    text,
                    subscript,
                    italic,
                }),
            }
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
                        push(&mut runs, sub, true, italic);
                    }
                    Some(c) => push(&mut runs, c.to_string(), true, italic),
                    None => push(&mut runs, "_".into(), false, italic),
                },
                c => push(&mut runs, c.to_string(), false, italic),
            }
        }
        Self { runs }
    }

    /// The markup parsed and set in italic throughout (point letters).
    pub fn italic(markup: &str) -> Self {
        let mut t = Self::parse(markup);
        for r in &mut t.runs {
            r.italic = true;
        }
        t
    }

    /// The runs.
    pub fn runs(&self) -> &[Run] {
        &self.runs
    }

    /// The characters without markup.
    pub fn plain(&self) -> String {
        self.runs.iter().map(|r| r.text.as_str()).collect()
    }

    /// The width in ems, estimated for a serif face (subscripts at 70 %).
    pub fn width_em(&self) -> f64 {
        self.runs
            .iter()
            .map(|r| {
                let w: f64 = r.text.chars().map(char_width).sum();
                if r.subscript { 0.7 * w } else { w }
            })
            .sum()
    }
}

/// A rough advance width in ems, on the wide side of the serif faces asked
/// for (DejaVu Serif is wider than Times).
fn char_width(c: char) -> f64 {
    match c {
        ' ' | '·' => 0.33,
        '.' | ',' | ':' | ';' | '\'' | '|' | 'i' | 'l' | 'j' | 'I' | '(' | ')' => 0.36,
        'f' | 't' | 'r' | '/' | '-' | '²' | '³' => 0.48,
        'm' | 'w' => 0.92,
        'M' | 'W' => 0.98,
        '=' | '+' | '×' | '≈' | '∞' => 0.84,
        '0'..='9' => 0.64,
        c if c.is_uppercase() => 0.76,
        _ => 0.62,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

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
    fn italic_label_and_trailing_underscore() {
        let t = RichText::italic("F_p");
        assert!(t.runs().iter().all(|r| r.italic));
        assert_eq!(RichText::parse("a_").plain(), "a_");
        assert!(RichText::parse("M").width_em() > RichText::parse("i").width_em());
    }
}
