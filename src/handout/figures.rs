//! The figures of a handout: the named figures of the catalogue drawn for
//! the handout's engine, and their SVG made fit to be inlined in a page.

use super::{Gas, Handout};
use crate::catalogue::{FigureOptions, Setting};
use crate::error::Result;
use crate::figure::{Figure, PageLength, PageUnit, Panel, Part, Role};
use crate::render::{Element, SvgOptions, fmt, to_svg_with};
use crate::{catalogue::FigureName, scene::Layer};

/// The mechanism figure `name` (one drawn by a scene) for the handout's
/// engine, pose, speed and units; `layers` in place of the figure's own
/// where given. With the handout's torque for Ng's figure.
pub(super) fn mechanism(h: &Handout, name: FigureName, layers: Option<&[Layer]>) -> Result<Figure> {
    // cannot fail: the handout passes mechanism figures only (the constants of this module), and every mechanism figure has a scene.
    #[allow(clippy::expect_used)]
    let scene = name
        .scene()
        .expect("the handout draws mechanism figures by a scene");
    // The page sets each figure to its column: a figure narrowed to its
    // drawing would print taller, so each keeps its own width.
    let page = scene.page().with_width_kept();
    let mut scene = scene
        .with_page(page)
        .with_mechanism(*h.mechanism())
        .with_angles(vec![h.angle()])
        .with_omega(h.omega())
        .with_units(h.units().clone());
    if let Some(layers) = layers {
        scene = scene.with_layers(layers.iter().copied());
    }
    if let Some(t) = h.torque() {
        scene = scene.with_torque(t);
    }
    scene.figure()
}

/// The diagram `name` for the handout's engine, pose, speed and units.
pub(super) fn diagram(h: &Handout, name: FigureName) -> Result<Figure> {
    name.figure(&options(h))
}

/// The figure `name` of the handout's engine on a page `width` by
/// `height` units (px): a figure laid out wide and low, so that printed
/// it takes less of a page's height; or, where the engine's drawing needs
/// more than `height` at that width (a long rod's crank gets a detail on
/// the lower page), on a page of `width` and the figure's own height.
pub(super) fn diagram_on_page(
    h: &Handout,
    name: FigureName,
    (width, height): (f64, f64),
) -> Result<Figure> {
    let width = Some(PageLength::new(width, PageUnit::Px)?);
    let low = FigureOptions {
        width,
        height: Some(PageLength::new(height, PageUnit::Px)?),
        ..options(h)
    };
    name.figure(&low).or_else(|_| {
        name.figure(&FigureOptions {
            width,
            ..options(h)
        })
    })
}

/// The options of a figure of the handout's engine: its mechanism, ω,
/// angle and units.
fn options(h: &Handout) -> FigureOptions {
    FigureOptions {
        mechanism: Some(*h.mechanism()),
        omega: Some(h.omega()),
        angle: Some(h.angle()),
        length_unit: Some(h.units().length().clone()),
        force_unit: Some(h.units().force().clone()),
        ..FigureOptions::default()
    }
}

/// The mechanism alone, on the page `fitted` was fitted to: the frame, the
/// links, the crank circle, the line of stroke and the letters A, B, C of
/// its first panel, the rest (constructions, dimensions, notes, an
/// enlarged detail) left out. Drawn on the page of a figure with the
/// velocity construction, it leaves room for the student's D and E.
pub(super) fn only_the_mechanism(fitted: &Figure) -> Figure {
    let Some(panel) = fitted.panels().first() else {
        return fitted.clone();
    };
    let keep = |item: &crate::figure::Item| match (item.part, item.role) {
        (Part::DetailMark, _) => false,
        (_, Role::Frame | Role::Link) => true,
        (part, Role::Curve) => part == Part::CrankCircle,
        (part, Role::Auxiliary) => part == Part::CentreLine,
        (part, Role::Label) => part == Part::Joint,
        _ => false,
    };
    let items = panel.items().iter().filter(|i| keep(i)).cloned().collect();
    let rect = *panel.rect();
    let height = (rect.max().y + rect.min().y).min(fitted.height());
    let panel = Panel::new(panel.id(), rect, *panel.transform(), items);
    Figure::new(
        fitted.name(),
        fitted.width(),
        height,
        fitted.style(),
        fitted.tolerance(),
        vec![panel],
        fitted.metadata().clone(),
    )
    .with_font(fitted.font())
}

/// The SVG of `figure` to be inlined in a page that holds other figures:
/// every `id` prefixed with `prefix-`, and every reference to one
/// (`url(#…)`, `href="#…"`) with it, so that no two elements of the page
/// share an id and each figure's references stay its own; without the SVG
/// namespace attribute, which HTML does not need, so that the page names
/// no address.
pub(super) fn inline(figure: &Figure, prefix: &str) -> String {
    to_svg_with(figure, &inline_options(prefix))
}

/// The options of [`inline`].
pub(super) fn inline_options(prefix: &str) -> SvgOptions {
    SvgOptions::default()
        .with_id_prefix(&format!("{prefix}-"))
        .inline()
}

/// The dynamics diagram `name` for the handout's engine, pose, speed,
/// units, reciprocating mass, coefficient of fluctuation of speed and gas
/// force (the example's is the figures' own); the pose, the coefficient
/// and the gas force only for a figure that takes them (the inertia
/// force's pose, the flywheel's coefficient, the turning moment's gas).
pub(super) fn dynamics(h: &Handout, name: FigureName) -> Result<Figure> {
    let (mass, fluctuation) = h.dynamics().unzip();
    let (data, bore, gas_force) = match h.gas().filter(|_| name.takes(Setting::Data)) {
        Some(Gas::Indicator { text, bore, .. }) => (Some(text.clone()), Some(*bore), None),
        Some(Gas::Constant(f)) => (None, None, Some(*f)),
        _ => (None, None, None),
    };
    let options = FigureOptions {
        data,
        bore,
        gas_force,
        mechanism: Some(*h.mechanism()),
        omega: Some(h.omega()),
        angle: Some(h.angle()).filter(|_| name.takes(Setting::Angle)),
        length_unit: Some(h.units().length().clone()),
        force_unit: Some(h.units().force().clone()),
        mass,
        fluctuation: fluctuation.filter(|_| name.takes(Setting::Fluctuation)),
        ..FigureOptions::default()
    };
    name.figure(&options)
}

/// A faint grid of squares `step` world units wide over the mechanism's
/// panel, lines through the crank centre C, a layer to be set just above
/// the figure's paper ([`SvgOptions::with_underlay`]): the page on which
/// a student measures and draws.
pub(super) fn grid(panel: &Panel, step: f64) -> Element {
    let rect = panel.rect();
    let map = panel.transform();
    let corners = [
        map.invert(crate::geom::Point::new(rect.min().x, rect.min().y)),
        map.invert(crate::geom::Point::new(rect.max().x, rect.max().y)),
    ];
    let (x0, x1) = (
        corners[0].x.min(corners[1].x),
        corners[0].x.max(corners[1].x),
    );
    let (y0, y1) = (
        corners[0].y.min(corners[1].y),
        corners[0].y.max(corners[1].y),
    );
    let mut d = String::new();
    let (top, bottom) = (rect.min().y, rect.max().y);
    let (left, right) = (rect.min().x, rect.max().x);
    let mut k = (x0 / step).ceil();
    while k * step <= x1 {
        let x = map.apply(crate::geom::Point::new(k * step, 0.0)).x;
        d.push_str(&format!("M{} {}V{}", fmt(x), fmt(top), fmt(bottom)));
        k += 1.0;
    }
    let mut k = (y0 / step).ceil();
    while k * step <= y1 {
        let y = map.apply(crate::geom::Point::new(0.0, k * step)).y;
        d.push_str(&format!("M{} {}H{}", fmt(left), fmt(y), fmt(right)));
        k += 1.0;
    }
    let path = Element::new("path")
        .set("d", d)
        .set("fill", "none")
        .set("stroke", "#9ab8d6")
        .set("stroke-opacity", "0.55")
        .set("stroke-width", "0.5");
    Element::new("g")
        .set("id", "grid")
        .set("class", "grid")
        .add(path)
}

/// A round grid step (1, 2 or 5 × 10^k world units) that makes squares
/// of about `target` page units at the panel's scale.
pub(super) fn grid_step(panel: &Panel, target: f64) -> f64 {
    let per_unit = panel.transform().scale();
    let raw = target / per_unit;
    let decade = 10f64.powf(raw.log10().floor());
    [1.0, 2.0, 5.0, 10.0]
        .into_iter()
        .map(|m| m * decade)
        .min_by(|a, b| {
            (a.ln() - raw.ln())
                .abs()
                .total_cmp(&(b.ln() - raw.ln()).abs())
        })
        .unwrap_or(decade)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{angle::Angle, mechanism::SliderCrank};

    #[test]
    fn ids_are_prefixed_and_nothing_refers_to_one() {
        let h = Handout::new(SliderCrank::in_line(0.5, 2.0).unwrap(), Angle::deg(40.0));
        let f = mechanism(&h, FigureName::Fig63Velocity, None).unwrap();
        let svg = inline(&f, "step-2");
        assert!(svg.contains("id=\"step-2-point-E\""), "{svg}");
        assert!(!svg.contains(" id=\"point-E\""));
        // A clipped detail keeps its clip.
        let f = mechanism(&h, FigureName::Fig66Kisch, None).unwrap();
        let svg = inline(&f, "k");
        if svg.contains("clip-path") {
            assert!(
                svg.contains("url(#k-clip-panel-detail)")
                    && svg.contains("id=\"k-clip-panel-detail\"")
            );
        }
    }

    #[test]
    fn the_grid_goes_under_the_drawing_through_c() {
        let h = Handout::new(SliderCrank::in_line(60.0, 240.0).unwrap(), Angle::deg(40.0));
        let f = mechanism(&h, FigureName::Fig62Displacement, Some(&[Layer::Mechanism])).unwrap();
        let panel = &f.panels()[0];
        let step = grid_step(panel, 18.0);
        assert!([1.0, 2.0, 5.0, 10.0, 20.0].contains(&step), "{step}");
        let options = SvgOptions::default().with_underlay(grid(panel, step));
        let svg = to_svg_with(&f, &options);
        let paper = svg.find("id=\"paper\"").unwrap();
        let grid_at = svg.find("id=\"grid\"").unwrap();
        let first_link = svg.find("link-crank").unwrap();
        assert!(paper < grid_at && grid_at < first_link);
        // A vertical line through C (x = 0).
        let cx = panel.transform().apply(crate::geom::Point::origin()).x;
        assert!(svg.contains(&format!("M{} ", fmt(cx))), "{svg}");
    }
}
