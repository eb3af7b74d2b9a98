//! `slider-crank analyze`: exact and graphical values at one or more angles.

use super::args::{AngleSpec, GuardArgs, LoadArgs, MechanismArgs, SpeedArgs, UnitArgs};
use super::output::Stdout;
use clap::Args;
use slider_crank::analytic::statics::Friction;
use slider_crank::construct::{Reading, Statics};
use slider_crank::dynamics::{Engine, EnginePose};
use slider_crank::geom::Point;
use slider_crank::render::plain;
use slider_crank::{Angle, Error, Input, Result, SliderCrank, Units};

/// Analyse the mechanism at one angle or a sweep of angles.
#[derive(Debug, Args)]
pub struct AnalyzeArgs {
    #[command(flatten)]
    pub mechanism: MechanismArgs,
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

/// The numbers written for one angle, the columns of `--max-cells`: the
/// mechanism (3), angle and ω (2), eight points (16), the analytic (6) and
/// graphical (4) values, the polygons (27: seven vectors and seven
/// numbers, and a point off the rod: along, across and its two images), Ritterhaus's (7: three points and CG) and Bennett's (9: four
/// points and CG) constructions and six virtual centres (12).
const VALUES_PER_ANGLE: u64 = 86;

/// What `--torque` adds to [`VALUES_PER_ANGLE`]: the seven statics.
const STATICS_VALUES: u64 = 7;

/// Everything computed at one angle: the reading ([`Reading::json`]
/// adds the six virtual centres) and, with masses, the engine's forces.
struct Report<'a> {
    reading: Reading,
    dynamics: Option<(&'a Engine, EnginePose)>,
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

fn analyse<'a>(
    m: &SliderCrank,
    degrees: f64,
    omega: f64,
    torque: Option<f64>,
    mu: f64,
    engine: Option<&'a Engine>,
) -> Result<Report<'a>> {
    let angle = Angle::from_degrees(degrees)?;
    let pose = m.pose(angle);
    Ok(Report {
        reading: Reading::new(&pose, omega, torque, mu)?,
        dynamics: engine.map(|e| Ok((e, e.at(angle)?))).transpose()?,
    })
}

/// A report as the JSON object `analyze --json` prints, serialised
/// where it is written ([`Reading::json`]; the engine's dynamics, when
/// asked for, as `table::dynamics_json` builds them).
struct ReportJson<'a> {
    mechanism: &'a SliderCrank,
    report: Report<'a>,
    units: &'a Units,
}

impl serde::Serialize for ReportJson<'_> {
    fn serialize<S: serde::Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
        let r = &self.report;
        let json = r.reading.json(self.mechanism, self.units);
        match &r.dynamics {
            Some((engine, at)) => {
                let angle = r.reading.pose.angle();
                let dynamics = slider_crank::table::dynamics_json(engine, at, angle, self.units);
                json.with_dynamics(&dynamics).serialize(s)
            }
            None => json.serialize(s),
        }
    }
}

fn fmt_point(p: Option<Point>) -> String {
    match p {
        Some(p) => format!("({}, {})", fixed(p.x, 6, 0), fixed(p.y, 6, 0)),
        None => "at infinity".into(),
    }
}

/// The text `analyze` prints for one angle: the points, the values
/// analytic beside graphical, and the statics and dynamics when asked for.
fn to_text(report: &Report, units: &Units) -> String {
    let r = &report.reading;
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
    if let Some((engine, at)) = &report.dynamics {
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

/// The reports at every angle of `spec`, computed as they are used.
fn reports<'a>(
    m: &'a SliderCrank,
    spec: &'a AngleSpec,
    omega: f64,
    args: &'a AnalyzeArgs,
    engine: Option<&'a Engine>,
) -> impl Iterator<Item = Result<Report<'a>>> + 'a {
    spec.iter()
        .map(move |d| analyse(m, d, omega, args.load.torque, args.load.friction, engine))
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
    let json = ReportJson {
        mechanism: m,
        report: analyse(m, degrees, omega, None, 0.0, None)?,
        units,
    };
    serde_json::to_value(&json).map_err(|e| Error::Io {
        message: e.to_string(),
        path: None,
        source: Some(std::sync::Arc::new(e.into())),
    })
}

fn pretty(value: &impl serde::Serialize) -> Result<String> {
    serde_json::to_string_pretty(value).map_err(|e| Error::Io {
        message: e.to_string(),
        path: None,
        source: Some(std::sync::Arc::new(e.into())),
    })
}

/// The flags the chain's flags refuse (a torque, the engine's masses),
/// and the request's size against `--max-cells`.
fn refuse_or_guard(args: &AnalyzeArgs) -> Result<()> {
    if args.chain.is_set() && args.load.torque.is_some() {
        return Err(Error::invalid(
            Input::Options,
            "--torque applies to the engine only, not with --slot-radius, --links or --inversion"
                .into(),
        ));
    }
    if args.chain.is_set() {
        super::dynamics::refuse_with_chain(&args.engine)?;
    }
    let angles = AngleSpec::parse(&args.angle)?.len();
    let statics = if args.load.torque.is_some() {
        STATICS_VALUES
    } else {
        0
    };
    args.guard.check(
        "analyze",
        (angles, &format!("{angles} angles")),
        (VALUES_PER_ANGLE + statics, "values each"),
    )
}

/// Runs the subcommand. Rows are computed twice, never all held: a first
/// pass finds any error (so that nothing is printed then), the second
/// prints the angles a chunk at a time, both on every core
/// ([`super::stream`]).
pub fn run(args: &AnalyzeArgs, out: &mut Stdout) -> Result<()> {
    let m = args.mechanism.mechanism()?;
    refuse_or_guard(args)?;
    let units = args.units.units(Units::FOOT_POUND);
    if super::chain::analyze(
        m,
        &args.chain,
        &args.speed,
        &args.angle,
        args.json,
        &units,
        out,
    )? {
        return Ok(());
    }
    let omega = args.speed.omega()?;
    let spec = AngleSpec::parse(&args.angle)?;
    let engine = args.engine.given().engine(m, omega, &units)?;
    let engine = engine.as_ref();
    let (torque, mu) = (args.load.torque, args.load.friction);
    let at = |d: f64| analyse(&m, d, omega, torque, mu, engine);
    super::stream::check_all(spec.iter(), at)?;
    if args.json {
        if !spec.is_list() {
            if let Some(r) = reports(&m, &spec, omega, args, engine).next() {
                let json = ReportJson {
                    mechanism: &m,
                    report: r?,
                    units: &units,
                };
                out.text(&pretty(&json)?)?;
                out.text("\n")?;
            }
            return Ok(());
        }
        let object = |d: f64| {
            Ok(ReportJson {
                mechanism: &m,
                report: at(d)?,
                units: &units,
            })
        };
        super::stream::json_array(spec.iter(), object, out)?;
        return out.text("\n");
    }
    let u = units.length();
    out.text(&format!(
        "slider-crank: r = {} {u}, l = {} {u}, e = {} {u} (n = {}), ω = {} rad/s, V_c = rω = {} {}\n",
        plain(m.crank()),
        plain(m.rod()),
        plain(m.offset()),
        plain(m.ratio()),
        fixed(omega, 6, 0),
        fixed(m.crank() * omega, 6, 0),
        units.velocity()
    ))?;
    for r in reports(&m, &spec, omega, args, engine) {
        out.text("\n")?;
        out.text(&to_text(&r?, &units))?;
    }
    Ok(())
}
