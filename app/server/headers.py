"""The one way request headers are read wherever a response depends on them.

The response cache keys on what a response depends on; if the cache read a header one
way (the last of two ``HX-Request`` lines) and the code that builds the response read it
another (the first), one client could store a full page under the fragment's key, or a
gzip body under the identity key, for every other client to receive. So the cache, the
gzip decision and the page route's fragment test all read through these functions: a
repeated header counts by its first line, as Starlette's ``Headers.get`` does.
"""

from collections.abc import Iterable

from starlette.datastructures import Headers

RawHeaders = Iterable[tuple[bytes, bytes]]


def first_header(headers: RawHeaders, name: bytes) -> bytes | None:
    """The first value of header ``name`` (lower case), or None when it is absent.

    >>> first_header([(b"hx-request", b"zzz"), (b"hx-request", b"true")], b"hx-request")
    b'zzz'
    """
    for key, value in headers:
        if key == name:
            return value
    return None


def _raw(headers: RawHeaders | Headers) -> list[tuple[bytes, bytes]]:
    """Raw ASGI headers from the scope's list or from a request's ``Headers``."""
    return list(headers.raw if isinstance(headers, Headers) else headers)


def is_htmx_fragment(headers: RawHeaders | Headers) -> bool:
    """An HTMX swap, which gets a fragment; a history restore needs the whole page.

    >>> is_htmx_fragment([(b"hx-request", b"true")])
    True
    >>> is_htmx_fragment([(b"hx-request", b"true"), (b"hx-history-restore-request", b"true")])
    False
    """
    raw = _raw(headers)
    return first_header(raw, b"hx-request") == b"true" and (
        first_header(raw, b"hx-history-restore-request") != b"true"
    )


def accepts_gzip(headers: RawHeaders | Headers) -> bool:
    """Whether the client takes a gzip body: ``gzip`` listed in Accept-Encoding, not at q=0.

    >>> accepts_gzip([(b"accept-encoding", b"gzip, deflate, br")])
    True
    >>> accepts_gzip([(b"accept-encoding", b"identity"), (b"accept-encoding", b"gzip")])
    False
    >>> accepts_gzip([(b"accept-encoding", b"gzip;q=0")])
    False
    """
    value = first_header(_raw(headers), b"accept-encoding") or b""
    for coding in value.lower().split(b","):
        name, _, params = coding.partition(b";")
        if name.strip() != b"gzip":
            continue
        quality = params.strip().removeprefix(b"q=").strip()
        return quality.rstrip(b"0.") != b"" if quality else True
    return False
