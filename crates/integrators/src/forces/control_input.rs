//! [`ControlInput`]: a control u(t) entering through an input map, `F_ext = B(g) u(t)`.

use crate::forces::{ExternalForce, Schedule};
use crate::IntegratorError;
use lie_groups::{LieGroup, Vector};

/// An input map `B(g): ℝᵏ → 𝔤*`, `u ↦ B(g) u`, linear in the inputs: the `B(x) u` of a control
/// system `ẋ = f(x) + B(x) u` written on T*G (Bloch, *Nonholonomic Mechanics and Control*, 2nd ed.
/// 2015, §6.1; Bullo–Lewis, *Geometric Control of Mechanical Systems*, 2005, §4.4: the control
/// forces F_j(g) of a forced affine connection system, here left-trivialized). Column j is the
/// body-frame covector (torque, wrench, generalized force) input j applies per unit, in the basis
/// of the algebra's `vee`; its power is `⟨B(g) u, ξ⟩`.
pub trait InputMap<G: LieGroup> {
    /// k, the number of inputs.
    fn inputs(&self) -> usize;
    /// `B(g) u` for the k inputs u; `g` is `None` when [`Self::needs_configuration`] is false and
    /// the run does not reconstruct g.
    fn apply(&self, g: Option<&G>, u: &[f64]) -> G::Algebra;
    /// Whether B depends on g (then integrators require and pass g). Body-fixed actuators do not.
    fn needs_configuration(&self) -> bool {
        false
    }
    /// The components of 𝔤* some column of B may have nonzero, `None` for any (the provided
    /// answer; [`crate::forces::ExternalForce::acts_on`]).
    fn acts_on(&self) -> Option<Vec<usize>> {
        None
    }
}

/// A body-fixed input map: B constant in the body frame, `B u = Σⱼ uⱼ bⱼ` with columns
/// `bⱼ ∈ 𝔤*` — actuators fixed to the body (thrusters, reaction-wheel motors, rotors, fins).
///
/// ```
/// use integrators::forces::{BodyInputMap, InputMap};
/// use lie_groups::Se3;
/// use nalgebra::Vector6;
///
/// // A thrust along the body's third axis and a torque about it, on SE(3) ((τ, f) ordering).
/// let b = BodyInputMap::<Se3>::new(vec![
///     Vector6::new(0.0, 0.0, 0.0, 0.0, 0.0, 1.0),
///     Vector6::new(0.0, 0.0, 1.0, 0.0, 0.0, 0.0),
/// ])?;
/// assert_eq!(b.apply(None, &[9.81, 0.5]), Vector6::new(0.0, 0.0, 0.5, 0.0, 0.0, 9.81));
/// # Ok::<(), integrators::IntegratorError>(())
/// ```
#[derive(Debug, Clone)]
pub struct BodyInputMap<G: LieGroup> {
    columns: Vec<G::Algebra>,
}

impl<G: LieGroup> BodyInputMap<G> {
    /// The map with columns `bⱼ` (at least one; each of the algebra's dimension and finite).
    pub fn new(columns: Vec<G::Algebra>) -> Result<Self, IntegratorError> {
        if columns.is_empty() {
            return Err(IntegratorError::InvalidParameter {
                reason: "an input map needs at least one column (one input)".into(),
            });
        }
        for (j, b) in columns.iter().enumerate() {
            if b.dim() != G::dim() {
                return Err(IntegratorError::InvalidParameter {
                    reason: format!(
                        "input map column {j} has {} entries, the algebra of {} has {}",
                        b.dim(),
                        G::name(),
                        G::dim()
                    ),
                });
            }
            if !b.is_finite() {
                return Err(IntegratorError::InvalidParameter {
                    reason: format!("input map column {j} = {:?} is not finite", b.to_vec()),
                });
            }
        }
        Ok(Self { columns })
    }
    /// The map whose columns are the basis covectors `e_{i₀}, e_{i₀+1}, …, e_{i₀+k−1}`: input j
    /// drives momentum component i₀ + j directly (a body torque on the first three components of
    /// 𝔰𝔬(3)* or 𝔰𝔢(3)*, wheel motors on the rotor momenta of a gyrostat).
    pub fn components(first: usize, count: usize) -> Result<Self, IntegratorError> {
        let n = G::dim();
        if count == 0 || first + count > n {
            return Err(IntegratorError::InvalidParameter {
                reason: format!(
                    "components {first}..{} are not a non-empty range of the {n} components of \
                     the algebra of {}",
                    first + count,
                    G::name()
                ),
            });
        }
        Self::new(
            (0..count)
                .map(|j| G::Algebra::basis(n, first + j))
                .collect(),
        )
    }
    /// The columns `bⱼ`.
    pub fn columns(&self) -> &[G::Algebra] {
        &self.columns
    }
}

impl<G: LieGroup> InputMap<G> for BodyInputMap<G> {
    fn inputs(&self) -> usize {
        self.columns.len()
    }
    /// `Σⱼ uⱼ bⱼ` (no allocation for stack algebras).
    #[inline]
    fn apply(&self, _g: Option<&G>, u: &[f64]) -> G::Algebra {
        self.columns
            .iter()
            .zip(u)
            .fold(G::Algebra::zeros(G::dim()), |acc, (b, &uj)| acc.axpy(uj, b))
    }
    /// The components where some column `bⱼ` is nonzero.
    fn acts_on(&self) -> Option<Vec<usize>> {
        Some(
            (0..G::dim())
                .filter(|&i| self.columns.iter().any(|b| b.get(i) != 0.0))
                .collect(),
        )
    }
}

/// The control force `F_ext(t, g) = B(g) u(t)`: the inputs u(t) of a [`Schedule`] (constant or
/// piecewise linear) through the input map B ([`InputMap`]; a body-fixed [`BodyInputMap`] by
/// default). It does not read ξ, so the splittings kick it exactly and keep their order.
/// [`crate::forces::BodyTorque`] is the case B = I.
///
/// Its work over a run is `∫ ⟨B(g) u(t), ξ⟩ dt`; the spatial momentum map `Ad*_{g⁻¹} μ` moves by
/// the applied spatial impulse `∫ Ad*_{g⁻¹} B(g) u dt`, so the components of J that every
/// column of `Ad*_{g⁻¹} B(g)` misses are kept: an internal torque (a reaction-wheel motor,
/// `mechanics::Gyrostat::wheel_torques`) leaves the total angular momentum unchanged.
#[derive(Debug, Clone)]
pub struct ControlInput<G: LieGroup, B = BodyInputMap<G>> {
    schedule: Schedule,
    map: B,
    _group: core::marker::PhantomData<fn() -> G>,
}

impl<G: LieGroup, B: InputMap<G>> ControlInput<G, B> {
    /// The inputs of `schedule` through `map`; the schedule's values must have one entry per
    /// input.
    pub fn new(map: B, schedule: Schedule) -> Result<Self, IntegratorError> {
        if schedule.dim() != map.inputs() {
            return Err(IntegratorError::InvalidParameter {
                reason: format!(
                    "the input map takes {} inputs, the schedule's values have {} entries",
                    map.inputs(),
                    schedule.dim()
                ),
            });
        }
        Ok(Self {
            schedule,
            map,
            _group: core::marker::PhantomData,
        })
    }
    /// The schedule u(t).
    pub fn schedule(&self) -> &Schedule {
        &self.schedule
    }
    /// The input map B.
    pub fn map(&self) -> &B {
        &self.map
    }
}

impl<G: LieGroup, B: InputMap<G>> ExternalForce<G> for ControlInput<G, B> {
    /// `B(g) u(t)` (u evaluated on the stack for up to [`Schedule::STACK_DIM`] inputs).
    #[inline]
    fn force(&self, t: f64, g: Option<&G>, _xi: &G::Algebra) -> G::Algebra {
        self.schedule.eval_with(t, |u| self.map.apply(g, u))
    }
    fn needs_configuration(&self) -> bool {
        self.map.needs_configuration()
    }
    fn reads_velocity(&self) -> bool {
        false
    }
    fn acts_on(&self) -> Option<Vec<usize>> {
        self.map.acts_on()
    }
    /// `1/Δt` of the schedule's shortest gap between knots, or the spin-up rate
    /// ([`crate::System::torque_rate`]) of its largest input `B(g) u`, whichever is larger.
    fn characteristic_rate<S: crate::System<G>>(
        &self,
        system: &S,
        _mu: &G::Algebra,
        g: Option<&G>,
    ) -> f64 {
        let spin = super::external_force::peak_torque_rate::<G, S>(system, &self.schedule, |u| {
            self.map.apply(g, u)
        });
        super::external_force::knot_rate(&self.schedule).max(spin)
    }
}
