//! Ng Fig. 2: the free-body diagram of a block on a plane tilted at φ, at
//! the instant it starts to slide: its weight mg with the components
//! mg sin φ down the plane and mg cos φ into it, the normal reaction N and
//! the friction μN up the plane, whence mg sin φ = μ mg cos φ (eq. 9) and
//! μ = tan φ (eq. 10). The tilt is the figure's angle (45° on Ng's rig).

use super::{Ctx, Sheet, short};
use crate::analytic::statics::mu_from_tilt_degrees;
use crate::diagram::Plot;
use crate::error::{Error, Field, Result};
use crate::figure::{Figure, Item, RichText, Role, Shape, TextSize};
use crate::geom::{Frame, Point, Vector};

/// The side of the block, world units (the plane is 1 long).
const SIDE: f64 = 0.2;

/// The length of the weight's arrow, world units.
const WEIGHT: f64 = 0.42;

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
    let incline = Incline::new(ctx, mu);
    let world = Frame::new(
        Point::new(-0.12, -0.06),
        Point::new(incline.foot.x + 0.12, incline.top.y + 0.06),
    );
    let rect =
        Frame::from_origin_size(16.0, 16.0, page.width() - 32.0, page.height() - 32.0 - 64.0);
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
    sheet.notes(Point::new(20.0, page.height() - 60.0), &notes(tilt, mu));
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
    /// The lengths of N's and the friction's arrows.
    normal: f64,
    friction: f64,
}

impl Incline {
    fn new(ctx: &Ctx, mu: f64) -> Self {
        let (sin, cos) = (ctx.angle.sin(), ctx.angle.cos());
        let u = Vector::new(cos, sin);
        let n = Vector::new(-sin, cos);
        let length = 1.0;
        let o = Point::origin();
        let top = o + u * length;
        let contact = o + u * (0.55 * length);
        let g = contact + n * (0.5 * SIDE);
        let normal = WEIGHT * cos;
        // Friction acts in the contact face: drawn from the block's uphill
        // face, parallel to the plane and just clear of its line, so that the
        // arrow reads as a force and not as the plane's edge.
        let clear = n * (0.1 * SIDE);
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
            friction: mu * normal,
        }
    }

    /// The plane on its hatched ground, the block and its centre G.
    fn plane_and_block(&self) -> Vec<Item> {
        let (u, n, contact) = (self.u, self.n, self.contact);
        vec![
            Item::new(
                "plane",
                Role::Frame,
                Shape::Polyline {
                    points: vec![self.o, self.top, self.foot],
                    closed: true,
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
        ]
    }

    /// The weight, N and the friction, and the weight's components along
    /// and into the plane.
    fn forces(&self) -> Vec<Item> {
        let arrow = |id: &str, role: Role, from: Point, to: Point| {
            Item::new(id, role, Shape::Arrow { from, to })
        };
        let (g, u, n) = (self.g, self.u, self.n);
        let down = Vector::new(0.0, -1.0);
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
            arrow(
                "component-along",
                Role::Auxiliary,
                g,
                g - u * (WEIGHT * self.sin),
            ),
            arrow(
                "component-across",
                Role::Auxiliary,
                g,
                g - n * (WEIGHT * self.cos),
            ),
        ]
    }

    /// The tilt φ at the foot, φ again between the weight and its
    /// component into the plane, and the components' right angle.
    fn angles(&self) -> Vec<Item> {
        let (u, n, g) = (self.u, self.n, self.g);
        // The angle between the weight and its component into the plane.
        let into = (-n).y.atan2((-n).x);
        vec![
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
        ]
    }

    /// The forces' names at their arrows' heads, each tried first beyond
    /// its head, except the weight's component along the plane, tried
    /// first on its side away from the weight: at steep tilts the two
    /// heads come together and their names, set side by side, read as
    /// one ("mg sin φ mg").
    fn labels(&self) -> Vec<Item> {
        let (g, u, n) = (self.g, self.u, self.n);
        let down = Vector::new(0.0, -1.0);
        [
            ("weight", g + down * WEIGHT, "*mg*", down),
            ("normal", self.face + n * self.normal, "*N*", n),
            ("friction", self.friction_at + u * self.friction, "μ*N*", u),
            ("along", g - u * (WEIGHT * self.sin), "*mg* sin φ", n),
            ("across", g - n * (WEIGHT * self.cos), "*mg* cos φ", -n),
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
