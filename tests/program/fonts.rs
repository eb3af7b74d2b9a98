//! The bundled type: every character the figures write has a glyph in
//! every bundled face (nothing falls back to another font), the SVG asks
//! for the chosen face first, and `--font` and the scene key choose it.

use slider_crank::catalogue::FigureOptions;
use slider_crank::figure::FontStyle;
use slider_crank::render::to_svg;
use slider_crank::{FigureName, Font, Scene, SceneFile};

/// The scene of a scene file that describes a mechanism figure.
fn read_scene(text: &str) -> slider_crank::Result<Scene> {
    SceneFile::from_toml(text)?.into_scene()
}
use std::collections::BTreeSet;
use std::process::Command;

/// The characters inside the `<text>` elements of an SVG, markup and
/// entities resolved.
fn text_chars(svg: &str) -> BTreeSet<char> {
    let mut chars = BTreeSet::new();
    for piece in svg.split("<text").skip(1) {
        let body = piece.split_once('>').map_or("", |(_, b)| b);
        let body = body.split("</text>").next().unwrap_or("");
        let mut in_tag = false;
        let plain: String = body
            .chars()
            .filter(|&c| match c {
                '<' => {
                    in_tag = true;
                    false
                }
                '>' => {
                    in_tag = false;
                    false
                }
                _ => !in_tag,
            })
            .collect();
        let plain = plain
            .replace("&lt;", "<")
            .replace("&gt;", ">")
            .replace("&amp;", "&");
        chars.extend(plain.chars());
    }
    chars
}

#[test]
fn every_character_of_every_named_figure_has_a_glyph_in_every_face() {
    let mut all = BTreeSet::new();
    for name in FigureName::ALL {
        let svg = to_svg(&name.figure(&FigureOptions::default()).unwrap());
        all.extend(text_chars(&svg));
    }
    // The symbols the figures are known to use are among what was read
    // (primes set as the modifier prime ʹ the text faces have).
    for c in ['θ', 'φ', 'ω', 'μ', '×', '−', 'ʹ', '\u{a0}'] {
        assert!(all.contains(&c), "{c:?} not found in any figure");
    }
    for font in Font::ALL {
        for style in [FontStyle::Regular, FontStyle::Italic] {
            let missing: String = all.iter().filter(|&&c| !font.has_glyph(c, style)).collect();
            assert!(missing.is_empty(), "{font} {style:?} lacks {missing:?}");
        }
    }
}

#[test]
fn the_svg_names_the_chosen_face_first() {
    for font in Font::ALL {
        let mut options = FigureOptions::default();
        options.font = Some(font);
        for name in [FigureName::Fig65Klein, FigureName::AccelerationDiagrams] {
            let svg = to_svg(&name.figure(&options).unwrap());
            let family = svg
                .split_once("font-family=\"")
                .and_then(|(_, r)| r.split_once('"'))
                .map(|(f, _)| f.to_string())
                .unwrap();
            let family = family.replace("&apos;", "'");
            let first = family.split(',').next().unwrap().trim().trim_matches('\'');
            assert_eq!(first, font.family(), "{}", name.name());
            assert!(family.ends_with("serif"));
        }
    }
}

#[test]
fn label_boxes_follow_the_faces_widths() {
    // Libertinus is narrower than New Computer Modern, and the tick
    // labels and legends of the plots are measured in the chosen face:
    // the same figure lays out differently.
    let svg = |font| {
        let mut options = FigureOptions::default();
        options.font = Some(font);
        to_svg(&FigureName::AccelerationDiagrams.figure(&options).unwrap())
    };
    let (ncm, lib) = (svg(Font::NewComputerModern), svg(Font::LibertinusSerif));
    assert_ne!(ncm, lib);
    let s = "Klein's construction";
    assert!(
        Font::LibertinusSerif.width(s, 13.0, FontStyle::Regular)
            < 0.97 * Font::NewComputerModern.width(s, 13.0, FontStyle::Regular)
    );
}

#[test]
fn the_scene_file_key_and_the_command_line_choose_the_face() {
    let s = read_scene("figure = \"fig-66-kisch\"\nfont = \"libertinus-serif\"\n").unwrap();
    assert_eq!(s.font(), Font::LibertinusSerif);
    assert!(to_svg(&s.figure().unwrap()).contains("font-family=\"&apos;Libertinus Serif&apos;"));
    let e = read_scene("figure = \"fig-66-kisch\"\nfont = \"comic\"\n")
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("libertinus-serif") && e.contains("line 2"),
        "{e}"
    );

    let bin = env!("CARGO_BIN_EXE_slider-crank");
    let out = Command::new(bin)
        .args(["figure", "rod-motion", "--font", "libertinus-serif"])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(
        String::from_utf8_lossy(&out.stdout).contains("font-family=\"&apos;Libertinus Serif&apos;")
    );
    let out = Command::new(bin)
        .args(["figure", "fig-62-displacement", "--font", "times"])
        .output()
        .unwrap();
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("new-computer-modern, libertinus-serif"),
        "{err}"
    );
    let help = Command::new(bin)
        .args(["figure", "--help"])
        .output()
        .unwrap();
    let help = String::from_utf8_lossy(&help.stdout);
    assert!(help.contains("--font") && help.contains("libertinus-serif"));
}
