//! Rendering the benchmark: results → context ([`super::context`]) → tera pages (HTML with
//! inline SVG, Markdown with SVG files), plus results.json and results.csv. Everything is
//! rendered in memory; [`crate::report::writer`] writes it.

use std::path::PathBuf;

use tera::Tera;

use super::context::context;
use super::sweep::SweepPoint;
use super::BenchResults;
use crate::error::{Error, Result};
use crate::report::render::{markdown_cell, template_error};
use crate::report::writer::OutFile;

const TEMPLATES: &[(&str, &str)] = &[
    (
        "bench.html",
        include_str!("../../templates/bench.html.tera"),
    ),
    ("bench.md", include_str!("../../templates/bench.md.tera")),
];

/// Columns of results.csv, units in the names.
pub const CSV_HEADER: &str = "problem,method,setting_kind,tolerance,h_s,steps_per_period,status,\
time_s,time_min_s,time_max_s,runs,rhs_evals,steps,accepted,rejected,n_events,n_events_exact,n_matched,kind_mismatches,\
reversals,err_event_s,err_x_m,err_vbar_m_s,x_end_m,v_end_m_s,error";

/// Renders the benchmark's files.
pub fn render(r: &BenchResults) -> Result<Vec<OutFile>> {
    let mut tera = Tera::default();
    tera.autoescape_on(vec![".html"]);
    tera.register_filter("cell", markdown_cell);
    tera.add_raw_templates(TEMPLATES.to_vec())
        .map_err(|e| template_error("(bench)", &e))?;
    let ctx = context(r)?;
    let context = tera::Context::from_serialize(&ctx).map_err(|e| template_error("context", &e))?;
    let page = |name: &str| -> Result<Vec<u8>> {
        tera.render(name, &context)
            .map(String::into_bytes)
            .map_err(|e| template_error(name, &e))
    };
    let mut files = vec![
        OutFile {
            path: PathBuf::from("index.html"),
            bytes: page("bench.html")?,
        },
        OutFile {
            path: PathBuf::from("bench.md"),
            bytes: page("bench.md")?,
        },
        OutFile {
            path: PathBuf::from("results.json"),
            bytes: (serde_json::to_string_pretty(&crate::results::Versioned::new(r)).map_err(
                |e| Error::Output {
                    path: "results.json".into(),
                    reason: e.to_string(),
                },
            )? + "\n")
                .into_bytes(),
        },
        OutFile {
            path: PathBuf::from("results.csv"),
            bytes: csv(&r.sweep).into_bytes(),
        },
    ];
    for f in ctx
        .wp_figures
        .iter()
        .chain(&ctx.order_figures)
        .chain(&ctx.failure_figures)
        .chain(ctx.long_runs.iter().map(|c| &c.figure))
    {
        files.push(OutFile {
            path: PathBuf::from(&f.file),
            bytes: f.svg.clone().into_bytes(),
        });
    }
    Ok(files)
}

/// One CSV field: numbers as written by Rust (shortest round-trip), text quoted when needed.
fn field(s: &str) -> String {
    if s.contains([',', '"', '\n']) {
        format!("\"{}\"", s.replace('"', "\"\""))
    } else {
        s.to_string()
    }
}

/// results.csv: one row per method × problem × setting.
pub fn csv(sweep: &[SweepPoint]) -> String {
    let f = |x: Option<f64>| x.map_or(String::new(), |v| v.to_string());
    let u = |x: Option<u64>| x.map_or(String::new(), |v| v.to_string());
    let z = |x: Option<usize>| x.map_or(String::new(), |v| v.to_string());
    let mut out = String::from(CSV_HEADER);
    out.push('\n');
    for p in sweep {
        let cells = [
            field(&p.problem),
            field(&p.method),
            p.setting_kind.clone(),
            f(p.tolerance),
            f(p.h_s),
            f(p.steps_per_period),
            p.status.clone(),
            f(p.time_s),
            f(p.time_min_s),
            f(p.time_max_s),
            p.runs.to_string(),
            u(p.rhs_evals),
            u(p.steps),
            u(p.accepted),
            u(p.rejected),
            z(p.n_events),
            p.n_events_exact.to_string(),
            z(p.n_matched),
            z(p.kind_mismatches),
            z(p.reversals),
            f(p.err_event_s),
            f(p.err_x_m),
            f(p.err_vbar_m_s),
            f(p.x_end_m),
            f(p.v_end_m_s),
            field(p.error.as_deref().unwrap_or("")),
        ];
        out.push_str(&cells.join(","));
        out.push('\n');
    }
    out
}
