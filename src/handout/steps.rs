//! The worked steps of a handout: §35–37 and Ng for one engine, each step
//! its text, figures and the values read off the construction beside the
//! exact ones, all taken from one [`Reading`].

use super::Handout;
use super::figures;
use crate::FigureName;
use crate::analytic::approx;
use crate::analytic::statics::Friction;
use crate::construct::Reading;
use crate::error::Result;

/// A value shown on a page: its name as `analyze --json` gives it
/// (`graphical.velocity`; `construction.CE` for the lengths of the
/// constructions) and the number, `None` where there is none (D at
/// infinity, a dead centre's force).
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Value {
    pub key: &'static str,
    pub value: Option<f64>,
    /// What is written where there is no number.
    pub none: &'static str,
}

impl Value {
    pub fn of(key: &'static str, value: f64) -> Self {
        Self {
            key,
            value: Some(value),
            none: "",
        }
    }

    pub fn maybe(key: &'static str, value: Option<f64>, none: &'static str) -> Self {
        Self { key, value, none }
    }
}

/// A row of a step's table: a quantity, the value read off the
/// construction (if it is read off one), the exact value, the unit.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Row {
    /// The quantity, in rich-text markup.
    pub quantity: String,
    pub read: Option<Value>,
    pub exact: Option<Value>,
    pub unit: String,
    /// Whether the student is asked for it on an exercise sheet.
    pub asked: bool,
}

impl Row {
    fn new(quantity: &str, read: Option<Value>, exact: Option<Value>, unit: &str) -> Self {
        Self {
            quantity: quantity.into(),
            read,
            exact,
            unit: unit.into(),
            asked: true,
        }
    }

    fn not_asked(mut self) -> Self {
        self.asked = false;
        self
    }
}

/// A figure of a step: inline SVG and its caption (rich text).
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Picture {
    pub svg: String,
    pub caption: String,
}

/// One step of the handout.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Step {
    pub id: &'static str,
    pub title: String,
    /// The seed's section and figure.
    pub source: &'static str,
    /// Paragraphs, rich text.
    pub text: Vec<String>,
    pub pictures: Vec<Picture>,
    pub rows: Vec<Row>,
}

/// A number as a page shows it: four significant figures, a true minus
/// sign, powers of ten beyond 10⁹ and below 10⁻⁴.
pub(super) fn show(x: f64) -> String {
    if x == 0.0 || !x.is_finite() {
        return "0".into();
    }
    let a = x.abs();
    let text = if (1e-4..1e9).contains(&a) {
        let digits = (3 - a.log10().floor() as i32).clamp(0, 12) as usize;
        format!("{x:.digits$}")
    } else {
        let k = a.log10().floor() as i32;
        let m = x / 10f64.powi(k);
        format!("{m:.3} × 10{}", superscript(k))
    };
    text.replace('-', "−")
}

/// A given number (a datum, not a result) as a page shows it: [`show`]
/// without trailing zeros (`250`, `0.5`, `40`).
pub(super) fn short(x: f64) -> String {
    let s = show(x);
    if s.contains('.') && !s.contains('×') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    }
}

/// `k` in Unicode superscripts (`⁻¹²`).
fn superscript(k: i32) -> String {
    k.to_string()
        .chars()
        .map(|c| match c {
            '-' => '⁻',
            d => ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹'][d as usize - '0' as usize],
        })
        .collect()
}

/// Units of a page.
struct Names {
    length: String,
    velocity: String,
    acceleration: String,
    force: String,
    torque: String,
}

impl Names {
    fn of(h: &Handout) -> Self {
        let u = h.units();
        Self {
            length: u.length().as_str().to_string(),
            velocity: u.velocity(),
            acceleration: u.acceleration(),
            force: u.force().as_str().to_string(),
            torque: u.torque(),
        }
    }
}

/// The rows of every value a handout and its exercise show, in order.
pub(super) fn rows(h: &Handout, r: &Reading) -> Vec<Row> {
    steps_rows(h, r).into_iter().flatten().collect()
}

/// The rows of each step, in order of the steps.
fn steps_rows(h: &Handout, r: &Reading) -> Vec<Vec<Row>> {
    let n = Names::of(h);
    let (len, vel, acc) = (
        n.length.as_str(),
        n.velocity.as_str(),
        n.acceleration.as_str(),
    );
    let m = h.mechanism();
    let k = &r.exact;
    let g = &r.graphical;
    let mut all = vec![
        vec![
            Row::new(
                "position of the cross-head *x*",
                None,
                Some(Value::of("analytic.position", k.position)),
                len,
            ),
            Row::new(
                "obliquity of the rod φ",
                None,
                Some(Value::of(
                    "analytic.rod_angle_deg",
                    k.rod_angle.to_degrees(),
                )),
                "°",
            ),
        ],
        vec![
            Row::new("*CE*", Some(Value::of("construction.CE", r.ce)), None, len),
            Row::new(
                "*BD*",
                Some(Value::maybe("construction.BD", r.bd(), "at infinity")),
                None,
                len,
            ),
        ],
        vec![Row::new(
            "piston velocity d*x*/d*t* = −ω · *CE*",
            Some(Value::of("graphical.velocity", g.velocity)),
            Some(Value::of("analytic.velocity", k.velocity)),
            vel,
        )],
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
                Some(Value::of("construction.BF_exact", r.be * r.be / m.rod())),
                len,
            )
            .not_asked(),
            Row::new("*CG*", Some(Value::of("construction.CG", r.cg)), None, len),
            Row::new("*FG*", Some(Value::of("construction.FG", r.fg)), None, len),
        ],
        vec![Row::new(
            "piston acceleration d²*x*/d*t*² = −ω² · *CG*",
            Some(Value::of("graphical.acceleration", g.acceleration)),
            Some(Value::of("analytic.acceleration", k.acceleration)),
            acc,
        )],
        vec![
            Row::new(
                "rod angular velocity dφ/d*t*, ω · *CB*/*BD*",
                Some(Value::of(
                    "graphical.rod_angular_velocity",
                    g.rod_angular_velocity,
                )),
                Some(Value::of(
                    "analytic.rod_angular_velocity",
                    k.rod_angular_velocity,
                )),
                "rad/s",
            ),
            Row::new(
                "rod angular acceleration d²φ/d*t*², ω² · *FG*/*l*",
                Some(Value::of(
                    "graphical.rod_angular_acceleration",
                    g.rod_angular_acceleration,
                )),
                Some(Value::of(
                    "analytic.rod_angular_acceleration",
                    k.rod_angular_acceleration,
                )),
                "rad/s²",
            ),
        ],
    ];
    if let Some(s) = &r.statics {
        let with_friction = match s.with_friction {
            Some(Friction::Force(f)) => Some(f),
            _ => None,
        };
        let no_friction = match s.with_friction {
            Some(Friction::SelfLocking(_)) => "self-locking",
            _ => "none (dead centre)",
        };
        all.push(vec![
            Row::new(
                "torque line *OM* (= *CE*)",
                Some(Value::of("construction.CE", r.ce)),
                Some(Value::of("statics.OM", s.om)),
                len,
            ),
            Row::new(
                "slider force *F*_p = *T*/*OM*",
                None,
                Some(Value::maybe(
                    "statics.slider_force",
                    s.force,
                    "none (dead centre)",
                )),
                &n.force,
            ),
            Row::new(
                "side thrust *F*_s = *F*_p tan φ",
                None,
                Some(Value::maybe(
                    "statics.side_thrust",
                    s.side_thrust,
                    "none (dead centre)",
                )),
                &n.force,
            ),
            Row::new(
                "with friction *F*_p′ = *F*_p(1 − μ tan φ)",
                None,
                Some(Value::maybe(
                    "statics.slider_force_with_friction",
                    with_friction,
                    no_friction,
                )),
                &n.force,
            ),
            Row::new(
                "transmission angle β",
                None,
                Some(Value::of(
                    "statics.transmission_angle_deg",
                    s.transmission_deg,
                )),
                "°",
            ),
        ]);
    }
    all
}

/// "above" or "below" the crank centre.
fn side(e: f64) -> &'static str {
    if e > 0.0 { "above" } else { "below" }
}

/// The data of the engine, as a sentence.
pub(super) fn data_sentence(h: &Handout) -> String {
    let n = Names::of(h);
    let m = h.mechanism();
    let u = &n.length;
    let mut s = format!(
        "Crank radius *r* = {} {u}, connecting rod *l* = {} {u} (*n* = *l*/*r* = {}), ",
        short(m.crank()),
        short(m.rod()),
        short(m.ratio())
    );
    if m.offset() == 0.0 {
        s.push_str("in line; ");
    } else {
        s.push_str(&format!(
            "line of stroke *e* = {} {u} {} the crank centre; ",
            short(m.offset().abs()),
            side(m.offset())
        ));
    }
    s.push_str(&format!(
        "{} rpm (ω = {} rad/s); crank angle θ = {}°",
        short(h.rpm()),
        show(h.omega()),
        short(h.angle().degrees())
    ));
    if let Some(t) = h.torque() {
        s.push_str(&format!(
            "; crank torque *T* = {} {}, μ = {}",
            short(t),
            n.torque,
            short(h.friction())
        ));
    }
    s.push('.');
    s
}

/// Every step of the handout.
pub(super) fn steps(h: &Handout, r: &Reading) -> Result<Vec<Step>> {
    let n = Names::of(h);
    let u = n.length.as_str();
    let m = h.mechanism();
    let pose = &r.pose;
    let omega = h.omega();
    let vc = m.crank() * omega;
    let in_line = m.offset() == 0.0;
    let mut rows = steps_rows(h, r).into_iter();
    let mut next = || rows.next().unwrap_or_default();
    let mut steps = Vec::new();

    // §35: the mechanism to scale.
    let fig62 = figures::mechanism(h, FigureName::Fig62Displacement, None)?;
    let mut text = vec![
        format!(
            "The crank *CB* of radius *r* = {} {u} turns about *C* at *N* = {} rpm, so ω = 2π*N*/60 = {} rad/s and the crank pin *B* moves at *V*_c = *r*ω = {} {}.",
            short(m.crank()),
            short(h.rpm()),
            show(omega),
            show(vc),
            n.velocity
        ),
        format!(
            "Draw the crank at θ = {}°, counter-clockwise from the outer dead centre (the crank pointing at the cross-head), and find the cross-head *A* on the line of stroke with the compasses set to the rod's length *l* = {} {u} about *B*.",
            short(h.angle().degrees()),
            short(m.rod())
        ),
    ];
    text.push(if in_line {
        format!(
            "The rod's obliquity φ follows from sin φ = sin θ/*n* with *n* = *l*/*r* = {}, and the cross-head stands at *x* = *r* cos θ + *r*√(*n*² − sin²θ) from *C*. Its difference from simple harmonic motion, the error due to obliquity *r*(√(*n*² − sin²θ) − *n*), is {} {u} here.",
            short(m.ratio()),
            show(pose.obliquity_error())
        )
    } else {
        format!(
            "The line of stroke is *e* = {} {u} {} the crank centre, so sin φ = (*r* sin θ − *e*)/*l* and *x* = *r* cos θ + √(*l*² − (*r* sin θ − *e*)²).",
            short(m.offset().abs()),
            side(m.offset())
        )
    });
    steps.push(Step {
        id: "mechanism",
        title: "The mechanism to scale".into(),
        source: "§35, Fig. 62",
        text,
        pictures: vec![Picture {
            svg: figures::inline(&fig62, "fig-62"),
            caption: format!(
                "The engine at θ = {}°: crank angle θ, obliquity φ, the displacement *x* of the cross-head from mid-stroke.",
                short(h.angle().degrees())
            ),
        }],
        rows: next(),
    });

    // §36: D and E.
    let fig63 = figures::mechanism(h, FigureName::Fig63Velocity, None)?;
    let mut text = vec![
        "*A* moves along the line of stroke and *B* at right angles to *CB*, so the rod's instantaneous centre *D* is where *CB* produced meets the perpendicular to the stroke through *A*. Produce *AB* to meet the perpendicular to the stroke through *C* in *E*. The triangles *ADB* and *ECB* are similar, so *V*_p/*V*_c = *AD*/*BD* = *CE*/*CB*.".to_string(),
    ];
    text.push(match r.bd() {
        Some(bd) => format!(
            "Measured: *CE* = {} {u} and *BD* = {} {u}. Where *D* falls off the drawing, *E* can still be found: it needs only the rod produced.",
            show(r.ce.abs()),
            show(bd)
        ),
        None => format!(
            "At this angle *CB* is perpendicular to the stroke: *D* is at infinity and the rod, for the instant, does not turn. *E* is still found, *CE* = {} {u}.",
            show(r.ce.abs())
        ),
    });
    steps.push(Step {
        id: "velocity",
        title: "D and E: the velocity construction".into(),
        source: "§36, Fig. 63",
        text,
        pictures: vec![Picture {
            svg: figures::inline(&fig63, "fig-63"),
            caption: "*D*, the instantaneous centre of the rod, and *E* on the perpendicular to the stroke through *C*; *CE* represents the piston velocity.".into(),
        }],
        rows: next(),
    });

    // §36: the velocity scale.
    let mut text = vec![format!(
        "*CB* = {} {u} represents *V*_c = {} {}, so the velocity scale is 1 {u} = *V*_c/*CB* = ω = {} {}. *CE* = {} {u} therefore represents a piston velocity of {} {}, {}.",
        short(m.crank()),
        show(vc),
        n.velocity,
        show(omega),
        n.velocity,
        show(r.ce.abs()),
        show(r.graphical.velocity.abs()),
        n.velocity,
        if r.graphical.velocity < 0.0 {
            "towards the crank"
        } else if r.graphical.velocity > 0.0 {
            "away from the crank"
        } else {
            "at rest"
        }
    )];
    text.push(
        "Signed as the rate of change of *x*, d*x*/d*t* = −ω · *CE*: negative while the piston moves towards the crank.".into(),
    );
    if in_line {
        text.push(format!(
            "The textbook's approximation, eq. (2), *V*_p ≈ *V*_c(sin θ + sin 2θ/2*n*), gives {} {} against the exact {}.",
            show(approx::velocity(pose, omega).approx.abs()),
            n.velocity,
            show(r.exact.velocity.abs())
        ));
    }
    steps.push(Step {
        id: "velocity-scale",
        title: "The velocity scale".into(),
        source: "§36",
        text,
        pictures: vec![],
        rows: next(),
    });

    // §36: Kisch.
    let fig66 = figures::mechanism(h, FigureName::Fig66Kisch, None)?;
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
    steps.push(Step {
        id: "kisch",
        title: "Kisch's construction".into(),
        source: "§36, Fig. 66",
        text,
        pictures: vec![Picture {
            svg: figures::inline(&fig66, "fig-66"),
            caption: "Kisch's construction: the semicircle on *AB*, the circle about *B* through *E*, *H*, and *HFG* perpendicular to *AB*.".into(),
        }],
        rows: next(),
    });

    // §36: the acceleration scale.
    let fig67 = figures::mechanism(h, FigureName::Fig67Example, None)?;
    let mut text = vec![format!(
        "If 1 {u} of the drawing represents ω = {} {} of velocity, 1 {u} of *CG* represents ω² = {} {} of acceleration. *CG* = {} {u}, so the piston acceleration is ω² · *CG* = {} {}, directed from *G* towards *C*.",
        show(omega),
        n.velocity,
        show(omega * omega),
        n.acceleration,
        show(r.cg.abs()),
        show(r.graphical.acceleration.abs()),
        n.acceleration
    )];
    text.push("Signed: d²*x*/d*t*² = −ω² · *CG*.".into());
    if in_line {
        text.push(format!(
            "The textbook's eq. (3), (*V*_c²/*r*)(cos θ + cos 2θ/*n*), gives {} {} against the exact {}.",
            show(approx::acceleration(pose, omega).approx.abs()),
            n.acceleration,
            show(r.exact.acceleration.abs())
        ));
    }
    steps.push(Step {
        id: "acceleration-scale",
        title: "The acceleration scale".into(),
        source: "§36, Fig. 67",
        text,
        pictures: vec![Picture {
            svg: figures::inline(&fig67, "fig-67"),
            caption: "The whole construction with its velocity and acceleration scales.".into(),
        }],
        rows: next(),
    });

    // §37: the rod.
    let rod_motion = figures::diagram(h, FigureName::RodMotion)?;
    let mut text = vec![match r.bd() {
        Some(bd) => format!(
            "The rod turns about *D* while the crank turns about *C*: its angular velocity is *V*_c/*BD* = ω · *CB*/*BD* = {} × {}/{} = {} rad/s.",
            show(omega),
            short(m.crank()),
            show(bd),
            show(r.graphical.rod_angular_velocity.abs())
        ),
        None => "With *D* at infinity the rod's angular velocity *V*_c/*BD* is zero.".into(),
    }];
    text.push(format!(
        "*FG* = {} {u} gives its angular acceleration, ω² · *FG*/*l* = {} rad/s².",
        show(r.fg.abs()),
        show(r.graphical.rod_angular_acceleration.abs())
    ));
    if in_line {
        text.push(format!(
            "The textbook's eq. (2a), −(*V*_c²/*r*²) sin θ/√(*n*² − sin²θ), gives {} rad/s² against the exact {}.",
            show(approx::rod_angular_acceleration(pose, omega).approx),
            show(r.exact.rod_angular_acceleration)
        ));
    }
    steps.push(Step {
        id: "rod",
        title: "The rod's angular velocity and acceleration".into(),
        source: "§37",
        text,
        pictures: vec![Picture {
            svg: figures::inline(&rod_motion, "rod-motion"),
            caption: "The rod's angular velocity and acceleration over the turn.".into(),
        }],
        rows: next(),
    });

    // Ng: the OM line and the forces.
    if let (Some(s), Some(t)) = (&r.statics, h.torque()) {
        let ng1 = figures::mechanism(h, FigureName::NgFig1Torque, None)?;
        let mut text = vec![
            "In Ng's letters the crank centre is *O*, the crank pin *C*, the slider *P*, and *M* is the textbook's *E*: *OM* = *CE*. With no friction, virtual work gives *F*_p · *OM* = *T* (eq. 2).".to_string(),
        ];
        text.push(match s.force {
            Some(f) => format!(
                "The crank torque *T* = {} {} and *OM* = {} {u} give the slider force *F*_p = *T*/*OM* = {} {} (eq. 6), and the side thrust on the guides *F*_s = *F*_p tan φ = {} {} (eq. 7).",
                short(t),
                n.torque,
                show(s.om),
                show(f),
                n.force,
                show(s.side_thrust.unwrap_or(0.0)),
                n.force
            ),
            None => "At a dead centre *OM* = 0: no finite slider force balances the torque.".into(),
        });
        text.push(match s.with_friction {
            Some(Friction::Force(f)) => format!(
                "With friction μ = {} in the guides, *F*_p′ = *F*_p(1 − μ tan φ) = {} {} (eq. 8). The transmission angle at the crank pin is β = {}° (eq. 11).",
                short(s.mu),
                show(f),
                n.force,
                show(s.transmission_deg)
            ),
            Some(Friction::SelfLocking(k)) => format!(
                "With friction μ = {} in the guides μ tan φ = {} ≥ 1: friction alone holds the slider. The transmission angle at the crank pin is β = {}°.",
                short(s.mu),
                show(k),
                show(s.transmission_deg)
            ),
            None => format!(
                "The transmission angle at the crank pin is β = {}°.",
                show(s.transmission_deg)
            ),
        });
        steps.push(Step {
            id: "forces",
            title: "The OM line and the forces".into(),
            source: "Ng, Fig. 1, eq. 2–11",
            text,
            pictures: vec![Picture {
                svg: figures::inline(&ng1, "ng-fig-1"),
                caption: "Ng's Fig. 1 for this engine: the torque line *OM*, the slider force and the side thrust.".into(),
            }],
            rows: next(),
        });
    }

    // §36: the diagrams.
    let velocity = figures::diagram(h, FigureName::Fig64VelocityDiagrams)?;
    let acceleration = figures::diagram(h, FigureName::AccelerationDiagrams)?;
    steps.push(Step {
        id: "diagrams",
        title: "Velocity and acceleration diagrams".into(),
        source: "§36, Fig. 64",
        text: vec![
            "Repeating the construction for a number of crank positions gives the diagrams: the polar diagram of piston velocity (*CE*′ = *CE* set off on the crank), the velocity on a distance base (*E*″ over *A*) and on a time base, against simple harmonic motion; then the same for the acceleration (*CG*). The pose worked above is marked.".into(),
        ],
        pictures: vec![
            Picture {
                svg: figures::inline(&velocity, "fig-64"),
                caption: "Piston velocity: polar diagram, distance base, time base.".into(),
            },
            Picture {
                svg: figures::inline(&acceleration, "acceleration"),
                caption: "Piston acceleration: distance base, time base, polar diagram.".into(),
            },
        ],
        rows: Vec::new(),
    });
    Ok(steps)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_show_four_figures_and_a_true_minus() {
        assert_eq!(show(10.3466), "10.35");
        assert_eq!(show(-0.351), "−0.3510");
        assert_eq!(show(242.1), "242.1");
        assert_eq!(show(1.5e10), "1.500 × 10¹⁰");
        assert_eq!(show(-2e-6), "−2.000 × 10⁻⁶");
        assert_eq!(show(0.0), "0");
        assert_eq!(short(250.0), "250");
        assert_eq!(short(0.5), "0.5");
        assert_eq!(short(1.5e10), "1.500 × 10¹⁰");
    }
}
