# syntax=docker/dockerfile:1
# SafeGate's image: a build stage that installs the dependencies into a virtualenv, and a slim
# runtime stage that gets only that virtualenv and the files the service reads, running as a
# non-root user. Build context: see .dockerignore (no .venv, databases, .git, tests or caches).

FROM python:3.11-slim AS build
ENV PIP_NO_CACHE_DIR=1 PIP_DISABLE_PIP_VERSION_CHECK=1
RUN python -m venv /opt/venv
ENV PATH=/opt/venv/bin:$PATH
WORKDIR /srv
COPY pyproject.toml README.md ./
COPY app ./app
# Editable, so that the package finds migrations/ and templates_db/ beside it in /srv (the
# runtime stage keeps the same paths); the dependencies land in /opt/venv.
RUN pip install -e .

FROM python:3.11-slim AS runtime
RUN groupadd --system --gid 10001 safegate \
 && useradd --system --uid 10001 --gid safegate --home-dir /srv --shell /usr/sbin/nologin safegate \
 && mkdir -p /srv/data && chown safegate:safegate /srv/data
COPY --from=build /opt/venv /opt/venv
WORKDIR /srv
COPY --from=build /srv/app ./app
COPY alembic.ini ./
COPY migrations ./migrations
COPY templates_db ./templates_db
ENV PATH=/opt/venv/bin:$PATH \
    PYTHONUNBUFFERED=1 \
    PYTHONDONTWRITEBYTECODE=1 \
    SAFEGATE_TEMPLATES_DIR=/srv/templates_db \
    SAFEGATE_DATABASE_URL=sqlite:////srv/data/safegate.db
USER 10001:10001
VOLUME ["/srv/data"]
EXPOSE 8000
# Liveness: the process answers. (Compose also waits on /readyz: database and library loaded.)
HEALTHCHECK --interval=15s --timeout=3s --start-period=60s --retries=3 \
  CMD ["python", "-c", "import urllib.request; urllib.request.urlopen('http://127.0.0.1:8000/healthz', timeout=2)"]
CMD ["safegate", "serve", "--host", "0.0.0.0", "--port", "8000"]
