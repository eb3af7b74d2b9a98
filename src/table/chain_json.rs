//! The chain of Fig. 60 as the analysis's JSON writes it (the block in a
//! curved slot, the quadric crank chain, the four inversions) and the
//! report `check` prints for the slot and the quadric chain: one copy for
//! the command line and the Python package.

use super::check_report::{closing, verdict};
use crate::angle::Angle;
use crate::chain::{
    Assembly, ChainCentres, ChainCheckRow, CylindricChain, GrashofClass, InvertedChain,
    QuadricChain, SlotConstruction,
};
use crate::construct::Link;
use crate::error::Result;
use crate::geom::{Intersection, MeetJson, Point, PointJson};
use crate::mechanism::SliderCrank;
use crate::number::plain;
use serde_json::{Value, json};

/// Default allowance of the checks of the slot and of the quadric chain: the
/// largest scaled difference (docs/design.md §6) between the chain's two
/// formulations.
pub const CHAIN_TOLERANCE: f64 = 1e-12;

use crate::number::unsigned_zero as num;

fn point_json(p: Point) -> Value {
    json!(PointJson(p, num))
}

/// A point, or `{"at_infinity": [dx, dy]}`, or `{"indeterminate": true}`
/// where two coincident lines leave it anywhere on a line ([`MeetJson`]).
pub fn centre_json(c: &Intersection) -> Value {
    MeetJson(c, num).value()
}

fn opt(x: Option<f64>) -> Value {
    x.map(|x| json!(num(x))).unwrap_or(Value::Null)
}

/// The block in a curved slot of radius ρ at `degrees` and crank speed
/// `omega` (rad/s): points, the arc's motion exact and read off the
/// constructions (`null` where a construction has no value, as at a dead
/// centre), and the six virtual centres. Errors only for an angle that
/// is not a finite number of degrees.
pub fn slot_json(chain: &CylindricChain, degrees: f64, omega: f64) -> Result<Value> {
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
        "virtual_centres": s.centres().to_json(),
    }))
}

/// The Grashof class's name in the JSON and the reports (`crank_rocker`,
/// `double_crank`, …).
pub fn grashof_name(g: GrashofClass) -> &'static str {
    match g {
        GrashofClass::CrankRocker => "crank_rocker",
        GrashofClass::DoubleCrank => "double_crank",
        GrashofClass::RockerCrank => "rocker_crank",
        GrashofClass::DoubleRocker => "double_rocker",
        GrashofClass::ChangePoint => "change_point",
        GrashofClass::TripleRocker => "triple_rocker",
    }
}

/// The quadric crank chain in assembly `mode` at `degrees` and crank speed
/// `omega`: points, the coupler's and lever's angles and rates (`null` at
/// a toggle, where the rates are unbounded), the six virtual centres.
/// Errors for an angle outside the crank's reach or not finite.
pub fn quadric_json(q: &QuadricChain, mode: Assembly, degrees: f64, omega: f64) -> Result<Value> {
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
        "virtual_centres": ChainCentres::of_quadric(&p).to_json(),
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

/// An inversion of the engine at `degrees` (the crank's angle against the
/// frame) and speed `omega` of the driving link: each link's angular
/// velocity and acceleration, the sliding pair's, the time ratio of a
/// quick return, the six virtual centres (`null` where a rate is
/// unbounded, at a dead centre of the driving link).
pub fn inversion_json(chain: &InvertedChain, degrees: f64, omega: f64) -> Result<Value> {
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
        "coriolis": coriolis_json(&p, omega),
        "quick_return": quick_return_json(chain, p.engine_pose().angle(), omega),
        "virtual_centres": p.centres().to_json(),
    }))
}

/// The polygons with the Coriolis component of inversions 2 and 3
/// (`CoriolisPolygon`): the slot's direction, the vectors from the pole
/// and the values read off them; `null` for inversions 1 and 4, and where
/// the chain does not move at this driver speed.
fn coriolis_json(p: &crate::chain::InversionPose, omega: f64) -> Value {
    p.motion(omega)
        .and(crate::chain::CoriolisPolygon::construct(p, omega))
        .map_or(Value::Null, |c| {
            let v = |x: crate::geom::Vector| json!([num(x.x), num(x.y)]);
            json!({
                "slot": v(c.slot()),
                "driven_velocity": v(c.driven()),
                "a_d_velocity": v(c.a_d()),
                "driven_acceleration": v(c.driven_acceleration()),
                "normal_end": v(c.n()),
                "coriolis": v(c.coriolis()),
                "a_d_acceleration": v(c.a_d_acceleration()),
                "omega_d": num(c.omega_d()),
                "alpha_d": num(c.alpha_d()),
                "sliding_velocity": num(c.sliding_velocity()),
                "sliding_acceleration": num(c.sliding_acceleration()),
            })
        })
}

/// The quick return of inversions 2 and 3 (`QuickReturn`) with the arm of
/// its default length, l + r: the time ratio, the driver's turn over each
/// stroke, the tool's stroke, and the tool's motion at this angle; `null`
/// for inversions 1 and 4.
fn quick_return_json(chain: &InvertedChain, angle: Angle, omega: f64) -> Value {
    let m = *chain.mechanism();
    let lever = crate::chain::QuickReturn::default_lever(&m);
    crate::chain::QuickReturn::new(m, chain.inversion(), lever).map_or(Value::Null, |q| {
        let (cutting, back) = q.stroke_angles();
        let t = q.at(angle, omega);
        json!({
            "lever": num(lever),
            "time_ratio": num(q.time_ratio()),
            "cutting_angle_deg": num(cutting.to_degrees()),
            "return_angle_deg": num(back.to_degrees()),
            "stroke_length": num(q.stroke_length()),
            "stroke": t.stroke.name(),
            "driver_angle_deg": num(t.driver_angle.to_degrees()),
            "tool": {
                "position": num(t.position),
                "velocity": num(t.velocity),
                "acceleration": num(t.acceleration),
            },
        })
    })
}

/// The first line of the slot's check report for the engine `m`
/// with its block in a slot of radius `rho` as given (the chain keeps the
/// curvature 1/ρ, which need not give back ρ's last digit).
pub fn slot_check_title(m: &SliderCrank, rho: f64) -> String {
    format!(
        "check: curved slot ρ = {}, r = {}, l = {}, e = {}",
        plain(rho),
        plain(m.crank()),
        plain(m.rod()),
        plain(m.offset())
    )
}

/// The first line of the report of inversion 2's or 3's check for the
/// engine `m`.
pub fn coriolis_check_title(m: &SliderCrank, inversion: u32) -> String {
    format!(
        "check: the polygons with the Coriolis component of inversion {inversion}, r = {}, l = {}, e = {}, against the chain's exact link motion (the driver at 1 rad/s)",
        plain(m.crank()),
        plain(m.rod()),
        plain(m.offset())
    )
}

/// The first line of the quadric chain's check report.
pub fn quadric_check_title(q: &QuadricChain) -> String {
    format!(
        "check: quadric chain a = {}, b = {}, c = {}, d = {} ({}), both assembly modes",
        plain(q.crank()),
        plain(q.coupler()),
        plain(q.lever()),
        plain(q.frame()),
        grashof_name(q.grashof())
    )
}

/// The report `check` prints for a chain under `title`, and whether every
/// row passed at `tolerance` (an empty `rows` passes).
pub fn chain_check_report(title: &str, rows: &[ChainCheckRow], tolerance: f64) -> (String, bool) {
    let mut out = format!(
        "{title}\na difference passes when at most {tolerance:.3e} × κ, κ the condition number of the quantity at that pose (1 far from a toggle or the slot's limit)\n\n"
    );
    out.push_str(&format!(
        "{:<40}{:>14}{:>12}{:>16}{:>10}  result\n",
        "quantity (scaled difference)", "worst", "κ there", "at θ (°)", "poses"
    ));
    let mut ok = true;
    for row in rows {
        let pass = row.passes(tolerance);
        ok &= pass;
        out.push_str(&format!(
            "{:<40}{:>14.3e}{:>12.3e}{:>16.6}{:>10}  {}\n",
            row.name,
            row.worst,
            row.condition,
            row.at_degrees,
            row.poses,
            verdict(pass)
        ));
    }
    out.push_str(closing(ok));
    (out, ok)
}
