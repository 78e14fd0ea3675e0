//! Shared fixtures of the batch tests: bodies in every regime, random states.
#![allow(dead_code)]

use integrators::ensemble::sphere_point;
use lie_groups::{LieGroup, So3};
use mechanics::{HeavyTop, RigidBody};
use nalgebra::Vector3;

/// Principal moments in the regimes the scalar tests cover: generic, near-symmetric, symmetric
/// (two equal moments, either side), a flat body, widely spread moments.
pub const MOMENTS: [[f64; 3]; 7] = [
    [1.0, 2.0, 3.0],
    [2.0, 3.0, 4.0],
    [1.0, 1.0, 2.0],
    [2.0, 1.0, 1.0],
    [1.0, 1.0 + 1e-9, 3.0],
    [0.1, 5.0, 5.1],
    [3.0, 1.0, 2.0],
];

/// A random momentum of norm `radius` and a random attitude, drawn from (seed, i).
pub fn state(radius: f64, seed: u64, i: u64) -> (Vector3<f64>, So3) {
    let pi: Vector3<f64> = sphere_point(3, radius, seed, i).unwrap();
    let w: Vector3<f64> = sphere_point(3, 2.5, seed ^ 0x5eed, i).unwrap();
    (pi, So3::exp(&w))
}

/// A momentum within `gap` (relative) of the separatrix of `body` (|Π|² = 2 h I_mid), random
/// otherwise.
pub fn near_separatrix(body: &RigidBody, gap: f64, seed: u64, i: u64) -> Vector3<f64> {
    let (_, m) = body.principal_frame();
    let mut idx = [0usize, 1, 2];
    idx.sort_by(|&a, &b| m[a].total_cmp(&m[b]));
    let [lo, mid, hi] = idx;
    // On the separatrix: Π_mid free, Π_lo² (1 − I_mid/I_lo)... solve D₂ = 0 for Π_hi given Π_lo.
    let u: Vector3<f64> = sphere_point(3, 1.0, seed, i).unwrap();
    let a = (1.0 / m[lo] - 1.0 / m[mid]).abs();
    let b = (1.0 / m[mid] - 1.0 / m[hi]).abs();
    let mut pi = Vector3::zeros();
    pi[lo] = u[0];
    pi[mid] = u[1];
    pi[hi] = u[0].abs() * (a / b).sqrt() * (1.0 + gap) * u[2].signum();
    pi
}

/// The free bodies of [`MOMENTS`].
pub fn bodies() -> Vec<RigidBody> {
    MOMENTS
        .iter()
        .map(|m| RigidBody::principal([m[0], m[1], m[2]]).unwrap())
        .collect()
}

/// Heavy tops over the same moments, centre of mass off every axis.
pub fn tops() -> Vec<HeavyTop> {
    MOMENTS
        .iter()
        .map(|m| HeavyTop::principal(*m, 1.5, 9.81, Vector3::new(0.1, -0.2, 0.5)).unwrap())
        .collect()
}

/// `max |a − b| / (ε · scale)`: the difference in units of the last place of `scale`.
pub fn ulps_of(a: &[f64], b: &[f64], scale: f64) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max)
        / (f64::EPSILON * scale)
}

/// The entries of a rotation, row-major.
pub fn entries(r: &So3) -> Vec<f64> {
    let m = r.as_matrix();
    (0..9).map(|i| m[(i / 3, i % 3)]).collect()
}
