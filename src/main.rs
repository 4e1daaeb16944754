//! `stickslip`: thin entry point. Parses the command line, runs it, prints the error chain.
//!
//! Exit codes: 0 success; 2 bad input (usage, parameter out of range, unreadable or malformed
//! scenario or tracked data, unknown scene, unwritable output, `--pdf` without Chromium); 1 an
//! internal failure: the engine, a figure or template, a fit that did not converge (its results
//! are written, flagged), or Chromium failing to print. [`Error::exit_code`] holds the rule.

use std::io::Write;
use std::path::Path;
use std::process::ExitCode;

use anyhow::{Context, Result};
use clap::Parser;

use stickslip::cli::{
    BenchArgs, Cli, Command, CommonArgs, EvalModel, FitArgs, HandoutArgs, PulledMassArgs,
    ReportArgs, SweepArgs, SweepModel, WoodpeckerArgs, WorksheetArgs,
};
use stickslip::error::Error;
use stickslip::params::{
    invalid, ModelName, PulledMassParams, Scenario, WoodpeckerParams, DEFAULT_PERIODS,
};
use stickslip::{output, report, results};

fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) if e.use_stderr() => {
            eprintln!("{}", one_line(&e.render().to_string()));
            return ExitCode::from(2);
        }
        Err(e) => {
            let _ = e.print();
            return ExitCode::SUCCESS;
        }
    };
    match run(cli) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e:#}");
            // The library's errors decide (Error::exit_code); the others are usage refused here.
            ExitCode::from(e.downcast_ref::<Error>().map_or(2, Error::exit_code))
        }
    }
}

/// clap's message on one line: the problem, the flags it names and the possible values, without
/// the usage and help hints that follow a blank line.
fn one_line(clap_message: &str) -> String {
    let line = clap_message
        .lines()
        .take_while(|l| !l.trim().is_empty())
        .map(str::trim)
        .collect::<Vec<_>>()
        .join(" ");
    if line.is_empty() {
        "error: invalid usage".to_string()
    } else {
        line
    }
}

fn run(cli: Cli) -> Result<()> {
    match cli.command {
        Command::Eval { model } => match model {
            EvalModel::PulledMass(args) => eval_pulled_mass(&args),
            EvalModel::Woodpecker(args) => eval_woodpecker(&args),
        },
        Command::Report(args) => report(&args),
        Command::Claims {
            seed,
            samples,
            model,
        } => claims(seed, samples, &model),
        Command::Bench(args) => bench(&args),
        Command::Handout(args) => handout(&args),
        Command::Sweep { model } => sweep(&model),
        Command::Fit(args) => fit(&args),
        Command::Worksheet(args) => worksheet(&args),
    }
}

/// `stickslip fit`: read, fit, write the files, print; a fit that did not converge is still
/// written and printed (flagged), then reported as an error (exit 1).
fn fit(args: &FitArgs) -> Result<()> {
    let common = &args.model.common;
    reject_flag("fit", "--periods", common.periods.is_some())?;
    reject_flag("fit", "--csv", common.csv.is_some())?;
    let (base, _) = woodpecker_params(&args.model)?;
    let opts = stickslip::fit::data::ReadOptions {
        columns: args.columns.clone(),
        unit: args.units,
    };
    let data = stickslip::fit::data::read(&args.file, &opts)?;
    let fit = stickslip::fit::fit(&data, &base, &args.free)?;
    report::write_all(&args.out, &stickslip::fit::render(&fit)?)?;
    print_stdout(&if common.json {
        stickslip::fit::json(&fit)?
    } else {
        stickslip::fit::text(&fit, &args.out)
    })?;
    if !fit.converged {
        return Err(Error::NotConverged {
            reason: format!(
                "{} (results in {} are flagged \"converged\": false)",
                fit.termination,
                args.out.display()
            ),
        }
        .into());
    }
    Ok(())
}

/// `stickslip worksheet`: every sheet and the key are rendered before anything is written.
fn worksheet(args: &WorksheetArgs) -> Result<()> {
    let request = stickslip::worksheet::Request {
        model: args.model,
        students: args.students,
        seed: args.seed,
        regime: args.regime.clone(),
        questions: args.questions.clone(),
    };
    let sheets = stickslip::worksheet::generate(&request)?;
    let files = stickslip::worksheet::render(&sheets, &args.format)?;
    let written = report::write_all(&args.out, &files)?;
    print_stdout(&format!(
        "wrote {} files for {} students ({}, regime {}) to {}\n",
        written.len(),
        sheets.students.len(),
        args.model.id(),
        sheets.regime,
        args.out.display()
    ))
}

/// `stickslip bench`: measure, render, write; the elapsed time goes to stderr.
fn bench(args: &BenchArgs) -> Result<()> {
    let started = std::time::Instant::now();
    let config = stickslip::bench::Config {
        quick: args.quick,
        repeats: args.repeats,
        peer: args.peer,
    };
    let results = stickslip::bench::run(&config)?;
    let files = stickslip::bench::render(&results)?;
    let written = report::write_all(&args.out, &files)?;
    eprintln!(
        "bench: elapsed {:.1} s (measurements {:.1} s)",
        started.elapsed().as_secs_f64(),
        results.elapsed_s
    );
    print_stdout(&format!(
        "wrote {} files to {}\n",
        written.len(),
        args.out.display()
    ))
}

fn report(args: &ReportArgs) -> Result<()> {
    let scenes = if args.scenarios.is_empty() {
        report::builtin_scenes()?
    } else {
        args.scenarios
            .iter()
            .map(|path| report::Scene::from_file(path))
            .collect::<stickslip::error::Result<Vec<_>>>()?
    };
    // Everything is rendered before anything is written: an error leaves no partial report.
    let files = report::render(&scenes, &args.format)?;
    let written = report::write_all(&args.out, &files)?;
    print_stdout(&format!(
        "wrote {} files for {} scenes to {}\n",
        written.len(),
        scenes.len(),
        args.out.display()
    ))
}

/// `stickslip handout`: the browser is looked up first and everything (the PDF included) is
/// rendered before anything is written.
fn handout(args: &HandoutArgs) -> Result<()> {
    use stickslip::handout;
    let Some(id) = args.scene.as_deref().filter(|_| !args.list) else {
        return print_stdout(&handout::list()?);
    };
    let browser = args.pdf.then(handout::pdf::locate).transpose()?;
    let scene = handout::find_scene(id)?;
    let files = handout::render(&scene, &args.format, browser.as_deref())?;
    let written = report::write_all(&args.out, &files)?;
    print_stdout(&format!(
        "wrote {} files for {} to {}\n",
        written.len(),
        scene.id,
        args.out.display()
    ))
}

fn claims(seed: u64, samples: usize, model: &EvalModel) -> Result<()> {
    let common = match model {
        EvalModel::PulledMass(args) => &args.common,
        EvalModel::Woodpecker(args) => &args.common,
    };
    reject_flag("claims", "--csv", common.csv.is_some())?;
    let (pulled, wood, json) = match model {
        EvalModel::PulledMass(args) => (
            pulled_params(args)?.0,
            WoodpeckerParams::default(),
            args.common.json,
        ),
        EvalModel::Woodpecker(args) => (
            PulledMassParams::default(),
            woodpecker_params(args)?.0,
            args.common.json,
        ),
    };
    let sample = stickslip::claims::Sample {
        seed,
        size: samples,
    };
    let claims = stickslip::claims::evaluate(&pulled, &wood, &sample)?;
    print_stdout(&if json {
        serde_json::to_string_pretty(&claims)? + "\n"
    } else {
        output::text::claims(&claims)
    })
}

/// The scenario (if any) and the number of periods, flags first.
fn load_common(common: &CommonArgs) -> Result<(Option<Scenario>, u32)> {
    let scenario = common.scenario.as_deref().map(Scenario::load).transpose()?;
    let periods = match common.periods {
        Some(n) => u32::try_from(n).map_err(|_| {
            invalid(
                "periods",
                n,
                format!("1 <= periods <= {}", stickslip::params::MAX_PERIODS),
            )
        })?,
        None => scenario
            .as_ref()
            .and_then(|s| s.periods)
            .unwrap_or(DEFAULT_PERIODS),
    };
    Ok((scenario, periods))
}

/// The model's parameters: the scenario's (defaults for keys it omits), or the defaults.
fn base_params<P: Default + for<'de> serde::Deserialize<'de>>(
    scenario: Option<&Scenario>,
    common: &CommonArgs,
    model: ModelName,
) -> Result<P> {
    match (scenario, &common.scenario) {
        (Some(s), Some(path)) => {
            ensure_model(s, model, path)?;
            Ok(s.params(path)?)
        }
        _ => Ok(P::default()),
    }
}

/// Overrides `slot` with a flag's value when the flag was given.
fn set<T: Copy>(slot: &mut T, flag: Option<T>) {
    if let Some(v) = flag {
        *slot = v;
    }
}

fn pulled_params(args: &PulledMassArgs) -> Result<(PulledMassParams, u32)> {
    let (scenario, periods) = load_common(&args.common)?;
    let mut p: PulledMassParams =
        base_params(scenario.as_ref(), &args.common, ModelName::PulledMass)?;
    set(&mut p.mu_s, args.mu_s);
    set(&mut p.mu_d, args.mu_d);
    set(&mut p.mass, args.mass);
    set(&mut p.k, args.k);
    set(&mut p.force, args.force);
    set(&mut p.g, args.g);
    Ok((p, periods))
}

fn eval_pulled_mass(args: &PulledMassArgs) -> Result<()> {
    let (p, periods) = pulled_params(args)?;
    let evaluation = match &args.common.csv {
        None => results::pulled_mass::evaluate(&p, periods)?,
        Some(dir) => {
            let (evaluation, runs) = results::pulled_mass::evaluate_with_runs(&p, periods, true)?;
            // Written before anything is printed: a bad target leaves no output at all.
            report::write_all(dir, &stickslip::export::pulled_mass_files(&runs))?;
            evaluation
        }
    };
    print_stdout(&if args.common.json {
        serde_json::to_string_pretty(&evaluation)? + "\n"
    } else {
        output::text::pulled_mass(&evaluation)
    })
}

fn woodpecker_params(args: &WoodpeckerArgs) -> Result<(WoodpeckerParams, u32)> {
    let (scenario, periods) = load_common(&args.common)?;
    let mut p: WoodpeckerParams =
        base_params(scenario.as_ref(), &args.common, ModelName::Woodpecker)?;
    set(&mut p.mu_s, args.mu_s);
    set(&mut p.mu_d, args.mu_d);
    set(&mut p.k, args.k);
    set(&mut p.m_sleeve, args.m_sleeve);
    set(&mut p.m_bird, args.m_bird);
    set(&mut p.l, args.l);
    set(&mut p.h, args.h);
    set(&mut p.z0, args.z0);
    set(&mut p.d0, args.d0);
    set(&mut p.g, args.g);
    if args.lever.is_some() {
        p.lever = args.lever;
    }
    set(&mut p.omega, args.omega);
    set(&mut p.counterpart, args.counterpart);
    Ok((p, periods))
}

fn eval_woodpecker(args: &WoodpeckerArgs) -> Result<()> {
    let (p, periods) = woodpecker_params(args)?;
    let evaluation = match &args.common.csv {
        None => results::woodpecker::evaluate(&p, periods)?,
        Some(dir) => {
            let (evaluation, runs) = results::woodpecker::evaluate_with_runs(&p, periods, true)?;
            report::write_all(dir, &stickslip::export::woodpecker_files(&p, &runs))?;
            evaluation
        }
    };
    print_stdout(&if args.common.json {
        serde_json::to_string_pretty(&evaluation)? + "\n"
    } else {
        output::text::woodpecker(&evaluation)
    })
}

/// `stickslip sweep`: the grid around the base parameters of flags and scenario; files are
/// written only once every point has been computed.
fn sweep(model: &SweepModel) -> Result<()> {
    let (grid, common, base, periods) = match model {
        SweepModel::PulledMass { sweep, model } => {
            let (p, periods) = pulled_params(model)?;
            let base = stickslip::sweep::Base::PulledMass(p);
            (sweep, &model.common, base, periods)
        }
        SweepModel::Woodpecker { sweep, model } => {
            let (p, periods) = woodpecker_params(model)?;
            let base = stickslip::sweep::Base::Woodpecker(p);
            (sweep, &model.common, base, periods)
        }
    };
    reject_flag("sweep", "--json", common.json)?;
    reject_flag("sweep", "--csv", common.csv.is_some())?;
    let SweepArgs {
        param,
        from,
        to,
        steps,
        out,
    } = grid;
    let spec = stickslip::sweep::GridSpec {
        param: param.clone(),
        from: *from,
        to: *to,
        steps: *steps,
        periods,
    };
    stickslip::sweep::validate(&base, &spec)?;
    let progress = stickslip::sweep::progress_bar(spec.steps);
    let result = stickslip::sweep::run(&base, &spec, &progress)?;
    let files = stickslip::sweep::render(&result)?;
    report::write_all(out, &files)?;
    print_stdout(&stickslip::sweep::summary_line(&result, out))
}

/// A flag that the subcommand does not use is refused rather than silently ignored.
fn reject_flag(command: &str, flag: &str, given: bool) -> Result<()> {
    if given {
        anyhow::bail!("{flag} does not apply to `stickslip {command}`");
    }
    Ok(())
}

fn ensure_model(s: &Scenario, want: ModelName, path: &Path) -> Result<()> {
    if s.model != want {
        return Err(Error::Scenario {
            path: path.display().to_string(),
            reason: format!("describes model {}, not {}", s.model.id(), want.id()),
        }
        .into());
    }
    Ok(())
}

fn print_stdout(text: &str) -> Result<()> {
    let mut stdout = std::io::stdout().lock();
    match stdout
        .write_all(text.as_bytes())
        .and_then(|()| stdout.flush())
    {
        // A closed pipe (`| head`) is not an error of ours.
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => Ok(()),
        other => other.context("writing to standard output"),
    }
}
