//! Display metadata of the closed-form quantities: symbol, unit, equation and tag, and the
//! formula in LaTeX, keyed by the §7 `closed_form` key.

/// How a closed-form quantity is shown.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Quantity {
    /// The §7 key.
    pub key: &'static str,
    /// Plain-text symbol.
    pub symbol: &'static str,
    /// SI unit ("" for dimensionless).
    pub unit: &'static str,
    /// Paper's equation number, or the physics.md section of a derived result.
    pub equation: &'static str,
    /// [P], [P*], [G] or [D] (physics.md tags).
    pub tag: &'static str,
    /// The formula in LaTeX.
    pub latex: &'static str,
}

const fn q(
    key: &'static str,
    symbol: &'static str,
    unit: &'static str,
    equation: &'static str,
    tag: &'static str,
    latex: &'static str,
) -> Quantity {
    Quantity {
        key,
        symbol,
        unit,
        equation,
        tag,
        latex,
    }
}

/// The pulled-mass closed forms (physics.md §1.3–1.4), in the order they are shown.
pub const PULLED_MASS: &[Quantity] = &[
    q("phi", "φ", "", "—", "[P]", r"\varphi = F/W"),
    q(
        "tau_slip",
        "τ_SL",
        "",
        "(13),(25)",
        "[P]",
        r"\tau_{SL} = \tfrac12\left(1 - \frac{\varphi}{2\mu_s}\right)",
    ),
    q(
        "t_slip",
        "t_SL",
        "s",
        "(13),(25)",
        "[P]",
        r"t_{SL} = T\,\tau_{SL}",
    ),
    q(
        "a_slip",
        "a_SL",
        "m/s²",
        "§1.3",
        "[D]",
        r"a_{SL} = \frac{g\varphi}{2}\left(1 - \frac{\mu_d}{\mu_s}\right)",
    ),
    q(
        "tau_max_speed",
        "τ_M",
        "",
        "(17)",
        "[P]",
        r"\tau_M = \tfrac12\left(1 + \frac{\varphi}{2\mu_d}\right)",
    ),
    q("t_max_speed", "t_M", "s", "(17)", "[P]", r"t_M = T\,\tau_M"),
    q(
        "v_max",
        "v_M",
        "m/s",
        "(26)",
        "[P]",
        r"v_M = \frac{g T \varphi^2 D}{16 \mu_s^2 \mu_d}",
    ),
    q(
        "tau_stick",
        "τ_ST",
        "",
        "(18),(25)",
        "[P]",
        r"\tau_{ST} = \tfrac12 (1 + \varphi\Theta)",
    ),
    q(
        "t_stick",
        "t_ST",
        "s",
        "(18),(25)",
        "[P]",
        r"t_{ST} = T\,\tau_{ST}",
    ),
    q(
        "slip_duration",
        "t_ST − t_SL",
        "s",
        "(21)",
        "[P]",
        r"t_{ST} - t_{SL} = \frac{T\varphi}{2}\,\frac{\mu_s + \mu_d + \sqrt{D}}{2\mu_s\mu_d}",
    ),
    q(
        "theta",
        "Θ",
        "",
        "(18)",
        "[P]",
        r"\Theta = \frac{\mu_s + \sqrt{D}}{2\mu_s\mu_d},\ D = \mu_s^2 + 2\mu_s\mu_d - \mu_d^2",
    ),
    q(
        "phi_stick_max",
        "1/Θ",
        "",
        "(20)",
        "[P]",
        r"\varphi \le 1/\Theta = \frac{2\mu_s\mu_d}{\mu_s + \sqrt{D}}",
    ),
    q(
        "phi_continuous",
        "φ_c",
        "",
        "§1.4",
        "[D]",
        r"\varphi_c = \frac{4\mu_s\mu_d}{2\mu_s + \sqrt{2D}}",
    ),
    q(
        "mu_min_equal",
        "μ_MIN",
        "",
        "(22)",
        "[P]",
        r"\mu_{MIN} = \frac{(1+\sqrt2)\,\varphi}{2}",
    ),
    q(
        "gamma",
        "Γ",
        "",
        "(28)",
        "[P*]",
        r"\Gamma = \frac{D^{3/2} + \mu_s^3 + 3\mu_s^2\mu_d - \mu_d^3}{96\,\mu_s^3\mu_d^2}",
    ),
    q(
        "v_avg",
        "v̄",
        "m/s",
        "(27)",
        "[P]",
        r"\bar v = g T \varphi^3 \Gamma",
    ),
    q(
        "advance_per_period",
        "x_T",
        "m",
        "(30)",
        "[P]",
        r"x_T = g T^2 \varphi^3 \Gamma",
    ),
    q(
        "power",
        "P",
        "W",
        "(29)",
        "[P]",
        r"P = F\bar v = \frac{gT}{W^3}\,\Gamma F^4",
    ),
    q(
        "tau_stick_late",
        "τ_ST,late",
        "",
        "§1.4",
        "[D]",
        r"\tau_{ST,late} = 1 + \tau'_M - \sqrt{2\tau_M'^2 - \frac{v_M}{gT\mu_d}}",
    ),
    q(
        "advance_per_period_late",
        "x_T,late",
        "m",
        "§1.4",
        "[D]",
        r"x_{T,late} = gT^2\,[F_1]_{\tau_{SL}}^{1/2} + [F_2]_{1/2}^{1} + [F_3]_{1}^{\tau_{ST,late}}",
    ),
    q(
        "v_avg_late",
        "v̄_late",
        "m/s",
        "§1.4",
        "[D]",
        r"\bar v_{late} = x_{T,late}/T",
    ),
];

/// The metadata of `key` in `table`.
pub fn find(table: &'static [Quantity], key: &str) -> Option<&'static Quantity> {
    table.iter().find(|q| q.key == key)
}
