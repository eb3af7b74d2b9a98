//! Headless Chromium driven through the DevTools protocol: a page opened,
//! scripts evaluated in it, the mouse and keyboard used as a person uses
//! them, and every console error and uncaught exception heard. The
//! protocol is JSON over a WebSocket; the few lines of WebSocket a client
//! needs (text frames, masked with a zero key as the protocol allows)
//! are here rather than a crate.

use serde_json::{Value, json};
use std::io::{BufRead, BufReader, Read, Write};
use std::net::TcpStream;
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

/// A browser with one page under control, ended when dropped.
pub struct Browser {
    child: Child,
    socket: TcpStream,
    next_id: u64,
    /// Console errors, uncaught exceptions and failed loads, as heard.
    pub errors: Vec<String>,
    _profile: tempfile::TempDir,
}

impl Browser {
    /// Starts `chromium` (as `browser`) headless at `width` × `height`
    /// and takes hold of its page.
    pub fn start(browser: &std::path::Path, (width, height): (u32, u32)) -> Self {
        let profile = tempfile::tempdir().unwrap();
        let mut child = Command::new(browser)
            .args(crate::browser::HEADLESS)
            .args([
                "--no-first-run",
                "--remote-debugging-port=0",
                &format!("--user-data-dir={}", profile.path().display()),
                &format!("--window-size={width},{height}"),
                "about:blank",
            ])
            .stdout(Stdio::null())
            .stderr(Stdio::piped())
            .spawn()
            .expect("Chromium runs");
        let mut stderr = BufReader::new(child.stderr.take().unwrap());
        let port = loop {
            let mut line = String::new();
            assert!(stderr.read_line(&mut line).unwrap() > 0, "Chromium ended");
            if let Some(rest) = line
                .trim()
                .strip_prefix("DevTools listening on ws://127.0.0.1:")
            {
                break rest.split('/').next().unwrap().parse::<u16>().unwrap();
            }
        };
        // Chromium's own complaints (D-Bus and the like) are not the page's.
        std::thread::spawn(move || std::io::copy(&mut stderr, &mut std::io::sink()));
        let list: Value = serde_json::from_str(&http_get(port, "/json/list")).unwrap();
        let page = list
            .as_array()
            .unwrap()
            .iter()
            .find(|t| t["type"] == "page")
            .expect("a page");
        let ws = page["webSocketDebuggerUrl"].as_str().unwrap();
        let path = &ws[ws.find("/devtools").unwrap()..];
        let socket = handshake(port, path);
        let mut browser = Self {
            child,
            socket,
            next_id: 0,
            errors: Vec::new(),
            _profile: profile,
        };
        for domain in ["Runtime.enable", "Log.enable", "Page.enable"] {
            browser.call(domain, json!({}));
        }
        browser
    }

    /// Sends `method` with `params` and waits for its result; events that
    /// come meanwhile are heard.
    pub fn call(&mut self, method: &str, params: Value) -> Value {
        self.next_id += 1;
        let id = self.next_id;
        let message = json!({ "id": id, "method": method, "params": params }).to_string();
        send(&mut self.socket, message.as_bytes());
        loop {
            let reply: Value = serde_json::from_slice(&receive(&mut self.socket)).unwrap();
            if reply["id"] == id {
                assert!(reply.get("error").is_none(), "{method}: {reply}");
                return reply["result"].clone();
            }
            self.hear(&reply);
        }
    }

    fn hear(&mut self, event: &Value) {
        let p = &event["params"];
        match event["method"].as_str() {
            Some("Runtime.exceptionThrown") => self
                .errors
                .push(format!("exception: {}", p["exceptionDetails"])),
            Some("Runtime.consoleAPICalled") if p["type"] == "error" => {
                self.errors.push(format!("console.error: {}", p["args"]))
            }
            Some("Log.entryAdded") if p["entry"]["level"] == "error" => {
                self.errors.push(format!("log: {}", p["entry"]["text"]))
            }
            _ => {}
        }
    }

    /// The value of the script `expression` (awaited if a promise).
    pub fn eval(&mut self, expression: &str) -> Value {
        let r = self.call(
            "Runtime.evaluate",
            json!({ "expression": expression, "returnByValue": true, "awaitPromise": true }),
        );
        assert!(r.get("exceptionDetails").is_none(), "{expression}: {r}");
        r["result"]["value"].clone()
    }

    /// Opens `url` and waits until `ready` (a script) is true.
    pub fn open(&mut self, url: &str, ready: &str) {
        self.call("Page.navigate", json!({ "url": url }));
        self.wait(ready);
    }

    /// Waits, 30 s at most, until the script `ready` is true.
    pub fn wait(&mut self, ready: &str) {
        let start = Instant::now();
        while self.eval(ready) != Value::Bool(true) {
            assert!(start.elapsed() < Duration::from_secs(30), "never: {ready}");
            std::thread::sleep(Duration::from_millis(2));
        }
    }

    /// A mouse event (`mousePressed`, `mouseMoved`, `mouseReleased`) at
    /// (`x`, `y`) CSS px, the left button down when `down`.
    pub fn mouse(&mut self, kind: &str, (x, y): (f64, f64), down: bool) {
        self.call(
            "Input.dispatchMouseEvent",
            json!({
                "type": kind, "x": x, "y": y, "button": "left",
                "buttons": if down { 1 } else { 0 }, "clickCount": 1,
            }),
        );
    }

    /// A touch event (`touchStart`, `touchMove`, `touchEnd`) of one finger
    /// at (`x`, `y`) CSS px (`touchEnd` lifts every finger).
    pub fn touch(&mut self, kind: &str, (x, y): (f64, f64)) {
        let points = if kind == "touchEnd" {
            json!([])
        } else {
            json!([{ "x": x, "y": y, "id": 1, "radiusX": 4, "radiusY": 4, "force": 1 }])
        };
        self.call(
            "Input.dispatchTouchEvent",
            json!({ "type": kind, "touchPoints": points }),
        );
    }

    /// A key pressed and released (`ArrowRight`, ...), with Shift held
    /// when `shift`.
    pub fn key(&mut self, key: &str, code: u32, shift: bool) {
        for kind in ["rawKeyDown", "keyUp"] {
            self.call(
                "Input.dispatchKeyEvent",
                json!({
                    "type": kind, "key": key, "code": key,
                    "windowsVirtualKeyCode": code, "modifiers": if shift { 8 } else { 0 },
                }),
            );
        }
    }

    /// Text typed where the focus is.
    pub fn type_text(&mut self, text: &str) {
        self.call("Input.insertText", json!({ "text": text }));
    }
}

impl Drop for Browser {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// The body of a plain GET on the DevTools port (read to its
/// Content-Length: the browser keeps the connection open).
fn http_get(port: u16, path: &str) -> String {
    let mut s = TcpStream::connect(("127.0.0.1", port)).unwrap();
    s.set_read_timeout(Some(Duration::from_secs(30))).unwrap();
    write!(s, "GET {path} HTTP/1.1\r\nHost: 127.0.0.1:{port}\r\n\r\n").unwrap();
    let head = read_head(&mut s);
    let length: usize = head
        .lines()
        .find_map(|l| {
            let (k, v) = l.split_once(':')?;
            k.eq_ignore_ascii_case("content-length")
                .then(|| v.trim().parse().ok())?
        })
        .expect("a Content-Length");
    let mut body = vec![0u8; length];
    s.read_exact(&mut body).unwrap();
    String::from_utf8(body).unwrap()
}

/// A reply's head, up to its blank line.
fn read_head(s: &mut TcpStream) -> String {
    let mut head = Vec::new();
    let mut byte = [0u8; 1];
    while !head.ends_with(b"\r\n\r\n") {
        s.read_exact(&mut byte).unwrap();
        head.push(byte[0]);
    }
    String::from_utf8_lossy(&head).into_owned()
}

/// The WebSocket opening handshake on `path`.
fn handshake(port: u16, path: &str) -> TcpStream {
    let mut s = TcpStream::connect(("127.0.0.1", port)).unwrap();
    s.set_read_timeout(Some(Duration::from_secs(60))).unwrap();
    write!(
        s,
        "GET {path} HTTP/1.1\r\nHost: 127.0.0.1:{port}\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n\
         Sec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\nSec-WebSocket-Version: 13\r\n\r\n"
    )
    .unwrap();
    let head = read_head(&mut s);
    assert!(head.starts_with("HTTP/1.1 101"), "{head}");
    s
}

/// One text frame, masked (a client's frames must be) with the zero key.
fn send(s: &mut TcpStream, payload: &[u8]) {
    let mut frame = vec![0x81u8];
    match payload.len() {
        n if n < 126 => frame.push(0x80 | n as u8),
        n if n < 65536 => {
            frame.push(0x80 | 126);
            frame.extend((n as u16).to_be_bytes());
        }
        n => {
            frame.push(0x80 | 127);
            frame.extend((n as u64).to_be_bytes());
        }
    }
    frame.extend([0, 0, 0, 0]);
    frame.extend(payload);
    s.write_all(&frame).unwrap();
}

/// One whole message (its frames joined), answering pings.
fn receive(s: &mut TcpStream) -> Vec<u8> {
    let mut message = Vec::new();
    loop {
        let mut head = [0u8; 2];
        s.read_exact(&mut head).unwrap();
        let (fin, opcode) = (head[0] & 0x80 != 0, head[0] & 0x0f);
        let len = match head[1] & 0x7f {
            126 => {
                let mut b = [0u8; 2];
                s.read_exact(&mut b).unwrap();
                u16::from_be_bytes(b) as usize
            }
            127 => {
                let mut b = [0u8; 8];
                s.read_exact(&mut b).unwrap();
                u64::from_be_bytes(b) as usize
            }
            n => n as usize,
        };
        let mut payload = vec![0u8; len];
        s.read_exact(&mut payload).unwrap();
        match opcode {
            0x8 => panic!("the browser closed the connection"),
            0x9 => {
                let mut pong = vec![0x8a, 0x80 | len as u8, 0, 0, 0, 0];
                pong.extend(&payload);
                s.write_all(&pong).unwrap();
                continue;
            }
            _ => message.extend(payload),
        }
        if fin {
            return message;
        }
    }
}
