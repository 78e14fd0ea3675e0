//! The method registry: one row per method, in `methods!`, from which everything about methods
//! in `lie-sim` is derived — the scene's `method` names and the options each takes
//! ([`spec::check`]), building it on a scene's model ([`build`]), `trade`'s and `choose`'s
//! candidates ([`candidates`]), the plot's families and styles ([`style`]), and the `lie-sim
//! methods` listing and the docs' method table (`crate::listing`).
//!
//! A row ([`Row`]) says what the method is called, what it is in one line, which options it takes
//! (`Takes`: τ, θ, coefficients, the modified Hamiltonian, a composition or processing around
//! it), which of them `trade` runs (`Trade`), and how it is drawn; its module holds its
//! constructor, generic over the scene's [`Model`] and over τ ([`crate::taus::with_tau`]). What
//! it applies to follows from the capabilities it asks the model for; its order, symmetry,
//! explicitness and what it keeps are the library's `MethodInfo`, read from the built method,
//! never restated here — and whether a composition or processing may wrap it is the built
//! method's own `SymmetricMethod::is_symmetric`.
//!
//! Adding a method is a module with its row and constructor, and one line in `methods!`.

pub mod families;
pub mod options;
mod quaternion_pair;
pub mod row;
pub mod spec;
pub mod wrap;

use crate::model::{Alg, Model};
use crate::plot::{Marker, SeriesStyle};
use crate::sim::Boxed;
use crate::taus::TauKind;
use families::Family;
use integrators::processing::ProcessingScheme;
use integrators::splitting::SplittingScheme;
use integrators::{CompositionScheme, MethodInfo, SolverConfig};
use options::Options;
use row::{Row, TauRule, SYMMETRIC_THETA};
use serde::Deserialize;
use std::fmt;
use wrap::BuildError;

/// The registry: one line per method, `Variant => module`; the module holds `ROW` (its [`Row`])
/// and `build` (its constructor). Generates [`MethodId`] (the scene's `method`), its rows, and
/// the one dispatch [`build`] from a spec to the method's constructor.
macro_rules! methods {
    ($($variant:ident => $module:ident,)*) => {
        $(mod $module;)*

        /// A method of the registry (the scene's `method = "…"`).
        #[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
        pub enum MethodId {
            $(
                #[doc = concat!("See the `", stringify!($module), "` row.")]
                $variant,
            )*
        }

        impl MethodId {
            /// Every method, in registry order (the order of tables and listings).
            pub const ALL: &'static [MethodId] = &[$(MethodId::$variant),*];

            /// Its row.
            pub fn row(self) -> &'static Row {
                match self {
                    $(MethodId::$variant => &$module::ROW,)*
                }
            }
        }

        /// The scene names, in registry order.
        const NAMES: &[&str] = &[$($module::ROW.name),*];

        /// Builds the method `spec` names on `model` from the state (μ₀, g₀), with the implicit
        /// solver's `config`: the one place where a method becomes a type.
        pub fn build<M: Model>(
            spec: &MethodSpec,
            config: &SolverConfig,
            model: &M,
            mu0: Alg<M::G>,
            g0: Option<M::G>,
        ) -> Result<Boxed<M::G>, BuildError> {
            match spec.method {
                $(MethodId::$variant => $module::build(&spec.options(), config, model, mu0, g0),)*
            }
        }
    };
}

methods! {
    LiePoisson => lie_poisson,
    EulerPoincare => euler_poincare,
    EulerArnold => euler_arnold,
    Rk4 => rk4,
    Rkmk4 => rkmk4,
    Splitting => splitting,
    KineticKick => kinetic_kick,
    CasimirSplitting => casimir_splitting,
    Exact => exact,
    RkmkDopri5 => rkmk_dopri5,
    RkmkDop853 => rkmk_dop853,
    Dopri5 => dopri5,
    Dop853 => dop853,
}

impl MethodId {
    /// The name used in scene files.
    pub fn name(self) -> &'static str {
        self.row().name
    }
    /// The method named `name`.
    pub fn by_name(name: &str) -> Option<Self> {
        Self::ALL.iter().copied().find(|m| m.name() == name)
    }
}

impl fmt::Display for MethodId {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl<'de> Deserialize<'de> for MethodId {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let name = String::deserialize(d)?;
        Self::by_name(&name).ok_or_else(|| serde::de::Error::unknown_variant(&name, NAMES))
    }
}

/// A fully specified method: the registry row and its options.
#[derive(Debug, Clone, PartialEq)]
pub struct MethodSpec {
    /// The method (the base method Φ when `composition` or `processing` is set).
    pub method: MethodId,
    /// τ, where the method takes one.
    pub tau: Option<TauKind>,
    /// θ ∈ [0, 1], where the method takes it.
    pub theta: Option<f64>,
    /// The composition scheme Ψ_h = Φ_{γ_s h} ∘ … ∘ Φ_{γ₁ h} around a symmetric base.
    pub composition: Option<CompositionScheme>,
    /// The method's coefficients (kinetic-kick's Strang, Blanes–Moan 4 or 6).
    pub splitting: Option<SplittingScheme>,
    /// The processed method P ∘ Kⁿ ∘ P⁻¹ of a symmetric base method (effective order 6).
    pub processing: Option<ProcessingScheme>,
    /// The modified Hamiltonian of this order (4: H − h²H₂; 6: H − h²H₂ − h⁴H₄).
    pub modified: Option<u32>,
    /// Run with reversible variable steps h = ε/ρ (`integrator.epsilon`, `crate::stepping`)
    /// rather than a fixed step: the same method, steered by the step-density controller.
    pub reversible: bool,
}

impl MethodSpec {
    /// The method alone, with τ where it takes exactly one (rkmk4's exp) and nothing else.
    pub fn plain(method: MethodId) -> Self {
        Self {
            method,
            tau: match method.row().takes.tau {
                TauRule::Only(t) => Some(t),
                _ => None,
            },
            theta: None,
            composition: None,
            splitting: None,
            processing: None,
            modified: None,
            reversible: false,
        }
    }
    /// Its options, as the method's constructor reads them.
    pub fn options(&self) -> Options {
        Options {
            tau: self.tau,
            theta: self.theta,
            composition: self.composition.clone(),
            splitting: self.splitting.clone(),
            processing: self.processing.clone(),
            modified: self.modified,
        }
    }
    /// The method's name for tables: its scene name, `modified-<name>` for the modified
    /// Hamiltonian, `processed-<name>` for a processed method.
    pub fn method_label(&self) -> String {
        if self.modified.is_some() {
            format!("modified-{}", self.method.name())
        } else if self.processing.is_some() {
            format!("processed-{}", self.method.name())
        } else {
            self.method.name().into()
        }
    }
    /// τ as a string for tables (`-` where it does not apply).
    pub fn tau_label(&self) -> String {
        self.tau.map_or_else(|| "-".into(), |t| t.name().into())
    }
    /// θ as a string for tables (`-` where it does not apply).
    pub fn theta_label(&self) -> String {
        self.theta.map_or_else(|| "-".into(), |t| format!("{t}"))
    }
    /// The composition or processing scheme's name for tables, the modified Hamiltonian's order
    /// (`order-4`, `order-6`), or the coefficients' (`-` without any).
    pub fn composition_label(&self) -> String {
        if let Some(p) = &self.processing {
            return p.name().into();
        }
        if let Some(order) = self.modified {
            return format!("order-{order}");
        }
        match (&self.composition, &self.splitting) {
            (Some(c), _) => c.name().into(),
            (None, Some(s)) => s.name().into(),
            (None, None) => "-".into(),
        }
    }
    /// The largest step this configuration takes from μ₀ where it is set by the state rather
    /// than by the row's [`row::Row::step_limit`] (hω): the modified Hamiltonian's
    /// (`mechanics::modified::ModifiedLiePoisson::step_limit`, refused beyond); `None`: the
    /// row's limit alone.
    // Read by the extremes harness only, a test, as the row's limit.
    #[cfg_attr(not(test), allow(dead_code))]
    pub fn state_step_limit<M: Model>(&self, model: &M, mu0: &Alg<M::G>) -> Option<f64> {
        if self.method == MethodId::LiePoisson {
            lie_poisson::modified_step_limit(&self.options(), model, mu0.clone(), false)
        } else {
            None
        }
    }
    /// The rate the error of this configuration's base step grows with at μ₀ where it is not
    /// the system's characteristic rate: the Lie–Poisson kernel's on the free body, ω_K = 1 /
    /// (the order-4 modified Hamiltonian's step limit), whose h² term bends H by (hω_K)² — on
    /// a thin rod some 10²|Ω| (`lie_poisson::modified_step_limit`); `None`: the system's rate.
    #[cfg_attr(not(test), allow(dead_code))]
    pub fn kernel_rate<M: Model>(&self, model: &M, mu0: &Alg<M::G>) -> Option<f64> {
        if self.method == MethodId::LiePoisson {
            lie_poisson::modified_step_limit(&self.options(), model, mu0.clone(), true)
                .map(|limit| 1.0 / limit)
        } else {
            None
        }
    }
    /// Base-method steps per step: the composition's or the processing kernel's stages, 1
    /// otherwise (a processed method also pays its processor's stages at each read).
    pub fn stages(&self) -> usize {
        match (&self.composition, &self.processing) {
            (Some(c), _) => c.stages(),
            (None, Some(p)) => p.kernel_stages(),
            (None, None) => 1,
        }
    }
}

/// `kahan-li-6 ∘ lie-poisson (τ = cayley, θ = 0.5)`.
impl fmt::Display for MethodSpec {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if let Some(c) = &self.composition {
            write!(f, "{} ∘ ", c.name())?;
        }
        if let Some(p) = &self.processing {
            write!(f, "processed {} ∘ ", p.name())?;
        }
        f.write_str(&self.options().base(self.method.name()))?;
        if self.reversible {
            f.write_str(", reversible steps")?;
        }
        Ok(())
    }
}

/// Every configuration `trade` and `choose` run, in table order: for each row in registry order,
/// its plain configurations (each set of coefficients × each τ × each θ), its compositions, its
/// modified Hamiltonians, its processed forms and its configurations with reversible variable
/// steps (`Trade`), each over the τ it takes.
pub fn candidates() -> Vec<MethodSpec> {
    let mut v = Vec::new();
    for &method in MethodId::ALL {
        let row = method.row();
        let taus: Vec<Option<TauKind>> = match row.takes.tau {
            TauRule::None => vec![None],
            TauRule::Any => TauKind::ALL.iter().copied().map(Some).collect(),
            TauRule::Only(t) => vec![Some(t)],
        };
        let thetas: Vec<Option<f64>> = if row.takes.theta {
            row.trade.thetas.iter().copied().map(Some).collect()
        } else {
            vec![None]
        };
        let coefficients: Vec<Option<SplittingScheme>> = if row.takes.coefficients {
            SplittingScheme::builtin().into_iter().map(Some).collect()
        } else {
            vec![None]
        };
        let plain = MethodSpec {
            splitting: row.takes.coefficients.then(SplittingScheme::strang),
            ..MethodSpec::plain(method)
        };
        let symmetric = row.takes.theta.then_some(SYMMETRIC_THETA);
        for s in &coefficients {
            for &tau in &taus {
                for &theta in &thetas {
                    v.push(MethodSpec {
                        tau,
                        theta,
                        splitting: s.clone(),
                        ..plain.clone()
                    });
                }
            }
        }
        for name in row.trade.compositions {
            let scheme: CompositionScheme = name
                .parse()
                .unwrap_or_else(|_| panic!("{}: {name} is not a composition scheme", row.name));
            for &tau in &taus {
                v.push(MethodSpec {
                    tau,
                    theta: symmetric,
                    composition: Some(scheme.clone()),
                    ..plain.clone()
                });
            }
        }
        for &(theta, order) in row.trade.modified {
            for &tau in &taus {
                v.push(MethodSpec {
                    tau,
                    theta: Some(theta),
                    modified: Some(order),
                    ..plain.clone()
                });
            }
        }
        if row.trade.processing {
            for p in ProcessingScheme::builtin() {
                for &tau in &taus {
                    v.push(MethodSpec {
                        tau,
                        theta: symmetric,
                        processing: Some(p.clone()),
                        ..plain.clone()
                    });
                }
            }
        }
        for name in row.trade.reversible {
            let composition = name.map(|n| {
                n.parse::<CompositionScheme>()
                    .unwrap_or_else(|_| panic!("{}: {n} is not a composition scheme", row.name))
            });
            // The symmetric configuration of a row with coefficients is each set of them (every
            // built-in scheme is a palindrome); a composition wraps its Strang configuration.
            let schemes = if composition.is_none() {
                coefficients.clone()
            } else {
                vec![plain.splitting.clone()]
            };
            for s in &schemes {
                for &tau in &taus {
                    v.push(MethodSpec {
                        tau,
                        theta: symmetric,
                        composition: composition.clone(),
                        splitting: s.clone(),
                        reversible: true,
                        ..plain.clone()
                    });
                }
            }
        }
    }
    v
}

/// Whether a method is *geometric*: it keeps some structure of the flow beyond g on G — it is
/// symmetric, or a Poisson map, or keeps the Casimirs, the momentum map or the energy — as its
/// `MethodInfo` says (g on G alone is what the plain baselines keep too, by renormalising or by
/// stepping on the group).
pub fn geometric(info: &MethodInfo) -> bool {
    info.symmetric || info.poisson || info.casimirs || info.momentum_map || info.energy
}

/// The family a configuration is drawn in: [`families::PROCESSED`] for a processed method, its
/// row's otherwise.
pub fn family(m: &MethodSpec) -> &'static Family {
    if m.processing.is_some() {
        &families::PROCESSED
    } else {
        (m.method.row().family)(&m.options())
    }
}

/// How a configuration's series is drawn: the colour of its [`family`]; τ = cayley and the
/// second of a pair ([`Row::second`]) dashed with hollow markers, the others solid with filled
/// ones; reversible steps + (× for a method's own order-4 and order-6 coefficients, see the
/// code); the marker by θ (0 ▲, ½ ●, 1 ■) or by scheme (order-4 triple jump ▲, McLachlan's ×,
/// order 6 ■, order 8 ◆; coefficients ●, ▲, ■ by order; a row's own marker: the exact flow ◆);
/// the modified Hamiltonians by (θ, order) (½ and 4 ●, 0 and 4 ▲, ½ and 6 ■, 0 and 6 ◆); the
/// processed methods by scheme (blanes-6 ●, 6-11 ▲, 6-13 ■), dashed as their base, filled for
/// τ = exp and the second of a pair (the splitting hollow, kinetic–kick filled).
pub fn style(m: &MethodSpec) -> SeriesStyle {
    let row = m.method.row();
    let second = m.tau == Some(TauKind::Cayley) || row.second;
    if let Some(p) = &m.processing {
        let marker = match p.name() {
            "blanes-6" => Marker::Circle,
            "blanes-casas-murua-6-11" => Marker::Triangle,
            _ => Marker::Square,
        };
        return SeriesStyle {
            color: family(m).color,
            dashed: second,
            marker,
            filled: if m.tau.is_some() { !second } else { second },
        };
    }
    if m.reversible {
        // Reversible variable steps: + in the method's colour, bold for the base method and
        // thin for a composition of it, dashed (solid for the second of a pair) from order 8;
        // a method's own higher-order coefficients × as their base, filled for order 4.
        let high = m.composition.as_ref().is_some_and(|c| c.order() >= 8);
        if let Some(order) = m.splitting.as_ref().map(|s| s.order()).filter(|&o| o > 2) {
            return SeriesStyle {
                color: family(m).color,
                dashed: second,
                marker: Marker::Cross,
                filled: order == 4,
            };
        }
        return SeriesStyle {
            color: family(m).color,
            dashed: second != high,
            marker: Marker::Plus,
            filled: m.composition.is_none(),
        };
    }
    let marker = if let Some(order) = m.modified {
        match (m.theta, order) {
            (Some(0.0), 4) => Marker::Triangle,
            (Some(0.0), _) => Marker::Diamond,
            (_, 4) => Marker::Circle,
            _ => Marker::Square,
        }
    } else if let Some(c) = &m.composition {
        match c.name() {
            "triple-jump-4" => Marker::Triangle,
            "mclachlan-4" => Marker::Cross,
            "kahan-li-6" => Marker::Square,
            _ => Marker::Diamond,
        }
    } else if let Some(s) = &m.splitting {
        match s.order() {
            2 => Marker::Circle,
            4 => Marker::Triangle,
            _ => Marker::Square,
        }
    } else if let Some(marker) = row.marker {
        marker
    } else {
        match m.theta {
            Some(0.0) => Marker::Triangle,
            Some(1.0) => Marker::Square,
            _ => Marker::Circle,
        }
    };
    SeriesStyle {
        color: family(m).color,
        dashed: second,
        marker,
        filled: !second,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_row_is_named_once_and_reads_back_from_its_name() {
        for (i, m) in MethodId::ALL.iter().enumerate() {
            assert_eq!(MethodId::by_name(m.name()), Some(*m));
            assert_eq!(NAMES[i], m.name());
            assert!(!m.row().summary.is_empty(), "{m}");
        }
        let mut names = NAMES.to_vec();
        names.sort();
        names.dedup();
        assert_eq!(names.len(), MethodId::ALL.len());
    }

    /// Each row's candidates are its plain configurations (coefficients × τ × θ) and the
    /// wrappers its `Trade` names over its τ; each candidate passes the scene's own option check
    /// (so `trade` runs nothing a scene could not name), and no two are alike.
    #[test]
    fn candidates_expand_each_rows_trade_over_its_options() {
        let all = candidates();
        for &m in MethodId::ALL {
            let row = m.row();
            let taus = match row.takes.tau {
                TauRule::Any => TauKind::ALL.len(),
                _ => 1,
            };
            let thetas = if row.takes.theta {
                row.trade.thetas.len()
            } else {
                1
            };
            let coefficients = if row.takes.coefficients {
                SplittingScheme::builtin().len()
            } else {
                1
            };
            let processing = if row.trade.processing {
                ProcessingScheme::builtin().len()
            } else {
                0
            };
            // The symmetric configuration runs with reversible steps for each set of
            // coefficients, a composition around the Strang one.
            let reversible: usize = row
                .trade
                .reversible
                .iter()
                .map(|c| if c.is_none() { coefficients } else { 1 })
                .sum();
            let want = taus
                * (coefficients * thetas
                    + row.trade.compositions.len()
                    + row.trade.modified.len()
                    + processing
                    + reversible);
            let got = all.iter().filter(|s| s.method == m).count();
            assert_eq!(got, want, "{m}");
        }
        for (i, a) in all.iter().enumerate() {
            assert!(all[i + 1..].iter().all(|b| b != a), "{a} twice");
        }
    }

    #[test]
    fn every_candidate_is_drawn_in_its_own_style_and_families_share_a_colour() {
        let all = candidates();
        let styles: Vec<SeriesStyle> = all.iter().map(style).collect();
        for (i, a) in styles.iter().enumerate() {
            for (j, b) in styles.iter().enumerate().skip(i + 1) {
                assert_ne!(a, b, "{} and {}", all[i], all[j]);
            }
        }
        for m in &all {
            for n in &all {
                let (f, g) = (family(m), family(n));
                assert_eq!(f.name == g.name, f.color == g.color, "{m} {n}");
            }
        }
    }
}
