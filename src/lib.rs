//! # stickslip
//!
//! Stick-slip models of Moggio, Onorato & Oss (Phys. Educ.): a pulled mass pressed by an
//! oscillating normal force, and the falling woodpecker toy. Every closed form of the paper's
//! linearized (triangle-wave) law is evaluated and checked against an exact, event-driven
//! integration of the same non-smooth equations; the harmonic law is integrated exactly too.
//!
//! ```text
//! params (clap / TOML, validated) → model (forces as data) → engine (exact, events located)
//!        → results (serde) → checks (closed form vs numeric) → output (text, JSON)
//! ```
//!
//! Both models are the same system: one body of mass M with Coulomb friction under a prescribed
//! driving force D(t) and friction-bearing normal force N_f(t) (guide §4). The engine in
//! [`engine`] integrates that system once for any [`engine::ForceLaw`]; a model only builds the
//! force law.
//!
//! The `cli` feature (default) adds the presentation layer: command line, reports, figures,
//! handouts, worksheets, sweeps, fits and benchmarks. Without it the core (params, models,
//! engine, results, claims, solvers, explore) builds on its own, for wasm32 too; there
//! [`wasm`] exports the explorer page's entry points (`stickslip explorer`). The `peers` feature
//! (off by default) adds the benchmark's compiled peer from diffsol; `python` (off by default)
//! the Python module of the wheel ([`python`]).

#[cfg(feature = "cli")]
pub mod bench;
#[cfg(feature = "cli")]
pub mod check;
pub mod claims;
#[cfg(feature = "cli")]
pub mod classroom;
#[cfg(feature = "cli")]
pub mod cli;
#[cfg(feature = "cli")]
pub mod commands;
#[cfg(feature = "cli")]
pub mod console;
#[cfg(feature = "cli")]
pub mod derivation;
pub mod draws;
pub mod engine;
pub mod error;
pub mod explore;
#[cfg(feature = "cli")]
pub mod export;
#[cfg(feature = "cli")]
pub mod fit;
pub mod fmath;
pub mod format;
#[cfg(feature = "cli")]
pub mod handout;
#[cfg(feature = "cli")]
pub mod lang;
pub mod models;
#[cfg(feature = "cli")]
pub mod output;
pub mod params;
#[cfg(feature = "cli")]
pub mod present;
#[cfg(feature = "python")]
pub mod python;
#[cfg(feature = "cli")]
pub mod report;
pub mod results;
#[cfg(feature = "cli")]
pub mod schema;
#[cfg(feature = "cli")]
pub mod shell;
pub mod solver;
#[cfg(feature = "cli")]
pub mod sweep;
#[cfg(target_arch = "wasm32")]
pub mod wasm;
#[cfg(feature = "cli")]
pub mod worksheet;
