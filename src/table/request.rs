//! The request of a table as a front end gives it: every option of
//! `table` as the user wrote it, the same for the command line (its
//! flags) and the Python package (its keywords), checked once here and
//! planned into the table's head and a row per angle ([`TablePlan`]).

use super::{Format, GivenEngine, Head, Locomotive, MaxCells, Table, TableName};
use crate::analytic::harmonics::{DEFAULT_DECIMALS, DEFAULT_ORDER, Harmonics};
use crate::analytic::kinematics::{crank_speed, rpm_to_omega};
use crate::chain::Inversion;
use crate::chain::QuickReturn;
use crate::dynamics::{
    DEFAULT_AXES, DEFAULT_CRANKS, DEFAULT_FRACTIONS, EXAMPLE_MASS, Engine, FlywheelAsk,
    InlineEngine, PartialBalance, RadialEngine, default_planes,
};
use crate::error::{Error, Field, Input, Result, Wording};
use crate::lists::{AngleSpec, Angles};
use crate::mechanism::SliderCrank;
use crate::sources::{CHAIN_60, ENGINE_35, NG_FRICTION, NG_RIG, NG_TORQUE, RPM};
use crate::units::{Unit, Units};

/// What a user asks of a table; `None` leaves the table's own value (the
/// §35 engine at 250 rpm for kinematics and dynamics, Ng's rig, torque
/// and μ = 1 for forces, the textbook's rows and columns for the ratio
/// tables: [`crate::sources`]). Each field is the option of its name on
/// every front end ([`Field::key`]): the field `force_unit` is the
/// command line's option of that name, hyphenated, and the Python
/// package's keyword. [`TableRequest::plan`] checks it; a field the table
/// does not use is refused there, as a field given with another it
/// cannot go with.
///
/// Fields may be added in later versions: start from
/// [`TableRequest::new`] and set the fields wanted.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct TableRequest<'a> {
    /// Which table.
    pub name: TableName,
    /// How it is written (text by default).
    pub format: Format,
    /// The ratios n = l/r of the ratio tables (∞ for the infinitely long
    /// rod).
    pub n: Option<Vec<f64>>,
    /// The crank angles of the rows.
    pub angles: Option<Angles<'a>>,
    /// The crank radius r.
    pub crank: Option<f64>,
    /// The rod length l.
    pub rod: Option<f64>,
    /// The offset e of the line of stroke (0 when not given).
    pub offset: Option<f64>,
    /// The crank speed in revolutions per minute (not with `omega`).
    pub rpm: Option<f64>,
    /// The crank speed ω in rad/s (not with `rpm`).
    pub omega: Option<f64>,
    /// The crank torque of `forces`.
    pub torque: Option<f64>,
    /// The slider's coefficient of friction of `forces` (Ng's by default)
    /// and of `dynamics` (0 by default).
    pub friction: Option<f64>,
    /// The decimals printed (at most 17).
    pub decimals: Option<usize>,
    /// The name of the length unit.
    pub unit: Option<Unit>,
    /// The name of the force unit (following `unit` when only that is
    /// given, [`Units::asked`]).
    pub force_unit: Option<Unit>,
    /// The engine of `dynamics`: the reciprocating mass m (also the
    /// locomotive's of `partial-balance`), the rod's mass with its centre
    /// and gyration, a constant gas force or an indicator diagram with its
    /// bore, each the field of its name (`mass`, `rod_mass`, …).
    pub engine: GivenEngine,
    /// The crank phases of `dynamics`' cylinders, degrees (one cylinder at
    /// 0 by default).
    pub phases: Option<Vec<f64>>,
    /// The coefficient of fluctuation of speed of the flywheel note (not
    /// with `flywheel`).
    pub fluctuation: Option<f64>,
    /// A flywheel's moment of inertia (not with `fluctuation`).
    pub flywheel: Option<f64>,
    /// The crank angles of `balance`'s cylinders, degrees ahead of the
    /// first.
    pub cranks: Option<Vec<f64>>,
    /// The distances of `balance`'s cylinders from the reference plane.
    pub planes: Option<Vec<f64>>,
    /// The harmonics of `harmonics`' series.
    pub order: Option<usize>,
    /// The fractions of the reciprocating mass `partial-balance` balances.
    pub fractions: Option<Vec<f64>>,
    /// A locomotive's wheel diameter for the hammer blow (with `speed`,
    /// `mass` and `crank`).
    pub wheel: Option<f64>,
    /// The locomotive's speed along the rails.
    pub speed: Option<f64>,
    /// The wheel's static load on the rail.
    pub load: Option<f64>,
    /// The axes of `radial`'s cylinders, degrees.
    pub axes: Option<Vec<f64>>,
    /// The inversion of `quick-return`, 3 or 2.
    pub inversion: Option<u32>,
    /// The arm of `quick-return`'s slotted link that drives the tool.
    pub lever: Option<f64>,
    /// The most values the table may compute ([`MaxCells`]).
    pub max_cells: u64,
}

/// A row of a table at a crank angle.
type Row<'a> = Box<dyn Fn(f64) -> Result<Vec<String>> + Send + Sync + 'a>;

/// The rows of a table at a crank angle (obliquity's ratios).
type Rows<'a> = Box<dyn Fn(f64) -> Result<Vec<Vec<String>>> + Send + Sync + 'a>;

/// How a planned table's rows are made.
enum Body<'a> {
    /// Made already, in the head's rows (harmonics).
    Made,
    /// One row an angle.
    Row(Angles<'a>, Row<'a>),
    /// Several rows an angle.
    Rows(Angles<'a>, Rows<'a>),
}

/// A table checked and ready to write: its title, headers and notes, and
/// its rows, made an angle at a time as they are written (memory does not
/// grow with the angles); its size was checked against the request's
/// bound.
pub struct TablePlan<'a> {
    format: Format,
    head: Table,
    body: Body<'a>,
}

impl std::fmt::Debug for TablePlan<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("TablePlan")
            .field("format", &self.format)
            .field("head", &self.head)
            .finish_non_exhaustive()
    }
}

impl<'a> TableRequest<'a> {
    /// The request of the table `name` with none of its options given:
    /// the table as `slider-crank table NAME` prints it.
    pub fn new(name: TableName) -> Self {
        TableRequest {
            name,
            format: Format::Text,
            n: None,
            angles: None,
            crank: None,
            rod: None,
            offset: None,
            rpm: None,
            omega: None,
            torque: None,
            friction: None,
            decimals: None,
            unit: None,
            force_unit: None,
            engine: GivenEngine::default(),
            phases: None,
            fluctuation: None,
            flywheel: None,
            cranks: None,
            planes: None,
            order: None,
            fractions: None,
            wheel: None,
            speed: None,
            load: None,
            axes: None,
            inversion: None,
            lever: None,
            max_cells: super::DEFAULT_MAX_CELLS,
        }
    }

    /// The table this request asks for, planned: every option checked,
    /// the head made and the size bounded, no row computed yet.
    ///
    /// Errors: a field the table does not use, or two that do not go
    /// together (`rpm` and `omega`, `gas_force` and `indicator`,
    /// `fluctuation` and `flywheel`, the rod's mass without its centre
    /// and gyration, an indicator diagram without its bore, the
    /// locomotive's mass and crank without its wheel); a ratio not above
    /// 1 or NaN, an angle not finite, more than 17 decimals; a mechanism,
    /// speed, load, engine or list the library refuses; more values than
    /// `max_cells` allows.
    pub fn plan(&self) -> Result<TablePlan<'a>> {
        self.refuse_unused()?;
        self.refuse_pairs()?;
        self.refuse_not_finite()?;
        if let Some(angles) = &self.angles {
            angles.check()?;
        }
        let decimals = self.decimals.unwrap_or(match self.name {
            TableName::Forces => 2,
            _ => 4,
        });
        if decimals > 17 {
            return Err(Error::OutOfRange {
                name: Field::Decimals,
                value: decimals as f64,
                reason: "at most 17 decimals are meaningful in f64".into(),
            });
        }
        let (head, body) = match self.name {
            TableName::Obliquity => self.obliquity()?,
            TableName::AccelerationFactor => self.acceleration_factor()?,
            TableName::Kinematics => self.kinematics(decimals)?,
            TableName::Forces => self.forces(decimals)?,
            TableName::Dynamics => self.dynamics(decimals)?,
            TableName::Balance => self.balance(decimals)?,
            TableName::Harmonics => (self.harmonics(decimals)?, Body::Made),
            TableName::PartialBalance => self.partial_balance(decimals)?,
            TableName::Radial => self.radial(decimals)?,
            TableName::QuickReturn => self.quick_return(decimals)?,
        };
        Ok(TablePlan {
            format: self.format,
            head,
            body,
        })
    }

    /// The fields given, each with whether it is given, in the order the
    /// command line's help lists them.
    fn given(&self) -> [(Field, bool); 32] {
        [
            (Field::Ratio, self.n.is_some()),
            (Field::Crank, self.crank.is_some()),
            (Field::Rod, self.rod.is_some()),
            (Field::Offset, self.offset.is_some()),
            (Field::Rpm, self.rpm.is_some()),
            (Field::Omega, self.omega.is_some()),
            (Field::Torque, self.torque.is_some()),
            (Field::Friction, self.friction.is_some()),
            (Field::Decimals, self.decimals.is_some()),
            (Field::Unit, self.unit.is_some()),
            (Field::ForceUnit, self.force_unit.is_some()),
            (Field::Mass, self.engine.mass.is_some()),
            (Field::RodMass, self.engine.rod_mass.is_some()),
            (Field::RodCg, self.engine.rod_cg.is_some()),
            (Field::RodGyration, self.engine.rod_gyration.is_some()),
            (Field::GasForce, self.engine.gas_force.is_some()),
            (Field::Indicator, self.engine.indicator.is_some()),
            (Field::Bore, self.engine.bore.is_some()),
            (Field::Gravity, self.engine.gravity.is_some()),
            (Field::Phase, self.phases.is_some()),
            (Field::Fluctuation, self.fluctuation.is_some()),
            (Field::Flywheel, self.flywheel.is_some()),
            (Field::Cranks, self.cranks.is_some()),
            (Field::Plane, self.planes.is_some()),
            (Field::Order, self.order.is_some()),
            (Field::BalancedFraction, self.fractions.is_some()),
            (Field::Wheel, self.wheel.is_some()),
            (Field::Speed, self.speed.is_some()),
            (Field::Load, self.load.is_some()),
            (Field::Axis, self.axes.is_some()),
            (Field::Inversion, self.inversion.is_some()),
            (Field::Lever, self.lever.is_some()),
        ]
    }

    /// Refuses the first field given that the table does not use: a
    /// table refuses what it would silently ignore (the ratio tables take
    /// no mechanism, speed, load or units; kinematics no ratios, load or
    /// force unit; forces no ratios or speed).
    fn refuse_unused(&self) -> Result<()> {
        let used = uses(self.name);
        match self
            .given()
            .into_iter()
            .find(|(field, given)| *given && !used.contains(field))
        {
            Some((field, _)) => Err(Error::refused(
                Input::Options,
                Wording::from(format!("table {} does not use ", self.name.name())).option(field),
            )),
            None => Ok(()),
        }
    }

    /// Refuses a number of a list that is not finite (NaN, or infinite
    /// but in the ratios n, where ∞ is the infinitely long rod), as the
    /// command line refuses it written in the list.
    fn refuse_not_finite(&self) -> Result<()> {
        let lists = [
            ("n", &self.n),
            ("phase", &self.phases),
            ("crank angle", &self.cranks),
            ("plane", &self.planes),
            ("fraction", &self.fractions),
            ("axis", &self.axes),
        ];
        for (name, list) in lists {
            let bad = |x: &&f64| x.is_nan() || (x.is_infinite() && name != "n");
            if let Some(x) = list.iter().flatten().find(bad) {
                return Err(Error::invalid(
                    Input::Links,
                    format!("invalid {name} '{x}': expected a finite number"),
                ));
            }
        }
        Ok(())
    }

    /// Refuses fields given together that do not go together, or one
    /// given without another it needs.
    fn refuse_pairs(&self) -> Result<()> {
        crank_speed(self.rpm, self.omega)?;
        self.engine.refuse_pairs()?;
        super::engine::refuse_both(
            self.fluctuation.is_some(),
            self.flywheel.is_some(),
            (Field::Fluctuation, Field::Flywheel),
            "the coefficient of fluctuation of speed or the flywheel",
        )?;
        if self.wheel.is_none() && (self.speed.is_some() || self.load.is_some()) {
            return Err(Error::refused(
                Input::Options,
                Wording::default()
                    .option(if self.speed.is_some() {
                        Field::Speed
                    } else {
                        Field::Load
                    })
                    .then(" is the locomotive's: give ")
                    .option(Field::Wheel)
                    .then(" with it"),
            ));
        }
        Ok(())
    }

    /// The mechanism of the lengths given, `own`'s crank and rod where not
    /// given, in line where no offset is.
    fn mechanism(&self, (crank, rod): (f64, f64)) -> Result<SliderCrank> {
        SliderCrank::new(
            self.crank.unwrap_or(crank),
            self.rod.unwrap_or(rod),
            self.offset.unwrap_or(0.0),
        )
    }

    /// ω from the speed given, the §35 engine's 250 rpm when none is.
    fn omega(&self) -> Result<f64> {
        Ok(crank_speed(self.rpm, self.omega)?.unwrap_or_else(|| rpm_to_omega(RPM)))
    }

    /// The units asked for, each `own`'s where not given.
    fn units(&self, own: Units) -> Units {
        own.asked(self.unit.as_ref(), self.force_unit.as_ref())
    }

    /// The angles given, or those of the text `own`.
    fn angles_or(&self, own: &str) -> Result<Angles<'a>> {
        match &self.angles {
            Some(a) => Ok(a.clone()),
            None => Ok(Angles::Spec(AngleSpec::parse(own)?)),
        }
    }

    /// The bound of the request.
    fn bound(&self) -> MaxCells {
        MaxCells::new(self.max_cells)
    }

    /// A table of a row per angle of `angles` under `head`, checked
    /// against the bound.
    fn per_angle(
        &self,
        head: Table,
        angles: Angles<'a>,
        row: Row<'a>,
    ) -> Result<(Table, Body<'a>)> {
        let command = format!("table {}", self.name.name());
        self.bound()
            .check_angles(&command, angles.len(), head.headers.len())?;
        Ok((head, Body::Row(angles, row)))
    }

    /// `obliquity`: φ for the ratios at the angles (90° by default).
    fn obliquity(&self) -> Result<(Table, Body<'a>)> {
        let ratios = self.n.clone().unwrap_or_else(|| vec![4.0, 5.0, 6.0]);
        let angles = self.angles_or("90")?;
        let first = angles.iter().next().unwrap_or(90.0);
        // Over several angles the title names none and each row its own.
        let several = angles.len() > 1;
        let head = super::obliquity_head(&ratios, first, several)?;
        self.bound()
            .check_obliquity(angles.len(), ratios.len() as u64, head.headers.len())?;
        let rows: Rows<'a> = Box::new(move |a| super::obliquity_rows(&ratios, a, several));
        Ok((head, Body::Rows(angles, rows)))
    }

    /// `acceleration-factor`: the textbook's factor for the ratios at the
    /// angles (the textbook's rows and columns by default).
    fn acceleration_factor(&self) -> Result<(Table, Body<'a>)> {
        let ratios = self
            .n
            .clone()
            .unwrap_or_else(|| super::TEXTBOOK_RATIOS.to_vec());
        let head = super::acceleration_factor_table(&ratios, &[])?;
        let angles = match &self.angles {
            Some(a) => a.clone(),
            None => Angles::List(&super::TEXTBOOK_ANGLES),
        };
        let row: Row<'a> = Box::new(move |d| {
            let t = super::acceleration_factor_table(&ratios, &[d])?;
            Ok(t.rows.into_iter().next().unwrap_or_default())
        });
        self.per_angle(head, angles, row)
    }

    /// `kinematics`: the exact values of the §35 engine (by default).
    fn kinematics(&self, decimals: usize) -> Result<(Table, Body<'a>)> {
        let m = self.mechanism(ENGINE_35)?;
        let omega = self.omega()?;
        let angles = self.angles_or(TURN_ANGLES)?;
        let head = super::kinematics_head(&m, omega, &self.units(Units::FOOT_POUND));
        let row: Row<'a> = Box::new(move |d| super::kinematics_row(&m, omega, d, decimals));
        self.per_angle(head, angles, row)
    }

    /// `forces`: Ng's Table 2 (his rig, torque and μ by default).
    fn forces(&self, decimals: usize) -> Result<(Table, Body<'a>)> {
        let m = self.mechanism(NG_RIG)?;
        let torque = self.torque.unwrap_or(NG_TORQUE);
        if !torque.is_finite() {
            return Err(Error::NotFinite {
                name: Field::Torque,
                value: torque,
            });
        }
        let mu = self.friction.unwrap_or(NG_FRICTION);
        let angles = self.angles_or("10:160:10")?;
        let head = super::forces_head(&m, torque, mu, &self.units(Units::MILLIMETRE_NEWTON));
        let row: Row<'a> = Box::new(move |d| super::forces_row(&m, torque, mu, d, decimals));
        self.per_angle(head, angles, row)
    }

    /// The engine of `dynamics`: the masses and gas force given, or the
    /// example mass; weighed by the gravity given, with the friction given.
    fn engine(&self, m: SliderCrank, omega: f64, units: &Units) -> Result<Engine> {
        if let Some(engine) = self.engine.engine(m, omega, units, self.friction)? {
            return Ok(engine);
        }
        let mut engine = Engine::new(m, EXAMPLE_MASS, omega)?;
        if let Some(g) = self.engine.gravity(units)? {
            engine = engine.with_gravity(g)?;
        }
        match self.friction {
            Some(mu) => engine.with_friction(mu),
            None => Ok(engine),
        }
    }

    /// `dynamics`: the engine's forces and torques, the turn's results in
    /// the notes.
    fn dynamics(&self, decimals: usize) -> Result<(Table, Body<'a>)> {
        let m = self.mechanism(ENGINE_35)?;
        let omega = self.omega()?;
        let units = self.units(Units::FOOT_POUND);
        let engine = self.engine(m, omega, &units)?;
        let phases = self.phases.clone().unwrap_or_else(|| vec![0.0]);
        let ask = match (self.fluctuation, self.flywheel) {
            (Some(c), _) => FlywheelAsk::Coefficient(c),
            (_, Some(i)) => FlywheelAsk::Inertia(i),
            _ => FlywheelAsk::None,
        };
        let angles = self.angles_or(TURN_ANGLES)?;
        let head = super::dynamics_head(&engine, &phases, ask, &units)?;
        // Each cylinder's torque beyond the first is a value of each row.
        self.bound()
            .check_cylinders(angles.len(), head.headers.len(), phases.len())?;
        let row: Row<'a> = Box::new(move |d| super::dynamics_row(&engine, &phases, d, decimals));
        Ok((head, Body::Row(angles, row)))
    }

    /// `balance`: an in-line engine's unbalanced forces and couples.
    fn balance(&self, decimals: usize) -> Result<(Table, Body<'a>)> {
        let m = self.mechanism(ENGINE_35)?;
        let cranks = self
            .cranks
            .clone()
            .unwrap_or_else(|| DEFAULT_CRANKS.to_vec());
        let planes = self
            .planes
            .clone()
            .unwrap_or_else(|| default_planes(cranks.len()));
        let engine = InlineEngine::new(&cranks, &planes, m.ratio())?;
        let angles = self.angles_or(TURN_ANGLES)?;
        let head = super::balance_head(&engine, &self.units(Units::FOOT_POUND));
        let row: Row<'a> = Box::new(move |d| super::balance_row(&engine, d, decimals));
        self.per_angle(head, angles, row)
    }

    /// `harmonics`: the acceleration's series and each cut's error, its
    /// rows made at once (8 decimals by default).
    fn harmonics(&self, decimals: usize) -> Result<Table> {
        let m = self.mechanism(ENGINE_35)?;
        let series = Harmonics::new(m.ratio(), self.order.unwrap_or(DEFAULT_ORDER))?;
        Ok(super::harmonics_table(
            &series,
            self.decimals.map_or(DEFAULT_DECIMALS, |_| decimals),
        ))
    }

    /// `partial-balance`: a single cylinder's unbalanced force for each
    /// fraction, and the hammer blow.
    fn partial_balance(&self, decimals: usize) -> Result<(Table, Body<'a>)> {
        let balances = self
            .fractions
            .clone()
            .unwrap_or_else(|| DEFAULT_FRACTIONS.to_vec())
            .into_iter()
            .map(PartialBalance::new)
            .collect::<Result<Vec<_>>>()?;
        let locomotive = match self.wheel {
            Some(wheel) => Some(Locomotive::new(
                self.engine.mass.unwrap_or(0.0),
                self.crank.unwrap_or(0.0),
                wheel,
                self.speed.unwrap_or(0.0),
                self.load,
            )?),
            None if self.engine.mass.is_some() || self.crank.is_some() => {
                return Err(Error::refused(
                    Input::Options,
                    Wording::from("table partial-balance takes ")
                        .option(Field::Mass)
                        .then(" and ")
                        .option(Field::Crank)
                        .then(" for the hammer blow only: give ")
                        .option(Field::Wheel)
                        .then(" and ")
                        .option(Field::Speed)
                        .then(" with them"),
                ));
            }
            None => None,
        };
        let angles = self.angles_or(TURN_ANGLES)?;
        let head = super::partial_balance_head(
            &balances,
            locomotive.as_ref(),
            &self.units(Units::FOOT_POUND),
        )?;
        let row: Row<'a> = Box::new(move |d| super::partial_balance_row(&balances, d, decimals));
        self.per_angle(head, angles, row)
    }

    /// `radial`: cylinders on one crank.
    fn radial(&self, decimals: usize) -> Result<(Table, Body<'a>)> {
        let m = self.mechanism(ENGINE_35)?;
        let axes = self.axes.clone().unwrap_or_else(|| DEFAULT_AXES.to_vec());
        let engine = RadialEngine::new(&axes, m.ratio())?;
        let angles = self.angles_or(TURN_ANGLES)?;
        let head = super::radial_head(&engine);
        let row: Row<'a> = Box::new(move |d| super::radial_row(&engine, d, decimals));
        self.per_angle(head, angles, row)
    }

    /// `quick-return`: the tool's motion over the two strokes (inversion
    /// 3 of Fig. 60's chain by default, every 15°).
    fn quick_return(&self, decimals: usize) -> Result<(Table, Body<'a>)> {
        let m = self.mechanism(CHAIN_60)?;
        let omega = self.omega()?;
        let inversion = Inversion::from_number(self.inversion.unwrap_or(3))?;
        let lever = self.lever.unwrap_or_else(|| QuickReturn::default_lever(&m));
        let q = QuickReturn::new(m, inversion, lever)?;
        // Every 15°: the strokes' ends at 90° and 270° among them.
        let angles = self.angles_or("0:360:15")?;
        let head = super::quick_return_head(&q, omega, &self.units(Units::FOOT_POUND));
        let row: Row<'a> = Box::new(move |d| super::quick_return_row(&q, omega, d, decimals));
        self.per_angle(head, angles, row)
    }
}

/// The angles of the tables over a turn when none are given: every 30°.
const TURN_ANGLES: &str = "0:360:30";

/// The fields the table `name` uses beyond its format, angles and bound.
fn uses(name: TableName) -> &'static [Field] {
    use Field as F;
    match name {
        TableName::Obliquity | TableName::AccelerationFactor => &[F::Ratio],
        TableName::Kinematics => &[
            F::Crank,
            F::Rod,
            F::Offset,
            F::Rpm,
            F::Omega,
            F::Decimals,
            F::Unit,
        ],
        TableName::Forces => &[
            F::Crank,
            F::Rod,
            F::Offset,
            F::Torque,
            F::Friction,
            F::Decimals,
            F::Unit,
            F::ForceUnit,
        ],
        TableName::Dynamics => &[
            F::Crank,
            F::Rod,
            F::Offset,
            F::Rpm,
            F::Omega,
            F::Decimals,
            F::Unit,
            F::ForceUnit,
            F::Mass,
            F::RodMass,
            F::RodCg,
            F::RodGyration,
            F::GasForce,
            F::Indicator,
            F::Bore,
            F::Gravity,
            F::Friction,
            F::Phase,
            F::Fluctuation,
            F::Flywheel,
        ],
        TableName::Balance => &[F::Crank, F::Rod, F::Decimals, F::Unit, F::Cranks, F::Plane],
        TableName::Harmonics => &[F::Crank, F::Rod, F::Decimals, F::Order],
        TableName::PartialBalance => &[
            F::Crank,
            F::Decimals,
            F::Unit,
            F::ForceUnit,
            F::Mass,
            F::BalancedFraction,
            F::Wheel,
            F::Speed,
            F::Load,
        ],
        TableName::Radial => &[F::Crank, F::Rod, F::Decimals, F::Axis],
        TableName::QuickReturn => &[
            F::Crank,
            F::Rod,
            F::Offset,
            F::Rpm,
            F::Omega,
            F::Decimals,
            F::Unit,
            F::Inversion,
            F::Lever,
        ],
    }
}

impl<'a> TablePlan<'a> {
    /// How the table is written.
    pub fn format(&self) -> Format {
        self.format
    }

    /// The table's title, headers and notes.
    pub fn head(&self) -> Head<'_> {
        Head {
            title: &self.head.title,
            headers: &self.head.headers,
            notes: &self.head.notes,
        }
    }

    /// The angles and the row at an angle, where the table has one row an
    /// angle (every table but obliquity and harmonics), for a writer that
    /// computes the rows on several cores.
    #[allow(clippy::type_complexity)]
    pub fn row_per_angle(
        &self,
    ) -> Option<(
        &Angles<'a>,
        &(dyn Fn(f64) -> Result<Vec<String>> + Sync + 'a),
    )> {
        match &self.body {
            Body::Row(angles, row) => Some((angles, row.as_ref())),
            _ => None,
        }
    }

    /// Writes the table through `out` a row at a time, as
    /// [`super::render_rows`] writes it (nothing when a row fails).
    pub fn write(&self, out: &mut dyn FnMut(&str) -> Result<()>) -> Result<()> {
        let head = self.head();
        match &self.body {
            Body::Made => super::render_rows(
                self.format,
                &head,
                || self.head.rows.iter().cloned().map(Ok),
                out,
            ),
            Body::Row(angles, row) => {
                super::render_rows(self.format, &head, || angles.iter().map(row), out)
            }
            Body::Rows(angles, rows) => super::render_rows(
                self.format,
                &head,
                || {
                    angles.iter().flat_map(|a| match rows(a) {
                        Ok(rows) => rows.into_iter().map(Ok).collect::<Vec<_>>(),
                        Err(e) => vec![Err(e)],
                    })
                },
                out,
            ),
        }
    }

    /// The table as written, whole.
    pub fn text(&self) -> Result<String> {
        let mut text = String::new();
        self.write(&mut |s| {
            text.push_str(s);
            Ok(())
        })?;
        Ok(text)
    }

    /// The table with its rows made, held in memory.
    pub fn table(&self) -> Result<Table> {
        let mut table = self.head.clone();
        match &self.body {
            Body::Made => {}
            Body::Row(angles, row) => {
                table.rows = angles.iter().map(row).collect::<Result<_>>()?;
            }
            Body::Rows(angles, rows) => {
                for a in angles.iter() {
                    table.rows.extend(rows(a)?);
                }
            }
        }
        Ok(table)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_request_of_no_option_is_the_gallery_s_table() {
        // The gallery's tables are made by the functions of each table
        // with its defaults written out (TableName::table), apart from
        // the request.
        for name in TableName::GALLERY {
            let planned = TableRequest::new(name).plan().unwrap().text().unwrap();
            let own = name.table().unwrap().render(Format::Text);
            assert_eq!(planned, own, "{}", name.name());
        }
    }

    #[test]
    fn fields_are_refused_by_their_keys() {
        let mut r = TableRequest::new(TableName::Kinematics);
        r.force_unit = Some("N".parse().unwrap());
        let e = r.plan().unwrap_err().to_string();
        assert_eq!(e, "table kinematics does not use `force_unit`");
        let mut r = TableRequest::new(TableName::Dynamics);
        r.engine.rod_mass = Some(1.0);
        let e = r.plan().unwrap_err().to_string();
        assert_eq!(
            e,
            "the rod's mass is given by `rod_mass`, `rod_cg` and `rod_gyration` together: `rod_cg` and `rod_gyration` not given"
        );
        let angles = [0.0, f64::NAN];
        let mut r = TableRequest::new(TableName::Kinematics);
        r.angles = Some(Angles::List(&angles));
        let e = r.plan().unwrap_err().to_string();
        assert!(e.starts_with("invalid angle 'NaN'"), "{e}");
    }

    #[test]
    fn the_bound_allows_exactly_the_values_asked() {
        // Kinematics: 13 angles (0° to 360° by 30°) × 7 columns = 91.
        let mut r = TableRequest::new(TableName::Kinematics);
        r.max_cells = 91;
        assert!(r.plan().is_ok());
        r.max_cells = 90;
        let e = r.plan().unwrap_err().to_string();
        assert!(e.contains("= 91 values, more than `max_cells = 90`"), "{e}");
    }
}
