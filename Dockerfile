FROM python:3.11-slim
WORKDIR /srv
COPY pyproject.toml README.md alembic.ini ./
COPY app ./app
COPY bench ./bench
COPY sim ./sim
COPY migrations ./migrations
COPY templates_db ./templates_db
RUN pip install --no-cache-dir .
ENV SAFEGATE_TEMPLATES_DIR=/srv/templates_db
EXPOSE 8000
CMD ["safegate", "serve", "--host", "0.0.0.0", "--port", "8000"]
