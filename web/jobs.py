"""The computations of every session, in bounded pools of threads (or of processes).

At most ``workers`` jobs run at once and at most ``queue`` more wait; a job beyond that
is refused at once (:class:`Busy`) instead of piling up.  A job's own size is bounded by
the library (``crankbase.validation.MAX_ROWS`` rows of a table, ``MAX_CYLINDERS``
cylinders, ``MAX_TABLE_ROWS`` tables of an array), and a session waits at most
``timeout`` seconds for it.  An exception inside a job is the job's result, raised in the
request of the session that asked for it only.
"""
from __future__ import annotations

import asyncio
import threading
from concurrent.futures import ThreadPoolExecutor

__all__ = ["JobPool", "Busy"]


class Busy(Exception):
    """Every worker is busy and the queue is full."""


class JobPool:
    """``workers`` threads (or, with ``processes``, processes started by "spawn": a job
    and its arguments must then be picklable) with ``queue`` places to wait."""

    def __init__(self, workers: int = 2, queue: int = 32, timeout: float = 120.0,
                 processes: bool = False):
        self.workers = int(workers)
        self.timeout = float(timeout)
        self._slots = threading.BoundedSemaphore(self.workers + int(queue))
        self._pending: set = set()
        self.processes = bool(processes)
        if processes:
            import multiprocessing
            from concurrent.futures import ProcessPoolExecutor

            self._pool = ProcessPoolExecutor(
                max_workers=self.workers, mp_context=multiprocessing.get_context("spawn"))
        else:
            self._pool = ThreadPoolExecutor(max_workers=self.workers,
                                            thread_name_prefix="crankdyn-job")

    def submit(self, fn, *args, **kwargs):
        """A :class:`concurrent.futures.Future` of ``fn(*args, **kwargs)``; :class:`Busy`
        when the pool and its queue are full."""
        if not self._slots.acquire(blocking=False):
            raise Busy()
        try:
            fut = self._pool.submit(fn, *args, **kwargs)
        except BaseException:
            self._slots.release()
            raise
        self._pending.add(fut)
        fut.add_done_callback(self._done)
        return fut

    def _done(self, fut):
        self._pending.discard(fut)
        self._slots.release()

    def drain(self, timeout: float | None = None) -> None:
        """Wait until every job submitted so far is done."""
        from concurrent.futures import wait

        wait(list(self._pending), timeout)

    async def run(self, fn, *args, **kwargs):
        """Run ``fn`` in the pool and wait for it (at most :attr:`timeout` seconds:
        :class:`TimeoutError`)."""
        fut = self.submit(fn, *args, **kwargs)
        return await asyncio.wait_for(asyncio.wrap_future(fut), self.timeout)

    async def wait(self, fut):
        """Wait for a future of :meth:`submit` (at most :attr:`timeout` seconds)."""
        return await asyncio.wait_for(asyncio.shield(asyncio.wrap_future(fut)), self.timeout)

    def close(self) -> None:
        """Cancel what waits; threads are left to end, processes are joined (their
        queues and semaphores released)."""
        self._pool.shutdown(wait=self.processes, cancel_futures=True)
