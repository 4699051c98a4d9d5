"""SafeGate under uvicorn with its spans kept in memory, for bench/perf/tracing_overhead.py.

Run: `python bench/perf/_traced_server.py PORT on|off`. With `on`, tracing is enabled and the
spans go to OpenTelemetry's in-memory exporter through the batch processor the service uses for
OTLP (so what is measured is making, batching and handing over the spans, not a network);
with `off`, the same process serves the default, untraced app. `GET /_bench/spans` answers how
many spans were exported so far, so the benchmark can check that tracing was really on.
"""

from __future__ import annotations

import sys

import uvicorn
from opentelemetry.sdk.trace.export.in_memory_span_exporter import InMemorySpanExporter

from app.api.logs import configure_logging
from app.config import Settings
from app.main import create_app


def main() -> None:
    port, mode = int(sys.argv[1]), sys.argv[2]
    settings = Settings(otel_enabled=mode == "on")
    configure_logging(settings.log_level)  # as `safegate serve`: the access lines are written
    exporter = InMemorySpanExporter()
    app = create_app(settings, span_exporter=exporter)

    @app.get("/_bench/spans", include_in_schema=False)
    def spans() -> int:
        app.state.tracing.force_flush()
        return len(exporter.get_finished_spans())

    uvicorn.run(app, host="127.0.0.1", port=port, log_level=settings.log_level, log_config=None,
                access_log=False)


if __name__ == "__main__":
    main()
