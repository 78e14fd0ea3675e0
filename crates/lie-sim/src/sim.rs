//! The seam between the scene runner and the integrators: a [`Simulation`] is a state (t, μ, g)
//! advanced one step at a time and read in place.
//!
//! Everything above this module (running, writing CSV, the monitors, the work-precision trade)
//! sees a scene only through it. Reads write into the caller's buffers — μ, g's entries, the
//! spatial momentum map, a whole trajectory row — so that a run that reads the state after every
//! step allocates nothing for it (groups whose matrix lives on the stack: SO(3), SE(2), SE(3)).

use crate::attitude::{self, Attitudes};
pub use crate::columns::Layout;
use crate::driver::{Driver, ReversibleDriver};
use faer::Mat;
use integrators::adaptive::{Controller, EmbeddedPair, Stats, Tolerance};
use integrators::dense_output::{DenseState, HermiteStep};
use integrators::{Integrator, IntegratorError, MethodInfo, StateSnapshot, SymmetricMethod};
use lie_groups::{LieGroup, Vector};
use nalgebra::{DMatrix, SMatrix};
use std::any::Any;

/// One running simulation: the integrator, its system and its state.
///
/// The momentum μ ∈ 𝔤* is given in the basis of the group's `vee` (Π for SO(3)); the group element
/// g (when reconstructed) as its matrix, row-major.
pub trait Simulation {
    /// Advances the state by one step of size `h`; on error the state is left unchanged and the
    /// integrator's message is returned.
    fn step(&mut self, h: f64) -> Result<(), String>;
    /// Current time t.
    fn time(&self) -> f64;
    /// The number of components of μ.
    fn momentum_dim(&self) -> usize;
    /// Side m of the group element's m×m matrix, or `None` when g is not reconstructed.
    fn group_side(&self) -> Option<usize>;
    /// Writes μ into `out` (its first [`Self::momentum_dim`] entries).
    fn read_momentum(&self, out: &mut [f64]);
    /// Writes g's matrix entries row-major into `out` (side² entries); `false` when g is not
    /// reconstructed.
    fn read_group(&self, out: &mut [f64]) -> bool;
    /// Total energy E = h(μ) + V(g).
    fn energy(&self) -> f64;
    /// The Casimir the system monitors (|Π|² for the free rigid body), if it has one.
    fn casimir(&self) -> Option<f64>;
    /// Writes the spatial momentum map `J = Ad*_{g⁻¹} μ` (R Π on SO(3), (R Π + x × R P, R P) on
    /// SE(3)) into `out`, in the basis of μ; `false` when g is not reconstructed. Conserved by the
    /// flow of a left-invariant system; which parts the system keeps is
    /// [`Self::conserved_momentum_map`].
    fn read_spatial_momentum(&self, out: &mut [f64]) -> bool;
    /// The parts of J the system's flow conserves (`integrators::System::conserved_momentum_map`).
    fn conserved_momentum_map(&self) -> Vec<Vec<usize>>;
    /// What the method is and keeps, as it describes itself (`integrators::MethodInfo`).
    fn info(&self) -> MethodInfo;
    /// Why the state cannot be read, when its reads computed NaN (a processed method whose
    /// processor failed: `integrators::Integrator::read_error`); `None` otherwise.
    fn read_error(&self) -> Option<String> {
        None
    }
    /// Remembers the current state as the start of the step about to be taken, for
    /// [`Self::read_at`].
    fn mark(&mut self) {}
    /// The row at time t between the marked state and the current one, by the cubic Hermite
    /// interpolant of `integrators::dense_output` (energy and Casimir evaluated at the
    /// interpolated state), written into `row`.
    fn read_at(&self, _t: f64, _row: &mut [f64]) -> Result<(), String> {
        Err("this simulation has no dense output".into())
    }

    /// One accepted step of a tolerance-driven run towards `t_end`, the last one landing on it
    /// exactly (`integrators::adaptive::Adaptive::step_towards`); on error the state is the last
    /// accepted one. A fixed-step simulation refuses.
    fn step_towards(&mut self, _t_end: f64) -> Result<(), String> {
        Err("this method takes a fixed step h, not a tolerance".into())
    }
    /// Accepted and rejected steps and the smallest and largest step of a tolerance-driven run;
    /// `None` for fixed steps.
    fn stats(&self) -> Option<Stats> {
        None
    }

    /// The power `⟨F_ext(t, g, ξ), ξ⟩` of the external forces at the current state (ξ = ∂h/∂μ), or
    /// `None` when the system is not forced.
    fn power(&self) -> Option<f64> {
        None
    }
    /// How many rigid-body attitudes the state holds (`crate::attitude`): 0 when g is not
    /// reconstructed.
    fn bodies(&self) -> usize {
        0
    }
    /// Writes the attitudes' cells (`crate::attitude::write_all`) into `out`; `false` when there
    /// are none.
    fn read_attitudes(&self, _out: &mut [f64]) -> bool {
        false
    }

    /// Which columns a trajectory row has.
    fn layout(&self) -> Layout {
        Layout {
            momentum: self.momentum_dim(),
            side: self.group_side(),
            casimir: self.casimir().is_some(),
            forced: self.power().is_some(),
            bodies: self.bodies(),
        }
    }
    /// The number of columns of a trajectory row ([`Layout::width`]).
    fn columns(&self) -> usize {
        self.layout().width()
    }
    /// The current state as a trajectory row written into `row` ([`Self::columns`] entries, in
    /// the order of [`Layout::names`]). The `work` cell, an integral along the run, is the
    /// runner's to fill: it is left as it was.
    fn read(&self, row: &mut [f64]) {
        row[0] = self.time();
        let n = self.momentum_dim();
        self.read_momentum(&mut row[1..1 + n]);
        let mut k = 1 + n;
        if let Some(m) = self.group_side() {
            self.read_group(&mut row[k..k + m * m]);
            k += m * m;
        }
        row[k] = self.energy();
        k += 1;
        if let Some(c) = self.casimir() {
            row[k] = c;
            k += 1;
        }
        if let Some(p) = self.power() {
            row[k] = p;
            k += 2;
        }
        self.read_attitudes(&mut row[k..]);
    }
    /// μ as a vector (allocates: for reads outside the stepping loop).
    fn momentum(&self) -> Vec<f64> {
        let mut v = vec![0.0; self.momentum_dim()];
        self.read_momentum(&mut v);
        v
    }
    /// g's entries row-major as a vector, or `None` (allocates).
    fn group_matrix(&self) -> Option<Vec<f64>> {
        let m = self.group_side()?;
        let mut v = vec![0.0; m * m];
        self.read_group(&mut v).then_some(v)
    }
}

/// A group's matrix written row-major into a slice, without building a faer matrix for the
/// stack-allocated ones (`lie_groups::DenseMatrix` only offers `to_mat`).
pub trait Entries {
    /// The side m of the m×m matrix.
    fn side(&self) -> usize;
    /// The entries row-major into `out` (m² entries).
    fn write_row_major(&self, out: &mut [f64]);
}

impl<const R: usize, const C: usize> Entries for SMatrix<f64, R, C> {
    fn side(&self) -> usize {
        R
    }
    fn write_row_major(&self, out: &mut [f64]) {
        for i in 0..R {
            for j in 0..C {
                out[i * C + j] = self[(i, j)];
            }
        }
    }
}

/// The matrices whose size is known at run time: nalgebra's (the composite groups: products,
/// powers) and faer's (SO(n), GL(n)), which spell `nrows`, `ncols` and `m[(i, j)]` alike.
macro_rules! dynamic_entries {
    ($($matrix:ty),*) => {$(
        impl Entries for $matrix {
            fn side(&self) -> usize {
                self.nrows()
            }
            fn write_row_major(&self, out: &mut [f64]) {
                let c = self.ncols();
                for i in 0..self.nrows() {
                    for j in 0..c {
                        out[i * c + j] = self[(i, j)];
                    }
                }
            }
        }
    )*};
}

dynamic_entries!(DMatrix<f64>, Mat<f64>);

/// The groups a simulation runs on: those whose matrix is [`Entries`] and whose attitudes are
/// known ([`Attitudes`]).
pub trait SimGroup: LieGroup<Matrix: Entries> + Attitudes {}

impl<G: LieGroup<Matrix: Entries> + Attitudes> SimGroup for G {}

/// The [`Integrator`] methods of a wrapper, each forwarded to the integrator that `$inner`
/// (`$inner_mut` for the step) reaches: the erasures below are their integrator, not a variant
/// of it, so every method is forwarded, the provided ones (`side`, `read_error`) included.
macro_rules! forward_integrator {
    ($self:ident => $inner:expr, $inner_mut:expr) => {
        fn step(&mut $self, h: f64) -> Result<(), IntegratorError> {
            $inner_mut.step(h)
        }
        fn time(&$self) -> f64 {
            $inner.time()
        }
        fn momentum(&$self) -> <Self::Group as LieGroup>::Algebra {
            $inner.momentum()
        }
        fn velocity(&$self) -> <Self::Group as LieGroup>::Algebra {
            $inner.velocity()
        }
        fn momentum_rate(&$self) -> <Self::Group as LieGroup>::Algebra {
            $inner.momentum_rate()
        }
        fn configuration(&$self) -> Option<&Self::Group> {
            $inner.configuration()
        }
        fn energy(&$self) -> f64 {
            $inner.energy()
        }
        fn casimir(&$self) -> Option<f64> {
            $inner.casimir()
        }
        fn method_name(&$self) -> String {
            $inner.method_name()
        }
        fn info(&$self) -> MethodInfo {
            $inner.info()
        }
        fn side(&$self) -> discretization::Side {
            $inner.side()
        }
        fn read_error(&$self) -> Option<IntegratorError> {
            $inner.read_error()
        }
    };
}

/// Any integrator of the integrators crate on the group G, boxed: the type a scene's method (with
/// its τ, θ, composition, processing) is erased to, so that one code path runs them all. A
/// method with an error estimate is boxed as a [`Pair`] ([`Boxed::pair`]), so that a scene may
/// run it to a tolerance ([`Boxed::into_pair`]); a symmetric one with its system
/// ([`Boxed::symmetric`]), so that a scene may run it with reversible variable steps
/// ([`Boxed::into_reversible`]); each as well as with fixed steps.
pub struct Boxed<G: LieGroup>(Erased<G>);

enum Erased<G: LieGroup> {
    Fixed(Box<dyn Integrator<Group = G>>),
    Pair(Pair<G>),
    Symmetric(Box<dyn DynSymmetric<Group = G>>),
}

/// A symmetric method with the system whose step density ρ steers its reversible variable
/// steps, type-erased: both concrete types are known only where the method is built. It is the
/// method itself as an [`Integrator`] (the steps and reads of a fixed-step run go straight to
/// it, one dynamic call each), and it can become a reversible driver.
trait DynSymmetric: Integrator {
    fn reversible(
        self: Box<Self>,
        epsilon: f64,
    ) -> Result<Box<dyn Driver<Group = Self::Group>>, IntegratorError>;
}

/// The method M and its monitor S (`integrators::System::step_density`).
struct Symmetric<M, S> {
    method: M,
    monitor: S,
}

impl<M, S> Integrator for Symmetric<M, S>
where
    M: Integrator,
{
    type Group = M::Group;
    forward_integrator!(self => self.method, self.method);
}

impl<M, S> DynSymmetric for Symmetric<M, S>
where
    M: SymmetricMethod + StateSnapshot + Clone + 'static,
    S: integrators::System<M::Group> + 'static,
{
    fn reversible(
        self: Box<Self>,
        epsilon: f64,
    ) -> Result<Box<dyn Driver<Group = M::Group>>, IntegratorError> {
        let Self { method, monitor } = *self;
        Ok(Box::new(ReversibleDriver::new(method, monitor, epsilon)?))
    }
}

impl<G: LieGroup> Boxed<G> {
    /// Erases `i`.
    pub fn new<I: Integrator<Group = G> + 'static>(i: I) -> Self {
        Self(Erased::Fixed(Box::new(i)))
    }
    /// Erases the embedded pair `p`, keeping its error estimate.
    pub fn pair<P: EmbeddedPair<Group = G> + 'static>(p: P) -> Self {
        Self(Erased::Pair(Pair(Box::new(p))))
    }
    /// Erases the symmetric method `method` (`SymmetricMethod::is_symmetric`), keeping
    /// `monitor`, whose step density steers its reversible variable steps; a method that is not
    /// symmetric is erased as by [`Boxed::new`].
    pub fn symmetric<M, S>(method: M, monitor: S) -> Self
    where
        M: SymmetricMethod + StateSnapshot + Clone + 'static,
        S: integrators::System<G> + 'static,
        M: Integrator<Group = G>,
    {
        if method.is_symmetric() {
            Self(Erased::Symmetric(Box::new(Symmetric { method, monitor })))
        } else {
            Self::new(method)
        }
    }
    /// The embedded pair, when the method is one; itself otherwise.
    pub fn into_pair(self) -> Result<Pair<G>, Self> {
        match self.0 {
            Erased::Pair(p) => Ok(p),
            other => Err(Self(other)),
        }
    }
    /// The method run with the reversible step-density controller and steps ε in τ
    /// (`integrators::adaptive::ReversibleSteps`), when it is symmetric; itself otherwise.
    #[allow(clippy::type_complexity)]
    pub fn into_reversible(
        self,
        epsilon: f64,
    ) -> Result<Result<Box<dyn Driver<Group = G>>, IntegratorError>, Self> {
        match self.0 {
            Erased::Symmetric(s) => Ok(s.reversible(epsilon)),
            other => Err(Self(other)),
        }
    }
    fn inner(&self) -> &dyn Integrator<Group = G> {
        match &self.0 {
            Erased::Fixed(b) => &**b,
            Erased::Pair(p) => &*p.0,
            Erased::Symmetric(s) => &**s,
        }
    }
    fn inner_mut(&mut self) -> &mut dyn Integrator<Group = G> {
        match &mut self.0 {
            Erased::Fixed(b) => &mut **b,
            Erased::Pair(p) => &mut *p.0,
            Erased::Symmetric(s) => &mut **s,
        }
    }
}

impl<G: LieGroup> Integrator for Boxed<G> {
    type Group = G;
    forward_integrator!(self => self.inner(), self.inner_mut());
}

/// An [`EmbeddedPair`] with its type erased (object safe: no `Clone` bound), so that a scene's
/// pair is one type for the adaptive driver whatever its group, tableau and system.
pub trait DynPair: Integrator + Any {
    /// [`EmbeddedPair::orders`].
    fn orders(&self) -> (u32, u32);
    /// [`EmbeddedPair::controller`].
    fn controller(&self) -> Controller;
    /// [`EmbeddedPair::error_exponent`].
    fn error_exponent(&self) -> u32;
    /// [`EmbeddedPair::try_step_to`].
    fn try_step_to(&mut self, t1: f64, tolerance: &Tolerance) -> Result<f64, IntegratorError>;
    /// [`EmbeddedPair::step_to`].
    fn step_to(&mut self, t1: f64) -> Result<(), IntegratorError>;
    /// [`EmbeddedPair::starting_step`].
    fn starting_step(&mut self, direction: f64, tolerance: &Tolerance) -> f64;
    /// A boxed copy.
    fn clone_box(&self) -> Box<dyn DynPair<Group = Self::Group>>;
    /// Overwrites `self` with `other`'s state, in place (`Clone::clone_from`: no allocation for
    /// a pair whose system holds none), when both are the same pair; `false` otherwise.
    fn copy_from(&mut self, other: &dyn Any) -> bool;
}

impl<P: EmbeddedPair + 'static> DynPair for P {
    fn orders(&self) -> (u32, u32) {
        EmbeddedPair::orders(self)
    }
    fn controller(&self) -> Controller {
        EmbeddedPair::controller(self)
    }
    fn error_exponent(&self) -> u32 {
        EmbeddedPair::error_exponent(self)
    }
    fn try_step_to(&mut self, t1: f64, tolerance: &Tolerance) -> Result<f64, IntegratorError> {
        EmbeddedPair::try_step_to(self, t1, tolerance)
    }
    fn step_to(&mut self, t1: f64) -> Result<(), IntegratorError> {
        EmbeddedPair::step_to(self, t1)
    }
    fn starting_step(&mut self, direction: f64, tolerance: &Tolerance) -> f64 {
        EmbeddedPair::starting_step(self, direction, tolerance)
    }
    fn clone_box(&self) -> Box<dyn DynPair<Group = P::Group>> {
        Box::new(self.clone())
    }
    fn copy_from(&mut self, other: &dyn Any) -> bool {
        match other.downcast_ref::<P>() {
            Some(o) => {
                self.clone_from(o);
                true
            }
            None => false,
        }
    }
}

/// A boxed [`DynPair`]: the [`EmbeddedPair`] the adaptive driver runs for any scene.
pub struct Pair<G: LieGroup>(Box<dyn DynPair<Group = G>>);

impl<G: LieGroup> Clone for Pair<G> {
    fn clone(&self) -> Self {
        Self(self.0.clone_box())
    }
    /// In place when both are copies of one pair (the run's mark each step): no allocation.
    fn clone_from(&mut self, source: &Self) {
        let other: &dyn Any = &*source.0;
        if !self.0.copy_from(other) {
            self.0 = source.0.clone_box();
        }
    }
}

impl<G: LieGroup> Integrator for Pair<G> {
    type Group = G;
    forward_integrator!(self => self.0, self.0);
}

impl<G: LieGroup> EmbeddedPair for Pair<G> {
    fn orders(&self) -> (u32, u32) {
        self.0.orders()
    }
    fn controller(&self) -> Controller {
        self.0.controller()
    }
    fn error_exponent(&self) -> u32 {
        self.0.error_exponent()
    }
    fn try_step_to(&mut self, t1: f64, tolerance: &Tolerance) -> Result<f64, IntegratorError> {
        self.0.try_step_to(t1, tolerance)
    }
    fn step_to(&mut self, t1: f64) -> Result<(), IntegratorError> {
        self.0.step_to(t1)
    }
    fn starting_step(&mut self, direction: f64, tolerance: &Tolerance) -> f64 {
        self.0.starting_step(direction, tolerance)
    }
}

/// Any integrator of the integrators crate, with its system, seen as a [`Simulation`].
pub struct Adapter<I: Integrator, S> {
    integrator: I,
    /// The system: energy and Casimir at interpolated states, its facts.
    system: S,
    /// The state at the start of the current step ([`Simulation::mark`]).
    marked: Option<DenseState<I::Group>>,
}

impl<I: Integrator, S> Adapter<I, S> {
    /// `integrator` advancing `system`.
    pub fn new(integrator: I, system: S) -> Self {
        Self {
            integrator,
            system,
            marked: None,
        }
    }
}

/// μ's components into `out`.
pub(crate) fn write_vector<V: Vector>(v: &V, out: &mut [f64]) {
    for (i, o) in out.iter_mut().enumerate().take(v.dim()) {
        *o = v.get(i);
    }
}

/// g's matrix side, when reconstructed.
pub(crate) fn group_side<I: Integrator<Group: SimGroup> + ?Sized>(i: &I) -> Option<usize> {
    i.configuration().map(|g| g.matrix().side())
}

/// g's entries row-major into `out`; `false` when g is not reconstructed.
pub(crate) fn read_group<I: Integrator<Group: SimGroup> + ?Sized>(i: &I, out: &mut [f64]) -> bool {
    match i.configuration() {
        Some(g) => {
            g.matrix().write_row_major(out);
            true
        }
        None => false,
    }
}

/// The spatial momentum map into `out` (see [`Simulation::read_spatial_momentum`]).
pub(crate) fn read_spatial_momentum<I: Integrator<Group: SimGroup> + ?Sized>(
    i: &I,
    out: &mut [f64],
) -> bool {
    // Ad*_{g⁻¹} μ = (Ad_{g⁻¹})ᵀ μ: `coadjoint_apply` is the dual map of Ad, so it is applied
    // to g⁻¹ (on SO(3), Ad_{R⁻¹} = Rᵀ and J = R Π).
    match i.configuration() {
        Some(g) => {
            write_vector(&g.inverse().coadjoint_apply(&i.momentum()), out);
            true
        }
        None => false,
    }
}

/// The power `⟨F_ext(t, g, ξ), ξ⟩` of `system`'s external forces at (t, μ, g), ξ = ∂h/∂μ; `None`
/// when it is not forced.
pub(crate) fn power_of<G: LieGroup, S: integrators::System<G>>(
    system: &S,
    t: f64,
    mu: &G::Algebra,
    g: Option<&G>,
) -> Option<f64> {
    system.is_forced().then(|| {
        let xi = system.velocity(mu);
        system.external_force(t, g, &xi).dot(&xi)
    })
}

/// How many attitudes g holds; none when g is not reconstructed.
pub(crate) fn attitudes_of<G: SimGroup>(g: Option<&G>) -> usize {
    g.map_or(0, |_| G::BODIES)
}

/// The trajectory row of the state (μ, g) at t into `row` (as [`Simulation::read`]: the `work`
/// cell is left for the runner), energy, Casimir and power from `system`.
pub(crate) fn write_row<G: SimGroup, S: integrators::System<G>>(
    system: &S,
    t: f64,
    mu: &G::Algebra,
    g: Option<&G>,
    row: &mut [f64],
) {
    row[0] = t;
    let n = mu.dim();
    write_vector(mu, &mut row[1..1 + n]);
    let mut k = 1 + n;
    if let Some(g) = g {
        let m = g.matrix();
        let side = m.side();
        m.write_row_major(&mut row[k..k + side * side]);
        k += side * side;
    }
    row[k] = system.energy(mu, g);
    k += 1;
    if let Some(c) = system.casimir(mu) {
        row[k] = c;
        k += 1;
    }
    if let Some(p) = power_of(system, t, mu, g) {
        row[k] = p;
        k += 2;
    }
    if let Some(g) = g {
        attitude::write_all(g, &mut row[k..]);
    }
}

impl<I, S> Simulation for Adapter<I, S>
where
    I: Integrator,
    I::Group: SimGroup,
    S: integrators::System<I::Group>,
{
    fn step(&mut self, h: f64) -> Result<(), String> {
        self.integrator.step(h).map_err(|e| e.to_string())
    }
    fn time(&self) -> f64 {
        self.integrator.time()
    }
    fn momentum_dim(&self) -> usize {
        <I::Group as LieGroup>::dim()
    }
    fn group_side(&self) -> Option<usize> {
        group_side(&self.integrator)
    }
    fn read_momentum(&self, out: &mut [f64]) {
        write_vector(&self.integrator.momentum(), out);
    }
    fn read_group(&self, out: &mut [f64]) -> bool {
        read_group(&self.integrator, out)
    }
    fn energy(&self) -> f64 {
        self.integrator.energy()
    }
    fn casimir(&self) -> Option<f64> {
        self.integrator.casimir()
    }
    fn read_spatial_momentum(&self, out: &mut [f64]) -> bool {
        read_spatial_momentum(&self.integrator, out)
    }
    fn conserved_momentum_map(&self) -> Vec<Vec<usize>> {
        self.system.conserved_momentum_map()
    }
    fn power(&self) -> Option<f64> {
        let i = &self.integrator;
        power_of(&self.system, i.time(), &i.momentum(), i.configuration())
    }
    fn bodies(&self) -> usize {
        attitudes_of(self.integrator.configuration())
    }
    fn read_attitudes(&self, out: &mut [f64]) -> bool {
        self.integrator
            .configuration()
            .map(|g| attitude::write_all(g, out))
            .is_some()
    }
    fn info(&self) -> MethodInfo {
        self.integrator.info()
    }
    fn read_error(&self) -> Option<String> {
        self.integrator.read_error().map(|e| e.to_string())
    }
    fn mark(&mut self) {
        self.marked = Some(DenseState::of(&self.integrator));
    }
    fn read_at(&self, t: f64, row: &mut [f64]) -> Result<(), String> {
        let start = self
            .marked
            .as_ref()
            .ok_or("no step marked for dense output")?;
        let step = HermiteStep::between(start, &DenseState::of(&self.integrator))
            .map_err(|e| e.to_string())?;
        let (mu, g) = step.at(t);
        write_row(&self.system, t, &mu, g.as_ref(), row);
        Ok(())
    }
}

#[cfg(test)]
pub(crate) mod mock {
    //! A closed-form stand-in for the integrators, to test the runner without them: the free rigid
    //! body spinning about a principal axis, Π constant and R(t) = exp(t Ω̂), Ω = Π₃/I₃ e₃.
    use super::Simulation;

    /// Uniform rotation about e₃ at rate `omega`, with optional step failure after `fail_after`.
    pub struct Spin {
        pub t: f64,
        pub omega: f64,
        pub reconstruct: bool,
        pub fail_after: Option<usize>,
        pub steps: usize,
    }

    impl Spin {
        fn matrix(&self) -> [f64; 9] {
            let (s, c) = (self.omega * self.t).sin_cos();
            [c, -s, 0.0, s, c, 0.0, 0.0, 0.0, 1.0]
        }
    }

    impl Simulation for Spin {
        fn step(&mut self, h: f64) -> Result<(), String> {
            if self.fail_after == Some(self.steps) {
                return Err("no convergence".into());
            }
            self.t += h;
            self.steps += 1;
            Ok(())
        }
        fn time(&self) -> f64 {
            self.t
        }
        fn momentum_dim(&self) -> usize {
            3
        }
        fn read_momentum(&self, out: &mut [f64]) {
            out[..3].copy_from_slice(&[0.0, 0.0, 3.0 * self.omega]);
        }
        fn group_side(&self) -> Option<usize> {
            self.reconstruct.then_some(3)
        }
        fn read_group(&self, out: &mut [f64]) -> bool {
            if self.reconstruct {
                out[..9].copy_from_slice(&self.matrix());
            }
            self.reconstruct
        }
        fn energy(&self) -> f64 {
            0.5 * 3.0 * self.omega * self.omega
        }
        fn casimir(&self) -> Option<f64> {
            Some(9.0 * self.omega * self.omega)
        }
        /// R Π = Π: the rotation is about Π's own axis e₃.
        fn read_spatial_momentum(&self, out: &mut [f64]) -> bool {
            if self.reconstruct {
                self.read_momentum(out);
            }
            self.reconstruct
        }
        /// The free body's: all of J.
        fn conserved_momentum_map(&self) -> Vec<Vec<usize>> {
            vec![vec![0], vec![1], vec![2]]
        }
        fn bodies(&self) -> usize {
            usize::from(self.reconstruct)
        }
        fn read_attitudes(&self, out: &mut [f64]) -> bool {
            if self.reconstruct {
                let r = lie_groups::So3::from_rotation_vector(&nalgebra::Vector3::new(
                    0.0,
                    0.0,
                    self.omega * self.t,
                ));
                crate::attitude::write(&r, out);
            }
            self.reconstruct
        }
        /// The exact uniform rotation.
        fn info(&self) -> integrators::MethodInfo {
            integrators::MethodInfo {
                order: integrators::MethodInfo::EXACT,
                symmetric: true,
                explicit: true,
                poisson: true,
                casimirs: true,
                momentum_map: true,
                energy: true,
                on_group: true,
            }
        }
    }
}
