//! Buffers reused from impact to impact: a [`Buf`] is a `Vec` whose storage comes from, and
//! goes back to, a small per-thread list of spare ones, so that an impact run again and again
//! (a sweep, a map, an uncertainty study) allocates nothing once its thread has run it, whatever
//! other impacts ran in between (`tests/modal_alloc.rs`).
//!
//! A buffer that knows its size takes the smallest spare that holds it (else the largest, which
//! it then grows), so that the spares settle to the sizes a thread's impacts need whatever the
//! order buffers are taken and dropped in.
//!
//! (Written here rather than taken from an object-pool crate: the need is a `Vec` that returns
//! its storage on drop, and the pool crates add locking or shared handles that a per-thread
//! list does not need.)

use std::cell::RefCell;
use std::ops::{Deref, DerefMut};
use std::thread::LocalKey;

/// Most spare buffers kept per thread and element type (enough for every buffer one impact
/// holds at once; more are freed).
const KEPT: usize = 32;

/// An element type with a per-thread list of spare buffers.
pub trait Pooled: Copy + 'static {
    /// This type's list of spare buffers.
    fn spares() -> &'static LocalKey<RefCell<Vec<Vec<Self>>>>;
}

/// Declare the per-thread spare list of an element type.
macro_rules! pooled {
    ($($t:ty),*) => {$(
        impl Pooled for $t {
            fn spares() -> &'static ::std::thread::LocalKey<::std::cell::RefCell<Vec<Vec<Self>>>> {
                thread_local! {
                    static SPARES: ::std::cell::RefCell<Vec<Vec<$t>>> =
                        const { ::std::cell::RefCell::new(Vec::new()) };
                }
                &SPARES
            }
        }
    )*};
}
pub(crate) use pooled;

pooled!(f64, (f64, f64));

/// A `Vec` whose storage is taken from this thread's spares and given back when dropped.
pub struct Buf<T: Pooled>(Vec<T>);

impl<T: Pooled> Buf<T> {
    /// An empty buffer (a spare one's storage if there is one).
    pub fn new() -> Self {
        Buf::with_capacity(0)
    }

    /// An empty buffer for at least `n` elements: the smallest spare that holds them, else the
    /// largest spare grown to hold them, else a new one.
    pub fn with_capacity(n: usize) -> Self {
        let spare = T::spares()
            .try_with(|s| {
                let mut s = s.borrow_mut();
                // (newest first; an exact fit, the usual case when an impact repeats, ends it)
                let (mut fit, mut largest): (Option<usize>, Option<usize>) = (None, None);
                for i in (0..s.len()).rev() {
                    let c = s[i].capacity();
                    if c == n {
                        fit = Some(i);
                        break;
                    }
                    if c > n && fit.is_none_or(|f| c < s[f].capacity()) {
                        fit = Some(i);
                    }
                    if largest.is_none_or(|l| c > s[l].capacity()) {
                        largest = Some(i);
                    }
                }
                fit.or(largest).map(|i| s.swap_remove(i))
            })
            .ok()
            .flatten();
        let mut v = spare.unwrap_or_default();
        v.reserve(n);
        Buf(v)
    }

    /// `len` copies of `value`.
    pub fn filled(value: T, len: usize) -> Self {
        let mut b = Buf::with_capacity(len);
        b.0.resize(len, value);
        b
    }
}

impl<T: Pooled + std::fmt::Debug> std::fmt::Debug for Buf<T> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        self.0.fmt(f)
    }
}

impl<T: Pooled> Default for Buf<T> {
    fn default() -> Self {
        Buf::new()
    }
}

impl<T: Pooled> Drop for Buf<T> {
    fn drop(&mut self) {
        let mut v = std::mem::take(&mut self.0);
        if v.capacity() == 0 {
            return;
        }
        v.clear();
        // (at thread exit the list may be gone: the storage is then simply freed)
        let _ = T::spares().try_with(|s| {
            let mut s = s.borrow_mut();
            if s.len() < KEPT {
                s.push(v);
            }
        });
    }
}

impl<T: Pooled> Clone for Buf<T> {
    fn clone(&self) -> Self {
        let mut b = Buf::with_capacity(self.0.len());
        b.0.extend_from_slice(&self.0);
        b
    }
}

impl<T: Pooled> Deref for Buf<T> {
    type Target = Vec<T>;

    fn deref(&self) -> &Vec<T> {
        &self.0
    }
}

impl<T: Pooled> DerefMut for Buf<T> {
    fn deref_mut(&mut self) -> &mut Vec<T> {
        &mut self.0
    }
}

impl<T: Pooled> FromIterator<T> for Buf<T> {
    fn from_iter<I: IntoIterator<Item = T>>(iter: I) -> Self {
        let iter = iter.into_iter();
        let mut b = Buf::with_capacity(iter.size_hint().0);
        b.0.extend(iter);
        b
    }
}

impl<T: Pooled> Extend<T> for Buf<T> {
    fn extend<I: IntoIterator<Item = T>>(&mut self, iter: I) {
        self.0.extend(iter);
    }
}

impl<'a, T: Pooled> IntoIterator for &'a Buf<T> {
    type Item = &'a T;
    type IntoIter = std::slice::Iter<'a, T>;

    fn into_iter(self) -> Self::IntoIter {
        self.0.iter()
    }
}

impl<'a, T: Pooled> IntoIterator for &'a mut Buf<T> {
    type Item = &'a mut T;
    type IntoIter = std::slice::IterMut<'a, T>;

    fn into_iter(self) -> Self::IntoIter {
        self.0.iter_mut()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A dropped buffer's storage serves the next one on the same thread; contents never leak
    /// from one to the next; clones and collections are whole copies.
    #[test]
    fn a_dropped_buffer_is_reused_empty() {
        let a: Buf<f64> = Buf::filled(1.5, 100);
        let ptr = a.as_ptr();
        drop(a);
        let b: Buf<f64> = Buf::new();
        assert!(b.is_empty());
        assert_eq!(b.as_ptr(), ptr, "the spare storage is reused");
        assert!(b.capacity() >= 100);
        let c: Buf<f64> = (0..5).map(f64::from).collect();
        assert_eq!(&c[..], &[0.0, 1.0, 2.0, 3.0, 4.0]);
        let d = c.clone();
        assert_eq!(&d[..], &c[..]);
        assert_ne!(d.as_ptr(), c.as_ptr());
        let (x, y): (Buf<f64>, Buf<f64>) = (0..3).map(|i| (i as f64, -(i as f64))).unzip();
        assert_eq!((&x[..], &y[..]), (&[0.0, 1.0, 2.0][..], &[0.0, -1.0, -2.0][..]));
    }

    /// A buffer of known size takes the smallest spare that holds it, so a large request is not
    /// handed a small spare while a large one waits (the order of drops does not matter).
    #[test]
    fn a_sized_buffer_takes_the_smallest_spare_that_holds_it() {
        <f64>::spares().with(|s| s.borrow_mut().clear());
        let (small, large): (Buf<f64>, Buf<f64>) = (Buf::filled(0.0, 4), Buf::filled(0.0, 1000));
        let large_ptr = large.as_ptr();
        drop(large);
        drop(small);
        let b: Buf<f64> = Buf::with_capacity(500);
        assert_eq!(b.as_ptr(), large_ptr);
        let c: Buf<f64> = Buf::with_capacity(2);
        assert!(c.capacity() < 1000, "the small spare");
        assert_eq!(format!("{:?}", Buf::<f64>::filled(1.0, 2)), "[1.0, 1.0]", "prints as a Vec");
    }

    /// No more than [`KEPT`] spares are held, whatever was dropped.
    #[test]
    fn the_spare_list_is_bounded() {
        let many: Vec<Buf<(f64, f64)>> = (0..3 * KEPT).map(|_| Buf::filled((0.0, 0.0), 8)).collect();
        drop(many);
        let held = <(f64, f64)>::spares().with(|s| s.borrow().len());
        assert!(held <= KEPT, "{held}");
    }
}
