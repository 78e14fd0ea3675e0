//! Processing: high effective order from a cheap kernel, by conjugation
//! (Butcher 1969; Blanes, Casas & Ros 1999, "Symplectic integration with processing: a general
//! study", SIAM J. Sci. Comput. 21, 711–727; Blanes 2001, Appl. Numer. Math. 37, 289–306;
//! Blanes, Casas & Murua 2004, "On the numerical integration of ODEs by processed methods", SIAM
//! J. Numer. Anal. 42, 531–552, and 2006, SIAM J. Sci. Comput. 27, 1817–1843).
//!
//! A processed method is `Ψ_h = P_h ∘ K_h ∘ P_h⁻¹` with a kernel K and a processor P; its n steps
//! are `P ∘ Kⁿ ∘ P⁻¹`, so P⁻¹ is applied once at the start, K at every step and P only where the
//! state is output ([`Processed`]: reads apply P, steps never do). Ψ has *effective order* p when
//! `Ψ_h = φ_h + O(h^{p+1})`: the output is then order p although K alone is only order 2 — the
//! kernel needs to meet only the order conditions that conjugation cannot remove.
//!
//! ## What processing can and cannot remove, for a general symmetric basic method
//! Backward error analysis writes a symmetric basic method Φ (θ = ½ Lie–Poisson or
//! Euler–Poincaré, a Strang splitting, …) as `Φ_h = exp(hX + h³E₃ + h⁵E₅ + h⁷E₇ + …)`, X the
//! vector field and E₃, E₅, … error fields that, for a general Φ, satisfy no relation. A kernel
//! `K_h = Φ_{γ_s h} ∘ … ∘ Φ_{γ₁ h}` (palindromic, Σγ = 1) has, by the BCH formula,
//!
//! ```text
//! log K_h = hX + h³ (Σγ³) E₃ + h⁵ ((Σγ⁵) E₅ + c₅ [X,[X,E₃]]) + h⁷ (… E₇, [E₃,[X,E₃]], …) + …
//! ```
//!
//! and a processor `P = exp(Z)` changes it to `log Ψ = e^{ad Z} log K = log K + [Z, hX] + …`.
//! Grade by grade (grade = power of h), the terms conjugation can cancel are exactly those in the
//! image of `ad_X` — commutators with X of what lies one grade below:
//! - **grade 3**: the only element is E₃ and grade 2 is empty, so nothing: effective order 4
//!   needs Σγ³ = 0, the classical order-4 condition. Processing cannot make order 4 cheaper for a
//!   black-box symmetric method; it could only remove the `[X,[X,E₃]]` part of an order-4
//!   composition's h⁵ error, and for the triple jump that part is 0.14 against 5.29 on E₅
//!   (`tools/processing_conditions.txt`). No effective-order-4 scheme is shipped here; order 4 at
//!   order-2 cost comes from the modified Hamiltonian (`mechanics::modified`).
//! - **grade 5**: E₅ stays (Σγ⁵ = 0 needed); `[X,[X,E₃]] = ad_X [X,E₃]` is removed by a
//!   processor with `Z = h⁴ c₅ [X,E₃] + …`. Effective order 6 needs Σγ = 1, Σγ³ = Σγ⁵ = 0 —
//!   three conditions instead of the four of order 6 — and the freedom goes into a much smaller
//!   error.
//! - **grade 7**: E₇ and `[E₃,[X,E₃]]` stay, the two X-commutators `[X,[X,E₅]]` and
//!   `ad_X⁴ E₃` go: effective order 8 needs five conditions instead of eight.
//!
//! For a **two-part splitting** `e^{a₁hA} e^{b₁hB} …` processing removes more (grade 3 is spanned
//! by `[A,[A,B]]` and `[B,[A,B]]`, and `[[A,B], A+B]` is removable), but the palindromic kernels with
//! two B flows never reach it: their h³ error `α[A,[A,B]] + β[B,[A,B]]` has α = β only for
//! `a² − a/2 + 1/12 = 0`, which has no real root (the script prints the derivation). So the
//! kinetic–kick splittings are processed here as black-box symmetric methods like the others.
//!
//! ## Schemes ([`ProcessingScheme`]) and how they were checked
//! `tools/processing_conditions.py` composes the kernel and processor in the free associative
//! algebra on X, E₃, …, E₉ in 50-digit arithmetic, measures `log(P K P⁻¹) − hX` word by word, and
//! projects the printed digits onto the exact solution set (Gauss–Newton, minimum-norm steps);
//! its output `tools/processing_conditions.txt` is compared with the crate's coefficients by
//! `tests/processing.rs`. `s·C^{1/p}` (stages × the largest leading-error coefficient C^{1/p}) is
//! the cost for a given accuracy, up to a common factor:
//!
//! | scheme | kernel stages | processor stages | eff. order | residual of the printed digits | to an exact solution | C (grade p+1) | s·C^{1/p} |
//! |---|---|---|---|---|---|---|---|
//! | [`ProcessingScheme::blanes_6`] | 7 | 10 | 6 | 1.1e-15 | 3.2e-16 | 0.141 | 5.05 |
//! | [`ProcessingScheme::blanes_casas_murua_6_11`] | 11 | 12 | 6 | 4.1e-16 | 5.3e-15 | 1.2e-3 | 3.59 |
//! | [`ProcessingScheme::blanes_casas_murua_6_13`] | 13 | 12 | 6 | 3.2e-16 | 3.0e-15 | 3.4e-4 | 3.43 |
//! | Blanes–Casas–Murua order 8 (not shipped, see below) | 13 | 20 | 8 | 4.0e-16 | 1.5e-15 | 8.5e-4 | 5.37 |
//! | Kahan–Li 6 ([`crate::CompositionScheme::kahan_li_6`]), unprocessed | 9 | — | 6 | 6e-27 | — | 3.6e-2 | 5.16 |
//! | Kahan–Li 8 ([`crate::CompositionScheme::kahan_li_8`]), unprocessed | 17 | — | 8 | 1e-27 | — | 7.5e-4 | 6.92 |
//!
//! So the 11- and 13-stage processed kernels reach order 6 for ~0.7× the work of the best
//! composition (the 7-stage one is the cheapest step, at Kahan–Li's accuracy per work). The
//! effective orders fitted on the rigid body and the heavy top, for Lie–Poisson, Euler–Poincaré,
//! the Strang splitting and the kinetic–kick, are within 0.2 of 6 (`tests/processing.rs`).
//!
//! The order-8 set of Blanes, Casas & Murua (13 + 20 stages, ~0.78× Kahan–Li 8's work) passes the
//! 50-digit check but is not shipped: on the Strang splitting its errors between 1e-8 and 1e-12
//! fall with local slopes 7.2–9.7 (the optimised h⁸ term competes with the next ones down to
//! round-off), so its order could not be fitted to ±0.2 in double precision.
//!
//! ## Cost and conventions
//! - A step costs the kernel's s basic steps; a read costs P's r basic steps (once per step at
//!   most: the output is cached until the next step); the first step also applies P⁻¹.
//! - P is taken for |h| (the processor of a symmetric kernel is even in h), so Ψ is symmetric;
//!   a change of |h| re-processes once (P then P⁻¹), e.g. at a run's shortened last step.
//! - Everything the basic method keeps (Casimirs, the momentum map, g on G, symplecticity) is
//!   kept by the output: P, K and P⁻¹ are all compositions of the basic method.
//! - The basic method must be symmetric: [`ComposedKernel::new`] and [`Processed::new`] refuse
//!   anything else by name (Lie–Poisson with θ ≠ ½, RK4, …).

mod composed_kernel;
mod kernel;
mod processed;
mod scheme;

pub use composed_kernel::ComposedKernel;
pub use kernel::ProcessingKernel;
pub use processed::Processed;
pub use scheme::ProcessingScheme;
