//! TikZ output (`--out FILE.tex`) compiled by LaTeX: every named figure's
//! standalone TikZ compiles with pdfLaTeX and with LuaLaTeX to one page of
//! the program's PDF size; rasterised (pdftoppm, 36 dpi), its lines agree
//! with the program's own PDF of the figure pixel for pixel within one
//! pixel (2 pt), the text left out of both (its words' boxes, read with
//! pdftotext, grown by 2 pt); and every label the layout placed (the SVG's
//! `label-…` texts) stands within [`LETTER_TOLERANCE`] of where the
//! program's PDF has it. A title of LaTeX's markup characters compiles and
//! prints as given.
//!
//! These need TeX Live (pdflatex, lualatex, TikZ, geometry, lmodern) and
//! poppler-utils; a plain `cargo test` lists them as ignored, `.ci/run`
//! installs both and runs them.

use crate::{command, common};
use command::{run, succeeded};
use slider_crank::FigureName;
use std::collections::HashSet;
use std::path::{Path, PathBuf};
use std::process::Command;

/// How far (pt) a label's first letter in the TikZ PDF may stand from
/// the same letter in the program's PDF (a quarter of a letter's size): LaTeX's glyphs and scripts are not the
/// bundled faces', so a word's box moves by a little of its width.
const LETTER_TOLERANCE: f64 = 3.0;

/// The least share of the dark pixels of one raster's lines that have a
/// dark pixel of the other's within one pixel.
const LINES_AGREE: f64 = 0.99;

/// Resolution of the rasters compared, dots per inch (1 px = 2 pt).
const DPI: f64 = 36.0;

/// The standard output of `tool args…`, which must succeed; a missing
/// tool fails the test with what to install.
fn tool(tool: &str, args: &[&str]) -> Vec<u8> {
    let out = Command::new(tool).args(args).output().unwrap_or_else(|e| {
        panic!("{tool} could not be run ({e}): install TeX Live and poppler-utils")
    });
    assert!(
        out.status.success(),
        "{tool} {args:?}: {}{}",
        String::from_utf8_lossy(&out.stdout)
            .lines()
            .filter(|l| l.starts_with('!') || l.contains("Error"))
            .collect::<Vec<_>>()
            .join("\n"),
        String::from_utf8_lossy(&out.stderr)
    );
    out.stdout
}

/// `tex` compiled by `engine` in its directory, as `job`.pdf.
fn compile(engine: &str, tex: &Path, job: &str) -> PathBuf {
    let dir = tex.parent().unwrap();
    tool(
        engine,
        &[
            "-interaction=nonstopmode",
            "-halt-on-error",
            "-output-directory",
            dir.to_str().unwrap(),
            "-jobname",
            job,
            tex.to_str().unwrap(),
        ],
    );
    dir.join(format!("{job}.pdf"))
}

/// The page count and size (pt) pdfinfo gives.
fn page(pdf: &Path) -> (usize, f64, f64) {
    let info = String::from_utf8(tool("pdfinfo", &[pdf.to_str().unwrap()])).unwrap();
    let field = |name: &str| {
        info.lines()
            .find_map(|l| l.strip_prefix(name))
            .map(str::trim)
            .unwrap_or_else(|| panic!("no {name} in {info}"))
            .to_owned()
    };
    let pages = field("Pages:").parse().unwrap();
    let size: Vec<f64> = (field("Page size:").split_whitespace())
        .filter_map(|w| w.parse().ok())
        .collect();
    (pages, size[0], size[1])
}

/// A word of the page and its box (pt, y down).
#[derive(Debug, Clone)]
struct Word {
    text: String,
    min: (f64, f64),
    max: (f64, f64),
}

impl Word {
    /// Where its first letter stands: the box's left side, halfway down
    /// (a word's right side moves with what follows its letter, a prime
    /// set in the word or beside it).
    fn start(&self) -> (f64, f64) {
        (self.min.0, 0.5 * (self.min.1 + self.max.1))
    }
}

/// The words pdftotext reads with their boxes.
fn words(pdf: &Path) -> Vec<Word> {
    let html =
        String::from_utf8(tool("pdftotext", &["-bbox", pdf.to_str().unwrap(), "-"])).unwrap();
    let attr = |tag: &str, name: &str| -> f64 {
        let at = tag.find(&format!("{name}=\"")).unwrap() + name.len() + 2;
        tag[at..].split('"').next().unwrap().parse().unwrap()
    };
    html.split("<word ")
        .skip(1)
        .map(|rest| {
            let (tag, body) = rest.split_once('>').unwrap();
            let text = body.split("</word>").next().unwrap();
            Word {
                text: text
                    .replace("&amp;", "&")
                    .replace("&lt;", "<")
                    .replace("&gt;", ">"),
                min: (attr(tag, "xMin"), attr(tag, "yMin")),
                max: (attr(tag, "xMax"), attr(tag, "yMax")),
            }
        })
        .collect()
}

/// The dark pixels of the page at [`DPI`], grey level under 160.
fn dark_pixels(pdf: &Path) -> HashSet<(i64, i64)> {
    let pgm = tool(
        "pdftoppm",
        &[
            "-gray",
            "-r",
            &DPI.to_string(),
            "-singlefile",
            pdf.to_str().unwrap(),
        ],
    );
    // P5, width, height, maximum, one byte a pixel.
    let mut fields = Vec::new();
    let mut at = 0;
    while fields.len() < 4 {
        while pgm[at].is_ascii_whitespace() {
            at += 1;
        }
        let start = at;
        while !pgm[at].is_ascii_whitespace() {
            at += 1;
        }
        fields.push(String::from_utf8_lossy(&pgm[start..at]).to_string());
    }
    assert_eq!(fields[0], "P5");
    let w: usize = fields[1].parse().unwrap();
    let pixels = &pgm[at + 1..];
    (pixels.iter().enumerate())
        .filter(|(_, v)| **v < 160)
        .map(|(i, _)| ((i % w) as i64, (i / w) as i64))
        .collect()
}

/// The share of `a` with a pixel of `b` within one pixel.
fn share_near(a: &HashSet<(i64, i64)>, b: &HashSet<(i64, i64)>) -> f64 {
    if a.is_empty() {
        return 1.0;
    }
    let near =
        |&(x, y): &(i64, i64)| (-1..=1).any(|dx| (-1..=1).any(|dy| b.contains(&(x + dx, y + dy))));
    a.iter().filter(|p| near(p)).count() as f64 / a.len() as f64
}

/// `pixels` without those under a word of `words` (its box grown by 2 pt).
fn without_text(pixels: &HashSet<(i64, i64)>, words: &[Word]) -> HashSet<(i64, i64)> {
    let k = DPI / 72.0;
    let under = |&(x, y): &(i64, i64)| {
        let (x, y) = (x as f64 / k, y as f64 / k);
        words.iter().any(|w| {
            x >= w.min.0 - 2.5 && x <= w.max.0 + 2.5 && y >= w.min.1 - 2.5 && y <= w.max.1 + 2.5
        })
    };
    pixels.iter().filter(|p| !under(p)).copied().collect()
}

/// The labels of the SVG: their first letters and anchors in pt.
fn labels(svg: &str) -> Vec<(char, (f64, f64))> {
    let mut out = Vec::new();
    for tag in svg.split("<text ").skip(1) {
        let (attrs, body) = tag.split_once('>').unwrap();
        if !attrs.contains("id=\"label-") {
            continue;
        }
        let num = |name: &str| -> f64 {
            let at = attrs.find(&format!(" {name}=\"")).unwrap() + name.len() + 3;
            attrs[at..].split('"').next().unwrap().parse().unwrap()
        };
        if let Some(c) = body.chars().next().filter(char::is_ascii_alphabetic) {
            out.push((c, (0.75 * num("x"), 0.75 * num("y"))));
        }
    }
    out
}

/// The word of `words` starting with `c` whose start is nearest `at`, and
/// its distance.
fn nearest(words: &[Word], c: char, at: (f64, f64)) -> Option<(&Word, f64)> {
    (words.iter())
        .filter(|w| w.text.starts_with(c))
        .map(|w| {
            let (x, y) = w.start();
            (w, ((x - at.0).powi(2) + (y - at.1).powi(2)).sqrt())
        })
        .min_by(|a, b| a.1.total_cmp(&b.1))
}

/// The faults of one compiled TikZ PDF against the program's PDF of the
/// same figure, whose labels are `labels`.
fn faults(tikz: &Path, program: &Path, labels: &[(char, (f64, f64))]) -> Vec<String> {
    let mut faults = Vec::new();
    let (pages, w, h) = page(tikz);
    let (_, pw, ph) = page(program);
    if pages != 1 || (w - pw).abs() > 0.5 || (h - ph).abs() > 0.5 {
        faults.push(format!(
            "{pages} pages of {w} × {h} pt, the PDF's {pw} × {ph}"
        ));
    }
    let (tw, pw) = (words(tikz), words(program));
    let all: Vec<Word> = tw.iter().chain(&pw).cloned().collect();
    let t = without_text(&dark_pixels(tikz), &all);
    let p = without_text(&dark_pixels(program), &all);
    let (a, b) = (share_near(&p, &t), share_near(&t, &p));
    if a < LINES_AGREE || b < LINES_AGREE {
        faults.push(format!(
            "lines agree {a:.3} (PDF in TikZ), {b:.3} (TikZ in PDF)"
        ));
    }
    for &(c, at) in labels {
        // A label not found in the program's PDF is a fault, not a
        // letter passed unchecked.
        let Some((want, _)) = nearest(&pw, c, at) else {
            faults.push(format!("label {c:?} at {at:?}: no such word in the PDF"));
            continue;
        };
        match nearest(&tw, c, want.start()) {
            Some((_, d)) if d <= LETTER_TOLERANCE => {}
            other => faults.push(format!(
                "label {:?} at {:?} in the PDF; in the TikZ {:?}",
                want.text,
                want.start(),
                other.map(|(w, d)| (w.text.clone(), w.start(), d))
            )),
        }
    }
    faults
}

#[test]
#[ignore = "needs TeX Live and poppler-utils: run with `-- --ignored` (.ci/run does)"]
fn every_figure_as_tikz_compiles_with_both_engines_and_matches_its_pdf() {
    let dir = tempfile::tempdir().unwrap();
    // The figures on the test threads (each its own files; LaTeX runs
    // on one core, so one figure at a time left the other idle).
    let names = FigureName::ALL.map(|f| f.name());
    let failures: Vec<String> =
        common::in_threads(&names, |name| tikz_faults(dir.path(), name)).concat();
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// The faults of figure `name` written in `dir` as standalone TikZ,
/// compiled by both engines, against its PDF from the program.
fn tikz_faults(dir: &Path, name: &str) -> Vec<String> {
    let tex = dir.join(format!("{name}.tex"));
    let pdf = dir.join(format!("{name}-program.pdf"));
    for out in [&tex, &pdf] {
        let mut args = vec!["figure", name, "--out", out.to_str().unwrap()];
        if out == &tex {
            args.push("--tikz-standalone");
        }
        succeeded(&run(&args));
    }
    let svg = run(&["figure", name]);
    succeeded(&svg);
    let labels = labels(&String::from_utf8(svg.stdout).unwrap());
    let mut failures = Vec::new();
    for engine in ["pdflatex", "lualatex"] {
        let compiled = compile(engine, &tex, &format!("{name}-{engine}"));
        for f in faults(&compiled, &pdf, &labels) {
            failures.push(format!("{name} ({engine}): {f}"));
        }
    }
    failures
}

#[test]
#[ignore = "needs TeX Live and poppler-utils: run with `-- --ignored` (.ci/run does)"]
fn a_title_of_latex_markup_characters_compiles_and_prints_as_given() {
    let dir = tempfile::tempdir().unwrap();
    let tex = dir.path().join("hostile.tex");
    // `_` before a character is the title markup of a subscript, so it
    // comes last, where it is a character.
    let title = r"100% \LaTeX{} $x$ #1 & a^b ~c {d} x_";
    succeeded(&run(&[
        "figure",
        "fig-63-velocity",
        "--title",
        title,
        "--out",
        tex.to_str().unwrap(),
        "--tikz-standalone",
    ]));
    for engine in ["pdflatex", "lualatex"] {
        let pdf = compile(engine, &tex, &format!("hostile-{engine}"));
        let text = String::from_utf8(tool("pdftotext", &[pdf.to_str().unwrap(), "-"])).unwrap();
        assert!(
            text.lines().any(|l| l.trim() == title),
            "{engine}: the title is not printed as given:\n{text}"
        );
    }
}

#[test]
fn the_gallery_writes_tikz_when_its_manifest_names_it_as_figure_does() {
    let dir = tempfile::tempdir().unwrap();
    let manifest = dir.path().join("gallery.toml");
    std::fs::write(
        &manifest,
        "formats = [\"tikz\"]\nfigures = [\"fig-65-klein\", \"ng-fig-1-torque\"]\n",
    )
    .unwrap();
    let out = dir.path().join("g");
    succeeded(&run(&[
        "gallery",
        "--manifest",
        manifest.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]));
    for name in ["fig-65-klein", "ng-fig-1-torque"] {
        let one = dir.path().join(format!("{name}.tex"));
        succeeded(&run(&["figure", name, "--out", one.to_str().unwrap()]));
        let written = std::fs::read(out.join(format!("{name}.tex"))).unwrap();
        assert_eq!(written, std::fs::read(&one).unwrap(), "{name}");
        assert!(written.starts_with(b"% ") && !written.windows(9).any(|w| w == b"\\document"));
    }
    let index = std::fs::read_to_string(out.join("index.html")).unwrap();
    assert!(index.contains(">TikZ<"), "{index}");
}
