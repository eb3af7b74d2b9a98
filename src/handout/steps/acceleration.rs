//! §36, the acceleration: Kisch's construction, and the acceleration scale
//! that turns *CG* into the piston acceleration.

use super::show;
use super::work::Work;
use super::{Picture, Row, Step, Value};
use crate::analytic::approx;
use crate::catalogue::FigureName;
use crate::error::Result;
use crate::handout::figures;

/// §36, Fig. 66: Kisch's construction for *F* and *G*, with its enlarged
/// detail when the construction is small.
pub(super) fn kisch(w: &Work) -> Result<Step> {
    let fig66 = figures::mechanism(w.h, FigureName::Fig66Kisch, None)?;
    let r = w.r;
    let u = w.length();
    let mut text = vec![format!(
        "On *AB* describe a semicircle *AHB*. With centre *B* and radius *BE* = {} {u} cut it in *H*. Draw *HFG* perpendicular to *AB*, cutting *AB* in *F* and the line through *C* parallel to the stroke in *G*. As *BF*/*BH* = *BH*/*BA* and *BH* = *BE*, *BA* · *BF* = *BE*²: *BF* = {} {u}, and *CG* = {} {u} represents the piston acceleration.",
        show(r.be),
        show(r.bf()),
        show(r.cg.abs())
    )];
    if fig66.panels().len() > 1 {
        text.push("Near the crank the construction is small at the scale of the engine: the framed detail repeats it enlarged.".into());
    }
    text.push("Kisch's construction never needs *D*. Klein's (Fig. 65) draws *CF* parallel to *DE* and finds the same *F* and *G*.".into());
    Ok(Step {
        id: "kisch",
        title: "Kisch's construction".into(),
        source: "§36, Fig. 66",
        text,
        pictures: vec![Picture::of(
            &fig66,
            "fig-66",
            "Kisch's construction: the semicircle on *AB*, the circle about *B* through *E*, *H*, and *HFG* perpendicular to *AB*.",
        )],
        rows: kisch_rows(w),
    })
}

/// The lengths of Kisch's construction: *BE* and *BF* (shown, not asked),
/// *CG* and *FG*.
pub(super) fn kisch_rows(w: &Work) -> Vec<Row> {
    let (r, len) = (w.r, w.length());
    vec![
        Row::new(
            "*BE*, radius of the circle about *B*",
            Some(Value::of("construction.BE", r.be)),
            None,
            len,
        )
        .not_asked(),
        Row::new(
            "*BF*, where *HF* meets *AB*",
            Some(Value::of("construction.BF", r.bf())),
            Some(Value::of(
                "construction.BF_exact",
                r.be * r.be / w.mechanism().rod(),
            )),
            len,
        )
        .not_asked(),
        Row::new("*CG*", Some(Value::of("construction.CG", r.cg)), None, len),
        Row::new("*FG*", Some(Value::of("construction.FG", r.fg)), None, len),
    ]
}

/// §36, Fig. 67: the acceleration scale, 1 unit of length to ω², and the
/// piston acceleration it gives; beside the textbook's eq. (3) in line.
pub(super) fn acceleration_scale(w: &Work) -> Result<Step> {
    let fig67 = figures::mechanism(w.h, FigureName::Fig67Example, None)?;
    let mut text = vec![scale(w)];
    text.push("Signed: d²*x*/d*t*² = −ω² · *CG*.".into());
    if w.in_line() {
        text.push(format!(
            "The textbook's eq. (3), (*V*_c²/*r*)(cos θ + cos 2θ/*n*), gives {} {} against the exact {}.",
            show(approx::acceleration(w.pose(), w.omega()).approx.abs()),
            w.n.acceleration,
            show(w.r.exact.acceleration.abs())
        ));
    }
    Ok(Step {
        id: "acceleration-scale",
        title: "The acceleration scale".into(),
        source: "§36, Fig. 67",
        text,
        pictures: vec![Picture::of(
            &fig67,
            "fig-67",
            "The whole construction with its velocity and acceleration scales.",
        )],
        rows: acceleration_scale_rows(w),
    })
}

/// The scale and the piston acceleration *CG* represents.
fn scale(w: &Work) -> String {
    let (u, omega) = (w.length(), w.omega());
    let (velocity, acceleration) = (&w.n.velocity, &w.n.acceleration);
    format!(
        "If 1 {u} of the drawing represents ω = {} {velocity} of velocity, 1 {u} of *CG* represents ω² = {} {acceleration} of acceleration. *CG* = {} {u}, so the piston acceleration is ω² · *CG* = {} {acceleration}, directed from *G* towards *C*.",
        show(omega),
        show(omega * omega),
        show(w.r.cg.abs()),
        show(w.r.graphical.acceleration.abs())
    )
}

/// The piston acceleration, read off and exact.
pub(super) fn acceleration_scale_rows(w: &Work) -> Vec<Row> {
    vec![Row::new(
        "piston acceleration d²*x*/d*t*² = −ω² · *CG*",
        Some(Value::of(
            "graphical.acceleration",
            w.r.graphical.acceleration,
        )),
        Some(Value::of("analytic.acceleration", w.r.exact.acceleration)),
        &w.n.acceleration,
    )]
}
