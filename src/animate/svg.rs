//! The self-playing SVG of an animation.
//!
//! One document the size of the frames (the tallest, should one need more
//! room for its notes): a `<metadata>` whose JSON is the first frame's
//! without what belongs to one pose (`angle_deg`, `points`,
//! `evaluations`) and with an `animation` object (`frames`, `period`,
//! `angles_deg`, the `id_prefix` of frame 0), then one group per frame
//! (`id="f000"`, `class="animation-frame"`, `data-angle-deg`), holding the still
//! figure with its ids prefixed (`f000-point-E`) and its own metadata.
//!
//! Each group carries an SMIL `<animate>` of its `visibility`
//! (`calcMode="discrete"`, `repeatCount="indefinite"`) that shows it for
//! its share of the period, the shares meeting at the same written key
//! times so that one frame shows at a time; Chromium and Firefox play it,
//! in a page or as an image. A viewer that does not animate (resvg, print)
//! shows the first frame: the others are hidden by their attribute.

use super::{FRAMES_HERE, Frame, Reel, split};
use crate::error::Result;
use crate::render::{Element, Node, fmt, root_size};
use serde_json::{Value, json};

/// The document written to `sink` a frame at a time, as `frames` are
/// drawn.
pub(super) fn write(
    animation: &Reel,
    frames: &mut dyn Iterator<Item = Frame>,
    sink: &mut dyn FnMut(&str) -> Result<()>,
) -> Result<()> {
    let skeleton = skeleton(animation);
    let (head, tail) = split(&skeleton);
    sink(head)?;
    let count = animation.angles().len();
    for (k, frame) in frames.enumerate() {
        if k > 0 {
            sink("\n")?;
        }
        sink(&group(&frame, k, count, animation.period()).to_string())?;
    }
    sink(tail)
}

/// The document with [`FRAMES_HERE`] where the frames' groups go.
fn skeleton(animation: &Reel) -> String {
    let (w, h) = (animation.width(), animation.height());
    let unit = animation.size_unit();
    let mut doc = Element::document()
        .set("width", root_size(w, unit))
        .set("height", root_size(h, unit))
        .set("viewBox", format!("0 0 {} {}", fmt(w), fmt(h)))
        .set("font-family", animation.font_family().to_owned());
    if let Some(title) = animation.title() {
        doc = doc.add(Element::text("title", title.to_owned()));
    }
    doc = doc.add(metadata(animation));
    doc = doc.add(Node::Block(FRAMES_HERE.into()));
    doc.to_document()
}

/// Frame `k` of `count`: its group, hidden but for the first, and the
/// animation that shows it in its turn.
fn group(frame: &Frame, k: usize, count: usize, period: f64) -> Element {
    let prefix = Frame::prefix(k);
    let mut g = Element::new("g");
    g.assign("id", prefix.trim_end_matches('-').to_owned());
    g.assign("class", "animation-frame");
    g.assign("data-angle-deg", fmt(frame.angle().degrees()));
    if k > 0 {
        g.assign("visibility", "hidden");
    }
    g.append(Node::Block(frame.body(&prefix)));
    g.append(turn(k, count, period));
    g
}

/// The `<animate>` that shows frame `k` of `count` from k/count to
/// (k + 1)/count of every period.
fn turn(k: usize, count: usize, period: f64) -> Element {
    let at = |i: usize| key_time(i, count);
    let (values, times) = match k {
        0 => ("visible;hidden".to_string(), format!("0;{}", at(1))),
        k if k + 1 == count => ("hidden;visible".to_string(), format!("0;{}", at(k))),
        k => (
            "hidden;visible;hidden".to_string(),
            format!("0;{};{}", at(k), at(k + 1)),
        ),
    };
    let mut a = Element::new("animate");
    a.assign("attributeName", "visibility");
    a.assign("calcMode", "discrete");
    a.assign("values", values);
    a.assign("keyTimes", times);
    a.assign("dur", format!("{}s", seconds(period)));
    a.assign("begin", "0s");
    a.assign("repeatCount", "indefinite");
    a
}

/// i/count written to 8 decimals: the same text for the end of one
/// frame's share and the start of the next.
fn key_time(i: usize, count: usize) -> String {
    let t = format!("{:.8}", i as f64 / count as f64);
    t.trim_end_matches('0').trim_end_matches('.').to_string()
}

/// A period in seconds, as given ([`super::MIN_PERIOD`] to
/// [`super::MAX_PERIOD`]).
pub(super) fn seconds(period: f64) -> String {
    // The shortest decimal that reads back as the period: exactly the
    // duration asked for, in at most a score of digits over the periods
    // allowed (1 ms to an hour).
    format!("{period}")
}

/// The document's metadata: the first frame's, less what belongs to its
/// pose, with the animation's own.
fn metadata(animation: &Reel) -> Element {
    let mut meta = animation.first().metadata();
    for key in ["angle_deg", "points", "evaluations"] {
        meta.remove(key);
    }
    meta.insert("height".into(), json!(animation.height()));
    let angles: Vec<f64> = animation.angles().iter().map(|a| a.degrees()).collect();
    meta.insert(
        "animation".into(),
        json!({
            "frames": angles.len(),
            "period": animation.period(),
            "angles_deg": angles,
            "id_prefix": Frame::prefix(0),
        }),
    );
    let json = serde_json::to_string(&Value::Object(meta)).unwrap_or_else(|_| "{}".into());
    Element::text("metadata", json)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shares_meet_at_the_same_key_times() {
        let count = 72;
        let keys: Vec<String> = (0..count)
            .map(|k| turn(k, count, 4.0).to_string())
            .collect();
        assert!(
            keys[0].contains(r#"keyTimes="0;0.01388889""#),
            "{}",
            keys[0]
        );
        assert!(keys[1].contains(r#"keyTimes="0;0.01388889;0.02777778""#));
        assert!(keys[71].contains(r#"values="hidden;visible""#));
        assert!(keys[71].contains(r#"keyTimes="0;0.98611111""#));
        assert!(keys[5].contains(r#"dur="4s""#));
        assert_eq!(key_time(1, 2), "0.5");
        // Written as given: 1.5 ms is not rounded to 2 ms.
        assert_eq!(seconds(0.0015), "0.0015");
        assert_eq!(seconds(0.001), "0.001");
        assert_eq!(seconds(2.5), "2.5");
        assert_eq!(seconds(3600.0), "3600");
    }
}
