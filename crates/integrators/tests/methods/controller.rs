//! The PI step-size controller against its formula written with powers, as Hairer's `dopri5.f`
//! writes it: `fac = safety · err^(−α) · err_prev^β`, clamped, `err_prev ≥ 1e-4`, no growth
//! after a rejection, and a rejection retried with `safety · err^(−1/k)`.

use integrators::adaptive::Controller;

/// The factor of an accepted step from powers, with `prev` the last accepted error (floored).
fn accepted(c: &Controller, err: f64, prev: f64, after_rejection: bool) -> f64 {
    let fac = if err == 0.0 {
        c.max_factor
    } else {
        (c.safety * err.powf(-c.alpha) * prev.max(1e-4).powf(c.beta))
            .clamp(c.min_factor, c.max_factor)
    };
    if after_rejection {
        fac.min(1.0)
    } else {
        fac
    }
}

#[test]
fn factors_follow_the_pi_formula_with_its_floor_clamps_and_rejections() {
    for mut c in [
        Controller::pi(5, 0.04).with_limits(0.2, 10.0),
        Controller::pi(8, 0.0).with_limits(1.0 / 3.0, 6.0),
        Controller::elementary(2),
    ] {
        let template = c;
        // A sequence through every branch: ordinary errors, a tiny one (the floor), an exact
        // step (err = 0), rejections (finite, infinite, NaN), and the accepted step after them.
        let errs = [
            0.3,
            0.9,
            1e-7,
            0.5,
            0.0,
            0.02,
            3.0,
            250.0,
            0.7,
            f64::INFINITY,
            f64::NAN,
            1e-3,
            1.0,
        ];
        let mut prev = 1e-4;
        let mut rejected = false;
        for err in errs {
            let d = c.decide(err);
            if err.is_nan() || err > 1.0 {
                let want = if err.is_finite() {
                    (template.safety * err.powf(-template.reject_exponent))
                        .max(template.min_factor)
                        .min(1.0)
                } else {
                    template.min_factor
                };
                assert!(!d.accept, "err {err} accepted");
                assert!(
                    (d.factor - want).abs() <= 1e-14 * want,
                    "reject {err}: {} vs {want}",
                    d.factor
                );
                rejected = true;
            } else {
                let want = accepted(&template, err, prev, rejected);
                assert!(d.accept, "err {err} rejected");
                assert!(
                    (d.factor - want).abs() <= 1e-14 * want,
                    "β = {}, err {err}: {} vs {want}",
                    template.beta,
                    d.factor
                );
                prev = err;
                rejected = false;
            }
        }
        // reset forgets the history: the next factor is that of a fresh controller.
        c.reset();
        let mut fresh = template;
        assert_eq!(c.decide(0.25), fresh.decide(0.25));
    }
}

#[test]
fn the_remembered_error_is_floored_at_1e_minus_4() {
    // After a nearly exact step the next factor uses 1e-4, not 1e-12: with β = 0.04 the two
    // differ by (1e-8)^0.04 ≈ 0.48, so a missing floor fails this test.
    let mut c = Controller::pi(5, 0.04).with_limits(1e-6, 1e6);
    c.decide(1e-12);
    let got = c.decide(0.5).factor;
    let want = c.safety * 0.5f64.powf(-c.alpha) * 1e-4f64.powf(c.beta);
    assert!((got - want).abs() <= 1e-14 * want, "{got} vs {want}");
}
