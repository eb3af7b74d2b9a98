//! The turning-moment diagram of 3600 poses and the flywheel of one
//! engine: the §35 engine with a rod of mass and the example indicator
//! diagram; the same turn with a heavy rod (as heavy as the piston, its
//! radius of gyration a third of its length); and the balance of a
//! six-cylinder in-line engine, 0-120-240-240-120-0, at 3600 angles.
//!
//! `cargo bench --features bench --bench dynamics`; the times are recorded in
//! docs/benchmarks.md with the whole-process time of `table dynamics`.

use criterion::{Criterion, criterion_group, criterion_main};
use slider_crank::dynamics::{
    Engine, Flywheel, GasForce, IndicatorDiagram, InlineEngine, RodMass, TurningMoment,
    default_planes,
};
use slider_crank::{Angle, SliderCrank};
use std::hint::black_box;

fn build(rod: RodMass) -> Engine {
    let m = SliderCrank::in_line(0.5, 3.0).unwrap();
    let text = include_str!("../examples/indicator.csv");
    let gas = IndicatorDiagram::from_csv(text, 10.0 / 12.0, "indicator").unwrap();
    Engine::new(m, 10.0, 26.18)
        .unwrap()
        .with_rod(rod)
        .unwrap()
        .with_gas(GasForce::Indicator(gas))
        .unwrap()
}

fn bench(c: &mut Criterion) {
    let engine = build(RodMass::new(6.0, 1.0, 0.9).unwrap());
    let heavy = build(RodMass::new(10.0, 1.0, 1.0).unwrap());
    let cranks = [0.0, 120.0, 240.0, 240.0, 120.0, 0.0];
    let angles: Vec<Angle> = (0..3600).map(|k| Angle::deg(k as f64 / 10.0)).collect();
    let mut group = c.benchmark_group("dynamics");
    group.bench_function("3600 poses, every force (EnginePose)", |b| {
        b.iter(|| {
            angles
                .iter()
                .map(|a| engine.at(*black_box(a)).unwrap().torque)
                .sum::<f64>()
        })
    });
    group.bench_function("3600 poses with a heavy rod, every force", |b| {
        b.iter(|| {
            angles
                .iter()
                .map(|a| {
                    let at = heavy.at(*black_box(a)).unwrap();
                    at.torque + at.loads.crank_pin[0]
                })
                .sum::<f64>()
        })
    });
    group.bench_function("six-cylinder balance: polygons and 3600 angles", |b| {
        b.iter(|| {
            let e = InlineEngine::new(black_box(&cranks), &default_planes(6), 6.0).unwrap();
            angles
                .iter()
                .map(|a| {
                    let (p, s) = e.forces_at(*a);
                    let (pc, sc) = e.couples_at(*a);
                    p + s + pc + sc + e.exact_force(*a).unwrap()
                })
                .sum::<f64>()
        })
    });
    group.bench_function("turning moment over the turn and flywheel", |b| {
        b.iter(|| {
            let tm = TurningMoment::new(black_box(&engine), &[0.0]).unwrap();
            Flywheel::for_coefficient(tm.fluctuation, engine.omega(), 0.02)
                .unwrap()
                .inertia
        })
    });
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
