"""The HTTP ceiling: a bare FastAPI ``async def`` returning a small dict.

No middleware, no dependencies, no validation: what one uvicorn worker serves when the
app does nothing. The selector's throughput is reported as a fraction of this.
"""

from fastapi import FastAPI

app = FastAPI(docs_url=None, redoc_url=None, openapi_url=None)


@app.get("/ceiling")
async def ceiling() -> dict[str, str]:
    return {"status": "ok"}
