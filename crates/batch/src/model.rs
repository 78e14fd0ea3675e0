//! The body every lane of a batch carries: a rigid body in principal axes, free or in a uniform
//! field — the free rigid body and the heavy top of `mechanics`, read from them.

use crate::BatchError;
use mechanics::{HeavyTop, RigidBody};

/// A rigid body in principal axes (𝕀 = diag(I₁, I₂, I₃)), free or in a uniform field, shared by
/// every lane of a batch (lanes differ by their state; a sweep over parameters runs one batch per
/// parameter set).
///
/// - Free: `h(Π) = ½ Σ Πᵢ²/Iᵢ`, `Π̇ = Π × Ω`, `Ṙ = R Ω̂` ([`mechanics::RigidBody`]).
/// - In a uniform field along −e₃ in space: `V(R) = ⟨m g χ, Γ⟩`, `Γ = Rᵀe₃`, force
///   `F(R) = Γ × m g χ` ([`mechanics::HeavyTop`]: a top under gravity, or any body whose
///   potential is linear in the body-frame direction of a fixed field — a dipole in a uniform
///   electric or magnetic field, with m g χ its dipole moment and the field along e₃).
///
/// The batched methods need 𝕀 diagonal, so that each principal-axis rotation of the free body's
/// splitting is a plane rotation of two coordinates ([`BatchError::Unsupported`] otherwise: express
/// the state in the principal frame, `Π' = AᵀΠ`, `R' = R A`, with A from
/// [`RigidBody::principal_frame`]).
#[derive(Debug, Clone, PartialEq)]
pub struct BodyModel {
    /// Iᵢ, as the body keeps them (the exact flow rebuilds the body from them).
    pub(crate) moments: [f64; 3],
    /// 1/Iᵢ.
    pub(crate) inv_moments: [f64; 3],
    /// The splitting's axes `[r, p, s]` ([`RigidBody::split_axes`]).
    pub(crate) split_axes: [usize; 3],
    /// `(1/I_r, 1/I_p − 1/I_r, 1/I_s − 1/I_r)`.
    pub(crate) split_rates: [f64; 3],
    /// m g χ, in a field.
    pub(crate) field: Option<[f64; 3]>,
}

impl BodyModel {
    /// The free rigid body `body` (its inertia tensor must be diagonal).
    pub fn free(body: &RigidBody) -> Result<Self, BatchError> {
        if !body.is_diagonal() {
            return Err(BatchError::Unsupported {
                reason: "the batched methods need an inertia tensor in principal axes (diagonal); \
                         rotate the state into the principal frame of RigidBody::principal_frame"
                    .into(),
            });
        }
        let (_, moments) = body.principal_frame();
        // As `RigidBody` computes them, so that the rates are the same doubles.
        let inv = [1.0 / moments[0], 1.0 / moments[1], 1.0 / moments[2]];
        let [r, p, s] = body.split_axes();
        Ok(Self {
            moments: [moments[0], moments[1], moments[2]],
            inv_moments: inv,
            split_axes: [r, p, s],
            split_rates: [inv[r], inv[p] - inv[r], inv[s] - inv[r]],
            field: None,
        })
    }
    /// The heavy top `top` (a body in a uniform field; diagonal inertia tensor).
    pub fn heavy_top(top: &HeavyTop) -> Result<Self, BatchError> {
        let mut model = Self::free(top.body())?;
        let chi = top.centre_of_mass();
        let mg = top.mass() * top.gravity();
        // `HeavyTop` keeps χ·(m g) the same way.
        model.field = Some([chi[0] * mg, chi[1] * mg, chi[2] * mg]);
        Ok(model)
    }
    /// The principal moments Iᵢ.
    pub fn moments(&self) -> [f64; 3] {
        self.moments
    }
    /// The principal moments' inverses 1/Iᵢ.
    pub fn inverse_moments(&self) -> [f64; 3] {
        self.inv_moments
    }
    /// m g χ, for a body in a field.
    pub fn field_arm(&self) -> Option<[f64; 3]> {
        self.field
    }
}
