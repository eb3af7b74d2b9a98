//! The quadric crank chain (four-bar), textbook §34, Fig. 60 (a).

use crate::angle::Angle;
use crate::error::{Error, Field, Input, Result, positive};
use crate::geom::{Point, Vector, cross, perp};
use crate::mechanism::in_range;
use std::f64::consts::PI;

/// Default relative tolerance of the quadric chain: how far (relative to
/// the link lengths) a pose may lie outside the reach of the crank and still
/// be taken as the limit (a toggle), how nearly the coupler and lever must
/// line up to count as a toggle, and how nearly s + l = p + q makes a change
/// point.
pub const CLOSURE_TOLERANCE: f64 = 1e-12;

/// The two ways of assembling the chain at one crank angle.
///
/// The pin A = O_bc lies on one side of the diagonal from the crank pin
/// B = O_ab to the lever's pivot O_cd: **open** is the left side of the
/// directed line B → O_cd (at θ = 90° the coupler and frame do not cross),
/// **crossed** the right side.
///
/// Branch rule at a toggle or change point, where A lies on the diagonal:
/// the position is the one common point of both modes (at the one pose
/// where B = O_cd, possible only when a = d at θ = 0, it is the limit as θ
/// decreases to 0); the rates of a mode at a change point are the limits
/// as θ decreases to the change point, that is, those of the branch that
/// carries that mode's name just counter-clockwise of it. (A parallelogram
/// is then open for 0 ≤ θ < 180° and crossed for 180° ≤ θ < 360°: the
/// side of the diagonal changes as the chain passes through the line.)
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Assembly {
    /// A to the left of B → O_cd.
    Open,
    /// A to the right of B → O_cd.
    Crossed,
}

crate::error::parse_by_name!(Assembly);

impl Assembly {
    /// The name on the command line: `open`, `crossed`.
    pub fn name(&self) -> &'static str {
        match self {
            Assembly::Open => "open",
            Assembly::Crossed => "crossed",
        }
    }

    /// The assembly mode of that name; the error lists the names.
    pub fn from_name(name: &str) -> Result<Self> {
        [Assembly::Open, Assembly::Crossed]
            .into_iter()
            .find(|a| a.name() == name)
            .ok_or_else(|| {
                Error::invalid(
                    Input::Assembly,
                    format!("unknown assembly '{name}': expected open or crossed"),
                )
            })
    }

    fn sign(self) -> f64 {
        match self {
            Assembly::Open => 1.0,
            Assembly::Crossed => -1.0,
        }
    }
}

/// Grashof's classification by the shortest s, longest l and other two
/// lengths p, q.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum GrashofClass {
    /// s + l < p + q, the crank a shortest: the crank turns fully, the lever
    /// rocks.
    CrankRocker,
    /// s + l < p + q, the frame d shortest: crank and lever both turn fully
    /// (drag link).
    DoubleCrank,
    /// s + l < p + q, the lever c shortest: the lever turns fully, the crank
    /// rocks.
    RockerCrank,
    /// s + l < p + q, the coupler b shortest: crank and lever rock, the
    /// coupler turns fully relative to both.
    DoubleRocker,
    /// s + l = p + q (within the tolerance), for example a + c = b + d: the
    /// chain can lie flat in one line, where the two assembly modes meet
    /// (a parallelogram, a kite).
    ChangePoint,
    /// s + l > p + q: no link turns fully relative to another.
    TripleRocker,
}

/// Where the crank can go: the crank angle θ, folded into [0, π] as
/// min(θ, 2π − θ), must lie in [`CrankReach::lower`, `CrankReach::upper`].
///
/// The reach is the same for both assembly modes. At a limit the coupler
/// and lever lie in one line (a toggle): the crank cannot pass it and must
/// turn back.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CrankReach {
    lower: f64,
    upper: f64,
}

impl CrankReach {
    /// Smallest folded crank angle reached, in radians (0: the crank passes
    /// θ = 0).
    pub fn lower(&self) -> f64 {
        self.lower
    }

    /// Largest folded crank angle reached, in radians (π: the crank passes
    /// θ = 180°).
    pub fn upper(&self) -> f64 {
        self.upper
    }

    /// Whether the crank turns a full revolution.
    pub fn is_full(&self) -> bool {
        self.lower == 0.0 && self.upper == PI
    }

    /// The limits of the crank's range as angles in [0, 2π), where the crank
    /// must turn back; empty when it turns fully. With both limits the crank
    /// swings in one of two separate arcs, [lower, upper] or
    /// [2π − upper, 2π − lower].
    pub fn limits(&self) -> Vec<f64> {
        let mut out = Vec::new();
        for t in [self.lower, self.upper] {
            if t > 0.0 && t < PI {
                out.push(t);
                out.push(2.0 * PI - t);
            }
        }
        out.sort_by(f64::total_cmp);
        out
    }

    /// Whether the crank reaches `angle` (boundaries included).
    pub fn reaches(&self, angle: Angle) -> bool {
        let t = angle.radians();
        let folded = t.min(2.0 * PI - t);
        folded >= self.lower && folded <= self.upper
    }
}

/// A quadric crank chain: crank a, coupler b, lever c, frame d, validated
/// once.
///
/// Frame: the crank's fixed pivot C = O_ad at the origin, the lever's fixed
/// pivot O_cd at (d, 0); the crank angle θ counter-clockwise from +x; crank
/// pin B = O_ab, coupler–lever pin A = O_bc (the textbook's letters as for
/// the slider-crank: C, B, A). Angular rates are per unit crank angle
/// (multiply by ω, ω² for a crank turning at constant ω), counter-clockwise
/// positive.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct QuadricChain {
    a: f64,
    b: f64,
    c: f64,
    d: f64,
    tolerance: f64,
}

impl QuadricChain {
    /// Validates the four lengths (each finite, positive, within
    /// [`crate::mechanism::MIN_LENGTH`, `crate::mechanism::MAX_LENGTH`]); the longest must be
    /// shorter than the other three together, else the chain is rigid or
    /// cannot close. Uses [`CLOSURE_TOLERANCE`].
    pub fn new(crank: f64, coupler: f64, lever: f64, frame: f64) -> Result<Self> {
        Self::with_tolerance(crank, coupler, lever, frame, CLOSURE_TOLERANCE)
    }

    /// As [`QuadricChain::new`] with an explicit relative `tolerance`
    /// (finite, in [0, 1e-3]).
    pub fn with_tolerance(
        crank: f64,
        coupler: f64,
        lever: f64,
        frame: f64,
        tolerance: f64,
    ) -> Result<Self> {
        let a = in_range(Field::Crank, positive(Field::Crank, crank)?)?;
        let b = in_range(Field::Coupler, positive(Field::Coupler, coupler)?)?;
        let c = in_range(Field::Lever, positive(Field::Lever, lever)?)?;
        let d = in_range(Field::Frame, positive(Field::Frame, frame)?)?;
        if !(0.0..=1e-3).contains(&tolerance) {
            return Err(Error::OutOfRange {
                name: Field::Tolerance,
                value: tolerance,
                reason: "give a relative tolerance between 0 and 1e-3".into(),
            });
        }
        let longest = a.max(b).max(c).max(d);
        let rest = a + b + c + d - longest;
        if longest >= rest {
            return Err(Error::OutOfRange {
                name: Field::LongestLink,
                value: longest,
                reason: format!(
                    "the longest link must be shorter than the other three together ({rest}), else the chain cannot move"
                ),
            });
        }
        Ok(Self {
            a,
            b,
            c,
            d,
            tolerance,
        })
    }

    /// Crank length a (C to B).
    pub fn crank(&self) -> f64 {
        self.a
    }

    /// Coupler length b (B to A).
    pub fn coupler(&self) -> f64 {
        self.b
    }

    /// Lever length c (O_cd to A).
    pub fn lever(&self) -> f64 {
        self.c
    }

    /// Frame length d (C to O_cd).
    pub fn frame(&self) -> f64 {
        self.d
    }

    /// The relative tolerance in use.
    pub fn tolerance(&self) -> f64 {
        self.tolerance
    }

    /// The lever's fixed pivot O_cd = (d, 0).
    pub fn lever_pivot(&self) -> Point {
        Point::new(self.d, 0.0)
    }

    /// The Grashof class (ties s + l = p + q within the tolerance are
    /// [`GrashofClass::ChangePoint`]).
    pub fn grashof(&self) -> GrashofClass {
        let mut sorted = [self.a, self.b, self.c, self.d];
        sorted.sort_by(f64::total_cmp);
        let excess = (sorted[0] + sorted[3]) - (sorted[1] + sorted[2]);
        if excess.abs() <= self.tolerance * (sorted[0] + sorted[3]) {
            GrashofClass::ChangePoint
        } else if excess > 0.0 {
            GrashofClass::TripleRocker
        } else if sorted[0] == self.d {
            GrashofClass::DoubleCrank
        } else if sorted[0] == self.a {
            GrashofClass::CrankRocker
        } else if sorted[0] == self.c {
            GrashofClass::RockerCrank
        } else {
            GrashofClass::DoubleRocker
        }
    }

    /// The crank's reach: the diagonal |O_cd − B| runs from |a − d| at θ = 0
    /// to a + d at θ = π and must lie within [|b − c|, b + c].
    pub fn reach(&self) -> CrankReach {
        let (a, b, c, d) = (self.a, self.b, self.c, self.d);
        let lower = if (a - d).abs() < (b - c).abs() {
            self.diagonal_angle((b - c).abs())
        } else {
            0.0
        };
        let upper = if a + d > b + c {
            self.diagonal_angle(b + c)
        } else {
            PI
        };
        CrankReach { lower, upper }
    }

    /// The crank angle in [0, π] where the diagonal |O_cd − B| equals `k`,
    /// by half angles (no cancellation near 0 or π).
    fn diagonal_angle(&self, k: f64) -> f64 {
        let (a, d) = (self.a, self.d);
        let sin2 = ((k - a + d) * (k + a - d)).max(0.0);
        let cos2 = ((a + d - k) * (a + d + k)).max(0.0);
        2.0 * sin2.sqrt().atan2(cos2.sqrt())
    }

    /// The chain at crank angle `angle` in assembly mode `mode`.
    ///
    /// Errors with [`Error::OutOfRange`] when the crank does not reach the
    /// angle (beyond a toggle by more than the tolerance); within the
    /// tolerance of a toggle the pose is the toggle.
    pub fn pose(&self, angle: Angle, mode: Assembly) -> Result<QuadricPose> {
        QuadricPose::new(*self, angle, mode)
    }
}

/// Angular velocities and accelerations of the coupler and lever per unit
/// crank rate, for a crank turning at constant speed (counter-clockwise
/// positive; multiply velocities by ω and accelerations by ω²).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct LinkRates {
    /// Coupler b: dλ_b/dθ.
    pub coupler_velocity: f64,
    /// Lever c: dλ_c/dθ.
    pub lever_velocity: f64,
    /// Coupler b: d²λ_b/dθ².
    pub coupler_acceleration: f64,
    /// Lever c: d²λ_c/dθ².
    pub lever_acceleration: f64,
}

/// The quadric chain at one crank angle and assembly mode.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct QuadricPose {
    chain: QuadricChain,
    angle: Angle,
    mode: Assembly,
    b: Point,
    /// A − B, the coupler.
    coupler: Vector,
    /// A − O_cd, the lever.
    lever: Vector,
}

impl QuadricPose {
    fn new(chain: QuadricChain, angle: Angle, mode: Assembly) -> Result<Self> {
        // Lengths scaled by a power of two near the longest (exact), so
        // that the products of four lengths below neither overflow nor
        // underflow at any scale; the pose is scaled back at the end.
        let scale = unit_scale(chain.a.max(chain.b).max(chain.c).max(chain.d));
        let (a, b, c, d) = (
            chain.a / scale,
            chain.b / scale,
            chain.c / scale,
            chain.d / scale,
        );
        let (sin, cos) = (angle.sin(), angle.cos());
        let pin = Point::new(a * cos, a * sin);
        // 1 ± cos θ without cancellation.
        let (plus, minus) = if cos >= 0.0 {
            (1.0 + cos, sin * sin / (1.0 + cos))
        } else {
            (sin * sin / (1.0 - cos), 1.0 - cos)
        };
        // The diagonal f = O_cd − B, |f|² = (a − d)² + 2ad(1 − cos θ).
        let f = Vector::new((d - a) + a * minus, -a * sin);
        let f2 = (a - d) * (a - d) + 2.0 * a * d * minus;
        let fl = f2.sqrt();
        // Unit diagonal B → O_cd; when B = O_cd (a = d at θ = 0) its limit
        // as θ decreases to 0.
        let unit = if fl == 0.0 {
            Vector::new(0.0, -1.0)
        } else {
            f / f.norm()
        };
        // (b + c)² − |f|² and |f|² − (b − c)², each from exact differences
        // of the lengths: the two factors of the height that vanish at the
        // toggles.
        let (grashof, across) = (
            exact_difference(b + c, a + d, b, c, a, d) * (a + b + c + d),
            exact_difference(a + c, b + d, a, c, b, d) * exact_difference(a + b, c + d, a, b, c, d),
        );
        let (outer, inner) = (grashof + 2.0 * a * d * plus, across + 2.0 * a * d * minus);
        let tol = chain.tolerance * (b + c) * (b + c);
        if outer < -tol || inner < -tol {
            return Err(Error::OutOfRange {
                name: Field::Angle,
                value: angle.degrees(),
                reason: format!("the crank of this chain reaches only {}", describe(&chain)),
            });
        }
        // Within rounding of a toggle (or beyond it within the tolerance),
        // the toggle itself. The factors are squares of lengths: the
        // tolerance on them would be its square root on the height. Each is
        // the sum of two terms, each computed to a few ulps (the length
        // differences exactly): its rounding is a few ulps of the terms,
        // not of the lengths' square, so that a change point approached
        // (s + l = p + q, where the first term is 0) is not taken for it
        // 10⁻⁵° away.
        let rounding = |x: f64, term: f64, angular: f64| {
            if x <= 8.0 * f64::EPSILON * (term.abs() + angular) {
                0.0
            } else {
                x
            }
        };
        let outer = rounding(outer, grashof, 2.0 * a * d * plus);
        let inner = rounding(inner, across, 2.0 * a * d * minus);
        // Distances along the diagonal from B and from O_cd to the foot of
        // the perpendicular from A, and its height.
        let (along, back, height) = if fl == 0.0 {
            (0.0, 0.0, b)
        } else {
            let along = ((b - c) * (b + c) + f2) / (2.0 * fl);
            let back = ((b - c) * (b + c) - f2) / (2.0 * fl);
            let height = (outer * inner).sqrt() / (2.0 * fl);
            (along, back, height.min(b))
        };
        let side = perp(&unit) * (height * mode.sign());
        let coupler = (unit * along + side) * scale;
        let lever = (unit * back + side) * scale;
        Ok(Self {
            chain,
            angle,
            mode,
            b: pin * scale,
            coupler,
            lever,
        })
    }

    /// The chain.
    pub fn chain(&self) -> &QuadricChain {
        &self.chain
    }

    /// The crank angle.
    pub fn angle(&self) -> Angle {
        self.angle
    }

    /// The assembly mode.
    pub fn mode(&self) -> Assembly {
        self.mode
    }

    /// The crank's pivot C = O_ad (the origin).
    pub fn c(&self) -> Point {
        Point::origin()
    }

    /// The crank pin B = O_ab.
    pub fn b(&self) -> Point {
        self.b
    }

    /// The coupler–lever pin A = O_bc.
    pub fn a(&self) -> Point {
        self.b + self.coupler
    }

    /// The coupler vector A − B (length b).
    pub fn coupler_vector(&self) -> Vector {
        self.coupler
    }

    /// The lever vector A − O_cd (length c).
    pub fn lever_vector(&self) -> Vector {
        self.lever
    }

    /// The coupler's angle λ_b, of A − B from +x, in (−π, π].
    pub fn coupler_angle(&self) -> f64 {
        self.coupler.y.atan2(self.coupler.x)
    }

    /// The lever's angle λ_c, of A − O_cd from +x, in (−π, π].
    pub fn lever_angle(&self) -> f64 {
        self.lever.y.atan2(self.lever.x)
    }

    /// Whether the coupler and lever lie in one line within the tolerance
    /// (a toggle or a change point).
    pub fn is_toggle(&self) -> bool {
        let (b, c) = (self.chain.b, self.chain.c);
        cross(&self.coupler, &self.lever).abs() <= self.chain.tolerance * b * c
    }

    /// Angular velocities and accelerations of coupler and lever per unit
    /// crank rate; `None` at a toggle that limits the crank's range, where
    /// they grow without bound (a crank at constant speed cannot pass it).
    /// At a change point they are the limits of the branch named by the
    /// mode (see [`Assembly`]): finite velocities, and accelerations 0.
    pub fn rates(&self) -> Option<LinkRates> {
        let ua = self.b.coords;
        let (ub, uc) = (self.coupler, self.lever);
        if !self.is_toggle() {
            let den = cross(&ub, &uc);
            let wb = -cross(&ua, &uc) / den;
            let wc = -cross(&ua, &ub) / den;
            let r = ua + ub * (wb * wb) - uc * (wc * wc);
            let q = -perp(&r);
            return Some(LinkRates {
                coupler_velocity: wb,
                lever_velocity: wc,
                coupler_acceleration: cross(&q, &uc) / den,
                lever_acceleration: cross(&q, &ub) / den,
            });
        }
        self.change_point_rates()
    }

    /// Rates where the whole chain lies flat on the frame line: the two
    /// branches through the node have coupler rates λ′ solving
    /// b_x(c_x − b_x) λ′² − 2 a_x b_x λ′ + a_x(c_x − a_x) = 0 (the second
    /// order of the loop equation), and zero angular accelerations (its
    /// third order). The branch is picked by the side of the diagonal just
    /// counter-clockwise of the node (at the node itself, or within the
    /// tolerance counter-clockwise of it), or the mode's branch clockwise of
    /// it for a pose within the tolerance clockwise of it.
    fn change_point_rates(&self) -> Option<LinkRates> {
        let tol = self.chain.tolerance;
        let flat = self.b.y.abs() <= tol * self.chain.a
            && self.coupler.y.abs() <= tol * self.chain.b
            && self.lever.y.abs() <= tol * self.chain.c;
        if !flat {
            return None;
        }
        let (ax, bx, cx) = (self.b.x, self.coupler.x, self.lever.x);
        let fx = self.chain.d - ax;
        let q2 = bx * (cx - bx);
        let q1 = -2.0 * ax * bx;
        let q0 = ax * (cx - ax);
        let roots: Vec<f64> = if q2.abs() <= tol * (bx * bx + cx * cx) {
            vec![-q0 / q1]
        } else {
            let disc = (q1 * q1 - 4.0 * q2 * q0).max(0.0).sqrt();
            let q = -0.5 * (q1 + q1.signum() * disc);
            let mut r = vec![q / q2];
            if q != 0.0 {
                r.push(q0 / q);
            }
            r
        };
        // Within the tolerance but just clockwise of the node (sin θ cos θ
        // < 0), the pose lies on the branch whose mode is the other one
        // counter-clockwise of it: the side of the diagonal changes there.
        let before = self.b.y * self.b.x < 0.0;
        let want = if before {
            -self.mode.sign()
        } else {
            self.mode.sign()
        };
        let wb = roots
            .into_iter()
            .find(|&w| (bx * (fx * w + ax)) * want > 0.0 && w.is_finite())?;
        Some(LinkRates {
            coupler_velocity: wb,
            lever_velocity: (ax + bx * wb) / cx,
            coupler_acceleration: 0.0,
            lever_acceleration: 0.0,
        })
    }
}

/// (p + q) − (r + s), given `sum` = p + q and `other` = r + s as rounded,
/// to within an ulp of the result: the roundings of both sums (Knuth's
/// two-sum) added back after the difference, which is exact where it
/// cancels (Sterbenz). Zero exactly when p + q = r + s exactly.
fn exact_difference(sum: f64, other: f64, p: f64, q: f64, r: f64, s: f64) -> f64 {
    let lost = |total: f64, x: f64, y: f64| {
        let y_part = total - x;
        (x - (total - y_part)) + (y - y_part)
    };
    (sum - other) + (lost(sum, p, q) - lost(other, r, s))
}

/// The power of two nearest below `longest` (a positive, finite length):
/// dividing by it is exact and brings the longest link into [1, 2).
fn unit_scale(longest: f64) -> f64 {
    2f64.powi(longest.log2().floor() as i32)
}

fn describe(chain: &QuadricChain) -> String {
    let reach = chain.reach();
    let (lo, hi) = (reach.lower.to_degrees(), reach.upper.to_degrees());
    if lo == 0.0 {
        format!("−{hi}° to {hi}°")
    } else if hi == 180.0 {
        format!("{lo}° to {}°", 360.0 - lo)
    } else {
        format!("{lo}° to {hi}° and {}° to {}°", 360.0 - hi, 360.0 - lo)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn validation_refuses_chains_that_cannot_move() {
        assert!(QuadricChain::new(1.0, 2.0, 3.0, 6.0).is_err());
        assert!(QuadricChain::new(1.0, 2.0, 3.0, 7.0).is_err());
        assert!(QuadricChain::new(1.0, 2.0, 3.0, 5.9).is_ok());
        assert!(QuadricChain::new(0.0, 2.0, 3.0, 4.0).is_err());
        assert!(QuadricChain::new(f64::NAN, 2.0, 3.0, 4.0).is_err());
        assert!(QuadricChain::with_tolerance(1.0, 2.0, 3.0, 4.0, -1.0).is_err());
    }

    #[test]
    fn a_change_point_approached_has_the_rates_of_its_branch() {
        // a, b, c, d = 1, 2, 3, 4: a + d = b + c, all four links in line at
        // θ = 180°. There the loop's second order, with a_x = −1, b_x = 2,
        // c_x = −3, is −10 λ′² + 4 λ′ + 2 = 0: λ′ = (1 ± √6)/5, the lever's
        // (a_x + b_x λ′)/c_x. Clockwise of the node the open chain is on the
        // root (1 − √6)/5 (its rates at 179.9° are within 10⁻³ of it).
        let m = QuadricChain::new(1.0, 2.0, 3.0, 4.0).unwrap();
        let six = 6f64.sqrt();
        let (low, high) = ((1.0 - six) / 5.0, (1.0 + six) / 5.0);
        let lever = |w: f64| (-1.0 + 2.0 * w) / -3.0;
        let rates = |deg: f64, mode| {
            let p = m.pose(Angle::from_degrees(deg).unwrap(), mode).unwrap();
            p.rates().map(|r| (r.coupler_velocity, r.lever_velocity))
        };
        for deg in [179.9, 179.99999, 180.0 - 1e-9, 180.0 - 1e-12] {
            let (wb, wc) = rates(deg, Assembly::Open).expect("finite rates");
            assert!(
                (wb - low).abs() < 1e-3 && (wc - lever(low)).abs() < 1e-3,
                "{deg}: {wb} {wc}"
            );
            let (wb, _) = rates(deg, Assembly::Crossed).expect("finite rates");
            assert!((wb - high).abs() < 1e-3, "{deg} crossed: {wb}");
        }
        // At the node and counter-clockwise of it, the branch rule of
        // `Assembly`: the open chain continues the crossed one.
        for deg in [180.0, 180.0 + 1e-12, 180.001] {
            let (wb, _) = rates(deg, Assembly::Open).unwrap();
            assert!((wb - high).abs() < 1e-3, "{deg}: {wb}");
        }
    }

    #[test]
    fn grashof_classes() {
        use GrashofClass::*;
        let class = |a, b, c, d| QuadricChain::new(a, b, c, d).unwrap().grashof();
        assert_eq!(class(1.0, 3.0, 2.5, 3.2), CrankRocker);
        assert_eq!(class(3.0, 2.5, 3.2, 1.0), DoubleCrank);
        assert_eq!(class(3.0, 2.5, 1.0, 3.2), RockerCrank);
        assert_eq!(class(3.0, 1.0, 2.5, 3.2), DoubleRocker);
        assert_eq!(class(1.0, 3.0, 1.0, 3.0), ChangePoint);
        assert_eq!(class(3.0, 2.0, 3.0, 4.5), TripleRocker);
    }

    #[test]
    fn reach_of_a_crank_rocker_is_full_and_of_a_rocker_is_limited() {
        let full = QuadricChain::new(1.0, 3.0, 2.5, 3.2).unwrap().reach();
        assert!(full.is_full() && full.limits().is_empty());
        // Triple rocker: |f| = b + c at the limit, law of cosines.
        let m = QuadricChain::new(3.0, 2.0, 3.0, 4.5).unwrap();
        let r = m.reach();
        let cos = (9.0 + 20.25 - 25.0) / (2.0 * 3.0 * 4.5);
        assert!((r.upper() - f64::acos(cos)).abs() < 1e-15);
        assert_eq!(r.lower(), 0.0);
        assert!(m.pose(Angle::deg(170.0), Assembly::Open).is_err());
        let at = Angle::from_radians(r.upper()).unwrap();
        let toggle = m.pose(at, Assembly::Open).unwrap();
        assert!(toggle.is_toggle() && toggle.rates().is_none());
        assert_eq!(
            toggle.a(),
            m.pose(at, Assembly::Crossed).unwrap().a(),
            "both modes meet at a toggle"
        );
    }

    #[test]
    fn parallelogram_open_branch_translates_the_coupler() {
        let m = QuadricChain::new(1.0, 3.0, 1.0, 3.0).unwrap();
        for d in [0.0, 30.0, 90.0, 179.0] {
            let p = m.pose(Angle::deg(d), Assembly::Open).unwrap();
            let r = p.rates().unwrap();
            assert!(r.coupler_velocity.abs() < 1e-15, "{d}: {r:?}");
            assert!((r.lever_velocity - 1.0).abs() < 1e-15, "{d}");
        }
        // At θ = 180° the parallelogram is the crossed branch (the side of
        // the diagonal changes as the chain passes the line).
        let p = m.pose(Angle::deg(180.0), Assembly::Crossed).unwrap();
        assert_eq!(p.rates().unwrap().coupler_velocity, 0.0);
        // The anti-parallelogram at θ = 0: 2a/(a − d) from the node equation.
        let x = m
            .pose(Angle::deg(0.0), Assembly::Crossed)
            .unwrap()
            .rates()
            .unwrap();
        assert!((x.coupler_velocity + 1.0).abs() < 1e-15, "{x:?}");
    }
}
