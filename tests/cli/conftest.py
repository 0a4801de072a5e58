"""Fixtures of the CLI tests."""

import pytest


@pytest.fixture
def cwd(tmp_path, monkeypatch):
    """A fresh working directory (relative outputs land in it)."""
    monkeypatch.chdir(tmp_path)
    return tmp_path
