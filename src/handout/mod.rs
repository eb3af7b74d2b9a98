//! Teaching handouts and exercise sheets: self-contained printable HTML
//! pages for one engine.
//!
//! [`Handout::page`] works the engine through textbook §35–37 and Ng's
//! paper step by step: the mechanism to scale, D and E, the velocity
//! scale, Kisch's construction with its enlarged detail, the acceleration
//! scale, the rod's rates, the OM line and the forces when a torque is
//! given, and the velocity and acceleration diagrams; every value read off
//! a construction is set beside the exact one. [`Handout::exercise`] draws
//! only the mechanism to scale on a faint grid, with the data and empty
//! answer fields, and [`Handout::key`] is its answer key. [`Class`] makes
//! a class's worth of different engines from a seed, reproducibly
//! ([`SplitMix64`]).
//!
//! Every page is one file: figures inlined as SVG, the style sheet in the
//! page, nothing fetched from anywhere. Print rules for A4 or Letter
//! ([`Paper`]) keep each figure and table on one page. Each value is
//! written with its full precision in a `data-value` attribute beside a
//! `data-key` that names it as the analysis's JSON does
//! (`graphical.velocity`, `statics.OM`), so that a program can read the
//! page.
//!
//! ```
//! use slider_crank::handout::Handout;
//! use slider_crank::{Angle, SliderCrank};
//!
//! let engine = SliderCrank::in_line(0.5, 3.0)?; // the §35 engine
//! let handout = Handout::new(engine, Angle::deg(45.0));
//! let page = handout.page()?;
//! assert!(page.contains(r#"data-key="graphical.velocity""#));
//! assert!(!page.contains("<script"));
//! # Ok::<(), slider_crank::Error>(())
//! ```

mod class;
mod command;
mod dynamics;
mod exercise;
mod figures;
mod page;
mod random;
mod request;
mod scale;
mod steps;

pub use class::{Class, MAX_CLASS};
pub use dynamics::{DynamicsAsk, Gas};
pub use random::SplitMix64;
pub use request::{DEFAULT_HANDOUT_ANGLE, HandoutRequest};

use crate::analytic::kinematics::check_omega;
use crate::construct::Reading;
use crate::error::{Error, Input, Result};
use crate::{angle::Angle, mechanism::SliderCrank, units::Units};

/// The paper a page is printed on.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Paper {
    /// ISO A4, 210 × 297 mm.
    #[default]
    A4,
    /// US Letter, 8.5 × 11 in.
    Letter,
}

crate::error::parse_by_name!(Paper);

impl Paper {
    /// The name on the command line: `a4`, `letter`.
    pub fn name(&self) -> &'static str {
        match self {
            Paper::A4 => "a4",
            Paper::Letter => "letter",
        }
    }

    /// The paper of that name; the error lists the names.
    pub fn from_name(name: &str) -> Result<Self> {
        match name {
            "a4" => Ok(Paper::A4),
            "letter" => Ok(Paper::Letter),
            _ => Err(Error::invalid(
                Input::Paper,
                format!("unknown paper '{name}': expected a4 or letter"),
            )),
        }
    }

    /// The size of the CSS `@page` rule: `A4`, `letter`.
    pub fn css_size(&self) -> &'static str {
        match self {
            Paper::A4 => "A4",
            Paper::Letter => "letter",
        }
    }
}

/// The dynamics a handout works: the reciprocating mass, the coefficient
/// of fluctuation of speed the flywheel is sized for and the gas force.
#[derive(Debug, Clone, PartialEq)]
struct Dynamics {
    mass: f64,
    fluctuation: f64,
    gas: Gas,
}

/// One engine at one crank angle, to be worked through on a handout or set
/// as an exercise. Built with [`Handout::new`] and the `with_*` methods,
/// each of which validates its value.
#[derive(Debug, Clone, PartialEq)]
pub struct Handout {
    mechanism: SliderCrank,
    angle: Angle,
    omega: f64,
    units: Units,
    torque: Option<f64>,
    friction: f64,
    dynamics: Option<Dynamics>,
    paper: Paper,
    title: Option<String>,
}

impl Handout {
    /// `mechanism` at `angle`, turning at 250 rpm (the §35 engine's),
    /// lengths in feet and forces in pounds-force, no torque, on A4.
    pub fn new(mechanism: SliderCrank, angle: Angle) -> Self {
        Self {
            mechanism,
            angle,
            omega: crate::analytic::kinematics::rpm_to_omega(crate::sources::RPM),
            units: Units::FOOT_POUND,
            torque: None,
            friction: 0.0,
            dynamics: None,
            paper: Paper::A4,
            title: None,
        }
    }

    /// At crank speed `omega` in rad/s (positive counter-clockwise); an
    /// error when it is not finite or out of range.
    pub fn with_omega(mut self, omega: f64) -> Result<Self> {
        self.omega = check_omega(omega)?;
        Ok(self)
    }

    /// With lengths and forces in `units` (names only: no number is
    /// converted). With the dynamics ([`Handout::with_dynamics_asked`])
    /// units that do not match the gas force's (the example's feet and
    /// pounds-force, a diagram's declared pressure unit) make
    /// [`Handout::page`] an error.
    pub fn with_units(mut self, units: Units) -> Self {
        self.units = units;
        self
    }

    /// With a crank torque `torque` (force × length, counter-clockwise
    /// positive) and the coefficient of friction `friction` of the slider
    /// in its guides: adds the OM line and the forces (Ng). An error for a
    /// torque that is not finite or a coefficient that is negative or not
    /// finite.
    pub fn with_torque(mut self, torque: f64, friction: f64) -> Result<Self> {
        crate::construct::check_load(torque, friction)?;
        self.torque = Some(torque);
        self.friction = friction;
        Ok(self)
    }

    /// With the engine's dynamics worked after the diagrams: the
    /// reciprocating mass `mass` (> 0, in the unit that makes mass ×
    /// length/s² the force unit: slug with ft and lbf, kg with m and N)
    /// and the example's gas force ([`Gas::Example`]: the turning-moment
    /// figure's steam indicator diagram, lbf/ft² on a 10 in bore), through
    /// the inertia force, the crank effort *F*·*OM*, the turning-moment
    /// diagram and the flywheel for the coefficient of fluctuation of
    /// speed `fluctuation` (0 < C_s < 2; 0.02 is usual). For the engine's
    /// own gas force, [`Handout::with_dynamics_asked`].
    ///
    /// Errors: a mass not positive or not finite; a coefficient out of
    /// range; units other than feet and pounds-force, the example's.
    pub fn with_dynamics(self, mass: f64, fluctuation: f64) -> Result<Self> {
        self.with_dynamics_asked(&DynamicsAsk {
            mass: Some(mass),
            fluctuation: Some(fluctuation),
            ..DynamicsAsk::default()
        })
    }

    /// With the dynamics `ask` gives (the mass, the coefficient of
    /// fluctuation, the gas force, the indicator diagram and its bore, as
    /// the command line and the Python package fill it), validated once
    /// here and refused in one line that names the fields, which each
    /// front end spells its way ([`crate::Error::spelled`]). Nothing
    /// asked: the handout unchanged.
    ///
    /// Errors: a gas force, diagram, bore or coefficient without a mass; a
    /// constant gas force with a diagram; a diagram without its bore or a
    /// bore without its diagram; a mass not positive or not finite; a
    /// coefficient out of range; a gas force not finite; a diagram that
    /// cannot be read, or whose header declares its pressures in another
    /// unit than the handout's force per length²; the example's diagram
    /// (no gas force given) with units other than feet and pounds-force.
    /// Units changed later are checked again when the page is made.
    pub fn with_dynamics_asked(mut self, ask: &DynamicsAsk) -> Result<Self> {
        if let Some(d) = ask.dynamics()? {
            d.gas.diagram(&self.units)?;
            self.dynamics = Some(d);
        }
        Ok(self)
    }

    /// Printed on `paper`.
    pub fn with_paper(mut self, paper: Paper) -> Self {
        self.paper = paper;
        self
    }

    /// With a heading of its own (an exercise sheet's "Exercise 7").
    pub fn with_title(mut self, title: impl Into<String>) -> Self {
        self.title = Some(title.into());
        self
    }

    /// The mechanism.
    pub fn mechanism(&self) -> &SliderCrank {
        &self.mechanism
    }

    /// The crank angle.
    pub fn angle(&self) -> Angle {
        self.angle
    }

    /// The crank speed ω in rad/s.
    pub fn omega(&self) -> f64 {
        self.omega
    }

    /// The crank speed in revolutions per minute.
    pub fn rpm(&self) -> f64 {
        self.omega * 60.0 / std::f64::consts::TAU
    }

    /// The units.
    pub fn units(&self) -> &Units {
        &self.units
    }

    /// The crank torque, if given.
    pub fn torque(&self) -> Option<f64> {
        self.torque
    }

    /// The coefficient of friction (used with a torque).
    pub fn friction(&self) -> f64 {
        self.friction
    }

    /// The reciprocating mass and the coefficient of fluctuation of speed
    /// of the dynamics, if they are worked.
    pub fn dynamics(&self) -> Option<(f64, f64)> {
        self.dynamics.as_ref().map(|d| (d.mass, d.fluctuation))
    }

    /// The gas force of the dynamics, if they are worked.
    pub fn gas(&self) -> Option<&Gas> {
        self.dynamics.as_ref().map(|d| &d.gas)
    }

    /// The paper.
    pub fn paper(&self) -> Paper {
        self.paper
    }

    /// Everything read at the pose: what `analyze` prints for this engine.
    pub fn reading(&self) -> Result<Reading> {
        let pose = self.mechanism.pose(self.angle);
        Reading::new(&pose, self.omega, self.torque, self.friction)
    }

    /// The worked handout: every step with its figure and values.
    pub fn page(&self) -> Result<String> {
        let reading = self.reading()?;
        let steps = steps::steps(self, &reading)?;
        let mut all = steps::rows(self, &reading);
        all.extend(
            steps
                .iter()
                .filter(|s| steps::DYNAMICS.contains(&s.id))
                .flat_map(|s| s.rows.clone()),
        );
        Ok(page::handout(self, &steps, &all))
    }

    /// The exercise sheet: the mechanism to scale on a faint grid, the
    /// data, and empty answer fields (no answer on it).
    pub fn exercise(&self) -> Result<String> {
        let reading = self.reading()?;
        exercise::sheet(self, &reading)
    }

    /// The exercise's answer key: the data, the construction drawn, and
    /// every answer read off it beside the exact value.
    pub fn key(&self) -> Result<String> {
        let reading = self.reading()?;
        exercise::key(self, &reading)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::error::Field;

    #[test]
    fn paper_names_round_trip() {
        for p in [Paper::A4, Paper::Letter] {
            assert_eq!(Paper::from_name(p.name()), Ok(p));
        }
        assert!(
            Paper::from_name("a5")
                .unwrap_err()
                .to_string()
                .contains("a4 or letter")
        );
    }

    #[test]
    fn bad_values_are_refused() {
        let h = Handout::new(SliderCrank::in_line(1.0, 4.0).unwrap(), Angle::deg(30.0));
        assert!(h.clone().with_omega(f64::NAN).is_err());
        assert!(h.clone().with_torque(f64::INFINITY, 0.0).is_err());
        assert!(h.clone().with_torque(1.0, -1.0).is_err());
        assert!(h.clone().with_torque(1.0, 0.5).is_ok());
        assert!(h.clone().with_dynamics(0.0, 0.02).is_err());
        assert!(h.clone().with_dynamics(1.0, 2.0).is_err());
        assert!(h.clone().with_dynamics(1.0, f64::NAN).is_err());
        assert!(
            h.clone()
                .with_units(Units::MILLIMETRE_NEWTON)
                .with_dynamics(1.0, 0.02)
                .is_err()
        );
        // Units changed after the dynamics are refused when the page is
        // made, as the indicator diagram is in lbf/ft².
        let late = h.with_dynamics(1.0, 0.02).unwrap();
        assert_eq!(late.dynamics(), Some((1.0, 0.02)));
        let e = late
            .with_units(Units::MILLIMETRE_NEWTON)
            .page()
            .unwrap_err();
        assert!(e.to_string().contains("lbf/ft²"), "{e}");
    }

    #[test]
    fn an_si_engine_works_its_own_gas_force() {
        let h = Handout::new(SliderCrank::in_line(60.0, 240.0).unwrap(), Angle::deg(40.0))
            .with_units(Units::MILLIMETRE_NEWTON);
        let ask = |gas_force: Option<f64>, diagram: Option<&str>, bore: Option<f64>| DynamicsAsk {
            mass: Some(0.002),
            gas_force,
            indicator: diagram.map(|t| (t.to_string(), "p.csv".to_string())),
            bore,
            ..DynamicsAsk::default()
        };
        let own = "fraction,expansion (MPa),compression (MPa)\n0,2,0.1\n1,0.2,0.1\n";
        assert!(
            h.clone()
                .with_dynamics_asked(&ask(None, Some(own), Some(100.0)))
                .is_ok()
        );
        assert!(
            h.clone()
                .with_dynamics_asked(&ask(Some(5000.0), None, None))
                .is_ok()
        );
        let psf = "fraction,expansion (lbf/ft²),compression\n0,2,0.1\n1,0.2,0.1\n";
        let e = h
            .clone()
            .with_dynamics_asked(&ask(None, Some(psf), Some(100.0)))
            .unwrap_err();
        assert!(
            e.to_string()
                .contains("p.csv: its pressures are in lbf/ft²"),
            "{e}"
        );
        let e = h
            .clone()
            .with_dynamics_asked(&ask(None, None, None))
            .unwrap_err();
        assert!(
            e.to_string()
                .contains("`indicator = CSV` with `bore = D`, or `gas_force = F`"),
            "{e}"
        );
        let Error::Invalid { message, .. } = &e else {
            panic!("{e:?}")
        };
        assert_eq!(
            message.fields().collect::<Vec<_>>(),
            [Field::Indicator, Field::Bore, Field::GasForce]
        );
        let e = h
            .clone()
            .with_dynamics_asked(&ask(None, Some(own), None))
            .unwrap_err();
        assert!(
            e.to_string().contains("give `bore = D` with `indicator`"),
            "{e}"
        );
        let e = h
            .with_dynamics_asked(&ask(Some(1.0), Some(own), Some(1.0)))
            .unwrap_err();
        assert!(e.to_string().contains("not both"), "{e}");
    }
}
