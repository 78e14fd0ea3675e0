//! The attitudes a configuration holds, written in a form a reader can take in at a glance: the
//! unit quaternion and the rotation vector of each rigid body's rotation R, beside the matrix.
//!
//! Conventions (one for every system, stated in `lie-sim run --help` and the README):
//! - **Quaternion** `qw, qx, qy, qz`: scalar first, Hamilton's product, R = R(q) rotating body
//!   vectors into space (R maps the body frame to the spatial frame, as the group element g does),
//!   sign chosen with `qw ≥ 0` (the hemisphere of the identity, so q is a function of R alone; at
//!   a rotation angle of exactly π both signs have `qw = 0` and the one nalgebra gives is kept).
//! - **Rotation vector** `rv1, rv2, rv3`: φ = θ n with θ ∈ [0, π] the rotation angle and n the
//!   axis, R = exp(φ̂) — `So3::log`, accurate near 0 and near π. Both jump when θ passes π (the
//!   rotation is then reached the shorter way round); |φ| = θ is the angle plotted by
//!   `lie-sim plot`.
//!
//! Which rotations: SO(3) itself; the rotation part of SE(3) (g = (R, x)); SE(2)'s planar
//! rotation by ϑ, as the rotation about the third axis (φ = (0, 0, ϑ) for |ϑ| ≤ π); the factors of
//! products and powers in order (the gyrostat's platform; each of the coupled bodies); none for
//! ℝⁿ and SO(n), whose elements are not a body's attitude.

use lie_groups::{LieGroup, Power, Product, Rn, Se2, Se3, So3, SoN};
use nalgebra::{Quaternion, UnitQuaternion, Vector3};

/// The rigid-body attitudes an element of a configuration group holds (see the module page).
pub trait Attitudes {
    /// How many attitudes an element holds.
    const BODIES: usize;
    /// The k-th attitude, k < [`Self::BODIES`].
    fn attitude(&self, k: usize) -> So3;
}

impl Attitudes for So3 {
    const BODIES: usize = 1;
    fn attitude(&self, _k: usize) -> So3 {
        *self
    }
}

impl Attitudes for Se3 {
    const BODIES: usize = 1;
    fn attitude(&self, _k: usize) -> So3 {
        *self.rotation()
    }
}

impl Attitudes for Se2 {
    const BODIES: usize = 1;
    /// The rotation by ϑ about the third axis.
    fn attitude(&self, _k: usize) -> So3 {
        So3::from_rotation_vector(&Vector3::new(0.0, 0.0, self.rotation().angle()))
    }
}

impl<const N: usize> Attitudes for Rn<N> {
    const BODIES: usize = 0;
    fn attitude(&self, _k: usize) -> So3 {
        So3::identity()
    }
}

impl<const N: usize> Attitudes for SoN<N> {
    const BODIES: usize = 0;
    fn attitude(&self, _k: usize) -> So3 {
        So3::identity()
    }
}

impl<G: Attitudes, H: Attitudes> Attitudes for Product<G, H> {
    const BODIES: usize = G::BODIES + H::BODIES;
    fn attitude(&self, k: usize) -> So3 {
        if k < G::BODIES {
            self.g.attitude(k)
        } else {
            self.h.attitude(k - G::BODIES)
        }
    }
}

impl<G: Attitudes, const N: usize> Attitudes for Power<G, N> {
    const BODIES: usize = G::BODIES * N;
    fn attitude(&self, k: usize) -> So3 {
        self.parts[k / G::BODIES].attitude(k % G::BODIES)
    }
}

/// Cells per attitude: `qw, qx, qy, qz, rv1, rv2, rv3`.
pub const CELLS: usize = 7;

/// The column names of `bodies` attitudes: `qw, qx, qy, qz, rv1, rv2, rv3` for one, each with the
/// suffix `_k` (k = 1 … bodies) for several.
pub fn columns(bodies: usize) -> Vec<String> {
    const NAMES: [&str; CELLS] = ["qw", "qx", "qy", "qz", "rv1", "rv2", "rv3"];
    (1..=bodies)
        .flat_map(|k| {
            NAMES.iter().map(move |n| {
                if bodies == 1 {
                    (*n).to_string()
                } else {
                    format!("{n}_{k}")
                }
            })
        })
        .collect()
}

/// The cells of R (see the module page) into `out` ([`CELLS`] entries); NaN for a matrix whose
/// logarithm fails (not finite).
pub fn write(r: &So3, out: &mut [f64]) {
    let q = UnitQuaternion::from(*r);
    let s = if q.w < 0.0 { -1.0 } else { 1.0 };
    out[0] = s * q.w;
    out[1] = s * q.i;
    out[2] = s * q.j;
    out[3] = s * q.k;
    let phi = r.log().unwrap_or_else(|_| Vector3::repeat(f64::NAN));
    out[4..CELLS].copy_from_slice(phi.as_slice());
}

/// Every attitude of `g` into `out` ([`CELLS`] × `G::BODIES` entries).
pub fn write_all<G: Attitudes>(g: &G, out: &mut [f64]) {
    for (k, cells) in out.chunks_exact_mut(CELLS).take(G::BODIES).enumerate() {
        write(&g.attitude(k), cells);
    }
}

/// The angle θ ∈ [0, π] of R₀ᵀR — how far each body turned — between two sets of attitude cells
/// ([`write_all`]), body by body (`So3::angle`, accurate near 0 and π).
pub fn turned(from: &[f64], to: &[f64]) -> Vec<f64> {
    let rotation = |c: &[f64]| {
        So3::from(UnitQuaternion::new_normalize(Quaternion::new(
            c[0], c[1], c[2], c[3],
        )))
    };
    from.chunks_exact(CELLS)
        .zip(to.chunks_exact(CELLS))
        .map(|(a, b)| rotation(a).inverse().compose(&rotation(b)).angle())
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The cells against closed forms: a rotation by θ about a unit axis n has q = (cos θ/2,
    /// sin θ/2 n) and φ = θ n; past π the same rotation is reached by −n the shorter way, and the
    /// quaternion keeps qw ≥ 0.
    #[test]
    fn cells_match_the_closed_forms_of_an_axis_angle_rotation() {
        let n = Vector3::new(1.0, -2.0, 2.0) / 3.0;
        for theta in [0.0, 1e-9, 0.7, 2.5, std::f64::consts::PI - 1e-7, 4.0] {
            let r = So3::from_rotation_vector(&(n * theta));
            let mut c = [0.0; CELLS];
            write(&r, &mut c);
            // θ > π: the rotation by 2π − θ about −n.
            let (t, axis) = if theta > std::f64::consts::PI {
                (2.0 * std::f64::consts::PI - theta, -n)
            } else {
                (theta, n)
            };
            let (s, co) = (t / 2.0).sin_cos();
            let want = [
                co,
                s * axis[0],
                s * axis[1],
                s * axis[2],
                t * axis[0],
                t * axis[1],
                t * axis[2],
            ];
            for (got, want) in c.iter().zip(want) {
                // q to rounding; φ near π loses digits as the log must (|φ| ~ π, sin θ ~ 1e-7).
                assert!((got - want).abs() < 1e-8, "θ = {theta}: {c:?} vs {want:?}");
            }
            assert!(c[0] >= 0.0);
        }
    }

    /// Products and powers list their factors' attitudes in order; SE(2)'s is the rotation about
    /// the third axis; ℝⁿ holds none.
    #[test]
    fn products_powers_and_planar_rotations_hold_the_expected_attitudes() {
        let a = So3::from_rotation_vector(&Vector3::new(0.1, 0.2, 0.3));
        let b = So3::from_rotation_vector(&Vector3::new(-0.4, 0.0, 0.5));
        let pair = Power::new([Se3::from_rotation(a), Se3::from_rotation(b)]);
        assert_eq!(<Power<Se3, 2> as Attitudes>::BODIES, 2);
        assert_eq!(pair.attitude(1), b);
        let gyro = Product::new(a, Rn::<3>::identity());
        assert_eq!(<Product<So3, Rn<3>> as Attitudes>::BODIES, 1);
        assert_eq!(gyro.attitude(0), a);
        let planar = Se2::exp(&Vector3::new(0.6, 1.0, -2.0));
        let mut c = [0.0; CELLS];
        write(&planar.attitude(0), &mut c);
        assert!(
            (c[6] - 0.6).abs() < 1e-15 && c[4] == 0.0 && c[5] == 0.0,
            "{c:?}"
        );
        assert_eq!(columns(2)[7], "qw_2");
        // a then b: b turned from a by the angle of aᵀb.
        let (mut ca, mut cb) = ([0.0; CELLS], [0.0; CELLS]);
        write(&a, &mut ca);
        write(&b, &mut cb);
        let want = a.inverse().compose(&b).log().unwrap().norm();
        assert!((turned(&ca, &cb)[0] - want).abs() < 1e-14);
        assert_eq!(columns(1), ["qw", "qx", "qy", "qz", "rv1", "rv2", "rv3"]);
    }
}
