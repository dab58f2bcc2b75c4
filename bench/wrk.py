"""Run wrk and parse its text report (requests/s, latency percentiles, errors)."""

import re
import shutil
import subprocess
from dataclasses import dataclass
from pathlib import Path

WRK = "wrk"
INSTALL_HINT = "wrk not found: install it with `apt-get install wrk` (Debian/Ubuntu)."
_UNITS = {"us": 1e-3, "ms": 1.0, "s": 1e3, "m": 60e3, "h": 3600e3}


@dataclass(frozen=True)
class WrkResult:
    requests: int
    requests_per_s: float
    p50_ms: float
    p99_ms: float
    non_2xx_3xx: int
    socket_errors: dict[str, int]

    @property
    def errors(self) -> int:
        return self.non_2xx_3xx + sum(self.socket_errors.values())

    @property
    def answered_per_s(self) -> float:
        """Requests a second answered with 2xx/3xx: a shed request's quick 503 is not
        throughput.

        >>> WrkResult(1000, 100.0, 1.0, 2.0, 250, {}).answered_per_s
        75.0
        """
        if not self.requests:
            return 0.0
        return self.requests_per_s * (self.requests - self.non_2xx_3xx) / self.requests


def _ms(text: str) -> float:
    match = re.fullmatch(r"([\d.]+)(us|ms|s|m|h)", text)
    if match is None:
        raise ValueError(f"not a wrk duration: {text!r}")
    return float(match[1]) * _UNITS[match[2]]


def parse(output: str) -> WrkResult:
    """Figures from ``wrk --latency`` output.

    >>> r = parse(SAMPLE)
    >>> r.requests, r.requests_per_s, r.p50_ms, r.p99_ms, r.non_2xx_3xx, r.errors
    (45012, 4498.6, 6.9, 1100.0, 3, 10)
    """
    rps = re.search(r"Requests/sec:\s+([\d.]+)", output)
    total = re.search(r"(\d+) requests in", output)
    p50 = re.search(r"^\s+50%\s+(\S+)", output, re.M)
    p99 = re.search(r"^\s+99%\s+(\S+)", output, re.M)
    if not (rps and total and p50 and p99):
        raise ValueError(f"unexpected wrk output:\n{output}")
    non2xx = re.search(r"Non-2xx or 3xx responses:\s+(\d+)", output)
    sock = re.search(
        r"Socket errors: connect (\d+), read (\d+), write (\d+), timeout (\d+)", output
    )
    names = ("connect", "read", "write", "timeout")
    return WrkResult(
        requests=int(total[1]),
        requests_per_s=float(rps[1]),
        p50_ms=_ms(p50[1]),
        p99_ms=_ms(p99[1]),
        non_2xx_3xx=int(non2xx[1]) if non2xx else 0,
        socket_errors=dict(zip(names, map(int, sock.groups()), strict=True))
        if sock
        else dict.fromkeys(names, 0),
    )


def available() -> bool:
    return shutil.which(WRK) is not None


def run(
    url: str,
    seconds: int,
    *,
    threads: int = 2,
    connections: int = 32,
    headers: dict[str, str] | None = None,
    script: Path | None = None,
    script_args: tuple[str, ...] = (),
    cpus: str | None = None,
) -> WrkResult:
    """One wrk run; ``cpus`` pins wrk with taskset (keeps it off the server's core)."""
    cmd = [WRK, f"-t{threads}", f"-c{connections}", f"-d{seconds}s", "--latency"]
    for name, value in (headers or {}).items():
        cmd += ["-H", f"{name}: {value}"]
    if script is not None:
        cmd += ["-s", str(script)]
    cmd.append(url)
    if script_args:
        cmd += ["--", *script_args]
    if cpus is not None and shutil.which("taskset"):
        cmd = ["taskset", "-c", cpus, *cmd]
    done = subprocess.run(cmd, capture_output=True, text=True, timeout=seconds + 60, check=True)
    return parse(done.stdout)


SAMPLE = """\
Running 10s test @ http://127.0.0.1:8001/api/v1/select
  2 threads and 32 connections
  Thread Stats   Avg      Stdev     Max   +/- Stdev
    Latency     7.10ms    1.02ms  20.41ms   90.12%
    Req/Sec     2.26k   120.11     2.51k    70.00%
  Latency Distribution
     50%    6.90ms
     75%    7.40ms
     90%    8.01ms
     99%    1.10s
  45012 requests in 10.01s, 12.3MB read
  Socket errors: connect 0, read 2, write 0, timeout 5
  Non-2xx or 3xx responses: 3
Requests/sec:   4498.60
Transfer/sec:      1.23MB
"""
