//! Scenes: one per figure (or figure group) of the paper, each a scenario file plus what to
//! show. The built-in scenes are the default report; a user's scenario file becomes a scene
//! with the standard figures of its model.

use std::path::{Path, PathBuf};

use serde::Serialize;

use crate::error::{Error, Result};
use crate::models::{with_capability, Capability, Model};
use crate::params::{Scenario, DEFAULT_PERIODS};
use crate::present::Present;
use crate::report::figures::spec::{CategoryMap, LineChart};

pub mod sampling;

/// What a scene draws. Each kind may produce one or more figures.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum FigureKind {
    /// Pulled mass: x, v, a against t for both laws, with t_SL, t_M, t_ST (Figs. 5, 6, 10).
    PulledMotion { periods: f64 },
    /// Pulled mass: F against μs N(t) and μd N(t), with t_SL, t_M, t_ST.
    PulledForces,
    /// Pulled mass: the (μd, μs) domain for the scene's φ, both laws on a grid (Fig. 9).
    PulledDomain,
    /// Pulled mass: position over 10 periods and the line of slope v̄ (Fig. 11).
    PulledLongRun,
    /// Pulled mass: speed and acceleration, harmonic against linear (Fig. 12).
    PulledCompare,
    /// Woodpecker: y_S and v against t for both laws, with the characteristic times (Figs. 15,
    /// 16, 26).
    WoodMotion { periods: f64 },
    /// Woodpecker: the spring coordinate, harmonic against the three counterparts (Fig. 17).
    WoodSpring,
    /// Woodpecker: W_S + F_e against 2λμs|F_e| and 2λμd|F_e|, with t_SL^(I) (Fig. 18).
    WoodForces,
    /// Woodpecker: a, v, y and the characteristic times of phase 1 or 2 (Fig. 19).
    WoodPhase { phase: u8 },
    /// Woodpecker: v for μd below, at and above μd,MIN of phase 1 or 2 (Fig. 20).
    WoodMuSweep { phase: u8 },
    /// Woodpecker: sleeve and woodpecker positions and the speed (Fig. 23).
    WoodPositions,
    /// Woodpecker: regimes in the (μd, z0) plane with μd,MIN and μd,HALT of both phases.
    WoodRegimeMap,
    /// Woodpecker: the example track (synthetic) with the harmonic law fitted to it from the
    /// scene's parameters (Figs. 26–27).
    WoodTracked,
}

/// A drawing ready for a renderer.
#[derive(Clone, Debug, PartialEq)]
pub enum Drawing {
    Chart(LineChart),
    Map(CategoryMap),
}

impl Drawing {
    /// Every text the drawing shows: axis labels, legend entries, reference-line and marker
    /// labels (to write them in another language before the legend is sized).
    pub fn labels_mut(&mut self) -> Vec<&mut String> {
        match self {
            Drawing::Chart(c) => {
                let mut labels = vec![&mut c.x_label];
                for panel in &mut c.panels {
                    labels.push(&mut panel.y_label);
                    labels.extend(panel.curves.iter_mut().map(|c| &mut c.label));
                    labels.extend(panel.h_lines.iter_mut().map(|h| &mut h.1));
                }
                labels.extend(c.markers.iter_mut().map(|m| &mut m.label));
                labels
            }
            Drawing::Map(m) => {
                let mut labels = vec![&mut m.x_label, &mut m.y_label];
                labels.extend(m.categories.iter_mut().map(|c| &mut c.0));
                labels.extend(m.curves.iter_mut().map(|c| &mut c.label));
                labels
            }
        }
    }
}

/// One figure of a scene: a file-name id, a caption and the drawing.
#[derive(Clone, Debug, PartialEq)]
pub struct Figure {
    pub id: String,
    pub caption: String,
    pub drawing: Drawing,
}

/// The part of the reading path a scene belongs to: the paper's two models, then the user's
/// own scenario files.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Part {
    PulledMass,
    Woodpecker,
    Scenarios,
}

impl Part {
    /// Every part, in reading order.
    pub const ALL: [Part; 3] = [Part::PulledMass, Part::Woodpecker, Part::Scenarios];

    /// The heading of the part in the index.
    pub fn heading(self) -> &'static str {
        match self {
            Part::PulledMass => "Part 1. The pulled mass",
            Part::Woodpecker => "Part 2. The falling woodpecker",
            Part::Scenarios => "Your scenarios",
        }
    }

    /// The part's story in two sentences: what the apparatus is and what to follow.
    pub fn story(self) -> &'static str {
        match self {
            Part::PulledMass => {
                "A block on a table is pulled by a constant force F while a spring presses it \
                 down with a mass hanging under the table: the normal force N oscillates, so \
                 friction alternately holds the block and lets it slide. Read the pages in order: \
                 the pull against the friction limits, then each kind of motion, then the price \
                 of the linearized law that makes every result a closed formula."
            }
            Part::Woodpecker => {
                "The toy woodpecker slides down its pole in jerks: the bird swings on a spring, \
                 tilting the sleeve so that it grips the pole and lets go twice per swing. The \
                 same stick-slip rule as in Part 1, with the grip set by the lever l/h; the pages \
                 follow one period phase by phase, then the regimes and the real toy."
            }
            Part::Scenarios => "Scenes from the scenario files given to `stickslip report`.",
        }
    }
}

/// A scene of the report.
#[derive(Clone, Debug, PartialEq)]
pub struct Scene {
    /// File stem of the scene's pages.
    pub id: String,
    pub title: String,
    /// Where the scene sits in the reading path.
    pub part: Part,
    /// Why the scene matters, in a sentence: the index's line and the page's opening.
    pub why: String,
    /// What the scene shows and what to look for.
    pub caption: String,
    /// The scenario's description of the parameters.
    pub description: String,
    /// The model and its parameters.
    pub setup: Model,
    /// Periods integrated for the results tables.
    pub periods: u32,
    pub figures: Vec<FigureKind>,
    /// Claims of the paper (guide §11) that concern the scene.
    pub claims: Vec<u8>,
}

impl Scene {
    /// A user's scenario as a scene: its parameters, title and description, and what to draw.
    pub fn from_scenario(
        id: &str,
        scenario: &Scenario,
        path: &Path,
        caption: &str,
        figures: Vec<FigureKind>,
        claims: Vec<u8>,
    ) -> Result<Self> {
        let setup = scenario.model_params(path)?;
        setup.validate()?;
        Ok(Self {
            id: id.to_string(),
            title: scenario.title.clone(),
            part: Part::Scenarios,
            why: String::new(),
            caption: caption.to_string(),
            description: scenario.description.trim().to_string(),
            setup,
            periods: scenario.periods.unwrap_or(DEFAULT_PERIODS),
            figures,
            claims,
        })
    }

    /// A user's scenario file as a scene with the standard figures of its model.
    pub fn from_file(path: &Path) -> Result<Self> {
        let scenario = Scenario::load(path)?;
        let id = path
            .file_stem()
            .map(|s| page_name(&s.to_string_lossy()))
            .filter(|s| !s.is_empty())
            .ok_or_else(|| Error::Scenario {
                path: path.display().to_string(),
                reason: "the file name gives no scene name".to_string(),
            })?;
        let model = scenario.model;
        let standard = with_capability!(&model, present, p => p.standard_scene(),
            else return Err(model.missing(Capability::Present)));
        let (figures, claims, caption) = (standard.figures, standard.claims, standard.caption);
        Self::from_scenario(&id, &scenario, path, caption, figures, claims)
    }

    /// Scenes from the user's scenario files, refused when two would write the same pages (their
    /// file stems equal, ignoring case as some file systems do) or when one would write a page of
    /// the report itself ([`RESERVED_PAGES`]).
    pub fn from_files(paths: &[PathBuf]) -> Result<Vec<Self>> {
        let mut scenes: Vec<Self> = Vec::with_capacity(paths.len());
        for path in paths {
            let scene = Self::from_file(path)?;
            let key = scene.id.to_lowercase();
            let clash = |reason: String| Error::Scenario {
                path: path.display().to_string(),
                reason,
            };
            if RESERVED_PAGES.contains(&key.as_str()) {
                return Err(clash(format!(
                    "its pages {0}.html and {0}.md would replace the report's own: rename the file",
                    scene.id
                )));
            }
            if let Some(j) = scenes.iter().position(|s| s.id.to_lowercase() == key) {
                return Err(clash(format!(
                    "would write the same pages ({}.html, {}.md) as {}: rename one of the files",
                    scene.id,
                    scene.id,
                    paths[j].display()
                )));
            }
            scenes.push(scene);
        }
        Ok(scenes)
    }

    /// The figures of the scene, built from its parameters.
    pub fn build_figures(&self) -> Result<Vec<Figure>> {
        let mut out = Vec::new();
        for kind in &self.figures {
            let built = with_capability!(&self.setup, present, p => p.figures(&self.id, *kind)?,
                else return Err(self.setup.missing(Capability::Present)));
            out.extend(built);
        }
        Ok(out)
    }
}

/// The page name of a scenario file's stem: letters, digits, `-`, `_` and `.` kept, any other
/// character (space, `|`, `<`, `#`, `%`, a control character…) as `-`, so that the name is
/// safe in a file name, a URL and a Markdown link.
pub fn page_name(stem: &str) -> String {
    stem.chars()
        .map(|c| {
            if c.is_alphanumeric() || matches!(c, '-' | '_' | '.') {
                c
            } else {
                '-'
            }
        })
        .collect()
}

/// Page names of the report itself, which no scene may take (compared in lower case).
pub const RESERVED_PAGES: &[&str] = &["index", "all-scenes"];

/// A built-in scene: a scenario file compiled into the binary and its place in the story.
struct Builtin {
    id: &'static str,
    /// The figure(s) of the paper it reproduces, and what they show (unique).
    title: &'static str,
    part: Part,
    why: &'static str,
    file: &'static str,
    text: &'static str,
    caption: &'static str,
    figures: &'static [FigureKind],
    claims: &'static [u8],
}

macro_rules! scenario_file {
    ($name:literal) => {
        ($name, include_str!(concat!("../../../scenarios/", $name)))
    };
}

const FIG05: (&str, &str) = scenario_file!("fig05-immediate-slip.toml");
const FIG06: (&str, &str) = scenario_file!("fig06-continuous-slip.toml");
const SET_B: (&str, &str) = scenario_file!("set-b-slip-stick.toml");
const SET_C: (&str, &str) = scenario_file!("set-c-late-stick.toml");
const FIG15: (&str, &str) = scenario_file!("fig15-double-slip-stick.toml");
const FIG16: (&str, &str) = scenario_file!("fig16-no-intermediate-halt.toml");
const FIG26: (&str, &str) = scenario_file!("fig26-tracked-toy.toml");
const LAMBDA1: (&str, &str) = scenario_file!("lambda1-printed-formulas.toml");

/// The title, part and why of a built-in scene.
struct Story {
    title: &'static str,
    part: Part,
    why: &'static str,
}

const fn pulled(title: &'static str, why: &'static str) -> Story {
    Story {
        title,
        part: Part::PulledMass,
        why,
    }
}

const fn wood(title: &'static str, why: &'static str) -> Story {
    Story {
        title,
        part: Part::Woodpecker,
        why,
    }
}

const fn builtin(
    id: &'static str,
    story: Story,
    scenario: (&'static str, &'static str),
    caption: &'static str,
    figures: &'static [FigureKind],
    claims: &'static [u8],
) -> Builtin {
    Builtin {
        id,
        title: story.title,
        part: story.part,
        why: story.why,
        file: scenario.0,
        text: scenario.1,
        caption,
        figures,
        claims,
    }
}

const BUILTINS: &[Builtin] = &[
    builtin(
        "fig05-immediate-slip",
        pulled(
            "Fig. 5: immediate slip",
            "The simplest case sets the scale: a pull stronger than friction can ever hold, φ = F/W > 2μs.",
        ),
        FIG05,
        "Immediate slip: F exceeds the largest static capacity 2μsW, so the mass slips at t = 0 \
         and never sticks. Position, speed and acceleration under both laws.",
        &[FigureKind::PulledMotion { periods: 2.0 }],
        &[],
    ),
    builtin(
        "fig06-continuous-slip",
        pulled(
            "Fig. 6: continuous slip",
            "Friction brakes the block every period but never stops it: its speed oscillates about a steady drift.",
        ),
        FIG06,
        "Non-immediate continuous slip (the paper's Fig. 6 set): the slip starts where F = μs N, \
         the speed peaks where F = μd N, and the mass never comes back to rest.",
        &[FigureKind::PulledMotion { periods: 2.0 }],
        &[1],
    ),
    builtin(
        "pulled-forces",
        pulled(
            "The pull against the friction limits",
            "One picture decides the motion: where F crosses μs N the slip starts, where it crosses μd N the speed peaks.",
        ),
        SET_B,
        "The competing forces: the pull F against the static capacity μs N(t) and the dynamic \
         friction μd N(t). The slip starts where F crosses μs N (t_SL), the speed is largest \
         where F = μd N (t_M), and the mass sticks at t_ST.",
        &[FigureKind::PulledForces],
        &[1],
    ),
    builtin(
        "fig09-domain",
        pulled(
            "Fig. 9: where the block sticks, in the (μd, μs) plane",
            "Which friction pairs give stick-slip, and the band where the paper's condition (20) misses a late stick.",
        ),
        FIG06,
        "The (μd, μs) plane for the Fig. 6 value of φ = F/W: where the mass sticks in the same \
         period (20), sticks late in the next period, or slips for ever, for the linear \
         closed forms and for the exact harmonic integration; the analytic boundaries are drawn \
         over the computed regimes.",
        &[FigureKind::PulledDomain],
        &[1],
    ),
    builtin(
        "fig10-linear-slip-stick",
        pulled(
            "Fig. 10: slip-stick within one period",
            "Textbook stick-slip: every characteristic time has a closed formula, each checked here against the integration.",
        ),
        SET_B,
        "Slip-stick within one period (set B): position, speed and acceleration with the \
         characteristic times of the closed forms.",
        &[FigureKind::PulledMotion { periods: 1.5 }],
        &[2],
    ),
    builtin(
        "late-stick",
        pulled(
            "Late stick: the block stops in the next period",
            "A motion the paper's Fig. 9 calls non-stick: the block halts early in the following period.",
        ),
        SET_C,
        "Late stick (set C): (20) is violated, yet the mass stops early in the next period, \
         before the next slip onset — the band the paper's Fig. 9 calls non-stick.",
        &[FigureKind::PulledMotion { periods: 2.0 }],
        &[1],
    ),
    builtin(
        "fig11-position",
        pulled(
            "Fig. 11: ten periods of position and the mean speed",
            "The staircase motion and its mean speed v̄, the number an experiment measures.",
        ),
        SET_B,
        "Position over ten periods and the line of slope v̄ through the slip onsets.",
        &[FigureKind::PulledLongRun],
        &[2, 7],
    ),
    builtin(
        "fig12-harmonic-vs-linear",
        pulled(
            "Fig. 12: the harmonic law against its linearization",
            "What the triangle-wave approximation changes in the motion: the price of closed formulas.",
        ),
        SET_B,
        "Speed and acceleration of the harmonic law against its linearization, in the settled \
         motion.",
        &[FigureKind::PulledCompare],
        &[3],
    ),
    builtin(
        "fig15-double-slip-stick",
        wood(
            "Fig. 15: double slip-stick of the falling woodpecker",
            "The toy as it works: two slips and two halts per swing of the bird.",
        ),
        FIG15,
        "The falling woodpecker (Fig. 15 set): two slips and two sticks per period under both \
         laws. Sleeve position and speed with the characteristic times.",
        &[FigureKind::WoodMotion { periods: 2.0 }],
        &[8],
    ),
    builtin(
        "fig16-no-intermediate-halt",
        wood(
            "Fig. 16: no intermediate halt under the harmonic law (z0 = 7.1 mm)",
            "Regime boundaries are sharp: 0.1 mm of spring set-up changes the motion.",
        ),
        FIG16,
        "A 0.1 mm larger z0 removes the intermediate halt of the harmonic law: one slip per \
         period with two speed maxima.",
        &[FigureKind::WoodMotion { periods: 2.0 }],
        &[8],
    ),
    builtin(
        "fig17-spring-coordinate",
        wood(
            "Fig. 17: the spring coordinate and its linear counterparts",
            "Three ways to replace the bird's harmonic swing by a triangle wave, and how far each is off.",
        ),
        FIG15,
        "The spring coordinate of the harmonic law against its three linear counterparts \
         (same extremes, same zeros, same zeros and slopes).",
        &[FigureKind::WoodSpring],
        &[3],
    ),
    builtin(
        "fig18-forces",
        wood(
            "Fig. 18: the driving force against the grip",
            "Why the sleeve slips: its weight and the spring force against the friction the lever can hold.",
        ),
        FIG15,
        "The driving force W_S + F_e against the static capacity 2λμs|F_e| (and the dynamic \
         friction 2λμd|F_e|): the slip of phase I starts where they cross.",
        &[FigureKind::WoodForces],
        &[],
    ),
    builtin(
        "fig19-phase-one",
        wood(
            "Fig. 19: phase I step by step",
            "The first slip of each period, with each of its characteristic times.",
        ),
        FIG15,
        "Phase I of the linear law: acceleration, speed and position with t_SL, t0, t_M, t_ST.",
        &[FigureKind::WoodPhase { phase: 1 }],
        &[5],
    ),
    builtin(
        "fig20-mu-d-min-one",
        wood(
            "Fig. 20: the critical dynamic friction of phase I",
            "The friction μd,MIN at which the sleeve stops exactly at half a period.",
        ),
        FIG15,
        "Phase I for μd below, at and above μd,MIN^(I): at the critical value the sleeve \
         stops exactly at T/2.",
        &[FigureKind::WoodMuSweep { phase: 1 }],
        &[4, 5],
    ),
    builtin(
        "phase-two",
        wood(
            "Phase II and its critical dynamic friction",
            "The second slip of the period, and the friction μd,MIN at which it ends at the period's end.",
        ),
        FIG15,
        "Phase II likewise: acceleration, speed and position, and μd below, at and above \
         μd,MIN^(II).",
        &[
            FigureKind::WoodPhase { phase: 2 },
            FigureKind::WoodMuSweep { phase: 2 },
        ],
        &[4],
    ),
    builtin(
        "fig23-positions",
        wood(
            "Fig. 23: sleeve and bird positions",
            "The bird swings about the falling sleeve: the motion the eye follows on the real toy.",
        ),
        FIG15,
        "Sleeve and woodpecker positions and the sleeve speed (harmonic law): the bird \
         oscillates about the falling sleeve.",
        &[FigureKind::WoodPositions],
        &[7],
    ),
    builtin(
        "fig26-tracked-toy",
        wood(
            "Figs. 26-27: the parameters of the tracked toy",
            "The model with the parameters of a real, video-tracked toy.",
        ),
        FIG26,
        "The tracked toy's parameters (Figs. 26–27): sleeve position and speed under both laws, \
         and a tracked track (synthetic here: the paper does not give its tracked data) with \
         the harmonic law fitted to it, as `stickslip fit` does for your own video.",
        &[FigureKind::WoodMotion { periods: 3.0 }, FigureKind::WoodTracked],
        &[3, 8],
    ),
    builtin(
        "woodpecker-regime-map",
        wood(
            "The woodpecker's regimes in the (μd, z0) plane",
            "Where the toy halts twice, once or never, and how well the closed-form boundaries find it.",
        ),
        FIG15,
        "Regimes in the (μd, z0) plane: the linear orbit (closed forms) and the harmonic law \
         (exact integration), with the analytic boundaries μd,MIN and μd,HALT of both phases.",
        &[FigureKind::WoodRegimeMap],
        &[4, 5, 6],
    ),
    builtin(
        "lambda1-printed-formulas",
        wood(
            "The printed formulas (λ = 1): a sleeve that never halts",
            "The paper's formulas as printed leave out the lever: with them the toy would not work.",
        ),
        LAMBDA1,
        "The printed formulas (λ = 1, N = |F_e|): with the paper's friction values the sleeve \
         never sticks.",
        &[FigureKind::WoodMotion { periods: 2.0 }],
        &[8],
    ),
];

/// The built-in scenes of the default report, in order.
pub fn builtin_scenes() -> Result<Vec<Scene>> {
    BUILTINS
        .iter()
        .map(|b| {
            let path = Path::new("scenarios").join(b.file);
            let scenario = Scenario::parse(b.text, &path)?;
            let scene = Scene::from_scenario(
                b.id,
                &scenario,
                &path,
                b.caption,
                b.figures.to_vec(),
                b.claims.to_vec(),
            )?;
            Ok(Scene {
                title: b.title.to_string(),
                part: b.part,
                why: b.why.to_string(),
                ..scene
            })
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn builtin_scenes_parse_and_have_unique_ids() {
        let scenes = builtin_scenes().unwrap();
        let mut ids: Vec<_> = scenes.iter().map(|s| s.id.clone()).collect();
        ids.sort();
        ids.dedup();
        assert_eq!(ids.len(), scenes.len());
        assert!(scenes.iter().all(|s| !s.figures.is_empty()));
        assert!(ids.iter().all(|id| !RESERVED_PAGES.contains(&id.as_str())));
    }

    /// Eight pages were once all titled after Fig. 15: a title names what its page shows.
    #[test]
    fn builtin_titles_are_unique_and_every_scene_says_why_it_matters() {
        let scenes = builtin_scenes().unwrap();
        let mut titles: Vec<_> = scenes.iter().map(|s| s.title.to_lowercase()).collect();
        titles.sort();
        titles.dedup();
        assert_eq!(titles.len(), scenes.len());
        for s in &scenes {
            assert!(s.why.ends_with('.') && s.why.len() > 40, "{}", s.id);
            assert_ne!(s.part, Part::Scenarios, "{}", s.id);
            let model = if s.part == Part::PulledMass {
                "pulled-mass"
            } else {
                "woodpecker"
            };
            assert_eq!(s.setup.id(), model, "{}", s.id);
        }
    }
}
