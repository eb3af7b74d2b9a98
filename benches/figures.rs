//! Time to build each seed figure: the scene's constructions and the figure
//! model, then the SVG text, then both; each diagram's model and SVG; and
//! one PNG.

use criterion::{Criterion, criterion_group, criterion_main};
use slider_crank::FigureName;
use slider_crank::catalogue::FigureOptions;
use slider_crank::render::{to_png, to_svg};
use std::hint::black_box;
use std::time::Duration;

fn figures(c: &mut Criterion) {
    let mut group = c.benchmark_group("figure");
    group
        .sample_size(40)
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(2));
    for name in FigureName::SCENES {
        let scene = name.scene().unwrap();
        group.bench_function(format!("model/{}", name.name()), |b| {
            b.iter(|| black_box(&scene).figure().unwrap())
        });
        let figure = scene.figure().unwrap();
        group.bench_function(format!("svg/{}", name.name()), |b| {
            b.iter(|| to_svg(black_box(&figure)))
        });
        group.bench_function(format!("total/{}", name.name()), |b| {
            b.iter(|| to_svg(&black_box(&scene).figure().unwrap()))
        });
    }
    // The diagrams: plots with curves traced to 0.01 px, and the
    // mechanism panels they draw on.
    let defaults = FigureOptions::default();
    for name in FigureName::DIAGRAMS {
        group.bench_function(format!("model/{}", name.name()), |b| {
            b.iter(|| black_box(name).figure(&defaults).unwrap())
        });
        let figure = name.figure(&defaults).unwrap();
        group.bench_function(format!("svg/{}", name.name()), |b| {
            b.iter(|| to_svg(black_box(&figure)))
        });
    }
    group.finish();
    let svg = to_svg(&FigureName::Fig67Example.scene().unwrap().figure().unwrap());
    let mut png = c.benchmark_group("png");
    png.sample_size(10).measurement_time(Duration::from_secs(3));
    png.bench_function("fig-67-example at 2x", |b| {
        b.iter(|| to_png(black_box(&svg), 2.0).unwrap())
    });
    png.finish();
}

criterion_group!(benches, figures);
criterion_main!(benches);
