//! Helpers shared by the figure tests (a module of each test crate:
//! `tests/library`, `tests/rendering`, `tests/program`).

#[cfg(feature = "png")]
use resvg::tiny_skia;

/// `svg` rendered through resvg at scale 1.
#[cfg(feature = "png")]
pub fn render(svg: &str) -> tiny_skia::Pixmap {
    let png = slider_crank::render::to_png(svg, 1.0).unwrap();
    tiny_skia::Pixmap::decode_png(&png).unwrap()
}

/// The dark pixels of a rendering and all its pixels: (dark, total).
#[cfg(feature = "png")]
pub fn inked(pixmap: &tiny_skia::Pixmap) -> (usize, usize) {
    let dark = pixmap
        .pixels()
        .iter()
        .filter(|p| (p.red() as u32 + p.green() as u32 + p.blue() as u32) < 300)
        .count();
    (dark, (pixmap.width() * pixmap.height()) as usize)
}

/// Insta settings that keep snapshots in the top-level `snapshots/` (the
/// path is taken from the asserting file, one of `tests/<crate>/*.rs`),
/// named by the name the test gives, without the module path.
pub fn snapshot_settings() -> insta::Settings {
    let mut s = insta::Settings::clone_current();
    s.set_snapshot_path("../../snapshots");
    s.set_prepend_module_to_snapshot(false);
    s
}

/// The points of the first path inside the element `id` (a group: an
/// arrow's shaft and head, an arc): every pair of numbers of its `d`
/// (moves' and lines' ends, and a curve's controls and ends), page units.
pub fn group_path(svg: &str, id: &str) -> Vec<(f64, f64)> {
    let at = svg.find(&format!("id=\"{id}\"")).expect(id);
    let d = svg[at..]
        .split(" d=\"")
        .nth(1)
        .and_then(|s| s.split('"').next())
        .unwrap_or_else(|| panic!("no path in {id}"));
    let numbers: Vec<f64> = d
        .split(|c: char| c.is_ascii_alphabetic() || c.is_whitespace())
        .filter_map(|w| w.parse().ok())
        .collect();
    numbers.chunks(2).map(|p| (p[0], p[1])).collect()
}

/// The `<metadata>` JSON of an SVG.
pub fn metadata(svg: &str) -> serde_json::Value {
    let a = svg.find("<metadata>").unwrap() + "<metadata>".len();
    let b = svg.find("</metadata>").unwrap();
    let text = svg[a..b]
        .replace("&lt;", "<")
        .replace("&gt;", ">")
        .replace("&amp;", "&");
    serde_json::from_str(&text).unwrap()
}

/// The start tag of the element with `id`.
pub fn tag<'a>(svg: &'a str, id: &str) -> Option<&'a str> {
    let at = svg.find(&format!("id=\"{id}\""))?;
    let start = svg[..at].rfind('<')?;
    let end = at + svg[at..].find('>')?;
    Some(&svg[start..end])
}

/// The text of attribute `name` of the element with `id`.
pub fn attr(svg: &str, id: &str, name: &str) -> Option<String> {
    let t = tag(svg, id)?;
    let key = format!(" {name}=\"");
    let v = t.find(&key)? + key.len();
    Some(t[v..v + t[v..].find('"')?].to_string())
}

/// The page distance from `p` to the segment `a`–`b` (to `a` where the
/// segment is a point).
pub fn segment_distance(p: (f64, f64), a: (f64, f64), b: (f64, f64)) -> f64 {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let len2 = dx * dx + dy * dy;
    let t = if len2 == 0.0 {
        0.0
    } else {
        (((p.0 - a.0) * dx + (p.1 - a.1) * dy) / len2).clamp(0.0, 1.0)
    };
    (p.0 - a.0 - t * dx).hypot(p.1 - a.1 - t * dy)
}

/// The box of `points` as (x0, x1, y0, y1); infinite and reversed for
/// none.
pub fn bounds_of(points: &[(f64, f64)]) -> (f64, f64, f64, f64) {
    let xs = points.iter().map(|p| p.0);
    let ys = points.iter().map(|p| p.1);
    (
        xs.clone().fold(f64::MAX, f64::min),
        xs.fold(f64::MIN, f64::max),
        ys.clone().fold(f64::MAX, f64::min),
        ys.fold(f64::MIN, f64::max),
    )
}

/// A numeric attribute of the element with `id`; panics if missing.
pub fn num(svg: &str, id: &str, name: &str) -> f64 {
    attr(svg, id, name)
        .unwrap_or_else(|| panic!("no {name} on #{id}"))
        .parse()
        .unwrap()
}

/// The text of `svg` as a reader sees it: its tags dropped, its no-break
/// spaces (a run's edge spaces) read as spaces.
pub fn read_text(svg: &str) -> String {
    let mut text = String::new();
    let mut in_tag = false;
    for ch in svg.chars() {
        match ch {
            '<' => in_tag = true,
            '>' => in_tag = false,
            '\u{a0}' if !in_tag => text.push(' '),
            _ if !in_tag => text.push(ch),
            _ => {}
        }
    }
    text
}

/// The page sizes an author fixes (issue 20): a column of 120 mm, a
/// 4.5-inch column, and a wide short page (width, height).
pub const FIXED_PAGES: [(&str, Option<&str>); 3] =
    [("120mm", None), ("4.5in", None), ("800", Some("300"))];

/// Figure options asking for a page `width` wide and, if given, `height`
/// tall (as `--width`, `--height` spell them).
pub fn on_page(width: &str, height: Option<&str>) -> slider_crank::catalogue::FigureOptions {
    let mut options = slider_crank::catalogue::FigureOptions::default();
    options.width = Some(width.parse().unwrap());
    options.height = height.map(|h| h.parse().unwrap());
    options
}

/// Threads a suite's long loop runs on (CI has two cores).
pub const THREADS: usize = 2;

/// `f` of every item, in the items' order, the items dealt round-robin
/// over [`THREADS`] threads (none: an empty list). A panic in `f` is
/// raised again in the caller, its message kept.
pub fn in_threads<T: Sync, R: Send>(items: &[T], f: impl Fn(&T) -> R + Sync) -> Vec<R> {
    let f = &f;
    let mut done: Vec<(usize, R)> = std::thread::scope(|s| {
        let handles: Vec<_> = (0..THREADS)
            .map(|t| {
                let mine = items.iter().enumerate().skip(t).step_by(THREADS);
                s.spawn(move || mine.map(|(i, x)| (i, f(x))).collect::<Vec<_>>())
            })
            .collect();
        handles
            .into_iter()
            .flat_map(|h| h.join().unwrap_or_else(|e| std::panic::resume_unwind(e)))
            .collect()
    });
    done.sort_by_key(|(i, _)| *i);
    done.into_iter().map(|(_, r)| r).collect()
}

/// The tail and the tip of the arrow `id` on the page: the start of its
/// shaft and the first point of its head (the renderer draws the head
/// from the tip). Panics where there is no such arrow.
pub fn arrow_ends(svg: &str, id: &str) -> ((f64, f64), (f64, f64)) {
    let at = svg
        .find(&format!("id=\"{id}\""))
        .unwrap_or_else(|| panic!("no {id}"));
    let mut starts = svg[at..].split(" d=\"M").skip(1).map(|s| {
        let end = s.find(|c: char| c.is_ascii_alphabetic()).unwrap();
        let mut xy = s[..end]
            .split_whitespace()
            .map(|v| v.parse::<f64>().unwrap());
        (xy.next().unwrap(), xy.next().unwrap())
    });
    (starts.next().unwrap(), starts.next().unwrap())
}

/// The strokes of the group `id` (each path's pieces from one `M` to the
/// next), page units; empty where there is no such group.
pub fn group_strokes(svg: &str, id: &str) -> Vec<((f64, f64), (f64, f64))> {
    let Some(at) = svg.find(&format!("id=\"{id}\"")) else {
        return Vec::new();
    };
    let end = at + svg[at..].find("</g>").expect("group closed");
    let mut strokes = Vec::new();
    for d in svg[at..end].split(" d=\"").skip(1) {
        let d = &d[..d.find('"').expect("d closed")];
        for piece in d.split('M') {
            let numbers: Vec<f64> = piece
                .split(|c: char| c == 'L' || c == 'Z' || c.is_whitespace())
                .filter_map(|w| w.parse().ok())
                .collect();
            let points: Vec<(f64, f64)> = numbers.chunks(2).map(|p| (p[0], p[1])).collect();
            strokes.extend(points.windows(2).map(|w| (w[0], w[1])));
        }
    }
    strokes
}
