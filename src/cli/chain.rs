//! The chain of Fig. 60 on the command line: `analyze --slot-radius`,
//! `--links`, `--inversion`, and `check` for the curved slot and the quadric
//! chain.

use super::args::{AngleSpec, SpeedArgs};
use super::output::Stdout;
use clap::{Args, ValueEnum};
use serde_json::{Value, json};
use slider_crank::chain::{
    ChainCentres, ChainCheckRow, CylindricChain, GrashofClass, InvertedChain, QuadricChain,
    SlotConstruction, quadric_sweep, slot_sweep,
};
use slider_crank::construct::Link;
use slider_crank::geom::{Intersection, Point};
use slider_crank::render::plain;
use slider_crank::{Angle, Assembly, Error, Inversion, Result, SliderCrank, Units};

/// The chain flags shared by `analyze` and `check`.
#[derive(Debug, Clone, Args)]
pub struct ChainArgs {
    /// Put the block in a circular slot of radius ρ (Fig. 60 b), in the
    /// length unit: its centre O_cd is at (0, e − ρ), below the stroke for
    /// ρ > 0, above it for ρ < 0; |ρ| must exceed (l + r + e)/2 for ρ > 0,
    /// (l + r − e)/2 for ρ < 0
    #[arg(
        long,
        allow_hyphen_values = true,
        value_name = "RHO",
        conflicts_with_all = ["links", "inversion"]
    )]
    pub slot_radius: Option<f64>,
    /// A quadric crank chain instead of the engine (Fig. 60 a): the lengths
    /// of crank a, coupler b, lever c and frame d, comma-separated (in place
    /// of --crank, --rod and --offset)
    #[arg(
        long,
        allow_hyphen_values = true,
        value_name = "A,B,C,D",
        conflicts_with_all = ["inversion", "crank", "rod", "offset"]
    )]
    pub links: Option<String>,
    /// Assembly mode of the quadric chain (with --links)
    #[arg(long, value_enum, default_value_t = AssemblyArg::Open, requires = "links")]
    pub assembly: AssemblyArg,
    /// Fix another link of the slider-crank chain: 1 frame d (the engine),
    /// 2 crank a, 3 rod b, 4 slider c; --angle is then the crank's angle
    /// against the frame and --rpm or --omega the speed of the driving link
    #[arg(long, value_name = "N")]
    pub inversion: Option<u32>,
}

/// The assembly mode flag.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum AssemblyArg {
    /// A to the left of the diagonal from B to O_cd
    Open,
    /// A to the right of the diagonal from B to O_cd
    Crossed,
}

impl ChainArgs {
    /// Whether any chain flag asks for something other than the engine.
    pub fn is_set(&self) -> bool {
        self.slot_radius.is_some() || self.links.is_some() || self.inversion.is_some()
    }

    fn quadric(&self) -> Result<Option<(QuadricChain, Assembly)>> {
        let Some(spec) = &self.links else {
            return Ok(None);
        };
        let v = super::args::parse_list(spec, "link length", false)?;
        let [a, b, c, d] = v[..] else {
            return Err(Error::Parse(format!(
                "invalid --links '{spec}': expected four lengths a,b,c,d (crank, coupler, lever, frame)"
            )));
        };
        let mode = match self.assembly {
            AssemblyArg::Open => Assembly::Open,
            AssemblyArg::Crossed => Assembly::Crossed,
        };
        Ok(Some((QuadricChain::new(a, b, c, d)?, mode)))
    }
}

/// +0.0 for −0.0, so that no "-0" is printed.
fn num(x: f64) -> f64 {
    x + 0.0
}

fn point_json(p: Point) -> Value {
    json!([num(p.x), num(p.y)])
}

/// A point, or `{"at_infinity": [dx, dy]}`, or `{"indeterminate": true}`
/// where two coincident lines leave it anywhere on a line.
pub fn centre_json(c: &Intersection) -> Value {
    match c {
        Intersection::Point(p) => point_json(*p),
        Intersection::AtInfinity(d) => json!({"at_infinity": [num(d.x), num(d.y)]}),
        Intersection::Coincident => json!({"indeterminate": true}),
    }
}

/// The six centres as a JSON object keyed `O_ab` … `O_cd` (the form the
/// figures' metadata uses too).
pub fn centres_json(c: &ChainCentres) -> Value {
    c.to_json()
}

fn opt(x: Option<f64>) -> Value {
    x.map(|x| json!(num(x))).unwrap_or(Value::Null)
}

fn slot_json(chain: &CylindricChain, degrees: f64, omega: f64) -> Result<Value> {
    let p = chain.pose(Angle::from_degrees(degrees)?);
    let s = SlotConstruction::construct(&p);
    let m = chain.mechanism();
    let w2 = omega * omega;
    Ok(json!({
        "mechanism": {"crank": m.crank(), "rod": m.rod(), "offset": num(m.offset()),
                      "slot_radius": chain.slot_radius()},
        "angle_deg": num(p.angle().degrees()),
        "omega": num(omega),
        "points": {
            "C": point_json(p.c()), "B": point_json(p.b()), "A": point_json(p.a()),
            "D": centre_json(&s.d()),
            "E": s.e().map(point_json).unwrap_or(Value::Null),
            "O_cd": centre_json(&chain.slot_centre()),
        },
        "analytic": {
            "arc_position": num(p.arc_position()),
            "velocity": num(omega * p.arc_rate()),
            "acceleration": num(w2 * p.arc_acceleration()),
            "slot_angle_deg": num(p.slot_angle().to_degrees()),
            "lever_angular_velocity": num(omega * p.lever_rate()),
            "lever_angular_acceleration": num(w2 * p.lever_acceleration()),
            "rod_angle_deg": num(p.obliquity().to_degrees()),
            "rod_angular_velocity": num(omega * p.obliquity_rate()),
            "rod_angular_acceleration": num(w2 * p.obliquity_acceleration()),
        },
        "graphical": {
            "velocity": opt(s.arc_rate_from_e().map(|v| omega * v)),
            "velocity_from_D": opt(s.arc_rate_from_d().map(|v| omega * v)),
            "acceleration": opt(s.arc_acceleration_from_klein().map(|a| w2 * a)),
            "rod_angular_velocity": opt(s.obliquity_rate_from_d().map(|v| omega * v)),
        },
        "virtual_centres": centres_json(s.centres()),
    }))
}

fn grashof_name(g: GrashofClass) -> &'static str {
    match g {
        GrashofClass::CrankRocker => "crank_rocker",
        GrashofClass::DoubleCrank => "double_crank",
        GrashofClass::RockerCrank => "rocker_crank",
        GrashofClass::DoubleRocker => "double_rocker",
        GrashofClass::ChangePoint => "change_point",
        GrashofClass::TripleRocker => "triple_rocker",
    }
}

fn quadric_json(q: &QuadricChain, mode: Assembly, degrees: f64, omega: f64) -> Result<Value> {
    let p = q.pose(Angle::from_degrees(degrees)?, mode)?;
    let reach = q.reach();
    let rates = p.rates();
    let w2 = omega * omega;
    Ok(json!({
        "mechanism": {
            "crank": q.crank(), "coupler": q.coupler(), "lever": q.lever(), "frame": q.frame(),
            "assembly": if mode == Assembly::Open { "open" } else { "crossed" },
            "grashof": grashof_name(q.grashof()),
            "reach_deg": [num(reach.lower().to_degrees()), num(reach.upper().to_degrees())],
        },
        "angle_deg": num(p.angle().degrees()),
        "omega": num(omega),
        "points": {
            "C": point_json(p.c()), "B": point_json(p.b()), "A": point_json(p.a()),
            "O_cd": point_json(q.lever_pivot()),
        },
        "analytic": {
            "toggle": p.is_toggle(),
            "coupler_angle_deg": num(p.coupler_angle().to_degrees()),
            "lever_angle_deg": num(p.lever_angle().to_degrees()),
            "coupler_angular_velocity": opt(rates.map(|r| omega * r.coupler_velocity)),
            "lever_angular_velocity": opt(rates.map(|r| omega * r.lever_velocity)),
            "coupler_angular_acceleration": opt(rates.map(|r| w2 * r.coupler_acceleration)),
            "lever_angular_acceleration": opt(rates.map(|r| w2 * r.lever_acceleration)),
        },
        "virtual_centres": centres_json(&ChainCentres::of_quadric(&p)),
    }))
}

fn link_name(l: Link) -> &'static str {
    match l {
        Link::A => "a",
        Link::B => "b",
        Link::C => "c",
        Link::D => "d",
    }
}

fn inversion_json(chain: &InvertedChain, degrees: f64, omega: f64) -> Result<Value> {
    let p = chain.pose(Angle::from_degrees(degrees)?);
    let inv = chain.inversion();
    let m = chain.mechanism();
    let motion = p.motion(omega);
    let mut links = serde_json::Map::new();
    for (i, l) in [Link::A, Link::B, Link::C, Link::D].into_iter().enumerate() {
        links.insert(
            link_name(l).into(),
            json!({
                "angular_velocity": opt(motion.and_then(|x| x.velocity.get(i).copied())),
                "angular_acceleration": opt(motion.and_then(|x| x.acceleration.get(i).copied())),
            }),
        );
    }
    Ok(json!({
        "mechanism": {"crank": m.crank(), "rod": m.rod(), "offset": num(m.offset())},
        "inversion": inv.number(),
        "fixed": link_name(inv.fixed()),
        "driver": link_name(inv.driver()),
        "name": inv.name(),
        "angle_deg": num(p.engine_pose().angle().degrees()),
        "omega": num(omega),
        "links": links,
        "sliding": {
            "velocity": opt(motion.map(|x| x.sliding_velocity)),
            "acceleration": opt(motion.map(|x| x.sliding_acceleration)),
        },
        "time_ratio": opt(chain.time_ratio()),
        "virtual_centres": centres_json(p.centres()),
    }))
}

/// `analyze` for the chain flags: `Ok(false)` when none is given. As for
/// the engine, rows are computed twice, never held: a first pass finds any
/// error (so that nothing is printed then), the second prints each angle.
pub fn analyze(
    m: SliderCrank,
    chain: &ChainArgs,
    speed: &SpeedArgs,
    angle_spec: &str,
    as_json: bool,
    units: &Units,
    out: &mut Stdout,
) -> Result<bool> {
    if !chain.is_set() {
        return Ok(false);
    }
    let omega = speed.omega()?;
    let spec = AngleSpec::parse(angle_spec)?;
    let values: Box<dyn Fn(f64) -> Result<Value>> = if let Some(rho) = chain.slot_radius {
        let slot = CylindricChain::new(m, rho)?;
        Box::new(move |d| slot_json(&slot, d, omega))
    } else if let Some((q, mode)) = chain.quadric()? {
        Box::new(move |d| quadric_json(&q, mode, d, omega))
    } else {
        // `is_set` with neither of the others: the inversion is given.
        let n = chain.inversion.unwrap_or(1);
        let inv = InvertedChain::new(m, Inversion::from_number(n)?);
        Box::new(move |d| inversion_json(&inv, d, omega))
    };
    let one = |d: f64| -> Result<Value> {
        let mut v = values(d)?;
        if let Some(fields) = v.as_object_mut() {
            fields.insert("units".into(), json!(units));
        }
        Ok(v)
    };
    for d in spec.iter() {
        one(d)?;
    }
    let pretty = |v: &Value| {
        serde_json::to_string_pretty(v).map_err(|e| Error::Io {
            message: e.to_string(),
            path: None,
            source: Some(std::sync::Arc::new(e.into())),
        })
    };
    if as_json {
        if !spec.is_list() {
            for d in spec.iter() {
                out.text(&pretty(&one(d)?)?)?;
                out.text("\n")?;
            }
            return Ok(true);
        }
        out.text("[")?;
        for (i, d) in spec.iter().enumerate() {
            out.text(if i == 0 { "\n" } else { ",\n" })?;
            let text = pretty(&one(d)?)?;
            let lines: Vec<String> = text.lines().map(|l| format!("  {l}")).collect();
            out.text(&lines.join("\n"))?;
        }
        out.text("\n]\n")?;
        return Ok(true);
    }
    for d in spec.iter() {
        let mut text = String::new();
        flatten("", &one(d)?, &mut text);
        text.push('\n');
        out.text(&text)?;
    }
    Ok(true)
}

/// One `key.sub = value` line per number, for the text output.
fn flatten(prefix: &str, v: &Value, out: &mut String) {
    match v {
        Value::Object(map) => {
            for (k, x) in map {
                let key = if prefix.is_empty() {
                    k.clone()
                } else {
                    format!("{prefix}.{k}")
                };
                flatten(&key, x, out);
            }
        }
        other => out.push_str(&format!("{prefix:<44} {other}\n")),
    }
}

/// `check` for the chain flags: the report and whether all passed;
/// `Ok(None)` when no chain flag is given.
pub fn check(
    m: SliderCrank,
    chain: &ChainArgs,
    samples: usize,
    tolerance: f64,
) -> Result<Option<(String, bool)>> {
    if chain.inversion.is_some() {
        return Err(Error::Parse(
            "check takes no --inversion: every inversion has the engine's relative motion, which check without it covers".into(),
        ));
    }
    let (title, rows): (String, Vec<ChainCheckRow>) = if let Some(rho) = chain.slot_radius {
        let slot = CylindricChain::new(m, rho)?;
        (
            format!(
                "check: curved slot ρ = {}, r = {}, l = {}, e = {}",
                plain(rho),
                plain(m.crank()),
                plain(m.rod()),
                plain(m.offset())
            ),
            slot_sweep(&slot, samples),
        )
    } else if let Some((q, _)) = chain.quadric()? {
        (
            format!(
                "check: quadric chain a = {}, b = {}, c = {}, d = {} ({}), both assembly modes",
                plain(q.crank()),
                plain(q.coupler()),
                plain(q.lever()),
                plain(q.frame()),
                grashof_name(q.grashof())
            ),
            quadric_sweep(&q, samples),
        )
    } else {
        return Ok(None);
    };
    let mut out = format!(
        "{title}\na difference passes when at most {tolerance:.3e} × κ, κ the condition number of the quantity at that pose (1 far from a toggle or the slot's limit)\n\n"
    );
    out.push_str(&format!(
        "{:<40}{:>14}{:>12}{:>16}{:>10}  result\n",
        "quantity (scaled difference)", "worst", "κ there", "at θ (°)", "poses"
    ));
    let mut ok = true;
    for row in &rows {
        let pass = row.passes(tolerance);
        ok &= pass;
        out.push_str(&format!(
            "{:<40}{:>14.3e}{:>12.3e}{:>16.6}{:>10}  {}\n",
            row.name,
            row.worst,
            row.condition,
            row.at_degrees,
            row.poses,
            if pass { "ok" } else { "FAIL" }
        ));
    }
    out.push_str(if ok {
        "\nall within tolerance\n"
    } else {
        "\nsome quantities exceed the tolerance\n"
    });
    Ok(Some((out, ok)))
}
