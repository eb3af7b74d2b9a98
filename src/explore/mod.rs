//! The explorer (feature `explore`): a page served on the loopback address
//! where a figure follows the crank as it is dragged, and the engine
//! changes as its controls are set.
//!
//! The library gives the parts that are not the command line's: the
//! server ([`Explorer`], listening on 127.0.0.1 and ::1 only), the reading
//! of a request ([`Request`], bounded, its `Host` checked against DNS
//! rebinding), the replies ([`Reply`], [`Refusal`]) and the page
//! ([`page`]). What a request asks for is a figure request: the program
//! (`slider-crank explore`) reads its query as the options of `figure`,
//! through the same parser and checks, so that no rule is written twice.
//! Nothing on the file system is read or written for a request.

mod page;
mod request;
mod server;

pub use page::{WORKER, page};
pub use request::{
    MAX_FIELDS, MAX_HEAD_BYTES, MAX_HEADERS, MAX_VALUE_CHARS, Request, is_loopback_host,
};
pub use server::{Explorer, Handler, QUEUE, TIMEOUT, WORKERS};

/// A request refused: the HTTP status and the reason, one line.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Refusal {
    status: u16,
    reason: String,
}

impl Refusal {
    /// A refusal with `status` (4xx or 5xx) and `reason`.
    pub fn new(status: u16, reason: &str) -> Self {
        Self {
            status,
            reason: reason.to_string(),
        }
    }

    /// The HTTP status.
    pub fn status(&self) -> u16 {
        self.status
    }

    /// The reason, one line.
    pub fn reason(&self) -> &str {
        &self.reason
    }
}

/// A reply: status, type, body and, for a download, the file name the
/// browser is to save it as.
#[derive(Debug, Clone)]
pub struct Reply {
    status: u16,
    content_type: &'static str,
    body: Vec<u8>,
    attachment: Option<String>,
}

impl Reply {
    /// A 200 reply of `content_type` (`text/html; charset=utf-8`, ...).
    pub fn ok(content_type: &'static str, body: Vec<u8>) -> Self {
        Self {
            status: 200,
            content_type,
            body,
            attachment: None,
        }
    }

    /// A 200 reply the browser saves as the file `name` (only ASCII
    /// letters, digits, `-`, `_` and `.` are kept of it).
    pub fn download(content_type: &'static str, body: Vec<u8>, name: &str) -> Self {
        let name: String = name
            .chars()
            .filter(|c| c.is_ascii_alphanumeric() || matches!(c, '-' | '_' | '.'))
            .collect();
        Self {
            attachment: Some(name),
            ..Self::ok(content_type, body)
        }
    }

    /// A 204 reply with nothing in it (the icon a browser asks for).
    pub fn empty() -> Self {
        Self {
            status: 204,
            ..Self::ok("text/plain; charset=utf-8", Vec::new())
        }
    }

    /// The refusal as a plain-text reply of its status.
    pub fn refused(refusal: &Refusal) -> Self {
        let body = format!("slider-crank explore: {}\n", refusal.reason());
        Self {
            status: refusal.status(),
            content_type: "text/plain; charset=utf-8",
            body: body.into_bytes(),
            attachment: None,
        }
    }

    /// The HTTP status.
    pub fn status(&self) -> u16 {
        self.status
    }

    /// The body.
    pub fn body(&self) -> &[u8] {
        &self.body
    }

    /// The status line and headers, ending in the blank line. Every reply
    /// closes its connection, is never cached, and may load nothing from
    /// outside the page (no network: the page carries its faces).
    pub fn head(&self) -> String {
        let mut head = format!(
            "HTTP/1.1 {} {}\r\nContent-Type: {}\r\nContent-Length: {}\r\nConnection: close\r\n\
             Cache-Control: no-store\r\nX-Content-Type-Options: nosniff\r\n\
             Content-Security-Policy: default-src 'none'; connect-src 'self'; img-src 'self' data: blob:; \
             style-src 'unsafe-inline'; font-src data:; script-src 'unsafe-inline'; worker-src 'self'\r\n",
            self.status,
            reason_phrase(self.status),
            self.content_type,
            self.body.len()
        );
        if let Some(name) = &self.attachment {
            head.push_str(&format!(
                "Content-Disposition: attachment; filename=\"{name}\"\r\n"
            ));
        }
        head.push_str("\r\n");
        head
    }
}

/// The phrase of an HTTP status the explorer sends.
fn reason_phrase(status: u16) -> &'static str {
    match status {
        200 => "OK",
        204 => "No Content",
        400 => "Bad Request",
        404 => "Not Found",
        405 => "Method Not Allowed",
        408 => "Request Timeout",
        421 => "Misdirected Request",
        422 => "Unprocessable Content",
        431 => "Request Header Fields Too Large",
        503 => "Service Unavailable",
        _ => "Internal Server Error",
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_download_names_its_file_and_a_refusal_says_why() {
        let d = Reply::download("image/png", vec![1, 2], "fig\"66\r\n.png");
        let head = d.head();
        assert!(head.starts_with("HTTP/1.1 200 OK\r\n"));
        assert!(head.contains("Content-Length: 2\r\n"));
        assert!(head.contains("filename=\"fig66.png\"\r\n"), "{head}");
        let r = Reply::refused(&Refusal::new(421, "foreign host"));
        assert!(r.head().starts_with("HTTP/1.1 421 Misdirected Request\r\n"));
        assert_eq!(r.body(), b"slider-crank explore: foreign host\n");
    }
}
