//! Buffers reused from impact to impact: a [`Buf`] is a `Vec` whose storage comes from, and
//! goes back to, a small per-thread list of spare ones, so that an impact run again and again
//! (a sweep, a map, an uncertainty study) allocates nothing once its thread has run one.
//!
//! (Written here rather than taken from an object-pool crate: the need is a `Vec` that returns
//! its storage on drop, some forty lines, and the pool crates add locking or shared handles
//! that a per-thread list does not need.)

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
#[derive(Debug)]
pub struct Buf<T: Pooled>(Vec<T>);

impl<T: Pooled> Buf<T> {
    /// An empty buffer (a spare one's storage if there is one).
    pub fn new() -> Self {
        let spare = T::spares().try_with(|s| s.borrow_mut().pop()).ok().flatten();
        Buf(spare.unwrap_or_default())
    }

    /// `len` copies of `value`.
    pub fn filled(value: T, len: usize) -> Self {
        let mut b = Buf::new();
        b.0.resize(len, value);
        b
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
        let mut b = Buf::new();
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
        let mut b = Buf::new();
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

    /// No more than [`KEPT`] spares are held, whatever was dropped.
    #[test]
    fn the_spare_list_is_bounded() {
        let many: Vec<Buf<(f64, f64)>> = (0..3 * KEPT).map(|_| Buf::filled((0.0, 0.0), 8)).collect();
        drop(many);
        let held = <(f64, f64)>::spares().with(|s| s.borrow().len());
        assert!(held <= KEPT, "{held}");
    }
}
