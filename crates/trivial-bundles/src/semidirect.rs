//! The trivialized tangent and cotangent bundles of §1.1 of the paper as Lie groups:
//! TG ≅ G ⋉ 𝔤 ([`TangentBundle`]) and T*G ≅ G ⋉ 𝔤* ([`CotangentBundle`]).
//!
//! Both implement [`LieGroup`] themselves, with algebra coordinates [`Pair`], dense block operators
//! and a faithful block-matrix representation, so the generic suite of `lie_groups::testing`
//! applies to them and so nesting them gives the higher bundles of §1.2 ([`crate::higher`]).
//!
//! `compose`, `inverse`, `adjoint_apply`, `coadjoint_apply`, `bracket` and `ad_dual_apply` are
//! written with the base group's applied maps only (never its operator matrices through faer), so
//! they allocate nothing when G is a fixed-size group, and neither do they for the nested bundles.

use crate::Pair;
use faer::{Mat, MatRef};
use lie_groups::{DenseMatrix, DomainReason, LieError, LieGroup, Operator, StructureCheck, Vector};

/// Relative tolerance of the block-structure checks in `from_matrix`: an entry that must vanish (or
/// equal another) may be off by `STRUCTURE_TOL · (1 + ‖M‖_max)`. Matrices built by `matrix()` meet
/// it with a margin of ~10⁶ (their structural entries are exact or differ by a few roundings).
const STRUCTURE_TOL: f64 = 1e-9;

/// Size m of the base group's m×m matrix representation.
fn matrix_size<G: LieGroup>() -> usize {
    G::identity().matrix().to_mat().nrows()
}

/// A vector of NaNs: what an infallible map returns on input of the wrong shape.
fn nan_vector<V: Vector>(dim: usize) -> V {
    V::from_fn(dim, |_| f64::NAN)
}

/// The `rows × cols` block of `m` at `(i, j)`, or NaNs where it falls outside `m`.
fn block(m: MatRef<'_, f64>, i: usize, j: usize, rows: usize, cols: usize) -> Mat<f64> {
    Mat::from_fn(rows, cols, |r, c| {
        if i + r < m.nrows() && j + c < m.ncols() {
            m[(i + r, j + c)]
        } else {
            f64::NAN
        }
    })
}

/// Writes `src` into `dst` with its top-left corner at `(i, j)`.
fn put(dst: &mut Mat<f64>, i: usize, j: usize, src: MatRef<'_, f64>) {
    for c in 0..src.ncols() {
        for r in 0..src.nrows() {
            dst[(i + r, j + c)] = src[(r, c)];
        }
    }
}

fn max_abs(m: MatRef<'_, f64>) -> f64 {
    let mut best = 0.0f64;
    for c in 0..m.ncols() {
        for r in 0..m.nrows() {
            best = best.max(m[(r, c)].abs());
        }
    }
    best
}

fn max_abs_diff(a: MatRef<'_, f64>, b: MatRef<'_, f64>) -> f64 {
    max_abs((a.to_owned() - b.to_owned()).as_ref())
}

fn all_finite(m: MatRef<'_, f64>) -> bool {
    (0..m.ncols()).all(|c| (0..m.nrows()).all(|r| m[(r, c)].is_finite()))
}

/// The base group's algebra element read from an m×m block (`G::vee`), NaN if the block does not
/// have the shape of G's matrices.
fn vee_block<G: LieGroup>(m: MatRef<'_, f64>) -> G::Algebra {
    match G::Matrix::from_mat(m) {
        Some(x) => G::vee(&x),
        None => nan_vector(G::dim()),
    }
}

fn group_block<G: LieGroup>(m: MatRef<'_, f64>) -> Option<G::Matrix> {
    G::Matrix::from_mat(m)
}

/// The n×n matrix of the linear map a ↦ ad*_a μ (column j is ad*_{eⱼ} μ). It is antisymmetric:
/// ⟨ad*_a μ, b⟩ = ⟨μ, [a, b]⟩ = −⟨ad*_b μ, a⟩.
fn ad_dual_in_first<G: LieGroup>(mu: &G::Algebra) -> Mat<f64> {
    let n = G::dim();
    let mut k = Mat::zeros(n, n);
    for j in 0..n {
        let col = G::ad_dual_apply(&G::Algebra::basis(n, j), mu);
        for i in 0..n {
            k[(i, j)] = col.get(i);
        }
    }
    k
}

fn block_operator(tl: &Mat<f64>, bl: &Mat<f64>, br: &Mat<f64>) -> Mat<f64> {
    let n = tl.nrows();
    let mut m = Mat::zeros(2 * n, 2 * n);
    put(&mut m, 0, 0, tl.as_ref());
    put(&mut m, n, 0, bl.as_ref());
    put(&mut m, n, n, br.as_ref());
    m
}

fn structure_error(check: StructureCheck, error: f64, tolerance: f64) -> LieError {
    LieError::NotStructured {
        check,
        error,
        tolerance,
    }
}

// ---------------------------------------------------------------------------------------------
// TG ≅ G ⋉ 𝔤
// ---------------------------------------------------------------------------------------------

/// The left-trivialized tangent bundle TG ≅ G ⋉ 𝔤 (§1.1): elements (g, ξ) with ξ = g⁻¹ u for
/// u ∈ T_g G, and the group structure that makes the trivialization tr_TG a group isomorphism,
///
/// - product `(g, ξ)(h, η) = (gh, Ad_{h⁻¹} ξ + η)`,
/// - inverse `(g, ξ)⁻¹ = (g⁻¹, −Ad_g ξ)`, identity `(e, 0)`.
///
/// Algebra 𝔤 ⋉ 𝔤 with coordinates `Pair { a, b }` (a along G, b along the fibre) and bracket
/// `[(a, b), (c, d)] = ([a, c], [a, d] + [b, c])`.
///
/// Matrix representation (faithful, 2m × 2m for G ⊂ ℝ^{m×m}): `(g, ξ) ↦ [[g, g ξ̂], [0, g]]`, with
/// algebra `(a, b) ↦ [[â, b̂], [0, â]]`. Then
/// - `exp(a, b) = (exp a, d^L exp_a (b))` (Van Loan: the top-right block of the exponential is
///   e^â (d^L exp_a b)^), `log(g, ξ) = (log g, (d^L exp_a)⁻¹ ξ)` with a = log g;
/// - `Ad_{(g, ξ)} = [[Ad_g, 0], [Ad_g ad_ξ, Ad_g]]`, i.e. `Ad_{(g,ξ)}(a, b) = (Ad_g a,
///   Ad_g (b + [ξ, a]))` (conjugation of the block matrices);
/// - `ad_{(a, b)} = [[ad_a, 0], [ad_b, ad_a]]`.
#[derive(Clone, Debug)]
pub struct TangentBundle<G: LieGroup> {
    g: G,
    xi: G::Algebra,
}

impl<G: LieGroup + Copy> Copy for TangentBundle<G> where G::Algebra: Copy {}

impl<G: LieGroup> TangentBundle<G> {
    /// `(g, ξ)`: the point g with left-trivialized velocity ξ = g⁻¹ ġ.
    #[inline]
    pub fn from_parts(g: G, xi: G::Algebra) -> Self {
        Self { g, xi }
    }
    /// The base point g (the projection pr₁: G ⋉ 𝔤 → G).
    #[inline]
    pub fn base(&self) -> &G {
        &self.g
    }
    /// The fibre coordinate ξ ∈ 𝔤.
    #[inline]
    pub fn fiber(&self) -> &G::Algebra {
        &self.xi
    }
    /// `(g, ξ)` by value.
    #[inline]
    pub fn into_parts(self) -> (G, G::Algebra) {
        (self.g, self.xi)
    }
}

impl<G: LieGroup> LieGroup for TangentBundle<G> {
    type Algebra = Pair<G::Algebra, G::Algebra>;
    type Operator = Mat<f64>;
    type Matrix = Mat<f64>;

    fn name() -> String {
        format!("T{}", G::name())
    }
    fn dim() -> usize {
        2 * G::dim()
    }
    fn identity() -> Self {
        Self::from_parts(G::identity(), G::Algebra::zeros(G::dim()))
    }
    /// `(g, ξ)(h, η) = (gh, Ad_{h⁻¹} ξ + η)`.
    // `inline(always)`: with the base parts inlined the body over SE(3) is past LLVM's inlining
    // threshold; out of line, the 144-byte result goes through a return slot and a memcpy, which
    // cost more than the product's arithmetic (`benches/bundles.rs` times it against its parts).
    #[inline(always)]
    fn compose(&self, other: &Self) -> Self {
        let xi = other.g.adjoint_inverse_apply(&self.xi).add(&other.xi);
        Self::from_parts(self.g.compose(&other.g), xi)
    }
    /// `(g, ξ)⁻¹ = (g⁻¹, −Ad_g ξ)`.
    #[inline]
    fn inverse(&self) -> Self {
        Self::from_parts(self.g.inverse(), self.g.adjoint_apply(&self.xi).neg())
    }
    /// `exp(a, b) = (exp a, d^L exp_a (b))`.
    fn exp(x: &Self::Algebra) -> Self {
        Self::from_parts(G::exp(&x.a), G::dexp_left(&x.a).apply(&x.b))
    }
    /// `log(g, ξ) = (a, (d^L exp_a)⁻¹ ξ)` with `a = log g`; an error where log g does not exist or
    /// d^L exp_a is singular.
    fn log(&self) -> Result<Self::Algebra, LieError> {
        let a = self.g.log()?;
        let b = G::dexp_left_inv(&a).apply(&self.xi);
        if !b.is_finite() {
            return Err(LieError::OutOfDomain(
                DomainReason::TangentBundleDexpSingular,
            ));
        }
        Ok(Pair::new(a, b))
    }
    /// `(a, b) ↦ [[â, b̂], [0, â]]`.
    fn hat(x: &Self::Algebra) -> Mat<f64> {
        let m = matrix_size::<G>();
        let a = G::hat(&x.a).to_mat();
        let mut out = Mat::zeros(2 * m, 2 * m);
        put(&mut out, 0, 0, a.as_ref());
        put(&mut out, m, m, a.as_ref());
        put(&mut out, 0, m, G::hat(&x.b).to_mat().as_ref());
        out
    }
    /// Reads a from the top-left and b from the top-right m×m block.
    fn vee(x: &Mat<f64>) -> Self::Algebra {
        let m = matrix_size::<G>();
        let x = x.as_ref();
        Pair::new(
            vee_block::<G>(block(x, 0, 0, m, m).as_ref()),
            vee_block::<G>(block(x, 0, m, m, m).as_ref()),
        )
    }
    /// `[[g, g ξ̂], [0, g]]`.
    fn matrix(&self) -> Mat<f64> {
        let g = self.g.matrix().to_mat();
        let m = g.nrows();
        let u = &g * G::hat(&self.xi).to_mat();
        let mut out = Mat::zeros(2 * m, 2 * m);
        put(&mut out, 0, 0, g.as_ref());
        put(&mut out, m, m, g.as_ref());
        put(&mut out, 0, m, u.as_ref());
        out
    }
    /// Checks the block structure `[[g, u], [0, g]]`, that g is on G and that g⁻¹ u ∈ 𝔤.
    fn from_matrix(x: &Mat<f64>) -> Result<Self, LieError> {
        let m = matrix_size::<G>();
        if x.nrows() != 2 * m || x.ncols() != 2 * m {
            return Err(LieError::DimensionMismatch {
                expected: 2 * m,
                got: if x.nrows() != 2 * m {
                    x.nrows()
                } else {
                    x.ncols()
                },
            });
        }
        let x = x.as_ref();
        if !all_finite(x) {
            return Err(LieError::NonFinite {
                what: "matrix of G ⋉ 𝔤",
            });
        }
        let tol = STRUCTURE_TOL * (1.0 + max_abs(x));
        let lower = max_abs(x.submatrix(m, 0, m, m));
        if lower > tol {
            return Err(structure_error(
                StructureCheck::TangentLowerBlock,
                lower,
                tol,
            ));
        }
        let diag = max_abs_diff(x.submatrix(0, 0, m, m), x.submatrix(m, m, m, m));
        if diag > tol {
            return Err(structure_error(
                StructureCheck::TangentDiagonalBlocks,
                diag,
                tol,
            ));
        }
        let gm = group_block::<G>(x.submatrix(0, 0, m, m)).ok_or(LieError::DimensionMismatch {
            expected: m,
            got: x.nrows() / 2,
        })?;
        let g = G::from_matrix(&gm)?;
        let xi_hat = g.inverse().matrix().to_mat() * x.submatrix(0, m, m, m);
        let xi = vee_block::<G>(xi_hat.as_ref());
        let off = max_abs_diff(G::hat(&xi).to_mat().as_ref(), xi_hat.as_ref());
        if off > tol {
            return Err(structure_error(
                StructureCheck::TangentNotInAlgebra,
                off,
                tol,
            ));
        }
        Ok(Self::from_parts(g, xi))
    }
    /// Reads g from the top-left block and ξ = (g⁻¹ u)ˇ from the top-right block, without checks.
    fn from_matrix_unchecked(x: &Mat<f64>) -> Self {
        let m = matrix_size::<G>();
        let x = x.as_ref();
        let gm = block(x, 0, 0, m, m);
        let g = match group_block::<G>(gm.as_ref()) {
            Some(gm) => G::from_matrix_unchecked(&gm),
            None => G::identity(),
        };
        let xi_hat = g.inverse().matrix().to_mat() * block(x, 0, m, m, m);
        Self::from_parts(g, vee_block::<G>(xi_hat.as_ref()))
    }
    /// `Ad_{(g, ξ)} = [[Ad_g, 0], [Ad_g ad_ξ, Ad_g]]`.
    fn adjoint(&self) -> Mat<f64> {
        let ad_g = self.g.adjoint().to_mat();
        let lower = &ad_g * G::ad(&self.xi).to_mat();
        block_operator(&ad_g, &lower, &ad_g)
    }
    /// `ad_{(a, b)} = [[ad_a, 0], [ad_b, ad_a]]`.
    fn ad(x: &Self::Algebra) -> Mat<f64> {
        let ad_a = G::ad(&x.a).to_mat();
        block_operator(&ad_a, &G::ad(&x.b).to_mat(), &ad_a)
    }
    /// `Ad_{(g, ξ)}(a, b) = (Ad_g a, Ad_g (b + [ξ, a]))`.
    #[inline]
    fn adjoint_apply(&self, x: &Self::Algebra) -> Self::Algebra {
        let b = x.b.add(&G::bracket(&self.xi, &x.a));
        Pair::new(self.g.adjoint_apply(&x.a), self.g.adjoint_apply(&b))
    }
    /// `Ad*_{(g, ξ)}(α, β) = (Ad*_g α + ad*_ξ Ad*_g β, Ad*_g β)`, the transpose of [`Self::adjoint`].
    #[inline]
    fn coadjoint_apply(&self, x: &Self::Algebra) -> Self::Algebra {
        let beta = self.g.coadjoint_apply(&x.b);
        let alpha = self
            .g
            .coadjoint_apply(&x.a)
            .add(&G::ad_dual_apply(&self.xi, &beta));
        Pair::new(alpha, beta)
    }
    /// `[(a, b), (c, d)] = ([a, c], [a, d] + [b, c])`.
    #[inline]
    fn bracket(x: &Self::Algebra, y: &Self::Algebra) -> Self::Algebra {
        Pair::new(
            G::bracket(&x.a, &y.a),
            G::bracket(&x.a, &y.b).add(&G::bracket(&x.b, &y.a)),
        )
    }
    /// `ad*_{(a, b)}(α, β) = (ad*_a α + ad*_b β, ad*_a β)`.
    #[inline]
    fn ad_dual_apply(x: &Self::Algebra, mu: &Self::Algebra) -> Self::Algebra {
        Pair::new(
            G::ad_dual_apply(&x.a, &mu.a).add(&G::ad_dual_apply(&x.b, &mu.b)),
            G::ad_dual_apply(&x.a, &mu.b),
        )
    }
    fn is_finite(&self) -> bool {
        self.g.is_finite() && self.xi.is_finite()
    }
}

// ---------------------------------------------------------------------------------------------
// T*G ≅ G ⋉ 𝔤*
// ---------------------------------------------------------------------------------------------

/// The left-trivialized cotangent bundle T*G ≅ G ⋉ 𝔤* (§1.1): elements (g, μ) with μ = T*_e L_g p
/// for p ∈ T*_g G, and, with `Ad*_g := (Ad_g)ᵀ` (the dual map),
///
/// - product `(g, μ)(h, ν) = (gh, Ad*_h μ + ν)`,
/// - inverse `(g, μ)⁻¹ = (g⁻¹, −Ad*_{g⁻¹} μ)`, identity `(e, 0)`.
///
/// The paper prints `Ad*_{h⁻¹} μ` and `−Ad*_g μ`, meaning the coadjoint *action*; with the dual-map
/// convention those formulas are not associative (slip 1 of `NOTES.md`; the tests pin the form
/// above on every group).
///
/// Algebra 𝔤 ⋉ 𝔤* with coordinates `Pair { a, b }` (a ∈ 𝔤, b = m ∈ 𝔤*) and bracket
/// `[(a, m), (c, n)] = ([a, c], ad*_c m − ad*_a n)`.
///
/// Matrix representation (faithful, (m + n + 1)-square for G ⊂ ℝ^{m×m}, n = dim 𝔤):
/// `(g, μ) ↦ blockdiag(g, [[Ad_g, 0], [μᵀ, 1]])` — a homomorphism because
/// `[[Ad_g, 0], [μᵀ, 1]] [[Ad_h, 0], [νᵀ, 1]] = [[Ad_gh, 0], [(Ad_hᵀ μ + ν)ᵀ, 1]]` — with algebra
/// `(a, m) ↦ blockdiag(â, [[ad_a, 0], [mᵀ, 0]])`. Then
/// - `exp(a, m) = (exp a, (d^L exp_{−a})ᵀ m)`: the bottom row of `exp [[ad_a, 0], [mᵀ, 0]]` is
///   `mᵀ Σ_k ad_a^k/(k+1)! = mᵀ d^L exp_{−a}`; `log(g, μ) = (a, (d^L exp_{−a})^{−ᵀ} μ)`;
/// - `Ad_{(g, μ)}(a, m) = (Ad_g a, Ad*_{g⁻¹}(m + ad*_a μ))`;
/// - `ad_{(a, m)} = [[ad_a, 0], [K_m, −ad_aᵀ]]` with `K_m c := ad*_c m`.
#[derive(Clone, Debug)]
pub struct CotangentBundle<G: LieGroup> {
    g: G,
    mu: G::Algebra,
}

impl<G: LieGroup + Copy> Copy for CotangentBundle<G> where G::Algebra: Copy {}

impl<G: LieGroup> CotangentBundle<G> {
    /// `(g, μ)`: the point g with left-trivialized momentum μ ∈ 𝔤*.
    #[inline]
    pub fn from_parts(g: G, mu: G::Algebra) -> Self {
        Self { g, mu }
    }
    /// The base point g (the projection pr₁: G ⋉ 𝔤* → G).
    #[inline]
    pub fn base(&self) -> &G {
        &self.g
    }
    /// The fibre coordinate μ ∈ 𝔤*.
    #[inline]
    pub fn fiber(&self) -> &G::Algebra {
        &self.mu
    }
    /// `(g, μ)` by value.
    #[inline]
    pub fn into_parts(self) -> (G, G::Algebra) {
        (self.g, self.mu)
    }
}

impl<G: LieGroup> LieGroup for CotangentBundle<G> {
    type Algebra = Pair<G::Algebra, G::Algebra>;
    type Operator = Mat<f64>;
    type Matrix = Mat<f64>;

    fn name() -> String {
        format!("T*{}", G::name())
    }
    fn dim() -> usize {
        2 * G::dim()
    }
    fn identity() -> Self {
        Self::from_parts(G::identity(), G::Algebra::zeros(G::dim()))
    }
    /// `(g, μ)(h, ν) = (gh, Ad*_h μ + ν)`.
    #[inline]
    fn compose(&self, other: &Self) -> Self {
        let mu = other.g.coadjoint_apply(&self.mu).add(&other.mu);
        Self::from_parts(self.g.compose(&other.g), mu)
    }
    /// `(g, μ)⁻¹ = (g⁻¹, −Ad*_{g⁻¹} μ)`.
    #[inline]
    fn inverse(&self) -> Self {
        let g_inv = self.g.inverse();
        let mu = g_inv.coadjoint_apply(&self.mu).neg();
        Self::from_parts(g_inv, mu)
    }
    /// `exp(a, m) = (exp a, (d^L exp_{−a})ᵀ m)`.
    fn exp(x: &Self::Algebra) -> Self {
        let mu = G::dexp_left(&x.a.neg()).apply_transpose(&x.b);
        Self::from_parts(G::exp(&x.a), mu)
    }
    /// `log(g, μ) = (a, (d^L exp_{−a})^{−ᵀ} μ)` with `a = log g`; an error where log g does not
    /// exist or d^L exp_{−a} is singular.
    fn log(&self) -> Result<Self::Algebra, LieError> {
        let a = self.g.log()?;
        let m = G::dexp_left_inv(&a.neg()).apply_transpose(&self.mu);
        if !m.is_finite() {
            return Err(LieError::OutOfDomain(
                DomainReason::CotangentBundleDexpSingular,
            ));
        }
        Ok(Pair::new(a, m))
    }
    /// `(a, m) ↦ blockdiag(â, [[ad_a, 0], [mᵀ, 0]])`.
    fn hat(x: &Self::Algebra) -> Mat<f64> {
        let (m, n) = (matrix_size::<G>(), G::dim());
        let mut out = Mat::zeros(m + n + 1, m + n + 1);
        put(&mut out, 0, 0, G::hat(&x.a).to_mat().as_ref());
        put(&mut out, m, m, G::ad(&x.a).to_mat().as_ref());
        for j in 0..n {
            out[(m + n, m + j)] = x.b.get(j);
        }
        out
    }
    /// Reads a from the top-left m×m block and m from the bottom row of the second block.
    fn vee(x: &Mat<f64>) -> Self::Algebra {
        let (m, n) = (matrix_size::<G>(), G::dim());
        if x.nrows() != m + n + 1 || x.ncols() != m + n + 1 {
            return nan_vector(2 * n);
        }
        let a = vee_block::<G>(x.as_ref().submatrix(0, 0, m, m));
        Pair::new(a, G::Algebra::from_fn(n, |j| x[(m + n, m + j)]))
    }
    /// `blockdiag(g, [[Ad_g, 0], [μᵀ, 1]])`.
    fn matrix(&self) -> Mat<f64> {
        let (m, n) = (matrix_size::<G>(), G::dim());
        let mut out = Mat::zeros(m + n + 1, m + n + 1);
        put(&mut out, 0, 0, self.g.matrix().to_mat().as_ref());
        put(&mut out, m, m, self.g.adjoint().to_mat().as_ref());
        for j in 0..n {
            out[(m + n, m + j)] = self.mu.get(j);
        }
        out[(m + n, m + n)] = 1.0;
        out
    }
    /// Checks the block structure, that g is on G and that the middle block is Ad_g.
    fn from_matrix(x: &Mat<f64>) -> Result<Self, LieError> {
        let (m, n) = (matrix_size::<G>(), G::dim());
        let size = m + n + 1;
        if x.nrows() != size || x.ncols() != size {
            return Err(LieError::DimensionMismatch {
                expected: size,
                got: if x.nrows() != size {
                    x.nrows()
                } else {
                    x.ncols()
                },
            });
        }
        let x = x.as_ref();
        if !all_finite(x) {
            return Err(LieError::NonFinite {
                what: "matrix of G ⋉ 𝔤*",
            });
        }
        let tol = STRUCTURE_TOL * (1.0 + max_abs(x));
        let off = max_abs(x.submatrix(0, m, m, n + 1)).max(max_abs(x.submatrix(m, 0, n + 1, m)));
        if off > tol {
            return Err(structure_error(
                StructureCheck::CotangentOffDiagonal,
                off,
                tol,
            ));
        }
        let mut last = (x[(m + n, m + n)] - 1.0).abs();
        for i in 0..n {
            last = last.max(x[(m + i, m + n)].abs());
        }
        if last > tol {
            return Err(structure_error(
                StructureCheck::CotangentLastColumn,
                last,
                tol,
            ));
        }
        let gm = group_block::<G>(x.submatrix(0, 0, m, m)).ok_or(LieError::DimensionMismatch {
            expected: m,
            got: m,
        })?;
        let g = G::from_matrix(&gm)?;
        let ad = max_abs_diff(x.submatrix(m, m, n, n), g.adjoint().to_mat().as_ref());
        if ad > tol {
            return Err(structure_error(
                StructureCheck::CotangentAdjointBlock,
                ad,
                tol,
            ));
        }
        let mu = G::Algebra::from_fn(n, |j| x[(m + n, m + j)]);
        Ok(Self::from_parts(g, mu))
    }
    /// Reads g from the top-left block and μ from the bottom row, without checks.
    fn from_matrix_unchecked(x: &Mat<f64>) -> Self {
        let (m, n) = (matrix_size::<G>(), G::dim());
        let x = x.as_ref();
        let g = match group_block::<G>(block(x, 0, 0, m, m).as_ref()) {
            Some(gm) => G::from_matrix_unchecked(&gm),
            None => G::identity(),
        };
        let row = block(x, m + n, m, 1, n);
        Self::from_parts(g, G::Algebra::from_fn(n, |j| row[(0, j)]))
    }
    /// `Ad_{(g, μ)} = [[Ad_g, 0], [Ad*_{g⁻¹} K_μ, Ad*_{g⁻¹}]]` with `K_μ a := ad*_a μ`.
    fn adjoint(&self) -> Mat<f64> {
        let ad_g = self.g.adjoint().to_mat();
        let co_inv = self.g.inverse().adjoint().to_mat().transpose().to_owned();
        let lower = &co_inv * ad_dual_in_first::<G>(&self.mu);
        block_operator(&ad_g, &lower, &co_inv)
    }
    /// `ad_{(a, m)} = [[ad_a, 0], [K_m, −ad_aᵀ]]` with `K_m c := ad*_c m`.
    fn ad(x: &Self::Algebra) -> Mat<f64> {
        let ad_a = G::ad(&x.a).to_mat();
        let neg_t = Mat::from_fn(ad_a.ncols(), ad_a.nrows(), |i, j| -ad_a[(j, i)]);
        block_operator(&ad_a, &ad_dual_in_first::<G>(&x.b), &neg_t)
    }
    /// `Ad_{(g, μ)}(a, m) = (Ad_g a, Ad*_{g⁻¹}(m + ad*_a μ))`.
    #[inline]
    fn adjoint_apply(&self, x: &Self::Algebra) -> Self::Algebra {
        let m = x.b.add(&G::ad_dual_apply(&x.a, &self.mu));
        Pair::new(
            self.g.adjoint_apply(&x.a),
            self.g.inverse().coadjoint_apply(&m),
        )
    }
    /// `Ad*_{(g, μ)}(α, β) = (Ad*_g α − ad*_{Ad_{g⁻¹} β} μ, Ad_{g⁻¹} β)`, the transpose of
    /// [`Self::adjoint`] (K_μ is antisymmetric).
    #[inline]
    fn coadjoint_apply(&self, x: &Self::Algebra) -> Self::Algebra {
        let beta = self.g.inverse().adjoint_apply(&x.b);
        let alpha = self
            .g
            .coadjoint_apply(&x.a)
            .sub(&G::ad_dual_apply(&beta, &self.mu));
        Pair::new(alpha, beta)
    }
    /// `[(a, m), (c, n)] = ([a, c], ad*_c m − ad*_a n)`.
    #[inline]
    fn bracket(x: &Self::Algebra, y: &Self::Algebra) -> Self::Algebra {
        Pair::new(
            G::bracket(&x.a, &y.a),
            G::ad_dual_apply(&y.a, &x.b).sub(&G::ad_dual_apply(&x.a, &y.b)),
        )
    }
    /// `ad*_{(a, m)}(α, β) = (ad*_a α − ad*_β m, −[a, β])`.
    #[inline]
    fn ad_dual_apply(x: &Self::Algebra, mu: &Self::Algebra) -> Self::Algebra {
        Pair::new(
            G::ad_dual_apply(&x.a, &mu.a).sub(&G::ad_dual_apply(&mu.b, &x.b)),
            G::bracket(&x.a, &mu.b).neg(),
        )
    }
    fn is_finite(&self) -> bool {
        self.g.is_finite() && self.mu.is_finite()
    }
}
