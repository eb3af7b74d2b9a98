//! The request of `check` as a front end gives it: the engine or a chain
//! made of it, the poses and the allowance, checked once here for the
//! command line and the Python package, then run into the report the
//! command prints ([`CheckOutcome`]).

use super::check_report::{DEFAULT_ULPS, check_allowance, engine_check_report};
use super::{
    CHAIN_TOLERANCE, MaxCells, chain_check_report, coriolis_check_title, quadric_check_title,
    slot_check_title,
};
use crate::chain::{
    Assembly, ChainCheckRow, CylindricChain, Inversion, InvertedChain, QuadricChain,
    coriolis_sweep, quadric_sweep, slot_sweep,
};
use crate::construct::{Quantity, SweepReport, sweep};
use crate::error::{Error, Field, Input, Result, Wording};
use crate::mechanism::SliderCrank;
use crate::sources::ENGINE_35;

/// Equally spaced poses a check compares when none are given.
pub const DEFAULT_SAMPLES: usize = 100_000;

/// What a user asks of `check`; `None` leaves the command's own value
/// (the §35 engine, in line; every construction of the engine). Each
/// field is the option of its name on every front end ([`Field::key`]).
/// [`CheckRequest::plan`] checks it: the chain fields one at a time, not
/// `links` with a length of the engine, `assembly` only with `links`,
/// `inversion` 2 or 3 only (the inversions with polygons of their own),
/// the allowance and the poses × quantities against `max_cells`.
///
/// Fields may be added in later versions: start from
/// [`CheckRequest::default`] and set the fields wanted.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct CheckRequest {
    /// The crank radius r.
    pub crank: Option<f64>,
    /// The rod length l.
    pub rod: Option<f64>,
    /// The offset e of the line of stroke (0 when not given).
    pub offset: Option<f64>,
    /// Equally spaced poses over the turn, at least 1 (the dead centres,
    /// 0°, 90°, 180° and 270° are always added).
    pub samples: usize,
    /// The allowance, in the scaled units of the design's §6: the engine's
    /// differences pass at most `tolerance` × κ (4 ulps by default), a
    /// chain's at most `tolerance` ([`CHAIN_TOLERANCE`] by default).
    pub tolerance: Option<f64>,
    /// The block in a circular slot of this radius (Fig. 60 b).
    pub slot_radius: Option<f64>,
    /// A quadric crank chain of these links a, b, c, d in place of the
    /// engine (Fig. 60 a).
    pub links: Option<[f64; 4]>,
    /// The quadric chain's assembly (open when not given).
    pub assembly: Option<Assembly>,
    /// The engine's chain with the crank (2) or the rod (3) fixed: its
    /// velocity and acceleration polygons with the Coriolis component.
    pub inversion: Option<u32>,
    /// The most poses × quantities compared ([`MaxCells`]).
    pub max_cells: u64,
}

impl Default for CheckRequest {
    /// The request of no option: `slider-crank check`.
    fn default() -> Self {
        CheckRequest {
            crank: None,
            rod: None,
            offset: None,
            samples: DEFAULT_SAMPLES,
            tolerance: None,
            slot_radius: None,
            links: None,
            assembly: None,
            inversion: None,
            max_cells: super::DEFAULT_MAX_CELLS,
        }
    }
}

/// What a check compares.
#[derive(Debug)]
enum Subject {
    Engine,
    Slot(CylindricChain, f64),
    Quadric(QuadricChain),
    Inversion(InvertedChain, u32),
}

/// A check checked and ready to run: what it compares, at how many poses,
/// within what allowance.
#[derive(Debug)]
pub struct CheckPlan {
    mechanism: SliderCrank,
    subject: Subject,
    samples: usize,
    tolerance: f64,
}

/// What a check found: the report the command prints, whether every
/// quantity passed, and the rows it was written from.
#[derive(Debug, Clone, PartialEq)]
pub struct CheckOutcome {
    /// The report, byte for byte as `check` prints it.
    pub text: String,
    /// Whether every quantity is within the allowance (`check`'s exit
    /// status 0).
    pub passed: bool,
    /// The allowance the differences were held to.
    pub tolerance: f64,
    /// The rows: the engine's sweep or a chain's.
    pub rows: CheckRows,
}

/// The rows of a check's report.
#[derive(Debug, Clone, PartialEq)]
pub enum CheckRows {
    /// Every construction of the engine against the analytic core.
    Engine(SweepReport),
    /// A chain's quantities, each against its exact value.
    Chain(Vec<ChainCheckRow>),
}

impl CheckRequest {
    /// The request checked: the engine (or the chain made of it), the
    /// poses and the allowance, the size against `max_cells`.
    pub fn plan(&self) -> Result<CheckPlan> {
        let m = SliderCrank::new(
            self.crank.unwrap_or(ENGINE_35.0),
            self.rod.unwrap_or(ENGINE_35.1),
            self.offset.unwrap_or(0.0),
        )?;
        self.refuse_pairs()?;
        let engine_default = DEFAULT_ULPS * f64::EPSILON;
        let tolerance = check_allowance(self.samples, self.tolerance, engine_default)?;
        MaxCells::new(self.max_cells).check_poses(self.samples as u64, Quantity::ALL.len())?;
        let subject = self.subject(m)?;
        let tolerance = match subject {
            Subject::Engine => tolerance,
            _ => self.tolerance.unwrap_or(CHAIN_TOLERANCE),
        };
        Ok(CheckPlan {
            mechanism: m,
            subject,
            samples: self.samples,
            tolerance,
        })
    }

    /// Refuses the chain fields given together, `links` with a length of
    /// the engine, `assembly` without `links`.
    fn refuse_pairs(&self) -> Result<()> {
        let lengths = [
            (Field::Crank, self.crank.is_some()),
            (Field::Rod, self.rod.is_some()),
            (Field::Offset, self.offset.is_some()),
        ];
        super::analyze::refuse_chain_pairs(
            self.slot_radius.is_some(),
            self.links.is_some(),
            self.inversion.is_some(),
            self.assembly.is_some(),
            &lengths,
        )
    }

    /// What the request compares: a chain where one is given, else the
    /// engine.
    fn subject(&self, m: SliderCrank) -> Result<Subject> {
        if let Some(rho) = self.slot_radius {
            return Ok(Subject::Slot(CylindricChain::new(m, rho)?, rho));
        }
        if let Some([a, b, c, d]) = self.links {
            let q = QuadricChain::new(a, b, c, d)?;
            return Ok(Subject::Quadric(q));
        }
        if let Some(n) = self.inversion {
            let inversion = Inversion::from_number(n)?;
            if !matches!(inversion, Inversion::Crank | Inversion::Rod) {
                return Err(Error::refused(
                    Input::Options,
                    Wording::default().option(Field::Inversion).then(format!(
                        " {n}: only inversions 2 and 3 have polygons of their own (the Coriolis component); every inversion has the engine's relative motion, which the engine's check covers"
                    )),
                ));
            }
            return Ok(Subject::Inversion(InvertedChain::new(m, inversion), n));
        }
        Ok(Subject::Engine)
    }
}

impl CheckPlan {
    /// Compares every quantity at the poses: the report and its rows.
    /// Time grows with the poses (bounded by the request's `max_cells`).
    pub fn run(&self) -> CheckOutcome {
        let m = &self.mechanism;
        let (title, rows) = match &self.subject {
            Subject::Engine => {
                let report = sweep(m, self.samples);
                let (text, passed) = engine_check_report(m, &report, self.tolerance);
                return self.outcome(text, passed, CheckRows::Engine(report));
            }
            Subject::Slot(s, rho) => (slot_check_title(m, *rho), slot_sweep(s, self.samples)),
            Subject::Quadric(q) => (quadric_check_title(q), quadric_sweep(q, self.samples)),
            Subject::Inversion(chain, n) => (
                coriolis_check_title(m, *n),
                coriolis_sweep(chain, self.samples),
            ),
        };
        let (text, passed) = chain_check_report(&title, &rows, self.tolerance);
        self.outcome(text, passed, CheckRows::Chain(rows))
    }

    fn outcome(&self, text: String, passed: bool, rows: CheckRows) -> CheckOutcome {
        CheckOutcome {
            text,
            passed,
            tolerance: self.tolerance,
            rows,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn refused(r: &CheckRequest) -> String {
        r.plan().unwrap_err().to_string()
    }

    #[test]
    fn the_default_allowance_is_four_ulps_for_the_engine_and_1e_12_for_a_chain() {
        let engine = CheckRequest {
            samples: 36,
            ..CheckRequest::default()
        };
        let outcome = engine.plan().unwrap().run();
        assert_eq!(outcome.tolerance, 4.0 * f64::EPSILON);
        assert!(outcome.passed && matches!(outcome.rows, CheckRows::Engine(_)));
        let slot = CheckRequest {
            slot_radius: Some(4.0),
            ..engine.clone()
        };
        let outcome = slot.plan().unwrap().run();
        assert_eq!(outcome.tolerance, 1e-12);
        assert!(matches!(&outcome.rows, CheckRows::Chain(rows) if !rows.is_empty()));
        let given = CheckRequest {
            tolerance: Some(1e-9),
            ..slot
        };
        assert_eq!(given.plan().unwrap().run().tolerance, 1e-9);
    }

    #[test]
    fn fields_that_do_not_go_together_are_refused_by_their_keys() {
        let base = CheckRequest::default();
        let links_and_rod = CheckRequest {
            links: Some([1.0, 3.0, 3.0, 3.0]),
            rod: Some(3.0),
            ..base.clone()
        };
        assert!(refused(&links_and_rod).contains("`links` cannot be used with `rod`"));
        let assembly_alone = CheckRequest {
            assembly: Some(Assembly::Crossed),
            ..base.clone()
        };
        assert!(refused(&assembly_alone).contains("`assembly` is the quadric chain's"));
        let pump = CheckRequest {
            inversion: Some(4),
            ..base.clone()
        };
        assert!(refused(&pump).contains("`inversion` 4: only inversions 2 and 3"));
        let no_pose = CheckRequest {
            samples: 0,
            ..base.clone()
        };
        assert!(refused(&no_pose).contains("at least 1 pose"));
        let too_many = CheckRequest {
            max_cells: 10,
            ..base
        };
        assert!(refused(&too_many).contains("100000 poses"));
    }
}
