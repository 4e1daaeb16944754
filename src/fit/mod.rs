//! `stickslip fit`: a model fitted to the tracked positions of a real apparatus, the optional
//! capability [`Capability::Fit`] of a model. What names no model lives here; the fit itself
//! (its model function, free parameters, search, synthetic example and outputs) lives in the
//! folder of the model that offers it (the harmonic woodpecker's: `models/woodpecker/fit/`).
//!
//! ```text
//! data     (t_i, y_i), i = 1..n, read from a tracking app's CSV (m, cm, mm)      data.rs
//! verdict  is the residual the noise? if not, is the position unit slipped?       verdict.rs
//! model    FitTracked: the model's fit of the data, from a base parameter set and
//!          the free parameters, and its outputs (files, JSON, terminal text)      this file
//! ```

pub mod data;
pub mod verdict;

use std::path::Path;

use serde::Serialize;

use crate::error::{Error, Result};
use crate::models::{with_capability, Capability, Model, Physics};
use crate::report::OutFile;
pub use data::Tracked;
pub use verdict::{ScaleSlip, Verdict};

/// A model's fit of tracked data ([`Capability::Fit`]), implemented by its params struct in its
/// folder: the params are the given values (fixed ones, and the start of the free ones).
pub trait FitTracked: Physics {
    /// A parameter the fit may adjust, named on the command line (`--free`).
    type Free: Copy + clap::ValueEnum;
    /// The parameters fitted unless asked otherwise (the default of `--free`).
    const DEFAULT_FREE: &'static [Self::Free];
    /// The outcome, written as fit.json (SI units) and printed by `fit --json`; its JSON Schema
    /// is reports/schema/'s.
    type Outcome: Serialize + schemars::JsonSchema;

    /// Fits the `free` parameters of `self` (validated) to `data`. A fit that does not converge
    /// or does not describe the data is an outcome, flagged ([`FitTracked::fitted`]).
    fn fit_tracked(&self, data: &Tracked, free: &[Self::Free]) -> Result<Self::Outcome>;

    /// The outputs of `outcome`, whose files go to the folder `out`.
    fn fitted(outcome: &Self::Outcome, out: &Path) -> Result<Fitted>;
}

/// The outputs of a fit, whatever the model.
#[derive(Clone, Debug, PartialEq)]
pub struct Fitted {
    /// fit.json and the model's other files (fit.csv, fit.svg), relative to `out`.
    pub files: Vec<OutFile>,
    /// What `fit --json` prints (fit.json's text, with a final newline).
    pub json: String,
    /// The terminal summary.
    pub text: String,
    /// Whether the search converged, and how it ended.
    pub converged: bool,
    pub termination: String,
    /// `None` when the fitted model describes the data, else the verdict in brief.
    pub misfit: Option<String>,
}

/// Fits `model` (the given values) to `data`, the parameters named `free` (`--free`) free, and
/// renders the outputs for the folder `out`. A model without [`Capability::Fit`] is refused
/// ([`Model::missing`]), as is a name that is not one of its free parameters.
pub fn fit(model: &Model, data: &Tracked, free: &[&str], out: &Path) -> Result<Fitted> {
    fn run<M: FitTracked>(p: &M, data: &Tracked, free: &[&str], out: &Path) -> Result<Fitted> {
        let free = free
            .iter()
            .map(|name| {
                <M::Free as clap::ValueEnum>::from_str(name, false).map_err(|_| {
                    Error::InvalidParam {
                        name: "free",
                        value: name.to_string(),
                        rule: format!(
                            "one of {} (the parameters the fit of the {} model adjusts)",
                            free_names::<M>().join(", "),
                            M::ID
                        ),
                    }
                })
            })
            .collect::<Result<Vec<_>>>()?;
        M::fitted(&p.fit_tracked(data, &free)?, out)
    }
    with_capability!(model, fit, p => run(p, data, free, out),
        else Err(model.missing(Capability::Fit)))
}

/// The names of the parameters the fit of `M` may adjust, as `--free` takes them.
fn free_names<M: FitTracked>() -> Vec<String> {
    <M::Free as clap::ValueEnum>::value_variants()
        .iter()
        .filter_map(clap::ValueEnum::to_possible_value)
        .map(|v| v.get_name().to_string())
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Twelve rows of a falling toy (m): enough for a fit to read.
    fn example() -> Tracked {
        let rows: String = (0..12)
            .map(|i| format!("{},{}\n", f64::from(i) * 0.01, 0.1 + f64::from(i) * 0.01))
            .collect();
        let text = format!("t,y\n{rows}");
        data::parse(&text, Path::new("toy.csv"), &data::ReadOptions::default()).unwrap()
    }

    #[test]
    fn a_model_without_the_capability_is_refused_with_the_one_line_message() {
        for model in Model::defaults()
            .into_iter()
            .filter(|m| !m.has(Capability::Fit))
        {
            let e = fit(&model, &example(), &[], Path::new("fit")).unwrap_err();
            assert_eq!(e, model.missing(Capability::Fit));
            assert_eq!(
                e.to_string(),
                format!("the {} model has no fit of tracked data", model.id())
            );
            assert_eq!(e.exit_code(), 2);
        }
    }

    #[test]
    fn a_free_name_the_model_does_not_adjust_is_refused_naming_the_valid_ones() {
        let model = Model::offering(Capability::Fit)[0];
        let e = fit(&model, &example(), &["bogus"], Path::new("fit")).unwrap_err();
        assert!(
            e.to_string()
                .starts_with("invalid parameter free = bogus: must satisfy one of "),
            "{e}"
        );
        assert_eq!(e.exit_code(), 2);
    }
}
