//! `slider-crank analyze`: exact and graphical values at one or more angles.

use super::args::{AngleSpec, GivenMechanismArgs, GuardArgs, LoadArgs, SpeedArgs, UnitArgs};
use super::output::Stdout;
use clap::Args;
use slider_crank::analytic::statics::Friction;
use slider_crank::construct::{Reading, Statics};
use slider_crank::geom::Point;
use slider_crank::lists::Angles;
use slider_crank::render::plain;
use slider_crank::table::{Analysis, AnalyzePlan, AnalyzeRequest};
use slider_crank::{Angle, Error, Result, SliderCrank, Units};

/// Analyse the mechanism at one angle or a sweep of angles.
#[derive(Debug, Args)]
pub struct AnalyzeArgs {
    #[command(flatten)]
    pub mechanism: GivenMechanismArgs,
    /// Crank angle θ in degrees, counter-clockwise from +x, the direction
    /// from the crank centre towards the slider (0: outer dead centre): one
    /// angle, a list 0,30,60 or a range START:STOP:STEP (STOP included)
    #[arg(
        long,
        visible_alias = "angles",
        default_value = "45",
        value_name = "DEG",
        allow_hyphen_values = true
    )]
    pub angle: String,
    #[command(flatten)]
    pub speed: SpeedArgs,
    #[command(flatten)]
    pub load: LoadArgs,
    /// Print JSON (schema in docs/design.md §4): one object, or an array
    /// for a list or range of angles
    #[arg(long)]
    pub json: bool,
    #[command(flatten)]
    pub units: UnitArgs,
    #[command(flatten)]
    pub chain: super::chain::ChainArgs,
    #[command(flatten)]
    pub guard: GuardArgs,
    #[command(flatten)]
    pub engine: super::dynamics::EngineArgs,
}

/// +0.0 for −0.0, so that no "-0" is printed.
fn num(x: f64) -> f64 {
    x + 0.0
}

/// `x` with `decimals` decimals, in exponent form beyond 1e12 or below
/// 1e-6 (no 300-digit numbers), right-aligned in `width`.
fn fixed(x: f64, decimals: usize, width: usize) -> String {
    let a = x.abs();
    if a != 0.0 && !(1e-6..1e12).contains(&a) {
        format!("{:>width$.decimals$e}", num(x))
    } else {
        format!("{:>width$.decimals$}", num(x))
    }
}

/// A value column of the text table: [`fixed`] in 20 characters, with at
/// least one space before it however long the number.
fn column(x: f64) -> String {
    format!("{:>20}", format!(" {}", fixed(x, 10, 0)))
}

fn fmt_point(p: Option<Point>) -> String {
    match p {
        Some(p) => format!("({}, {})", fixed(p.x, 6, 0), fixed(p.y, 6, 0)),
        None => "at infinity".into(),
    }
}

/// The text `analyze` prints for the engine at one angle: the points,
/// the values analytic beside graphical, and the statics and dynamics
/// when asked for; for a chain, one `key.sub = value` line per number.
fn to_text(analysis: &Analysis, units: &Units) -> String {
    let (r, dynamics) = match analysis {
        Analysis::Engine(e) => (&e.reading, &e.dynamics),
        Analysis::Chain(values) => {
            let mut text = String::new();
            super::chain::flatten("", values, &mut text);
            text.push('\n');
            return text;
        }
    };
    let length = units.length();
    let mut out = format!("θ = {}°\n", plain(r.pose.angle().degrees()));
    out.push_str(&format!(
        "  points ({length}): C crank centre, B crank pin, A cross-head, D instantaneous centre of the rod,\n          \
         E where the rod produced meets the perpendicular to the stroke through C,\n          \
         F and G of Klein's and Kisch's constructions, H of Kisch's\n",
    ));
    for (name, p) in [
        ("C", Some(r.pose.c())),
        ("B", Some(r.pose.b())),
        ("A", Some(r.pose.a())),
        ("D", r.d.point()),
        ("E", Some(r.e)),
        ("F", Some(r.f)),
        ("G", Some(r.g)),
        ("H", r.h),
    ] {
        out.push_str(&format!("    {name}  {}\n", fmt_point(p)));
    }
    values(r, units, &mut out);
    if let Some(s) = &r.statics {
        statics_text(s, units, &mut out);
    }
    if let Some((engine, at)) = dynamics {
        out.push_str(&super::dynamics::to_text(engine, at, r.pose.angle(), units));
    }
    out
}

/// The table of values, analytic beside graphical, of `analyze`'s text.
fn values(r: &Reading, units: &Units, out: &mut String) {
    let length = units.length();
    out.push_str(&format!(
        "  {:<26}{:>20}{:>20}  unit\n",
        "quantity", "analytic", "graphical"
    ));
    let k = &r.exact;
    out.push_str(&format!(
        "  {:<26}{}{:20}  {length}\n",
        "position x_A",
        column(k.position),
        ""
    ));
    let (velocity, acceleration) = (units.velocity(), units.acceleration());
    let rows = [
        (
            "velocity dx/dt",
            k.velocity,
            r.graphical.velocity,
            velocity.as_str(),
        ),
        (
            "acceleration d²x/dt²",
            k.acceleration,
            r.graphical.acceleration,
            acceleration.as_str(),
        ),
        (
            "rod angular velocity",
            k.rod_angular_velocity,
            r.graphical.rod_angular_velocity,
            "rad/s",
        ),
        (
            "rod angular accel.",
            k.rod_angular_acceleration,
            r.graphical.rod_angular_acceleration,
            "rad/s²",
        ),
    ];
    out.push_str(&format!(
        "  {:<26}{}{:20}  °\n",
        "rod angle φ",
        column(k.rod_angle.to_degrees()),
        ""
    ));
    for (name, a, g, unit) in rows {
        out.push_str(&format!(
            "  {:<26}{}{}  {unit}\n",
            name,
            column(a),
            column(g)
        ));
    }
}

/// Ng's statics in `analyze`'s text.
fn statics_text(s: &Statics, units: &Units, out: &mut String) {
    let length = units.length();
    let force = units.force();
    out.push_str(&format!("  statics (μ = {})\n", plain(num(s.mu))));
    out.push_str(&format!(
        "    OM (= CE)                 {} {length}\n",
        fixed(s.om, 10, 0)
    ));
    match s.force {
        Some(f) => {
            out.push_str(&format!(
                "    slider force F_p          {} {force}\n",
                fixed(f, 10, 0)
            ));
            out.push_str(&format!(
                "    side thrust F_s           {} {force}\n",
                fixed(s.side_thrust.unwrap_or(0.0), 10, 0)
            ));
        }
        None => out.push_str("    slider force F_p          unbounded (dead centre: OM = 0)\n"),
    }
    match s.with_friction {
        Some(Friction::Force(f)) => out.push_str(&format!(
            "    with friction F_p'        {} {force}\n",
            fixed(f, 10, 0)
        )),
        Some(Friction::SelfLocking(k)) => out.push_str(&format!(
            "    with friction F_p'        self-locking (μ|tan φ| = {} ≥ 1)\n",
            fixed(k, 6, 0)
        )),
        None => {}
    }
    out.push_str(&format!(
        "    transmission angle β (°)  {:.10}\n",
        num(s.transmission_deg)
    ));
}

/// The object `analyze --json` prints for the mechanism `m` at `degrees`
/// turning at `omega` (no torque, no engine masses): the values the
/// explorer sets beside its figure.
#[cfg(feature = "explore")]
pub fn json_at(
    m: &SliderCrank,
    degrees: f64,
    omega: f64,
    units: &Units,
) -> Result<serde_json::Value> {
    let pose = m.pose(Angle::from_degrees(degrees)?);
    Ok(Reading::new(&pose, omega, None, 0.0)?.to_json(m, units))
}

fn pretty(value: &impl serde::Serialize) -> Result<String> {
    serde_json::to_string_pretty(value).map_err(|e| Error::Io {
        message: e.to_string(),
        path: None,
        source: Some(std::sync::Arc::new(e.into())),
    })
}

/// The request the flags make ([`AnalyzeRequest`]): the angles and the
/// links parsed, the rest as given.
fn request(args: &AnalyzeArgs) -> Result<AnalyzeRequest<'static>> {
    let mut r = AnalyzeRequest::default();
    let m = &args.mechanism;
    (r.crank, r.rod, r.offset) = (m.crank, m.rod, m.offset);
    r.angles = Some(Angles::Spec(AngleSpec::parse(&args.angle)?));
    (r.rpm, r.omega) = (args.speed.rpm, args.speed.omega);
    // `--friction` without `--torque` or the engine is refused by the
    // request; with a torque its default is 0.
    r.torque = args.load.torque;
    r.friction = (r.torque.and(Some(args.load.friction.unwrap_or(0.0)))).or(args.load.friction);
    (r.unit, r.force_unit) = (args.units.length.clone(), args.units.force.clone());
    r.engine = args.engine.given();
    (r.slot_radius, r.links, r.assembly, r.inversion) = args.chain.fields()?;
    r.max_cells = args.guard.max_cells;
    Ok(r)
}

/// Runs the subcommand. Rows are computed twice, never all held: a first
/// pass finds any error (so that nothing is printed then), the second
/// prints the angles a chunk at a time, both on every core
/// ([`super::stream`]).
pub fn run(args: &AnalyzeArgs, out: &mut Stdout) -> Result<()> {
    let plan = request(args)?.plan()?;
    super::stream::check_all(plan.angles().iter(), |d| plan.at(d))?;
    if args.json {
        if !plan.is_list() {
            for d in plan.angles().iter() {
                out.text(&pretty(&plan.json_at(d)?)?)?;
                out.text("\n")?;
            }
            return Ok(());
        }
        super::stream::json_array(plan.angles().iter(), |d| plan.json_at(d), out)?;
        return out.text("\n");
    }
    if !plan.is_chain() {
        out.text(&head(&plan))?;
    }
    for d in plan.angles().iter() {
        if !plan.is_chain() {
            out.text("\n")?;
        }
        out.text(&to_text(&plan.at(d)?, plan.units()))?;
    }
    Ok(())
}

/// The line `analyze` prints of the engine before its angles.
fn head(plan: &AnalyzePlan) -> String {
    let (m, omega, units) = (plan.mechanism(), plan.omega(), plan.units());
    let u = units.length();
    format!(
        "slider-crank: r = {} {u}, l = {} {u}, e = {} {u} (n = {}), ω = {} rad/s, V_c = rω = {} {}\n",
        plain(m.crank()),
        plain(m.rod()),
        plain(m.offset()),
        plain(m.ratio()),
        fixed(omega, 6, 0),
        fixed(m.crank() * omega, 6, 0),
        units.velocity()
    )
}
