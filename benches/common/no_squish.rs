//! The plain competitor of the molecular-dynamics field: the NO_SQUISH free-rotor step (Miller,
//! Eleftheriou, Pattnaik, Ndirango, Newns & Martyna 2002, "Symplectic quaternion scheme for
//! biophysical molecular dynamics", J. Chem. Phys. 116, 8649), written as LAMMPS writes it
//! (`no_squish_rotate` of `fix_nve_asphere`/`fix_rigid`): a unit quaternion q and its conjugate
//! momentum p = 2 q ⊗ (0, Π), and the symmetric sequence of exact rotations about the body axes
//! `R₃(h/2) R₂(h/2) R₁(h) R₂(h/2) R₃(h/2)`,
//!
//! ```text
//! R_k(t):  ζ = t (p · P_k q) / (4 I_k),  q ← cos ζ q + sin ζ P_k q,  p ← cos ζ p + sin ζ P_k p,
//! P₁q = (−q₁, q₀, q₃, −q₂),  P₂q = (−q₂, −q₃, q₀, q₁),  P₃q = (−q₃, q₂, −q₁, q₀),
//! ```
//!
//! about 170 flops and five sin/cos a step (two axes twice: the principal-axis splitting, order
//! 2, symmetric, the free body's five-rotation Strang step). Used by `benches/batch.rs` as the
//! hand-written scalar step of a rigid molecule, with libm's `sin_cos`.

/// A free rotor with principal moments `1/inv_i` in NO_SQUISH variables.
#[derive(Clone, Debug)]
pub struct NoSquish {
    /// 1/(4 Iₖ).
    pub quarter_inv_i: [f64; 3],
    /// The attitude quaternion (w, x, y, z).
    pub q: [f64; 4],
    /// Its conjugate momentum.
    pub p: [f64; 4],
}

impl NoSquish {
    /// The rotor with moments `moments` at attitude q (unit) and body momentum Π.
    pub fn new(moments: [f64; 3], q: [f64; 4], pi: [f64; 3]) -> Self {
        // p = 2 q ⊗ (0, Π)
        let [w, x, y, z] = q;
        let [a, b, c] = pi;
        let p = [
            2.0 * (-x * a - y * b - z * c),
            2.0 * (w * a + y * c - z * b),
            2.0 * (w * b - x * c + z * a),
            2.0 * (w * c + x * b - y * a),
        ];
        Self {
            quarter_inv_i: moments.map(|i| 0.25 / i),
            q,
            p,
        }
    }
    /// The body momentum Π = vector part of ½ q* ⊗ p.
    pub fn momentum(&self) -> [f64; 3] {
        let [w, x, y, z] = self.q;
        let [p0, p1, p2, p3] = self.p;
        [
            0.5 * (w * p1 - x * p0 - y * p3 + z * p2),
            0.5 * (w * p2 + x * p3 - y * p0 - z * p1),
            0.5 * (w * p3 - x * p2 + y * p1 - z * p0),
        ]
    }
    #[inline(always)]
    fn rotate(&mut self, k: usize, t: f64) {
        let perm = |v: [f64; 4]| match k {
            1 => [-v[1], v[0], v[3], -v[2]],
            2 => [-v[2], -v[3], v[0], v[1]],
            _ => [-v[3], v[2], -v[1], v[0]],
        };
        let (kq, kp) = (perm(self.q), perm(self.p));
        let phi = (self.p[0] * kq[0] + self.p[1] * kq[1] + self.p[2] * kq[2] + self.p[3] * kq[3])
            * self.quarter_inv_i[k - 1];
        let (s, c) = (t * phi).sin_cos();
        for i in 0..4 {
            self.q[i] = c * self.q[i] + s * kq[i];
            self.p[i] = c * self.p[i] + s * kp[i];
        }
    }
    /// One NO_SQUISH step of size h.
    #[inline]
    pub fn step(&mut self, h: f64) {
        let half = 0.5 * h;
        self.rotate(3, half);
        self.rotate(2, half);
        self.rotate(1, h);
        self.rotate(2, half);
        self.rotate(3, half);
    }
}
