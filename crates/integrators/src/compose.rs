//! Higher order by composition: one step of size h of [`Composition`] is the sequence of steps of
//! sizes γ₁h, γ₂h, …, γ_s h of a symmetric base method Φ,
//!
//! ```text
//! Ψ_h = Φ_{γ_s h} ∘ … ∘ Φ_{γ₂ h} ∘ Φ_{γ₁ h},      Σ γ_i = 1.
//! ```
//!
//! If Φ is symmetric (Φ_{−h} = Φ_h⁻¹) of order 2 and the coefficients are palindromic
//! (γ_i = γ_{s+1−i}), Ψ is symmetric, and its order is the order of the scheme (Hairer, Lubich,
//! Wanner, *Geometric Numerical Integration*, 2nd ed., §II.4 and §V.3). Geometric properties of Φ
//! that are closed under composition — Casimirs and momentum maps conserved to round-off,
//! symplecticity, staying on G — are inherited by Ψ.
//!
//! The base method must be symmetric: compositions of a non-symmetric method of order 1 or 2 do not
//! reach the advertised order. For the integrators of this crate that means θ = ½
//! ([`SymmetricMethod`]); [`Composition::new`] refuses anything else.
//!
//! ## Schemes ([`CompositionScheme`]) and how their coefficients were checked
//! Every set below was verified independently of its source by composing, in 80-digit arithmetic,
//! the symmetric order-2 splitting `Φ_h = e^{hA/2} e^{hB/2} e^{hC} e^{hB/2} e^{hA/2}` of the linear
//! ODE `x' = (A + B + C) x` with random non-commuting 6×6 matrices A, B, C, and measuring the
//! order of the local error against `e^{h(A+B+C)}` at h = 2⁻²…2⁻⁵. Measured local orders (order + 1):
//!
//! | scheme | stages | order | Σγ − 1 | local order measured |
//! |---|---|---|---|---|
//! | [`CompositionScheme::triple_jump`]`(4)` | 3 | 4 | 0 | 5.26, 5.11, 5.05 |
//! | [`CompositionScheme::triple_jump`]`(6)` | 9 | 6 | 0 | 6.92, 6.94, 6.98 |
//! | [`CompositionScheme::triple_jump`]`(8)` | 27 | 8 | 0 | 9.37, 9.14, 9.06 |
//! | [`CompositionScheme::suzuki_fractal`]`(4)` | 5 | 4 | 0 | 4.95, 4.96, 4.98 |
//! | [`CompositionScheme::suzuki_fractal`]`(6)` | 25 | 6 | 0 | 6.89, 6.95, 6.97 |
//! | [`CompositionScheme::mclachlan_4`] | 5 | 4 | 0 (Σγ³ = 4·10⁻²¹) | 5.06, 5.00, 4.99 |
//! | [`CompositionScheme::kahan_li_6`] | 9 | 6 | 1·10⁻²⁶ | 7.07, 6.97, 6.98 |
//! | [`CompositionScheme::kahan_li_8`] | 17 | 8 | 0 | 8.96, 8.98, 8.99 |
//! | [`CompositionScheme::mclachlan_8`] | 15 | 8 | −2·10⁻²⁶ | 9.01, 9.01, 9.00 |
//! | [`CompositionScheme::sofroniou_spaletta_10`] | 35 | 10 | −3·10⁻²⁶ | 10.96, 10.97, 10.98 |
//!
//! The same check runs in double precision in `tests/compose.rs`. It is sensitive: listing the Sofroniou–Spaletta
//! coefficients in the wrong order gives Σγ − 1 = −0.03 and local order 1. The digits of
//! Sofroniou–Spaletta's order-6 and order-8 sets could not be obtained from a source that could
//! be checked here, so only their order-10 set is shipped.
//!
//! ## Example
//! ```
//! use integrators::{Composition, CompositionScheme, Integrator, LiePoisson};
//! use mechanics::RigidBody;
//! use lie_groups::{Cayley, So3};
//! use nalgebra::Vector3;
//!
//! let body = RigidBody::principal([1.0, 2.0, 3.0])?;
//! let base = LiePoisson::<So3, Cayley, _>::new(body, 0.5, Vector3::new(0.5, 1.0, 0.2), None)?;
//! // Order 6 from 9 steps of the order-2 θ = ½ scheme.
//! let mut psi = Composition::new(base, CompositionScheme::kahan_li_6())?;
//! psi.step(0.1)?;
//! assert_eq!(psi.time(), 0.1);
//! # Ok::<(), integrators::IntegratorError>(())
//! ```

use crate::clock::Clock;
use crate::{EulerPoincare, Integrator, IntegratorError, LiePoisson, System};
use core::fmt;
use core::str::FromStr;
use lie_groups::{LieGroup, Tau};

/// A method whose symmetry can be checked at run time: Φ_{−h} ∘ Φ_h = id (Hairer–Lubich–Wanner,
/// Def. V.1.4). Only symmetric methods can be put in a [`Composition`].
pub trait SymmetricMethod: Integrator {
    /// Whether this instance is symmetric (for [`LiePoisson`] and [`EulerPoincare`]: θ = ½).
    fn is_symmetric(&self) -> bool;
    /// The rates of the motion its variable steps must resolve ([`crate::DensityScope`]): the
    /// step density the reversible steps ([`crate::adaptive::ReversibleSteps`]) ask the monitor
    /// for. Provided: [`DensityScope::Full`](crate::DensityScope::Full); a method made of exact
    /// flows of the kinetic energy's pieces declares
    /// [`DensityScope::SpinFollowed`](crate::DensityScope::SpinFollowed), and a composition
    /// declares its base method's.
    fn density_scope(&self) -> crate::DensityScope {
        crate::DensityScope::Full
    }
}

/// Saving and restoring the state (t, μ or ξ, g) of an integrator, so that a composite step can
/// be undone when one of its sub-steps fails, and its time set to exactly t + h.
pub trait StateSnapshot: Integrator {
    /// The saved state.
    type State: Clone + fmt::Debug + Send;
    /// A copy of the current state.
    fn snapshot(&self) -> Self::State;
    /// Puts back a state returned by [`StateSnapshot::snapshot`] of the same integrator.
    fn restore(&mut self, state: Self::State) -> Result<(), IntegratorError>;
    /// Sets the time t, leaving the rest of the state alone.
    fn set_time(&mut self, t: f64) -> Result<(), IntegratorError>;
}

impl<G: LieGroup, T: Tau<G>, S: System<G>> SymmetricMethod for LiePoisson<G, T, S> {
    /// θ = ½: the discretization map (g τ(−ξ/2), g τ(ξ/2)) is symmetric under
    /// (g_k, g_{k+1}, ξ) ↦ (g_{k+1}, g_k, −ξ), so the cotangent-lift step is symmetric; and θ = 0
    /// or 1 without a potential or force, where the two steps coincide
    /// ([`LiePoisson::is_self_adjoint`]).
    fn is_symmetric(&self) -> bool {
        self.is_self_adjoint()
    }
}

impl<G: LieGroup, T: Tau<G>, S: System<G>> SymmetricMethod for EulerPoincare<G, T, S> {
    /// θ = ½, as for [`LiePoisson`].
    fn is_symmetric(&self) -> bool {
        self.theta() == 0.5
    }
}

impl<G: LieGroup, T: Tau<G>, S: System<G>> StateSnapshot for LiePoisson<G, T, S> {
    /// (t, μ, g).
    type State = (f64, G::Algebra, Option<G>);
    fn snapshot(&self) -> Self::State {
        (self.time(), self.momentum(), self.configuration().cloned())
    }
    fn restore(&mut self, (t, mu, g): Self::State) -> Result<(), IntegratorError> {
        self.reset(t, mu, g)
    }
    fn set_time(&mut self, t: f64) -> Result<(), IntegratorError> {
        if !t.is_finite() {
            return Err(IntegratorError::NonFinite { what: "time t" });
        }
        self.set_time_only(t);
        Ok(())
    }
}

impl<G: LieGroup, T: Tau<G>, S: System<G>> StateSnapshot for EulerPoincare<G, T, S> {
    /// (t, ξ, g): ξ is the state variable of the Euler–Poincaré scheme.
    type State = (f64, G::Algebra, Option<G>);
    fn snapshot(&self) -> Self::State {
        (self.time(), self.velocity(), self.configuration().cloned())
    }
    fn restore(&mut self, (t, xi, g): Self::State) -> Result<(), IntegratorError> {
        self.reset(t, xi, g)
    }
    fn set_time(&mut self, t: f64) -> Result<(), IntegratorError> {
        if !t.is_finite() {
            return Err(IntegratorError::NonFinite { what: "time t" });
        }
        self.set_time_only(t);
        Ok(())
    }
}

/// Kahan & Li (1997), "Composition constants for raising the orders of unconventional schemes
/// for ordinary differential equations", Math. Comp. 66, scheme s9odr6a; digits as printed in
/// Hairer–Lubich–Wanner §V.3.2. Listed γ₁ … γ₅ (γ₅ the middle; γ_{10−i} = γ_i).
#[allow(clippy::excessive_precision)] // the published digits, kept verbatim to compare with the source
const KAHAN_LI_6_HALF: [f64; 5] = [
    0.39216144400731413927925056,
    0.33259913678935943859974864,
    -0.70624617255763935980996482,
    0.08221359629355080023149045,
    0.79854399093482996339895035,
];

/// Kahan & Li (1997), scheme s17odr8a; digits as printed in Hairer–Lubich–Wanner §V.3.2.
/// Listed γ₁ … γ₉ (γ₉ the middle; γ_{18−i} = γ_i).
#[allow(clippy::excessive_precision)] // the published digits, kept verbatim to compare with the source
const KAHAN_LI_8_HALF: [f64; 9] = [
    0.13020248308889008087881763,
    0.56116298177510838456196441,
    -0.38947496264484728640807860,
    0.15884190655515560089621075,
    -0.39590389413323757733623154,
    0.18453964097831570709183254,
    0.25837438768632204729397911,
    0.29501172360931029887096624,
    -0.60550853383003451169892108,
];

/// McLachlan (1995), SIAM J. Sci. Comput. 16, the 15-stage symmetric order-8 scheme with error
/// coefficient 0.14 (HLW §V.3.2 lists it among the optimised order-8 schemes). Listed γ₁ … γ₈
/// (γ₈ the middle; γ_{16−i} = γ_i).
#[allow(clippy::excessive_precision)] // the published digits, kept verbatim to compare with the source
const MCLACHLAN_8_HALF: [f64; 8] = [
    0.74167036435061295344822780,
    -0.40910082580003159399730010,
    0.19075471029623837995387626,
    -0.57386247111608226665638773,
    0.29906418130365592384446354,
    0.33462491824529818378495798,
    0.31529309239676659663205666,
    -0.79688793935291635401978884,
];

/// Sofroniou & Spaletta (2005), "Derivation of symmetric composition constants for symmetric
/// integrators", Optim. Methods Softw. 20, 597–613: the 35-stage symmetric order-10 scheme.
/// Listed γ₁ … γ₁₈ (γ₁₈ the middle; γ_{36−i} = γ_i).
#[allow(clippy::excessive_precision)] // the published digits, kept verbatim to compare with the source
const SOFRONIOU_SPALETTA_10_HALF: [f64; 18] = [
    0.07879572252168641926390768,
    0.31309610341510852776481247,
    0.02791838323507806610952027,
    -0.22959284159390709415121340,
    0.13096206107716486317465686,
    -0.26973340565451071434460973,
    0.07497334315589143566613711,
    0.11199342399981020488957508,
    0.36613344954622675119314812,
    -0.39910563013603589787862981,
    0.10308739852747107731580277,
    0.41143087395589023782070412,
    -0.00486636058313526176219566,
    -0.39203335370863990644808194,
    0.05194250296244964703718290,
    0.05066509075992449633587434,
    0.04967437063972987905456880,
    0.04931773575959453791768001,
];

/// McLachlan (1995), "On the numerical integration of ordinary differential equations by
/// symmetric composition methods", SIAM J. Sci. Comput. 16, the 5-stage order-4 scheme
/// (Hairer–Lubich–Wanner §V.3.2): γ₁ = γ₅ = 0.28, γ₂ = γ₄ the root of Σγ³ = 0 below,
/// γ₃ = 1 − 2γ₁ − 2γ₂.
#[allow(clippy::excessive_precision)] // the published digits, kept verbatim to compare with the source
const MCLACHLAN_4_GAMMA2: f64 = 0.62546642846767004501;

/// A set of composition coefficients γ₁ … γ_s (Σγ_i = 1) with the order it gives when applied
/// to a symmetric method of order 2 (at least that order for a symmetric base of higher order).
#[derive(Debug, Clone, PartialEq)]
pub struct CompositionScheme {
    name: String,
    gammas: Vec<f64>,
    order: u32,
}

/// Expands (γ₁, …, γ_m) with γ_m the middle into the palindrome (γ₁, …, γ_m, …, γ₁).
fn palindrome(half: &[f64]) -> Vec<f64> {
    let mut g = half.to_vec();
    g.extend(half.iter().rev().skip(1));
    g
}

/// The composition of two schemes: a step of `outer` whose sub-steps are steps of `inner`,
/// γ = (a_i b_j)_{i, j}.
fn nest(outer: &[f64], inner: &[f64]) -> Vec<f64> {
    outer
        .iter()
        .flat_map(|a| inner.iter().map(move |b| a * b))
        .collect()
}

/// Checks that `order` is an even number in 4..=10 (beyond, the stage counts 3⁴, 5⁴ make the
/// recursive schemes pointless in double precision).
fn check_recursive_order(order: u32, what: &str) -> Result<(), IntegratorError> {
    if matches!(order, 4 | 6 | 8 | 10) {
        Ok(())
    } else {
        Err(IntegratorError::InvalidParameter {
            reason: format!("{what}: order {order} is not one of 4, 6, 8, 10"),
        })
    }
}

impl CompositionScheme {
    /// The triple jump (Creutz & Gocksch 1989, Suzuki 1990, Yoshida 1990; HLW §II.4, eq. (4.4)):
    /// from a symmetric method of order p, `γ₁ = γ₃ = 1/(2 − 2^{1/(p+1)})`, `γ₂ = 1 − 2γ₁` gives
    /// order p + 2; applied recursively from p = 2 up to `order` ∈ {4, 6, 8, 10}, with
    /// 3^{(order−2)/2} stages (3, 9, 27, 81).
    pub fn triple_jump(order: u32) -> Result<Self, IntegratorError> {
        check_recursive_order(order, "triple jump")?;
        let mut gammas = vec![1.0];
        for p in (2..order).step_by(2) {
            let g1 = 1.0 / (2.0 - 2f64.powf(1.0 / f64::from(p + 1)));
            gammas = nest(&[g1, 1.0 - 2.0 * g1, g1], &gammas);
        }
        Ok(Self {
            name: format!("triple-jump-{order}"),
            gammas,
            order,
        })
    }

    /// Suzuki's fractal (Suzuki 1990; HLW §II.4, eq. (4.5)): from a symmetric method of order p,
    /// `γ₁ = γ₂ = γ₄ = γ₅ = 1/(4 − 4^{1/(p+1)})`, `γ₃ = 1 − 4γ₁` gives order p + 2; applied
    /// recursively from p = 2 up to `order` ∈ {4, 6, 8, 10}, with 5^{(order−2)/2} stages
    /// (5, 25, 125, 625). Smaller error constants than the triple jump, at more stages.
    pub fn suzuki_fractal(order: u32) -> Result<Self, IntegratorError> {
        check_recursive_order(order, "Suzuki fractal")?;
        let mut gammas = vec![1.0];
        for p in (2..order).step_by(2) {
            let g1 = 1.0 / (4.0 - 4f64.powf(1.0 / f64::from(p + 1)));
            gammas = nest(&[g1, g1, 1.0 - 4.0 * g1, g1, g1], &gammas);
        }
        Ok(Self {
            name: format!("suzuki-{order}"),
            gammas,
            order,
        })
    }

    /// McLachlan's optimised 5-stage symmetric scheme of order 4 (McLachlan 1995, SIAM J. Sci.
    /// Comput. 16, 151–168; HLW §V.3.2): γ₁ = γ₅ = 0.28, γ₂ = γ₄ = 0.62546642846767004501,
    /// γ₃ = 1 − 2γ₁ − 2γ₂. (Σγ_i³ = 4·10⁻²¹ with these digits: the order-4 condition.)
    pub fn mclachlan_4() -> Self {
        let (g1, g2) = (0.28, MCLACHLAN_4_GAMMA2);
        Self {
            name: "mclachlan-4".into(),
            gammas: palindrome(&[g1, g2, 1.0 - 2.0 * g1 - 2.0 * g2]),
            order: 4,
        }
    }

    /// Kahan & Li's optimised 9-stage symmetric scheme of order 6 (Kahan & Li 1997, Math. Comp.
    /// 66, 1089–1099, "s9odr6a"; HLW §V.3.2, eq. (3.12)).
    pub fn kahan_li_6() -> Self {
        Self {
            name: "kahan-li-6".into(),
            gammas: palindrome(&KAHAN_LI_6_HALF),
            order: 6,
        }
    }

    /// Kahan & Li's optimised 17-stage symmetric scheme of order 8 (Kahan & Li 1997,
    /// "s17odr8a"; HLW §V.3.2, eq. (3.13)).
    pub fn kahan_li_8() -> Self {
        Self {
            name: "kahan-li-8".into(),
            gammas: palindrome(&KAHAN_LI_8_HALF),
            order: 8,
        }
    }

    /// McLachlan's optimised 15-stage symmetric scheme of order 8 (McLachlan 1995; HLW §V.3.2).
    pub fn mclachlan_8() -> Self {
        Self {
            name: "mclachlan-8".into(),
            gammas: palindrome(&MCLACHLAN_8_HALF),
            order: 8,
        }
    }

    /// Sofroniou & Spaletta's 35-stage symmetric scheme of order 10 (Sofroniou & Spaletta 2005,
    /// Optim. Methods Softw. 20). In double precision its local error reaches round-off already
    /// at moderate steps; it pays off only for very tight tolerances.
    pub fn sofroniou_spaletta_10() -> Self {
        Self {
            name: "sofroniou-spaletta-10".into(),
            gammas: palindrome(&SOFRONIOU_SPALETTA_10_HALF),
            order: 10,
        }
    }

    /// A user-supplied scheme. Errors unless the γ_i are finite, non-empty, and sum to 1 within
    /// 1e-12 (the rounding of the published 20-digit sets is ~1e-16); `order` is taken on trust.
    pub fn custom(
        name: impl Into<String>,
        gammas: Vec<f64>,
        order: u32,
    ) -> Result<Self, IntegratorError> {
        let sum: f64 = gammas.iter().sum();
        if gammas.is_empty() || !gammas.iter().all(|g| g.is_finite()) || (sum - 1.0).abs() > 1e-12 {
            return Err(IntegratorError::InvalidParameter {
                reason: format!("composition coefficients {gammas:?} must be finite and sum to 1"),
            });
        }
        Ok(Self {
            name: name.into(),
            gammas,
            order,
        })
    }

    /// Every built-in scheme, by its [`CompositionScheme::name`] (each parses back with
    /// [`str::parse`]).
    pub fn builtin() -> Vec<Self> {
        let mut all = Vec::new();
        for order in [4, 6, 8] {
            all.extend(Self::triple_jump(order));
        }
        for order in [4, 6, 8] {
            all.extend(Self::suzuki_fractal(order));
        }
        all.extend([
            Self::mclachlan_4(),
            Self::kahan_li_6(),
            Self::kahan_li_8(),
            Self::mclachlan_8(),
            Self::sofroniou_spaletta_10(),
        ]);
        all
    }

    /// The name, e.g. `"kahan-li-6"`, `"triple-jump-8"`.
    pub fn name(&self) -> &str {
        &self.name
    }
    /// The coefficients γ₁ … γ_s.
    pub fn gammas(&self) -> &[f64] {
        &self.gammas
    }
    /// The number of stages s: base-method steps per composite step.
    pub fn stages(&self) -> usize {
        self.gammas.len()
    }
    /// The order on a symmetric base method of order 2.
    pub fn order(&self) -> u32 {
        self.order
    }
    /// Whether γ_i = γ_{s+1−i} exactly (then the composition of a symmetric method is symmetric).
    pub fn is_symmetric(&self) -> bool {
        self.gammas.iter().eq(self.gammas.iter().rev())
    }
}

impl FromStr for CompositionScheme {
    type Err = IntegratorError;
    /// Parses a built-in name: `triple-jump-{4,6,8,10}`, `suzuki-{4,6,8,10}`, `mclachlan-4`,
    /// `kahan-li-6`, `kahan-li-8`, `mclachlan-8`, `sofroniou-spaletta-10`.
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        let order = |rest: &str| {
            rest.parse::<u32>()
                .map_err(|_| IntegratorError::InvalidParameter {
                    reason: format!("unknown composition scheme {s:?}"),
                })
        };
        match s {
            "mclachlan-4" => Ok(Self::mclachlan_4()),
            "kahan-li-6" => Ok(Self::kahan_li_6()),
            "kahan-li-8" => Ok(Self::kahan_li_8()),
            "mclachlan-8" => Ok(Self::mclachlan_8()),
            "sofroniou-spaletta-10" => Ok(Self::sofroniou_spaletta_10()),
            _ => {
                if let Some(rest) = s.strip_prefix("triple-jump-") {
                    Self::triple_jump(order(rest)?)
                } else if let Some(rest) = s.strip_prefix("suzuki-") {
                    Self::suzuki_fractal(order(rest)?)
                } else {
                    Err(IntegratorError::InvalidParameter {
                        reason: format!("unknown composition scheme {s:?}"),
                    })
                }
            }
        }
    }
}

/// A symmetric method Φ raised to higher order by composition: one [`Integrator::step`] of size h
/// takes the steps γ₁h, …, γ_s h of Φ (see the module page).
///
/// A failed sub-step restores the state saved at the start of the composite step and returns the
/// sub-step's error, so the [`Integrator`] contract (an error leaves the state untouched) holds.
/// After a successful step the time is set to exactly t + h (Σγ_i h is t + h only to rounding).
/// A `Composition` is itself symmetric when its scheme is palindromic, so it can be nested.
#[derive(Debug, Clone)]
pub struct Composition<I> {
    inner: I,
    scheme: CompositionScheme,
    /// The composite step's own time: Σ γᵢh = h only up to rounding, so the base method's time
    /// after the sub-steps is replaced by this clock's, advanced by h ([`crate::Clock`]).
    clock: Clock,
}

impl<I: SymmetricMethod + StateSnapshot> Composition<I> {
    /// Wraps the symmetric method `inner`. Errors ([`IntegratorError::InvalidParameter`]) if
    /// `inner` is not symmetric (e.g. θ ≠ ½) or the scheme is not palindromic.
    pub fn new(inner: I, scheme: CompositionScheme) -> Result<Self, IntegratorError> {
        if !inner.is_symmetric() {
            return Err(IntegratorError::InvalidParameter {
                reason: format!(
                    "composition needs a symmetric base method, {} is not (θ must be ½)",
                    inner.method_name()
                ),
            });
        }
        if !scheme.is_symmetric() {
            return Err(IntegratorError::InvalidParameter {
                reason: format!("composition scheme {} is not palindromic", scheme.name()),
            });
        }
        let clock = Clock::at(inner.time());
        Ok(Self {
            inner,
            scheme,
            clock,
        })
    }
}

impl<I> Composition<I> {
    /// The base method.
    pub fn inner(&self) -> &I {
        &self.inner
    }
    /// The base method, mutably (for [`crate::processing::ComposedKernel`]'s processor, whose
    /// stages are steps of the base method).
    pub(crate) fn inner_mut(&mut self) -> &mut I {
        &mut self.inner
    }
    /// Unwraps the base method.
    pub fn into_inner(self) -> I {
        self.inner
    }
    /// The scheme.
    pub fn scheme(&self) -> &CompositionScheme {
        &self.scheme
    }
}

impl<I: StateSnapshot> Integrator for Composition<I> {
    type Group = I::Group;

    fn step(&mut self, h: f64) -> Result<(), IntegratorError> {
        if !h.is_finite() {
            return Err(IntegratorError::NonFinite { what: "step h" });
        }
        let saved = self.inner.snapshot();
        // The base method's time may have been set from outside (a restore, a reset).
        self.clock.set(self.inner.time());
        let t1 = self.clock.advanced(h);
        for &gamma in &self.scheme.gammas {
            if let Err(e) = self.inner.step(gamma * h) {
                self.inner.restore(saved)?;
                return Err(e);
            }
        }
        self.inner.set_time(t1.now())?;
        self.clock = t1;
        Ok(())
    }
    fn time(&self) -> f64 {
        self.inner.time()
    }
    fn momentum(&self) -> <Self::Group as LieGroup>::Algebra {
        self.inner.momentum()
    }
    fn velocity(&self) -> <Self::Group as LieGroup>::Algebra {
        self.inner.velocity()
    }
    fn momentum_rate(&self) -> <Self::Group as LieGroup>::Algebra {
        self.inner.momentum_rate()
    }
    fn configuration(&self) -> Option<&Self::Group> {
        self.inner.configuration()
    }
    fn energy(&self) -> f64 {
        self.inner.energy()
    }
    fn casimir(&self) -> Option<f64> {
        self.inner.casimir()
    }
    /// The scheme's order (the base is symmetric of order 2, by [`Composition::new`]), symmetric,
    /// and whatever the base keeps: every flag of [`crate::MethodInfo`] is closed under composition.
    fn side(&self) -> discretization::Side {
        self.inner.side()
    }
    fn info(&self) -> crate::MethodInfo {
        crate::MethodInfo {
            order: self.scheme.order(),
            symmetric: true,
            ..self.inner.info()
        }
    }
    fn method_name(&self) -> String {
        format!(
            "composition({}, {} stages)∘{}",
            self.scheme.name,
            self.scheme.stages(),
            self.inner.method_name()
        )
    }
}

impl<I: SymmetricMethod + StateSnapshot> SymmetricMethod for Composition<I> {
    /// Symmetric base and palindromic γ (always, by [`Composition::new`]).
    fn is_symmetric(&self) -> bool {
        self.inner.is_symmetric() && self.scheme.is_symmetric()
    }
    /// The base method's: each substep is one of its steps.
    fn density_scope(&self) -> crate::DensityScope {
        self.inner.density_scope()
    }
}

impl<I: StateSnapshot> StateSnapshot for Composition<I> {
    type State = I::State;
    fn snapshot(&self) -> Self::State {
        self.inner.snapshot()
    }
    fn restore(&mut self, state: Self::State) -> Result<(), IntegratorError> {
        self.inner.restore(state)
    }
    fn set_time(&mut self, t: f64) -> Result<(), IntegratorError> {
        self.inner.set_time(t)
    }
}
