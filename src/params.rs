//! Input parameters: serde structs with the paper's values as defaults, validation that names
//! the rule, and scenario files (TOML).

use std::path::Path;

use serde::{Deserialize, Serialize};

use crate::error::{Error, Result};
use crate::formula::woodpecker::Counterpart;

/// Standard gravity used throughout the paper (m/s²).
pub const G_STANDARD: f64 = 9.81;
/// Largest number of periods a run may ask for.
pub const MAX_PERIODS: u32 = 1_000_000;
/// Periods integrated unless asked otherwise (physics.md §0: 8–12).
pub const DEFAULT_PERIODS: u32 = 8;

/// The pulled mass of Sec. 2 (physics.md §1). Defaults: the paper's Fig. 6 set.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct PulledMassParams {
    /// Static friction coefficient μs.
    pub mu_s: f64,
    /// Dynamic friction coefficient μd (0 < μd ≤ μs).
    pub mu_d: f64,
    /// Mass m of the block (kg); the hanging mass m' = m, so the inertial mass is 2m.
    pub mass: f64,
    /// Spring constant k (N/m) of the hanging mass' spring.
    pub k: f64,
    /// Constant pulling force F (N).
    pub force: f64,
    /// Gravitational acceleration g (m/s²).
    pub g: f64,
}

impl Default for PulledMassParams {
    /// The Fig. 6 set: μs = 0.4, μd = 0.25, m = 0.06 kg, k = 45 N/m, F = 0.18 N.
    fn default() -> Self {
        Self {
            mu_s: 0.4,
            mu_d: 0.25,
            mass: 0.06,
            k: 45.0,
            force: 0.18,
            g: G_STANDARD,
        }
    }
}

impl PulledMassParams {
    /// Checks every parameter against its valid range.
    pub fn validate(&self) -> Result<()> {
        validate_friction(self.mu_s, self.mu_d)?;
        positive("mass", self.mass)?;
        positive("k", self.k)?;
        positive("force", self.force)?;
        positive("g", self.g)
    }

    /// Weight W = m g (N).
    pub fn weight(&self) -> f64 {
        self.mass * self.g
    }

    /// Angular frequency ω = √(k/m') with m' = m (rad/s), eq. (6).
    pub fn omega(&self) -> f64 {
        (self.k / self.mass).sqrt()
    }

    /// Period T = 2π/ω (s).
    pub fn period(&self) -> f64 {
        std::f64::consts::TAU / self.omega()
    }

    /// φ = F/W.
    pub fn phi(&self) -> f64 {
        self.force / self.weight()
    }
}

/// How ω of the harmonic woodpecker is defined (physics.md §2; regimes do not depend on it).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "cli", derive(clap::ValueEnum))]
#[serde(rename_all = "lowercase")]
pub enum OmegaMode {
    /// ω = √(k/m_W) (default: reproduces the paper's figures).
    Bird,
    /// ω = √(k (m_S + m_W)/(m_S m_W)), the reduced mass.
    Reduced,
    /// ω = √(k/(m_S + m_W)).
    Total,
}

/// The falling woodpecker of Sec. 3 (physics.md §2–3). Defaults: the paper's Fig. 15 set.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct WoodpeckerParams {
    /// Static friction coefficient μs.
    pub mu_s: f64,
    /// Dynamic friction coefficient μd (0 < μd ≤ μs).
    pub mu_d: f64,
    /// Spring constant k (N/m).
    pub k: f64,
    /// Sleeve mass m_S (kg).
    pub m_sleeve: f64,
    /// Woodpecker (bird) mass m_W (kg).
    pub m_bird: f64,
    /// Lever arm l of the spring force about the sleeve centre (m).
    pub l: f64,
    /// Distance h between the two pole contacts (m).
    pub h: f64,
    /// Spring offset z0 (m).
    pub z0: f64,
    /// Spring oscillation amplitude d0 (m).
    pub d0: f64,
    /// Gravitational acceleration g (m/s²).
    pub g: f64,
    /// Lever ratio λ (N = λ|F_e| at each contact); `None` = l/h.
    pub lever: Option<f64>,
    /// Definition of ω (TOML key `omega`; written as `omega_mode` in JSON output, where
    /// `omega` is the value in rad/s).
    #[serde(rename(serialize = "omega_mode", deserialize = "omega"))]
    pub omega: OmegaMode,
    /// Linear counterpart of the harmonic spring coordinate (§3.1).
    pub counterpart: Counterpart,
}

impl Default for WoodpeckerParams {
    /// The Fig. 15 set: μs = 0.65, μd = 0.32, k = 20 N/m, m_S = 6 g, m_W = 14 g, l = 16 mm,
    /// h = 7 mm, z0 = 7 mm, d0 = 9 mm; λ = l/h, ω = √(k/m_W), counterpart `zeros`.
    fn default() -> Self {
        Self {
            mu_s: 0.65,
            mu_d: 0.32,
            k: 20.0,
            m_sleeve: 0.006,
            m_bird: 0.014,
            l: 0.016,
            h: 0.007,
            z0: 0.007,
            d0: 0.009,
            g: G_STANDARD,
            lever: None,
            omega: OmegaMode::Bird,
            counterpart: Counterpart::Zeros,
        }
    }
}

impl WoodpeckerParams {
    /// Checks every parameter against its valid range.
    pub fn validate(&self) -> Result<()> {
        validate_friction(self.mu_s, self.mu_d)?;
        positive("k", self.k)?;
        positive("m_sleeve", self.m_sleeve)?;
        positive("m_bird", self.m_bird)?;
        positive("l", self.l)?;
        positive("h", self.h)?;
        if !self.z0.is_finite() {
            return Err(invalid("z0", num(self.z0), "-inf < z0 < inf"));
        }
        positive("d0", self.d0)?;
        positive("g", self.g)?;
        if let Some(lever) = self.lever {
            positive("lever", lever)?;
        }
        Ok(())
    }

    /// Lever ratio λ: the given one, else l/h.
    pub fn lambda(&self) -> f64 {
        self.lever.unwrap_or(self.l / self.h)
    }

    /// Sleeve weight W_S = m_S g (N).
    pub fn sleeve_weight(&self) -> f64 {
        self.m_sleeve * self.g
    }

    /// Angular frequency ω (rad/s) of the chosen mode.
    pub fn omega(&self) -> f64 {
        let (k, ms, mw) = (self.k, self.m_sleeve, self.m_bird);
        match self.omega {
            OmegaMode::Bird => (k / mw).sqrt(),
            OmegaMode::Reduced => (k * (ms + mw) / (ms * mw)).sqrt(),
            OmegaMode::Total => (k / (ms + mw)).sqrt(),
        }
    }

    /// Period T = 2π/ω (s).
    pub fn period(&self) -> f64 {
        std::f64::consts::TAU / self.omega()
    }
}

/// Checks the number of periods to integrate: 1 ≤ periods ≤ 10⁶.
pub fn validate_periods(periods: u32) -> Result<()> {
    if (1..=MAX_PERIODS).contains(&periods) {
        Ok(())
    } else {
        Err(invalid(
            "periods",
            periods,
            format!("1 <= periods <= {MAX_PERIODS}"),
        ))
    }
}

/// An error for parameter `name` with `value`, which must satisfy `rule`.
pub fn invalid(name: &'static str, value: impl ToString, rule: impl Into<String>) -> Error {
    Error::InvalidParam {
        name,
        value: value.to_string(),
        rule: rule.into(),
    }
}

/// Largest friction coefficient accepted: far beyond any real pair of surfaces, and small
/// enough that μ² and μ³ in the closed forms cannot overflow.
pub const MU_MAX: f64 = 100.0;

/// Checks μs and μd: 0 < μd ≤ μs ≤ [`MU_MAX`].
pub fn validate_friction(mu_s: f64, mu_d: f64) -> Result<()> {
    positive("mu_s", mu_s)?;
    if mu_s > MU_MAX {
        return Err(invalid("mu_s", num(mu_s), format!("0 < mu_s <= {MU_MAX}")));
    }
    positive("mu_d", mu_d)?;
    if mu_d > mu_s {
        return Err(invalid(
            "mu_d",
            num(mu_d),
            format!("0 < mu_d <= mu_s (mu_s = {mu_s})"),
        ));
    }
    Ok(())
}

/// A parameter value as written in messages: plain for ordinary magnitudes, else scientific.
pub fn num(x: f64) -> String {
    let a = x.abs();
    if a != 0.0 && a.is_finite() && !(1e-4..1e6).contains(&a) {
        format!("{x:e}")
    } else {
        x.to_string()
    }
}

/// Requires a finite value > 0.
pub fn positive(name: &'static str, value: f64) -> Result<()> {
    if value.is_finite() && value > 0.0 {
        Ok(())
    } else {
        Err(invalid(name, num(value), format!("0 < {name} < inf")))
    }
}

/// Which model a scenario describes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "cli", derive(clap::ValueEnum))]
#[serde(rename_all = "kebab-case")]
pub enum ModelName {
    /// The pulled mass (paper Sec. 2).
    PulledMass,
    /// The falling woodpecker (paper Sec. 3).
    Woodpecker,
}

impl ModelName {
    /// The name used on the command line and in scenario files.
    pub fn id(self) -> &'static str {
        match self {
            Self::PulledMass => "pulled-mass",
            Self::Woodpecker => "woodpecker",
        }
    }
}

/// A scenario file: a model, a title, optionally the number of periods, and the parameters
/// (missing ones take the model's defaults).
#[derive(Clone, Debug, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Scenario {
    pub model: ModelName,
    pub title: String,
    #[serde(default)]
    pub description: String,
    pub periods: Option<u32>,
    #[serde(default)]
    pub params: toml::Table,
}

impl Scenario {
    /// Reads and parses a scenario file.
    pub fn load(path: &Path) -> Result<Self> {
        let text = std::fs::read_to_string(path).map_err(|e| Error::Scenario {
            path: path.display().to_string(),
            reason: e.to_string(),
        })?;
        Self::parse(&text, path)
    }

    /// Parses scenario text; `path` only names the file in errors.
    pub fn parse(text: &str, path: &Path) -> Result<Self> {
        toml::from_str(text).map_err(|e| toml_error(&e, text, path))
    }

    /// The parameters as the model's struct (defaults for keys not given).
    pub fn params<P: for<'de> Deserialize<'de>>(&self, path: &Path) -> Result<P> {
        P::deserialize(toml::Value::Table(self.params.clone())).map_err(|e| Error::Scenario {
            path: path.display().to_string(),
            reason: format!("[params]: {}", e.message().trim()),
        })
    }
}

/// One line from a TOML error: the line number and the message, without the source snippet.
fn toml_error(e: &toml::de::Error, text: &str, path: &Path) -> Error {
    let line = e
        .span()
        .map(|s| text[..s.start.min(text.len())].matches('\n').count() + 1);
    let reason = match line {
        Some(l) => format!("line {l}: {}", e.message().trim()),
        None => e.message().trim().to_string(),
    };
    Error::Scenario {
        path: path.display().to_string(),
        reason: reason.replace('\n', " "),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn defaults_are_the_fig6_set_and_valid() {
        let p = PulledMassParams::default();
        p.validate().unwrap();
        assert!((p.period() - 0.229_429_488_381_819_04).abs() < 1e-15);
    }

    #[test]
    fn each_bad_value_names_its_parameter() {
        type Spoil = fn(&mut PulledMassParams);
        let cases: [(&str, Spoil); 7] = [
            ("mu_s", |p| p.mu_s = 0.0),
            ("mu_d", |p| p.mu_d = 0.5),
            ("mu_d", |p| p.mu_d = -0.1),
            ("mass", |p| p.mass = f64::NAN),
            ("k", |p| p.k = f64::INFINITY),
            ("force", |p| p.force = 0.0),
            ("g", |p| p.g = -9.81),
        ];
        for (name, spoil) in cases {
            let mut p = PulledMassParams::default();
            spoil(&mut p);
            match p.validate() {
                Err(Error::InvalidParam { name: got, .. }) => assert_eq!(got, name),
                other => panic!("{name}: expected an error, got {other:?}"),
            }
        }
        assert!(validate_periods(0).is_err());
        assert!(validate_periods(MAX_PERIODS + 1).is_err());
    }

    #[test]
    fn unknown_scenario_keys_are_refused_with_the_line() {
        let text = "model = \"pulled-mass\"\ntitle = \"x\"\ncolour = 3\n";
        let err = Scenario::parse(text, Path::new("s.toml")).unwrap_err();
        let msg = err.to_string();
        assert!(msg.contains("line 3") && msg.contains("colour"), "{msg}");
        assert!(!msg.contains('\n'));
        let text = "model = \"pulled-mass\"\ntitle = \"x\"\n[params]\nmu = 3\n";
        let sc = Scenario::parse(text, Path::new("s.toml")).unwrap();
        let err = sc
            .params::<PulledMassParams>(Path::new("s.toml"))
            .unwrap_err();
        assert!(err.to_string().contains("unknown field `mu`"), "{err}");
    }
}
