"""HTTP plumbing around the app: limits, load shedding, caching, compression, static files."""
