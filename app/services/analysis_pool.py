"""The analysis pool: Stages 1-5 run in worker processes, so nothing on the event loop waits
behind another request's analysis.

In: a job (a module-level function `job(deciders, *args)`, picklable by reference) and its
arguments, from an async route. Out: the job's return value, awaited without blocking the loop.
The analysis is CPU-bound Python (and an LLM analyzer blocks on the network for up to its
timeout), so a thread would still hold the GIL against the loop; processes do not. Websockets,
probes and reads stay on the loop and never queue behind an analysis.

Sizing: `gate_workers` processes (0: one per core the process may use), each with its own
`Deciders` (the gate, extension and verification services on its own engine, template cache
and analyzer; no migration or seeding), at niceness
`gate_worker_nice` so the loop's process gets a core first. At most `gate_workers + gate_queue`
jobs are in the pool at once; one more raises `Busy` (503 with Retry-After, estimated from the
recent job times and the queue) instead of letting the queue, and every caller's wait, grow.

Templates: every job carries the main process's `TemplateCache.version`; a worker that has not
seen that version reloads the active templates from the database before running the job.
Workers are forked from a fork server that has imported the pipeline and run it once
(`analysis_warmup`), and imported litellm when the analyzer uses an LLM, so a new worker starts
in tens of milliseconds with its caches warm. As with any multiprocessing start method but
`fork`, a script that builds the app must guard its entry point (`if __name__ == "__main__"`),
since each worker imports the main module.
Workers exit on their own within a second of the app's process dying, however it died.
Tracing: with tracing on, a job records its stages (`app.adapters.tracing.stages`) and they come
back with its result, to become spans under the request that awaited it.
Fails: `Busy` when full; `Unavailable` when a worker died (the pool is replaced; the next call
runs on fresh workers); whatever the job raises (SafeGate errors pickle whole).
"""

from __future__ import annotations

import asyncio
import logging
import math
import multiprocessing
import os
import signal
import threading
import time
from collections.abc import Callable
from concurrent.futures import Future, ProcessPoolExecutor
from concurrent.futures.process import BrokenProcessPool
from typing import Any, ParamSpec, TypeVar

import anyio.to_thread

from app.adapters.tracing import Tracing, stages
from app.config import Settings
from app.domain.errors import Busy, Unavailable
from app.metrics import Metrics, pid_alive
from app.services.container import Deciders, build_deciders
from app.services.template_cache import TemplateCache
from app.store import Repositories, create_engine_for

P = ParamSpec("P")
T = TypeVar("T")
Job = Callable[..., T]

WARMUP_MODULE = "app.services.analysis_warmup"
LLM_PRELOAD_MODULE = "app.adapters.llm.preload"
RETRY_AFTER_MAX_SECONDS = 60
OWNER_CHECK_SECONDS = 1.0
_EWMA_WEIGHT = 0.2
_log = logging.getLogger("safegate.analysis_pool")


def default_workers() -> int:
    """One worker per core this process may run on."""
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except AttributeError:  # not Linux
        return max(1, os.cpu_count() or 1)


# The worker side: one `Deciders` and template cache per worker process, built by
# `_init_worker`.
_worker_deciders: Deciders | None = None
_worker_templates: TemplateCache | None = None
_worker_templates_version = -1


def build_worker_deciders(settings: Settings) -> tuple[Deciders, TemplateCache]:
    """A worker's services: the app's database and analyzer, without migrating or seeding."""
    repositories = Repositories.on(create_engine_for(settings.database_url))
    templates = TemplateCache(repositories.templates)
    # The worker's own metrics, never read: the jobs return what the app counts.
    return build_deciders(settings, repositories, templates, Metrics()), templates


def _started_at(pid: int) -> str | None:
    """When a process started (Linux: /proc), to tell it from a later one with its pid."""
    try:
        with open(f"/proc/{pid}/stat", encoding="ascii", errors="replace") as stat:
            return stat.read().rpartition(")")[2].split()[19]
    except (OSError, IndexError):
        return None


def _alive(pid: int, started: str | None) -> bool:
    if started is not None:
        return _started_at(pid) == started
    return pid_alive(pid)


def _watch_owner(owner: int) -> None:
    """Exit when the app's process is gone (killed with SIGKILL, say): a worker's queues are
    shared with its siblings, so it would otherwise wait for work forever, holding its
    database connections (and the fork server, which lives while any worker does)."""
    started = _started_at(owner)

    def watch() -> None:
        while _alive(owner, started):
            time.sleep(OWNER_CHECK_SECONDS)
        os._exit(0)

    threading.Thread(target=watch, name="safegate-owner-watch", daemon=True).start()


def _init_worker(settings: Settings, templates_version: int, owner: int) -> None:
    global _worker_deciders, _worker_templates, _worker_templates_version
    # The app's process owns the workers' lifetime; Ctrl-C reaches the whole process group.
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    _watch_owner(owner)
    if settings.gate_worker_nice:
        os.nice(settings.gate_worker_nice)
    _worker_deciders, _worker_templates = build_worker_deciders(settings)
    _worker_templates_version = templates_version


def _run_job(templates_version: int, job: Job[T], args: tuple[Any, ...],
             trace_stages: bool = False) -> tuple[T, float, stages.StageTrace | None]:
    global _worker_templates_version
    deciders, templates = _worker_deciders, _worker_templates
    if deciders is None or templates is None:  # pragma: no cover - the initializer always ran
        raise Unavailable("the analysis worker was not initialised")
    if templates_version != _worker_templates_version:
        templates.refresh()
        _worker_templates_version = templates_version
    started = time.perf_counter()
    with stages.recording(trace_stages) as trace:
        result = job(deciders, *args)
    return result, time.perf_counter() - started, trace


def _ready() -> int:
    return os.getpid()


class AnalysisPool:
    """Worker processes for Stages 1-5, with a bounded queue in front of them."""

    def __init__(self, settings: Settings, templates: TemplateCache,
                 metrics: Metrics | None = None, tracing: Tracing | None = None) -> None:
        self.settings = settings
        self._tracing = tracing or Tracing()
        self.workers = settings.gate_workers or default_workers()
        self.capacity = self.workers + settings.gate_queue
        self._templates = templates
        self._metrics = metrics or Metrics()
        self._in_flight = 0
        self._job_seconds = 0.05
        self._executor = self._new_executor()

    @property
    def in_flight(self) -> int:
        """Jobs running or waiting in the pool."""
        return self._in_flight

    def _new_executor(self) -> ProcessPoolExecutor:
        context = multiprocessing.get_context("forkserver")
        preload = ["app.main", WARMUP_MODULE]
        if self.settings.analyzer != "symbolic":
            preload.append(LLM_PRELOAD_MODULE)
        # Read when the fork server starts (the first pool of the process), ignored after.
        context.set_forkserver_preload(preload)
        return ProcessPoolExecutor(
            max_workers=self.workers,
            mp_context=context,
            initializer=_init_worker,
            initargs=(self.settings, self._templates.version, os.getpid()),
        )

    async def start(self) -> None:
        """Start every worker now (not on the first request) and wait until each answers.

        Workers are spawned as jobs arrive and no worker is idle; one no-op per worker,
        submitted together, starts them all. Submitting blocks while the fork server starts,
        so it happens in a thread.
        """
        executor = self._executor
        futures = await anyio.to_thread.run_sync(
            lambda: [executor.submit(_ready) for _ in range(self.workers)])
        await asyncio.gather(*(asyncio.wrap_future(f) for f in futures))

    def retry_after(self) -> int:
        """Seconds until the queue has likely drained enough to take a new job."""
        seconds = self._job_seconds * max(1, self._in_flight) / self.workers
        return max(1, min(RETRY_AFTER_MAX_SECONDS, math.ceil(seconds)))

    async def run(self, job: Callable[..., T], *args: Any) -> T:
        """Run `job(deciders, *args)` in a worker and return its result.

        Raises:
            Busy: the workers are busy and the queue is full.
            Unavailable: a worker died while the job waited or ran.
        """
        if self._in_flight >= self.capacity:
            raise Busy(
                f"the gate is busy: {self.workers} analysis workers and a queue of "
                f"{self.settings.gate_queue} are full; retry after {self.retry_after()} s",
                retry_after=self.retry_after())
        executor = self._executor
        try:
            future: Future[tuple[T, float, stages.StageTrace | None]] = executor.submit(
                _run_job, self._templates.version, job, args, self._tracing.enabled)
        except BrokenProcessPool as error:
            self._replace(executor)
            raise Unavailable("an analysis worker stopped; retry") from error
        self._in_flight += 1
        self._count()
        waiting = asyncio.wrap_future(future)
        waiting.add_done_callback(self._finished)
        try:
            result, _, trace = await asyncio.shield(waiting)
        except BrokenProcessPool as error:
            self._replace(executor)
            raise Unavailable("an analysis worker stopped while deciding; retry") from error
        self._tracing.replay(trace)
        return result

    def _count(self) -> None:
        """Publish the pool's load (gauges summed over replicas in multiprocess mode)."""
        self._metrics.analysis_in_flight.set(self._in_flight)
        self._metrics.analysis_queued.set(max(0, self._in_flight - self.workers))

    def _finished(self, done: asyncio.Future[tuple[Any, float, Any]]) -> None:
        self._in_flight -= 1
        self._count()
        if done.cancelled() or done.exception() is not None:
            return
        _, seconds, _ = done.result()
        self._job_seconds += _EWMA_WEIGHT * (seconds - self._job_seconds)

    def _replace(self, broken: ProcessPoolExecutor) -> None:
        if self._executor is broken:
            _log.error("an analysis worker died; starting a new pool")
            broken.shutdown(wait=False, cancel_futures=True)
            self._executor = self._new_executor()

    def close(self) -> None:
        """Stop the workers (jobs still queued are cancelled; running ones finish)."""
        self._executor.shutdown(wait=True, cancel_futures=True)
