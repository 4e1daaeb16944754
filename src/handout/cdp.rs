//! One headless Chromium for every PDF of a run, driven over the DevTools protocol, with one
//! of two ways to carry its messages ([`Transport`]):
//!
//! - the pipe (`--remote-debugging-pipe`, Unix): the browser reads commands on its fd 3 and
//!   answers on fd 4, each message JSON ended by a NUL byte; nothing is open to other programs;
//! - a WebSocket (`--remote-debugging-port=0`, every system, the one used on Windows): the
//!   browser picks a free port on 127.0.0.1 and writes it, with its WebSocket path, in the file
//!   `DevToolsActivePort` of its profile folder; each message is one text message of JSON.
//!
//! Both feed the same protocol code ([`Session`]): only sending one message and the thread
//! that reads them differ.
//!
//! ```text
//! Target.createTarget → Target.attachToTarget (flat session) → Page.enable → Page.navigate
//!   → Page.loadEventFired → Page.printToPDF (ReturnAsStream) → IO.read … eof → Target.closeTarget
//! ```
//!
//! The time allowed follows progress: every message of the browser (an answer, an event, a
//! chunk of the PDF) restarts the clock, so a long print that keeps streaming is never cut,
//! and a browser that says nothing for [`STALL`] is taken for stuck and killed. The PDF streams
//! in chunks of [`CHUNK`] bytes: it never sits in one base64 message.

use std::fs::File;
#[cfg(unix)]
use std::io::{BufRead, BufReader, Write};
use std::net::TcpStream;
#[cfg(unix)]
use std::os::unix::io::{FromRawFd, RawFd};
#[cfg(unix)]
use std::os::unix::process::CommandExt;
use std::path::Path;
use std::process::{Child, Command, Stdio};
use std::sync::mpsc::{self, Receiver, RecvTimeoutError};
use std::time::{Duration, Instant};

use base64::Engine;
use serde_json::{json, Value};
use tungstenite::protocol::Role;
use tungstenite::{Message, WebSocket};

/// Silence after which the browser is taken for stuck (no answer, event or PDF chunk). A page
/// of 50 students loads and prints in a few seconds at load 1.
pub const STALL: Duration = Duration::from_secs(60);
/// Bytes of PDF asked for per `IO.read` (its answer is about 1.4 MB of base64: one WebSocket
/// message, well under tungstenite's default limit of 64 MiB per message).
const CHUNK: u32 = 1 << 20;
/// How often a starting browser's `DevToolsActivePort`, or a quitting one's status, is looked at.
const POLL: Duration = Duration::from_millis(20);
/// Time a browser that closed its end of the connection is given to exit before it is killed.
const EXIT_GRACE: Duration = Duration::from_secs(2);
/// The file in the profile folder where the browser writes its port and WebSocket path.
const PORT_FILE: &str = "DevToolsActivePort";

/// How the DevTools messages travel between this program and the browser.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Transport {
    /// `--remote-debugging-pipe`: the browser's fds 3 and 4, JSON ended by NUL (Unix only).
    #[cfg(unix)]
    Pipe,
    /// `--remote-debugging-port=0`: a WebSocket to 127.0.0.1 at the port the browser writes in
    /// `DevToolsActivePort` (every system).
    WebSocket,
}

impl Default for Transport {
    /// The pipe where there is one (no port open to other programs of the machine), else the
    /// WebSocket.
    fn default() -> Self {
        #[cfg(unix)]
        return Transport::Pipe;
        #[cfg(not(unix))]
        return Transport::WebSocket;
    }
}

/// The sending half of a transport.
enum Link {
    #[cfg(unix)]
    Pipe(File),
    /// Writes only: the socket's clone in the reader thread reads (Chromium sends no pings, so
    /// that one writes nothing before the connection ends). Boxed: one per session, 264 bytes.
    WebSocket(Box<WebSocket<TcpStream>>),
}

impl Link {
    /// Sends one JSON message.
    fn send(&mut self, message: &Value) -> Result<(), String> {
        match self {
            #[cfg(unix)]
            Link::Pipe(commands) => {
                let mut bytes = serde_json::to_vec(message).map_err(|e| e.to_string())?;
                bytes.push(0);
                commands.write_all(&bytes).map_err(|e| e.to_string())
            }
            Link::WebSocket(socket) => socket
                .send(Message::text(message.to_string()))
                .map_err(|e| e.to_string()),
        }
    }
}

/// A running browser, the sending half of its transport and the messages it sends.
pub struct Session {
    child: Child,
    link: Link,
    messages: Receiver<Value>,
    next_id: u64,
}

/// Makes a pipe; (read end, write end).
#[cfg(unix)]
fn pipe() -> std::io::Result<(RawFd, RawFd)> {
    let mut fds = [0; 2];
    // SAFETY: `fds` has room for the two descriptors pipe(2) writes.
    if unsafe { libc::pipe(fds.as_mut_ptr()) } != 0 {
        return Err(std::io::Error::last_os_error());
    }
    Ok((fds[0], fds[1]))
}

/// A thread that reads the browser's messages with `next` (the bytes of one message; `None`
/// once the connection ends) and hands the JSON ones to the returned receiver, which
/// disconnects when the connection ends.
fn relay<B: AsRef<[u8]>>(mut next: impl FnMut() -> Option<B> + Send + 'static) -> Receiver<Value> {
    let (send, messages) = mpsc::channel();
    std::thread::spawn(move || {
        while let Some(bytes) = next() {
            if let Ok(v) = serde_json::from_slice::<Value>(bytes.as_ref()) {
                if send.send(v).is_err() {
                    break;
                }
            }
        }
    });
    messages
}

/// Kills a browser that is not of use, so that it does not outlive the run.
fn kill(mut child: Child) {
    let _ = child.kill();
    let _ = child.wait();
}

/// The port and WebSocket path of a complete `DevToolsActivePort` (`9222\n/devtools/browser/<id>`).
fn parse_port_file(text: &str) -> Option<(u16, &str)> {
    let mut lines = text.lines();
    let port = lines.next()?.trim().parse().ok().filter(|p| *p != 0)?;
    let path = lines.next()?.trim();
    let id = path.strip_prefix("/devtools/browser/")?;
    (!id.is_empty()).then_some((port, path))
}

impl Session {
    /// Starts `browser` with `flags` (headless) and the profile folder `profile`, and connects
    /// to it over `transport`; its stderr goes to `log`.
    pub fn start(
        browser: &Path,
        flags: &[&str],
        profile: &Path,
        log: File,
        transport: Transport,
    ) -> Result<Self, String> {
        let mut command = Command::new(browser);
        command
            .args(flags)
            .arg(format!("--user-data-dir={}", profile.display()))
            .stdin(Stdio::null())
            .stdout(Stdio::null())
            .stderr(log);
        let (child, link, messages) = match transport {
            #[cfg(unix)]
            Transport::Pipe => Self::start_pipe(command)?,
            Transport::WebSocket => Self::start_websocket(command, profile)?,
        };
        Ok(Self {
            child,
            link,
            messages,
            next_id: 0,
        })
    }

    #[cfg(unix)]
    fn start_pipe(mut command: Command) -> Result<(Child, Link, Receiver<Value>), String> {
        // Browser reads commands from `to_browser.0` (its fd 3), writes to `from_browser.1` (fd 4).
        let to_browser = pipe().map_err(|e| format!("pipe: {e}"))?;
        let from_browser = pipe().map_err(|e| format!("pipe: {e}"))?;
        let (child_in, child_out) = (to_browser.0, from_browser.1);
        command.arg("--remote-debugging-pipe");
        // SAFETY: between fork and exec only async-signal-safe calls (dup2).
        unsafe {
            command.pre_exec(move || {
                if libc::dup2(child_in, 3) < 0 || libc::dup2(child_out, 4) < 0 {
                    return Err(std::io::Error::last_os_error());
                }
                Ok(())
            });
        }
        let spawned = command.spawn();
        // SAFETY: the child's ends are ours to close (the child has its copies); the parent's
        // ends are owned by the Files made from them, once each.
        let (commands, answers) = unsafe {
            libc::close(child_in);
            libc::close(child_out);
            (
                File::from_raw_fd(to_browser.1),
                File::from_raw_fd(from_browser.0),
            )
        };
        let child = spawned.map_err(|e| format!("cannot start: {e}"))?;
        let mut reader = BufReader::new(answers);
        let messages = relay(move || {
            let mut buf = Vec::new();
            match reader.read_until(0, &mut buf) {
                Ok(0) | Err(_) => None,
                Ok(_) => {
                    if buf.last() == Some(&0) {
                        buf.pop();
                    }
                    Some(buf)
                }
            }
        });
        Ok((child, Link::Pipe(commands), messages))
    }

    fn start_websocket(
        mut command: Command,
        profile: &Path,
    ) -> Result<(Child, Link, Receiver<Value>), String> {
        // A killed browser's file would name a port nobody listens on (or somebody else does).
        let port_file = profile.join(PORT_FILE);
        match std::fs::remove_file(&port_file) {
            Err(e) if e.kind() != std::io::ErrorKind::NotFound => {
                return Err(format!("{}: {e}", port_file.display()))
            }
            _ => {}
        }
        command.arg("--remote-debugging-port=0");
        let mut child = command.spawn().map_err(|e| format!("cannot start: {e}"))?;
        match Self::connect(&mut child, &port_file) {
            Ok((link, messages)) => Ok((child, link, messages)),
            Err(reason) => {
                kill(child);
                Err(reason)
            }
        }
    }

    /// Waits for the browser's `DevToolsActivePort` (at most [`STALL`], failing as soon as the
    /// browser exits) and opens the WebSocket it names.
    fn connect(child: &mut Child, port_file: &Path) -> Result<(Link, Receiver<Value>), String> {
        let started = Instant::now();
        let (port, path) = loop {
            let text = std::fs::read_to_string(port_file).unwrap_or_default();
            if let Some((port, path)) = parse_port_file(&text) {
                break (port, path.to_string());
            }
            if let Ok(Some(status)) = child.try_wait() {
                return Err(format!("the browser quit ({status}) at start"));
            }
            if started.elapsed() > STALL {
                return Err(format!(
                    "no {PORT_FILE} within {} s, stopped",
                    STALL.as_secs()
                ));
            }
            std::thread::sleep(POLL);
        };
        let url = format!("ws://127.0.0.1:{port}{path}");
        let failed = |e: &dyn std::fmt::Display| format!("{url}: {e}");
        let stream = TcpStream::connect(("127.0.0.1", port)).map_err(|e| failed(&e))?;
        // The handshake is bounded like every answer; the reader then waits as long as needed
        // (the receiving end keeps the clock).
        stream
            .set_read_timeout(Some(STALL))
            .map_err(|e| failed(&e))?;
        let writer = stream.try_clone().map_err(|e| failed(&e))?;
        // The default configuration: messages up to 64 MiB, reassembled from their frames.
        let (mut reader, _) =
            tungstenite::client::client(url.as_str(), stream).map_err(|e| failed(&e))?;
        reader
            .get_ref()
            .set_read_timeout(None)
            .map_err(|e| failed(&e))?;
        let messages = relay(move || loop {
            match reader.read() {
                Ok(m @ (Message::Text(_) | Message::Binary(_))) => return Some(m.into_data()),
                Ok(_) => {}
                Err(_) => return None,
            }
        });
        let link = Link::WebSocket(Box::new(WebSocket::from_raw_socket(
            writer,
            Role::Client,
            None,
        )));
        Ok((link, messages))
    }

    /// The next message, or an error after [`STALL`] of silence or when the browser quit.
    fn receive(&mut self) -> Result<Value, String> {
        match self.messages.recv_timeout(STALL) {
            Ok(v) => Ok(v),
            Err(RecvTimeoutError::Timeout) => {
                Err(format!("no answer for {} s, stopped", STALL.as_secs()))
            }
            Err(RecvTimeoutError::Disconnected) => Err(self.ended()),
        }
    }

    /// Why the connection ended: the browser's exit status, waited for [`EXIT_GRACE`] (a
    /// browser that closed the connection but runs on is killed: never a hang).
    fn ended(&mut self) -> String {
        let started = Instant::now();
        loop {
            match self.child.try_wait() {
                Ok(Some(status)) => return format!("the browser quit ({status})"),
                Ok(None) if started.elapsed() < EXIT_GRACE => std::thread::sleep(POLL),
                Ok(None) => {
                    let _ = self.child.kill();
                    let _ = self.child.wait();
                    return "the browser closed the connection, killed".to_string();
                }
                Err(e) => return format!("the browser's status: {e}"),
            }
        }
    }

    /// Sends `method` with `params` (to the page `session`, if any) and returns its result;
    /// events that arrive meanwhile are passed to `event`.
    fn call(
        &mut self,
        session: Option<&str>,
        method: &str,
        params: Value,
        event: &mut dyn FnMut(&Value),
    ) -> Result<Value, String> {
        self.next_id += 1;
        let id = self.next_id;
        let mut message = json!({"id": id, "method": method, "params": params});
        if let Some(s) = session {
            message["sessionId"] = json!(s);
        }
        if self.link.send(&message).is_err() {
            // A connection that cannot be written to (a broken pipe, a reset): the browser's
            // end says why, as for a receive.
            return Err(self.ended());
        }
        loop {
            let v = self.receive()?;
            if v["id"] == json!(id) {
                if let Some(err) = v.get("error") {
                    return Err(format!("{method}: {}", err["message"]));
                }
                return Ok(v["result"].clone());
            }
            event(&v);
        }
    }

    /// Prints the page at `url` and returns the PDF's bytes.
    pub fn print(&mut self, url: &str) -> Result<Vec<u8>, String> {
        let mut ignore = |_: &Value| {};
        let target = self.call(
            None,
            "Target.createTarget",
            json!({"url": "about:blank"}),
            &mut ignore,
        )?;
        let target_id = target["targetId"].as_str().unwrap_or_default().to_string();
        let attached = self.call(
            None,
            "Target.attachToTarget",
            json!({"targetId": target_id, "flatten": true}),
            &mut ignore,
        )?;
        let session = attached["sessionId"]
            .as_str()
            .ok_or("Target.attachToTarget: no session")?
            .to_string();
        let result = self.print_in(&session, url);
        // The page is closed whatever happened: its memory goes back before the next one.
        let closed = self.call(
            None,
            "Target.closeTarget",
            json!({"targetId": target_id}),
            &mut ignore,
        );
        let bytes = result?;
        closed?;
        Ok(bytes)
    }

    fn print_in(&mut self, session: &str, url: &str) -> Result<Vec<u8>, String> {
        let s = Some(session);
        let loaded = std::cell::Cell::new(false);
        let on_load = |v: &Value| {
            if v["method"] == "Page.loadEventFired" && v["sessionId"] == session {
                loaded.set(true);
            }
        };
        self.call(s, "Page.enable", json!({}), &mut |v| on_load(v))?;
        self.call(s, "Page.navigate", json!({"url": url}), &mut |v| on_load(v))?;
        // The page's load event: its fonts and figures are in.
        while !loaded.get() {
            let v = self.receive()?;
            on_load(&v);
        }
        // As `--print-to-pdf`: the page's @page size and margins, no header or footer.
        let printed = self.call(
            s,
            "Page.printToPDF",
            json!({
                "preferCSSPageSize": true,
                "displayHeaderFooter": false,
                "transferMode": "ReturnAsStream",
            }),
            &mut |_| {},
        )?;
        let handle = printed["stream"]
            .as_str()
            .ok_or("Page.printToPDF: no stream")?
            .to_string();
        let mut pdf = Vec::new();
        loop {
            let chunk = self.call(
                s,
                "IO.read",
                json!({"handle": handle, "size": CHUNK}),
                &mut |_| {},
            )?;
            let data = chunk["data"].as_str().unwrap_or_default();
            if chunk["base64Encoded"] == json!(true) {
                base64::engine::general_purpose::STANDARD
                    .decode_vec(data, &mut pdf)
                    .map_err(|e| format!("IO.read: {e}"))?;
            } else {
                pdf.extend_from_slice(data.as_bytes());
            }
            if chunk["eof"] == json!(true) {
                break;
            }
        }
        self.call(s, "IO.close", json!({"handle": handle}), &mut |_| {})?;
        Ok(pdf)
    }

    /// Asks the browser to quit and waits for it (killed when it does not answer).
    pub fn close(mut self) {
        if self
            .call(None, "Browser.close", json!({}), &mut |_| {})
            .is_err()
        {
            let _ = self.child.kill();
        }
        let _ = self.child.wait();
    }
}

impl Drop for Session {
    fn drop(&mut self) {
        // A session dropped on an error path: the browser must not outlive the run.
        if let Ok(None) = self.child.try_wait() {
            let _ = self.child.kill();
            let _ = self.child.wait();
        }
    }
}

#[cfg(test)]
mod port_file_tests {
    use super::*;

    #[test]
    fn the_port_file_is_read_only_when_complete() {
        let id = "/devtools/browser/8c2b2a1e-83ae-4bfd-a6c6-3a55748b8379";
        assert_eq!(parse_port_file(&format!("41517\n{id}")), Some((41517, id)));
        assert_eq!(
            parse_port_file(&format!("41517\r\n{id}\n")),
            Some((41517, id))
        );
        // Being written, or not a browser's.
        for partial in [
            "",
            "41517",
            "41517\n",
            "41517\n/devtools/browser/",
            "0\n/devtools/browser/x",
        ] {
            assert_eq!(parse_port_file(partial), None, "{partial:?}");
        }
        assert_eq!(parse_port_file("x\n/devtools/browser/x"), None);
    }
}

/// Needs Chromium, as the PDF tests of tests/handout.rs and tests/worksheet.rs do.
#[cfg(all(test, unix))]
mod tests {
    use super::*;

    fn page(dir: &Path, name: &str, text: &str) -> String {
        let file = dir.join(name);
        std::fs::write(
            &file,
            format!("<!doctype html><title>{name}</title><p>{text}</p>"),
        )
        .unwrap();
        format!("file://{}", file.display())
    }

    #[test]
    fn a_browser_killed_mid_session_is_an_error_not_a_hang_and_the_next_one_prints() {
        let browser = crate::handout::pdf::locate().expect("Chromium for the PDF tests");
        let dir = tempfile::tempdir().unwrap();
        let flags = crate::handout::pdf::HEADLESS_FLAGS;
        for transport in [Transport::Pipe, Transport::WebSocket] {
            let profile = dir.path().join(format!("{transport:?}"));
            let log = File::create(dir.path().join(format!("{transport:?}.log"))).unwrap();
            let mut session = Session::start(&browser, flags, &profile, log, transport).unwrap();
            let pdf = session.print(&page(dir.path(), "a.html", "one")).unwrap();
            assert!(pdf.starts_with(b"%PDF"), "{transport:?}");
            session.child.kill().unwrap();
            let err = session
                .print(&page(dir.path(), "b.html", "two"))
                .unwrap_err();
            assert!(err.contains("quit"), "{transport:?}: {err}");
            drop(session);
            // The next browser on the same profile is not misled by the killed one's port file.
            let log = File::create(dir.path().join(format!("{transport:?}-2.log"))).unwrap();
            let mut session = Session::start(&browser, flags, &profile, log, transport).unwrap();
            let pdf = session.print(&page(dir.path(), "c.html", "three")).unwrap();
            assert!(pdf.starts_with(b"%PDF"), "{transport:?}");
            session.close();
        }
    }
}
