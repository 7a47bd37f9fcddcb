//! Cancelling calls whose answer is no longer needed: a part job of a plan that was thrown
//! away, a run that ended. A [`CancelToken`] is installed for the current thread with
//! [`scope`]; every call the client makes on that thread while the scope lasts checks the
//! token while it waits (for a free slot at the endpoint, for the answer, between the
//! pieces of a stream) and ends as `cancelled` within a tenth of a second of it being
//! set, closing its connection so that a local server stops generating.
//!
//! A thread-local scope rather than a parameter: the calls happen deep inside code that
//! knows nothing of cancellation (the asset forge's loop, a code writer), on the worker
//! thread that runs the job.

use std::cell::RefCell;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};

/// A flag shared by the code that may cancel and the calls that obey it.
#[derive(Debug, Clone, Default)]
pub struct CancelToken(Arc<AtomicBool>);

impl CancelToken {
    pub fn new() -> Self {
        Self::default()
    }

    /// Cancels every call made under this token, now and later.
    pub fn cancel(&self) {
        self.0.store(true, Ordering::SeqCst);
    }

    pub fn is_cancelled(&self) -> bool {
        self.0.load(Ordering::SeqCst)
    }
}

thread_local! {
    static CURRENT: RefCell<Vec<CancelToken>> = const { RefCell::new(Vec::new()) };
}

/// Runs `f` with `token` installed for this thread: calls made inside end when it is
/// cancelled. Scopes nest; a call obeys every token of the enclosing scopes.
pub fn scope<T>(token: &CancelToken, f: impl FnOnce() -> T) -> T {
    struct Pop;
    impl Drop for Pop {
        fn drop(&mut self) {
            CURRENT.with(|c| {
                c.borrow_mut().pop();
            });
        }
    }
    CURRENT.with(|c| c.borrow_mut().push(token.clone()));
    let _pop = Pop;
    f()
}

/// The tokens in force on this thread (empty outside any scope).
pub(crate) fn current() -> Vec<CancelToken> {
    CURRENT.with(|c| c.borrow().clone())
}

/// True when any of `tokens` is cancelled.
pub(crate) fn any_cancelled(tokens: &[CancelToken]) -> bool {
    tokens.iter().any(CancelToken::is_cancelled)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn scopes_nest_and_end() {
        let outer = CancelToken::new();
        let inner = CancelToken::new();
        assert!(current().is_empty());
        scope(&outer, || {
            scope(&inner, || {
                assert_eq!(current().len(), 2);
                outer.cancel();
                assert!(any_cancelled(&current()));
            });
            assert_eq!(current().len(), 1);
        });
        assert!(current().is_empty());
        assert!(!inner.is_cancelled());
    }
}
