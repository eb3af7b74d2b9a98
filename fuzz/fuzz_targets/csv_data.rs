//! CSV data to a figure (`slider-crank figure NAME --data FILE`): the
//! first byte picks the figure, the rest is the file.
#![no_main]

#[allow(dead_code)]
#[path = "../../tests/common/hostile.rs"]
mod hostile;

libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    let Some((&which, rest)) = data.split_first() else {
        return;
    };
    if let Ok(text) = std::str::from_utf8(rest) {
        hostile::csv_data(which, text);
    }
});
