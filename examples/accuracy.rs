//! The accuracy study of docs/accuracy.md: where the direct intersection
//! formulas lose digits, and what the constructions of `construct` reach.
//!
//! `cargo run --release --example accuracy`

use slider_crank::construct::{Kisch, Quantity, VelocityLine, sweep};
use slider_crank::geom::{Circle, CircleIntersection, Line, Point, Vector};
use slider_crank::{Angle, Pose, SliderCrank};

/// E_y by intersecting the rod line anchored at A with the vertical.
fn e_direct(p: &Pose) -> f64 {
    let rod = Line::through(p.a(), p.b()).unwrap();
    let v = Line::new(p.c(), Vector::new(0.0, 1.0)).unwrap();
    rod.intersect_eps(&v, 0.0).point().unwrap().y
}

/// G_x from a given F (perpendicular at F meets y = 0).
fn g_from_f(p: &Pose, f: Point) -> f64 {
    let dir = p.b() - p.a();
    let perp = Line::new(f, Vector::new(-dir.y, dir.x)).unwrap();
    let x_axis = Line::new(p.c(), Vector::new(1.0, 0.0)).unwrap();
    perp.intersect_eps(&x_axis, 0.0).point().unwrap().x
}

/// Klein's F by intersecting the line CF ∥ DE with AB; `None` if the lines
/// are taken as parallel.
fn klein_direct(p: &Pose) -> Option<f64> {
    let crank = Line::through(p.c(), p.b()).unwrap();
    let normal = Line::new(p.a(), Vector::new(0.0, 1.0)).unwrap();
    let d = crank.intersect(&normal).point()?;
    let e = VelocityLine::construct(p).e();
    let cf = Line::new(p.c(), e - d)?;
    let ab = Line::through(p.a(), p.b()).unwrap();
    let f = cf.intersect(&ab).point()?;
    Some(g_from_f(p, f))
}

/// Kisch's F by intersecting the two circles and dropping H onto AB.
fn kisch_direct(p: &Pose) -> Option<f64> {
    let e = VelocityLine::construct(p).e();
    let b = p.b();
    let around_b = Circle::new(b, (e - b).norm()).expect("finite points");
    let semi = Circle::on_diameter(p.a(), b);
    let h = match semi.intersect_circle(&around_b, 0.0) {
        CircleIntersection::Two(h, _) | CircleIntersection::Tangent(h) => h,
        _ => return None,
    };
    let ab = Line::through(p.a(), b).unwrap();
    Some(g_from_f(p, ab.foot(h)))
}

fn worst(
    poses: impl Iterator<Item = Pose>,
    f: impl Fn(&Pose) -> Option<f64>,
    exact: impl Fn(&Pose) -> f64,
) -> (f64, usize) {
    let mut w: f64 = 0.0;
    let mut missing = 0;
    for p in poses {
        match f(&p) {
            Some(v) => w = w.max((v - exact(&p)).abs() / p.mechanism().crank()),
            None => missing += 1,
        }
    }
    (w, missing)
}

/// One table row: Kisch's F through the circles against BA·BF = BE².
fn kisch_row(poses: &[Pose], region: &str) {
    let exact = |p: &Pose| -p.position_acceleration();
    let direct = worst(poses.iter().copied(), kisch_direct, exact);
    let used = worst(
        poses.iter().copied(),
        |p| {
            Some(
                Kisch::construct(p, &VelocityLine::construct(p))
                    .points()
                    .cg(),
            )
        },
        exact,
    );
    println!(
        "| Kisch F (CG) | {region} | {} | {} |",
        fmt(direct),
        fmt(used)
    );
}

fn fmt(w: (f64, usize)) -> String {
    if w.1 > 0 {
        format!("{:.1e} ({} poses not constructible)", w.0, w.1)
    } else {
        format!("{:.1e}", w.0)
    }
}

fn main() {
    println!("## Direct formulas against the formulations used\n");
    println!("| construction | region | direct | used |");
    println!("|---|---|---|---|");

    // E: anchored at A against anchored at B, large offset and huge n.
    for (n, frac) in [(6.0, 0.0), (1e3, 0.9), (1e6, 0.9)] {
        let m = SliderCrank::new(1.0, n, frac * (n - 1.0)).unwrap();
        let poses = || (0..3600).map(move |k| m.pose(Angle::deg(k as f64 * 0.1)));
        let exact = |p: &Pose| -p.position_rate();
        let direct = worst(poses(), |p| Some(e_direct(p)), exact);
        let used = worst(poses(), |p| Some(VelocityLine::construct(p).ce()), exact);
        println!(
            "| E (CE) | n = {n}, e = {frac}·(l − r), whole turn | {} | {} |",
            fmt(direct),
            fmt(used)
        );
    }

    // Klein: line intersection near the dead centres (an offset mechanism,
    // so that the dead centres are not at exact angles).
    let off = SliderCrank::new(1.0, 4.3, 0.37).unwrap();
    let (outer, inner) = (
        off.outer_dead_centre().radians(),
        off.inner_dead_centre().radians(),
    );
    for k in [1e-1, 1e-3, 1e-5, 1e-7, 1e-9] {
        let poses = || {
            [outer + k, outer - k, inner + k, inner - k]
                .into_iter()
                .map(|t| off.pose(Angle::from_radians(t).unwrap()))
        };
        let exact = |p: &Pose| -p.position_acceleration();
        let direct = worst(poses(), klein_direct, exact);
        let used = worst(
            poses(),
            |p| {
                let d = slider_crank::construct::InstantCentre::construct(p);
                let e = VelocityLine::construct(p);
                slider_crank::construct::Klein::construct(p, &d, &e).map(|k| k.points().cg())
            },
            exact,
        );
        println!(
            "| Klein F (CG) | n = 4.3, e = 0.37 r, θ = dead centre ± {k:e} rad | {} | {} |",
            fmt(direct),
            fmt(used)
        );
    }
    let m = SliderCrank::in_line(1.0, 4.0).unwrap();

    // Kisch: circle intersection where H approaches B (θ → 90°) or the
    // circles become tangent, and near the dead centres.
    for k in [1.0, 1e-2, 1e-4, 1e-6] {
        let poses = [90.0 - k, 90.0 + k, 270.0 - k, 270.0 + k].map(|d| m.pose(Angle::deg(d)));
        kisch_row(&poses, &format!("n = 4, θ = 90° or 270° ± {k:e}°"));
    }
    for k in [1e-1, 1e-3, 1e-5, 1e-7, 1e-9] {
        let poses = [outer + k, outer - k, inner + k, inner - k]
            .map(|t| off.pose(Angle::from_radians(t).unwrap()));
        kisch_row(
            &poses,
            &format!("n = 4.3, e = 0.37 r, θ = dead centre ± {k:e} rad"),
        );
    }

    // The rod's run w = √(l² − h²) near the limit of assembly.
    println!("\n## The rod's run w = l cos φ near the limit of assembly\n");
    println!("| l − (r + |e|) | √(l² − h²) | √((l − h)(l + h)) (reference) |");
    println!("|---|---|---|");
    for gap in [1e-2, 1e-5, 1e-8, 1e-11] {
        let (r, e): (f64, f64) = (1.0, 0.5);
        let l = r + e + gap;
        // At θ = 270° h = −(r + e): the rod is steepest. l − |h| is exact
        // (Sterbenz), so the factored form is correct to an ulp and serves
        // as the reference.
        let h = -(r + e);
        let plain = (l * l - h * h).sqrt();
        let factored = ((l - h.abs()) * (l + h.abs())).sqrt();
        let exact = factored;
        println!(
            "| {gap:e} | {:.1e} | {:.1e} |",
            ((plain - exact) / exact).abs(),
            ((factored - exact) / exact).abs()
        );
    }

    println!("\n## Error due to obliquity for long rods (relative error)\n");
    println!("| n | w − l | −h²/(w + l) |");
    println!("|---|---|---|");
    for n in [10.0, 1e3, 1e6, 1e8] {
        let p = SliderCrank::in_line(1.0, n).unwrap().pose(Angle::deg(45.0));
        let accurate = p.obliquity_error();
        let naive = p.run() - n;
        println!(
            "| {n:e} | {:.1e} | 0 (reference) |",
            ((naive - accurate) / accurate).abs()
        );
    }

    println!("\n## `check` over the done-when matrix (100 000 poses + singular angles)\n");
    println!("| r | n | e / (l − r) | worst over all quantities | worst quantity |");
    println!("|---|---|---|---|---|");
    let mut overall: f64 = 0.0;
    for r in [1e-9, 1.0, 1e9] {
        for n in [1.05, 1.5, 4.0, 6.0, 100.0, 1e6] {
            for frac in [0.0, 0.9, -0.9] {
                let l = n * r;
                let m = SliderCrank::new(r, l, frac * (l - r)).unwrap();
                let rep = sweep(&m, 100_000);
                let (q, e): (Quantity, f64) =
                    rep.worst
                        .iter()
                        .map(|w| (w.0, w.1))
                        .fold(
                            (Quantity::Velocity, 0.0),
                            |a, b| if b.1 > a.1 { b } else { a },
                        );
                overall = overall.max(e);
                println!("| {r:e} | {n} | {frac} | {e:.1e} | {} |", q.name());
            }
        }
    }
    println!("\nworst of all: {overall:.2e}");
}
