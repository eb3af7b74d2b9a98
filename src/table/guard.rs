//! The one bound on the size of a request: the values a table, a sweep of
//! `analyze` or a check computes (rows × columns), checked before any of
//! them is computed. The command line's option and the Python package's
//! keyword are this bound, with the same default and the same message
//! (naming the field [`Field::MaxCells`], which each spells its way).

use crate::error::{Error, Field, Input, Result, Wording};

/// The default bound: fifty million values, about a gigabyte of text and
/// a minute of work (a million angles of the analysis's JSON are 45
/// million).
pub const DEFAULT_MAX_CELLS: u64 = 50_000_000;

/// The most values one request may compute: rows × columns of a table,
/// angles × the values of each for `analyze`, poses × the quantities
/// compared for `check`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct MaxCells {
    /// The most values allowed (0: none, so that any request of a
    /// value is refused).
    pub limit: u64,
}

impl MaxCells {
    /// The bound `limit`.
    pub const fn new(limit: u64) -> Self {
        MaxCells { limit }
    }

    /// Checks `rows` × `columns` against the bound; `rows_are` and
    /// `columns_are` say what they are for the message (`100000 angles ×
    /// 200 ratios = 20000000 rows`, `columns`), `command` what asks
    /// (`table obliquity`). The product is taken in 128 bits: it never
    /// overflows.
    ///
    /// Errors: [`Error::Invalid`] (about the options) naming the product
    /// and the bound that would allow it, as the field
    /// [`Field::MaxCells`].
    pub fn check(
        &self,
        command: &str,
        (rows, rows_are): (u64, &str),
        (columns, columns_are): (u64, &str),
    ) -> Result<()> {
        let cells = u128::from(rows) * u128::from(columns);
        if cells <= u128::from(self.limit) {
            return Ok(());
        }
        Err(Error::refused(
            Input::Options,
            Wording::from(format!(
                "{command} asks for {rows_are} × {columns} {columns_are} = {cells} values, more than "
            ))
            .set(Field::MaxCells, self.limit)
            .then(": give ")
            .set(Field::MaxCells, cells)
            .then(" (or more) to compute them, or fewer angles"),
        ))
    }

    /// [`check`](Self::check) of a table with a row per angle: `angles`
    /// rows of `columns` columns (`table kinematics asks for 10000000
    /// angles × 7 columns = …`).
    pub fn check_angles(&self, command: &str, angles: u64, columns: usize) -> Result<()> {
        self.check(
            command,
            (angles, &format!("{angles} angles")),
            (columns as u64, "columns"),
        )
    }

    /// [`check`](Self::check) of `table dynamics`: a row per angle of
    /// `columns` columns, the last of which, with several cylinders, sums
    /// a torque for each of `cylinders`: each counts as a value.
    pub fn check_cylinders(&self, angles: u64, columns: usize, cylinders: usize) -> Result<()> {
        let extra = cylinders.saturating_sub(1);
        self.check(
            "table dynamics",
            (angles, &format!("{angles} angles")),
            (
                (columns + extra) as u64,
                &format!("columns and cylinders' torques ({cylinders} cylinders)"),
            ),
        )
    }

    /// [`check`](Self::check) of `table obliquity`: a row per angle and
    /// ratio, `columns` columns.
    pub fn check_obliquity(&self, angles: u64, ratios: u64, columns: usize) -> Result<()> {
        let rows = angles.saturating_mul(ratios);
        self.check(
            "table obliquity",
            (
                rows,
                &format!("{angles} angles × {ratios} ratios = {rows} rows"),
            ),
            (columns as u64, "columns"),
        )
    }

    /// [`check`](Self::check) of `check`: `poses` poses, `quantities`
    /// quantities compared at each.
    pub fn check_poses(&self, poses: u64, quantities: usize) -> Result<()> {
        self.check(
            "check",
            (poses, &format!("{poses} poses")),
            (quantities as u64, "quantities"),
        )
    }
}

impl Default for MaxCells {
    /// [`DEFAULT_MAX_CELLS`].
    fn default() -> Self {
        MaxCells::new(DEFAULT_MAX_CELLS)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_bound_allows_exactly_the_limit_and_names_itself_as_a_field() {
        let bound = MaxCells::new(600);
        assert!(bound.check_angles("table kinematics", 100, 6).is_ok());
        let e = bound.check_angles("table kinematics", 100, 7).unwrap_err();
        assert_eq!(
            e.to_string(),
            "table kinematics asks for 100 angles × 7 columns = 700 values, more than `max_cells = 600`: give `max_cells = 700` (or more) to compute them, or fewer angles"
        );
        let e = MaxCells::default()
            .check_obliquity(100_000, 10_000, 3)
            .unwrap_err();
        let Error::Invalid { message, .. } = &e else {
            panic!("{e:?}")
        };
        assert_eq!(
            message.fields().collect::<Vec<_>>(),
            [Field::MaxCells, Field::MaxCells]
        );
        assert!(
            e.to_string().contains(
                "1000000000 rows × 3 columns = 3000000000 values, more than `max_cells = 50000000`: give `max_cells = 3000000000` (or more)"
            ),
            "{e}"
        );
    }

    #[test]
    fn each_cylinder_s_torque_counts() {
        // 64 cylinders cost 63 more torques a row than one.
        let flag = MaxCells::new(1100);
        assert!(flag.check_cylinders(100, 11, 1).is_ok());
        let e = flag.check_cylinders(100, 11, 64).unwrap_err().to_string();
        assert!(
            e.contains(
                "100 angles × 74 columns and cylinders' torques (64 cylinders) = 7400 values"
            ),
            "{e}"
        );
    }

    #[test]
    fn the_product_does_not_overflow() {
        let e = MaxCells::default()
            .check_obliquity(u64::MAX, u64::MAX, usize::MAX)
            .unwrap_err();
        assert!(e.to_string().contains(&format!(
            "= {} values",
            u128::from(u64::MAX) * u128::from(u64::MAX)
        )));
        assert!(MaxCells::new(0).check_poses(0, 6).is_ok());
        assert!(MaxCells::new(0).check_poses(1, 6).is_err());
    }
}
