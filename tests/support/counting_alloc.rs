//! A global allocator that counts the allocations of the calling thread, for the tests
//! that prove a step loop allocates nothing (declared once by each test binary that counts:
//! tests/steppers/main.rs, tests/many_particles.rs, app/tests/scenes/main.rs; per thread,
//! since the other tests' threads and the harness's own allocate at any time).

use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;

struct Counting;

thread_local! {
    // const-initialized: reading it never allocates (no lazy initialization)
    static ALLOCATIONS: Cell<usize> = const { Cell::new(0) };
}

/// Allocations made so far by this thread.
pub fn allocations() -> usize {
    ALLOCATIONS.with(Cell::get)
}

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        // `try_with`: the thread's slot may already be gone while it shuts down
        let _ = ALLOCATIONS.try_with(|n| n.set(n.get() + 1));
        System.alloc(layout)
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        System.dealloc(ptr, layout)
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;
