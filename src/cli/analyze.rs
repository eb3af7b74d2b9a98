//! `slider-crank analyze`: exact and graphical values at one or more angles.

use super::args::{MechanismArgs, SpeedArgs, parse_angles};
use clap::Args;
use serde_json::{Value, json};
use slider_crank::analytic::statics::{self, Friction};
use slider_crank::construct::{InstantCentre, Kisch, VelocityLine};
use slider_crank::geom::{Intersection, Point};
use slider_crank::{Angle, ChainCentres, Kinematics, Result, SliderCrank};

/// Analyse the mechanism at one angle or a sweep of angles.
#[derive(Debug, Args)]
pub struct AnalyzeArgs {
    #[command(flatten)]
    pub mechanism: MechanismArgs,
    /// Crank angle in degrees, counter-clockwise from the line of stroke
    /// (0: outer dead centre); also a list 0,30,60 or a range START:STOP:STEP
    #[arg(
        long,
        default_value = "45",
        value_name = "DEG",
        allow_hyphen_values = true
    )]
    pub angle: String,
    #[command(flatten)]
    pub speed: SpeedArgs,
    /// Crank torque T (counter-clockwise positive): adds statics (Ng eq. 6–11)
    #[arg(long, allow_negative_numbers = true, value_name = "T")]
    pub torque: Option<f64>,
    /// Coefficient of friction μ ≥ 0 of the slider in its guides (with --torque)
    #[arg(
        long,
        allow_negative_numbers = true,
        value_name = "MU",
        default_value_t = 0.0
    )]
    pub friction: f64,
    /// Print JSON (DESIGN.md §4): one object, or an array for several angles
    #[arg(long)]
    pub json: bool,
    #[command(flatten)]
    pub chain: super::chain::ChainArgs,
}

/// Everything computed at one angle.
struct Report {
    degrees: f64,
    omega: f64,
    c: Point,
    b: Point,
    a: Point,
    d: Intersection,
    e: Point,
    f: Point,
    g: Point,
    h: Option<Point>,
    exact: Kinematics,
    graphical: [f64; 4],
    statics: Option<Statics>,
    centres: ChainCentres,
}

struct Statics {
    om: f64,
    force: Option<f64>,
    side_thrust: Option<f64>,
    with_friction: Option<Friction>,
    transmission: f64,
    mu: f64,
}

/// +0.0 for −0.0, so that no "-0" is printed.
fn num(x: f64) -> f64 {
    x + 0.0
}

fn point_json(p: Point) -> Value {
    json!([num(p.x), num(p.y)])
}

fn opt_point_json(p: Option<Point>) -> Value {
    p.map(point_json).unwrap_or(Value::Null)
}

fn analyse(
    m: &SliderCrank,
    degrees: f64,
    omega: f64,
    torque: Option<f64>,
    mu: f64,
) -> Result<Report> {
    let pose = m.pose(Angle::from_degrees(degrees)?);
    let exact = Kinematics::new(&pose, omega)?;
    let d = InstantCentre::construct(&pose);
    let e = VelocityLine::construct(&pose);
    let kisch = Kisch::construct(&pose, &e);
    let graphical = [
        omega * e.velocity_ratio(),
        omega * omega * kisch.points().acceleration_ratio(),
        omega * d.rod_angular_velocity_ratio(),
        omega * omega * kisch.points().rod_angular_acceleration_ratio(),
    ];
    let statics = match torque {
        None => None,
        Some(t) => {
            let force = statics::slider_force(&pose, t);
            let with_friction = match force {
                Some(f) => Some(statics::with_friction(&pose, f, mu)?),
                None => None,
            };
            Some(Statics {
                om: statics::om(&pose),
                force,
                side_thrust: force.map(|f| statics::side_thrust(&pose, f)),
                with_friction,
                transmission: pose.transmission_angle().to_degrees(),
                mu,
            })
        }
    };
    Ok(Report {
        degrees: pose.angle().degrees(),
        omega,
        c: pose.c(),
        b: pose.b(),
        a: pose.a(),
        d: d.d(),
        e: e.e(),
        f: kisch.points().f(),
        g: kisch.points().g(),
        h: kisch.h(),
        exact,
        graphical,
        statics,
        centres: ChainCentres::of_slider_crank(&pose),
    })
}

fn to_json(m: &SliderCrank, r: &Report) -> Value {
    let mut v = json!({
        "mechanism": {"crank": m.crank(), "rod": m.rod(), "offset": num(m.offset())},
        "angle_deg": num(r.degrees),
        "omega": num(r.omega),
        "points": {
            "C": point_json(r.c), "B": point_json(r.b), "A": point_json(r.a),
            "D": super::chain::centre_json(&r.d), "E": point_json(r.e), "F": point_json(r.f),
            "G": point_json(r.g), "H": opt_point_json(r.h),
        },
        "analytic": {
            "position": num(r.exact.position),
            "velocity": num(r.exact.velocity),
            "acceleration": num(r.exact.acceleration),
            "rod_angle_deg": num(r.exact.rod_angle.to_degrees()),
            "rod_angular_velocity": num(r.exact.rod_angular_velocity),
            "rod_angular_acceleration": num(r.exact.rod_angular_acceleration),
        },
        "graphical": {
            "velocity": num(r.graphical[0]),
            "acceleration": num(r.graphical[1]),
            "rod_angular_velocity": num(r.graphical[2]),
            "rod_angular_acceleration": num(r.graphical[3]),
        },
        "virtual_centres": super::chain::centres_json(&r.centres),
    });
    if let Some(s) = &r.statics {
        let (with_friction, locking) = match s.with_friction {
            Some(Friction::Force(f)) => (json!(num(f)), false),
            Some(Friction::SelfLocking(_)) => (Value::Null, true),
            None => (Value::Null, false),
        };
        v["statics"] = json!({
            "OM": num(s.om),
            "slider_force": s.force.map(num),
            "side_thrust": s.side_thrust.map(num),
            "slider_force_with_friction": with_friction,
            "self_locking": locking,
            "friction": s.mu,
            "transmission_angle_deg": num(s.transmission),
        });
    }
    v
}

fn fmt_point(p: Option<Point>) -> String {
    match p {
        Some(p) => format!("({:.6}, {:.6})", num(p.x), num(p.y)),
        None => "at infinity".into(),
    }
}

fn to_text(r: &Report) -> String {
    let mut out = format!("θ = {}°\n", r.degrees);
    out.push_str("  points (C crank centre, B crank pin, A cross-head, D rod centre, E on CE, F G H Kisch)\n");
    for (name, p) in [
        ("C", Some(r.c)),
        ("B", Some(r.b)),
        ("A", Some(r.a)),
        ("D", r.d.point()),
        ("E", Some(r.e)),
        ("F", Some(r.f)),
        ("G", Some(r.g)),
        ("H", r.h),
    ] {
        out.push_str(&format!("    {name}  {}\n", fmt_point(p)));
    }
    out.push_str(&format!(
        "  {:<26}{:>20}{:>20}\n",
        "quantity", "analytic", "graphical"
    ));
    let k = &r.exact;
    out.push_str(&format!(
        "  {:<26}{:>20.10}\n",
        "position x_A",
        num(k.position)
    ));
    let rows = [
        ("velocity dx/dt", k.velocity, r.graphical[0]),
        ("acceleration d²x/dt²", k.acceleration, r.graphical[1]),
        (
            "rod angular velocity",
            k.rod_angular_velocity,
            r.graphical[2],
        ),
        (
            "rod angular accel.",
            k.rod_angular_acceleration,
            r.graphical[3],
        ),
    ];
    out.push_str(&format!(
        "  {:<26}{:>20.10}\n",
        "rod angle φ (°)",
        num(k.rod_angle.to_degrees())
    ));
    for (name, a, g) in rows {
        out.push_str(&format!(
            "  {:<26}{:>20.10}{:>20.10}\n",
            name,
            num(a),
            num(g)
        ));
    }
    if let Some(s) = &r.statics {
        out.push_str(&format!("  statics (μ = {})\n", s.mu));
        out.push_str(&format!(
            "    OM (= CE)                 {:.10}\n",
            num(s.om)
        ));
        match s.force {
            Some(f) => {
                out.push_str(&format!("    slider force F_p          {:.10}\n", num(f)));
                out.push_str(&format!(
                    "    side thrust F_s           {:.10}\n",
                    num(s.side_thrust.unwrap_or(0.0))
                ));
            }
            None => out.push_str("    slider force F_p          unbounded (dead centre: OM = 0)\n"),
        }
        match s.with_friction {
            Some(Friction::Force(f)) => {
                out.push_str(&format!("    with friction F_p'        {:.10}\n", num(f)))
            }
            Some(Friction::SelfLocking(k)) => out.push_str(&format!(
                "    with friction F_p'        self-locking (μ|tan φ| = {k:.6} ≥ 1)\n"
            )),
            None => {}
        }
        out.push_str(&format!(
            "    transmission angle β (°)  {:.10}\n",
            num(s.transmission)
        ));
    }
    out
}

/// Runs the subcommand, returning the whole output (printed only on success).
pub fn run(args: &AnalyzeArgs) -> Result<String> {
    let m = args.mechanism.mechanism()?;
    if args.chain.is_set() && args.torque.is_some() {
        return Err(slider_crank::Error::Parse(
            "--torque applies to the engine only, not with --slot-radius, --links or --inversion"
                .into(),
        ));
    }
    if let Some(out) = super::chain::analyze(m, &args.chain, &args.speed, &args.angle, args.json)? {
        return Ok(out);
    }
    let omega = args.speed.omega()?;
    let angles = parse_angles(&args.angle)?;
    if let Some(t) = args.torque.filter(|t| !t.is_finite()) {
        return Err(slider_crank::Error::NotFinite {
            name: "torque",
            value: t,
        });
    }
    if !(args.friction >= 0.0 && args.friction.is_finite()) {
        return Err(slider_crank::Error::OutOfRange {
            name: "friction",
            value: args.friction,
            reason: "the coefficient of friction must be a finite number ≥ 0".into(),
        });
    }
    let reports = angles
        .iter()
        .map(|&d| analyse(&m, d, omega, args.torque, args.friction))
        .collect::<Result<Vec<_>>>()?;
    if args.json {
        let value = if reports.len() == 1 && !args.angle.contains([':', ',']) {
            to_json(&m, &reports[0])
        } else {
            Value::Array(reports.iter().map(|r| to_json(&m, r)).collect())
        };
        let mut s = serde_json::to_string_pretty(&value)
            .map_err(|e| slider_crank::Error::Io(e.to_string()))?;
        s.push('\n');
        return Ok(s);
    }
    let mut out = format!(
        "slider-crank: r = {}, l = {}, e = {} (n = {}), ω = {:.6} rad/s, V_c = rω = {:.6}\n",
        m.crank(),
        m.rod(),
        m.offset(),
        m.ratio(),
        omega,
        m.crank() * omega
    );
    for r in &reports {
        out.push('\n');
        out.push_str(&to_text(r));
    }
    Ok(out)
}
