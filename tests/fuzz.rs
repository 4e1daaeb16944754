//! The fuzz harness of the hardening issue: proptest drives three of the doors adversarial input
//! comes through (the command line, scenario files, tracked-data files) with the values that
//! once broke them (1e308, NaN, control bytes, stray quotes, newlines in keys, -1 counts) mixed
//! with arbitrary text; `tests/finite.rs` drives the fourth, the library evaluation, over the
//! whole accepted parameter range.
//!
//! Every case must end in a result or a typed error whose message is one line of at most 300
//! characters without control characters; never a panic, and never an internal failure (exit 1)
//! for input the tool accepts, except a fit that does not converge.
//!
//! Cases per target: `FUZZ_CASES` (default 256, the bounded count CI runs); a long run is
//! `FUZZ_CASES=20000 cargo test --release --test fuzz`.

use std::path::Path;

use clap::Parser;
use proptest::prelude::*;
use proptest::test_runner::Config;
use stickslip::cli::{Cli, Command};
use stickslip::commands::model_params;
use stickslip::error::Error;
use stickslip::fit::data::{parse, ReadOptions};
use stickslip::models::woodpecker::fit::{fit, FitParam};
use stickslip::models::woodpecker::WoodpeckerParams;
use stickslip::models::Model;
use stickslip::params::Scenario;

/// Longest message the command line prints (main adds "error: ").
const MESSAGE_CHARS: usize = 300 - "error: ".len();

fn config() -> Config {
    let cases = std::env::var("FUZZ_CASES")
        .ok()
        .and_then(|n| n.parse().ok())
        .unwrap_or(256);
    Config {
        cases,
        failure_persistence: None,
        ..Config::default()
    }
}

/// One line, bounded, no control characters.
fn assert_message(label: &str, msg: &str) {
    assert!(
        msg.chars().count() <= MESSAGE_CHARS,
        "{label}: {} chars: {msg}",
        msg.chars().count()
    );
    assert!(
        !msg.chars().any(char::is_control),
        "{label}: control character in {msg:?}"
    );
}

/// Input is refused with exit 2; exit 1 means the tool failed on input it accepted.
fn assert_refused(label: &str, e: &Error) {
    assert_message(label, &e.to_string());
    assert_eq!(e.exit_code(), 2, "{label}: internal failure: {e}");
}

/// Values that broke a parser once, and arbitrary text.
fn value() -> impl Strategy<Value = String> {
    const NASTY: &[&str] = &[
        "0",
        "-0",
        "1",
        "-1",
        "0.4",
        "0.32",
        "1e-9",
        "1e-51",
        "1e50",
        "1e51",
        "1e308",
        "-1e308",
        "1e-320",
        "nan",
        "NaN",
        "inf",
        "-inf",
        "",
        " ",
        "0x10",
        "1,5",
        "4e",
        ".",
        "\u{7}",
        "a\nb",
        "\u{1b}[31m",
        "\u{202e}",
        "\"",
        "9999999999999999999999",
        "0.470879999999999",
    ];
    prop_oneof![
        4 => proptest::sample::select(NASTY).prop_map(str::to_string),
        3 => any::<f64>().prop_map(|x| x.to_string()),
        2 => (-60.0..60.0f64).prop_map(|e| format!("{:e}", 10f64.powf(e))),
        1 => "\\PC{0,12}",
        1 => proptest::collection::vec(any::<char>(), 0..8).prop_map(String::from_iter),
    ]
}

/// The flags of a model as the command line spells them (`--mu-s`), from its registry.
fn model_flags(model: &str) -> Vec<String> {
    Model::from_id(model).map_or_else(Vec::new, |m| {
        m.flags()
            .iter()
            .map(|f| format!("--{}", f.key.replace('_', "-")))
            .collect()
    })
}

fn flag(model: &str) -> impl Strategy<Value = String> {
    const SHARED: &[&str] = &["--periods", "--scenario", "--json", "--nope", "-x", "--"];
    let shared = proptest::sample::select(SHARED).prop_map(str::to_string);
    let own = model_flags(model);
    if own.is_empty() {
        return shared.boxed();
    }
    prop_oneof![4 => proptest::sample::select(own), 1 => shared].boxed()
}

/// `stickslip eval MODEL` with flags and values in any order.
fn eval_line() -> impl Strategy<Value = Vec<String>> {
    proptest::sample::select(&["pulled-mass", "woodpecker", "belt", "pendulum", ""][..])
        .prop_flat_map(|model| {
            proptest::collection::vec((flag(model), value()), 0..6).prop_map(move |pairs| {
                let mut argv = vec!["stickslip".to_string(), "eval".to_string(), model.into()];
                for (f, v) in pairs {
                    argv.push(f.to_string());
                    // --periods runs what it asks for: keep it short, or refused.
                    if f == "--periods" && v.parse::<i64>().is_ok_and(|n| n > 16) {
                        argv.push("16".to_string());
                    } else if f == "--scenario" && v.len().is_multiple_of(2) {
                        argv.push(format!(
                            "{}/scenarios/fig15-double-slip-stick.toml",
                            env!("CARGO_MANIFEST_DIR")
                        ));
                    } else {
                        argv.push(v);
                    }
                }
                argv
            })
        })
}

/// Parses and evaluates an `eval` command line as main does, without printing.
fn eval(argv: &[String]) -> Result<(), String> {
    let cli = Cli::try_parse_from(argv).map_err(|e| e.render().to_string())?;
    let Command::Eval { model } = cli.command else {
        unreachable!("an eval line parses as eval")
    };
    let label = format!("{argv:?}");
    let outcome = model_params(&model.args)
        .and_then(|(model, periods)| Ok(stickslip::explore::evaluate_json(&model, periods)?));
    match outcome {
        Ok(json) => {
            for bad in ["NaN", "Infinity", "inf"] {
                assert!(!json.contains(bad), "{label}: {bad} in {json}");
            }
        }
        Err(e) => match e.downcast_ref::<Error>() {
            Some(e) => assert_refused(&label, e),
            None => assert_message(&label, &format!("{e:#}")),
        },
    }
    Ok(())
}

/// A scenario file: TOML lines with real and odd keys, values of every type, and junk.
fn scenario_text() -> impl Strategy<Value = String> {
    let key = prop_oneof![
        proptest::sample::select(
            &[
                "mu_s",
                "mu_d",
                "force",
                "mass",
                "k",
                "g",
                "z0",
                "d0",
                "m_sleeve",
                "m_bird",
                "lever",
                "omega",
                "counterpart",
                "periods",
                "l",
                "h"
            ][..]
        )
        .prop_map(str::to_string),
        "\\PC{1,8}".prop_map(|k| format!("\"{}\"", k.replace(['"', '\\'], ""))),
        Just("\"a\\nb\"".to_string()),
    ];
    let toml_value = prop_oneof![
        value().prop_map(|v| v.parse::<f64>().map_or_else(
            |_| format!("{v:?}"),
            |x| if x.is_finite() {
                format!("{x:e}")
            } else {
                format!("{v:?}")
            }
        )),
        any::<i64>().prop_map(|n| n.to_string()),
        Just("nan".to_string()),
        Just("inf".to_string()),
        Just("true".to_string()),
        Just("[1, 2]".to_string()),
        Just("{ a = 1 }".to_string()),
    ];
    let param_line = (key, toml_value).prop_map(|(k, v)| format!("{k} = {v}"));
    (
        proptest::sample::select(&["pulled-mass", "woodpecker", "belt", "pendulum", ""][..]),
        value(),
        value(),
        proptest::collection::vec(param_line, 0..8),
        "\\PC{0,20}",
        0..4u8,
    )
        .prop_map(|(model, title, description, params, junk, mode)| {
            let mut text = format!(
                "model = {model:?}\ntitle = {title:?}\ndescription = {description:?}\n\n[params]\n"
            );
            for line in params {
                text.push_str(&line);
                text.push('\n');
            }
            match mode {
                0 => text.push_str(&junk),
                1 => text = text.replace("[params]", &junk),
                _ => {}
            }
            text
        })
}

/// A tracked-data file as apps write it, sometimes broken: comments, a title, a header, a
/// units row, `,` or `;` with decimal commas, rows of a falling toy, and corruption.
fn tracked_text() -> impl Strategy<Value = String> {
    (
        any::<bool>(),
        any::<bool>(),
        proptest::sample::select(&["t,y", "time;y", "t,x,y", "a,b", "t", "\"t\",\"y\""][..]),
        proptest::sample::select(&["", "s,mm", "(s),(m)", "s,m,mm"][..]),
        10..80usize,
        (-3.0..3.0f64).prop_map(|e| 10f64.powf(e) / 240.0),
        proptest::collection::vec((0..200usize, value()), 0..3),
    )
        .prop_map(|(title, comment, header, units, rows, dt, corrupt)| {
            let semicolon = header.contains(';');
            let sep = if semicolon { ";" } else { "," };
            let units = units.replace([',', ';'], sep);
            let mut lines = Vec::new();
            if comment {
                lines.push("# tracked with a phone".to_string());
            }
            if title {
                lines.push("mass A".to_string());
            }
            lines.push(header.to_string());
            if !units.is_empty() {
                lines.push(units.to_string());
            }
            let cols = header.matches([',', ';']).count() + 1;
            for i in 0..rows {
                let t = i as f64 * dt;
                let y = 0.2 - 0.024 * t + 0.002 * (t * 38.0).sin();
                let mut cells: Vec<String> = (0..cols.max(2))
                    .map(|c| {
                        if c == 0 {
                            format!("{t:.6}")
                        } else {
                            format!("{y:.7}")
                        }
                    })
                    .collect();
                if semicolon {
                    cells.iter_mut().for_each(|c| *c = c.replace('.', ","));
                }
                lines.push(cells.join(sep));
            }
            for (at, junk) in corrupt {
                let n = lines.len();
                lines[at % n] = junk;
            }
            lines.join("\n") + "\n"
        })
}

proptest! {
    #![proptest_config(config())]

    /// The command line: parsed or refused by clap in one line; a parsed `eval` evaluates
    /// to finite numbers or is refused with exit 2.
    #[test]
    fn command_lines(argv in eval_line()) {
        if let Err(clap_message) = eval(&argv) {
            let first = clap_message.lines().next().unwrap_or_default();
            prop_assert!(!first.is_empty() || clap_message.is_empty());
        }
    }

    /// Scenario files: parsed to a valid model, or refused naming the problem in one line.
    #[test]
    fn scenario_files(text in scenario_text()) {
        let path = Path::new("fuzz.toml");
        let read = Scenario::parse(&text, path).and_then(|s| {
            let model = s.model_params(path)?;
            model.validate().map(|()| s)
        });
        match read {
            Ok(scenario) => prop_assert!(!scenario.title.contains('\n')),
            Err(e) => assert_refused(&format!("{text:?}"), &e),
        }
    }

    /// Tracked data: read or refused in one line; what is read is fitted, or the fit says it
    /// did not converge.
    #[test]
    fn tracked_data(text in tracked_text()) {
        let path = Path::new("fuzz.csv");
        let opts = ReadOptions { columns: None, unit: None };
        match parse(&text, path, &opts) {
            Ok(data) => match fit(&data, &WoodpeckerParams::default(), &FitParam::DEFAULT) {
                Ok(f) => prop_assert!(f.estimates.iter().all(|e| e.value.is_finite())),
                // A search that did not converge, or a negative verdict on data that fit
                // only in another unit: reported in one line.
                Err(Error::NotConverged { reason } | Error::Verdict { reason }) => {
                    assert_message(&text, &reason)
                }
                Err(e) => assert_refused(&text, &e),
            },
            Err(e) => assert_refused(&text, &e),
        }
    }
}
