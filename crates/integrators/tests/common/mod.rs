//! Test utilities: independent references for the free rigid body (closed forms, classical RK4 on
//! (R as a 3×3 matrix, Π)) and a least-squares order fit.
#![allow(dead_code)]

use integrators::{Integrator, IntegratorError};
use lie_groups::So3;
use nalgebra::{Matrix3, Vector3};

/// Rodrigues' formula exp(ŵ), written independently of `lie_groups::So3::exp`.
pub fn rodrigues(w: &Vector3<f64>) -> Matrix3<f64> {
    let t = w.norm();
    let k = w.cross_matrix();
    if t < 1e-4 {
        Matrix3::identity() + k * (1.0 - t * t / 6.0) + k * k * (0.5 - t * t / 24.0)
    } else {
        Matrix3::identity() + k * (t.sin() / t) + k * k * ((1.0 - t.cos()) / (t * t))
    }
}

/// Exact solution of the axisymmetric body 𝕀 = diag(i, i, i3) from (R0, Π0):
/// `Π(t) = Rz(−βt) Π0`, `R(t) = R0 exp(t Π̂0 / i) Rz(βt)`, β = Π3 (1/i3 − 1/i).
/// (Check: Ω̂ = RᵀṘ = (Rz(−βt)Π0)^/i + β ê3 = (𝕀⁻¹Π)^ and Π̇ = Π × βe3 = Π × Ω.)
pub fn axisymmetric_exact(
    i: f64,
    i3: f64,
    r0: &Matrix3<f64>,
    pi0: &Vector3<f64>,
    t: f64,
) -> (Matrix3<f64>, Vector3<f64>) {
    let beta = pi0.z * (1.0 / i3 - 1.0 / i);
    let rz = |a: f64| rodrigues(&Vector3::new(0.0, 0.0, a));
    let pi = rz(-beta * t) * pi0;
    let r = r0 * rodrigues(&(pi0 * (t / i))) * rz(beta * t);
    (r, pi)
}

/// Classical RK4 on `Ṙ = R Ω̂`, `Π̇ = Π × Ω`, Ω = 𝕀⁻¹Π, with `n` steps over [0, t].
pub fn rk4_reference(
    inertia: &Matrix3<f64>,
    r0: &Matrix3<f64>,
    pi0: &Vector3<f64>,
    t: f64,
    n: usize,
) -> (Matrix3<f64>, Vector3<f64>) {
    let iinv = inertia.try_inverse().unwrap();
    let f = |r: &Matrix3<f64>, p: &Vector3<f64>| {
        let om = iinv * p;
        (r * om.cross_matrix(), p.cross(&om))
    };
    rk4_matrix_momentum(f, r0, pi0, t, n)
}

/// Runs `n` steps of size `h` and returns (R, Π) at the end.
pub fn run<I: Integrator<Group = So3>>(
    mut integ: I,
    h: f64,
    n: usize,
) -> Result<(Matrix3<f64>, Vector3<f64>), IntegratorError> {
    for _ in 0..n {
        integ.step(h)?;
    }
    let r = *integ.configuration().expect("reconstructed").as_matrix();
    Ok((r, integ.momentum()))
}

/// Least-squares slope of log(err) against log(h).
pub fn fitted_order(hs: &[f64], errs: &[f64]) -> f64 {
    let x: Vec<f64> = hs.iter().map(|h| h.ln()).collect();
    let y: Vec<f64> = errs.iter().map(|e| e.ln()).collect();
    let n = x.len() as f64;
    let mx = x.iter().sum::<f64>() / n;
    let my = y.iter().sum::<f64>() / n;
    let sxy: f64 = x.iter().zip(&y).map(|(a, b)| (a - mx) * (b - my)).sum();
    let sxx: f64 = x.iter().map(|a| (a - mx) * (a - mx)).sum();
    sxy / sxx
}

/// A fixed rotation used as R(0) (not the identity, so that errors in R are not special).
pub fn r0() -> Matrix3<f64> {
    rodrigues(&Vector3::new(0.3, -0.5, 0.8))
}

/// A heavy top (test fixture): the rigid body in the potential `V(R) = m g χ·(Rᵀe₃)`.
/// `⟨T*_e L_R dV, ζ⟩ = d/ds V(R exp(sζ)) = −mg χ·(ζ × Γ)`, Γ = Rᵀe₃, so
/// `T*_e L_R dV = mg χ × Γ` and the force is `F = mg Γ × χ` (Π̇ = Π × Ω + mg Γ × χ).
#[derive(Debug, Clone)]
pub struct TestHeavyTop {
    pub body: mechanics::systems::RigidBody,
    pub mgchi: Vector3<f64>,
}

impl integrators::System<So3> for TestHeavyTop {
    fn hamiltonian(&self, mu: &Vector3<f64>) -> f64 {
        self.body.hamiltonian(mu)
    }
    fn velocity(&self, mu: &Vector3<f64>) -> Vector3<f64> {
        self.body.velocity(mu)
    }
    fn hessian(&self, mu: &Vector3<f64>) -> Matrix3<f64> {
        self.body.hessian(mu)
    }
    fn momentum(&self, xi: &Vector3<f64>) -> Vector3<f64> {
        self.body.momentum(xi)
    }
    fn has_potential(&self) -> bool {
        true
    }
    fn potential(&self, g: &So3) -> f64 {
        self.mgchi.dot(&(g.as_matrix().transpose() * Vector3::z()))
    }
    fn potential_differential(&self, g: &So3) -> Vector3<f64> {
        self.mgchi
            .cross(&(g.as_matrix().transpose() * Vector3::z()))
    }
}

/// Classical RK4 for the heavy top: `Ṙ = R Ω̂`, `Π̇ = Π × Ω + (Rᵀe₃) × mgχ`.
pub fn rk4_heavy_top(
    inertia: &Matrix3<f64>,
    mgchi: &Vector3<f64>,
    r0: &Matrix3<f64>,
    pi0: &Vector3<f64>,
    t: f64,
    n: usize,
) -> (Matrix3<f64>, Vector3<f64>) {
    let iinv = inertia.try_inverse().unwrap();
    let f = |r: &Matrix3<f64>, p: &Vector3<f64>| {
        let om = iinv * p;
        (
            r * om.cross_matrix(),
            p.cross(&om) + (r.transpose() * Vector3::z()).cross(mgchi),
        )
    };
    rk4_matrix_momentum(f, r0, pi0, t, n)
}

// ---- Helpers for the ready-made systems (tests/systems_*.rs) ----

/// Classical RK4 on a state vector `y ∈ ℝᵈ` (as a `DVector`) for `ẏ = f(y)`, `n` steps over [0, t].
pub fn rk4_dvec(
    f: impl Fn(&nalgebra::DVector<f64>) -> nalgebra::DVector<f64>,
    y0: &nalgebra::DVector<f64>,
    t: f64,
    n: usize,
) -> nalgebra::DVector<f64> {
    rk4_dvec_t(|_, y| f(y), y0, t, n)
}

/// A rigid body's state on SE(3) as 18 numbers for the RK4 references: R (column-major), x,
/// μ = (Π, P).
pub fn pack_se3(g: &lie_groups::Se3, mu: &nalgebra::Vector6<f64>) -> Vec<f64> {
    let mut y = g.rotation().as_matrix().as_slice().to_vec();
    y.extend_from_slice(g.translation().as_slice());
    y.extend_from_slice(mu.as_slice());
    y
}

/// The inverse of [`pack_se3`] on the first 18 numbers of `y`: (R, x, μ).
pub fn unpack_se3(y: &[f64]) -> (Matrix3<f64>, Vector3<f64>, nalgebra::Vector6<f64>) {
    (
        Matrix3::from_column_slice(&y[0..9]),
        Vector3::from_column_slice(&y[9..12]),
        nalgebra::Vector6::from_column_slice(&y[12..18]),
    )
}

/// Classical RK4 for a time-dependent field `ẏ = f(t, y)` on `y ∈ ℝᵈ` (a `DVector`), `n` steps
/// over [0, t] (the forced systems' references: schedules of time).
pub fn rk4_dvec_t(
    f: impl Fn(f64, &nalgebra::DVector<f64>) -> nalgebra::DVector<f64>,
    y0: &nalgebra::DVector<f64>,
    t: f64,
    n: usize,
) -> nalgebra::DVector<f64> {
    let h = t / n as f64;
    let mut y = y0.clone();
    for k in 0..n {
        let s = k as f64 * h;
        let k1 = f(s, &y);
        let k2 = f(s + h / 2.0, &(&y + &k1 * (h / 2.0)));
        let k3 = f(s + h / 2.0, &(&y + &k2 * (h / 2.0)));
        let k4 = f(s + h, &(&y + &k3 * h));
        y += (k1 + k2 * 2.0 + k3 * 2.0 + k4) * (h / 6.0);
    }
    y
}

/// The Richardson extrapolation `(16 y_{n} − y_{n/2})/15` of two RK4 runs with n and n/2 steps:
/// an order-6-accurate reference (RK4's leading error term cancels).
pub fn rk4_richardson(
    f: impl Fn(f64, &nalgebra::DVector<f64>) -> nalgebra::DVector<f64>,
    y0: &nalgebra::DVector<f64>,
    t: f64,
    n: usize,
) -> nalgebra::DVector<f64> {
    let fine = rk4_dvec_t(&f, y0, t, n);
    let coarse = rk4_dvec_t(&f, y0, t, n / 2);
    (fine * 16.0 - coarse) / 15.0
}

/// Central finite difference of `s ↦ V(g exp(s eᵢ))` at s = 0, for every basis direction eᵢ:
/// the left-trivialized differential `T*_e L_g dV` to O(δ²) (δ = 1e-5: error ~1e-10 relative).
pub fn fd_left_differential<G: lie_groups::LieGroup>(v: impl Fn(&G) -> f64, g: &G) -> Vec<f64> {
    use lie_groups::Vector;
    let n = G::dim();
    let d = 1e-5;
    (0..n)
        .map(|i| {
            let e = G::Algebra::basis(n, i);
            let plus = v(&g.compose(&G::exp(&e.scale(d))));
            let minus = v(&g.compose(&G::exp(&e.scale(-d))));
            (plus - minus) / (2.0 * d)
        })
        .collect()
}

/// Max |E − E₀| over the first and the last tenth of `steps` steps of size h.
pub fn energy_error_tenths<I: Integrator>(mut integ: I, h: f64, steps: usize) -> (f64, f64) {
    let e0 = integ.energy();
    let (mut first, mut last) = (0.0f64, 0.0f64);
    for k in 0..steps {
        integ.step(h).unwrap();
        let e = (integ.energy() - e0).abs();
        if k < steps / 10 {
            first = first.max(e);
        } else if k >= steps - steps / 10 {
            last = last.max(e);
        }
    }
    (first, last)
}

/// Classical RK4 with `n` steps over [0, t] on (R as a plain 3×3 matrix, Π) for the vector field
/// `f(R, Π) = (Ṙ, Π̇)`: the shared loop of the independent references above.
fn rk4_matrix_momentum(
    f: impl Fn(&Matrix3<f64>, &Vector3<f64>) -> (Matrix3<f64>, Vector3<f64>),
    r0: &Matrix3<f64>,
    pi0: &Vector3<f64>,
    t: f64,
    n: usize,
) -> (Matrix3<f64>, Vector3<f64>) {
    let h = t / n as f64;
    let (mut r, mut p) = (*r0, *pi0);
    for _ in 0..n {
        let (k1r, k1p) = f(&r, &p);
        let (k2r, k2p) = f(&(r + k1r * (h / 2.0)), &(p + k1p * (h / 2.0)));
        let (k3r, k3p) = f(&(r + k2r * (h / 2.0)), &(p + k2p * (h / 2.0)));
        let (k4r, k4p) = f(&(r + k3r * h), &(p + k3p * h));
        r += (k1r + k2r * 2.0 + k3r * 2.0 + k4r) * (h / 6.0);
        p += (k1p + k2p * 2.0 + k3p * 2.0 + k4p) * (h / 6.0);
    }
    (r, p)
}

/// Deterministic 6×6 matrix with entries uniform in [−s, s] (a 64-bit LCG, Knuth's MMIX
/// constants).
fn lcg_matrix(seed: &mut u64, s: f64) -> nalgebra::SMatrix<f64, 6, 6> {
    nalgebra::SMatrix::<f64, 6, 6>::from_fn(|_, _| {
        *seed = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((*seed >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0) * s
    })
}

/// `x' = (A + B + C)x` for three fixed random non-commuting 6×6 matrices (entries in [−0.4, 0.4]):
/// the test bed of the full order conditions of compositions and processing.
pub struct LinearSplitting {
    a: nalgebra::SMatrix<f64, 6, 6>,
    b: nalgebra::SMatrix<f64, 6, 6>,
    c: nalgebra::SMatrix<f64, 6, 6>,
}

impl LinearSplitting {
    pub fn new() -> Self {
        let mut seed = 0x5eed;
        Self {
            a: lcg_matrix(&mut seed, 0.4),
            b: lcg_matrix(&mut seed, 0.4),
            c: lcg_matrix(&mut seed, 0.4),
        }
    }
    /// The symmetric order-2 splitting `e^{hA/2} e^{hB/2} e^{hC} e^{hB/2} e^{hA/2}`.
    pub fn strang(&self, h: f64) -> nalgebra::SMatrix<f64, 6, 6> {
        let ea = (self.a * (h / 2.0)).exp();
        let eb = (self.b * (h / 2.0)).exp();
        ea * eb * (self.c * h).exp() * eb * ea
    }
    /// The exact flow `e^{h(A+B+C)}`.
    pub fn exact(&self, h: f64) -> nalgebra::SMatrix<f64, 6, 6> {
        ((self.a + self.b + self.c) * h).exp()
    }
}

/// McLachlan's principal-axis splitting of the free body, the split `RigidBody` used before its
/// own (an axisymmetric body plus one rotation): three pieces on
/// `RigidBody::principal_piece_velocity` with the trait's generic exp / Ad* flows.
#[derive(Clone, Debug)]
pub struct PrincipalAxes(pub mechanics::systems::RigidBody);

impl integrators::System<So3> for PrincipalAxes {
    fn hamiltonian(&self, mu: &Vector3<f64>) -> f64 {
        self.0.hamiltonian(mu)
    }
    fn velocity(&self, mu: &Vector3<f64>) -> Vector3<f64> {
        self.0.velocity(mu)
    }
    fn momentum(&self, xi: &Vector3<f64>) -> Vector3<f64> {
        self.0.momentum(xi)
    }
}

impl integrators::splitting::SplitSystem<So3> for PrincipalAxes {
    fn pieces(&self) -> usize {
        3
    }
    fn piece_velocity(&self, i: usize, mu: &Vector3<f64>) -> Vector3<f64> {
        self.0.principal_piece_velocity(i, mu)
    }
}

/// The distance of a state (R, Π) from a reference: max(‖ΔR‖_max, ‖ΔΠ‖_max / scale).
pub fn error_vs(
    reference: &(Matrix3<f64>, Vector3<f64>),
    got: &(Matrix3<f64>, Vector3<f64>),
    scale: f64,
) -> f64 {
    (got.0 - reference.0)
        .amax()
        .max((got.1 - reference.1).amax() / scale)
}
