"""Render deploy/nginx.conf.template for a set of app processes.

    python3 deploy/render.py --listen 80 --upstream 127.0.0.1:8001 \\
        --upstream 127.0.0.1:8002 --static-root /srv/leadscrew/static --user www-data \\
        > /etc/leadscrew-nginx/nginx.conf

The output goes to stdout; paths inside it (pid, logs, temporary files) are relative to
the prefix nginx is started with (``nginx -p PREFIX``), so nothing needs root-only paths.
"""

import argparse
import sys
from pathlib import Path

TEMPLATE = Path(__file__).resolve().with_name("nginx.conf.template")


def render(listen: str, upstreams: list[str], static_root: Path, user: str | None) -> str:
    """The configuration text; ``user`` None leaves the worker user to nginx's default."""
    servers = "\n".join(f"        server {address} max_fails=0;" for address in upstreams)
    fields = {
        "{{USER}}": f"user {user};" if user else "",
        "{{LISTEN}}": listen,
        "{{UPSTREAMS}}": servers,
        "{{STATIC_ROOT}}": str(static_root.resolve()),
    }
    text = TEMPLATE.read_text()
    for field, value in fields.items():
        text = text.replace(field, value)
    return text


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--listen", required=True, help="nginx listen value: 80, 127.0.0.1:8080")
    parser.add_argument("--upstream", action="append", required=True, help="host:port, repeatable")
    parser.add_argument("--static-root", type=Path, required=True, help="the app's static/")
    parser.add_argument("--user", help="the user nginx's workers run as (when started as root)")
    args = parser.parse_args(argv)
    sys.stdout.write(render(args.listen, args.upstream, args.static_root, args.user))
    return 0


if __name__ == "__main__":
    sys.exit(main())
