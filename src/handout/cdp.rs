//! One headless Chromium for every PDF of a run, driven over the DevTools protocol on a pipe
//! (`--remote-debugging-pipe`: the browser reads commands on its fd 3 and answers on fd 4,
//! each message JSON ended by a NUL byte). Unix only: the pipes are handed over as fds 3 and 4.
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
use std::io::{BufRead, BufReader, Write};
use std::os::unix::io::{FromRawFd, RawFd};
use std::os::unix::process::CommandExt;
use std::path::Path;
use std::process::{Child, Command, Stdio};
use std::sync::mpsc::{self, Receiver, RecvTimeoutError};
use std::time::Duration;

use base64::Engine;
use serde_json::{json, Value};

/// Silence after which the browser is taken for stuck (no answer, event or PDF chunk). A page
/// of 50 students loads and prints in a few seconds at load 1.
pub const STALL: Duration = Duration::from_secs(60);
/// Bytes of PDF asked for per `IO.read`.
const CHUNK: u32 = 1 << 20;

/// A running browser with its command pipe and the messages it sends.
pub struct Session {
    child: Child,
    commands: File,
    messages: Receiver<Value>,
    next_id: u64,
}

/// Makes a pipe; (read end, write end).
fn pipe() -> std::io::Result<(RawFd, RawFd)> {
    let mut fds = [0; 2];
    // SAFETY: `fds` has room for the two descriptors pipe(2) writes.
    if unsafe { libc::pipe(fds.as_mut_ptr()) } != 0 {
        return Err(std::io::Error::last_os_error());
    }
    Ok((fds[0], fds[1]))
}

impl Session {
    /// Starts `browser` with `flags` (headless, profile) and the DevTools pipe; its stderr goes
    /// to `log`.
    pub fn start(browser: &Path, flags: &[String], log: File) -> Result<Self, String> {
        // Browser reads commands from `to_browser.0` (its fd 3), writes to `from_browser.1` (fd 4).
        let to_browser = pipe().map_err(|e| format!("pipe: {e}"))?;
        let from_browser = pipe().map_err(|e| format!("pipe: {e}"))?;
        let (child_in, child_out) = (to_browser.0, from_browser.1);
        let mut command = Command::new(browser);
        command
            .args(flags)
            .arg("--remote-debugging-pipe")
            .stdin(Stdio::null())
            .stdout(Stdio::null())
            .stderr(log);
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
        let (send, messages) = mpsc::channel();
        std::thread::spawn(move || {
            let mut reader = BufReader::new(answers);
            let mut buf = Vec::new();
            loop {
                buf.clear();
                match reader.read_until(0, &mut buf) {
                    Ok(0) | Err(_) => break,
                    Ok(_) => {
                        if buf.last() == Some(&0) {
                            buf.pop();
                        }
                        if let Ok(v) = serde_json::from_slice::<Value>(&buf) {
                            if send.send(v).is_err() {
                                break;
                            }
                        }
                    }
                }
            }
        });
        Ok(Self {
            child,
            commands,
            messages,
            next_id: 0,
        })
    }

    /// The next message, or an error after [`STALL`] of silence or when the browser quit.
    fn receive(&mut self) -> Result<Value, String> {
        match self.messages.recv_timeout(STALL) {
            Ok(v) => Ok(v),
            Err(RecvTimeoutError::Timeout) => {
                Err(format!("no answer for {} s, stopped", STALL.as_secs()))
            }
            Err(RecvTimeoutError::Disconnected) => {
                let status = self.child.wait().map(|s| s.to_string());
                Err(format!(
                    "the browser quit ({})",
                    status.unwrap_or_else(|e| e.to_string())
                ))
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
        let mut bytes = serde_json::to_vec(&message).map_err(|e| e.to_string())?;
        bytes.push(0);
        self.commands
            .write_all(&bytes)
            .map_err(|e| format!("{method}: {e}"))?;
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
