//! Where each named figure comes from in the seeds, and what it shows: the
//! captions of the gallery.

use super::FigureName;
use super::specs::Source;

/// The textbook chapter, as the captions name it.
const BOOK: &str = "Textbook, Chapter IV “Slider-crank chains”";

/// Ng's paper, as the captions name it.
const NG: &str = "Ng, “A slider-crank experiment to determine the action of static forces”";

impl FigureName {
    /// The seed, section and figure it reproduces (`Textbook, Chapter IV
    /// “Slider-crank chains”, §36, Fig. 67`); for a figure the seed
    /// describes without drawing, the section and equations it is drawn
    /// from; `curve-benchmark` says it is not from the seeds.
    pub fn source(&self) -> String {
        match self.spec().source {
            Source::Book(place) => format!("{BOOK}, {place}"),
            Source::Ng(place) => format!("{NG}, {place}"),
            Source::Outside(whole) => whole.to_string(),
        }
    }

    /// What it shows, in a sentence or two, at the seed's own parameters.
    pub fn description(&self) -> &'static str {
        self.spec().caption
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_figure_names_its_seed_and_section() {
        for f in FigureName::ALL {
            let source = f.source();
            let seed = source.starts_with(BOOK) && source.contains('§')
                || source.starts_with(NG) && source.contains("Fig. ");
            assert!(
                seed || f == FigureName::CurveBenchmark,
                "{}: {source}",
                f.name()
            );
            assert!(!f.description().is_empty());
        }
    }
}
