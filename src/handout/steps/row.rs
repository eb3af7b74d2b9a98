//! The rows of a step's table and the values in them.

/// A value shown on a page: its name as the analysis's JSON gives it
/// (`graphical.velocity`; `construction.CE` for the lengths of the
/// constructions) and the number, `None` where there is none (D at
/// infinity, a dead centre's force).
#[derive(Debug, Clone, PartialEq)]
pub(in crate::handout) struct Value {
    pub key: &'static str,
    pub value: Option<f64>,
    /// What is written where there is no number.
    pub none: &'static str,
}

impl Value {
    pub fn of(key: &'static str, value: f64) -> Self {
        Self {
            key,
            value: Some(value),
            none: "",
        }
    }

    pub fn maybe(key: &'static str, value: Option<f64>, none: &'static str) -> Self {
        Self { key, value, none }
    }
}

/// A row of a step's table: a quantity, the value read off the
/// construction (if it is read off one), the exact value, the unit.
#[derive(Debug, Clone, PartialEq)]
pub(in crate::handout) struct Row {
    /// The quantity, in rich-text markup.
    pub quantity: String,
    pub read: Option<Value>,
    pub exact: Option<Value>,
    pub unit: String,
    /// Whether the student is asked for it on an exercise sheet.
    pub asked: bool,
}

impl Row {
    /// A row the student is asked for.
    pub(super) fn new(
        quantity: &str,
        read: Option<Value>,
        exact: Option<Value>,
        unit: &str,
    ) -> Self {
        Self {
            quantity: quantity.into(),
            read,
            exact,
            unit: unit.into(),
            asked: true,
        }
    }

    /// The row, shown on the key but not asked for on the sheet.
    pub(super) fn not_asked(mut self) -> Self {
        self.asked = false;
        self
    }
}
