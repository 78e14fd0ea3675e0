//! Counting heap allocations, for the "hot paths allocate nothing" tests of every crate.
//!
//! A test binary installs the allocator once and measures closures with [`allocations`]:
//!
//! ```ignore
//! #[global_allocator]
//! static GLOBAL: lie_groups::testing::CountingAllocator = lie_groups::testing::CountingAllocator;
//!
//! assert_eq!(lie_groups::testing::allocations(|| { /* hot path */ }), 0);
//! ```

use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;

/// The system allocator, counting the allocations made by each thread.
pub struct CountingAllocator;

thread_local! {
    /// Allocations made by this thread. Counted per thread: the test harness's own threads
    /// allocate concurrently (seen in CI under load as spurious counts), and must not be charged
    /// to the code under test. `const` initialisation: reading it never allocates.
    static ALLOCATIONS: Cell<usize> = const { Cell::new(0) };
}

unsafe impl GlobalAlloc for CountingAllocator {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        // `try_with`: the thread-local may already be gone while a thread shuts down.
        let _ = ALLOCATIONS.try_with(|n| n.set(n.get() + 1));
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) }
    }
}

/// Heap allocations made by `f` on the calling thread (0 unless [`CountingAllocator`] is the
/// binary's global allocator).
pub fn allocations(f: impl FnOnce()) -> usize {
    let before = ALLOCATIONS.with(Cell::get);
    f();
    ALLOCATIONS.with(Cell::get) - before
}
