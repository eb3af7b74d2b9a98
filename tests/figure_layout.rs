//! Single figures at the engines and pages where their layout once failed
//! (issue 20), each read back from its SVG alone: how much of the page the
//! drawing takes, which letter stands by which point, what crosses what.

#[allow(dead_code)] // the helpers the other figure tests use
mod common;
#[allow(dead_code)] // the reader's other helpers
#[path = "common/plate.rs"]
mod plate;

use plate::{Plate, Rect};
use slider_crank::catalogue::FigureOptions;
use slider_crank::render::to_svg;
use slider_crank::{Angle, FigureName, SliderCrank};

/// `name`'s SVG for the engine r, l, e at `deg`, on `width` if given.
fn svg(name: FigureName, engine: Option<(f64, f64, f64, f64)>, width: Option<&str>) -> String {
    let mut options = FigureOptions::default();
    if let Some((r, l, e, deg)) = engine {
        options.mechanism = Some(SliderCrank::new(r, l, e).unwrap());
        options.angle = Some(Angle::deg(deg));
    }
    options.width = width.map(|w| w.parse().unwrap());
    to_svg(&name.figure(&options).unwrap())
}

fn centre(r: &Rect) -> (f64, f64) {
    ((r.x0 + r.x1) / 2.0, (r.y0 + r.y1) / 2.0)
}

fn distance(a: (f64, f64), b: (f64, f64)) -> f64 {
    (a.0 - b.0).hypot(a.1 - b.1)
}

/// The box of every ink whose owner's id starts with one of `prefixes`.
fn ink_of(plate: &Plate, prefixes: &[&str]) -> Rect {
    Rect::around(
        plate
            .ink
            .iter()
            .filter(|(id, _)| prefixes.iter().any(|p| id.starts_with(p)))
            .flat_map(|(_, r)| [(r.x0, r.y0), (r.x1, r.y1)]),
    )
    .unwrap()
}

/// The coupler curves at a short offset rod (issue 20): the drawing took
/// a third of a 760-unit page, A's and C's letters overprinted, and P₁'s
/// letter stood nearer P₂'s and P₃'s dots than its own.
#[test]
fn coupler_curves_at_a_short_rod_fill_the_page_and_letter_their_own_points() {
    let engine = Some((1.0, 1.1, 0.08, 110.0));
    let text = svg(FigureName::CouplerCurves, engine, None);
    let plate = Plate::read(&text);
    let drawn = ink_of(
        &plate,
        &[
            "curve-", "link-", "point-", "guide", "hatch", "circle", "block",
        ],
    );
    let share = (drawn.x1 - drawn.x0) / plate.width;
    assert!(
        share >= 0.6,
        "the drawing spans {share:.2} of the page's width"
    );
    let panel = &plate.panels[0];
    let label = |id: &str| panel.labels.iter().find(|l| l.id == id).unwrap().rect;
    for k in 1..=3 {
        let own = format!("P{k}");
        let at = centre(&label(&format!("label-{own}")));
        let mine = distance(at, panel.markers[&own]);
        for (other, p) in &panel.markers {
            assert!(
                other == &own || distance(at, *p) > mine,
                "{own}'s letter is {mine:.1} from its dot, {:.1} from {other}'s",
                distance(at, *p)
            );
        }
    }
    let (a, c) = (label("label-A"), label("label-C"));
    assert!(!a.overlaps(&c), "A {a:?} and C {c:?} overprint");
}

/// Inversion 2 (issue 20): its panel was the world the frame sweeps over
/// a turn, a disc about C, and at one pose the drawing sat low on its
/// page, the top 200 and the left 450 units empty. At its default, on
/// 120 mm and at a short rod near the inner dead centre, the drawing now
/// starts within 60 units of the page's top and spans 60 % of its width.
#[test]
fn inversion_2_fits_its_page_to_the_drawing() {
    let cases = [
        (None, None),
        (None, Some("120mm")),
        (Some((1.0, 1.2, 0.0, 170.0)), None),
    ];
    for (engine, width) in cases {
        let text = svg(FigureName::Inversion2RotatingBlock, engine, width);
        let plate = Plate::read(&text);
        let drawn = ink_of(
            &plate,
            &[
                "link-",
                "point-",
                "circle-",
                "block",
                "line-",
                "offpage-",
                "infinity-",
            ],
        );
        let share = (drawn.x1 - drawn.x0) / plate.width;
        assert!(
            share >= 0.6,
            "{engine:?} {width:?}: the drawing spans {share:.2} of the width"
        );
        assert!(
            drawn.y0 <= 60.0,
            "{engine:?} {width:?}: the drawing starts {:.0} down",
            drawn.y0
        );
    }
}
