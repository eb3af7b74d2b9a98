//! The forces of the whole engine, the rod's inertia included: the loads
//! on the cross-head and crank pins, the thrust on the guides, the force
//! along the rod and the shaking force, from Newton–Euler on the slider
//! and on the rod as a rigid body, with the weights and the guides'
//! friction where the engine has them.

use super::guide::slide;
use super::rod::{RodInertia, RodMass};
use crate::mechanism::Pose;

/// The forces of the whole engine at one pose: the reciprocating parts of
/// mass m and the rod with its own inertia (a massless rod when the engine
/// has none, and then each force equals its value for the reciprocating
/// parts alone in [`super::EnginePose`]). Vectors are x and y in the world
/// frame; the crank is massless (or balanced about C), so the load on its
/// pin is also the load on the main bearing.
///
/// Newton–Euler, at constant ω, with gravity g and the guides' friction
/// f (along x, μ |N| against the motion): the slider along x gives the
/// pin force F_A of the slider on the rod, F_A,x = −F (F the piston
/// effort towards the crank, gas + m a − m g_x − f); the rod's moments
/// about B, (A − B) × F_A + (G − B) × m_r g = I_G α + (G − B) × m_r a_G,
/// give F_A,y; the slider across x gives the guides' reaction
/// N = F_A,y − m g_y, on which f depends (solved exactly,
/// [`super::check_friction`]); the rod's forces give the crank's pin force
/// F_B = m_r (a_G − g) − F_A. The torque on the crank, B × (−F_B), is then
/// the crank effort with the rod's inertia and weight torques
/// ([`super::EnginePose::torque`]), which the tests check.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct EngineLoads {
    /// The force of the rod on the cross-head pin A, −F_A.
    pub crosshead_pin: [f64; 2],
    /// The force of the rod on the crank pin B, −F_B: the crank-pin load,
    /// and the main bearing's (the crank massless).
    pub crank_pin: [f64; 2],
    /// The force along the rod at the cross-head, compression positive:
    /// the cross-head pin's force along B → A (with a heavy rod the pin
    /// force also has a part across the rod).
    pub rod_force: f64,
    /// The thrust of the slider on its guides along +y.
    pub guide_thrust: f64,
    /// The piston effort of the equivalent dynamical system: F with the
    /// rod's mass at the cross-head m_A = m_r BG / l moving with the piston,
    /// gas force + (m + m_A) a towards the crank (and, with gravity, the
    /// weight of m + m_A along the stroke; with friction, the guides'
    /// friction of the reciprocating parts alone).
    pub piston_effort_equivalent: f64,
    /// The shaking force on the frame, −m a_A − m_r a_G: the inertia
    /// forces of the reciprocating parts and the rod (the gas force acts
    /// on the piston and the cylinder head alike and cancels; the weights
    /// are a steady load, not shaking).
    pub shaking_force: [f64; 2],
    /// The guides' friction on the slider towards the crank, with the
    /// rod's inertia in the guides' reaction; `None` for a frictionless
    /// engine.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub friction: Option<f64>,
}

/// The slider's part in the balances at one pose.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Slider {
    /// The crank speed ω.
    pub omega: f64,
    /// The reciprocating mass m.
    pub mass: f64,
    /// F₀, the piston effort without friction, towards the crank: gas
    /// force + m a − m g_x.
    pub effort: f64,
    /// Gravity's acceleration.
    pub gravity: [f64; 2],
    /// The coefficient of friction μ.
    pub friction: f64,
    /// The direction of the slider's motion along +x (0 at rest).
    pub motion: f64,
    /// The extra piston effort towards the crank of the equivalent
    /// system's mass at the cross-head, m_A (a − g_x), a = ω² s″.
    pub equivalent: f64,
}

impl Slider {
    /// The piston effort F and the guides' reaction N of the
    /// reciprocating parts with a massless rod: N = F tan φ − m g_y.
    pub fn alone(&self, pose: &Pose) -> (f64, f64) {
        let (t, weight) = (pose.tan_obliquity(), self.mass * self.gravity[1]);
        slide(
            self.effort,
            |f| f * t - weight,
            t,
            self.friction,
            self.motion,
        )
    }
}

impl EngineLoads {
    /// The loads at `pose` for the slider `slider`, with the rod `rod` and
    /// its inertia there (`None`: a massless rod), and the whole engine's
    /// piston effort F (with the friction its guides' reaction gives).
    pub(crate) fn new(
        pose: &Pose,
        slider: &Slider,
        rod: Option<(&RodMass, &RodInertia)>,
    ) -> (Self, f64) {
        let l = pose.mechanism().rod();
        // A − B = (w, −h), h = l sin φ, w = l cos φ > 0.
        let (w, h) = (pose.run(), pose.rise());
        let beta = rod.map_or(0.0, |(m, _)| m.cg() / l);
        let g = slider.gravity;
        // The rod's inertia force with its weight, m_r (g − a_G), and
        // −I_G α; both zero for a massless rod.
        let (f, couple) = rod.map_or(([0.0, 0.0], 0.0), |(m, i)| {
            let weight = [m.mass() * g[0], m.mass() * g[1]];
            ([i.force[0] + weight[0], i.force[1] + weight[1]], i.couple)
        });
        // Moments about B: w F_A,y + h F_A,x = −couple + β (A − B) × (−f),
        // and F_A,x = −F, so F_A,y = (moment + h F)/w, and the guides'
        // reaction N = F_A,y − m g_y = P + tan φ F.
        let moment = -couple - beta * (w * f[1] + h * f[0]);
        let weight = slider.mass * g[1];
        let (effort, reaction) = slide(
            slider.effort,
            |f| (moment + h * f) / w - weight,
            pose.tan_obliquity(),
            slider.friction,
            slider.motion,
        );
        let pin_a = [-effort, (moment + h * effort) / w];
        let a = slider.omega * slider.omega * pose.position_acceleration();
        let (alone, _) = slider.alone(pose);
        let loads = Self {
            crosshead_pin: [-pin_a[0], -pin_a[1]],
            crank_pin: [f[0] + pin_a[0], f[1] + pin_a[1]],
            rod_force: (-pin_a[0] * w + pin_a[1] * h) / l,
            guide_thrust: -reaction,
            piston_effort_equivalent: alone + slider.equivalent,
            shaking_force: [
                -slider.mass * a + rod.map_or(0.0, |(_, i)| i.force[0]),
                rod.map_or(0.0, |(_, i)| i.force[1]),
            ],
            friction: (slider.friction > 0.0).then_some(effort - slider.effort),
        };
        (loads, effort)
    }

    /// Every value, for the finite check.
    pub(crate) fn values(&self) -> [f64; 10] {
        [
            self.crosshead_pin[0],
            self.crosshead_pin[1],
            self.crank_pin[0],
            self.crank_pin[1],
            self.rod_force,
            self.guide_thrust,
            self.piston_effort_equivalent,
            self.shaking_force[0],
            self.shaking_force[1],
            self.friction.unwrap_or(0.0),
        ]
    }
}

#[cfg(test)]
mod tests {
    use crate::dynamics::{Engine, GasForce, RodMass};
    use crate::{Angle, SliderCrank};
    use nalgebra::{Matrix4, Vector4};

    /// Positions of A, B and the rod's angle at θ (radians), from the
    /// pose's points alone.
    fn at(m: &SliderCrank, t: f64) -> ([f64; 2], [f64; 2], f64) {
        let p = m.pose(Angle::from_radians(t).unwrap());
        let (a, b) = (p.a(), p.b());
        ([a.x, a.y], [b.x, b.y], (a.y - b.y).atan2(a.x - b.x))
    }

    /// d²/dθ² of `f` by a sixth-order central difference.
    fn second(f: impl Fn(f64) -> f64, t: f64, h: f64) -> f64 {
        let c = [2.0, -27.0, 270.0, -490.0, 270.0, -27.0, 2.0];
        (0..7)
            .map(|i| c[i] * f(t + (i as f64 - 3.0) * h))
            .sum::<f64>()
            / (180.0 * h * h)
    }

    fn cross(a: [f64; 2], b: [f64; 2]) -> f64 {
        a[0] * b[1] - a[1] * b[0]
    }

    /// Newton–Euler written here from the bodies' motion (accelerations by
    /// finite differences of positions): the slider along x, the rod's
    /// forces and its moments about G, solved for the pin forces; the
    /// loads must be these, and the crank's torque from them the engine's.
    #[test]
    fn the_loads_are_newton_euler_of_the_slider_and_the_rod() {
        let engines = [
            (1.0, 3.0, 0.0, 2.0, 5.0, 0.35, 1.1),
            (0.3, 1.2, 0.0, 250.0, 100.0, 0.4, 0.45),
            (1.0, 1.05, 0.02, 1.0, 3.0, 0.9, 0.2),
            (2.0, 9.0, -4.0, 0.5, 7.0, 2.0, 3.5),
            (1.0, 4.0, 1.5, 0.0, 2.0, 4.0, 0.0),
        ];
        let (omega, gas) = (-37.0, 800.0);
        for (r, l, e, mass, rod_mass, cg, k) in engines {
            let m = SliderCrank::new(r, l, e).unwrap();
            let engine = Engine::new(m, mass, omega)
                .unwrap()
                .with_rod(RodMass::new(rod_mass, cg, k).unwrap())
                .unwrap()
                .with_gas(GasForce::Constant(gas))
                .unwrap();
            for deg in [0.0, 1.0, 37.0, 90.0, 91.0, 180.0, 233.0, 270.0, 300.0] {
                let t = Angle::deg(deg).radians();
                let w2 = omega * omega;
                let h = 1e-3;
                let acc = |f: &dyn Fn(f64) -> f64| w2 * second(f, t, h);
                let beta = cg / l;
                let g = |t: f64, i: usize| {
                    let (a, b, _) = at(&m, t);
                    b[i] + beta * (a[i] - b[i])
                };
                let a_a = acc(&|t| at(&m, t).0[0]);
                let a_g = [acc(&|t| g(t, 0)), acc(&|t| g(t, 1))];
                let alpha = acc(&|t| at(&m, t).2);
                let (pa, pb, _) = at(&m, t);
                let pg = [g(t, 0), g(t, 1)];
                let (ra, rb) = (
                    [pa[0] - pg[0], pa[1] - pg[1]],
                    [pb[0] - pg[0], pb[1] - pg[1]],
                );
                // Unknowns F_A (slider on rod), F_B (crank on rod).
                #[rustfmt::skip]
                let matrix = Matrix4::new(
                    1.0, 0.0, 0.0, 0.0,
                    1.0, 0.0, 1.0, 0.0,
                    0.0, 1.0, 0.0, 1.0,
                    -ra[1], ra[0], -rb[1], rb[0],
                );
                let rhs = Vector4::new(
                    -gas - mass * a_a,
                    rod_mass * a_g[0],
                    rod_mass * a_g[1],
                    rod_mass * k * k * alpha,
                );
                let x = matrix.lu().solve(&rhs).unwrap();
                let at = engine.at(Angle::deg(deg)).unwrap();
                let loads = at.loads;
                let scale = (gas.abs() + (mass + rod_mass) * r * w2) * (1.0 + l / r);
                let close = |got: f64, want: f64, what: &str| {
                    assert!(
                        (got - want).abs() <= 1e-6 * scale,
                        "{what} at r {r} l {l} e {e}, {deg}°: {got} against {want}"
                    );
                };
                close(loads.crosshead_pin[0], -x[0], "cross-head pin x");
                close(loads.crosshead_pin[1], -x[1], "cross-head pin y");
                close(loads.crank_pin[0], -x[2], "crank pin x");
                close(loads.crank_pin[1], -x[3], "crank pin y");
                close(loads.guide_thrust, -x[1], "guide thrust");
                let u = [(pa[0] - pb[0]) / l, (pa[1] - pb[1]) / l];
                close(loads.rod_force, -(x[0] * u[0] + x[1] * u[1]), "rod force");
                close(
                    loads.shaking_force[0],
                    -mass * a_a - rod_mass * a_g[0],
                    "shaking x",
                );
                close(loads.shaking_force[1], -rod_mass * a_g[1], "shaking y");
                close(
                    loads.piston_effort_equivalent,
                    gas + (mass + rod_mass * cg / l) * a_a,
                    "equivalent effort",
                );
                // The crank's torque from its pin load is the engine's
                // (virtual work with the rod's inertia torque).
                let torque = cross(pb, [-x[2], -x[3]]);
                close(torque, at.torque, "torque");
            }
        }
    }

    /// Without the rod's mass the loads are the reciprocating parts':
    /// F / cos φ along the rod and −F tan φ on the guides.
    #[test]
    fn a_massless_rod_gives_the_reciprocating_parts_forces() {
        let m = SliderCrank::new(1.0, 3.5, 0.4).unwrap();
        let engine = Engine::new(m, 2.0, 30.0)
            .unwrap()
            .with_gas(GasForce::Constant(-120.0))
            .unwrap();
        for deg in [0.0, 45.0, 90.0, 200.0, 333.0] {
            let at = engine.at(Angle::deg(deg)).unwrap();
            let scale = at.piston_effort.abs() + 1.0;
            assert!((at.loads.rod_force - at.rod_force).abs() <= 1e-12 * scale);
            assert!((at.loads.guide_thrust - at.guide_thrust).abs() <= 1e-12 * scale);
            assert_eq!(at.loads.piston_effort_equivalent, at.piston_effort);
            assert_eq!(at.loads.shaking_force, [-at.inertia_force, 0.0]);
        }
    }
}
