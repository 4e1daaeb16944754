//! Figures as SVG strings: plain-data specifications ([`spec`]) drawn by the renderers
//! ([`chart`], [`map`]) in one style ([`style`]).

pub mod chart;
pub mod map;
pub mod style;

pub use crate::present::spec;
