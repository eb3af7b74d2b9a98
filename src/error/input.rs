//! The kinds of input an [`Error::Invalid`](super::Error::Invalid) is about.

/// What a user gave that was not understood: the kind of input an
/// [`Error::Invalid`](super::Error::Invalid) is about, so that a caller
/// sorts errors by kind rather than by their text (the command line puts
/// the data file's path before an error of [`Input::Data`]).
///
/// Its `Display` is how a message names that input (`data file`, `scene
/// file`); the error's own message says what was wrong.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Input {
    /// Crank angles: one angle, a list or a range (`0:360:30`), or the
    /// angles a scene or an animation is drawn at (none is an error).
    Angles,
    /// The names of a mechanism figure's layers.
    Layers,
    /// A page length with its unit (`120mm`).
    PageLength,
    /// A figure's title.
    Title,
    /// The name of a length or force unit.
    Unit,
    /// The name of a notation (`textbook`, `ng`).
    Notation,
    /// The name of a drawing style.
    Style,
    /// The name of a font.
    Font,
    /// The name of a calibration line's fit.
    Fit,
    /// The name of a quadric chain's assembly (`open`, `crossed`).
    Assembly,
    /// The name of a handout's paper size.
    Paper,
    /// The name of an output format (`svg`, `png`, `pdf`).
    FileFormat,
    /// The name of a table's format (`text`, `markdown`, `csv`).
    TableFormat,
    /// The path of a file to write, whose extension names no format the
    /// command writes.
    OutputFile,
    /// The name of a figure, or a figure of the wrong kind for the request
    /// (a diagram where a mechanism figure is needed).
    FigureName,
    /// Options that do not go together, or an option the figure, table or
    /// command does not use.
    Options,
    /// A scene file (TOML): its syntax, keys and values.
    Scene,
    /// A gallery's manifest and the entries it names.
    Manifest,
    /// The measured data (CSV) a figure draws ([`crate::Field::Data`]).
    Data,
    /// An indicator diagram (CSV) of the engine's gas pressures.
    Indicator,
    /// The points a calibration line is fitted through.
    Calibration,
    /// An SVG read back to be written as PNG or PDF, or a face it holds.
    Svg,
    /// The four link lengths of a quadric chain (`a,b,c,d`).
    Links,
    /// The command line as a whole, as its parser reports it.
    CommandLine,
}

impl Input {
    /// How a message names the input (`data file`, `angles`).
    pub fn name(self) -> &'static str {
        match self {
            Input::Angles => "angles",
            Input::Layers => "layers",
            Input::PageLength => "page length",
            Input::Title => "title",
            Input::Unit => "unit name",
            Input::Notation => "notation",
            Input::Style => "style",
            Input::Font => "font",
            Input::Fit => "fit",
            Input::Assembly => "assembly",
            Input::Paper => "paper",
            Input::FileFormat => "format",
            Input::TableFormat => "table format",
            Input::OutputFile => "output file",
            Input::FigureName => "figure name",
            Input::Options => "options",
            Input::Scene => "scene file",
            Input::Manifest => "manifest",
            Input::Data => "data file",
            Input::Indicator => "indicator diagram",
            Input::Calibration => "calibration data",
            Input::Svg => "SVG",
            Input::Links => "links",
            Input::CommandLine => "command line",
        }
    }
}

impl std::fmt::Display for Input {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

#[cfg(test)]
mod tests {
    use super::Input;
    use crate::analytic::calibration::fit_with_intercept;
    use crate::catalogue::Fit;
    use crate::dynamics::IndicatorDiagram;
    use crate::error::Error;
    use crate::figure::Style;

    /// The message `r`'s error prints and the kind of input it is about.
    fn refused<T: std::fmt::Debug>(r: crate::error::Result<T>) -> (Input, String) {
        match r {
            Err(e @ Error::Invalid { input, .. }) => (input, e.to_string()),
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn errors_name_their_input_and_read_as_before() {
        assert_eq!(
            refused("bold".parse::<Style>()),
            (
                Input::Style,
                "unknown style 'bold': expected textbook or handout".to_string()
            )
        );
        assert_eq!(
            refused("linear".parse::<Fit>()),
            (
                Input::Fit,
                "unknown fit 'linear': expected origin, intercept or both".to_string()
            )
        );
        assert_eq!(
            refused(fit_with_intercept(&[(1.0, 2.0)])),
            (
                Input::Calibration,
                "a line fit needs at least 2 points, got 1".to_string()
            )
        );
        let one_row = IndicatorDiagram::new(vec![0.0], vec![1.0], vec![1.0], 1.0);
        assert_eq!(
            refused(one_row),
            (
                Input::Indicator,
                "an indicator diagram has 2 to 10000 rows, each with a fraction and two pressures"
                    .to_string()
            )
        );
    }
}
