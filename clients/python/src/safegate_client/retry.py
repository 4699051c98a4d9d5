"""When the SDK tries a request again, and how long it waits: `RetryPolicy`.

In: the outcome of one attempt (an httpx response, or the transport error that replaced it).
Out: whether to try again and after how many seconds. Retried: connection failures and
timeouts, and the answers that say "not now" (502, 503 with its `Retry-After`, 504). Never
retried: any other status (a 4xx is the caller's to fix; a 200 is an answer, whatever its
verdict). When the attempts run out the last failure is raised (`ApiError`, or
`SafeGateUnavailable` for a transport failure): a failure is never turned into a decision,
let alone an `authorize`.
"""

from __future__ import annotations

from dataclasses import dataclass

import httpx

RETRIED_STATUSES = frozenset({502, 503, 504})


@dataclass(frozen=True)
class RetryPolicy:
    """How often and how patiently to try again.

    Attributes:
        attempts: tries in all, the first included (1: never retry).
        backoff: seconds before the first retry, doubled for each one after.
        max_wait: the longest single wait, whatever `Retry-After` asks for.
    """

    attempts: int = 3
    backoff: float = 0.2
    max_wait: float = 5.0

    def retries(self, attempt: int, outcome: httpx.Response | httpx.TransportError) -> bool:
        """Whether to try again after `attempt` (1-based) ended with `outcome`."""
        if attempt >= self.attempts:
            return False
        if isinstance(outcome, httpx.TransportError):
            return True
        return outcome.status_code in RETRIED_STATUSES

    def wait(self, attempt: int, outcome: httpx.Response | httpx.TransportError) -> float:
        """Seconds to wait before attempt `attempt + 1`: the server's `Retry-After` when it
        gives one, else exponential backoff; never more than `max_wait`."""
        if isinstance(outcome, httpx.Response):
            asked = outcome.headers.get("retry-after", "")
            if asked.isdigit():
                return min(float(asked), self.max_wait)
        backoff: float = self.backoff * 2.0 ** (attempt - 1)
        return min(backoff, self.max_wait)


NO_RETRIES = RetryPolicy(attempts=1)
