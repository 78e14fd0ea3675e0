//! Every run ends exactly at T: after n steps of h an integrator's time is the rounded n·fl(h)
//! (`integrators::Clock`), not n roundings away from it, so an output requested at T is met and
//! a force schedule sees the right t. Plain accumulation fails these tests: 2000 steps of 0.05
//! end at 99.99999999999646 (checked by replacing `Clock::advance` by `t += h`).

use integrators::adaptive::RkmkDop853;
use integrators::baselines::{QuaternionDopri5, QuaternionRk4};
use integrators::dense_output::integrate_dense;
use integrators::processing::{ComposedKernel, Processed, ProcessingScheme};
use integrators::splitting::{KineticKick, Splitting, SplittingScheme};
use integrators::{
    Composition, CompositionScheme, EulerPoincare, GraggBulirschStoer, Integrator, LiePoisson,
    Rkmk4,
};
use lie_groups::{Cayley, ExpMap, LieGroup, So3};
use mechanics::exact::FreeBodyFlow;
use mechanics::{HeavyTop, RigidBody};
use nalgebra::Vector3;

const PI0: Vector3<f64> = Vector3::new(0.3, -0.2, 0.5);

fn body() -> RigidBody {
    RigidBody::principal([1.0, 2.0, 3.0]).unwrap()
}

fn top() -> HeavyTop {
    HeavyTop::principal([1.0, 2.0, 3.0], 1.0, 9.81, Vector3::new(0.0, 0.1, 0.5)).unwrap()
}

/// n steps of h from t = 0 end at `end` exactly, and a dense run asked for output at `end` sees it.
fn ends_on_time<I: Integrator + Clone>(name: &str, method: I, h: f64, n: usize, end: f64) {
    let mut m = method.clone();
    for _ in 0..n {
        m.step(h).unwrap();
    }
    assert_eq!(m.time(), end, "{name}: {n} steps of {h}");
    let mut m = method;
    let mut seen = Vec::new();
    integrate_dense(&mut m, h, n, &[end], |t, _, _| seen.push(t), &[]).unwrap();
    assert_eq!(seen, [end], "{name}: the output at T = {end}");
}

fn every_method(h: f64, n: usize, end: f64) {
    let g = Some(So3::identity());
    ends_on_time(
        "lie-poisson",
        LiePoisson::<So3, Cayley, _>::new(body(), 0.5, PI0, g).unwrap(),
        h,
        n,
        end,
    );
    ends_on_time(
        "lie-poisson θ = 0, heavy top",
        LiePoisson::<So3, ExpMap, _>::new(top(), 0.0, PI0, g).unwrap(),
        h,
        n,
        end,
    );
    ends_on_time(
        "euler-poincare",
        EulerPoincare::<So3, Cayley, _>::from_momentum(body(), 0.5, PI0, g).unwrap(),
        h,
        n,
        end,
    );
    ends_on_time(
        "rk4",
        QuaternionRk4::new(body(), PI0, g).unwrap(),
        h,
        n,
        end,
    );
    ends_on_time("rkmk4", Rkmk4::new(top(), PI0, g).unwrap(), h, n, end);
    // The embedded pairs' fixed steps too (their adaptive steps land on chosen end times).
    ends_on_time(
        "quaternion dopri5, fixed steps",
        QuaternionDopri5::new(top(), PI0, g).unwrap(),
        h,
        n,
        end,
    );
    ends_on_time(
        "rkmk dop853, fixed steps",
        RkmkDop853::new(body(), PI0, g).unwrap(),
        h,
        n,
        end,
    );
    ends_on_time(
        "gragg-bulirsch-stoer",
        GraggBulirschStoer::new(body(), PI0, g).unwrap(),
        h,
        n,
        end,
    );
    ends_on_time(
        "splitting",
        Splitting::new(top(), PI0, g).unwrap(),
        h,
        n,
        end,
    );
    ends_on_time(
        "kinetic-kick",
        KineticKick::new(
            top(),
            FreeBodyFlow::new(top().body()),
            SplittingScheme::blanes_moan_4(),
            PI0,
            g,
        )
        .unwrap(),
        h,
        n,
        end,
    );
    // Σ γᵢ h = h only up to rounding: the composition keeps its own clock
    ends_on_time(
        "composition",
        Composition::new(
            LiePoisson::<So3, Cayley, _>::new(body(), 0.5, PI0, g).unwrap(),
            CompositionScheme::kahan_li_6(),
        )
        .unwrap(),
        h,
        n,
        end,
    );
    ends_on_time(
        "processed splitting",
        Processed::new(
            ComposedKernel::new(
                Splitting::new(top(), PI0, g).unwrap(),
                ProcessingScheme::blanes_6(),
            )
            .unwrap(),
        )
        .unwrap(),
        h,
        n,
        end,
    );
}

#[test]
fn runs_end_exactly_at_t_and_meet_an_output_there() {
    every_method(0.05, 2000, 100.0);
    every_method(0.01, 1000, 10.0);
    every_method(-0.01, 700, -7.0);
}
