//! The columns of a trajectory row, as `lie-sim run` writes them and `plot`, `--reference` and
//! `trade --write-reference` read them (by name):
//!
//! `t, mu1 … muN, g11 … gmm, energy[, casimir][, power, work][, qw, qx, qy, qz, rv1, rv2, rv3]`
//!
//! - `mu1 … muN`: the body momentum μ in the basis of the group's `vee` (Π on SO(3));
//! - `g11 … gmm`: the group element's m×m matrix, row-major (`g1_1 …` for m ≥ 10), only where g is
//!   reconstructed;
//! - `energy`: E = h(μ) + V(g); `casimir` where the system monitors one;
//! - `power, work` where the scene has `[forces]`: the power P = ⟨F_ext(t, g, ξ), ξ⟩ of the forces
//!   at the row's state and their work W(t) = ∫₀ᵗ P dt by the trapezoid rule over the run's steps
//!   (error O(h²) where P is smooth; a row between two steps adds the trapezoid to it), so that
//!   E − E₀ − W is the energy balance the method misses;
//! - the attitudes, where g is reconstructed and holds any ([`crate::attitude`]: unit quaternion
//!   `qw ≥ 0` scalar first and rotation vector φ = θ n, θ ∈ [0, π]; `_k` suffixes for several
//!   bodies).
//!
//! The columns before `power` keep the names and places they had before the later ones were
//! added: the new columns come last.

/// Which columns a trajectory row has (see the module page).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Layout {
    /// N, the components of μ.
    pub momentum: usize,
    /// m, the side of g's matrix, when reconstructed.
    pub side: Option<usize>,
    /// Whether the system monitors a Casimir.
    pub casimir: bool,
    /// Whether the scene has forces (the `power` and `work` columns).
    pub forced: bool,
    /// How many attitudes the rows hold.
    pub bodies: usize,
}

impl Layout {
    /// The column names, in order.
    pub fn names(&self) -> Vec<String> {
        let mut h = vec!["t".to_string()];
        h.extend((1..=self.momentum).map(|i| format!("mu{i}")));
        h.extend(group_names(self.side));
        h.push("energy".into());
        if self.casimir {
            h.push("casimir".into());
        }
        if self.forced {
            h.extend(["power".into(), "work".into()]);
        }
        h.extend(crate::attitude::columns(self.bodies));
        h
    }
    /// The number of columns.
    pub fn width(&self) -> usize {
        let side = self.side.unwrap_or(0);
        2 + self.momentum
            + side * side
            + usize::from(self.casimir)
            + 2 * usize::from(self.forced)
            + crate::attitude::CELLS * self.bodies
    }
    /// The index of the `work` column, when the scene has forces.
    pub fn work(&self) -> Option<usize> {
        let side = self.side.unwrap_or(0);
        self.forced
            .then(|| 3 + self.momentum + side * side + usize::from(self.casimir))
    }
}

/// The names of the group columns of an m×m matrix, row-major: `g11 …`, or `g1_1 …` for m ≥ 10
/// (two-digit indices would be ambiguous without a separator); none without one.
pub fn group_names(side: Option<usize>) -> Vec<String> {
    let m = side.unwrap_or(0);
    (1..=m)
        .flat_map(|i| {
            (1..=m).map(move |j| {
                if m >= 10 {
                    format!("g{i}_{j}")
                } else {
                    format!("g{i}{j}")
                }
            })
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Names and width agree for every combination, and `work` is where its name is.
    #[test]
    fn width_and_work_index_agree_with_the_names() {
        for side in [None, Some(3), Some(12)] {
            for casimir in [false, true] {
                for forced in [false, true] {
                    for bodies in [0, 1, 3] {
                        let l = Layout {
                            momentum: 6,
                            side,
                            casimir,
                            forced,
                            bodies,
                        };
                        let names = l.names();
                        assert_eq!(names.len(), l.width(), "{l:?}");
                        assert_eq!(l.work(), names.iter().position(|n| n == "work"), "{l:?}");
                    }
                }
            }
        }
    }
}
