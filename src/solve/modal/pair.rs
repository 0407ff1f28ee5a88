//! Two `f64`s worked on at once: a coordinate's `[q, q']` and the step coefficients acting on
//! it. On x86-64 a pair is an SSE2 register (part of every x86-64 processor, so the portable
//! build has it); elsewhere two plain numbers. The arithmetic is the same either way (no fused
//! multiply-add), so results do not depend on the machine.

#[cfg(all(target_arch = "x86_64", target_feature = "sse2"))]
use std::arch::x86_64::{
    __m128d, _mm_add_pd, _mm_mul_pd, _mm_set1_pd, _mm_setr_pd, _mm_storeu_pd, _mm_unpackhi_pd, _mm_unpacklo_pd,
};

/// A pair of `f64`.
#[cfg(all(target_arch = "x86_64", target_feature = "sse2"))]
#[derive(Clone, Copy, Debug)]
#[repr(transparent)]
pub(super) struct Pair(__m128d);

#[cfg(not(all(target_arch = "x86_64", target_feature = "sse2")))]
#[derive(Clone, Copy, Debug)]
pub(super) struct Pair([f64; 2]);

#[cfg(all(target_arch = "x86_64", target_feature = "sse2"))]
impl Pair {
    #[inline(always)]
    pub fn new(a: f64, b: f64) -> Pair {
        // SAFETY: SSE2 is part of the x86-64 baseline.
        Pair(unsafe { _mm_setr_pd(a, b) })
    }

    #[inline(always)]
    pub fn splat(a: f64) -> Pair {
        // SAFETY: as above.
        Pair(unsafe { _mm_set1_pd(a) })
    }

    #[inline(always)]
    pub fn add(self, o: Pair) -> Pair {
        // SAFETY: as above.
        Pair(unsafe { _mm_add_pd(self.0, o.0) })
    }

    #[inline(always)]
    pub fn mul(self, o: Pair) -> Pair {
        // SAFETY: as above.
        Pair(unsafe { _mm_mul_pd(self.0, o.0) })
    }

    /// `[a, a]` and `[b, b]` of `[a, b]`.
    #[inline(always)]
    pub fn spread(self) -> (Pair, Pair) {
        // SAFETY: as above.
        unsafe { (Pair(_mm_unpacklo_pd(self.0, self.0)), Pair(_mm_unpackhi_pd(self.0, self.0))) }
    }

    #[inline(always)]
    pub fn get(self) -> [f64; 2] {
        let mut out = [0.0; 2];
        // SAFETY: as above; `out` holds two f64 (unaligned store).
        unsafe { _mm_storeu_pd(out.as_mut_ptr(), self.0) };
        out
    }
}

#[cfg(not(all(target_arch = "x86_64", target_feature = "sse2")))]
impl Pair {
    #[inline(always)]
    pub fn new(a: f64, b: f64) -> Pair {
        Pair([a, b])
    }

    #[inline(always)]
    pub fn splat(a: f64) -> Pair {
        Pair([a, a])
    }

    #[inline(always)]
    pub fn add(self, o: Pair) -> Pair {
        Pair([self.0[0] + o.0[0], self.0[1] + o.0[1]])
    }

    #[inline(always)]
    pub fn mul(self, o: Pair) -> Pair {
        Pair([self.0[0] * o.0[0], self.0[1] * o.0[1]])
    }

    #[inline(always)]
    pub fn spread(self) -> (Pair, Pair) {
        (Pair([self.0[0]; 2]), Pair([self.0[1]; 2]))
    }

    #[inline(always)]
    pub fn get(self) -> [f64; 2] {
        self.0
    }
}

impl Default for Pair {
    fn default() -> Pair {
        Pair::splat(0.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pair_arithmetic_is_elementwise() {
        let (a, b) = (Pair::new(1.5, -2.0), Pair::new(0.25, 3.0));
        assert_eq!(a.add(b).get(), [1.75, 1.0]);
        assert_eq!(a.mul(b).get(), [0.375, -6.0]);
        let (lo, hi) = a.spread();
        assert_eq!((lo.get(), hi.get()), ([1.5, 1.5], [-2.0, -2.0]));
        assert_eq!(Pair::splat(4.0).get(), [4.0, 4.0]);
    }
}
