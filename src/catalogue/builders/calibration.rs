//! Ng Fig. 7: the force transducer's calibration, strain against force,
//! with the least-squares line through the origin (Ng's spreadsheet
//! trendline, whose uncentred R² is his 0.9998), the ordinary fit with an
//! intercept, or both; each with its equation and R².

use super::{Ctx, Sheet, Table};
use crate::analytic::calibration::{LineFit, NG_TABLE_1, fit_through_origin, fit_with_intercept};
use crate::catalogue::Fit;
use crate::diagram::{Axis, Curve, Plot};
use crate::error::{Input, Result};
use crate::figure::{Dash, Figure, Symbol};
use crate::geom::{Frame, Point, Vector};
use serde_json::json;

fn equation(fit: &LineFit) -> String {
    let b = fit.intercept;
    if b == 0.0 {
        format!("*y* = {:.3} *x*", fit.slope)
    } else {
        let sign = if b < 0.0 { "−" } else { "+" };
        format!("*y* = {:.3} *x* {sign} {:.3}", fit.slope, b.abs())
    }
}

pub(in crate::catalogue) fn build(ctx: &Ctx) -> Result<Figure> {
    let page = ctx.page();
    let mut sheet = Sheet::new(ctx);
    sheet.mechanism(ctx, false, false);
    let points: Vec<(f64, f64)> = match ctx.options.data.as_deref() {
        Some(text) => {
            Table::parse(text, Input::Data, "data")?.pairs(&["force", "weight"], &["strain"])?
        }
        None => NG_TABLE_1.to_vec(),
    };
    let which = ctx.options.fit.unwrap_or_default();
    let origin = fit_through_origin(&points)?;
    let intercept = fit_with_intercept(&points)?;
    let (x_lo, x_hi) = points
        .iter()
        .fold((0.0f64, 0.0f64), |(lo, hi), p| (lo.min(p.0), hi.max(p.0)));
    let (y_lo, y_hi) = points
        .iter()
        .fold((0.0f64, 0.0f64), |(lo, hi), p| (lo.min(p.1), hi.max(p.1)));
    let x = Axis::nice(&format!("force ({})", ctx.units.force()), x_lo, x_hi)?;
    let (x0, x1) = x.range();
    let ends = |f: &LineFit| [f.at(x0), f.at(x1)];
    let mut all_y = vec![y_lo, y_hi];
    for f in [&origin, &intercept] {
        all_y.extend(ends(f));
    }
    let y = Axis::nice(
        "strain reading (×10⁻⁶)",
        all_y.iter().cloned().fold(f64::INFINITY, f64::min),
        all_y.iter().cloned().fold(f64::NEG_INFINITY, f64::max),
    )?;
    let rect =
        Frame::from_origin_size(16.0, 16.0, page.width() - 32.0, page.height() - 32.0 - 20.0);
    let mut plot = Plot::new("calibration", rect, x, y, ctx.tolerance, ctx.font)?.with_caption(
        if ctx.options.data.is_some() {
            "Calibration of the force transducer (the data given)"
        } else {
            "Calibration of the force transducer (Ng, Table 1)"
        },
    );
    let mut notes = Vec::new();
    let mut meta = serde_json::Map::new();
    for (kind, fit, dash, name) in [
        (Fit::Origin, origin, Dash::Solid, "through the origin"),
        (Fit::Intercept, intercept, Dash::Dashed, "with an intercept"),
    ] {
        if which != kind && which != Fit::Both {
            continue;
        }
        let line = move |x: f64| Some((Point::new(x, fit.at(x)), Vector::new(1.0, fit.slope)));
        let pieces: [(&dyn Curve, _); 1] = [(&line, x0..=x1)];
        plot.curve(
            &format!("curve-fit-{}", kind.name()),
            &pieces,
            dash,
            Some(&format!("fit {name}: {}", equation(&fit))),
        )?;
        if kind == Fit::Origin {
            notes.push(format!(
                "through the origin: *R*² = {:.4} about zero",
                fit.r_squared_uncentred
            ));
            notes.push(format!(
                "(Ng’s 0.9998), {:.4} about the mean",
                fit.r_squared
            ));
        } else {
            notes.push(format!("with an intercept: *R*² = {:.4}", fit.r_squared));
        }
        meta.insert(
            kind.name().into(),
            json!({"slope": fit.slope, "intercept": fit.intercept,
                   "r_squared": fit.r_squared, "r_squared_uncentred": fit.r_squared_uncentred}),
        );
    }
    plot.points("point-calibration", &points, Symbol::Disc, Some("measured"));
    plot.note("r-squared", &notes);
    sheet.meta("fits", serde_json::Value::Object(meta));
    sheet.plot(plot);
    Ok(sheet.finish())
}
