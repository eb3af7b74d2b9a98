//! Marks on a construction: arrows, right-angle marks, angle marks and
//! dimensions, in page sizes whatever the scale.

use super::centre::Course;
use super::mark::{Mark, TextAnchor};
use super::markup::{arc_beziers, arrow_head, finite, path, polyline_d, unit};
use super::symbol_sizes::{ANGLE_STEP, ARROW_LENGTH, RIGHT_ANGLE};
use super::text::{starts_italic, text_half, text_node};
use super::{ALONG_ARC, Ink, PanelLayout, Pending};
use crate::figure::angle_radius;
use crate::figure::{Item, PageFromWorld, Pen, RichText, Role, Shape, TextSize};
use crate::geom::{Frame, Point, Vector};

/// Step by which a dimension's text slides along its line off a line
/// drawn through it, page units.
const SLIDE: f64 = 4.0;
/// The least clear length between a dimension's two heads drawn inside
/// its extension lines, page units; a shorter dimension has its heads
/// outside, pointing in. At 4 units the stroke of a long rod's engine
/// (27 units) had its two heads inside, merged into one black shape.
const HEADS_GAP: f64 = 12.0;
/// How far a dimension line runs on past an outside head, page units.
const LEADER: f64 = 6.0;
/// The first stretch of an extension line, from its point, on which a
/// letter may stand (a point's letter beside it, as A's beside the slider
/// on the line of stroke), page units: a slider block's half height and a
/// little more.
const EXTENSION_FREE: f64 = 20.0;
/// How far an end tick of a dimension drawn on the line it measures
/// (offset 0: a scale bar, a curve's ΔE) reaches each side of it, page
/// units: there no extension line runs to the dimension line, and one
/// drawn from its point (3 units off) to a unit past it printed as a
/// speck over the head, against the text's "²" at the bar's end.
const TICK: f64 = 3.0;
/// Room between the end of a scale bar's tick and its text, page units.
const TICK_ROOM: f64 = 2.0;

impl PanelLayout<'_> {
    /// A straight arrow with its head at `to`; labels keep off the shaft
    /// and the head.
    pub(super) fn arrow(&mut self, ink: &Ink, from: Point, to: Point) -> Option<Mark> {
        let (a, b) = (self.p(from), self.p(to));
        if !finite(&a) || !finite(&b) {
            return None;
        }
        let u = unit(b - a)?;
        self.obstacles.segment(a, b);
        if ink.role == Role::Force {
            // A text naming a line keeps nearer its own than a force.
            self.links.push((a, b));
        }
        // The head is wider than the shaft: keep labels off it too.
        let half = 0.5 * ARROW_LENGTH;
        self.obstacles
            .boxed(Frame::around(b - u * half, Vector::new(half, half)));
        let shaft = polyline_d(&[a, b - u * (0.6 * ARROW_LENGTH)], false);
        Some(
            ink.tag(Mark::group())
                .with(path(shaft, ink.pen))
                .with(arrow_head(b, u, ink.pen.colour)),
        )
    }

    /// A right-angle mark at `vertex` between the world directions `u`
    /// and `v`: two short full strokes, which labels keep off.
    pub(super) fn right_angle(
        &mut self,
        ink: &Ink,
        vertex: Point,
        u: Vector,
        v: Vector,
    ) -> Option<Mark> {
        let c = self.p(vertex);
        let u = unit(self.t.apply_vector(u))?;
        let v = unit(self.t.apply_vector(v))?;
        let s = RIGHT_ANGLE;
        let pts = [c + u * s, c + u * s + v * s, c + v * s];
        if !pts.iter().all(finite) {
            return None;
        }
        self.obstacles.polyline(&pts);
        let pen = Pen {
            width: 0.7,
            dash: None,
            ..ink.pen
        };
        Some(ink.tag(path(polyline_d(&pts, false), pen)))
    }

    /// The radius of the angle mark of `sweep` (its size) at the page
    /// point `c`: [`angle_radius`] (larger for a small angle), and [`ANGLE_STEP`] more for each larger
    /// angle at the same vertex ([`angle_radii`]).
    fn angle_radius(&mut self, c: Point, sweep: f64) -> f64 {
        // Each entry serves one mark, in drawing order: two equal angles
        // at one vertex take their two radii in turn.
        let found =
            (self.angle_radii.iter()).position(|(v, s, _)| (*v - c).norm() < 1.0 && *s == sweep);
        found.map_or(angle_radius(sweep), |k| self.angle_radii.remove(k).2)
    }

    /// An angle mark: an arc of page radius [`ANGLE_RADIUS`] about
    /// `vertex` from the world angle `start` turning `sweep`, its name
    /// (if any) placed with the labels beside the arc's middle.
    pub(super) fn angle_mark(
        &mut self,
        ink: &Ink,
        vertex: Point,
        (start, sweep): (f64, f64),
        text: Option<&RichText>,
    ) -> Option<Mark> {
        let c = self.p(vertex);
        if !finite(&c) {
            return None;
        }
        let (page_start, page_sweep) = self.page_angles(start, sweep);
        let radius = self.angle_radius(c, sweep.abs());
        self.bezier_obstacles(&arc_beziers(c, radius, page_start, page_sweep));
        let course = Course::Arc {
            centre: c,
            radius,
            start: page_start,
            sweep: page_sweep,
        };
        if let Some(text) = text {
            // The arc's point a share `k` along it and the page direction
            // out to it from the vertex.
            let at = |k: f64| {
                // Within [`OFF_MIDDLE`] of the middle: a wide angle's
                // letter by its middle shows which way it runs.
                let off = ((k - 0.5) * sweep.abs()).clamp(-OFF_MIDDLE, OFF_MIDDLE);
                let w = start + 0.5 * sweep + off * sweep.signum();
                let u = unit(self.t.apply_vector(Vector::new(w.cos(), w.sin())))?;
                Some((c + u * radius, u))
            };
            let dir = at(0.5)?.1;
            let along = ALONG_ARC.iter().filter_map(|k| at(*k)).collect();
            self.pending.push(Pending {
                id: format!("label-{}", ink.id.trim_start_matches("angle-")),
                anchor: c + dir * radius,
                text: text.clone(),
                size: self.style.font_size(TextSize::Small) + 2.0,
                gap: 2.0,
                letter: false,
                toward: Some(dir),
                joint: false,
                line: None,
                along,
                wedge: Some((c, dir, 0.5 * sweep.abs())),
            });
        }
        Some(self.open_line(ink, course))
    }

    /// A dimension between `from` and `to`: extension lines, the line set
    /// off by `offset` page units towards the world direction `side` with
    /// a head at each end, and its text beside the middle. A dimension
    /// shorter than two heads and [`HEADS_GAP`] has its heads outside the
    /// extension lines, pointing in, as a draughtsman draws a small one.
    pub(super) fn dimension(
        &mut self,
        ink: &Ink,
        (from, to): (Point, Point),
        side: Vector,
        offset: f64,
        text: &RichText,
    ) -> Option<Mark> {
        let pen = ink.pen;
        let (a, b) = (self.p(from), self.p(to));
        let n = unit(self.t.apply_vector(side))?;
        let u = unit(b - a)?;
        let (a2, b2) = (a + n * offset, b + n * offset);
        // On its own line (offset 0) the ends are ticks across it and the
        // text stands beyond them; off it, extension lines from the
        // points to a little past the dimension line.
        let on_line = offset == 0.0;
        let ext = |p: Point, q: Point| match on_line {
            true => polyline_d(&[q - n * TICK, q + n * TICK], false),
            false => polyline_d(&[p + n * 3.0, q + n * 4.0], false),
        };
        let size = self.style.font_size(TextSize::Small) + 1.0;
        let half = text_half(text, size, self.font);
        let lift = if on_line { TICK + TICK_ROOM } else { 3.0 };
        let centre = self.dimension_text((a2, b2), n, half, lift);
        self.obstacles.text(Frame::around(centre, half));
        // Too short for both heads inside: the heads point in from
        // outside the extension lines, on the line produced each way.
        let outside = (b2 - a2).norm() < 2.0 * ARROW_LENGTH + HEADS_GAP;
        let (line, towards) = if outside {
            let past = u * (ARROW_LENGTH + LEADER);
            ([a2 - past, b2 + past], u)
        } else {
            ([a2 + u * 2.0, b2 - u * 2.0], -u)
        };
        self.obstacles.segment(line[0], line[1]);
        // A text naming a line keeps nearer its own than a dimension
        // line (l set between x's heads reads as x's value).
        self.dimensions.push((line[0], line[1]));
        // Letters keep off the extension lines but for their first
        // stretch, where the dimensioned point's own letter may stand.
        for (p, q) in [(a, a2), (b, b2)] {
            if (q - p).norm() > EXTENSION_FREE + 4.0 {
                self.obstacles.segment(p + n * EXTENSION_FREE, q + n * 4.0);
            }
        }
        let thin = Pen { width: 0.5, ..pen };
        Some(
            ink.tag(Mark::group())
                .with(path(ext(a, a2), thin))
                .with(path(ext(b, b2), thin))
                .with(path(polyline_d(&line, false), pen))
                .with(arrow_head(a2, towards, pen.colour))
                .with(arrow_head(b2, -towards, pen.colour))
                .with(text_node(
                    &format!("{}-text", ink.id),
                    centre,
                    text,
                    size,
                    pen.colour,
                    TextAnchor::Middle,
                    starts_italic(text),
                )),
        )
    }

    /// The centre of a dimension's text (half-size `half`) beside its
    /// line `a2`–`b2` on the side `n`: at the middle, or where a line
    /// drawn already runs through it, slid along the dimension line (by
    /// steps of [`SLIDE`], the text within the line's ends) as little as
    /// clears it by a step, else as little as clears it; the middle where
    /// nothing does; `lift` (page units) between the line and the text.
    fn dimension_text(
        &self,
        (a2, b2): (Point, Point),
        n: Vector,
        half: Vector,
        lift: f64,
    ) -> Point {
        let middle = nalgebra::center(&a2, &b2) + n * (half.y + lift);
        let Some(u) = unit(b2 - a2) else {
            return middle;
        };
        let steps = ((0.5 * (b2 - a2).norm() - half.x) / SLIDE).floor().max(0.0) as i32;
        let places = (0..=steps)
            .flat_map(|k| [k, -k])
            .map(|k| middle + u * (SLIDE * f64::from(k)));
        let clear = |c: &Point, margin: f64| {
            let b = Frame::around(*c, half + Vector::new(margin, 0.0));
            self.obstacles.cost(&b) == 0.0
        };
        places
            .clone()
            .find(|c| clear(c, SLIDE))
            .or_else(|| places.clone().find(|c| clear(c, 0.0)))
            .unwrap_or(middle)
    }

    /// The page angles (start, sweep) of an arc from the world angle
    /// `start` turning `sweep`.
    fn page_angles(&self, start: f64, sweep: f64) -> (f64, f64) {
        let dir = self.t.apply_vector(Vector::new(start.cos(), start.sin()));
        (dir.y.atan2(dir.x), sweep * self.orientation())
    }
}

/// The most (radians) an angle's letter is tried away from its arc's
/// middle along the arc: 30°. A direct crank's θ of 269° had its letter
/// 78° round from its middle, read as the reverse crank's.
const OFF_MIDDLE: f64 = std::f64::consts::PI / 6.0;

/// The radii of the angle marks among `items` drawn by the map `t`: at a
/// vertex shared by several, the largest angle innermost at its
/// [`angle_radius`] and each smaller one [`ANGLE_STEP`] further out, so
/// that two adjacent angles (Ng's β and φ at the crank pin) read as two,
/// and the smaller, whose letter needs the room, gets the longer arc. An
/// arc arrow about the same vertex (the crank torque T about O) has the
/// marks beyond it, from [`ANGLE_STEP`] outside it: θ's arc inside T's,
/// its letter outside both, could not be told from T's. As (page vertex,
/// size of the sweep, radius).
pub(super) fn angle_radii(t: &PageFromWorld, items: &[&Item]) -> Vec<(Point, f64, f64)> {
    let marks: Vec<(Point, f64, f64)> = items
        .iter()
        .filter_map(|item| match &item.shape {
            Shape::AngleMark {
                vertex,
                start,
                sweep,
                ..
            } => Some((t.apply(*vertex), *start, *sweep)),
            _ => None,
        })
        .collect();
    let arrows: Vec<(Point, f64)> = items
        .iter()
        .filter_map(|item| match &item.shape {
            Shape::Arc {
                centre,
                radius,
                arrow: true,
                ..
            } => Some((t.apply(*centre), radius * t.scale())),
            _ => None,
        })
        .collect();
    let feet: Vec<(Point, Vector)> = items
        .iter()
        .filter_map(|item| match &item.shape {
            Shape::Bearing { centre, foot } => Some((t.apply(*centre), foot.axes().0)),
            _ => None,
        })
        .collect();
    marks
        .iter()
        .enumerate()
        .map(|(k, &(c, start, sweep))| {
            let at = |v: &Point| (*v - c).norm() < 1.0;
            // Two equal angles at one vertex (Ng's φ and β at 180°, on
            // the same arms) take two radii too, the first drawn inside:
            // on one arc the two letters read as one angle's.
            let larger = (marks.iter().enumerate())
                .filter(|(j, (v, b, s))| {
                    let equal =
                        s.abs() == sweep.abs() && *j < k && within((*b, *s), start + 0.5 * sweep);
                    at(v) && (s.abs() > sweep.abs() || equal)
                })
                .count();
            let least = (arrows.iter())
                .filter(|(v, _)| at(v))
                .map(|(_, r)| r + ANGLE_STEP)
                .fold(angle_radius(sweep), f64::max);
            let on_foot = (feet.iter()).any(|(v, out)| at(v) && crosses(t, (start, sweep), *out));
            let least = if on_foot {
                least.max(CLEAR_OF_BEARING)
            } else {
                least
            };
            (c, sweep.abs(), least + ANGLE_STEP * larger as f64)
        })
        .collect()
}

/// Whether the world direction `w` lies within the arc from the world
/// angle `start` turning `sweep`: an equal angle's middle there draws on
/// the same arc.
fn within((start, sweep): (f64, f64), w: f64) -> bool {
    let turned = (w - start).rem_euclid(std::f64::consts::TAU);
    let turned = if sweep < 0.0 {
        std::f64::consts::TAU - turned
    } else {
        turned
    };
    turned < sweep.abs()
}

/// The least radius (page units) of an angle's arc that passes over a
/// bearing at its vertex: past the corners of its hatched foot (17 out,
/// hatched to 23, 22 along: 32 from the centre) by a gap. θ's arc at 28
/// ran through a hanging bearing's hatching (Fig. 62 at 270°, long rods).
const CLEAR_OF_BEARING: f64 = 36.0;

/// Whether the arc from the world angle `start` turning `sweep` passes
/// within 50° of the page direction `out` (a bearing's foot).
fn crosses(t: &PageFromWorld, (start, sweep): (f64, f64), out: Vector) -> bool {
    (0..=24).any(|k| {
        let w = start + sweep * f64::from(k) / 24.0;
        let d = t.apply_vector(Vector::new(w.cos(), w.sin()));
        d.norm() > 0.0 && d.normalize().dot(&out) > 50f64.to_radians().cos()
    })
}

#[cfg(test)]
mod tests {
    use super::super::symbol_sizes::RIGHT_ANGLE;
    use super::super::text::{BASELINE, text_half};
    use crate::figure::Style;
    use crate::figure::{
        Figure, Font, Item, PageFromWorld, Panel, RichText, Role, Shape, TextSize,
    };
    use crate::geom::{Frame, Point, Vector};
    use crate::render::to_svg;

    /// The number after `name="` in the element with `id`.
    fn attribute(svg: &str, id: &str, name: &str) -> f64 {
        let at = svg.find(&format!("id=\"{id}\"")).unwrap();
        let start = svg[..at].rfind('<').unwrap();
        let tag = &svg[start..start + svg[start..].find('>').unwrap()];
        let from = tag.find(&format!(" {name}=\"")).unwrap() + name.len() + 3;
        tag[from..from + tag[from..].find('"').unwrap()]
            .parse()
            .unwrap()
    }

    /// The figure of one panel holding `items`, 200 units square, world
    /// and page alike.
    fn one_panel(items: Vec<Item>) -> Figure {
        let rect = Frame::from_origin_size(0.0, 0.0, 200.0, 200.0);
        let panel = Panel::new("panel", rect, PageFromWorld::identity(), items);
        Figure::new(
            "test",
            200.0,
            200.0,
            Style::Textbook,
            0.01,
            vec![panel],
            Default::default(),
        )
    }

    /// The x coordinates of the paths of the group `id`, path by path.
    fn path_xs(svg: &str, id: &str) -> Vec<Vec<f64>> {
        let at = svg.find(&format!("id=\"{id}\"")).unwrap();
        let group = &svg[at..at + svg[at..].find("</g>").unwrap()];
        group
            .split(" d=\"")
            .skip(1)
            .map(|d| {
                let d = &d[..d.find('"').unwrap()];
                let numbers: Vec<f64> = d
                    .split(|c: char| !(c.is_ascii_digit() || c == '.' || c == '-'))
                    .filter_map(|t| t.parse().ok())
                    .collect();
                numbers.iter().step_by(2).copied().collect()
            })
            .collect()
    }

    #[test]
    fn a_short_dimension_has_its_heads_outside() {
        for (length, outside) in [(12.0, true), (40.0, false)] {
            let (from, to) = (Point::new(80.0, 100.0), Point::new(80.0 + length, 100.0));
            let item = Item::new(
                "dimension-x",
                Role::Dimension,
                Shape::Dimension {
                    from,
                    to,
                    side: Vector::new(0.0, -1.0),
                    offset: 20.0,
                    text: RichText::italic("x"),
                },
            );
            let svg = to_svg(&one_panel(vec![item]));
            let paths = path_xs(&svg, "dimension-x");
            // Extension lines, the line, then the two heads.
            let line = &paths[2];
            let (lo, hi) = line
                .iter()
                .fold((f64::MAX, f64::MIN), |(lo, hi), x| (lo.min(*x), hi.max(*x)));
            assert_eq!(lo < from.x && hi > to.x, outside, "{length}: line {line:?}");
            // A head's tip is on its extension line; its back is outside
            // the dimension when the heads point in.
            let head = &paths[3];
            let back = head[1];
            assert!((head[0] - from.x).abs() < 1e-9, "{length}: {head:?}");
            assert_eq!(back < from.x, outside, "{length}: head {head:?}");
        }
    }

    #[test]
    fn labels_keep_off_extension_lines() {
        // A dimension upright at x = 180 set off 120 to the left: its
        // extension lines run along y = 100 and y = 140. A label asked for
        // on the upper one, 70 from its point, with a link just above it:
        // right of its anchor it would sit across the extension line.
        let items = vec![
            Item::new(
                "dimension-e",
                Role::Dimension,
                Shape::Dimension {
                    from: Point::new(180.0, 100.0),
                    to: Point::new(180.0, 140.0),
                    side: Vector::new(-1.0, 0.0),
                    offset: 120.0,
                    text: RichText::italic("e"),
                },
            ),
            Item::new(
                "link-rod",
                Role::Link,
                Shape::Polyline {
                    points: vec![Point::new(60.0, 92.0), Point::new(170.0, 92.0)],
                    closed: false,
                },
            ),
            Item::new(
                "value-v",
                Role::Label,
                Shape::Label {
                    anchor: Point::new(110.0, 100.0),
                    text: RichText::italic("v"),
                    size: TextSize::Small,
                    toward: None,
                    line: None,
                },
            ),
        ];
        let svg = to_svg(&one_panel(items));
        let size = attribute(&svg, "value-v", "font-size");
        let centre_y = attribute(&svg, "value-v", "y") - BASELINE * size;
        let half = text_half(&RichText::italic("v"), size, Font::default());
        // `half` carries a unit of room on each side, which placement lets
        // touch a line, and the glyph's box a unit more.
        assert!(
            (centre_y - 100.0).abs() > half.y - 2.0,
            "label centred at y {centre_y}, half height {}",
            half.y
        );
    }

    #[test]
    fn letters_keep_off_right_angle_marks() {
        // The mark in each quadrant about the lettered point: wherever the
        // letter would rather go, it must not sit on the strokes.
        let vertex = Point::new(100.0, 100.0);
        let text = RichText::italic("C");
        for (u, v) in [(1.0, 1.0), (-1.0, 1.0), (-1.0, -1.0), (1.0, -1.0)] {
            let (u, v) = (Vector::new(u, 0.0), Vector::new(0.0, v));
            let items = vec![
                Item::new(
                    "angle-C",
                    Role::Construction,
                    Shape::RightAngle { vertex, u, v },
                ),
                Item::new(
                    "label-C",
                    Role::Label,
                    Shape::Label {
                        anchor: vertex,
                        text: text.clone(),
                        size: TextSize::Letter,
                        toward: None,
                        line: None,
                    },
                ),
            ];
            let svg = to_svg(&one_panel(items));
            let size = attribute(&svg, "label-C", "font-size");
            let centre = Point::new(
                attribute(&svg, "label-C", "x"),
                attribute(&svg, "label-C", "y") - BASELINE * size,
            );
            // The glyph's box (without the unit of room placement adds).
            let half = text_half(&text, size, Font::default()) - Vector::new(1.0, 1.0);
            let s = RIGHT_ANGLE;
            let corner = vertex + u * s + v * s;
            for (a, b) in [(vertex + u * s, corner), (corner, vertex + v * s)] {
                for k in 0..=50 {
                    let p = a + (b - a) * (k as f64 / 50.0);
                    let d = p - centre;
                    assert!(
                        d.x.abs() > half.x || d.y.abs() > half.y,
                        "u {u:?}, v {v:?}: label at {centre:?} on the mark at {p:?}"
                    );
                }
            }
        }
    }
}
