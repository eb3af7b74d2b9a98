//! `slider-crank explore` (issue 44): the server run as a user runs it,
//! spoken to over a socket. A figure request answers what `figure` and
//! `analyze --json` print for the same flags; every bad request gets its
//! refusal and leaves the server serving; it listens on loopback only and
//! ends on Ctrl-C.

use serde_json::Value;
use std::io::{BufRead, BufReader, Read, Write};
use std::net::TcpStream;
use std::process::{Child, Command, Stdio};
use std::time::Duration;

/// A running explorer, ended when dropped.
pub struct Server {
    child: Child,
    /// The port it printed.
    pub port: u16,
}

impl Server {
    /// `slider-crank explore --port 0 ARGS`, once it has printed its address.
    pub fn start(args: &[&str]) -> Self {
        let mut child = Command::new(env!("CARGO_BIN_EXE_slider-crank"))
            .args(["explore", "--port", "0"])
            .args(args)
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .expect("the binary runs");
        let mut line = String::new();
        BufReader::new(child.stdout.take().unwrap())
            .read_line(&mut line)
            .unwrap();
        let port = line
            .split("http://127.0.0.1:")
            .nth(1)
            .and_then(|rest| rest.split('/').next())
            .and_then(|p| p.parse().ok())
            .unwrap_or_else(|| panic!("no address printed: {line:?}"));
        Self { child, port }
    }

    /// The reply to the raw request `text`: status and body.
    pub fn raw(&self, text: &[u8]) -> (u16, Vec<u8>) {
        let mut s = TcpStream::connect(("127.0.0.1", self.port)).unwrap();
        s.set_read_timeout(Some(Duration::from_secs(30))).unwrap();
        s.write_all(text).unwrap();
        let mut reply = Vec::new();
        s.read_to_end(&mut reply).unwrap();
        split(&reply)
    }

    /// GET `target` with the right Host.
    pub fn get(&self, target: &str) -> (u16, Vec<u8>) {
        let port = self.port;
        self.raw(format!("GET {target} HTTP/1.1\r\nHost: 127.0.0.1:{port}\r\n\r\n").as_bytes())
    }

    /// GET `target`, which must answer 200; the body as text.
    pub fn text(&self, target: &str) -> String {
        let (status, body) = self.get(target);
        let body = String::from_utf8(body).unwrap();
        assert_eq!(status, 200, "{target}: {body}");
        body
    }
}

impl Drop for Server {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// Status and body of a whole reply.
fn split(reply: &[u8]) -> (u16, Vec<u8>) {
    let end = reply
        .windows(4)
        .position(|w| w == b"\r\n\r\n")
        .unwrap_or_else(|| panic!("no head: {:?}", String::from_utf8_lossy(reply)));
    let head = String::from_utf8_lossy(&reply[..end]);
    let status = head.split(' ').nth(1).unwrap().parse().unwrap();
    (status, reply[end + 4..].to_vec())
}

/// The program's standard output for `args`, which must succeed.
fn program(args: &[&str]) -> String {
    let out = crate::command::run(args);
    crate::command::succeeded(&out);
    String::from_utf8(out.stdout).unwrap()
}

#[test]
fn a_figure_request_is_the_figure_command_and_its_values_are_analyze() {
    let server = Server::start(&[]);
    let reply: Value = serde_json::from_str(&server.text(
        "/figure?name=fig-65-klein&crank=0.5&rod=2.5&offset=0.1&angle=30&rpm=300&layers=mechanism,klein,velocity",
    ))
    .unwrap();
    let flags = [
        "--crank", "0.5", "--rod", "2.5", "--offset", "0.1", "--angle", "30", "--rpm", "300",
    ];
    let mut figure = vec!["figure", "fig-65-klein"];
    figure.extend(flags);
    figure.extend(["--layers", "mechanism,klein,velocity"]);
    assert_eq!(reply["svg"].as_str().unwrap(), program(&figure));
    let mut analyze = vec!["analyze", "--json"];
    analyze.extend(flags);
    let expected: Value = serde_json::from_str(&program(&analyze)).unwrap();
    assert_eq!(reply["analyze"], expected);
    // A diagram that draws no pose has no values.
    let reply: Value =
        serde_json::from_str(&server.text("/figure?name=approximation-error")).unwrap();
    assert!(reply["analyze"].is_null());
    assert!(reply["svg"].as_str().unwrap().starts_with("<svg"));
}

#[test]
fn the_page_is_served_whole_with_nothing_from_outside() {
    let server = Server::start(&["fig-63-velocity"]);
    let page = server.text("/");
    assert!(page.starts_with("<!DOCTYPE html>"));
    assert!(page.contains("\"initial\":\"fig-63-velocity\""));
    assert!(page.contains("@font-face") && page.contains("data:font/"));
    for outside in ["src=\"http", "href=\"http", "url(http", "@import"] {
        assert!(!page.contains(outside), "{outside}");
    }
}

#[test]
fn downloads_are_the_figure_in_each_format_and_the_handout() {
    let server = Server::start(&[]);
    let q = "name=fig-66-kisch&angle=40&rod=2.5";
    let (status, png) = server.get(&format!("/download?format=png&{q}"));
    assert_eq!(status, 200);
    assert!(png.starts_with(b"\x89PNG\r\n\x1a\n"));
    let (status, pdf) = server.get(&format!("/download?format=pdf&{q}"));
    assert_eq!(status, 200);
    assert!(pdf.starts_with(b"%PDF-"));
    let svg = server.text(&format!("/download?format=svg&{q}"));
    assert!(svg.contains("@font-face"), "the SVG carries its faces");
    let handout = server.text("/handout?angle=40&rod=2.5&rpm=300");
    let expected = {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("h.html");
        let p = path.to_str().unwrap();
        program(&[
            "handout", "--angle", "40", "--rod", "2.5", "--rpm", "300", "--out", p,
        ]);
        std::fs::read_to_string(&path).unwrap()
    };
    assert_eq!(handout, expected);
}

/// Bad requests, each with the status it must get and a word of its reason.
const BAD: [(&str, u16, &str); 12] = [
    ("/figure?rod=0.1", 422, "too short"),
    ("/figure?rod=1e999", 422, "finite"),
    ("/figure?angle=nan", 422, "finite"),
    ("/figure?crank=abc", 422, "invalid value"),
    ("/figure?name=no-such-figure", 422, "unknown figure"),
    ("/figure?layers=mechanism,bogus", 422, "unknown layer"),
    (
        "/figure?name=turning-moment&angle=30",
        422,
        "does not use --angle",
    ),
    ("/figure?data=/etc/passwd", 400, "no file"),
    ("/figure?out=/tmp/x.svg", 400, "no file"),
    ("/figure?color=red", 400, "unknown value"),
    ("/figure?title=a%0ab", 400, "control character"),
    ("/nothing-here", 404, "no page"),
];

#[test]
fn bad_requests_are_refused_and_the_server_keeps_serving() {
    let server = Server::start(&[]);
    for (target, status, reason) in BAD {
        let (got, body) = server.get(target);
        let body = String::from_utf8(body).unwrap();
        assert_eq!(got, status, "{target}: {body}");
        assert!(body.contains(reason), "{target}: {body}");
        assert_eq!(body.lines().count(), 1, "{target}: one line");
    }
    // The same refusal as the command line's, word for word.
    let out = crate::command::run(&["figure", "fig-66-kisch", "--rod", "0.1"]);
    let said = String::from_utf8(out.stderr).unwrap();
    let (_, body) = server.get("/figure?rod=0.1");
    let body = String::from_utf8(body).unwrap();
    assert_eq!(
        body.trim_start_matches("slider-crank explore: "),
        said.trim_start_matches("slider-crank: error: ")
    );
    let port = server.port;
    let raw: Vec<(Vec<u8>, u16)> = vec![
        (
            b"\x16\x03\x01\x02\x00\x01\x00\x01\xfc\x03\x03garbage\r\n\r\n".to_vec(),
            400,
        ),
        (b"GET / HTTP/1.1\r\n\r\n".to_vec(), 400),
        (
            b"POST /figure HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n".to_vec(),
            405,
        ),
        (
            format!("GET / HTTP/1.1\r\nHost: evil.example:{port}\r\n\r\n").into_bytes(),
            421,
        ),
        (
            format!(
                "GET / HTTP/1.1\r\nHost: 127.0.0.1:{port}\r\nX: {}\r\n\r\n",
                "y".repeat(9000)
            )
            .into_bytes(),
            431,
        ),
        (
            format!(
                "GET /figure?rod={} HTTP/1.1\r\nHost: 127.0.0.1:{port}\r\n\r\n",
                "9".repeat(500)
            )
            .into_bytes(),
            400,
        ),
    ];
    for (request, status) in raw {
        let shown: String = String::from_utf8_lossy(&request).chars().take(60).collect();
        assert_eq!(server.raw(&request).0, status, "{shown}");
    }
    // A client that sends half a request and waits is let go.
    let mut slow = TcpStream::connect(("127.0.0.1", port)).unwrap();
    slow.write_all(b"GET / HTTP/1.1\r\nHost: 127.0").unwrap();
    let mut reply = Vec::new();
    slow.read_to_end(&mut reply).unwrap();
    assert_eq!(split(&reply).0, 408);
    assert!(server.text("/figure").contains("\"svg\""));
}

#[test]
fn ten_thousand_rapid_requests_are_answered_or_refused_and_it_serves_on() {
    let server = Server::start(&[]);
    let port = server.port;
    let counts: Vec<(u32, u32)> = std::thread::scope(|scope| {
        let clients: Vec<_> = (0..50)
            .map(|k| {
                scope.spawn(move || {
                    let (mut ok, mut busy) = (0, 0);
                    for i in 0..200 {
                        let target = format!("/figure?angle={}", (k * 200 + i) % 360);
                        let mut s = TcpStream::connect(("127.0.0.1", port)).unwrap();
                        s.set_read_timeout(Some(Duration::from_secs(60))).unwrap();
                        let request =
                            format!("GET {target} HTTP/1.1\r\nHost: 127.0.0.1:{port}\r\n\r\n");
                        // The server may refuse before it reads the request.
                        let _ = s.write_all(request.as_bytes());
                        let mut reply = Vec::new();
                        let _ = s.read_to_end(&mut reply);
                        match split(&reply).0 {
                            200 => ok += 1,
                            503 => busy += 1,
                            other => panic!("status {other}"),
                        }
                    }
                    (ok, busy)
                })
            })
            .collect();
        clients.into_iter().map(|c| c.join().unwrap()).collect()
    });
    let ok: u32 = counts.iter().map(|c| c.0).sum();
    let busy: u32 = counts.iter().map(|c| c.1).sum();
    assert_eq!(ok + busy, 10_000);
    assert!(ok > 0);
    assert!(server.text("/figure?angle=10").contains("\"svg\""));
}

/// The addresses listening on `port` from /proc/net/tcp and tcp6, as hex.
#[cfg(target_os = "linux")]
fn listening(port: u16) -> Vec<String> {
    let mut found = Vec::new();
    for table in ["/proc/net/tcp", "/proc/net/tcp6"] {
        let Ok(text) = std::fs::read_to_string(table) else {
            continue;
        };
        for line in text.lines().skip(1) {
            let f: Vec<&str> = line.split_whitespace().collect();
            let (address, state) = (f[1], f[3]);
            let (ip, p) = address.split_once(':').unwrap();
            if state == "0A" && u16::from_str_radix(p, 16).unwrap() == port {
                found.push(ip.to_string());
            }
        }
    }
    found
}

#[cfg(target_os = "linux")]
#[test]
fn it_listens_on_the_loopback_addresses_only() {
    let server = Server::start(&[]);
    let found = listening(server.port);
    assert!(!found.is_empty());
    // 127.0.0.1 and ::1 as the kernel writes them (little-endian words).
    for ip in &found {
        assert!(
            ip == "0100007F" || ip == "00000000000000000000000001000000",
            "listening on {ip}"
        );
    }
    assert!(found.iter().any(|ip| ip == "0100007F"));
}

#[cfg(unix)]
#[test]
fn ctrl_c_ends_it() {
    let mut server = Server::start(&[]);
    let pid = server.child.id().to_string();
    assert!(
        Command::new("kill")
            .args(["-INT", &pid])
            .status()
            .unwrap()
            .success()
    );
    let status = server.child.wait().unwrap();
    use std::os::unix::process::ExitStatusExt;
    assert_eq!(status.signal(), Some(2), "{status:?}");
}
