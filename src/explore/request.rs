//! One HTTP request as the explorer reads it: a `GET` of a path with a
//! query of named values, from a client that named a loopback host. Every
//! part is bounded, and anything else is a [`Refusal`] with its status
//! and a one-line reason.

use super::Refusal;

/// Most bytes of a request's head (request line and headers); the
/// longest a page sends is under 1 kB.
pub const MAX_HEAD_BYTES: usize = 8 * 1024;

/// Most headers a request may carry.
pub const MAX_HEADERS: usize = 32;

/// Most values in a query (the figure's options are about twenty).
pub const MAX_FIELDS: usize = 32;

/// Most characters of one decoded query value (a title is at most 200).
pub const MAX_VALUE_CHARS: usize = 400;

/// A parsed request: its path and its query, decoded.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Request {
    path: String,
    query: Vec<(String, String)>,
}

impl Request {
    /// Reads the head of a request (up to and including the blank line)
    /// and checks it: a `GET` of an absolute path, HTTP/1.x, a
    /// `Host` that is the loopback address with `port` (or `localhost`),
    /// and a query of at most [`MAX_FIELDS`] decodable values. `Ok(None)`:
    /// the head is not complete yet.
    pub fn parse(head: &[u8], port: u16) -> Result<Option<Self>, Refusal> {
        if head.len() > MAX_HEAD_BYTES {
            return Err(Refusal::new(431, "the request's head is longer than 8 KiB"));
        }
        let mut headers = [httparse::EMPTY_HEADER; MAX_HEADERS];
        let mut parsed = httparse::Request::new(&mut headers);
        let status = parsed.parse(head).map_err(|e| match e {
            httparse::Error::TooManyHeaders => {
                Refusal::new(431, &format!("more than {MAX_HEADERS} headers"))
            }
            e => Refusal::new(400, &format!("malformed request: {e}")),
        })?;
        if status.is_partial() {
            return Ok(None);
        }
        match parsed.method {
            Some("GET") => {}
            _ => return Err(Refusal::new(405, "only GET is served")),
        }
        let host = parsed
            .headers
            .iter()
            .filter(|h| h.name.eq_ignore_ascii_case("host"))
            .map(|h| h.value)
            .collect::<Vec<_>>();
        match host.as_slice() {
            [one] if is_loopback_host(one, port) => {}
            [_] => {
                return Err(Refusal::new(
                    421,
                    "the Host header names another host: the explorer answers only to 127.0.0.1, [::1] or localhost on its port",
                ));
            }
            _ => return Err(Refusal::new(400, "a request names its Host once")),
        }
        let target = parsed.path.unwrap_or("");
        let (path, query) = target.split_once('?').unwrap_or((target, ""));
        if !path.starts_with('/') {
            return Err(Refusal::new(400, "the path must start with /"));
        }
        Ok(Some(Self {
            path: decode(path)?,
            query: parse_query(query)?,
        }))
    }

    /// The path, decoded (`/figure`).
    pub fn path(&self) -> &str {
        &self.path
    }

    /// The query's values in order, decoded.
    pub fn query(&self) -> &[(String, String)] {
        &self.query
    }

    /// The value of `name` in the query, if given.
    pub fn get(&self, name: &str) -> Option<&str> {
        self.query
            .iter()
            .find(|(k, _)| k == name)
            .map(|(_, v)| v.as_str())
    }
}

/// Whether `host` (a Host header's value) is the loopback address on
/// `port`: `127.0.0.1:PORT`, `[::1]:PORT` or `localhost:PORT`. A page
/// that a foreign site's name was made to resolve to 127.0.0.1 (DNS
/// rebinding) sends that name, and is refused.
pub fn is_loopback_host(host: &[u8], port: u16) -> bool {
    let Ok(host) = std::str::from_utf8(host) else {
        return false;
    };
    let Some((name, given)) = host.rsplit_once(':') else {
        return false;
    };
    given == port.to_string()
        && (name == "127.0.0.1" || name == "[::1]" || name.eq_ignore_ascii_case("localhost"))
}

/// The query's `name=value` pairs (`&`-separated), each decoded.
fn parse_query(query: &str) -> Result<Vec<(String, String)>, Refusal> {
    let mut fields = Vec::new();
    for pair in query.split('&').filter(|p| !p.is_empty()) {
        if fields.len() == MAX_FIELDS {
            return Err(Refusal::new(
                400,
                &format!("more than {MAX_FIELDS} values in the query"),
            ));
        }
        let (name, value) = pair.split_once('=').unwrap_or((pair, ""));
        let value = decode(value)?;
        if value.chars().count() > MAX_VALUE_CHARS {
            return Err(Refusal::new(
                400,
                &format!("a value longer than {MAX_VALUE_CHARS} characters"),
            ));
        }
        fields.push((decode(name)?, value));
    }
    Ok(fields)
}

/// Percent-decodes `text` (`+` is a space), which must decode to UTF-8
/// with no control character.
fn decode(text: &str) -> Result<String, Refusal> {
    let bad = || Refusal::new(400, "the query is not percent-encoded UTF-8 text");
    let mut bytes = Vec::with_capacity(text.len());
    let mut rest = text.bytes();
    while let Some(b) = rest.next() {
        match b {
            b'%' => {
                let hi = rest.next().and_then(hex).ok_or_else(bad)?;
                let lo = rest.next().and_then(hex).ok_or_else(bad)?;
                bytes.push(hi * 16 + lo);
            }
            b'+' => bytes.push(b' '),
            b => bytes.push(b),
        }
    }
    let text = String::from_utf8(bytes).map_err(|_| bad())?;
    if text.chars().any(char::is_control) {
        return Err(Refusal::new(
            400,
            "a value holds a line break or other control character",
        ));
    }
    Ok(text)
}

fn hex(b: u8) -> Option<u8> {
    (b as char).to_digit(16).and_then(|d| u8::try_from(d).ok())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn head(target: &str, host: &str) -> Vec<u8> {
        format!("GET {target} HTTP/1.1\r\nHost: {host}\r\n\r\n").into_bytes()
    }

    #[test]
    fn a_figure_request_is_read_and_decoded() {
        let r = Request::parse(
            &head("/figure?rod=2.5&title=a%20b+c&x", "127.0.0.1:8080"),
            8080,
        )
        .unwrap()
        .unwrap();
        assert_eq!(r.path(), "/figure");
        assert_eq!(r.get("rod"), Some("2.5"));
        assert_eq!(r.get("title"), Some("a b c"));
        assert_eq!(r.get("x"), Some(""));
        assert_eq!(r.get("crank"), None);
    }

    #[test]
    fn a_partial_head_asks_for_more() {
        assert_eq!(Request::parse(b"GET / HTTP/1.1\r\nHo", 1), Ok(None));
    }

    #[test]
    fn foreign_hosts_and_bad_requests_are_refused_with_their_status() {
        let status = |bytes: &[u8]| Request::parse(bytes, 8080).unwrap_err().status();
        assert_eq!(status(&head("/", "evil.example:8080")), 421);
        assert_eq!(status(&head("/", "127.0.0.1:8081")), 421);
        assert_eq!(status(&head("/", "127.0.0.1")), 421);
        assert_eq!(status(b"GET / HTTP/1.1\r\n\r\n"), 400);
        assert_eq!(
            status(b"POST / HTTP/1.1\r\nHost: 127.0.0.1:8080\r\n\r\n"),
            405
        );
        assert_eq!(status(b"\x00\x01garbage\r\n\r\n"), 400);
        assert_eq!(status(&head("/?a=%zz", "127.0.0.1:8080")), 400);
        assert_eq!(status(&head("/?a=%ff", "127.0.0.1:8080")), 400);
        assert_eq!(status(&head("/?a=%0a", "127.0.0.1:8080")), 400);
        let many = (0..40)
            .map(|k| format!("v{k}=1"))
            .collect::<Vec<_>>()
            .join("&");
        assert_eq!(status(&head(&format!("/?{many}"), "[::1]:8080")), 400);
        let long = "9".repeat(MAX_VALUE_CHARS + 1);
        assert_eq!(
            status(&head(&format!("/?rod={long}"), "localhost:8080")),
            400
        );
        assert_eq!(status(&vec![b'G'; MAX_HEAD_BYTES + 1]), 431);
    }

    /// `text` percent-encoded, every byte but letters and digits.
    fn encode(text: &str) -> String {
        text.bytes()
            .map(|b| {
                if b.is_ascii_alphanumeric() {
                    (b as char).to_string()
                } else {
                    format!("%{b:02X}")
                }
            })
            .collect()
    }

    proptest::proptest! {
        // The bounded twin of the fuzz target `explore_request`: any bytes
        // are read or refused, never a panic, and a refusal is a client
        // error with a one-line reason.
        #[test]
        fn any_bytes_are_read_or_refused(bytes in proptest::collection::vec(proptest::num::u8::ANY, 0..600)) {
            if let Err(r) = Request::parse(&bytes, 8080) {
                proptest::prop_assert!((400..500).contains(&r.status()));
                proptest::prop_assert!(!r.reason().contains('\n'));
            }
        }

        // Any query of printable names and values comes back as it was
        // sent, once percent-encoded.
        #[test]
        fn an_encoded_query_is_decoded_as_sent(
            fields in proptest::collection::vec(("[a-z-]{1,12}", "[^\\p{Cc}]{0,40}"), 0..MAX_FIELDS)
        ) {
            let query: Vec<String> = fields
                .iter()
                .map(|(k, v)| format!("{}={}", encode(k), encode(v)))
                .collect();
            let bytes = head(&format!("/figure?{}", query.join("&")), "127.0.0.1:8080");
            let request = Request::parse(&bytes, 8080).unwrap().unwrap();
            let sent: Vec<(String, String)> = fields.into_iter().collect();
            proptest::prop_assert_eq!(request.query(), sent.as_slice());
        }
    }

    /// A request head built from parts a client might send, well formed
    /// or not: a method, a target of any bytes (percent-escapes, `+`,
    /// `&`, `=` and `?` among them), a version, a Host of several kinds
    /// (the loopback's, a foreign one, none, two) and any other headers.
    fn any_head() -> impl proptest::strategy::Strategy<Value = (Vec<u8>, u8)> {
        use proptest::prelude::*;
        let method = prop_oneof!["GET", "POST", "HEAD", "get", "[A-Z]{0,8}"];
        let piece = prop_oneof![
            "[a-z]{1,8}",
            "%[0-9a-fA-F]{2}",
            "%[0-9a-zA-Z]{0,2}",
            Just("&".to_string()),
            Just("=".to_string()),
            Just("?".to_string()),
            Just("+".to_string()),
            "[^\\r\\n ]{1,4}",
        ];
        let target = (
            prop_oneof![Just("/"), Just("/figure"), Just(""), Just("*"), Just("//x")],
            proptest::collection::vec(piece, 0..60),
        )
            .prop_map(|(path, pieces)| format!("{path}?{}", pieces.concat()));
        let version = prop_oneof!["HTTP/1.1", "HTTP/1.0", "HTTP/2", "[A-Z/.0-9]{0,9}"];
        // 0: the loopback's Host, 1: a foreign one, 2: none, 3: two.
        let host = 0u8..4;
        let other = proptest::collection::vec(("[A-Za-z-]{1,12}", "[ -~]{0,30}"), 0..6);
        (method, target, version, host, other).prop_map(|(m, t, v, host, other)| {
            let mut head = format!("{m} {t} {v}\r\n");
            match host {
                0 => head.push_str("Host: 127.0.0.1:8080\r\n"),
                1 => head.push_str("Host: rebound.example:8080\r\n"),
                2 => {}
                _ => head.push_str("Host: localhost:8080\r\nHost: [::1]:8080\r\n"),
            }
            for (name, value) in other {
                if !name.eq_ignore_ascii_case("host") {
                    head.push_str(&format!("{name}: {value}\r\n"));
                }
            }
            head.push_str("\r\n");
            (head.into_bytes(), host)
        })
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(10_000))]

        // Heads near the well formed, 10 000 of them: a request read has
        // a path from `/`, at most MAX_FIELDS values of at most
        // MAX_VALUE_CHARS characters and no control character, and came
        // from the loopback's Host; any other is refused with a 4xx and
        // one line, a foreign or missing Host never read.
        #[test]
        fn heads_near_the_well_formed_are_read_within_bounds_or_refused((bytes, host) in any_head()) {
            match Request::parse(&bytes, 8080) {
                Ok(Some(r)) => {
                    proptest::prop_assert_eq!(host, 0);
                    proptest::prop_assert!(r.path().starts_with('/'));
                    proptest::prop_assert!(r.query().len() <= MAX_FIELDS);
                    for (k, v) in r.query() {
                        proptest::prop_assert!(v.chars().count() <= MAX_VALUE_CHARS);
                        proptest::prop_assert!(!k.chars().chain(v.chars()).any(char::is_control));
                    }
                }
                // A head httparse takes for unfinished (a version cut
                // short): the server reads on, within MAX_HEAD_BYTES.
                Ok(None) => {}
                Err(r) => {
                    proptest::prop_assert!((400..500).contains(&r.status()));
                    proptest::prop_assert!(!r.reason().is_empty() && !r.reason().contains('\n'));
                }
            }
        }
    }

    #[test]
    fn the_loopback_names_are_the_only_hosts() {
        for ok in ["127.0.0.1:80", "[::1]:80", "localhost:80", "LocalHost:80"] {
            assert!(is_loopback_host(ok.as_bytes(), 80), "{ok}");
        }
        for bad in [
            "127.0.0.2:80",
            "localhost.evil:80",
            "[::1]",
            "x:80",
            "127.0.0.1:080",
        ] {
            assert!(!is_loopback_host(bad.as_bytes(), 80), "{bad}");
        }
    }
}
