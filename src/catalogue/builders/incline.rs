//! Ng Fig. 2: the free-body diagram of a block on a plane tilted at φ, at
//! the instant it starts to slide: its weight mg with the components
//! mg sin φ down the plane and mg cos φ into it, the normal reaction N and
//! the friction μN up the plane, whence mg sin φ = μ mg cos φ (eq. 9) and
//! μ = tan φ (eq. 10). The tilt is the figure's angle (45° on Ng's rig).

use super::{Ctx, Sheet, short, sig};
use crate::analytic::statics::mu_from_tilt_degrees;
use crate::diagram::Plot;
use crate::error::{Error, Field, Result};
use crate::figure::{Figure, Item, RichText, Role, Shape, TextSize};
use crate::geom::{Frame, Point, Vector};

/// The side of the block, world units (the plane is 1 long).
const SIDE: f64 = 0.2;

/// The length of the weight's arrow, world units.
const WEIGHT: f64 = 0.42;

/// The least length an arrow is drawn, world units (a third of the
/// block's side, three heads on the default page): near 90° the normal
/// reaction and the weight's component into the plane, near 0° the
/// friction and the component along it, are a few thousandths of the
/// weight, and at scale they were bare heads (at 89.58°, N = 0.0073 mg).
/// An arrow drawn longer is said so in the notes.
const LEAST: f64 = SIDE / 3.0;

/// Within this angle (degrees) of the weight a component of it is set
/// beside it, [`BESIDE`] off: at 89.58° the component along the plane
/// lay under the weight's arrow and was hidden.
const ALONG_WEIGHT: f64 = 10.0;

/// How far a component within [`ALONG_WEIGHT`] of the weight is set off
/// it, world units (a fifth of the block's side).
const BESIDE: f64 = SIDE / 5.0;

/// Within this angle (degrees) of upright the plane is drawn as a line
/// hatched underneath rather than a wedge: the wedge's upright side and
/// the plane, 0.4° apart at 89.58°, read as one double line.
const STEEP: f64 = 15.0;

/// How far off the plane the friction is drawn, world units (a third of
/// the block's side): a tenth of it read as a second line of the plane.
const FRICTION_OFF: f64 = SIDE / 3.0;

pub(in crate::catalogue) fn build(ctx: &Ctx) -> Result<Figure> {
    let page = ctx.page();
    let tilt = ctx.angle.degrees();
    if !(tilt > 0.0 && tilt < 90.0) {
        return Err(Error::OutOfRange {
            name: Field::Angle,
            value: tilt,
            reason: "the tilt of the plane is between 0° and 90°".into(),
        });
    }
    let mu = mu_from_tilt_degrees(tilt)?;
    let mut sheet = Sheet::new(ctx);
    sheet.mechanism(ctx, false, false);
    sheet.meta("tilt_deg", serde_json::json!(tilt));
    sheet.meta("mu", serde_json::json!(mu));
    let incline = Incline::new(ctx);
    let mut lines = notes(tilt, mu).to_vec();
    lines.extend(incline.lengthened());
    // Each line of the notes 18 units, 24 more under them.
    let room = 24.0 + 18.0 * lines.len() as f64;
    let world = incline.reach();
    let rect =
        Frame::from_origin_size(16.0, 16.0, page.width() - 32.0, page.height() - 36.0 - room);
    let mut plot = Plot::world("incline", rect, &world, false, ctx.tolerance, ctx.font)?
        .with_caption(&format!(
            "A block on a plane tilted at φ = {}°, on the point of sliding",
            short(tilt)
        ));
    let items = [
        incline.plane_and_block(),
        incline.forces(),
        incline.angles(),
        incline.labels(),
    ];
    for item in items.into_iter().flatten() {
        plot.push(item);
    }
    sheet.plot(plot);
    sheet.notes(Point::new(20.0, page.height() - room), &lines);
    Ok(sheet.finish())
}

/// The plane and the block on it, and where the forces act, world units
/// (the plane 1 long from its foot at the origin).
struct Incline {
    phi: f64,
    sin: f64,
    cos: f64,
    /// Up the plane.
    u: Vector,
    /// Out of the plane.
    n: Vector,
    /// The plane's foot, its top, and the point below its top.
    o: Point,
    top: Point,
    foot: Point,
    /// The middle of the block's face on the plane.
    contact: Point,
    /// The block's centre.
    g: Point,
    /// Where N is drawn from: the block's far face, on its line through G.
    face: Point,
    /// Where the friction is drawn from.
    friction_at: Point,
    /// The lengths of N's and the friction's arrows, each at least
    /// [`LEAST`]; the weight's components are as long as these.
    normal: f64,
    friction: f64,
}

impl Incline {
    fn new(ctx: &Ctx) -> Self {
        let (sin, cos) = (ctx.angle.sin(), ctx.angle.cos());
        let u = Vector::new(cos, sin);
        let n = Vector::new(-sin, cos);
        let length = 1.0;
        let o = Point::origin();
        let top = o + u * length;
        let contact = o + u * (0.55 * length);
        let g = contact + n * (0.5 * SIDE);
        // N = mg cos φ, μN = mg sin φ at the point of sliding.
        let normal = (WEIGHT * cos).max(LEAST);
        let friction = (WEIGHT * sin).max(LEAST);
        // Friction acts in the contact face: drawn from the block's uphill
        // face, parallel to the plane and clear of its line, so that the
        // arrow reads as a force and not as the plane's edge.
        let clear = n * FRICTION_OFF;
        Self {
            phi: ctx.angle.radians(),
            sin,
            cos,
            u,
            n,
            o,
            top,
            foot: Point::new(top.x, 0.0),
            contact,
            g,
            // N acts across the contact face; drawn on its line through G.
            face: g + n * (0.5 * SIDE),
            friction_at: contact + u * (0.5 * SIDE) + clear,
            normal,
            friction,
        }
    }

    /// The world frame the figure spans: the plane and its ground, and
    /// every arrow's head (at a shallow tilt N rises far above the
    /// plane's top, and ran off the page).
    fn reach(&self) -> Frame {
        let down = Vector::new(0.0, -1.0);
        let [along, across] = self.components();
        let heads = [
            self.g + down * WEIGHT,
            self.face + self.n * self.normal,
            self.friction_at + self.u * self.friction,
            along.1,
            across.1,
        ];
        let (lo, hi) = heads.iter().fold(
            (
                Point::new(-0.12, -0.06),
                Point::new(self.foot.x + 0.12, self.top.y + 0.06),
            ),
            |(lo, hi), p| {
                (
                    Point::new(lo.x.min(p.x - 0.06), lo.y.min(p.y - 0.06)),
                    Point::new(hi.x.max(p.x + 0.06), hi.y.max(p.y + 0.06)),
                )
            },
        );
        Frame::new(lo, hi)
    }

    /// Whether the weight's component along the plane (`along`) or into
    /// it lies within [`ALONG_WEIGHT`] of the weight.
    fn near_weight(&self, along: bool) -> bool {
        let off_weight = if along {
            90.0 - self.phi.to_degrees()
        } else {
            self.phi.to_degrees()
        };
        off_weight <= ALONG_WEIGHT
    }

    /// Where the weight's components start: at G, or [`BESIDE`] off it
    /// where one would lie along the weight (the one along the plane
    /// set away from the plane, the one into it set uphill).
    fn component_from(&self, along: bool) -> Point {
        match (along, self.near_weight(along)) {
            (true, true) => self.g + self.n * BESIDE,
            (false, true) => self.g + self.u * BESIDE,
            _ => self.g,
        }
    }

    /// The weight's component along the plane (down it) and into it,
    /// from where each starts to its head.
    fn components(&self) -> [(Point, Point); 2] {
        let along = self.component_from(true);
        let across = self.component_from(false);
        [
            (along, along - self.u * self.friction),
            (across, across - self.n * self.normal),
        ]
    }

    /// Where the name of the weight's component into the plane is tried
    /// first: beyond its head, or uphill where that head lies in the block
    /// (beyond it is the plane and its hatching) or the component is set
    /// beside the weight (beyond it is the weight's name).
    fn across_side(&self) -> Vector {
        if self.normal < 0.5 * SIDE || self.near_weight(false) {
            self.u
        } else {
            -self.n
        }
    }

    /// The notes' line naming the arrows drawn longer than to scale
    /// ([`LEAST`]), if any.
    fn lengthened(&self) -> Option<String> {
        let (names, share) = if WEIGHT * self.cos < LEAST {
            ("*N* and *mg* cos φ", self.cos)
        } else if WEIGHT * self.sin < LEAST {
            ("μ*N* and *mg* sin φ", self.sin)
        } else {
            return None;
        };
        Some(format!(
            "{names} ({} *mg*) are drawn longer than to scale, to be seen.",
            sig(share)
        ))
    }

    /// The plane on its hatched ground, the block and its centre G; within
    /// [`STEEP`] of upright the plane a line hatched underneath.
    fn plane_and_block(&self) -> Vec<Item> {
        let (u, n, contact) = (self.u, self.n, self.contact);
        let steep = 90.0 - self.phi.to_degrees() < STEEP;
        let plane = match steep {
            true => vec![self.o, self.top],
            false => vec![self.o, self.top, self.foot],
        };
        let mut items = vec![
            Item::new(
                "plane",
                Role::Frame,
                Shape::Polyline {
                    points: plane,
                    closed: !steep,
                },
            ),
            Item::new(
                "hatch-ground",
                Role::Frame,
                Shape::Hatch {
                    from: Point::new(-0.08, 0.0),
                    to: Point::new(self.foot.x + 0.08, 0.0),
                    side: Vector::new(0.0, -1.0),
                },
            ),
            // Open, so that the forces at its centre show.
            Item::new(
                "block",
                Role::Link,
                Shape::Polyline {
                    points: vec![
                        contact - u * (0.5 * SIDE),
                        contact + u * (0.5 * SIDE),
                        contact + u * (0.5 * SIDE) + n * SIDE,
                        contact - u * (0.5 * SIDE) + n * SIDE,
                    ],
                    closed: true,
                },
            ),
            Item::new("point-G", Role::Construction, Shape::Dot { centre: self.g }),
        ];
        // A steep plane is a line hatched on its solid side (no wedge).
        if steep {
            items.push(Item::new(
                "hatch-plane",
                Role::Frame,
                Shape::Hatch {
                    from: self.o,
                    to: self.top,
                    side: -n,
                },
            ));
        }
        items
    }

    /// The weight, N and the friction, and the weight's components along
    /// and into the plane.
    fn forces(&self) -> Vec<Item> {
        let arrow = |id: &str, role: Role, from: Point, to: Point| {
            Item::new(id, role, Shape::Arrow { from, to })
        };
        let (g, u, n) = (self.g, self.u, self.n);
        let down = Vector::new(0.0, -1.0);
        let [along, across] = self.components();
        vec![
            arrow("force-weight", Role::Force, g, g + down * WEIGHT),
            arrow(
                "force-normal",
                Role::Force,
                self.face,
                self.face + n * self.normal,
            ),
            arrow(
                "force-friction",
                Role::Force,
                self.friction_at,
                self.friction_at + u * self.friction,
            ),
            arrow("component-along", Role::Auxiliary, along.0, along.1),
            arrow("component-across", Role::Auxiliary, across.0, across.1),
        ]
    }

    /// The tilt φ at the foot, φ again between the weight and its
    /// component into the plane where that is drawn to scale, and the
    /// components' right angle. A component drawn longer than to scale
    /// lies inside the block near 90°, and its angle's letter stood
    /// outside the block, cut off from its arc (at 89.03°).
    fn angles(&self) -> Vec<Item> {
        let (u, n, g) = (self.u, self.n, self.g);
        // The angle between the weight and its component into the plane.
        let into = (-n).y.atan2((-n).x);
        let to_scale = WEIGHT * self.cos >= LEAST;
        let mut items = vec![
            Item::new(
                "angle-tilt",
                Role::Dimension,
                Shape::AngleMark {
                    vertex: self.o,
                    start: 0.0,
                    sweep: self.phi,
                    text: Some(RichText::italic("φ")),
                },
            ),
            Item::new(
                "angle-weight",
                Role::Dimension,
                Shape::AngleMark {
                    vertex: g,
                    start: into,
                    sweep: -self.phi,
                    text: Some(RichText::italic("φ")),
                },
            ),
            Item::new(
                "angle-components",
                Role::Dimension,
                Shape::RightAngle {
                    vertex: g,
                    u: -u,
                    v: -n,
                },
            ),
        ];
        if !to_scale {
            items.retain(|item| item.id != "angle-weight");
        }
        items
    }

    /// The forces' names at their arrows' heads, each tried first beyond
    /// its head, except the weight's component along the plane, tried
    /// first on its side away from the weight: at steep tilts the two
    /// heads come together and their names, set side by side, read as
    /// one ("mg sin φ mg").
    fn labels(&self) -> Vec<Item> {
        let (g, u, n) = (self.g, self.u, self.n);
        let down = Vector::new(0.0, -1.0);
        let [along, across] = self.components();
        [
            ("weight", g + down * WEIGHT, "*mg*", down),
            ("normal", self.face + n * self.normal, "*N*", n),
            ("friction", self.friction_at + u * self.friction, "μ*N*", u),
            ("along", along.1, "*mg* sin φ", n),
            ("across", across.1, "*mg* cos φ", self.across_side()),
        ]
        .into_iter()
        .map(|(id, at, text, toward)| {
            Item::new(
                format!("label-force-{id}"),
                Role::Label,
                Shape::Label {
                    anchor: at,
                    text: RichText::parse(text),
                    size: TextSize::Small,
                    toward: Some(toward),
                    line: None,
                },
            )
        })
        .collect()
    }
}

/// The notes: the balance along the plane (eq. 9) and μ = tan φ (eq. 10)
/// at this tilt.
fn notes(tilt: f64, mu: f64) -> [String; 2] {
    [
        "Along the plane: *mg* sin φ = μ*N* = μ*mg* cos φ (eq. 9), so μ = tan φ (eq. 10).".into(),
        format!(
            "φ = {}°: μ = tan φ = {}{}",
            short(tilt),
            short(mu),
            if tilt == 45.0 {
                " (Ng’s rig first slid at 45°: μ = 1)."
            } else {
                "."
            }
        ),
    ]
}
