//! The Jacobians of the actions on points (`∂(g·p)/∂p`, and `∂(g·p)/∂g` in both trivializations)
//! against central finite differences, for every group that acts on ℝⁿ.

use nalgebra::{SVector, Vector2, Vector3};

lie_groups::action_suite!(so2_action, lie_groups::So2, Vector2<f64>, 2, 3.0);
lie_groups::action_suite!(so3_action, lie_groups::So3, Vector3<f64>, 3, 1.8);
lie_groups::action_suite!(se2_action, lie_groups::Se2, Vector2<f64>, 2, 3.0);
lie_groups::action_suite!(se3_action, lie_groups::Se3, Vector3<f64>, 3, 1.8);
lie_groups::action_suite!(r3_action, lie_groups::Rn<3>, SVector<f64, 3>, 3, 10.0);
#[cfg(feature = "faer")]
lie_groups::action_suite!(so4_action, lie_groups::SoN<4>, faer::Col<f64>, 4, 1.2);
#[cfg(feature = "faer")]
lie_groups::action_suite!(gl3_action, lie_groups::GlN<3>, faer::Col<f64>, 3, 0.5);
