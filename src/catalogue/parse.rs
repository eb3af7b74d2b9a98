//! Scene files in TOML. Every error names the line and column of the bad
//! key or value. The keys are those of the serde structs below
//! ([`keys`] lists them from the structs themselves); docs/scene-format.md
//! is their reference.

use super::{FigureName, FigureOptions, SceneFile, Setting};
use crate::construct::CouplerPoint;
use crate::dynamics::checked_coefficient;
use crate::error::{Error, Field, Input, Result, non_negative};
use crate::figure::{Font, PageLength, Style, Title};
use crate::scene::{Layer, Notation, Page, Scene, valid};
use crate::{angle::Angle, mechanism::SliderCrank, units::Unit};
use serde::Deserialize;
use std::ops::Range;
use toml::Spanned;

/// The version of scene files this program reads (the `version` key).
pub(crate) const VERSION: i64 = 1;

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct File {
    /// The version of the format, read before the rest ([`Versioned`]).
    #[serde(rename = "version")]
    _version: Option<serde::de::IgnoredAny>,
    /// A named figure to start from; the other keys override it.
    figure: Option<Spanned<String>>,
    name: Option<Spanned<String>>,
    title: Option<Title>,
    mechanism: Option<MechanismFile>,
    units: Option<UnitsFile>,
    angle: Option<Spanned<Degrees>>,
    angles: Option<Spanned<Vec<Degrees>>>,
    layers: Option<Spanned<Vec<Layer>>>,
    style: Option<Style>,
    font: Option<Font>,
    notation: Option<Spanned<Notation>>,
    mirror: Option<Spanned<bool>>,
    page: Option<PageFile>,
    rpm: Option<Spanned<f64>>,
    omega: Option<Spanned<f64>>,
    torque: Option<Spanned<f64>>,
    /// The older spelling of `[units] force`.
    force_unit: Option<Spanned<Unit>>,
    coupler: Option<Spanned<CouplerFile>>,
    tolerance: Option<Spanned<f64>>,
    /// The reciprocating mass of the engine dynamics diagrams.
    mass: Option<Spanned<f64>>,
    /// The coefficient of fluctuation of speed of `flywheel`.
    fluctuation: Option<Spanned<f64>>,
}

/// The coupler point in a scene file: `coupler = 0.3` (on the rod, from
/// A), or `coupler = [0.5, 0.25]`, along the rod and off its line in rod
/// lengths ([`CouplerPoint::off_rod`]).
#[derive(Debug, Clone, Deserialize)]
#[serde(untagged)]
enum CouplerFile {
    Along(f64),
    Point(Vec<f64>),
}

impl CouplerFile {
    /// The point, or why not.
    fn point(&self) -> Result<CouplerPoint> {
        match self {
            CouplerFile::Along(t) => CouplerPoint::new(*t),
            CouplerFile::Point(p) => match p.as_slice() {
                [t] => CouplerPoint::new(*t),
                [t, h] => CouplerPoint::off_rod(*t, *h),
                _ => Err(crate::error::Error::invalid(
                    Input::Scene,
                    "coupler is a number t or a list [t, h] of two".to_string(),
                )),
            },
        }
    }
}

/// A crank angle in a scene file: a number of degrees. A text such as
/// `"120deg"` or `"120°"` is refused with what to write instead.
#[derive(Debug, Clone, Copy)]
struct Degrees(f64);

impl<'de> Deserialize<'de> for Degrees {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> std::result::Result<Self, D::Error> {
        struct Visitor;
        impl serde::de::Visitor<'_> for Visitor {
            type Value = Degrees;

            fn expecting(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
                f.write_str("an angle in degrees, a number such as 120")
            }

            fn visit_f64<E: serde::de::Error>(self, v: f64) -> std::result::Result<Degrees, E> {
                Ok(Degrees(v))
            }

            fn visit_i64<E: serde::de::Error>(self, v: i64) -> std::result::Result<Degrees, E> {
                Ok(Degrees(v as f64))
            }

            fn visit_u64<E: serde::de::Error>(self, v: u64) -> std::result::Result<Degrees, E> {
                Ok(Degrees(v as f64))
            }

            fn visit_str<E: serde::de::Error>(self, v: &str) -> std::result::Result<Degrees, E> {
                let number = v
                    .trim()
                    .trim_end_matches(|c: char| c.is_alphabetic() || c == '°')
                    .trim();
                let shown: String = v.chars().take(20).flat_map(char::escape_default).collect();
                Err(E::custom(match number.parse::<f64>() {
                    Ok(n) if n.is_finite() => format!(
                        "an angle is a number of degrees without quotes or unit: write {n} for \"{shown}\""
                    ),
                    _ => format!(
                        "an angle is a number of degrees without quotes or unit, such as 120, not \"{shown}\""
                    ),
                }))
            }
        }
        d.deserialize_any(Visitor)
    }
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct MechanismFile {
    crank: Option<Spanned<f64>>,
    rod: Option<Spanned<f64>>,
    offset: Option<Spanned<f64>>,
    /// The older spelling of `[units] length`.
    unit: Option<Spanned<Unit>>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct UnitsFile {
    length: Option<Spanned<Unit>>,
    force: Option<Spanned<Unit>>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct PageFile {
    width: Option<Spanned<PageLength>>,
    height: Option<Spanned<PageLength>>,
    margin: Option<Spanned<f64>>,
}

/// The `version` key alone, read before the rest of the file so that a
/// newer file is refused for its version rather than for a key this
/// program does not know.
#[derive(Debug, Deserialize)]
struct Versioned {
    version: Option<Spanned<Version>>,
}

/// A `version` as written: an integer of any size TOML reads (beyond
/// `i64` too, which `toml::Value` cannot hold), or something else, shown
/// as written (cut to 40 characters).
#[derive(Debug)]
enum Version {
    Integer(i128),
    Other(String),
}

impl<'de> Deserialize<'de> for Version {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> std::result::Result<Self, D::Error> {
        d.deserialize_any(VersionVisitor)
    }
}

struct VersionVisitor;

impl<'de> serde::de::Visitor<'de> for VersionVisitor {
    type Value = Version;

    fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        f.write_str("a version number")
    }
    fn visit_i64<E>(self, v: i64) -> std::result::Result<Version, E> {
        Ok(Version::Integer(v.into()))
    }
    fn visit_u64<E>(self, v: u64) -> std::result::Result<Version, E> {
        Ok(Version::Integer(v.into()))
    }
    fn visit_i128<E>(self, v: i128) -> std::result::Result<Version, E> {
        Ok(Version::Integer(v))
    }
    fn visit_u128<E>(self, v: u128) -> std::result::Result<Version, E> {
        Ok(Version::Integer(i128::try_from(v).unwrap_or(i128::MAX)))
    }
    fn visit_f64<E>(self, v: f64) -> std::result::Result<Version, E> {
        Ok(Version::Other(format!("{v:?}")))
    }
    fn visit_bool<E>(self, v: bool) -> std::result::Result<Version, E> {
        Ok(Version::Other(v.to_string()))
    }
    fn visit_str<E>(self, v: &str) -> std::result::Result<Version, E> {
        Ok(Version::Other(format!("{v:?}")))
    }
    fn visit_seq<A: serde::de::SeqAccess<'de>>(
        self,
        mut seq: A,
    ) -> std::result::Result<Version, A::Error> {
        while seq.next_element::<serde::de::IgnoredAny>()?.is_some() {}
        Ok(Version::Other("an array".into()))
    }
    fn visit_map<A: serde::de::MapAccess<'de>>(
        self,
        mut map: A,
    ) -> std::result::Result<Version, A::Error> {
        while map
            .next_entry::<serde::de::IgnoredAny, serde::de::IgnoredAny>()?
            .is_some()
        {}
        Ok(Version::Other("a table".into()))
    }
}

/// Refuses a file of another version than [`VERSION`] (a newer one, or a
/// version that is not a positive integer), at its line and column.
fn check_version(text: &str) -> Result<()> {
    // Broken TOML is reported by the full parse, with its location.
    let Ok(Versioned {
        version: Some(version),
    }) = toml::from_str::<Versioned>(text)
    else {
        return Ok(());
    };
    let message = match version.get_ref() {
        Version::Integer(v) if *v == i128::from(VERSION) => return Ok(()),
        Version::Integer(v) if *v > i128::from(VERSION) => format!(
            "this scene file is version {v}, newer than this program reads: it reads version {VERSION}"
        ),
        other => {
            let shown = match other {
                Version::Integer(v) => v.to_string(),
                Version::Other(s) => s.chars().take(40).collect(),
            };
            format!(
                "invalid version {shown}: this program reads scene files of version {VERSION} (an integer)"
            )
        }
    };
    Err(located(Input::Scene, text, version.span(), message))
}

/// 1-based line and column of byte offset `at` in `text`.
fn line_column(text: &str, at: usize) -> (usize, usize) {
    let at = at.min(text.len());
    let before = &text[..at];
    let line = before.matches('\n').count() + 1;
    let column = before
        .rfind('\n')
        .map_or(before, |i| &before[i + 1..])
        .chars()
        .count()
        + 1;
    (line, column)
}

/// A TOML syntax or key error of `text`, a file of kind `input`, placed
/// at its line and column when the parser gives a place.
pub(crate) fn toml_error(input: Input, text: &str, e: &toml::de::Error) -> Error {
    let message = e.message().trim().to_string();
    match e.span() {
        Some(span) => located(input, text, span, message),
        None => Error::invalid(input, message),
    }
}

/// An [`Error::Invalid`] about `input` whose message starts with the line
/// and column of `span` in `text` (scene files and gallery manifests
/// alike).
pub(crate) fn located(
    input: Input,
    text: &str,
    span: Range<usize>,
    message: impl std::fmt::Display,
) -> Error {
    let (line, column) = line_column(text, span.start);
    Error::invalid(input, format!("line {line}, column {column}: {message}"))
}

/// Runs a validation, locating its error at `span` in the scene file.
fn at<T>(text: &str, span: Range<usize>, r: Result<T>) -> Result<T> {
    r.map_err(|e| located(Input::Scene, text, span, e))
}

pub(super) fn parse(text: &str) -> Result<SceneFile> {
    check_version(text)?;
    let file: File = toml::from_str(text).map_err(|e| toml_error(Input::Scene, text, &e))?;
    let start = match &file.figure {
        Some(name) => {
            let figure = at(text, name.span(), FigureName::from_name(name.get_ref()))?;
            match figure.scene() {
                Some(scene) => scene,
                None => return diagram(text, file, figure),
            }
        }
        None => Scene::new(
            SliderCrank::in_line(crate::sources::ENGINE_35.0, crate::sources::ENGINE_35.1)?,
            Angle::from_degrees(45.0)?,
        )
        .with_layers([Layer::Mechanism]),
    };
    Ok(SceneFile::Mechanism(mechanism_scene(text, &file, start)?))
}

/// The validated mechanism of a `[mechanism]` table, the lengths it does
/// not give `own`'s (as a flag changes one length of the figure's own),
/// an error located at the value that is wrong: the crank, the rod, or
/// the offset.
fn mechanism(text: &str, m: &MechanismFile, own: &SliderCrank) -> Result<SliderCrank> {
    let value = |v: &Option<Spanned<f64>>, own: f64| v.as_ref().map_or(own, |v| *v.get_ref());
    let built = SliderCrank::new(
        value(&m.crank, own.crank()),
        value(&m.rod, own.rod()),
        value(&m.offset, own.offset()),
    );
    let crank = matches!(
        &built,
        Err(Error::NotPositive {
            name: Field::Crank,
            ..
        } | Error::NotFinite {
            name: Field::Crank,
            ..
        })
    );
    let offset = matches!(
        &built,
        Err(Error::NotFinite {
            name: Field::Offset,
            ..
        })
    );
    // The value at fault, or else the first length the table gives.
    let order = match (crank, offset) {
        (true, _) => [&m.crank, &m.rod, &m.offset],
        (_, true) => [&m.offset, &m.rod, &m.crank],
        _ => [&m.rod, &m.crank, &m.offset],
    };
    let span = order
        .into_iter()
        .find_map(|v| v.as_ref().map(Spanned::span))
        .unwrap_or_default();
    at(text, span, built)
}

/// The length and force units the file names: `[units] length` and
/// `force`, or their older spellings `[mechanism] unit` and `force_unit`
/// (one spelling for each).
fn units(text: &str, file: &File) -> Result<(Option<Unit>, Option<Unit>)> {
    let new = file.units.as_ref();
    let pick =
        |new: Option<&Spanned<Unit>>, old: Option<&Spanned<Unit>>, key: &str, was: &str| match (
            new, old,
        ) {
            (Some(n), Some(_)) => Err(located(
                Input::Scene,
                text,
                n.span(),
                format!("give the {key} unit once: `[units] {key}` replaces the older `{was}`"),
            )),
            (n, o) => Ok(n.or(o).map(|u| u.get_ref().clone())),
        };
    let length = pick(
        new.and_then(|u| u.length.as_ref()),
        file.mechanism.as_ref().and_then(|m| m.unit.as_ref()),
        "length",
        "[mechanism] unit",
    )?;
    let force = pick(
        new.and_then(|u| u.force.as_ref()),
        file.force_unit.as_ref(),
        "force",
        "force_unit",
    )?;
    Ok((length, force))
}

/// `page` with the file's `[page]` keys in place of its own, an error
/// located at the value out of range.
fn page(text: &str, p: &PageFile, page: &Page) -> Result<Page> {
    let options = FigureOptions {
        width: p.width.as_ref().map(|w| *w.get_ref()),
        height: p.height.as_ref().map(|h| *h.get_ref()),
        ..FigureOptions::default()
    };
    let margin = p.margin.as_ref().map_or(page.margin(), |m| *m.get_ref());
    let base = Page::new(page.width(), page.height(), margin).map(|b| b.with_unit(page.unit()));
    // A scene file's height is the most the drawing takes (a file
    // printed as a figure's default scene carries the figure's own, which
    // grows for a detail): only a height asked for with the figure is held.
    let built = base
        .and_then(|b| options.page(&b))
        .map(Page::with_height_free);
    let span = match &built {
        Err(
            Error::NotPositive { name, .. }
            | Error::NotFinite { name, .. }
            | Error::OutOfRange { name, .. },
        ) => match *name {
            Field::PageWidth => p.width.as_ref().map(|s| s.span()),
            Field::PageHeight => p.height.as_ref().map(|s| s.span()),
            _ => p.margin.as_ref().map(|s| s.span()),
        },
        _ => None,
    };
    match span {
        Some(span) => at(text, span, built),
        None => built,
    }
}

/// ω from `rpm` or `omega` (not both), with the span it was given at.
fn speed(text: &str, file: &File) -> Result<Option<(f64, Range<usize>)>> {
    match (&file.rpm, &file.omega) {
        (Some(_), Some(w)) => Err(located(
            Input::Scene,
            text,
            w.span(),
            "give either `rpm` or `omega`, not both",
        )),
        // Checked as every front end's rpm is, at its line: a speed whose ω underflows
        // is named as the rpm given, not as an ω of 0.
        (Some(n), None) => {
            let omega = at(
                text,
                n.span(),
                crate::analytic::kinematics::omega_from_rpm(*n.get_ref()),
            )?;
            Ok(Some((omega, n.span())))
        }
        (None, Some(w)) => Ok(Some((*w.get_ref(), w.span()))),
        (None, None) => Ok(None),
    }
}

/// Refuses a scene `name` (written into the figure's metadata) that
/// [`crate::error::text_fault`] finds unfit, as a title does.
fn check_name(name: &str) -> Result<()> {
    match crate::error::text_fault(name) {
        None => Ok(()),
        Some(why) => Err(Error::invalid(Input::Scene, format!("invalid name: {why}"))),
    }
}

/// Refuses the keys of the engine dynamics diagrams (`mass`,
/// `fluctuation`) in a mechanism figure's file, at their line.
fn no_dynamics(text: &str, file: &File) -> Result<()> {
    let keys = [
        ("mass", file.mass.as_ref().map(|m| m.span())),
        ("fluctuation", file.fluctuation.as_ref().map(|c| c.span())),
    ];
    match keys.into_iter().find_map(|(k, s)| s.map(|s| (k, s))) {
        Some((key, span)) => Err(located(
            Input::Scene,
            text,
            span,
            format!(
                "`{key}` is a key of the engine dynamics diagrams (turning-moment, inertia-force, primary-secondary, direct-reverse-cranks, flywheel, crank-pin-loads), not of a mechanism figure"
            ),
        )),
        None => Ok(()),
    }
}

/// The mechanism figure's scene `scene` (or the plain scene of a file
/// that names no figure) with the file's changes, each refused at its
/// line and column where it is wrong.
fn mechanism_scene(text: &str, file: &File, scene: Scene) -> Result<Scene> {
    no_dynamics(text, file)?;
    let scene = named(text, file, scene)?;
    let scene = posed(text, file, scene)?;
    let scene = styled(text, file, scene)?;
    moving(text, file, scene)
}

/// The scene with the file's name, title, mechanism and units.
fn named(text: &str, file: &File, mut scene: Scene) -> Result<Scene> {
    if let Some(n) = &file.name {
        at(text, n.span(), check_name(n.get_ref()))?;
        scene = scene.with_name(n.get_ref().clone());
    } else if file.figure.is_none() {
        scene = scene.with_name("scene");
    }
    if let Some(t) = &file.title {
        scene = scene.with_title(t.clone());
    }
    if let Some(m) = &file.mechanism {
        let built = mechanism(text, m, scene.mechanism())?;
        scene = scene.with_mechanism(built);
    }
    let (length, force) = units(text, file)?;
    let units = scene.units().clone().asked(length.as_ref(), force.as_ref());
    scene = scene.with_units(units);
    Ok(scene)
}

/// The scene at the file's `angle` or `angles` (not both).
fn posed(text: &str, file: &File, mut scene: Scene) -> Result<Scene> {
    match (&file.angle, &file.angles) {
        (Some(_), Some(b)) => {
            return Err(located(
                Input::Scene,
                text,
                b.span(),
                "give either `angle` or `angles`, not both",
            ));
        }
        (Some(a), None) => {
            let angle = at(text, a.span(), Angle::from_degrees(a.get_ref().0))?;
            scene = scene.with_angles(vec![angle]);
        }
        (None, Some(list)) => {
            let angles = list
                .get_ref()
                .iter()
                .map(|d| Angle::from_degrees(d.0))
                .collect::<Result<Vec<_>>>();
            let angles = at(text, list.span(), angles)?;
            at(text, list.span(), valid::angles(&angles))?;
            scene = scene.with_angles(angles);
        }
        (None, None) => {}
    }
    Ok(scene)
}

/// The scene with the file's layers, style, face, letters, side and
/// page.
fn styled(text: &str, file: &File, mut scene: Scene) -> Result<Scene> {
    if let Some(layers) = &file.layers {
        // An empty list would draw a blank page: refused as an empty list
        // of layers is everywhere.
        if layers.get_ref().is_empty() {
            return Err(located(
                Input::Scene,
                text,
                layers.span(),
                "layers names no layer",
            ));
        }
        scene = scene.with_layers(layers.get_ref().iter().copied());
    }
    if let Some(s) = file.style {
        scene = scene.with_style(s);
    }
    if let Some(f) = file.font {
        scene = scene.with_font(f);
    }
    if let Some(n) = &file.notation {
        scene = scene.with_notation(*n.get_ref());
    }
    if let Some(m) = &file.mirror {
        scene = scene.with_mirror(*m.get_ref());
    }
    if let Some(p) = &file.page {
        let built = page(text, p, scene.page())?;
        scene = scene.with_page(built);
    }
    Ok(scene)
}

/// The scene with the file's speed, torque, coupler point and
/// tolerance.
fn moving(text: &str, file: &File, mut scene: Scene) -> Result<Scene> {
    if let Some((omega, span)) = speed(text, file)? {
        scene = scene.with_omega(at(text, span, valid::omega(omega))?);
    }
    if let Some(t) = &file.torque {
        scene = scene.with_torque(at(text, t.span(), valid::torque(*t.get_ref()))?);
    }
    if let Some(q) = &file.coupler {
        let point = q.get_ref().point();
        scene = scene.with_coupler(at(text, q.span(), point)?);
    }
    if let Some(t) = &file.tolerance {
        scene = scene.with_tolerance(at(text, t.span(), valid::tolerance(*t.get_ref()))?);
    }
    Ok(scene)
}

/// Refuses the keys of the mechanism figures' scenes in the file of the
/// diagram `name`, at the first one's line and column.
fn refuse_scene_keys(text: &str, file: &File, name: FigureName) -> Result<()> {
    let scene_only = [
        ("name", file.name.as_ref().map(|s| s.span())),
        ("angles", file.angles.as_ref().map(|s| s.span())),
        ("layers", file.layers.as_ref().map(|s| s.span())),
        ("torque", file.torque.as_ref().map(|s| s.span())),
        ("coupler", file.coupler.as_ref().map(|s| s.span())),
        ("tolerance", file.tolerance.as_ref().map(|s| s.span())),
        (
            "[page] margin",
            file.page
                .as_ref()
                .and_then(|p| p.margin.as_ref())
                .map(|s| s.span()),
        ),
    ];
    for (key, span) in scene_only {
        if let Some(span) = span {
            return Err(located(
                Input::Scene,
                text,
                span,
                format!(
                    "`{key}` is a key of the mechanism figures; {} is a diagram",
                    name.name()
                ),
            ));
        }
    }
    Ok(())
}

/// A named diagram with the file's changes: the keys of the mechanism
/// figures' scenes (`name`, `angles`, `layers`, `torque`, `coupler`,
/// `tolerance`, `[page] margin`) are refused, and so is any key the
/// diagram has no use for, each at its line and column.
fn diagram(text: &str, file: File, name: FigureName) -> Result<SceneFile> {
    refuse_scene_keys(text, &file, name)?;
    // Each option, refused where the diagram does not take it.
    let refuse = |setting: Setting, key: &str, span: Range<usize>| -> Result<()> {
        if name.takes(setting) {
            Ok(())
        } else {
            Err(located(
                Input::Scene,
                text,
                span,
                format!("{} does not use `{key}`", name.name()),
            ))
        }
    };
    let mut options = FigureOptions::default();
    if let Some(m) = &file.mechanism {
        let first = [&m.crank, &m.rod, &m.offset]
            .into_iter()
            .find_map(|v| v.as_ref().map(Spanned::span));
        if let Some(span) = first {
            let built = mechanism(text, m, &name.mechanism())?;
            refuse(Setting::Mechanism, "[mechanism]", span)?;
            options.mechanism = Some(built);
        }
    }
    if let Some(a) = &file.angle {
        let angle = at(text, a.span(), name.angle(a.get_ref().0))?;
        refuse(Setting::Angle, "angle", a.span())?;
        options.angle = Some(angle);
    }
    if let Some((omega, span)) = speed(text, &file)? {
        let key = if file.rpm.is_some() { "rpm" } else { "omega" };
        refuse(Setting::Speed, key, span.clone())?;
        if !(omega > 0.0 && omega.is_finite()) {
            return Err(located(
                Input::Scene,
                text,
                span,
                "the diagrams are drawn for a crank turning counter-clockwise: give a positive speed",
            ));
        }
        options.omega = Some(omega);
    }
    if let Some(n) = &file.notation {
        refuse(Setting::Notation, "notation", n.span())?;
    }
    if let Some(m) = &file.mirror {
        refuse(Setting::Mirror, "mirror", m.span())?;
        options.mirror = Some(*m.get_ref());
    }
    if let Some(m) = &file.mass {
        refuse(Setting::Mass, "mass", m.span())?;
        let mass = non_negative(Field::Mass, *m.get_ref());
        options.mass = Some(at(text, m.span(), mass)?);
    }
    if let Some(c) = &file.fluctuation {
        refuse(Setting::Fluctuation, "fluctuation", c.span())?;
        let coefficient = checked_coefficient(*c.get_ref());
        options.fluctuation = Some(at(text, c.span(), coefficient)?);
    }
    options.style = file.style;
    options.font = file.font;
    options.title = file.title.clone();
    (options.length_unit, options.force_unit) = units(text, &file)?;
    if let Some(p) = &file.page {
        page(text, p, &name.page())?;
        options.width = p.width.as_ref().map(|w| *w.get_ref());
        options.height = p.height.as_ref().map(|h| *h.get_ref());
    }
    Ok(SceneFile::Diagram(name, options))
}

/// Every key a scene file may hold, read off the serde structs that parse
/// it: the top-level keys, each followed by the keys of its table as
/// `table.key` when it holds one, in the order of the structs.
pub(crate) fn keys() -> Vec<String> {
    let mut keys = Vec::new();
    for &field in introspect::fields::<File>() {
        keys.push(field.to_string());
        if let Some(inner) = introspect::table_fields::<File>(field) {
            keys.extend(inner.iter().map(|k| format!("{field}.{k}")));
        }
    }
    keys
}

/// The field names of derived `Deserialize` impls, asked of the impls
/// themselves: a deserializer that drives them only far enough to see the
/// names they expect.
mod introspect {
    use serde::Deserialize;
    use serde::de::{self, DeserializeSeed, Deserializer, IntoDeserializer, MapAccess, Visitor};

    type E = de::value::Error;
    type Names = Option<&'static [&'static str]>;

    /// Ends a deserialization once it has shown what was wanted.
    fn stop() -> E {
        de::Error::custom("only listing keys")
    }

    /// Records the field names of the struct deserialized from it (through
    /// an `Option`); any other value stops.
    struct Fields<'a>(&'a mut Names);

    impl<'de> Deserializer<'de> for Fields<'_> {
        type Error = E;

        fn deserialize_any<V: Visitor<'de>>(self, _: V) -> Result<V::Value, E> {
            Err(stop())
        }

        fn deserialize_option<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value, E> {
            visitor.visit_some(self)
        }

        fn deserialize_struct<V: Visitor<'de>>(
            self,
            name: &'static str,
            fields: &'static [&'static str],
            _: V,
        ) -> Result<V::Value, E> {
            // `Spanned` is a struct to serde, a value to TOML.
            if !name.starts_with("$__") {
                *self.0 = Some(fields);
            }
            Err(stop())
        }

        serde::forward_to_deserialize_any! {
            bool i8 i16 i32 i64 i128 u8 u16 u32 u64 u128 f32 f64 char str
            string bytes byte_buf unit unit_struct newtype_struct seq tuple
            tuple_struct map enum identifier ignored_any
        }
    }

    /// A table of one key whose value records the fields of a struct.
    struct One<'a> {
        key: Option<&'static str>,
        names: &'a mut Names,
    }

    impl<'de> Deserializer<'de> for One<'_> {
        type Error = E;

        fn deserialize_any<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value, E> {
            visitor.visit_map(self)
        }

        serde::forward_to_deserialize_any! {
            bool i8 i16 i32 i64 i128 u8 u16 u32 u64 u128 f32 f64 char str
            string bytes byte_buf option unit unit_struct newtype_struct seq
            tuple tuple_struct map struct enum identifier ignored_any
        }
    }

    impl<'de> MapAccess<'de> for One<'_> {
        type Error = E;

        fn next_key_seed<K: DeserializeSeed<'de>>(
            &mut self,
            seed: K,
        ) -> Result<Option<K::Value>, E> {
            self.key
                .take()
                .map(|k| seed.deserialize(k.into_deserializer()))
                .transpose()
        }

        fn next_value_seed<V: DeserializeSeed<'de>>(&mut self, seed: V) -> Result<V::Value, E> {
            seed.deserialize(Fields(self.names))
        }
    }

    /// The field names of the struct `T`.
    pub(super) fn fields<T: for<'de> Deserialize<'de>>() -> &'static [&'static str] {
        let mut names = None;
        let _ = T::deserialize(Fields(&mut names));
        names.unwrap_or(&[])
    }

    /// The field names of the table held by the field `key` of the struct
    /// `T`; `None` when that field holds a value.
    pub(super) fn table_fields<T: for<'de> Deserialize<'de>>(
        key: &'static str,
    ) -> Option<&'static [&'static str]> {
        let mut names = None;
        let _ = T::deserialize(One {
            key: Some(key),
            names: &mut names,
        });
        names
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_keys_are_those_of_the_structs() {
        let keys = keys();
        for k in [
            "version",
            "figure",
            "mechanism",
            "mechanism.crank",
            "mechanism.unit",
            "units.force",
            "page.margin",
            "force_unit",
            "tolerance",
        ] {
            assert!(keys.iter().any(|x| x == k), "{k} missing from {keys:?}");
        }
        assert!(!keys.iter().any(|x| x.starts_with("angle.")), "{keys:?}");
        assert_eq!(keys.len(), 31, "{keys:?}");
    }

    #[test]
    fn a_newer_or_invalid_version_is_refused_first() {
        let e = parse("version = 2\nnew_key = 1\n").unwrap_err().to_string();
        assert_eq!(
            e,
            "line 1, column 11: this scene file is version 2, newer than this program reads: it reads version 1"
        );
        for bad in ["0", "-1", "1.0", "\"1\"", "[1]"] {
            let e = parse(&format!("version = {bad}\n"))
                .unwrap_err()
                .to_string();
            assert!(
                e.starts_with("line 1, column 11: invalid version ") && e.contains("version 1"),
                "{e}"
            );
        }
        assert!(parse("version = 1\n").is_ok());
    }

    #[test]
    fn names_and_titles_with_non_characters_are_refused_at_their_place() {
        for (text, expected) in [
            (
                "name = \"a\\uFFFEb\"\n",
                "line 1, column 8: invalid name: it holds the non-character U+FFFE",
            ),
            (
                "name = \"a\\rb\"\n",
                "line 1, column 8: invalid name: it holds a control character",
            ),
            (
                "\ntitle = \"\\uFFFF\"\n",
                "line 2, column 9: invalid title: it holds the non-character U+FFFF",
            ),
            (
                "name = \"a\\u202Eb\"\n",
                "line 1, column 8: invalid name: it holds the bidirectional control U+202E",
            ),
            (
                "title = \"\\u200Bx\"\n",
                "line 1, column 9: invalid title: it holds the invisible character U+200B",
            ),
        ] {
            let e = parse(text).unwrap_err().to_string();
            assert!(e.starts_with(expected), "{text}: {e}");
        }
    }

    #[test]
    fn versions_beyond_64_bits_are_newer_not_version_1() {
        for huge in ["9223372036854775808", "99999999999999999999"] {
            let e = parse(&format!("version = {huge}\n"))
                .unwrap_err()
                .to_string();
            assert_eq!(
                e,
                format!(
                    "line 1, column 11: this scene file is version {huge}, newer than this program reads: it reads version 1"
                )
            );
        }
    }

    #[test]
    fn an_angle_with_a_unit_is_told_what_to_write() {
        let e = parse("figure = \"fig-66-kisch\"\nangle = \"120deg\"\n")
            .unwrap_err()
            .to_string();
        assert!(e.starts_with("line 2, column 9: "), "{e}");
        assert!(e.contains("write 120 for \"120deg\""), "{e}");
        assert!(!e.contains("f64") && !e.contains('\n'), "{e}");
        let e = parse("angles = [30, \"60°\"]\n").unwrap_err().to_string();
        assert!(e.contains("write 60 for"), "{e}");
        let e = parse("angle = \"north\"\n").unwrap_err().to_string();
        assert!(e.contains("such as 120"), "{e}");
        assert!(parse("figure = \"fig-66-kisch\"\nangle = 120\n").is_ok());
    }

    #[test]
    fn line_and_column_are_one_based() {
        assert_eq!(line_column("ab\ncd", 0), (1, 1));
        assert_eq!(line_column("ab\ncd", 4), (2, 2));
        assert_eq!(line_column("é\nx", 3), (2, 1));
    }
}
