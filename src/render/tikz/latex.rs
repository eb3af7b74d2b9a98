//! A figure's rich texts as LaTeX: symbols in maths (`$A$`, `$\varphi$`,
//! `$V_\mathrm{p}$`, `$\omega^{2}\cdot CG$`), words in text, every
//! character a book's LaTeX might read as markup escaped, so that a
//! title with `\`, `{`, `%`, `$`, `#`, `_`, `^` or `~` prints as given.
//! Only ASCII is written: each other character the figures set has its
//! LaTeX command (both pdfLaTeX and LuaLaTeX set them in the book's own
//! fonts); one with none is written `?`.

use crate::figure::{RichText, Run};

/// A piece of the text: in maths or in text mode.
enum Piece {
    Math(String),
    Text(String),
}

/// `text` as LaTeX for a node's contents, on one line.
pub(super) fn latex(text: &RichText) -> String {
    let mut pieces: Vec<Piece> = Vec::new();
    for run in text.runs() {
        if run.subscript || run.superscript {
            let mark = if run.subscript { '_' } else { '^' };
            let inner = math_run(&run.text, run.italic);
            push_math(&mut pieces, format!("{mark}{{{inner}}}"), true);
        } else if run.italic || is_symbols(run) {
            push_math(&mut pieces, math_run(&run.text, run.italic), false);
        } else {
            for c in run.text.chars() {
                match text_char(c) {
                    Piece::Text(t) => push_text(&mut pieces, &t),
                    Piece::Math(m) => push_math(&mut pieces, m, false),
                }
            }
        }
    }
    let mut out = String::new();
    for p in pieces {
        match p {
            Piece::Math(m) => {
                out.push('$');
                // A prime after a degree sign ("90°′", an angle of the
                // second curve) would be a second superscript on one
                // base, which LaTeX refuses: it primes an empty group.
                out.push_str(&m.replace("^{\\circ}'", "^{\\circ}{}'"));
                out.push('$');
            }
            Piece::Text(t) => out.push_str(&t),
        }
    }
    out
}

/// Adds maths to the last piece if that is maths, else as a new piece;
/// a script with nothing before it in maths gets an empty base.
fn push_math(pieces: &mut Vec<Piece>, m: String, script: bool) {
    match pieces.last_mut() {
        Some(Piece::Math(last)) => last.push_str(&m),
        _ => pieces.push(Piece::Math(if script { format!("{{}}{m}") } else { m })),
    }
}

fn push_text(pieces: &mut Vec<Piece>, t: &str) {
    match pieces.last_mut() {
        Some(Piece::Text(last)) => last.push_str(t),
        _ => pieces.push(Piece::Text(t.to_owned())),
    }
}

/// Whether an upright run is symbols only (no letter, nor a word): set
/// in maths, as `·` between two italic quantities.
fn is_symbols(run: &Run) -> bool {
    !run.text.is_empty()
        && run
            .text
            .chars()
            .all(|c| !c.is_alphanumeric() && c != ' ' && math_symbol(c).is_some())
}

/// A run's characters in maths: letters italic where `italic`, else in
/// `\mathrm`; spaces kept.
fn math_run(s: &str, italic: bool) -> String {
    let mut out = String::new();
    let mut upright = String::new();
    let flush = |out: &mut String, upright: &mut String| {
        if !upright.is_empty() {
            out.push_str(&format!("\\mathrm{{{upright}}}"));
            upright.clear();
        }
    };
    for c in s.chars() {
        if c.is_ascii_alphanumeric() && !(italic || c.is_ascii_digit()) {
            upright.push(c);
            continue;
        }
        flush(&mut out, &mut upright);
        match c {
            ' ' | '\u{a0}' => out.push_str("\\ "),
            c if c.is_ascii_alphanumeric() => out.push(c),
            c => out.push_str(&math_symbol(c).unwrap_or_else(|| text_in_math(c))),
        }
    }
    flush(&mut out, &mut upright);
    out
}

/// A character with no maths command, in maths: its text form in an
/// `\mbox`.
fn text_in_math(c: char) -> String {
    match text_char(c) {
        Piece::Text(t) => format!("\\mbox{{{t}}}"),
        Piece::Math(m) => m,
    }
}

/// The maths command of a symbol or Greek letter the figures set, with a
/// space after a control word; `None` for other characters.
fn math_symbol(c: char) -> Option<String> {
    let word = |w: &str| Some(format!("\\{w} "));
    match c {
        'α' => word("alpha"),
        'β' => word("beta"),
        'γ' => word("gamma"),
        'δ' => word("delta"),
        'ε' => word("varepsilon"),
        'θ' => word("theta"),
        'λ' => word("lambda"),
        'μ' | 'µ' => word("mu"),
        'π' => word("pi"),
        'ρ' => word("rho"),
        'σ' => word("sigma"),
        'τ' => word("tau"),
        'φ' => word("varphi"),
        'ψ' => word("psi"),
        'ω' => word("omega"),
        'Δ' => word("Delta"),
        'Ω' => word("Omega"),
        'Σ' => word("Sigma"),
        '·' => word("cdot"),
        '×' => word("times"),
        '÷' => word("div"),
        '±' => word("pm"),
        '→' => word("to"),
        '∞' => word("infty"),
        '√' => word("surd"),
        '≈' => word("approx"),
        '≤' => word("leq"),
        '≥' => word("geq"),
        '°' => Some("^{\\circ}".into()),
        '′' | 'ʹ' | '\'' => Some("'".into()),
        '″' | 'ʺ' => Some("''".into()),
        '−' | '-' => Some("-".into()),
        '+' | '=' | '/' | '(' | ')' | '[' | ']' | '.' | ',' | ':' | ';' | '<' | '>' | '|' => {
            Some(c.to_string())
        }
        _ => None,
    }
}

/// A character in text mode: ASCII escaped where LaTeX reads it as
/// markup, the non-ASCII characters the figures set by their commands
/// (symbols in maths), any other `?`.
fn text_char(c: char) -> Piece {
    let t = |s: &str| Piece::Text(s.to_owned());
    match c {
        '\\' => t("\\textbackslash{}"),
        '{' => t("\\{"),
        '}' => t("\\}"),
        '%' => t("\\%"),
        '$' => t("\\$"),
        '#' => t("\\#"),
        '_' => t("\\_"),
        '&' => t("\\&"),
        '^' => t("\\textasciicircum{}"),
        '~' => t("\\textasciitilde{}"),
        '<' => t("\\textless{}"),
        '>' => t("\\textgreater{}"),
        '|' => t("\\textbar{}"),
        '"' => t("\\textquotedbl{}"),
        '-' => t("-{}"),
        '`' => t("\\textasciigrave{}"),
        '\'' | '’' => t("'{}"),
        '‘' => t("`{}"),
        '\u{a0}' => t("~"),
        '\u{202f}' => t("\\,"),
        '–' => t("--{}"),
        '—' => t("---{}"),
        '§' => t("\\S{}"),
        '¼' => t("\\textonequarter{}"),
        '½' => t("\\textonehalf{}"),
        '¾' => t("\\textthreequarters{}"),
        'é' => t("\\'e"),
        'è' => t("\\`e"),
        'ü' => t("\\\"u"),
        'ö' => t("\\\"o"),
        'ä' => t("\\\"a"),
        c if c.is_ascii() && !c.is_ascii_control() => Piece::Text(c.to_string()),
        c => match math_symbol(c) {
            Some(m) => Piece::Math(m),
            None => t("?"),
        },
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn of(markup: &str) -> String {
        latex(&RichText::parse(markup))
    }

    #[test]
    fn a_prime_after_a_degree_sign_primes_an_empty_group() {
        // "90°′" as "90^{\circ}'" is a double superscript in LaTeX.
        assert_eq!(of("90°′"), "90$^{\\circ}{}'$");
        assert_eq!(of("*a*′"), "$a'$");
    }

    #[test]
    fn symbols_are_maths_in_the_books_notation() {
        assert_eq!(latex(&RichText::italic("A")), "$A$");
        assert_eq!(of("*V*_p"), "$V_{\\mathrm{p}}$");
        assert_eq!(of("φ"), "$\\varphi $");
        assert_eq!(of("*CE*"), "$CE$");
    }

    #[test]
    fn every_markup_character_of_latex_is_escaped_in_text() {
        // `_` before a character is the markup of a subscript; at the end
        // it is a character.
        assert_eq!(
            of(r"a\b{c}%d$e#f^h~i&j x_"),
            r"a\textbackslash{}b\{c\}\%d\$e\#f\textasciicircum{}h\textasciitilde{}i\&j x\_"
        );
    }

    #[test]
    fn a_character_with_no_command_is_a_question_mark_and_ascii_stays() {
        assert_eq!(of("x 漢"), "x ?");
        assert_eq!(of("Scale 1:2"), "Scale 1:2");
    }
}
