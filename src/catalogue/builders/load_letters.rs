//! The letters of the polar load diagram ([`super::loads`]), set by the
//! figure, not the layout: each (the pole's *O* first, then the
//! quarters') on the nearest of three rings about its point, of sixteen
//! directions, where its box stands clear of both curves, of every other
//! dot and the pole, and of the letters set before it, and nearer its own
//! point than any other. Where no near ring has a clear side, it is set
//! at the nearest clear place within three ems with a leader to its dot,
//! as a draughtsman letters a point with no room beside it. A side chosen
//! for its room at one distance (two and a half dots' diameters) and
//! left to the layout stood clear only on the layout's last ring, where
//! a letter reads as another curve's point (the dashed 270°′ at r = 1,
//! l = 47.6 r on 4.5 in, lettered on the full curve some 25 units above
//! its dot: the tenth review), and beside a short rod's pole the letters
//! piled on each other.

use super::Ctx;
use crate::figure::{Align, Font, Item, PageFromWorld, RichText, Role, Shape, TextSize};
use crate::geom::{Frame, Point, Vector, crossing, point_segment_distance, segment_distance};

/// Room between a point and its letter's box, page units: the layout's
/// gap for a letter.
const GAP: f64 = 4.0;

/// How much farther than touching each ring of sides tried sits, page
/// units: the layout's first three (its fourth and fifth, 12 and 17, put
/// the ink an em or more from its point).
const RINGS: [f64; 3] = [0.0, 4.0, 8.0];

/// The rings of the places farther out, page units beyond the gap, each
/// with a leader: out to three ems (a letter farther off is not read
/// with its dot, leader or not).
const FAR_RINGS: [f64; 8] = [12.0, 17.0, 22.0, 28.0, 34.0, 40.0, 46.0, 51.0];

/// The rings beyond [`FAR_RINGS`], out to four ems, page units beyond
/// the gap: only where no place within three ems is clear, before the
/// letter is left to the layout, which sets it by no rule of these
/// ("180°′" an eighth of an em under *O* at r = 1, l = 1.1 r on 500
/// units, its dot by the × with no room within three ems).
const FARTHEST_RINGS: [f64; 3] = [57.0, 62.0, 68.0];

/// A direction's component below this is along an axis.
const ALONG: f64 = 1e-9;

/// How far short of its dot a leader is taken to stop when its place is
/// chosen, page units: clear of the dot (2.1) by a unit and a half, the
/// room every rule of a leader measures.
const LEADER_SHORT: f64 = 3.6;

/// How far short of its dot's centre a leader is drawn to, page units:
/// the dot's radius, so that the leader ends on its dot. Drawn to
/// [`LEADER_SHORT`], at a small scale it ended on the curves about the
/// dot, on no dot of its own ("270°′" on the *x* axis in (a) at the
/// default engine, "0°′" on the wedge's line at r = 1, l = 1.05 r on 500
/// units: the fifteenth review).
const LEADER_END: f64 = 2.1;

/// Where a text set at a fixed place has its place: the middle of its
/// letters, this many ems above its baseline ([`Shape::Text`]).
const MIDDLE: f64 = 0.35;

/// Room a letter's box keeps about its glyphs, and from a curve, page
/// units: the layout's room and clearance.
const ROOM: f64 = 1.0;

/// Room a letter's box keeps from another dot's centre, page units: the
/// dot's radius (2.1) and a unit and a half.
const DOT_ROOM: f64 = 3.6;

/// Room a letter's box keeps from the pole's centre, page units: the
/// ×'s half-width and a unit and a half.
const POLE_ROOM: f64 = 5.5;

/// Dots nearer each other than this, page units, are one place: a letter
/// may stand on either side of the pair.
const ONE_PLACE: f64 = 4.0;

/// Room a quarter's letter keeps from the pole's letter *O*, in ems of
/// the letters: more than an em, so that the two read as two labels
/// ("0°" two word spaces from "O" read as one, "0° O", at the default
/// engine: the eleventh review).
const POLE_LETTER_ROOM: f64 = 1.2;

/// How much nearer its own dot than any other, in ems, a letter set
/// beside its dot (with no leader) stands: a letter about as near two
/// dots names either ("270°" 9.5 units from its dot and 9.2 from the 0°
/// dot it stood under at r = 1, l = 46.2 r; "0°′" 14 and 16 units from
/// its dot and the 180° dot at l = 3.35 r, e = 1.72 r: the thirteenth
/// review).
const NEARER: f64 = 0.4;

/// Room a led letter's box keeps from every dot but its own, in ems: a
/// letter against another dot, its leader running off to its own, reads
/// as that dot's ("0°′" touching an unlettered dot at r = 1, l = 2.32 r,
/// e = −0.685 r: the thirteenth review).
const LED_DOT_ROOM: f64 = 0.5;

/// Room a leader keeps from every letter it does not start at, in ems:
/// nearer, it reads as running through it (the 180°′ leader by "0°′"
/// at the default engine on 120 mm).
const LEADER_CLEAR: f64 = 0.25;

/// Room a leader's start keeps from every letter but its own, in ems:
/// a leader starting between two letters ("180°′" stacked over "180°" at
/// r = 1, l = 3.35 r, e = 1.72 r: the thirteenth review) belongs to
/// either.
const START_ROOM: f64 = 0.4;

/// Room between two letters on one line (their boxes level), in ems: a
/// word space and more, so that two letters side by side read as two
/// ("180°" and "0°" a unit apart read as "180°0°" at r = 1, l = 2.97 r,
/// e = −1.2 r on 4.5 in: the twelfth review).
const LINE_ROOM: f64 = 0.6;

/// Dots nearer each other than this, in ems, but not one place, are a
/// pair: each one's letter stands beyond its own dot, away from the
/// other, so that no reader takes it for the other's ("0°′" and "180°′"
/// on dots 5 units apart, stacked on one side, at r = 1, l = 3.18 r,
/// e = −1.79 r: the twelfth review).
const PAIR: f64 = 0.75;

/// The twelfth review's rules a place keeps, beyond the room every
/// letter keeps.
#[derive(Clone, Copy)]
struct Rules {
    /// A pair's letters each beyond its own dot ([`PAIR`]).
    pairs: bool,
    /// [`LINE_ROOM`] from a letter on its line, and clear of the leaders.
    lines: bool,
    /// A letter beside its dot [`NEARER`] nearer it than any other dot.
    nearer: bool,
    /// A letter beside its dot seeing it across no line
    /// ([`Letters::across`]): not the pole's, whose × stands where
    /// curves cross.
    sight: bool,
}

impl Rules {
    /// Only the room every letter keeps.
    const NONE: Self = Self {
        pairs: false,
        lines: false,
        nearer: false,
        sight: false,
    };
    /// A pair's letters beyond their dots.
    const PAIRS: Self = Self {
        pairs: true,
        lines: false,
        nearer: false,
        sight: false,
    };
    /// Letters on a line apart and clear of the leaders.
    const LINES: Self = Self {
        pairs: false,
        lines: true,
        nearer: false,
        sight: false,
    };
    /// Both, [`NEARER`] and in sight of its dot.
    const ALL: Self = Self {
        pairs: true,
        lines: true,
        nearer: true,
        sight: true,
    };
    /// Both and [`NEARER`]: the pole's letter's.
    const POLE: Self = Self {
        sight: false,
        ..Self::ALL
    };
    /// Both, without [`NEARER`].
    const NEAR: Self = Self {
        pairs: true,
        lines: true,
        nearer: false,
        sight: false,
    };
}

/// The letters set so far in a panel and what each later letter keeps
/// clear of.
#[derive(Clone)]
pub(super) struct Letters {
    /// Both curves as world segments (their jumps' dotted lines within
    /// the cycle too).
    curves: Vec<(Point, Point)>,
    /// The dotted lines of the jumps at the cycle's start and end, and
    /// the sides of a detail's box ([`Letters::keep_off`]): kept clear of
    /// by letters, crossed by leaders as a curve is not.
    jumps: Vec<(Point, Point)>,
    /// The boxes of the letters set so far: world centre and half-size.
    boxes: Vec<(Point, Vector)>,
    /// The leaders set so far (world): kept clear of by letters, and
    /// crossed by no later leader.
    leaders: Vec<(Point, Point)>,
    /// The pole's letter's box, where it is set (the first letter set).
    pole: Option<Boxed>,
    /// Page units to the world unit.
    scale: f64,
    /// The panel's map, world to page.
    map: PageFromWorld,
    /// The world box every letter stays inside (the plot's area, in (a)
    /// above the scale bar's room).
    inside: Frame,
    /// The face the letters are measured in.
    font: Font,
    /// The letters' size, page units.
    size: f64,
}

/// A box: its centre and half-size.
type Boxed = (Point, Vector);

/// A letter set with a leader ([`Letters::led`]).
pub(super) struct Led {
    /// The letter and its leader.
    pub(super) items: [Item; 2],
    /// Whether its place was the least bad of places that each mislead:
    /// its leader across another leader or through a letter, or a pair's
    /// letter short of its dot, or astray by another dot. The letters
    /// set before it may be set again in another order
    /// ([`super::loads`]'s marks, the hardest first).
    pub(super) misleads: bool,
}

impl Letters {
    /// The letters of a panel drawn by `map` (uniform, world to page)
    /// whose curves are the loads `sampled` in order (each sample both
    /// curves' loads), each letter inside the world box `inside`.
    pub(super) fn new(
        ctx: &Ctx,
        sampled: &[[Vector; 2]],
        map: PageFromWorld,
        inside: Frame,
    ) -> Self {
        let trace = |pick: fn(&[Vector; 2]) -> Vector| -> Vec<Point> {
            sampled.iter().map(|s| Point::origin() + pick(s)).collect()
        };
        let traces = [trace(|s| s[0]), trace(|s| s[1])];
        let curves = (traces.iter())
            .flat_map(|t| t.iter().copied().zip(t.iter().copied().skip(1)))
            .collect();
        // Each trace's end joined to its start: the jump at the cycle's
        // start and end, drawn dotted, which a letter set over read as
        // struck through ("0°" on the dotted line at the default engine).
        let jumps = (traces.iter())
            .filter_map(|t| Some((*t.last()?, *t.first()?)))
            .collect();
        Self {
            curves,
            jumps,
            boxes: Vec::new(),
            leaders: Vec::new(),
            pole: None,
            scale: map.scale(),
            map,
            inside,
            font: ctx.font,
            size: ctx.style.font_size(TextSize::Letter),
        }
    }

    /// Keeps every letter set after this clear of the `lines` (world) as
    /// of the dotted jumps, which leaders may cross: the sides of the box
    /// about the region a detail enlarges.
    pub(super) fn keep_off(&mut self, lines: &[(Point, Point)]) {
        self.jumps.extend_from_slice(lines);
    }

    /// The letter `text` of the dot `from`, `id`, set by the figure where
    /// it stands clear nearest its point: on the first ring with a clear
    /// side, the side with the most room; the box recorded for the
    /// letters after it. `None` where no ring within [`RINGS`] has one
    /// ([`Letters::led`] then sets it farther out). `dots` are the other
    /// points drawn (the pole first). `strict`, it keeps the twelfth
    /// review's rules too: beyond its dot, away from the other, where two
    /// dots are a pair ([`PAIR`]); [`LINE_ROOM`] from a letter on its
    /// line; clear of the leaders set. A letter with no such side is led
    /// ([`Letters::led`], which prefers places keeping them), and only
    /// where no place is clear set beside its dot without them.
    pub(super) fn beside(
        &mut self,
        from: Point,
        text: RichText,
        dots: &[Point],
        id: String,
        strict: bool,
    ) -> Option<Item> {
        let rules = if strict { Rules::ALL } else { Rules::NONE };
        self.beside_with(from, text, dots, id, rules)
    }

    /// [`Letters::beside`] keeping `rules`.
    fn beside_with(
        &mut self,
        from: Point,
        text: RichText,
        dots: &[Point],
        id: String,
        rules: Rules,
    ) -> Option<Item> {
        let half = self.half(&text);
        let curves = self.curves_near(from, half, *RINGS.last().unwrap_or(&0.0));
        let b = RINGS.iter().find_map(|&ring| {
            (directions().filter_map(|u| {
                let b = (self.centre(from, u, half, ring), half);
                self.room(b, from, (&curves, dots), false, rules)
                    .map(|room| (b, room))
            }))
            .max_by(|a, b| a.1.total_cmp(&b.1))
        })?;
        self.boxes.push(b.0);
        Some(self.text(b.0, text, id))
    }

    /// The pole's letter `text` beside the pole (the world origin), `id`,
    /// as [`Letters::beside`] sets a dot's, or where no near ring has a
    /// clear side, farther out with its leader `leader_id`
    /// ([`Letters::led`]); the quarters' letters set after it keep
    /// [`POLE_LETTER_ROOM`] from it. Empty where no place within three
    /// ems is clear.
    pub(super) fn pole(
        &mut self,
        text: RichText,
        dots: &[Point],
        (id, leader_id): (String, String),
    ) -> Vec<Item> {
        let o = Point::origin();
        let first = self.beside_with(o, text.clone(), dots, id.clone(), Rules::POLE);
        // Nearer the × than any dot, if not by [`NEARER`], rather than
        // led an em or more away (r = 1, l = 1.05 r: its dead centres'
        // dots all about the ×).
        let first =
            first.or_else(|| self.beside_with(o, text.clone(), dots, id.clone(), Rules::NEAR));
        let items = match first {
            Some(item) => vec![item],
            None => match self.led(o, text.clone(), dots, (id.clone(), leader_id)) {
                Some(led) => Vec::from(led.items),
                None => self.beside(o, text, dots, id, false).into_iter().collect(),
            },
        };
        if !items.is_empty() {
            self.pole = self.boxes.last().copied();
        }
        items
    }

    /// The letter `text`, `id`, its ink's box `b` (world).
    fn text(&self, b: Boxed, text: RichText, id: String) -> Item {
        let ink = text.measure(self.font, self.size);
        let centre = self.map.apply(b.0);
        let middle = centre - Vector::new(0.0, 0.5 * (ink.below - ink.above) + MIDDLE * self.size);
        Item::new(
            id,
            Role::Label,
            Shape::Text {
                at: self.map.invert(middle),
                offset: Vector::zeros(),
                text,
                align: Align::Middle,
                size: TextSize::Letter,
            },
        )
    }

    /// The letter `text` of the dot `from` set by the figure where no
    /// near side is clear ([`Letters::side`]): on the nearest of
    /// [`FAR_RINGS`] with a clear place, the place first that keeps a
    /// pair's letters beyond their dots ([`PAIR`]) with a leader crossing
    /// no leader set and running through no letter (either misleads:
    /// which dot is named), then whose leader crosses the fewest lines of
    /// the curves, then keeping [`LINE_ROOM`] and clear of the leaders,
    /// then on the nearest ring, then with the most room, and a
    /// leader from its box drawn on to its dot ([`LEADER_END`]): the
    /// text `id` and the leader `leader_id`, and whether even that place
    /// misleads ([`Led::misleads`]); `None` where no place within three
    /// ems is clear. The box is recorded for the letters after it.
    pub(super) fn led(
        &mut self,
        from: Point,
        text: RichText,
        dots: &[Point],
        ids: (String, String),
    ) -> Option<Led> {
        self.led_on(&FAR_RINGS, from, text, dots, ids)
    }

    /// [`Letters::led`] on the rings [`FARTHEST_RINGS`], past three ems:
    /// where no place nearer is clear.
    pub(super) fn led_farther(
        &mut self,
        from: Point,
        text: RichText,
        dots: &[Point],
        ids: (String, String),
    ) -> Option<Led> {
        self.led_on(&FARTHEST_RINGS, from, text, dots, ids)
    }

    /// [`Letters::led`] on the `rings`.
    fn led_on(
        &mut self,
        rings: &[f64],
        from: Point,
        text: RichText,
        dots: &[Point],
        (id, leader_id): (String, String),
    ) -> Option<Led> {
        let half = self.half(&text);
        let curves = self.curves_near(from, half, *rings.last().unwrap_or(&0.0));
        // Fewest crossings first over every ring, then the nearest ring,
        // then the most room: the nearest ring's least crossed place
        // crossed a curve where a ring farther out had a place crossing
        // none (the offset engine r = 1, l = 3.83, e = −1.63: the
        // eleventh review).
        let (b, (blocked, misleads, ..), _) = (rings.iter().enumerate())
            .flat_map(|(k, &ring)| {
                let (this, curves) = (&*self, &curves);
                directions().filter_map(move |u| {
                    let b = (this.centre(from, u, half, ring), half);
                    let (a, end) = this.leader(b, from);
                    let room = this.room(b, from, (curves, dots), true, Rules::NONE)?;
                    let keeps = |rules| this.room(b, from, (curves, dots), true, rules).is_some();
                    // A leader across a leader or through a letter first,
                    // then a pair's letter or a leader astray.
                    let blocked = this.leader_blocked(a, end);
                    // The pole's letter, by its × unlike a dot, not held to
                    // a dot's rules, but nearer its × than any dot: led
                    // past a plain dot it read as that dot's (r = 1,
                    // l = 3.87 r, e = 1.85 r on 120 mm: O 16 units from
                    // the dashed 60° and 42 from its ×).
                    let astray = if from == Point::origin() {
                        let own = to_box(b, from);
                        dots.iter().any(|q| to_box(b, *q) < own)
                    } else {
                        this.astray(b, (a, end), from, dots)
                    };
                    let misleads = !keeps(Rules::PAIRS) || astray;
                    let crowds = !keeps(Rules::LINES);
                    let crossed = (curves.iter())
                        .filter(|(p, q)| crossing(a, from, *p, *q).is_some())
                        .count();
                    Some((b, (blocked, misleads, crossed, crowds, k), room))
                })
            })
            .min_by(|a, b| a.1.cmp(&b.1).then(b.2.total_cmp(&a.2)))?;
        self.boxes.push(b);
        let (a, end) = self.leader(b, from);
        // Drawn on to its dot, the last unit and a half along the same
        // line, and kept clear of by the leaders after it as drawn.
        let on = LEADER_END / self.scale;
        let end = if (from - a).norm() > on {
            from - (from - a) * (on / (from - a).norm())
        } else {
            end
        };
        self.leaders.push((a, end));
        Some(Led {
            items: [
                self.text(b, text, id),
                Item::new(
                    leader_id,
                    // A thin full line, as a dimension's.
                    Role::Dimension,
                    Shape::Polyline {
                        points: vec![a, end],
                        closed: false,
                    },
                ),
            ],
            misleads: blocked || misleads,
        })
    }

    /// A leader from the box `b` to `from` (world): from the box's point
    /// nearest `from` to [`LEADER_SHORT`] short of it.
    fn leader(&self, (c, h): Boxed, from: Point) -> (Point, Point) {
        let a = Point::new(
            from.x.clamp(c.x - h.x, c.x + h.x),
            from.y.clamp(c.y - h.y, c.y + h.y),
        );
        let d = from - a;
        let short = LEADER_SHORT / self.scale;
        let end = if d.norm() > short {
            from - d * (short / d.norm())
        } else {
            a
        };
        (a, end)
    }

    /// The half-size (world) of the box of the letter `text`: its ink and
    /// the room about it.
    fn half(&self, text: &RichText) -> Vector {
        let ink = text.measure(self.font, self.size);
        Vector::new(0.5 * ink.width + ROOM, 0.5 * (ink.above + ink.below) + ROOM) / self.scale
    }

    /// The middle (world) of a box of half-size `half` whose point
    /// nearest `from` lies `ring` page units beyond the gap from it in
    /// the direction `u`: touching there by a corner, or by a side where
    /// `u` runs along an axis (a wide letter set by a diagonal's reach
    /// from its middle stood two ems off).
    fn centre(&self, from: Point, u: Vector, half: Vector, ring: f64) -> Point {
        let side = |c: f64, h: f64| {
            if c.abs() < ALONG { 0.0 } else { c.signum() * h }
        };
        from + u * ((GAP + ring) / self.scale) + Vector::new(side(u.x, half.x), side(u.y, half.y))
    }

    /// The curves' segments that a box of half-size `half` on a ring
    /// out to `ring` about `from` may meet.
    fn curves_near(&self, from: Point, half: Vector, ring: f64) -> Vec<(Point, Point)> {
        let out = (GAP + ring + 8.0) / self.scale + 2.0 * (half.x + half.y);
        (self.curves.iter())
            .filter(|(a, b)| point_segment_distance(from, *a, *b) < out)
            .copied()
            .collect()
    }

    /// The least room, page units, about the box `b` of the letter of
    /// `from` (to the curves, the dots, the letters set), capped at a
    /// letter's em; `None` where the box meets one of them, stands within
    /// [`DOT_ROOM`] of a dot ([`POLE_ROOM`] of the pole, `dots`' first),
    /// or nearer another dot than its own. A box `led` (with a leader,
    /// which names its dot) may stand nearer another dot, but keeps its
    /// room from every dot, its own and those at its place included.
    fn room(
        &self,
        b: Boxed,
        from: Point,
        (curves, dots): (&[(Point, Point)], &[Point]),
        led: bool,
        rules: Rules,
    ) -> Option<f64> {
        let s = self.scale;
        let own = to_box(b, from);
        if led && own * s < DOT_ROOM {
            return None;
        }
        let nearer = if rules.nearer {
            NEARER * self.size
        } else {
            0.0
        };
        let mut least = self.size;
        for (k, q) in dots.iter().enumerate() {
            if rules.pairs && k > 0 && !self.beyond(b, from, *q, led) {
                return None;
            }
            if !led && (*q - from).norm() * s < ONE_PLACE {
                continue;
            }
            let d = to_box(b, *q);
            let keep = if k == 0 { POLE_ROOM } else { DOT_ROOM };
            // Its middle nearer its own dot too: a wide letter under two
            // dots, its box by both, reads as either ("90°′" between two
            // dots of the dashed curve at r = 1, l = 52 r in (a)).
            let middle = (*q - b.0).norm() - (from - b.0).norm();
            if d * s < keep || (!led && ((d - own) * s < nearer || middle * s < nearer)) {
                return None;
            }
            least = least.min(d * s - keep);
        }
        // Its dot seen from it across no line: a letter beyond a curve
        // from its dot reads as that curve's, its dot left bare ("0°"
        // over the wedge's two strands, its dot under them, at r = 1,
        // l = 1.07 r on 4.5 in).
        if !led && rules.sight && self.across(b, from, curves) {
            return None;
        }
        self.clear(b, curves, rules.lines)
            .map(|room| room.min(least))
    }

    /// Whether a line of the `curves` or a dotted jump runs between the
    /// box `b` and its dot `from`: across the way from [`LEADER_SHORT`]
    /// off the dot (past its own curve there) to the box's nearest point.
    fn across(&self, b: Boxed, from: Point, curves: &[(Point, Point)]) -> bool {
        let (a, start) = self.leader(b, from);
        // `leader` runs from the box to short of the dot: the same way.
        (curves.iter().chain(&self.jumps)).any(|(p, q)| crossing(a, start, *p, *q).is_some())
    }

    /// Whether the box `b` of the letter of `from` (or, `led`, its
    /// leader's start) stands beyond `from` away from the dot `q` where
    /// the two are a pair ([`PAIR`]); true where they are not.
    fn beyond(&self, b: Boxed, from: Point, q: Point, led: bool) -> bool {
        let apart = (from - q).norm() * self.scale;
        if !(ONE_PLACE..PAIR * self.size).contains(&apart) {
            return true;
        }
        let u = (from - q).normalize();
        if led {
            let (a, _) = self.leader(b, from);
            return (a - from).dot(&u) > 0.0;
        }
        let (c, h) = b;
        let nearest = (c - from).dot(&u) - h.x * u.x.abs() - h.y * u.y.abs();
        nearest >= 0.0
    }

    /// Whether a leader from `a` to `end` (world) would cross a leader set
    /// before it or run through a letter set before it (two leaders
    /// crossed in an X at r = 1, l = 2.97 r, e = −1.2 r: the twelfth
    /// review).
    fn leader_blocked(&self, a: Point, end: Point) -> bool {
        (self.leaders.iter()).any(|(p, q)| crossing(a, end, *p, *q).is_some())
            || (self.boxes.iter())
                .any(|o| segment_to_box(*o, a, end) * self.scale < LEADER_CLEAR * self.size)
    }

    /// Whether the letter `b` led to `from` by the leader `a`–`end`
    /// (world) could be read as another's: its box within
    /// [`LED_DOT_ROOM`] of another of the `dots` (the pole first), its
    /// leader within [`DOT_ROOM`] of one ([`POLE_ROOM`] of the pole: a
    /// leader through the × reads as pointing at *O*), or its start within
    /// [`START_ROOM`] of another letter.
    fn astray(&self, b: Boxed, (a, end): (Point, Point), from: Point, dots: &[Point]) -> bool {
        let s = self.scale;
        let mut others =
            (dots.iter().enumerate()).filter(|(_, q)| (**q - from).norm() * s >= ONE_PLACE);
        let near_dot = others.any(|(k, q)| {
            let keep = if k == 0 { POLE_ROOM } else { DOT_ROOM };
            to_box(b, *q) * s < LED_DOT_ROOM * self.size
                || point_segment_distance(*q, a, end) * s < keep
        });
        let shared = (self.boxes.iter()).any(|o| to_box(*o, a) * s < START_ROOM * self.size);
        near_dot || shared
    }

    /// The least room, page units, between the box `b` and the curves and
    /// the letters set, capped at an em; `None` where it meets one.
    fn clear(&self, b: Boxed, curves: &[(Point, Point)], lines: bool) -> Option<f64> {
        let s = self.scale;
        let (c, h) = b;
        let (lo, hi) = (self.inside.min(), self.inside.max());
        if c.x - h.x < lo.x || c.x + h.x > hi.x || c.y - h.y < lo.y || c.y + h.y > hi.y {
            return None;
        }
        let mut least = self.size;
        // A segment whose box lies farther off than an em and the room
        // changes nothing: passed over before its distance is measured
        // (with a margin for the rounding of the two measures).
        let far = (self.size + ROOM) * (1.0 + 1e-9) + 1e-9;
        for (p, q) in curves.iter().chain(&self.jumps) {
            if boxes_gap(b, *p, *q) * s > far {
                continue;
            }
            let d = segment_to_box(b, *p, *q) * s;
            if d < ROOM {
                return None;
            }
            least = least.min(d - ROOM);
        }
        for (p, q) in self.leaders.iter().filter(|_| lines) {
            let d = segment_to_box(b, *p, *q) * s;
            // A leader's start is its letter's: another letter by it
            // would share the leader, and one on its way stand on it.
            if d < LEADER_CLEAR * self.size || to_box(b, *p) * s < START_ROOM * self.size {
                return None;
            }
            least = least.min(d - ROOM);
        }
        for o in &self.boxes {
            let keep = if Some(*o) == self.pole {
                POLE_LETTER_ROOM * self.size
            } else if lines && level(b, *o) {
                LINE_ROOM * self.size
            } else {
                ROOM
            };
            let gap = boxes_apart(b, *o) * s;
            if gap < keep {
                return None;
            }
            least = least.min(gap - keep);
        }
        Some(least)
    }
}

/// The sixteen directions tried, every 22.5° from +x.
fn directions() -> impl Iterator<Item = Vector> {
    (0..16).map(|k| {
        let (s, c) = (std::f64::consts::PI / 8.0 * k as f64).sin_cos();
        Vector::new(c, s)
    })
}

/// The distance from the point `p` to the box `b` (0 inside).
fn to_box((c, h): Boxed, p: Point) -> f64 {
    let dx = ((p.x - c.x).abs() - h.x).max(0.0);
    let dy = ((p.y - c.y).abs() - h.y).max(0.0);
    dx.hypot(dy)
}

/// The distance from the segment `p`–`q` to the box `b` (0 where it
/// meets it).
fn segment_to_box(b: Boxed, p: Point, q: Point) -> f64 {
    let (c, h) = b;
    if to_box(b, p) == 0.0 || to_box(b, q) == 0.0 {
        return 0.0;
    }
    let corners = [
        Point::new(c.x - h.x, c.y - h.y),
        Point::new(c.x + h.x, c.y - h.y),
        Point::new(c.x + h.x, c.y + h.y),
        Point::new(c.x - h.x, c.y + h.y),
    ];
    (corners.iter().zip(corners.iter().cycle().skip(1)))
        .map(|(a, b)| segment_distance(*a, *b, p, q))
        .fold(f64::INFINITY, f64::min)
}

/// The gap between the box `b` and the box of the segment `p`–`q`, the
/// larger of its two axes' (0 where they meet): never more than the
/// distance from the segment to `b`.
fn boxes_gap((c, h): Boxed, p: Point, q: Point) -> f64 {
    let gap = |lo: f64, hi: f64, c: f64, h: f64| (lo - (c + h)).max((c - h) - hi).max(0.0);
    gap(p.x.min(q.x), p.x.max(q.x), c.x, h.x).max(gap(p.y.min(q.y), p.y.max(q.y), c.y, h.y))
}

/// Whether two boxes are level: on one line, their heights overlapping.
fn level((a, ha): Boxed, (b, hb): Boxed) -> bool {
    (a.y - b.y).abs() < ha.y + hb.y
}

/// The gap between two boxes (0 where they meet).
fn boxes_apart((a, ha): Boxed, (b, hb): Boxed) -> f64 {
    let dx = ((a.x - b.x).abs() - ha.x - hb.x).max(0.0);
    let dy = ((a.y - b.y).abs() - ha.y - hb.y).max(0.0);
    dx.hypot(dy)
}
