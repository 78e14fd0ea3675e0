//! Steps one method of the trade tables n times: the driver for load-independent per-step costs
//! (instruction counts) when the machine is shared and wall-clock figures are not to be trusted.
//! `cargo xtask docs --only callgrind-step-cost` runs it under callgrind for every method of
//! docs/benchmarks.md's instruction tables; by hand:
//!
//! ```text
//! cargo build --release -p lie-integrators --example step_cost
//! for n in 2000 4000; do
//!   valgrind --tool=callgrind --callgrind-out-file=/tmp/cg.$n \
//!     target/release/examples/step_cost free/processed/blanes-casas-murua-6-11 $n
//! done
//! # instructions per step = (Ir(4000) − Ir(2000)) / 2000, Ir from the "summary:" line
//! ```
//!
//! The systems and steps are those of `benches/splitting.rs` (free body 𝕀 = diag(1, 2, 3),
//! Π₀ = (0.5, 1, 0.2); heavy top mgχ = (0, 0.1, 0.5); h = 0.01; R reconstructed). Methods:
//! `<free|top>/rk4-hand`, `…/rk4`, `…/rkmk4`, `…/strang`, `…/lp-cayley-0.5`, `…/lp-cayley-0`,
//! `free/modified/<exp|cayley>/<0.5|0>/<4|6>`, `…/processed/<scheme>` (steps only) and
//! `…/processed-read/<scheme>` (a step and a read, which applies the processor),
//! `top/kinetic-kick/<strang|blanes-moan-4|blanes-moan-6>`, `top/processed-kk/<scheme>`;
//! on the generalized rigid body of SO(n) (`so-n/<n>/…`, n ∈ {3, 4, 5, 6, 8, 10, 20, 50}, the
//! sizes `lie-sim` compiles; J = diag(1 + i/n), a generic |M| ≈ 1 as in `benches/integrators.rs`,
//! R reconstructed): `…/lp-cayley-0.5` (Newton), `…/lp-cayley-0.5-fp` (fixed point),
//! `…/rkmk4` — the per-step costs `lie-sim`'s work limit counts (`crates/lie-sim/src/bounds.rs`);
//! the embedded pairs `…/fixed/<pair>` (fixed steps of h) and `…/adaptive/<pair>` (n accepted
//! steps under error control at rtol = atol = 1e-9, rejected attempts included), for `<pair>` one
//! of `dopri5`, `dop853` (on (q, Π)), `rkmk-dopri5`, `rkmk-dop853`: the price of error control
//! per accepted step.

#[path = "../benches/common/hand_rk4.rs"]
mod hand_rk4;

use hand_rk4::HandRk4;
use integrators::adaptive::{Adaptive, EmbeddedPair, RkmkDop853, RkmkDopri5, Tolerance};
use integrators::baselines::{QuaternionDop853, QuaternionDopri5, QuaternionRk4, Rkmk4};
use integrators::processing::{Processed, ProcessingScheme};
use integrators::splitting::{KineticKick, Splitting, SplittingScheme};
use integrators::{Integrator, IntegratorError, LiePoisson, SolverConfig, SolverKind, System};
use lie_groups::{Cayley, ExpMap, LieGroup, So3, SoN, Vector};
use mechanics::exact::FreeBodyFlow;
use mechanics::modified::{ModifiedLiePoisson, ModifiedScheme};
use mechanics::systems::{GeneralizedRigidBody, HeavyTop, RigidBody};
use nalgebra::Vector3;
use std::hint::black_box;

const H: f64 = 0.01;

fn g0() -> So3 {
    So3::exp(&Vector3::new(0.3, -0.5, 0.8))
}

fn steps<I: Integrator<Group = So3>>(
    mut i: I,
    n: usize,
    read: bool,
) -> Result<f64, IntegratorError> {
    let mut acc = 0.0;
    for _ in 0..n {
        i.step(black_box(H))?;
        if read {
            acc += i.momentum()[0];
        }
    }
    Ok(acc + i.momentum()[0])
}

/// n accepted steps of `pair` under error control at 1e-9 (towards a time it does not reach).
fn accepted<P: EmbeddedPair<Group = So3>>(pair: P, n: usize) -> Result<f64, IntegratorError> {
    let mut run = Adaptive::new(pair, Tolerance::uniform(1e-9)?);
    for _ in 0..n {
        run.step_towards(black_box(1e9))?;
    }
    Ok(run.method().momentum()[0])
}

/// Fixed steps (`adaptive` false) or accepted steps under error control of the pair `name`.
fn pair<S: System<So3> + Clone>(
    system: S,
    name: &str,
    adaptive: bool,
    n: usize,
) -> Result<f64, IntegratorError> {
    let (pi0, g) = (Vector3::new(0.5, 1.0, 0.2), Some(g0()));
    match (name, adaptive) {
        ("dopri5", false) => steps(QuaternionDopri5::new(system, pi0, g)?, n, false),
        ("dopri5", true) => accepted(QuaternionDopri5::new(system, pi0, g)?, n),
        ("dop853", false) => steps(QuaternionDop853::new(system, pi0, g)?, n, false),
        ("dop853", true) => accepted(QuaternionDop853::new(system, pi0, g)?, n),
        ("rkmk-dopri5", false) => steps(RkmkDopri5::new(system, pi0, g)?, n, false),
        ("rkmk-dopri5", true) => accepted(RkmkDopri5::new(system, pi0, g)?, n),
        ("rkmk-dop853", false) => steps(RkmkDop853::new(system, pi0, g)?, n, false),
        ("rkmk-dop853", true) => accepted(RkmkDop853::new(system, pi0, g)?, n),
        _ => Err(IntegratorError::InvalidParameter {
            reason: format!("unknown embedded pair {name:?} (see the example's doc comment)"),
        }),
    }
}

/// n steps of `method` on the generalized rigid body of SO(N).
fn so_n<const N: usize>(method: &str, n: usize) -> Result<f64, IntegratorError> {
    let j: Vec<f64> = (0..N).map(|i| 1.0 + i as f64 / N as f64).collect();
    let body = GeneralizedRigidBody::<N>::new(&j)?;
    let d = SoN::<N>::DIM;
    let mu0 = <<SoN<N> as LieGroup>::Algebra as Vector>::from_fn(d, |p| {
        ((p as f64 * 0.7548776662).fract() - 0.5) * 2.0 / (d as f64).sqrt()
    });
    let g0 = Some(SoN::<N>::identity());
    let read = |mut i: Box<dyn Integrator<Group = SoN<N>>>| -> Result<f64, IntegratorError> {
        for _ in 0..n {
            i.step(black_box(H))?;
        }
        Ok(Vector::get(&i.momentum(), 0))
    };
    match method {
        "lp-cayley-0.5" => read(Box::new(LiePoisson::<SoN<N>, Cayley, _>::new(
            body, 0.5, mu0, g0,
        )?)),
        "lp-cayley-0.5-fp" => read(Box::new(
            LiePoisson::<SoN<N>, Cayley, _>::new(body, 0.5, mu0, g0)?.with_solver(SolverConfig {
                kind: SolverKind::FixedPoint,
                ..SolverConfig::default()
            }),
        )),
        "rkmk4" => read(Box::new(Rkmk4::new(body, mu0, g0)?)),
        _ => Err(IntegratorError::InvalidParameter {
            reason: format!("unknown SO(n) method {method:?} (see the example's doc comment)"),
        }),
    }
}

fn run<S: System<So3> + Clone + integrators::splitting::SplitSystem<So3>>(
    system: S,
    flow: FreeBodyFlow,
    mgchi: Vector3<f64>,
    method: &str,
    n: usize,
) -> Result<f64, IntegratorError> {
    let pi0 = Vector3::new(0.5, 1.0, 0.2);
    let g = Some(g0());
    let parts: Vec<&str> = method.split('/').collect();
    let scheme = |name: &str| name.parse::<ProcessingScheme>();
    match parts.as_slice() {
        ["rk4-hand"] => {
            let moments = [1.0, 2.0, 3.0];
            // As in the bench: the free body's hand-written step has no gravity code at all.
            if mgchi == Vector3::zeros() {
                let mut hand = HandRk4::<false>::new(moments, mgchi, pi0, g0().as_matrix());
                for _ in 0..n {
                    hand.step(black_box(H));
                }
                Ok(hand.pi[0])
            } else {
                let mut hand = HandRk4::<true>::new(moments, mgchi, pi0, g0().as_matrix());
                for _ in 0..n {
                    hand.step(black_box(H));
                }
                Ok(hand.pi[0])
            }
        }
        ["rk4"] => steps(QuaternionRk4::new(system, pi0, g)?, n, false),
        ["rkmk4"] => steps(Rkmk4::new(system, pi0, g)?, n, false),
        ["strang"] => steps(Splitting::new(system, pi0, g)?, n, false),
        ["lp-cayley-0.5"] => steps(
            LiePoisson::<So3, Cayley, _>::new(system, 0.5, pi0, g)?,
            n,
            false,
        ),
        ["lp-cayley-0"] => steps(
            LiePoisson::<So3, Cayley, _>::new(system, 0.0, pi0, g)?,
            n,
            false,
        ),
        ["processed", name] => steps(
            Processed::composition(Splitting::new(system, pi0, g)?, scheme(name)?)?,
            n,
            false,
        ),
        ["processed-read", name] => steps(
            Processed::composition(Splitting::new(system, pi0, g)?, scheme(name)?)?,
            n,
            true,
        ),
        ["kinetic-kick", name] => steps(
            KineticKick::new(system, flow, SplittingScheme::by_name(name)?, pi0, g)?,
            n,
            false,
        ),
        ["processed-kk", name] => steps(
            Processed::composition(
                KineticKick::new(system, flow, SplittingScheme::strang(), pi0, g)?,
                scheme(name)?,
            )?,
            n,
            false,
        ),
        ["fixed", name] => pair(system, name, false, n),
        ["adaptive", name] => pair(system, name, true, n),
        _ => Err(IntegratorError::InvalidParameter {
            reason: format!("unknown method {method:?} (see the example's doc comment)"),
        }),
    }
}

fn main() -> Result<(), IntegratorError> {
    let args: Vec<String> = std::env::args().collect();
    let (Some(method), Some(n)) = (args.get(1), args.get(2).and_then(|s| s.parse().ok())) else {
        eprintln!("usage: step_cost <free|top|so-n>/<method> <steps>");
        std::process::exit(2);
    };
    let body = RigidBody::principal([1.0, 2.0, 3.0])?;
    let x = if let Some(m) = method.strip_prefix("free/modified/") {
        let p: Vec<&str> = m.split('/').collect();
        let [tau, theta, order] = p.as_slice() else {
            eprintln!("free/modified/<exp|cayley>/<0.5|0>/<4|6>");
            std::process::exit(2);
        };
        let scheme = ModifiedScheme::new(
            theta.parse().unwrap_or(f64::NAN),
            order.parse().unwrap_or(0),
        )?;
        let pi0 = Vector3::new(0.5, 1.0, 0.2);
        if *tau == "exp" {
            steps(
                ModifiedLiePoisson::<ExpMap>::with_scheme(body, scheme, pi0, Some(g0()))?,
                n,
                false,
            )?
        } else {
            steps(
                ModifiedLiePoisson::<Cayley>::with_scheme(body, scheme, pi0, Some(g0()))?,
                n,
                false,
            )?
        }
    } else if let Some(m) = method.strip_prefix("so-n/") {
        let (size, m) = m.split_once('/').unwrap_or((m, ""));
        match size {
            "3" => so_n::<3>(m, n)?,
            "4" => so_n::<4>(m, n)?,
            "5" => so_n::<5>(m, n)?,
            "6" => so_n::<6>(m, n)?,
            "8" => so_n::<8>(m, n)?,
            "10" => so_n::<10>(m, n)?,
            "20" => so_n::<20>(m, n)?,
            "50" => so_n::<50>(m, n)?,
            _ => {
                eprintln!("so-n/<3|4|5|6|8|10|20|50>/<lp-cayley-0.5|lp-cayley-0.5-fp|rkmk4>");
                std::process::exit(2);
            }
        }
    } else if let Some(m) = method.strip_prefix("free/") {
        let flow = FreeBodyFlow::new(&body);
        run(body, flow, Vector3::zeros(), m, n)?
    } else if let Some(m) = method.strip_prefix("top/") {
        let mgchi = Vector3::new(0.0, 0.1, 0.5);
        let top = HeavyTop::principal([1.0, 2.0, 3.0], 1.0, 1.0, mgchi)?;
        let flow = FreeBodyFlow::new(top.body());
        run(top, flow, mgchi, m, n)?
    } else {
        eprintln!("usage: step_cost <free|top|so-n>/<method> <steps>");
        std::process::exit(2);
    };
    println!("{x}");
    Ok(())
}
