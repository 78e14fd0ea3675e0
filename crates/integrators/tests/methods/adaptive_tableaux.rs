//! The embedded pairs' coefficients against their order conditions, checked numerically from
//! the tableaux: Σ bᵢ Φᵢ(t) = 1/γ(t) for every rooted tree t (Butcher's conditions; Hairer,
//! Nørsett, Wanner, *Solving ODEs I*, §II.2, Theorem 2.13) through the order each solution
//! claims, and the failure of at least one condition one order up (so that the claimed orders
//! are the orders, not lower bounds). The trees are generated, not listed: their counts
//! through order 8 are checked against 1, 1, 2, 4, 9, 20, 48, 115 (OEIS A000081).

use integrators::adaptive::{ButcherPair, Dop853, DormandPrince54};

/// A rooted tree: its order |t|, its density γ(t) and its children (indices of earlier trees).
struct Tree {
    order: usize,
    gamma: f64,
    children: Vec<usize>,
}

/// Every rooted tree up to `max_order`, each tree after its subtrees: a tree of order n is a
/// multiset of trees of total order n − 1, enumerated with non-decreasing indices.
fn trees(max_order: usize) -> Vec<Tree> {
    let mut all = vec![Tree {
        order: 1,
        gamma: 1.0,
        children: vec![],
    }];
    for n in 2..=max_order {
        let existing = all.len();
        let mut found = Vec::new();
        let mut stack = vec![(0usize, n - 1, Vec::<usize>::new())];
        while let Some((start, remaining, children)) = stack.pop() {
            if remaining == 0 {
                found.push(children);
                continue;
            }
            for (i, tree) in all.iter().enumerate().take(existing).skip(start) {
                if tree.order <= remaining {
                    let mut c = children.clone();
                    c.push(i);
                    stack.push((i, remaining - tree.order, c));
                }
            }
        }
        for children in found {
            let gamma = n as f64 * children.iter().map(|&c| all[c].gamma).product::<f64>();
            all.push(Tree {
                order: n,
                gamma,
                children,
            });
        }
    }
    all
}

/// The largest residual |Σ bᵢΦᵢ(t) − 1/γ(t)| (relative to Σ|bᵢΦᵢ(t)| where that exceeds 1)
/// over the trees of order `order`.
fn residual<const N: usize>(all: &[Tree], a: &[[f64; N]; N], b: &[f64; N], order: usize) -> f64 {
    // Φᵢ(t) = Πₖ (A Φ(tₖ))ᵢ, computed for every tree in turn.
    let mut phi: Vec<[f64; N]> = Vec::with_capacity(all.len());
    let mut worst = 0.0f64;
    for tree in all {
        let mut p = [1.0; N];
        for &c in &tree.children {
            for i in 0..N {
                p[i] *= (0..N).map(|j| a[i][j] * phi[c][j]).sum::<f64>();
            }
        }
        if tree.order == order {
            let sum: f64 = (0..N).map(|i| b[i] * p[i]).sum();
            let size: f64 = (0..N).map(|i| (b[i] * p[i]).abs()).sum::<f64>().max(1.0);
            worst = worst.max((sum - 1.0 / tree.gamma).abs() / size);
        }
        phi.push(p);
    }
    worst
}

/// Asserts the order conditions of `b` hold through `order` (to `tol`) and fail at order + 1.
fn assert_order<const N: usize>(label: &str, a: &[[f64; N]; N], b: &[f64; N], order: usize) {
    let all = trees(order + 1);
    for k in 1..=order {
        let r = residual(&all, a, b, k);
        println!("{label}: order-{k} conditions, largest residual {r:.1e}");
        // The coefficients are given to 30 digits and rounded to f64; DOP853's aᵢⱼ reach 44, so
        // the sums of order 8 round at ~1e-14 of their size.
        assert!(r < 1e-13, "{label}: order-{k} condition violated by {r:e}");
    }
    let r = residual(&all, a, b, order + 1);
    println!(
        "{label}: order-{} conditions, largest residual {r:.1e}",
        order + 1
    );
    assert!(
        r > 1e-6,
        "{label} satisfies the conditions of order {}",
        order + 1
    );
}

fn row_sums_are_nodes<const N: usize>(label: &str, a: &[[f64; N]; N], c: &[f64; N]) {
    for i in 0..N {
        let s: f64 = a[i].iter().sum();
        assert!(
            (s - c[i]).abs() < 1e-14,
            "{label}: Σⱼ a{i}ⱼ = {s} ≠ c{i} = {}",
            c[i]
        );
        for (j, &aij) in a[i].iter().enumerate().skip(i) {
            assert_eq!(aij, 0.0, "{label}: a{i}{j} on or above the diagonal");
        }
    }
}

fn minus<const N: usize>(b: &[f64; N], e: &[f64; N]) -> [f64; N] {
    core::array::from_fn(|i| b[i] - e[i])
}

#[test]
fn rooted_trees_are_counted_as_in_a000081() {
    let all = trees(8);
    let counts: Vec<usize> = (1..=8)
        .map(|n| all.iter().filter(|t| t.order == n).count())
        .collect();
    assert_eq!(counts, [1, 1, 2, 4, 9, 20, 48, 115]);
    // γ of the tall tree of order 4 ([[[•]]]) is 4·3·2·1, of the bushy one ([•,•,•]) is 4.
    let order4: Vec<f64> = all
        .iter()
        .filter(|t| t.order == 4)
        .map(|t| t.gamma)
        .collect();
    assert!(order4.contains(&24.0) && order4.contains(&4.0));
}

#[test]
fn dormand_prince_is_order_5_with_an_order_4_embedded_solution() {
    type P = DormandPrince54;
    row_sums_are_nodes("dopri5", &P::A, &P::C);
    assert_order("dopri5 b", &P::A, &P::B, 5);
    assert_order("dopri5 b̂", &P::A, &minus(&P::B, &P::E), 4);
    // First same as last: the last row of A is b, at c = 1.
    assert_eq!(P::A[6], P::B);
    assert_eq!(P::C[6], 1.0);
}

#[test]
fn dop853_is_order_8_with_order_5_and_3_estimators() {
    type P = Dop853;
    row_sums_are_nodes("dop853", &P::A, &P::C);
    assert_order("dop853 b", &P::A, &P::B, 8);
    assert_order("dop853 b − e₅", &P::A, &minus(&P::B, &P::E), 5);
    assert_order("dop853 b − e₃", &P::A, &minus(&P::B, &P::E_LOW.unwrap()), 3);
}

/// The check can fail: one coefficient of Dormand–Prince changed in its 7th digit breaks an
/// order condition of order ≤ 5.
#[test]
fn a_perturbed_coefficient_breaks_the_order_conditions() {
    type P = DormandPrince54;
    let mut a = P::A;
    a[4][3] *= 1.0 + 1e-7;
    let all = trees(5);
    let worst = (1..=5)
        .map(|k| residual(&all, &a, &P::B, k))
        .fold(0.0, f64::max);
    assert!(worst > 1e-9, "perturbation not seen: {worst:e}");
}
