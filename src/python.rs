//! The Python module `stickslip._native` (feature `python`, built by maturin from
//! `pyproject.toml`; the package around it is `python/stickslip/`). Three doors, each thin:
//!
//! ```text
//! run(argv)            the command line on the process's own streams → exit code
//!                      (the `stickslip` console script of the wheel)
//! call(argv)           the command line with its output captured → (code, stdout, stderr)
//!                      (check, claims, sweep, fit, worksheet, handout, report in Python)
//! evaluate(setup, n)   one parameter set (explore::Setup as JSON) over n periods → the guide §14 JSON
//!                      of `eval --json`, the regime in words and the CSV files of `eval --csv`
//! figure(setup)        the model's standard motion figure (SVG) for the rich display
//! quantities(model)    the registry of closed forms: symbol, unit, equation, MathML
//! law_regimes()        the integration regimes of the laws in words
//! ```
//!
//! A refusal raises the exception that `stickslip.errors.error_for(code, message)` makes of the
//! exit code and the one-line message the command line would print (without its "error: "
//! label). Every call runs without the GIL, one at a time (the hints of a run are process-wide).

use std::sync::Mutex;

use pyo3::prelude::*;

use crate::console::{run_args, Streams};
use crate::error::{Error, Result};
use crate::explore::{parse, Explore, Setup};
use crate::export::CsvDialect;
use crate::models::param::invalid;
use crate::models::with_capability;
use crate::present::Present;
use crate::report::figures::{chart, map};
use crate::report::math::mathml;
use crate::report::scene::Drawing;

/// One command line at a time: the hints of a run are gathered process-wide.
static ONE_AT_A_TIME: Mutex<()> = Mutex::new(());

/// The Python exception of a refusal: `stickslip.errors.error_for(exit code, message)`.
fn refusal(py: Python<'_>, e: &Error) -> PyErr {
    let message = crate::error::excerpt(&e.to_string(), 300);
    let made = py
        .import("stickslip.errors")
        .and_then(|m| m.getattr("error_for"))
        .and_then(|f| f.call1((e.exit_code(), message)));
    match made {
        Ok(exception) => PyErr::from_value(exception),
        Err(import_failed) => import_failed,
    }
}

/// The command line `argv` (without the program name) on the process's stdout and stderr;
/// returns the exit code.
#[pyfunction]
fn run(py: Python<'_>, argv: Vec<String>) -> u8 {
    py.detach(|| {
        let _turn = ONE_AT_A_TIME
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner);
        let (mut out, mut err) = (std::io::stdout(), std::io::stderr());
        run_args(
            program(argv),
            Streams {
                out: &mut out,
                err: &mut err,
                process: true,
            },
        )
    })
}

/// The command line `argv` (without the program name) with its output captured: (exit code,
/// stdout, stderr).
#[pyfunction]
fn call(py: Python<'_>, argv: Vec<String>) -> (u8, String, String) {
    py.detach(|| {
        let _turn = ONE_AT_A_TIME
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner);
        let (mut out, mut err) = (Vec::new(), Vec::new());
        let code = run_args(
            program(argv),
            Streams {
                out: &mut out,
                err: &mut err,
                process: false,
            },
        );
        let text = |b: Vec<u8>| String::from_utf8_lossy(&b).into_owned();
        (code, text(out), text(err))
    })
}

fn program(argv: Vec<String>) -> impl Iterator<Item = String> {
    std::iter::once("stickslip".to_string()).chain(argv)
}

/// What [`evaluate`] returns: the guide §14 JSON, the extras JSON (regime in words, applicability),
/// the CSV files of `eval --csv` as (name, text) and the model's laws as (id in the CSV names,
/// name, key of its summary in the JSON).
type Evaluated = (
    String,
    String,
    Vec<(String, String)>,
    Vec<(&'static str, &'static str, &'static str)>,
);

/// One parameter set (`setup`: the JSON of [`Setup`]) over `periods` periods (`None`: 8, as
/// `stickslip eval`), as `stickslip eval MODEL … --json --csv DIR` computes it.
#[pyfunction]
#[pyo3(signature = (setup, periods=None))]
fn evaluate(py: Python<'_>, setup: String, periods: Option<i64>) -> PyResult<Evaluated> {
    py.detach(|| evaluated(&setup, periods))
        .map_err(|e| refusal(py, &e))
}

fn evaluated(setup: &str, periods: Option<i64>) -> Result<Evaluated> {
    let model = parse::<Setup>(setup.as_bytes())?.model()?;
    let periods = match periods {
        None => crate::params::DEFAULT_PERIODS,
        Some(n) => u32::try_from(n).map_err(|_| {
            invalid(
                "periods",
                n,
                format!("1 <= periods <= {}", crate::params::MAX_PERIODS),
            )
        })?,
    };
    with_capability!(&model, present, p => evaluated_model(p, periods),
    else Err(Error::Unsupported {
        model: model.id(),
        what: "the Python evaluation (series and display) yet: use stickslip.cli(['eval', …, '--json'])"
            .to_string(),
    }))
}

/// The evaluation with what the package needs to read it for any model: its laws by name.
fn evaluated_model<M: Explore + Present>(p: &M, periods: u32) -> Result<Evaluated> {
    let laws = <M as Present>::LAWS
        .iter()
        .map(|l| (l.id, l.name, l.summary))
        .collect();
    let json = |e: serde_json::Error| Error::InvalidLaw(e.to_string());
    let (evaluation, files) = p.evaluate_with_csv(periods)?;
    let extras = crate::explore::Extras {
        closed_form: M::regime(&evaluation),
        applicability: M::applicability(&evaluation),
        period: p.period(),
        periods,
    };
    let files = CsvDialect::default()
        .apply(files)
        .into_iter()
        .map(|f| {
            let text = String::from_utf8_lossy(&f.bytes).into_owned();
            (f.path.display().to_string(), text)
        })
        .collect();
    Ok((
        serde_json::to_string_pretty(&crate::results::Versioned::new(&evaluation)).map_err(json)?,
        serde_json::to_string(&extras).map_err(json)?,
        files,
        laws,
    ))
}

/// The model's standard motion figure for the parameter set `setup` (SVG), as the report draws
/// it: position and speed against time under both laws, with the characteristic times.
#[pyfunction]
fn figure(py: Python<'_>, setup: String) -> PyResult<String> {
    py.detach(|| figure_svg(&setup))
        .map_err(|e| refusal(py, &e))
}

fn figure_svg(setup: &str) -> Result<String> {
    let model = parse::<Setup>(setup.as_bytes())?.model()?;
    model.validate()?;
    let figures = with_capability!(&model, present, p => {
        let kind = p.standard_scene().figures[0];
        p.figures_of("python", kind)?
    }, else return Err(Error::Unsupported {
        model: model.id(),
        what: "figures yet".to_string(),
    }));
    let Some(first) = figures.first() else {
        return Ok(String::new());
    };
    let svg = match &first.drawing {
        Drawing::Chart(c) => chart::line_chart(c),
        Drawing::Map(m) => map::category_map(m),
    };
    svg.map_err(|e| Error::Figure {
        id: first.id.clone(),
        reason: e.to_string(),
    })
}

/// A closed form of the registry for the rich display: (JSON key (guide §14), plain symbol, unit, equation,
/// symbol in MathML, formula in MathML, formula in LaTeX, meaning).
type QuantityRow = (
    &'static str,
    &'static str,
    &'static str,
    &'static str,
    String,
    String,
    &'static str,
    &'static str,
);

/// The closed forms of the model `model` ("pulled-mass", "woodpecker"), in the registry's order.
#[pyfunction]
fn quantities(py: Python<'_>, model: String) -> PyResult<Vec<QuantityRow>> {
    let setup = Setup {
        model,
        ..Setup::default()
    };
    let model = setup.model().map_err(|e| refusal(py, &e))?;
    // A model that the explorer does not carry has no rows for the display yet.
    let list = with_capability!(&model, explore, p => quantities_of(p), else Vec::new());
    Ok(list
        .into_iter()
        .map(|q| {
            (
                q.id,
                q.symbol,
                q.unit,
                q.equation,
                mathml(q.tex),
                mathml(q.latex),
                q.latex,
                q.words,
            )
        })
        .collect())
}

fn quantities_of<M: Explore>(_: &M) -> Vec<&'static crate::results::quantity::Quantity> {
    M::quantities()
}

/// The integration regimes of the laws: (JSON id (guide §14), in words).
#[pyfunction]
fn law_regimes() -> Vec<(&'static str, &'static str)> {
    crate::explore::integration_regimes()
        .into_iter()
        .map(|r| (r.id, r.words))
        .collect()
}

/// The module `stickslip._native`.
#[pymodule]
fn _native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(run, m)?)?;
    m.add_function(wrap_pyfunction!(call, m)?)?;
    m.add_function(wrap_pyfunction!(evaluate, m)?)?;
    m.add_function(wrap_pyfunction!(figure, m)?)?;
    m.add_function(wrap_pyfunction!(quantities, m)?)?;
    m.add_function(wrap_pyfunction!(law_regimes, m)?)?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}
