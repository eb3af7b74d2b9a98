//! The teaching pages in a real browser (issue 12): the gallery's
//! `index.html`, a handout, an exercise sheet and an animation opened in
//! headless Chromium. Each page must load with no script error and no
//! failed request, draw every figure (ink where each `<svg>` and `<img>`
//! shown is), and print on A4 and Letter with no figure or table taller than the printable
//! page (each is `break-inside: avoid`, so one that fits is never cut); the
//! animation must move.
//!
//! Chromium is found as `$CHROMIUM`, `chromium` or `chromium-browser`, and
//! the printed pages are read with poppler's `pdfinfo`, `pdftotext` and
//! `pdffonts`. These tests are ignored by a plain `cargo test`, which lists
//! them as ignored (not run) with the reason; `cargo test --test program --
//! --ignored` runs them, as `.ci/run` does after installing both, and there
//! a missing program fails the test.

use crate::command;

use command::{run, succeeded};
use resvg::tiny_skia::Pixmap;
use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::Command;

/// The flags every test starts Chromium with: headless, without the
/// sandbox (CI runs as root), the GPU or scroll bars.
pub(crate) const HEADLESS: [&str; 4] = [
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--hide-scrollbars",
];

/// The width of the screen the pages are opened at, CSS px.
const SCREEN: u32 = 1100;
/// A paper the handout prints on: how pdfinfo names it, and its printable
/// width and height at the handout's margins (15 mm each side, 14 mm top,
/// 16 mm bottom), in CSS px (96 per inch).
struct Paper {
    pdfinfo: &'static str,
    printable: (f64, f64),
}

const PX_PER_MM: f64 = 96.0 / 25.4;
const A4: Paper = Paper {
    pdfinfo: "(A4)",
    printable: ((210.0 - 30.0) * PX_PER_MM, (297.0 - 30.0) * PX_PER_MM),
};
const LETTER: Paper = Paper {
    pdfinfo: "(letter)",
    printable: ((215.9 - 30.0) * PX_PER_MM, (279.4 - 30.0) * PX_PER_MM),
};
/// The height of the window the probe opens pages in, CSS px.
const WINDOW: u32 = 900;
/// The tallest screenshot taken, px (Chromium's texture limit is 16384).
const TALLEST: f64 = 16000.0;

/// The browser; a test that asked for it fails when it is missing.
pub(crate) fn browser() -> PathBuf {
    let named = std::env::var_os("CHROMIUM").map(PathBuf::from);
    let found = named
        .into_iter()
        .chain(["chromium", "chromium-browser"].map(PathBuf::from))
        .find(|b| {
            Command::new(b)
                .arg("--version")
                .output()
                .is_ok_and(|o| o.status.success())
        });
    found.expect(
        "Chromium was not found as $CHROMIUM, chromium or chromium-browser: \
         install it (Debian: chromium) to run the browser tests",
    )
}

/// A poppler tool run with `args`, which must succeed; a test that asked
/// for it fails when it is missing.
fn poppler(tool: &str, args: &[&str]) -> std::process::Output {
    let out = Command::new(tool).args(args).output().unwrap_or_else(|e| {
        panic!("{tool} could not be run ({e}): install poppler-utils to run the browser tests")
    });
    assert!(
        out.status.success(),
        "{tool} {args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    out
}

/// Virtual time a page is given to load and run, ms.
const SETTLE_MS: u32 = 3000;

/// Headless Chromium on `url` with `extra` flags, `budget` ms of virtual
/// time; its standard output.
fn chromium_at(
    browser: &Path,
    (width, height): (u32, u32),
    budget: u32,
    extra: &[&str],
    url: &str,
) -> String {
    let out = Command::new(browser)
        .args(HEADLESS)
        .args([
            "--allow-file-access-from-files",
            &format!("--virtual-time-budget={budget}"),
            &format!("--window-size={width},{height}"),
        ])
        .args(extra)
        .arg(url)
        .output()
        .expect("Chromium runs");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8_lossy(&out.stdout).into_owned()
}

/// [`chromium_at`] with the page settled.
fn chromium(browser: &Path, width: u32, height: u32, extra: &[&str], url: &str) -> String {
    chromium_at(browser, (width, height), SETTLE_MS, extra, url)
}

fn url(path: &Path) -> String {
    format!("file://{}", path.canonicalize().unwrap().display())
}

/// Listens, before the page's own scripts run, for script errors, failed
/// loads and `console.error`; once loaded, writes what it heard and the
/// box of every figure into the page as `<pre id="probe">` JSON. With
/// `#print` in the URL it first applies the page's `@media print` rules,
/// so that the boxes are those of the printed page.
const PROBE: &str = r#"<script>
(() => {
  const errors = [];
  window.addEventListener('error', e => {
    const t = e.target;
    errors.push(t && t !== window ? 'failed to load ' + (t.src || t.href || t.tagName) : String(e.message));
  }, true);
  window.addEventListener('unhandledrejection', e => errors.push('unhandled rejection ' + e.reason));
  const error = console.error.bind(console);
  console.error = (...a) => { errors.push(a.join(' ')); error(...a); };
  window.addEventListener('load', () => {
    if (location.hash === '#print') {
      const css = [];
      for (const sheet of document.styleSheets) {
        for (const rule of sheet.cssRules) {
          if (rule.media && rule.media.mediaText.includes('print')) {
            for (const inner of rule.cssRules) css.push(inner.cssText);
          }
        }
      }
      const style = document.createElement('style');
      style.textContent = css.join('\n');
      document.head.appendChild(style);
    }
    const box = e => { const r = e.getBoundingClientRect(); return [r.left + scrollX, r.top + scrollY, r.width, r.height]; };
    const figures = [...document.querySelectorAll('svg, img')]
      .filter(e => !e.parentElement.closest('svg') && e.getClientRects().length > 0)
      .map(e => ({ box: box(e), loaded: e.tagName !== 'IMG' || (e.complete && e.naturalWidth > 0) }));
    const blocks = [...document.querySelectorAll('figure, table, .block')]
      .map(e => ({ tag: e.tagName, id: e.id, height: box(e)[3] }));
    // Every text of a drawing inside the drawing, and every legend's text
    // inside the legend's frame, as the browser set them.
    const overflows = [];
    const inside = (a, b) => a.left >= b.left - 0.5 && a.right <= b.right + 0.5
      && a.top >= b.top - 0.5 && a.bottom <= b.bottom + 0.5;
    for (const svg of document.querySelectorAll('svg')) {
      if (svg.parentElement.closest('svg') || svg.getClientRects().length === 0) continue;
      const frame = svg.getBoundingClientRect();
      for (const t of svg.querySelectorAll('text')) {
        const r = t.getBoundingClientRect();
        if (r.width > 0 && !inside(r, frame)) overflows.push(t.textContent);
      }
      for (const box of svg.querySelectorAll('[id$="-legend-box"]')) {
        const stem = box.id.slice(0, -'box'.length);
        const frame = box.getBoundingClientRect();
        for (const t of svg.querySelectorAll('text[id^="' + stem + '"]')) {
          const r = t.getBoundingClientRect();
          if (r.width > 0 && !inside(r, frame)) overflows.push(t.textContent);
        }
      }
    }
    const notes = [...document.querySelectorAll('svg text[id*="note-"]')]
      .filter(t => t.getClientRects().length > 0).map(t => t.textContent);
    const out = document.createElement('pre');
    out.id = 'probe';
    out.textContent = JSON.stringify({ errors, figures, blocks, overflows, notes, height: document.documentElement.scrollHeight });
    document.body.appendChild(out);
  });
})();
</script>"#;

/// What the probe heard on `page` opened `width` px wide.
fn probe(browser: &Path, page: &Path, width: u32, print: bool) -> Value {
    let html = std::fs::read_to_string(page).unwrap();
    let at = html.find("<head>").expect("a <head>") + "<head>".len();
    let probed = page.with_file_name(format!(
        "probe-{}",
        page.file_name().unwrap().to_string_lossy()
    ));
    std::fs::write(&probed, format!("{}{PROBE}{}", &html[..at], &html[at..])).unwrap();
    let hash = if print { "#print" } else { "" };
    let dom = chromium(
        browser,
        width,
        WINDOW,
        &["--dump-dom"],
        &(url(&probed) + hash),
    );
    std::fs::remove_file(&probed).unwrap();
    let start = dom.find("<pre id=\"probe\">").expect("the probe ran") + 16;
    let end = start + dom[start..].find("</pre>").unwrap();
    let json = dom[start..end]
        .replace("&quot;", "\"")
        .replace("&lt;", "<")
        .replace("&gt;", ">")
        .replace("&amp;", "&");
    serde_json::from_str(&json).unwrap()
}

/// Opens `page` as a reader would and checks it: no error, every figure
/// loaded and inked in a screenshot.
fn check_page(browser: &Path, page: &Path) -> Value {
    let name = page.display();
    let report = probe(browser, page, SCREEN, false);
    assert_eq!(report["errors"], Value::Array(vec![]), "{name}");
    let figures = report["figures"].as_array().unwrap();
    assert!(!figures.is_empty(), "{name}: no figure");
    let height = report["height"].as_f64().unwrap().min(TALLEST);
    let shot = page.with_extension("shot.png");
    chromium(
        browser,
        SCREEN,
        height as u32,
        &[&format!("--screenshot={}", shot.display())],
        &url(page),
    );
    let pixmap = Pixmap::load_png(&shot).unwrap();
    std::fs::remove_file(&shot).unwrap();
    for (k, f) in figures.iter().enumerate() {
        assert_eq!(
            f["loaded"],
            Value::Bool(true),
            "{name}: figure {k} not loaded"
        );
        let b = figure_box(f);
        assert!(
            b[2] > 10.0 && b[3] > 10.0,
            "{name}: figure {k} has no size: {b:?}"
        );
        if b[1] + b[3] > height {
            continue; // below the screenshot (only on very long pages)
        }
        let ink = inked(&pixmap, &b);
        assert!(
            ink as f64 > 1e-3 * b[2] * b[3],
            "{name}: figure {k} at {b:?} is blank ({ink} inked pixels)"
        );
    }
    report
}

/// A figure's box as the probe reports it: `[x, y, w, h]`, CSS px.
fn figure_box(figure: &Value) -> Vec<f64> {
    figure["box"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v.as_f64().unwrap())
        .collect()
}

/// Pixels darker than light grey inside the box `[x, y, w, h]`.
fn inked(pixmap: &Pixmap, b: &[f64]) -> usize {
    let (x0, y0) = (b[0].max(0.0) as u32, b[1].max(0.0) as u32);
    let x1 = ((b[0] + b[2]) as u32).min(pixmap.width());
    let y1 = ((b[1] + b[3]) as u32).min(pixmap.height());
    let mut n = 0;
    for y in y0..y1 {
        for x in x0..x1 {
            let p = pixmap.pixel(x, y).unwrap().demultiply();
            if p.alpha() > 0 && p.red().min(p.green()).min(p.blue()) < 160 {
                n += 1;
            }
        }
    }
    n
}

/// Prints `page` to PDF and checks it: pages of `paper`, every figure's
/// caption in its text, and, laid out as printed, no figure or table
/// taller than the printable page.
fn check_print(browser: &Path, page: &Path, paper: &Paper) {
    let name = page.display();
    let (width, height) = paper.printable;
    let report = probe(browser, page, width.round() as u32, true);
    assert_eq!(
        report["overflows"],
        Value::Array(vec![]),
        "{name}: texts past their drawing or legend on {}",
        paper.pdfinfo
    );
    for block in report["blocks"].as_array().unwrap() {
        let h = block["height"].as_f64().unwrap();
        assert!(
            h <= height,
            "{name}: {block} is taller than a page {} ({height:.0} px) and would be cut",
            paper.pdfinfo
        );
    }
    let pdf = page.with_extension("print.pdf");
    chromium(
        browser,
        SCREEN,
        900,
        &[
            "--no-pdf-header-footer",
            &format!("--print-to-pdf={}", pdf.display()),
        ],
        &url(page),
    );
    let info = poppler("pdfinfo", &[pdf.to_str().unwrap()]);
    let info = String::from_utf8_lossy(&info.stdout);
    let html = std::fs::read_to_string(page).unwrap();
    // A page that names its paper prints on it (the animation names none).
    if html.contains("@page") {
        assert!(info.contains(paper.pdfinfo), "{name}: {info}");
    }
    let text = poppler("pdftotext", &["-raw", pdf.to_str().unwrap(), "-"]);
    let text = String::from_utf8_lossy(&text.stdout);
    let captions = html.matches("<span class=\"label\">Figure ").count();
    for k in 1..=captions {
        assert!(
            text.contains(&format!("Figure {k}.")) || text.contains(&format!("FIGURE {k}.")),
            "{name}: the caption of figure {k} is not in the printed text"
        );
    }
    // Every note of the drawings printed whole, in the faces the page
    // carries (issue 22: a fallback face cut Fig. 5's note short).
    let bare = |s: &str| s.chars().filter(|c| !c.is_whitespace()).collect::<String>();
    let printed = bare(&text);
    let notes = report["notes"].as_array().unwrap();
    for note in notes {
        let note = note.as_str().unwrap().replace("&nbsp;", " ");
        assert!(
            printed.contains(&bare(&note)),
            "{name}: the note “{note}” is not whole in the printed text on {}",
            paper.pdfinfo
        );
    }
    assert_fonts_embedded(&pdf);
}

/// The printed PDF's faces: the page's own, every one embedded, no
/// fallback text face. Chromium embeds the faces a page carries (CFF
/// outlines) as Type 3 fonts, which have no name; a face it found on the
/// system has its name (`DejaVuSerif`). The monospace face of the
/// commands (`code`) is the reader's own.
fn assert_fonts_embedded(pdf: &Path) {
    let out = poppler("pdffonts", &[pdf.to_str().unwrap()]);
    let list = String::from_utf8_lossy(&out.stdout);
    let fonts: Vec<Vec<&str>> = list
        .lines()
        .skip(2)
        .map(|l| l.split_whitespace().collect())
        .collect();
    let carried =
        |name: &str| name == "[none]" || name.contains("NewCM") || name.contains("Libertinus");
    assert!(
        fonts.iter().any(|f| carried(f[0])),
        "{}: none of the page's faces: {list}",
        pdf.display()
    );
    for f in &fonts {
        assert!(
            carried(f[0]) || f[0].contains("Mono"),
            "{}: a fallback face {}: {list}",
            pdf.display(),
            f[0]
        );
        // The column "emb", fifth from the end, says yes.
        assert!(
            f.len() >= 6 && f[f.len() - 5] == "yes",
            "{}: {f:?}",
            pdf.display()
        );
    }
}

#[test]
#[ignore = "needs Chromium and poppler-utils: run with `-- --ignored` (.ci/run does)"]
fn the_gallery_index_shows_every_figure() {
    let browser = browser();
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("gallery");
    succeeded(&run(&["gallery", "--out", out.to_str().unwrap()]));
    let report = check_page(&browser, &out.join("index.html"));
    // Every figure of the gallery is shown (one PNG each).
    let shown = report["figures"].as_array().unwrap().len();
    let pngs = std::fs::read_dir(&out)
        .unwrap()
        .filter(|e| {
            e.as_ref()
                .unwrap()
                .path()
                .extension()
                .is_some_and(|x| x == "png")
        })
        .count();
    assert!(pngs >= 20, "{pngs} figures in the gallery");
    assert_eq!(shown, pngs, "figures shown in index.html");
}

#[test]
#[ignore = "needs Chromium and poppler-utils: run with `-- --ignored` (.ci/run does)"]
fn the_checks_fail_on_a_broken_page() {
    let browser = browser();
    let dir = tempfile::tempdir().unwrap();
    let page = |name: &str, body: &str| {
        let path = dir.path().join(name);
        std::fs::write(
            &path,
            format!("<!DOCTYPE html><html><head><title>t</title></head><body>{body}</body></html>"),
        )
        .unwrap();
        path
    };
    let fails = |path: PathBuf, what: &str| {
        let b = browser.clone();
        let r = std::panic::catch_unwind(move || check_page(&b, &path));
        assert!(r.is_err(), "{what} passed the check");
    };
    fails(
        page(
            "missing.html",
            r#"<img src="nowhere.png" width="50" height="50">"#,
        ),
        "a missing image",
    );
    fails(
        page("blank.html", r#"<svg width="200" height="100"></svg>"#),
        "a blank figure",
    );
    fails(
        page(
            "script.html",
            r#"<svg width="50" height="50"><rect width="50" height="50"/></svg><script>undefinedFunction()</script>"#,
        ),
        "a script error",
    );
    let tall = page(
        "tall.html",
        r#"<figure><svg width="100" height="3000"><rect width="100" height="3000"/></svg><figcaption>Figure 1.</figcaption></figure>"#,
    );
    let b = browser.clone();
    assert!(
        std::panic::catch_unwind(move || check_print(&b, &tall, &A4)).is_err(),
        "a figure taller than a page"
    );
    // And a sound page passes.
    check_page(
        &browser,
        &page(
            "sound.html",
            r#"<svg width="50" height="50"><rect width="50" height="50"/></svg>"#,
        ),
    );
}

#[test]
#[ignore = "needs Chromium and poppler-utils: run with `-- --ignored` (.ci/run does)"]
fn a_handout_loads_draws_and_prints_on_a4_and_letter() {
    let browser = browser();
    let dir = tempfile::tempdir().unwrap();
    // An offset engine in millimetres with its forces.
    let engine = "--crank 60 --rod 240 --offset 10 --unit mm --rpm 900 --angle 40 --torque 2000";
    let write = |name: &str, paper: &str| {
        let page = dir.path().join(name);
        let mut args = vec!["handout"];
        args.extend(engine.split(' '));
        args.extend(["--paper", paper, "--out", page.to_str().unwrap()]);
        succeeded(&run(&args));
        page
    };
    let page = write("engine.html", "a4");
    check_page(&browser, &page);
    check_print(&browser, &page, &A4);
    check_print(&browser, &write("letter.html", "letter"), &LETTER);
    // Issue 22's teacher's engine, whose Fig. 5 note and Fig. 8 legend a
    // fallback face once overran.
    let teacher =
        "--crank 60 --rod 240 --unit mm --rpm 1500 --angle 30 --torque 5000 --friction 0.1";
    for (file, paper, size) in [
        ("t-a4.html", "a4", &A4),
        ("t-letter.html", "letter", &LETTER),
    ] {
        let page = dir.path().join(file);
        let mut args = vec!["handout"];
        args.extend(teacher.split(' '));
        args.extend(["--paper", paper, "--out", page.to_str().unwrap()]);
        succeeded(&run(&args));
        check_print(&browser, &page, size);
        // Issue 22: pages half empty where a tall figure went on to the
        // next. Printed, it takes 10 A4 or 11 Letter pages (one more than
        // before the polygons' step), and every page but the last is set
        // at least half way down.
        let fills = page_fills(&page.with_extension("print.pdf"));
        println!(
            "{file}: {} pages set {fills:.2?} of the way down",
            fills.len()
        );
        let most = if paper == "a4" { 10 } else { 11 };
        assert!(fills.len() <= most, "{file}: {} pages", fills.len());
        for (k, fill) in fills.iter().enumerate().take(fills.len() - 1) {
            assert!(
                *fill >= 0.5,
                "{file}: page {} set {:.0} % of the way down: {fills:.2?}",
                k + 1,
                100.0 * fill
            );
        }
    }
}

#[test]
#[ignore = "needs Chromium and poppler-utils: run with `-- --ignored` (.ci/run does)"]
fn a_handout_with_the_engines_dynamics_prints_on_a4_and_letter() {
    let browser = browser();
    let dir = tempfile::tempdir().unwrap();
    // The §35 engine with a reciprocating mass: three more steps, each a
    // tall figure. Printed, 12 pages on either paper (one more since the
    // polygons' step), every page but the last at least half full.
    for (file, paper, size) in [
        ("d-a4.html", "a4", &A4),
        ("d-letter.html", "letter", &LETTER),
    ] {
        let page = dir.path().join(file);
        let args = ["handout", "--mass", "10", "--paper", paper, "--out"];
        let mut args = args.to_vec();
        args.push(page.to_str().unwrap());
        succeeded(&run(&args));
        if paper == "a4" {
            check_page(&browser, &page);
        }
        check_print(&browser, &page, size);
        let fills = page_fills(&page.with_extension("print.pdf"));
        println!(
            "{file}: {} pages set {fills:.2?} of the way down",
            fills.len()
        );
        assert!(fills.len() <= 12, "{file}: {} pages", fills.len());
        for (k, fill) in fills.iter().enumerate().take(fills.len() - 1) {
            assert!(
                *fill >= 0.5,
                "{file}: page {} set {:.0} % of the way down: {fills:.2?}",
                k + 1,
                100.0 * fill
            );
        }
    }
}

/// How far down each page of the printed `pdf` its text reaches: the
/// bottom of its lowest word (a figure's lowest text is its caption)
/// from the top of the printable page, as a fraction of the printable
/// height (the handout's margins: 14 mm top, 16 mm bottom).
fn page_fills(pdf: &Path) -> Vec<f64> {
    let out = poppler("pdftotext", &["-bbox", pdf.to_str().unwrap(), "-"]);
    let html = String::from_utf8_lossy(&out.stdout);
    let number = |tag: &str, name: &str| -> f64 {
        let at = tag.find(&format!("{name}=\"")).unwrap() + name.len() + 2;
        tag[at..at + tag[at..].find('"').unwrap()].parse().unwrap()
    };
    let pt_per_mm = 72.0 / 25.4;
    html.split("<page ")
        .skip(1)
        .map(|page| {
            let height = number(page, "height");
            let lowest = page
                .split("<word ")
                .skip(1)
                .map(|w| number(w, "yMax"))
                .fold(0.0, f64::max);
            (lowest - 14.0 * pt_per_mm) / (height - 30.0 * pt_per_mm)
        })
        .collect()
}

#[test]
#[ignore = "needs Chromium and poppler-utils: run with `-- --ignored` (.ci/run does)"]
fn an_exercise_sheet_and_its_key_load_draw_and_print_on_a4_and_letter() {
    let browser = browser();
    let dir = tempfile::tempdir().unwrap();
    for (paper, size) in [("a4", &A4), ("letter", &LETTER)] {
        let page = dir.path().join(format!("sheet-{paper}.html"));
        succeeded(&run(&[
            "handout",
            "--crank",
            "0.5",
            "--rod",
            "2.5",
            "--angle",
            "130",
            "--torque",
            "40",
            "--exercise",
            "--paper",
            paper,
            "--out",
            page.to_str().unwrap(),
        ]));
        let key = dir.path().join(format!("sheet-{paper}-key.html"));
        if paper == "a4" {
            check_page(&browser, &page);
            check_page(&browser, &key);
        }
        check_print(&browser, &page, size);
        check_print(&browser, &key, size);
    }
}

#[test]
#[ignore = "needs Chromium and poppler-utils: run with `-- --ignored` (.ci/run does)"]
fn an_animation_plays_and_its_frame_is_drawn() {
    let browser = browser();
    let dir = tempfile::tempdir().unwrap();
    let page = dir.path().join("kisch.html");
    succeeded(&run(&[
        "animate",
        "fig-66-kisch",
        "--frames",
        "24",
        "--period",
        "2",
        "--out",
        page.to_str().unwrap(),
    ]));
    // One frame shown at a time, drawn, with no script error.
    let report = check_page(&browser, &page);
    assert_eq!(report["figures"].as_array().unwrap().len(), 1, "{report}");
    // The page is the window's height, the frame scaled into what the
    // heading and the controls leave: it plays without scrolling.
    let window = f64::from(WINDOW);
    assert!(report["height"].as_f64().unwrap() <= window, "{report}");
    let frame = figure_box(&report["figures"][0]);
    assert!(
        frame[1] + frame[3] <= window,
        "the frame runs below the window: {frame:?}"
    );
    assert!(
        frame[3] >= 0.5 * window,
        "the frame is small in its window: {frame:?}"
    );
    // Printed, the frame shown keeps its faces and its notes whole.
    check_print(&browser, &page, &A4);
    check_print(&browser, &page, &LETTER);
    // Playing: two moments a second apart show different frames.
    let shot = |ms: u32| {
        let path = dir.path().join(format!("at-{ms}.png"));
        chromium_at(
            &browser,
            (SCREEN, 900),
            ms,
            &[&format!("--screenshot={}", path.display())],
            &url(&page),
        );
        std::fs::read(&path).unwrap()
    };
    assert!(shot(500) != shot(1500), "the animation does not move");
}

/// Prints the standalone SVG `svg` (opened as the browser opens a file)
/// to PDF and checks its faces are the figure's own, embedded.
fn check_svg_faces(browser: &Path, svg: &Path) {
    let pdf = svg.with_extension("print.pdf");
    chromium(
        browser,
        SCREEN,
        900,
        &[
            "--no-pdf-header-footer",
            &format!("--print-to-pdf={}", pdf.display()),
        ],
        &url(svg),
    );
    assert_fonts_embedded(&pdf);
}

#[test]
#[ignore = "needs Chromium and poppler-utils: run with `-- --ignored` (.ci/run does)"]
fn a_standalone_svg_with_embed_fonts_is_set_in_its_own_face() {
    let browser = browser();
    let dir = tempfile::tempdir().unwrap();
    // Italic letters, Greek, primes (from the maths face) and digits.
    for name in ["fig-67-example", "ng-fig-8-forces", "rod-motion"] {
        let svg = dir.path().join(format!("{name}.svg"));
        succeeded(&run(&[
            "figure",
            name,
            "--embed-fonts",
            "--out",
            svg.to_str().unwrap(),
        ]));
        check_svg_faces(&browser, &svg);
    }
    // Libertinus Serif too.
    let svg = dir.path().join("libertinus.svg");
    succeeded(&run(&[
        "figure",
        "fig-66-kisch",
        "--font",
        "libertinus-serif",
        "--embed-fonts",
        "--out",
        svg.to_str().unwrap(),
    ]));
    check_svg_faces(&browser, &svg);
}

/// Writes, once the page has loaded, the box (CSS px) round the
/// mechanism of the frame shown (its guides, block, rod, crank and crank
/// circle) and the window's size into the page as `<pre id="mechanism">`.
const MECHANISM_PROBE: &str = r#"<script>
window.addEventListener('load', () => {
  const frame = document.querySelector('.animation-frame:not([hidden])');
  const parts = ['guide-upper', 'guide-lower', 'block-slider', 'link-rod', 'link-crank', 'circle-crank'];
  const boxes = [...frame.querySelectorAll('[id]')]
    .filter(e => parts.some(p => e.id.endsWith('-' + p)))
    .map(e => e.getBoundingClientRect());
  const left = Math.min(...boxes.map(b => b.left)), right = Math.max(...boxes.map(b => b.right));
  const top = Math.min(...boxes.map(b => b.top)), bottom = Math.max(...boxes.map(b => b.bottom));
  const out = document.createElement('pre');
  out.id = 'mechanism';
  out.textContent = JSON.stringify({ parts: boxes.length, left, right, top, bottom,
    width: innerWidth, height: innerHeight, title: document.title });
  document.body.appendChild(out);
});
</script>"#;

#[test]
#[ignore = "needs Chromium and poppler-utils: run with `-- --ignored` (.ci/run does)"]
fn a_projected_animation_fills_a_1920_by_1080_screen() {
    let browser = browser();
    let dir = tempfile::tempdir().unwrap();
    let page = dir.path().join("klein.html");
    succeeded(&run(&[
        "animate",
        "fig-65-klein",
        "--projector",
        "--frames",
        "12",
        "--out",
        page.to_str().unwrap(),
    ]));
    let html = std::fs::read_to_string(&page).unwrap();
    // The heading names the engine drawn, not only the textbook's figure.
    assert!(html.contains("Fig. 65 (Klein’s construction): r = 0.5 ft, l = 3 ft, in line"));
    let at = html.find("<head>").unwrap() + "<head>".len();
    let probed = dir.path().join("probed.html");
    std::fs::write(
        &probed,
        format!("{}{MECHANISM_PROBE}{}", &html[..at], &html[at..]),
    )
    .unwrap();
    let dom = chromium_at(
        &browser,
        (1920, 1080),
        SETTLE_MS,
        &["--dump-dom"],
        &url(&probed),
    );
    let start = dom.find("<pre id=\"mechanism\">").expect("the probe ran") + 20;
    let end = start + dom[start..].find("</pre>").unwrap();
    let m: Value = serde_json::from_str(&dom[start..end].replace("&quot;", "\"")).unwrap();
    let number = |k: &str| m[k].as_f64().unwrap();
    assert_eq!(number("width"), 1920.0, "{m}");
    assert!(m["parts"].as_u64().unwrap() >= 6, "every part found: {m}");
    // The mechanism at least half the window's width, whole within it.
    let wide = number("right") - number("left");
    assert!(wide >= 960.0, "the mechanism is {wide} px wide: {m}");
    assert!(number("left") >= 0.0 && number("right") <= 1920.0, "{m}");
    assert!(
        number("top") >= 0.0 && number("bottom") <= number("height"),
        "{m}"
    );
}
