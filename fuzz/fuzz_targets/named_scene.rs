//! A scene file for any named figure (`slider-crank scene FILE.toml` with
//! `figure = "NAME"`): the first line names the figure, the rest is the
//! file; diagrams as well as mechanism figures.
#![no_main]

#[allow(dead_code)]
#[path = "../../tests/common/hostile.rs"]
mod hostile;

libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    if let Ok(text) = std::str::from_utf8(data) {
        hostile::named_scene(text);
    }
});
