//! The conventions of a Rust command line, as a user meets them: `stickslip completions
//! <SHELL>` prints a script for each of the five shells that names the subcommands,
//! `stickslip man` prints a roff page that opens with `.TH` and lists the subcommands, an
//! unknown shell is bad input (exit 2), `-o` is the short form of every `--out`, `-` reads
//! standard input for `fit`, `--scenario` and `--formulas`, and `--csv -` is refused.

use assert_cmd::Command;
use clap::CommandFactory;

use stickslip::cli::Cli;

/// Subcommands every script and the page must name.
const SUBCOMMANDS: [&str; 8] = [
    "eval",
    "report",
    "bench",
    "sweep",
    "check",
    "worksheet",
    "completions",
    "man",
];

fn stickslip() -> Command {
    let mut cmd = Command::cargo_bin("stickslip").expect("binary");
    cmd.current_dir(env!("CARGO_MANIFEST_DIR"));
    cmd
}

fn stdout_of(args: &[&str]) -> String {
    let out = stickslip()
        .args(args)
        .assert()
        .success()
        .get_output()
        .clone();
    assert!(out.stderr.is_empty(), "{args:?}: nothing on stderr");
    String::from_utf8(out.stdout).expect("UTF-8")
}

#[test]
fn completions_of_every_shell_name_the_subcommands() {
    for shell in ["bash", "zsh", "fish", "powershell", "elvish"] {
        let script = stdout_of(&["completions", shell]);
        assert!(!script.trim().is_empty(), "{shell}: empty script");
        for sub in SUBCOMMANDS {
            assert!(script.contains(sub), "{shell}: {sub} not completed");
        }
        // The model subcommands come from the registry, and the flags with them.
        assert!(script.contains("woodpecker"), "{shell}");
        assert!(script.contains("--out"), "{shell}");
    }
}

#[test]
fn an_unknown_shell_is_bad_input_with_the_choices_on_one_line() {
    let out = stickslip()
        .args(["completions", "tcsh"])
        .assert()
        .code(2)
        .get_output()
        .clone();
    assert!(out.stdout.is_empty());
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(err.trim_end().lines().count(), 1, "{err}");
    assert!(err.contains("bash") && err.contains("powershell"), "{err}");
}

#[test]
fn the_man_page_is_roff_that_opens_with_th_and_lists_the_subcommands() {
    let page = stdout_of(&["man"]);
    assert!(
        page.starts_with(".TH stickslip 1 "),
        "{}",
        &page[..80.min(page.len())]
    );
    for section in [
        ".SH NAME",
        ".SH SYNOPSIS",
        ".SH DESCRIPTION",
        ".SH SUBCOMMANDS",
    ] {
        assert!(page.contains(section), "{section}");
    }
    for sub in SUBCOMMANDS {
        assert!(
            page.contains(&format!("stickslip\\-{sub}(1)")),
            "{sub} not listed"
        );
    }
    // The apostrophe string is defined before the text uses it.
    let defined = page.find(".ds Aq").expect("Aq defined");
    let used = page.find("\\*(Aq").expect("Aq used");
    assert!(defined < used);
}

/// Every `--out` of every subcommand (the model subcommands included) has `-o`.
#[test]
fn every_out_flag_has_the_short_form_o() {
    fn visit(cmd: &clap::Command, path: &str, found: &mut Vec<String>) {
        for arg in cmd.get_arguments() {
            if arg.get_long() == Some("out") {
                assert_eq!(arg.get_short(), Some('o'), "{path} --out");
                found.push(path.to_string());
            }
        }
        for sub in cmd.get_subcommands() {
            visit(sub, &format!("{path} {}", sub.get_name()), found);
        }
    }
    let mut found = Vec::new();
    visit(&Cli::command(), "stickslip", &mut found);
    for command in [
        "report",
        "bench",
        "handout",
        "sweep woodpecker",
        "check pulled-mass",
        "fit",
        "worksheet",
        "explorer",
    ] {
        assert!(
            found.contains(&format!("stickslip {command}")),
            "{command}: no --out ({found:?})"
        );
    }
}

#[test]
fn o_writes_where_out_would() {
    let dir = tempfile::tempdir().expect("temporary folder");
    let out = dir.path().join("grid");
    stickslip()
        .args([
            "sweep",
            "pulled-mass",
            "--param",
            "mu_d",
            "--from",
            "0.2",
            "--to",
            "0.3",
            "--steps",
            "2",
            "-o",
        ])
        .arg(&out)
        .assert()
        .success();
    for file in ["sweep.csv", "sweep.svg"] {
        assert!(out.join(file).is_file(), "{file} not written to -o");
    }
}

/// A command's `--help` lists only flags it takes: every shared flag a command refuses
/// ("does not apply to `stickslip …`") is absent from its help.
#[test]
fn help_lists_no_flag_the_command_refuses() {
    let out_dir = tempfile::tempdir().unwrap();
    let out = out_dir.path().join("out").display().to_string();
    let sweep = [
        "sweep",
        "woodpecker",
        "--param",
        "z0",
        "--from",
        "0.005",
        "--to",
        "0.007",
        "--steps",
        "2",
    ];
    let runs: [(&[&str], &[&str], bool); 5] = [
        (
            &["eval", "pulled-mass"],
            &["eval", "pulled-mass", "--help"],
            false,
        ),
        (
            &["claims", "--samples", "5", "pulled-mass"],
            &["claims", "pulled-mass", "--help"],
            false,
        ),
        (
            &["check", "pulled-mass", "v_avg = 1", "--samples", "5"],
            &["check", "pulled-mass", "--help"],
            true,
        ),
        (&sweep, &["sweep", "woodpecker", "--help"], true),
        (
            &["fit", "scenarios/tracked-toy-example.csv"],
            &["fit", "--help"],
            true,
        ),
    ];
    for (args, help_args, takes_out) in runs {
        let help = stdout_of(help_args);
        for (flag, value) in [
            ("--csv", Some(out.as_str())),
            ("--csv-dialect", Some("semicolon")),
            ("--json", None),
            ("--periods", Some("3")),
        ] {
            let listed = help
                .lines()
                .any(|l| l.trim_start().split([' ', ',']).any(|w| w == flag));
            let mut run = stickslip();
            run.args(args).arg(flag).args(value);
            if takes_out {
                run.arg("--out").arg(&out);
            }
            let stderr = String::from_utf8(run.output().unwrap().stderr).unwrap();
            let refused = stderr.contains("does not apply");
            assert!(
                !(listed && refused),
                "{args:?}: help lists {flag}, refused: {stderr}"
            );
            // Hidden flags are still refused with the one-line reason, not unknown.
            if !listed {
                assert!(
                    !stderr.contains("unexpected argument"),
                    "{args:?} {flag}: {stderr}"
                );
            }
        }
    }
}

#[test]
fn a_dash_reads_standard_input_for_fit_scenario_and_formulas() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let read = |p: &str| std::fs::read_to_string(root.join(p)).expect("input file");
    let dir = tempfile::tempdir().expect("temporary folder");
    let run = |args: &[&str], stdin: Option<String>| {
        let mut cmd = stickslip();
        cmd.args(args);
        if let Some(text) = stdin {
            cmd.write_stdin(text);
        }
        let out = cmd.assert().success().get_output().clone();
        String::from_utf8(out.stdout).expect("UTF-8")
    };

    let scenario = "scenarios/fig16-no-intermediate-halt.toml";
    assert_eq!(
        run(
            &["eval", "woodpecker", "--scenario", "-", "--json"],
            Some(read(scenario))
        ),
        run(
            &["eval", "woodpecker", "--scenario", scenario, "--json"],
            None
        )
    );

    let formulas = "scenarios/checks/paper-formulas.toml";
    let check = |source: &str, stdin| {
        let mut cmd = stickslip();
        cmd.args([
            "check",
            "pulled-mass",
            "--formulas",
            source,
            "--samples",
            "20",
            "--json",
        ]);
        if let Some(text) = stdin {
            cmd.write_stdin(text);
        }
        // Some of the file's formulas are wrong on purpose: a verdict (exit 3), reported in full.
        cmd.assert().code(3).get_output().stdout.clone()
    };
    assert_eq!(check("-", Some(read(formulas))), check(formulas, None));

    let data = "scenarios/tracked-toy-example.csv";
    let out = |name: &str| dir.path().join(name).display().to_string();
    let from_stdin = run(&["fit", "-", "-o", &out("a"), "--json"], Some(read(data)));
    let from_file = run(&["fit", data, "-o", &out("b"), "--json"], None);
    let fitted = |json: &str| {
        let mut v: serde_json::Value = serde_json::from_str(json).expect("JSON");
        v["data"]["file"] = serde_json::Value::Null;
        v
    };
    assert_eq!(fitted(&from_stdin), fitted(&from_file));
}

#[test]
fn standard_input_is_read_once_and_csv_to_standard_output_is_refused() {
    let dir = tempfile::tempdir().expect("temporary folder");
    let refused = |args: &[&str]| {
        let out = stickslip()
            .current_dir(dir.path())
            .args(args)
            .write_stdin("")
            .assert()
            .code(2)
            .get_output()
            .clone();
        assert!(out.stdout.is_empty());
        String::from_utf8(out.stderr).expect("UTF-8")
    };
    let err = refused(&["eval", "woodpecker", "--csv", "-"]);
    assert!(err.starts_with("error: --csv takes a folder"), "{err}");
    assert!(!dir.path().join("-").exists(), "no folder named -");
    let err = refused(&["fit", "-", "--scenario", "-", "-o", "fit"]);
    assert_eq!(
        err,
        "error: FILE and --scenario: only one of them can be - (standard input is read once)\n"
    );
}

/// The first key of a JSON document (the text as written, so the order is the writer's).
fn first_key(text: &str) -> String {
    let rest = text.trim_start().strip_prefix('{').expect("an object");
    let rest = rest.trim_start().strip_prefix('"').expect("a key");
    rest.split('"').next().unwrap().to_string()
}

#[test]
fn every_json_output_opens_with_the_schema_version() {
    let tmp = tempfile::tempdir().unwrap();
    let dir = |name: &str| tmp.path().join(name).display().to_string();
    let formula = "v_avg = g*T*phi^3*Gamma";
    let mut texts = vec![
        ("eval", stdout_of(&["eval", "woodpecker", "--json"])),
        ("claims", stdout_of(&["claims", "pulled-mass", "--json"])),
        (
            "check",
            stdout_of(&["check", "pulled-mass", formula, "--samples", "3", "--json"]),
        ),
    ];
    stdout_of(&[
        "check",
        "pulled-mass",
        formula,
        "--samples",
        "3",
        "-o",
        &dir("c"),
    ]);
    stdout_of(&["worksheet", "--model", "woodpecker", "-o", &dir("w")]);
    stdout_of(&[
        "fit",
        "scenarios/tracked-toy-example.csv",
        "--scenario",
        "scenarios/fig26-tracked-toy.toml",
        "-o",
        &dir("f"),
    ]);
    for file in ["c/check.json", "w/answer-key.json", "f/fit.json"] {
        texts.push((
            file,
            std::fs::read_to_string(tmp.path().join(file)).unwrap(),
        ));
    }
    for (what, text) in texts {
        assert_eq!(first_key(&text), stickslip::results::SCHEMA_KEY, "{what}");
        let v: serde_json::Value = serde_json::from_str(&text).unwrap();
        assert_eq!(
            v[stickslip::results::SCHEMA_KEY],
            stickslip::results::SCHEMA_VERSION,
            "{what}"
        );
    }
}
