//! The runner of the suites' property tests: proptest's, called through one function per strategy.
//!
//! A `proptest!` block compiles proptest's runner (case generation, shrinking, failure
//! persistence) once per test: its strategy carries a closure of the test's own type, and so does
//! its body. Over the suites' groups and bundles those copies of the runner outweigh the checks
//! they run. Here the test is taken as `&dyn Fn` and the strategy as given, so that every test
//! drawing from one strategy type (three algebra elements of one group, say) shares one compiled
//! runner.

use proptest::strategy::Strategy;
use proptest::test_runner::{contextualize_config, Config, TestRunner};

/// Runs `test` on `cases` values drawn from `strategy` (proptest's `PROPTEST_*` variables apply,
/// as in `proptest!`), and panics with proptest's report of the minimal failing value if `test`
/// panics on any: the failure is shrunk, and its seed persisted beside `source_file` (pass
/// `file!()`) under proptest's default failure persistence, as `proptest!` does. `name` is the
/// test's path, for proptest's messages.
pub fn check_cases<S: Strategy>(
    name: &'static str,
    source_file: &'static str,
    cases: u32,
    strategy: &S,
    test: &dyn Fn(S::Value),
) {
    let mut config = contextualize_config(Config::with_cases(cases));
    config.test_name = Some(name);
    config.source_file = Some(source_file);
    let mut runner = TestRunner::new(config);
    if let Err(e) = runner.run(strategy, |value| {
        test(value);
        Ok(())
    }) {
        panic!("{e}\n{runner}");
    }
}
