//! Command-line interface (clap derive). Flags override the values of a `--scenario` file;
//! what neither gives takes the paper's default set.

use std::path::PathBuf;

use clap::{Args, Parser, Subcommand};

use crate::fit::data::{Columns, Unit};
use crate::fit::FitParam;
use crate::models::woodpecker::formula::Counterpart;
use crate::params::{ModelName, OmegaMode};
use crate::report::Format;

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
        model: EvalModel,
    },
    /// Render the report: the built-in scenes of the paper's figures, or the given scenario
    /// files, as HTML and Markdown.
    Report(ReportArgs),
    /// Evaluate the claims of the paper (physics.md §6) on the given parameters (the other
    /// model keeps the paper's default set) and on a seeded random sample.
    Claims {
        /// Seed of the random sample.
        #[arg(long, default_value_t = 2017)]
        seed: u64,
        /// Random parameter sets per sampled claim (1 to 1000000).
        #[arg(long, default_value_t = 2000)]
        samples: usize,
        #[command(subcommand)]
        model: EvalModel,
    },
    /// Benchmark every time-stepping method against the exact engine: work-precision sweeps,
    /// where each method fails, and optionally SciPy side by side (written to --out).
    Bench(BenchArgs),
    /// A two-page lecture handout for one scene: the chain of formulas from the equation of
    /// motion to the result with the numbers substituted, figures, the verification table and
    /// the paper's claims (HTML for A4 print, Markdown; --pdf through headless Chromium).
    Handout(HandoutArgs),
    /// Vary one parameter on a uniform grid and integrate both laws at each point: v̄, slips
    /// and sticks per period and the regime (sweep.csv, sweep.svg in --out).
    Sweep {
        #[command(subcommand)]
        model: SweepModel,
    },
    /// Fit the harmonic woodpecker to the tracked positions of a real toy (Figs. 26–27): μd,
    /// z0, d0 (optionally μs, k) by Levenberg–Marquardt, with standard errors, residuals and
    /// the overlay figure (fit.json, fit.csv, fit.svg in --out).
    Fit(FitArgs),
    /// Exercise sheets, one per student with its own parameter set in the requested regime, and
    /// the answer key: every answer worked out from the closed forms and confirmed by the exact
    /// integration (worksheets.*, answer-key.*, answer-key.json in --out).
    Worksheet(WorksheetArgs),
}

/// Options of `stickslip fit`; the woodpecker flags and `--scenario` give the fixed values and
/// the starting values of the free ones.
#[derive(Debug, Args)]
pub struct FitArgs {
    /// Tracked positions: a CSV file with a header row, a time column (s) and a position
    /// column (m or mm); `,` or `;` separated, `#` comments and title lines allowed.
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
    #[arg(long, value_enum, value_delimiter = ',', default_values_t = FitParam::DEFAULT)]
    pub free: Vec<FitParam>,
    /// Output folder (fit.json, fit.csv, fit.svg).
    #[arg(long, default_value = "fit")]
    pub out: PathBuf,
    #[command(flatten)]
    pub model: WoodpeckerArgs,
}

/// Options of `stickslip worksheet`.
#[derive(Debug, Args)]
pub struct WorksheetArgs {
    /// Model of the exercises.
    #[arg(long, value_enum)]
    pub model: ModelName,
    /// Students, one sheet each (1 to 500).
    #[arg(long, default_value_t = 30,
          value_parser = clap::value_parser!(u32).range(1..=i64::from(crate::worksheet::MAX_STUDENTS)))]
    pub students: u32,
    /// Seed of the parameter draw: the same seed gives the same sheets.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Regime of every student's case [default: slip_stick for the pulled mass,
    /// double_slip_stick for the woodpecker].
    #[arg(long, value_name = "REGIME")]
    pub regime: Option<String>,
    /// Questions, comma-separated keys [default: every question that the regime allows].
    #[arg(long, value_delimiter = ',', value_name = "KEYS")]
    pub questions: Option<Vec<String>>,
    /// Output folder.
    #[arg(long, default_value = "worksheets")]
    pub out: PathBuf,
    /// Formats, comma-separated (answer-key.json is always written).
    #[arg(long, value_enum, value_delimiter = ',', default_values_t = [Format::Html, Format::Md])]
    pub format: Vec<Format>,
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
    #[arg(long, value_name = "N",
          value_parser = clap::value_parser!(u32).range(2..=100_000))]
    pub steps: u32,
    /// Output folder (sweep.csv, sweep.svg).
    #[arg(long, default_value = "sweep")]
    pub out: PathBuf,
}

#[derive(Debug, Subcommand)]
pub enum SweepModel {
    /// Sweep a parameter of the pulled mass.
    PulledMass {
        #[command(flatten)]
        sweep: SweepArgs,
        #[command(flatten)]
        model: PulledMassArgs,
    },
    /// Sweep a parameter of the woodpecker.
    Woodpecker {
        #[command(flatten)]
        sweep: SweepArgs,
        #[command(flatten)]
        model: WoodpeckerArgs,
    },
}

/// Options of `stickslip bench`.
#[derive(Debug, Args)]
pub struct BenchArgs {
    /// Output folder (index.html, bench.md, figures/, results.json, results.csv).
    #[arg(long, default_value = "reports/bench")]
    pub out: PathBuf,
    /// Reduced sweep: three settings per method, one timed run (for tests).
    #[arg(long)]
    pub quick: bool,
    /// Run a peer on the same problems and compare times at equal error.
    #[arg(long, value_enum)]
    pub peer: Option<crate::bench::PeerChoice>,
    /// Timed runs per setting, after one warm-up (1 to 1000).
    #[arg(long, default_value_t = crate::bench::DEFAULT_REPEATS,
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
    #[arg(long, default_value = "reports")]
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
    #[arg(long, default_value = "handouts")]
    pub out: PathBuf,
    /// Also print the HTML to <SCENE>.pdf with headless Chromium ($STICKSLIP_CHROMIUM, else
    /// chromium, chromium-browser or google-chrome on PATH).
    #[arg(long)]
    pub pdf: bool,
    /// Formats, comma-separated.
    #[arg(long, value_enum, value_delimiter = ',', default_values_t = [Format::Html, Format::Md])]
    pub format: Vec<Format>,
}

#[derive(Debug, Subcommand)]
pub enum EvalModel {
    /// The pulled mass pressed by an oscillating normal force (paper Sec. 2).
    PulledMass(PulledMassArgs),
    /// The falling woodpecker toy: the sleeve on the pole (paper Sec. 3).
    Woodpecker(WoodpeckerArgs),
}

/// Options shared by every model.
#[derive(Debug, Args)]
pub struct CommonArgs {
    /// Scenario file (TOML) with the parameters; flags given as well override it.
    #[arg(long, value_name = "FILE")]
    pub scenario: Option<PathBuf>,
    /// Periods to integrate (1 to 1000000) [default: 8, or the scenario's].
    #[arg(long, allow_hyphen_values = true)]
    pub periods: Option<i64>,
    /// Print the JSON object of physics.md §7 instead of tables.
    #[arg(long)]
    pub json: bool,
    /// Also write the time series and event lists of both laws as CSV files to this folder
    /// (`eval` only).
    #[arg(long, value_name = "DIR")]
    pub csv: Option<PathBuf>,
}

/// Parameters of the pulled mass [defaults: the paper's Fig. 6 set].
#[derive(Debug, Args)]
pub struct PulledMassArgs {
    #[command(flatten)]
    pub common: CommonArgs,
    /// Static friction coefficient μs [default: 0.4].
    #[arg(long, allow_hyphen_values = true)]
    pub mu_s: Option<f64>,
    /// Dynamic friction coefficient μd, 0 < μd ≤ μs [default: 0.25].
    #[arg(long, allow_hyphen_values = true)]
    pub mu_d: Option<f64>,
    /// Mass m of the block in kg (the hanging mass is equal) [default: 0.06].
    #[arg(long, allow_hyphen_values = true)]
    pub mass: Option<f64>,
    /// Spring constant k in N/m [default: 45].
    #[arg(long, allow_hyphen_values = true)]
    pub k: Option<f64>,
    /// Pulling force F in N [default: 0.18].
    #[arg(long, allow_hyphen_values = true)]
    pub force: Option<f64>,
    /// Gravitational acceleration g in m/s² [default: 9.81].
    #[arg(long, allow_hyphen_values = true)]
    pub g: Option<f64>,
}

/// Parameters of the woodpecker [defaults: the paper's Fig. 15 set].
#[derive(Debug, Args)]
pub struct WoodpeckerArgs {
    #[command(flatten)]
    pub common: CommonArgs,
    /// Static friction coefficient μs [default: 0.65].
    #[arg(long, allow_hyphen_values = true)]
    pub mu_s: Option<f64>,
    /// Dynamic friction coefficient μd, 0 < μd ≤ μs [default: 0.32].
    #[arg(long, allow_hyphen_values = true)]
    pub mu_d: Option<f64>,
    /// Spring constant k in N/m [default: 20].
    #[arg(long, allow_hyphen_values = true)]
    pub k: Option<f64>,
    /// Sleeve mass m_S in kg [default: 0.006].
    #[arg(long, allow_hyphen_values = true)]
    pub m_sleeve: Option<f64>,
    /// Woodpecker (bird) mass m_W in kg [default: 0.014].
    #[arg(long, allow_hyphen_values = true)]
    pub m_bird: Option<f64>,
    /// Lever arm l of the spring force in m [default: 0.016].
    #[arg(long, allow_hyphen_values = true)]
    pub l: Option<f64>,
    /// Distance h between the two pole contacts in m [default: 0.007].
    #[arg(long, allow_hyphen_values = true)]
    pub h: Option<f64>,
    /// Spring offset z0 in m [default: 0.007].
    #[arg(long, allow_hyphen_values = true)]
    pub z0: Option<f64>,
    /// Spring oscillation amplitude d0 in m [default: 0.009].
    #[arg(long, allow_hyphen_values = true)]
    pub d0: Option<f64>,
    /// Gravitational acceleration g in m/s² [default: 9.81].
    #[arg(long, allow_hyphen_values = true)]
    pub g: Option<f64>,
    /// Lever ratio λ (each contact carries λ|F_e|) [default: l/h].
    #[arg(long, allow_hyphen_values = true)]
    pub lever: Option<f64>,
    /// Definition of ω [default: bird].
    #[arg(long, value_enum)]
    pub omega: Option<OmegaMode>,
    /// Linear counterpart of the harmonic spring coordinate [default: zeros].
    #[arg(long, value_enum)]
    pub counterpart: Option<Counterpart>,
}
