//! Compile-time unrolling of the stage loops of the explicit pairs ([`crate::adaptive`]).
//!
//! A stage loop `for i in 1..N { for j in 0..i { … A[i][j] … } }` over a tableau of constants is
//! not unrolled by the compiler once its body holds a whole stage: the coefficients are then
//! loaded from memory, the zero ones multiplied in, and the stage vectors kept in a stack array.
//! `unroll!(I < N => { … })` writes the body out once per index with `I` a constant, so each
//! aᵢⱼ is a literal, a zero one vanishes with its `if`, and the stage values stay in registers —
//! the step a hand-written implementation would be.

/// `unroll!(I < N => { body })`: `body` for I = 0, 1, …, 15 (a `const I: usize` each) while
/// `I < N`; `unroll!(I in 1..N => { body })` from I = 1. N must be ≤ 16.
macro_rules! unroll {
    ($i:ident < $n:expr => $body:block) => {
        $crate::unroll::unroll!(@ $i < $n => $body; 0 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15)
    };
    ($i:ident in 1..$n:expr => $body:block) => {
        $crate::unroll::unroll!(@ $i < $n => $body; 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15)
    };
    (@ $i:ident < $n:expr => $body:block; $($k:literal)*) => {
        $(
            {
                const $i: usize = $k;
                if $i < $n $body
            }
        )*
    };
}

pub(crate) use unroll;
