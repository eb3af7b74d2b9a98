//! All constructions of one pose against the analytic core alone.
//!
//! `cargo bench --features bench --bench constructions`; the ratio is recorded in
//! docs/benchmarks.md.

use criterion::{Criterion, criterion_group, criterion_main};
use slider_crank::analytic::kinematics::Kinematics;
use slider_crank::construct::{
    Graphical, InstantCentre, Kisch, Klein, TorqueLine, VelocityLine, VirtualCentres,
};
use slider_crank::{Angle, SliderCrank};
use std::hint::black_box;

fn angles() -> Vec<Angle> {
    (0..360).map(|k| Angle::deg(k as f64 + 0.5)).collect()
}

fn bench(c: &mut Criterion) {
    let m = SliderCrank::new(0.5, 3.0, 0.1).unwrap();
    let angles = angles();
    let mut group = c.benchmark_group("per 360 poses");
    group.bench_function("analytic core (x, v, a, φ, dφ, d²φ)", |b| {
        b.iter(|| {
            let mut acc = 0.0;
            for a in &angles {
                let p = m.pose(*black_box(a));
                acc += p.position()
                    + p.position_rate()
                    + p.position_acceleration()
                    + p.obliquity()
                    + p.obliquity_rate()
                    + p.obliquity_acceleration();
            }
            acc
        })
    });
    group.bench_function("all constructions (D, E, Klein, Kisch, OM, centres)", |b| {
        b.iter(|| {
            let mut acc = 0.0;
            for a in &angles {
                let p = m.pose(*black_box(a));
                let d = InstantCentre::construct(&p);
                let e = VelocityLine::construct(&p);
                let kisch = Kisch::construct(&p, &e);
                let torque = TorqueLine::construct(&p, &e);
                let centres = VirtualCentres::construct(&p, &d, &e);
                acc += d.rod_angular_velocity_ratio()
                    + e.velocity_ratio()
                    + kisch.points().acceleration_ratio()
                    + kisch.points().rod_angular_acceleration_ratio()
                    + torque.om()
                    + centres.all().len() as f64;
                if let Some(k) = Klein::construct(&p, &d, &e) {
                    acc += k.points().acceleration_ratio();
                }
            }
            acc
        })
    });
    group.bench_function("velocity and Kisch acceleration only (E, F, G)", |b| {
        b.iter(|| {
            let mut acc = 0.0;
            for a in &angles {
                let p = m.pose(*black_box(a));
                let e = VelocityLine::construct(&p);
                let kisch = Kisch::construct(&p, &e);
                acc += e.velocity_ratio() + kisch.points().acceleration_ratio();
            }
            acc
        })
    });
    group.bench_function("a sweep's pose: degrees, Kinematics, Graphical", |b| {
        let degrees: Vec<f64> = (0..360).map(|k| k as f64 + 0.5).collect();
        b.iter(|| {
            let mut acc = 0.0;
            for d in &degrees {
                let Ok(angle) = Angle::from_degrees(*black_box(d)) else {
                    continue;
                };
                let p = m.pose(angle);
                let (Ok(k), Ok(g)) = (Kinematics::new(&p, 26.0), Graphical::new(&p, 26.0)) else {
                    continue;
                };
                acc += k.position + k.velocity + k.acceleration + g.velocity + g.acceleration;
            }
            acc
        })
    });
    group.bench_function("a sweep's pose: degrees, Kinematics", |b| {
        let degrees: Vec<f64> = (0..360).map(|k| k as f64 + 0.5).collect();
        b.iter(|| {
            let mut acc = 0.0;
            for d in &degrees {
                let Ok(angle) = Angle::from_degrees(*black_box(d)) else {
                    continue;
                };
                if let Ok(k) = Kinematics::new(&m.pose(angle), 26.0) {
                    acc += k.position + k.velocity + k.acceleration;
                }
            }
            acc
        })
    });
    // The floor under any exact sweep: the sine and cosine of the angle and
    // the rod's arctangent, which every pose needs whatever else it reads.
    group.bench_function("the floor: sine, cosine and the rod's arctangent", |b| {
        let radians: Vec<f64> = (0..360).map(|k| (k as f64 + 0.5).to_radians()).collect();
        b.iter(|| {
            let mut acc = 0.0;
            for t in &radians {
                let (s, c) = black_box(*t).sin_cos();
                acc += c + (0.5 * s - 0.1).atan2(3.0);
            }
            acc
        })
    });
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
