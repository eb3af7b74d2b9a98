//! The turning-moment diagram of 3600 poses and the flywheel of one
//! engine: the §35 engine with a rod of mass and the example indicator
//! diagram.
//!
//! `cargo bench --bench dynamics`; the times are recorded in
//! docs/benchmarks.md with the whole-process time of `table dynamics`.

use criterion::{Criterion, criterion_group, criterion_main};
use slider_crank::dynamics::{
    Engine, Flywheel, GasForce, IndicatorDiagram, RodMass, TurningMoment,
};
use slider_crank::{Angle, SliderCrank};
use std::hint::black_box;

fn engine() -> Engine {
    let m = SliderCrank::in_line(0.5, 3.0).unwrap();
    let text = include_str!("../examples/indicator.csv");
    let gas = IndicatorDiagram::from_csv(text, 10.0 / 12.0, "indicator").unwrap();
    Engine::new(m, 10.0, 26.18)
        .unwrap()
        .with_rod(RodMass::new(6.0, 1.0, 0.9).unwrap())
        .unwrap()
        .with_gas(GasForce::Indicator(gas))
        .unwrap()
}

fn bench(c: &mut Criterion) {
    let engine = engine();
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
