//! The relative-velocity method: the velocity and acceleration polygons
//! (docs/polygons.md) as a worked step, beside §36–37's constructions.

use super::show;
use super::work::Work;
use super::{Picture, Row, Step, Value};
use crate::catalogue::FigureName;
use crate::construct::{AccelerationPolygon, VelocityPolygon};
use crate::error::Result;
use crate::handout::figures;

/// The page the polygons' figure is laid out on, px: wide and low (the
/// figure's own page is 533 by 720), so that printed it takes about 115
/// mm of a page's height and no page before it is left half empty for
/// want of room.
const PAGE: (f64, f64) = (760.0, 480.0);

/// The polygons of the handout's pose: the piston's velocity *oa* and the
/// rod's ab/AB, the piston's acceleration *o*′*a*′ and the rod's
/// *xa*′/AB, each beside the exact value.
pub(super) fn polygons(w: &Work) -> Result<Step> {
    let figure = figures::diagram_on_page(w.h, FigureName::VelocityAccelerationPolygons, PAGE)?;
    let pose = w.pose();
    let v = VelocityPolygon::construct(pose, None);
    let a = AccelerationPolygon::construct(pose, &v, None);
    let (om, u) = (w.omega(), w.length());
    let (r, l) = (w.mechanism().crank(), w.mechanism().rod());
    let ab = v.ab().norm();
    let text = vec![
        format!(
            "Draw *ob* = ω*r* = {} {u}/s perpendicular to *CB*; from *b* a line perpendicular to *AB* (the velocity of *B* relative to *A*), from *o* a line parallel to the stroke: they meet at *a*. *oa* is the piston's velocity, {} {u}/s, and *ab*/*AB* = {} rad/s the rod's angular velocity.",
            show(om.abs() * r),
            show(om * v.slider_velocity_ratio()),
            show(om.abs() * ab / l),
        ),
        format!(
            "Draw *o*′*b*′ = ω²*r* = {} {u}/s² towards *C*; from *b*′ the rod's normal component (*ab*)²/*AB* = {} {u}/s² along *AB* towards *B*, to *x*; from *x* a line perpendicular to *AB*, from *o*′ a line parallel to the stroke: they meet at *a*′. *o*′*a*′ is the piston's acceleration, {} {u}/s², and *xa*′/*AB* = {} rad/s² the rod's angular acceleration.",
            show(om * om * r),
            show(om * om * ab * ab / l),
            show(om * om * a.slider_acceleration_ratio()),
            show(om * om * a.tangential().norm() / l),
        ),
    ];
    Ok(Step {
        id: "polygons",
        title: "The velocity and acceleration polygons".into(),
        source: "the relative-velocity method",
        text,
        pictures: vec![Picture::of(
            &figure,
            "polygons",
            "The velocity polygon *oba* and the acceleration polygon *o*′*b*′*xa*′, each to the scale its notes state.",
        )],
        rows: polygons_rows(w, &v, &a),
    })
}

/// The piston's and the rod's rates read off the polygons, beside the
/// exact values; shown, not asked on an exercise sheet (the sheet asks
/// them of §36–37's constructions).
fn polygons_rows(w: &Work, v: &VelocityPolygon, a: &AccelerationPolygon) -> Vec<Row> {
    let (om, k) = (w.omega(), &w.r.exact);
    let u = w.length();
    let row = |quantity: &str, read: Value, exact: Value, unit: String| {
        Row::new(quantity, Some(read), Some(exact), &unit).not_asked()
    };
    vec![
        row(
            "piston velocity, *oa*",
            Value::of("polygons.slider_velocity", om * v.slider_velocity_ratio()),
            Value::of("analytic.velocity", k.velocity),
            format!("{u}/s"),
        ),
        row(
            "rod angular velocity, *ab*/*AB*",
            Value::of(
                "polygons.rod_angular_velocity",
                om * v.rod_angular_velocity_ratio(),
            ),
            Value::of("analytic.rod_angular_velocity", k.rod_angular_velocity),
            "rad/s".into(),
        ),
        row(
            "piston acceleration, *o*′*a*′",
            Value::of(
                "polygons.slider_acceleration",
                om * om * a.slider_acceleration_ratio(),
            ),
            Value::of("analytic.acceleration", k.acceleration),
            format!("{u}/s²"),
        ),
        row(
            "rod angular acceleration, *xa*′/*AB*",
            Value::of(
                "polygons.rod_angular_acceleration",
                om * om * a.rod_angular_acceleration_ratio(),
            ),
            Value::of(
                "analytic.rod_angular_acceleration",
                k.rod_angular_acceleration,
            ),
            "rad/s²".into(),
        ),
    ]
}
