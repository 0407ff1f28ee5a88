//! The modal solver's prepared impact allocates nothing once its thread has run one (issue:
//! "no per-impact allocation"): this test binary counts the allocations of its own thread
//! through a counting global allocator.

use racket_impact::params::{Params, SolverKind, TangentialLaw};
use racket_impact::solve::modal::ModalModel;
use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;

/// The system allocator, counting the allocations of each thread.
struct Counting;

thread_local! {
    static ALLOCATIONS: Cell<usize> = const { Cell::new(0) };
}

// SAFETY: every call is passed on to the system allocator unchanged; the count is a
// const-initialised thread-local `Cell`, which itself never allocates.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        let _ = ALLOCATIONS.try_with(|c| c.set(c.get() + 1));
        // SAFETY: the caller's contract, passed on.
        unsafe { System.alloc(layout) }
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        // SAFETY: as above.
        unsafe { System.dealloc(ptr, layout) }
    }

    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        let _ = ALLOCATIONS.try_with(|c| c.set(c.get() + 1));
        // SAFETY: as above.
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

/// Allocations of this thread while `f` runs.
fn allocations(f: impl FnOnce()) -> usize {
    let before = ALLOCATIONS.with(Cell::get);
    f();
    ALLOCATIONS.with(Cell::get) - before
}

fn modal(p: Params) -> ModalModel {
    let mut p = p;
    p.numerics.solver = SolverKind::Modal;
    ModalModel::new(&p).unwrap()
}

#[test]
fn a_prepared_normal_impact_allocates_nothing_after_the_first() {
    for (x, r, ks) in [(0.16, 0.0, 2.74e4), (0.30, 0.05, 1.5e4), (0.02, 0.08, 5e4), (0.0, 0.0, 6e4)] {
        let mut p = Params::paper();
        (p.impact.x, p.impact.r, p.strings.ks) = (x, r, ks);
        let m = modal(p);
        let first = m.run().unwrap();
        let mut again = None;
        let count = allocations(|| {
            for _ in 0..5 {
                again = Some(m.run().unwrap());
            }
        });
        assert_eq!(count, 0, "x {x}, r {r}, ks {ks}: {count} allocations in 5 impacts");
        assert_eq!(format!("{first:?}"), format!("{:?}", again.unwrap()), "the same impact twice");
    }
}

/// Impacts that need buffers of different sizes, taken in turn on one thread: once each has
/// run, none allocates (the spares settle to the sizes they need whatever the order).
#[test]
fn interleaved_impacts_allocate_nothing_once_each_has_run() {
    let models: Vec<ModalModel> = [(0.0, 0.0, 6e4), (0.16, 0.0, 2.74e4), (0.45, 0.08, 1e4), (0.02, 0.03, 3e4)]
        .into_iter()
        .map(|(x, r, ks)| {
            let mut p = Params::paper();
            (p.impact.x, p.impact.r, p.strings.ks) = (x, r, ks);
            modal(p)
        })
        .collect();
    for m in &models {
        m.run().unwrap();
    }
    let count = allocations(|| {
        for _ in 0..5 {
            for m in models.iter().chain(models.iter().rev()) {
                m.run().unwrap();
            }
        }
    });
    assert_eq!(count, 0, "{count} allocations in 40 interleaved impacts");
}

/// The first run of an impact on a fresh thread does allocate (the spare buffers), so the
/// counter sees allocations: the test above cannot pass by counting nothing.
#[test]
fn the_counter_sees_the_first_impacts_buffers() {
    let m = modal(Params::paper());
    let count = std::thread::spawn(move || {
        allocations(|| {
            m.run().unwrap();
        })
    })
    .join()
    .unwrap();
    assert!(count > 0, "{count}");
}

#[test]
fn a_prepared_oblique_impact_allocates_nothing_after_the_first() {
    for law in [TangentialLaw::Elastic, TangentialLaw::Physical] {
        let mut p = Params::paper();
        (p.oblique.angle_deg, p.oblique.spin_rpm, p.oblique.tangential) = (30.0, 2000.0, law);
        let m = modal(p);
        m.run().unwrap();
        let count = allocations(|| {
            for _ in 0..5 {
                m.run().unwrap();
            }
        });
        assert_eq!(count, 0, "{law:?}: {count} allocations in 5 impacts");
    }
}
