//! The request of `analyze` as a front end gives it: every option of
//! `analyze` as the user wrote it, the same for the command line (its
//! flags) and the Python package (its keywords), checked once here and
//! planned into the subject analysed at each angle ([`AnalyzePlan`]).

use super::{GivenEngine, MaxCells, dynamics_json, inversion_json, quadric_json, slot_json};
use crate::analytic::kinematics::{crank_speed, rpm_to_omega};
use crate::angle::Angle;
use crate::chain::{Assembly, CylindricChain, Inversion, InvertedChain, QuadricChain};
use crate::construct::Reading;
use crate::dynamics::{Engine, EnginePose};
use crate::error::{Error, Field, Input, Result, Wording};
use crate::lists::{AngleSpec, Angles};
use crate::mechanism::SliderCrank;
use crate::sources::{ENGINE_35, RPM};
use crate::units::{Unit, Units};
use serde::{Serialize, Serializer};
use serde_json::{Value, json};

/// The numbers written for one angle, the columns of the request's bound:
/// the mechanism (3), angle and ω (2), eight points (16), the analytic
/// (6) and graphical (4) values, the polygons (27: seven vectors and
/// seven numbers, and a point off the rod: along, across and its two
/// images), Ritterhaus's (7: three points and CG) and Bennett's (9: four
/// points and CG) constructions and six virtual centres (12).
pub const VALUES_PER_ANGLE: u64 = 86;

/// What a torque adds to [`VALUES_PER_ANGLE`]: the seven statics.
pub const STATICS_VALUES: u64 = 7;

/// The crank angle analysed when none is given, degrees.
pub const DEFAULT_ANGLE: &str = "45";

/// What a user asks of `analyze`; `None` leaves the command's own value
/// (the §35 engine, in line, at 45° and 250 rpm, in feet and pounds:
/// [`crate::sources`]). Each field is the option of its name on every
/// front end ([`Field::key`]): the field `slot_radius` is the command
/// line's option of that name, hyphenated, and the Python package's
/// keyword. [`AnalyzeRequest::plan`] checks it.
///
/// Fields may be added in later versions: start from
/// [`AnalyzeRequest::default`] and set the fields wanted.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct AnalyzeRequest<'a> {
    /// The crank radius r.
    pub crank: Option<f64>,
    /// The rod length l.
    pub rod: Option<f64>,
    /// The offset e of the line of stroke (0 when not given).
    pub offset: Option<f64>,
    /// The crank angles analysed (45° when not given).
    pub angles: Option<Angles<'a>>,
    /// The crank speed in revolutions per minute (not with `omega`).
    pub rpm: Option<f64>,
    /// The crank speed ω in rad/s (not with `rpm`).
    pub omega: Option<f64>,
    /// A crank torque: adds Ng's statics (the engine only).
    pub torque: Option<f64>,
    /// The slider's coefficient of friction in its guides: of the statics
    /// (with `torque`) and of the engine's dynamics (with its masses); 0
    /// when not given.
    pub friction: Option<f64>,
    /// The name of the length unit.
    pub unit: Option<Unit>,
    /// The name of the force unit (following `unit` when only that is
    /// given, [`Units::asked`]).
    pub force_unit: Option<Unit>,
    /// The engine's masses and gas force: any of them adds its dynamics
    /// (the engine only).
    pub engine: GivenEngine,
    /// The block in a circular slot of this radius (Fig. 60 b; not with
    /// `links` or `inversion`).
    pub slot_radius: Option<f64>,
    /// A quadric crank chain of these links a, b, c, d in place of the
    /// engine (Fig. 60 a; not with `crank`, `rod`, `offset` or
    /// `inversion`).
    pub links: Option<[f64; 4]>,
    /// The quadric chain's assembly (with `links`; open when not given).
    pub assembly: Option<Assembly>,
    /// The engine's chain with another link fixed, 1 to 4.
    pub inversion: Option<u32>,
    /// The most values the analysis may compute ([`MaxCells`]).
    pub max_cells: u64,
}

impl Default for AnalyzeRequest<'_> {
    /// The request of no option: `slider-crank analyze`.
    fn default() -> Self {
        AnalyzeRequest {
            crank: None,
            rod: None,
            offset: None,
            angles: None,
            rpm: None,
            omega: None,
            torque: None,
            friction: None,
            unit: None,
            force_unit: None,
            engine: GivenEngine::default(),
            slot_radius: None,
            links: None,
            assembly: None,
            inversion: None,
            max_cells: super::DEFAULT_MAX_CELLS,
        }
    }
}

/// What is analysed at each angle.
enum Subject {
    /// The engine, with a torque's statics and its masses' dynamics.
    Engine {
        torque: Option<f64>,
        friction: f64,
        engine: Option<Box<Engine>>,
    },
    /// The block in a curved slot.
    Slot(CylindricChain),
    /// A quadric crank chain.
    Quadric(QuadricChain, Assembly),
    /// An inversion of the engine's chain.
    Inversion(InvertedChain),
}

/// An analysis checked and ready to compute: the mechanism, speed,
/// units, angles and what is analysed; no angle computed yet. Its size
/// was checked against the request's bound.
pub struct AnalyzePlan<'a> {
    mechanism: SliderCrank,
    omega: f64,
    units: Units,
    angles: Angles<'a>,
    subject: Subject,
}

impl std::fmt::Debug for AnalyzePlan<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("AnalyzePlan")
            .field("mechanism", &self.mechanism)
            .field("omega", &self.omega)
            .field("angles", &self.angles)
            .finish_non_exhaustive()
    }
}

/// The analysis at one angle.
pub enum Analysis<'p> {
    /// The engine's reading and forces.
    Engine(Box<EngineAnalysis<'p>>),
    /// A chain's values, the JSON object `analyze` prints for it (with
    /// its `units`).
    Chain(Value),
}

/// The analysis of the engine at one angle.
pub struct EngineAnalysis<'p> {
    /// The reading ([`Reading`]: points, values, polygons,
    /// constructions, with a torque the statics).
    pub reading: Reading,
    /// With masses or a gas force, the engine and its forces at the pose.
    pub dynamics: Option<(&'p Engine, EnginePose)>,
}

impl<'a> AnalyzeRequest<'a> {
    /// The analysis this request asks for, planned: every option checked,
    /// the engine built (an indicator diagram read) and the size bounded,
    /// no angle computed yet.
    ///
    /// Errors: a mechanism the library refuses; two fields that do not go
    /// together (`rpm` and `omega`, `friction` without `torque` or an
    /// engine, `gravity` without a mass, the
    /// engine's as [`GivenEngine::refuse_pairs`] says, `slot_radius`,
    /// `links` and `inversion` with one another, `links` with a length of
    /// the engine, `assembly` without `links`, `torque` or the engine's
    /// masses with a chain); an angle not finite; more values than
    /// `max_cells` allows; a speed, torque, chain or engine the library
    /// refuses.
    pub fn plan(&self) -> Result<AnalyzePlan<'a>> {
        let mechanism = SliderCrank::new(
            self.crank.unwrap_or(ENGINE_35.0),
            self.rod.unwrap_or(ENGINE_35.1),
            self.offset.unwrap_or(0.0),
        )?;
        self.refuse_pairs()?;
        self.refuse_with_chain()?;
        let angles = match &self.angles {
            Some(a) => a.clone(),
            None => Angles::Spec(AngleSpec::parse(DEFAULT_ANGLE)?),
        };
        angles.check()?;
        self.bound(&angles)?;
        let units = Units::FOOT_POUND.asked(self.unit.as_ref(), self.force_unit.as_ref());
        let omega = crank_speed(self.rpm, self.omega)?.unwrap_or_else(|| rpm_to_omega(RPM));
        let subject = self.subject(mechanism, omega, &units)?;
        Ok(AnalyzePlan {
            mechanism,
            omega,
            units,
            angles,
            subject,
        })
    }

    /// Refuses fields given together that do not go together, or one
    /// given without another it needs.
    fn refuse_pairs(&self) -> Result<()> {
        crank_speed(self.rpm, self.omega)?;
        if self.friction.is_some() && self.torque.is_none() && !self.engine.is_given() {
            return Err(Error::refused(
                Input::Options,
                Wording::default()
                    .option(Field::Friction)
                    .then(" applies with a torque (the statics) or the engine's dynamics: give ")
                    .option(Field::Torque)
                    .then(" or ")
                    .option(Field::Mass)
                    .then(" too"),
            ));
        }
        self.engine.refuse_pairs()?;
        self.engine.refuse_gravity_alone()?;
        let lengths = [
            (Field::Crank, self.crank.is_some()),
            (Field::Rod, self.rod.is_some()),
            (Field::Offset, self.offset.is_some()),
        ];
        refuse_chain_pairs(
            self.slot_radius.is_some(),
            self.links.is_some(),
            self.inversion.is_some(),
            self.assembly.is_some(),
            &lengths,
        )
    }

    /// Refuses a torque or the engine's masses with a chain: they apply
    /// to the engine only.
    fn refuse_with_chain(&self) -> Result<()> {
        if self.slot_radius.is_none() && self.links.is_none() && self.inversion.is_none() {
            return Ok(());
        }
        let only = |given: Wording| {
            given
                .then(" to the engine only, not with ")
                .option(Field::SlotRadius)
                .then(", ")
                .option(Field::Links)
                .then(" or ")
                .option(Field::Inversion)
        };
        if self.torque.is_some() {
            let w = Wording::default().option(Field::Torque).then(" applies");
            return Err(Error::refused(Input::Options, only(w)));
        }
        if self.engine.is_given() {
            let w = Wording::default()
                .option(Field::Mass)
                .then(", ")
                .option(Field::RodMass)
                .then(", ")
                .option(Field::GasForce)
                .then(" and ")
                .option(Field::Indicator)
                .then(" apply");
            return Err(Error::refused(Input::Options, only(w)));
        }
        Ok(())
    }

    /// Checks the angles × the values of each against `max_cells`.
    fn bound(&self, angles: &Angles) -> Result<()> {
        let n = angles.len();
        let statics = if self.torque.is_some() {
            STATICS_VALUES
        } else {
            0
        };
        MaxCells::new(self.max_cells).check(
            "analyze",
            (n, &format!("{n} angles")),
            (VALUES_PER_ANGLE + statics, "values each"),
        )
    }

    /// What the request analyses: a chain where one is given, else the
    /// engine with its statics and dynamics.
    fn subject(&self, m: SliderCrank, omega: f64, units: &Units) -> Result<Subject> {
        if let Some(rho) = self.slot_radius {
            return Ok(Subject::Slot(CylindricChain::new(m, rho)?));
        }
        if let Some([a, b, c, d]) = self.links {
            let mode = self.assembly.unwrap_or(Assembly::Open);
            return Ok(Subject::Quadric(QuadricChain::new(a, b, c, d)?, mode));
        }
        if let Some(n) = self.inversion {
            let inversion = Inversion::from_number(n)?;
            return Ok(Subject::Inversion(InvertedChain::new(m, inversion)));
        }
        Ok(Subject::Engine {
            torque: self.torque,
            friction: self.friction.unwrap_or(0.0),
            engine: (self.engine)
                .engine(m, omega, units, self.friction)?
                .map(Box::new),
        })
    }
}

/// Refuses the chain fields given together (`slot_radius`, `links`,
/// `inversion`: one at a time), `links` with one of the engine's
/// `lengths` given (a quadric chain has its own), and `assembly` without
/// `links`: the same refusals for `analyze` and `check`.
pub(super) fn refuse_chain_pairs(
    slot_radius: bool,
    links: bool,
    inversion: bool,
    assembly: bool,
    lengths: &[(Field, bool)],
) -> Result<()> {
    let chain = [
        (Field::SlotRadius, slot_radius),
        (Field::Links, links),
        (Field::Inversion, inversion),
    ];
    let none: &[(Field, bool)] = &[];
    for (i, &(x, a)) in chain.iter().enumerate() {
        let with_lengths = if x == Field::Links { lengths } else { none };
        for &(y, b) in chain.iter().skip(i + 1).chain(with_lengths) {
            if a && b {
                return Err(Error::refused(
                    Input::Options,
                    Wording::default()
                        .option(x)
                        .then(" cannot be used with ")
                        .option(y),
                ));
            }
        }
    }
    if assembly && !links {
        return Err(Error::refused(
            Input::Options,
            Wording::default()
                .option(Field::Assembly)
                .then(" is the quadric chain's: give ")
                .option(Field::Links)
                .then(" with it"),
        ));
    }
    Ok(())
}

impl<'a> AnalyzePlan<'a> {
    /// The engine analysed (the one a chain is made of; the §35 engine's
    /// lengths beside a quadric chain of its own links).
    pub fn mechanism(&self) -> &SliderCrank {
        &self.mechanism
    }

    /// The crank speed ω, rad/s.
    pub fn omega(&self) -> f64 {
        self.omega
    }

    /// The units the values are written in.
    pub fn units(&self) -> &Units {
        &self.units
    }

    /// The angles, degrees.
    pub fn angles(&self) -> &Angles<'a> {
        &self.angles
    }

    /// Whether the angles were asked for as a list or a range (written
    /// as a JSON array, even of one angle) rather than as one angle.
    pub fn is_list(&self) -> bool {
        match &self.angles {
            Angles::Spec(s) => s.is_list(),
            Angles::List(_) => true,
        }
    }

    /// Whether a chain is analysed rather than the engine.
    pub fn is_chain(&self) -> bool {
        !matches!(self.subject, Subject::Engine { .. })
    }

    /// The analysis at `degrees`.
    ///
    /// Errors: an angle not finite; a pose the chain cannot take (a
    /// quadric chain out of reach); the statics or dynamics refused.
    pub fn at(&self, degrees: f64) -> Result<Analysis<'_>> {
        let chain = |v: Result<Value>| -> Result<Analysis<'_>> {
            let mut v = v?;
            if let Some(fields) = v.as_object_mut() {
                fields.insert("units".into(), json!(self.units));
            }
            Ok(Analysis::Chain(v))
        };
        match &self.subject {
            Subject::Engine {
                torque,
                friction,
                engine,
            } => {
                let angle = Angle::from_degrees(degrees)?;
                let pose = self.mechanism.pose(angle);
                Ok(Analysis::Engine(Box::new(EngineAnalysis {
                    reading: Reading::new(&pose, self.omega, *torque, *friction)?,
                    dynamics: engine
                        .as_deref()
                        .map(|e| Ok((e, e.at(angle)?)))
                        .transpose()?,
                })))
            }
            Subject::Slot(slot) => chain(slot_json(slot, degrees, self.omega)),
            Subject::Quadric(q, mode) => chain(quadric_json(q, *mode, degrees, self.omega)),
            Subject::Inversion(inv) => chain(inversion_json(inv, degrees, self.omega)),
        }
    }

    /// The JSON object `analyze` prints at `degrees`, serialised where it
    /// is written.
    ///
    /// Errors: as [`AnalyzePlan::at`].
    pub fn json_at(&self, degrees: f64) -> Result<AnalysisJson<'_>> {
        Ok(AnalysisJson {
            mechanism: &self.mechanism,
            units: &self.units,
            analysis: self.at(degrees)?,
        })
    }
}

/// The JSON object of an [`Analysis`] ([`AnalyzePlan::json_at`]): the
/// engine's reading as [`Reading::json`] writes it with the engine's
/// `dynamics` member ([`dynamics_json`]) where asked for, or the chain's
/// object.
pub struct AnalysisJson<'p> {
    mechanism: &'p SliderCrank,
    units: &'p Units,
    analysis: Analysis<'p>,
}

impl Serialize for AnalysisJson<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
        let (mechanism, units) = (self.mechanism, self.units);
        match &self.analysis {
            Analysis::Engine(e) => {
                let (reading, dynamics) = (&e.reading, &e.dynamics);
                let json = reading.json(mechanism, units);
                match dynamics {
                    Some((engine, at)) => {
                        let angle = reading.pose.angle();
                        let dynamics = dynamics_json(engine, at, angle, units);
                        json.with_dynamics(&dynamics).serialize(s)
                    }
                    None => json.serialize(s),
                }
            }
            Analysis::Chain(v) => v.serialize(s),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_request_of_no_option_is_the_section_35_engine_at_45_degrees() {
        let plan = AnalyzeRequest::default().plan().unwrap();
        let m = plan.mechanism();
        assert_eq!((m.crank(), m.rod(), m.offset()), (0.5, 3.0, 0.0));
        // 250 rpm: 2π × 250 / 60 rad/s.
        assert!((plan.omega() - 2.0 * std::f64::consts::PI * 250.0 / 60.0).abs() < 1e-12);
        assert_eq!(plan.angles().iter().collect::<Vec<_>>(), [45.0]);
        assert!(!plan.is_list() && !plan.is_chain());
    }

    #[test]
    fn fields_are_refused_by_their_keys() {
        let refused = |r: AnalyzeRequest| r.plan().unwrap_err().to_string();
        let r = AnalyzeRequest {
            friction: Some(0.2),
            ..Default::default()
        };
        assert_eq!(
            refused(r),
            "`friction` applies with a torque (the statics) or the engine's dynamics: give `torque` or `mass` too"
        );
        let r = AnalyzeRequest {
            engine: GivenEngine {
                gravity: Some(crate::dynamics::Gravity::TowardsCrank),
                ..Default::default()
            },
            ..Default::default()
        };
        assert_eq!(
            refused(r),
            "`gravity` weighs the engine's masses: give `mass` or `rod_mass` with it"
        );
        let r = AnalyzeRequest {
            torque: Some(1.0),
            inversion: Some(2),
            ..Default::default()
        };
        assert_eq!(
            refused(r),
            "`torque` applies to the engine only, not with `slot_radius`, `links` or `inversion`"
        );
        let r = AnalyzeRequest {
            links: Some([1.0, 3.0, 3.0, 3.0]),
            rod: Some(3.0),
            ..Default::default()
        };
        assert_eq!(refused(r), "`links` cannot be used with `rod`");
        let r = AnalyzeRequest {
            assembly: Some(Assembly::Crossed),
            ..Default::default()
        };
        assert_eq!(
            refused(r),
            "`assembly` is the quadric chain's: give `links` with it"
        );
    }

    #[test]
    fn the_bound_allows_exactly_the_values_asked() {
        // 0° to 360° by 90°: five angles of 86 values, 93 with a torque.
        let mut r = AnalyzeRequest {
            angles: Some(Angles::Spec(AngleSpec::parse("0:360:90").unwrap())),
            max_cells: 5 * 86,
            ..Default::default()
        };
        assert!(r.plan().is_ok());
        r.torque = Some(1.0);
        assert!(r.plan().is_err());
        r.max_cells = 5 * (86 + 7);
        assert!(r.plan().is_ok());
    }
}
