//! Scene files: every error names its line and column (that every
//! example builds is `tests/library/scene_format.rs`).

use slider_crank::figure::PageUnit;
use slider_crank::render::to_svg;
use slider_crank::{FigureName, Layer, Scene, SceneFile, Style, Units};

/// The scene of a scene file that describes a mechanism figure.
fn read_scene(text: &str) -> slider_crank::Result<Scene> {
    SceneFile::from_toml(text)?.into_scene()
}

fn error(text: &str) -> String {
    read_scene(text).unwrap_err().to_string()
}

#[test]
fn a_misspelt_key_is_named_with_its_line_and_column() {
    let e = error("name = \"x\"\nlayers = [\"mechanism\"]\nanlge = 45\n");
    assert!(e.starts_with("line 3, column 1:"), "{e}");
    assert!(e.contains("anlge"), "{e}");
    // Inside a table, indented.
    let e = error("[mechanism]\ncrank = 0.5\n  rdo = 3.0\n");
    assert!(e.starts_with("line 3, column 3:"), "{e}");
    assert!(e.contains("rdo"), "{e}");
}

#[test]
fn a_bad_value_is_named_with_its_line_and_column() {
    let e = error("angle = 30\nlayers = [\"mechanism\", \"kisc\"]\n");
    assert!(e.starts_with("line 2, column 24:"), "{e}");
    assert!(e.contains("kisc") && e.contains("kisch"), "{e}");
    let e = error("style = \"book\"\n");
    assert!(e.starts_with("line 1, column 9:"), "{e}");
    let e = error("[mechanism]\ncrank = -1\nrod = 3\n");
    assert!(e.starts_with("line 2, column 9:"), "{e}");
    assert!(e.contains("crank must be greater than zero"), "{e}");
    let e = error("[mechanism]\ncrank = 1\nrod = 1.5\noffset = 0.6\n");
    assert!(e.starts_with("line 3, column 7:"), "{e}");
    assert!(e.contains("too short"), "{e}");
    let e = error("angle = 10\nangles = [1, 2]\n");
    assert!(e.starts_with("line 2, column 10:"), "{e}");
    let e = error("[page]\nwidth = 10\n");
    assert!(e.starts_with("line 2, column 9:"), "{e}");
    let e = error("coupler = 1.5\n");
    assert!(e.starts_with("line 1, column 11:"), "{e}");
    let e = error("figure = \"fig-64\"\n");
    assert!(
        e.starts_with("line 1, column 10:") && e.contains("fig-67-example"),
        "{e}"
    );
    let e = error("angle = \"forty\"\n");
    assert!(e.starts_with("line 1, column 9:"), "{e}");
}

#[test]
fn broken_toml_is_located_too() {
    let e = error("angle = 45\nlayers = [\"mechanism\"\n");
    assert!(e.starts_with("line "), "{e}");
}

#[test]
fn a_named_figure_can_be_restyled_in_a_scene_file() {
    let s = read_scene("figure = \"fig-67-example\"\nstyle = \"handout\"\n").unwrap();
    assert_eq!(s.name(), "fig-67-example");
    assert_eq!(s.style(), Style::Handout);
    assert!(s.has(Layer::Kisch) && s.has(Layer::Scales));
    assert_eq!(s.angles()[0].degrees(), 45.0);
    assert!(s.is_mirrored());
}

/// The text of the SVG element with id `id`, markup removed.
fn text_of(svg: &str, id: &str) -> String {
    let start = svg
        .find(&format!("id=\"{id}\""))
        .unwrap_or_else(|| panic!("no {id}"));
    let body = &svg[start..];
    let body = &body[body.find('>').unwrap() + 1..body.find("</text>").unwrap()];
    let mut out = String::new();
    let mut in_tag = false;
    for c in body.chars() {
        match c {
            '<' => in_tag = true,
            '>' => in_tag = false,
            // The notes keep a symbol with its value by no-break spaces.
            '\u{a0}' if !in_tag => out.push(' '),
            c if !in_tag => out.push(c),
            _ => {}
        }
    }
    out.replace("&lt;", "<")
        .replace("&gt;", ">")
        .replace("&amp;", "&")
}

#[test]
fn a_force_beyond_the_largest_number_is_not_drawn_as_a_dead_centre() {
    // Issue 9 (6), on the figure: T = 1e308 on r = 1e-100, l = 3e-100 at
    // 45°, where OM = 8.8e-101 is small but not zero. The notes said "dead
    // centre: OM = 0" and wrote F_c = T/r = inf as 0.
    let scene = |angle: f64, rod: &str| {
        let text = format!(
            "angle = {angle}\nlayers = [\"mechanism\", \"velocity\", \"torque\"]\ntorque = 1e308\n\
             [mechanism]\ncrank = 1e-100\nrod = {rod}\n"
        );
        to_svg(&read_scene(&text).unwrap().figure().unwrap())
    };
    let svg = scene(45.0, "3e-100");
    let om = text_of(&svg, "note-scales-1");
    assert!(om.contains("8.786×10−101"), "{om}");
    let forces = text_of(&svg, "note-scales-2");
    assert!(!forces.contains("dead centre"), "{forces}");
    assert!(forces.contains("Fc = T/r exceeds 1.798×10308"), "{forces}");
    assert!(forces.contains("Fp = T/CE exceeds 1.798×10308"), "{forces}");
    // The slider force's arrow is drawn in the sense of T / OM.
    assert!(svg.contains("id=\"force-Fp\""));
    for bad in ["inf", "NaN", "= 0 "] {
        assert!(!forces.contains(bad), "{bad}: {forces}");
    }
    // A hair from the dead centre, OM = 2.3e-332 is below the smallest
    // number: not written 0, not a dead centre; F_s = T/(4r) exceeds the
    // largest number too.
    let svg = scene(1e-230, "3e-100");
    let om = text_of(&svg, "note-scales-1");
    assert!(om.contains("CE < 4.941×10−324"), "{om}");
    let forces = text_of(&svg, "note-scales-2");
    assert!(!forces.contains("dead centre"), "{forces}");
    assert!(forces.contains("Fp = T/CE exceeds"), "{forces}");
    assert!(forces.contains("Fs exceeds"), "{forces}");
    // At the dead centre it is one.
    let svg = scene(0.0, "3e-100");
    let forces = text_of(&svg, "note-scales-2");
    assert!(forces.contains("dead centre: CE = 0"), "{forces}");
    assert!(!svg.contains("id=\"force-Fp\""));
    // A finite force whose side thrust is beyond the largest number (one
    // ulp from the limit of assembly, at 90°).
    let text = "angle = 90\nlayers = [\"mechanism\", \"velocity\", \"torque\"]\ntorque = 1e308\n\
                [mechanism]\ncrank = 1\nrod = 1.0000000000000002\n";
    let svg = to_svg(&read_scene(text).unwrap().figure().unwrap());
    let forces = text_of(&svg, "note-scales-2");
    assert!(forces.contains("Fp = 1.000×10308"), "{forces}");
    assert!(forces.contains("Fs exceeds 1.798×10308"), "{forces}");
}

#[test]
fn a_scene_file_may_start_from_a_diagram() {
    let text = "figure = \"fig-64-velocity-diagrams\"\nangle = 30\nomega = 100\n\
                [mechanism]\ncrank = 150\nrod = 600\n[units]\nlength = \"mm\"\n\
                [page]\nwidth = \"200mm\"\n";
    let SceneFile::Diagram(name, options) = SceneFile::from_toml(text).unwrap() else {
        panic!("a diagram");
    };
    assert_eq!(name, FigureName::Fig64VelocityDiagrams);
    assert_eq!(options.length_unit.as_ref().unwrap().as_str(), "mm");
    assert_eq!(options.angle.unwrap().degrees(), 30.0);
    let svg = to_svg(&SceneFile::from_toml(text).unwrap().figure().unwrap());
    assert!(svg.contains("(mm/s)") && !svg.contains("ft"));
    assert!(svg.contains("width=\"200mm\""));
    // Scene::from_toml reads mechanism figures only, and says where to look.
    let e = error(text);
    assert!(
        e.contains("is a diagram") && e.contains("fig-67-example"),
        "{e}"
    );
}

#[test]
fn a_diagram_refuses_the_keys_it_does_not_use_at_their_place() {
    let e = |text: &str| SceneFile::from_toml(text).unwrap_err().to_string();
    let err = e("figure = \"rod-motion\"\nlayers = [\"mechanism\"]\n");
    assert!(
        err.starts_with("line 2, column 10:") && err.contains("`layers`"),
        "{err}"
    );
    let err = e("figure = \"ng-fig-7-calibration\"\nangle = 30\n");
    assert!(
        err.starts_with("line 2, column 9:") && err.contains("does not use `angle`"),
        "{err}"
    );
    let err = e("figure = \"rod-motion\"\nmirror = true\n");
    assert!(err.contains("does not use `mirror`"), "{err}");
    let err = e("figure = \"fig-64-velocity-diagrams\"\nnotation = \"ng\"\n");
    assert!(err.contains("does not use `notation`"), "{err}");
    let err = e("figure = \"fig-64-velocity-diagrams\"\n[page]\nmargin = 4\n");
    assert!(err.starts_with("line 3, column 10:"), "{err}");
    let err = e("figure = \"rod-motion\"\nrpm = -100\n");
    assert!(
        err.starts_with("line 2, column 7:") && err.contains("positive"),
        "{err}"
    );
}

#[test]
fn units_are_grouped_and_the_old_spelling_still_reads() {
    let new = read_scene("[units]\nlength = \"mm\"\nforce = \"N\"\n").unwrap();
    let old = read_scene("force_unit = \"N\"\n[mechanism]\ncrank = 0.5\nrod = 3\nunit = \"mm\"\n")
        .unwrap();
    assert_eq!(new.units(), &Units::MILLIMETRE_NEWTON);
    assert_eq!(old.units(), new.units());
    let e = error("force_unit = \"N\"\n[units]\nforce = \"kN\"\n");
    assert!(
        e.starts_with("line 3, column 9:") && e.contains("[units] force"),
        "{e}"
    );
    let e = error("[units]\nlength = \"\"\n");
    assert!(
        e.starts_with("line 2, column 10:") && e.contains("invalid unit name"),
        "{e}"
    );
    let e = error("[units]\nlenght = \"mm\"\n");
    assert!(e.starts_with("line 2, column 1:"), "{e}");
}

#[test]
fn a_scene_page_may_be_physical_and_the_figure_titled() {
    let s = read_scene(
        "figure = \"fig-63-velocity\"\ntitle = \"Fig. 63\"\nnotation = \"ng\"\n[page]\nwidth = \"6in\"\nheight = 400\n",
    )
    .unwrap();
    assert_eq!(s.page().width(), 576.0);
    assert_eq!(s.page().unit(), PageUnit::In);
    let svg = to_svg(&s.figure().unwrap());
    assert!(svg.contains("width=\"6in\"") && svg.contains("<title>Fig. 63</title>"));
    assert!(svg.contains("id=\"line-OM\""));
    let e = error("[page]\nwidth = \"6 parsecs\"\n");
    assert!(
        e.starts_with("line 2, column 9:") && e.contains("invalid page length"),
        "{e}"
    );
    let e = error("[page]\nwidth = \"0.2in\"\n");
    assert!(
        e.starts_with("line 2, column 9:") && e.contains("between 50"),
        "{e}"
    );
    let e = error("title = \"\"\n");
    assert!(
        e.starts_with("line 1, column 9:") && e.contains("invalid title"),
        "{e}"
    );
}

#[test]
fn a_series_is_the_scene_held_over_its_range_at_each_angle() {
    use slider_crank::Angle;
    let degrees = |d: &[f64]| -> Vec<Angle> { d.iter().map(|d| Angle::deg(*d)).collect() };
    let scene = FigureName::Fig65Klein.scene().unwrap();
    assert_eq!(scene.held_view(), None);
    // Held over a quarter turn: each frame is that scene at its angle.
    let range = degrees(&[0.0, 30.0, 60.0, 90.0]);
    let held = scene.clone().with_held_view(range.clone());
    assert_eq!(held.held_view(), Some(range.as_slice()));
    let angles = degrees(&[15.0, 90.0]);
    let frames = held.frames(&angles).unwrap();
    for (a, frame) in angles.iter().zip(&frames) {
        let one = held.clone().with_angles(vec![*a]).figure().unwrap();
        assert_eq!(to_svg(frame), to_svg(&one));
    }
    // Not held: the series is held over the whole revolution, so a frame
    // differs from the figure fitted to its own pose.
    let frames = scene.frames(&angles).unwrap();
    let own = scene.clone().with_angles(vec![angles[0]]).figure().unwrap();
    assert_ne!(
        frames[0].panels()[0].transform(),
        own.panels()[0].transform()
    );
    // An overlay keeps its ghosts, its first pose moves.
    let overlay = scene.with_angles(degrees(&[30.0, 200.0]));
    let frame = &overlay.frames(&degrees(&[70.0])).unwrap()[0];
    let svg = to_svg(frame);
    assert!(svg.contains("\"angles_deg\":[70.0,200.0]"), "{svg}");
}

#[test]
fn a_held_view_needs_one_to_3960_angles() {
    use slider_crank::Angle;
    let scene = FigureName::Fig63Velocity.scene().unwrap();
    // Checked once, when the figure is built.
    let held = scene.clone().with_held_view(Vec::new());
    let e = held.figure().unwrap_err().to_string();
    assert_eq!(e, "a view is held over at least one angle");
    assert!(held.frames(&[Angle::deg(0.0)]).is_err());
    let many = vec![Angle::deg(0.0); 3961];
    let e = scene
        .clone()
        .with_held_view(many.clone())
        .figure()
        .unwrap_err()
        .to_string();
    assert!(e.contains("at most 3960"), "{e}");
    assert!(scene.frames(&[]).is_err());
    assert!(scene.frames(&many).is_err());
}

#[test]
fn a_scenes_items_say_what_they_are_by_their_parts() {
    use slider_crank::figure::{Panel, Part};
    let figure = FigureName::Fig66Kisch.scene().unwrap().figure().unwrap();
    let [main, detail] = figure.panels() else {
        panic!("a main view and a detail: {:?}", figure.panels().len());
    };
    let ids = |panel: &Panel, part: Part| -> Vec<String> {
        let of = panel.items().iter().filter(|i| i.part == part);
        of.map(|i| i.id.clone()).collect()
    };
    assert_eq!(ids(main, Part::CentreLine), ["line-stroke"]);
    assert_eq!(ids(detail, Part::CentreLine), ["detail-line-stroke"]);
    assert_eq!(ids(main, Part::CrankCircle), ["circle-crank"]);
    assert_eq!(
        ids(main, Part::Joint),
        [
            "point-C", "label-C", "point-B", "label-B", "point-A", "label-A"
        ]
    );
    // The constructed points inside the detail's frame, left to the
    // detail, are kept on the main view as undrawn marks (a pin's letter
    // there keeps nearer its pin than them), then the frame and its tag.
    assert_eq!(
        ids(main, Part::DetailMark),
        [
            "point-E",
            "point-H",
            "point-F",
            "point-G",
            "detail-frame",
            "label-detail",
            "detail-border",
            "detail-caption"
        ]
    );
    assert!(ids(main, Part::Notes).is_empty());
    let figure = FigureName::Fig67Example.scene().unwrap().figure().unwrap();
    let main = figure.panels().first().unwrap();
    assert_eq!(ids(main, Part::Notes), ["note-scales"]);
}

/// The figure of a scene file, as SVG text.
fn scene_svg(text: &str) -> String {
    to_svg(&SceneFile::from_toml(text).unwrap().figure().unwrap())
}

/// The figure `name` as the request `request` asks it, as SVG text.
fn request_svg(name: FigureName, request: slider_crank::catalogue::FigureRequest) -> String {
    to_svg(&name.figure(&request.options(name).unwrap()).unwrap())
}

#[test]
fn a_mechanism_table_may_give_one_length_as_a_flag_does() {
    use slider_crank::catalogue::FigureRequest;
    // A mechanism figure, a diagram and a plain scene: the lengths the
    // table does not give are the figure's own (the §35 engine's r = 0.5,
    // l = 3, in line), as `--rod 2.5` alone changes only the rod.
    let mut rod = FigureRequest::default();
    rod.rod = Some(2.5);
    let mut crank = FigureRequest::default();
    crank.crank = Some(0.4);
    assert_eq!(
        scene_svg("figure = \"fig-63-velocity\"\n[mechanism]\nrod = 2.5\n"),
        request_svg(FigureName::Fig63Velocity, rod)
    );
    assert_eq!(
        scene_svg("figure = \"turning-moment\"\n[mechanism]\ncrank = 0.4\n"),
        request_svg(FigureName::TurningMoment, crank)
    );
    let plain = read_scene("[mechanism]\nrod = 2.5\n").unwrap();
    let m = plain.mechanism();
    assert_eq!((m.crank(), m.rod(), m.offset()), (0.5, 2.5, 0.0));
    // A length that cannot be is still refused at its place.
    let e = error("[mechanism]\n\nrod = 0.4\n");
    assert!(
        e.starts_with("line 3, column 7:") && e.contains("rod"),
        "{e}"
    );
    let e = error("[mechanism]\noffset = 5\n");
    assert!(e.starts_with("line 2, column 10:"), "{e}");
}

#[test]
fn a_bad_mass_or_fluctuation_is_refused_at_its_line() {
    let e = |text: &str| SceneFile::from_toml(text).unwrap_err().to_string();
    let err = e("figure = \"turning-moment\"\n\nmass = -1\n");
    assert_eq!(err, "line 3, column 8: mass must not be negative, got -1");
    let err = e("figure = \"turning-moment\"\nmass = nan\n");
    assert!(
        err.starts_with("line 2, column 8: mass must be a finite"),
        "{err}"
    );
    let err = e("figure = \"flywheel\"\nfluctuation = 3\n");
    assert!(
        err.starts_with("line 2, column 15: fluctuation = 3 is out of range"),
        "{err}"
    );
    let err = e("figure = \"flywheel\"\nfluctuation = 0\n");
    assert!(err.starts_with("line 2, column 15:"), "{err}");
}
