//! The bounded pool every solve, check and read runs on: `workers` permits, at most `queue`
//! requests waiting for one (more is "busy" at once), a wait of at most [`MAX_WAIT`] (then
//! "busy"), the work on a blocking thread with any panic caught.

use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Arc;
use std::time::Duration;
use tokio::sync::{OwnedSemaphorePermit, Semaphore};

/// The longest a request waits for a worker.
pub const MAX_WAIT: Duration = Duration::from_secs(10);

/// Why work did not run.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Refused {
    /// The queue is full, or the wait ran out.
    Busy,
    /// The work panicked (a bug of the engine, caught), or its thread was lost.
    Panicked,
}

/// The pool: permits for the workers, and the count of requests waiting.
#[derive(Debug, Clone)]
pub struct Pool {
    permits: Arc<Semaphore>,
    waiting: Arc<AtomicUsize>,
    queue: usize,
    wait: Duration,
}

/// One waiting request, counted while it lives.
struct Waiting<'a>(&'a AtomicUsize);

impl Drop for Waiting<'_> {
    fn drop(&mut self) {
        self.0.fetch_sub(1, Ordering::SeqCst);
    }
}

impl Pool {
    /// A pool of `workers` (at least one) with `queue` places to wait.
    pub fn new(workers: usize, queue: usize) -> Pool {
        Pool {
            permits: Arc::new(Semaphore::new(workers.max(1))),
            waiting: Arc::new(AtomicUsize::new(0)),
            queue,
            wait: MAX_WAIT,
        }
    }

    /// The same pool with another longest wait (tests).
    pub fn with_wait(mut self, wait: Duration) -> Pool {
        self.wait = wait;
        self
    }

    /// A worker's permit, held by the caller until dropped, if one is free now: work that
    /// holds it is in flight (a test holds one to stand for a slow request).
    pub fn try_hold(&self) -> Option<OwnedSemaphorePermit> {
        Arc::clone(&self.permits).try_acquire_owned().ok()
    }

    /// A permit: at once when free, else after waiting in the queue (busy when the queue is
    /// full or the wait runs out).
    async fn permit(&self) -> Result<OwnedSemaphorePermit, Refused> {
        if let Ok(p) = Arc::clone(&self.permits).try_acquire_owned() {
            return Ok(p);
        }
        let before = self.waiting.fetch_add(1, Ordering::SeqCst);
        let _counted = Waiting(&self.waiting);
        if before >= self.queue {
            return Err(Refused::Busy);
        }
        match tokio::time::timeout(self.wait, Arc::clone(&self.permits).acquire_owned()).await {
            Ok(Ok(p)) => Ok(p),
            _ => Err(Refused::Busy),
        }
    }

    /// Runs `work` on a blocking thread once a worker is free; a panic is caught.
    pub async fn run<T: Send + 'static>(
        &self,
        work: impl FnOnce() -> T + Send + 'static,
    ) -> Result<T, Refused> {
        let permit = self.permit().await?;
        let joined = tokio::task::spawn_blocking(move || {
            let _permit = permit;
            std::panic::catch_unwind(std::panic::AssertUnwindSafe(work))
        })
        .await;
        match joined {
            Ok(Ok(out)) => Ok(out),
            _ => Err(Refused::Panicked),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[tokio::test]
    async fn busy_when_the_queue_is_full() {
        let pool = Pool::new(1, 0);
        let held = pool.try_hold();
        assert!(held.is_some());
        assert_eq!(pool.run(|| 1).await, Err(Refused::Busy));
        drop(held);
        assert_eq!(pool.run(|| 2).await, Ok(2));
    }

    #[tokio::test]
    async fn busy_after_the_wait() {
        let pool = Pool::new(1, 1).with_wait(Duration::from_millis(50));
        let held = pool.try_hold();
        assert_eq!(pool.run(|| 1).await, Err(Refused::Busy));
        drop(held);
        assert_eq!(pool.waiting.load(Ordering::SeqCst), 0);
    }

    #[tokio::test]
    async fn a_waiting_request_runs_when_a_worker_is_free() {
        let pool = Pool::new(1, 1);
        let held = pool.try_hold();
        let p = pool.clone();
        let waiting = tokio::spawn(async move { p.run(|| 3).await });
        tokio::task::yield_now().await;
        drop(held);
        assert_eq!(waiting.await.ok(), Some(Ok(3)));
    }

    #[tokio::test]
    async fn a_panic_is_caught() {
        let pool = Pool::new(1, 0);
        #[allow(clippy::panic)]
        let out = pool.run(|| -> u8 { panic!("a bug") }).await;
        assert_eq!(out, Err(Refused::Panicked));
        assert_eq!(pool.run(|| 4).await, Ok(4));
    }
}
