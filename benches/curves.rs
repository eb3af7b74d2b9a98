//! Run time against error for curves: the polar velocity curve and the
//! fixed centrode at tolerances 1e-1 … 1e-5 page units, traced as (a) a
//! uniform polyline with the fewest equal steps whose measured error is
//! within the tolerance, (a′) the same with the fewest steps whose measured
//! error is within the adaptive cubic path's, (b) an adaptive polyline and
//! (c) adaptive cubic Béziers. The step counts are found (by measurement)
//! before timing; only the tracing is timed.
//!
//! `cargo bench --features bench --bench curves`, then `cargo run --release --example
//! curve_table` for the table with segments and measured errors
//! (docs/benchmarks.md).

#[path = "common/curve_cases.rs"]
mod cases;

use cases::{TOLERANCES, cases};
use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use slider_crank::diagram::Method;
use std::hint::black_box;
use std::time::Duration;

fn curves(c: &mut Criterion) {
    for case in cases() {
        let mut group = c.benchmark_group(format!("curves-{}", case.name));
        group
            .sample_size(30)
            .warm_up_time(Duration::from_millis(500))
            .measurement_time(Duration::from_secs(2));
        for tol in TOLERANCES {
            let id = format!("{tol:e}");
            let steps = case.uniform_steps(tol);
            let cubic_error = case.error(&case.trace(Method::Cubic, tol));
            let same_error_steps = case.uniform_steps(cubic_error);
            let methods = [
                ("uniform", Method::Uniform(steps)),
                ("uniform-same-error", Method::Uniform(same_error_steps)),
                ("polyline", Method::Polyline),
                ("cubic", Method::Cubic),
            ];
            for (name, method) in methods {
                group.bench_with_input(BenchmarkId::new(name, &id), &method, |b, &m| {
                    b.iter(|| case.trace(black_box(m), black_box(tol)))
                });
            }
        }
        group.finish();
    }
}

criterion_group!(benches, curves);
criterion_main!(benches);
