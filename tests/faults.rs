//! Faults while writing (issue 27): a crash at every rename of an install and `kill -9` at
//! random times leave the output folder, once the next run has recovered it, exactly the
//! complete previous or the complete new output, with no staging folder left; a symbolic link
//! planted below `--out` is refused before any write; a second writer is refused while one
//! holds the folder. One small scenario (set B) keeps it fast; the counts are modest for CI.

use std::collections::BTreeMap;
use std::fs;
use std::path::{Path, PathBuf};
use std::process::{Command as Process, Stdio};
use std::time::{Duration, Instant};

use assert_cmd::cargo::CommandCargoExt;
use rand::{Rng, SeedableRng};

/// `kill -9` runs (random instants over the run's duration).
const RANDOM_KILLS: usize = 40;

fn bin() -> Process {
    Process::cargo_bin("stickslip").unwrap()
}

/// Every file under `dir` (relative path → bytes); folders end in `/`.
fn tree(dir: &Path) -> BTreeMap<String, Vec<u8>> {
    fn walk(root: &Path, dir: &Path, out: &mut BTreeMap<String, Vec<u8>>) {
        for e in fs::read_dir(dir).unwrap() {
            let p = e.unwrap().path();
            let rel = p.strip_prefix(root).unwrap().display().to_string();
            let meta = fs::symlink_metadata(&p).unwrap();
            if meta.is_dir() {
                out.insert(rel + "/", Vec::new());
                walk(root, &p, out);
            } else {
                out.insert(rel, fs::read(&p).unwrap());
            }
        }
    }
    let mut out = BTreeMap::new();
    walk(dir, dir, &mut out);
    out
}

fn staging_left(dir: &Path) -> bool {
    fs::read_dir(dir).unwrap().any(|e| {
        e.unwrap()
            .file_name()
            .to_string_lossy()
            .starts_with(".stickslip-")
    })
}

fn copy_tree(from: &Path, to: &Path) {
    fs::create_dir_all(to).unwrap();
    for (rel, bytes) in tree(from) {
        match rel.strip_suffix('/') {
            Some(d) => fs::create_dir_all(to.join(d)).unwrap(),
            None => fs::write(to.join(rel), bytes).unwrap(),
        }
    }
}

/// Set B with `title`: the same files, other bytes.
fn scenario(dir: &Path, title: &str) -> PathBuf {
    let text = fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("scenarios/set-b-slip-stick.toml"),
    )
    .unwrap();
    let start = text.find("title").unwrap();
    let end = start + text[start..].find('\n').unwrap();
    let text = format!("{}title = \"{title}\"{}", &text[..start], &text[end..]);
    let path = dir.join(format!("{title}/set-b-slip-stick.toml"));
    fs::create_dir_all(path.parent().unwrap()).unwrap();
    fs::write(&path, text).unwrap();
    path
}

fn report(scenario: &Path, out: &Path) -> Process {
    let mut p = bin();
    p.arg("report")
        .arg(scenario)
        .arg("--out")
        .arg(out)
        .stdout(Stdio::null())
        .stderr(Stdio::null());
    p
}

/// The old output (with a file of the user's beside it), the new one, and the new scenario.
struct Fixture {
    root: tempfile::TempDir,
    old: BTreeMap<String, Vec<u8>>,
    new: BTreeMap<String, Vec<u8>>,
    new_scenario: PathBuf,
    template: PathBuf,
}

fn fixture() -> Fixture {
    let root = tempfile::tempdir().unwrap();
    let template = root.path().join("template");
    fs::create_dir_all(&template).unwrap();
    fs::write(template.join("notes.txt"), b"the user's own file").unwrap();
    let old_scenario = scenario(root.path(), "zq-old");
    assert!(report(&old_scenario, &template).status().unwrap().success());
    let old = tree(&template);
    let new_scenario = scenario(root.path(), "zq-new");
    let reference = root.path().join("reference");
    copy_tree(&template, &reference);
    assert!(report(&new_scenario, &reference)
        .status()
        .unwrap()
        .success());
    let new = tree(&reference);
    assert_ne!(old, new);
    assert_eq!(
        old.keys().collect::<Vec<_>>(),
        new.keys().collect::<Vec<_>>()
    );
    Fixture {
        root,
        old,
        new,
        new_scenario,
        template,
    }
}

impl Fixture {
    fn fresh(&self, name: &str) -> PathBuf {
        let out = self.root.path().join(name);
        copy_tree(&self.template, &out);
        out
    }

    /// Old or new, exactly; which one.
    fn state(&self, out: &Path) -> &'static str {
        let now = tree(out);
        if now == self.old {
            "old"
        } else if now == self.new {
            "new"
        } else {
            let mixed: Vec<_> = now
                .iter()
                .filter(|(k, v)| self.old.get(*k) != Some(v) && self.new.get(*k) != Some(v))
                .map(|(k, _)| k.clone())
                .collect();
            panic!(
                "{} is neither the old nor the new output: {mixed:?}",
                out.display()
            );
        }
    }
}

#[test]
fn a_crash_at_every_rename_of_an_install_ends_complete_after_the_next_run() {
    let f = fixture();
    // Only the files whose bytes change are installed (the others are left as they are).
    let files = f
        .new
        .iter()
        .filter(|(k, v)| !k.ends_with('/') && f.old.get(*k) != Some(*v))
        .count();
    for n in 0..=files {
        let out = f.fresh(&format!("crash-{n}"));
        let status = report(&f.new_scenario, &out)
            .env("STICKSLIP_CRASH_AFTER_RENAMES", n.to_string())
            .status()
            .unwrap();
        if n < files {
            assert!(!status.success(), "rename {n}: the crash did not happen");
            assert!(staging_left(&out), "rename {n}: the journal is gone");
        }
        // The next writer (here the library's recovery, under the folder's lock) finishes the
        // committed install.
        stickslip::report::writer::recover(&out).unwrap();
        assert!(!staging_left(&out), "rename {n}: staging left");
        assert_eq!(f.state(&out), "new", "rename {n}");
    }
}

#[test]
fn kill_9_at_random_times_leaves_old_or_new_and_the_next_run_cleans_up() {
    let f = fixture();
    // How long a run takes here, to aim the kills over the whole of it.
    let started = Instant::now();
    let timing = f.fresh("timing");
    assert!(report(&f.new_scenario, &timing).status().unwrap().success());
    let span = started.elapsed().as_micros() as u64 + 1;
    let mut rng = rand::rngs::StdRng::seed_from_u64(27);
    let (mut olds, mut news, mut stale) = (0, 0, 0);
    for i in 0..RANDOM_KILLS {
        let out = f.fresh(&format!("kill-{i}"));
        let mut child = report(&f.new_scenario, &out).spawn().unwrap();
        std::thread::sleep(Duration::from_micros(rng.gen_range(0..span * 6 / 5)));
        let _ = child.kill();
        let _ = child.wait();
        stale += usize::from(staging_left(&out));
        if i % 4 == 3 {
            // The next run of the tool removes or finishes the staging and writes its own.
            assert!(report(&f.new_scenario, &out).status().unwrap().success());
            assert!(
                !staging_left(&out),
                "kill {i}: staging left by the next run"
            );
            assert_eq!(f.state(&out), "new");
            continue;
        }
        stickslip::report::writer::recover(&out).unwrap();
        assert!(!staging_left(&out), "kill {i}: staging left");
        match f.state(&out) {
            "old" => olds += 1,
            _ => news += 1,
        }
    }
    eprintln!("{RANDOM_KILLS} kills: {olds} old, {news} new after recovery; {stale} left staging");
}

#[test]
fn a_symlink_planted_below_out_is_refused_and_nothing_is_written_through_it() {
    let f = fixture();
    let base = f.root.path().join("planted");
    let outside = base.join("outside");
    let out = base.join("out");
    fs::create_dir_all(&outside).unwrap();
    fs::create_dir_all(&out).unwrap();
    fs::write(outside.join("set-b-slip-stick-motion.svg"), b"precious").unwrap();
    std::os::unix::fs::symlink("../outside", out.join("figures")).unwrap();
    let output = report(&f.new_scenario, &out)
        .stderr(Stdio::piped())
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(2));
    let err = String::from_utf8_lossy(&output.stderr);
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(
        err.contains("figures") && err.contains("symbolic link"),
        "{err}"
    );
    assert_eq!(tree(&outside).len(), 1);
    assert_eq!(
        fs::read(outside.join("set-b-slip-stick-motion.svg")).unwrap(),
        b"precious"
    );
    assert!(!staging_left(&out));
    // A link in place of an output file is refused too (the file it points to stays).
    fs::remove_file(out.join("figures")).unwrap();
    let index = f.new.keys().find(|k| k.ends_with(".html")).unwrap().clone();
    std::os::unix::fs::symlink("../outside/set-b-slip-stick-motion.svg", out.join(&index)).unwrap();
    let output = report(&f.new_scenario, &out).output().unwrap();
    assert_eq!(output.status.code(), Some(2));
    assert_eq!(
        fs::read(outside.join("set-b-slip-stick-motion.svg")).unwrap(),
        b"precious"
    );
}

#[test]
fn a_second_writer_is_refused_while_one_holds_the_folder() {
    let f = fixture();
    let out = f.fresh("busy");
    // This process holds the folder as a running writer would.
    stickslip::report::lock::claim(&out).unwrap();
    let output = report(&f.new_scenario, &out)
        .stderr(Stdio::piped())
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(2));
    let err = String::from_utf8_lossy(&output.stderr);
    assert!(
        err.starts_with("error: cannot write") && err.contains("another stickslip"),
        "{err}"
    );
    assert_eq!(f.state(&out), "old");
}

#[test]
fn two_writers_at_once_never_interleave() {
    let f = fixture();
    let other = scenario(f.root.path(), "zq-other");
    for i in 0..4 {
        let out = f.fresh(&format!("race-{i}"));
        let mut a = report(&f.new_scenario, &out)
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        let mut b = report(&other, &out).stderr(Stdio::piped()).spawn().unwrap();
        let (sa, sb) = (a.wait().unwrap(), b.wait().unwrap());
        for s in [sa, sb] {
            assert!(matches!(s.code(), Some(0 | 2)), "{s}");
        }
        assert!(!staging_left(&out));
        // The folder is one run's complete output: all files of one title (but the physics
        // guide, the same in both).
        let now = tree(&out);
        let page = |k: &String| k.ends_with(".html") && !k.ends_with("guide.html");
        let of = |title: &str| {
            now.iter()
                .filter(|(k, v)| page(k) && String::from_utf8_lossy(v).contains(title))
                .count()
        };
        let pages = now.keys().filter(|k| page(k)).count();
        assert!(
            of("zq-new") == pages || of("zq-other") == pages,
            "interleaved: {now:?}"
        );
    }
}
