//! The cost of `lie-sim run`'s loop against the steps it runs (issue #26, item 6: a run that
//! writes no rows between t = 0 and T costs ≤ 1.2× the same steps as `trade` times them).
//!
//! Per method on the free rigid body (𝕀 = diag(2, 3, 4), Π₀ = (1, ½, −0.3), R reconstructed,
//! h = 0.01, 10⁶ steps), two rows, each on a simulation built outside the timing by the same
//! `lie_sim::build::build_with` the command uses:
//! - `run_loop/<method>/run`: `lie_sim::run::run_simulation`, the whole of `lie-sim run` after
//!   the scene is read — the energy and Casimir monitor after every step, the two rows at
//!   t = 0 and T (`stride` beyond the run), the CSV written to a temporary file and renamed;
//! - `run_loop/<method>/steps`: `lie_sim::measure::timed_run`, the loop `trade` times (the steps,
//!   the invariants sampled every 8 steps).
//!
//! The ratio run/steps is the loop's overhead. Compare ratios within one run only.
//! Run: `cargo bench -p lie-integrators --bench run_loop`.

use criterion::{criterion_group, criterion_main, BatchSize, Criterion};
use lie_sim::build::build_with;
use lie_sim::scene::{Overrides, Scene};
use std::hint::black_box;

/// Enough steps that the run's fixed costs (the file created, synced to disk and renamed, which
/// is what makes its output durable) are a small part of the time: the bench compares per-step
/// costs.
const STEPS: u64 = 1_000_000;
const H: f64 = 0.01;

/// The scene of `method` (its `[integrator]` lines besides step and duration).
fn scene(method: &str) -> Scene {
    let text = format!(
        "name = \"run loop\"\n\
         [system]\nkind = \"free-rigid-body\"\ninertia = [2.0, 3.0, 4.0]\n\
         [initial]\nmomentum = [1.0, 0.5, -0.3]\n\
         attitude = {{ quaternion = [0.8660254037844387, 0.0, 0.0, 0.5] }}\n\
         [integrator]\n{method}\nstep = {H}\nduration = {}\nreconstruct = true\n\
         [output]\nstride = {}\n",
        STEPS as f64 * H,
        2 * STEPS
    );
    Scene::parse(&text, "run_loop", "run_loop", Overrides::default()).expect("a valid scene")
}

fn bench(c: &mut Criterion) {
    let dir = std::env::temp_dir().join(format!("lie-sim-run-loop-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("a temporary directory");
    let out = dir.join("run.csv");
    let methods = [
        (
            "lie_poisson_cayley_half",
            "method = \"lie-poisson\"\ntau = \"cayley\"\ntheta = 0.5",
        ),
        ("rk4", "method = \"rk4\""),
        ("splitting", "method = \"splitting\""),
    ];
    let mut group = c.benchmark_group("run_loop");
    group.sample_size(10);
    for (name, method) in methods {
        let scene = scene(method);
        assert_eq!(scene.steps(), STEPS);
        let build = || {
            build_with(
                &scene.system,
                &scene.method,
                scene.reconstruct,
                &scene.solver,
                scene.variable,
            )
            .expect("the scene builds")
        };
        group.bench_function(format!("{name}/run"), |b| {
            b.iter_batched(
                build,
                |mut sim| {
                    let summary = lie_sim::run::run_simulation(sim.as_mut(), &scene, &out, false)
                        .expect("the run completes");
                    assert_eq!(summary.rows, 2);
                    black_box(summary.max_energy_error)
                },
                BatchSize::LargeInput,
            )
        });
        group.bench_function(format!("{name}/steps"), |b| {
            b.iter_batched(
                build,
                |mut sim| {
                    let timed = lie_sim::measure::timed_run(sim.as_mut(), scene.duration, H)
                        .expect("the run completes");
                    black_box(timed)
                },
                BatchSize::LargeInput,
            )
        });
    }
    group.finish();
    let _ = std::fs::remove_dir_all(&dir);
}

criterion_group!(benches, bench);
criterion_main!(benches);
