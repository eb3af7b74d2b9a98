//! The curve engine against the exact curves: every traced path is measured
//! independently (dense samples, nearest points) and must be within its
//! tolerance, both ways; poles, cusps and the frame are handled.

use slider_crank::SliderCrank;
use slider_crank::construct::{CentrodeKind, CouplerPoint};
use slider_crank::diagram::{
    Curve, Deviation, Locus, LocusKind, Method, Segment, Subpath, TraceOptions, TracedPath,
    measure, trace,
};
use slider_crank::figure::PageFromWorld;
use slider_crank::geom::{Frame, Point, Vector};
use std::f64::consts::{PI, TAU};
use std::ops::RangeInclusive;

const TOLERANCES: [f64; 4] = [1e-1, 1e-2, 1e-3, 1e-4];

/// A page map with `scale` px per world unit, y down, world `centre` at the
/// page centre of a `w` × `h` frame; `mirror` flips x (the cylinder on the
/// left, as the textbook draws it).
fn panel(scale: f64, mirror: bool, centre: Point, w: f64, h: f64) -> (PageFromWorld, Frame) {
    let sx = if mirror { -scale } else { scale };
    let map = PageFromWorld::scale_translate(
        sx,
        -scale,
        0.5 * w - sx * centre.x,
        0.5 * h + scale * centre.y,
    )
    .unwrap();
    (map, Frame::new(Point::new(0.0, 0.0), Point::new(w, h)))
}

fn mechanisms() -> Vec<SliderCrank> {
    [
        (1.0, 1.05, 0.0),
        (1.0, 4.0, 0.0),
        (0.5, 3.0, 0.0),
        (1.0, 4.0, 1.5),
        (1.0, 6.0, -2.0),
    ]
    .into_iter()
    .map(|(r, l, e)| SliderCrank::new(r, l, e).unwrap())
    .collect()
}

/// Traces and measures; returns the path and its measured deviation.
fn traced<C: Curve + ?Sized>(
    curve: &C,
    range: RangeInclusive<f64>,
    map: &PageFromWorld,
    frame: &Frame,
    tolerance: f64,
) -> (TracedPath, Deviation) {
    let options = TraceOptions::with_tolerance(tolerance);
    let path = trace(curve, range.clone(), map, frame, Method::Cubic, &options)
        .unwrap_or_else(|e| panic!("tolerance {tolerance}: {e}"));
    let deviation = measure(&path, curve, range, map, frame);
    (path, deviation)
}

fn assert_within(deviation: &Deviation, tolerance: f64, what: &str) {
    assert!(
        deviation.path_to_curve <= tolerance,
        "{what}: path strays {:e} from the curve, tolerance {tolerance:e}",
        deviation.path_to_curve
    );
    assert!(
        deviation.curve_to_path <= tolerance,
        "{what}: visible curve is {:e} from the path, tolerance {tolerance:e}",
        deviation.curve_to_path
    );
}

fn world_point<C: Curve + ?Sized>(curve: &C, t: f64) -> Point {
    curve.eval(t).unwrap().0
}

#[test]
fn polar_velocity_curves_are_within_tolerance() {
    for m in mechanisms() {
        let curve = Locus::new(m, LocusKind::PolarVelocity);
        // CE never exceeds about 1.1 r here (n = 1.05 reaches about 1.6 r).
        let r = m.crank();
        for (scale, mirror) in [(100.0 / r, false), (400.0 / r, true)] {
            let size = 4.0 * r * scale;
            let (map, frame) = panel(scale, mirror, Point::origin(), size, size);
            for tol in TOLERANCES {
                let (path, d) = traced(&curve, 0.0..=360.0, &map, &frame, tol);
                assert_within(&d, tol, &format!("{m:?} scale {scale} tol {tol}"));
                // Wholly inside the frame: one subpath from θ = 0 to 360°.
                assert_eq!(path.subpaths().len(), 1, "{m:?}");
                let sub = &path.subpaths()[0];
                assert_eq!(sub.start(), map.apply(world_point(&curve, 0.0)));
                assert_eq!(sub.end(), map.apply(world_point(&curve, 360.0)));
            }
        }
    }
}

#[test]
fn polar_curve_passes_through_c_at_the_dead_centres() {
    let m = SliderCrank::in_line(0.5, 3.0).unwrap();
    let curve = Locus::new(m, LocusKind::PolarVelocity);
    let (map, frame) = panel(300.0, false, Point::origin(), 400.0, 400.0);
    let path = trace(
        &curve,
        0.0..=360.0,
        &map,
        &frame,
        Method::Cubic,
        &TraceOptions::default(),
    )
    .unwrap();
    let c = map.apply(Point::origin());
    assert_eq!(c, Point::new(200.0, 200.0));
    let sub = &path.subpaths()[0];
    assert_eq!(sub.start(), c);
    // Some segment ends exactly at C for θ = 180° (a dyadic parameter).
    assert!(
        sub.segments().iter().any(|s| (s.end() - c).norm() < 1e-9),
        "no vertex at C"
    );
}

#[test]
fn centrodes_run_to_the_frame_edge_without_spikes() {
    for m in [
        SliderCrank::in_line(0.5, 3.0).unwrap(),
        SliderCrank::new(1.0, 4.0, 1.5).unwrap(),
        SliderCrank::in_line(1.0, 1.05).unwrap(),
    ] {
        for kind in [CentrodeKind::Fixed, CentrodeKind::Moving] {
            let curve = Locus::new(m, LocusKind::Centrode(kind));
            let scale = 100.0 / m.crank();
            let centre = Point::new(0.5 * m.rod(), 0.0);
            let (map, frame) = panel(scale, true, centre, 800.0, 600.0);
            for tol in TOLERANCES {
                let what = format!("{m:?} {kind:?} tol {tol}");
                let (path, d) = traced(&curve, 0.0..=360.0, &map, &frame, tol);
                assert_within(&d, tol, &what);
                assert!(path.subpaths().len() >= 2, "{what}: the poles split it");
                for sub in path.subpaths() {
                    // No spikes: every point of the path stays in the frame
                    // (up to the tolerance).
                    for (start, seg) in sub.pieces() {
                        for k in 0..=16 {
                            let p = seg.eval(start, k as f64 / 16.0);
                            let out = outside_distance(&frame, p);
                            assert!(out <= 2.0 * tol, "{what}: {p} is {out} outside");
                        }
                    }
                    // Each end is where the range ends or on the frame's edge.
                    for end in [sub.start(), sub.end()] {
                        let at_range_end = [0.0, 360.0]
                            .iter()
                            .any(|&t| (map.apply(world_point(&curve, t)) - end).norm() < 1e-9);
                        let edge = edge_distance(&frame, end);
                        assert!(
                            at_range_end || edge <= tol,
                            "{what}: end {end} is {edge} from the edge"
                        );
                    }
                }
            }
        }
    }
}

#[test]
fn fixed_centrode_has_three_branches_in_the_frame() {
    // In-line engine: θ in (−90°, 90°) is one branch through (l + r, 0), θ in
    // (90°, 270°) another; on 0..360 the first is cut at 0, giving three.
    let m = SliderCrank::in_line(0.5, 3.0).unwrap();
    let curve = Locus::new(m, LocusKind::Centrode(CentrodeKind::Fixed));
    let (map, frame) = panel(100.0, false, Point::new(1.5, 0.0), 600.0, 600.0);
    let path = trace(
        &curve,
        0.0..=360.0,
        &map,
        &frame,
        Method::Cubic,
        &TraceOptions::default(),
    )
    .unwrap();
    assert_eq!(path.subpaths().len(), 3);
    let ends: Vec<f64> = path
        .subpaths()
        .iter()
        .flat_map(|s| [s.start().y, s.end().y])
        .collect();
    // Starts at θ = 0 (page y 300), leaves at the top (y = 0), comes in at
    // the bottom (y = 600), and so on.
    let expected = [300.0, 0.0, 600.0, 0.0, 600.0, 300.0];
    for (y, e) in ends.iter().zip(expected) {
        assert!((y - e).abs() <= 0.01, "{ends:?}");
    }
}

#[test]
fn centrodes_close_to_their_poles() {
    // Ranges ending just short of the pole, in a frame large enough that the
    // curve stays inside until very near it.
    let m = SliderCrank::in_line(1.0, 4.0).unwrap();
    for kind in [CentrodeKind::Fixed, CentrodeKind::Moving] {
        let curve = Locus::new(m, LocusKind::Centrode(kind));
        let (map, frame) = panel(200.0, false, Point::origin(), 1e5, 1e5);
        for tol in [1e-2, 1e-4] {
            let (path, d) = traced(&curve, -89.0..=89.0, &map, &frame, tol);
            assert_within(&d, tol, &format!("{kind:?} tol {tol}"));
            assert_eq!(path.subpaths().len(), 1);
        }
        let (path, d) = traced(&curve, 89.0..=91.0, &map, &frame, 1e-3);
        assert_within(&d, 1e-3, &format!("{kind:?} across the pole"));
        assert_eq!(path.subpaths().len(), 2, "{kind:?}: one branch each side");
    }
}

#[test]
fn coupler_curves_are_within_tolerance() {
    for m in mechanisms() {
        for t in [0.3, 0.7] {
            let curve = Locus::new(m, LocusKind::Coupler(CouplerPoint::new(t).unwrap()));
            let scale = 250.0 / m.crank();
            let centre = Point::new(0.5 * m.rod(), m.offset() * 0.5);
            let w = (m.rod() + 2.5 * m.crank()) * scale;
            let h = (2.5 * m.crank() + m.offset().abs()) * scale;
            let (map, frame) = panel(scale, true, centre, w, h);
            for tol in TOLERANCES {
                let (path, d) = traced(&curve, 0.0..=360.0, &map, &frame, tol);
                assert_within(&d, tol, &format!("{m:?} t {t} tol {tol}"));
                assert_eq!(path.subpaths().len(), 1);
            }
        }
    }
}

#[test]
fn page_paths_map_to_world_and_back_within_tolerance() {
    let m = SliderCrank::new(1.0, 4.0, 1.5).unwrap();
    let curve = Locus::new(m, LocusKind::Centrode(CentrodeKind::Moving));
    // A sheared, non-uniform map: the engine works in page space anyway.
    let map = PageFromWorld::new([180.0, 20.0, -30.0, -120.0, 400.0, 300.0]).unwrap();
    let frame = Frame::new(Point::new(0.0, 0.0), Point::new(800.0, 600.0));
    let tol = 1e-3;
    let (path, _) = traced(&curve, 0.0..=360.0, &map, &frame, tol);
    assert!(!path.is_empty());
    let world = path.transform(&map.inverse()).unwrap();
    assert_eq!(world.segment_count(), path.segment_count());
    let back = world.transform(&map).unwrap();
    let d = measure(&back, &curve, 0.0..=360.0, &map, &frame);
    assert_within(&d, tol, "round trip");
}

/// The astroid (cos³ t, sin³ t): four cusps where the derivative vanishes.
fn astroid(t: f64) -> Option<(Point, Vector)> {
    let (s, c) = t.sin_cos();
    Some((
        Point::new(c * c * c, s * s * s),
        Vector::new(-3.0 * c * c * s, 3.0 * s * s * c),
    ))
}

#[test]
fn cusps_converge() {
    let (map, frame) = panel(200.0, false, Point::origin(), 500.0, 500.0);
    // Four initial pieces put the astroid's cusps at piece ends, three put
    // two of them inside pieces.
    for pieces in [4, 3] {
        let mut counts = Vec::new();
        for tol in TOLERANCES {
            let mut options = TraceOptions::with_tolerance(tol);
            options.initial_pieces = pieces;
            let path = trace(&astroid, 0.0..=TAU, &map, &frame, Method::Cubic, &options).unwrap();
            let d = measure(&path, &astroid, 0.0..=TAU, &map, &frame);
            assert_within(&d, tol, &format!("astroid, {pieces} pieces, tol {tol}"));
            counts.push(path.segment_count());
        }
        // Convergence, not blow-up: ten times tighter costs a bounded factor.
        for w in counts.windows(2) {
            assert!(w[1] <= 4 * w[0], "{counts:?}");
        }
    }
    // (sin² s, sin³ s): a semicubical cusp at s = 0, inside a piece, where
    // the derivative (2 sin s cos s, 3 sin² s cos s) vanishes.
    let cusp = |s: f64| {
        let (sn, c) = s.sin_cos();
        Some((
            Point::new(sn * sn, sn * sn * sn),
            Vector::new(2.0 * sn * c, 3.0 * sn * sn * c),
        ))
    };
    let (map, frame) = panel(200.0, false, Point::new(0.5, 0.0), 300.0, 500.0);
    for tol in TOLERANCES {
        let mut options = TraceOptions::with_tolerance(tol);
        options.initial_pieces = 3;
        let path = trace(&cusp, -1.0..=1.0, &map, &frame, Method::Cubic, &options).unwrap();
        let d = measure(&path, &cusp, -1.0..=1.0, &map, &frame);
        assert_within(&d, tol, &format!("semicubical cusp, tol {tol}"));
        assert!(path.segment_count() < 200, "{}", path.segment_count());
    }
}

#[test]
fn a_cubic_curve_is_one_segment_per_piece() {
    let curve = |t: f64| Some((Point::new(t, t * t * t), Vector::new(1.0, 3.0 * t * t)));
    let map = PageFromWorld::identity();
    let frame = Frame::new(Point::new(-1.0, -1.0), Point::new(2.0, 2.0));
    let mut options = TraceOptions::with_tolerance(1e-12);
    options.initial_pieces = 1;
    let path = trace(&curve, 0.0..=1.0, &map, &frame, Method::Cubic, &options).unwrap();
    assert_eq!(path.segment_count(), 1);
    let Segment::Cubic(c1, c2, end) = path.subpaths()[0].segments()[0] else {
        panic!("not a cubic")
    };
    assert!((c1 - Point::new(1.0 / 3.0, 0.0)).norm() < 1e-15);
    assert!((c2 - Point::new(2.0 / 3.0, 0.0)).norm() < 1e-15);
    assert_eq!(end, Point::new(1.0, 1.0));
    // A line is one chord for the adaptive polyline.
    let line = |t: f64| Some((Point::new(2.0 * t, t), Vector::new(2.0, 1.0)));
    let path = trace(&line, -0.5..=0.5, &map, &frame, Method::Polyline, &options).unwrap();
    assert_eq!(path.segment_count(), 1);
}

/// The unit circle, parameter in radians.
fn circle(t: f64) -> Option<(Point, Vector)> {
    let (s, c) = t.sin_cos();
    Some((Point::new(c, s), Vector::new(-s, c)))
}

#[test]
fn uniform_polyline_has_its_vertices_on_the_curve() {
    let (map, frame) = panel(100.0, false, Point::origin(), 300.0, 300.0);
    let options = TraceOptions::default();
    let path = trace(
        &circle,
        0.0..=TAU,
        &map,
        &frame,
        Method::Uniform(4),
        &options,
    )
    .unwrap();
    assert_eq!(path.segment_count(), 4);
    let sub = &path.subpaths()[0];
    let vertices: Vec<Point> = std::iter::once(sub.start())
        .chain(sub.segments().iter().map(Segment::end))
        .collect();
    let expected = [
        (250.0, 150.0),
        (150.0, 50.0),
        (50.0, 150.0),
        (150.0, 250.0),
        (250.0, 150.0),
    ];
    for (v, (x, y)) in vertices.iter().zip(expected) {
        assert!((v - Point::new(x, y)).norm() < 1e-12, "{v}");
    }
}

#[test]
fn measure_of_an_inscribed_polygon_is_its_sagitta() {
    // Regular n-gon in a circle of radius 100 px: the sagitta
    // 100 (1 − cos(π/n)) both ways.
    let (map, frame) = panel(100.0, false, Point::origin(), 300.0, 300.0);
    for n in [6usize, 40, 333] {
        let vertex = |k: usize| map.apply(circle(TAU * k as f64 / n as f64).unwrap().0);
        let segments = (1..=n).map(|k| Segment::Line(vertex(k))).collect();
        let path = TracedPath::new(vec![Subpath::new(vertex(0), segments).unwrap()]);
        let d = measure(&path, &circle, 0.0..=TAU, &map, &frame);
        let sagitta = 100.0 * (1.0 - (PI / n as f64).cos());
        assert!(
            (d.path_to_curve - sagitta).abs() <= 1e-9 * sagitta,
            "{n}: {} vs {sagitta}",
            d.path_to_curve
        );
        // The curve is sampled at its own spacing; it finds the sagitta
        // within a few per cent.
        assert!(d.curve_to_path <= sagitta * (1.0 + 1e-9));
        assert!(
            d.curve_to_path >= 0.95 * sagitta,
            "{n}: {}",
            d.curve_to_path
        );
    }
}

#[test]
fn measure_sees_a_missing_branch_and_a_spike() {
    let (map, frame) = panel(100.0, false, Point::origin(), 300.0, 300.0);
    let options = TraceOptions::default();
    // Half the circle drawn: the other half is up to the diameter away.
    let half = trace(&circle, 0.0..=PI, &map, &frame, Method::Cubic, &options).unwrap();
    let d = measure(&half, &circle, 0.0..=TAU, &map, &frame);
    assert!(d.path_to_curve <= options.tolerance);
    // The lowest point is 100√2 from either end of the drawn half.
    assert!(
        (d.curve_to_path - 100.0 * 2f64.sqrt()).abs() < 0.5,
        "{}",
        d.curve_to_path
    );
    // A line across the middle: 100 px from the circle at the centre.
    let spike = TracedPath::new(vec![
        Subpath::new(
            Point::new(50.0, 150.0),
            vec![Segment::Line(Point::new(250.0, 150.0))],
        )
        .unwrap(),
    ]);
    let d = measure(&spike, &circle, 0.0..=TAU, &map, &frame);
    assert!(
        (d.path_to_curve - 100.0).abs() < 1e-6,
        "{}",
        d.path_to_curve
    );
    let empty = measure(&TracedPath::default(), &circle, 0.0..=TAU, &map, &frame);
    assert_eq!(empty.path_to_curve, 0.0);
    assert_eq!(empty.curve_to_path, f64::INFINITY);
}

#[test]
fn a_brief_pass_through_a_corner_is_found() {
    // A circle of radius 3 (300 px) centred off the frame: only a small arc
    // near the corner (0, 0) of a 300 × 300 frame is visible.
    let big = |t: f64| {
        let (s, c) = t.sin_cos();
        Some((
            Point::new(-2.1 + 3.0 * c, 2.1 + 3.0 * s),
            Vector::new(-3.0 * s, 3.0 * c),
        ))
    };
    let (map, frame) = panel(100.0, false, Point::new(1.5, -1.5), 300.0, 300.0);
    let options = TraceOptions::with_tolerance(1e-3);
    let path = trace(&big, 0.0..=TAU, &map, &frame, Method::Cubic, &options).unwrap();
    assert_eq!(path.subpaths().len(), 1);
    let d = measure(&path, &big, 0.0..=TAU, &map, &frame);
    assert_within(&d, 1e-3, "corner");
    for end in [path.subpaths()[0].start(), path.subpaths()[0].end()] {
        assert!(edge_distance(&frame, end) <= 1e-3, "{end}");
    }
}

#[test]
fn excursions_out_of_the_frame_split_the_path() {
    // The circle of radius 100 px in a frame that cuts off its left and right
    // caps; both range ends inside, at the lowest point (150, 250): three
    // subpaths.
    let (map, _) = panel(100.0, false, Point::origin(), 300.0, 300.0);
    let narrow = Frame::new(Point::new(80.0, 0.0), Point::new(220.0, 300.0));
    let range = -PI / 2.0..=1.5 * PI;
    for method in [Method::Cubic, Method::Polyline, Method::Uniform(500)] {
        let path = trace(
            &circle,
            range.clone(),
            &map,
            &narrow,
            method,
            &TraceOptions::default(),
        )
        .unwrap();
        assert_eq!(path.subpaths().len(), 3, "{method:?}");
        let d = measure(&path, &circle, range.clone(), &map, &narrow);
        if method != Method::Uniform(500) {
            assert_within(&d, 0.01, &format!("{method:?}"));
        }
        for sub in path.subpaths() {
            for end in [sub.start(), sub.end()] {
                let x_edge = (end.x - 80.0).abs().min((end.x - 220.0).abs());
                let lowest = (end - Point::new(150.0, 250.0)).norm();
                assert!(x_edge <= 0.01 || lowest < 1e-9, "{method:?}: {end}");
            }
        }
    }
}

#[test]
fn bad_requests_are_errors_not_panics() {
    let (map, frame) = panel(100.0, false, Point::origin(), 300.0, 300.0);
    let run = |range: RangeInclusive<f64>, method: Method, options: TraceOptions| {
        trace(&circle, range, &map, &frame, method, &options)
    };
    let ok = TraceOptions::default();
    for tol in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        assert!(
            run(0.0..=1.0, Method::Cubic, TraceOptions::with_tolerance(tol)).is_err(),
            "{tol}"
        );
    }
    assert!(run(1.0..=1.0, Method::Cubic, ok).is_err());
    assert!(run(1.0..=0.0, Method::Cubic, ok).is_err());
    assert!(run(f64::NAN..=1.0, Method::Cubic, ok).is_err());
    assert!(run(-f64::MAX..=f64::MAX, Method::Cubic, ok).is_err());
    assert!(run(0.0..=1.0, Method::Uniform(0), ok).is_err());
    let mut none = ok;
    none.initial_pieces = 0;
    assert!(run(0.0..=1.0, Method::Cubic, none).is_err());
    let mut few = TraceOptions::with_tolerance(1e-6);
    few.max_segments = 5;
    let err = run(0.0..=TAU, Method::Cubic, few).unwrap_err();
    assert!(err.to_string().contains("more than 5 segments"), "{err}");
}

#[test]
fn a_jump_is_reported_not_looped_over() {
    let jump = |t: f64| {
        Some((
            Point::new(t, if t < 0.3 { 0.0 } else { 1.0 }),
            Vector::new(1.0, 0.0),
        ))
    };
    let map = PageFromWorld::scale_translate(100.0, 100.0, 0.0, 0.0).unwrap();
    let frame = Frame::new(Point::new(-10.0, -10.0), Point::new(200.0, 200.0));
    let err = trace(
        &jump,
        0.0..=1.0,
        &map,
        &frame,
        Method::Cubic,
        &TraceOptions::default(),
    )
    .unwrap_err();
    assert!(err.to_string().contains("near parameter 0.29"), "{err}");
}

#[test]
fn undefined_and_non_finite_curves_give_no_nan() {
    let (map, frame) = panel(100.0, false, Point::origin(), 300.0, 300.0);
    let options = TraceOptions::default();
    let nowhere = |_: f64| -> Option<(Point, Vector)> { None };
    let path = trace(&nowhere, 0.0..=1.0, &map, &frame, Method::Cubic, &options).unwrap();
    assert!(path.is_empty());
    // NaN on a stretch of the range, a hole in the curve: two subpaths, all
    // finite.
    let holed = |t: f64| {
        if (2.0..2.5).contains(&t) {
            Some((Point::new(f64::NAN, 0.0), Vector::new(0.0, f64::NAN)))
        } else {
            circle(t)
        }
    };
    for method in [Method::Cubic, Method::Polyline, Method::Uniform(100)] {
        let path = trace(&holed, 0.0..=TAU, &map, &frame, method, &options).unwrap();
        assert_eq!(path.subpaths().len(), 2, "{method:?}");
        for sub in path.subpaths() {
            for (start, seg) in sub.pieces() {
                let p = seg.eval(start, 0.5);
                assert!(p.x.is_finite() && p.y.is_finite());
            }
        }
    }
}

/// How far `p` is outside the frame (0 inside).
fn outside_distance(frame: &Frame, p: Point) -> f64 {
    let (lo, hi) = (frame.min(), frame.max());
    let dx = (lo.x - p.x).max(p.x - hi.x).max(0.0);
    let dy = (lo.y - p.y).max(p.y - hi.y).max(0.0);
    dx.hypot(dy)
}

/// Distance from `p` to the frame's boundary.
fn edge_distance(frame: &Frame, p: Point) -> f64 {
    let (lo, hi) = (frame.min(), frame.max());
    if frame.contains(p) {
        (p.x - lo.x).min(hi.x - p.x).min(p.y - lo.y).min(hi.y - p.y)
    } else {
        outside_distance(frame, p)
    }
}

mod random {
    use super::*;
    use proptest::prelude::*;

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(24))]
        /// Random mechanisms, curves, page maps and tolerances: the measured
        /// deviation is within the tolerance both ways.
        #[test]
        fn every_traced_curve_is_within_its_tolerance(
            log_n_minus_1 in -1.3f64..1.3,
            offset_frac in -0.9f64..0.9,
            which in 0usize..4,
            coupler_t in 0.0f64..=1.0,
            scale in 100.0f64..400.0,
            mirror in any::<bool>(),
            squash in 0.7f64..1.3,
            shift_x in -100.0f64..100.0,
            shift_y in -100.0f64..100.0,
            log_tol in -4.0f64..-1.0,
        ) {
            let l = 1.0 + 10f64.powf(log_n_minus_1);
            let m = SliderCrank::new(1.0, l, offset_frac * (l - 1.0)).unwrap();
            let kind = match which {
                0 => LocusKind::PolarVelocity,
                1 => LocusKind::Centrode(CentrodeKind::Fixed),
                2 => LocusKind::Centrode(CentrodeKind::Moving),
                _ => LocusKind::Coupler(CouplerPoint::new(coupler_t).unwrap()),
            };
            let curve = Locus::new(m, kind);
            let sx = if mirror { -scale } else { scale };
            let map = PageFromWorld::scale_translate(sx, -scale * squash, 400.0 + shift_x, 300.0 + shift_y)
                .unwrap();
            let frame = Frame::new(Point::new(0.0, 0.0), Point::new(800.0, 600.0));
            let tol = 10f64.powf(log_tol);
            let (_, d) = traced(&curve, 0.0..=360.0, &map, &frame, tol);
            prop_assert!(d.max() <= tol, "{:?} {:?} tol {:e}: {:?}", m, kind, tol, d);
        }
    }
}

#[test]
fn degenerate_frames_draw_nothing_and_do_not_panic() {
    let map = PageFromWorld::scale_translate(100.0, -100.0, 150.0, 150.0).unwrap();
    let options = TraceOptions::default();
    let point = Frame::new(Point::new(150.0, 150.0), Point::new(150.0, 150.0));
    let nan = Frame::new(Point::new(f64::NAN, 0.0), Point::new(1.0, f64::NAN));
    let huge = Frame::new(
        Point::new(f64::NEG_INFINITY, -1e300),
        Point::new(f64::INFINITY, 1e300),
    );
    for frame in [point, nan] {
        for method in [Method::Cubic, Method::Polyline, Method::Uniform(10)] {
            let path = trace(&circle, 0.0..=TAU, &map, &frame, method, &options).unwrap();
            assert!(path.is_empty(), "{frame:?} {method:?}");
            let d = measure(&path, &circle, 0.0..=TAU, &map, &frame);
            assert!(!d.path_to_curve.is_nan() && !d.curve_to_path.is_nan());
        }
    }
    // An unbounded frame clips nothing: the whole circle, within tolerance.
    let path = trace(&circle, 0.0..=TAU, &map, &huge, Method::Cubic, &options).unwrap();
    assert_eq!(path.subpaths().len(), 1);
    let (bounded_map, bounded) = panel(100.0, false, Point::origin(), 300.0, 300.0);
    assert_eq!(bounded_map, map);
    let d = measure(&path, &circle, 0.0..=TAU, &map, &bounded);
    assert_within(&d, options.tolerance, "unbounded frame");
    let d = measure(&path, &circle, 0.0..=TAU, &map, &huge);
    assert!(!d.path_to_curve.is_nan() && !d.curve_to_path.is_nan());
}
