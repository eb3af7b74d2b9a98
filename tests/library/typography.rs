//! One typographic convention in every figure, read from the written SVG
//! alone (docs/design.md, "Typography"): a small Greek letter (a
//! quantity's symbol, π excepted) is italic wherever it is written,
//! drawing, legend, caption or note; digits, subscripts and exponents are
//! upright; a prime is set in the style of the letter it marks; no
//! straight apostrophe is set.

use crate::common;

use common::{FIXED_PAGES, on_page};
use skrifa::MetadataProvider;
use slider_crank::catalogue::FigureOptions;
use slider_crank::figure::FontStyle;
use slider_crank::render::to_svg;
use slider_crank::{FigureName, Font, Notation};

/// One character as set: the character, italic, and whether it is in a
/// subscript or exponent (a run with a size of its own).
#[derive(Debug, Clone, Copy)]
struct Set {
    c: char,
    italic: bool,
    small: bool,
}

/// The value of attribute `name` in a start tag's text.
fn attr<'a>(tag: &'a str, name: &str) -> Option<&'a str> {
    let key = format!(" {name}=\"");
    let at = tag.find(&key)? + key.len();
    tag[at..].find('"').map(|end| &tag[at..at + end])
}

/// The characters of `text` (element content), entities decoded.
fn chars(text: &str) -> Vec<char> {
    text.replace("&lt;", "<")
        .replace("&gt;", ">")
        .replace("&quot;", "\"")
        .replace("&apos;", "'")
        .replace("&amp;", "&")
        .chars()
        .collect()
}

/// Every `<text>` of `svg`: its id and its characters as set. The writer
/// puts runs in flat `<tspan>`s, each with the attributes it changes.
fn texts(svg: &str) -> Vec<(String, Vec<Set>)> {
    let mut out = Vec::new();
    let mut rest = svg;
    while let Some(start) = rest.find("<text ") {
        let tag_end = start + rest[start..].find('>').expect("a closed tag");
        let tag = &rest[start..tag_end];
        let close = tag_end + rest[tag_end..].find("</text>").expect("a text closes");
        let base = attr(tag, "font-style") == Some("italic");
        let id = attr(tag, "id").unwrap_or("").to_string();
        let mut set = Vec::new();
        let mut body = &rest[tag_end + 1..close];
        while !body.is_empty() {
            match body.find("<tspan") {
                Some(0) => {
                    let open = body.find('>').expect("a closed tspan tag");
                    let span = &body[..open];
                    let end = body.find("</tspan>").expect("a tspan closes");
                    let italic = attr(span, "font-style").map_or(base, |s| s == "italic");
                    let small = attr(span, "font-size").is_some();
                    for c in chars(&body[open + 1..end]) {
                        set.push(Set { c, italic, small });
                    }
                    body = &body[end + "</tspan>".len()..];
                }
                found => {
                    let end = found.unwrap_or(body.len());
                    for c in chars(&body[..end]) {
                        set.push(Set {
                            c,
                            italic: base,
                            small: false,
                        });
                    }
                    body = &body[end..];
                }
            }
        }
        out.push((id, set));
        rest = &rest[close..];
    }
    out
}

/// What breaks the convention in one text, if anything.
fn fault(text: &[Set]) -> Option<String> {
    for (i, s) in text.iter().enumerate() {
        let greek = matches!(s.c, 'β'..='ω' | 'ϑ' | 'ϕ' | 'ϵ') && s.c != 'π';
        if greek && !s.italic {
            return Some(format!("{} upright", s.c));
        }
        // New Computer Modern's italic α is an italic a: α_d read a_d.
        if s.c == 'α' && s.italic {
            return Some("α italic, read as a".into());
        }
        if s.c.is_ascii_digit() && s.italic {
            return Some(format!("digit {} italic", s.c));
        }
        if s.small && s.italic {
            return Some(format!("subscript or exponent {} italic", s.c));
        }
        if s.c == '\'' {
            return Some("a straight apostrophe".into());
        }
        if matches!(s.c, '′' | '″' | '‴' | 'ʹ' | 'ʺ')
            && let Some(before) = i.checked_sub(1).and_then(|j| text.get(j))
            && before.c.is_alphabetic()
            && !before.small
            && before.italic != s.italic
        {
            return Some(format!("{}{} in two styles", before.c, s.c));
        }
    }
    None
}

/// The whole text, for a message.
fn plain(text: &[Set]) -> String {
    text.iter().map(|s| s.c).collect()
}

#[test]
fn every_figure_sets_one_typographic_convention() {
    let mut cases: Vec<(String, String)> = FigureName::ALL
        .iter()
        .map(|name| {
            let svg = to_svg(&name.figure(&FigureOptions::default()).unwrap());
            (name.name().to_string(), svg)
        })
        .collect();
    for name in [FigureName::Fig67Example, FigureName::Fig63Velocity] {
        let mut options = FigureOptions::default();
        options.notation = Some(Notation::Ng);
        let svg = to_svg(&name.figure(&options).unwrap());
        cases.push((format!("{} --notation ng", name.name()), svg));
    }
    let mut faults = Vec::new();
    for (what, svg) in &cases {
        for (id, text) in texts(svg) {
            if let Some(f) = fault(&text) {
                faults.push(format!("{what} #{id}: {f} in \"{}\"", plain(&text)));
            }
        }
    }
    assert!(faults.is_empty(), "{}", faults.join("\n"));
}

#[test]
fn the_checker_sees_each_fault() {
    // The checker itself, on texts the writer could set wrongly.
    let svg = |body: &str| format!("<svg><text id=\"t\" font-style=\"normal\">{body}</text></svg>");
    let fault_of = |body: &str| {
        let t = texts(&svg(body));
        fault(&t[0].1)
    };
    assert_eq!(fault_of("at θ = 30°"), Some("θ upright".into()));
    assert_eq!(
        fault_of("<tspan font-style=\"italic\">θ</tspan> = 30°"),
        None
    );
    assert_eq!(
        fault_of("<tspan font-style=\"italic\">E</tspan>′"),
        Some("E′ in two styles".into())
    );
    assert_eq!(fault_of("<tspan font-style=\"italic\">E′</tspan>"), None);
    assert_eq!(
        fault_of(
            "<tspan font-style=\"italic\">P</tspan><tspan dy=\"3\" font-size=\"9\" font-style=\"italic\">1</tspan>"
        ),
        Some("digit 1 italic".into())
    );
    assert_eq!(
        fault_of("V<tspan dy=\"3\" font-size=\"9\" font-style=\"italic\">c</tspan>"),
        Some("subscript or exponent c italic".into())
    );
    assert_eq!(
        fault_of("Ng&apos;s paper"),
        Some("a straight apostrophe".into())
    );
    assert_eq!(fault_of("2π rad, Ng’s paper"), None);
    assert_eq!(
        fault_of("<tspan font-style=\"italic\">α</tspan> = 3 rad/s²"),
        Some("α italic, read as a".into())
    );
    assert_eq!(fault_of("α = 3 rad/s²"), None);
}

/// Whether a text sets the velocity letter `v` (italic) with the
/// subscript c or p.
fn has_velocity(text: &[Set], v: char) -> bool {
    text.windows(2)
        .any(|w| w[0].c == v && w[0].italic && w[1].small && matches!(w[1].c, 'c' | 'p'))
}

#[test]
fn ng_notation_writes_ngs_small_v() {
    // Issue 20: `--notation ng` on Fig. 67 still wrote V_c, V_p where Ng
    // writes v_c, v_p; the textbook's letters stay capital.
    for (notation, ours, theirs) in [(Notation::Ng, 'v', 'V'), (Notation::Textbook, 'V', 'v')] {
        let mut options = FigureOptions::default();
        options.notation = Some(notation);
        let svg = to_svg(&FigureName::Fig67Example.figure(&options).unwrap());
        let all = texts(&svg);
        assert!(
            all.iter().any(|(_, t)| has_velocity(t, ours)),
            "{notation:?}"
        );
        assert!(
            !all.iter().any(|(_, t)| has_velocity(t, theirs)),
            "{notation:?}"
        );
    }
}

/// Whether the text face of `font` in `style` (not its maths face) has
/// `c`, read from the font file's character map.
fn text_face_has(font: Font, style: FontStyle, c: char) -> bool {
    let face = skrifa::FontRef::new(font.data(style)).unwrap();
    face.charmap().map(c).is_some()
}

#[test]
fn every_character_is_in_its_own_text_face() {
    // A character the text face lacks (′, ∫ in New Computer Modern) is
    // found by a renderer in the maths face, and resvg then sets the whole
    // line in that upright face: every italic of it lost in the PNG and
    // the PDF (issue 20, "F′, theory: F(1 − μ tan φ)" all roman). Every
    // character of every figure, in both faces, is in the text face of its
    // own style.
    for font in Font::ALL {
        let mut options = FigureOptions::default();
        options.font = Some(font);
        for name in FigureName::ALL {
            let svg = to_svg(&name.figure(&options).unwrap());
            for (id, text) in texts(&svg) {
                for s in &text {
                    let style = if s.italic {
                        FontStyle::Italic
                    } else {
                        FontStyle::Regular
                    };
                    assert!(
                        s.c == '\u{a0}' || text_face_has(font, style, s.c),
                        "{} in {font}: {:?} ({style:?}) of #{id} \"{}\" is not in the text face",
                        name.name(),
                        s.c,
                        plain(&text)
                    );
                }
            }
        }
    }
}

/// The value of a `<text>`'s attribute, as a number.
fn number(tag: &str, name: &str) -> f64 {
    attr(tag, name).and_then(|v| v.parse().ok()).unwrap()
}

/// The advance of characters as set at `size` in `font` (subscripts and
/// exponents at 70 %), from the face's own widths.
fn advance(font: Font, set: &[Set], size: f64) -> f64 {
    set.iter()
        .map(|s| {
            let style = if s.italic {
                FontStyle::Italic
            } else {
                FontStyle::Regular
            };
            let at = if s.small { 0.7 * size } else { size };
            font.width(&s.c.to_string(), at, style)
        })
        .sum()
}

#[test]
fn notes_keep_their_size_on_a_fixed_page() {
    // `--width 120mm` shrank Fig. 60's notes to 4–6 pt while its letters
    // stayed 12.75 pt; the notes now wrap (and the page grows) instead:
    // every line of every note is set at the notes' 13 units, on every
    // figure at each fixed size, and none reaches past the page's right
    // edge (widths from the face's own advances).
    let font = Font::NewComputerModern;
    for (width, height) in FIXED_PAGES {
        for name in FigureName::ALL {
            let options = on_page(width, height);
            // A diagram whose plots do not fit a page refuses it by name.
            let figure = match name.figure(&options) {
                Ok(f) => f,
                Err(e) if e.to_string().contains("leaves no room for the plots") => continue,
                // A mechanism figure whose detail and notes need more than
                // the height asked for refuses it, naming the height.
                Err(e) if e.to_string().contains("this figure needs") => continue,
                Err(e) => panic!("{}: {e}", name.name()),
            };
            let svg = to_svg(&figure);
            let view: Vec<f64> = attr(&svg, "viewBox")
                .unwrap()
                .split(' ')
                .map(|v| v.parse().unwrap())
                .collect();
            let mut rest = svg.as_str();
            while let Some(at) = rest.find("<text ") {
                let tag = &rest[at..at + rest[at..].find('>').unwrap()];
                rest = &rest[at + tag.len()..];
                if !attr(tag, "id").unwrap_or("").starts_with("note-") {
                    continue;
                }
                let size = number(tag, "font-size");
                let what = format!("{} at {width} × {height:?}: {tag}", name.name());
                assert_eq!(size, 13.0, "{what}");
                let text = &rest[1..rest.find("</text>").unwrap()];
                let (_, set) = &texts(&format!("{tag}>{text}</text>"))[0];
                let advance = advance(font, set, size);
                assert!(
                    number(tag, "x") + advance <= view[2] + 0.5,
                    "{what}: {advance}"
                );
            }
        }
    }
}

#[test]
fn panel_captions_never_run_together() {
    // Fig. 60's three captions at 120 mm ran into each other; each is
    // now broken to its panel's width. The lines of neighbouring
    // captions at one height do not overlap.
    let font = Font::NewComputerModern;
    for (width, height) in FIXED_PAGES {
        let options = on_page(width, height);
        let svg = to_svg(&FigureName::Fig60Chains.figure(&options).unwrap());
        let mut spans: Vec<(f64, f64, f64)> = Vec::new();
        for (id, set) in texts(&svg) {
            if !id.starts_with("caption") {
                continue;
            }
            let at = svg.find(&format!("id=\"{id}\"")).unwrap();
            let start = svg[..at].rfind("<text ").unwrap();
            let tag = &svg[start..at + svg[at..].find('>').unwrap()];
            let (x, y, size) = (number(tag, "x"), number(tag, "y"), number(tag, "font-size"));
            let w = advance(font, &set, size);
            spans.push((y, x - 0.5 * w, x + 0.5 * w));
        }
        assert!(spans.len() >= 3, "{width}: {spans:?}");
        for (i, a) in spans.iter().enumerate() {
            for b in &spans[i + 1..] {
                let apart = (a.0 - b.0).abs() > 1.0 || a.2 <= b.1 || b.2 <= a.1;
                assert!(apart, "{width}: captions overlap {a:?} {b:?}");
            }
        }
    }
}

#[test]
fn captions_stay_on_a_narrow_page() {
    // `inversion-2-rotating-block --width 120mm` set its caption "Inversion
    // 2: link a fixed, rotating block: Whitworth quick return, Gnome
    // engine" past both edges of the page; a caption too wide for its
    // panel keeps its head and the notes open with the name. The plots'
    // captions of seven diagrams (acceleration-diagrams, turning-moment,
    // flywheel, …) ran past a 120 mm page: they are now broken to their
    // panel. Every centred caption of every figure at each fixed size
    // lies within the page.
    let font = Font::NewComputerModern;
    let mut wide = Vec::new();
    for (width, height) in FIXED_PAGES {
        for name in FigureName::ALL {
            let options = on_page(width, height);
            let Ok(figure) = name.figure(&options) else {
                continue; // refused by name: see the notes' test above
            };
            let svg = to_svg(&figure);
            let page: f64 = attr(&svg, "viewBox")
                .unwrap()
                .split(' ')
                .nth(2)
                .unwrap()
                .parse()
                .unwrap();
            for (id, set) in texts(&svg) {
                if !id.contains("caption") {
                    continue;
                }
                let at = svg.find(&format!("id=\"{id}\"")).unwrap();
                let start = svg[..at].rfind("<text ").unwrap();
                let tag = &svg[start..at + svg[at..].find('>').unwrap()];
                if attr(tag, "text-anchor") != Some("middle") {
                    continue;
                }
                let (x, size) = (number(tag, "x"), number(tag, "font-size"));
                let half = 0.5 * advance(font, &set, size);
                if !(x - half >= -0.5 && x + half <= page + 0.5) {
                    wide.push(format!(
                        "{} at {width}: {id} from {:.1} to {:.1} on a page {page} wide",
                        name.name(),
                        x - half,
                        x + half
                    ));
                }
            }
        }
    }
    assert!(
        wide.is_empty(),
        "captions past the page:\n{}",
        wide.join("\n")
    );
}
