//! The curve benchmark's table: for the polar velocity curve and the fixed
//! centrode at tolerances 1e-1 … 1e-5 px, the segments, measured error and
//! time of a uniform polyline (fewest steps within the tolerance, and fewest
//! within the cubic path's measured error), an adaptive polyline and
//! adaptive cubic Béziers.
//!
//! Times are criterion's mean estimates from `cargo bench --features bench --bench curves`
//! (read from target/criterion); where a benchmark has not been run the
//! example times the trace itself (median of 15 batches) and says so.
//!
//! `cargo run --release --example curve_table` prints the markdown table
//! and writes docs/curve-benchmarks.csv.

#[path = "../benches/common/curve_cases.rs"]
mod cases;

use cases::{Case, TOLERANCES, cases};
use slider_crank::diagram::{Method, TracedPath};
use std::fmt::Write as _;
use std::time::Instant;

struct Row {
    method: &'static str,
    steps: Option<usize>,
    segments: usize,
    error: f64,
    time_us: f64,
    timed_by: &'static str,
}

fn criterion_mean_us(group: &str, method: &str, tol: &str) -> Option<f64> {
    let dir = std::env::var("CARGO_TARGET_DIR").unwrap_or_else(|_| "target".into());
    let file = format!("{dir}/criterion/{group}/{method}/{tol}/new/estimates.json");
    let text = std::fs::read_to_string(file).ok()?;
    let json: serde_json::Value = serde_json::from_str(&text).ok()?;
    Some(json["mean"]["point_estimate"].as_f64()? / 1000.0)
}

fn self_timed_us(case: &Case, method: Method, tol: f64) -> f64 {
    let once = Instant::now();
    let _ = case.trace(method, tol);
    let reps = (0.01 / once.elapsed().as_secs_f64().max(1e-9)).clamp(1.0, 10_000.0) as usize;
    let mut batches: Vec<f64> = (0..15)
        .map(|_| {
            let start = Instant::now();
            for _ in 0..reps {
                std::hint::black_box(case.trace(method, tol));
            }
            start.elapsed().as_secs_f64() * 1e6 / reps as f64
        })
        .collect();
    batches.sort_by(f64::total_cmp);
    batches[7]
}

fn row(case: &Case, name: &'static str, method: Method, tol: f64, path: &TracedPath) -> Row {
    let group = format!("curves-{}", case.name);
    let (time_us, timed_by) = match criterion_mean_us(&group, name, &format!("{tol:e}")) {
        Some(t) => (t, "criterion"),
        None => (self_timed_us(case, method, tol), "example"),
    };
    Row {
        method: name,
        steps: match method {
            Method::Uniform(n) => Some(n),
            _ => None,
        },
        segments: path.segment_count(),
        error: case.error(path),
        time_us,
        timed_by,
    }
}

fn main() {
    let mut csv = String::from(
        "curve,tolerance_px,method,steps,segments,measured_error_px,time_us,timed_by\n",
    );
    let mut md = String::new();
    for case in cases() {
        writeln!(md, "\n### {}\n", case.description).unwrap();
        md.push_str(
            "| tolerance (px) | uniform: steps / segments / error / µs | uniform at the cubic's error: steps / segments / error / µs | adaptive polyline: segments / error / µs | cubic: segments / error / µs | uniform ÷ cubic segments (same tolerance, same error) |\n",
        );
        md.push_str("|---|---|---|---|---|---|\n");
        for tol in TOLERANCES {
            let cubic_path = case.trace(Method::Cubic, tol);
            let cubic = row(&case, "cubic", Method::Cubic, tol, &cubic_path);
            let steps = case.uniform_steps(tol);
            let uniform_method = Method::Uniform(steps);
            let uniform = row(
                &case,
                "uniform",
                uniform_method,
                tol,
                &case.trace(uniform_method, tol),
            );
            let same_method = Method::Uniform(case.uniform_steps(cubic.error));
            let same = row(
                &case,
                "uniform-same-error",
                same_method,
                tol,
                &case.trace(same_method, tol),
            );
            let polyline = row(
                &case,
                "polyline",
                Method::Polyline,
                tol,
                &case.trace(Method::Polyline, tol),
            );
            let cell = |r: &Row| {
                let steps = r.steps.map_or(String::new(), |n| format!("{n} / "));
                format!("{steps}{} / {:.2e} / {:.1}", r.segments, r.error, r.time_us)
            };
            writeln!(
                md,
                "| {tol:.0e} | {} | {} | {} | {} | {:.1}×, {:.1}× |",
                cell(&uniform),
                cell(&same),
                cell(&polyline),
                cell(&cubic),
                uniform.segments as f64 / cubic.segments as f64,
                same.segments as f64 / cubic.segments as f64,
            )
            .unwrap();
            for r in [&uniform, &same, &polyline, &cubic] {
                writeln!(
                    csv,
                    "{},{tol:e},{},{},{},{:.4e},{:.3},{}",
                    case.name,
                    r.method,
                    r.steps.map_or(String::new(), |n| n.to_string()),
                    r.segments,
                    r.error,
                    r.time_us,
                    r.timed_by
                )
                .unwrap();
            }
            eprintln!("{} {tol:e} done", case.name);
        }
    }
    print!("{md}");
    std::fs::create_dir_all("docs").expect("docs folder");
    std::fs::write("docs/curve-benchmarks.csv", csv).expect("write the CSV");
    eprintln!("wrote docs/curve-benchmarks.csv");
}
