//! A polygon's panel and its enlarged detail: the vectors as arrows, the
//! points lettered (those that coincide by one letter), the scale bar,
//! the right angles, and the box round the region a detail enlarges.

use super::super::{Ctx, short};
use super::polygons::{Arrow, Lettered, Polygons, Subject};
use super::{HEADLESS, MIN_ARROW, STEPS, round_below};

use crate::chain::Inversion;
use crate::diagram::Plot;
use crate::error::Result;
use crate::figure::{Hue, RIGHT_ANGLE, RichText, Role, Shape};
use crate::geom::{Frame, Point, Vector, side_by_side};
use crate::scene::{COINCIDE, Canvas, Marker};
use serde_json::Value;

/// Room kept about a polygon for its letters and its bar, in shares of
/// its largest extent.
pub(super) const PAD: f64 = 0.16;

/// The page length under which a polygon's subject (the sliding velocity,
/// the Coriolis component) in its panel gets an enlarged detail: at a
/// long rod the driven point's velocity and acceleration make the polygon
/// a needle and the subject a few units at its tip.
pub(super) const SUBJECT_LEAST: f64 = 40.0;

/// The most the subject is drawn in its detail, page units.
pub(super) const SUBJECT_MOST: f64 = 200.0;

/// The least the subject is drawn in a detail that holds its crowd whole,
/// page units: a plain side (longer than [`MIN_ARROW`]) with a letter at
/// either end. Where the crowd is whole only with the subject shorter,
/// the detail draws the subject at twice [`SUBJECT_LEAST`] and the far
/// points run off its edge; where it fits at this or more, the crowd is
/// whole (inversion 3 at l = 26 r, 89.9°: a′_d, 13 times the Coriolis
/// component from k and folded onto o′ in the polygon, stood off a ×2500
/// detail that drew o′k 80 units; whole at ×500, o′k is 11 units, the
/// magnification rounded down to a round step).
pub(super) const SUBJECT_WHOLE: f64 = 16.0;

/// Room kept in a detail between its frame and the points it enlarges,
/// page units (their letters).
pub(super) const DETAIL_PAD: f64 = 40.0;

/// Page distance within which a point of a polygon crowds the subject of
/// its detail (or another point so crowding): the detail takes it in.
pub(super) const CROWD: f64 = 24.0;

/// The shortest piece of a side a detail draws, page units.
const DETAIL_LEAST: f64 = 0.5;

/// The least side of the box marking a detail's region on the polygon,
/// page units.
pub(super) const BOX_LEAST: f64 = 16.0;

/// A polygon as its panels draw it.
pub(super) struct Drawn<'a> {
    pub(super) name: &'a str,
    pub(super) caption: &'a str,
    pub(super) points: Vec<Lettered>,
    pub(super) arrows: Vec<Arrow>,
    pub(super) hue: Hue,
    pub(super) per: &'a str,
    pub(super) subject: Option<Subject>,
}

/// The region of a polygon its detail enlarges (world, from the pole)
/// and the magnification over the polygon's panel.
#[derive(Debug, Clone, Copy)]
pub(super) struct Window {
    pub(super) frame: Frame,
    pub(super) magnification: f64,
}

/// The scale bar's line below a polygon's lowest point, in shares of
/// its largest extent: clear of the lowest point's letter (the pole's,
/// set beside or below it), the bar's length written below the line.
pub(super) const BAR_DROP: f64 = 0.16;

/// Room below the bar's line for its length, in shares of the polygon's
/// largest extent.
const BAR_ROOM: f64 = 0.1;

/// The least drop of the bar's line below the lowest point, page units:
/// a letter set below the point (4 units off, 17 tall, a subscript
/// below) and the bar's heads (3.2 units either side of its line). On a
/// narrow page [`BAR_DROP`] of the polygon's extent is less: at 4.5 in,
/// l = 57 r, 90.9° inversion 3's bar ran under "a′_d, o′".
const BAR_LETTERS: f64 = 34.0;

/// The world frame of `points` (from the pole), grown by [`PAD`] of its
/// largest extent each way but below, where it holds the bar
/// ([`BAR_DROP`] below the lowest point) and its length; a frame
/// thinner than half its width is made that tall above, so that a
/// polygon folded onto a line keeps room for its letters and the bar
/// stays by it; the bar at least `least` (world) below the lowest point.
/// Returns the frame, the extent and the bar's height.
pub(super) fn polygon_frame(points: &[Lettered], least: f64) -> (Frame, f64, f64) {
    let lo = points.iter().fold(Vector::zeros(), |m, p| m.inf(&p.2));
    let hi = points.iter().fold(Vector::zeros(), |m, p| m.sup(&p.2));
    let size = hi - lo;
    let extent = size.x.max(size.y);
    let pad = PAD * extent;
    let grow = (0.5 * extent - size.y).max(0.0);
    let bar = lo.y - (BAR_DROP * extent).max(least);
    let min = Point::new(lo.x - pad, bar - BAR_ROOM * extent);
    let max = Point::from(hi) + Vector::new(pad, pad + grow);
    (Frame::new(min, max), extent, bar)
}

/// A polygon's panel: its vectors as arrows (those long enough to carry
/// a head), its points lettered (those that crowd by one letter), a
/// scale bar of a round length below, and what `more` adds; where its
/// subject is drawn shorter than [`SUBJECT_LEAST`], the region about it
/// is boxed and left to a detail of `detail` page units (its points are
/// lettered there). Returns the plot, the bar's length, the points'
/// places (from the pole, in velocity or acceleration units) and the
/// detail's window.
pub(super) fn polygon_plot(
    ctx: &Ctx,
    rect: Frame,
    drawn: &Drawn,
    detail: (f64, f64),
    more: &impl Fn(&mut Canvas),
) -> Result<(Plot, f64, Value, Option<Window>)> {
    let (mut world, extent, mut y) = polygon_frame(&drawn.points, 0.0);
    let mut plot = Plot::world(drawn.name, rect, &world, false, ctx.tolerance, ctx.font)?
        .with_caption(drawn.caption);
    // Framed again where the bar would stand among the lowest point's
    // letters, with room for them (a tenth more, for the taller frame's
    // smaller scale).
    let least = 1.1 * BAR_LETTERS / plot.map().scale();
    if least > BAR_DROP * extent {
        (world, _, y) = polygon_frame(&drawn.points, least);
        plot = Plot::world(drawn.name, rect, &world, false, ctx.tolerance, ctx.font)?
            .with_caption(drawn.caption);
    }
    let map = *plot.map();
    let window = drawn
        .subject
        .and_then(|side| window(&drawn.points, side, closing(drawn), map.scale(), detail));
    let mut s = Canvas::new(map, map.world_frame(&plot.area()));
    if let Some(w) = window {
        s = s.quiet(w.frame);
    }
    let old = s.set_hue(Some(drawn.hue));
    let offsets = apart(&s, drawn, MIN_ARROW);
    for ((id, role, from, to), off) in drawn.arrows.iter().zip(offsets) {
        let (from, to) = (Point::from(*from) + off, Point::from(*to) + off);
        let length = s.page((to - from).norm());
        if length >= HEADLESS {
            s.push(*id, *role, Shape::Arrow { from, to });
        } else if length >= MIN_ARROW {
            s.segment(*id, *role, from, to);
        } else {
            continue;
        }
        ticks(&mut s, id, (from, to), off, window.map(|w| w.frame));
    }
    more(&mut s);
    s.set_hue(old);
    if let Some(w) = window {
        mark_window(&mut s, drawn.name, &w.frame);
    }
    letter(&mut s, &drawn.points, window.map(|w| w.frame));
    let bar = round_below(0.45 * extent, &STEPS);
    let x = world.min().x + PAD * extent * 0.5;
    let unit = format!("{}{}", ctx.unit(), drawn.per);
    s.push(
        format!("{}-bar", drawn.name),
        Role::Dimension,
        Shape::Dimension {
            from: Point::new(x, y),
            to: Point::new(x + bar, y),
            side: Vector::new(0.0, -1.0),
            offset: 0.0,
            text: RichText::parse(&format!("{} {unit}", short(bar))),
        },
    );
    let (items, points) = s.finish();
    for item in items {
        plot.push(item);
    }
    Ok((plot, bar, Value::Object(points), window))
}

/// Where a polygon closes: the end of its result (a′_d), if it has one.
fn closing(drawn: &Drawn) -> Option<Vector> {
    (drawn.arrows.iter())
        .find(|a| a.1 == Role::Result)
        .map(|a| a.3)
}

/// The region a polygon's detail enlarges, where its subject `side` is
/// drawn shorter than [`SUBJECT_LEAST`] at `scale` (page units per unit):
/// the points crowding about the subject (within [`CROWD`] of it or of
/// each other) whole where they fit the detail's `area` with the subject
/// at most [`SUBJECT_MOST`] and at least [`SUBJECT_WHOLE`], else the
/// subject at twice [`SUBJECT_LEAST`] about its middle (the long sides
/// run off the detail's edge), but where the crowd holds the point the
/// polygon closes at (`closing`): that is never left off the detail,
/// the subject drawn as short as it then is (inversion 3 at l = 45.6 r,
/// 89.62°: o′k, 0.2 ft/s² against a sliding acceleration of 4.5, drawn
/// 80 units at ×1000 with a′_d far off the detail's edge; now whole at
/// ×50); the magnification a round step. `None` where the subject reads
/// in the polygon itself.
pub(super) fn window(
    points: &[Lettered],
    side: Subject,
    closing: Option<Vector>,
    scale: f64,
    area: (f64, f64),
) -> Option<Window> {
    let length = (side.1 - side.0).norm();
    if length <= 0.0 || !length.is_finite() {
        return None;
    }
    if length * scale >= SUBJECT_LEAST {
        return crowd_window(points, side, closing, scale, area);
    }
    let about = |start: &[Vector]| window_about(points, side, start, (closing, scale, area));
    // The point the polygon closes at, where another stands within
    // [`CROWD`] of it (not lettered with it, [`COINCIDE`]): its letter
    // finds no room by its dot among the sides there and is read in the
    // detail with the subject (inversion 2 at l = 1.85 r, e = −0.65 r,
    // 0°: a′_d, 12 units above n, the tangential component too short to
    // draw, lettered across o′a′ 15 units from its dot), where the detail
    // then still enlarges at least [`CROWD_ENLARGED`] times (on a page
    // 500 wide it enlarged it once, the box round the whole polygon).
    crowded_closing(points, side, closing, scale)
        .map(|(c, _)| about(&[side.0, side.1, c]))
        .filter(|w| w.magnification >= CROWD_ENLARGED)
        .or_else(|| Some(about(&[side.0, side.1])))
}

/// Where the subject `side` reads in the polygon: the detail of the
/// point the polygon closes at (`closing`) and the nearest point that
/// crowds it (within [`CROWD`], not lettered with it, [`COINCIDE`]),
/// enlarged about the two ([`window_about`], the short side between them
/// its subject) at least [`CROWD_ENLARGED`] times; `None` where no point
/// crowds it. Inversion 2 at l = 2.8 r, e = 1.22 r, 0°: a′_d stood 9
/// units below n (the tangential component too short to draw), o′a′ 10
/// units below it and k a′_d to its left, and its letter found room
/// only across o′a′, 35 units below its dot.
fn crowd_window(
    points: &[Lettered],
    side: Subject,
    closing: Option<Vector>,
    scale: f64,
    area: (f64, f64),
) -> Option<Window> {
    let (c, near) = crowded_closing(points, side, closing, scale)?;
    let w = window_about(points, (near, c), &[near, c], (closing, scale, area));
    (w.magnification >= CROWD_ENLARGED).then_some(w)
}

/// The point the polygon closes at (`closing`), where it is not an end
/// of the subject `side`, and the point of `points` nearest it that
/// crowds it ([`crowder`]); `None` where none does.
fn crowded_closing(
    points: &[Lettered],
    side: Subject,
    closing: Option<Vector>,
    scale: f64,
) -> Option<(Vector, Vector)> {
    let c = closing.filter(|c| *c != side.0 && *c != side.1)?;
    Some((c, crowder(points, c, scale)?))
}

/// The point of `points` nearest `c` that crowds it on the page at
/// `scale`: within [`CROWD`] of it but not lettered with it
/// ([`COINCIDE`]); `None` where none does.
fn crowder(points: &[Lettered], c: Vector, scale: f64) -> Option<Vector> {
    let apart = |p: &Vector| (p - c).norm() * scale;
    (points.iter())
        .map(|p| p.2)
        .filter(|p| (COINCIDE..CROWD).contains(&apart(p)))
        .min_by(|p, q| apart(p).total_cmp(&apart(q)))
}

/// The least magnification of a detail that takes in the crowded point
/// the polygon closes at besides its subject ([`window`]).
const CROWD_ENLARGED: f64 = 2.0;

/// [`window`] about the points `start` (the subject's ends, and the
/// point the polygon closes at where it is crowded) and those crowding
/// them; `closing`, `scale` and `area` as there.
fn window_about(
    points: &[Lettered],
    side: Subject,
    start: &[Vector],
    (closing, scale, area): (Option<Vector>, f64, (f64, f64)),
) -> Window {
    let length = (side.1 - side.0).norm();
    let mut crowd = start.to_vec();
    loop {
        let near = points
            .iter()
            .map(|p| p.2)
            .find(|p| !crowd.contains(p) && crowd.iter().any(|c| (c - p).norm() * scale < CROWD));
        match near {
            Some(p) => crowd.push(p),
            None => break,
        }
    }
    let lo = crowd.iter().fold(side.0, |m, p| m.inf(p));
    let hi = crowd.iter().fold(side.0, |m, p| m.sup(p));
    let size = hi - lo;
    let room = (area.0 - 2.0 * DETAIL_PAD, area.1 - 2.0 * DETAIL_PAD);
    let fit = (room.0 / size.x).min(room.1 / size.y);
    let whole = fit.min(SUBJECT_MOST / length);
    let closes = closing.is_some_and(|c| crowd.contains(&c));
    let wanted = if closes || whole * length >= SUBJECT_WHOLE {
        whole
    } else {
        2.0 * SUBJECT_LEAST / length
    };
    let magnification = round_below(wanted / scale, &STEPS).max(1.0);
    let detail = magnification * scale;
    let centre = if detail <= fit * (1.0 + 1e-9) {
        (lo + hi) * 0.5
    } else {
        (side.0 + side.1) * 0.5
    };
    let half = Vector::new(area.0, area.1) * (0.5 / detail);
    let frame = Frame::new(Point::from(centre - half), Point::from(centre + half));
    Window {
        frame,
        magnification,
    }
}

/// The box on a polygon marking the region its detail enlarges (at
/// least [`BOX_LEAST`] a side).
pub(in crate::catalogue::builders) fn mark_window(s: &mut Canvas, name: &str, frame: &Frame) {
    let least = s.world(BOX_LEAST);
    let size = frame.max() - frame.min();
    let grow = Vector::new((least - size.x).max(0.0), (least - size.y).max(0.0)) * 0.5;
    let seen = *s.frame();
    let lo = (frame.min() - grow).sup(&seen.min());
    let hi = (frame.max() + grow).inf(&seen.max());
    s.push(
        format!("{name}-detail-box"),
        Role::Auxiliary,
        Shape::Polyline {
            points: vec![lo, Point::new(hi.x, lo.y), hi, Point::new(lo.x, hi.y)],
            closed: true,
        },
    );
}

/// Letters the polygon's `points`, those that coincide on the page
/// (within [`COINCIDE`]) by one letter, those in the region left to a
/// detail (`quiet`) not here but the pole (the first point): the polygon
/// is read from it, and a box with no letter at its start leaves the
/// reader to guess where the polygon begins (inversion 3 near 90° at a
/// long rod, where o′ and k lie within a few units of each other).
pub(super) fn letter(s: &mut Canvas, points: &[Lettered], quiet: Option<Frame>) {
    let points: Vec<(&str, &str, Point)> = (points.iter())
        .map(|(id, markup, at)| (*id, *markup, Point::from(*at)))
        .collect();
    let Some((first, rest)) = points.split_first() else {
        return;
    };
    let held = |p: Point| quiet.is_some_and(|f| f.contains(p));
    if !held(first.2) {
        s.letter_crowded(&points, COINCIDE, Point::origin(), quiet);
        return;
    }
    // The pole held: lettered with the points outside the region, last,
    // so that one of them within reach names it too ("a′_d, o′"), else
    // by its own letter; the others held recorded for the detail.
    let mut shown: Vec<(&str, &str, Point)> = rest.iter().copied().filter(|p| !held(p.2)).collect();
    shown.push(*first);
    for p in rest.iter().filter(|p| held(p.2)) {
        s.record(p.0, p.2);
    }
    let joined = (rest.iter())
        .any(|p| !held(p.2) && s.contains(p.2) && s.page((p.2 - first.2).norm()) < COINCIDE);
    s.letter_crowded(&shown, COINCIDE, Point::origin(), None);
    if !joined {
        s.lettered(first.0, first.2, first.1, Marker::Dot, first.2);
    }
}

/// The detail of a polygon: the region of `window` enlarged in `rect`,
/// its sides clipped at the edge (an arrowhead where the side ends
/// inside), its points there lettered, captioned with the
/// magnification.
pub(super) fn detail_plot(
    ctx: &Ctx,
    rect: Frame,
    drawn: &Drawn,
    window: &Window,
    more: &impl Fn(&mut Canvas),
) -> Result<Plot> {
    let name = format!("{}-detail", drawn.name);
    let caption = format!(
        "{}: the boxed region enlarged ×{}",
        drawn.caption,
        short(window.magnification)
    );
    let mut plot = Plot::world(&name, rect, &window.frame, false, ctx.tolerance, ctx.font)?
        .with_caption(&caption);
    let map = *plot.map();
    let mut s = Canvas::new(map, map.world_frame(&plot.area())).detail("detail-");
    let old = s.set_hue(Some(drawn.hue));
    let offsets = apart(&s, drawn, DETAIL_LEAST);
    for ((id, role, from, to), off) in drawn.arrows.iter().zip(offsets) {
        let (from, to) = (Point::from(*from) + off, Point::from(*to) + off);
        // The piece inside the frame; a side that misses it has none (the
        // clip of its line lies beyond its ends).
        let inside = s.frame().clip_segment(from, to).filter(|(p, q)| {
            let middle = Point::from((p.coords + q.coords) * 0.5);
            s.contains(middle) && s.page((q - p).norm()) >= DETAIL_LEAST
        });
        let Some((tail, head)) = inside else {
            continue;
        };
        let role = *role;
        if s.contains(to) && s.page((to - tail).norm()) >= HEADLESS {
            s.push(*id, role, Shape::Arrow { from: tail, to });
        } else {
            s.segment(*id, role, tail, head);
        }
        ticks(&mut s, id, (from, to), off, None);
    }
    more(&mut s);
    s.set_hue(old);
    letter(&mut s, &drawn.points, None);
    for item in s.finish().0 {
        plot.push(item);
    }
    Ok(plot)
}

/// Page distance between two sides of a polygon that lie on one line,
/// drawn side by side: more than a head's width (6.4 units), so that
/// each arrow and its head are seen on their own.
pub(super) const SIDE_APART: f64 = 7.0;

/// The offsets (world) that set each of a polygon's arrows drawn on `s`
/// clear of those it would run over ([`side_by_side`]), each side taken
/// as the piece of it `s` shows (a detail's sides clipped at its frame:
/// at l = 49.8 r, 90.89° inversion 2's o′a′ and o′n, one line far below
/// the ×25 detail, were set apart there though a′ and n stand 85 units
/// apart in it, o′a′'s head stopping 7 units beside a′), those drawn
/// shorter than `least` page units counted as points (a panel draws none
/// shorter than [`MIN_ARROW`], a detail down to [`DETAIL_LEAST`]: at
/// l = 26 r, 89.9° inversion 3's o′k, 11.4 units at ×500, lay along
/// o′c′): the result (the heavier side) keeps its place, then the
/// subject (the Coriolis component, its head on its point), the others
/// set beside them in their order (inversion 2 at l = 1.06 r, 180°: o′n,
/// a′_d k and o′a′_d on one line read as one line with a head at either
/// end). A side the frame misses counts as a point.
fn apart(s: &Canvas, drawn: &Drawn, least: f64) -> Vec<Vector> {
    // A side whose line runs through a point of the polygon between its
    // ends (not the result) is set beside the others rather than they
    // beside it: on the line, it would run through that point's dot
    // (inversion 2 at l = 45.1 r, 90.25°: the Coriolis component k a′
    // through n and its right angle, the tangential component n a′_d
    // along it set beside, touching neither of its dots).
    let rank = |a: &Arrow| {
        if a.1 == Role::Result {
            0
        } else if passes_point(s, (a.2, a.3), drawn) {
            3
        } else if drawn.subject == Some((a.2, a.3)) {
            1
        } else {
            2
        }
    };
    let mut order: Vec<(usize, &Arrow)> = drawn.arrows.iter().enumerate().collect();
    order.sort_by_key(|(_, a)| rank(a));
    let sides: Vec<(Point, Point)> = (order.iter())
        .map(|(_, (_, _, from, to))| {
            let (from, to) = (Point::from(*from), Point::from(*to));
            match s.frame().clip_segment(from, to) {
                Some((p, q)) if s.page((q - p).norm()) >= least => (p, q),
                _ => (from, from),
            }
        })
        .collect();
    let mut offsets = vec![Vector::zeros(); drawn.arrows.len()];
    for ((i, _), o) in order
        .into_iter()
        .zip(side_by_side(&sides, s.world(SIDE_APART)))
    {
        if let Some(slot) = offsets.get_mut(i) {
            *slot = o;
        }
    }
    // On the polygon's own panel only: its detail keeps the heads on the
    // points they end at where it can (the ninth review read a′ set
    // beside as the polygon not closing); a side set beside there is
    // joined to its points by ticks ([`ticks`]).
    if least == MIN_ARROW {
        for (i, (_, _, from, to)) in drawn.arrows.iter().enumerate() {
            if let Some(off) = offsets.get_mut(i).filter(|o| o.norm() == 0.0) {
                *off = clear_of_points(s, (*from, *to), drawn);
            }
        }
    } else {
        in_place_unless_on_a_line(s, drawn, &mut offsets);
    }
    offsets
}

/// In a detail, each side set beside its place farther than
/// [`TICK_MOST`] (no tick joins it to its dots) drawn at its place
/// instead, where there it lies on no other side's line (an end of it
/// stands farther than [`ON_LINE`] from the line of every other side):
/// it then runs dot to dot, leaving the sides it meets at a narrow
/// angle. Set twice [`SIDE_APART`] beside o′a′_d, inversion 3's k a′_d
/// at l = 26.3 r, 270.7° (o′ and k 8 units apart at ×50) touched
/// neither k nor a′_d and read as a vector of its own. Sides on one
/// line keep their places beside one another.
fn in_place_unless_on_a_line(s: &Canvas, drawn: &Drawn, offsets: &mut [Vector]) {
    let most = s.world(TICK_MOST);
    let on = s.world(ON_LINE);
    let lines: Vec<(Point, Vector)> = (drawn.arrows.iter())
        .map(|(_, _, from, to)| (Point::from(*from), to - from))
        .collect();
    for (i, off) in offsets.iter_mut().enumerate() {
        let Some((from, side)) = lines.get(i).copied() else {
            continue;
        };
        if off.norm() <= most || side.norm() <= 0.0 {
            continue;
        }
        let to = from + side;
        let off_line =
            |p: Point, (a, u): (Point, Vector)| crate::geom::cross(&u, &(p - a)).abs() / u.norm();
        let on_a_line = (lines.iter().enumerate())
            .filter(|(j, (_, u))| *j != i && u.norm() > 0.0)
            .any(|(_, l)| off_line(from, *l) <= on && off_line(to, *l) <= on);
        if !on_a_line {
            *off = Vector::zeros();
        }
    }
}

/// Whether the side `from`→`to` of a polygon drawn on `s` runs through a
/// point of it (`drawn`) that is not its end: within [`ON_LINE`] of its
/// line, farther than [`SIDE_APART`] along it from either end, inside
/// the frame. Every such point counts, those ending a side along it too
/// (unlike [`clear_of_points`]): they are what [`apart`] sets it beside.
fn passes_point(s: &Canvas, (from, to): (Vector, Vector), drawn: &Drawn) -> bool {
    let side = to - from;
    let length = side.norm();
    if length.is_nan() || length <= 0.0 || s.page(length) < 2.0 * SIDE_APART {
        return false;
    }
    let u = side / length;
    let across = Vector::new(-u.y, u.x);
    let (on, end) = (s.world(ON_LINE), s.world(SIDE_APART));
    (drawn.points.iter()).any(|(_, _, p)| {
        let along = (p - from).dot(&u);
        s.contains(Point::from(*p))
            && along > end
            && along < length - end
            && (p - from).dot(&across).abs() < on
    })
}

/// The ticks that join a side set `off` (world) beside its place, drawn
/// from `from` to `to` there, to the dots of its ends, each end whose dot
/// `s` shows (not one in the region `quiet` left to a detail, which
/// draws the dot: a tick to no dot, inversion 2 at l = 1.85 r,
/// e = −0.65 r, 0°): a side set beside with nothing to its dots read as a vector
/// of its own (inversion 2 at l = 45.1 r, 90.25°: n a′_d beside k a′,
/// touching neither n nor a′_d). Ids `{id}-tick-tail`, `{id}-tick-head`.
/// None for a side set farther than [`TICK_MOST`]: three sides leaving
/// the pole on one line, the outer set twice [`SIDE_APART`] beside, drew
/// a tick 14 units across from o′ that read as a side of its own (l =
/// 45.1 r, 90.25°, the polygon's panel).
fn ticks(s: &mut Canvas, id: &str, (from, to): (Point, Point), off: Vector, quiet: Option<Frame>) {
    let apart = s.page(off.norm());
    if !(1.0..=TICK_MOST).contains(&apart) {
        return;
    }
    for (end, at) in [("tail", from), ("head", to)] {
        let dot = at - off;
        if s.contains(dot) && !quiet.is_some_and(|f| f.contains(dot)) {
            s.segment(format!("{id}-tick-{end}"), Role::Construction, dot, at);
        }
    }
}

/// The offset (world) that sets the side `from`→`to`, drawn on `s`, off
/// a point of the polygon (`points`) its line runs through between its
/// ends: [`SIDE_APART`] across it, away from the pole; none where it
/// passes none (inversion 2 at l = 2.84 r, e = -1.38 r, 89.44°: the
/// Coriolis component k a′ ran through n, o′n ending on it, and k n a′
/// read as two sides joined at n). A point within [`ON_LINE`] of the
/// line counts, not one within [`SIDE_APART`] of an end (a side's own
/// ends, and the dots crowding them, are lettered there), nor one that
/// ends a side along it.
fn clear_of_points(s: &Canvas, (from, to): (Vector, Vector), drawn: &Drawn) -> Vector {
    let side = to - from;
    let length = side.norm();
    if s.page(length) < 2.0 * SIDE_APART {
        return Vector::zeros();
    }
    let u = side / length;
    let across = Vector::new(-u.y, u.x);
    let (on, end) = (s.world(ON_LINE), s.world(SIDE_APART));
    // A point that ends a side along this one is [`side_by_side`]'s to
    // set apart (inversion 2 at l = 1.06 r, 180°: every side on one line).
    let along_it = |p: &Vector| {
        (drawn.arrows.iter()).any(|(_, _, a, b)| {
            (a == p || b == p) && (b - a).norm() > 0.0 && (b - a).normalize().perp(&u).abs() < 1e-6
        })
    };
    let passed = (drawn.points.iter()).find(|(_, _, p)| {
        let along = (p - from).dot(&u);
        (along > end && along < length - end) && (p - from).dot(&across).abs() < on && !along_it(p)
    });
    match passed {
        // The pole o′ is the origin: away from it.
        Some(_) => {
            let sign = if from.dot(&across) > 0.0 { 1.0 } else { -1.0 };
            across * sign * s.world(SIDE_APART)
        }
        None => Vector::zeros(),
    }
}

/// The farthest a side is set beside its place and still joined to its
/// dots by ticks ([`ticks`]), page units: once [`SIDE_APART`] and a
/// half.
const TICK_MOST: f64 = 1.5 * SIDE_APART + 0.01;

/// Page distance within which a polygon's point counts as lying on a
/// side's line ([`clear_of_points`]): a dot's radius and a stroke.
const ON_LINE: f64 = 3.0;

/// The right angles of the acceleration polygon: d's tangential component
/// against its normal one at n, the Coriolis component against the slot
/// at k, each where both arms are long enough on the page to hold it.
pub(super) fn right_angles(s: &mut Canvas, polygons: &Polygons) {
    let p = &polygons.p;
    let n = p.n();
    let k = polygons.k();
    let normal = polygons.normal_from() - n;
    let tangential = p.a_d_acceleration() - n;
    let coriolis = match polygons.inversion {
        Inversion::Rod => -p.coriolis(),
        _ => p.coriolis(),
    };
    let sliding = p.a_d_acceleration() - k;
    for (id, vertex, u, v) in [
        ("angle-n", n, normal, tangential),
        ("angle-k", k, coriolis, sliding),
    ] {
        let seen = s.contains(Point::from(vertex));
        if seen && s.page(u.norm()) >= 2.0 * RIGHT_ANGLE && s.page(v.norm()) >= 2.0 * RIGHT_ANGLE {
            s.push(
                id,
                Role::Construction,
                Shape::RightAngle {
                    vertex: Point::from(vertex),
                    u,
                    v,
                },
            );
        }
    }
}

/// The sides of a polygon drawn without a head (shorter on its panel at
/// `scale` page units per unit than [`HEADLESS`], at least [`MIN_ARROW`])
/// and not drawn with one in its detail (`window`), each named by the
/// letters of its ends ("*c*′*n*"): the notes say they are too short for
/// one, their sense read from the letters at their ends (inversion 3 at
/// l = 1.54 r, e = −0.464 r, 0°: c′n and n a′_d, 15 units each, were
/// drawn as plain lines with no word why).
pub(super) fn headless(drawn: &Drawn, scale: f64, window: Option<Window>) -> Vec<String> {
    let letter = |at: Vector| {
        (drawn.points.iter())
            .find(|p| p.2 == at)
            .map_or("", |p| p.1)
    };
    (drawn.arrows.iter())
        .filter(|(_, _, from, to)| {
            let length = (to - from).norm() * scale;
            let in_detail = window.is_some_and(|w| {
                w.frame.contains(Point::from(*from))
                    && w.frame.contains(Point::from(*to))
                    && length * w.magnification >= HEADLESS
            });
            (MIN_ARROW..HEADLESS).contains(&length) && !in_detail
        })
        .map(|(_, _, from, to)| format!("{}{}", letter(*from), letter(*to)))
        .collect()
}

/// Two sides of a polygon on one line through a point they meet at: their
/// names and the point's letter ([`lined_up`]).
pub(super) type Lined = (String, String, String);

/// The sine of the angle within which two sides of a polygon leaving one
/// point the opposite ways read as one straight line (2°).
const ONE_LINE: f64 = 0.035;

/// The pairs of a polygon's sides drawn (at least [`MIN_ARROW`] long on
/// its panel at `scale` page units per unit, or in its detail `window`
/// where it reaches in) that meet at a point and run on from it the
/// opposite ways along one line ([`ONE_LINE`]), each named by the letters
/// of its ends, and the point's letter: they read as one side through
/// the point, and the notes tell them apart (inversion 3 at l = 1.04 r,
/// 269.87°: o′c′ and the Coriolis component o′k, one line through o′ in
/// the ×50 detail). Sides set beside one another are not such pairs:
/// they overlap, these only meet.
pub(super) fn lined_up(drawn: &Drawn, scale: f64, window: Option<Window>) -> Vec<Lined> {
    let letter = |at: Vector| {
        (drawn.points.iter())
            .find(|p| p.2 == at)
            .map_or("", |p| p.1)
    };
    let shown = |(from, to): (Vector, Vector)| {
        let length = (to - from).norm() * scale;
        length >= MIN_ARROW
            || window.is_some_and(|w| {
                length * w.magnification >= MIN_ARROW
                    && (w.frame.contains(Point::from(from)) || w.frame.contains(Point::from(to)))
            })
    };
    let sides: Vec<(Vector, Vector)> = (drawn.arrows.iter())
        .map(|a| (a.2, a.3))
        .filter(|s| shown(*s))
        .collect();
    let name = |(from, to): (Vector, Vector)| format!("{}{}", letter(from), letter(to));
    let mut pairs = Vec::new();
    for (i, p) in sides.iter().enumerate() {
        for q in sides.iter().skip(i + 1) {
            // The point they share, and each one's way from it.
            let ends = [(p.0, p.1), (p.1, p.0)];
            let shared = ends.iter().find_map(|(at, far)| {
                [(q.0, q.1), (q.1, q.0)]
                    .iter()
                    .find(|(other, _)| other == at)
                    .map(|(_, other_far)| (*at, far - at, other_far - at))
            });
            let Some((at, u, v)) = shared else { continue };
            let (u, v) = (u.normalize(), v.normalize());
            let pair = (name(*p), name(*q), letter(at).to_string());
            // Once each: sides whose ends coincide with other points are
            // named by the first point's letter, and two such pairs are
            // named alike (inversion 2 at l = 1.1 r, 0°).
            let named = (pairs.iter()).any(|(a, b, _): &Lined| {
                (*a == pair.0 && *b == pair.1) || (*a == pair.1 && *b == pair.0)
            });
            if u.dot(&v) < 0.0 && (u.x * v.y - u.y * v.x).abs() < ONE_LINE && !named {
                pairs.push(pair);
            }
        }
    }
    pairs
}
