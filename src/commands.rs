//! The subcommands: each reads its options, calls the library and writes or prints the
//! result. Everything a command writes is rendered first, so an error leaves no partial output.

use std::io::Write;

use anyhow::{Context, Result};

use crate::cli::{
    BenchArgs, CheckArgs, ClaimsArgs, Cli, Command, CommonArgs, ExplorerArgs, FitArgs, HandoutArgs,
    ModelArgs, ModelCommand, ReportArgs, SheetFormat, SweepArgs, WorksheetArgs,
};
use crate::error::Error;
use crate::export::CsvDialect;
use crate::models::param::invalid;
use crate::models::{with_capability, Model};
use crate::params::{Scenario, DEFAULT_PERIODS, MAX_PERIODS};
use crate::present::Present;
use crate::report::{self, Format};

/// Runs a parsed command line; what it prints goes to `out`, its notes to `err`.
pub fn run(cli: Cli, out: &mut dyn Write, err: &mut dyn Write) -> Result<()> {
    match cli.command {
        Command::Eval { model } => eval(&model.args, out),
        Command::Report(args) => report(&args, out),
        Command::Claims {
            seed,
            samples,
            model,
        } => claims(seed, samples, &model, out),
        Command::Bench(args) => bench(&args, out),
        Command::Handout(args) => handout(&args, out, err),
        Command::Sweep { model: Some(model) } => sweep(&model, out),
        Command::Sweep { model: None } => sweep_every_model(out),
        Command::Check { model } => check(&model, out),
        Command::Fit(args) => fit(&args, out),
        Command::Worksheet(args) => worksheet(&args, out),
        Command::Explorer(args) => explorer(&args, out),
        Command::Completions { shell } => print_stdout(out, &crate::shell::completions(shell)),
        Command::Man => print_stdout(
            out,
            &crate::shell::man_page().context("rendering the man page")?,
        ),
    }
}

/// Hints for the user gathered while a command runs, printed by `main` when it succeeds.
static HINTS: std::sync::Mutex<Vec<String>> = std::sync::Mutex::new(Vec::new());

/// The hints gathered so far (one line each), emptied.
pub fn take_hints() -> Vec<String> {
    std::mem::take(
        &mut *HINTS
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner),
    )
}

/// The model's parameters and the periods to integrate: the defaults, overridden by the
/// scenario file (if any), overridden by the flags given.
pub fn model_params(args: &ModelArgs) -> Result<(Model, u32)> {
    let common = &args.common;
    let scenario = common.scenario.as_deref().map(Scenario::load).transpose()?;
    let periods = match common.periods {
        Some(n) => u32::try_from(n)
            .map_err(|_| invalid("periods", n, format!("1 <= periods <= {MAX_PERIODS}")))?,
        None => scenario
            .as_ref()
            .and_then(|s| s.periods)
            .unwrap_or(DEFAULT_PERIODS),
    };
    let mut model = match (&scenario, &common.scenario) {
        (Some(s), Some(path)) => {
            if s.model.id() != args.model.id() {
                return Err(Error::Scenario {
                    path: path.display().to_string(),
                    reason: format!("describes model {}, not {}", s.model.id(), args.model.id()),
                }
                .into());
            }
            s.model_params(path)?
        }
        _ => args.model,
    };
    for &(key, value) in &args.numbers {
        model.set(key, value);
    }
    // A value that looks typed in mm or g runs as given, with a word on stderr once the command
    // has succeeded (a failing one prints its one-line error only).
    let hints = args
        .numbers
        .iter()
        .filter_map(|&(k, v)| model.unit_hint(k, v));
    HINTS
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner)
        .extend(hints);
    for (key, value) in &args.choices {
        model.set_choice(key, value);
    }
    Ok((model, periods))
}

/// `stickslip eval MODEL`: the evaluation (guide §14) as tables or JSON, and the CSV files with --csv.
fn eval(args: &ModelArgs, out: &mut dyn Write) -> Result<()> {
    if args.common.csv.is_none() && args.common.csv_dialect.is_some() {
        anyhow::bail!("--csv-dialect applies to the files of --csv DIR: give --csv too");
    }
    if args.common.csv.as_deref() == Some(std::path::Path::new(crate::params::STDIN)) {
        // Four files (time series and events of both laws) do not fit one stream.
        anyhow::bail!("--csv takes a folder for its four files, not - (standard output)");
    }
    fn show<M: Present>(p: &M, periods: u32, args: &ModelArgs) -> Result<String> {
        let evaluation = match &args.common.csv {
            None => p.evaluate(periods)?,
            Some(dir) => {
                report::lock::claim_if_exists(dir)?;
                let (evaluation, files) = p.evaluate_with_csv(periods)?;
                let files = dialect(&args.common).apply(files);
                // Written before anything is printed: a bad target leaves no output at all.
                report::write_all(dir, &files)?;
                evaluation
            }
        };
        Ok(if args.common.json {
            serde_json::to_string_pretty(&crate::results::Versioned::new(&evaluation))? + "\n"
        } else {
            M::text(&evaluation)
        })
    }
    // The JSON of any model; its tables and CSV files where the model presents itself.
    let (model, periods) = model_params(args)?;
    let text = if args.common.json && args.common.csv.is_none() {
        crate::explore::evaluate_json(&model, periods)? + "\n"
    } else {
        with_capability!(&model, present, p => show(p, periods, args)?,
            else return Err(Error::Unsupported {
                model: model.id(),
                what: "text tables or CSV files yet: give --json".to_string(),
            }.into()))
    };
    print_stdout(out, &text)
}

/// `stickslip claims [MODEL]`: the paper's claims on the given parameters (the other model keeps
/// the paper's set) and on a seeded random sample.
fn claims(
    seed: u64,
    samples: usize,
    model: &Option<ModelCommand<ClaimsArgs>>,
    out: &mut dyn Write,
) -> Result<()> {
    let sample = crate::claims::Sample {
        seed,
        size: samples,
    };
    // Without a model: the paper's sets, as text.
    let (claims, json) = match model {
        Some(model) => {
            let common = &model.args.common;
            reject_flag("claims", "--csv", common.csv.is_some())?;
            reject_flag("claims", "--csv-dialect", common.csv_dialect.is_some())?;
            let (params, _) = model_params(&model.args)?;
            (crate::claims::of(&params, &sample)?, common.json)
        }
        None => (crate::claims::paper(&sample)?, false),
    };
    print_stdout(
        out,
        &if json {
            serde_json::to_string_pretty(&crate::results::Versioned::new(&claims))? + "\n"
        } else {
            crate::output::text::claims(&claims)
        },
    )
}

/// `stickslip fit`: read, fit, write the files, print; a fit that did not converge is still
/// written and printed (flagged), then reported as an error (exit 1); one that converged to a
/// minimum that does not describe the data likewise, as a negative verdict (exit 3).
fn fit(args: &FitArgs, out: &mut dyn Write) -> Result<()> {
    let common = &args.model.args.common;
    reject_flag("fit", "--periods", common.periods.is_some())?;
    reject_flag("fit", "--csv", common.csv.is_some())?;
    one_stdin(&[
        ("FILE", Some(&args.file)),
        ("--scenario", common.scenario.as_deref()),
    ])?;
    let model = model_params(&args.model.args)?.0;
    let opts = crate::fit::data::ReadOptions {
        columns: args.columns.clone(),
        unit: args.units,
    };
    report::lock::claim_if_exists(&args.out)?;
    let data = crate::fit::data::read(&args.file, &opts)?;
    let free: Vec<&str> = args.free.iter().map(|f| f.name()).collect();
    let fit = crate::fit::fit(&model, &data, &free, &args.out)?;
    let files = dialect(common).apply(fit.files);
    refuse_overwriting_inputs(&args.out, &files, &[("FILE", &args.file)])?;
    report::write_all(&args.out, &files)?;
    print_stdout(out, if common.json { &fit.json } else { &fit.text })?;
    if !fit.converged {
        return Err(Error::NotConverged {
            reason: format!(
                "{} (results in {} are flagged \"converged\": false)",
                fit.termination,
                shown(&args.out)
            ),
        }
        .into());
    }
    if let Some(misfit) = fit.misfit {
        return Err(Error::Verdict {
            reason: format!("{misfit} (results in {}, flagged)", shown(&args.out)),
        }
        .into());
    }
    Ok(())
}

/// `stickslip worksheet`: every sheet and the key are rendered before anything is written.
fn worksheet(args: &WorksheetArgs, out: &mut dyn Write) -> Result<()> {
    let request = crate::worksheet::Request {
        model: args.model,
        students: args.students,
        seed: args.seed,
        regime: args.regime.clone(),
        questions: args.questions.clone(),
    };
    report::lock::claim_if_exists(&args.out)?;
    // The browser is found before any work: without it, nothing is drawn or written.
    let browser = args.pdf.then(crate::handout::pdf::locate).transpose()?;
    let progress = crate::output::progress::progress_bar(args.students, "students");
    let sheets = crate::worksheet::generate(&request, &progress)?;
    let pages: Vec<Format> = args.format.iter().filter_map(|f| f.page()).collect();
    let mut files = crate::worksheet::render(&sheets, &pages, args.lang)?;
    if let Some(browser) = &browser {
        files.extend(crate::worksheet::pdf(&sheets, args.lang, browser)?);
    }
    files.extend(crate::worksheet::moodle::render(
        &sheets,
        args.format.contains(&SheetFormat::Moodle),
        args.format.contains(&SheetFormat::Gift),
        args.lang,
    )?);
    if args.format.contains(&SheetFormat::Qti) {
        files.push(crate::worksheet::qti::render(&sheets, args.lang)?);
    }
    let written = report::write_all(&args.out, &files)?;
    // The regimes in words, with their counts when the class is mixed.
    let mut counts: Vec<(&str, usize)> = Vec::new();
    for s in &sheets.students {
        let id = s.case.closed_form_regime();
        match counts.iter_mut().find(|(r, _)| *r == id) {
            Some((_, n)) => *n += 1,
            None => counts.push((id, 1)),
        }
    }
    let regimes = match counts.as_slice() {
        [(id, _)] => format!("regime: {}", report::context::regime_words(id)),
        _ => counts
            .iter()
            .map(|(id, n)| format!("{n} × {}", report::context::regime_words(id)))
            .collect::<Vec<_>>()
            .join(", "),
    };
    print_stdout(
        out,
        &format!(
            "wrote {} files for {} students ({}; {regimes}) to {}\n",
            written.len(),
            sheets.students.len(),
            args.model.id(),
            shown(&args.out)
        ),
    )
}

/// `stickslip bench`: measure, render, write; the elapsed time goes to stderr.
fn bench(args: &BenchArgs, out: &mut dyn Write) -> Result<()> {
    report::lock::claim_if_exists(&args.out)?;
    let started = std::time::Instant::now();
    let config = crate::bench::Config {
        quick: args.quick,
        repeats: args.repeats,
        peer: args.peer,
    };
    let results = crate::bench::run(&config)?;
    let files = crate::bench::render(&results)?;
    let written = report::write_all(&args.out, &files)?;
    eprintln!(
        "bench: elapsed {:.1} s (measurements {:.1} s)",
        started.elapsed().as_secs_f64(),
        results.elapsed_s
    );
    print_stdout(
        out,
        &format!("wrote {} files to {}\n", written.len(), shown(&args.out)),
    )
}

/// `stickslip report`: the built-in scenes or the given scenario files.
fn report(args: &ReportArgs, out: &mut dyn Write) -> Result<()> {
    report::lock::claim_if_exists(&args.out)?;
    let (scenes, files) = if args.scenarios.is_empty() {
        let scenes = report::builtin_scenes()?;
        let (mut files, links) = crate::classroom::material(&scenes, &args.format)?;
        files.extend(report::render_with(&scenes, &args.format, &links)?);
        // The JSON Schemas of the tool's outputs, beside the built-in report (reports/schema/).
        files.extend(crate::schema::files()?);
        (scenes, files)
    } else {
        let scenes = report::Scene::from_files(&args.scenarios)?;
        let files = report::render(&scenes, &args.format)?;
        (scenes, files)
    };
    let inputs: Vec<(&str, &std::path::Path)> = args
        .scenarios
        .iter()
        .map(|p| ("SCENARIOS", p.as_path()))
        .collect();
    refuse_overwriting_inputs(&args.out, &files, &inputs)?;
    let written = report::write_all(&args.out, &files)?;
    let plural = |n: usize, word: &str| format!("{n} {word}{}", if n == 1 { "" } else { "s" });
    print_stdout(
        out,
        &format!(
            "wrote {} for {} to {}\n",
            plural(written.len(), "file"),
            plural(scenes.len(), "scene"),
            shown(&args.out)
        ),
    )
}

/// `stickslip explorer`: the page, with the built-in scenes as presets.
fn explorer(args: &ExplorerArgs, out: &mut dyn Write) -> Result<()> {
    report::lock::claim_if_exists(&args.out)?;
    let page = report::explorer::render(
        &report::builtin_scenes()?,
        report::explorer::Placement::Alone,
    )?;
    report::write_all(&args.out, std::slice::from_ref(&page))?;
    print_stdout(
        out,
        &format!("wrote {} to {}\n", page.path.display(), shown(&args.out)),
    )
}

/// `stickslip handout`: the browser is looked up first and everything (the PDF included) is
/// rendered before anything is written.
fn handout(args: &HandoutArgs, out: &mut dyn Write, err: &mut dyn Write) -> Result<()> {
    use crate::handout;
    let Some(id) = args.scene.as_deref().filter(|_| !args.list) else {
        return print_stdout(out, &handout::list()?);
    };
    report::lock::claim_if_exists(&args.out)?;
    let browser = args.pdf.then(handout::pdf::locate).transpose()?;
    let scene = handout::find_scene(id)?;
    let words = crate::lang::phrases::Translator::new(args.lang)?;
    let mut files = handout::render(&scene, &args.format, browser.as_deref(), &words)?;
    // The physics guide the handout links, beside it.
    files.extend(report::guide::files(&args.format, false)?);
    let written = report::write_all(&args.out, &files)?;
    let missing = words.missing();
    if !missing.is_empty() {
        // A scenario file's own words, or a claim worded for parameters the catalogue has not met.
        let _ = writeln!(
            err,
            "note: {} phrase(s) have no {} translation and stay in English, e.g. \"{}\"",
            missing.len(),
            args.lang.code(),
            // A scenario's title can be any length: one bounded line on the terminal.
            crate::error::excerpt(&missing[0], 80)
        );
    }
    print_stdout(
        out,
        &format!(
            "wrote {} files for {} to {}\n",
            written.len(),
            scene.id,
            shown(&args.out)
        ),
    )
}

/// `stickslip sweep MODEL`: the grid around the base parameters of flags and scenario; files
/// are written only once every point has been computed.
fn sweep(model: &ModelCommand<SweepArgs>, out: &mut dyn Write) -> Result<()> {
    let common = &model.args.common;
    reject_flag("sweep", "--json", common.json)?;
    reject_flag("sweep", "--csv", common.csv.is_some())?;
    let (base, periods) = model_params(&model.args)?;
    let grid = &model.extra;
    let spec = crate::sweep::GridSpec {
        param: grid.param.clone(),
        from: grid.from,
        to: grid.to,
        steps: grid.steps,
        periods,
    };
    crate::sweep::validate(&base, &spec)?;
    let (files, summary) = run_sweep(&base, &spec, &grid.out, dialect(common))?;
    if let Some(path) = &common.scenario {
        refuse_overwriting_inputs(&grid.out, &files, &[("--scenario", path)])?;
    }
    report::write_all(&grid.out, &files)?;
    print_stdout(out, &summary)
}

/// `stickslip sweep` without a model: every model that can sweep, at its default set over its
/// own grid ([`crate::sweep::default_spec`]), each into `sweep/MODEL/`.
fn sweep_every_model(out: &mut dyn Write) -> Result<()> {
    for base in Model::defaults() {
        let Some(spec) = crate::sweep::default_spec(&base, DEFAULT_PERIODS) else {
            continue;
        };
        let folder = std::path::Path::new("sweep").join(base.id());
        let (files, summary) = run_sweep(&base, &spec, &folder, CsvDialect::default())?;
        report::write_all(&folder, &files)?;
        print_stdout(out, &summary)?;
    }
    Ok(())
}

/// Runs the sweep `spec` of `base` for the folder `folder` (claimed if it exists): its files
/// and its summary line.
fn run_sweep(
    base: &Model,
    spec: &crate::sweep::GridSpec,
    folder: &std::path::Path,
    dialect: CsvDialect,
) -> Result<(Vec<report::OutFile>, String)> {
    report::lock::claim_if_exists(folder)?;
    let progress = crate::output::progress::progress_bar(spec.steps, "sweep");
    let result = crate::sweep::run(base, spec, &progress)?;
    let summary = crate::sweep::summary_line(&result, folder);
    Ok((dialect.apply(crate::sweep::render(&result)?), summary))
}

/// `stickslip check MODEL FORMULA --quantity NAME` (or `--formulas FILE`): each report as text
/// or JSON, and with `--out` as a page.
fn check(model: &ModelCommand<CheckArgs>, out: &mut dyn Write) -> Result<()> {
    let common = &model.args.common;
    reject_flag("check", "--csv", common.csv.is_some())?;
    reject_flag("check", "--csv-dialect", common.csv_dialect.is_some())?;
    reject_flag("check", "--periods", common.periods.is_some())?;
    one_stdin(&[
        ("--formulas", model.extra.formulas.as_deref()),
        ("--scenario", common.scenario.as_deref()),
    ])?;
    let (case, _) = model_params(&model.args)?;
    let args = &model.extra;
    if args.symbols {
        reject_flag("check --symbols", "--json", common.json)?;
        return print_stdout(out, &crate::check::symbols_text(&case));
    }
    if let Some(out) = &args.out {
        report::lock::claim_if_exists(out)?;
    }
    let entries = match (&args.formulas, &args.formula) {
        (Some(file), _) => crate::check::read_formulas(file)?,
        (None, Some(formula)) => vec![crate::check::Entry {
            formula: formula.clone(),
            quantity: args.quantity.clone(),
            regime: args.regime.clone(),
        }],
        _ => anyhow::bail!("give a FORMULA (and --quantity NAME), or --formulas FILE"),
    };
    // Every table draws --samples sets: the product is the work, bounded like one formula's.
    let work = entries.len().saturating_mul(args.samples);
    if entries.len() > 1 && work > crate::check::MAX_SAMPLES {
        return Err(invalid(
            "samples",
            args.samples,
            format!(
                "[[check]] tables of --formulas x --samples <= {} (here {} x {})",
                crate::check::MAX_SAMPLES,
                entries.len(),
                args.samples
            ),
        )
        .into());
    }
    let reports = entries
        .into_iter()
        .map(|e| {
            crate::check::run(&crate::check::Request {
                case,
                formula: e.formula,
                quantity: e.quantity,
                regime: e.regime.or_else(|| args.regime.clone()),
                samples: args.samples,
                seed: args.seed,
            })
        })
        .collect::<std::result::Result<Vec<_>, _>>()?;
    if let Some(out) = &args.out {
        let mut files = Vec::new();
        for (i, r) in reports.iter().enumerate() {
            let rendered = crate::check::render(r)?;
            if reports.len() == 1 {
                files.extend(rendered);
            } else {
                files.extend(rendered.into_iter().map(|f| {
                    let path = f.path.with_file_name(format!("check-{}", i + 1));
                    let ext = f.path.extension().unwrap_or_default().to_owned();
                    report::OutFile {
                        path: path.with_extension(ext),
                        ..f
                    }
                }));
            }
        }
        report::write_all(out, &files)?;
    }
    print_stdout(
        out,
        &match (common.json, reports.as_slice()) {
            (true, [one]) => {
                serde_json::to_string_pretty(&crate::results::Versioned::new(one))? + "\n"
            }
            (true, all) => {
                let all: Vec<_> = all.iter().map(crate::results::Versioned::new).collect();
                serde_json::to_string_pretty(&all)? + "\n"
            }
            (false, all) => all
                .iter()
                .map(crate::check::text)
                .collect::<Vec<_>>()
                .join("\n"),
        },
    )?;
    // Reported in full above; the exit code (3) lets a script or CI job act on the verdict.
    match reports.iter().find_map(crate::check::Report::negative) {
        Some(verdict) => Err(verdict.into()),
        None => Ok(()),
    }
}

/// An output that would replace one of the command's own input files is refused (exit 2)
/// before anything is written: `stickslip fit fit/fit.csv` must not overwrite its data.
fn refuse_overwriting_inputs(
    out: &std::path::Path,
    files: &[report::OutFile],
    inputs: &[(&str, &std::path::Path)],
) -> Result<()> {
    for (flag, input) in inputs {
        let Ok(input_meta) = std::fs::metadata(input) else {
            continue;
        };
        for f in files {
            let target = out.join(&f.path);
            if std::fs::metadata(&target).is_ok_and(|m| same_file(&m, &input_meta)) {
                return Err(Error::Output {
                    path: target.display().to_string(),
                    reason: format!(
                        "is the input file {flag} of this command: choose another --out"
                    ),
                }
                .into());
            }
        }
    }
    Ok(())
}

#[cfg(unix)]
fn same_file(a: &std::fs::Metadata, b: &std::fs::Metadata) -> bool {
    use std::os::unix::fs::MetadataExt;
    a.dev() == b.dev() && a.ino() == b.ino()
}

#[cfg(not(unix))]
fn same_file(_a: &std::fs::Metadata, _b: &std::fs::Metadata) -> bool {
    false
}

/// At most one input may be `-` (standard input is read once).
fn one_stdin(inputs: &[(&str, Option<&std::path::Path>)]) -> Result<()> {
    let stdin = std::path::Path::new(crate::params::STDIN);
    let named: Vec<&str> = inputs
        .iter()
        .filter(|(_, p)| *p == Some(stdin))
        .map(|(flag, _)| *flag)
        .collect();
    if named.len() > 1 {
        anyhow::bail!(
            "{}: only one of them can be - (standard input is read once)",
            named.join(" and ")
        );
    }
    Ok(())
}

/// The CSV dialect asked for.
fn dialect(common: &CommonArgs) -> CsvDialect {
    common.csv_dialect.unwrap_or_default()
}

/// A flag that the subcommand does not use is refused rather than silently ignored.
fn reject_flag(command: &str, flag: &str, given: bool) -> Result<()> {
    if given {
        anyhow::bail!("{flag} does not apply to `stickslip {command}`");
    }
    Ok(())
}

/// A path the user gave, for a line on the terminal: control bytes escaped, bounded.
fn shown(path: &std::path::Path) -> String {
    crate::error::excerpt_path(&path.display().to_string())
}

/// Prints to standard output (or the writer that stands for it); a closed pipe (`| head`) is
/// not an error of ours.
fn print_stdout(out: &mut dyn Write, text: &str) -> Result<()> {
    match out.write_all(text.as_bytes()).and_then(|()| out.flush()) {
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => Ok(()),
        other => other.context("writing to standard output"),
    }
}
