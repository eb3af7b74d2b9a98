//! The polygons of inversions 2 and 3 with the Coriolis component against
//! the chain's exact link motion (docs/polygons.md).

use slider_crank::chain::{CoriolisPolygon, Inversion, InvertedChain};
use slider_crank::geom::{Vector, cross};
use slider_crank::{Angle, SliderCrank};

/// Every 7.5°, the quarters exactly and a hair off them.
fn angles() -> Vec<f64> {
    let mut out: Vec<f64> = (0..48).map(|k| 7.5 * f64::from(k)).collect();
    for q in [0.0, 90.0, 180.0, 270.0] {
        out.extend([q + 1e-7, q - 1e-7]);
    }
    out
}

const LINK_D: usize = 3;

#[test]
fn the_coriolis_polygons_read_the_exact_link_motion() {
    for (r, l, e) in [
        (0.5, 1.5, 0.0),
        (1.0, 1.05, 0.0),
        (1.0, 4.0, 1.2),
        (1.0, 60.0, -20.0),
        (1e-6, 3e-6, 0.0),
    ] {
        let m = SliderCrank::new(r, l, e).unwrap();
        for inversion in [Inversion::Crank, Inversion::Rod] {
            let chain = InvertedChain::new(m, inversion);
            for deg in angles() {
                let pose = chain.pose(Angle::deg(deg));
                let w = 3.0;
                let Some(exact) = pose.motion(w) else {
                    continue;
                };
                let p = CoriolisPolygon::construct(&pose, w).unwrap();
                // Scales: ω for rates, ω² for accelerations, r for lengths,
                // and the condition of a short rod near its limit.
                let k = (l / (l - r - e.abs())).powi(3);
                let rate = w * k * 1e-12;
                let what = format!("{inversion:?} {l} {e} {deg}");
                assert!(
                    (p.omega_d() - exact.velocity[LINK_D]).abs() <= rate,
                    "{what}: ω_d"
                );
                assert!(
                    (p.alpha_d() - exact.acceleration[LINK_D]).abs() <= w * rate,
                    "{what}: α_d {} {}",
                    p.alpha_d(),
                    exact.acceleration[LINK_D]
                );
                assert!(
                    (p.sliding_velocity() - exact.sliding_velocity).abs() <= r * rate,
                    "{what}: v"
                );
                assert!(
                    (p.sliding_acceleration() - exact.sliding_acceleration).abs() <= r * w * rate,
                    "{what}: sliding acceleration {} {}",
                    p.sliding_acceleration(),
                    exact.sliding_acceleration
                );
            }
        }
    }
}

#[test]
fn the_coriolis_component_is_2_omega_v_turned_in_the_sense_of_omega() {
    let m = SliderCrank::new(1.0, 3.0, 0.4).unwrap();
    for inversion in [Inversion::Crank, Inversion::Rod] {
        let chain = InvertedChain::new(m, inversion);
        for deg in angles() {
            let pose = chain.pose(Angle::deg(deg));
            let p = CoriolisPolygon::construct(&pose, 2.0).unwrap();
            let (u, c) = (p.slot(), p.coriolis());
            let size = 2.0 * p.omega_d().abs() * p.sliding_velocity().abs();
            assert!((c.norm() - size).abs() <= 1e-12, "{deg}: |2ωv|");
            // Perpendicular to the slot, on the side ω turns the sliding
            // velocity of d's point relative to the block towards.
            assert!(c.dot(&u).abs() <= 1e-12, "{deg}: ⟂ slot");
            let v = match inversion {
                Inversion::Crank => u * p.sliding_velocity(),
                _ => -u * p.sliding_velocity(),
            };
            if size > 1e-9 {
                assert!(cross(&v, &c) * p.omega_d() > 0.0, "{deg}: sense");
            }
        }
    }
}

#[test]
fn the_polygons_close() {
    // Inversion 3: o → c → a_d closes with a_d along the slot (the block at
    // rest); inversion 2: o → a_d → a with a − a_d along the slot.
    let m = SliderCrank::in_line(0.5, 1.5).unwrap();
    for deg in angles() {
        let p3 = CoriolisPolygon::construct(
            &InvertedChain::new(m, Inversion::Rod).pose(Angle::deg(deg)),
            1.0,
        )
        .unwrap();
        assert!(cross(&p3.slot(), &p3.a_d()).abs() <= 1e-14, "{deg}");
        let p2 = CoriolisPolygon::construct(
            &InvertedChain::new(m, Inversion::Crank).pose(Angle::deg(deg)),
            1.0,
        )
        .unwrap();
        assert!(
            cross(&p2.slot(), &(p2.driven() - p2.a_d())).abs() <= 1e-14,
            "{deg}"
        );
        // a′_d − n is the tangential component, ⟂ to the normal one.
        let t: Vector = p2.a_d_acceleration() - p2.n();
        assert!(
            t.dot(&p2.n()).abs() <= 1e-12 * (1.0 + p2.n().norm()),
            "{deg}"
        );
    }
    let frame = InvertedChain::new(m, Inversion::Frame).pose(Angle::deg(30.0));
    assert!(CoriolisPolygon::construct(&frame, 1.0).is_none());
}

/// The point `name` of the figure's polygon `polygon` in its metadata.
fn read(meta: &serde_json::Value, polygon: &str, name: &str) -> Vector {
    let p = &meta[polygon][name];
    Vector::new(p[0].as_f64().unwrap(), p[1].as_f64().unwrap())
}

#[test]
fn the_coriolis_figures_read_the_exact_link_motion_off_their_polygons() {
    use slider_crank::FigureName;
    use slider_crank::catalogue::FigureOptions;
    for (r, l, e) in [(0.5, 1.5, 0.0), (1.0, 1.05, 0.0), (1.0, 4.0, 1.2)] {
        let m = SliderCrank::new(r, l, e).unwrap();
        for (name, inversion) in [
            (FigureName::CoriolisInversion2, Inversion::Crank),
            (FigureName::CoriolisInversion3, Inversion::Rod),
        ] {
            for deg in [0.0, 37.5, 90.0, 180.0, 250.0] {
                let mut options = FigureOptions::default();
                options.mechanism = Some(m);
                options.angle = Some(Angle::deg(deg));
                let svg = slider_crank::render::to_svg(&name.figure(&options).unwrap());
                let meta = crate::common::metadata(&svg);
                let w = meta["omega"].as_f64().unwrap();
                let pose = InvertedChain::new(m, inversion).pose(Angle::deg(deg));
                let exact = pose.motion(w).unwrap();
                let engine = pose.engine_pose();
                let ca = (engine.a() - engine.c()).norm();
                let (v, a) = ("velocity_polygon", "acceleration_polygon");
                // The driven point's image, and the sliding vectors: o a_d
                // (d on the block at rest) in inversion 3, a_d a (the
                // block on d) in inversion 2.
                let (driven, driven2) = match inversion {
                    Inversion::Rod => ("c", "c2"),
                    _ => ("a", "a2"),
                };
                let ad = read(&meta, v, "ad");
                let (omega_d, sliding) = match inversion {
                    Inversion::Rod => ((ad - read(&meta, v, driven)).norm() / ca, ad.norm()),
                    _ => (ad.norm() / ca, (read(&meta, v, driven) - ad).norm()),
                };
                let coriolis = match inversion {
                    Inversion::Rod => read(&meta, a, "k") - read(&meta, a, "o2"),
                    _ => read(&meta, a, driven2) - read(&meta, a, "k"),
                };
                let slide = (read(&meta, a, "ad2") - read(&meta, a, "k")).norm();
                // The metadata's 12 significant digits, at the polygons'
                // sizes (ω_d up to 40 ω at l = 1.05 r).
                let vs = w * (l + r) * 50.0;
                let what = format!("{name:?} {l} {e} {deg}");
                let w_d = exact.velocity[LINK_D];
                assert!(
                    (omega_d - w_d.abs()).abs() <= 1e-10 * vs,
                    "{what}: ω_d {omega_d} {w_d}"
                );
                let v_exact = exact.sliding_velocity.abs();
                assert!((sliding - v_exact).abs() <= 1e-10 * vs, "{what}: v");
                let c = 2.0 * (w_d * exact.sliding_velocity).abs();
                assert!(
                    (coriolis.norm() - c).abs() <= 1e-10 * vs * vs,
                    "{what}: 2ωv"
                );
                let s = exact.sliding_acceleration.abs();
                assert!(
                    (slide - s).abs() <= 1e-10 * vs * vs,
                    "{what}: sliding acceleration"
                );
            }
        }
    }
}

/// The page length of the link `id` (its path's first and last points).
fn drawn_length(svg: &str, id: &str) -> Option<f64> {
    let d = crate::common::attr(svg, id, "d")?;
    let numbers: Vec<f64> = d
        .split(|c: char| c == 'M' || c == 'L' || c.is_whitespace())
        .filter_map(|w| w.parse().ok())
        .collect();
    let (a, b) = (&numbers[..2], &numbers[numbers.len() - 2..]);
    Some((b[0] - a[0]).hypot(b[1] - a[1]))
}

#[test]
fn inversion_3_s_crank_is_seen_with_its_omega_at_every_rod() {
    use slider_crank::FigureName;
    use slider_crank::catalogue::FigureOptions;
    // At l = 50 r the crank was drawn 9 px long between touching pins,
    // inside B's bearing, and the driver's ω was left out for want of
    // room: some panel (the mechanism's, else its detail) draws the crank
    // at least 40 px long (two pins and a letter between) with ω.
    for rod in [1.06, 4.0, 28.5, 50.0, 50.1] {
        for deg in [0.0, 91.0, 180.0, 269.38] {
            let mut options = FigureOptions::default();
            options.mechanism = Some(SliderCrank::new(1.0, rod, 0.0).unwrap());
            options.angle = Some(Angle::deg(deg));
            let figure = FigureName::CoriolisInversion3.figure(&options).unwrap();
            let svg = slider_crank::render::to_svg(&figure);
            let seen = ["", "detail-"].iter().any(|prefix| {
                let long =
                    drawn_length(&svg, &format!("{prefix}link-crank")).is_some_and(|l| l >= 40.0);
                let omega = svg.contains(&format!("id=\"{prefix}arc-omega\""))
                    && svg.contains(&format!("id=\"{prefix}label-omega\""));
                long && omega
            });
            assert!(
                seen,
                "l = {rod}, θ = {deg}°: no panel shows the crank with ω"
            );
        }
    }
}
