//! The marks of the dynamics figures read back from their SVG: the crank
//! effort's arc of the inertia force figure and the torque arrow of Ng's
//! Fig. 1, each by what it names and clear of what it does not.

use crate::plate;

use plate::{Panel, Plate, Pt, Seg};
use slider_crank::catalogue::FigureOptions;
use slider_crank::{Angle, FigureName, SliderCrank, render::to_svg};

/// The plate of `figure` at a crank of 1, `rod`, `offset` and `degrees`.
fn plate_at(figure: &str, rod: f64, offset: f64, degrees: f64) -> Plate {
    let mut options = FigureOptions::default();
    options.mechanism = Some(SliderCrank::new(1.0, rod, offset).unwrap());
    options.angle = Some(Angle::deg(degrees));
    let f = FigureName::from_name(figure).unwrap().figure(&options);
    Plate::read(&to_svg(&f.unwrap()))
}

/// The pieces of the strokes of `panel` with the id `id`.
fn segs<'a>(panel: &'a Panel, id: &str) -> Vec<&'a Seg> {
    panel
        .strokes
        .iter()
        .filter(|s| s.id == id)
        .flat_map(|s| &s.segs)
        .collect()
}

fn distance(p: Pt, q: Pt) -> f64 {
    (p.0 - q.0).hypot(p.1 - q.1)
}

#[test]
fn the_crank_effort_s_arc_keeps_off_the_ends_of_the_construction() {
    // The inertia force at l = 2.04 r, e = 0.562 r, 90.16°: CG on the
    // main view as long as the arc's radius, the arc ran through G,
    // where CG and the line from B end, its head there: it read as the
    // arrowhead of the line from B. The arc keeps a letter's room from
    // the ends of the lines.
    let plate = plate_at("inertia-force", 2.04, 0.562, 90.16);
    let main = &plate.panels[0];
    let arc = segs(main, "torque-T");
    assert!(!arc.is_empty(), "no crank effort on the main view");
    // G: the end of CG away from C.
    let c = plate.point(main, "C").expect("C");
    let cg = segs(main, "line-CG");
    let g = [cg.first().expect("no CG").0, cg.last().expect("no CG").1]
        .into_iter()
        .max_by(|p, q| distance(*p, c).total_cmp(&distance(*q, c)))
        .unwrap();
    let near = arc
        .iter()
        .map(|s| s.distance_to(g))
        .fold(f64::INFINITY, f64::min);
    assert!(near >= 10.0, "the arc {near:.1} from G");
}
