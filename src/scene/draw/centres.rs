//! The six virtual centres of the chain (§34), named O_ab ... O_cd.

use super::LayerCtx;
use crate::construct::Link;
use crate::figure::{RichText, Role, Shape, TextSize};
use crate::geom::{Intersection, Vector};
use crate::scene::canvas::Canvas;

/// Length of the arrow that shows a centre at infinity, page units.
const ARROW: f64 = 30.0;

fn link(l: Link) -> char {
    match l {
        Link::A => 'a',
        Link::B => 'b',
        Link::C => 'c',
        Link::D => 'd',
    }
}

pub(crate) fn draw(ctx: &LayerCtx, canvas: &mut Canvas) {
    let pose = ctx.main.pose();
    let centres = *ctx.main.virtual_centres().all();
    for (p, q, centre) in centres {
        let name = format!("{}{}", link(p), link(q));
        let id = format!("centre-O-{name}");
        let text = RichText::italic(&format!("O_{{{name}}}"));
        match centre {
            Intersection::Point(x) if canvas.contains(x) => {
                canvas.push(id, Role::Construction, Shape::Dot { centre: x });
                canvas.label(format!("label-O-{name}"), x, text, TextSize::Small);
            }
            Intersection::Point(x) => {
                // Off the page: an arrow from the slider towards it.
                let from = pose.a();
                if let Some((_, edge)) = canvas.frame().clip_segment(from, x) {
                    let tail = canvas.edge_arrow(id, edge, (x - from).normalize(), ARROW);
                    canvas.label(format!("label-O-{name}"), tail, text, TextSize::Small);
                }
            }
            Intersection::AtInfinity(d) => {
                // O_cd lies at infinity across the stroke, O_bd (θ = 90°,
                // 270°) along the crank: the arrow starts at the slider or
                // the crank pin.
                let (from, mut u) = if p == Link::C || q == Link::C {
                    (pose.a(), Vector::new(0.0, 1.0))
                } else {
                    (pose.b(), d.into_inner())
                };
                if u.dot(&(from - pose.c())) < 0.0 && u.y.abs() > 0.5 && from == pose.b() {
                    u = -u;
                }
                if let Some((_, edge)) = canvas.frame().clip_ray(from, u) {
                    let tail = canvas.edge_arrow(id, edge, u, ARROW);
                    canvas.label(
                        format!("label-O-{name}"),
                        tail,
                        RichText::parse(&format!("*O*_{{{name}}} at ∞")),
                        TextSize::Small,
                    );
                }
            }
            Intersection::Coincident => {}
        }
    }
}
