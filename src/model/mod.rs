//! The physical model: contact law (ball + strings), the discrete beam, and reduced cases.

pub mod beam;
pub mod contact;
pub mod free;
pub mod reduced;
pub mod rigid;

/// `sum_i f(i)` over `0..n` for each of `K` sums at once, with four partial sums each (so that
/// the loop vectorises instead of waiting on one chain of additions).
#[inline(always)]
pub(crate) fn sum4<const K: usize>(n: usize, f: impl Fn(usize) -> [f64; K]) -> [f64; K] {
    let mut acc = [[0.0; K]; 4];
    let whole = n - n % 4;
    for c in 0..n / 4 {
        for (i, a) in acc.iter_mut().enumerate() {
            for (a, x) in a.iter_mut().zip(f(4 * c + i)) {
                *a += x;
            }
        }
    }
    let mut tail = [0.0; K];
    for i in whole..n {
        for (t, x) in tail.iter_mut().zip(f(i)) {
            *t += x;
        }
    }
    std::array::from_fn(|k| (acc[0][k] + acc[2][k]) + (acc[1][k] + acc[3][k]) + tail[k])
}
