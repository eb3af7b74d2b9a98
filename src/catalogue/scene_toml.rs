//! Scene files written out: the TOML of a named figure with every key it
//! uses at the figure's own value, each with a comment, as a starting
//! point. The parser reads it back to the same figure.

use super::specs::At;
use super::{FigureName, Setting, parse};
use crate::figure::{PageLength, PageUnit};
use crate::scene::{Layer, Scene};
use std::fmt::Write;

/// A number as TOML: an integer where the value is one (`45`, `250`),
/// else the shortest text that reads back to the same f64 (`0.01`,
/// `1e-100`).
fn number(v: f64) -> String {
    if v == v.trunc() && v.abs() < 1e15 {
        format!("{}", v as i64)
    } else {
        format!("{v:?}")
    }
}

/// A text as a TOML string, quoted and escaped.
fn text(s: &str) -> String {
    toml::Value::String(s.to_string()).to_string()
}

/// A page length in `unit` that reads back to `units` page units exactly
/// (`"160mm"`), or the page units themselves.
fn page_length(units: f64, unit: PageUnit) -> String {
    if unit.is_physical() {
        let mut v = units / unit.page_units();
        for _ in 0..8 {
            match PageLength::new(v, unit) {
                Ok(l) if l.page_units() == units => return text(&format!("{}{unit}", number(v))),
                Ok(l) if l.page_units() < units => v = v.next_up(),
                _ => v = v.next_down(),
            }
        }
    }
    number(units)
}

/// The crank speed as `rpm = N` where a number of revolutions per minute
/// reads back to `omega` exactly, else as `omega = W`.
fn speed(omega: f64) -> String {
    let rpm = omega * 60.0 / std::f64::consts::TAU;
    let round: f64 = format!("{rpm:.9e}").parse().unwrap_or(rpm);
    match [round, rpm]
        .into_iter()
        .find(|n| crate::analytic::kinematics::rpm_to_omega(*n) == omega)
    {
        Some(n) => format!("rpm = {}", number(n)),
        None => format!("omega = {}", number(omega)),
    }
}

/// Appends `comment` as `#` lines of at most 78 characters.
fn comment(out: &mut String, comment: &str) {
    let mut line = String::from("#");
    for word in comment.split(' ') {
        if line.len() > 1 && line.chars().count() + 1 + word.chars().count() > 78 {
            let _ = writeln!(out, "{line}");
            line = String::from("#");
        }
        line.push(' ');
        line.push_str(word);
    }
    let _ = writeln!(out, "{line}");
}

/// Appends `comment` and `line`.
fn key(out: &mut String, text: &str, line: &str) {
    comment(out, text);
    let _ = writeln!(out, "{line}");
}

const VERSION: &str = "The version of the scene file format (1, the one this program reads).";
const STYLE: &str = "The style: textbook (black ink) or handout (colour).";
const FONT: &str = "The face of the text: new-computer-modern or libertinus-serif.";
const TITLE: &str =
    "A title set centred below the figure (*A* italic, V_p a subscript); none by default.";
const MECHANISM: &str = "Crank radius r, rod length l (> r + |e|) and offset e of the line of stroke, in the length unit.";
const UNITS: &str = "The names of the units, written beside quantities; no number is converted.";
const PAGE: &str = "The page: a number of page units (px, 96 to the inch), or a text with its unit, \"120mm\" or \"4.5in\".";

fn mechanism_table(out: &mut String, m: &crate::mechanism::SliderCrank) {
    out.push_str("\n[mechanism]\n");
    comment(out, MECHANISM);
    let _ = writeln!(out, "crank = {}", number(m.crank()));
    let _ = writeln!(out, "rod = {}", number(m.rod()));
    let _ = writeln!(out, "offset = {}", number(m.offset()));
}

fn units_table(out: &mut String, units: &crate::units::Units) {
    out.push_str("\n[units]\n");
    comment(out, UNITS);
    let _ = writeln!(out, "length = {}", text(units.length().as_str()));
    let _ = writeln!(out, "force = {}", text(units.force().as_str()));
}

/// The opening of a file printed for `name`: what it is (`what`), how to
/// use it, anything `more` to say, and its version.
fn header(out: &mut String, what: &str, name: FigureName, more: &str) {
    comment(
        out,
        &format!(
            "{what}: `slider-crank scene` on this file draws what `slider-crank figure {0}` draws. Change a value, or delete a key to take its default (docs/scene-format.md).{more}",
            name.name()
        ),
    );
    out.push('\n');
    key(out, VERSION, &format!("version = {}", parse::VERSION));
}

/// The scene file of a mechanism figure's `scene`, every key given:
/// reading it back gives the same scene (a held view, which no key
/// expresses, aside).
pub(crate) fn scene(name: FigureName, scene: &Scene) -> String {
    let mut out = String::new();
    header(
        &mut out,
        &format!(
            "The scene of {} with every key at the figure's own value",
            name.name()
        ),
        name,
        "",
    );
    pose_keys(&mut out, scene);
    look_keys(&mut out, scene);
    motion_keys(&mut out, scene);
    mechanism_table(&mut out, scene.mechanism());
    units_table(&mut out, scene.units());
    let page = scene.page();
    out.push_str("\n[page]\n");
    comment(
        &mut out,
        &format!(
            "{PAGE} The height is the most the figure takes: it ends below its drawing. The margin is in page units."
        ),
    );
    let _ = writeln!(out, "width = {}", page_length(page.width(), page.unit()));
    let _ = writeln!(out, "height = {}", page_length(page.height(), page.unit()));
    let _ = writeln!(out, "margin = {}", number(page.margin()));
    out
}

/// A scene's name, its pose or poses, and its layers.
fn pose_keys(out: &mut String, scene: &Scene) {
    key(
        out,
        "The name written in the figure's metadata.",
        &format!("name = {}", text(scene.name())),
    );
    let degrees: Vec<String> = scene.angles().iter().map(|a| number(a.degrees())).collect();
    if let [one] = degrees.as_slice() {
        key(
            out,
            "Crank angle θ in degrees, counter-clockwise from the line of stroke (0: outer dead centre).",
            &format!("angle = {one}"),
        );
    } else {
        key(
            out,
            "The poses, degrees: the first carries the constructions, the others are ghosts.",
            &format!("angles = [{}]", degrees.join(", ")),
        );
    }
    let all: Vec<&str> = Layer::ALL.iter().map(|l| l.name()).collect();
    let layers: Vec<String> = scene.layers().iter().map(|l| text(l.name())).collect();
    key(
        out,
        &format!("The layers drawn, any of: {}.", all.join(", ")),
        &format!("layers = [{}]", layers.join(", ")),
    );
}

/// A scene's style, face, letters and side.
fn look_keys(out: &mut String, scene: &Scene) {
    key(
        out,
        STYLE,
        &format!("style = {}", text(scene.style().name())),
    );
    key(out, FONT, &format!("font = {}", text(scene.font().name())));
    key(
        out,
        "The letters: textbook (C, B, A, D, E) or ng (O, C, P, I, M).",
        &format!("notation = {}", text(scene.notation().name())),
    );
    key(
        out,
        "Whether the cylinder is drawn on the left, as the textbook draws it.",
        &format!("mirror = {}", scene.is_mirrored()),
    );
}

/// `coupler = t`, or `coupler = [t, h]` for a point off the rod's line.
fn coupler(scene: &Scene) -> String {
    let q = scene.coupler();
    match q.across() {
        0.0 => format!("coupler = {}", number(q.t())),
        h => format!("coupler = [{}, {}]", number(q.t()), number(h)),
    }
}

/// A scene's speed, torque, coupler point, tolerance and title.
fn motion_keys(out: &mut String, scene: &Scene) {
    key(
        out,
        "Crank speed, revolutions per minute (or omega, rad/s; counter-clockwise when positive).",
        &speed(scene.omega()),
    );
    key(
        out,
        "Crank torque of the torque layer, force × length.",
        &format!("torque = {}", number(scene.torque())),
    );
    key(
        out,
        "The point of the rod whose path the coupler layer draws, from A (0) to B (1).",
        &coupler(scene),
    );
    key(
        out,
        "The drawing tolerance of curves, page units.",
        &format!("tolerance = {}", number(scene.tolerance())),
    );
    match scene.title() {
        Some(t) => key(out, TITLE, &format!("title = {}", text(t.as_str()))),
        None => key(out, TITLE, "# title = \"…\""),
    }
}

/// The scene file of a diagram: `figure` and the keys it uses, at its own
/// values.
pub(crate) fn diagram(name: FigureName) -> String {
    let takes = |s: Setting| name.takes(s);
    let mut out = String::new();
    let data = match (takes(Setting::Data), takes(Setting::Fit)) {
        (true, true) => " Its measured data and its fit are not keys of a scene file.",
        (true, false) => " Its measured data is not a key of a scene file.",
        _ => "",
    };
    header(
        &mut out,
        &format!(
            "The diagram {} with every key it takes at its own value",
            name.name()
        ),
        name,
        data,
    );
    key(
        &mut out,
        "The diagram: its keys below change it.",
        &format!("figure = {}", text(name.name())),
    );
    diagram_keys(&mut out, name);
    if takes(Setting::Mechanism) {
        mechanism_table(&mut out, &name.mechanism());
    }
    units_table(&mut out, &name.units());
    let page = name.page();
    out.push_str("\n[page]\n");
    comment(
        &mut out,
        &format!("{PAGE} The diagram lays its plots out on it."),
    );
    if narrowed(name) {
        comment(
            &mut out,
            "The figure's own page is narrowed to what the diagram draws; a width given is kept.",
        );
        let _ = writeln!(out, "# width = {}", number(page.width()));
    } else {
        let _ = writeln!(out, "width = {}", number(page.width()));
    }
    let _ = writeln!(out, "height = {}", number(page.height()));
    out
}

/// Whether the diagram at its defaults comes out narrower than its page
/// (Inversion 2 and the coupler curves narrow their own page to what they
/// draw): its scene file then leaves the width out, since a width given
/// is kept.
fn narrowed(name: FigureName) -> bool {
    name.figure(&super::FigureOptions::default())
        .is_ok_and(|f| f.width() < name.page().width())
}

/// The keys a diagram takes beside `figure`, each at its own value:
/// the angle (or the plane's tilt), speed, style, face, side, mass and
/// coefficient of fluctuation, and the title.
fn diagram_keys(out: &mut String, name: FigureName) {
    let takes = |s: Setting| name.takes(s);
    if takes(Setting::Angle) {
        let what = if matches!(name.spec().at, At::Tilt(_)) {
            "The tilt of the plane, degrees (0 < φ < 90)."
        } else {
            "Crank angle θ of the pose whose construction is drawn, degrees."
        };
        key(
            out,
            what,
            &format!("angle = {}", number(name.angle_degrees())),
        );
    }
    if takes(Setting::Speed) {
        key(
            out,
            "Crank speed, revolutions per minute (or omega, rad/s), positive.",
            &speed(crate::analytic::kinematics::rpm_to_omega(
                crate::sources::RPM,
            )),
        );
    }
    key(out, STYLE, "style = \"textbook\"");
    key(
        out,
        FONT,
        &format!("font = {}", text(crate::figure::Font::default().name())),
    );
    if takes(Setting::Mirror) {
        key(
            out,
            "Whether the mechanism is drawn with the cylinder on the left.",
            &format!("mirror = {}", !name.is_ng()),
        );
    }
    if takes(Setting::Mass) {
        key(
            out,
            "Reciprocating mass m of the engine, force·s²/length (slug with lbf and ft), positive.",
            &format!("mass = {}", number(crate::dynamics::EXAMPLE_MASS)),
        );
    }
    if takes(Setting::Fluctuation) {
        key(
            out,
            "Coefficient of fluctuation of speed C_s = (ω_max − ω_min)/ω, above 0 and below 2.",
            &format!(
                "fluctuation = {}",
                number(crate::dynamics::DEFAULT_FLUCTUATION)
            ),
        );
    }
    key(out, TITLE, "# title = \"…\"");
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_read_back() {
        for v in [0.0, 45.0, 250.0, 0.01, 264.87, 1e-100, 1.5e300, -3.25, 1e15] {
            let s = number(v);
            let back: f64 = toml::from_str::<toml::Table>(&format!("v = {s}")).unwrap()["v"]
                .as_float()
                .or_else(|| {
                    toml::from_str::<toml::Table>(&format!("v = {s}")).unwrap()["v"]
                        .as_integer()
                        .map(|i| i as f64)
                })
                .unwrap();
            assert_eq!(back, v, "{s}");
        }
        assert_eq!(number(45.0), "45");
        assert_eq!(number(0.5), "0.5");
    }

    #[test]
    fn speeds_read_back() {
        assert_eq!(
            speed(crate::analytic::kinematics::rpm_to_omega(250.0)),
            "rpm = 250"
        );
        assert_eq!(
            speed(crate::analytic::kinematics::rpm_to_omega(1200.0)),
            "rpm = 1200"
        );
        assert_eq!(speed(26.16), "omega = 26.16");
    }

    #[test]
    fn a_scene_reads_back_to_itself() {
        use crate::construct::CouplerPoint;
        use crate::figure::Title;
        use crate::{
            angle::Angle, figure::Style, mechanism::SliderCrank, scene::Page, units::Units,
        };
        let angles = [30.0, 120.0, 212.5].map(Angle::deg);
        let page = Page::sized("160mm".parse().unwrap(), "4.5in".parse().unwrap(), 12.5).unwrap();
        let scene = Scene::new(SliderCrank::new(25.0, 72.0, -3.5).unwrap(), angles[0])
            .with_name("a \"quoted\" name")
            .with_angles(angles.to_vec())
            .with_layers([Layer::Mechanism, Layer::Coupler, Layer::Torque])
            .with_style(Style::Handout)
            .with_font(crate::figure::Font::LibertinusSerif)
            .with_notation(crate::scene::Notation::Ng)
            .with_mirror(true)
            .with_page(page)
            .with_omega(-26.16)
            .with_units(Units::MILLIMETRE_NEWTON)
            .with_title(Title::new("Ng’s rig, *O* and *M*").unwrap())
            .with_torque(264.87)
            .with_coupler(CouplerPoint::new(0.25).unwrap())
            .with_tolerance(0.005);
        let text = super::scene(FigureName::Fig67Example, &scene);
        match super::super::parse::parse(&text).unwrap() {
            crate::catalogue::SceneFile::Mechanism(back) => assert_eq!(back, scene, "{text}"),
            _ => panic!("a diagram"),
        }
    }

    #[test]
    fn physical_page_lengths_read_back() {
        for (v, u) in [
            (160.0, PageUnit::Mm),
            (4.5, PageUnit::In),
            (33.3, PageUnit::Mm),
        ] {
            let units = PageLength::new(v, u).unwrap().page_units();
            let s = page_length(units, u);
            let l: PageLength = s.trim_matches('"').parse().unwrap();
            assert_eq!(l.page_units(), units, "{s}");
            assert_eq!(l.unit(), u);
        }
        assert_eq!(page_length(760.0, PageUnit::Px), "760");
    }
}
