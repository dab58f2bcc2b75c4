"""Settings from the environment (LEADSCREW_*) or the command line."""

from functools import lru_cache
from pathlib import Path

from pydantic_settings import BaseSettings, SettingsConfigDict


class Settings(BaseSettings):
    model_config = SettingsConfigDict(env_prefix="LEADSCREW_")

    catalog_dirs: list[Path] = []
    max_body_bytes: int = 64 * 1024
    max_query_chars: int = 4096
    max_query_params: int = 100
    #: bytes of whole responses kept per process for repeated selection queries (0: off)
    response_cache_bytes: int = 16 * 1024 * 1024
    #: responses kept at most, however small (0: off)
    response_cache_entries: int = 4096


@lru_cache
def get_settings() -> Settings:
    return Settings()
