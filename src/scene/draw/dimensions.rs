//! The dimensions layer (Fig. 62): crank angle θ, displacement x from
//! mid-stroke, the stroke, r and l.

use super::LayerCtx;
use crate::figure::{RichText, Role, Shape, TextSize, angle_radius};
use crate::geom::{Point, Vector};
use crate::scene::canvas::{Canvas, Marker};
use crate::scene::notation::Named;

/// Clear distance of the first dimension line below the guides, page units.
const FIRST: f64 = 22.0;
/// Spacing of stacked dimension lines, page units.
const STEP: f64 = 24.0;
/// How far below the guides the dimensions reach, page units: the
/// second line, its text and the text's descent.
pub(crate) const DEPTH: f64 = FIRST + STEP + 26.0;

/// θ at C, φ between the rod and a parallel to the stroke through B, and
/// the links' lengths r and l.
pub(crate) fn angles(ctx: &LayerCtx, canvas: &mut Canvas) {
    let pose = ctx.main.pose();
    let m = pose.mechanism();
    let (a, b, c) = (pose.a(), pose.b(), pose.c());
    let theta = pose.angle().radians();
    if theta > 0.0 && !canvas.is_bare(c) {
        canvas.push(
            "angle-theta",
            Role::Dimension,
            Shape::AngleMark {
                vertex: c,
                start: 0.0,
                sweep: theta,
                text: Some(RichText::italic("θ")),
            },
        );
    }
    // φ at B: a short parallel to the stroke towards the slider, and the
    // arc from it to the rod.
    let ba = a - b;
    let phi = obliquity(ctx);
    let reach = canvas.world(PARALLEL).min(0.6 * ba.x);
    let past_arc = canvas.page(reach) >= angle_radius(phi) + 4.0;
    if canvas.page(ba.norm()) * phi.abs() > 6.0 && opens(phi) && past_arc && !canvas.is_bare(b) {
        canvas.segment(
            "line-parallel-B",
            Role::Auxiliary,
            b,
            b + Vector::new(reach, 0.0),
        );
        canvas.push(
            "angle-phi",
            Role::Dimension,
            Shape::AngleMark {
                vertex: b,
                start: 0.0,
                sweep: phi,
                text: Some(RichText::italic("φ")),
            },
        );
    }
    if !canvas.is_bare(nalgebra::center(&c, &b)) {
        canvas.line_label("value-r", (c, b), RichText::italic("r"), TextSize::Small);
    }
    let l = if ctx.scene.notation() == crate::scene::Notation::Ng {
        RichText::italic("l")
    } else {
        RichText::parse(&format!("*l* = {}*r*", crate::number::short(m.ratio())))
    };
    if !canvas.is_bare(nalgebra::center(&b, &a)) {
        canvas.line_label("value-l", (b, a), l, TextSize::Small);
    }
}

/// The least opening (page units) of an angle's arc at its
/// [`angle_radius`] for it to be drawn: a smaller one is a single line
/// with a letter beside it (φ at long rods, at most 1.2° at 48 cranks).
const LEAST_OPENING: f64 = 3.0;

/// Whether the obliquity `phi` (radians) opens its arc by
/// [`LEAST_OPENING`]; where not, it is left unmarked and the notes give
/// its value ([`phi_note`]).
fn opens(phi: f64) -> bool {
    angle_radius(phi) * phi.abs() >= LEAST_OPENING
}

/// The angle φ at B from the parallel to the stroke to the rod, as
/// [`angles`] marks it (radians).
fn obliquity(ctx: &LayerCtx) -> f64 {
    let pose = ctx.main.pose();
    let ba = pose.a() - pose.b();
    ba.y.atan2(ba.x)
}

/// The note for an obliquity too small to mark ([`opens`]): its value in
/// degrees; none where it is marked or zero (a dead centre of an engine
/// without offset, where there is nothing to mark).
pub(crate) fn phi_note(ctx: &LayerCtx, letter: &str) -> Option<RichText> {
    let phi = obliquity(ctx);
    (phi != 0.0 && !opens(phi)).then(|| {
        RichText::parse(&format!(
            "The angle *{letter}* ({}°) is too small to show at this scale.",
            crate::number::sig(phi.abs().to_degrees())
        ))
    })
}

/// Length of the parallel to the stroke through B that φ is measured
/// from, page units: past the largest arc of an angle
/// ([`crate::figure::ANGLE_RADIUS_MOST`]) by a margin.
const PARALLEL: f64 = crate::figure::ANGLE_RADIUS_MOST + 12.0;

/// Whether the displacement and the stroke are dimensioned above the
/// guides: where the line of stroke runs above the whole crank circle
/// (an offset e > r), the side away from the crank; or where the links
/// reach below the guides over the stroke's span (a rod of less than two
/// cranks near 270°: the stroke's extension line beside the crank
/// doubled it, its arrowhead landed on the rod), and not above them, the
/// side they leave clear. Below them otherwise (the textbook's Fig. 62),
/// where the crank circle reaches past the stroke both ways or lies
/// above it; a view held over a series of poses keeps its side.
pub(crate) fn above(ctx: &LayerCtx) -> bool {
    let m = ctx.scene.mechanism();
    if m.offset() > m.crank() {
        return true;
    }
    ctx.scene.held_view().is_none() && reach_beyond(ctx, -1.0) && !reach_beyond(ctx, 1.0)
}

/// Whether the crank or the rod runs beyond the guide on `side` (+1
/// above the line of stroke, −1 below, world) over the stroke's span
/// and [`SPAN_MARGIN`] of a block's length either way: across the
/// dimensions stacked there.
fn reach_beyond(ctx: &LayerCtx, side: f64) -> bool {
    let pose = ctx.main.pose();
    let e = pose.mechanism().offset();
    let (near, far) = ctx.sizes.travel;
    let margin = SPAN_MARGIN * ctx.sizes.block_half_length;
    let (x0, x1) = (near.min(far) - margin, near.max(far) + margin);
    let h = ctx.sizes.block_half_height;
    let (a, b, c) = (pose.a(), pose.b(), pose.c());
    [(c, b), (b, a)].into_iter().any(|(p, q)| {
        (0..=64).any(|k| {
            let t = f64::from(k) / 64.0;
            let s = p + (q - p) * t;
            (x0..=x1).contains(&s.x) && side * (s.y - e) > h
        })
    })
}

/// How far past the stroke's ends, in blocks' half-lengths, a link
/// beyond the guides counts against the dimensions there: their
/// extension lines and arrowheads.
const SPAN_MARGIN: f64 = 1.0;

pub(crate) fn draw(ctx: &LayerCtx, canvas: &mut Canvas) {
    let pose = ctx.main.pose();
    let m = pose.mechanism();
    let e = m.offset();
    let (a, c) = (pose.a(), pose.c());
    // Mid-stroke O and the displacement x = OA (signed: A beyond O, away
    // from C, is positive here).
    let (near, far) = ctx.sizes.travel;
    let o = Point::new(0.5 * (near + far), e);
    let below = match above(ctx) {
        true => Vector::new(0.0, 1.0),
        false => Vector::new(0.0, -1.0),
    };
    let guide = canvas.page(ctx.sizes.block_half_height);
    canvas.point(ctx.letter(Named::MidStroke), o, Marker::Dot, c);
    // However short x is on the page, it is dimensioned (the heads point
    // in from outside its extension lines, as a draughtsman dimensions a
    // length shorter than its arrows, onto one line where x is under a
    // pixel): near 90° on a long rod x is a few thousandths of the
    // stroke, and left out it read as missing. Only x = 0 is not.
    if (a - o).norm() > 0.0 {
        canvas.push(
            "dimension-x",
            Role::Dimension,
            Shape::Dimension {
                from: o,
                to: a,
                side: below,
                offset: guide + FIRST,
                text: RichText::italic("x"),
            },
        );
    }
    canvas.push(
        "dimension-stroke",
        Role::Dimension,
        Shape::Dimension {
            from: Point::new(near, e),
            to: Point::new(far, e),
            side: below,
            offset: guide + FIRST + STEP,
            text: RichText::parse("stroke"),
        },
    );
}

/// How far from the crank centre the offset's extension line starts,
/// page units, where no torque arrow stands about it: past its letter
/// (an em and a half of the small text beside a pin). Set past θ's arc
/// too (36), it left one more plate of the sweep with two letters within
/// half an em than the plate check holds.
const CENTRE_ROOM: f64 = 26.0;

/// The offset e of the line of stroke from the crank centre, dimensioned
/// on the side away from the slider, beyond the crank circle and beyond
/// whatever the constructions draw on that side (Kisch's semicircle and
/// its arc reach past the circle at some poses): beyond the frame the main
/// view was fitted to, so that in a held view it stays put.
pub(crate) fn offset(ctx: &LayerCtx, canvas: &mut Canvas) {
    let m = ctx.scene.mechanism();
    let (r, e) = (m.crank(), m.offset());
    if canvas.page(e.abs()) < 4.0 {
        return;
    }
    let reach = ctx.sizes.fitted.unwrap_or_else(|| super::fit::frame(ctx));
    let beyond = r.max(-reach.min().x);
    // The extension lines start past what stands about the crank centre
    // on that side: its letter, and the torque arrow about it where one
    // is drawn (at l = 3.77 r, e = −1.56 r, 90.04° the line from the
    // centre struck through O's letter and crossed the arc). They stay
    // within the crank circle's reach, so that each keeps a length.
    let torque = ctx.scene.has(crate::scene::Layer::Torque) && !canvas.is_bare(Point::origin());
    let crowded = match torque {
        true => super::torque::TORQUE_REACH,
        false => CENTRE_ROOM,
    };
    let start = canvas.world(crowded).min(beyond);
    canvas.push(
        "dimension-e",
        Role::Dimension,
        Shape::Dimension {
            from: Point::new(-start, 0.0),
            to: Point::new(-start, e),
            side: Vector::new(-1.0, 0.0),
            offset: canvas.page(beyond - start) + 18.0,
            text: RichText::italic("e"),
        },
    );
}
