//! The curve engine's benchmark as a figure: segments and time against the
//! measured error, log–log, for each curve and method of
//! docs/curve-benchmarks.csv (written by `examples/curve_table.rs`), or of
//! the table given as data.

use super::{Ctx, Sheet, Table};
use crate::diagram::{Axis, LEGEND_GAP, Plot};
use crate::error::{Error, Input, Result};
use crate::figure::{Dash, Figure, Symbol};
use crate::geom::{Frame, Point};

/// The table the repository ships.
const TABLE: &str = include_str!("../../../docs/curve-benchmarks.csv");

/// The methods drawn, with their markers and names.
const METHODS: [(&str, Symbol, &str); 3] = [
    ("cubic", Symbol::Disc, "cubic Béziers, adaptive"),
    ("polyline", Symbol::Square, "line segments, adaptive"),
    ("uniform", Symbol::Triangle, "line segments, equal steps"),
];

/// One row: curve, method, segments, measured error, time.
struct Row<'a> {
    curve: &'a str,
    method: &'a str,
    segments: f64,
    error: f64,
    time: f64,
}

/// The narrowest page (page units) that sets the two plots side by side,
/// each with its legend inside.
const NARROWEST_COLUMNS: f64 = 700.0;

/// A plot whose legend is taller than this share of its height cannot
/// hold it in a corner clear of the data (the sweep of the table's rows
/// fills the plot from corner to corner): on a page this short the two
/// plots share one legend beside the second. At the figure's own page
/// the legend takes a fifth of a plot's height; at 800 × 300, two
/// fifths, where it lay on the data in both.
const SHORT: f64 = 0.35;

/// One of the two plots: its id, ordinate's title, caption and the value
/// of a row it draws against the measured error.
type Panel = (&'static str, &'static str, &'static str, fn(&Row) -> f64);

/// The two plots.
const PANELS: [Panel; 2] = [
    (
        "segments",
        "segments",
        "(a) Segments against measured error",
        |r| r.segments,
    ),
    (
        "time",
        "time per curve (µs)",
        "(b) Time against measured error",
        |r| r.time,
    ),
];

pub(in crate::catalogue) fn build(ctx: &Ctx) -> Result<Figure> {
    let page = ctx.page();
    let text = ctx.options.data.as_deref().unwrap_or(TABLE);
    let table = Table::parse(text, Input::Data, "data")?;
    let rows = rows(&table)?;
    let mut sheet = Sheet::new(ctx);
    sheet.mechanism(ctx, false, false);
    // Side by side where each holds its legend (about 330 units wide);
    // on a narrower page one above the other, each as tall as beside.
    let columns = page.width() >= NARROWEST_COLUMNS;
    let width = match columns {
        true => 0.5 * (page.width() - 48.0),
        false => page.width() - 32.0,
    };
    let height = page.height() - 32.0 - 40.0;
    let place = |k: usize| match columns {
        true => Point::new(16.0 + k as f64 * (width + 16.0), 16.0),
        false => Point::new(16.0, 16.0 + k as f64 * (height + 16.0)),
    };
    let notes_top = match columns {
        true => page.height() - 40.0,
        false => {
            let top = 16.0 + 2.0 * (height + 16.0);
            sheet.height(top + 40.0);
            top
        }
    };
    // The legend, the same for both plots, measured on a plot of the
    // first's place.
    let (legend, tall) = plot(
        ctx,
        &rows,
        PANELS[1],
        Frame::from_origin_size(16.0, 16.0, width, height),
    )?
    .legend_size();
    if columns && tall > SHORT * height {
        // Too short a page for either plot to hold the legend clear of
        // its data: one legend for both, beside the second.
        let room = legend + LEGEND_GAP;
        let width = 0.5 * (page.width() - 48.0 - room);
        let rects = [
            Frame::from_origin_size(16.0, 16.0, width, height),
            Frame::from_origin_size(32.0 + width, 16.0, width + room, height),
        ];
        let first = plot(ctx, &rows, PANELS[0], rects[0])?.without_legend();
        sheet.plot(first);
        sheet.plot(plot(ctx, &rows, PANELS[1], rects[1])?.with_legend_set_beside());
    } else {
        for (k, panel) in PANELS.into_iter().enumerate() {
            let at = place(k);
            let rect = Frame::from_origin_size(at.x, at.y, width, height);
            sheet.plot(plot(ctx, &rows, panel, rect)?);
        }
    }
    sheet.notes(
        Point::new(20.0, notes_top),
        &[if ctx.options.data.is_some() {
            "From the table given.".to_string()
        } else {
            "The library’s own curves as it flattens them: segments, measured error and criterion times, on the machine that measured them.".to_string()
        }],
    );
    Ok(sheet.finish())
}

/// The rows of `table` of a method drawn with positive segments, error
/// and time; refused where there are none.
fn rows(table: &Table) -> Result<Vec<Row<'_>>> {
    let curves = table.texts(table.column(&["curve"])?)?;
    let methods = table.texts(table.column(&["method"])?)?;
    let segments = table.numbers(table.column(&["segments"])?)?;
    let errors = table.numbers(table.column(&["measured"])?)?;
    let times = table.numbers(table.column(&["time"])?)?;
    let rows: Vec<Row> = curves
        .into_iter()
        .zip(methods)
        .zip(segments)
        .zip(errors)
        .zip(times)
        .map(|((((curve, method), segments), error), time)| Row {
            curve,
            method,
            segments,
            error,
            time,
        })
        .filter(|r| METHODS.iter().any(|m| m.0 == r.method))
        .filter(|r| r.segments > 0.0 && r.error > 0.0 && r.time > 0.0)
        .collect();
    if rows.is_empty() {
        return Err(Error::invalid(Input::Data,
            "data: no row of method cubic, polyline or uniform with positive segments, error and time"
                .into(),
        ));
    }
    Ok(rows)
}

/// The least and greatest of `f` over `rows`.
fn range(rows: &[Row], f: &dyn Fn(&Row) -> f64) -> (f64, f64) {
    rows.iter()
        .map(f)
        .fold((f64::INFINITY, 0.0f64), |(lo, hi), v| {
            (lo.min(v), hi.max(v))
        })
}

/// One plot of `rows` in `rect`, log–log: a line style a curve, a marker
/// a method, with a decade of room above the data for the legend.
fn plot(
    ctx: &Ctx,
    rows: &[Row],
    (name, title, caption, value): Panel,
    rect: Frame,
) -> Result<Plot> {
    let mut names: Vec<&str> = Vec::new();
    for r in rows {
        if !names.contains(&r.curve) {
            names.push(r.curve);
        }
    }
    let (e0, e1) = range(rows, &|r| r.error);
    let (lo, hi) = range(rows, &value);
    let x = Axis::log("measured error (px)", e0, e1)?;
    let y = Axis::log(title, lo, 10.0 * hi)?;
    let mut plot = Plot::new(name, rect, x, y, ctx.tolerance, ctx.font)?
        .with_grid()
        .with_caption(caption);
    let dashes = [Dash::Solid, Dash::Dashed, Dash::DashDot, Dash::Dotted];
    for (curve, &dash) in names.iter().zip(dashes.iter().cycle()) {
        for (method, symbol, _) in METHODS {
            let mut points: Vec<(f64, f64)> = rows
                .iter()
                .filter(|r| r.curve == *curve && r.method == method)
                .map(|r| (r.error, value(r)))
                .collect();
            points.sort_by(|a, b| a.0.total_cmp(&b.0));
            let id = format!("{name}-{curve}-{method}");
            plot.line(&format!("series-{id}"), &points, dash, None);
            plot.points(&format!("point-{id}"), &points, symbol, None);
        }
        plot.legend_line(&format!("curve: {curve}"), dash);
    }
    for (_, symbol, label) in METHODS {
        plot.legend_marker(label, symbol);
    }
    Ok(plot)
}
