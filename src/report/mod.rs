//! The report: every scene of the paper as a verified, printable page (HTML with inline SVG
//! and MathML; GitHub Markdown with SVG files), rendered in memory and written atomically.
//!
//! ```text
//! scene (scenario + figure kinds) → context (formatted numbers, MathML) + figures (SVG)
//!       → tera templates (templates/) → files (writer)
//! ```

pub mod context;
pub mod explorer;
pub mod figures;
pub mod guide;
pub mod lock;
pub mod math;
pub mod render;
pub mod scene;
pub mod sketch;
pub mod writer;

pub use render::{render, render_with, Format, Material};
pub use scene::{builtin_scenes, Scene};
pub use writer::{write_all, OutFile};
