//! Embedded explicit Runge–Kutta pairs: the Butcher tableaux the adaptive methods are built on.
//!
//! A pair of s stages advances `y₁ = y₀ + h Σ bᵢ kᵢ`, `kᵢ = f(t₀ + cᵢh, y₀ + h Σ_{j<i} aᵢⱼ kⱼ)`,
//! and estimates the local error by `h Σ eᵢ kᵢ` with `e = b − b̂` for an embedded solution
//! `ŷ₁ = y₀ + h Σ b̂ᵢ kᵢ` of lower order — at no extra stage. The tableaux are applied to the
//! (q, Π) equations by [`crate::baselines::QuaternionDopri5`] / [`crate::baselines::QuaternionDop853`]
//! and in the algebra by the RKMK pairs ([`crate::adaptive::RkmkDopri5`],
//! [`crate::adaptive::RkmkDop853`]).
//!
//! The coefficients are the published ones, and `tests/methods/adaptive_tableaux.rs` checks them
//! numerically: every order condition (all rooted trees) through order 5 for the Dormand–Prince
//! solution and through 4 for its embedded one, through order 8 for DOP853 with its 5th- and
//! 3rd-order estimators through 5 and 3, and cᵢ = Σⱼ aᵢⱼ.

// The coefficients are written digit for digit as published (30 digits), so that they can be
// compared with the source; the compiler rounds them to f64.
#![allow(clippy::excessive_precision)]

use super::Controller;

/// The Butcher tableau of an embedded explicit pair with `N` stages (strictly lower triangular A).
///
/// Implemented by zero-sized marker types ([`DormandPrince54`], [`Dop853`]) so that the
/// coefficients are compile-time constants in the integrators' stage loops: a zero aᵢⱼ costs
/// nothing there, as in a step written out by hand.
pub trait ButcherPair<const N: usize>:
    Copy + Clone + core::fmt::Debug + Default + Send + Sync + 'static
{
    /// A short name, e.g. `"dopri5"`.
    const NAME: &'static str;
    /// The nodes cᵢ.
    const C: [f64; N];
    /// The coefficients aᵢⱼ (zero on and above the diagonal).
    const A: [[f64; N]; N];
    /// The weights bᵢ of the solution that is advanced (order [`Self::ORDER`]).
    const B: [f64; N];
    /// The error weights `e = b − b̂` of the embedded solution (order [`Self::EMBEDDED_ORDER`]).
    const E: [f64; N];
    /// A second, lower-order error estimator `b − b̂₃` where the pair has one (DOP853), combined
    /// with the first as in Hairer's `dop853.f` (see [`ButcherPair::error_norm`]).
    const E_LOW: Option<[f64; N]>;
    /// The classical order of the advanced solution.
    const ORDER: u32;
    /// The order of the embedded solution `ŷ`.
    const EMBEDDED_ORDER: u32;
    /// The power of h the error estimate scales with (`ERROR_EXPONENT` = p̂ + 1 for a plain pair;
    /// 8 for DOP853's combined estimate): the controller's exponent is 1/`ERROR_EXPONENT`.
    const ERROR_EXPONENT: u32;
    /// First same as last: the last stage is evaluated at (t₀ + h, y₁), so it is the next step's
    /// first stage.
    const FSAL: bool;

    /// The step-size controller the pair's authors recommend ([`Controller`]).
    fn controller() -> Controller;

    /// The scaled error norm of a step from the scaled estimates: with `sum` = Σ (êᵢ/scᵢ)² of
    /// the estimator `E`, `sum_low` of `E_LOW` and `n` components, the root mean square
    /// `√(sum/n)` for a plain pair; DOP853's `sum / √(n (sum + 0.01 sum_low))` (Hairer, Nørsett,
    /// Wanner, *Solving ODEs I*, §II.10; `dop853.f`), which behaves like h⁸ where the 5th-order
    /// estimate alone would behave like h⁶.
    #[inline(always)]
    fn error_norm(sum: f64, sum_low: f64, n: usize) -> f64 {
        match Self::E_LOW {
            None => (sum / n as f64).sqrt(),
            Some(_) => {
                let denominator = sum + 0.01 * sum_low;
                if denominator > 0.0 {
                    sum / (n as f64 * denominator).sqrt()
                } else {
                    0.0
                }
            }
        }
    }

    /// The weights of an embedded solution, for measuring the embedded orders: `b − e`, or the
    /// second estimator's `b − e_low` with `low`. Errors: `low` for a pair with one estimator.
    fn embedded_weights(low: bool) -> Result<[f64; N], crate::IntegratorError> {
        let e = match (low, Self::E_LOW) {
            (false, _) => Self::E,
            (true, Some(e)) => e,
            (true, None) => {
                return Err(crate::IntegratorError::InvalidParameter {
                    reason: format!("{} has one error estimator", Self::NAME),
                })
            }
        };
        Ok(core::array::from_fn(|i| Self::B[i] - e[i]))
    }
}

/// The Dormand–Prince 5(4) pair (J. R. Dormand, P. J. Prince, "A family of embedded Runge–Kutta
/// formulae", J. Comput. Appl. Math. 6 (1980) 19–26; Hairer–Nørsett–Wanner, *Solving ODEs I*,
/// Table II.5.2): 7 stages, first same as last, so 6 evaluations a step; order 5 advanced
/// (local extrapolation), order 4 embedded. scipy's `RK45`, `ode_solvers::Dopri5`, MATLAB's
/// `ode45`.
#[derive(Debug, Clone, Copy, Default)]
pub struct DormandPrince54;

const B5: [f64; 7] = [
    35.0 / 384.0,
    0.0,
    500.0 / 1113.0,
    125.0 / 192.0,
    -2187.0 / 6784.0,
    11.0 / 84.0,
    0.0,
];
const B4: [f64; 7] = [
    5179.0 / 57600.0,
    0.0,
    7571.0 / 16695.0,
    393.0 / 640.0,
    -92097.0 / 339200.0,
    187.0 / 2100.0,
    1.0 / 40.0,
];

impl ButcherPair<7> for DormandPrince54 {
    const NAME: &'static str = "dopri5";
    const C: [f64; 7] = [0.0, 1.0 / 5.0, 3.0 / 10.0, 4.0 / 5.0, 8.0 / 9.0, 1.0, 1.0];
    const A: [[f64; 7]; 7] = [
        [0.0; 7],
        [1.0 / 5.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0],
        [3.0 / 40.0, 9.0 / 40.0, 0.0, 0.0, 0.0, 0.0, 0.0],
        [44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0, 0.0, 0.0, 0.0, 0.0],
        [
            19372.0 / 6561.0,
            -25360.0 / 2187.0,
            64448.0 / 6561.0,
            -212.0 / 729.0,
            0.0,
            0.0,
            0.0,
        ],
        [
            9017.0 / 3168.0,
            -355.0 / 33.0,
            46732.0 / 5247.0,
            49.0 / 176.0,
            -5103.0 / 18656.0,
            0.0,
            0.0,
        ],
        B5,
    ];
    const B: [f64; 7] = B5;
    // e = b − b̂, entry by entry (71/57600, 0, −71/16695, 71/1920, −17253/339200, 22/525, −1/40).
    const E: [f64; 7] = [
        B5[0] - B4[0],
        B5[1] - B4[1],
        B5[2] - B4[2],
        B5[3] - B4[3],
        B5[4] - B4[4],
        B5[5] - B4[5],
        B5[6] - B4[6],
    ];
    const E_LOW: Option<[f64; 7]> = None;
    const ORDER: u32 = 5;
    const EMBEDDED_ORDER: u32 = 4;
    const ERROR_EXPONENT: u32 = 5;
    const FSAL: bool = true;

    /// Hairer's `dopri5.f` defaults: PI control with β = 0.04, safety 0.9, the step changed by a
    /// factor in [0.2, 10].
    fn controller() -> Controller {
        Controller::pi(5, 0.04).with_limits(0.2, 10.0)
    }
}

/// DOP853, the explicit Runge–Kutta pair of order 8 of Dormand and Prince with the 5th- and
/// 3rd-order error estimators of Hairer (E. Hairer, S. P. Nørsett, G. Wanner, *Solving ODEs I*,
/// 2nd ed., §II.10; Hairer's `dop853.f`, whose coefficients scipy's `dop853_coefficients.py`
/// reproduces and which are copied here from it): 12 stages, 12 evaluations a step (the last
/// stage is not at y₁; the rate at y₁ is the next step's first stage). scipy's `DOP853`,
/// `ode_solvers::Dop853`.
#[derive(Debug, Clone, Copy, Default)]
pub struct Dop853;

const DOP853_B: [f64; 12] = [
    5.42937341165687622380535766363e-2,
    0.0,
    0.0,
    0.0,
    0.0,
    4.45031289275240888144113950566,
    1.89151789931450038304281599044,
    -5.8012039600105847814672114227,
    3.1116436695781989440891606237e-1,
    -1.52160949662516078556178806805e-1,
    2.01365400804030348374776537501e-1,
    4.47106157277725905176885569043e-2,
];

impl ButcherPair<12> for Dop853 {
    const NAME: &'static str = "dop853";
    const C: [f64; 12] = [
        0.0,
        0.526001519587677318785587544488e-01,
        0.789002279381515978178381316732e-01,
        0.118350341907227396726757197510,
        0.281649658092772603273242802490,
        0.333333333333333333333333333333,
        0.25,
        0.307692307692307692307692307692,
        0.651282051282051282051282051282,
        0.6,
        0.857142857142857142857142857142,
        1.0,
    ];
    const A: [[f64; 12]; 12] = [
        [0.0; 12],
        [
            5.26001519587677318785587544488e-2,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
        ],
        [
            1.97250569845378994544595329183e-2,
            5.91751709536136983633785987549e-2,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
        ],
        [
            2.95875854768068491816892993775e-2,
            0.0,
            8.87627564304205475450678981324e-2,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
        ],
        [
            2.41365134159266685502369798665e-1,
            0.0,
            -8.84549479328286085344864962717e-1,
            9.24834003261792003115737966543e-1,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
        ],
        [
            3.7037037037037037037037037037e-2,
            0.0,
            0.0,
            1.70828608729473871279604482173e-1,
            1.25467687566822425016691814123e-1,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
        ],
        [
            3.7109375e-2,
            0.0,
            0.0,
            1.70252211019544039314978060272e-1,
            6.02165389804559606850219397283e-2,
            -1.7578125e-2,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
        ],
        [
            3.70920001185047927108779319836e-2,
            0.0,
            0.0,
            1.70383925712239993810214054705e-1,
            1.07262030446373284651809199168e-1,
            -1.53194377486244017527936158236e-2,
            8.27378916381402288758473766002e-3,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
        ],
        [
            6.24110958716075717114429577812e-1,
            0.0,
            0.0,
            -3.36089262944694129406857109825,
            -8.68219346841726006818189891453e-1,
            2.75920996994467083049415600797e1,
            2.01540675504778934086186788979e1,
            -4.34898841810699588477366255144e1,
            0.0,
            0.0,
            0.0,
            0.0,
        ],
        [
            4.77662536438264365890433908527e-1,
            0.0,
            0.0,
            -2.48811461997166764192642586468,
            -5.90290826836842996371446475743e-1,
            2.12300514481811942347288949897e1,
            1.52792336328824235832596922938e1,
            -3.32882109689848629194453265587e1,
            -2.03312017085086261358222928593e-2,
            0.0,
            0.0,
            0.0,
        ],
        [
            -9.3714243008598732571704021658e-1,
            0.0,
            0.0,
            5.18637242884406370830023853209,
            1.09143734899672957818500254654,
            -8.14978701074692612513997267357,
            -1.85200656599969598641566180701e1,
            2.27394870993505042818970056734e1,
            2.49360555267965238987089396762,
            -3.0467644718982195003823669022,
            0.0,
            0.0,
        ],
        [
            2.27331014751653820792359768449,
            0.0,
            0.0,
            -1.05344954667372501984066689879e1,
            -2.00087205822486249909675718444,
            -1.79589318631187989172765950534e1,
            2.79488845294199600508499808837e1,
            -2.85899827713502369474065508674,
            -8.87285693353062954433549289258,
            1.23605671757943030647266201528e1,
            6.43392746015763530355970484046e-1,
            0.0,
        ],
    ];
    const B: [f64; 12] = DOP853_B;
    // The 5th-order estimator `er` of dop853.f.
    const E: [f64; 12] = [
        0.1312004499419488073250102996e-1,
        0.0,
        0.0,
        0.0,
        0.0,
        -0.1225156446376204440720569753e1,
        -0.4957589496572501915214079952,
        0.1664377182454986536961530415e1,
        -0.3503288487499736816886487290,
        0.3341791187130174790297318841,
        0.8192320648511571246570742613e-1,
        -0.2235530786388629525884427845e-1,
    ];
    // b − b̂₃ with b̂₃ = (bhh1, bhh2, bhh3) of dop853.f on stages 1, 9 and 12.
    const E_LOW: Option<[f64; 12]> = Some([
        DOP853_B[0] - 0.244094488188976377952755905512,
        0.0,
        0.0,
        0.0,
        0.0,
        DOP853_B[5],
        DOP853_B[6],
        DOP853_B[7],
        DOP853_B[8] - 0.733846688281611857341361741547,
        DOP853_B[9],
        DOP853_B[10],
        DOP853_B[11] - 0.220588235294117647058823529412e-1,
    ]);
    const ORDER: u32 = 8;
    const EMBEDDED_ORDER: u32 = 5;
    const ERROR_EXPONENT: u32 = 8;
    const FSAL: bool = false;

    /// Hairer's `dop853.f` defaults: elementary control (β = 0), safety 0.9, the step changed
    /// by a factor in [1/3, 6].
    fn controller() -> Controller {
        Controller::pi(8, 0.0).with_limits(1.0 / 3.0, 6.0)
    }
}
