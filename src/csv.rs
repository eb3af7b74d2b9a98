//! A small CSV reader for measured data: a header line of column names,
//! then one row per line. Fields are separated by commas and trimmed;
//! blank lines and lines starting with `#` are skipped; there is no
//! quoting. Errors name the line.

use crate::error::{Error, Input, Result};

/// Most rows read from one file.
const MAX_ROWS: usize = 100_000;

/// A table read from CSV text.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Table {
    input: Input,
    what: String,
    names: Vec<String>,
    /// The unit each column's header declares, `(lbf/ft²)` or `[N/mm²]`
    /// after its name; `None` where it declares none.
    units: Vec<Option<String>>,
    /// Line number (1-based) and fields.
    rows: Vec<(usize, Vec<String>)>,
}

/// A column name without its unit: `angle (deg)` and `angle_deg` are
/// `angle`.
fn bare(name: &str) -> String {
    let name = name.trim().trim_start_matches('\u{feff}').to_lowercase();
    name.split(['(', '[', ' ', '_'])
        .next()
        .unwrap_or("")
        .to_string()
}

/// The unit a column's header declares after its name, in parentheses or
/// brackets (`expansion (lbf/ft²)`, `p [MPa]`), trimmed; `None` where it
/// declares none or leaves the brackets empty.
fn declared_unit(name: &str) -> Option<String> {
    let open = name.find(['(', '['])?;
    let close = if name[open..].starts_with('(') {
        ')'
    } else {
        ']'
    };
    let inside = &name[open + 1..];
    let unit = inside[..inside.find(close).unwrap_or(inside.len())].trim();
    (!unit.is_empty()).then(|| unit.to_string())
}

/// Longest text a field of a data file may hold (a curve's or a
/// method's name).
pub(crate) const MAX_TEXT_CHARS: usize = 80;

/// A name from the file as an error shows it: quoted, control and
/// invisible characters escaped, cut after 40 characters.
fn shown(name: &str) -> String {
    let cut: String = name.chars().take(40).collect();
    let more = if cut.len() < name.len() { "…" } else { "" };
    format!("\"{}\"{more}", cut.escape_debug())
}

impl Table {
    /// Reads `text`, the `input` named `what` in errors (`data`,
    /// `indicator diagram FILE`); its errors are [`Error::Invalid`] about
    /// `input`.
    pub(crate) fn parse(text: &str, input: Input, what: &str) -> Result<Self> {
        let mut lines = text
            .lines()
            .enumerate()
            .map(|(i, l)| (i + 1, l.trim()))
            .filter(|(_, l)| !l.is_empty() && !l.starts_with('#'));
        let Some((_, header)) = lines.next() else {
            return Err(Error::invalid(input, format!("{what}: no header line")));
        };
        let names: Vec<String> = header.split(',').map(bare).collect();
        let units = header.split(',').map(declared_unit).collect();
        let mut rows = Vec::new();
        for (n, line) in lines {
            let fields: Vec<String> = line.split(',').map(|f| f.trim().to_string()).collect();
            if fields.len() != names.len() {
                return Err(Error::invalid(
                    input,
                    format!(
                        "{what} line {n}: {} fields where the header has {}",
                        fields.len(),
                        names.len()
                    ),
                ));
            }
            if rows.len() == MAX_ROWS {
                return Err(Error::invalid(
                    input,
                    format!("{what}: more than {MAX_ROWS} rows"),
                ));
            }
            rows.push((n, fields));
        }
        if rows.is_empty() {
            return Err(Error::invalid(
                input,
                format!("{what}: no rows after the header"),
            ));
        }
        Ok(Self {
            input,
            what: what.to_string(),
            names,
            units,
            rows,
        })
    }

    /// Refuses a column whose name is none of `known`: a column the
    /// reader would pass over is named, not ignored.
    pub(crate) fn only(&self, known: &[&str]) -> Result<()> {
        match self.names.iter().find(|n| !known.contains(&n.as_str())) {
            None => Ok(()),
            Some(n) => Err(Error::invalid(
                self.input,
                format!(
                    "{}: no column is read by the name {} (the columns read are {})",
                    self.what,
                    shown(n),
                    known.join(", ")
                ),
            )),
        }
    }

    /// The index of the first column called any of `names` (without
    /// units, any case).
    pub(crate) fn column(&self, names: &[&str]) -> Result<usize> {
        self.names
            .iter()
            .position(|n| names.contains(&n.as_str()))
            .ok_or_else(|| {
                Error::invalid(
                    self.input,
                    format!(
                        "{}: no column named {} (the header has {})",
                        self.what,
                        names.join(" or "),
                        self.names.join(", ")
                    ),
                )
            })
    }

    /// The unit the header declares for the column (`lbf/ft²` of
    /// `expansion (lbf/ft²)`), `None` where it declares none.
    pub(crate) fn unit(&self, column: usize) -> Option<&str> {
        self.units.get(column).and_then(|u| u.as_deref())
    }

    /// The column's name without its unit.
    pub(crate) fn name(&self, column: usize) -> &str {
        self.names.get(column).map_or("", String::as_str)
    }

    /// The column's values as finite numbers.
    // cannot fail: every row has as many fields as the header has names
    // (`parse` refuses a row with more or fewer), and every caller passes a
    // position in the names found by `column`.
    #[allow(clippy::indexing_slicing)]
    pub(crate) fn numbers(&self, column: usize) -> Result<Vec<f64>> {
        self.rows
            .iter()
            .map(|(n, fields)| {
                let f = &fields[column];
                match f.parse::<f64>() {
                    Ok(v) if v.is_finite() => Ok(v),
                    _ => Err(Error::invalid(
                        self.input,
                        format!(
                            "{} line {n}: '{f}' in column {} is not a finite number",
                            self.what, self.names[column]
                        ),
                    )),
                }
            })
            .collect()
    }

    /// The column's texts, each a name a figure may set: at most
    /// [`MAX_TEXT_CHARS`] characters and fit as every user's text is
    /// ([`crate::error::text_fault`]), so that a field costs what a name
    /// does and writes well-formed output.
    // cannot fail: as for `numbers`, the column is one of `column`'s and
    // every row has a field for each.
    #[allow(clippy::indexing_slicing)]
    pub(crate) fn texts(&self, column: usize) -> Result<Vec<&str>> {
        self.rows
            .iter()
            .map(|(n, f)| {
                let text = f[column].as_str();
                let why = if text.chars().count() > MAX_TEXT_CHARS {
                    Some(format!("it is longer than {MAX_TEXT_CHARS} characters"))
                } else {
                    crate::error::text_fault(text)
                };
                match why {
                    None => Ok(text),
                    Some(why) => Err(Error::invalid(
                        self.input,
                        format!(
                            "{} line {n}: the {} {}: {why}",
                            self.what,
                            self.names[column],
                            shown(text)
                        ),
                    )),
                }
            })
            .collect()
    }

    /// Pairs of two numeric columns found by name.
    pub(crate) fn pairs(&self, x: &[&str], y: &[&str]) -> Result<Vec<(f64, f64)>> {
        let xs = self.numbers(self.column(x)?)?;
        let ys = self.numbers(self.column(y)?)?;
        Ok(xs.into_iter().zip(ys).collect())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_name_too_long_or_unfit_is_refused_at_its_line() {
        let long = "x".repeat(100_000);
        let t = Table::parse(&format!("curve,n\n{long},1\nok,2\n"), Input::Data, "d.csv").unwrap();
        let e = t.texts(0).unwrap_err().to_string();
        assert!(e.starts_with("d.csv line 2: the curve \"xxx"), "{e}");
        assert!(e.ends_with("it is longer than 80 characters"), "{e}");
        assert!(e.chars().count() < 200, "{e}");
        for bad in ["a\u{FFFF}", "\u{202E}b", "c\u{200B}"] {
            let t = Table::parse(&format!("curve,n\n{bad},1\n"), Input::Data, "d.csv").unwrap();
            let e = t.texts(0).unwrap_err().to_string();
            assert!(e.contains("it holds the"), "{e}");
            assert!(!e.contains(bad), "the text is shown escaped: {e}");
        }
        let t = Table::parse(
            &format!("curve,n\n{},1\n", "y".repeat(80)),
            Input::Data,
            "d",
        )
        .unwrap();
        assert_eq!(t.texts(0).unwrap()[0].len(), 80);
    }

    #[test]
    fn reads_named_columns_with_units_and_comments() {
        let t = Table::parse(
            "# Ng, Table 2\nangle (deg), force_N\n40, 9.22\n\n50,7.65\n",
            Input::Data,
            "data",
        )
        .unwrap();
        assert_eq!(
            t.pairs(&["angle"], &["force"]).unwrap(),
            [(40.0, 9.22), (50.0, 7.65)]
        );
        assert_eq!(t.texts(0).unwrap(), ["40", "50"]);
        assert_eq!(t.unit(0), Some("deg"));
        assert_eq!(t.unit(1), None);
        let t = Table::parse("p [ MPa ],q (),r (lbf/ft²\n1,2,3\n", Input::Data, "d").unwrap();
        assert_eq!(
            (t.unit(0), t.unit(1), t.unit(2)),
            (Some("MPa"), None, Some("lbf/ft²"))
        );
        assert_eq!(t.name(0), "p");
    }

    #[test]
    fn errors_name_the_line() {
        let bad = Table::parse("angle,force\n40,abc\n", Input::Data, "d.csv").unwrap();
        let e = bad.pairs(&["angle"], &["force"]).unwrap_err().to_string();
        assert!(e.contains("d.csv line 2") && e.contains("abc"), "{e}");
        let e = Table::parse("angle,force\n40\n", Input::Indicator, "d.csv").unwrap_err();
        assert_eq!(
            e.to_string(),
            "d.csv line 2: 1 fields where the header has 2"
        );
        assert!(
            matches!(
                e,
                Error::Invalid {
                    input: Input::Indicator,
                    ..
                }
            ),
            "{e:?}"
        );
        assert!(Table::parse("", Input::Data, "d").is_err());
        assert!(Table::parse("angle,force\n", Input::Data, "d").is_err());
        let e = Table::parse("theta,f\n1,2\n", Input::Data, "d")
            .unwrap()
            .column(&["angle"])
            .unwrap_err();
        assert!(e.to_string().contains("theta, f"), "{e}");
        let nan = Table::parse("angle,force\n40,NaN\n", Input::Data, "d").unwrap();
        assert!(nan.pairs(&["angle"], &["force"]).is_err());
    }
}
