FROM python:3.11-slim
WORKDIR /srv/leadscrew-selector
COPY pyproject.toml README.md constraints.txt ./
COPY app ./app
COPY templates ./templates
COPY static ./static
COPY catalog ./catalog
RUN python3 -m pip install --no-cache-dir -c constraints.txt . \
    && useradd --create-home --uid 10001 selector
USER selector
EXPOSE 8000
HEALTHCHECK --interval=30s --timeout=3s --start-period=10s --retries=3 \
    CMD python3 -c "import urllib.request,sys; sys.exit(0 if urllib.request.urlopen('http://127.0.0.1:8000/api/v1/health', timeout=2).status == 200 else 1)"
CMD ["leadscrew-selector", "--host", "0.0.0.0", "--port", "8000"]
