//! Printing to PDF with headless Chromium: find the browser, print pages from a private
//! temporary folder (its own profile, no network, no first-run work; [`Printer`]: one browser
//! for every PDF of a run), and hand back the bytes; the caller writes them with the report's
//! atomic writer, so a failure leaves no PDF.

use std::ffi::OsString;
use std::fs;
use std::path::{Path, PathBuf};
use std::time::Duration;

use super::cdp::{Session, Transport};
use crate::error::{Error, Result};

/// Environment variable naming the browser binary; it wins over the search.
pub const BROWSER_ENV: &str = "STICKSLIP_CHROMIUM";
/// The operating systems whose browser install folders are known.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Os {
    Linux,
    MacOs,
    Windows,
}

impl Os {
    /// The system this program was built for (other Unix systems search like Linux).
    pub const CURRENT: Os = if cfg!(windows) {
        Os::Windows
    } else if cfg!(target_os = "macos") {
        Os::MacOs
    } else {
        Os::Linux
    };
}

/// Where a browser may be: a program name looked up on PATH, or a file where an installer puts it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Candidate {
    OnPath(&'static str),
    File(PathBuf),
}

/// Chromium-family browsers that print headless (Chromium, Google Chrome, Microsoft Edge),
/// where teachers have them on `os`, in the order they are tried. `env` reads an environment
/// variable (the Windows install roots and the macOS home folder).
pub fn candidates(os: Os, env: &dyn Fn(&str) -> Option<OsString>) -> Vec<Candidate> {
    use Candidate::{File, OnPath};
    match os {
        Os::Linux => [
            "chromium",
            "chromium-browser",
            "google-chrome",
            "google-chrome-stable",
            "microsoft-edge",
            "microsoft-edge-stable",
        ]
        .into_iter()
        .map(OnPath)
        .collect(),
        Os::MacOs => {
            const APPS: [&str; 3] = [
                "Google Chrome.app/Contents/MacOS/Google Chrome",
                "Microsoft Edge.app/Contents/MacOS/Microsoft Edge",
                "Chromium.app/Contents/MacOS/Chromium",
            ];
            let home_apps = env("HOME").map(|h| PathBuf::from(h).join("Applications"));
            let mut found: Vec<Candidate> = ["/Applications"]
                .into_iter()
                .map(PathBuf::from)
                .chain(home_apps)
                .flat_map(|dir| APPS.map(|app| File(dir.join(app))))
                .collect();
            found.extend(["chromium", "google-chrome"].into_iter().map(OnPath));
            found
        }
        Os::Windows => {
            // Per-machine installs under Program Files (either), per-user ones under LOCALAPPDATA.
            const APPS: [&str; 3] = [
                r"Google\Chrome\Application\chrome.exe",
                r"Microsoft\Edge\Application\msedge.exe",
                r"Chromium\Application\chrome.exe",
            ];
            let roots: Vec<PathBuf> = ["ProgramFiles", "ProgramFiles(x86)", "LOCALAPPDATA"]
                .into_iter()
                .filter_map(|v| env(v).filter(|r| !r.is_empty()).map(PathBuf::from))
                .collect();
            let mut found: Vec<Candidate> = APPS
                .iter()
                .flat_map(|app| roots.iter().map(move |r| File(r.join(app))))
                .collect();
            found.extend(
                ["chrome.exe", "msedge.exe", "chromium.exe"]
                    .into_iter()
                    .map(OnPath),
            );
            found
        }
    }
}

/// The browser to print with: `$STICKSLIP_CHROMIUM`, else the first of [`candidates`] that
/// exists (Chromium, Chrome or Edge on PATH or in their install folders).
pub fn locate() -> Result<PathBuf> {
    let env = |name: &str| std::env::var_os(name);
    locate_in(
        std::env::var_os(BROWSER_ENV),
        std::env::var_os("PATH"),
        &candidates(Os::CURRENT, &env),
    )
}

fn locate_in(
    named: Option<OsString>,
    path: Option<OsString>,
    candidates: &[Candidate],
) -> Result<PathBuf> {
    if let Some(named) = named.filter(|n| !n.is_empty()) {
        let named = PathBuf::from(named);
        // A bare name is looked up on PATH like the defaults.
        let found = if named.components().count() == 1 {
            search(path.as_deref(), &named)
        } else {
            is_executable(&named).then(|| named.clone())
        };
        return found.ok_or_else(|| Error::NoChromium {
            detail: format!(
                " ({BROWSER_ENV} = {}: not an executable file)",
                named.display()
            ),
        });
    }
    candidates
        .iter()
        .find_map(|c| match c {
            Candidate::OnPath(name) => search(path.as_deref(), Path::new(name)),
            Candidate::File(file) => is_executable(file).then(|| file.clone()),
        })
        .ok_or_else(|| Error::NoChromium {
            detail: String::new(),
        })
}

fn search(path: Option<&std::ffi::OsStr>, name: &Path) -> Option<PathBuf> {
    std::env::split_paths(path?)
        .map(|dir| dir.join(name))
        .find(|candidate| is_executable(candidate))
}

#[cfg(unix)]
fn is_executable(path: &Path) -> bool {
    use std::os::unix::fs::PermissionsExt;
    fs::metadata(path).is_ok_and(|m| m.is_file() && m.permissions().mode() & 0o111 != 0)
}

/// Without Unix permission bits any regular file counts; one that is not a program fails to
/// start when printing, which is reported as [`Error::Pdf`].
#[cfg(not(unix))]
fn is_executable(path: &Path) -> bool {
    fs::metadata(path).is_ok_and(|m| m.is_file())
}

/// Chromium's flags for printing offline without a desktop: headless, no sandbox (CI runs as
/// root), no GPU, no network of its own. No page header or footer: the DevTools print command
/// says `displayHeaderFooter: false` (the flag `--no-pdf-header-footer` would put the browser
/// in its one-shot print mode, which ends the session).
pub const HEADLESS_FLAGS: &[&str] = &[
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-quic",
    "--no-first-run",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
];

/// Prefix of the private temporary folder of one print (page, profile, PDF, log).
const WORK_PREFIX: &str = "stickslip-pdf-";
/// An unlocked work folder untouched for this long is a killed print's.
const STALE_AFTER: Duration = Duration::from_secs(120);

/// Removes the work folders of earlier prints that were killed: folders of this user named
/// `stickslip-pdf-*` in `tmp`, untouched for [`STALE_AFTER`], whose lock no running print
/// holds.
fn remove_stale_work_folders(tmp: &Path) {
    let Ok(entries) = fs::read_dir(tmp) else {
        return;
    };
    for e in entries.flatten() {
        if !e.file_name().to_string_lossy().starts_with(WORK_PREFIX) {
            continue;
        }
        let path = e.path();
        let Ok(meta) = fs::symlink_metadata(&path) else {
            continue;
        };
        // A folder made a moment ago may be a running print's that has not locked it yet.
        let settled = meta
            .modified()
            .ok()
            .and_then(|m| m.elapsed().ok())
            .is_some_and(|age| age > STALE_AFTER);
        if !meta.is_dir() || !owned_by_me(&meta) || !settled {
            continue;
        }
        let Ok(dir) = fs::File::open(&path) else {
            continue;
        };
        if !crate::report::lock::is_busy(&dir) {
            let _ = fs::remove_dir_all(&path);
        }
    }
}

#[cfg(unix)]
fn owned_by_me(meta: &fs::Metadata) -> bool {
    use std::os::unix::fs::MetadataExt;
    // SAFETY: getuid has no preconditions.
    meta.uid() == unsafe { libc::getuid() }
}

#[cfg(not(unix))]
fn owned_by_me(_meta: &fs::Metadata) -> bool {
    false
}

/// A fresh private work folder, locked while in use: a run killed mid-print leaves the folder
/// (and Chromium's profile, some MB) unlocked, and the next `--pdf` removes it.
fn work_folder() -> std::io::Result<(tempfile::TempDir, fs::File)> {
    remove_stale_work_folders(&std::env::temp_dir());
    let work = tempfile::Builder::new().prefix(WORK_PREFIX).tempdir()?;
    let lock = fs::File::open(work.path())?;
    crate::report::lock::hold(&lock);
    Ok((work, lock))
}

/// One browser for every PDF of a run: one Chromium process prints them all over the DevTools
/// protocol ([`super::cdp`]; the pipe on Unix, a WebSocket on 127.0.0.1 elsewhere), each page in
/// its own tab closed after it, with a time limit that follows progress.
pub struct Printer {
    browser: PathBuf,
    /// Private folder of the pages and the profile, locked while in use.
    work: tempfile::TempDir,
    _lock: fs::File,
    transport: Transport,
    session: Option<Session>,
    /// Browser processes started so far.
    starts: u32,
}

impl Printer {
    /// A printer with `browser` over the system's [`Transport::default`], started at its first
    /// page.
    pub fn new(browser: &Path) -> Result<Self> {
        Self::with_transport(browser, Transport::default())
    }

    /// A printer with `browser` over `transport`, started at its first page.
    pub fn with_transport(browser: &Path, transport: Transport) -> Result<Self> {
        let (work, lock) = work_folder().map_err(|e| Error::Pdf {
            path: String::new(),
            browser: browser.display().to_string(),
            reason: format!("temporary folder: {e}"),
        })?;
        Ok(Self {
            browser: browser.to_path_buf(),
            work,
            _lock: lock,
            transport,
            session: None,
            starts: 0,
        })
    }

    /// Browser processes this printer has started.
    pub fn starts(&self) -> u32 {
        self.starts
    }

    /// Prints `html` (a self-contained page, saved as `name`) and returns the PDF's bytes. The
    /// time allowed follows the browser's progress ([`super::cdp::STALL`] of silence at most),
    /// whatever the number of pages.
    pub fn print(&mut self, name: &str, html: &str) -> Result<Vec<u8>> {
        let fail = |reason: String| Error::Pdf {
            path: name.to_string(),
            browser: self.browser.display().to_string(),
            reason,
        };
        let page = self.work.path().join(name);
        fs::write(&page, html).map_err(|e| fail(format!("{}: {e}", page.display())))?;
        let log = self.work.path().join("chromium.log");
        // The browser's own last words say why it quit (no display, a missing library).
        let browser_fail = |reason: String| fail(format!("{reason}{}", last_message(&log)));
        if self.session.is_none() {
            let log_file =
                fs::File::create(&log).map_err(|e| fail(format!("{}: {e}", log.display())))?;
            let profile = self.work.path().join("profile");
            self.starts += 1;
            self.session = Some(
                Session::start(
                    &self.browser,
                    HEADLESS_FLAGS,
                    &profile,
                    log_file,
                    self.transport,
                )
                .map_err(browser_fail)?,
            );
        }
        let printed = match self.session.as_mut() {
            Some(session) => session.print(&file_url(&page)),
            None => Err("not started".to_string()),
        };
        let _ = fs::remove_file(&page);
        match printed {
            Ok(bytes) if bytes.starts_with(b"%PDF") => Ok(bytes),
            Ok(_) => Err(fail("no PDF written".to_string())),
            Err(reason) => {
                // A browser that failed once is not trusted with the next page.
                self.session = None;
                Err(browser_fail(reason))
            }
        }
    }

    /// Quits the browser.
    pub fn close(self) {
        if let Some(session) = self.session {
            session.close();
        }
    }
}

/// "; last message: …" with the last line the browser wrote to `log`, or nothing.
fn last_message(log: &Path) -> String {
    fs::read_to_string(log)
        .unwrap_or_default()
        .lines()
        .rev()
        .find(|l| !l.trim().is_empty())
        .map_or(String::new(), |l| format!("; last message: {}", l.trim()))
}

/// The `file:` URL of an absolute path: `file:///tmp/x.html`, `file:///C:/Users/x.html`.
fn file_url(path: &Path) -> String {
    let shown = path.display().to_string().replace('\\', "/");
    let slash = if shown.starts_with('/') { "" } else { "/" };
    format!("file://{slash}{shown}")
}

#[cfg(test)]
mod candidate_tests {
    use super::*;

    fn no_env(_: &str) -> Option<OsString> {
        None
    }

    #[test]
    fn linux_looks_for_chromium_chrome_and_edge_on_path() {
        let names: Vec<_> = candidates(Os::Linux, &no_env)
            .into_iter()
            .map(|c| match c {
                Candidate::OnPath(n) => n,
                Candidate::File(f) => panic!("{} is not a PATH name", f.display()),
            })
            .collect();
        assert_eq!(
            names[..3],
            ["chromium", "chromium-browser", "google-chrome"]
        );
        assert!(names.contains(&"google-chrome-stable") && names.contains(&"microsoft-edge"));
    }

    #[test]
    fn macos_looks_in_the_applications_folders_then_on_path() {
        let home = |v: &str| (v == "HOME").then(|| OsString::from("/Users/ada"));
        let found = candidates(Os::MacOs, &home);
        let files: Vec<PathBuf> = found
            .iter()
            .filter_map(|c| match c {
                Candidate::File(f) => Some(f.clone()),
                Candidate::OnPath(_) => None,
            })
            .collect();
        assert_eq!(
            files[0],
            Path::new("/Applications/Google Chrome.app/Contents/MacOS/Google Chrome")
        );
        assert!(files.contains(&PathBuf::from(
            "/Applications/Microsoft Edge.app/Contents/MacOS/Microsoft Edge"
        )));
        assert!(files.contains(&PathBuf::from(
            "/Users/ada/Applications/Chromium.app/Contents/MacOS/Chromium"
        )));
        assert_eq!(files.len(), 6);
        assert!(found.contains(&Candidate::OnPath("chromium")));
        // Without HOME only /Applications.
        assert_eq!(candidates(Os::MacOs, &no_env).len(), 3 + 2);
    }

    #[test]
    fn windows_looks_in_program_files_and_local_app_data_for_exe_files() {
        let env = |v: &str| match v {
            "ProgramFiles" => Some(OsString::from(r"C:\Program Files")),
            "ProgramFiles(x86)" => Some(OsString::from(r"C:\Program Files (x86)")),
            "LOCALAPPDATA" => Some(OsString::from(r"C:\Users\ada\AppData\Local")),
            _ => None,
        };
        let found = candidates(Os::Windows, &env);
        let shown: Vec<String> = found
            .iter()
            .map(|c| match c {
                Candidate::File(f) => f.display().to_string(),
                Candidate::OnPath(n) => (*n).to_string(),
            })
            .collect();
        // Joined with the separator of the machine running the test: compare with `/` for `\`.
        let shown: Vec<String> = shown.iter().map(|s| s.replace('/', "\\")).collect();
        for want in [
            r"C:\Program Files\Google\Chrome\Application\chrome.exe",
            r"C:\Program Files (x86)\Google\Chrome\Application\chrome.exe",
            r"C:\Users\ada\AppData\Local\Google\Chrome\Application\chrome.exe",
            r"C:\Program Files (x86)\Microsoft\Edge\Application\msedge.exe",
            r"C:\Program Files\Microsoft\Edge\Application\msedge.exe",
            r"C:\Users\ada\AppData\Local\Chromium\Application\chrome.exe",
            "chrome.exe",
            "msedge.exe",
        ] {
            assert!(shown.iter().any(|s| s == want), "{want} not in {shown:?}");
        }
        assert_eq!(found.len(), 3 * 3 + 3);
        // A root that is not set adds nothing.
        assert_eq!(candidates(Os::Windows, &no_env).len(), 3);
    }

    #[test]
    fn file_urls_have_three_slashes_on_every_system() {
        assert_eq!(file_url(Path::new("/tmp/a b.html")), "file:///tmp/a b.html");
        assert_eq!(
            file_url(Path::new(r"C:\Users\x.html")),
            "file:///C:/Users/x.html"
        );
    }
}

// The fake browsers are shell scripts made executable with Unix permissions.
#[cfg(all(test, unix))]
mod tests {
    use super::*;

    fn executable(dir: &Path, name: &str) -> PathBuf {
        use std::os::unix::fs::PermissionsExt;
        let path = dir.join(name);
        fs::write(&path, "#!/bin/sh\necho 'cannot open display' >&2\nexit 3\n").unwrap();
        fs::set_permissions(&path, fs::Permissions::from_mode(0o755)).unwrap();
        path
    }

    #[test]
    fn the_environment_variable_wins_over_path_and_must_name_an_executable() {
        let dir = tempfile::tempdir().unwrap();
        let on_path = executable(dir.path(), "chromium");
        let other = executable(dir.path(), "my-browser");
        let path = Some(dir.path().as_os_str().to_owned());
        let linux = candidates(Os::Linux, &|_| None);
        assert_eq!(locate_in(None, path.clone(), &linux).unwrap(), on_path);
        // An install folder's file is found without PATH.
        let installed = [Candidate::File(other.clone())];
        assert_eq!(locate_in(None, None, &installed).unwrap(), other);
        assert_eq!(
            locate_in(Some(other.clone().into()), path.clone(), &linux).unwrap(),
            other
        );
        assert_eq!(
            locate_in(Some("my-browser".into()), path.clone(), &linux).unwrap(),
            other
        );
        let err = locate_in(Some(dir.path().join("nope").into()), path, &linux).unwrap_err();
        assert!(err.to_string().contains("STICKSLIP_CHROMIUM"), "{err}");
        let err = locate_in(None, Some(OsString::new()), &linux).unwrap_err();
        assert!(err.to_string().starts_with("--pdf needs headless Chromium"));
    }

    #[test]
    fn a_browser_that_quits_is_an_error_of_the_printer() {
        let dir = tempfile::tempdir().unwrap();
        let fake = executable(dir.path(), "fake-chromium");
        for transport in [Transport::Pipe, Transport::WebSocket] {
            let mut printer = Printer::with_transport(&fake, transport).unwrap();
            let err = printer.print("x.html", "<p>x</p>").unwrap_err();
            assert!(matches!(err, Error::Pdf { .. }), "{err}");
            assert!(err.to_string().contains("fake-chromium"), "{err}");
            // Said as soon as it exits, not after a silence of `STALL`.
            assert!(err.to_string().contains("quit (exit status: 3)"), "{err}");
            assert!(
                err.to_string()
                    .ends_with("; last message: cannot open display"),
                "{err}"
            );
        }
    }

    /// The text of a PDF, by pdftotext (poppler-utils, as the PDF tests of tests/ need).
    fn pdf_text(pdf: &[u8]) -> String {
        let dir = tempfile::tempdir().unwrap();
        let file = dir.path().join("x.pdf");
        fs::write(&file, pdf).unwrap();
        let out = std::process::Command::new("pdftotext")
            .arg(&file)
            .arg("-")
            .output()
            .expect("pdftotext for the PDF tests");
        String::from_utf8_lossy(&out.stdout).into_owned()
    }

    /// Needs Chromium, as the PDF tests of tests/handout.rs and tests/worksheet.rs do.
    /// A page with an image of noise (a BMP of 1024 × 768 pixels from a fixed sequence), which
    /// no compression shrinks: its PDF is several [`super::super::cdp`] chunks long.
    fn noise_page() -> String {
        use base64::Engine;
        let (w, h) = (1024u32, 768u32);
        let size = 54 + 3 * w * h;
        let mut bmp = Vec::with_capacity(size as usize);
        bmp.extend_from_slice(b"BM");
        for v in [size, 0, 54, 40] {
            bmp.extend_from_slice(&v.to_le_bytes());
        }
        bmp.extend_from_slice(&w.to_le_bytes());
        bmp.extend_from_slice(&h.to_le_bytes());
        bmp.extend_from_slice(&1u16.to_le_bytes());
        bmp.extend_from_slice(&24u16.to_le_bytes());
        bmp.extend_from_slice(&[0; 24]);
        let mut x = 12345u32;
        bmp.extend((0..3 * w * h).map(|_| {
            x = x.wrapping_mul(1_103_515_245).wrapping_add(12_345);
            (x >> 24) as u8
        }));
        let data = base64::engine::general_purpose::STANDARD.encode(bmp);
        format!(
            "<!doctype html><title>noise</title><p>marker-noise</p>\
             <img style=\"width:160mm\" src=\"data:image/bmp;base64,{data}\">"
        )
    }

    #[test]
    fn a_pdf_of_several_chunks_arrives_whole_over_either_transport() {
        let browser = locate().expect("Chromium for the PDF tests");
        for transport in [Transport::Pipe, Transport::WebSocket] {
            let mut printer = Printer::with_transport(&browser, transport).unwrap();
            let pdf = printer.print("noise.html", &noise_page()).unwrap();
            assert!(pdf.len() > 2 << 20, "{transport:?}: {} bytes", pdf.len());
            assert!(pdf.starts_with(b"%PDF") && pdf.trim_ascii_end().ends_with(b"%%EOF"));
            assert!(pdf_text(&pdf).contains("marker-noise"), "{transport:?}");
            printer.close();
        }
    }

    #[test]
    fn one_browser_prints_every_pdf_of_a_run_over_either_transport() {
        let browser = locate().expect("Chromium for the PDF tests");
        assert_eq!(Transport::default(), Transport::Pipe);
        for transport in [Transport::Pipe, Transport::WebSocket] {
            let mut printer = Printer::with_transport(&browser, transport).unwrap();
            let one = printer
                .print("a.html", "<!doctype html><title>a</title><p>marker-one</p>")
                .unwrap();
            let two = printer
                .print("b.html", "<!doctype html><title>b</title><p>marker-two</p>")
                .unwrap();
            assert!(one.starts_with(b"%PDF") && two.starts_with(b"%PDF"));
            // Each tab prints its own page, not the first one's.
            let (one, two) = (pdf_text(&one), pdf_text(&two));
            assert!(
                one.contains("marker-one") && !one.contains("marker-two"),
                "{one}"
            );
            assert!(
                two.contains("marker-two") && !two.contains("marker-one"),
                "{two}"
            );
            assert_eq!(printer.starts(), 1, "{transport:?}");
            printer.close();
        }
    }
}
