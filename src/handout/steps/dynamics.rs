//! The engine's dynamics, when a reciprocating mass is given: the inertia
//! force from Klein's *CG*, the crank effort *F*·*OM* through Ng's line,
//! the turning-moment diagram over the turn and the flywheel
//! (`docs/dynamics.md`).

use super::work::Work;
use super::{Picture, Row, Step, Value};
use super::{short, show};
use crate::catalogue::FigureName;
use crate::dynamics::{Engine, EnginePose, Flywheel, GasForce, IndicatorDiagram, TurningMoment};
use crate::error::{Error, Input, Result};
use crate::handout::figures;
use crate::units::Units;

/// The turning-moment figure's indicator diagram (steam at 100 psi gauge
/// cut off at 30 % of the stroke), in lbf/ft², so that the page's numbers
/// are those of its figures.
const INDICATOR: &str = include_str!("../../../examples/indicator.csv");

/// The turning-moment figure's bore, 10 in in feet.
const BORE: f64 = 10.0 / 12.0;

/// What the dynamics steps share: the engine with its mass and gas
/// force, its forces at the pose, the turn and the flywheel.
struct Worked {
    engine: Engine,
    diagram: IndicatorDiagram,
    at: EnginePose,
    turn: TurningMoment,
    flywheel: Flywheel,
}

impl Worked {
    /// The dynamics of the handout's engine; `None` without a mass.
    ///
    /// Errors: units other than feet and pounds-force (the indicator
    /// diagram's), and those of the engine's forces.
    fn of(w: &Work) -> Result<Option<Self>> {
        let Some((mass, fluctuation)) = w.h.dynamics() else {
            return Ok(None);
        };
        if *w.h.units() != Units::FOOT_POUND {
            return Err(Error::invalid(Input::Options,
                "the handout's dynamics take their gas force from an indicator diagram in lbf/ft² with a 10 in bore: give lengths in ft and forces in lbf with --mass".into(),
            ));
        }
        let diagram = IndicatorDiagram::from_csv(INDICATOR, BORE, "examples/indicator.csv")?;
        let engine = Engine::new(*w.mechanism(), mass, w.omega())?
            .with_gas(GasForce::Indicator(diagram.clone()))?;
        let at = engine.at(w.h.angle())?;
        let turn = TurningMoment::new(&engine, &[0.0])?;
        let flywheel = Flywheel::for_coefficient(turn.fluctuation, w.omega(), fluctuation)?;
        Ok(Some(Self {
            engine,
            diagram,
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
    let area = d.diagram.area();
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
            format!(
                "The steam of the indicator diagram (gauge pressure against the stroke, 100 psi cut off at 30 %) acts on a 10 in bore, *A* = π*D*²/4 = {} {u}². Here the piston is {} % of the stroke from the outer dead centre on the {} stroke: *p* = {} {f}/{u}², *F*_g = *pA* = {} {f}.",
                show(area),
                show(100.0 * fraction),
                if expansion { "expansion" } else { "return" },
                show(at.gas_force / area),
                show(at.gas_force)
            ),
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
            "gas force *F*_g = *pA*",
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
    let indicated = d.diagram.work(w.mechanism().stroke());
    Ok(Step {
        id: "turning-moment",
        title: "The turning-moment diagram".into(),
        source: "Ng, eq. 2, round the turn",
        text: vec![
            format!(
                "Repeating *T* = *F*·*OM* round the turn gives the turning-moment diagram. Its area is the work of one turn, *W* = ∫*T* dθ = {} {t}: the indicator diagram's work, *A* × stroke × ∮*p* d*x* = {} {t}, as the inertia forces do no work over a turn. The mean torque is *T*_{{mean}} = *W*/2π = {} {t}.",
                show(tm.work),
                show(indicated),
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
