//! Scene files in TOML. Every error names the line and column of the bad
//! key or value.

use super::{Layer, Notation, Page, Scene};
use crate::construct::CouplerPoint;
use crate::error::{Error, Result};
use crate::figure::{FigureName, Font};
use crate::render::Style;
use crate::{Angle, SliderCrank};
use serde::Deserialize;
use toml::Spanned;

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct SceneFile {
    /// A named figure to start from; the other keys override it.
    figure: Option<Spanned<String>>,
    name: Option<String>,
    mechanism: Option<MechanismFile>,
    angle: Option<Spanned<f64>>,
    angles: Option<Spanned<Vec<f64>>>,
    layers: Option<Vec<Layer>>,
    style: Option<Style>,
    font: Option<Font>,
    notation: Option<Notation>,
    mirror: Option<bool>,
    page: Option<PageFile>,
    rpm: Option<Spanned<f64>>,
    omega: Option<Spanned<f64>>,
    torque: Option<Spanned<f64>>,
    force_unit: Option<String>,
    coupler: Option<Spanned<f64>>,
    tolerance: Option<Spanned<f64>>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct MechanismFile {
    crank: Spanned<f64>,
    rod: Spanned<f64>,
    offset: Option<Spanned<f64>>,
    unit: Option<String>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct PageFile {
    width: Option<Spanned<f64>>,
    height: Option<Spanned<f64>>,
    margin: Option<Spanned<f64>>,
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

fn located(text: &str, span: std::ops::Range<usize>, message: impl std::fmt::Display) -> Error {
    let (line, column) = line_column(text, span.start);
    Error::Parse(format!("line {line}, column {column}: {message}"))
}

/// Runs a validation, locating its error at `span`.
fn at<T>(text: &str, span: std::ops::Range<usize>, r: Result<T>) -> Result<T> {
    r.map_err(|e| located(text, span, e))
}

pub(super) fn parse(text: &str) -> Result<Scene> {
    let file: SceneFile = toml::from_str(text).map_err(|e| {
        let message = e.message().trim().to_string();
        match e.span() {
            Some(span) => located(text, span, message),
            None => Error::Parse(message),
        }
    })?;
    let mut scene = match &file.figure {
        Some(name) => {
            let figure = FigureName::from_name(name.get_ref()).and_then(|f| {
                f.scene().ok_or_else(|| {
                    Error::Parse(format!(
                        "'{}' is a diagram; a scene starts from a mechanism figure: {}",
                        f.name(),
                        FigureName::SCENES.map(|s| s.name()).join(", ")
                    ))
                })
            });
            at(text, name.span(), figure)?
        }
        None => Scene::new(SliderCrank::in_line(0.5, 3.0)?, Angle::from_degrees(45.0)?)
            .with_layers([Layer::Mechanism]),
    };
    if let Some(n) = file.name {
        scene = scene.named(n);
    } else if file.figure.is_none() {
        scene = scene.named("scene");
    }
    if let Some(m) = file.mechanism {
        let offset = m.offset.as_ref().map_or(0.0, |o| *o.get_ref());
        let built = SliderCrank::new(*m.crank.get_ref(), *m.rod.get_ref(), offset);
        // Name the value that is wrong: the crank, the rod, or the offset.
        let span = match &built {
            Err(
                Error::NotPositive { name: "crank", .. } | Error::NotFinite { name: "crank", .. },
            ) => m.crank.span(),
            Err(Error::NotFinite { name: "offset", .. }) => {
                m.offset.as_ref().map_or(m.rod.span(), |o| o.span())
            }
            _ => m.rod.span(),
        };
        scene.mechanism = at(text, span, built)?;
        if let Some(u) = m.unit {
            scene.unit = u;
        }
    }
    match (&file.angle, &file.angles) {
        (Some(_), Some(b)) => {
            return Err(located(
                text,
                b.span(),
                "give either `angle` or `angles`, not both",
            ));
        }
        (Some(a), None) => {
            let angle = at(text, a.span(), Angle::from_degrees(*a.get_ref()))?;
            scene = scene.with_angles(vec![angle])?;
        }
        (None, Some(list)) => {
            let angles = list
                .get_ref()
                .iter()
                .map(|d| Angle::from_degrees(*d))
                .collect::<Result<Vec<_>>>();
            let angles = at(text, list.span(), angles)?;
            scene = at(text, list.span(), scene.with_angles(angles))?;
        }
        (None, None) => {}
    }
    if let Some(layers) = file.layers {
        scene = scene.with_layers(layers);
    }
    if let Some(s) = file.style {
        scene = scene.with_style(s);
    }
    if let Some(f) = file.font {
        scene = scene.with_font(f);
    }
    if let Some(n) = file.notation {
        scene = scene.with_notation(n);
    }
    if let Some(m) = file.mirror {
        scene = scene.mirrored(m);
    }
    if let Some(p) = file.page {
        let get = |v: &Option<Spanned<f64>>, d: f64| v.as_ref().map_or(d, |s| *s.get_ref());
        let page = Page::new(
            get(&p.width, scene.page.width()),
            get(&p.height, scene.page.height()),
            get(&p.margin, scene.page.margin()),
        );
        let span = match &page {
            Err(
                Error::NotPositive { name, .. }
                | Error::NotFinite { name, .. }
                | Error::OutOfRange { name, .. },
            ) => match *name {
                "page width" => p.width.as_ref().map(|s| s.span()),
                "page height" => p.height.as_ref().map(|s| s.span()),
                _ => p.margin.as_ref().map(|s| s.span()),
            },
            _ => None,
        };
        scene.page = match span {
            Some(span) => at(text, span, page)?,
            None => page?,
        };
    }
    match (&file.rpm, &file.omega) {
        (Some(_), Some(w)) => {
            return Err(located(
                text,
                w.span(),
                "give either `rpm` or `omega`, not both",
            ));
        }
        (Some(n), None) => {
            scene = at(
                text,
                n.span(),
                scene.with_omega(crate::rpm_to_omega(*n.get_ref())),
            )?
        }
        (None, Some(w)) => scene = at(text, w.span(), scene.with_omega(*w.get_ref()))?,
        (None, None) => {}
    }
    if let Some(t) = &file.torque {
        scene = at(text, t.span(), scene.with_torque(*t.get_ref()))?;
    }
    if let Some(f) = file.force_unit {
        scene = scene.with_force_unit(f);
    }
    if let Some(q) = &file.coupler {
        let point = CouplerPoint::new(*q.get_ref()).ok_or_else(|| Error::OutOfRange {
            name: "coupler",
            value: *q.get_ref(),
            reason: "the coupler point is a fraction of the rod from A (0) to B (1)".into(),
        });
        scene = scene.with_coupler(at(text, q.span(), point)?);
    }
    if let Some(t) = &file.tolerance {
        scene = at(text, t.span(), scene.with_tolerance(*t.get_ref()))?;
    }
    Ok(scene)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn line_and_column_are_one_based() {
        assert_eq!(line_column("ab\ncd", 0), (1, 1));
        assert_eq!(line_column("ab\ncd", 4), (2, 2));
        assert_eq!(line_column("é\nx", 3), (2, 1));
    }
}
