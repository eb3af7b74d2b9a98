//! The engine's dynamics, when a reciprocating mass is given: the inertia
//! force from Klein's *CG*, the crank effort *F*·*OM* through Ng's line,
//! the turning-moment diagram over the turn and the flywheel
//! (`docs/dynamics.md`).

use super::work::Work;
use super::{Picture, Row, Step, Value};
use super::{short, show};
use crate::catalogue::FigureName;
use crate::dynamics::{Engine, EnginePose, Flywheel, GasForce, IndicatorDiagram, TurningMoment};
use crate::error::Result;
use crate::handout::{Gas, figures};

/// What the dynamics steps share: the engine with its mass and gas
/// force, its forces at the pose, the turn and the flywheel.
struct Worked {
    engine: Engine,
    /// The gas force's indicator diagram; `None` for a constant force.
    diagram: Option<IndicatorDiagram>,
    gas: Gas,
    at: EnginePose,
    turn: TurningMoment,
    flywheel: Flywheel,
}

impl Worked {
    /// The dynamics of the handout's engine; `None` without a mass.
    ///
    /// Errors: a gas force whose units are not the handout's (the
    /// example's feet and pounds-force, a diagram's declared unit), and
    /// those of the engine's forces.
    fn of(w: &Work) -> Result<Option<Self>> {
        let Some(d) = &w.h.dynamics else {
            return Ok(None);
        };
        let units = w.h.units();
        let force = d.gas.force(units)?;
        let diagram = match &force {
            GasForce::Indicator(diagram) => Some(diagram.clone()),
            _ => None,
        };
        let engine = Engine::new(*w.mechanism(), d.mass, w.omega())?.with_gas(force)?;
        let at = engine.at(w.h.angle())?;
        let turn = TurningMoment::new(&engine, &[0.0])?;
        let flywheel = Flywheel::for_coefficient(turn.fluctuation, w.omega(), d.fluctuation)?;
        Ok(Some(Self {
            engine,
            diagram,
            gas: d.gas.clone(),
            at,
            turn,
            flywheel,
        }))
    }
}

/// The three steps of the dynamics, none without a mass.
pub(super) fn dynamics(w: &Work) -> Result<Vec<Step>> {
    let Some(d) = Worked::of(w)? else {
        return Ok(Vec::new());
    };
    Ok(vec![inertia(w, &d)?, turning(w, &d)?, flywheel(w, &d)?])
}

/// The dynamics of an exercise: the data it gives (the reciprocating
/// mass, the gas force at the pose) as a sentence, and the rows of the
/// inertia step, the gas force given rather than asked; `None` without a
/// mass.
pub(in crate::handout) fn exercise_dynamics(w: &Work) -> Result<Option<(String, Vec<Row>)>> {
    let Some(d) = Worked::of(w)? else {
        return Ok(None);
    };
    let data = format!(
        "Reciprocating mass *m* = {} {}; the gas force at this pose *F*_g = {} {} (positive towards the crank).",
        short(d.engine.reciprocating_mass()),
        mass_unit(w),
        show(d.at.gas_force),
        w.n.force
    );
    let rows = inertia_rows(w, &d)
        .into_iter()
        .map(|row| {
            if row.quantity.starts_with("gas force") {
                row.not_asked()
            } else {
                row
            }
        })
        .collect();
    Ok(Some((data, rows)))
}

/// The mass unit the forces imply ([`crate::units::Units::mass`]).
fn mass_unit(w: &Work) -> String {
    w.h.units().mass()
}

/// The inertia force from Klein's *CG*, the gas force, the piston effort
/// and the crank effort *F*·*OM*.
fn inertia(w: &Work, d: &Worked) -> Result<Step> {
    let figure = figures::dynamics(w.h, FigureName::InertiaForce)?;
    let (at, f, u) = (&d.at, &w.n.force, w.length());
    let m = d.engine.reciprocating_mass();
    let pose = w.pose();
    let mech = w.mechanism();
    let outer = mech.pose(mech.outer_dead_centre()).position();
    let fraction = (outer - pose.position()) / mech.stroke();
    let expansion = w.omega() * pose.position_rate() < 0.0;
    Ok(Step {
        id: "inertia",
        title: "The inertia force and the crank effort".into(),
        source: "§36, Fig. 65; Ng, eq. 2",
        text: vec![
            format!(
                "The piston and cross-head, of mass *m* = {} {}, need the force *m* d²*x*/d*t*² to follow the cross-head. Klein's *CG* = {} {u} gives d²*x*/d*t*² = −ω²·*CG*: the inertia force, positive towards the crank like every force on the piston here, is *F*_i = −*m*ω²·*CG* = {} {f}, against the exact {} {f}.",
                short(m),
                mass_unit(w),
                show(w.r.cg),
                show(at.inertia_force_graphical),
                show(at.inertia_force)
            ),
            gas_sentence(w, d, fraction, expansion),
            format!(
                "The piston effort *F* = *F*_g + *F*_i = {} {f} turns the crank through Ng's line: *T* = *F*·*OM* = {} × {} = {} {}, and by the exact formula *F* *r* sin(θ + φ)/cos φ = {}. The figure draws the inertia force alone.",
                show(at.piston_effort),
                show(at.piston_effort),
                show(at.om),
                show(at.crank_effort),
                w.n.torque,
                show(at.crank_effort_exact)
            ),
        ],
        pictures: vec![Picture::of(
            &figure,
            "inertia-force",
            "The inertia force −*m*ω²·*CG* from Klein's construction, drawn at the cross-head and resolved along the rod and on the guides, and its crank effort through *OM*.",
        )],
        rows: inertia_rows(w, d),
    })
}

/// What the inertia step says of the gas force at the pose: the
/// diagram's pressure there times the piston's area, or the constant.
fn gas_sentence(w: &Work, d: &Worked, fraction: f64, expansion: bool) -> String {
    let (f, u) = (&w.n.force, w.length());
    let Some(diagram) = &d.diagram else {
        return format!(
            "The gas force is taken constant, *F*_g = {} {f} towards the crank.",
            show(d.at.gas_force)
        );
    };
    let area = diagram.area();
    let whose = match &d.gas {
        Gas::Indicator { bore, source, .. } => format!(
            "The gas of the indicator diagram {source} (gauge pressure against the stroke) acts on a bore *D* = {} {u}",
            short(*bore)
        ),
        _ => "The steam of the indicator diagram (gauge pressure against the stroke, 100 psi cut off at 30 %) acts on a 10 in bore".into(),
    };
    format!(
        "{whose}, *A* = π*D*²/4 = {} {u}². Here the piston is {} % of the stroke from the outer dead centre on the {} stroke: *p* = {} {f}/{u}², *F*_g = *pA* = {} {f}.",
        show(area),
        show(100.0 * fraction),
        if expansion { "expansion" } else { "return" },
        show(d.at.gas_force / area),
        show(d.at.gas_force)
    )
}

/// The forces at the pose and the crank effort.
fn inertia_rows(w: &Work, d: &Worked) -> Vec<Row> {
    let at = &d.at;
    let force = &w.n.force;
    vec![
        Row::new(
            "inertia force *F*_i = −*m*ω²·*CG*",
            Some(Value::of(
                "dynamics.inertia_force_klein",
                at.inertia_force_graphical,
            )),
            Some(Value::of("dynamics.inertia_force", at.inertia_force)),
            force,
        ),
        Row::new(
            if d.diagram.is_some() {
                "gas force *F*_g = *pA*"
            } else {
                "gas force *F*_g"
            },
            None,
            Some(Value::of("dynamics.gas_force", at.gas_force)),
            force,
        ),
        Row::new(
            "piston effort *F* = *F*_g + *F*_i",
            None,
            Some(Value::of("dynamics.piston_effort", at.piston_effort)),
            force,
        ),
        Row::new(
            "crank effort *T* = *F*·*OM*",
            Some(Value::of("dynamics.crank_effort", at.crank_effort)),
            Some(Value::of(
                "dynamics.crank_effort_exact",
                at.crank_effort_exact,
            )),
            &w.n.torque,
        ),
    ]
}

/// The turning-moment diagram: the work of the turn, the mean torque and
/// the fluctuation of energy.
fn turning(w: &Work, d: &Worked) -> Result<Step> {
    let figure = figures::dynamics(w.h, FigureName::TurningMoment)?;
    let (tm, t) = (&d.turn, &w.n.torque);
    let done = match &d.diagram {
        Some(diagram) => format!(
            "the indicator diagram's work, *A* × stroke × ∮*p* d*x* = {} {t}, as the inertia forces do no work over a turn",
            show(diagram.work(w.mechanism().stroke()))
        ),
        None => "nothing, as a constant gas force takes back on the return stroke what it gave on the outward one and the inertia forces do no work over a turn".into(),
    };
    Ok(Step {
        id: "turning-moment",
        title: "The turning-moment diagram".into(),
        source: "Ng, eq. 2, round the turn",
        text: vec![
            format!(
                "Repeating *T* = *F*·*OM* round the turn gives the turning-moment diagram. Its area is the work of one turn, *W* = ∫*T* dθ = {} {t}: {done}. The mean torque is *T*_{{mean}} = *W*/2π = {} {t}.",
                show(tm.work),
                show(tm.mean)
            ),
            format!(
                "Between its {} crossings of the mean line the curve encloses areas that the flywheel stores (above) and gives back (below). The energy stored is least at θ = {}° and most at θ = {}°: the fluctuation of energy Δ*E* = *E*_{{max}} − *E*_{{min}} = {} {t}, integrated exactly, not by counting squares.",
                tm.lobes.len().saturating_sub(1),
                short(tm.min_energy_deg),
                short(tm.max_energy_deg),
                show(tm.fluctuation)
            ),
        ],
        pictures: vec![Picture::of(
            &figure,
            "turning-moment",
            "The turning-moment diagram with its mean line and the areas between them, and the energy stored over the turn.",
        )],
        rows: turning_rows(w, d),
    })
}

/// The work, the mean torque and ΔE.
fn turning_rows(w: &Work, d: &Worked) -> Vec<Row> {
    let (tm, t) = (&d.turn, &w.n.torque);
    let row = |q: &str, key, v| Row::new(q, None, Some(Value::of(key, v)), t);
    vec![
        row("work of one turn *W* = ∫*T* dθ", "turn.work", tm.work),
        row(
            "mean torque *T*_{mean} = *W*/2π",
            "turn.mean_torque",
            tm.mean,
        ),
        row(
            "fluctuation of energy Δ*E*",
            "turn.fluctuation",
            tm.fluctuation,
        ),
    ]
}

/// The flywheel for the coefficient of fluctuation of speed.
fn flywheel(w: &Work, d: &Worked) -> Result<Step> {
    let figure = figures::dynamics(w.h, FigureName::Flywheel)?;
    let fly = &d.flywheel;
    let omega = w.omega();
    Ok(Step {
        id: "flywheel",
        title: "The flywheel".into(),
        source: "from the turning-moment diagram",
        text: vec![format!(
            "Between the least and the most energy a flywheel of moment of inertia *I* takes up Δ*E* = ½*I*(ω_{{max}}² − ω_{{min}}²) = *I*ω²*C*_s, with the coefficient of fluctuation of speed *C*_s = (ω_{{max}} − ω_{{min}})/ω. For *C*_s = {}: *I* = Δ*E*/(ω²*C*_s) = {} / ({}² × {}) = {} {}, and the speed runs from ω_{{min}} = ω(1 − *C*_s/2) = {} to ω_{{max}} = {} rad/s.",
            short(fly.coefficient),
            show(fly.fluctuation),
            show(omega),
            short(fly.coefficient),
            show(fly.inertia),
            inertia_unit(w),
            show(omega * (1.0 - 0.5 * fly.coefficient)),
            show(omega * (1.0 + 0.5 * fly.coefficient))
        )],
        pictures: vec![Picture::of(
            &figure,
            "flywheel",
            "The energy stored above its least, rising by Δ*E*, and the crank speed with the flywheel.",
        )],
        rows: vec![Row::new(
            "flywheel *I* = Δ*E*/(ω²*C*_s)",
            None,
            Some(Value::of("flywheel.inertia", fly.inertia)),
            &inertia_unit(w),
        )],
    })
}

/// The unit of a moment of inertia
/// ([`crate::units::Units::moment_of_inertia`]).
fn inertia_unit(w: &Work) -> String {
    w.h.units().moment_of_inertia()
}
