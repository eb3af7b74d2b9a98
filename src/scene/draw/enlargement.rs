//! The enlargement of the acceleration polygon's crowded end: near 90°
//! at a long rod the crank pin's ω²r and the rod's tangential component
//! are nearly equal and opposite, the polygon folds onto one line and
//! the piston's acceleration c′a′ closing it is a few units long; at the
//! dead centres the normal component b′x, the closing side and the image
//! q′ end within a few units of each other. Their arrowheads stack and
//! the reader cannot tell which line carries which. As a book does for a
//! short side, the region about the points that crowd is boxed on the
//! polygon and drawn again beside it, enlarged a round number of times:
//! there the heads stand apart on their own lines, each point lettered.
//! (Drawing the collinear vectors side by side instead would put them
//! off the points they join and mislead the measure the polygon is read
//! by.)

use crate::figure::{Align, RichText, Role, Shape, TextSize};
use crate::geom::{Frame, Point, Vector};
use crate::number::short;
use crate::scene::canvas::Canvas;

/// Page distance within which two points of the polygon crowd: their
/// letters (about 12 × 17 units) and arrowheads (about 10 long) cannot
/// both stand clear.
pub(crate) const CROWD: f64 = 24.0;

/// Page distance under which points that crowd are one point for every
/// magnification worth drawing (b′ and x near 90° at a long rod, 1e-3
/// units apart and less): no enlargement for them. c′ and a′ at 89° on a
/// rod of 60 cranks stand 0.12 units apart, enlarged ×500.
pub(crate) const DISTINCT: f64 = 0.05;

/// The crowd's extent in the enlargement, at least, in shares of the
/// box's width.
const TARGET: f64 = 0.5;

/// Room between the polygons' outermost point and the enlargement's box,
/// page units: a letter group beside that point ("*b*′, *x*").
const AWAY: f64 = 70.0;

/// The least side of the box marking the enlarged region on the polygon,
/// page units.
const BOX_LEAST: f64 = 16.0;

/// Room between the enlargement and its caption below it, page units.
const CAPTION_DROP: f64 = 20.0;

/// What the fit keeps below the enlargement for its caption, page units.
pub(crate) const CAPTION_ROOM: f64 = CAPTION_DROP + 12.0;

/// The least magnification worth a box: less, the crowd is some 30 units
/// across and reads on the polygon (a small polygon on a narrow page).
const LEAST: f64 = 4.0;

/// The magnifications offered: round steps times a power of ten.
const STEPS: [f64; 7] = [1.0, 2.0, 2.5, 3.0, 4.0, 5.0, 8.0];

/// The enlargement: the world region about the crowd, the box it is
/// drawn in (world, beside the polygons), the magnification, and what
/// the box stands beside.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Enlargement {
    pub region: Frame,
    pub frame: Frame,
    pub magnification: f64,
    /// What the box stands beside: the polygons and their captions.
    pub beside: Frame,
}

impl Enlargement {
    /// Where the world point `p` of the region is drawn in the box.
    pub(crate) fn map(&self, p: Point) -> Point {
        let (r, f) = (self.region, self.frame);
        let rc = Point::from((r.min().coords + r.max().coords) * 0.5);
        let fc = Point::from((f.min().coords + f.max().coords) * 0.5);
        fc + (p - rc) * self.magnification
    }
}

/// The largest round step not above `x` (at least 1, `x` positive).
fn round_below(x: f64) -> f64 {
    let decade = 10f64.powf(x.log10().floor());
    STEPS
        .iter()
        .map(|s| s * decade)
        .filter(|s| *s <= x * (1.0 + 1e-12))
        .fold(decade, f64::max)
        .max(1.0)
}

/// The groups of `points` within [`CROWD`] page units of each other (at
/// `scale` page units per world unit), each as the corners of its box.
fn crowds(points: &[Point], scale: f64) -> Vec<(Point, Point)> {
    let mut left: Vec<Point> = points.to_vec();
    let mut out = Vec::new();
    while !left.is_empty() {
        let first = left.remove(0);
        let mut group = vec![first];
        while let Some(j) = left
            .iter()
            .position(|p| (group.iter()).any(|g| (g - p).norm() * scale < CROWD))
        {
            group.push(left.remove(j));
        }
        let lo = group.iter().fold(first, |m, p| m.inf(p));
        let hi = group.iter().fold(first, |m, p| m.sup(p));
        out.push((lo, hi));
    }
    out
}

/// The enlargement the acceleration polygon's `points` need at `scale`,
/// in a box `room` (world) beside `polygons` (the box of both polygons
/// and of any caption wider than them, world) on the page's right (world
/// x to the left where `mirrored`), its top no higher than theirs: the
/// crowd of largest extent among those whose points stand apart,
/// enlarged to half the box's width or less by a round step, if any.
pub(crate) fn enlargement(
    points: &[Point],
    scale: f64,
    polygons: Frame,
    mirrored: bool,
    room: Vector,
) -> Option<Enlargement> {
    let (lo, hi) = crowds(points, scale)
        .into_iter()
        .filter(|(lo, hi)| (hi - lo).norm() * scale >= DISTINCT)
        .max_by(|a, b| (a.1 - a.0).norm().total_cmp(&(b.1 - b.0).norm()))?;
    let size = hi - lo;
    let magnification = round_below(TARGET * room.x / size.x.max(size.y));
    if magnification < LEAST {
        return None;
    }
    let half = room * (0.5 / magnification);
    let centre = Point::from((lo.coords + hi.coords) * 0.5);
    let region = Frame::new(centre - half, centre + half);
    let away = AWAY / scale;
    let x0 = if mirrored {
        polygons.min().x - away - room.x
    } else {
        polygons.max().x + away
    };
    let y1 = (centre.y + 0.5 * room.y).min(polygons.max().y);
    let frame = Frame::new(Point::new(x0, y1 - room.y), Point::new(x0 + room.x, y1));
    Some(Enlargement {
        region,
        frame,
        magnification,
        beside: polygons,
    })
}

/// Draws the enlargement: the region boxed on the polygon, the box, the
/// polygon's `vectors` (id, role, from, to, whether an arrow) mapped into
/// it and clipped at its edge (an arrow where its head is inside), its
/// `letters` (id, markup, point) inside lettered, and the caption.
pub(crate) fn draw(
    canvas: &mut Canvas,
    e: &Enlargement,
    vectors: &[(String, Role, Point, Point, bool)],
    letters: &[(String, String, Point)],
) {
    let least = canvas.world(BOX_LEAST);
    let size = e.region.max() - e.region.min();
    let grow = Vector::new((least - size.x).max(0.0), (least - size.y).max(0.0)) * 0.5;
    rectangle(
        canvas,
        "acceleration-enlarged-region",
        Frame::new(e.region.min() - grow, e.region.max() + grow),
    );
    rectangle(canvas, "acceleration-enlargement", e.frame);
    for (id, role, from, to, arrow) in vectors {
        let (p, q) = (e.map(*from), e.map(*to));
        let Some((tail, head)) = e.frame.clip_segment(p, q) else {
            continue;
        };
        if canvas.page((head - tail).norm()) < 0.5 {
            continue;
        }
        let id = format!("enlarged-{id}");
        let headed = *arrow && e.frame.contains(q) && canvas.page((q - tail).norm()) >= 12.0;
        if headed {
            canvas.push(id, *role, Shape::Arrow { from: tail, to: q });
        } else {
            canvas.push(
                id,
                *role,
                Shape::Polyline {
                    points: vec![tail, head],
                    closed: false,
                },
            );
        }
    }
    let inside: Vec<(String, String, Point)> = (letters.iter())
        .map(|(id, markup, p)| (format!("enlarged-{id}"), markup.clone(), e.map(*p)))
        .filter(|(_, _, p)| e.frame.contains(*p))
        .collect();
    let inside: Vec<(&str, &str, Point)> = (inside.iter())
        .map(|(id, markup, p)| (id.as_str(), markup.as_str(), *p))
        .collect();
    let pole = e.map(letters.first().map_or(Point::origin(), |l| l.2));
    canvas.letter_crowded(&inside, super::COINCIDE, pole, None);
    let at = Point::new(0.5 * (e.frame.min().x + e.frame.max().x), e.frame.min().y);
    canvas.push(
        "caption-acceleration-enlargement",
        Role::Label,
        Shape::Text {
            at,
            offset: Vector::new(0.0, CAPTION_DROP),
            text: RichText::parse(&format!(
                "the boxed end enlarged ×{}",
                short(e.magnification)
            )),
            align: Align::Middle,
            size: TextSize::Small,
        },
    );
}

/// A closed rectangle `id` round `f`, thin.
fn rectangle(canvas: &mut Canvas, id: &str, f: Frame) {
    let (lo, hi) = (f.min(), f.max());
    canvas.push(
        id,
        Role::Auxiliary,
        Shape::Polyline {
            points: vec![lo, Point::new(hi.x, lo.y), hi, Point::new(lo.x, hi.y)],
            closed: true,
        },
    );
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A box 180 by 130.
    const ROOM: Vector = Vector::new(180.0, 130.0);

    #[test]
    fn points_apart_get_no_enlargement_and_a_crowd_of_distinct_points_does() {
        let around = Frame::new(Point::new(0.0, -10.0), Point::new(10.0, 0.0));
        // At 1 page unit per unit: 30 apart, none crowds.
        let apart = [Point::new(0.0, 0.0), Point::new(30.0, 0.0)];
        assert_eq!(enlargement(&apart, 1.0, around, false, ROOM), None);
        // b′ and x near 90°: 1e-5 apart, one point at any magnification.
        let one = [Point::new(0.0, 0.0), Point::new(1e-5, 0.0)];
        assert_eq!(enlargement(&one, 1.0, around, false, ROOM), None);
        // c′ and a′ 5 apart: ×18 would draw them 90 apart (half the box);
        // the round step below 18 is 10. 30 apart in a chain of three, ×3:
        // none.
        let folded = [
            Point::new(0.0, 0.0),
            Point::new(5.0, 0.0),
            Point::new(0.0, -200.0),
        ];
        let e = enlargement(&folded, 1.0, around, false, ROOM).unwrap();
        assert_eq!(e.magnification, 10.0);
        // The region's middle is drawn at the box's middle, 10 times apart.
        let (p, q) = (e.map(folded[0]), e.map(folded[1]));
        assert!(((q - p).norm() - 50.0).abs() < 1e-9);
        // The box beside the polygons, AWAY to their right.
        assert!((e.frame.min().x - (10.0 + AWAY)).abs() < 1e-9);
        assert!(e.frame.max().y <= 0.0);
        let chain = [
            Point::new(0.0, 0.0),
            Point::new(15.0, 0.0),
            Point::new(30.0, 0.0),
        ];
        assert_eq!(enlargement(&chain, 1.0, around, false, ROOM), None);
    }
}
