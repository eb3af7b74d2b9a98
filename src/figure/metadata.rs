//! What a figure records beside what it draws, written to the SVG's
//! `<metadata>` (docs/design.md §4): the engine, the speed and the pose,
//! every plot's area and axes (typed, for the keys more than one figure
//! writes and a reader looks up), and the figure's own values under keys of
//! its choosing.

use serde::Serialize;
use serde_json::{Map, Value};

/// The engine a figure draws, as its metadata records it (the key
/// `mechanism`): the three lengths in `unit`.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct EngineRecord {
    /// The crank's length r.
    pub crank: f64,
    /// The rod's length l.
    pub rod: f64,
    /// The offset e of the line of stroke (0: in line).
    pub offset: f64,
    /// The lengths' unit, as printed (`ft`, `m`); empty for none.
    pub unit: String,
}

/// How an axis of a plot places its values, as the record names it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum AxisScale {
    /// Equal steps of value are equal lengths.
    Linear,
    /// Equal ratios are equal lengths.
    Log,
}

/// One axis of a plot: its title (plain text), the range it shows and its
/// scale.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct AxisRecord {
    /// The title, without markup.
    pub title: String,
    /// The least value shown.
    pub min: f64,
    /// The greatest value shown.
    pub max: f64,
    /// Linear or logarithmic.
    pub scale: AxisScale,
}

/// A plot of the figure (an item of `plots`): the panel it draws in, its
/// plot area on the page (`[x, y, width, height]`) and, for a plot with
/// axes, the two axes.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PlotRecord {
    /// The id of the plot's panel.
    pub panel: String,
    /// The plot area, page units: left, top, width, height.
    pub area: [f64; 4],
    /// The horizontal axis (`None`: a plot without axes, a polar diagram).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub x: Option<AxisRecord>,
    /// The vertical axis (`None` with `x`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub y: Option<AxisRecord>,
}

/// What a figure records beside what it draws. Each typed part is written
/// under its key only when set (`mechanism`, `omega`, `angle_deg`, `plots`
/// when there is one); the figure's own values ([`Metadata::insert`])
/// under theirs. The writer adds its own keys (docs/design.md §4); the
/// keys are written in their sorted order, whatever the order they were
/// set in.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Metadata {
    engine: Option<EngineRecord>,
    omega: Option<f64>,
    angle_deg: Option<f64>,
    plots: Vec<PlotRecord>,
    values: Map<String, Value>,
}

impl Metadata {
    /// No record at all: a figure that draws no engine (a plot of data)
    /// and sets none.
    pub fn new() -> Self {
        Self::default()
    }

    /// Records the engine drawn.
    pub fn set_engine(&mut self, engine: EngineRecord) {
        self.engine = Some(engine);
    }

    /// Records the crank's angular speed ω, rad/s.
    pub fn set_omega(&mut self, omega: f64) {
        self.omega = Some(omega);
    }

    /// Records the pose drawn, the crank angle θ in degrees (the first of
    /// several poses held in one view).
    pub fn set_angle_deg(&mut self, degrees: f64) {
        self.angle_deg = Some(degrees);
    }

    /// Adds a plot's record, after those added before.
    pub fn push_plot(&mut self, plot: PlotRecord) {
        self.plots.push(plot);
    }

    /// Records one of the figure's own values under `key`, replacing one
    /// recorded there before; under a key of a typed part (`mechanism`,
    /// `omega`, `angle_deg`, `plots`) it is replaced by the typed part
    /// when written, if that part is set.
    pub fn insert(&mut self, key: impl Into<String>, value: Value) {
        self.values.insert(key.into(), value);
    }

    /// The engine drawn (`None`: a figure that records none).
    pub fn engine(&self) -> Option<&EngineRecord> {
        self.engine.as_ref()
    }

    /// The crank's angular speed, rad/s, where recorded.
    pub fn omega(&self) -> Option<f64> {
        self.omega
    }

    /// The pose drawn, degrees, where recorded.
    pub fn angle_deg(&self) -> Option<f64> {
        self.angle_deg
    }

    /// The plots' records, in the order added (empty: no plot).
    pub fn plots(&self) -> &[PlotRecord] {
        &self.plots
    }

    /// The figure's own value under `key` (`None`: not recorded; the typed
    /// parts are read by their own methods).
    pub fn value(&self, key: &str) -> Option<&Value> {
        self.values.get(key)
    }

    /// The same record with every number rounded by `round` (the typed
    /// parts' numbers and every non-integer number of the values, however
    /// deep), for text that stays the same where the last bits of a
    /// computation differ.
    pub fn rounded(mut self, round: impl Fn(f64) -> f64 + Copy) -> Self {
        if let Some(e) = &mut self.engine {
            (e.crank, e.rod, e.offset) = (round(e.crank), round(e.rod), round(e.offset));
        }
        self.omega = self.omega.map(round);
        self.angle_deg = self.angle_deg.map(round);
        for p in &mut self.plots {
            p.area = p.area.map(round);
            for a in [&mut p.x, &mut p.y].into_iter().flatten() {
                (a.min, a.max) = (round(a.min), round(a.max));
            }
        }
        self.values
            .values_mut()
            .for_each(|v| round_numbers(v, round));
        self
    }

    /// The JSON object of the record: the values, then the typed parts
    /// that are set over them.
    pub fn to_json(&self) -> Map<String, Value> {
        let mut map = self.values.clone();
        let mut put = |key: &str, value: Option<Value>| {
            if let Some(v) = value {
                map.insert(key.into(), v);
            }
        };
        put("mechanism", self.engine.as_ref().map(to_value));
        put("omega", self.omega.map(Value::from));
        put("angle_deg", self.angle_deg.map(Value::from));
        put(
            "plots",
            (!self.plots.is_empty())
                .then(|| Value::Array(self.plots.iter().map(to_value).collect())),
        );
        map
    }
}

/// A record as JSON (`Null` for one serde cannot write: none of these
/// types has a map with keys that are not strings, so never).
fn to_value(record: &impl Serialize) -> Value {
    serde_json::to_value(record).unwrap_or(Value::Null)
}

/// Rounds every non-integer number in `v` by `round`.
fn round_numbers(v: &mut Value, round: impl Fn(f64) -> f64 + Copy) {
    match v {
        Value::Number(n) => {
            if let Some(x) = n.as_f64()
                && !n.is_i64()
                && !n.is_u64()
            {
                *v = Value::from(round(x));
            }
        }
        Value::Array(a) => a.iter_mut().for_each(|v| round_numbers(v, round)),
        Value::Object(o) => o.values_mut().for_each(|v| round_numbers(v, round)),
        _ => {}
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    fn engine() -> EngineRecord {
        EngineRecord {
            crank: 0.5,
            rod: 3.0,
            offset: 0.0,
            unit: "ft".into(),
        }
    }

    #[test]
    fn an_empty_record_writes_no_key() {
        assert!(Metadata::new().to_json().is_empty());
    }

    #[test]
    fn the_typed_parts_are_written_under_their_keys_over_a_value_of_the_same_key() {
        let mut m = Metadata::new();
        m.insert("mechanism", json!("overwritten"));
        m.insert("ratios", json!([1, 2]));
        m.set_engine(engine());
        m.set_omega(26.0);
        let json = Value::Object(m.to_json());
        assert_eq!(
            json,
            json!({"mechanism": {"crank": 0.5, "rod": 3.0, "offset": 0.0, "unit": "ft"},
                   "omega": 26.0, "ratios": [1, 2]})
        );
        assert_eq!(m.value("ratios"), Some(&json!([1, 2])));
        assert_eq!(m.engine().map(|e| e.rod), Some(3.0));
        assert_eq!(m.angle_deg(), None);
    }

    #[test]
    fn a_plot_without_axes_writes_none_and_plots_keep_their_order() {
        let mut m = Metadata::new();
        let axis = AxisRecord {
            title: "θ".into(),
            min: 0.0,
            max: 360.0,
            scale: AxisScale::Log,
        };
        for (panel, x) in [("panel-b", Some(axis)), ("panel-a", None)] {
            m.push_plot(PlotRecord {
                panel: panel.into(),
                area: [1.0, 2.0, 3.0, 4.0],
                y: x.clone(),
                x,
            });
        }
        let plots = &m.to_json()["plots"];
        assert_eq!(plots[0]["panel"], "panel-b");
        assert_eq!(plots[0]["x"]["scale"], "log");
        assert_eq!(
            plots[1],
            json!({"panel": "panel-a", "area": [1.0, 2.0, 3.0, 4.0]})
        );
    }

    #[test]
    fn rounding_reaches_every_number_but_integers() {
        let mut m = Metadata::new();
        m.set_engine(engine());
        m.set_angle_deg(60.000_000_000_001);
        m.insert("deep", json!({"a": [0.1 + 0.2, 7]}));
        let r = m.rounded(|x| (x * 1e6).round() / 1e6);
        assert_eq!(r.angle_deg(), Some(60.0));
        assert_eq!(r.value("deep"), Some(&json!({"a": [0.3, 7]})));
    }
}
