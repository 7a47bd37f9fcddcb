//! Cooperative cancellation of long computations: a job that was cancelled or ran out of
//! time must stop working, not only stop being waited for. The caller runs the work inside
//! [`scope`] with its flag; loops deep inside the layout and the verification call
//! [`requested`] between units of work and wind down (their partial result is thrown away
//! by the caller, which checks its flag after they return).
//!
//! A thread-scoped flag rather than a parameter threaded through every solver function:
//! the work runs on the one thread that called [`scope`], and code that never runs in a
//! scope (the CLI, the tests) pays one thread-local read per check.

use std::cell::RefCell;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};

thread_local! {
    static FLAGS: RefCell<Vec<Arc<AtomicBool>>> = const { RefCell::new(Vec::new()) };
}

/// Runs `f` with `flag` in force on this thread: [`requested`] is true inside it once the
/// flag is set. Scopes nest; any enclosing flag counts.
pub fn scope<T>(flag: &Arc<AtomicBool>, f: impl FnOnce() -> T) -> T {
    struct Pop;
    impl Drop for Pop {
        fn drop(&mut self) {
            FLAGS.with(|c| {
                c.borrow_mut().pop();
            });
        }
    }
    FLAGS.with(|c| c.borrow_mut().push(Arc::clone(flag)));
    let _pop = Pop;
    f()
}

/// True when the work running on this thread should stop.
pub fn requested() -> bool {
    FLAGS.with(|c| c.borrow().iter().any(|f| f.load(Ordering::Relaxed)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_flag_counts_only_inside_its_scope_and_on_its_thread() {
        let flag = Arc::new(AtomicBool::new(false));
        assert!(!requested());
        scope(&flag, || {
            assert!(!requested());
            flag.store(true, Ordering::Relaxed);
            assert!(requested());
            let other = std::thread::spawn(requested).join().unwrap_or(true);
            assert!(!other, "another thread is not in the scope");
            let inner = Arc::new(AtomicBool::new(false));
            scope(&inner, || assert!(requested(), "an enclosing flag counts"));
        });
        assert!(!requested());
    }
}
