"""The production setup in deploy/: nginx in front of two app processes, and Kubernetes.

nginx runs from deploy/nginx.conf.template rendered by deploy/render.py to free ports and
a temporary prefix, as the current user, in front of two processes started as
``leadscrew-selector`` starts them. Without /usr/sbin/nginx the proxy tests are skipped
locally and fail in CI (CI=true). The Kubernetes manifests are checked against the
Kubernetes schemas that ``kubernetes-validate`` ships (no network needed).
"""

import getpass
import gzip
import os
import socket
import subprocess
import sys
import threading
import time
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import httpx
import kubernetes_validate
import pytest
import yaml

ROOT = Path(__file__).resolve().parents[1]
NGINX = "/usr/sbin/nginx"
K8S = ROOT / "deploy" / "k8s"
#: a Kubernetes release whose schemas kubernetes-validate carries
K8S_VERSION = "1.33.0"
SELECT = "/api/v1/select?load_n=100&speed_mm_s=50&length_mm=500&lead_mm=10"


def _free_port() -> int:
    with socket.socket() as sock:
        sock.bind(("127.0.0.1", 0))
        return int(sock.getsockname()[1])


def _wait_for(url: str, proc: subprocess.Popen[bytes], what: str) -> None:
    deadline = time.monotonic() + 60
    while True:
        try:
            if httpx.get(url, timeout=2).status_code == 200:
                return
        except httpx.HTTPError:
            pass
        assert proc.poll() is None, f"{what} exited with {proc.returncode}"
        assert time.monotonic() < deadline, f"{what} did not start"
        time.sleep(0.1)


def _stop(proc: subprocess.Popen[bytes]) -> None:
    proc.terminate()
    try:
        proc.wait(timeout=10)
    except subprocess.TimeoutExpired:
        proc.kill()
        proc.wait()


@pytest.fixture(scope="module")
def proxy(tmp_path_factory: pytest.TempPathFactory) -> Iterator[str]:
    """Base URL of nginx in front of two app processes."""
    if not Path(NGINX).exists():
        if os.environ.get("CI") == "true":
            pytest.fail(f"{NGINX} is missing in CI: the proxy tests must run")
        pytest.skip(f"{NGINX} not installed (apt-get install nginx)")
    prefix = tmp_path_factory.mktemp("nginx")
    (prefix / "logs").mkdir()
    (prefix / "temp").mkdir()
    apps: list[subprocess.Popen[bytes]] = []
    nginx = None
    try:
        upstreams = []
        for _ in range(2):
            port = _free_port()
            cmd = [sys.executable, "-m", "app.cli", "--port", str(port), "--log-level", "warning"]
            apps.append(subprocess.Popen(cmd, cwd=ROOT))
            upstreams += ["--upstream", f"127.0.0.1:{port}"]
        for proc, address in zip(apps, upstreams[1::2], strict=True):
            _wait_for(f"http://{address}/api/v1/health", proc, "app")
        listen = f"127.0.0.1:{_free_port()}"
        render = [sys.executable, str(ROOT / "deploy" / "render.py"), "--listen", listen]
        render += [*upstreams, "--static-root", str(ROOT / "static"), "--user", getpass.getuser()]
        config = subprocess.run(render, capture_output=True, text=True, check=True).stdout
        (prefix / "nginx.conf").write_text(config)
        args = [NGINX, "-p", str(prefix), "-c", str(prefix / "nginx.conf")]
        args += ["-e", str(prefix / "logs" / "error.log")]
        subprocess.run([*args, "-t"], check=True, capture_output=True)
        nginx = subprocess.Popen([*args, "-g", "daemon off;"])
        _wait_for(f"http://{listen}/api/v1/health", nginx, "nginx")
        yield f"http://{listen}"
    finally:
        if nginx is not None:
            _stop(nginx)
        for proc in apps:
            _stop(proc)


def test_the_proxy_serves_the_app(proxy: str) -> None:
    response = httpx.get(proxy + SELECT, timeout=10)
    assert response.status_code == 200 and response.json()["candidates"]
    assert response.headers["x-content-type-options"] == "nosniff"
    head = httpx.head(proxy + "/api/v1/health", timeout=10)
    assert head.status_code == 200 and head.content == b""


def test_static_files_come_from_nginx_gzipped_with_cache_headers(proxy: str) -> None:
    raw = (ROOT / "static" / "css" / "app.css").read_bytes()
    with httpx.stream(
        "GET", proxy + "/static/css/app.css", headers={"Accept-Encoding": "gzip"}, timeout=10
    ) as response:
        body = b"".join(response.iter_raw())
        headers = response.headers
    assert headers["content-encoding"] == "gzip" and gzip.decompress(body) == raw
    assert "max-age=600" in headers["cache-control"]
    vendor = httpx.get(proxy + "/static/vendor/htmx-2.0.11.min.js", timeout=10)
    assert "immutable" in vendor.headers["cache-control"]


def test_the_proxy_refuses_oversized_heads_and_bodies(proxy: str) -> None:
    big_header = httpx.get(proxy + "/api/v1/health", headers={"X-Big": "a" * 20_000}, timeout=10)
    assert big_header.status_code in (400, 431, 494)
    body = httpx.post(proxy + "/api/v1/select", content=b" " * 200_000, timeout=10)
    assert body.status_code == 413


def _slow_header_flood(
    address: tuple[str, int], sockets: int, stop: threading.Event, open_counts: list[int]
) -> None:
    """Open ``sockets`` connections that send half a request head, then one header byte
    a second each until ``stop``; ``open_counts`` gets how many took the byte, each second."""
    flood = []
    for _ in range(sockets):
        sock = socket.create_connection(address, timeout=5)
        sock.sendall(b"GET /api/v1/health HTTP/1.1\r\nHost: x\r\nX-Slow: ")
        flood.append(sock)
    while not stop.wait(1.0):
        alive = 0
        for sock in flood:
            try:
                sock.sendall(b"a")
                alive += 1
            except OSError:
                pass
        open_counts.append(alive)
    for sock in flood:
        sock.close()


def test_a_slow_header_flood_does_not_stop_normal_requests(proxy: str) -> None:
    host, port = proxy.removeprefix("http://").split(":")
    stop = threading.Event()
    open_counts: list[int] = []
    flood = threading.Thread(
        target=_slow_header_flood, args=((host, int(port)), 200, stop, open_counts)
    )
    flood.start()
    try:
        deadline = time.monotonic() + 30
        while len(open_counts) < 2:  # every flood socket connected and trickling
            assert flood.is_alive() and time.monotonic() < deadline, "the flood did not start"
            time.sleep(0.1)
        statuses = []
        for i in range(20):
            query = SELECT.replace("load_n=100", f"load_n={100 + i}")
            statuses.append(httpx.get(proxy + query, timeout=5).status_code)
            page = httpx.get(proxy + "/?load=100&speed=50&length=500", timeout=5)
            statuses.append(page.status_code)
    finally:
        stop.set()
        flood.join()
    assert statuses == [200] * 40
    # open when the normal requests began (nginx drops them at client_header_timeout)
    assert open_counts[:2] == [200, 200]


# --- Kubernetes ------------------------------------------------------------------------


def _manifests() -> dict[str, dict[str, Any]]:
    docs = [d for f in sorted(K8S.glob("*.yaml")) for d in yaml.safe_load_all(f.read_text())]
    return {doc["kind"]: doc for doc in docs if doc}


@pytest.mark.parametrize("path", sorted(K8S.glob("*.yaml")), ids=lambda p: p.name)
def test_manifests_are_valid_kubernetes(path: Path) -> None:
    for doc in yaml.safe_load_all(path.read_text()):
        kubernetes_validate.validate(doc, K8S_VERSION, strict=True)


def test_the_manifests_fit_together() -> None:
    docs = _manifests()
    assert set(docs) == {"Deployment", "Service", "HorizontalPodAutoscaler"}
    deployment, service, hpa = docs["Deployment"], docs["Service"], docs["HorizontalPodAutoscaler"]
    spec = deployment["spec"]
    assert spec["replicas"] >= 2
    labels = spec["template"]["metadata"]["labels"]
    assert spec["selector"]["matchLabels"].items() <= labels.items()
    assert service["spec"]["selector"].items() <= labels.items()
    (container,) = spec["template"]["spec"]["containers"]
    for probe in ("readinessProbe", "livenessProbe"):
        assert container[probe]["httpGet"]["path"] == "/api/v1/health"
    assert {"cpu", "memory"} <= container["resources"]["requests"].keys()
    assert {"cpu", "memory"} <= container["resources"]["limits"].keys()
    assert hpa["apiVersion"] == "autoscaling/v2"
    assert hpa["spec"]["scaleTargetRef"]["name"] == deployment["metadata"]["name"]
    assert hpa["spec"]["minReplicas"] >= 2


def test_an_invalid_manifest_is_caught() -> None:
    """The validation above can fail: a replica count as text does not pass."""
    deployment = _manifests()["Deployment"]
    broken = {**deployment, "spec": {**deployment["spec"], "replicas": "three"}}
    with pytest.raises(kubernetes_validate.ValidationError):
        kubernetes_validate.validate(broken, K8S_VERSION, strict=True)
