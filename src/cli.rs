//! Command-line interface (clap derive). The model subcommands and their parameter flags are
//! made from the model registry ([`crate::models`]); flags override the values of a
//! `--scenario` file, and what neither gives takes the paper's default set.

use std::path::PathBuf;

use std::marker::PhantomData;

use clap::builder::{PossibleValuesParser, TypedValueParser};
use clap::{Arg, ArgAction, ArgMatches, Args, FromArgMatches, Parser, Subcommand};

use crate::export::CsvDialect;
use crate::fit::data::{Columns, Unit};
use crate::fit::FitTracked;
use crate::models::woodpecker::WoodpeckerParams;
use crate::models::{Model, Physics};
use crate::report::Format;
use crate::worksheet::Lang;

/// Stick-slip models of a physics paper: closed forms checked against exact integration.
#[derive(Debug, Parser)]
#[command(name = "stickslip", version, about, long_about = None)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Command,
}

#[derive(Debug, Subcommand)]
pub enum Command {
    /// Evaluate every closed form of a model, check it against the exact integration of the
    /// linearized law, and compare with the harmonic law.
    Eval {
        #[command(subcommand)]
        model: ModelCommand<NoArgs>,
    },
    /// Render the report: the built-in scenes of the paper's figures, or the given scenario
    /// files, as HTML and Markdown.
    Report(ReportArgs),
    /// Evaluate the claims of the paper (guide §11, where the paper is wrong) on the given parameters (the other
    /// model keeps the paper's default set) and on a seeded random sample.
    Claims {
        /// Seed of the random sample.
        #[arg(long, default_value_t = 2017, allow_negative_numbers = true)]
        seed: u64,
        /// Random parameter sets per sampled claim (1 to 1000000).
        #[arg(long, default_value_t = 2000, allow_negative_numbers = true)]
        samples: usize,
        /// The model whose parameters are given; without one, both models at the paper's sets.
        #[command(subcommand)]
        model: Option<ModelCommand<ClaimsArgs>>,
    },
    /// Benchmark every time-stepping method against the exact engine: work-precision sweeps,
    /// where each method fails, and optionally SciPy side by side (written to --out).
    Bench(BenchArgs),
    /// A two-page lecture handout for one scene: the chain of formulas from the equation of
    /// motion to the result with the numbers substituted, figures, the verification table and
    /// the paper's claims (HTML for A4 print, Markdown; --pdf through headless Chromium).
    Handout(HandoutArgs),
    /// Vary one parameter on a uniform grid and integrate both laws at each point: v̄, slips
    /// and sticks per period and the regime (sweep.csv, sweep.svg in --out; without a model,
    /// every model over its own grid, in sweep/MODEL/).
    Sweep {
        /// The model swept; without one, every model that can sweep, at the paper's set over
        /// its own grid (the pulled mass's pull F, the woodpecker's offset z0), written to
        /// sweep/MODEL/.
        #[command(subcommand)]
        model: Option<ModelCommand<SweepArgs>>,
    },
    /// Put your own formula against the exact integration: at the given parameters and on a
    /// seeded sample of the regimes where the quantity is measured (agreement, counterexamples,
    /// where it fails by regime).
    Check {
        #[command(subcommand)]
        model: ModelCommand<CheckArgs>,
    },
    /// Fit the harmonic woodpecker to the tracked positions of a real toy (Figs. 26–27): μd,
    /// z0, d0 (optionally μs, k) by Levenberg–Marquardt, with standard errors, residuals and
    /// the overlay figure (fit.json, fit.csv, fit.svg in --out).
    Fit(FitArgs),
    /// Exercise sheets, one per student with its own parameter set in the requested regime, and
    /// the answer key: every answer worked out from the closed forms and confirmed by the exact
    /// integration (worksheets.*, answer-key.*, answer-key.json in --out).
    Worksheet(WorksheetArgs),
    /// The explorer: one self-contained HTML page (explorer.html in --out) with sliders over
    /// both models, the exact motion of both force laws, every closed form checked live, the
    /// regime map and the apparatus animated; it works offline, from file://.
    Explorer(ExplorerArgs),
    /// Print the completion script of a shell to stdout, e.g. `stickslip completions bash >
    /// ~/.local/share/bash-completion/completions/stickslip`.
    Completions {
        /// The shell.
        #[arg(value_enum)]
        shell: clap_complete::Shell,
    },
    /// Print the man page (roff) to stdout, e.g. `stickslip man > stickslip.1 && man
    /// ./stickslip.1`.
    Man,
}

/// Options of `stickslip explorer`.
#[derive(Debug, Args)]
pub struct ExplorerArgs {
    /// Output folder.
    #[arg(long, short = 'o', default_value = "reports")]
    pub out: PathBuf,
}

/// Options of `stickslip fit`; the woodpecker flags and `--scenario` give the fixed values and
/// the starting values of the free ones.
#[derive(Debug, Args)]
pub struct FitArgs {
    /// Tracked positions: a CSV file with a header row, a time column (s) and a position
    /// column (m, cm or mm); `,` or `;` separated, `#` comments and title lines allowed; rows
    /// with a blank time or position cell are skipped and counted. Exit 3 when the fitted
    /// model does not describe the data (files written, flagged). `-` reads standard input.
    #[arg(value_name = "FILE")]
    pub file: PathBuf,
    /// Time and position columns, each a header name or a 1-based number [default: the first
    /// column, and the column named y, else the second].
    #[arg(long, value_name = "T,Y")]
    pub columns: Option<Columns>,
    /// Unit of the position column [default: the unit the file declares, else m].
    #[arg(long, value_enum)]
    pub units: Option<Unit>,
    /// Parameters to fit, comma-separated; the others keep their given values.
    #[arg(long, value_enum, value_delimiter = ',',
          default_values_t = WoodpeckerParams::DEFAULT_FREE.to_vec())]
    pub free: Vec<<WoodpeckerParams as FitTracked>::Free>,
    /// Output folder (fit.json, fit.csv, fit.svg).
    #[arg(long, short = 'o', default_value = "fit")]
    pub out: PathBuf,
    #[command(flatten)]
    pub model: ModelFlags<WoodpeckerParams>,
}

/// Options of `stickslip worksheet`.
#[derive(Debug, Args)]
pub struct WorksheetArgs {
    /// Model of the exercises.
    #[arg(long, value_parser = model_parser())]
    pub model: Model,
    /// Students, one sheet each (1 to 500).
    #[arg(long, default_value_t = 30, allow_negative_numbers = true,
          value_parser = clap::value_parser!(u32).range(1..=i64::from(crate::worksheet::MAX_STUDENTS)))]
    pub students: u32,
    /// Seed of the parameter draw: the same seed gives the same sheets.
    #[arg(long, default_value_t = 1, allow_negative_numbers = true)]
    pub seed: u64,
    /// Regime of every student's case, or `mixed`: the class drawn across all the model's
    /// regimes, at least ⌊n/r⌋ of the n students in each of its r regimes (the first n mod r
    /// regimes one more), in a seeded shuffled order, with the questions every regime can answer
    /// [default: slip_stick for the pulled mass, double_slip_stick for the woodpecker].
    #[arg(long, value_name = "REGIME")]
    pub regime: Option<String>,
    /// Questions, comma-separated keys [default: every question that the regime allows].
    #[arg(long, value_delimiter = ',', value_name = "KEYS")]
    pub questions: Option<Vec<String>>,
    /// Output folder.
    #[arg(long, short = 'o', default_value = "worksheets")]
    pub out: PathBuf,
    /// Formats, comma-separated (answer-key.json is always written): html, md, moodle (Moodle
    /// XML question bank), gift (Moodle GIFT), qti (QTI 1.2 package for Canvas).
    #[arg(long, value_enum, value_delimiter = ',',
          default_values_t = [SheetFormat::Html, SheetFormat::Md])]
    pub format: Vec<SheetFormat>,
    /// Also print the worksheets and the answer key to worksheets.pdf and answer-key.pdf (A4,
    /// one student per page; above 100 students one pair per 100, answer-key-001-100.pdf …)
    /// with headless Chromium ($STICKSLIP_CHROMIUM, else Chromium, Chrome or Edge on PATH or
    /// in their install folders).
    #[arg(long)]
    pub pdf: bool,
    /// Language of the worksheets, answer keys and question banks (words and decimal sign).
    #[arg(long, value_enum, default_value_t = Lang::En)]
    pub lang: Lang,
}

/// What `stickslip worksheet` writes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum SheetFormat {
    /// worksheets.html and answer-key.html.
    Html,
    /// worksheets.md and answer-key.md, figures as SVG files.
    Md,
    /// worksheets.moodle.xml: a Moodle question bank, one category per question.
    Moodle,
    /// worksheets.gift.txt: the same in Moodle's GIFT format (without the figure question).
    Gift,
    /// worksheets.qti.zip: the same as a QTI 1.2 package for Canvas, one question group per
    /// question.
    Qti,
}

impl SheetFormat {
    /// The report format of a page format.
    pub fn page(self) -> Option<Format> {
        match self {
            SheetFormat::Html => Some(Format::Html),
            SheetFormat::Md => Some(Format::Md),
            SheetFormat::Moodle | SheetFormat::Gift | SheetFormat::Qti => None,
        }
    }
}

/// The grid of `stickslip sweep`.
#[derive(Debug, Args)]
pub struct SweepArgs {
    /// Parameter to vary: a numeric parameter of the model (e.g. z0, mu_d, k).
    #[arg(long, value_name = "NAME")]
    pub param: String,
    /// First grid value (SI units, as the model flag).
    #[arg(long, allow_hyphen_values = true, value_name = "A")]
    pub from: f64,
    /// Last grid value (SI units, as the model flag).
    #[arg(long, allow_hyphen_values = true, value_name = "B")]
    pub to: f64,
    /// Grid points, both ends included (2 to 100000).
    #[arg(long, value_name = "N", allow_negative_numbers = true,
          value_parser = clap::value_parser!(u32).range(2..=100_000))]
    pub steps: u32,
    /// Output folder (sweep.csv, sweep.svg).
    #[arg(long, short = 'o', default_value = "sweep")]
    pub out: PathBuf,
}

/// The formula and sample of `stickslip check`.
#[derive(Debug, Args)]
pub struct CheckArgs {
    /// The formula, plain (`g*T*phi^3*Gamma`), LaTeX (`g T \varphi^3 \Gamma`) or pasted
    /// Unicode (`g T φ³ Γ`), in the model's parameters and derived symbols (an unknown symbol
    /// names the nearest known ones); optionally with the quantity on the left (`v_avg = …`).
    /// Precedence is the mathematical one (−x² = −(x²)); the output starts with how it was
    /// read. Exit 0 when it agrees on every compared set, 3 when it disagrees or nothing could
    /// be compared, 2 on bad input.
    #[arg(
        value_name = "FORMULA",
        allow_hyphen_values = true,
        required_unless_present_any = ["formulas", "symbols"]
    )]
    pub formula: Option<String>,
    /// The measured quantity it gives: a closed-form key of the model's `eval --json`
    /// (guide §14; t_slip, t_stick, v_avg …; an unknown name lists the model's keys), or
    /// `sticks` for a condition; not needed when the formula's left side names it.
    #[arg(long, value_name = "NAME")]
    pub quantity: Option<String>,
    /// Only sets of this closed-form regime (the regime a formula is stated for, e.g.
    /// slip_stick for the paper's (18) and (27)) [default: every regime].
    #[arg(long, value_name = "ID")]
    pub regime: Option<String>,
    /// Several formulas from a TOML file: `[[check]]` tables with `formula`, `quantity` and
    /// optionally `regime` (`-`: standard input).
    #[arg(long, value_name = "FILE", conflicts_with_all = ["formula", "quantity"])]
    pub formulas: Option<PathBuf>,
    /// Parameter sets drawn (1 to 100000).
    #[arg(long, default_value_t = crate::check::DEFAULT_SAMPLES, allow_negative_numbers = true)]
    pub samples: usize,
    /// Seed of the draw.
    #[arg(long, default_value_t = 1, allow_negative_numbers = true)]
    pub seed: u64,
    /// List the symbols a formula may use, with their values at the given parameters, and exit.
    #[arg(long, conflicts_with_all = ["formula", "formulas"])]
    pub symbols: bool,
    /// Also write the report as a page (check.html, check.md) and check.json to this folder.
    #[arg(long, short = 'o', value_name = "DIR")]
    pub out: Option<PathBuf>,
}

/// Options of `stickslip bench`.
#[derive(Debug, Args)]
pub struct BenchArgs {
    /// Output folder (index.html, bench.md, figures/, results.json, results.csv).
    #[arg(long, short = 'o', default_value = "reports/bench")]
    pub out: PathBuf,
    /// Reduced sweep: three settings per method, one timed run (for tests).
    #[arg(long)]
    pub quick: bool,
    /// Run a peer on the same problems and compare times at equal error.
    #[arg(long, value_enum)]
    pub peer: Option<crate::bench::PeerChoice>,
    /// Timed runs per setting, after one warm-up (1 to 1000).
    #[arg(long, default_value_t = crate::bench::DEFAULT_REPEATS, allow_negative_numbers = true,
          value_parser = clap::value_parser!(u32).range(1..=1000))]
    pub repeats: u32,
}

/// Options of `stickslip report`.
#[derive(Debug, Args)]
pub struct ReportArgs {
    /// Scenario files (TOML) to render, one scene each [default: the built-in scenes].
    #[arg(value_name = "SCENARIO")]
    pub scenarios: Vec<PathBuf>,
    /// Output folder.
    #[arg(long, short = 'o', default_value = "reports")]
    pub out: PathBuf,
    /// Formats, comma-separated.
    #[arg(long, value_enum, value_delimiter = ',', default_values_t = [Format::Html, Format::Md])]
    pub format: Vec<Format>,
}

/// Options of `stickslip handout`.
#[derive(Debug, Args)]
pub struct HandoutArgs {
    /// A built-in scene id (see --list) or a scenario file (TOML).
    #[arg(value_name = "SCENE", required_unless_present = "list")]
    pub scene: Option<String>,
    /// Print the built-in scene ids with their captions and exit.
    #[arg(long, conflicts_with_all = ["scene", "pdf"])]
    pub list: bool,
    /// Output folder.
    #[arg(long, short = 'o', default_value = "handouts")]
    pub out: PathBuf,
    /// Also print the HTML to <SCENE>.pdf with headless Chromium ($STICKSLIP_CHROMIUM, else
    /// Chromium, Chrome or Edge on PATH or in their install folders).
    #[arg(long)]
    pub pdf: bool,
    /// Formats, comma-separated.
    #[arg(long, value_enum, value_delimiter = ',', default_values_t = [Format::Html, Format::Md])]
    pub format: Vec<Format>,
    /// Language of the handout (words, figure labels and decimal sign).
    #[arg(long, value_enum, default_value_t = Lang::En)]
    pub lang: Lang,
}

/// Options shared by every model.
#[derive(Clone, Debug, Args)]
pub struct CommonArgs {
    /// Scenario file (TOML) with the parameters (`-`: standard input); flags given as well
    /// override it.
    #[arg(long, value_name = "FILE")]
    pub scenario: Option<PathBuf>,
    /// Periods to integrate (1 to 1000000) [default: 8, or the scenario's].
    #[arg(long, allow_hyphen_values = true)]
    pub periods: Option<i64>,
    /// Print the evaluation as one JSON object (machine-readable) instead of tables.
    #[arg(long)]
    pub json: bool,
    /// Also write the time series and event lists of both laws as CSV files to this folder
    /// (`eval` only).
    #[arg(long, value_name = "DIR")]
    pub csv: Option<PathBuf>,
    /// How CSV files write numbers (`eval --csv`, `sweep`, `fit`) [default: standard].
    #[arg(long, value_enum, value_name = "DIALECT")]
    pub csv_dialect: Option<CsvDialect>,
}

/// A subcommand without options of its own.
#[derive(Clone, Debug, Args)]
pub struct NoArgs {}

/// `claims`: no options of its own beside the model's (its seed and sample come before the model).
#[derive(Clone, Debug, Args)]
pub struct ClaimsArgs {}

/// The shared options (ids of [`CommonArgs`]) a command refuses: hidden from its `--help`, so
/// that the help lists only what the command takes (the command still says why it refuses one).
pub trait Refuses {
    const REFUSED: &'static [&'static str] = &[];
}

impl Refuses for NoArgs {}
impl Refuses for ClaimsArgs {
    const REFUSED: &'static [&'static str] = &["csv", "csv_dialect"];
}
impl Refuses for SweepArgs {
    const REFUSED: &'static [&'static str] = &["json", "csv"];
}
impl Refuses for CheckArgs {
    const REFUSED: &'static [&'static str] = &["csv", "csv_dialect", "periods"];
}

/// `cmd` with the shared options `refused` hidden from its help.
fn hide(cmd: clap::Command, refused: &[&str]) -> clap::Command {
    refused
        .iter()
        .fold(cmd, |cmd, id| cmd.mut_arg(*id, |a| a.hide(true)))
}

/// The parameter flags of a model as given on the command line, and the shared options. The
/// flags are made from the model's parameter descriptors; [`crate::commands::model_params`]
/// applies them over the scenario and the defaults.
#[derive(Clone, Debug)]
pub struct ModelArgs {
    /// The model, with its default parameters.
    pub model: Model,
    pub common: CommonArgs,
    /// The numeric parameters given, by key.
    pub numbers: Vec<(&'static str, f64)>,
    /// The options given, by key.
    pub choices: Vec<(&'static str, String)>,
}

impl ModelArgs {
    /// The model's flags and the shared options, added to `cmd`.
    fn augment(model: &Model, cmd: clap::Command) -> clap::Command {
        let flags = model.flags().into_iter().map(|f| {
            let arg = Arg::new(f.key)
                .long(f.key.replace('_', "-"))
                .value_name(f.key.to_uppercase())
                .help(f.help)
                .action(ArgAction::Set);
            match f.values {
                None => arg
                    .allow_hyphen_values(true)
                    .value_parser(clap::value_parser!(f64)),
                Some(values) => arg.value_parser(PossibleValuesParser::new(values)),
            }
        });
        CommonArgs::augment_args(cmd.args(flags))
    }

    /// The flags given for `model`.
    fn from_matches(model: Model, m: &ArgMatches) -> Result<Self, clap::Error> {
        let mut args = Self {
            model,
            common: CommonArgs::from_arg_matches(m)?,
            numbers: Vec::new(),
            choices: Vec::new(),
        };
        for flag in model.flags() {
            match flag.values {
                None => {
                    if let Some(v) = m.get_one::<f64>(flag.key) {
                        args.numbers.push((flag.key, *v));
                    }
                }
                Some(_) => {
                    if let Some(v) = m.get_one::<String>(flag.key) {
                        args.choices.push((flag.key, v.clone()));
                    }
                }
            }
        }
        Ok(args)
    }
}

/// The flags of one model, flattened into a command that is about that model (`fit`).
#[derive(Clone, Debug)]
pub struct ModelFlags<M> {
    pub args: ModelArgs,
    model: PhantomData<M>,
}

impl<M: Physics> FromArgMatches for ModelFlags<M> {
    fn from_arg_matches(m: &ArgMatches) -> Result<Self, clap::Error> {
        Ok(Self {
            args: ModelArgs::from_matches(M::default().into_model(), m)?,
            model: PhantomData,
        })
    }

    fn update_from_arg_matches(&mut self, m: &ArgMatches) -> Result<(), clap::Error> {
        *self = Self::from_arg_matches(m)?;
        Ok(())
    }
}

impl<M: Physics> Args for ModelFlags<M> {
    fn augment_args(cmd: clap::Command) -> clap::Command {
        // `fit` refuses --periods and --csv (its integration spans the tracked data).
        hide(
            ModelArgs::augment(&M::default().into_model(), cmd),
            &["periods", "csv"],
        )
    }

    fn augment_args_for_update(cmd: clap::Command) -> clap::Command {
        Self::augment_args(cmd)
    }
}

/// One subcommand per registered model (`eval pulled-mass`, `sweep woodpecker`), each with the
/// model's flags, the shared options and the options `X` of the command.
#[derive(Clone, Debug)]
pub struct ModelCommand<X> {
    pub args: ModelArgs,
    pub extra: X,
}

impl<X: FromArgMatches> FromArgMatches for ModelCommand<X> {
    fn from_arg_matches(m: &ArgMatches) -> Result<Self, clap::Error> {
        let Some((id, sub)) = m.subcommand() else {
            return Err(clap::Error::new(clap::error::ErrorKind::MissingSubcommand));
        };
        let model = Model::from_id(id)
            .ok_or_else(|| clap::Error::new(clap::error::ErrorKind::InvalidSubcommand))?;
        Ok(Self {
            args: ModelArgs::from_matches(model, sub)?,
            extra: X::from_arg_matches(sub)?,
        })
    }

    fn update_from_arg_matches(&mut self, m: &ArgMatches) -> Result<(), clap::Error> {
        *self = Self::from_arg_matches(m)?;
        Ok(())
    }
}

impl<X: Args + Refuses> Subcommand for ModelCommand<X> {
    fn augment_subcommands(cmd: clap::Command) -> clap::Command {
        Model::defaults().iter().fold(cmd, |cmd, model| {
            let sub = ModelArgs::augment(model, clap::Command::new(model.id()));
            // The model's line, not the doc of `X`, is the subcommand's about.
            cmd.subcommand(hide(X::augment_args(sub), X::REFUSED).about(model.about()))
        })
    }

    fn augment_subcommands_for_update(cmd: clap::Command) -> clap::Command {
        Self::augment_subcommands(cmd)
    }

    fn has_subcommand(name: &str) -> bool {
        Model::from_id(name).is_some()
    }
}

/// `--model`: a registered model id.
fn model_parser() -> impl TypedValueParser<Value = Model> {
    PossibleValuesParser::new(Model::ids())
        .map(|id| Model::from_id(&id).unwrap_or_else(|| Model::defaults()[0]))
}
