//! `slider-crank animate`: one revolution of a mechanism figure, every
//! frame the still figure in one held view, written as a self-playing SVG
//! or an HTML page, and refused in one line when asked for the wrong thing.

use crate::command;
use crate::common;
use crate::plate;

use command::{run, succeeded};
use plate::Plate;
use slider_crank::animate::{Animation, Frame};
use slider_crank::catalogue::FigureOptions;
use slider_crank::render::to_svg;
use slider_crank::{Angle, FigureName};
use std::collections::HashSet;
use std::path::{Path, PathBuf};

/// A scratch directory of its own for each test.
fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!(
        "slider-crank-animate-{}-{name}",
        std::process::id()
    ));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// The animation the program writes for `args` into `file` in a scratch
/// directory, as text.
fn animate(name: &str, file: &str, args: &[&str]) -> String {
    let dir = scratch(name);
    let out = dir.join(file);
    let mut all = vec!["animate"];
    all.extend_from_slice(args);
    all.extend(["--out", out.to_str().unwrap()]);
    let result = run(&all);
    succeeded(&result);
    let text = std::fs::read_to_string(&out).unwrap();
    std::fs::remove_dir_all(&dir).unwrap();
    text
}

/// The content of a still figure's SVG: between its root's tags.
fn inner(svg: &str) -> &str {
    let start = svg.find('>').unwrap() + 1;
    let end = svg.rfind("</svg>").unwrap();
    svg[start..end].trim_matches('\n')
}

/// Each frame's content in an animation's SVG, in order, its ids
/// un-prefixed: the still figure's content, if all is well.
fn svg_frames(svg: &str) -> Vec<String> {
    let mut frames = Vec::new();
    for k in 0.. {
        let Some(at) = svg.find(&format!(" id=\"f{k:03}\"")) else {
            break;
        };
        let start = at + svg[at..].find('>').unwrap() + 1;
        let end = start + svg[start..].find("<animate ").unwrap();
        let body = svg[start..end].trim_matches('\n');
        frames.push(body.replace(&Frame::prefix(k), ""));
    }
    frames
}

/// Every `data-page-from-world` in `text`.
fn maps(text: &str) -> Vec<&str> {
    let key = "data-page-from-world=\"";
    text.match_indices(key)
        .map(|(at, _)| {
            let v = &text[at + key.len()..];
            &v[..v.find('"').unwrap()]
        })
        .collect()
}

/// Every `id="…"` value in `text`.
fn ids(text: &str) -> Vec<&str> {
    text.match_indices(" id=\"")
        .map(|(at, key)| {
            let v = &text[at + key.len()..];
            &v[..v.find('"').unwrap()]
        })
        .collect()
}

/// The scene of a named figure at its own parameters.
fn scene(name: FigureName) -> slider_crank::Scene {
    name.scene_with(&FigureOptions::default()).unwrap().unwrap()
}

/// The still figures of `animation` as `Scene::frames` draws them: in a
/// view held over every degree and the animation's own angles.
fn stills(scene: &slider_crank::Scene, animation: &Animation) -> Vec<String> {
    let angles: Vec<Angle> = animation.frames().iter().map(Frame::angle).collect();
    let mut held: Vec<Angle> = (0..360).map(|d| Angle::deg(f64::from(d))).collect();
    held.extend_from_slice(&angles);
    let held = scene.clone().with_held_view(held);
    held.frames(&angles).unwrap().iter().map(to_svg).collect()
}

#[test]
fn every_frame_is_the_still_figure_of_the_held_series() {
    let scene = scene(FigureName::Fig65Klein);
    let animation = Animation::new(&scene, 12, 3.0).unwrap();
    let stills = stills(&scene, &animation);
    assert_eq!(animation.frames().len(), 12);
    for (frame, still) in animation.frames().iter().zip(&stills) {
        assert_eq!(&frame.svg(), still, "at {}°", frame.angle().degrees());
    }
    // ... and the self-playing SVG holds them, ids un-prefixed, byte for
    // byte, as does the page.
    let played = svg_frames(&animation.to_svg());
    assert_eq!(played.len(), 12);
    for (k, (body, still)) in played.iter().zip(&stills).enumerate() {
        assert_eq!(body, inner(still), "frame {k}");
    }
    let page = animation.to_html();
    for (k, still) in stills.iter().enumerate() {
        let body = animation.frames()[k].body(&Frame::prefix(k));
        assert!(page.contains(&body), "frame {k} is not in the page");
        assert_eq!(body.replace(&Frame::prefix(k), ""), inner(still));
    }
}

#[test]
fn the_first_frame_draws_what_figure_draws_at_that_angle() {
    let svg = animate(
        "first",
        "kisch.svg",
        &["fig-66-kisch", "--angle", "60", "--frames", "8"],
    );
    // At 60° CE is long at both scales: a right-angle mark is drawn only
    // on a leg longer than two of its sides, so near a dead centre the
    // still (fitted to one pose, larger) may mark C where the held view
    // cannot.
    let still = run(&["figure", "fig-66-kisch", "--angle", "60"]);
    succeeded(&still);
    let still = String::from_utf8(still.stdout).unwrap();
    let frames = svg_frames(&svg);
    assert_eq!(frames.len(), 8);
    // The same pose and constructions, in world coordinates (the held
    // view maps them elsewhere on the page than the still's own fit).
    let (ours, theirs) = (common::metadata(&frames[0]), common::metadata(&still));
    for key in [
        "angle_deg",
        "points",
        "layers",
        "evaluations",
        "mechanism",
        "notation",
    ] {
        assert_eq!(ours[key], theirs[key], "{key}");
    }
    // The same primitives: every id of the still figure, and no other.
    let mut a: Vec<&str> = ids(&frames[0]).into_iter().collect();
    let mut b: Vec<&str> = ids(&still).into_iter().collect();
    a.sort_unstable();
    b.sort_unstable();
    assert_eq!(a, b);
}

#[test]
fn the_frames_share_one_page_map_and_the_mechanism_moves() {
    let svg = animate("maps", "klein.svg", &["fig-65-klein", "--frames", "12"]);
    let frames = svg_frames(&svg);
    assert_eq!(frames.len(), 12);
    let first = maps(&frames[0]);
    assert_eq!(first.len(), 2, "the mechanism and the detail");
    for (k, f) in frames.iter().enumerate() {
        assert_eq!(maps(f), first, "frame {k}");
    }
    // The slider and E move from one frame to the next.
    let meta: Vec<_> = frames.iter().map(|f| common::metadata(f)).collect();
    assert_ne!(meta[0]["points"]["A"], meta[1]["points"]["A"]);
    assert_ne!(meta[0]["points"]["E"], meta[1]["points"]["E"]);
    let block = |f: &str| common::attr(f, "block-slider", "d").expect("the slider is drawn");
    assert_ne!(block(&frames[0]), block(&frames[1]));
    let top = common::metadata(&svg);
    assert_eq!(top["animation"]["frames"], 12);
    assert_eq!(top["animation"]["period"], 4.0);
    assert_eq!(top["page_from_world"], meta[0]["page_from_world"]);
}

#[test]
fn d_runs_off_to_infinity_and_back_with_its_arrow() {
    let svg = animate(
        "infinity",
        "klein.svg",
        &["fig-65-klein", "--angle", "0", "--frames", "8"],
    );
    let frames = svg_frames(&svg);
    let mut kinds = Vec::new();
    for (k, f) in frames.iter().enumerate() {
        let d = &common::metadata(f)["points"]["D"];
        // 90° and 270° are frames 2 and 6: CB is perpendicular to the
        // stroke, D is a direction, drawn as an arrow at the frame's edge;
        // near them D is beyond the page, an arrow pointing to it.
        let at_infinity = d.get("at_infinity").is_some();
        assert_eq!(at_infinity, k == 2 || k == 6, "frame {k}: D = {d}");
        let mut drawn: Vec<&str> = ["point-D", "offpage-D", "infinity-D"]
            .into_iter()
            .filter(|id| f.contains(&format!(" id=\"{id}\"")))
            .collect();
        // At a dead centre D is at A: its dot is A's, lettered "A, D".
        if d == &common::metadata(f)["points"]["A"] {
            assert!(drawn.is_empty(), "frame {k}: D at A drawn apart {drawn:?}");
            assert!(letter_of(f, "label-A").contains("A, D"), "frame {k}");
            drawn.push("at A");
        }
        assert_eq!(drawn.len(), 1, "frame {k}: {drawn:?}");
        assert_eq!(drawn[0] == "infinity-D", at_infinity, "frame {k}");
        kinds.push(drawn[0]);
    }
    // At the dead centres with A, off the page near them, at infinity at
    // 90° and 270°.
    let seen: HashSet<&str> = kinds.iter().copied().collect();
    let want: HashSet<&str> = ["at A", "offpage-D", "infinity-D"].into();
    assert_eq!(seen, want, "{kinds:?}");
}

/// The text of the element `id` in `svg`, its tags left out.
fn letter_of(svg: &str, id: &str) -> String {
    let from = svg.find(&format!(" id=\"{id}\"")).unwrap_or(svg.len());
    let rest = &svg[from..];
    let open = rest.find('>').map_or(rest.len(), |i| i + 1);
    let close = rest.find("</text>").unwrap_or(rest.len());
    common::read_text(rest.get(open..close).unwrap_or(""))
}

#[test]
fn ids_are_unique_and_nothing_is_fetched() {
    let svg = animate("ids", "a.svg", &["fig-67-example", "--frames", "6"]);
    let html = animate(
        "ids",
        "a.html",
        &["fig-67-example", "--frames", "6", "--period", "2.5"],
    );
    for (what, text) in [("svg", &svg), ("html", &html)] {
        let all = ids(text);
        let unique: HashSet<&str> = all.iter().copied().collect();
        assert_eq!(all.len(), unique.len(), "{what}: an id repeats");
        // Every reference is to an id of the document.
        for (at, key) in text.match_indices("url(#") {
            let v = &text[at + key.len()..];
            let id = &v[..v.find(')').unwrap()];
            assert!(unique.contains(id), "{what}: url(#{id}) resolves");
        }
        let without_namespace = text.replace("xmlns=\"http://www.w3.org/2000/svg\"", "");
        for bad in [
            "http:", "https:", "src=", "@import", "<link", "<img", "<iframe",
        ] {
            assert!(!without_namespace.contains(bad), "{what}: {bad}");
        }
        for (at, key) in text.match_indices("href=\"") {
            let v = &text[at + key.len()..];
            assert!(
                v.starts_with('#'),
                "{what}: href to {}",
                &v[..v.find('"').unwrap()]
            );
        }
    }
    // The SVG plays by itself: one animation per frame, the first frame
    // shown without one.
    assert_eq!(svg.matches("<animate ").count(), 6);
    assert_eq!(svg.matches("calcMode=\"discrete\"").count(), 6);
    assert_eq!(svg.matches("visibility=\"hidden\"").count(), 5);
    // Nothing inside a frame sets its own visibility, which would show
    // through a hidden frame.
    assert_eq!(svg.matches(" visibility=").count(), 5);
    assert!(svg.starts_with("<svg") && svg.trim_end().ends_with("</svg>"));
    // The page: a slider over the frames, a play button, its script.
    assert!(html.starts_with("<!DOCTYPE html>"));
    assert!(html.contains(r#"type="range""#) && html.contains(r#"max="5""#));
    assert!(html.contains(r#"<button id="play""#));
    assert!(html.contains("<script>") && html.contains(r#"data-period="2.5""#));
    assert_eq!(html.matches(r#"class="animation-frame""#).count(), 6);
}

/// Runs `args` with `--out` a file in a scratch directory and asserts a
/// refusal: exit 2, one line naming `says`, no file.
fn refused(name: &str, args: &[&str], file: &str, says: &str) {
    let dir = scratch(name);
    let out = dir.join(file);
    let mut all = vec!["animate"];
    all.extend_from_slice(args);
    all.extend(["--out", out.to_str().unwrap()]);
    let result = run(&all);
    let stderr = String::from_utf8_lossy(&result.stderr);
    assert_eq!(result.status.code(), Some(2), "{args:?}: {stderr}");
    assert_eq!(stderr.lines().count(), 1, "{args:?}: {stderr}");
    assert!(stderr.contains(says), "{args:?}: {stderr}");
    assert!(result.stdout.is_empty());
    assert!(!Path::new(&out).exists(), "{args:?} wrote a file");
    assert_eq!(std::fs::read_dir(&dir).unwrap().count(), 0, "{args:?}");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn bad_requests_are_refused_in_one_line_and_write_nothing() {
    let k = "fig-66-kisch";
    refused("f0", &[k, "--frames", "0"], "a.svg", "2 to 3600 frames");
    refused("f1", &[k, "--frames", "1"], "a.svg", "2 to 3600 frames");
    refused(
        "fbig",
        &[k, "--frames", "100000"],
        "a.svg",
        "2 to 3600 frames",
    );
    refused("fneg", &[k, "--frames", "-3"], "a.svg", "--frames");
    refused("pneg", &[k, "--period", "-1"], "a.svg", "period");
    refused("p0", &[k, "--period", "0"], "a.svg", "period");
    refused("pnan", &[k, "--period", "nan"], "a.svg", "period");
    refused("pinf", &[k, "--period", "inf"], "a.html", "period");
    refused("gif", &[k], "x.gif", ".svg");
    refused("gif2", &[k], "x.gif", ".html");
    refused("png", &[k], "x.png", "not an animation format");
    let diagram = "fig-64-velocity-diagrams";
    refused(
        "diagram",
        &[diagram],
        "a.svg",
        "fig-64-velocity-diagrams is a diagram",
    );
    refused("diagram2", &[diagram], "a.html", "fig-66-kisch");
    refused("data", &[k, "--data", "x"], "a.svg", "takes no --data");
    refused("fit", &[k, "--fit", "both"], "a.svg", "takes no --fit");
    refused("rod", &[k, "--rod", "0.1"], "a.svg", "rod");
}

#[test]
fn an_existing_file_is_kept_when_the_request_is_refused() {
    let dir = scratch("keep");
    let out = dir.join("a.svg");
    std::fs::write(&out, "old").unwrap();
    let result = run(&[
        "animate",
        "fig-63-velocity",
        "--frames",
        "0",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(result.status.code(), Some(2));
    assert_eq!(std::fs::read_to_string(&out).unwrap(), "old");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_dash_prints_the_svg_and_a_bare_name_gets_svg() {
    let out = run(&[
        "animate",
        "fig-62-displacement",
        "--frames",
        "3",
        "--out",
        "-",
    ]);
    succeeded(&out);
    let printed = String::from_utf8(out.stdout).unwrap();
    assert!(printed.starts_with("<svg") && printed.contains("<animate "));
    assert_eq!(svg_frames(&printed).len(), 3);
    let written = animate("bare", "turn", &["fig-62-displacement", "--frames", "3"]);
    assert_eq!(written, printed);
}

#[test]
fn the_options_of_figure_reach_every_frame() {
    let svg = animate(
        "options",
        "ng.svg",
        &[
            "ng-fig-1-torque",
            "--frames",
            "4",
            "--offset",
            "5",
            "--style",
            "handout",
            "--unit",
            "in",
        ],
    );
    let frames = svg_frames(&svg);
    assert_eq!(frames.len(), 4);
    for f in &frames {
        let meta = common::metadata(f);
        assert_eq!(meta["mechanism"]["offset"], 5.0);
        assert_eq!(meta["mechanism"]["unit"], "in");
        assert_eq!(meta["style"], "handout");
    }
    let angles: Vec<f64> = frames
        .iter()
        .map(|f| common::metadata(f)["angle_deg"].as_f64().unwrap())
        .collect();
    let start = angles[0];
    for (k, a) in angles.iter().enumerate() {
        let want = (start + 90.0 * k as f64).rem_euclid(360.0);
        assert!((a - want).abs() < 1e-9, "frame {k}: {a} ≠ {want}");
    }
}

#[test]
fn help_offers_the_animation_flags_and_not_the_diagram_ones() {
    let out = run(&["animate", "--help"]);
    succeeded(&out);
    let text = String::from_utf8(out.stdout).unwrap();
    for flag in [
        "--frames", "--period", "--out", "--crank", "--layers", "--style",
    ] {
        assert!(text.contains(flag), "{flag}");
    }
    assert!(
        !text.contains("--data") && !text.contains("--fit"),
        "{text}"
    );
    assert!(text.contains("first frame"));
    assert!(text.matches("[default: 72]").count() == 1);
}

// ---------------------------------------------------------------- plates

/// Ink reaches this far (px) past the page at most.
const PAGE_SLACK: f64 = 0.5;
/// A point's letter lies within this many font sizes of its point.
const REACH_EM: f64 = 1.5;

/// The rules of the plate check that a frame of an animation must keep
/// in its held view: nothing off the page, every point lettered near it.
fn plate_failures(svg: &str) -> Vec<String> {
    let plate = Plate::read(svg);
    let page = plate.page().shrunk(-PAGE_SLACK);
    let mut out: Vec<String> = plate
        .ink
        .iter()
        .filter(|(_, r)| !page.contains(r))
        .map(|(id, _)| format!("off the page: {id}"))
        .collect();
    for panel in &plate.panels {
        for (letter, &at) in &panel.markers {
            if plate.page().distance_to(at) > 0.0 {
                continue;
            }
            let id = format!("{}label-{letter}", panel.prefix);
            // A pin inside a crank's detail is lettered in the detail only.
            let in_detail = |p: &&plate::Panel| {
                p.prefix == "detail-" && p.labels.iter().any(|l| l.id == format!("detail-{id}"))
            };
            match panel.labels.iter().find(|l| l.id == id) {
                None if panel.prefix.is_empty() && plate.panels.iter().any(|p| in_detail(&p)) => {}
                None => out.push(format!("{id} missing")),
                Some(l) if l.rect.distance_to(at) > REACH_EM * l.font_size => {
                    out.push(format!("{id} far from its point"))
                }
                Some(_) => {}
            }
        }
    }
    out
}

#[test]
fn frames_drawn_alone_are_plates() {
    let mut report = Vec::new();
    for name in [
        FigureName::Fig63Velocity,
        FigureName::Fig66Kisch,
        FigureName::NgFig1Torque,
    ] {
        let animation = Animation::new(&scene(name), 8, 4.0).unwrap();
        for frame in animation.frames() {
            for f in plate_failures(&frame.svg()) {
                report.push(format!("{name} at {}°: {f}", frame.angle().degrees()));
            }
        }
    }
    assert!(report.is_empty(), "{}", report.join("\n"));
}

// ------------------------------------------------------ in a browser

/// A headless Chromium on the path; a test that asked for it fails when
/// there is none.
fn chromium() -> &'static str {
    ["chromium", "chromium-browser", "google-chrome"]
        .into_iter()
        .find(|name| {
            std::process::Command::new(name)
                .arg("--version")
                .output()
                .is_ok_and(|o| o.status.success())
        })
        .expect(
            "no chromium, chromium-browser or google-chrome on the path: \
             install Chromium (Debian: chromium) to run this test",
        )
}

/// Chromium run headless on `file` with `args`, given a minute; its
/// standard output (through a file: a page's DOM fills a pipe).
fn browse(browser: &str, file: &Path, args: &[&str]) -> Vec<u8> {
    use std::process::{Command, Stdio};
    use std::time::{Duration, Instant};
    let url = format!("file://{}", file.display());
    let dump = file.with_extension("out");
    let mut child = Command::new(browser)
        .args(crate::browser::HEADLESS)
        .args(args)
        .arg(url)
        .stdout(std::fs::File::create(&dump).unwrap())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let deadline = Instant::now() + Duration::from_secs(60);
    while child.try_wait().unwrap().is_none() {
        if Instant::now() > deadline {
            child.kill().unwrap();
            panic!("{browser} took more than a minute on {}", file.display());
        }
        std::thread::sleep(Duration::from_millis(50));
    }
    std::fs::read(&dump).unwrap()
}

#[test]
#[ignore = "needs Chromium: run with `-- --ignored` (.ci/run does)"]
fn chromium_plays_the_page() {
    let browser = chromium();
    let dir = scratch("chromium");
    let (svg, html) = (dir.join("a.svg"), dir.join("a.html"));
    for out in [&svg, &html] {
        let path = out.to_str().unwrap();
        succeeded(&run(&[
            "animate",
            "fig-63-velocity",
            "--frames",
            "8",
            "--out",
            path,
        ]));
    }
    // The page's script moves the slider on: one frame shown, not the
    // first, and the angle written beside the slider is its angle.
    let dom = browse(
        browser,
        &html,
        &["--virtual-time-budget=3000", "--dump-dom"],
    );
    let dom = String::from_utf8(dom).unwrap();
    let shown: Vec<&str> = dom
        .match_indices("<div class=\"animation-frame\"")
        .map(|(at, _)| &dom[at..at + dom[at..].find('>').unwrap()])
        .filter(|tag| !tag.contains("hidden"))
        .collect();
    assert_eq!(shown.len(), 1, "{shown:?}");
    assert!(!shown[0].contains("id=\"f000\""), "still the first frame");
    let angle = shown[0].split("data-angle-deg=\"").nth(1).unwrap();
    let angle = &angle[..angle.find('"').unwrap()];
    assert!(dom.contains(&format!("θ = {angle}°")), "{angle}");
    // That the SVG plays by itself is not asserted here: headless
    // Chromium advances SMIL only as it paints frames, which a loaded
    // machine may not do within a virtual-time budget.
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn the_page_is_headed_by_the_figure_and_its_slider_speaks_the_angle() {
    // Issue 22: the heading was the slug, the slider announced 0–71.
    let html = animate("a11y", "k.html", &["fig-66-kisch", "--frames", "4"]);
    let h1 = &html[html.find("<h1>").unwrap() + 4..html.find("</h1>").unwrap()];
    assert!(
        h1.contains("Fig. 66") && !h1.contains("fig-66-kisch"),
        "{h1}"
    );
    // And the engine drawn, not only the textbook's figure.
    assert!(h1.ends_with(": r = 0.5 ft, l = 3 ft, in line"), "{h1}");
    let offset = animate(
        "a11y-offset",
        "k.html",
        &[
            "fig-66-kisch",
            "--frames",
            "4",
            "--crank",
            "60",
            "--rod",
            "250",
            "--offset",
            "-12",
            "--unit",
            "mm",
        ],
    );
    assert!(
        offset.contains(": r = 60 mm, l = 250 mm, e = −12 mm</h1>"),
        "the offset engine"
    );
    let slider = &html[html.find("<input").unwrap()..];
    let slider = &slider[..slider.find('>').unwrap()];
    assert!(slider.contains("aria-valuetext=\"θ = 60°\""), "{slider}");
    // The script keeps it in step with the frame shown.
    assert!(html.contains("setAttribute('aria-valuetext'"), "the script");
    let titled = animate(
        "a11y-title",
        "k.html",
        &["fig-66-kisch", "--frames", "4", "--title", "Kisch"],
    );
    assert!(titled.contains("<h1>Kisch</h1>"));
}
