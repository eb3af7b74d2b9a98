//! Gravity and the guides' friction in the running engine, against a
//! model written here from the free-body diagrams of each body (the
//! slider, the rod as a rigid body, the massless crank), with the
//! kinematics carried as second-order jets of x_A(θ) and φ(θ) and the
//! friction's sign found by trying both signs of the guides' reaction:
//! nothing of the library but the engine asked and its answers.

use nalgebra::{Matrix5, Vector5};
use slider_crank::dynamics::{Engine, GasForce, RodMass, TurningMoment};
use slider_crank::{Angle, SliderCrank};

/// A value with its first and second derivatives in θ.
#[derive(Clone, Copy, Debug)]
struct Jet(f64, f64, f64);

impl Jet {
    fn add(self, o: Jet) -> Jet {
        Jet(self.0 + o.0, self.1 + o.1, self.2 + o.2)
    }
    fn scale(self, k: f64) -> Jet {
        Jet(k * self.0, k * self.1, k * self.2)
    }
    fn mul(self, o: Jet) -> Jet {
        Jet(
            self.0 * o.0,
            self.1 * o.0 + self.0 * o.1,
            self.2 * o.0 + 2.0 * self.1 * o.1 + self.0 * o.2,
        )
    }
    fn sqrt(self) -> Jet {
        let v = self.0.sqrt();
        let d = self.1 / (2.0 * v);
        Jet(v, d, (self.2 - 2.0 * d * d) / (2.0 * v))
    }
    fn atan2(y: Jet, x: Jet) -> Jet {
        // d atan2 = (x dy − y dx)/(x² + y²).
        let q = x.0 * x.0 + y.0 * y.0;
        let num = x.0 * y.1 - y.0 * x.1;
        let d = num / q;
        let dnum = x.0 * y.2 - y.0 * x.2;
        let dq = 2.0 * (x.0 * x.1 + y.0 * y.1);
        Jet(y.0.atan2(x.0), d, (dnum * q - num * dq) / (q * q))
    }
}

/// The engine as the test sees it.
#[derive(Clone, Copy, Debug)]
struct Case {
    r: f64,
    l: f64,
    e: f64,
    omega: f64,
    m: f64,
    rod: (f64, f64, f64),
    gas: f64,
    g: [f64; 2],
    mu: f64,
}

/// The free-body answers at one angle.
#[derive(Debug)]
struct Answer {
    /// F_A, the slider's force on the rod; F_B, the crank's.
    fa: [f64; 2],
    fb: [f64; 2],
    /// The guides' reaction on the slider along +y and their friction
    /// along +x.
    n: f64,
    f: f64,
    /// The torque the rod delivers to the crank, B × (−F_B).
    torque: f64,
    /// The same by virtual work: the external forces' power less dK/dt,
    /// over ω.
    torque_by_work: f64,
    /// x_A′, for the friction's work.
    rate: f64,
}

fn solve(c: &Case, t: f64) -> Answer {
    let (sin, cos) = (
        Jet(t.sin(), t.cos(), -t.sin()),
        Jet(t.cos(), -t.sin(), -t.cos()),
    );
    let b = [cos.scale(c.r), sin.scale(c.r)];
    // x_A = r cos θ + √(l² − (r sin θ − e)²); A = (x_A, e).
    let rise = b[1].add(Jet(-c.e, 0.0, 0.0));
    let run = Jet(c.l * c.l, 0.0, 0.0)
        .add(rise.mul(rise).scale(-1.0))
        .sqrt();
    let xa = b[0].add(run);
    let a = [xa, Jet(c.e, 0.0, 0.0)];
    // The rod's angle from B to A.
    let angle = Jet::atan2(a[1].add(b[1].scale(-1.0)), a[0].add(b[0].scale(-1.0)));
    let (mr, bg, k) = c.rod;
    let beta = bg / c.l;
    let g_pt = [0, 1].map(|i| b[i].scale(1.0 - beta).add(a[i].scale(beta)));
    let w2 = c.omega * c.omega;
    let acc_a = w2 * xa.2;
    let acc_g = [w2 * g_pt[0].2, w2 * g_pt[1].2];
    let alpha = w2 * angle.2;
    let inertia = mr * k * k;
    // The slider's motion along +x, 0 at rest (a dead centre).
    let s = if xa.1.abs() <= 1e-12 * c.r {
        0.0
    } else {
        (xa.1 * c.omega).signum()
    };
    let ra = [a[0].0 - g_pt[0].0, a[1].0 - g_pt[1].0];
    let rb = [b[0].0 - g_pt[0].0, b[1].0 - g_pt[1].0];
    // Unknowns F_Ax, F_Ay, F_Bx, F_By, N; the friction −μ s σ N with σ
    // the sign of N, tried both ways.
    let mut found = None;
    for sigma in [1.0, -1.0] {
        #[rustfmt::skip]
        let matrix = Matrix5::new(
            // slider x: m a = −gas − F_Ax − μ s σ N + m g_x
            1.0, 0.0, 0.0, 0.0, c.mu * s * sigma,
            // slider y: 0 = −F_Ay + N + m g_y
            0.0, -1.0, 0.0, 0.0, 1.0,
            // rod x, y: m_r a_G = F_A + F_B + m_r g
            1.0, 0.0, 1.0, 0.0, 0.0,
            0.0, 1.0, 0.0, 1.0, 0.0,
            // rod's moments about G: I α = (A − G) × F_A + (B − G) × F_B
            -ra[1], ra[0], -rb[1], rb[0], 0.0,
        );
        let rhs = Vector5::new(
            -c.gas - c.m * acc_a + c.m * c.g[0],
            -c.m * c.g[1],
            mr * (acc_g[0] - c.g[0]),
            mr * (acc_g[1] - c.g[1]),
            inertia * alpha,
        );
        let x = matrix
            .lu()
            .solve(&rhs)
            .expect("the balances are independent");
        if x[4] * sigma >= 0.0 || (c.mu * s == 0.0) {
            assert!(found.is_none() || x[4] == 0.0, "two solutions at {t}");
            found = Some(x);
            if c.mu * s == 0.0 {
                break;
            }
        }
    }
    let x = found.expect("one sign of N agrees");
    let (fa, fb, n) = ([x[0], x[1]], [x[2], x[3]], x[4]);
    let f = -c.mu * s * n.abs();
    let torque = b[0].0 * -fb[1] - b[1].0 * -fb[0];
    let g1 = [g_pt[0].1, g_pt[1].1];
    let power =
        -c.gas * xa.1 + f * xa.1 + c.m * c.g[0] * xa.1 + mr * (c.g[0] * g1[0] + c.g[1] * g1[1]);
    let dk = w2
        * (c.m * xa.1 * xa.2
            + mr * (g1[0] * g_pt[0].2 + g1[1] * g_pt[1].2)
            + inertia * angle.1 * angle.2);
    Answer {
        fa,
        fb,
        n,
        f,
        torque,
        torque_by_work: power - dk,
        rate: xa.1,
    }
}

fn engine(c: &Case) -> Engine {
    let m = SliderCrank::new(c.r, c.l, c.e).unwrap();
    Engine::new(m, c.m, c.omega)
        .unwrap()
        .with_rod(RodMass::new(c.rod.0, c.rod.1, c.rod.2).unwrap())
        .unwrap()
        .with_gas(GasForce::Constant(c.gas))
        .unwrap()
        .with_gravity(c.g)
        .unwrap()
        .with_friction(c.mu)
        .unwrap()
}

fn draws(mut seed: u64) -> impl FnMut() -> f64 {
    move || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// |tan φ| at its largest, written here: |r sin θ − e| reaches r + |e|.
fn largest_tan(c: &Case) -> f64 {
    let h = c.r + c.e.abs();
    h / (c.l * c.l - h * h).sqrt()
}

fn random_case(next: &mut impl FnMut() -> f64, gravity: usize) -> Case {
    let r = 0.2 + 2.0 * next();
    // n from 1.05 to 50, half of them below 4.
    let n = if next() < 0.5 {
        1.05 + 3.0 * next()
    } else {
        4.0 + 46.0 * next()
    };
    let l = n * r;
    let e = if next() < 0.3 {
        0.0
    } else {
        (next() - 0.5) * 1.6 * (l - r)
    };
    let sign = if next() < 0.3 { -1.0 } else { 1.0 };
    let omega = sign * (1.0 + 100.0 * next());
    let m = 5.0 * next();
    // Heavy rods: up to four times the reciprocating mass.
    let rod = (20.0 * next(), l * next(), l * next());
    let g_size = r * omega * omega * (0.2 + 3.0 * next());
    let g = [[0.0, 0.0], [-g_size, 0.0], [g_size, 0.0], [0.0, -g_size]][gravity];
    let mut c = Case {
        r,
        l,
        e,
        omega,
        m,
        rod,
        gas: 200.0 * next() - 100.0,
        g,
        mu: 0.0,
    };
    c.mu = 0.9 * next() / largest_tan(&c);
    c
}

/// Every force and torque of the engine with gravity (none, towards and
/// away from the crank, and across the stroke) and friction against the
/// free-body model, at random engines (n 1.05 to 50, offsets, negative
/// speeds, heavy rods) at random angles, the dead centres, 90° and 270°;
/// the torque also against virtual work with the rod, gravity and
/// friction.
#[test]
fn every_force_is_the_free_body_diagrams() {
    let mut next = draws(0x9a71_7e39_0f1c);
    for i in 0..400 {
        let c = random_case(&mut next, i % 4);
        let engine = engine(&c);
        let m = *engine.mechanism();
        let mut angles = vec![0.0, 90.0, 180.0, 270.0, 360.0 * next(), 360.0 * next()];
        angles.push(m.outer_dead_centre().degrees());
        angles.push(m.inner_dead_centre().degrees());
        for deg in angles {
            let angle = Angle::deg(deg);
            let want = solve(&c, angle.radians());
            let at = engine.at(angle).unwrap();
            let size = [
                want.fa[0], want.fa[1], want.fb[0], want.fb[1], want.n, c.gas,
            ]
            .iter()
            .fold(0.0f64, |a, b| a.max(b.abs()));
            let tol = 1e-8 * (size + 1e-300) * (1.0 + c.l / c.r);
            let close = |got: f64, want: f64, what: &str| {
                assert!(
                    (got - want).abs() <= tol,
                    "{what} at {c:?}, {deg}°: {got} against {want} (tolerance {tol:e})"
                );
            };
            let loads = at.loads;
            close(loads.crosshead_pin[0], -want.fa[0], "cross-head pin x");
            close(loads.crosshead_pin[1], -want.fa[1], "cross-head pin y");
            close(loads.crank_pin[0], -want.fb[0], "crank pin x");
            close(loads.crank_pin[1], -want.fb[1], "crank pin y");
            close(loads.guide_thrust, -want.n, "guide thrust");
            let u = [
                (m.pose(angle).a().x - m.pose(angle).b().x) / c.l,
                (m.pose(angle).a().y - m.pose(angle).b().y) / c.l,
            ];
            close(
                loads.rod_force,
                -(want.fa[0] * u[0] + want.fa[1] * u[1]),
                "rod force",
            );
            close(loads.friction.unwrap_or(0.0), -want.f, "friction");
            let arm = c.r * (1.0 + c.l / c.r);
            close(at.torque / arm, want.torque / arm, "torque");
            close(want.torque_by_work / arm, want.torque / arm, "virtual work");
            close(
                engine.torque(&m.pose(angle)) / arm,
                want.torque / arm,
                "the diagram's torque",
            );
            close(at.weight.unwrap_or(0.0), -c.m * c.g[0], "weight");
            // The reciprocating parts alone: the same model with a
            // massless rod.
            let alone = solve(
                &Case {
                    rod: (0.0, c.rod.1, c.rod.2),
                    ..c
                },
                angle.radians(),
            );
            close(at.piston_effort, -alone.fa[0], "piston effort");
            close(at.guide_thrust, -alone.n, "guide thrust, massless rod");
            close(
                at.friction.unwrap_or(0.0),
                -alone.f,
                "friction, massless rod",
            );
            close(
                at.rod_force,
                -(alone.fa[0] * u[0] + alone.fa[1] * u[1]),
                "rod force, massless rod",
            );
            close(
                at.crank_effort_exact / arm,
                alone.torque / arm,
                "crank effort, massless rod",
            );
        }
    }
}

/// At a dead centre the slider is at rest and the friction is taken as
/// 0; a hair either side it is μ |N| against the motion.
#[test]
fn at_a_dead_centre_the_friction_is_zero() {
    let c = Case {
        r: 1.0,
        l: 3.0,
        e: 0.4,
        omega: 10.0,
        m: 2.0,
        rod: (3.0, 1.0, 1.2),
        gas: 50.0,
        g: [-9.81, 0.0],
        mu: 0.2,
    };
    let engine = engine(&c);
    let m = *engine.mechanism();
    for dc in [m.outer_dead_centre(), m.inner_dead_centre()] {
        let at = engine.at(dc).unwrap();
        assert_eq!(at.friction, Some(0.0), "{}", dc.degrees());
        assert_eq!(at.loads.friction, Some(0.0));
        for side in [-1e-6, 1e-6] {
            let near = Angle::deg(dc.degrees() + side);
            let got = engine.at(near).unwrap().loads.friction.unwrap();
            let want = solve(&c, near.radians());
            assert!(got != 0.0 && (got + want.f).abs() <= 1e-9 * want.n.abs());
        }
    }
}

/// Over a turn gravity does no work: the turn's work with the weights is
/// the work without them, for each direction of gravity, with a heavy
/// rod and a gas force.
#[test]
fn gravity_does_no_work_over_a_turn() {
    let mut next = draws(0x6a5f_0e39_d00d);
    for i in 0..24 {
        let mut c = random_case(&mut next, 1 + i % 3);
        c.mu = 0.0;
        let with = TurningMoment::new(&engine(&c), &[0.0]).unwrap();
        let without = TurningMoment::new(&engine(&Case { g: [0.0, 0.0], ..c }), &[0.0]).unwrap();
        let tol = with.tolerance + without.tolerance;
        assert!(
            (with.work - without.work).abs() <= 2.0 * tol,
            "{c:?}: {} against {} ({tol:e})",
            with.work,
            without.work
        );
        // And the weights do change the torque within the turn.
        assert!(
            (with.fluctuation - without.fluctuation).abs() > 1e3 * tol,
            "{c:?}"
        );
    }
}

/// The guides' friction takes work out of every turn: the turn's work
/// ∫ T dθ changes by ∫ f x_A′ dθ (f the friction along +x, from the
/// free-body model, integrated here by Simpson's rule between the dead
/// centres), which is negative for ω > 0 (positive for ω < 0, where θ
/// runs against time), and the mean torque by that over 2π.
#[test]
fn friction_takes_its_work_from_the_mean_torque() {
    let mut next = draws(0xf1c7_10e3_9a11);
    for i in 0..12 {
        let mut c = random_case(&mut next, i % 3);
        c.mu = 0.8 * next() / largest_tan(&c) + 0.01;
        let with = TurningMoment::new(&engine(&c), &[0.0]).unwrap();
        let without = TurningMoment::new(&engine(&Case { mu: 0.0, ..c }), &[0.0]).unwrap();
        let m = SliderCrank::new(c.r, c.l, c.e).unwrap();
        let (odc, idc) = (
            m.outer_dead_centre().radians(),
            m.inner_dead_centre().radians(),
        );
        let idc = if idc < odc {
            idc + std::f64::consts::TAU
        } else {
            idc
        };
        let pieces = [(odc, idc), (idc, odc + std::f64::consts::TAU)];
        let k = 20_000;
        let mut work = 0.0;
        for (a, b) in pieces {
            let h = (b - a) / k as f64;
            for j in 0..=k {
                let t = a + h * j as f64;
                let w = if j == 0 || j == k {
                    1.0
                } else if j % 2 == 1 {
                    4.0
                } else {
                    2.0
                };
                let at = solve(&c, t);
                work += w * h / 3.0 * at.f * at.rate;
            }
        }
        assert!(work * c.omega.signum() < 0.0, "{c:?}: {work}");
        let change = with.work - without.work;
        let scale = work.abs() * 1e-5 + with.tolerance + without.tolerance;
        assert!(
            (change - work).abs() <= scale,
            "{c:?}: {change} against {work}"
        );
        let mean = with.mean - without.mean;
        assert!(
            (mean - work / std::f64::consts::TAU).abs() <= scale,
            "{mean}"
        );
    }
}

/// A coefficient of friction for which the slider self-locks somewhere
/// in the turn is refused, once, naming the bound; so is one negative or
/// not a number.
#[test]
fn a_self_locking_slider_is_refused() {
    let m = SliderCrank::new(1.0, 1.1, 0.0).unwrap();
    // tan φ at 90° = 1/√0.21 = 2.182: μ below 0.4583.
    let e = Engine::new(m, 1.0, 10.0).unwrap();
    assert!(e.clone().with_friction(0.458).is_ok());
    let msg = e.clone().with_friction(0.459).unwrap_err().to_string();
    assert!(
        msg.contains("self-locks") && msg.contains("below 1/|tan φ| = 0.458258"),
        "{msg}"
    );
    assert!(e.clone().with_friction(-0.1).is_err());
    assert!(e.clone().with_friction(f64::NAN).is_err());
    assert!(e.with_gravity([f64::INFINITY, 0.0]).is_err());
}

/// Without gravity and friction nothing changes: no weight or friction
/// is reported, and every value is what the frictionless engine gives.
#[test]
fn no_gravity_and_no_friction_leave_the_engine_as_it_was() {
    let c = Case {
        r: 1.0,
        l: 3.0,
        e: 0.2,
        omega: 20.0,
        m: 2.0,
        rod: (3.0, 1.0, 1.2),
        gas: 50.0,
        g: [0.0, 0.0],
        mu: 0.0,
    };
    let at = engine(&c).at(Angle::deg(40.0)).unwrap();
    assert_eq!(at.weight, None);
    assert_eq!(at.friction, None);
    assert_eq!(at.loads.friction, None);
    let json = serde_json::to_string(&at).unwrap();
    assert!(
        !json.contains("weight") && !json.contains("friction"),
        "{json}"
    );
}
