//! The HTML page of an animation: the frames inline, one shown at a time,
//! a range slider over the frames to scrub the crank angle and a
//! play/pause button, driven by a small inline script. Nothing is
//! fetched; without the script the page shows the first frame, and a
//! printed page shows the frame on screen without the controls.

use super::svg::seconds;
use super::{FRAMES_HERE, Frame, Reel, split};
use crate::error::Result;
use crate::render::{fmt, root_size};
use maud::{Markup, PreEscaped, html};

/// The page's style, after the shared book page ([`crate::html::document`]).
/// On a screen the page is the window: the heading and the controls take
/// what they need and the frame is scaled into the rest, as large as the
/// window's width and height allow (never below 16rem), so that the whole
/// drawing plays without scrolling and fills a projector's screen; a
/// printed page keeps the book's measure.
const STYLE: &str = "
body { max-width: 64rem; }
.stage svg { display: block; max-width: 100%; height: auto; }
@media screen {
  body { display: flex; flex-direction: column; box-sizing: border-box; height: 100vh;
         max-width: none; margin-top: 0; margin-bottom: 0; padding: 1rem 2rem; }
  h1 { margin-top: 0; }
  .stage { flex: 1 1 0; min-height: 16rem; }
  .animation-frame { height: 100%; }
  .stage svg { width: 100%; height: 100%; }
}
.controls { display: flex; align-items: center; gap: 1rem; padding: .5rem 0; position: sticky;
            top: 0; background: #fff; }
.controls input { flex: 1; }
.controls output { min-width: 6em; font-variant-numeric: tabular-nums; }
@media print { .controls { display: none; } }
";

/// Shows one frame at a time: the slider picks it, the button plays the
/// revolution in its period from the frame shown (and pauses), playing
/// from the start unless the reader prefers reduced motion.
const SCRIPT: &str = "
(() => {
  const stage = document.getElementById('stage');
  const frames = stage.querySelectorAll(':scope > .animation-frame');
  const slider = document.getElementById('angle');
  const value = document.getElementById('angle-value');
  const degrees = document.getElementById('angle-deg');
  const button = document.getElementById('play');
  const step = Number(stage.dataset.period) * 1000 / frames.length;
  let shown = 0, timer = null, start = 0, from = 0;
  const show = (k) => {
    frames[shown].hidden = true;
    frames[k].hidden = false;
    shown = k;
    slider.value = k;
    degrees.textContent = frames[k].dataset.angleDeg;
    slider.setAttribute('aria-valuetext', value.textContent);
  };
  const tick = () => {
    const k = (from + Math.floor((performance.now() - start) / step)) % frames.length;
    if (k !== shown) show(k);
  };
  const play = () => {
    from = shown;
    start = performance.now();
    timer = setInterval(tick, Math.max(step / 2, 10));
    button.textContent = 'Pause';
    button.setAttribute('aria-pressed', 'true');
  };
  const pause = () => {
    clearInterval(timer);
    timer = null;
    button.textContent = 'Play';
    button.setAttribute('aria-pressed', 'false');
  };
  button.addEventListener('click', () => (timer === null ? play() : pause()));
  slider.addEventListener('input', () => { pause(); show(Number(slider.value)); });
  if (!matchMedia('(prefers-reduced-motion: reduce)').matches) play();
})();
";

/// What the page is headed with: the title given, as given; else the
/// figure's place in its source (`Textbook, Chapter IV “Slider-crank
/// chains”, §36, Fig. 66 (Kisch’s construction)`), or the scene's name,
/// followed by the engine drawn ([`engine`]), which the source alone does
/// not name.
fn heading(animation: &Reel) -> String {
    if let Some(t) = animation.title() {
        return t.to_string();
    }
    let base = crate::catalogue::FigureName::from_name(animation.name())
        .map(|f| f.source())
        .unwrap_or_else(|_| animation.name().to_string());
    match engine(animation) {
        Some(engine) => format!("{base}: {engine}"),
        None => base,
    }
}

/// The engine the frames draw, from the first frame's metadata: `r = 0.5
/// ft, l = 3 ft, in line` (or `e = …`); `None` where the metadata has no
/// mechanism.
fn engine(animation: &Reel) -> Option<String> {
    let m = animation.first().engine()?;
    let (r, l, e, unit) = (m.crank, m.rod, m.offset, &m.unit);
    let show = |x: f64| crate::number::short_on(x, crate::number::SetOn::Page);
    let line = if e == 0.0 {
        "in line".to_string()
    } else {
        format!("e = {} {unit}", show(e))
    };
    Some(format!(
        "r = {} {unit}, l = {} {unit}, {line}",
        show(r),
        show(l)
    ))
}

/// The page written to `sink` a frame at a time, as `frames` are drawn.
pub(super) fn write(
    animation: &Reel,
    frames: &mut dyn Iterator<Item = Frame>,
    sink: &mut dyn FnMut(&str) -> Result<()>,
) -> Result<()> {
    let heading = heading(animation);
    let skeleton = skeleton(animation, &heading);
    let (head, tail) = split(&skeleton);
    sink(head)?;
    for (k, frame) in frames.enumerate() {
        sink(&frame_view(animation, &heading, &frame, k).into_string())?;
    }
    sink(tail)
}

/// The page with [`FRAMES_HERE`] where the frames go.
fn skeleton(animation: &Reel, heading: &str) -> String {
    let first = animation.first();
    let count = animation.angles().len();
    let title = format!("{heading}: one revolution of the crank");
    let body = html! {
        h1 { (heading) }
        p {
            "One revolution of the crank in " (count) " frames, "
            (seconds(animation.period())) " s a turn; the slider sets the crank angle "
            i { "θ" } "."
        }
        div .controls {
            button #play type="button" aria-pressed="false" { "Play" }
            input #angle type="range" min="0" max=(count - 1)
                step="1" value="0" aria-label="Crank angle θ"
                aria-valuetext={ "θ = " (fmt(first.angle().degrees())) "°" };
            output #angle-value for="angle" {
                i { "θ" } " = " span #angle-deg { (fmt(first.angle().degrees())) } "°"
            }
        }
        div #stage .stage data-period=(animation.period()) {
            (PreEscaped(FRAMES_HERE))
        }
        script { (PreEscaped(SCRIPT)) }
    };
    // The frames are written into the page after it is made: its faces
    // carry the first frame's characters, and every digit, sign and unit
    // the other frames' numbers may hold.
    let frames = format!(
        "{}0123456789.,+-\u{2212}°{}",
        frame_view(animation, heading, first, 0).into_string(),
        animation.font_family()
    );
    crate::html::document_covering(&title, STYLE, body, &frames)
}

/// Frame `k` as an inline SVG in its own block, hidden but for the first.
fn frame_view(animation: &Reel, heading: &str, frame: &Frame, k: usize) -> Markup {
    let prefix = Frame::prefix(k);
    let (w, h) = (animation.width(), animation.height());
    let unit = animation.size_unit();
    html! {
        div .animation-frame id=(prefix.trim_end_matches('-')) hidden[k > 0]
            data-angle-deg=(fmt(frame.angle().degrees())) {
            svg xmlns="http://www.w3.org/2000/svg" width=(root_size(w, unit))
                height=(root_size(h, unit)) viewBox={ "0 0 " (fmt(w)) " " (fmt(h)) }
                font-family=(animation.font_family()) role="img"
                aria-label={ (heading) " at θ = " (fmt(frame.angle().degrees())) "°" } {
                (PreEscaped(frame.body(&prefix)))
            }
        }
    }
}
