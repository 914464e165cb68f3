"""The computations of every session, in one bounded pool of threads.

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
    def __init__(self, workers: int = 2, queue: int = 32, timeout: float = 120.0):
        self.workers = int(workers)
        self.timeout = float(timeout)
        self._slots = threading.BoundedSemaphore(self.workers + int(queue))
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
        fut.add_done_callback(lambda _f: self._slots.release())
        return fut

    async def run(self, fn, *args, **kwargs):
        """Run ``fn`` in the pool and wait for it (at most :attr:`timeout` seconds:
        :class:`TimeoutError`)."""
        fut = self.submit(fn, *args, **kwargs)
        return await asyncio.wait_for(asyncio.wrap_future(fut), self.timeout)

    async def wait(self, fut):
        """Wait for a future of :meth:`submit` (at most :attr:`timeout` seconds)."""
        return await asyncio.wait_for(asyncio.shield(asyncio.wrap_future(fut)), self.timeout)

    def close(self) -> None:
        self._pool.shutdown(wait=False, cancel_futures=True)
