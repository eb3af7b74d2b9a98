//! A request to the explorer (`slider-crank explore`): the bytes as the
//! head of an HTTP request. No panic; a refusal is a client error (4xx)
//! with a reason of one line; a request read has a path that starts
//! with `/` and at most `MAX_FIELDS` values.
#![no_main]

use slider_crank::explore::{MAX_FIELDS, Request};

libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    match Request::parse(data, 8744) {
        Ok(Some(request)) => {
            assert!(request.path().starts_with('/'));
            assert!(request.query().len() <= MAX_FIELDS);
        }
        Ok(None) => {}
        Err(refusal) => {
            assert!((400..500).contains(&refusal.status()));
            assert!(!refusal.reason().is_empty() && !refusal.reason().contains('\n'));
        }
    }
});
