//! The explorer's HTTP server: listening on the loopback address only, a
//! fixed pool of workers fed by a bounded queue, one request a
//! connection, and a refusal (not a wait) when the queue is full.

use super::request::{MAX_HEAD_BYTES, Request};
use super::{Refusal, Reply};
use std::io::{ErrorKind, Read, Write};
use std::net::{IpAddr, Ipv4Addr, Ipv6Addr, Shutdown, SocketAddr, TcpListener, TcpStream};
use std::sync::mpsc::{Receiver, SyncSender, TrySendError, sync_channel};
use std::sync::{Arc, Mutex};
use std::time::Duration;

/// Workers drawing figures at once: the machine's two cores.
pub const WORKERS: usize = 2;

/// Connections accepted and waiting for a worker; one more is refused
/// at once with 503, so that a flood of requests costs a refusal each
/// and never a backlog.
pub const QUEUE: usize = 64;

/// How long a client may take to send its request or read the reply.
pub const TIMEOUT: Duration = Duration::from_secs(2);

/// What answers a request: the page, a figure, a download or a refusal.
pub type Handler = dyn Fn(&Request) -> Reply + Send + Sync;

/// The listening sockets, on the loopback address and nowhere else.
#[derive(Debug)]
pub struct Explorer {
    listeners: Vec<TcpListener>,
    port: u16,
}

impl Explorer {
    /// Listens on 127.0.0.1 at `port` (0: a free port the system picks)
    /// and on ::1 at the same port where the machine has IPv6 loopback.
    pub fn bind(port: u16) -> std::io::Result<Self> {
        let v4 = TcpListener::bind(SocketAddr::new(IpAddr::V4(Ipv4Addr::LOCALHOST), port))?;
        let port = v4.local_addr()?.port();
        let mut listeners = vec![v4];
        match TcpListener::bind(SocketAddr::new(IpAddr::V6(Ipv6Addr::LOCALHOST), port)) {
            Ok(v6) => listeners.push(v6),
            // No IPv6 on this machine: 127.0.0.1 alone.
            Err(e)
                if matches!(
                    e.kind(),
                    ErrorKind::AddrNotAvailable | ErrorKind::Unsupported
                ) => {}
            Err(e) if e.raw_os_error() == Some(97) => {} // EAFNOSUPPORT
            Err(e) => return Err(e),
        }
        Ok(Self { listeners, port })
    }

    /// The port listened on.
    pub fn port(&self) -> u16 {
        self.port
    }

    /// The addresses listened on, every one a loopback address.
    pub fn addresses(&self) -> Vec<SocketAddr> {
        self.listeners
            .iter()
            .filter_map(|l| l.local_addr().ok())
            .collect()
    }

    /// Answers requests with `handler` until the process ends: a thread
    /// accepting on each address, [`WORKERS`] threads answering.
    pub fn serve(self, handler: Arc<Handler>) -> std::io::Result<()> {
        let (queue, waiting) = sync_channel::<TcpStream>(QUEUE);
        let waiting = Arc::new(Mutex::new(waiting));
        for k in 0..WORKERS {
            let (waiting, handler) = (Arc::clone(&waiting), Arc::clone(&handler));
            let port = self.port;
            std::thread::Builder::new()
                .name(format!("explore-{k}"))
                .spawn(move || work(&waiting, handler.as_ref(), port))?;
        }
        let mut listeners = self.listeners;
        let Some(last) = listeners.pop() else {
            return Ok(());
        };
        for listener in listeners {
            let queue = queue.clone();
            std::thread::Builder::new()
                .name("explore-accept".into())
                .spawn(move || accept(&listener, &queue))?;
        }
        accept(&last, &queue);
        Ok(())
    }
}

/// Accepts connections into the queue, refusing those it has no room for.
fn accept(listener: &TcpListener, queue: &SyncSender<TcpStream>) {
    loop {
        match listener.accept() {
            Ok((stream, peer)) if peer.ip().is_loopback() => match queue.try_send(stream) {
                Ok(()) => {}
                Err(TrySendError::Full(stream)) => {
                    let busy = Refusal::new(503, "busy: too many requests at once, try again");
                    respond(stream, &Reply::refused(&busy));
                }
                Err(TrySendError::Disconnected(_)) => return,
            },
            // Never reached through a loopback listener; refused all the same.
            Ok(_) => {}
            // Out of file descriptors or a connection reset before it was
            // accepted: a moment's pause, then on.
            Err(_) => std::thread::sleep(Duration::from_millis(10)),
        }
    }
}

/// A worker: answers queued connections one at a time.
fn work(waiting: &Mutex<Receiver<TcpStream>>, handler: &Handler, port: u16) {
    loop {
        let next = match waiting.lock() {
            Ok(receiver) => receiver.recv(),
            Err(_) => return,
        };
        let Ok(stream) = next else { return };
        answer(stream, handler, port);
    }
}

/// Reads one request from `stream` and writes its reply, unless the
/// client has gone meanwhile (a page drops a request a newer drag has
/// superseded).
fn answer(mut stream: TcpStream, handler: &Handler, port: u16) {
    // The reply is written at once, in one piece (`respond`): nothing is
    // gained by Nagle's algorithm holding back its last segment.
    let _ = stream.set_nodelay(true);
    let _ = stream.set_read_timeout(Some(TIMEOUT));
    let _ = stream.set_write_timeout(Some(TIMEOUT));
    let request = match read_request(&mut stream, port) {
        Ok(Some(request)) => request,
        Ok(None) => return,
        Err(refusal) => return respond(stream, &Reply::refused(&refusal)),
    };
    if gone(&stream) {
        return;
    }
    let reply = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| handler(&request)))
        .unwrap_or_else(|_| {
            Reply::refused(&Refusal::new(500, "internal error: the figure failed"))
        });
    respond(stream, &reply);
}

/// The request's head, read until its blank line; `Ok(None)` when the
/// client closed the connection before sending one.
fn read_request(stream: &mut TcpStream, port: u16) -> Result<Option<Request>, Refusal> {
    let mut head = Vec::with_capacity(1024);
    let mut chunk = [0u8; 2048];
    loop {
        let n = match stream.read(&mut chunk) {
            Ok(0) if head.is_empty() => return Ok(None),
            Ok(0) => return Err(Refusal::new(400, "the request ended before its blank line")),
            Ok(n) => n,
            Err(e) if matches!(e.kind(), ErrorKind::WouldBlock | ErrorKind::TimedOut) => {
                return Err(Refusal::new(408, "the request took too long to arrive"));
            }
            Err(_) => return Ok(None),
        };
        head.extend(chunk.iter().take(n));
        if let Some(request) = Request::parse(&head, port)? {
            return Ok(Some(request));
        }
        if head.len() > MAX_HEAD_BYTES {
            return Err(Refusal::new(431, "the request's head is longer than 8 KiB"));
        }
    }
}

/// Whether the client has closed its side (nothing more to read, at once).
fn gone(stream: &TcpStream) -> bool {
    if stream.set_nonblocking(true).is_err() {
        return false;
    }
    let closed = matches!(stream.peek(&mut [0u8; 1]), Ok(0));
    let _ = stream.set_nonblocking(false);
    closed
}

/// Writes `reply`, head and body in one write, and closes the connection.
fn respond(mut stream: TcpStream, reply: &Reply) {
    let _ = stream.set_write_timeout(Some(TIMEOUT));
    let mut bytes = reply.head().into_bytes();
    bytes.extend_from_slice(reply.body());
    let written = stream.write_all(&bytes);
    if written.is_ok() {
        let _ = stream.flush();
    }
    let _ = stream.shutdown(Shutdown::Both);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn it_listens_on_loopback_only() {
        let explorer = Explorer::bind(0).unwrap();
        assert!(explorer.port() != 0);
        let addresses = explorer.addresses();
        assert!(!addresses.is_empty());
        for a in addresses {
            assert!(a.ip().is_loopback(), "{a}");
            assert_eq!(a.port(), explorer.port());
        }
    }
}
